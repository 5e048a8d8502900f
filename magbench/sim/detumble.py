r"""B-dot detumbling of a rigid spacecraft on a circular orbit, Monte Carlo members in one array.

SamSat-218D §"Rate damping" (seed lines 225–273: the law, its continuous and discrete
modes) with Kovalenko (1975) ch. 5–6 (detumbling, its time estimates). Composes
:class:`magbench.earth.CircularOrbit`, the rigid body of :mod:`magbench.dynamics` and the
laws of :mod:`magbench.control`, integrated with the classical RK4 scheme of
:func:`magbench.sim.rk4_step`, written out on component arrays (one (M,) array per vector
component) because the general (M, 3) form spent most of a step stacking arrays: the same
numbers to ~1e-14, about 2x faster at 1000 members. That numpy loop is the reference
(:mod:`magbench.sim._detumble_loops`, with the field table, body and schedule); runs
go through its compiled twin (:mod:`magbench.sim._detumble_kernel`), which repeats its
operations in scalar code, member by member, and gives the same numbers to the last bit
(40-100 times faster at a few members, where numpy's per-call overhead dominates).

``omega`` (the angular-velocity vector, final state of a run) is a name of the chapter-5
contract (``shared/reference/bdot_triad.md`` §9); ``rate`` is its magnitude.
"""

from dataclasses import replace

import numpy as np
from scipy.spatial.transform import Rotation

from .._validate import (as_choice, as_finite, as_inertia, as_nonnegative, as_positive, as_positive_or_infinite,
                         as_positive_scalar, as_quaternions, as_vectors, as_whole_steps, check_member_steps, shown)
from ..earth.circular_orbit import CircularOrbit
from ._detumble_loops import ESTIMATORS, LAWS, MODES, _Loop, _compiled_loop, _numpy_loop
from .dispersion import member_generators
from .result import DetumbleRun

__all__ = ["DetumbleRun", "simulate_detumble", "detumble_time", "draw_detumble_member", "detumble_monte_carlo"]



def _default_step(mode, control_interval, off_time, record_interval, speed):
    if mode == "sampled":
        return control_interval
    if mode == "duty":
        return min(0.25, off_time / 4.0)
    bound = min(0.5, 0.2 / speed) if speed > 0 else 0.5
    return record_interval / np.ceil(record_interval / bound - 1e-12)


def _initial_members(inertia, orbit, attitude, rate, gain):
    """Checked inertia matrix, initial quaternions (M, 4), rates (M, 3) and M."""
    j = as_inertia("inertia", inertia)
    if not isinstance(orbit, CircularOrbit):
        raise ValueError(f"orbit must be a magbench.earth.CircularOrbit, got {type(orbit).__name__}")
    q0 = as_quaternions("attitude", attitude)
    w0 = as_vectors("rate", rate)
    if q0.ndim > 2 or w0.ndim > 2:
        raise ValueError(f"attitude and rate must be (M, 4) or (4,) and (M, 3) or (3,), got {q0.shape} and {w0.shape}")
    phase = np.asarray(orbit.argument_of_latitude0)
    try:
        members = np.broadcast_shapes(q0.shape[:-1], w0.shape[:-1], phase.shape, np.shape(gain))
    except ValueError:
        raise ValueError(f"attitude {q0.shape}, rate {w0.shape}, orbit.argument_of_latitude0 {phase.shape} and gain "
                         f"{np.shape(gain)} must agree on the number of members M (or have none)") from None
    members = members[0] if members else 1
    q0 = np.array(np.broadcast_to(q0.reshape(-1, 4), (members, 4)))
    q0 /= np.linalg.norm(q0, axis=-1, keepdims=True)
    w0 = np.array(np.broadcast_to(w0.reshape(-1, 3), (members, 3)))
    return j, q0, w0, members


