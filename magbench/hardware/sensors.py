r"""Models of the bench's inertial and magnetic sensors: what they read for a true input.

The thesis's bench (thesis §4.2) carries an InvenSense MPU-6050 (3-axis gyro and
accelerometer, GY-521 board) and a Honeywell HMC5883L 3-axis magnetometer. These models
add the error terms the datasheets specify to a true signal, so that estimators and
closed-loop simulations can be run with realistic sensors.

Conventions
-----------
- SI in and out: rad/s, m/s² (specific force: at rest the accelerometer reads
  +9.81 m/s² *upwards*), tesla.
- Time runs along axis 0; any trailing axes (3 sensor axes, Monte Carlo members, ...)
  are independent channels. Every error parameter broadcasts against one sample
  (``true[0]``).
- Randomness only through the explicit ``rng`` argument (a ``numpy.random.Generator``):
  the same seed gives the same readings.
- White noise: the datasheets give a noise *density* [unit/√Hz]; the sample standard
  deviation is density·√bandwidth, where bandwidth is the noise bandwidth of the
  sensor's digital low-pass filter. The default bandwidth is the Nyquist frequency
  1/(2Δt) (no filtering below the sample rate). The samples are drawn independent; a
  bandwidth well below Nyquist would make real samples correlated, which this model
  does not reproduce.

Datasheets
----------
- InvenSense, *MPU-6000 and MPU-6050 Product Specification*, PS-MPU-6000A-00,
  revision 3.4 (2013-08-19): Table 6.1 (gyroscope) and Table 6.2 (accelerometer).
- Honeywell, *3-Axis Digital Compass IC HMC5883L*, form 900405, revision E
  (February 2013): specifications table.
"""

import numpy as np
from scipy.constants import g as STANDARD_GRAVITY

from .._validate import as_finite, as_nonnegative, as_positive, as_positive_scalar, shown

__all__ = [
    "MPU6050_GYRO_NOISE_DENSITY",
    "MPU6050_GYRO_TOTAL_RMS_NOISE",
    "MPU6050_GYRO_ZRO_TOLERANCE",
    "MPU6050_ACCEL_NOISE_DENSITY",
    "MPU6050_ACCEL_ZERO_G_TOLERANCE",
    "MPU6050_DLPF_BANDWIDTH",
    "HMC5883L_NOISE_FLOOR",
    "HMC5883L_MAX_OUTPUT_RATE",
    "HMC5883L_GAINS",
    "HMC5883L_MAX_COUNT",
    "noise_std_from_density",
    "magnetometer_full_scale",
    "gyro_readings",
    "accelerometer_readings",
    "magnetometer_readings",
    "roll_readings",
    "heading_readings",
]

_DEG = np.pi / 180.0

#: MPU-6050 gyro rate-noise spectral density [rad/s/√Hz]: 0.005 °/s/√Hz at 10 Hz
#: (PS-MPU-6000A-00 rev. 3.4, Table 6.1, "Rate Noise Spectral Density").
MPU6050_GYRO_NOISE_DENSITY = 0.005 * _DEG

#: MPU-6050 gyro total RMS noise [rad/s]: 0.05 °/s rms with DLPFCFG = 2 (100 Hz)
#: (Table 6.1, "Total RMS Noise"); equals the density times √(100 Hz).
MPU6050_GYRO_TOTAL_RMS_NOISE = 0.05 * _DEG

#: MPU-6050 gyro initial zero-rate-output tolerance [rad/s]: ±20 °/s at 25 °C (Table 6.1).
#: A bound, not a typical value: the bench calibrates the offset at start-up.
MPU6050_GYRO_ZRO_TOLERANCE = 20.0 * _DEG

#: MPU-6050 accelerometer noise power spectral density [m/s²/√Hz]: 400 µg/√Hz at 10 Hz
#: (PS-MPU-6000A-00 rev. 3.4, Table 6.2, "Noise Performance"), g = 9.80665 m/s².
MPU6050_ACCEL_NOISE_DENSITY = 400e-6 * STANDARD_GRAVITY

#: MPU-6050 accelerometer zero-g initial calibration tolerance, X and Y axes [m/s²]:
#: ±50 mg (Table 6.2; ±80 mg for Z). A bound, not a typical value.
MPU6050_ACCEL_ZERO_G_TOLERANCE = 50e-3 * STANDARD_GRAVITY

