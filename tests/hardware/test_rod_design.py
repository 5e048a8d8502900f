"""Hysteresis-rod design (Kovalenko 1975 §12.2): the rod count from (12.1), the body's central loop by
the demagnetising shear (Figs. 12.3–12.4) against a direct self-consistent simulation, the optimal
elongation (Fig. 12.6), and the mutual demagnetisation of parallel rods (E47b, Fig. 12.9) against
its closed-form limits and the measured points."""

import numpy as np
import pytest
from numpy.testing import assert_allclose
from scipy import integrate

from magbench import hardware
from magbench.constants import MU_0
from magbench.hardware import kernels, rod_design
from magbench.io import load_printed

PRINTED = load_printed("kovalenko")
#: A material (not a rod's apparent) Flatley–Henretty loop: Hc 12 A/m, Br 0.35 T, Bs 0.7 T (the
#: hysteresis module's example; ours, for the shear's checks only).
MATERIAL = (12.0, 0.35, 0.7)
#: E47b: the mumetal rods and the four measured points (seed line 239).
ROD_LENGTH = PRINTED["kov-rod-pair-rod-length"].value
ROD_DIAMETER = PRINTED["kov-rod-pair-rod-diameter"].value
GAPS = np.array([PRINTED[f"kov-rod-pair-gap-{i}"].value for i in range(1, 5)])
MEASURED = np.array([PRINTED[f"kov-rod-pair-ratio-{i}"].value for i in range(1, 5)])


# -- the rod count (12.1), p. 235 ------------------------------------------------------------------

def test_volume_required_inverts_kovalenko_12_1():
    torque = np.array([1e-7, 4e-6, 2e-5])
    volume = hardware.rod_volume_required(torque, 3.6, 0.72)
    # (12.1) forward gives the torque back: a product and a quotient, rounding only
    assert_allclose(hardware.hysteresis_damping_torque(volume, 3.6, 0.72), torque, rtol=1e-14)


def test_rod_count_is_the_least_whole_number_that_suffices():
    w, v = 3.6, 1e-6
    one_rod = float(hardware.hysteresis_damping_torque(v, w, 0.72))
    counts = hardware.rod_count_required(np.array([0.0, 1.0, 2.0, 2.001, 7.5]) * one_rod, v, w, 0.72)
    assert counts.tolist() == [0, 1, 2, 3, 8]
    assert counts.dtype.kind == "i"


@pytest.mark.parametrize("bad, name", [
    (dict(torque=-1.0), "torque"), (dict(rod_volume=0.0), "rod_volume"), (dict(loop_energy=0.0), "loop_energy"),
    (dict(averaging_factor=np.nan), "averaging_factor")])
def test_rod_count_refuses_bad_input(bad, name):
    args = dict(torque=1e-6, rod_volume=1e-6, loop_energy=3.6, averaging_factor=0.72) | bad
    with pytest.raises(ValueError, match=name):
        hardware.rod_count_required(**args)


def test_despin_torque_is_the_momentum_lost_over_the_time():
    assert_allclose(hardware.despin_torque_required(0.0936, 522.0 * 3600.0, 0.017),
                    (0.0936 - 0.017) / (522.0 * 3600.0), rtol=1e-15)  # one subtraction and one division
    with pytest.raises(ValueError, match="final_momentum"):
        hardware.despin_torque_required(0.01, 10.0, 0.02)


# -- the body's loop from the material's: Figs. 12.3–12.4 -------------------------------------------

def test_without_demagnetisation_the_body_loop_is_the_material_loop():
    h0 = np.array([6.0, 30.0, 200.0])
    w, central = hardware.rod_central_loop_energy(h0, 0.0, *MATERIAL)
    assert np.all(central <= h0)
    # the central amplitude is H0 up to exp(log(H0)) rounding (a few ulp), so the areas agree as closely
    assert_allclose(central, h0, rtol=1e-13)
    assert_allclose(w, hardware.rod_cycle_energy(h0, *MATERIAL), rtol=1e-10)


