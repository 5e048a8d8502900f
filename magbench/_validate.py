"""Input checks shared by the physics modules.

Each check raises ``ValueError`` naming the parameter, the offending value and the
expected range, so that bad input is never silently clipped or propagated as NaN.
"""

import numpy as np


def shown(value):
    """``repr`` of a value for an error message, with numpy scalars as plain Python numbers.

    numpy 2 writes ``np.float64(-0.5)`` for a scalar; a message says ``-0.5``.
    """
    if isinstance(value, np.generic) or (isinstance(value, np.ndarray) and value.ndim == 0):
        return repr(value.item())
    if isinstance(value, (tuple, list)):
        return repr(type(value)(v.item() if isinstance(v, np.generic) else v for v in value))
    return repr(value)


def _describe(value):
    arr = np.asarray(value)
    if arr.size == 1:
        return repr(arr.item())
    return f"array of shape {arr.shape}"


def as_finite(name, value):
    """Return ``value`` as a float array, raising if any element is NaN or infinite."""
    try:
        arr = np.asarray(value, dtype=float)
    except (TypeError, ValueError) as exc:
        raise ValueError(f"{name} must be numeric, got {shown(value)}") from exc
    if not np.all(np.isfinite(arr)):
        bad = arr[~np.isfinite(arr)].ravel()[0]
        raise ValueError(f"{name} must be finite, got {shown(bad)} in {_describe(arr)}")
    return arr


def as_positive(name, value, *, unit=""):
    """Return ``value`` as a float array, raising unless every element is finite and > 0."""
    arr = as_finite(name, value)
    if np.any(arr <= 0):
        bad = arr[arr <= 0].ravel()[0]
        raise ValueError(f"{name} must be > 0{(' ' + unit) if unit else ''}, got {shown(bad)}")
    return arr


def as_nonnegative(name, value, *, unit=""):
    """Return ``value`` as a float array, raising unless every element is finite and >= 0."""
    arr = as_finite(name, value)
    if np.any(arr < 0):
        bad = arr[arr < 0].ravel()[0]
        raise ValueError(f"{name} must be >= 0{(' ' + unit) if unit else ''}, got {shown(bad)}")
    return arr


def as_in_range(name, value, low, high, *, unit=""):
    """Return ``value`` as a float array, raising unless every element lies in [low, high]."""
    arr = as_finite(name, value)
    if np.any((arr < low) | (arr > high)):
        bad = arr[(arr < low) | (arr > high)].ravel()[0]
        raise ValueError(
            f"{name} must lie in [{low}, {high}]{(' ' + unit) if unit else ''}, got {shown(bad)}"
        )
    return arr


def as_positive_scalar(name, value, *, unit=""):
    """Return ``value`` as a float, raising unless it is a single finite number > 0."""
    arr = as_positive(name, value, unit=unit)
    if arr.ndim != 0:
        raise ValueError(f"{name} must be a scalar{(' [' + unit + ']') if unit else ''}, got shape {arr.shape}")
    return float(arr)


def as_vectors(name, value):
    """Return ``value`` as a finite float array whose trailing axis has length 3."""
    arr = as_finite(name, value)
    if arr.ndim == 0 or arr.shape[-1] != 3:
        raise ValueError(
            f"{name} must have shape (..., 3) (vectors on the trailing axis), got shape {arr.shape}"
        )
    return arr


def as_positive_or_infinite(name, value, *, unit=""):
    """Return ``value`` as a float array, raising unless every element is > 0 (``inf`` allowed, NaN not)."""
    try:
        arr = np.asarray(value, dtype=float)
    except (TypeError, ValueError) as exc:
        raise ValueError(f"{name} must be numeric, got {shown(value)}") from exc
    if np.any(np.isnan(arr)) or np.any(arr <= 0):
        bad = arr[np.isnan(arr) | (arr <= 0)].ravel()[0]
        raise ValueError(f"{name} must be > 0 (inf for no limit){(' ' + unit) if unit else ''}, got {shown(bad)}")
    return arr


def as_choice(name, value, choices):
    """Return ``value`` unchanged, raising unless it is one of ``choices``."""
    if not isinstance(value, str) or value not in choices:
        raise ValueError(f"{name} must be one of {', '.join(map(repr, choices))}, got {shown(value)}")
    return value