def _checked_law(duration, gain, max_dipole, law, mode, estimator):
    """Checked duration, gain (a column (M, 1) for member gains) and dipole limit of
    :func:`simulate_detumble`; the law, mode and estimator names checked too."""
    span = as_positive_scalar("duration", duration, unit="s")
    k = as_positive("gain", gain, unit="N·m·s" if law == "projected" else "A·m²·s/T")
    k = k[:, None] if k.ndim == 1 else k
    limit = as_positive_or_infinite("max_dipole", max_dipole, unit="A·m²")
    as_choice("law", law, LAWS)
    as_choice("mode", mode, MODES)
    as_choice("estimator", estimator, ESTIMATORS)
    return span, k, limit


def _checked_timing(control_interval, on_time, off_time, step, record_interval, gravity_gradient):
    """Checked sampling interval, duty-cycle times and record interval of
    :func:`simulate_detumble` (``gravity_gradient`` checked to be a bool)."""
    delta = as_positive_scalar("control_interval", control_interval, unit="s")
    t_on = as_positive_scalar("on_time", on_time, unit="s")
    t_off = as_positive_scalar("off_time", off_time, unit="s")
    if record_interval is not None:
        every = as_positive_scalar("record_interval", record_interval, unit="s")
    elif step is None:
        every = 1.0
    else:
        given = as_positive_scalar("step", step, unit="s")
        every = given * max(1, round(1.0 / given))
    if not isinstance(gravity_gradient, (bool, np.bool_)):
        raise ValueError(f"gravity_gradient must be True or False, got {gravity_gradient!r}")
    return delta, t_on, t_off, every


def _step_counts(mode, step, w0, delta, t_on, t_off, every, span):
    """The integration step h and what is counted in steps: (steps per sample, off steps,
    on steps), steps per record, the number of records and of steps. Every interval the
    mode uses must be a whole number of steps, so that samples, windows and records fall
    on step boundaries."""
    speed = float(np.max(np.linalg.norm(w0, axis=-1)))
    h = (_default_step(mode, delta, t_off, every, speed) if step is None
         else as_positive_scalar("step", step, unit="s"))
    per_sample = as_whole_steps("control_interval", delta, h) if mode == "sampled" else 0
    n_off = as_whole_steps("off_time", t_off, h) if mode == "duty" else 0
    n_on = as_whole_steps("on_time", t_on, h) if mode == "duty" else 0
    stride = as_whole_steps("record_interval", every, h)
    n_records = int(np.ceil(span / every - 1e-9)) + 1
    n_steps = (n_records - 1) * stride
    return h, (per_sample, n_off, n_on), stride, n_records, n_steps


