r"""Tilt from a whole logged record (offline, non-causal): the gyro bias from every rest
period, and a zero-phase (forward–backward) low-pass of the accelerometer.

Not in the sources: the post-processing counterpart of :func:`.tilt.complementary_tilt`
for bench logs, after the offline mode of VQF (Laidig & Seel 2023). SI.
"""

import numpy as np
from scipy.signal import butter, filtfilt

from .._validate import as_positive, as_positive_scalar, shown
from ..rotations import hamilton_product
from .tilt import _check_series3, _rotations, accelerometer_tilt, rest_gyro_bias, strapdown_orientation

__all__ = ["two_sided_rest", "offline_tilt"]

#: Fewest samples :func:`offline_tilt` accepts: Gustafsson's initial conditions for a
#: second-order filter are a least-squares fit that needs a few samples more than the order.
MIN_SAMPLES = 8


def two_sided_rest(gyro, accel, dt, rest_detector=None):
    r"""Rest samples of a whole record: VQF's rest detector run forwards and backwards.

    Parameters
    ----------
    gyro : array_like, shape (N, 3)
        Angular rate in the sensor frame [rad/s].
    accel : array_like, shape (N, 3)
        Specific force in the sensor frame [m/s²].
    dt : float
        Sample interval [s], > 0.
    rest_detector : dict, optional
        Thresholds passed to :func:`~magbench.estimation.rest_gyro_bias` (its keywords
        ``rate_threshold`` [rad/s], ``accel_threshold`` [m/s²], ``min_rest_time`` [s],
        ``rest_filter_tau`` [s]); default: its defaults (VQF's).

    Returns
    -------
    ndarray of bool, shape (N,)
        True where the sample is quiet seen from both directions (low-passed rate and
        accelerometer within the thresholds) and the quiet lasts ``min_rest_time`` in at
        least one of them [-].

    Notes
    -----
    Not in the sources. The causal detector needs ``min_rest_time`` of quiet before it
    calls a sample rest, so it misses the first part of every rest period, and its
    low-passes lag, so it still calls the first sample of a motion rest. Run over the
    time-reversed record (gyro negated, which its rate-norm test ignores) it misses the
    last part of a rest period instead and calls the last sample of a motion rest.
    Requiring quiet in both directions removes those motion samples; the duration test
    from either direction keeps the whole of a long rest period but the low-passes'
    settling time after motion. Reversing the record swaps the two passes, so the result
    is reversed with it.

    Examples
    --------
    >>> rest = two_sided_rest(np.zeros((400, 3)), np.tile([0.0, 0.0, 9.81], (400, 1)), 0.01)
    >>> bool(rest.all())    # the causal detector alone misses the first 1.5 s
    True
    """
    rate = np.asarray(gyro, dtype=float)
    acc = np.asarray(accel, dtype=float)
    detector = dict(rest_detector or {})
    instant = {**detector, "min_rest_time": 0.0}
    _, forward = rest_gyro_bias(rate, acc, dt, **detector)
    _, backward = rest_gyro_bias(-rate[::-1], acc[::-1], dt, **detector)
    _, quiet_forward = rest_gyro_bias(rate, acc, dt, **instant)
    _, quiet_backward = rest_gyro_bias(-rate[::-1], acc[::-1], dt, **instant)
    return (forward | backward[::-1]) & quiet_forward & quiet_backward[::-1]


def _checked_record(gyro, accel, dt, tau):
    """Checked gyro and accel (N, 3) arrays, sample interval and low-pass cut-off [Hz] of
    :func:`offline_tilt`."""
    rate = _check_series3("gyro", gyro)
    acc = _check_series3("accel", accel)
    if rate.shape != acc.shape:
        raise ValueError(f"gyro and accel must have the same shape (N, 3), got {rate.shape} and {acc.shape}")
    if len(rate) < MIN_SAMPLES:
        raise ValueError(f"gyro and accel must have at least {MIN_SAMPLES} samples for the forward-backward "
                         f"low-pass, got {len(rate)}")
    step = as_positive_scalar("dt", dt, unit="s")
    time_constant = float(as_positive("tau", tau, unit="s"))
    cutoff = np.sqrt(2.0) / (2.0 * np.pi * time_constant)
    if cutoff >= 0.5 / step:
        raise ValueError(f"tau must exceed {2.0 * np.sqrt(2.0) * step / (2.0 * np.pi):g} s (cut-off below the "
                         f"Nyquist frequency {0.5 / step:g} Hz), got {shown(time_constant)}")
    return rate, acc, step, cutoff