def test_the_central_amplitude_satisfies_the_shear_line():
    h0 = np.array([3.0, 24.0, 100.0, 400.0])
    n = hardware.rod_demagnetizing_factor(np.array([[50.0], [100.0], [248.0], [500.0]]))   # rows: rods
    _, central = hardware.rod_central_loop_energy(h0, n, *MATERIAL)
    _, b = hardware.settled_hysteresis_loop(central, *MATERIAL)
    # H_ц + N_ц B_ц/μ0 = H0 (Fig. 12.4's construction); interpolation and one Newton step leave
    # residuals up to 1.8e-6 H0 (measured, p = 20–500), held to 1e-5
    assert_allclose(central + n * b.max(axis=-1) / MU_0, np.broadcast_to(h0, central.shape), rtol=1e-5)


def test_the_loss_falls_with_the_demagnetising_factor():
    n = hardware.rod_demagnetizing_factor(np.array([500.0, 248.0, 100.0, 50.0, 20.0]))
    w, central = hardware.rod_central_loop_energy(24.0, n, *MATERIAL)
    assert np.all(np.diff(w) < 0) and np.all(np.diff(central) < 0)


def _self_consistent_body_loop(h0, n, cycles=3, per_cycle=3000):
    """The rod as a body: dB/dφ with H = H0 sin φ − N B/μ0 inside, the material's Flatley–Henretty
    slope s: dB = s dH, dH = dH0 − (N/μ0) dB, so dB/dφ = s H0 cos φ/(1 + sN/μ0). Returns the
    last cycle's ∮H0 dB (= ∮H dB, the shear term closing to zero) and the largest inner H."""
    hc, _, bs, k = hardware.limb_constants(*MATERIAL)
    dphi = 2.0 * np.pi / per_cycle

    def rate(phi, b):
        drive = h0 * np.cos(phi)
        s = kernels.hysteresis_slope(b, h0 * np.sin(phi) - n * b / MU_0, np.sign(drive), hc, bs, k)
        return s * drive / (1.0 + s * n / MU_0)

    b, path = np.zeros(np.shape(h0)), []
    for i in range(cycles * per_cycle + 1):
        path.append(b)
        phi = i * dphi
        k1 = rate(phi, b)
        k2 = rate(phi + dphi / 2, b + dphi / 2 * k1)
        k3 = rate(phi + dphi / 2, b + dphi / 2 * k2)
        k4 = rate(phi + dphi, b + dphi * k3)
        b = b + dphi / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
    last = np.array(path[-per_cycle - 1:])
    outer = h0 * np.sin(np.arange(cycles * per_cycle - per_cycle, cycles * per_cycle + 1) * dphi)[:, None]
    energy = np.sum(0.5 * (outer[1:] + outer[:-1]) * np.diff(last, axis=0), axis=0)
    return energy, np.max(outer - n * last / MU_0, axis=0)


def test_the_shear_gives_the_loss_of_the_self_consistent_body():
    # Kovalenko p. 230: the body's central loop is the material's, sheared by N_ц B/μ0, of equal
    # area. Integrated directly, the body with its own demagnetising field loses the same. Above Hc
    # only: below it the Flatley–Henretty loop still creeps after three cycles (its tip moves 3 %
    # from the 3rd to the 8th cycle at 6 A/m), and the two paths creep differently.
    h0, n = np.array([100.0, 300.0]), float(hardware.rod_demagnetizing_factor(100.0))
    direct, direct_central = _self_consistent_body_loop(h0, n)
    w, central = hardware.rod_central_loop_energy(h0, n, *MATERIAL)
    assert np.all(central > MATERIAL[0])
    # measured: 3.4e-5 in H_ц and 1.5e-4 in the area, the same with 12 000 steps a cycle (so from
    # the library's side: the trapezoid over 720 samples of its settled loop); held to about 3x
    assert_allclose(central, direct_central, rtol=1e-4)
    assert_allclose(w, direct, rtol=5e-4)


def test_the_optimal_elongation_falls_as_the_field_grows():
    # Kovalenko p. 233: "p0 depends on the magnetising field"; a stronger field saturates a
    # thicker rod, so the optimum moves to thicker rods
    p0 = [hardware.rod_optimal_elongation(h, *MATERIAL)[0] for h in (5.0, 24.0, 100.0)]
    assert p0[0] > p0[1] > p0[2]
    with pytest.raises(ValueError, match="outside elongations"):
        hardware.rod_optimal_elongation(24.0, *MATERIAL, elongations=[10.0, 11.0, 12.0])


