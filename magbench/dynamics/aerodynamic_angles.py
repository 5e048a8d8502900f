r"""SamSat-218D's attitude angles: attack, aerodynamic roll and velocity roll (an x-y-x sequence).

SamSat-218D §"Coordinate systems" (seed lines 61–69: the matrix B1 from orbital to body
axes) and §"Kinematics" (seed lines 211–223). The printed matrix is garbled; it is read
here as B1 = Rx(φn)·Ry(αn)·Rx(γa) with passive elementary rotations, which reproduces every
printed element. SI: radians, rad/s.
"""

import numpy as np

from .._validate import as_finite, shown

__all__ = ["aerodynamic_attitude_matrix", "aerodynamic_angles", "aerodynamic_body_rates"]


def aerodynamic_attitude_matrix(attack_angle, roll_angle, velocity_roll_angle):
    r"""Matrix B1 from orbital to body axes for SamSat-218D's angles.

    Parameters
    ----------
    attack_angle : array_like
        Spatial angle of attack αn (nutation) [rad].
    roll_angle : array_like
        Aerodynamic roll angle φn (proper rotation) [rad].
    velocity_roll_angle : array_like
        Velocity roll angle γa (precession) [rad].

    Returns
    -------
    ndarray, shape (..., 3, 3)
        B1 with v_body = B1 · v_orbital [-]:
        b11 = cos α, b12 = sin α sin γ, b13 = −sin α cos γ,
        b21 = sin α sin φ, b22 = cos φ cos γ − cos α sin φ sin γ,
        b23 = cos φ sin γ + cos α sin φ cos γ, b31 = sin α cos φ,
        b32 = −sin φ cos γ − cos α cos φ sin γ, b33 = −sin φ sin γ + cos α cos φ cos γ.

    Notes
    -----
    SamSat-218D §"Coordinate systems" (seed lines 61–69), reconstructed from the garbled
    text as B1 = Rx(φn) Ry(αn) Rx(γa) (passive rotations: Rx(a) = [[1, 0, 0], [0, c, s],
    [0, −s, c]], Ry(a) = [[c, 0, −s], [0, 1, 0], [s, 0, c]]).

    Examples
    --------
    >>> np.allclose(aerodynamic_attitude_matrix(0.0, 0.0, 0.0), np.eye(3))
    True
    """
    a = as_finite("attack_angle", attack_angle)
    f = as_finite("roll_angle", roll_angle)
    g = as_finite("velocity_roll_angle", velocity_roll_angle)
    a, f, g = np.broadcast_arrays(a, f, g)
    ca, sa, cf, sf, cg, sg = np.cos(a), np.sin(a), np.cos(f), np.sin(f), np.cos(g), np.sin(g)
    rows = [[ca, sa * sg, -sa * cg],
            [sa * sf, cf * cg - ca * sf * sg, cf * sg + ca * sf * cg],
            [sa * cf, -sf * cg - ca * cf * sg, -sf * sg + ca * cf * cg]]
    return np.stack([np.stack(row, axis=-1) for row in rows], axis=-2)


