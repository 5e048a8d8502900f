"""Checked inputs of the bench's loop: the run's length, members, initial state and
recording (:func:`_loop_inputs`) and the error sources per member (:func:`_error_arrays`).
Each bad value raises a ValueError naming it, its value and the range expected.
"""

import numpy as np

from ..._validate import as_count, as_finite, as_in_range, as_nonnegative, as_positive, check_member_steps, shown
from .config import ERROR_INPUTS, BenchErrors, BenchSetup


def _member_array(name, value, members):
    arr = as_finite(name, value)
    try:
        return np.array(np.broadcast_to(arr, (members,)), dtype=float)
    except ValueError:
        raise ValueError(f"{name} must be a scalar or have shape ({members},), got shape {arr.shape}") from None


def _loop_inputs(setup, duration, window, members, release_angle, release_rate, errors, rng, sensor_errors,
                 record_interval):
    """Checked inputs of :func:`simulate_bench`: steps, window, members, initial state,
    stiffness, moment scale, recording stride and sensor errors (None: draw them)."""
    if not isinstance(setup, BenchSetup):
        raise ValueError(f"setup must be a BenchSetup, got {type(setup).__name__}")
    if not isinstance(errors, BenchErrors):
        raise ValueError(f"errors must be a BenchErrors or None, got {type(errors).__name__}")
    moment_scale, thread_stiffness = errors.moment_scale, errors.thread_stiffness
    dt = setup.sample_interval
    steps_f = float(as_positive("duration", duration, unit="s")) / dt
    steps = int(round(steps_f))
    if abs(steps - steps_f) > 1e-6 * max(1.0, steps_f):
        raise ValueError(f"duration must be a whole number of samples of {dt} s, got {shown(duration)}")
    window = float(as_in_range("window", window, 0.0, steps * dt, unit="s"))
    if members is None:
        sizes = [np.size(v) for v in (release_angle, release_rate, thread_stiffness) if v is not None]
        if np.ndim(moment_scale) == 2:
            sizes.append(np.shape(moment_scale)[0])
        if sensor_errors is not None:
            sizes.append(np.shape(sensor_errors[0])[-1])
        members = max(sizes + [1])
    members = as_count("members", members)
    check_member_steps(members, steps)
    psi = _member_array("release_angle", release_angle, members)
    omega = _member_array("release_rate", release_rate, members)
    kappa = _member_array("thread_stiffness",
                          setup.thread_stiffness if thread_stiffness is None else thread_stiffness, members)
    as_nonnegative("thread_stiffness", kappa)
    scale = as_positive("moment_scale", moment_scale)
    try:
        scale = np.broadcast_to(scale, (members, 2))
    except ValueError:
        raise ValueError(f"moment_scale must broadcast to ({members}, 2), got shape {scale.shape}") from None
    every = 1 if record_interval is None else float(as_positive("record_interval", record_interval, unit="s")) / dt
    if abs(every - round(every)) > 1e-6 or round(every) < 1:
        raise ValueError(f"record_interval must be a multiple of the sample interval {dt} s, got {shown(record_interval)}")
    every = int(round(every))
    g_err = m_err = None
    if sensor_errors is not None:
        if rng is not None:
            raise ValueError("give either rng or sensor_errors, not both")
        g_err, m_err = (as_finite("sensor_errors", e) for e in sensor_errors)
        if g_err.shape != (steps, members) or m_err.shape != (steps, members, 2):
            raise ValueError(f"sensor_errors must have shapes ({steps}, {members}) and ({steps}, {members}, 2), "
                             f"got {g_err.shape} and {m_err.shape}")
    elif isinstance(rng, (list, tuple)):
        if len(rng) != members or not all(isinstance(g, np.random.Generator) for g in rng):
            raise ValueError(f"rng must be one numpy.random.Generator, or a list of {members} (one per member), "
                             f"got a {type(rng).__name__} of {len(rng)} items")
    elif rng is not None and not isinstance(rng, np.random.Generator):
        raise ValueError(f"rng must be a numpy.random.Generator, a list of them (one per member) or None, "
                         f"got {type(rng).__name__}")
    return steps, window, members, psi, omega, kappa, scale, every, g_err, m_err


def _error_arrays(members, errors):
    """Checked per-member arrays of the error sources of ``errors`` (None: left out)."""
    out = {}
    for name, value in errors.sources().items():
        if value is None:
            out[name] = None
            continue
        unit, shape, _ = ERROR_INPUTS[name]
        arr = as_finite(name, value)
        try:
            arr = np.array(np.broadcast_to(arr, (members,) + shape), dtype=float)
        except ValueError:
            raise ValueError(f"{name} [{unit}] must broadcast to shape {(members,) + shape}, "
                             f"got shape {arr.shape}") from None
        out[name] = arr
    if out.get("field_scale") is not None:
        as_positive("field_scale", out["field_scale"])
    if out.get("filter_coefficient") is not None:
        as_in_range("filter_coefficient", out["filter_coefficient"], 0.0, 1.0)
    if out.get("pwm_levels") is not None:
        lv = out["pwm_levels"]
        if np.any(lv < 1) or np.any(lv != np.rint(lv)):
            bad = lv[(lv < 1) | (lv != np.rint(lv))].ravel()[0]
            raise ValueError(f"pwm_levels must be whole numbers of duty steps >= 1, got {shown(bad)}")
    if out.get("magnetometer_matrix") is not None:
        det = np.linalg.det(out["magnetometer_matrix"])
        if np.any(det <= 0):
            raise ValueError("magnetometer_matrix must have a positive determinant (a sensor, not a "
                             f"mirror or a collapse), got determinant {shown(float(det[det <= 0].ravel()[0]))}")
    for name in ("magnetometer_misalignment", "heading_ripple", "field_azimuth"):
        if out.get(name) is not None:
            as_in_range(name, out[name], -np.pi, np.pi, unit="rad")
    if out.get("coil_misalignment") is not None:
        as_in_range("coil_misalignment", out["coil_misalignment"], -np.pi / 4, np.pi / 4, unit="rad")
    return out
