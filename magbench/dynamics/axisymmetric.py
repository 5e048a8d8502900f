r"""An axisymmetric body: the torque-free Euler case, its angular momentum and nutation, and the
conical rotation about the field of a body carrying a magnet on its symmetry axis.

TNS-0 preprint §2 (L141–L157: the Euler case fitted to each short session, eqs. (4)–(5), lost in
extraction) and §4 (L554–L580: the one-orbit model, rotation about B). Body axes: z along the
symmetry axis, A = B the transverse and C the axial moment of inertia. Euler angles 3-1-3
(precession ψ, nutation θ, proper rotation φ) from body axes to the L-frame (z along L), as
:func:`magbench.dynamics.euler_313_matrix`. SI throughout.
"""

import numpy as np

from .._validate import as_axisymmetric_inertias, as_finite, as_in_range, as_nonnegative, as_positive, as_vectors, shown
from .pendulum import euler_313_matrix

__all__ = ["euler_case_rates", "euler_case_angles", "euler_case_matrix", "body_rate_from_momentum",
           "momentum_and_nutation", "conical_rotation_angle", "conical_rotation_rate"]


def euler_case_rates(angular_momentum, nutation, transverse_inertia, axial_inertia):
    r"""Precession and proper-rotation rates of a torque-free axisymmetric body.

    Parameters
    ----------
    angular_momentum : float or array_like
        |L| ≥ 0 [kg·m²/s].
    nutation : float or array_like
        θ, angle between L and the symmetry axis, in [0, π] [rad].
    transverse_inertia : float or array_like
        A = B [kg·m²].
    axial_inertia : float or array_like
        C [kg·m²].

    Returns
    -------
    precession_rate : ndarray
        ψ̇ = L/A [rad/s].
    proper_rate : ndarray
        φ̇ = L cos θ (1/C − 1/A) [rad/s].

    Notes
    -----
    TNS-0 preprint §2 (L141–L157, eq. (4), lost): the Euler case. Reconstruction (Not in the
    sources: Beletsky (1965); Landau & Lifshitz, *Mechanics*, §35).
    """
    big_l = as_nonnegative("angular_momentum", angular_momentum, unit="kg·m²/s")
    theta = as_in_range("nutation", nutation, 0.0, np.pi, unit="rad")
    a, c = as_axisymmetric_inertias(transverse_inertia, axial_inertia)
    return big_l / a, big_l * np.cos(theta) * (1.0 / c - 1.0 / a)


def euler_case_angles(time, angular_momentum, nutation, transverse_inertia, axial_inertia, *, start_time=0.0,
                      initial_precession=0.0, initial_proper_rotation=0.0):
    r"""Euler angles of the torque-free axisymmetric body (the constants of TNS-0 Table 1).

    Parameters
    ----------
    time : float or array_like
        Time [s].
    angular_momentum : float or array_like
        |L| [kg·m²/s].
    nutation : float or array_like
        θ [rad].
    transverse_inertia : float or array_like
        A [kg·m²].
    axial_inertia : float or array_like
        C [kg·m²].
    start_time : float, optional
        t0 [s].
    initial_precession : float, optional
        ψ0 [rad].
    initial_proper_rotation : float, optional
        φ0 [rad].

    Returns
    -------
    precession, nutation, proper_rotation : ndarray
        ψ = ψ̇(t − t0) + ψ0, θ, φ = φ̇(t − t0) + φ0 [rad], broadcast together.

    Notes
    -----
    TNS-0 preprint §2, eq. (5) (L155–L157, lost in extraction; constants in Table 1).
    Reconstruction: Beletsky (1965) (Not in the sources). t0 trades against (ψ0, φ0): only five
    of the six constants are identifiable.
    """
    t = as_finite("time", time)
    psi_rate, phi_rate = euler_case_rates(angular_momentum, nutation, transverse_inertia, axial_inertia)
    t0 = as_finite("start_time", start_time)
    psi = psi_rate * (t - t0) + as_finite("initial_precession", initial_precession)
    phi = phi_rate * (t - t0) + as_finite("initial_proper_rotation", initial_proper_rotation)
    return np.broadcast_arrays(psi, np.asarray(nutation, dtype=float) + 0.0 * psi, phi)