# -- two parallel rods: E47b, Fig. 12.9 ---------------------------------------------------------------

def test_prolate_factor_matches_osborn():
    # Osborn (1945): a sphere 1/3; a/b = 2 gives 0.1736 (his Table I, 4 digits)
    # near the sphere the factor moves as (p − 1) (1e-6 here, held to 1e-5); 0.1736 is rounded to 4 digits
    assert_allclose(hardware.prolate_demagnetizing_factor(1.0 + 1e-6), 1.0 / 3.0, rtol=1e-5)
    assert_allclose(hardware.prolate_demagnetizing_factor(2.0), 0.1736, atol=5e-5)
    with pytest.raises(ValueError, match="elongation"):
        hardware.prolate_demagnetizing_factor(1.0)


def test_the_closed_form_is_the_line_charge_integral():
    for u in (0.01, 0.3, 1.0, 4.0):
        numeric, _ = integrate.dblquad(lambda y, x: x * y / np.sqrt(u * u + (x - y) ** 2), -1, 1, -1, 1,
                                       epsabs=1e-13)
        # adaptive quadrature to 1e-13 absolute; the closed form cancels terms of order 1
        assert_allclose(rod_design._line_pair_integral(u), numeric, rtol=1e-9, atol=1e-12)


def test_far_apart_the_rods_are_two_dipoles():
    l, d = ROD_LENGTH, ROD_DIAMETER
    volume = np.pi * d * d * l / 6.0
    s = np.array([30.0, 100.0]) * l
    # the next term of the expansion is O((l/s)²): 2e-4 at s = 30 l (measured), 2e-5 at 100 l
    ratio = hardware.parallel_rod_mutual_factor(s, l, d) / (volume / (4 * np.pi * s**3))
    assert_allclose(ratio, 1.0, rtol=5e-4)
    assert abs(ratio[1] - 1.0) < 5e-5
    assert_allclose(hardware.parallel_rod_demagnetizing_ratio(1e3 * l, l, d), 1.0, atol=1e-5)


@pytest.mark.parametrize("p", [300.0, 1e4])
def test_coincident_rods_give_the_exact_spheroid_values(p):
    # Each spheroid's charge sits on its surface at radius ρ(z) = b(1 − z²/a²)^½; weighted as the
    # charge (∝ z²), ⟨ln ρ⟩ = ln b + ln 2 − 4/3, i.e. a line sees itself at d·e^(−4/3). There the
    # two-line kernel must give one spheroid's own factor (two coincident rods: ratio 2), and at
    # twice that, 2d·e^(−4/3), one spheroid of twice the section (the merged rod: N(p/√2)/N(p)).
    # The kernel's expansion is exact to O(s/l) and N0's to O(1/p²): 5e-4 at p = 300, 1e-5 at 1e4.
    l, d = 0.6, 0.6 / p
    n0 = hardware.prolate_demagnetizing_factor(p)
    tolerance = 1e-3 if p < 1e3 else 2e-5
    assert_allclose(rod_design._mutual_factor(d * np.exp(-4 / 3), l, d) / n0, 1.0, rtol=tolerance)
    assert_allclose(1 + rod_design._mutual_factor(2 * d * np.exp(-4 / 3), l, d) / n0,
                    hardware.prolate_demagnetizing_factor(p / np.sqrt(2)) / n0, rtol=tolerance)


def test_touching_rods_lie_between_one_and_the_merged_rod():
    p = PRINTED["kov-rod-pair-theory-elongation"].value
    d = PRINTED["kov-rod-pair-theory-diameter"].value
    contact = float(hardware.parallel_rod_demagnetizing_ratio(d, p * d, d))
    merged = float(hardware.prolate_demagnetizing_factor(p / np.sqrt(2)) / hardware.prolate_demagnetizing_factor(p))
    assert 1.0 < contact < merged        # 1.755 < 1.872: two touching rods spread the section more
    with pytest.raises(ValueError, match="separation"):
        hardware.parallel_rod_demagnetizing_ratio(0.5 * d, p * d, d)


