"""magbench.control.field_stabilisation: the orienting law's geometry, Kovalenko's §6.5 estimates
against closed forms and python-control, and his printed numbers E47–E50."""

import numpy as np
import pytest
from numpy.testing import assert_allclose

from magbench.constants import EARTH_GM, EARTH_RADIUS, MU_0
from magbench.control import (capture_momentum, pointing_dipole, pointing_torque, dry_detumble_time, dry_friction_torque, dry_transient_time,
                              elastic_damper_response, kovalenko_detumble_time, orienting_dipole,
                              orienting_dipole_per_axis, orienting_torque, polar_disturbance_peak,
                              polar_error_factor, polar_forced_response, polar_forcing_coefficients,
                              steady_state_error_closed_form, steady_state_error_estimate, viscous_detumble_time)
from magbench.dynamics import planar_gravity_torque
from magbench.earth import (polar_field_b, polar_field_direction_acceleration, polar_field_direction_angle,
                            polar_fourier_coefficients)

RNG = np.random.default_rng(7)
FIELDS = RNG.normal(size=(200, 3)) * 3e-5
AXES = RNG.normal(size=(200, 3))
#: Kovalenko's Earth dipole, 8.1e25 CGS = 8.1e22 A·m² (§2.1).
EARTH_MOMENT = 8.1e22


def _orbit(altitude):
    r = EARTH_RADIUS + altitude
    return np.sqrt(EARTH_GM / r**3), MU_0 * EARTH_MOMENT / (4 * np.pi * r**3)


# -- the orienting law (6.8)–(6.14) -------------------------------------------------------------
def test_orienting_torque_turns_the_axis_toward_b_with_k0_theta():
    i0 = AXES / np.linalg.norm(AXES, axis=-1, keepdims=True)
    theta = np.arccos(np.clip(np.sum(i0 * FIELDS, -1) / np.linalg.norm(FIELDS, axis=-1), -1, 1))
    dipole = orienting_dipole(FIELDS, AXES, 2e-3)
    torque = orienting_torque(FIELDS, AXES, 2e-3)
    # L0 ⊥ B (cosine of the angle, rounding of unit vectors), |M0| = k0 θ, M0 ∥ i0 × B (6.11).
    cosine = np.sum(dipole * FIELDS, -1) / np.linalg.norm(FIELDS, axis=-1) / np.linalg.norm(dipole, axis=-1)
    assert_allclose(cosine, 0.0, atol=1e-13)
    assert_allclose(np.linalg.norm(torque, axis=-1), 2e-3 * theta, rtol=1e-12)
    direction = np.cross(i0, FIELDS)
    direction /= np.linalg.norm(direction, axis=-1, keepdims=True)
    assert_allclose(torque / np.linalg.norm(torque, axis=-1, keepdims=True), direction, atol=1e-12)


def test_orienting_law_limits():
    b = np.array([0.0, 0.0, 3e-5])
    # θ → 0: k̃0 → k0/B (6.9), and the dipole → 0 continuously (|L0| = k0 θ/B).
    small = orienting_dipole(b, [1e-9, 0.0, 1.0], 1e-3)
    assert_allclose(np.linalg.norm(small), 1e-3 * 1e-9 / 3e-5, rtol=1e-6)
    assert_allclose(orienting_dipole(b, [0.0, 0.0, 1.0], 1e-3), 0.0, atol=0)
    # θ = π: the bracket vanishes, so does L0 (no direction to turn).
    assert_allclose(orienting_dipole(b, [0.0, 0.0, -1.0], 1e-3), 0.0, atol=0)


def test_per_axis_law_is_the_bracket_of_6_8_for_the_x_axis():
    bracket = FIELDS * 0.0
    bracket[:] = np.array([1.0, 0.0, 0.0]) * np.sum(FIELDS**2, -1, keepdims=True) - FIELDS * FIELDS[:, :1]
    # Equal gains: (6.14) = k0 [x B² − B B_x], rounding of products ≈ 1e-9.
    assert_allclose(orienting_dipole_per_axis(FIELDS, [2.0, 2.0, 2.0]), 2.0 * bracket, atol=1e-22)


# -- detumbling and transient (6.45)–(6.54), E49 ------------------------------------------------
def test_e49_viscous_over_dry_detumbling_time():
    """E49 (seed line 141): equal initial damping k_д ω_н = M_T, down to 0.001 ω_н: the ratio
    is ln 1000/0.999 (printed as an expression; 6.9147)."""
    j, w0, kd = 30.0, 0.1, 2e-3
    ratio = viscous_detumble_time(j, kd, w0, 1e-3 * w0) / dry_detumble_time(j, kd * w0, w0, 1e-3 * w0)
    # Same expression, rounding only.
    assert_allclose(ratio, np.log(1000) / 0.999, rtol=1e-14)


