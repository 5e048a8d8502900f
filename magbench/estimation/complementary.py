r"""The complementary filter of thesis §4.2, eq. (39): one step, a whole series, its
time constant, the steady error a constant gyro offset leaves through it, and the
steady error terms of sensor noise and vibration.

The filter blends the integrated gyro rate with an absolute angle from another sensor.
SI: radians, rad/s, seconds.
"""

import numpy as np
from scipy.constants import g as STANDARD_GRAVITY
from scipy.signal import lfilter
from scipy.special import j0

from .._validate import as_finite, as_in_range, as_nonnegative, as_positive

__all__ = ["complementary_filter_step", "complementary_filter", "complementary_time_constant", "gyro_offset_error",
           "complementary_error_terms"]


def complementary_filter_step(angle, gyro_rate, reference_angle, dt, alpha):
    r"""One update of the complementary filter, for use inside a simulation loop.

    Parameters
    ----------
    angle : array_like
        Filtered angle of the previous step [rad].
    gyro_rate : array_like
        Gyro rate about the same axis at this step [rad/s].
    reference_angle : array_like
        Absolute angle from the reference sensor at this step [rad].
    dt : array_like
        Step length [s].
    alpha : array_like
        Filter coefficient A in [0, 1] [-].

    Returns
    -------
    ndarray
        The new filtered angle [rad],
        :math:`A\,(\text{angle} + \omega\,\Delta t) + (1 - A)\,\text{angle}_{ref}`.

    Notes
    -----
    Thesis eq. (39). No argument checks: the loop that calls this checks
    its inputs once (see :func:`complementary_filter`).

    Examples
    --------
    >>> float(complementary_filter_step(0.0, 1.0, 0.0, 0.01, 0.98))
    0.0098
    """
    return alpha * (angle + gyro_rate * dt) + (1.0 - alpha) * reference_angle


def complementary_filter(gyro_rate, accel_angle, dt, alpha, initial_angle=None):
    r"""The thesis's complementary filter over a whole record, vectorised over time.

    Parameters
    ----------
    gyro_rate : array_like, shape (N, ...)
        Gyro rate about the filtered axis [rad/s]; time runs along axis 0, further axes
        are independent channels (for instance Monte Carlo members).
    accel_angle : array_like, shape (N, ...)
        Absolute angle from the accelerometer (or any absolute reference) [rad],
        broadcastable against ``gyro_rate``.
    dt : float or array_like, shape (N,)
        Sample interval [s], > 0; an array gives the interval before each sample.
    alpha : float
        Filter coefficient A [-] in [0, 1]; the thesis uses 0.95–0.99.
    initial_angle : array_like, optional
        Filtered angle before the first sample [rad]. Default: the first reference angle.

    Returns
    -------
    ndarray, shape (N, ...)
        Filtered angle [rad]:
        :math:`\theta_k = A(\theta_{k-1} + \omega_k\Delta t_k) + (1 - A)\,\theta_{ref,k}`.

    Notes
    -----
    Thesis eq. (39), in the discrete form the thesis implies
    (its angle_gyro is the previous filtered angle advanced by the gyro). The recursion is
    linear with a constant pole A, so it runs as one IIR filter (scipy.signal.lfilter)
    instead of a Python loop. A = 0 returns the reference angle; A = 1 the gyro integral.
    The filter does not unwrap angles: pass continuous angles (np.unwrap) when they
    cross ±π.

    Examples
    --------
    >>> complementary_filter([0.0, 0.0, 0.0], [1.0, 1.0, 1.0], 0.01, 0.5, initial_angle=0.0)
    array([0.5  , 0.75 , 0.875])
    """
    gyro = as_finite("gyro_rate", gyro_rate)
    ref = as_finite("accel_angle", accel_angle)
    if gyro.ndim == 0:
        raise ValueError("gyro_rate must be an array with time along axis 0, got a scalar")
    gyro, ref = np.broadcast_arrays(gyro, ref)
    n = gyro.shape[0]
    if n == 0:
        raise ValueError("gyro_rate and accel_angle must hold at least one sample along axis 0, got none")
    step = as_positive("dt", dt, unit="s")
    if step.ndim == 1 and step.shape[0] == n:
        step = step.reshape((n,) + (1,) * (gyro.ndim - 1))
    elif step.ndim != 0:
        raise ValueError(f"dt must be a scalar or have shape ({n},), got shape {step.shape}")
    a = float(as_in_range("alpha", alpha, 0.0, 1.0))
    start = ref[0] if initial_angle is None else as_finite("initial_angle", initial_angle)
    start = np.broadcast_to(start, gyro.shape[1:])
    drive = a * gyro * step + (1.0 - a) * ref
    filtered, _ = lfilter([1.0], [1.0, -a], drive, axis=0, zi=(a * start)[np.newaxis])
    return filtered


def complementary_time_constant(dt, alpha):
    r"""Time constant of the complementary filter [s].

    Parameters
    ----------
    dt : array_like
        Sample interval [s], > 0.
    alpha : array_like
        Filter coefficient A [-] in [0, 1).

    Returns
    -------
    ndarray
        :math:`\tau = A\,\Delta t / (1 - A)` [s]: the reference enters through a first-order
        low-pass with this time constant, the gyro through the complementary high-pass.

    Notes
    -----
    Not in the thesis or the sources: follows from eq. (39).

    Examples
    --------
    >>> round(float(complementary_time_constant(0.01, 0.98)), 12)
    0.49
    """
    step = as_positive("dt", dt, unit="s")
    a = as_in_range("alpha", alpha, 0.0, np.nextafter(1.0, 0.0))
    return a * step / (1.0 - a)