def aerodynamic_angles(matrix):
    r"""SamSat-218D's angles (αn, φn, γa) from the attitude matrix B1.

    Parameters
    ----------
    matrix : array_like, shape (..., 3, 3)
        Rotation matrix B1 from orbital to body axes (orthonormal, determinant +1 to 1e-6) [-].

    Returns
    -------
    attack_angle : ndarray
        αn = arccos b11 ∈ [0, π] [rad].
    roll_angle : ndarray
        φn = atan2(b21, b31) ∈ [−π, π] [rad].
    velocity_roll_angle : ndarray
        γa = atan2(b12, −b13) ∈ [−π, π] [rad].

    Notes
    -----
    SamSat-218D §"Two-vector attitude" (seed line 183: "known trigonometric relations").
    Singular at αn = 0 and π, where only φn + γa (or φn − γa) is defined; there the
    atan2 of two zeros returns 0.

    Examples
    --------
    >>> b1 = aerodynamic_attitude_matrix(0.5, -1.0, 2.0)
    >>> np.round(aerodynamic_angles(b1), 12).tolist()
    [0.5, -1.0, 2.0]
    """
    b = as_finite("matrix", matrix)
    if b.ndim < 2 or b.shape[-2:] != (3, 3):
        raise ValueError(f"matrix must have shape (..., 3, 3), got shape {b.shape}")
    error = np.abs(b @ np.swapaxes(b, -1, -2) - np.eye(3)).max(axis=(-2, -1))
    if np.any(error > 1e-6) or np.any(np.linalg.det(b) < 0):
        raise ValueError(f"matrix must be a rotation matrix (orthonormal to 1e-6, det +1), "
                         f"got an orthonormality error of {shown(float(np.max(error)))}")
    # Rounding can put |b11| a few ulp above 1 for an orthonormal matrix; not a clip of bad input.
    attack = np.arccos(np.clip(b[..., 0, 0], -1.0, 1.0))
    roll = np.arctan2(b[..., 1, 0], b[..., 2, 0])
    velocity_roll = np.arctan2(b[..., 0, 1], -b[..., 0, 2])
    return attack, roll, velocity_roll


def aerodynamic_body_rates(attack_angle, roll_angle, velocity_roll_angle, attack_rate, roll_rate,
                           velocity_roll_rate, orbital_rate):
    r"""Absolute angular velocity in body axes from SamSat-218D's angles and their rates.

    Parameters
    ----------
    attack_angle : array_like
        Spatial angle of attack αn [rad].
    roll_angle : array_like
        Aerodynamic roll angle φn [rad].
    velocity_roll_angle : array_like
        Velocity roll angle γa [rad].
    attack_rate : array_like
        dαn/dt [rad/s].
    roll_rate : array_like
        dφn/dt [rad/s].
    velocity_roll_rate : array_like
        dγa/dt [rad/s].
    orbital_rate : array_like
        Rate ω0 at which the orbital frame turns about +OY (the mean motion on a circular
        orbit) [rad/s].

    Returns
    -------
    ndarray, shape (..., 3)
        ω in body axes [rad/s]:
        ωx = γ̇ cos α + φ̇ + ω0 b12, ωy = γ̇ sin φ sin α + α̇ cos φ + ω0 b22,
        ωz = γ̇ cos φ sin α − α̇ sin φ + ω0 b32.

    Notes
    -----
    SamSat-218D §"Kinematics" (seed lines 211–223), the kinematic equations of the x-y-x
    angles on a circular orbit.

    Deviation from source: the paper prints the orbital-rate term as ω0·(b21, b22, b23), a
    row of B1; the body components of the orbital frame's rate ω0·OY are the second
    *column* ω0·(b12, b22, b32). The printed form differs from finite differences of the
    attitude by about ω0 (see the errata chapter); the relative part is as printed.

    Examples
    --------
    >>> np.round(aerodynamic_body_rates(0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1e-3), 15).tolist()
    [0.0, 0.001, 0.0]
    """
    a = as_finite("attack_angle", attack_angle)
    f = as_finite("roll_angle", roll_angle)
    g = as_finite("velocity_roll_angle", velocity_roll_angle)
    da = as_finite("attack_rate", attack_rate)
    df = as_finite("roll_rate", roll_rate)
    dg = as_finite("velocity_roll_rate", velocity_roll_rate)
    w0 = as_finite("orbital_rate", orbital_rate)
    column = aerodynamic_attitude_matrix(a, f, g)[..., :, 1]
    sa, ca, sf, cf = np.sin(a), np.cos(a), np.sin(f), np.cos(f)
    relative = np.stack(np.broadcast_arrays(dg * ca + df, dg * sf * sa + da * cf, dg * cf * sa - da * sf), axis=-1)
    return relative + np.asarray(w0)[..., None] * column
