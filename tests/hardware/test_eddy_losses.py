"""Eddy losses of a rod and of a shell round it (Kovalenko 1975 §12.1, (12.2)–(12.9), (12.33),
(12.35)) against direct integration of the ring losses, and the book's printed numbers: α ≈ 0.288,
the coefficient 1.04·10⁻² and E44's ratio (1.4–2.8)·10⁻²."""

import numpy as np
import pytest
from numpy.testing import assert_allclose

from magbench import hardware
from magbench.constants import MU_0
from magbench.io import load_printed

PRINTED = load_printed("kovalenko")
COPPER = PRINTED["kovalenko-eddy-shell-resistivity"].value          # Ω·m, ρ_м (seed line 229)
PERMALLOY = (PRINTED["kovalenko-eddy-rod-resistivity"].value_low * 1.0,
             PRINTED["kovalenko-eddy-rod-resistivity"].value_high * 1.0)   # Ω·m ("ohm m" is SI)
C_PRINTED = PRINTED["kovalenko-eddy-parabola-c"].value
GAUSS = np.polynomial.legendre.leggauss(30)


def _integrate(f, low, high):
    x, w = GAUSS
    mid, half = (low + high) / 2, (high - low) / 2
    return np.sum(w * f(mid + half * x)) * half


def _ring_power(ring_radii, flux_radius, d_rod, length, rho, b_rate, c):
    """(12.2)–(12.3) summed ring by ring: a ring of radius y, section dx dy at x links the flux
    π min(y, d/2)² Ḃ_x and has resistance ρ 2πy/(dx dy); Ḃ_x follows the parabola (12.4)."""
    def per_x(x):
        bx = b_rate * (1 - c * (2 * x / length) ** 2)
        return np.array([_integrate(lambda y: (np.pi * flux_radius(y) ** 2 * b) ** 2 / (rho * 2 * np.pi * y),
                                    *ring_radii) for b in np.atleast_1d(bx)])
    return _integrate(per_x, -length / 2, length / 2)


def test_alpha_is_half_the_mean_square_of_the_axial_profile():
    for c in (0.0, 0.5, 0.85, 1.0):
        mean_square = _integrate(lambda u: (1 - c * u ** 2) ** 2, -1.0, 1.0) / 2
        # Gauss–Legendre with 30 nodes is exact for this quartic: rounding only
        assert_allclose(hardware.rod_eddy_profile_coefficient(c), mean_square / 2, rtol=1e-14)


def test_alpha_at_the_book_s_c_is_0_2889():
    assert hardware.rod_eddy_profile_coefficient(0.85) == pytest.approx(0.288917, abs=5e-7)


@pytest.mark.xfail(strict=True, reason="Kovalenko prints α ≈ 0,288 (seed line 222); ½ − c/3 + c²/10 at "
                   "his c = 0.85 is 0.28892, which rounds to 0.289: the printed value is truncated "
                   "(last-digit rounding, no downstream effect: 1.04·10⁻² holds with either)")
def test_alpha_printed_0_288_within_half_its_last_digit():
    row = PRINTED["kovalenko-eddy-alpha"]
    assert abs(hardware.rod_eddy_profile_coefficient(C_PRINTED) - row.value) <= row.resolution


def test_the_rod_loss_is_the_sum_of_its_ring_losses():
    d, l, rho, rate = 2.8e-3, 1.14, 0.6e-6, 0.01
    direct = _ring_power((0.0, d / 2), lambda y: y, d, l, rho, rate, 0.85)
    v = np.pi * d ** 2 * l / 4
    # Gauss–Legendre, 30 nodes on polynomials (y³; a quartic in x): exact to rounding
    assert_allclose(hardware.rod_eddy_power(v, d, rho, rate, 0.85), direct, rtol=1e-12)


def test_the_mean_torque_is_the_mean_loss_over_the_rate():
    v, d, rho, w, b0 = 7e-6, 2.8e-3, 0.6e-6, 0.002, 0.5
    t = np.linspace(0, 2 * np.pi / w, 64, endpoint=False)
    power = hardware.rod_eddy_power(v, d, rho, w * b0 * np.cos(w * t))  # Ḃ of B0 sin ωt (12.6)
    # equally spaced samples over whole periods average cos² exactly
    assert_allclose(hardware.rod_eddy_torque(v, d, rho, w, b0), power.mean() / w, rtol=1e-13)


def test_the_ideal_rod_coefficient_is_the_printed_1_04e_2():
    alpha = hardware.rod_eddy_profile_coefficient(C_PRINTED)
    coefficient = alpha / (32 * 0.93 ** 2)
    row = PRINTED["kovalenko-eddy-ideal-rod-coefficient"]    # printed "1,04" (seed line 223)
    assert abs(coefficient - row.value) <= row.resolution
    v, d, rho, w, h0, p = 7e-6, 2.8e-3, 0.6e-6, 0.002, 24.0, 400.0
    assert_allclose(hardware.rod_eddy_torque_from_field(v, d, rho, w, h0, p),
                    coefficient * v * d ** 2 * w * MU_0 ** 2 * h0 ** 2 * p ** 3.4 / rho, rtol=1e-12)


