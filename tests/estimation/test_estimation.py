"""Estimators against limits, closed forms, scipy's rotations and sequential loops."""

import numpy as np
import pytest
from numpy.testing import assert_allclose
from scipy.spatial.transform import Rotation

from magbench import estimation
from magbench.hardware import sensors
from magbench.rotations import hamilton_product

G = 9.81


# --- eq. (39): the single-axis complementary filter -------------------------------------

def test_alpha_zero_returns_reference():
    rng = np.random.default_rng(1)
    ref = rng.normal(size=(200, 2))
    out = estimation.complementary_filter(rng.normal(size=(200, 2)), ref, 0.01, 0.0)
    assert_allclose(out, ref, rtol=0, atol=0)   # A = 0: the gyro term is multiplied by 0 exactly


def test_alpha_one_returns_gyro_integral():
    rng = np.random.default_rng(2)
    rate = rng.normal(size=300)
    out = estimation.complementary_filter(rate, rng.normal(size=300), 0.02, 1.0, initial_angle=0.3)
    assert_allclose(out, 0.3 + np.cumsum(rate * 0.02), rtol=0, atol=1e-12)  # summation order only


def test_step_form_equals_vectorised_form():
    rng = np.random.default_rng(3)
    rate, ref = rng.normal(size=500), rng.normal(size=500)
    dt = rng.uniform(0.005, 0.02, size=500)
    out = estimation.complementary_filter(rate, ref, dt, 0.97, initial_angle=0.1)
    angle, loop = 0.1, []
    for w, r, h in zip(rate, ref, dt):
        angle = estimation.complementary_filter_step(angle, w, r, h, 0.97)
        loop.append(angle)
    assert_allclose(out, loop, rtol=0, atol=1e-12)  # same recursion, rounding only


def test_consistent_gyro_and_reference_reproduce_the_angle():
    # If ω_k Δt is exactly the angle increment and the reference is the true angle, eq. (39)
    # returns the true angle for every A (induction on θ_k = A(θ_{k-1}+Δθ_k) + (1-A)θ_k).
    t = np.arange(400) * 0.01
    angle = 0.7 * np.sin(2 * np.pi * 0.3 * t)
    rate = np.diff(angle, prepend=angle[0]) / 0.01
    for alpha in (0.0, 0.5, 0.95, 0.99):
        out = estimation.complementary_filter(rate, angle, 0.01, alpha)
        assert_allclose(out, angle, rtol=0, atol=1e-12)