def simulate_detumble(inertia, orbit, attitude, rate, duration, *, gain, max_dipole, law="bdot",
                      mode="continuous", control_interval=0.1, on_time=16.0, off_time=1.0, estimator="model",
                      step=None, gravity_gradient=True, record_interval=None, engine="compiled"):
    r"""Simulate B-dot detumbling of M members at once (RK4, fixed step).

    Parameters
    ----------
    inertia : array_like, shape (3,) or (3, 3)
        Principal moments (body axes principal) or the inertia tensor in body axes [kg·m²].
    orbit : CircularOrbit
        Orbit and field; an array ``argument_of_latitude0`` (M,) gives each member its orbit
        phase [-].
    attitude : array_like, shape (M, 4) or (4,)
        Initial attitude quaternion, scalar first, body → inertial [-].
    rate : array_like, shape (M, 3) or (3,)
        Initial angular velocity in body axes [rad/s].
    duration : float
        Simulated time; the run ends at the first record time ≥ duration [s].
    gain : float or array_like, shape (M,)
        k > 0: [A·m²·s/T] for ``law="bdot"``, [N·m·s] for ``law="projected"``.
    max_dipole : float or array_like, shape (3,)
        Largest dipole of each coil, > 0 (``inf``: no limit) [A·m²].
    law : {"bdot", "projected"}, optional
        m = −sat(kḂ) (:func:`magbench.control.bdot_dipole`) or the projected law
        (:func:`magbench.control.bdot_dipole_projected`) [-].
    mode : {"continuous", "sampled", "duty"}, optional
        "continuous": exact Ḃ_body = RᵀḂ_N − ω × B_body at every RK stage (on-board models);
        "sampled": every ``control_interval`` from t = 0, m = sat(−k(B_k − B_{k−1})/Δ), held,
        m = 0 before the second sample; "duty": each cycle starts at t = 0 with ``off_time``
        coils off, then ``on_time`` on, the dipole from ``estimator`` [-].
    control_interval : float, optional
        Sampling interval Δ of the "sampled" mode [s].
    on_time : float, optional
        Coils-on time of each duty cycle [s].
    off_time : float, optional
        Coils-off (measurement) time of each duty cycle [s].
    estimator : {"model", "hold", "propagate"}, optional
        Duty mode only. "model": exact Ḃ while on (on-board models); "hold": Ḃ from the field
        difference across the window, dipole held; "propagate": ω⊥ = −B × Ḃ/|B|² from the
        window, B_body propagated with it while on [-].
    step : float, optional
        Integration step [s]; by default ``control_interval`` (sampled), min(0.25 s,
        off_time/4) (duty), or the largest divisor of ``record_interval`` not above
        min(0.5 s, 0.2 rad / max|ω₀|) (continuous).
    gravity_gradient : bool, optional
        Include the gravity-gradient torque [-].
    record_interval : float, optional
        Interval between records of |ω|; a whole number of steps [s]. Default 1 s, or,
        with a given ``step``, the whole number of steps nearest 1 s (at least one: a 2 s
        step records every 2 s).
    engine : {"compiled", "numpy"}, optional
        "compiled": the numba loop of :mod:`magbench.sim._detumble_kernel`, one member at a
        time; "numpy": the vectorised reference loop, all members in each step. The same
        numbers to the last bit; duty mode with the "propagate" estimator always runs the
        numpy loop [-].

    Returns
    -------
    DetumbleRun
        ``time`` (K,), ``rate`` (M, K), final ``omega`` (M, 3) and ``attitude`` (M, 4), and
        ``inputs``.

    Notes
    -----
    SamSat-218D §"Rate damping" (seed lines 225–261) for the law and the two modes;
    SamSat-218D §"Equations of motion" (seed lines 163–199) and Kovalenko (1975) eq. (4.18)
    for the dynamics (aerodynamic torque neglected, ≲ 1 % of the control torque at 485 km).
    Torque m × B_body; q renormalised after every step (its drift is O(h⁵) per step).
    The duty-mode estimators are ours (the paper's ref. [1] is not available; see the shared
    reference §2): "model" is the only reading that damps the whole 5–45 °/s range.

    Examples
    --------
    >>> orbit = CircularOrbit(6856e3, np.radians(97.3), 7.72e22)
    >>> run = simulate_detumble([0.0067, 0.0419, 0.0419], orbit, [1.0, 0.0, 0.0, 0.0],
    ...                         np.radians([0.1, 10.0, 10.0]), 60.0, gain=1.691e4, max_dipole=0.2)
    >>> run.rate.shape, bool(run.rate[0, -1] < run.rate[0, 0])
    ((1, 61), True)
    """
    j, q0, w0, members = _initial_members(inertia, orbit, attitude, rate, gain)
    span, k, limit = _checked_law(duration, gain, max_dipole, law, mode, estimator)
    delta, t_on, t_off, every = _checked_timing(control_interval, on_time, off_time, step, record_interval,
                                                gravity_gradient)
    h, counts, stride, n_records, n_steps = _step_counts(mode, step, w0, delta, t_on, t_off, every, span)
    check_member_steps(members, n_steps)

    law_kk = k[:, 0] if k.ndim == 2 else k
    lim = np.broadcast_to(limit, (3,))
    if engine not in ("compiled", "numpy"):
        raise ValueError(f"engine must be 'compiled' or 'numpy', got {engine!r}")
    loop = _Loop(j, orbit, orbit.mean_motion if gravity_gradient else None, law, law_kk, lim, mode, estimator,
                 (delta, t_off) + counts, h, n_steps, stride)
    compiled = engine == "compiled" and not (mode == "duty" and estimator == "propagate")
    state, rates = (_compiled_loop if compiled else _numpy_loop)(loop, q0, w0)
    inputs = dict(inertia=j, orbit=orbit, attitude=q0, rate=w0, duration=span, gain=gain, max_dipole=max_dipole,
                  law=law, mode=mode, control_interval=delta, on_time=t_on, off_time=t_off, estimator=estimator,
                  step=h, gravity_gradient=bool(gravity_gradient), record_interval=every, engine=engine)
    return DetumbleRun(np.arange(n_records) * every, rates, state[4:].T.copy(), state[:4].T.copy(), inputs)


