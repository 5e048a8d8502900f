"""The Euler-case sun-sensor model and its fits (TNS-0 preprint §2) on synthetic sessions."""

import numpy as np
import pytest
from numpy.testing import assert_allclose

from magbench.estimation.spin_sessions import fit_nested_grid, rms, sensor_signals

A, C = 0.0406, 0.00625      # kg·m², TNS-0's (chapter 7's values)


def test_mirror_and_t0_are_not_identifiable():
    from magbench.estimation.spin_sessions import identifiability, mirror, sensor_signals

    t = np.linspace(0.0, 30.0, 301)
    p = np.array([0.0936, 1.086, 5.952, 1.0, 0.8])
    # The mirror (π − θ, −φ0, π − σ) gives the same signals for sensors along ±x and +z.
    assert_allclose(sensor_signals(t, mirror(p), A, C), sensor_signals(t, p, A, C), rtol=0, atol=1e-12)
    # t0 trades against the phases: one singular value of the 6-column Jacobian vanishes
    # (1e-9 of the largest: central differences of step 1e-6), the other five do not.
    sv = identifiability(p, t, A, C)
    assert sv[-1] / sv[0] < 1e-9 and sv[-2] / sv[0] > 1e-5


def test_frequency_first_recovers_a_synthetic_session():
    from magbench.estimation.spin_sessions import fit_frequency_first, mirror, synthetic_session

    truth = np.array([0.05, 0.9, 2.0, 4.0, 1.2])     # not a Table 1 row: the method is not tuned to it
    noise = 0.01
    t, s = synthetic_session(truth, A, C, noise=noise, seed=5)
    fit = fit_frequency_first(t, s, A, C)
    x = fit["params"]
    if abs(x[1] - truth[1]) > abs(x[1] - mirror(truth)[1]):
        truth = mirror(truth)
    # L from the spectral line and a polish: 0.1 %; angles to 5e-3 rad (noise 0.01 over 1800 samples).
    assert_allclose(x[0], truth[0], rtol=1e-3)
    assert_allclose(x[[1, 4]], truth[[1, 4]], atol=5e-3)
    # At the global minimum the rms residual is the noise level: 1800 samples, ±5 % is ~3 sd.
    assert_allclose(fit["rms"], noise, rtol=0.05)


def test_the_signals_are_the_cosine_law_of_each_normal_at_t0():
    """At t = t0 with ψ0 = φ0 = 0 the body axes are the L-frame turned by θ about x: the sensors
    see max(0, n·s) for s = (sin σ, 0, cos σ) rotated into the body."""
    theta, sigma = 0.7, 1.1
    s = sensor_signals(np.array([0.0]), [0.05, theta, 0.0, 0.0, sigma], A, C)[:, 0]
    sun_body = np.array([np.sin(sigma), np.sin(theta) * np.cos(sigma), np.cos(theta) * np.cos(sigma)])
    # R_x(θ) maps body to the L-frame; its transpose takes the Sun into the body; exact to rounding
    assert_allclose(s, np.maximum([sun_body[0], sun_body[2], -sun_body[0]], 0.0), rtol=0, atol=1e-15)


def test_the_truth_has_zero_residual():
    t = np.linspace(0.0, 20.0, 201)
    p = np.array([0.05, 0.9, 2.0, 4.0, 1.2])
    assert rms(p, t, sensor_signals(t, p, A, C), A, C) == 0.0


@pytest.mark.parametrize("call, match", [
    (lambda: sensor_signals([0.0], [0.05, 0.9, 2.0, 4.0, 1.2], -1.0, C), "transverse_inertia must be > 0"),
    (lambda: sensor_signals([0.0], [0.05, 0.9, 2.0], A, C), r"params must have shape \(\.\.\., 5\)"),
    (lambda: fit_nested_grid(np.arange(3.0), np.zeros((3, 3)), A, C, points=1.5), "points must be a whole number"),
])
def test_bad_input(call, match):
    with pytest.raises(ValueError, match=match):
        call()