def test_bdot_detumble_time_is_the_viscous_law():
    # kovalenko_detumble_time = (6.50) with k_д = (2/3) k ⟨B²⟩: one formula, so equal to rounding.
    assert_allclose(kovalenko_detumble_time(0.04, 5e4, 1.2e-9, 0.1, 0.01),
                    viscous_detumble_time(0.04, 2 / 3 * 5e4 * 1.2e-9, 0.1, 0.01), rtol=1e-15)


def test_transient_estimates():
    j, m, b, g0, mt = 150.0, 120.0, 2.2e-5, 1.0, 3e-4
    k = capture_momentum(j, m, b, g0)
    # (6.53) from the energy integral Jγ̇²/2 = LB(1 − cos γ0): rounding only.
    assert_allclose(k**2 / (2 * j), m * b * (1 - np.cos(g0)), rtol=1e-14)
    assert_allclose(dry_transient_time(j, m, b, g0, mt), k / mt, rtol=1e-15)
    assert_allclose(dry_friction_torque(120.0, 2.2e-5, np.pi / 2), 120.0 * 2.2e-5, rtol=1e-15)


# -- forced response (6.62)–(6.64) --------------------------------------------------------------
def test_forcing_coefficients_from_the_exact_series():
    n = 1e-3
    exact = polar_forcing_coefficients(650.0, 400.0, n, count=4)
    _, acc, grav = polar_fourier_coefficients(4)
    # A_k = −ω0² η̈_k + (3/2)(ΔJ/J) ω0² (sin 2λ)_k, rounding only.
    assert_allclose(exact, n**2 * (-acc + 1.5 * 400.0 / 650.0 * grav), rtol=1e-14)
    printed = polar_forcing_coefficients(650.0, 400.0, n, printed=True)
    assert_allclose(printed, n**2 * np.array([1.36 + 1.32 * 400 / 650, 1.2 + 0.4 * 400 / 650, 0.13 * 400 / 650]),
                    rtol=1e-14)


def test_printed_gravity_forcing_is_three_halves_of_the_printed_series():
    """The book's 1.32 and 0.4 are (3/2)·0.88 and (3/2)·0.27 (consistent with its own (6.61));
    the exact values are (3/2)·(8/9) = 1.333 and (3/2)·(8/27) = 0.444."""
    assert_allclose([1.32, 0.4], 1.5 * np.array([0.88, 0.27]), atol=0.005)   # printed digits


def test_forced_response_is_a_second_order_filter():
    j, m, b, kd, n = 650.0, 500.0, 2e-5, 0.2, 1e-3
    amp, phase = polar_forced_response(j, m, b, kd, n, 400.0)
    forcing = polar_forcing_coefficients(j, 400.0, n)
    w = 2 * n * np.arange(1, 4)
    response = forcing / (m * b / j - w**2 + 1j * kd / j * w)
    # |H| and arg H of 1/(ω_c² − ω² + 2ibω): rounding only.
    assert_allclose(amp, np.abs(response), rtol=1e-13)
    assert_allclose(phase, -np.angle(response), atol=1e-13)


def test_elastic_damper_transfer_function_against_python_control():
    control = pytest.importorskip("control")
    j, c, kd, ly, b = 150.0, 4e-3, 0.05, 120.0, 2.2e-5
    d2, wy2, wc2 = kd / j, c / j, ly * b / j
    p = control.tf("s")
    w_tf = (d2 * p + wy2 + wc2) / ((p**2 + d2 * p + wy2) * (d2 * p + wy2 + wc2) - (d2 * p + wy2) ** 2)
    freq = 2e-3 * np.arange(1, 4)
    expected = np.array([complex(w_tf(1j * f)) for f in freq])
    amp, phase = elastic_damper_response(1.0, freq, j, c, kd, ly, b)
    # python-control evaluates the same polynomials: rounding only.
    assert_allclose(amp, np.abs(expected), rtol=1e-10)
    assert_allclose(phase, np.angle(expected), atol=1e-10)


def test_elastic_damper_limits():
    j, kd, ly, b, w = 150.0, 0.05, 120.0, 2.2e-5, 2e-3
    # A stiff spring ties the damper magnet to the body: W → 1/(ω_c² − ω²), undamped.
    amp, _ = elastic_damper_response(1.0, w, j, 1e6, kd, ly, b)
    assert_allclose(amp, 1 / abs(ly * b / j - w**2), rtol=1e-6)   # c/J = 7e3 against ω_c² ≈ 2e-5