#: Noise bandwidth of the MPU-6050 digital low-pass filter at which the datasheet
#: states the gyro's total RMS noise [Hz] (DLPFCFG = 2, Table 6.1).
MPU6050_DLPF_BANDWIDTH = 100.0

#: HMC5883L noise floor [T]: 2 milligauss standard deviation over 100 samples at
#: VDD = 3.0 V, GN = 0, no averaging (form 900405 rev. E, specifications table).
HMC5883L_NOISE_FLOOR = 2e-3 * 1e-4

#: HMC5883L maximum output rate in continuous-measurement mode [Hz] (75 Hz, same table).
HMC5883L_MAX_OUTPUT_RATE = 75.0

#: HMC5883L gain settings, in the datasheet's units (form 900405 rev. E, "Configuration
#: Register B", gain table): recommended field range [gauss] and gain [counts per gauss],
#: for GN = 0 … 7. Multiply the gain by 1e4 for counts per tesla.
HMC5883L_GAINS = ((0.88, 1370.0), (1.3, 1090.0), (1.9, 820.0), (2.5, 660.0), (4.0, 440.0),
                  (4.7, 390.0), (5.6, 330.0), (8.1, 230.0))

#: Largest HMC5883L output [counts]: the data registers hold −2048 … 2047 and read
#: −4096 on overflow (same datasheet, "Data Output Registers").
HMC5883L_MAX_COUNT = 2047


def _check_rng(rng):
    if not isinstance(rng, np.random.Generator):
        raise ValueError(
            f"rng must be a numpy.random.Generator (e.g. numpy.random.default_rng(seed)), "
            f"got {type(rng).__name__}"
        )
    return rng


def _check_series(name, value):
    arr = as_finite(name, value)
    if arr.ndim == 0 or arr.shape[0] < 1:
        raise ValueError(f"{name} must be an array with time along axis 0, got shape {arr.shape}")
    return arr


def _channel(name, value, sample_shape, *, nonnegative=False):
    arr = as_nonnegative(name, value) if nonnegative else as_finite(name, value)
    try:
        return np.broadcast_to(arr, sample_shape)
    except ValueError:
        raise ValueError(
            f"{name} must broadcast against one sample of shape {sample_shape}, got shape {arr.shape}"
        ) from None


def magnetometer_full_scale(gain, max_count=HMC5883L_MAX_COUNT):
    r"""Largest flux density a digital magnetometer reports before its output overflows.

    Parameters
    ----------
    gain : array_like
        Gain setting [counts/T], > 0 (the HMC5883L's 1090 counts/G is 1.09e7 counts/T).
    max_count : array_like, optional
        Largest output count [counts], > 0; default :data:`HMC5883L_MAX_COUNT`.

    Returns
    -------
    ndarray
        Full scale B_max = max_count / gain [T].

    Notes
    -----
    Not in the thesis: Honeywell HMC5883L datasheet, form 900405 rev. E (gain table and
    output registers). The thesis measured its simulator's centre field with this sensor
    (thesis §2.4); a field above the full scale of the chosen gain reads as overflow.

    Examples
    --------
    >>> round(float(magnetometer_full_scale(1090.0e4)) * 1e4, 4)   # gauss, at GN = 1
    1.878
    """
    g = as_positive("gain", gain, unit="counts/T")
    n = as_positive("max_count", max_count, unit="counts")
    return n / g


def noise_std_from_density(density, dt, bandwidth=None):
    r"""Standard deviation of white-noise samples from a noise density.

    Parameters
    ----------
    density : array_like
        One-sided noise amplitude spectral density [unit/√Hz], >= 0.
    dt : float
        Sample interval [s], > 0.
    bandwidth : float, optional
        Noise bandwidth of the sensor's low-pass filter [Hz], in (0, 1/(2 dt)].
        Default: the Nyquist frequency 1/(2 dt).

    Returns
    -------
    ndarray
        :math:`\sigma = \rho\sqrt{B}` [unit].

    Notes
    -----
    Not in the thesis: white noise of one-sided density ρ has variance ρ²B in a band B.
    The MPU-6050 datasheet's own numbers obey it (0.005 °/s/√Hz · √100 Hz = 0.05 °/s rms).

    Examples
    --------
    >>> round(float(noise_std_from_density(0.005, 0.001, bandwidth=100.0)), 12)
    0.05
    """
    rho = as_nonnegative("density", density)
    step = as_positive_scalar("dt", dt, unit="s")
    nyquist = 0.5 / step
    if bandwidth is None:
        band = nyquist
    else:
        band = float(as_positive("bandwidth", bandwidth, unit="Hz"))
        if band > nyquist * (1.0 + 1e-12):
            raise ValueError(
                f"bandwidth must lie in (0, {nyquist:g}] Hz (the Nyquist frequency 1/(2 dt)), got {shown(band)}"
            )
    return rho * np.sqrt(band)


