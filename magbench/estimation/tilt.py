r"""Three-dimensional tilt from a gyro and an accelerometer: accelerometer tilt, strapdown
integration, the rest bias of the gyro, and the complementary tilt estimator.

Not in the sources beyond thesis §4.2's one-axis filter: it extends eq. (39) to
quaternions (a quaternion complementary filter, cf. Laidig and Seel, VQF). SI.
"""

import numpy as np
from scipy.signal import butter, lfilter, lfilter_zi
from scipy.spatial.transform import Rotation

from .._validate import as_finite, as_nonnegative, as_positive, as_positive_scalar, as_vectors, shown
from ..rotations import hamilton_product
from .complementary import complementary_filter

__all__ = ["accelerometer_tilt", "strapdown_orientation", "rest_gyro_bias", "complementary_tilt"]


def _rotations(quaternions):
    """scipy Rotation from (..., 4) quaternions in (w, x, y, z) order."""
    return Rotation.from_quat(quaternions, scalar_first=True)


def _quaternions(rotations):
    """(..., 4) quaternions in (w, x, y, z) order from a scipy Rotation."""
    return rotations.as_quat(scalar_first=True)


def _check_series3(name, value):
    arr = as_vectors(name, value)
    if arr.ndim != 2 or arr.shape[0] < 1:
        raise ValueError(f"{name} must have shape (N, 3) with N >= 1, got shape {arr.shape}")
    return arr


def accelerometer_tilt(accel):
    r"""Tilt from the accelerometer alone: the shortest rotation that turns the measured
    specific force to the Earth's up axis.

    Parameters
    ----------
    accel : array_like, shape (N, 3)
        Specific force in the sensor frame [m/s²]; at rest it points up. No sample may be
        zero.

    Returns
    -------
    ndarray, shape (N, 4)
        Unit quaternions (w, x, y, z) rotating sensor-frame vectors into an Earth frame
        with z up; the heading is that of the shortest arc (arbitrary but continuous).

    Notes
    -----
    Not in the thesis: the 3-D form of the thesis's accelerometer angle (§4, eq. 39's
    angle_acc). Exact at rest; during motion the acceleration tilts it (the reason for
    the complementary filter). A sample pointing exactly down has no unique shortest arc;
    the rotation by π about the sensor x axis is returned.

    Examples
    --------
    >>> q = accelerometer_tilt([[0.0, 0.0, 9.81], [9.81, 0.0, 0.0]])
    >>> np.round(q, 6).tolist()
    [[1.0, 0.0, 0.0, 0.0], [0.707107, 0.0, -0.707107, 0.0]]
    """
    acc = _check_series3("accel", accel)
    norm = np.linalg.norm(acc, axis=-1)
    if np.any(norm == 0):
        raise ValueError(f"accel must be non-zero in every sample, got a zero vector at index "
                         f"{int(np.flatnonzero(norm == 0)[0])}")
    u = acc / norm[:, np.newaxis]
    # Half-angle form of the shortest arc u -> e_z: q ∝ (1 + u_z, u_y, -u_x, 0).
    q = np.stack([1.0 + u[:, 2], u[:, 1], -u[:, 0], np.zeros(len(u))], axis=-1)
    down = q[:, 0] < 1e-12
    q[down] = [0.0, 1.0, 0.0, 0.0]
    return q / np.linalg.norm(q, axis=-1, keepdims=True) + 0.0   # + 0.0: no negative zeros