def euler_case_matrix(time, angular_momentum, nutation, transverse_inertia, axial_inertia, *, start_time=0.0,
                      initial_precession=0.0, initial_proper_rotation=0.0):
    r"""Rotation from body axes to the L-frame for the torque-free axisymmetric body.

    Parameters
    ----------
    time : float or array_like
        Time [s].
    angular_momentum : float or array_like
        |L| [kg·m²/s].
    nutation : float or array_like
        θ [rad].
    transverse_inertia : float or array_like
        A [kg·m²].
    axial_inertia : float or array_like
        C [kg·m²].
    start_time : float, optional
        t0 [s].
    initial_precession : float, optional
        ψ0 [rad].
    initial_proper_rotation : float, optional
        φ0 [rad].

    Returns
    -------
    ndarray, shape (..., 3, 3)
        R = R_z(ψ) R_x(θ) R_z(φ) [-]: ``R @ v_body`` gives L-frame components.

    Notes
    -----
    TNS-0 preprint §2 (L141–L157): the L-frame is inertial in the Euler case. Reconstruction
    (Not in the sources: Beletsky 1965).
    """
    psi, theta, phi = euler_case_angles(time, angular_momentum, nutation, transverse_inertia, axial_inertia,
                                        start_time=start_time, initial_precession=initial_precession,
                                        initial_proper_rotation=initial_proper_rotation)
    return euler_313_matrix(psi, theta, phi)


def body_rate_from_momentum(angular_momentum, nutation, transverse_inertia, axial_inertia, proper_rotation=0.0):
    r"""Body angular velocity of an axisymmetric body with given |L|, nutation and proper rotation.

    Parameters
    ----------
    angular_momentum : float or array_like
        |L| [kg·m²/s].
    nutation : float or array_like
        θ [rad].
    transverse_inertia : float or array_like
        A [kg·m²].
    axial_inertia : float or array_like
        C [kg·m²].
    proper_rotation : float or array_like, optional
        φ [rad].

    Returns
    -------
    ndarray, shape (..., 3)
        ω = (L sin θ sin φ / A, L sin θ cos φ / A, L cos θ / C) [rad/s]; L_body = R(ψ,θ,φ)ᵀ ẑ |L|.

    Notes
    -----
    Not in the sources: the 3-1-3 kinematics (Beletsky 1965); TNS-0 preprint §2 (L141–L157).
    """
    big_l = as_nonnegative("angular_momentum", angular_momentum, unit="kg·m²/s")
    theta = as_in_range("nutation", nutation, 0.0, np.pi, unit="rad")
    a, c = as_axisymmetric_inertias(transverse_inertia, axial_inertia)
    phi = as_finite("proper_rotation", proper_rotation)
    st = np.sin(theta)
    return np.stack(np.broadcast_arrays(big_l * st * np.sin(phi) / a, big_l * st * np.cos(phi) / a,
                                        big_l * np.cos(theta) / c), axis=-1)


def momentum_and_nutation(body_rate, transverse_inertia, axial_inertia):
    r"""|L| and the nutation angle from the body angular velocity of an axisymmetric body.

    Parameters
    ----------
    body_rate : array_like, shape (..., 3)
        ω in body axes, z along the symmetry axis [rad/s].
    transverse_inertia : float or array_like
        A [kg·m²].
    axial_inertia : float or array_like
        C [kg·m²].

    Returns
    -------
    angular_momentum : ndarray
        |L| = |(Aω1, Aω2, Cω3)| [kg·m²/s].
    nutation : ndarray
        θ = arccos(Cω3/|L|) [rad] (0 where L = 0).

    Notes
    -----
    TNS-0 preprint §2 (L141–L157; Fig. 14's L). Not in the sources: L = Jω (Beletsky 1965).
    """
    w = as_vectors("body_rate", body_rate)
    a, c = as_axisymmetric_inertias(transverse_inertia, axial_inertia)
    a, c = np.asarray(a)[..., None], np.asarray(c)
    lx, ly, lz = a[..., 0] * w[..., 0], a[..., 0] * w[..., 1], c * w[..., 2]
    big_l = np.sqrt(lx**2 + ly**2 + lz**2)
    cos_theta = np.divide(lz, big_l, out=np.ones_like(big_l), where=big_l > 0)
    return big_l, np.arccos(np.clip(cos_theta, -1.0, 1.0))


