r"""Dipole allocation: the moment that makes a wanted torque in a field, L = m × B.

Thesis §4.1 (the coils' moments along the body axes, with the thesis's small-angle
rotation of the field into the body). SI.
"""

import numpy as np

from .._validate import as_finite, as_vectors

__all__ = ["body_field_exact", "body_field_small_angle", "dipole_allocation", "ALLOCATIONS"]


def body_field_exact(psi, world_field):
    r"""Field in the mock-up's axes after a rotation ψ about the vertical.

    Parameters
    ----------
    psi : array_like
        Rotation of the body about the vertical z axis [rad].
    world_field : array_like, shape (..., 3)
        Field B⁰ in the fixed axes [T].

    Returns
    -------
    ndarray, shape (..., 3)
        :math:`\mathbf B = A(\psi)\mathbf B^0` with the exact
        :math:`A = \begin{bmatrix}\cos\psi & \sin\psi & 0\\ -\sin\psi & \cos\psi & 0\\ 0&0&1\end{bmatrix}` [T].

    Notes
    -----
    Thesis §4.1, with the exact rotation instead of the small-angle
    matrix. For B⁰ = (B0, 0, 0) it is B0 (cos ψ, −sin ψ, 0), the
    convention of eq. (36).

    Examples
    --------
    >>> np.round(body_field_exact(0.5 * np.pi, [1.0, 0.0, 0.0]), 12) + 0.0
    array([ 0., -1.,  0.])
    """
    psi = as_finite("psi", psi)[..., np.newaxis]
    b0 = as_vectors("world_field", world_field)
    c, s = np.cos(psi), np.sin(psi)
    return np.concatenate([c * b0[..., :1] + s * b0[..., 1:2], -s * b0[..., :1] + c * b0[..., 1:2],
                           np.broadcast_to(b0[..., 2:], np.broadcast_shapes(c.shape, b0[..., 2:].shape))],
                          axis=-1)


def body_field_small_angle(psi, world_field):
    r"""The thesis's small-angle approximation of the field in the mock-up's axes.

    Parameters
    ----------
    psi : array_like
        Rotation about the vertical [rad].
    world_field : array_like, shape (..., 3)
        Field B⁰ in the fixed axes [T].

    Returns
    -------
    ndarray, shape (..., 3)
        :math:`(B^0_x + \psi B^0_y,\ -\psi B^0_x + B^0_y,\ B^0_z)` [T]: the thesis's
        matrix A(φ, θ, ψ) with φ = θ = 0.

    Notes
    -----
    Thesis §4.1. The thesis then divides by :math:`|\mathbf B^0|`,
    not by the length of this vector, so the "unit" vector it allocates with is
    :math:`\sqrt{1+\psi^2}` long. Valid only while ψ² ≪ 1; the bench targets π/3 and
    2π/3.

    Examples
    --------
    >>> body_field_small_angle(0.1, [1.0, 0.0, 0.0])
    array([ 1. , -0.1,  0. ])
    """
    psi = as_finite("psi", psi)[..., np.newaxis]
    b0 = as_vectors("world_field", world_field)
    return np.concatenate([b0[..., :1] + psi * b0[..., 1:2], -psi * b0[..., :1] + b0[..., 1:2],
                           np.broadcast_to(b0[..., 2:], np.broadcast_shapes(psi.shape, b0[..., 2:].shape))],
                          axis=-1)


def dipole_allocation(desired_moment, field_direction):
    r"""Coil moments that realise a desired control dipole: M = m × b.

    Parameters
    ----------
    desired_moment : array_like, shape (..., 3)
        The controller's dipole demand m [A·m²] (the thesis uses m = (0, 0, m_z)).
    field_direction : array_like, shape (..., 3)
        Field direction b = B/|B| in body axes [-] (any length: it is used as given, so
        the thesis's small-angle vector can be passed unchanged).

    Returns
    -------
    ndarray, shape (..., 3)
        :math:`\mathbf M = \mathbf m\times\mathbf b` [A·m²]; with b_z = 0 and m = (0, 0,
        m_z): :math:`M_x = -m_z b_y`, :math:`M_y = m_z b_x`.

    Notes
    -----
    Thesis §4.1. With a unit b perpendicular to z, the torque of M
    is :math:`(\mathbf M\times\mathbf B)_z = -|\mathbf B|\,m_z`: the demand is realised
    exactly, with a minus sign that eq. (38) compensates by flipping the sign of (37)
    (the thesis does not say so).

    Examples
    --------
    >>> dipole_allocation([0.0, 0.0, 0.2], [0.0, -1.0, 0.0])
    array([0.2, 0. , 0. ])
    """
    return np.cross(as_vectors("desired_moment", desired_moment),
                    as_vectors("field_direction", field_direction)) + 0.0


ALLOCATIONS = ("exact", "small-angle")