def strapdown_orientation(gyro, dt, initial_orientation=None):
    r"""Orientation from the gyro alone: the product of the per-sample rotations.

    Parameters
    ----------
    gyro : array_like, shape (N, 3)
        Angular rate in the sensor frame [rad/s]; sample k rotates the sensor during the
        interval before it.
    dt : float
        Sample interval [s], > 0.
    initial_orientation : array_like, shape (4,), optional
        Unit quaternion (w, x, y, z) [-] before the first sample; default identity.

    Returns
    -------
    ndarray, shape (N, 4)
        Unit quaternions (w, x, y, z) rotating sensor-frame vectors into the frame of the
        initial orientation: :math:`q_k = q_{k-1}\otimes\exp(\omega_k\Delta t/2)`.

    Notes
    -----
    Not in the thesis: the 3-D form of eq. (39)'s angle_gyro (angle + ω·Δt), which is
    exact only for rotation about one fixed axis. The per-sample rotations are
    composed in a parallel prefix product (log₂N vectorised passes of the Hamilton
    product) instead of a Python loop; rounding grows with log N, not N. Errors of the gyro
    (bias, noise) accumulate without bound.

    Examples
    --------
    >>> q = strapdown_orientation(np.tile([0.0, 0.0, np.pi / 2], (100, 1)), 0.01)
    >>> np.round(q[-1], 12).tolist()   # 90° about z after 1 s
    [0.707106781187, 0.0, 0.0, 0.707106781187]
    """
    rate = _check_series3("gyro", gyro)
    step = as_positive_scalar("dt", dt, unit="s")
    prefix = _quaternions(Rotation.from_rotvec(rate * step))
    shift = 1
    while shift < len(prefix):
        # Hillis–Steele scan: P[i] <- P[i - shift] ⊗ P[i] (order kept: composition is not
        # commutative, associativity is all the scan needs).
        prefix[shift:] = hamilton_product(prefix[:-shift], prefix[shift:])
        shift *= 2
    prefix /= np.linalg.norm(prefix, axis=-1, keepdims=True)
    if initial_orientation is not None:
        start = as_finite("initial_orientation", initial_orientation)
        if start.shape != (4,) or not np.isclose(np.linalg.norm(start), 1.0, atol=1e-6):
            raise ValueError(f"initial_orientation must be a unit quaternion of shape (4,), got {shown(start)}")
        prefix = _quaternions(_rotations(start) * _rotations(prefix))
    return prefix


def _first_order_lowpass(signal, dt, tau):
    """Eq. (39) with no gyro term, y_k = A y_{k-1} + (1 - A) x_k, A = tau/(tau + dt), y_0 = x_0."""
    alpha = tau / (tau + dt)
    return complementary_filter(np.zeros_like(signal), signal, dt, alpha)


def _lowpass_from_mean(signal, dt, tau, order):
    """Low-pass along axis 0, started from the running mean of the first tau seconds.

    Until tau has elapsed the output is the mean of the samples so far (the best estimate
    of a constant from that many samples); the IIR filter then starts in steady state at
    that mean. This is how VQF initialises its filters (Laidig & Seel 2023, §3); starting
    from the first sample alone would carry that sample's error for several tau.
    """
    warmup = min(len(signal), max(1, int(round(tau / dt))))
    out = np.empty_like(signal)
    out[:warmup] = np.cumsum(signal[:warmup], axis=0) / np.arange(1, warmup + 1)[:, np.newaxis]
    rest = signal[warmup:]
    if len(rest):
        start = out[warmup - 1]
        if order == 1:
            alpha = tau / (tau + dt)
            # Eq. (39) with no gyro term: θ_k = A θ_{k-1} + (1 - A) x_k.
            out[warmup:] = complementary_filter(np.zeros_like(rest), rest, dt, alpha, initial_angle=start)
        else:
            b, a = butter(2, np.sqrt(2.0) / (2.0 * np.pi * tau), fs=1.0 / dt)
            out[warmup:], _ = lfilter(b, a, rest, axis=0, zi=lfilter_zi(b, a)[:, np.newaxis] * start)
    return out


