"""Chapter 8: Kovalenko's magnetopolar series, his worked examples E47/E48, the regenerated
Figs. 6.7 and 6.8, the libration damper and the eddy shell.

References nobody here chose: the closed-form Fourier coefficients of (6.32) (typed here as
fractions), the quasi-static limit of the planar equation (a stiff magnet follows the
disturbance), the RK4-independent linear solution, and the printed numbers.
"""

import numpy as np
import pytest
from numpy.testing import assert_allclose

from magbench import figures
from magbench.chapters import ch08_field_stabilisation as CH
from magbench.chapters import comparisons, errata

CHAPTER_KEY = "ch08"
EXPECTED_ERRATA = {
    "kov-polar-eta1": "1/3 = 0.3333; the printed 0.34 is one unit of its last digit high",
    "kov-polar-eta2": "the exact second coefficient is 1/18 = 0.0556, not 0.075",
    "kov-polar-etaddot1": "4/3 = 1.333, not 1.36 (4 × the rounded 0.34)",
    "kov-polar-etaddot2": "8/9 = 0.889, not 1.20 (16 × the wrong 0.075)",
    "kov-polar-etaddot-e1": "(4/3)(1/3)^0 = 1.333 for perigee at the node, not 4.0",
    "kov-polar-etaddot-e3": "4.0, not 5.8",
    "kov-polar-etaddot-e5": "100/27 = 3.70, not 2.4",
    "kov-polar-gravity1": "8/9 = 0.889; 0.88 truncates it",
    "kov-polar-gravity2": "8/27 = 0.296, not 0.27",
    "kov-polar-gravity3": "8/81 = 0.0988, not 0.08",
    "kov-polar-forcing-a1-gravity": "(3/2)(8/9) = 1.333, not 1.32",
    "kov-polar-forcing-a3-gravity": "(3/2)(8/81) = 0.148, not 0.13",
    "kov-polar-error-factor": "the maximum of 6 sin 2u/(1 + 3 sin²u)^(5/2) is 1.9030, not 1.92",
    "kov-e47-disturbance-peak": "84.1 N·m/T at u = 17.0°, not 82",
    "kov-e47-disturbance-angle": "the peak is at 17.0°, not 20°",
    "kov-e47-error-estimate": "(6.75) gives 9.68° with the exact peak and 9.44° with the printed 82; not 9.5",
    "kov-e47-natural-frequency": "3.954, which the printed 3.9 truncates",
    "kov-e48-error-674": "(6.74) gives 6.72° at any altitude, not 6.5",
    "kov-e48-error-678": "(6.78) gives 0.87° at 800 km; the printed 2.75° is not reproduced",
    "kovalenko-eddy-alpha": "0.28892, truncated to 0.288",
}


def test_printed_value(printed_check):
    assert_allclose(printed_check.measured, printed_check.model, rtol=0, atol=printed_check.tolerance)


def test_errata_match_expectation():
    assert {e.id for e in errata(CHAPTER_KEY)} == set(EXPECTED_ERRATA)


def test_field_rotation_figure_is_the_closed_form_series():
    """η − u = Σ (1/3)ⁿ/n sin 2nu: the figure's exact curve against forty terms of the series
    (the remainder (1/3)⁴¹ is below 1e-19)."""
    data = figures.compute("kov-field-rotation")
    u = data.series[0].columns["u"][1]
    n = np.arange(1, 41)[:, None]
    series = np.sum((1 / 3) ** n / n * np.sin(2 * n * u), axis=0)
    assert_allclose(data.series[0].columns["eta"][1], series, rtol=0, atol=1e-14)   # float rounding only
    gravity = 8 / 3 * np.sum((1 / 3) ** n * np.sin(2 * n * u), axis=0)
    assert_allclose(data.series[0].columns["gravity"][1], gravity, rtol=0, atol=1e-14)


def test_e47_steady_state_is_fig_6_7():
    """Our planar run: the largest |γ| over the last two of ten orbits, 16.47° at u = 39.6°
    (tests/sim/test_planar.py; the step halved moves it by 1e-3°). The rows compare it with
    Kovalenko's 'about 17° at ω0t ≈ 40°' read off his figure, to one unit of the digit."""
    case = CH.e47_case()
    assert_allclose(np.degrees(case["simulated"]), 16.47, atol=0.01)
    rows = {r.id: r for r in comparisons(CHAPTER_KEY)}
    assert rows["kov-e47-fig6-7-error"].verdict == "agrees"
    assert rows["kov-e47-fig6-7-angle"].verdict == "agrees"
    # the estimate is well below the simulated error: the book's 'does not agree well enough'
    assert case["estimate"] < 0.65 * case["simulated"]


