r"""The libration angles of a gravity-gradient boom: the body z axis (the boom) measured from
the local vertical of a circular orbit, in the orbit plane (pitch) and out of it (roll)."""

import numpy as np

from .._validate import as_finite, as_quaternions
from . import kernels

__all__ = ["libration_angles"]


def libration_angles(attitude, orbital_axes):
    r"""Pitch, roll and total libration angle of the body z axis from the local vertical.

    Parameters
    ----------
    attitude : array_like, shape (..., 4)
        Scalar-first quaternion q, body → inertial (any non-zero length) [-].
    orbital_axes : array_like, shape (..., 3, 3)
        Rows X (along track), Y (orbit normal), Z (radial, up) in inertial components, as
        :meth:`magbench.earth.CircularOrbit.orbital_axes` gives them [-].

    Returns
    -------
    ndarray, shape (..., 3)
        Pitch θ = atan2(b_X, b_Z) (in the orbit plane, about the orbit normal), roll
        φ = arcsin b_Y (out of the plane) and total angle arccos b_Z, where b is the body z
        axis in orbital components [rad].

    Notes
    -----
    Not in the sources: the pitch/roll of a boom from the local vertical as in Hughes,
    *Spacecraft Attitude Dynamics* (1986), §9.3; Kovalenko (1975) §4.2 uses the same angles
    for the gravity-gradient torque (4.18).

    Examples
    --------
    >>> np.round(libration_angles([1.0, 0.0, 0.0, 0.0], np.eye(3)), 12).tolist()
    [0.0, 0.0, 0.0]
    """
    q = as_quaternions("attitude", attitude)
    axes = as_finite("orbital_axes", orbital_axes)
    if axes.ndim < 2 or axes.shape[-2:] != (3, 3):
        raise ValueError(f"orbital_axes must have shape (..., 3, 3), got shape {axes.shape}")
    return kernels.libration_angles(q, axes)