def conical_rotation_angle(rotation_rate, field, magnet_moment, transverse_inertia, axial_inertia):
    r"""Angle θ′ between B and the symmetry axis of a body rotating uniformly about B.

    Parameters
    ----------
    rotation_rate : float or array_like
        Ω, the rate of the rotation about B, ≠ 0 [rad/s].
    field : float or array_like
        |B| [T].
    magnet_moment : float or array_like
        m of the magnet along the symmetry axis [A·m²].
    transverse_inertia : float or array_like
        A [kg·m²]; A > C (a prolate body) for a solution with the magnet toward +B.
    axial_inertia : float or array_like
        C [kg·m²].

    Returns
    -------
    ndarray
        θ′ = arccos[mB / (Ω²(A − C))] [rad]; NaN where |mB/(Ω²(A − C))| > 1 (no conical
        rotation: the rotation is too slow and the magnet simply aligns).

    Notes
    -----
    Not in the sources (ours, exact for a uniform field): a body with ω = Ω B̂, its axis at θ′
    from B, has dL/dt = ω × L = (C − A)Ω² cos θ′ B̂ × ê3, which the magnet torque m ê3 × B
    balances iff Ω²(A − C) cos θ′ = mB. It models the final regime of the TNS-0 preprint §4
    (L554–L580, Table 2: θ′ = 0.85 rad; conclusions L590: ≈ 45°).

    Examples
    --------
    >>> round(float(np.degrees(conical_rotation_angle(0.02, 35e-6, 0.35, 0.0406, 0.00625))), 2)
    26.93
    """
    rate = as_finite("rotation_rate", rotation_rate)
    if np.any(rate == 0):
        raise ValueError("rotation_rate must be non-zero [rad/s] (no conical rotation at rest)")
    b = as_nonnegative("field", field, unit="T")
    m = as_finite("magnet_moment", magnet_moment)
    a, c = as_axisymmetric_inertias(transverse_inertia, axial_inertia)
    if np.any(a == c):
        raise ValueError("transverse_inertia must differ from axial_inertia (a spherical body has no conical rotation)")
    ratio = m * b / (rate**2 * (a - c))
    with np.errstate(invalid="ignore"):
        return np.where(np.abs(ratio) <= 1.0, np.arccos(np.clip(ratio, -1.0, 1.0)), np.nan)


def conical_rotation_rate(angle, field, magnet_moment, transverse_inertia, axial_inertia):
    r"""Rate Ω of the uniform rotation about B that keeps the symmetry axis at θ′ from B.

    Parameters
    ----------
    angle : float or array_like
        θ′, in [0, π/2) for A > C [rad].
    field : float or array_like
        |B| [T].
    magnet_moment : float or array_like
        m ≥ 0 [A·m²].
    transverse_inertia : float or array_like
        A [kg·m²].
    axial_inertia : float or array_like
        C [kg·m²].

    Returns
    -------
    ndarray
        Ω = √(mB / ((A − C) cos θ′)) [rad/s]; NaN where the right side is negative.

    Notes
    -----
    Not in the sources (ours): the inverse of :func:`conical_rotation_angle`, the relation
    Ω²(A − C) cos θ′ = mB for the final regime of the TNS-0 preprint §4 (L554–L580).
    """
    theta = as_in_range("angle", angle, 0.0, np.pi, unit="rad")
    b = as_nonnegative("field", field, unit="T")
    m = as_nonnegative("magnet_moment", magnet_moment, unit="A·m²")
    a, c = as_axisymmetric_inertias(transverse_inertia, axial_inertia)
    value = m * b / ((a - c) * np.cos(theta))
    with np.errstate(invalid="ignore"):
        return np.where(value >= 0, np.sqrt(np.abs(value)), np.nan)