def detumble_time(time, rate, threshold=np.radians(0.5), dwell=0.0):
    r"""Time at which each member is detumbled: |ω| ≤ threshold from then on for ``dwell``.

    Parameters
    ----------
    time : array_like, shape (K,)
        Record times, increasing [s].
    rate : array_like, shape (M, K) or (K,)
        |ω| at the record times [rad/s].
    threshold : float, optional
        Largest |ω| counted as detumbled [rad/s]; 0.5 °/s by default.
    dwell : float, optional
        How long |ω| must stay at or below ``threshold`` (every record in [t, t + dwell],
        which must lie inside the run); 0 takes the first crossing [s].

    Returns
    -------
    ndarray, shape (M,) or ()
        The first record time that qualifies [s]; NaN if none does.

    Notes
    -----
    Not in the sources: SamSat-218D §"Rate damping" (Fig. 2) gives no criterion; the
    0.5 °/s threshold is Basilisk's and Cp557's convention, the dwell Cp557's (30 s).

    Examples
    --------
    >>> detumble_time([0.0, 1.0, 2.0, 3.0], [[0.1, 0.0, 0.0, 0.0], [0.1, 0.0, 0.1, 0.0]], 0.05, 1.0).tolist()
    [1.0, nan]
    """
    t = as_finite("time", time)
    if t.ndim != 1 or t.size < 1 or np.any(np.diff(t) <= 0):
        raise ValueError(f"time must be a 1-D increasing array [s], got shape {t.shape}")
    r = as_nonnegative("rate", rate, unit="rad/s")
    if r.shape[-1] != t.size or r.ndim > 2:
        raise ValueError(f"rate must have shape (M, {t.size}) or ({t.size},), got {r.shape}")
    limit = as_nonnegative("threshold", threshold, unit="rad/s")
    hold = as_nonnegative("dwell", dwell, unit="s")
    below = r <= limit
    index = np.arange(t.size)
    # Index of the first record above the threshold at or after each record (K if none).
    next_above = np.minimum.accumulate(np.where(below, t.size, index)[..., ::-1], axis=-1)[..., ::-1]
    end = np.append(t, np.inf)[next_above]
    ok = below & (end > t + hold) & (t + hold <= t[-1])
    first = np.argmax(ok, axis=-1)
    return np.where(ok.any(axis=-1), t[first], np.nan)


