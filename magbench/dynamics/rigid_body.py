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

from .._validate import as_inertia, as_positive, as_quaternions, as_vectors
from . import kernels

__all__ = ["rotate_to_body", "rotate_to_inertial", "quaternion_rate", "euler_rates", "gravity_gradient_torque"]


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
    return kernels.rotate(as_quaternions("quaternion", quaternion), as_vectors("vectors", vectors), -1.0)


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
    return kernels.rotate(as_quaternions("quaternion", quaternion), as_vectors("vectors", vectors), 1.0)


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
    return kernels.quaternion_rate(as_quaternions("quaternion", quaternion), as_vectors("omega", omega))


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
    return kernels.euler_rates(w, tau, as_inertia("inertia", inertia))


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
    return kernels.gravity_gradient_torque(r, as_inertia("inertia", inertia), n)