def test_sweep_reaches_the_linear_solution_between_resonances():
    """A stiff magnet (ω_c ≫ 2ω0) with γ ≈ 2° is nearly linear, so between the harmonics'
    resonances (ω_c = 2kω0, shifted down a little by the sin γ softening) the simulated γ_max
    approaches the linear steady solution; and it never falls below the estimate (6.75), which
    neglects the dynamics, by more than 10 %. The stiff points are chosen ≥ 0.5ω0 from 2kω0
    and from the simulated peaks (9.75 and 11.25); measured up to 10.4 % apart (the lightest
    damper at 11.75, nearest the shifted peak), so 12 %."""
    s = CH.error_sweep()
    stiff = np.isin(np.round(s["frequency"], 2), [10.5, 10.75, 11.0, 11.75])
    assert stiff.sum() == 4
    assert_allclose(s["simulated"][:, stiff], s["linear"][:, stiff], rtol=0.12)
    ok = np.isfinite(s["estimate"])
    assert np.all(s["simulated"][:, ok] > 0.9 * s["estimate"][ok])
    assert s["simulated"].shape == (len(CH.DAMPING_FACTORS), CH.SWEEP_MAGNETS)


def test_ball_damper_brings_20_degrees_down_tenfold():
    """The chapter's boom (the satellite ours): 20° at the start, below 2° (a factor ≥ 10) over
    the last orbit at the default coupling, from every phase; the undamped boom keeps its 20°."""
    s = CH.libration_study()
    base = 1 + CH.LIBRATION_DAMPING_FACTORS.index(1.0)
    assert_allclose(np.degrees(s["envelope"][0, base]), 20.0, atol=0.5)   # the first orbit holds the start
    assert np.all(s["residual"][base] <= np.radians(2.0)), np.degrees(s["residual"][base])
    assert np.all(s["residual"][0] > np.radians(19.0))


def test_eddy_shell_thickness_scales_inversely():
    """τ ∝ 1/thickness (thin shell): the matched walls are the 1 mm τ over the target, in mm."""
    m = CH.eddy_shell_match()
    assert_allclose(m["cylinder_thickness_fit"], 1e-3 * m["cylinder_tau_1mm"] / m["time_constant_fit"], rtol=1e-14)
    # the cylinder's transverse + axial mean is larger than the sphere's (2π/3)σ d a⁴ for this long hull
    assert m["cylinder_thickness_fit"] < m["sphere_thickness_fit"]


@pytest.mark.parametrize("name, value, message", [
    ("sweep_frequency_min", 13.0, "sweep_frequency_min and sweep_frequency_max"),
    ("sweep_orbits", 2.0, "sweep_orbits must be >= 3"),
    ("libration_orbits", 1.0, "libration_orbits must be >= 2"),
])
def test_bad_inputs_are_refused_by_name(name, value, message):
    from magbench.params import chapter_parameters

    p = chapter_parameters(CHAPTER_KEY, overrides="")
    p[name] = value
    study = CH.libration_study if name.startswith("libration") else CH.error_sweep
    with pytest.raises(ValueError, match=message):
        study(p)


def test_e48_locked_damper_is_a_rigid_magnet_and_the_run_disagrees():
    """With the friction a hundredfold the damper's magnet sticks to the body, so the body
    moves as one carrying a rigid magnet of the damper's moment (no damping at all): the same
    largest angles per orbit. Kovalenko's 5.5–7.5° is then out of reach of this model, and the
    row says so."""
    from magbench.dynamics import PlanarBody, PlanarDamper
    from magbench.params import chapter_parameters
    from magbench.sim import planar_error_orbit_maxima, simulate_planar

    p = chapter_parameters(CHAPTER_KEY, overrides="")
    case = CH.e48_case(p)
    orbit = CH.polar_orbit(p, "e48_altitude")
    rigid = simulate_planar(PlanarBody(p["e48_inertia"], p["e48_damper_moment"]), PlanarDamper(),
                            case["mean_motion"], case["equatorial_b"], 0.0, 0.0, CH.E48_ORBITS * orbit.period,
                            case["step"])
    # 1e-9 rad: the stuck magnet's rate is the body's to rounding (the stick rule is exact)
    assert_allclose(case["locked_maxima"], planar_error_orbit_maxima(rigid, case["mean_motion"])[:, 0], atol=1e-9)
    rows = {r.id: r for r in comparisons(CHAPTER_KEY)}
    assert rows["kov-e48-fig6-10-error"].verdict == "disagrees"
    assert np.all(case["orbit_maxima"][1:] > np.radians(20.0))