def gyro_offset_error(offset, filter_coefficient, sample_interval):
    r"""Steady pointing error a constant gyro offset leaves through the filter [rad].

    Parameters
    ----------
    offset : array_like
        Gyro zero-rate offset b [rad/s].
    filter_coefficient : array_like
        A_f of thesis eq. (39) [-], in (0, 1).
    sample_interval : array_like
        Loop period Δt [s], > 0.

    Returns
    -------
    ndarray
        :math:`A_f\,b\,\Delta t/(1-A_f)`, the filter's fixed point at rest: the controller
        holds the estimate on target and the mock-up sits this far beside it.

    Notes
    -----
    Thesis eq. (39) at rest with the gyro reading the offset b: the fixed point of
    ψ̂ = A_f(ψ̂ + bΔt) + (1 − A_f)ψ is ψ̂ − ψ = A_f bΔt/(1 − A_f). Not in the thesis as a
    formula; chapter 4's bench and error budget score the gyro's offset by it.

    Examples
    --------
    >>> round(float(gyro_offset_error(0.01, 0.98, 0.01)), 6)
    0.0049
    """
    a = np.asarray(filter_coefficient, float)
    dt = np.asarray(sample_interval, float)
    if np.any(~np.isfinite(a) | (a <= 0) | (a >= 1)):
        raise ValueError(f"filter_coefficient must lie in (0, 1), got {a}")
    if np.any(~np.isfinite(dt) | (dt <= 0)):
        raise ValueError(f"sample_interval must be > 0 s, got {dt}")
    # b·τ: the filter's time constant written once (complementary_time_constant)
    return np.asarray(offset, float) * complementary_time_constant(dt, a)


def complementary_error_terms(sample_interval, alpha, gyro_offset, gyro_noise_std, accel_noise_std,
                              vibration_amplitude, vibration_frequency, motion_amplitude,
                              gravity=STANDARD_GRAVITY):
    r"""Closed-form steady error terms of the complementary filter on a roll angle [rad].

    Parameters
    ----------
    sample_interval : float
        Δt [s], > 0.
    alpha : array_like
        Filter coefficient A [-] in [0, 1).
    gyro_offset : array_like
        Constant gyro offset b [rad/s].
    gyro_noise_std : array_like
        Per-sample standard deviation of the gyro's white noise σ_ω [rad/s], >= 0.
    accel_noise_std : array_like
        Per-sample standard deviation of the accelerometer's white noise σ_a [m/s²], >= 0.
    vibration_amplitude : array_like
        Amplitude a_v of a sinusoidal vibration on the accelerometer's y axis [m/s²], >= 0.
    vibration_frequency : float
        Its frequency f_v [Hz], >= 0.
    motion_amplitude : array_like
        Amplitude θ0 of the sinusoidal roll [rad].
    gravity : float, optional
        g [m/s²], > 0; default standard gravity.

    Returns
    -------
    offset, accel_noise, vibration, gyro_noise : ndarray
        Each [rad]: a gyro offset b gives the constant offset b·τ with τ = AΔt/(1−A);
        accelerometer noise (angle std σ_a/g) passes the low-pass with variance gain
        (1−A)/(1+A); the vibration (angle amplitude ≈ a_v cos θ/g, cos θ at its RMS over the
        roll, √((1 + J0(2θ0))/2)) passes with the gain |(1−A)/(1−A e^{−jωΔt})| at its
        frequency, as an RMS; gyro noise σ_ω is integrated with gain AΔt, variance gain
        A²Δt²/(1−A²). The terms add in quadrature to the RMS error.

    Notes
    -----
    Thesis eq. (39) as a linear filter: the error terms are not in the thesis.

    Examples
    --------
    >>> terms = complementary_error_terms(0.01, 0.98, 0.001, 0.0, 0.0, 0.0, 7.0, 0.0)
    >>> [round(float(t), 8) for t in terms]
    [0.00049, 0.0, 0.0, 0.0]
    """
    as_positive("sample_interval", sample_interval, unit="s")
    as_finite("gyro_offset", gyro_offset)
    as_nonnegative("gyro_noise_std", gyro_noise_std, unit="rad/s")
    as_nonnegative("accel_noise_std", accel_noise_std, unit="m/s²")
    as_nonnegative("vibration_amplitude", vibration_amplitude, unit="m/s²")
    as_nonnegative("vibration_frequency", vibration_frequency, unit="Hz")
    as_finite("motion_amplitude", motion_amplitude)
    as_positive("gravity", gravity, unit="m/s²")
    tau = complementary_time_constant(sample_interval, alpha)
    acc_std = accel_noise_std / gravity
    # RMS of cos θ over a sine of amplitude θ0: sqrt((1 + J0(2θ0))/2).
    cos_rms = np.sqrt(0.5 * (1 + j0(2 * motion_amplitude)))
    z = np.exp(1j * 2 * np.pi * vibration_frequency * sample_interval)
    gain = np.abs((1 - alpha) / (1 - alpha / z))
    vib = vibration_amplitude / gravity * cos_rms / np.sqrt(2) * gain
    acc = acc_std * np.sqrt((1 - alpha) / (1 + alpha))
    gyr = gyro_noise_std * alpha * sample_interval / np.sqrt(1 - alpha**2)
    return gyro_offset * tau, acc, vib, gyr
