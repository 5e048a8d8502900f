"""Torques on a spacecraft: the magnetic torque on a dipole.

Thesis §1.2, eqs. (4)–(8): L = m × B (the thesis writes M = L × B). SI throughout.
"""

import numpy as np

from .._validate import as_vectors
from ..constants import MU_0

__all__ = ["magnetic_torque", "magnetic_torque_from_h", "perpendicular_moment"]


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