# -- steady-state error (6.70)–(6.79), E47, E48, E50 --------------------------------------------
def test_error_factor_is_the_true_maximum():
    factor, u = polar_error_factor()
    grid = np.linspace(0, np.pi / 2, 200001)
    values = 6 * np.sin(2 * grid) / (1 + 3 * np.sin(grid) ** 2) ** 2.5
    # Grid spacing 8e-6 rad: the grid maximum is below the true one by < f''·h²/2 ≈ 1e-9.
    assert_allclose(factor, values.max(), atol=1e-9)
    assert_allclose(factor, 1.9030, atol=5e-5)
    assert_allclose(np.degrees(u), 15.90, atol=0.005)


def test_e50_printed_1_92_at_16_degrees():
    """Seed line 147: 'the maximum is reached at ω0t ≈ 16°', value 1.92."""
    _, u = polar_error_factor()
    assert_allclose(np.degrees(u), 16, atol=0.5)        # printed to the degree: agrees


@pytest.mark.xfail(strict=True, reason="the true maximum of 6 sin2u/(1+3sin²u)^(5/2) is 1.9030, "
                                       "0.017 below the printed 1.92 (half a unit: 0.005)")
def test_e50_printed_factor_1_92():
    assert_allclose(polar_error_factor()[0], 1.92, atol=0.005)


def test_disturbance_peak_reduces_to_the_closed_form_without_gravity():
    n, b0 = _orbit(1000e3)
    peak, u = polar_disturbance_peak(650.0, n, b0)
    factor, u_factor = polar_error_factor()
    # Two maximisations of the same function to 1e-12 rad: value to rounding.
    assert_allclose(peak, factor * n**2 * 650.0 / b0, rtol=1e-12)
    assert_allclose(u, u_factor, atol=1e-6)
    # And J|η̈|/B written with the Earth family's η̈ at the maximum.
    assert_allclose(peak, -650 * polar_field_direction_acceleration(u, n) / (b0 * np.sqrt(1 + 3 * np.sin(u) ** 2)),
                    rtol=1e-13)
    assert_allclose(steady_state_error_estimate(650.0, 500.0, n, b0),
                    steady_state_error_closed_form(650.0, 500.0, n, b0), rtol=1e-12)


def test_closed_form_does_not_depend_on_the_altitude():
    # ω0²/B0 = 4π GM/(μ0 M): the same angle at 700 and 1000 km, to rounding.
    assert_allclose(steady_state_error_closed_form(150.0, 120.0, *_orbit(700e3)),
                    steady_state_error_closed_form(150.0, 120.0, *_orbit(1000e3)), rtol=1e-12)


E47 = dict(inertia=650.0, moment=500.0, inertia_difference=650.0 - 250.0, altitude=1000e3)


def test_e47_computed():
    """E47 (seed line 147): J = 650 (transverse), 250 (axial), L = 500 A·m², h ≈ 1000 km."""
    n, b0 = _orbit(E47["altitude"])
    peak, u = polar_disturbance_peak(E47["inertia"], n, b0, E47["inertia_difference"])
    # Our numbers (Kovalenko's M = 8.1e22 A·m², R = 6371 km), to the digits reported.
    assert_allclose(peak, 84.10, atol=0.005)
    assert_allclose(np.degrees(u), 17.00, atol=0.005)
    assert_allclose(np.degrees(steady_state_error_estimate(E47["inertia"], E47["moment"], n, b0,
                                                           E47["inertia_difference"])), 9.68, atol=0.005)
    assert_allclose(np.sqrt(E47["moment"] * b0 / E47["inertia"]) / n, 3.954, atol=0.0005)


def test_e47_printed_82_at_20_degrees_is_the_value_at_20_not_the_peak():
    n, b0 = _orbit(E47["altitude"])
    u = np.radians(20.0)
    gravity = planar_gravity_torque(polar_field_direction_angle(u), n, E47["inertia_difference"])
    at_20 = (-E47["inertia"] * polar_field_direction_acceleration(u, n) + gravity) / polar_field_b(u, b0)
    assert_allclose(at_20, 82, atol=0.5)          # printed digits: agrees at u = 20°
    # The printed γ_max from the printed 82 by (6.75): arcsin(82/500) = 9.44°.
    assert_allclose(np.degrees(np.arcsin(82 / 500)), 9.44, atol=0.005)


