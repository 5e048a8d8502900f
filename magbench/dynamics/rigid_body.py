r"""A rigid spacecraft: attitude quaternion, Euler's equations and the gravity-gradient torque.

SamSat-218D §"Equations of motion" (seed lines 163–199: dK/dt + ω × K = M in principal
axes) and Kovalenko (1975) eq. (4.18) (gravity gradient). Quaternions are scalar-first
(w, x, y, z) and map body components to inertial ones, v_N = R(q) v_B (scipy's
``Rotation.from_quat(q, scalar_first=True)``). Vectors on a trailing axis of 3, Monte Carlo
members on leading axes. SI throughout.

``omega`` (the angular-velocity vector) is a name of the chapter-5 contract
(``shared/reference/bdot_triad.md`` §9); elsewhere the book says ``rate``.
"""

import numpy as np

from .._validate import as_finite, as_positive, as_vectors
from ..rotations import hamilton_product

__all__ = ["rotate_to_body", "rotate_to_inertial", "quaternion_rate", "euler_rates", "gravity_gradient_torque"]


def _cross(a, b):
    """a × b on a trailing axis of 3, broadcasting; no checks.

    The same numbers as :func:`numpy.cross`, written out because ``np.cross`` spends ~15 µs
    per call moving axes, two thirds of a detumbling step's time (the simulation calls it
    ten times per Runge–Kutta stage).
    """
    a0, a1, a2 = a[..., 0], a[..., 1], a[..., 2]
    b0, b1, b2 = b[..., 0], b[..., 1], b[..., 2]
    return np.stack([a1 * b2 - a2 * b1, a2 * b0 - a0 * b2, a0 * b1 - a1 * b0], axis=-1)


def _as_quaternions(name, value):
    q = as_finite(name, value)
    if q.ndim == 0 or q.shape[-1] != 4:
        raise ValueError(f"{name} must have shape (..., 4) (scalar-first quaternions), got shape {q.shape}")
    norm = np.linalg.norm(q, axis=-1)
    if np.any(norm == 0):
        raise ValueError(f"{name} must not contain the zero quaternion")
    return q


def _rotate(q, v, sign):
    """v rotated by the unit quaternion q (sign +1) or by its conjugate (sign −1); no checks."""
    q = q / np.linalg.norm(q, axis=-1, keepdims=True)
    w, u = q[..., :1], sign * q[..., 1:]
    t = 2.0 * _cross(u, v)
    return v + w * t + _cross(u, t)


def rotate_to_body(quaternion, vectors):
    r"""Inertial vectors expressed in body axes.

    Parameters
    ----------
    quaternion : array_like, shape (..., 4)
        Attitude q, scalar first, body → inertial; normalised here [-].
    vectors : array_like, shape (..., 3)
        Vectors in inertial components; broadcasts against ``quaternion`` [any unit].

    Returns
    -------
    ndarray, shape (..., 3)
        R(q)ᵀ v in body components [same unit as ``vectors``].

    Notes
    -----
    Not in the sources: the quaternion rotation v' = v + 2w(u × v) + 2u × (u × v) with the
    conjugate quaternion (Markley & Crassidis, *Fundamentals of Spacecraft Attitude
    Determination and Control*, 2014, eq. (2.124)); SamSat-218D §"Coordinate systems"
    uses the same body/reference transformation as a matrix.

    Examples
    --------
    >>> q = [np.cos(np.pi / 4), 0.0, 0.0, np.sin(np.pi / 4)]   # body turned 90° about z
    >>> np.round(rotate_to_body(q, [1.0, 0.0, 0.0]), 12).tolist()
    [0.0, -1.0, 0.0]
    """
    return _rotate(_as_quaternions("quaternion", quaternion), as_vectors("vectors", vectors), -1.0)


def rotate_to_inertial(quaternion, vectors):
    r"""Body vectors expressed in inertial axes.

    Parameters
    ----------
    quaternion : array_like, shape (..., 4)
        Attitude q, scalar first, body → inertial; normalised here [-].
    vectors : array_like, shape (..., 3)
        Vectors in body components; broadcasts against ``quaternion`` [any unit].

    Returns
    -------
    ndarray, shape (..., 3)
        R(q) v in inertial components [same unit as ``vectors``].

    Notes
    -----
    Not in the sources: Markley & Crassidis (2014) eq. (2.124).
    """
    return _rotate(_as_quaternions("quaternion", quaternion), as_vectors("vectors", vectors), 1.0)