#: Most member-steps (Monte Carlo members × integration steps) one simulation call takes:
#: about 80 times the book's largest runs (1000 members × 12 000 steps), and roughly an
#: hour on one core for the simulators here. More is refused at once with this number
#: rather than left to run for hours or to exhaust memory; split such a run into seeded
#: parts.
MAX_MEMBER_STEPS = 1e9


def as_count(name, value, *, minimum=1):
    """Return ``value`` as an int, raising unless it is a whole number >= ``minimum``.

    1.5 is refused rather than truncated to 1 (the caller would report 1.5 and compute 1).
    """
    try:
        number = float(value)
    except (TypeError, ValueError) as exc:
        raise ValueError(f"{name} must be a whole number >= {minimum}, got {shown(value)}") from exc
    if isinstance(value, bool) or not np.isfinite(number) or number != round(number) or number < minimum:
        raise ValueError(f"{name} must be a whole number >= {minimum}, got {shown(value)}")
    return int(round(number))


def as_whole_steps(name, value, step):
    """Number of integration steps of ``step`` [s] in ``value`` [s]; a ValueError naming
    ``name`` unless it is a whole number (≥ 1) of them."""
    ratio = value / step
    n = int(round(ratio))
    if n < 1 or abs(ratio - n) > 1e-9 * max(1.0, ratio):
        raise ValueError(f"{name} must be a whole number of steps ({shown(step)} s), got {shown(value)} s")
    return n


def as_run_timing(duration, step, record_interval=None):
    """(duration [s], step [s], steps between samples) of a fixed-step run, each checked:
    duration and step > 0, the record interval a whole number of steps (default: every step)."""
    total = as_positive_scalar("duration", duration, unit="s")
    h = as_positive_scalar("step", step, unit="s")
    every = 1 if record_interval is None else as_whole_steps(
        "record_interval", as_positive_scalar("record_interval", record_interval, unit="s"), h)
    return total, h, every


def check_member_steps(members, steps):
    """Raise if ``members`` × ``steps`` exceeds :data:`MAX_MEMBER_STEPS`."""
    work = float(members) * float(steps)
    if work > MAX_MEMBER_STEPS:
        raise ValueError(f"members × steps = {int(members)} × {int(steps)} = {work:.3g} exceeds "
                         f"{MAX_MEMBER_STEPS:.0e} member-steps (hours on one core): split the run into "
                         "smaller seeded runs")


def as_quaternions(name, value):
    """Return ``value`` as quaternions, shape (..., 4), scalar first, none of them zero.

    Not normalised: the rotations normalise (a quaternion of any non-zero length is read as
    its direction).
    """
    q = as_finite(name, value)
    if q.ndim == 0 or q.shape[-1] != 4:
        raise ValueError(f"{name} must have shape (..., 4) (scalar-first quaternions), got shape {q.shape}")
    norm = np.linalg.norm(q, axis=-1)
    if np.any(norm == 0):
        raise ValueError(f"{name} must not contain the zero quaternion")
    return q


def as_inertia(name, inertia):
    """Return ``inertia`` as positive principal moments (..., 3) or a symmetric positive-definite
    tensor (3, 3) [kg·m²]; a (3, 3) array is always read as a tensor."""
    j = as_finite(name, inertia)
    if j.shape == (3, 3):
        if not np.allclose(j, j.T, rtol=1e-12, atol=0.0):
            raise ValueError(f"{name} must be symmetric, got {j.tolist()}")
        if np.any(np.linalg.eigvalsh(j) <= 0):
            raise ValueError(f"{name} must be positive definite [kg·m²], got eigenvalues {np.linalg.eigvalsh(j)}")
        return j
    if j.ndim >= 1 and j.shape[-1] == 3:
        as_positive(name, j, unit="kg·m²")
        return j
    raise ValueError(f"{name} must have shape (..., 3) (principal moments) or (3, 3) (tensor) [kg·m²], "
                     f"got shape {j.shape}")


def as_axisymmetric_inertias(transverse_inertia, axial_inertia):
    """Return the transverse and axial moments (A, C) of an axisymmetric body [kg·m²], positive
    and meeting the triangle inequality C ≤ 2A."""
    a = as_positive("transverse_inertia", transverse_inertia, unit="kg·m²")
    c = as_positive("axial_inertia", axial_inertia, unit="kg·m²")
    if np.any(c > 2.0 * a):
        raise ValueError(f"axial_inertia must be <= 2 × transverse_inertia (triangle inequality), got C = "
                         f"{shown(np.max(c))} kg·m² with A = {shown(np.min(a))} kg·m²")
    return a, c
