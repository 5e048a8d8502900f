"""Momentum and energy exchange with the Earth (thesis §1.3)."""

import numpy as np
import pytest
from numpy.testing import assert_allclose

from magbench import attitude


def test_exchange_conserves_momentum_and_matches_limit():
    # Exact ratio −(2ω_E + Δω_E)/(2ω_c + Δω_c); for J_E → ∞ it tends to −ω_E/ω̄_c.
    ratio = attitude.momentum_exchange_energy_ratio(0.005, 0.1, -0.1, 8e37, 7.292115e-5)
    assert_allclose(ratio, -7.292115e-5 / 0.05, rtol=1e-12)


def test_non_rotating_earth_recovers_thesis_magnitude():
    # With ω_E = 0 and the spacecraft starting at rest, ΔT_E/ΔT_c = J_c/J_E exactly:
    # the thesis's estimate is the limit of a non-rotating Earth.
    ratio = attitude.momentum_exchange_energy_ratio(2.0, 0.0, 0.3, 5.0, 0.0)
    assert_allclose(ratio, attitude.thesis_energy_ratio(2.0, 5.0), rtol=1e-14)


def test_bad_input():
    with pytest.raises(ValueError, match="rate_change"):
        attitude.momentum_exchange_energy_ratio(1.0, 0.1, 0.0, 1.0, 0.0)
    with pytest.raises(ValueError, match="spacecraft_inertia"):
        attitude.thesis_energy_ratio(-1.0, 1.0)
    assert np.isfinite(attitude.thesis_energy_ratio(1.0, 2.0))
