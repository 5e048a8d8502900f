"""Hysteresis rods: the Flatley–Henretty loop's energy identities and Kovalenko's (12.1)."""

import numpy as np
import pytest
from numpy.testing import assert_allclose

from magbench.hardware import (hysteresis_damping_torque, hysteresis_loop_energy, hysteresis_response,
                               hysteresis_slope, limb_induction, limiting_loop_energy, rod_cycle_energy,
                               rod_demagnetizing_factor)
from magbench.units import oersted_to_ampere_per_meter

ROD = (12.0, 0.004, 0.025)  # apparent HyMu-80 rod values (Gerhardt & Palo 2010)


def test_limbs_pass_through_coercivity_and_remanence():
    hc, br, bs = ROD
    assert_allclose(limb_induction([hc, 0.0], *ROD), [0.0, -br], atol=1e-15)  # definition of k
    assert_allclose(limb_induction([-hc, 0.0], *ROD, ascending=False), [0.0, br], atol=1e-15)


def test_the_ascending_limb_is_invariant():
    hc, br, bs = ROD
    h = np.linspace(-50.0, 400.0, 901)
    b = hysteresis_response(h, *ROD, initial_induction=float(limb_induction(h[0], *ROD)))
    assert_allclose(b, limb_induction(h, *ROD), atol=1e-9)  # RK4 in H, sub-steps Hc/50


def test_loop_energy_of_an_ellipse_is_kovalenko_12_20():
    # Kovalenko (1975) eq. (12.20): B = B0 sin(t − δ) lagging H = H0 sin t has ∮H dB = π H0 B0 sin δ.
    t = np.linspace(0.0, 2 * np.pi, 4001)[:-1]
    h0, b0, delta = 24.0, 0.3, 0.2
    energy = hysteresis_loop_energy(h0 * np.sin(t), b0 * np.sin(t - delta))
    assert_allclose(energy, np.pi * h0 * b0 * np.sin(delta), rtol=1e-6)  # trapezoid on 4000 points: O(h²)


def test_large_amplitude_loop_is_the_area_between_the_limbs():
    hc, br, bs = ROD
    ha = np.array([240.0, 1200.0])
    ratio = rod_cycle_energy(ha, *ROD) / limiting_loop_energy(ha, *ROD)
    # The settled loop leaves the limbs only near its tips, a share that falls as Ha grows
    # (1.0 % below at 240 A/m, 0.04 % at 1200 A/m): the bound tightens with the amplitude.
    assert np.all(ratio < 1.0)
    assert_allclose(ratio, 1.0, rtol=0.015)
    assert 1.0 - ratio[1] < 0.1 * (1.0 - ratio[0])
    assert_allclose(limiting_loop_energy(1e9, *ROD), 4 * bs * hc, rtol=1e-6)  # (4Bs/πk)(π/2)(2kHc) limit


def test_reference_loop_energies():
    # shared reference §2: 0.0228, 0.0895, 0.217, 0.565, 0.874, 1.042, 1.170 J/m³ (three digits).
    ha = np.array([12.0, 20.0, 30.0, 60.0, 120.0, 240.0, 1200.0])
    assert_allclose(rod_cycle_energy(ha, *ROD), [0.0228, 0.0895, 0.217, 0.565, 0.874, 1.042, 1.170], rtol=3e-3)


def test_small_amplitude_cubic_law():
    ha = np.array([0.5, 1.0, 2.0])
    w = rod_cycle_energy(ha, *ROD)
    slopes = np.diff(np.log(w)) / np.diff(np.log(ha))
    # Rayleigh region (Kovalenko eq. 12.40): W ∝ Ha³; the next term is O(Ha/Hc) ≈ 4–17 %.
    assert_allclose(slopes, 3.0, atol=0.05)


def test_work_per_cycle_is_v_loop_integral_for_a_turning_rod():
    # A rod turning uniformly in a field H0: H = H0 cos φ along it, one cycle per revolution;
    # the energy the induction rate takes from the field equals ∮H dB (Warburg).
    h0 = 30.0
    phi = np.linspace(0.0, 3 * 2 * np.pi, 3 * 2000 + 1)
    h = h0 * np.cos(phi)
    b = hysteresis_response(h, *ROD)
    last = slice(4000, 6001)
    work = np.trapezoid(h[last], b[last])
    assert_allclose(work, rod_cycle_energy(h0, *ROD), rtol=2e-3)  # sine vs cosine start, 2000 vs 720 samples