def _quaternion_rate(q, omega):
    zero = np.zeros(np.broadcast_shapes(q.shape[:-1], omega.shape[:-1]) + (1,))
    pure = np.concatenate([zero, np.broadcast_to(omega, zero.shape[:-1] + (3,))], axis=-1)
    q = np.broadcast_to(q, pure.shape)
    return 0.5 * hamilton_product(q.reshape(-1, 4), pure.reshape(-1, 4)).reshape(pure.shape)


def quaternion_rate(quaternion, omega):
    r"""Time derivative of the attitude quaternion (kinematic equation).

    Parameters
    ----------
    quaternion : array_like, shape (..., 4)
        Attitude q, scalar first, body → inertial [-].
    omega : array_like, shape (..., 3)
        Angular velocity ω of the body relative to inertial space, in body axes [rad/s].

    Returns
    -------
    ndarray, shape (..., 4)
        q̇ = ½ q ⊗ (0, ω) [1/s].

    Notes
    -----
    Not in the sources (SamSat-218D §"Kinematics" uses angles; seed lines 211–223): the
    quaternion kinematics of Markley & Crassidis (2014) eq. (3.20), written for a
    body → inertial quaternion.
    """
    return _quaternion_rate(_as_quaternions("quaternion", quaternion), as_vectors("omega", omega))


def _inertia_matrix(name, inertia):
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


def _apply_inertia(j, v):
    return v @ j.T if j.shape == (3, 3) else j * v


def _euler_rates(omega, torque, j):
    rhs = torque - _cross(omega, _apply_inertia(j, omega))
    if j.shape == (3, 3):
        return np.linalg.solve(j, rhs[..., None])[..., 0] if rhs.ndim > 1 else np.linalg.solve(j, rhs)
    return rhs / j


def euler_rates(omega, torque, inertia):
    r"""Angular acceleration of a rigid body from Euler's equations.

    Parameters
    ----------
    omega : array_like, shape (..., 3)
        Angular velocity ω in body axes [rad/s].
    torque : array_like, shape (..., 3)
        External torque τ in body axes [N·m].
    inertia : array_like, shape (..., 3) or (3, 3)
        Principal moments (J_x, J_y, J_z) (body axes principal) or the full inertia tensor
        in body axes; a (3, 3) array is always read as a tensor [kg·m²].

    Returns
    -------
    ndarray, shape (..., 3)
        ω̇ = J⁻¹(τ − ω × Jω) [rad/s²].

    Notes
    -----
    SamSat-218D §"Equations of motion" (seed lines 163–199): dK/dt + ω × K = M, K = Jω;
    in principal axes J_x ω̇_x + (J_z − J_y) ω_y ω_z = M_x (cyclic). Kovalenko (1975)
    eq. (5.10) is the same law.

    Examples
    --------
    >>> euler_rates([0.0, 0.0, 1.0], [0.0, 0.0, 2.0], [1.0, 1.0, 4.0]).tolist()
    [0.0, 0.0, 0.5]
    """
    w = as_vectors("omega", omega)
    tau = as_vectors("torque", torque)
    return _euler_rates(w, tau, _inertia_matrix("inertia", inertia))


def _gravity_gradient_torque(radial, j, mean_motion):
    rhat = radial / np.linalg.norm(radial, axis=-1, keepdims=True)
    return 3.0 * np.asarray(mean_motion)[..., None] ** 2 * _cross(rhat, _apply_inertia(j, rhat))


def gravity_gradient_torque(radial_body, inertia, mean_motion):
    r"""Gravity-gradient torque on a rigid body on a circular orbit.

    Parameters
    ----------
    radial_body : array_like, shape (..., 3)
        Direction from the Earth's centre to the spacecraft, in body axes; only its
        direction is used (it must not be zero) [-].
    inertia : array_like, shape (..., 3) or (3, 3)
        Principal moments or the inertia tensor in body axes [kg·m²].
    mean_motion : float or array_like
        Orbital mean motion n = √(GM/r³) [rad/s].

    Returns
    -------
    ndarray, shape (..., 3)
        τ = 3n² r̂ × J r̂ in body axes [N·m]; zero when a principal axis is radial.

    Notes
    -----
    Kovalenko (1975) eq. (4.18); SamSat-218D §"Equations of motion" (seed line 189) lists
    it among the external torques.

    Examples
    --------
    >>> gravity_gradient_torque([1.0, 0.0, 0.0], [1.0, 2.0, 3.0], 1e-3).tolist()
    [0.0, 0.0, 0.0]
    """
    r = as_vectors("radial_body", radial_body)
    if np.any(np.linalg.norm(r, axis=-1) == 0):
        raise ValueError("radial_body must not contain a zero vector (its direction is the radial)")
    n = as_positive("mean_motion", mean_motion, unit="rad/s")
    return _gravity_gradient_torque(r, _inertia_matrix("inertia", inertia), n)
