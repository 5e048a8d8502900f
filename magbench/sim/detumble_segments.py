r"""Detumbling in segments, each with the largest step the current rate allows.

A tumbling body at 10°/s needs RK4 steps of a fraction of a second; damped to 0.5°/s, it
does with 1 s. :func:`simulate_detumble_segments` runs :func:`magbench.sim.simulate_detumble`
segment by segment, choosing each segment's step from the largest rate of any member at its
start (:func:`detumble_step`), so that the rotation per step stays below a bound
(``shared/reference/bdot_triad.md`` §7: ≤ 0.2 rad per step), and stops once every member has
reached a threshold. The orbit's phase and the pole's longitude carry over from segment to
segment, and a duty cycle continues in phase when a segment is a whole number of cycles.
"""

from dataclasses import replace

import numpy as np

from .._validate import as_nonnegative, as_positive_scalar, shown
from .detumble import simulate_detumble

__all__ = ["DETUMBLE_STEPS", "detumble_step", "simulate_detumble_segments"]

#: The steps a segment may take [s], largest first: each divides 1 s (and the 17 s duty cycle
#: of SamSat-218D into whole steps), so that records at 1 s fall on steps.
DETUMBLE_STEPS = (1.0, 0.5, 0.25, 0.2, 0.125, 0.1, 0.0625, 0.05)


def detumble_step(speed, largest_step, rotation_per_step=0.2):
    r"""The largest step of :data:`DETUMBLE_STEPS` for a body turning at ``speed``.

    Parameters
    ----------
    speed : float
        Largest angular rate |ω| of the members, ≥ 0 [rad/s].
    largest_step : float
        No step above it is taken, > 0 [s].
    rotation_per_step : float, optional
        Largest rotation in one step, |ω| h, > 0 [rad].

    Returns
    -------
    float
        The step h [s]; the smallest of :data:`DETUMBLE_STEPS` when none meets both bounds.

    Notes
    -----
    Not in the sources: the step rule of ``shared/reference/bdot_triad.md`` §7 (≤ 0.2 rad per
    RK4 step), which keeps the classical scheme's error per step far below the damping's.

    Examples
    --------
    >>> detumble_step(10 * 3.141592653589793 / 180, 1.0)
    1.0
    >>> detumble_step(1.0, 1.0)
    0.2
    """
    w = float(as_nonnegative("speed", speed, unit="rad/s"))
    largest = as_positive_scalar("largest_step", largest_step, unit="s")
    rotation = as_positive_scalar("rotation_per_step", rotation_per_step, unit="rad")
    for h in DETUMBLE_STEPS:
        # 1e-12: a largest step computed as a ratio (the off time over 4) may miss by an ulp
        if h <= largest + 1e-12 and h * w <= rotation:
            return h
    return DETUMBLE_STEPS[-1]


def _all_reached(rates, threshold):
    """Every member has fallen to ``threshold`` in some segment so far."""
    return bool(np.all(np.any(np.concatenate(rates, axis=-1) <= threshold, axis=-1)))


def simulate_detumble_segments(inertia, orbit, attitude, rate, duration, *, segment=1700.0, largest_step=1.0,
                               threshold=None, rotation_per_step=0.2, **options):
    r"""B-dot detumbling in segments, each with the largest step the current rate allows.

    Parameters
    ----------
    inertia, orbit, attitude, rate, duration : see simulate_detumble
        As for :func:`magbench.sim.simulate_detumble`: principal moments [kg·m²], the
        :class:`~magbench.earth.CircularOrbit` (members may differ in phase), initial attitude
        quaternions (M, 4) [-] and body rates (M, 3) [rad/s], and the span, > 0 [s].
    segment : float, optional
        Length of a segment, > 0 [s]; a whole number of duty cycles for a duty-cycled run
        (1700 s = 100 × SamSat-218D's 17 s), so that the cycle continues in phase.
    largest_step : float, optional
        No segment steps more than this, > 0 [s].
    threshold : float, optional
        Stop after the segment in which every member has reached |ω| ≤ threshold [rad/s];
        None runs the whole ``duration``.
    rotation_per_step : float, optional
        Largest rotation per RK4 step at the segment's largest |ω| (:func:`detumble_step`) [rad].
    options : keyword arguments
        Passed on to :func:`magbench.sim.simulate_detumble` (gain [A·m²·s/T], max_dipole
        [A·m²], law, mode, …).

    Returns
    -------
    time : ndarray, shape (K,)
        Record times from 0, at the runs' record interval [s].
    rate : ndarray, shape (M, K)
        |ω| of each member at those times [rad/s].

    Notes
    -----
    SamSat-218D §"Rate damping" (seed lines 225–273) simulated as
    :func:`magbench.sim.simulate_detumble` does; the segmenting and its step rule are ours
    (``shared/reference/bdot_triad.md`` §7).
    """
    span_total = as_positive_scalar("duration", duration, unit="s")
    length = as_positive_scalar("segment", segment, unit="s")
    if threshold is not None and not threshold > 0:
        raise ValueError(f"threshold must be > 0 [rad/s] or None, got {shown(threshold)}")
    q, w = np.atleast_2d(attitude), np.atleast_2d(rate)
    times, rates = [np.zeros(1)], [np.linalg.norm(w, axis=-1)[:, None]]
    elapsed = 0.0
    while elapsed < span_total - 1e-9:
        span = min(length, span_total - elapsed)
        h = detumble_step(float(np.max(np.linalg.norm(w, axis=-1))), largest_step, rotation_per_step)
        run = simulate_detumble(inertia, orbit, q, w, span, step=h, **options)
        times.append(elapsed + run.time[1:])
        rates.append(run.rate[:, 1:])
        elapsed += run.time[-1]
        q, w = run.attitude, run.omega
        orbit = replace(orbit, argument_of_latitude0=orbit.argument_of_latitude0 + orbit.mean_motion * run.time[-1],
                        dipole_longitude=orbit.dipole_longitude + orbit.earth_rotation_rate * run.time[-1])
        if threshold is not None and _all_reached(rates, threshold):
            break
    return np.concatenate(times), np.concatenate(rates, axis=-1)
