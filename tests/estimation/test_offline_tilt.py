"""offline_tilt against closed forms (rest with a gyro bias, constant-rate rotation), the
time-reversal symmetry of a forward-backward scheme, and its input checks.

The BROAD recordings and the peer vqf.offlineVQF are in tests/peers/test_vqf.py.
"""

import numpy as np
import pytest
from numpy.testing import assert_allclose
from scipy.spatial.transform import Rotation

from magbench import estimation

G = 9.81


def _up_in_sensor(q):
    """The Earth's up axis seen in the sensor frame: what a tilt estimate determines."""
    return Rotation.from_quat(q, scalar_first=True).inv().apply([0.0, 0.0, 1.0])


def _angle(u, v):
    """Angle between unit vectors, stable near zero [rad]."""
    return 2.0 * np.arctan2(np.linalg.norm(u - v, axis=-1), np.linalg.norm(u + v, axis=-1))


def test_static_tilt_with_constant_gyro_bias_is_recovered_exactly():
    # At rest the whole record is rest: the bias is the mean gyro, exactly the constant, the
    # corrected integral is the identity and the rotated accelerometer a constant that a
    # linear filter keeps in direction. The causal filter integrates the bias until its rest
    # detector has seen 1.5 s of quiet, so it is off by degrees here: the test names that defect.
    n, dt = 3000, 0.01
    bias = np.radians([0.8, -1.2, 0.5])       # [rad/s], norm 1.5 deg/s, below the 2 deg/s rest threshold
    true = Rotation.from_rotvec([0.4, -0.25, 0.0])          # sensor -> Earth
    accel = np.tile(true.inv().apply([0.0, 0.0, G]), (n, 1))
    gyro = np.tile(bias, (n, 1))
    up = _up_in_sensor(estimation.offline_tilt(gyro, accel, dt))
    expected = true.inv().apply([0.0, 0.0, 1.0])
    # 1e-9 rad: rounding of the prefix product and of filtfilt's least-squares ends.
    assert _angle(up, expected).max() < 1e-9
    causal = _up_in_sensor(estimation.complementary_tilt(gyro, accel, dt))
    assert _angle(causal, expected).max() > np.radians(1.0)


def test_constant_rate_rotation_between_rest_periods_is_recovered_exactly():
    # 5 s at rest, 20 s tumbling at 90 deg/s about a horizontal sensor axis, 5 s at rest, all
    # with a constant gyro bias. The rest periods give the bias exactly; the integral of a
    # constant rate is exact (one rotation vector per sample), so the accelerometer rotated
    # into the gyro frame is constant and the tilt exact, although it turns through 1800°.
    dt, rate = 0.005, np.radians(90.0)
    bias = np.radians([0.3, -0.7, 0.4])
    spin = np.concatenate([np.zeros(1000), np.full(4000, rate), np.zeros(1000)])
    gyro = np.stack([spin, np.zeros_like(spin), np.zeros_like(spin)], axis=1)
    start = Rotation.from_rotvec([0.0, 0.3, 0.0])
    # Sample k rotates the sensor during the interval before it (strapdown's convention).
    true = start * Rotation.from_rotvec(np.cumsum(gyro, axis=0) * dt)
    accel = true.inv().apply([0.0, 0.0, G])
    q = estimation.offline_tilt(gyro + bias, accel, dt)
    expected = true.inv().apply([0.0, 0.0, 1.0])
    # 1e-8 rad: 6000 composed rotations and the filter's ends, rounding only.
    assert _angle(_up_in_sensor(q), expected).max() < 1e-8