def gyro_readings(true_rate, dt, *, rng, noise_density=MPU6050_GYRO_NOISE_DENSITY,
                  bandwidth=None, bias=0.0, bias_random_walk=0.0):
    r"""What an MPU-6050 gyro reads for a true angular rate.

    Parameters
    ----------
    true_rate : array_like, shape (N, ...)
        True angular rate in the sensor frame [rad/s]; time along axis 0.
    dt : float
        Sample interval [s], > 0.
    rng : numpy.random.Generator
        Source of the noise [-].
    noise_density : array_like, optional
        Rate-noise density [rad/s/√Hz]; default the datasheet's 0.005 °/s/√Hz.
    bandwidth : float, optional
        Noise bandwidth of the digital low-pass filter [Hz]; default 1/(2 dt).
    bias : array_like, optional
        Constant zero-rate offset [rad/s] left after calibration; default 0 (the
        uncalibrated datasheet bound is ±20 °/s, :data:`MPU6050_GYRO_ZRO_TOLERANCE`).
    bias_random_walk : array_like, optional
        Bias drift as a rate random walk [rad/s/√s], >= 0: the bias changes by
        N(0, (K√dt)²) each sample, starting from ``bias``. Default 0: the datasheet
        gives no bias-instability figure, so drift is the user's choice.

    Returns
    -------
    ndarray, shape (N, ...)
        Gyro readings [rad/s]: true rate + bias(t) + white noise.

    Notes
    -----
    Not in the thesis: the thesis names the sensor (thesis §4.2) but no error model.
    Datasheet PS-MPU-6000A-00 rev. 3.4, Table 6.1.

    Examples
    --------
    >>> import numpy as np
    >>> w = gyro_readings(np.zeros((1000, 3)), 0.01, rng=np.random.default_rng(1), bias=0.01)
    >>> w.shape, bool(abs(w.mean() - 0.01) < 1e-3)
    ((1000, 3), True)
    """
    rng = _check_rng(rng)
    rate = _check_series("true_rate", true_rate)
    step = as_positive_scalar("dt", dt, unit="s")
    sample = rate.shape[1:]
    sigma = _channel("noise_density", noise_std_from_density(noise_density, step, bandwidth), sample)
    offset = _channel("bias", bias, sample)
    walk = _channel("bias_random_walk", bias_random_walk, sample, nonnegative=True)
    # A zero walk draws nothing: a Monte Carlo of 10^6 samples per member would otherwise
    # spend a third of its time drawing and summing zeros.
    drift = (np.cumsum(rng.standard_normal(rate.shape) * (walk * np.sqrt(step)), axis=0)
             if np.any(walk) else 0.0)
    return rate + offset + drift + sigma * rng.standard_normal(rate.shape)


