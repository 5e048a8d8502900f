"""Sensor models against the datasheets' own numbers and exact sampling statistics."""

import numpy as np
import pytest
from numpy.testing import assert_allclose
from scipy import stats

from magbench.hardware import sensors

# Two-sided probability of a false failure for each statistical check; the seeds are
# fixed, so a check either always passes or always fails, but the bound says how
# surprising a failure would be for a correct model.
P_FALSE = 1e-6


def _std_within_chi2(samples, sigma):
    """Assert the sample std is consistent with sigma: (n-1) s^2 / sigma^2 ~ chi2(n-1)."""
    n = samples.size
    ratio = (n - 1) * samples.var(ddof=1) / sigma**2
    low, high = stats.chi2.ppf([P_FALSE / 2, 1 - P_FALSE / 2], n - 1)
    assert low < ratio < high, f"(n-1)s²/σ² = {ratio:.1f} outside [{low:.1f}, {high:.1f}]"


def test_datasheet_density_and_total_noise_agree():
    # Table 6.1 states both 0.005 °/s/√Hz and 0.05 °/s rms at a 100 Hz filter: σ = ρ√B.
    sigma = sensors.noise_std_from_density(sensors.MPU6050_GYRO_NOISE_DENSITY, 1e-3,
                                           bandwidth=sensors.MPU6050_DLPF_BANDWIDTH)
    assert_allclose(sigma, sensors.MPU6050_GYRO_TOTAL_RMS_NOISE, rtol=1e-12)  # float rounding only


@pytest.mark.parametrize("bandwidth", [None, 20.0])
def test_gyro_noise_std_matches_density(bandwidth):
    dt = 0.005
    readings = sensors.gyro_readings(np.zeros((20000, 3)), dt, rng=np.random.default_rng(11),
                                     bandwidth=bandwidth)
    band = 0.5 / dt if bandwidth is None else bandwidth
    _std_within_chi2(readings, sensors.MPU6050_GYRO_NOISE_DENSITY * np.sqrt(band))


def test_accelerometer_noise_std_matches_density():
    dt = 0.01
    force = np.tile([0.0, 0.0, 9.81], (30000, 1))
    readings = sensors.accelerometer_readings(force, dt, rng=np.random.default_rng(12))
    _std_within_chi2(readings - force, sensors.MPU6050_ACCEL_NOISE_DENSITY * np.sqrt(0.5 / dt))


def test_magnetometer_noise_std_is_the_noise_floor():
    field = np.tile([18e-6, 3e-6, 48e-6], (20000, 1))
    readings = sensors.magnetometer_readings(field, 1 / 75, rng=np.random.default_rng(13))
    _std_within_chi2(readings - field, sensors.HMC5883L_NOISE_FLOOR)
    assert_allclose(sensors.HMC5883L_NOISE_FLOOR, 0.2e-6, rtol=1e-12)  # 2 mG = 0.2 µT exactly


def test_gyro_bias_is_the_mean():
    bias = np.array([0.01, -0.02, 0.003])
    readings = sensors.gyro_readings(np.zeros((40000, 3)), 0.01, rng=np.random.default_rng(14),
                                     bias=bias)
    sigma = sensors.MPU6050_GYRO_NOISE_DENSITY * np.sqrt(50.0)
    # The mean of n samples has std σ/√n; 5.3 standard errors is P ≈ 1e-7 per axis.
    assert_allclose(readings.mean(axis=0), bias, atol=5.3 * sigma / np.sqrt(readings.shape[0]))