def test_slope_and_rate():
    slope, rate = hysteresis_slope(0.0, 12.0, 5.0, *ROD)
    # On the ascending limb at B = 0 (H = Hc) the slope is the limb's: (2Bs/π) k.
    hc, br, bs = ROD
    k = np.tan(np.pi * br / (2 * bs)) / hc
    assert_allclose(slope, 2 * bs / np.pi * k, rtol=1e-12)  # closed form
    assert_allclose(rate, 5.0 * slope, rtol=1e-15)
    with pytest.raises(ValueError, match="induction must lie in"):
        hysteresis_slope(0.03, 0.0, 1.0, *ROD)


def test_kovalenko_transit_rods():
    # Kovalenko (1975) p. 229: 450 G·Oe ≈ 3.6 T·A/m; H0 = 0.3 Oe ≈ 24 A/m; p = 248, N_ц ≈ 0.79e-4.
    assert_allclose(450 * 1e-4 * oersted_to_ampere_per_meter(1.0), 3.6, atol=0.05)  # printed to two digits
    assert_allclose(oersted_to_ampere_per_meter(0.3), 24.0, atol=0.5)  # printed to two digits
    assert_allclose(rod_demagnetizing_factor(248.0), 0.79e-4, atol=0.005e-4)  # printed to two digits, eq. (9.25)
    torque = hysteresis_damping_torque(1e-6, 3.6, averaging_factor=0.725)
    assert_allclose(torque, 0.725 * 1e-6 * 3.6 / (2 * np.pi), rtol=1e-15)


def test_bad_material_is_refused():
    with pytest.raises(ValueError, match="remanence must be below saturation"):
        rod_cycle_energy(10.0, 12.0, 0.03, 0.025)
    with pytest.raises(ValueError, match="coercivity must be > 0"):
        limb_induction(1.0, 0.0, 0.004, 0.025)
    with pytest.raises(ValueError, match="volume must be >= 0"):
        hysteresis_damping_torque(-1.0, 1.0)
    with pytest.raises(ValueError, match="field must have n >= 2 samples"):
        hysteresis_response([1.0], *ROD)


def test_settled_loop_is_closed_odd_and_carries_the_cycle_energy():
    from magbench.hardware import settled_hysteresis_loop

    # Amplitudes above Hc: below it (6 A/m, say) the third cycle is still creeping (its ends
    # differ by ~1.5e-5 T), so "settled" is a claim only for loops that reach the limbs.
    ha = np.array([30.0, 200.0])
    h, b = settled_hysteresis_loop(ha, *ROD)
    assert h.shape == b.shape == (2, 721)
    # H is the sinusoid over φ = 4π … 6π; rounding of sin at ~19 rad only (1e-12 of Ha).
    assert_allclose(h, ha[:, None] * np.sin(np.linspace(4 * np.pi, 6 * np.pi, 721)), rtol=0, atol=1e-12 * ha.max())
    # Settled: the loop closes on itself, and B(φ + π) = −B(φ) (the model is odd in H, the
    # drive odd in φ + π); both to the RK4 error of 720 steps a cycle, far below Br = 4e-3 T.
    assert_allclose(b[:, -1], b[:, 0], rtol=0, atol=1e-6)
    assert_allclose(b[:, 360:], -b[:, :361], rtol=0, atol=1e-6)
    # Its ∮H dB is rod_cycle_energy's (the same samples: exact).
    assert_allclose(hysteresis_loop_energy(h[:, :-1], b[:, :-1]), rod_cycle_energy(ha, *ROD), rtol=0, atol=0)
    with pytest.raises(ValueError, match="samples"):
        settled_hysteresis_loop(ha, *ROD, samples=2)
    with pytest.raises(ValueError, match="field_amplitude"):
        settled_hysteresis_loop(-1.0, *ROD)