def accelerometer_readings(true_specific_force, dt, *, rng,
                           noise_density=MPU6050_ACCEL_NOISE_DENSITY, bandwidth=None,
                           bias=0.0, vibration_amplitude=0.0, vibration_frequency=0.0):
    r"""What an MPU-6050 accelerometer reads for a true specific force.

    Parameters
    ----------
    true_specific_force : array_like, shape (N, ...)
        True specific force (acceleration minus gravity) in the sensor frame [m/s²];
        at rest it is +9.81 m/s² along the sensor's up direction. Time along axis 0.
    dt : float
        Sample interval [s], > 0.
    rng : numpy.random.Generator
        Source of the noise and of the vibration phases [-].
    noise_density : array_like, optional
        Noise density [m/s²/√Hz]; default the datasheet's 400 µg/√Hz.
    bandwidth : float, optional
        Noise bandwidth of the digital low-pass filter [Hz]; default 1/(2 dt).
    bias : array_like, optional
        Constant offset [m/s²] left after calibration; default 0 (the uncalibrated
        datasheet bound is ±50 mg on X and Y, :data:`MPU6050_ACCEL_ZERO_G_TOLERANCE`).
    vibration_amplitude : array_like, optional
        Amplitude of a sinusoidal vibration added to each channel [m/s²], >= 0; default 0.
    vibration_frequency : array_like, optional
        Its frequency [Hz], >= 0; each channel gets an independent uniform random phase.

    Returns
    -------
    ndarray, shape (N, ...)
        Accelerometer readings [m/s²]: specific force + bias + vibration + white noise.

    Notes
    -----
    Not in the thesis: datasheet PS-MPU-6000A-00 rev. 3.4, Table 6.2. The vibration term
    stands for mechanical disturbances (fans, the thread's pendulum motion, a driver's
    PWM) that an accelerometer cannot tell from gravity.

    Examples
    --------
    >>> import numpy as np
    >>> f = accelerometer_readings(np.tile([0.0, 0.0, 9.81], (500, 1)), 0.01,
    ...                            rng=np.random.default_rng(2))
    >>> bool(np.allclose(f.mean(axis=0), [0.0, 0.0, 9.81], atol=0.01))
    True
    """
    rng = _check_rng(rng)
    force = _check_series("true_specific_force", true_specific_force)
    step = as_positive_scalar("dt", dt, unit="s")
    sample = force.shape[1:]
    sigma = _channel("noise_density", noise_std_from_density(noise_density, step, bandwidth), sample)
    offset = _channel("bias", bias, sample)
    amplitude = _channel("vibration_amplitude", vibration_amplitude, sample, nonnegative=True)
    frequency = _channel("vibration_frequency", vibration_frequency, sample, nonnegative=True)
    time = (np.arange(force.shape[0]) * step).reshape((-1,) + (1,) * len(sample))
    phase = rng.uniform(0.0, 2.0 * np.pi, size=sample)
    vibration = amplitude * np.sin(2.0 * np.pi * frequency * time + phase)
    return force + offset + vibration + sigma * rng.standard_normal(force.shape)


def magnetometer_readings(true_field, dt, *, rng, noise_std=HMC5883L_NOISE_FLOOR,
                          offset=0.0):
    r"""What an HMC5883L magnetometer reads for a true magnetic flux density.

    Parameters
    ----------
    true_field : array_like, shape (N, ...)
        True flux density in the sensor frame [T]; time along axis 0.
    dt : float
        Sample interval [s], > 0; the sensor outputs at most 75 Hz in continuous mode,
        so dt below 1/75 s repeats samples on the bench (not modelled here).
    rng : numpy.random.Generator
        Source of the noise [-].
    noise_std : array_like, optional
        Per-sample noise standard deviation [T], >= 0; default the datasheet's noise floor
        of 2 mG = 0.2 µT.
    offset : array_like, optional
        Hard-iron offset (field of magnetised parts fixed to the sensor) [T]; default 0.

    Returns
    -------
    ndarray, shape (N, ...)
        Magnetometer readings [T]: field + offset + white noise.

    Notes
    -----
    Not in the thesis: Honeywell HMC5883L datasheet, form 900405 rev. E. The datasheet
    states the noise as a per-sample standard deviation, not a density, so ``dt`` only
    enters through the shape check.

    Examples
    --------
    >>> import numpy as np
    >>> b = magnetometer_readings(np.tile([20e-6, 0.0, 45e-6], (200, 1)), 0.02,
    ...                           rng=np.random.default_rng(3))
    >>> bool(np.allclose(b.mean(axis=0), [20e-6, 0.0, 45e-6], atol=1e-7))
    True
    """
    rng = _check_rng(rng)
    field = _check_series("true_field", true_field)
    as_positive_scalar("dt", dt, unit="s")
    sample = field.shape[1:]
    sigma = _channel("noise_std", noise_std, sample, nonnegative=True)
    bias = _channel("offset", offset, sample)
    return field + bias + sigma * rng.standard_normal(field.shape)


def _mean_rate(angle, step):
    """Rate each gyro sample carries: the mean over the interval before it [rad/s] (zero first)."""
    return np.diff(angle, prepend=angle[0]) / step


def _angle_series(name, value):
    angle = _check_series(name, value)
    if angle.ndim != 1:
        raise ValueError(f"{name} must be one angle per sample, shape (N,), got shape {angle.shape}")
    return angle