def offline_tilt(gyro, accel, dt, *, tau=3.0, rest_bias=True, rest_detector=None):
    r"""3-D tilt (inclination) of a logged record, using the past and the future of each sample.

    Parameters
    ----------
    gyro : array_like, shape (N, 3)
        Angular rate in the sensor frame [rad/s]; sample k rotates the sensor during the
        interval before it (as in :func:`~magbench.estimation.strapdown_orientation`).
        N >= 8.
    accel : array_like, shape (N, 3)
        Specific force in the sensor frame [m/s²] (at rest it points up).
    dt : float
        Sample interval [s], > 0.
    tau : float, optional
        Time constant of the second-order Butterworth low-pass applied forwards and then
        backwards to the accelerometer [s], > 0 and long enough for the cut-off
        √2/(2πτ) to stay below the Nyquist frequency; default 3 s (VQF's accelerometer
        time constant, the same as :func:`~magbench.estimation.complementary_tilt`'s).
    rest_bias : bool, optional
        Subtract one constant gyro bias, the mean gyro over every rest sample of the
        record (:func:`two_sided_rest`), before integrating [-]; default True. Without rest
        samples no bias is subtracted. False integrates the raw gyro.
    rest_detector : dict, optional
        Thresholds passed to the rest detector (keywords of
        :func:`~magbench.estimation.rest_gyro_bias`: ``rate_threshold`` [rad/s],
        ``accel_threshold`` [m/s²], ``min_rest_time`` [s], ``rest_filter_tau`` [s]);
        default: its defaults (VQF's).

    Returns
    -------
    ndarray, shape (N, 4)
        Unit quaternions (w, x, y, z) rotating sensor-frame vectors into an Earth frame
        whose z axis points up; the heading (rotation about z) is left free, as in
        :func:`~magbench.estimation.complementary_tilt`.

    Raises
    ------
    ValueError
        If ``gyro`` or ``accel`` is not a finite (N, 3) array with N >= 8, their shapes
        differ, ``dt`` or ``tau`` is not positive, or ``tau`` puts the cut-off above the
        Nyquist frequency.

    Notes
    -----
    Not in the thesis: for post-processing a log, where every sample is available. The
    structure is that of :func:`~magbench.estimation.complementary_tilt` (gyro
    integral :math:`q_G`, accelerometer rotated into its frame, :math:`a_I = q_G\,a\,q_G^*`,
    low-passed, shortest rotation to the vertical :math:`q_c`, estimate
    :math:`q = q_c\otimes q_G`) with two changes that need the whole record:

    1. The gyro bias is one constant: the mean gyro over all rest samples, found by
       VQF's rest detector run in both directions (:func:`two_sided_rest`), instead of
       the causal running mean that is zero until the first rest (and that takes in
       the first sample of each motion, which its low-passes have not yet seen).
    2. The low-pass runs forwards and backwards (``scipy.signal.filtfilt``): zero phase,
       so it does not lag the gyro drift it corrects, with magnitude response
       :math:`|H|^2 = 1/(1 + (f/f_c)^4)` and :math:`f_c = \sqrt2/(2\pi\tau)` (the
       square of the one-pass Butterworth's). For a tilt drift that is a random walk
       and a motion acceleration that is the derivative of a stationary (bounded)
       velocity, the ratio of their spectra rises as :math:`f^4` at low frequency, so
       the Wiener smoother of that model, :math:`1/(1 + \text{ratio})`, has this
       response's low-frequency shape. The ends use
       Gustafsson's initial conditions (``method="gust"``; Gustafsson 1996, IEEE Trans.
       Signal Process. 44(4), 988–992), which make the forward–backward and the
       backward–forward passes agree: reversing the record (gyro negated and shifted by
       one sample) gives the reversed estimate, up to rounding.

    This is the scheme of the offline mode of VQF (``vqf.offlineVQF``; D. Laidig and
    T. Seel, "VQF: highly accurate IMU orientation estimation with bias estimation and
    magnetic disturbance rejection", Information Fusion 91 (2023) 187–204), except
    that VQF combines forward and backward bias estimates that also learn during
    motion; on the BROAD trials the two agree to a few thousandths of a degree of
    inclination RMSE (tests/peers/test_vqf.py). Everything is vectorised: one prefix
    product, one filtfilt, one rotation per sample.

    Examples
    --------
    >>> n = 1000
    >>> gyro = np.tile([0.01, -0.02, 0.005], (n, 1))          # a sensor at rest with a bias
    >>> accel = np.tile([0.0, 9.81 * np.sin(0.3), 9.81 * np.cos(0.3)], (n, 1))
    >>> q = offline_tilt(gyro, accel, 0.01)
    >>> from scipy.spatial.transform import Rotation
    >>> up = Rotation.from_quat(q, scalar_first=True).inv().apply([0.0, 0.0, 1.0])
    >>> round(float(np.degrees(np.arccos(up[-1, 2]))), 9)      # tilted 0.3 rad about x
    17.188733854
    """
    rate, acc, step, cutoff = _checked_record(gyro, accel, dt, tau)
    if rest_bias:
        rest = two_sided_rest(rate, acc, step, rest_detector)
        if rest.any():
            rate = rate - rate[rest].mean(axis=0)
    gyro_frame = strapdown_orientation(rate, step)
    acc_inertial = _rotations(gyro_frame).apply(acc)
    b, a = butter(2, cutoff, fs=1.0 / step)
    smooth = filtfilt(b, a, acc_inertial, axis=0, method="gust")
    q = hamilton_product(accelerometer_tilt(smooth), gyro_frame)
    return q / np.linalg.norm(q, axis=-1, keepdims=True)
