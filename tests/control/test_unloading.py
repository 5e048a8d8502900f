"""magbench.control.unloading: Kovalenko's §5.2 unloading laws, the linear law's torque and its
stability argument (5.3)–(5.5), the relay's dead zone, the pulsed law at B_a = 0."""

import numpy as np
import pytest
from numpy.testing import assert_allclose

from magbench.control import (pulsed_unloading_dipole, relay_coil_unloading_dipole, relay_unloading_dipole,
                              unloading_dipole, unloading_torque)

RNG = np.random.default_rng(25)
B = RNG.normal(size=(200, 3)) * 3e-5
K = RNG.normal(size=(200, 3))


def _perp(k, b):
    return k - b * np.sum(k * b, axis=-1, keepdims=True) / np.sum(b * b, axis=-1, keepdims=True)


def test_linear_torque_is_minus_k_times_the_momentum_across_the_field():
    # (5.3): L × B = −k K⊥, a vector identity: rounding only
    torque = np.cross(unloading_dipole(B, K, 0.02), B)
    assert_allclose(torque, -0.02 * _perp(K, B), atol=1e-15)
    assert_allclose(unloading_torque(B, K, 0.02), torque, atol=1e-15)
    # perpendicular to B (rounding relative to |τ||B|)
    assert_allclose(np.sum(torque * B, axis=-1) / (np.linalg.norm(torque, axis=-1) * np.linalg.norm(B, axis=-1)),
                    0.0, atol=1e-12)


def test_momentum_magnitude_never_grows_and_stays_where_k_is_along_b():
    # (5.4)–(5.5): d|K|²/dt = 2 K·(L × B) = −2k|K⊥|² ≤ 0; equality for K ∥ B
    rate = 2 * np.sum(K * unloading_torque(B, K, 0.05), axis=-1)
    assert np.all(rate <= 1e-15)
    assert_allclose(rate, -2 * 0.05 * np.sum(_perp(K, B) ** 2, axis=-1), atol=1e-14)
    along = 3.7 * B / np.linalg.norm(B, axis=-1, keepdims=True)
    assert_allclose(unloading_torque(B, along, 0.05), 0.0, atol=1e-15)


def test_linear_law_integrated_leaves_only_the_part_along_a_fixed_field():
    # K̇ = −k K⊥ in a fixed field: K∥ stays, K⊥ decays as e^{−kt} (closed form); Euler steps
    # of 1e-3/k → first-order error ~ 5e-4 relative
    b, k = np.array([1e-5, -2e-5, 3e-5]), 0.1
    m, dt = np.array([1.0, 2.0, -0.5]), 1e-2
    for _ in range(3000):
        m = m + dt * unloading_torque(b, m, k)
    k0 = np.array([1.0, 2.0, -0.5])
    par = b * (k0 @ b) / (b @ b)
    assert_allclose(m, par + (k0 - par) * np.exp(-k * 30.0), rtol=2e-3)


def test_relay_dead_zone_gives_zero_inside_and_full_relay_outside():
    zone = np.array([0.1, 0.2, 0.3])
    inside = RNG.uniform(-1, 1, size=(50, 3)) * zone * 0.999
    assert np.all(relay_unloading_dipole(B[:50], inside, 1e6, zone) == 0.0)
    outside = np.array([0.5, -0.5, 0.0])  # z inside its zone
    b = np.array([1e-5, 2e-5, 3e-5])
    # k F × B with F = (1, −1, 0): exact arithmetic on representable numbers
    assert_allclose(relay_unloading_dipole(b, outside, 2e5, zone), 2e5 * np.cross([1.0, -1.0, 0.0], b), rtol=1e-15)


def test_relay_torque_is_perpendicular_to_b():
    torque = np.cross(relay_unloading_dipole(B, K, 1e6, 0.2), B)
    assert_allclose(np.sum(torque * B, axis=-1), 0.0, atol=1e-18)


def test_pulsed_law_unloads_one_axis_only_where_b_has_no_component_along_it():
    b = np.array([0.0, 2e-5, -1e-5])
    torque = np.cross(pulsed_unloading_dipole(b, [0.3, 0.7, -0.2], 0.01, 0, 1e-7), b)
    assert_allclose(torque, [-0.003, 0.0, 0.0], atol=1e-16)  # −k K_x e_x exactly, rounding only
    off = pulsed_unloading_dipole([5e-6, 2e-5, -1e-5], [0.3, 0.7, -0.2], 0.01, 0, 1e-7)
    assert np.all(off == 0.0)


@pytest.mark.parametrize("call, match", [
    (lambda: unloading_dipole([0.0, 0.0, 0.0], [1.0, 0, 0], 0.1), "field must not contain a zero vector"),
    (lambda: unloading_dipole([1e-5, 0, 0], [1.0, 0], 0.1), "momentum must have shape"),
    (lambda: unloading_dipole([1e-5, 0, 0], [1.0, 0, 0], -0.1), "gain must be >= 0 1/s, got -0.1"),
    (lambda: relay_unloading_dipole([1e-5, 0, 0], [1.0, 0, 0], 1e6, -0.1), "dead_zone must be >= 0"),
    (lambda: relay_unloading_dipole([1e-5, 0, 0], [1.0, 0, 0], 1e6, [0.1, 0.1]), "dead_zone must be a scalar or"),
    (lambda: pulsed_unloading_dipole([1e-5, 0, 0], [1.0, 0, 0], 0.1, 3, 1e-7), "axis must be 0, 1 or 2, got 3"),
    (lambda: pulsed_unloading_dipole([1e-5, 0, 0], [1.0, 0, 0], 0.1, 0, np.nan), "field_threshold must be finite"),
])
def test_bad_input_names_parameter_value_and_range(call, match):
    with pytest.raises(ValueError, match=match):
        call()


def test_relay_coil_law_switches_full_dipole_outside_both_dead_zones_only():
    b = np.array([1e-5, -4e-6, 3e-5])
    # F = (1, 0, -1): δ = F × B = (0·3e-5 − (−1)(−4e-6), (−1)(1e-5) − 1·3e-5, 1·(−4e-6) − 0) = (−4e-6, −4e-5, −4e-6)
    law = relay_coil_unloading_dipole(b, [0.5, 0.05, -0.7], 50.0, 0.1, 5e-6)
    assert law.tolist() == [0.0, -50.0, 0.0]
    assert relay_coil_unloading_dipole(b, [0.5, 0.05, -0.7], 50.0, 0.1, 1e-6).tolist() == [-50.0, -50.0, -50.0]
    assert np.all(relay_coil_unloading_dipole(B, 0.05 * K / np.abs(K).max(), 50.0, 0.06, 0.0) == 0.0)
