"""Torques on a spacecraft: the magnetic torque on a dipole, a magnet on the symmetry axis and
hysteresis rods (TNS-0 preprint §3).

Thesis §1.2, eqs. (4)–(8): L = m × B (the thesis writes M = L × B). SI throughout.
"""

import numpy as np

from .._validate import as_finite, as_nonnegative, as_vectors
from ..constants import MU_0
from . import kernels

__all__ = ["magnetic_torque", "magnetic_torque_from_h", "perpendicular_moment", "hysteresis_rod_moment",
           "axial_magnet_torque"]


def magnetic_torque(moment, b):
    r"""Torque on a magnetic dipole in a field: the basic equation of magnetic control.

    Parameters
    ----------
    moment : array_like, shape (..., 3)
        Spacecraft magnetic moment, thesis symbol **L** [A·m²].
    b : array_like, shape (..., 3)
        Flux density, thesis symbol **B** [T].

    Returns
    -------
    ndarray, shape (..., 3)
        Torque, thesis symbol **M** [N·m]; always perpendicular to ``b``.

    Notes
    -----
    Thesis eq. (4) (components: eq. (6); Kovalenko eq. 1.1–1.2).

    Examples
    --------
    >>> magnetic_torque([1.0, 0.0, 0.0], [0.0, 0.0, 2.0]).tolist()   # eq. (7): M_y = −L_x B_z
    [0.0, -2.0, 0.0]
    """
    return np.cross(as_vectors("moment", moment), as_vectors("b", b))


def magnetic_torque_from_h(moment, h):
    r"""Torque on a magnetic dipole from the field strength H.

    Parameters
    ----------
    moment : array_like, shape (..., 3)
        Spacecraft magnetic moment **L** [A·m²].
    h : array_like, shape (..., 3)
        Field strength **H** [A/m].

    Returns
    -------
    ndarray, shape (..., 3)
        Torque μ0 **L** × **H** [N·m].

    Notes
    -----
    Thesis eq. (5).

    Deviation from source: the thesis writes **M** = **L** × **H**, which holds only in
    CGS units, where B and H coincide in vacuum. In SI the factor μ0 is required.
    """
    return MU_0 * np.cross(as_vectors("moment", moment), as_vectors("h", h))


def perpendicular_moment(moment, b):
    r"""Part of a magnetic moment perpendicular to the field: the only part that acts.

    Parameters
    ----------
    moment : array_like, shape (..., 3)
        Spacecraft magnetic moment **L** [A·m²].
    b : array_like, shape (..., 3)
        Flux density **B** [T]; must not be zero.

    Returns
    -------
    ndarray, shape (..., 3)
        **L**⊥ = **L** − (**L**·b̂) b̂ [A·m²], with **L**⊥ × **B** = **L** × **B**.

    Notes
    -----
    Thesis eq. (8).
    """
    m = as_vectors("moment", moment)
    bb = as_vectors("b", b)
    norm = np.linalg.norm(bb, axis=-1, keepdims=True)
    if np.any(norm == 0):
        raise ValueError("b must be non-zero: the perpendicular part is undefined in zero field")
    bhat = bb / norm
    return m - np.sum(m * bhat, axis=-1, keepdims=True) * bhat


def hysteresis_rod_moment(induction, rod_axes, volume):
    r"""Magnetic moment of a set of hysteresis rods in body axes.

    Parameters
    ----------
    induction : array_like, shape (..., k)
        Induction B of each of the k rods [T].
    rod_axes : array_like, shape (k, 3)
        Unit vector along each rod, body axes [-]; normalised here.
    volume : float or array_like, shape (k,)
        Volume V of each rod, ≥ 0 [m³].

    Returns
    -------
    ndarray, shape (..., 3)
        m = Σ V B/μ0 r̂ [A·m²].

    Notes
    -----
    TNS-0 preprint §3 (L392): rods along two orthogonal directions of the equatorial plane.
    Not in the sources: m = V B/μ0 (Flatley & Henretty 1995; Gerhardt & Palo 2010); V(B/μ0 − H)
    differs negligibly and dissipates the same ∮H dB.
    """
    b = as_finite("induction", induction)
    axes = as_vectors("rod_axes", rod_axes)
    if axes.ndim != 2 or b.ndim == 0 or b.shape[-1] != axes.shape[0]:
        raise ValueError(f"induction (..., k) and rod_axes (k, 3) must agree on k, got {b.shape} and {axes.shape}")
    norm = np.linalg.norm(axes, axis=-1, keepdims=True)
    if np.any(norm == 0):
        raise ValueError("rod_axes must not contain a zero vector")
    v = as_nonnegative("volume", volume, unit="m³")
    return kernels.rod_moment(b, axes / norm, v)


def axial_magnet_torque(magnet_moment, b):
    r"""Torque on a permanent magnet along the body's symmetry axis z.

    Parameters
    ----------
    magnet_moment : float or array_like
        Signed moment m along +z [A·m²].
    b : array_like, shape (..., 3)
        Flux density in body axes [T].

    Returns
    -------
    ndarray, shape (..., 3)
        m ẑ × B = m (−B_y, B_x, 0) [N·m].

    Notes
    -----
    TNS-0 preprint §3 (L392: a strong permanent magnet along the symmetry axis); thesis eq. (4)
    for the torque on a dipole.
    """
    m = as_finite("magnet_moment", magnet_moment)
    bb = as_vectors("b", b)
    m = m[..., None] if m.ndim else m
    return np.stack(np.broadcast_arrays(-bb[..., 1], bb[..., 0], 0.0 * bb[..., 2]), axis=-1) * m