def roll_readings(roll_angle, dt, *, rng, gyro_bias=0.0, vibration_amplitude=0.0, vibration_frequency=0.0):
    r"""What an MPU-6050 reads while it rolls about its x axis, z up when level.

    Parameters
    ----------
    roll_angle : array_like, shape (N,)
        Roll angle θ at each sample [rad].
    dt : float
        Sample interval [s], > 0.
    rng : numpy.random.Generator
        Source of the noise and the vibration phases [-]; the gyro draws first.
    gyro_bias : array_like, optional
        Gyro zero-rate offset [rad/s] (:func:`gyro_readings`); default 0.
    vibration_amplitude : array_like, optional
        Accelerometer vibration amplitude [m/s²], >= 0, scalar or per axis (3,)
        (:func:`accelerometer_readings`); default 0.
    vibration_frequency : array_like, optional
        Its frequency [Hz], >= 0, scalar or per axis (3,); default 0.

    Returns
    -------
    gyro_rate : ndarray, shape (N,)
        Gyro x readings [rad/s]; sample k carries the mean rate over the interval before it,
        (θ_k − θ_{k−1})/Δt (zero for the first).
    specific_force : ndarray, shape (N, 3)
        Accelerometer readings [m/s²] of the specific force g·(0, sin θ, cos θ).

    Notes
    -----
    Not in the thesis: the thesis's filter, eq. (39), takes a gyro rate and an
    accelerometer angle atan2(a_y, a_z); these are the readings a slow roll gives
    (no centripetal or tangential acceleration).

    Examples
    --------
    >>> w, f = roll_readings(np.zeros(100), 0.01, rng=np.random.default_rng(1))
    >>> w.shape, f.shape, bool(abs(f[:, 2].mean() - STANDARD_GRAVITY) < 0.01)
    ((100,), (100, 3), True)
    """
    angle = _angle_series("roll_angle", roll_angle)
    step = as_positive_scalar("dt", dt, unit="s")
    gyro = gyro_readings(_mean_rate(angle, step), step, rng=rng, bias=gyro_bias)
    force = STANDARD_GRAVITY * np.stack([np.zeros(angle.size), np.sin(angle), np.cos(angle)], axis=1)
    accel = accelerometer_readings(force, step, rng=rng, vibration_amplitude=vibration_amplitude,
                                   vibration_frequency=vibration_frequency)
    return gyro, accel


def heading_readings(heading, field, dt, *, rng, gyro_bias=0.0):
    r"""What an MPU-6050 and an HMC5883L read while they turn about the vertical in a
    horizontal field.

    Parameters
    ----------
    heading : array_like, shape (N,)
        Heading ψ at each sample [rad]: the angle from the field to the sensors' x axis,
        positive about z (up).
    field : float
        Magnitude of the horizontal flux density [T], >= 0.
    dt : float
        Sample interval [s], > 0.
    rng : numpy.random.Generator
        Source of the noise [-]; gyro, accelerometer and magnetometer draw in this order.
    gyro_bias : array_like, optional
        Gyro zero-rate offset [rad/s]; default 0.

    Returns
    -------
    gyro_rate : ndarray, shape (N,)
        Gyro z readings [rad/s]; sample k carries the mean rate over the interval before it.
    specific_force : ndarray, shape (N, 3)
        Accelerometer readings [m/s²] of (0, 0, g): the same for every heading.
    flux_density : ndarray, shape (N, 3)
        Magnetometer readings [T] of B·(cos ψ, −sin ψ, 0).

    Notes
    -----
    Not in the thesis: thesis §4.2 blends the gyro with an "accelerometer angle"; turning
    about the vertical, gravity is parallel to the rotation axis and the accelerometer
    cannot see the heading, while the magnetometer can.

    Examples
    --------
    >>> w, f, b = heading_readings(np.zeros(50), 20e-6, 0.01, rng=np.random.default_rng(1))
    >>> b.shape, bool(abs(b[:, 0].mean() - 20e-6) < 1e-7)
    ((50, 3), True)
    """
    psi = _angle_series("heading", heading)
    as_nonnegative("field", field, unit="T")
    step = as_positive_scalar("dt", dt, unit="s")
    n = psi.size
    gyro = gyro_readings(_mean_rate(psi, step), step, rng=rng, bias=gyro_bias)
    force = np.tile([0.0, 0.0, STANDARD_GRAVITY], (n, 1))
    accel = accelerometer_readings(force, step, rng=rng)
    b_true = field * np.stack([np.cos(psi), -np.sin(psi), np.zeros(n)], axis=1)
    return gyro, accel, magnetometer_readings(b_true, step, rng=rng)