@pytest.mark.xfail(strict=True, reason="the largest (Jη̈ + M_в)/B is 84.1 N·m/T at u = 17.0°, not 82 at 20° "
                                       "(82.3 is its value at 20°)")
def test_e47_printed_peak_82():
    n, b0 = _orbit(E47["altitude"])
    assert_allclose(polar_disturbance_peak(E47["inertia"], n, b0, E47["inertia_difference"])[0], 82, atol=0.5)


@pytest.mark.xfail(strict=True, reason="arcsin(82/500) = 9.44° and the true peak gives 9.68°; neither rounds "
                                       "to the printed 9.5° (half a unit 0.05°)")
def test_e47_printed_error_9_5_degrees():
    n, b0 = _orbit(E47["altitude"])
    value = steady_state_error_estimate(E47["inertia"], E47["moment"], n, b0, E47["inertia_difference"])
    assert_allclose(np.degrees(value), 9.5, atol=0.05)


@pytest.mark.xfail(strict=True, reason="ω_c/ω0 = √(L μ0 M/(4π J GM)) = 3.954 (altitude-free), 0.054 above "
                                       "the printed 3.9 (half a unit 0.05)")
def test_e47_printed_natural_frequency_3_9():
    n, b0 = _orbit(E47["altitude"])
    assert_allclose(np.sqrt(E47["moment"] * b0 / E47["inertia"]) / n, 3.9, atol=0.05)


def test_e48_computed():
    """E48 (seed line 150): h ≈ 800 km, L_y = 120 A·m², J = 150 kg·m², M_T = 3e-4 N·m."""
    n, b0 = _orbit(800e3)
    assert_allclose(np.degrees(steady_state_error_closed_form(150.0, 120.0, n, b0)), 6.72, atol=0.005)
    # (6.78) with L = L_y: 0.87°, against the printed 2.75° (not reproduced; inputs ambiguous).
    assert_allclose(np.degrees(steady_state_error_estimate(150.0, 120.0, n, b0, friction=3e-4)), 0.87, atol=0.005)


@pytest.mark.xfail(strict=True, reason="(6.74) gives 6.72° for J = 150, L = 120 at any altitude (ω0²/B0 is "
                                       "altitude-free); the printed 'about 6.5°' is 0.22° off (half a unit 0.05°)")
def test_e48_printed_6_5_degrees():
    n, b0 = _orbit(800e3)
    assert_allclose(np.degrees(steady_state_error_closed_form(150.0, 120.0, n, b0)), 6.5, atol=0.05)


@pytest.mark.xfail(strict=True, reason="(6.78) with L = L_y = 120, M_T = 3e-4 gives 0.87° at 800 km; the "
                                       "printed 2.75° is not reproduced")
def test_e48_printed_6_78_value():
    n, b0 = _orbit(800e3)
    value = steady_state_error_estimate(150.0, 120.0, n, b0, friction=3e-4)
    assert_allclose(np.degrees(value), 2.75, atol=0.005)


@pytest.mark.parametrize("call, match", [
    (lambda: orienting_dipole([0.0, 0.0, 0.0], [1.0, 0.0, 0.0], 1.0), "field"),
    (lambda: orienting_dipole([1.0, 0.0, 0.0], [0.0, 0.0, 0.0], 1.0), "axis"),
    (lambda: orienting_torque([1.0, 0.0, 0.0], [1.0, 0.0, 0.0], -1.0), "gain"),
    (lambda: dry_detumble_time(1.0, 1.0, 1.0, 2.0), "final_rate"),
    (lambda: steady_state_error_estimate(650.0, 10.0, *_orbit(1000e3)), "cannot hold"),
    (lambda: steady_state_error_closed_form(650.0, 1.0, *_orbit(1000e3)), "too small"),
    (lambda: polar_forcing_coefficients(1.0, 0.0, 1e-3, count=4, printed=True), "count"),
    (lambda: elastic_damper_response(1.0, 1e-3, 1.0, 1.0, 0.0, 1.0, 1e-5), "viscous"),
])
def test_bad_input_is_refused_by_name(call, match):
    with pytest.raises(ValueError, match=match):
        call()