def test_the_text_estimate_for_coincident_rods():
    # Kovalenko p. 238: N ∝ p^−1.7 (9.25) and p → p/√2 give (√2)^1.7 = 2^0.85 = 1.8025, "≈ 1,8"
    row = PRINTED["kov-rod-pair-coincident-estimate"]
    estimate = hardware.rod_demagnetizing_factor(200.0 / np.sqrt(2)) / hardware.rod_demagnetizing_factor(200.0)
    assert abs(estimate - row.value) <= row.resolution


@pytest.mark.xfail(strict=True, reason=(
    "The text's (√2)^1.7 = 1.80 is not the coincident limit of the book's own theory (spheroids, "
    "p = 300, Fig. 12.9): merging two spheroids into one of twice the section gives "
    "N(p/√2)/N(p) = 1.872 (Osborn's exact factor), 0.072 above the printed 1.8 (resolution 0.05). "
    "The power law 0.93 p^-1.7 is a fit for cylinders of p ≤ 250 and understates how N grows as p falls."))
def test_the_text_estimate_is_the_spheroid_theory_coincident_limit():
    row = PRINTED["kov-rod-pair-coincident-estimate"]
    p = PRINTED["kov-rod-pair-theory-elongation"].value
    exact = hardware.prolate_demagnetizing_factor(p / np.sqrt(2)) / hardware.prolate_demagnetizing_factor(p)
    assert abs(exact - row.value) <= row.resolution


def test_the_reconstruction_follows_the_measured_points():
    # E47b: mumetal cylinders 3 mm × 600 mm (p = 200), Δ read as the distance between the axes.
    # Spheroids of the same l/d give 1.736, 1.502, 1.301, 1.158 against 1.815, 1.605, 1.325, 1.15:
    # −6.4 % at worst (Δ = 10 mm). 7 %: the model's rods are spheroids kept uniformly magnetised,
    # the measured ones soft cylinders, whose charge gathers toward the ends (closer ends interact
    # more strongly at small gaps); the measured curve is read from a figure of ref. [55].
    model = hardware.parallel_rod_demagnetizing_ratio(GAPS, ROD_LENGTH, ROD_DIAMETER)
    assert_allclose(model, MEASURED, rtol=0.07)
    assert np.all(np.diff(model) < 0)


def test_reading_delta_as_the_gap_fits_worse():
    # The other reading (Δ the gap, axes Δ + d apart) misses the touching point by 12 %: the axes
    # reading is the one the tests use.
    gap = hardware.parallel_rod_demagnetizing_ratio(GAPS + ROD_DIAMETER, ROD_LENGTH, ROD_DIAMETER)
    axes = hardware.parallel_rod_demagnetizing_ratio(GAPS, ROD_LENGTH, ROD_DIAMETER)
    assert np.max(np.abs(gap / MEASURED - 1)) > np.max(np.abs(axes / MEASURED - 1))


# -- TNS-0 (chapter 7's satellite) by Kovalenko's procedure -----------------------------------------

def test_kovalenko_volume_for_tns0_is_below_the_calibrated_one():
    """Worked computation for chapter 8: the torque is Fig. 14's slope (4.10e-8 N·m); each rod seen
    by Kovalenko as turning in the full orbit-mean field (27.8 A/m). With chapter 7's own rod loop
    (apparent Flatley–Henretty constants, a body's loop: N_ц = 0, k_φ = 1) the procedure gives
    1.38e-6 m³ in all, 3.2 times less than the 4.40e-6 m³ chapter 7 calibrates: in TNS-0's flat
    spin each rod sees only part of the field across L (the balance implies an effective amplitude
    of 16.9 A/m, 0.61 of the mean). With the Transit rods' loop (3.6 J/m³ at 24 A/m, k_φ = 0.72) it
    gives 9.98e-8 m³: a loop 19 times larger per cycle needs that much less."""
    from magbench.chapters.ch07_tns0 import decay_balance, decay_fits, tns0_orbit
    from magbench.params import chapter_parameters

    p = chapter_parameters("ch07")
    torque = -decay_fits()[2].parameters["slope"] / 3600.0
    calibrated_total = 2.0 * decay_balance(p)["calibrated_volume"]
    orbit = tns0_orbit(p)
    field = np.mean(np.linalg.norm(orbit.field(np.linspace(0.0, orbit.period, 720, endpoint=False)), axis=-1)) / MU_0
    own, _ = hardware.rod_central_loop_energy(field, 0.0, p["rod_coercivity"], p["rod_remanence"],
                                              p["rod_saturation"])
    own_volume = hardware.rod_volume_required(torque, own)
    transit_volume = hardware.rod_volume_required(torque, p["transit_loop_energy"], 0.72)
    assert torque > 0
    assert transit_volume < own_volume < calibrated_total