def test_time_reversal_gives_the_reversed_estimate():
    # Played backwards, sample j of the record is sample N-1-j of the original with the gyro
    # negated; the interval before it is the interval after the original sample, so the gyro
    # also moves by one sample. A forward-backward filter with Gustafsson's ends is symmetric
    # under this; the causal filter is not (checked, so the test can fail).
    rng = np.random.default_rng(7)
    n, dt = 4000, 0.01
    t = np.arange(n) * dt
    gyro = np.stack([0.8 * np.sin(0.7 * t), 0.5 * np.cos(1.1 * t), 0.3 * np.sin(0.3 * t + 1)], axis=1)
    gyro += rng.normal(0.0, 0.01, gyro.shape)
    truth = Rotation.from_rotvec(np.cumsum(gyro, axis=0) * dt)
    accel = truth.inv().apply([0.0, 0.0, G]) + rng.normal(0.0, 0.5, (n, 3))   # motion and noise
    reversed_gyro = np.concatenate([[[0.0, 0.0, 0.0]], -gyro[:0:-1]])
    for rest_bias in (False, True):
        forward = _up_in_sensor(estimation.offline_tilt(gyro, accel, dt, rest_bias=rest_bias))
        backward = _up_in_sensor(estimation.offline_tilt(reversed_gyro, accel[::-1], dt,
                                                         rest_bias=rest_bias))[::-1]
        # 1e-9 rad: the two prefix products round differently; nothing else differs.
        assert _angle(forward, backward).max() < 1e-9
    causal_f = _up_in_sensor(estimation.complementary_tilt(gyro, accel, dt, rest_bias=False))
    causal_b = _up_in_sensor(estimation.complementary_tilt(reversed_gyro, accel[::-1], dt,
                                                           rest_bias=False))[::-1]
    assert _angle(causal_f, causal_b).max() > np.radians(0.1)


def test_two_sided_rest_covers_rest_and_never_motion():
    # The causal detector needs min_rest_time of quiet and its low-passes lag: it misses the
    # first 1.5 s and calls the first sample of the motion rest (run backwards, the last).
    # Two-sided: the record's start is rest, no motion sample is, and rest is found up to the
    # time the low-passed rate needs to settle on either side of the motion (60 deg/s to
    # 2 deg/s with tau 0.5 s: 0.5 ln 30 = 1.7 s).
    n, dt = 2000, 0.01    # 8 s rest, 4 s turning, 8 s rest
    gyro = np.zeros((n, 3))
    gyro[800:1200, 2] = np.radians(60.0)
    accel = np.tile([0.0, 0.0, G], (n, 1))
    _, causal = estimation.rest_gyro_bias(gyro, accel, dt)
    rest = estimation.two_sided_rest(gyro, accel, dt)
    assert not causal[:149].any() and causal[800]           # the defects named above
    settle = int(np.ceil(0.5 * np.log(30.0) / dt))
    assert rest[:800 - settle - 1].all() and rest[1200 + settle + 1:].all()
    assert not rest[800 - settle + 1:1200 + settle - 1].any()


def test_bias_comes_only_from_rest_and_none_without_rest():
    # Without any rest sample no bias is removed: a constant rate stays a rotation.
    n, dt = 2000, 0.01
    gyro = np.tile([0.0, np.radians(45.0), 0.0], (n, 1))
    true = Rotation.from_rotvec(np.cumsum(gyro, axis=0) * dt)
    accel = true.inv().apply([0.0, 0.0, G])
    q = estimation.offline_tilt(gyro, accel, dt)
    assert not estimation.two_sided_rest(gyro, accel, dt).any()
    assert _angle(_up_in_sensor(q), true.inv().apply([0.0, 0.0, 1.0])).max() < 1e-9   # rounding


@pytest.mark.parametrize("kwargs, message", [
    (dict(gyro=np.zeros((50, 2))), "gyro must have shape"),
    (dict(accel=np.zeros((49, 3)) + [0, 0, G]), "same shape"),
    (dict(gyro=np.zeros((5, 3)), accel=np.tile([0.0, 0.0, G], (5, 1))), "at least 8 samples"),
    (dict(dt=0.0), "dt"),
    (dict(dt=-0.01), "dt"),
    (dict(tau=0.0), "tau"),
    (dict(tau=1e-3), "Nyquist"),
    (dict(gyro=np.full((50, 3), np.nan)), "gyro"),
    (dict(accel=np.tile([0.0, np.inf, G], (50, 1))), "accel"),
])
def test_bad_input_is_rejected_with_a_clear_message(kwargs, message):
    args = dict(gyro=np.zeros((50, 3)), accel=np.tile([0.0, 0.0, G], (50, 1)), dt=0.01)
    args.update(kwargs)
    tau = args.pop("tau", 3.0)
    with pytest.raises(ValueError, match=message):
        estimation.offline_tilt(args["gyro"], args["accel"], args["dt"], tau=tau)


def test_unknown_rest_detector_setting_is_rejected():
    with pytest.raises(TypeError, match="rate_treshold"):
        estimation.offline_tilt(np.zeros((50, 3)), np.tile([0.0, 0.0, G], (50, 1)), 0.01,
                                rest_detector={"rate_treshold": 0.1})
