"""Checks of scalar inputs and coil poses shared by the field modules (SI)."""

import numpy as np

from .._validate import as_finite, as_positive, as_vectors, shown


def _scalar(name, value, check, **kw):
    arr = check(name, value, **kw)
    if arr.ndim != 0:
        raise ValueError(f"{name} must be a scalar, got an array of shape {arr.shape}")
    return float(arr)


def _finite_scalar(name, value):
    return _scalar(name, value, as_finite)


def _positive_scalar(name, value, unit=""):
    return _scalar(name, value, as_positive, unit=unit)


def _nonnegative_scalar(name, value, unit=""):
    v = _finite_scalar(name, value)
    if v < 0:
        raise ValueError(f"{name} must be >= 0{(' ' + unit) if unit else ''}, got {shown(v)}")
    return v


#: The tolerance of a uniform zone, as :func:`_tolerance` checks it (numpydoc entry for
#: :func:`magbench._docstrings.fill_docstring`).
TOLERANCE_DOC = """tolerance : float
    Allowed relative deviation δ = | |B| − B0 | / B0 [-], in (0, 1)."""


def _tolerance(tolerance):
    tol = _positive_scalar("tolerance", tolerance)
    if tol >= 1.0:
        raise ValueError(f"tolerance must lie in (0, 1), got {shown(tol)}")
    return tol


def _unit_normal(normal):
    n = as_vectors("normal", normal)
    if n.shape != (3,):
        raise ValueError(f"normal must be a single 3-vector, got shape {n.shape}")
    norm = float(np.linalg.norm(n))
    if norm == 0.0:
        raise ValueError("normal must be a non-zero 3-vector, got (0, 0, 0)")
    return n / norm


def _center(center):
    c = as_vectors("center", center)
    if c.shape != (3,):
        raise ValueError(f"center must be a single 3-vector, got shape {c.shape}")
    return c


def _frame(normal):
    """Rotation matrix whose columns are e1, e2, n (right-handed), from a unit normal.

    e1 = ŷ × n normalised (so n = ±ẑ gives e1 = ±x̂, n = x̂ gives e1 = −ẑ), or ẑ × n
    when n is within ~8° of ±ŷ.
    """
    n = _unit_normal(normal)
    ref = np.array([0.0, 1.0, 0.0]) if abs(n[1]) < 0.99 else np.array([0.0, 0.0, 1.0])
    e1 = np.cross(ref, n)
    e1 /= np.linalg.norm(e1)
    e2 = np.cross(n, e1)
    return np.stack([e1, e2, n], axis=-1)