# -- the Rayleigh region: (12.36), (12.37), (12.40) -------------------------------------------------

def _rayleigh_torque_over_length_cubed(p, mu=2300.0):
    # (12.1) with V = πl³/(4p²) and (12.40) at N = 0.93 p^−1.7 (9.25); a and H0 scale it only
    n = hardware.rod_demagnetizing_factor(p)
    return hardware.rayleigh_central_loop_energy(1.0, n, 1e-3, mu) / (8.0 * p * p)


def test_the_rayleigh_optimum_is_where_n_mu_is_two_over_3n_minus_2():
    from scipy.optimize import minimize_scalar

    mu = 2300.0     # μ_нач of 50Н tape, ГОСТ 10160-62 (Kovalenko p. 231)
    best = minimize_scalar(lambda lp: -_rayleigh_torque_over_length_cubed(np.exp(lp), mu),
                           bounds=(np.log(10), np.log(5e3)), method="bounded", options={"xatol": 1e-10})
    n_opt = float(hardware.rod_demagnetizing_factor(np.exp(best.x)))
    # the optimiser's tolerance in ln p (1e-10) moves N by 1.7e-10 relative; 1e-6 leaves room for its stopping rule
    assert_allclose(n_opt, hardware.rayleigh_optimal_demagnetizing_factor(mu), rtol=1e-6)


def test_the_book_optimal_loss_coefficient_is_12_40_at_half_the_field():
    # (12.37)'s 0.167 a H0³ is (12.40) at N μ_нач = 1, H_ц = H0/2: (4/3)/8 = 1/6 (μ0 for SI)
    row = PRINTED["kov-rayleigh-optimal-loss-coefficient"]
    mu = 2300.0
    coefficient = hardware.rayleigh_central_loop_energy(1.0, 1.0 / mu, 1.0, mu) / MU_0
    assert abs(coefficient - row.value) <= row.resolution


@pytest.mark.xfail(strict=True, reason=(
    "Kovalenko's (12.36), read as N_ц.0 = 1/μ_нач (the numerator is lost in the OCR; (12.37)'s 0.167 "
    "fits 1), is not the optimum of (12.1) with (12.40) at a fixed length: with N = 0.93 p^-1.7 the torque "
    "p^-2 (1 + N μ)^-3 peaks at N μ = 2/(3·1.7 − 2) = 0.645; at N μ = 1 it is 7 % lower. The book "
    "quotes (12.36) from his refs. [31, 54, 55], whose assumptions may differ."))
def test_the_book_rayleigh_optimum_n_mu_is_one():
    assert_allclose(hardware.rayleigh_optimal_demagnetizing_factor(2300.0) * 2300.0, 1.0, rtol=0.05)


def test_at_n_mu_one_the_torque_is_seven_percent_below_the_optimum():
    mu = 2300.0
    p_book = (0.93 * mu) ** (1 / 1.7)                                        # N μ = 1
    p_best = (0.93 * mu / (2 / 3.1)) ** (1 / 1.7)                            # N μ = 2/3.1
    loss = 1 - _rayleigh_torque_over_length_cubed(p_book, mu) / _rayleigh_torque_over_length_cubed(p_best, mu)
    # closed form 1 − (1/0.645)^(2/1.7) (1.645/2)³ = 0.0686; rounding only
    assert_allclose(loss, 1 - (3.1 / 2) ** (2 / 1.7) * ((1 + 2 / 3.1) / 2) ** 3, rtol=1e-12)
    assert 0.06 < loss < 0.08