def rest_gyro_bias(gyro, accel, dt, *, rate_threshold=np.radians(2.0), accel_threshold=0.5,
                   min_rest_time=1.5, rest_filter_tau=0.5):
    r"""Gyro bias estimated, causally, from the periods in which the sensor is at rest.

    Parameters
    ----------
    gyro : array_like, shape (N, 3)
        Angular rate in the sensor frame [rad/s].
    accel : array_like, shape (N, 3)
        Specific force in the sensor frame [m/s²].
    dt : float
        Sample interval [s], > 0.
    rate_threshold : float, optional
        Rest needs the low-passed gyro norm below this [rad/s]; default 2 °/s.
    accel_threshold : float, optional
        Rest needs the accelerometer within this of its low-passed value [m/s²];
        default 0.5 m/s².
    min_rest_time : float, optional
        Both conditions must hold this long before a sample counts as rest [s]; default 1.5 s.
    rest_filter_tau : float, optional
        Time constant of the first-order low-passes used by the tests [s]; default 0.5 s.

    Returns
    -------
    bias : ndarray, shape (N, 3)
        Estimated bias at each sample [rad/s]: the mean gyro over all rest samples up to
        and including it, 0 before the first rest. Subtract it from the gyro.
    rest : ndarray of bool, shape (N,)
        Which samples were classified as rest [-].

    Notes
    -----
    Not in the thesis: the rest detector of the VQF filter (Laidig & Seel 2023,
    Information Fusion 91, 187–204), whose published defaults these are. It assumes a
    constant bias within a record and rotation slower than ``rate_threshold`` never
    lasting ``min_rest_time`` (a turntable at 1 °/s would be taken for bias).

    Examples
    --------
    >>> n = 400
    >>> bias, rest = rest_gyro_bias(np.tile([0.01, 0.0, -0.02], (n, 1)),
    ...                             np.tile([0.0, 0.0, 9.81], (n, 1)), 0.01)
    >>> int(np.argmax(rest)), np.round(bias[-1], 12).tolist()   # rest from 1.5 s on: 150 samples
    (149, [0.01, 0.0, -0.02])
    """
    rate = _check_series3("gyro", gyro)
    acc = _check_series3("accel", accel)
    if rate.shape != acc.shape:
        raise ValueError(f"gyro and accel must have the same shape (N, 3), got {rate.shape} and {acc.shape}")
    step = as_positive_scalar("dt", dt, unit="s")
    rate_th = float(as_positive("rate_threshold", rate_threshold, unit="rad/s"))
    acc_th = float(as_positive("accel_threshold", accel_threshold, unit="m/s²"))
    min_time = float(as_nonnegative("min_rest_time", min_rest_time, unit="s"))
    tau_rest = float(as_positive("rest_filter_tau", rest_filter_tau, unit="s"))
    smooth_rate = _first_order_lowpass(rate, step, tau_rest)
    smooth_acc = _first_order_lowpass(acc, step, tau_rest)
    quiet = ((np.linalg.norm(smooth_rate, axis=1) < rate_th)
             & (np.linalg.norm(acc - smooth_acc, axis=1) < acc_th))
    index = np.arange(len(quiet))
    # Length of the quiet run ending at each sample: index minus the last loud index.
    last_loud = np.maximum.accumulate(np.where(quiet, -1, index))
    rest = quiet & ((index - last_loud) * step >= min_time)
    count = np.cumsum(rest)
    total = np.cumsum(np.where(rest[:, np.newaxis], rate, 0.0), axis=0)
    bias = np.divide(total, count[:, np.newaxis], out=np.zeros_like(total), where=count[:, np.newaxis] > 0)
    return bias, rest