def test_bias_random_walk_variance_grows_linearly():
    # Random walk K per √s: after t the bias has variance K² t; members on a trailing axis.
    k, dt, n, members = 1e-3, 0.01, 500, 4000
    readings = sensors.gyro_readings(np.zeros((n, members)), dt, rng=np.random.default_rng(15),
                                     noise_density=0.0, bias_random_walk=k)
    _std_within_chi2(readings[-1], k * np.sqrt(n * dt))
    _std_within_chi2(readings[n // 4 - 1], k * np.sqrt(n // 4 * dt))


def test_vibration_power():
    # Uniform samples over whole periods: mean of sin² is exactly 1/2 whatever the phase.
    dt, freq, amp = 0.01, 7.0, 0.3
    force = np.zeros((1000, 3))   # 10 s = 70 whole periods
    readings = sensors.accelerometer_readings(force, dt, rng=np.random.default_rng(16),
                                              noise_density=0.0, vibration_amplitude=amp,
                                              vibration_frequency=freq)
    assert_allclose((readings**2).mean(axis=0), amp**2 / 2, rtol=1e-10)  # trig sums, rounding only
    assert np.all(np.abs(readings) <= amp + 1e-15)


def test_seeded_and_broadcast_over_members():
    true = np.zeros((50, 8, 3))
    a = sensors.gyro_readings(true, 0.01, rng=np.random.default_rng(5), bias=[0.0, 0.0, 1.0])
    b = sensors.gyro_readings(true, 0.01, rng=np.random.default_rng(5), bias=[0.0, 0.0, 1.0])
    assert a.shape == (50, 8, 3)
    assert_allclose(a, b, rtol=0, atol=0)  # same seed, same numbers
    assert np.all(a[..., 2] > 0.5)  # bias broadcast along the trailing axis


def test_zero_noise_is_identity():
    true = np.linspace(-1, 1, 30).reshape(10, 3)
    out = sensors.gyro_readings(true, 0.01, rng=np.random.default_rng(0), noise_density=0.0)
    assert_allclose(out, true, rtol=0, atol=0)


@pytest.mark.parametrize("call, match", [
    (lambda: sensors.gyro_readings(np.zeros((5, 3)), 0.01, rng=1), "rng"),
    (lambda: sensors.gyro_readings(np.zeros((5, 3)), -0.01, rng=np.random.default_rng()), "dt"),
    (lambda: sensors.gyro_readings(np.zeros((5, 3)), [0.01, 0.01], rng=np.random.default_rng()), "dt"),
    (lambda: sensors.gyro_readings(0.0, 0.01, rng=np.random.default_rng()), "true_rate"),
    (lambda: sensors.gyro_readings([[np.nan]], 0.01, rng=np.random.default_rng()), "true_rate"),
    (lambda: sensors.gyro_readings(np.zeros((5, 3)), 0.01, rng=np.random.default_rng(),
                                   bias=[1.0, 2.0]), "bias"),
    (lambda: sensors.gyro_readings(np.zeros((5, 3)), 0.01, rng=np.random.default_rng(),
                                   bias_random_walk=-1.0), "bias_random_walk"),
    (lambda: sensors.gyro_readings(np.zeros((5, 3)), 0.01, rng=np.random.default_rng(),
                                   bandwidth=60.0), "bandwidth"),
    (lambda: sensors.accelerometer_readings(np.zeros((5, 3)), 0.01, rng=np.random.default_rng(),
                                            vibration_amplitude=-0.1), "vibration_amplitude"),
    (lambda: sensors.magnetometer_readings(np.zeros((5, 3)), 0.01, rng=np.random.default_rng(),
                                           noise_std=-1e-7), "noise_std"),
])
def test_bad_input(call, match):
    with pytest.raises(ValueError, match=match):
        call()


def test_magnetometer_full_scale_from_the_datasheet():
    # Gain 1090 counts/G and the largest count 2047: 2047/1090 G (exact arithmetic; rounding only).
    assert_allclose(sensors.magnetometer_full_scale(1090.0e4), 2047 / 1090 * 1e-4, rtol=1e-15)
    assert sensors.HMC5883L_GAINS[1] == (1.3, 1090.0)


def test_every_recommended_range_lies_inside_its_full_scale():
    # The datasheet recommends each range within what the registers can hold: a property of
    # the table, not of our choice. Ranges in gauss, gains in counts per gauss.
    for rng, gain in sensors.HMC5883L_GAINS:
        assert sensors.magnetometer_full_scale(gain * 1e4) * 1e4 >= rng
    gains = [g for _, g in sensors.HMC5883L_GAINS]
    assert gains == sorted(gains, reverse=True)      # wider range, lower gain


@pytest.mark.parametrize("kw, name", [({"gain": 0.0}, "gain"), ({"gain": -1.0}, "gain"),
                                      ({"max_count": 0}, "max_count")])
def test_magnetometer_full_scale_bad_input(kw, name):
    args = {"gain": 1090.0e4} | kw
    with pytest.raises(ValueError, match=name):
        sensors.magnetometer_full_scale(**args)


def test_roll_readings_are_the_gyro_and_accelerometer_models_of_the_roll():
    """The gyro reads the mean rate over each interval, the accelerometer g·(0, sin θ, cos θ),
    drawn from one generator in that order: equal to the two models called by hand."""
    dt = 0.01
    angle = 0.4 * np.sin(np.linspace(0.0, 6.0, 300))
    gyro, accel = sensors.roll_readings(angle, dt, rng=np.random.default_rng(4), gyro_bias=0.01,
                                        vibration_amplitude=[0.0, 0.5, 0.0], vibration_frequency=[0.0, 7.0, 0.0])
    rng = np.random.default_rng(4)
    rate = np.concatenate([[0.0], np.diff(angle)]) / dt
    g = 9.80665
    expected_gyro = sensors.gyro_readings(rate, dt, rng=rng, bias=0.01)
    expected_accel = sensors.accelerometer_readings(
        g * np.stack([np.zeros_like(angle), np.sin(angle), np.cos(angle)], axis=1), dt, rng=rng,
        vibration_amplitude=[0.0, 0.5, 0.0], vibration_frequency=[0.0, 7.0, 0.0])
    assert np.array_equal(gyro, expected_gyro) and np.array_equal(accel, expected_accel)


def test_heading_readings_see_the_heading_in_the_magnetometer_only():
    """Turning about the vertical: the accelerometer reads (0, 0, g) whatever the heading,
    the magnetometer B·(cos ψ, −sin ψ, 0) (its heading atan2(−b_y, b_x) is ψ within noise)."""
    psi = np.linspace(0.0, 2.0, 400)
    b0 = 20e-6
    gyro, accel, mag = sensors.heading_readings(psi, b0, 0.01, rng=np.random.default_rng(5))
    assert gyro.shape == (400,) and accel.shape == mag.shape == (400, 3)
    # 6σ of the datasheet noise: accelerometer 400 µg/√Hz at 50 Hz, magnetometer 0.2 µT.
    sigma_a = sensors.noise_std_from_density(sensors.MPU6050_ACCEL_NOISE_DENSITY, 0.01)
    assert_allclose(accel, np.tile([0.0, 0.0, 9.80665], (400, 1)), atol=6 * sigma_a)
    assert_allclose(np.arctan2(-mag[:, 1], mag[:, 0]), psi, atol=6 * sensors.HMC5883L_NOISE_FLOOR / b0)


@pytest.mark.parametrize("call, match", [
    (lambda: sensors.roll_readings(np.zeros((5, 2)), 0.01, rng=np.random.default_rng(1)), "roll_angle"),
    (lambda: sensors.roll_readings(np.zeros(5), -0.01, rng=np.random.default_rng(1)), "dt"),
    (lambda: sensors.heading_readings(np.zeros(5), -1e-6, 0.01, rng=np.random.default_rng(1)), "field"),
    (lambda: sensors.heading_readings(np.zeros(5), 1e-6, 0.01, rng=1), "rng"),
])
def test_motion_readings_name_bad_input(call, match):
    with pytest.raises(ValueError, match=match):
        call()