def test_the_printed_values_used_here_are_the_data_files():
    """The printed numbers of E47, E48 and E50 asserted here, in tests/earth/test_polar_orbit.py and
    tests/sim/test_planar.py, as magbench/data/kovalenko/printed.csv
    records them (value and half-unit resolution)."""
    from magbench.io import load_printed

    printed = load_printed("kovalenko")
    used = {"kov-polar-eta1": (0.34, 0.005), "kov-polar-eta2": (0.075, 0.0005), "kov-polar-etaddot1": (1.36, 0.005),
            "kov-polar-etaddot2": (1.20, 0.005), "kov-polar-gravity1": (0.88, 0.005),
            "kov-polar-gravity2": (0.27, 0.005), "kov-polar-gravity3": (0.08, 0.005),
            "kov-polar-error-factor": (1.92, 0.005), "kov-polar-error-factor-angle": (16, 0.5),
            "kov-e47-disturbance-peak": (82, 0.5), "kov-e47-error-estimate": (9.5, 0.05),
            "kov-e47-natural-frequency": (3.9, 0.05), "kov-e48-error-674": (6.5, 0.05),
            "kov-e48-error-678": (2.75, 0.005), "kov-polar-etaddot-e1": (4.0, 0.05),
            "kov-polar-etaddot-e3": (5.8, 0.05), "kov-polar-etaddot-e5": (2.4, 0.05),
            "kov-e47-simulated-error": (17, 0.5), "kov-e47-simulated-angle": (40, 0.5)}
    for key, (value, resolution) in used.items():
        row = printed[key]
        assert (row.value_low, row.resolution) == (value, resolution), key


def test_forced_response_of_members_equals_one_call_each():
    """Magnets and dampers as member arrays (one per member): the same as one call each, the
    harmonics on the first axis."""
    moment, viscous = np.array([200.0, 500.0, 900.0]), np.array([0.1, 0.2, 0.4])
    amp, phase = polar_forced_response(650.0, moment, 2e-5, viscous, 1e-3, 400.0, count=4)
    assert amp.shape == phase.shape == (4, 3)
    for i in range(3):
        a, f = polar_forced_response(650.0, moment[i], 2e-5, viscous[i], 1e-3, 400.0, count=4)
        assert_allclose(amp[:, i], a, rtol=1e-15)
        assert_allclose(phase[:, i], f, rtol=1e-15)


def test_pointing_at_b_is_the_orienting_law():
    """(6.16) with p = B/B is (6.8) ("p replaces B"), for random fields and axes."""
    rng = np.random.default_rng(7)
    b, i0 = rng.normal(size=(200, 3)) * 2e-5, rng.normal(size=(200, 3))
    p = b / np.linalg.norm(b, axis=-1, keepdims=True)
    # 1e-12 relative: two groupings of the same products
    assert_allclose(pointing_dipole(b, i0, p, 1e-3), orienting_dipole(b, i0, 1e-3), rtol=1e-12, atol=1e-18)


def test_pointing_torque_never_increases_the_error():
    """The book (p. 130): the torque (6.17) "always tends to reduce the orientation error": its
    component along i0 × p (the turn of i0 toward p) is ≥ 0; it is (B·p)² − 2 cos ψ (B·p)(B·i0)
    + (B·i0)² ≥ (1 − |cos ψ|)((B·p)² + (B·i0)²) times a positive factor, so it vanishes only
    where B·p = B·i0 = 0. And the torque is across B, as every magnetic torque."""
    rng = np.random.default_rng(8)
    b, i0, p = rng.normal(size=(3, 1000, 3))
    torque = pointing_torque(b, i0, p, 1e-3)
    i0 /= np.linalg.norm(i0, axis=-1, keepdims=True)
    p /= np.linalg.norm(p, axis=-1, keepdims=True)
    assert np.all(np.sum(torque * np.cross(i0, p), axis=-1) >= 0)
    # 1e-15 N·m: rounding of torques of order 1e-3 N·m
    assert_allclose(np.sum(torque * b, axis=-1), 0.0, atol=1e-15)
    with pytest.raises(ValueError, match="direction must not contain a zero vector"):
        pointing_dipole(b[0], i0[0], [0.0, 0.0, 0.0], 1e-3)


def test_disturbance_ratio_peaks_where_the_peak_says():
    """The ratio along the orbit and its maximum (polar_disturbance_peak) are one function:
    on a fine grid the ratio's largest value is the peak to the grid's resolution."""
    from magbench.control import polar_disturbance_ratio

    u = np.linspace(0.0, np.pi / 2, 200001)
    ratio = polar_disturbance_ratio(u, 650.0, 1e-3, 2e-5, 400.0)
    peak, where = polar_disturbance_peak(650.0, 1e-3, 2e-5, 400.0)
    # 1e-9 relative: the grid step 8e-6 rad off a smooth maximum changes the value by ~1e-11
    assert_allclose(ratio.max(), peak, rtol=1e-9)
    assert_allclose(u[np.argmax(ratio)], where, atol=1e-5)