def complementary_tilt(gyro, accel, dt, *, tau=3.0, order=2, rest_bias=True):
    r"""3-D tilt (inclination) from gyro and accelerometer: eq. (39) generalised.

    Parameters
    ----------
    gyro : array_like, shape (N, 3)
        Angular rate in the sensor frame [rad/s].
    accel : array_like, shape (N, 3)
        Specific force in the sensor frame [m/s²] (at rest it points up).
    dt : float
        Sample interval [s], > 0.
    tau : float, optional
        Time constant of the accelerometer low-pass [s], > 0; default 3 s. Below it
        the gyro dominates, above it the accelerometer.
    order : {1, 2}, optional
        Order of the low-pass [-]. 1: a first-order filter with pole
        A = τ/(τ + Δt), the exact 3-D counterpart of eq. (39). 2 (default): a
        second-order Butterworth with cut-off √2/(2πτ), which suppresses motion
        accelerations by 40 dB/decade instead of 20.
    rest_bias : bool, optional
        Subtract the gyro bias estimated at rest (:func:`rest_gyro_bias`, VQF's defaults)
        before integrating [-]; default True. False integrates the raw gyro.

    Returns
    -------
    ndarray, shape (N, 4)
        Unit quaternions (w, x, y, z) rotating sensor-frame vectors into an Earth frame
        whose z axis points up. The heading (rotation about z) is left free: it is
        whatever the gyro integral makes it, since gravity cannot observe it.

    Notes
    -----
    Not in the thesis: extends eq. (39) to 3-D motion. In one axis eq. (39) is
    θ = G + LP(θ_acc − G), with G the gyro integral and LP the first-order low-pass of
    pole A. Here G is the strapdown orientation :math:`q_G` (:func:`strapdown_orientation`),
    the accelerometer is rotated into its frame, :math:`a_I = q_G\,a\,q_G^*`, and
    low-passed there, where gravity is nearly constant and motion accelerations average
    out; the estimate is :math:`q = q_c\otimes q_G`, with :math:`q_c` the shortest
    rotation taking LP(:math:`a_I`) to up. This is the tilt part of the VQF filter of
    Laidig & Seel (2023, "VQF: highly accurate IMU orientation estimation with bias
    estimation and magnetic disturbance rejection", Information Fusion 91, 187–204),
    whose default accelerometer time constant is also 3 s, with its rest detector for
    the gyro bias but without its bias estimation during motion. During the first τ the
    low-pass returns the running mean of the rotated accelerometer (VQF's
    initialisation), so no single start-up sample dominates. Everything is vectorised: a prefix product, one IIR pass and
    one rotation per sample.

    Examples
    --------
    >>> still = complementary_tilt(np.zeros((50, 3)), np.tile([0.0, 9.81, 0.0], (50, 1)), 0.01)
    >>> from scipy.spatial.transform import Rotation
    >>> up = Rotation.from_quat(still, scalar_first=True).apply([0.0, 1.0, 0.0])
    >>> np.round(up[-1], 12).tolist()   # the sensor's y axis, which gravity says is up
    [0.0, 0.0, 1.0]
    """
    rate = _check_series3("gyro", gyro)
    acc = _check_series3("accel", accel)
    if rate.shape != acc.shape:
        raise ValueError(f"gyro and accel must have the same shape (N, 3), got {rate.shape} and {acc.shape}")
    step = as_positive_scalar("dt", dt, unit="s")
    time_constant = float(as_positive("tau", tau, unit="s"))
    if order not in (1, 2):
        raise ValueError(f"order must be 1 or 2, got {order!r}")
    if rest_bias:
        rate = rate - rest_gyro_bias(rate, acc, step)[0]
    gyro_frame = strapdown_orientation(rate, step)
    acc_inertial = _rotations(gyro_frame).apply(acc)
    if order == 2 and np.sqrt(2.0) / (2.0 * np.pi * time_constant) >= 0.5 / step:
        raise ValueError(f"tau must exceed {2.0 * np.sqrt(2.0) * step / (2.0 * np.pi):g} s for order 2 "
                         f"(cut-off below the Nyquist frequency {0.5 / step:g} Hz), got {shown(time_constant)}")
    smooth = _lowpass_from_mean(acc_inertial, step, time_constant, order)
    correction = accelerometer_tilt(smooth)
    q = hamilton_product(correction, gyro_frame)
    return q / np.linalg.norm(q, axis=-1, keepdims=True)
