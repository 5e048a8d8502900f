"""magbench.control B-dot laws and gains: dissipation, projection, saturation, closed forms."""

import numpy as np
import pytest
from numpy.testing import assert_allclose

from magbench.constants import EARTH_GM
from magbench.control import (avanzini_giulietti_gain, bdot_dipole, bdot_dipole_projected, held_bdot_rate_limit,
                              samsat_gain)

RNG = np.random.default_rng(5)
B = RNG.normal(size=(500, 3)) * 3e-5
W = RNG.normal(size=(500, 3)) * 0.2


def test_bdot_is_a_viscous_damper_for_a_fixed_field():
    """With Ḃ_body = −ω × B, m = kω × B and τ = m × B = −kB²ω⊥ (Kovalenko 6.3)."""
    k = 1e4
    torque = np.cross(bdot_dipole(-np.cross(W, B), k), B)
    b2 = np.sum(B * B, axis=-1, keepdims=True)
    w_perp = W - B * np.sum(W * B, axis=-1, keepdims=True) / b2
    # Same vector algebra two ways: rounding relative 1e-15.
    assert_allclose(torque, -k * b2 * w_perp, rtol=1e-12, atol=1e-25)


@pytest.mark.parametrize("limit", [np.inf, 0.2, 1e-3])
def test_power_never_positive_with_per_axis_saturation(limit):
    rate = -np.cross(W, B)
    for m in (bdot_dipole(rate, 1e4, limit), bdot_dipole_projected(B, rate, 1e-5, limit)):
        power = np.sum(np.cross(m, B) * W, axis=-1)   # ω·τ
        assert np.all(power <= 1e-30)
        assert np.all(np.abs(m) <= limit)


def test_projected_law_ignores_the_change_of_magnitude_and_matches_avanzini_giulietti():
    k = 2.6e-5
    growth = B * 0.01   # Ḃ ∥ B: only |B| changes
    # Rounding (1e-16 relative) of the two cancelling terms k|Ḃ|/B² ≲ 1 A·m² for the smallest |B| drawn.
    assert_allclose(bdot_dipole_projected(B, growth, k), 0.0, atol=1e-15)
    rate = -np.cross(W, B) + growth
    bnorm = np.linalg.norm(B, axis=-1, keepdims=True)
    h = 1e-4
    bhat = lambda t: (B + rate * t) / np.linalg.norm(B + rate * t, axis=-1, keepdims=True)   # noqa: E731
    # m = −(k/|B|) db̂/dt with a central difference: error O(h²|Ḃ/B|³) relative ≈ 1e-10.
    assert_allclose(bdot_dipole_projected(B, rate, k), -k / bnorm * (bhat(h) - bhat(-h)) / (2 * h),
                    rtol=1e-6, atol=1e-12)


def test_gain_and_saturation_broadcast():
    m = bdot_dipole(np.ones((4, 3)) * 1e-6, np.array([1.0, 10.0, 1e5, 1e6]), 0.2)
    assert_allclose(m[:, 0], [-1e-6, -1e-5, -0.1, -0.2], rtol=1e-15)


def test_avanzini_giulietti_number():
    # Shared reference §4: 3U (J_min = 0.00666667) at 500 km, 51.6°: k* = 2.6363e-5 N·m·s (5 digits printed).
    n = np.sqrt(EARTH_GM / 6871e3**3)
    assert_allclose(avanzini_giulietti_gain(n, np.radians(51.6), 0.00666667), 2.6363e-5, rtol=5e-5)


def test_samsat_gain_numbers():
    # Shared reference §3: 1.691e4 at (0.1, 10, 10) °/s and the Fig. 1 list, 4 digits printed.
    rates = np.radians([[0.1, w, w] for w in range(5, 50, 5)])
    expected = [3.382e4, 1.691e4, 1.128e4, 8456, 6765, 5638, 4832, 4228, 3758]
    assert_allclose(samsat_gain(0.2, rates, 47.9e-6), expected, rtol=5e-4)


def test_held_limit_is_ten_point_six_degrees():
    # π/17 s = 10.588 °/s (shared reference §2, "10.6 °/s").
    assert_allclose(np.degrees(held_bdot_rate_limit(16.0, 1.0)), 180.0 / 17.0, rtol=1e-15)


@pytest.mark.parametrize("call, match", [
    (lambda: bdot_dipole([1.0, 0.0], 1.0), "field_rate must have shape"),
    (lambda: bdot_dipole([1.0, 0.0, 0.0], -1.0), "gain must be > 0"),
    (lambda: bdot_dipole([1.0, 0.0, 0.0], 1.0, 0.0), "max_dipole must be > 0"),
    (lambda: bdot_dipole([1.0, 0.0, 0.0], 1.0, np.nan), "max_dipole"),
    (lambda: bdot_dipole_projected([0.0, 0.0, 0.0], [1.0, 0.0, 0.0], 1.0), "field must not contain a zero"),
    (lambda: avanzini_giulietti_gain(1e-3, 4.0, 0.01), "geomagnetic_inclination must lie in"),
    (lambda: samsat_gain(0.2, [0.0, 0.0, 0.0], 5e-5), "initial_rate must not be zero"),
    (lambda: held_bdot_rate_limit(16.0, -1.0), "off_time must be > 0"),
])
def test_bad_input(call, match):
    with pytest.raises(ValueError, match=match):
        call()