def draw_detumble_member(rng, rate_range):
    r"""One member's random attitude, initial rate and orbit phase.

    Parameters
    ----------
    rng : numpy.random.Generator
        The member's own generator [-] (:func:`magbench.sim.dispersion.member_generators`).
    rate_range : tuple of float
        Lowest and highest initial |ω| [rad/s].

    Returns
    -------
    attitude : ndarray, shape (4,)
        Uniform on the rotations (scipy's ``Rotation.random``), scalar first [-].
    rate : ndarray, shape (3,)
        Axis uniform on the sphere, magnitude uniform in ``rate_range`` [rad/s].
    phase : float
        Orbit phase, uniform in [0, 2π) [rad].

    Notes
    -----
    Not in the sources: the envelope's draws (shared reference §6.2); the draws' order is
    part of the contract (a study's rows depend on it).

    Examples
    --------
    >>> q, w, u = draw_detumble_member(np.random.default_rng([7, 0]), (0.1, 0.2))
    >>> bool(0.1 <= np.linalg.norm(w) <= 0.2 and 0.0 <= u < 2.0 * np.pi)
    True
    """
    low, high = rate_range
    attitude = Rotation.random(rng=rng).as_quat(scalar_first=True)
    axis = rng.normal(size=3)
    rate = axis / np.linalg.norm(axis) * rng.uniform(low, high)
    return attitude, rate, rng.uniform(0.0, 2.0 * np.pi)


def detumble_monte_carlo(inertia, orbit, *, members, seed, duration, rate_range, first_member=0, **options):
    r"""Detumbling from random attitudes, rate axes, rate magnitudes and orbit phases.

    Parameters
    ----------
    inertia : array_like, shape (3,) or (3, 3)
        Principal moments or inertia tensor [kg·m²].
    orbit : CircularOrbit
        Orbit and field; each member's orbit phase is drawn uniformly and added to
        ``argument_of_latitude0`` [-].
    members : int
        Number of members M ≥ 1 [-].
    seed : int
        The study's seed ≥ 0: member k draws from ``numpy.random.default_rng([seed, k])``
        [-], so that a member's draws do not depend on how many members run beside it.
    duration : float
        Simulated time [s].
    rate_range : tuple of float
        Lowest and highest initial |ω|, drawn uniformly; axis uniform on the sphere [rad/s].
    first_member : int, optional
        Index k of the first member [-]; members ``first_member`` … ``first_member + M − 1``
        run (a chunk of a larger study, :mod:`magbench.sim.dispersion`).
    options : keyword arguments
        ``**options``: keyword arguments of :func:`simulate_detumble` (``gain`` and ``max_dipole`` required)
        [SI].

    Returns
    -------
    DetumbleRun
        As :func:`simulate_detumble`; ``inputs["draws"]`` holds the drawn attitude, rate and
        orbit phase (:func:`draw_detumble_member`).

    Notes
    -----
    Not in the sources: the envelope runs of the shared reference §6.2 (uniform attitude
    by scipy's ``Rotation.random``); Kovalenko (1975) eq. (6.50) estimates their median.
    """
    m = int(as_positive_scalar("members", members))
    if m != members:
        raise ValueError(f"members must be a positive integer, got {shown(members)}")
    bounds = as_nonnegative("rate_range", rate_range, unit="rad/s")
    if bounds.shape != (2,) or not bounds[0] <= bounds[1] or bounds[1] == 0:
        raise ValueError(f"rate_range must be (low, high) with 0 <= low <= high, high > 0 [rad/s], got {shown(rate_range)}")
    if np.ndim(orbit.argument_of_latitude0) != 0:
        raise ValueError("orbit.argument_of_latitude0 must be a scalar here (each member's phase is drawn), "
                         f"got shape {np.shape(orbit.argument_of_latitude0)}")
    draws = [draw_detumble_member(rng, bounds) for rng in member_generators(seed, first_member, first_member + m)]
    attitude, rate, phase = (np.array(d) for d in zip(*draws))
    phase = orbit.argument_of_latitude0 + phase
    run = simulate_detumble(inertia, replace(orbit, argument_of_latitude0=phase), attitude, rate, duration,
                            **options)
    run.inputs["draws"] = {"attitude": attitude, "rate": rate, "argument_of_latitude0": phase}
    run.inputs["seed"] = seed
    return run