@pytest.mark.parametrize("alpha", [0.95, 0.99])
def test_frequency_response_is_first_order(alpha):
    # Reference-to-output transfer (gyro = 0): H(z) = (1 - A)/(1 - A z^-1). After the transient,
    # the response to a sinusoid has |H| and arg H of that closed form; at low frequency it
    # tends to the continuous 1/(1 + jωτ) with τ = AΔt/(1 - A).
    dt, freq = 0.01, 0.25
    n = 40000
    t = np.arange(n) * dt
    out = estimation.complementary_filter(np.zeros(n), np.sin(2 * np.pi * freq * t), dt, alpha,
                                          initial_angle=0.0)
    tail = slice(n // 2, n)     # transient decays as A^k: A^20000 < 1e-80
    basis = np.stack([np.sin(2 * np.pi * freq * t[tail]), np.cos(2 * np.pi * freq * t[tail])], 1)
    coef, *_ = np.linalg.lstsq(basis, out[tail], rcond=None)
    measured = coef[0] + 1j * coef[1]            # out = Re(H e^{jωt}) -> sin coef Re H, cos coef Im H
    z = np.exp(1j * 2 * np.pi * freq * dt)
    exact = (1 - alpha) / (1 - alpha / z)
    assert_allclose(measured, exact, rtol=1e-9)  # least-squares fit of an exact sinusoid
    tau = estimation.complementary_time_constant(dt, alpha)
    continuous = 1 / (1 + 1j * 2 * np.pi * freq * tau)
    # Discretisation error is O(ωΔt) relative; ωΔt = 0.016 here.
    assert_allclose(measured, continuous, rtol=2 * 2 * np.pi * freq * dt)


# --- 3-D: accelerometer tilt, strapdown, complementary_tilt ---------------------------

def _random_rotations(n, seed):
    return Rotation.random(n, random_state=seed)


def test_accelerometer_tilt_maps_gravity_to_up():
    rot = _random_rotations(50, 4)
    accel = rot.inv().apply([0.0, 0.0, G])       # what a still sensor reads in each orientation
    q = estimation.accelerometer_tilt(accel)
    assert_allclose(np.linalg.norm(q, axis=1), 1.0, atol=1e-14)
    up = Rotation.from_quat(q, scalar_first=True).apply(accel)
    assert_allclose(up, np.tile([0.0, 0.0, G], (50, 1)), atol=1e-12)  # rounding of unit vectors


def test_accelerometer_tilt_upside_down():
    q = estimation.accelerometer_tilt([[0.0, 0.0, -G]])
    up = Rotation.from_quat(q, scalar_first=True).apply([0.0, 0.0, -G])
    assert_allclose(up, [[0.0, 0.0, G]], atol=1e-12)


def test_hamilton_product_matches_scipy():
    p, q = _random_rotations(100, 5), _random_rotations(100, 6)
    mine = hamilton_product(p.as_quat(scalar_first=True), q.as_quat(scalar_first=True))
    peer = (p * q).as_quat(scalar_first=True)
    assert_allclose(np.abs(np.sum(mine * peer, axis=1)), 1.0, atol=1e-14)  # same rotation up to sign


def test_strapdown_equals_sequential_composition():
    rng = np.random.default_rng(7)
    rate = rng.normal(scale=2.0, size=(1001, 3))
    start = _random_rotations(1, 8)[0]
    fast = estimation.strapdown_orientation(rate, 0.003, start.as_quat(scalar_first=True))
    loop = start
    for k, step in enumerate(Rotation.from_rotvec(rate * 0.003)):
        loop = loop * step
        if k in (0, 500, 1000):
            # Rounding: 1000 compositions in different association orders.
            assert_allclose(abs(np.dot(fast[k], loop.as_quat(scalar_first=True))), 1.0, atol=1e-12)


def test_static_input_gives_exact_tilt_heading_free():
    for seed in range(5):
        true = _random_rotations(1, 10 + seed)[0]
        accel = np.tile(true.inv().apply([0.0, 0.0, G]), (300, 1))
        q = estimation.complementary_tilt(np.zeros((300, 3)), accel, 0.01)
        assert q.shape == (300, 4)
        est = Rotation.from_quat(q, scalar_first=True)
        # The sensor's up direction (the tilt) is exact; the heading is left free.
        assert_allclose(est.inv().apply([0, 0, 1]), np.tile(true.inv().apply([0, 0, 1]), (300, 1)),
                        atol=1e-12)


@pytest.mark.parametrize("order", [1, 2])
def test_rotation_with_consistent_accel_is_tracked(order):
    # Constant body rate about a tilted axis: the strapdown is exact, the accelerometer
    # rotated into the gyro frame is constant, so the tilt is exact at every sample.
    dt, n = 0.005, 4000
    rate = np.array([0.4, -0.7, 1.1])
    start = _random_rotations(1, 20)[0]
    true = start * Rotation.from_rotvec(np.outer(np.arange(n), rate * dt))
    accel = true.inv().apply([0.0, 0.0, G])
    q0 = estimation.accelerometer_tilt(accel[:1])
    # Start the filter at the true first sample: the first gyro sample rotates before it.
    q = estimation.complementary_tilt(np.vstack([np.zeros(3), np.tile(rate, (n - 1, 1))]), accel, dt,
                                      order=order)
    est = Rotation.from_quat(q, scalar_first=True)
    assert_allclose(np.linalg.norm(q, axis=1), 1.0, atol=1e-14)
    assert_allclose(est.inv().apply([0, 0, 1]), true.inv().apply([0, 0, 1]), atol=1e-9)  # rounding over 4000 steps
    assert q0.shape == (1, 4)


def test_filter_beats_both_baselines_with_realistic_sensors():
    # A wobbling, shaken sensor: the datasheet's noise, a residual gyro bias, vibration and
    # 2 m/s² of linear acceleration (which the accelerometer cannot tell from gravity).
    # Two minutes; the residual bias after a start-up calibration is taken as 0.1 °/s.
    dt, n = 0.01, 12000
    rng = np.random.default_rng(30)
    t = np.arange(n) * dt
    rotvec = np.stack([0.5 * np.sin(0.4 * t), 0.4 * np.sin(0.23 * t + 1), 0.8 * np.sin(0.1 * t)], axis=1)
    true = Rotation.from_rotvec(rotvec)
    rate = np.zeros((n, 3))
    rate[1:] = (true[:-1].inv() * true[1:]).as_rotvec() / dt
    gyro = sensors.gyro_readings(rate, dt, rng=rng, bias=np.radians([0.1, -0.1, 0.05]))
    linear = 2.0 * np.stack([np.sin(2 * np.pi * 0.5 * t), np.cos(2 * np.pi * 0.3 * t), 0 * t], axis=1)
    accel = sensors.accelerometer_readings(true.inv().apply(linear + [0, 0, G]), dt, rng=rng,
                                           vibration_amplitude=0.5, vibration_frequency=7.0)

    def tilt_rms(q):
        est = Rotation.from_quat(q, scalar_first=True)
        cos = np.sum(est.inv().apply([0, 0, 1]) * true.inv().apply([0, 0, 1]), axis=1)
        return np.sqrt(np.mean(np.arccos(np.clip(cos, -1, 1)) ** 2))

    filtered = tilt_rms(estimation.complementary_tilt(gyro, accel, dt, rest_bias=False))
    accel_only = tilt_rms(estimation.accelerometer_tilt(accel))
    gyro_only = tilt_rms(estimation.strapdown_orientation(gyro, dt, true[0].as_quat(scalar_first=True)))
    assert filtered < 0.5 * min(accel_only, gyro_only)


def test_rest_bias_recovers_a_constant_bias():
    rng = np.random.default_rng(40)
    bias = np.array([0.01, -0.004, 0.02])
    gyro = sensors.gyro_readings(np.zeros((3000, 3)), 0.01, rng=rng, bias=bias)
    accel = sensors.accelerometer_readings(np.tile([0, 0, G], (3000, 1)), 0.01, rng=rng)
    est, rest = estimation.rest_gyro_bias(gyro, accel, 0.01)
    assert rest[-1] and not rest[:140].any()
    sigma = sensors.MPU6050_GYRO_NOISE_DENSITY * np.sqrt(50.0)
    # Mean of the rest samples: standard error σ/√n, 5.3 of them ≈ P 1e-7.
    assert_allclose(est[-1], bias, atol=5.3 * sigma / np.sqrt(rest.sum()))


def test_rest_not_detected_while_rotating():
    gyro = np.tile([0.0, 0.0, np.radians(10.0)], (2000, 1))
    accel = np.tile([0.0, 0.0, G], (2000, 1))
    est, rest = estimation.rest_gyro_bias(gyro, accel, 0.01)
    assert not rest.any() and np.all(est == 0)


def test_magnetometer_heading_inverts_the_planar_field():
    psi = np.linspace(-3.1, 3.1, 101)
    b = 314e-6 * np.stack([np.cos(psi), -np.sin(psi), np.full_like(psi, 0.2)], axis=-1)
    assert_allclose(estimation.magnetometer_heading(b), psi, atol=1e-13)  # atan2 rounding


def test_error_terms_offset_is_the_fixed_point_and_noise_terms_vanish_without_noise():
    """The offset term is gyro_offset_error's fixed point A·b·Δt/(1−A); with no noise and
    no vibration the other three terms are exactly zero."""
    alpha = np.array([0.9, 0.98])
    offset, acc, vib, gyr = estimation.complementary_error_terms(0.01, alpha, 0.02, 0.0, 0.0, 0.0, 7.0, 0.3)
    assert_allclose(offset, estimation.gyro_offset_error(0.02, alpha, 0.01), rtol=1e-15)   # same formula, rounding
    assert not np.any(acc) and not np.any(vib) and not np.any(gyr)


def test_error_terms_noise_gains_match_the_filtered_noise():
    """Gyro noise σ_ω through eq. (39) has std σ_ω·AΔt/√(1−A²); reference noise σ
    (σ_a/g as an angle) has std σ·√((1−A)/(1+A)): the closed forms against the filter
    run on 200 000 samples of white noise."""
    rng = np.random.default_rng(11)
    n, dt, alpha, sg, sa = 200_000, 0.01, 0.95, 0.01, 0.05
    _, acc, _, gyr = estimation.complementary_error_terms(dt, alpha, 0.0, sg, sa, 0.0, 0.0, 0.0, gravity=1.0)
    from_gyro = estimation.complementary_filter(sg * rng.standard_normal(n), np.zeros(n), dt, alpha)
    from_ref = estimation.complementary_filter(np.zeros(n), sa * rng.standard_normal(n), dt, alpha)
    # rtol 0.02: the std of 2e5 correlated samples (correlation time ≈ 20 samples) scatters by ≈ 0.5 %.
    assert_allclose([from_gyro[100:].std(), from_ref[100:].std()], [gyr, acc], rtol=0.02)


@pytest.mark.parametrize("call, match", [
    (lambda: estimation.complementary_tilt(np.zeros((5, 3)), np.zeros((4, 3)), 0.01), "same shape"),
    (lambda: estimation.complementary_tilt(np.zeros((5, 2)), np.zeros((5, 2)), 0.01), "gyro"),
    (lambda: estimation.complementary_tilt(np.zeros((5, 3)), np.ones((5, 3)), 0.01, tau=-1), "tau"),
    (lambda: estimation.complementary_tilt(np.zeros((5, 3)), np.ones((5, 3)), 0.01, order=3), "order"),
    (lambda: estimation.complementary_tilt(np.zeros((5, 3)), np.ones((5, 3)), 0.01, tau=0.001), "tau"),
    (lambda: estimation.complementary_tilt(np.zeros((5, 3)), np.ones((5, 3)), [0.01] * 5), "dt"),
    (lambda: estimation.complementary_tilt(np.full((5, 3), np.nan), np.ones((5, 3)), 0.01), "gyro"),
    (lambda: estimation.accelerometer_tilt(np.zeros((2, 3))), "accel"),
    (lambda: estimation.strapdown_orientation(np.zeros((5, 3)), 0.01, [1, 0, 0]), "initial_orientation"),
    (lambda: estimation.magnetometer_heading([0.0, 0.0, 1.0]), "horizontal"),
    (lambda: estimation.rest_gyro_bias(np.zeros((5, 3)), np.ones((5, 3)), 0.01, min_rest_time=-1),
     "min_rest_time"),
    (lambda: estimation.complementary_filter(1.0, 1.0, 0.01, 0.9), "scalar"),
    (lambda: estimation.complementary_filter([1.0], [1.0], 0.01, 1.5), "alpha"),
    (lambda: estimation.complementary_error_terms(0.01, 0.98, 0.0, -1.0, 0.0, 0.0, 7.0, 0.0), "gyro_noise_std"),
    (lambda: estimation.complementary_error_terms(0.01, 1.0, 0.0, 0.0, 0.0, 0.0, 7.0, 0.0), "alpha"),
    (lambda: estimation.complementary_error_terms(0.0, 0.98, 0.0, 0.0, 0.0, 0.0, 7.0, 0.0), "sample_interval"),
])
def test_bad_input(call, match):
    with pytest.raises(ValueError, match=match):
        call()