def test_the_shell_loss_is_the_sum_of_its_ring_losses_with_the_rod_s_flux():
    d, big, l, rho, rate = 2.8e-3, 4.0e-3, 1.14, COPPER, 0.01
    direct = _ring_power((d / 2, big / 2), lambda y: d / 2, d, l, rho, rate, 0.85)
    v = np.pi * d ** 2 * l / 4
    w = 0.002
    # mean over B0 sin ωt: ⟨Ḃ²⟩ = ω²B0²/2 with rate = ωB0; 1/y on [0.7, 1] mm: Gauss 30 nodes ~1e-15
    assert_allclose(hardware.shell_eddy_torque(v, d, big, rho, w, rate / w), direct / 2 / w, rtol=1e-12)


@pytest.mark.parametrize("end", ["low", "high"])
def test_e44_rod_to_shell_ratio_reproduces_the_printed_range(end):
    """E44 (seed lines 228–229): V_c = V_к, D = √2 d, ρ_м = 0.0175·10⁻⁶, ρ_c = (0.45–0.9)·10⁻⁶;
    the low ratio comes with the high resistivity."""
    row = PRINTED["kovalenko-eddy-rod-shell-ratio"]
    rho_c, printed = (PERMALLOY[1], row.value_low) if end == "low" else (PERMALLOY[0], row.value_high)
    ratio = hardware.rod_to_shell_eddy_ratio(rho_c, COPPER, np.sqrt(2))
    assert abs(ratio - printed) <= row.resolution           # half a unit of the printed 1.4 / 2.8 (·10⁻²)
    d, l = 2.8e-3, 1.14
    v = np.pi * d ** 2 * l / 4
    v_shell = np.pi * (2 * d ** 2 - d ** 2) * l / 4
    assert_allclose(v_shell, v, rtol=1e-15)                # the example's V_c = V_к
    by_torques = hardware.rod_eddy_torque(v, d, rho_c, 0.002, 0.5) / hardware.shell_eddy_torque(
        v, d, np.sqrt(2) * d, COPPER, 0.002, 0.5)
    assert_allclose(by_torques, ratio, rtol=1e-13)


def test_the_winding_parameter_does_not_depend_on_the_number_of_turns():
    w, d, big, rho, kz, l = 0.002, 2.8e-3, 4.0e-3, COPPER, 0.7, 1.14
    for turns in (10, 1000):
        inductance = MU_0 * turns ** 2 * np.pi * d ** 2 / (4 * l)                  # (12.25)
        resistance = rho * np.pi * turns ** 2 * (big + d) / (l * (big - d) * kz)   # (12.32)
        assert_allclose(hardware.winding_parameter(w, d, big, rho, kz), w * inductance / resistance, rtol=1e-14)


@pytest.mark.parametrize("call, name", [
    (lambda: hardware.rod_eddy_profile_coefficient(1.5), "parabola_coefficient"),
    (lambda: hardware.rod_eddy_power(-1.0, 1e-3, 1e-6, 0.1), "volume"),
    (lambda: hardware.rod_eddy_torque(1e-6, 1e-3, 1e-6, -0.1, 0.5), "rate"),
    (lambda: hardware.shell_eddy_torque(1e-6, 2e-3, 1e-3, COPPER, 0.1, 0.5), "outer_diameter"),
    (lambda: hardware.rod_to_shell_eddy_ratio(0.5e-6, COPPER, 1.0), "diameter_ratio"),
    (lambda: hardware.winding_parameter(0.1, 1e-3, 2e-3, COPPER, 0.0), "fill_factor"),
    (lambda: hardware.rod_eddy_torque_from_field(1e-6, 1e-3, 1e-6, 0.1, 24.0, 5.0), "elongation"),
])
def test_bad_input_names_the_parameter(call, name):
    with pytest.raises(ValueError, match=name):
        call()


def test_the_winding_torque_peaks_at_a0_equal_n_over_k_with_the_value_of_12_31():
    v, h0, n, k = 7e-6, 24.0, 0.79e-4, 0.72
    a = np.geomspace(1e-6, 1e-2, 20001)
    m = hardware.winding_damping_torque(v, h0, n, a, k)
    # the grid's spacing is 0.05 %: the peak's place to that, its value to second order
    assert_allclose(a[np.argmax(m)], n / k, rtol=1e-3)
    assert_allclose(hardware.winding_damping_torque(v, h0, n, n / k, k), k * v * MU_0 * h0 ** 2 / (4 * n), rtol=1e-14)


def test_e45_transit_winding_beats_hysteresis_several_times():
    """E45 (seed line 229): Transit rods, p = 248, H₀ = 0.3 Oe ≈ 24 A/m, (∮HdB)_ц ≈ 3.6 T·A/m,
    N_ц ≈ 0.79·10⁻⁴. The book's ratio M*max/M_Г = πμ0H₀²/(2N_ц(∮HdB)_ц) is lost in the OCR;
    it says only "several times". With (12.31) and (12.1) at k = k_φ it is 4.0."""
    h0 = PRINTED["kov-transit-field-si"].value
    loop = PRINTED["kov-transit-loop-si"].value
    n = PRINTED["kov-transit-rod-demag"].value
    v, k = 7e-6, 0.72
    winding = hardware.winding_damping_torque(v, h0, n, n / k, k)
    hysteresis = hardware.hysteresis_damping_torque(v, loop, k)      # (12.1): k_φ V ∮HdB/(2π)
    assert_allclose(winding / hysteresis, np.pi * MU_0 * h0 ** 2 / (2 * n * loop), rtol=1e-13)
    assert round(float(winding / hysteresis), 1) == 4.0
