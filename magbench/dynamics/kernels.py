r"""The dynamics family's array kernels: the rigid body, the gyrostat, the rod moment and the
planar pitch model of a magnet-held body (Kovalenko §6.4).

Unchecked, SI, Monte Carlo members on leading axes, vectors on a trailing axis of 3 (the
layout of :mod:`magbench.dynamics`). The checked public functions of
:mod:`~magbench.dynamics.rigid_body`, :mod:`~magbench.dynamics.gyrostat`,
:mod:`~magbench.dynamics.torques` and :mod:`~magbench.dynamics.planar` validate their inputs
and call these; a simulator that has validated its inputs once calls them per step. Their
docstrings name the checked function that documents the physics.

A compiled (numba) twin sits beside a numpy kernel where a solver calls a right-hand side once
per stage from Python (:func:`scipy.integrate.solve_ivp`): there a numpy kernel on one state
spends its time in per-call overhead, a compiled one in arithmetic. Each twin repeats its numpy
kernel's operations in the same order, without fast-math, and the tests hold the two equal to
the last bit. ``cache=True`` keeps the compiled code in ``__pycache__``.
"""

import numpy as np
from numba import njit

from ..constants import MU_0
from ..rotations import hamilton_product

__all__ = ["cross", "rotate", "quaternion_rate", "apply_inertia", "euler_rates", "gravity_gradient_torque",
           "gyrostat_rates", "gyrostat_rhs", "rod_moment", "gyrostat_turning_field_rhs", "eddy_torque",
           "anisotropic_eddy_torque", "spherical_shell_eddy_torque", "viscous_damper_torque",
           "dry_friction_damper_torque", "spherical_damper_rhs", "libration_angles"]


def cross(a, b):
    """a × b on a trailing axis of 3, broadcasting; the checked form is :func:`numpy.cross`.

    The same numbers as :func:`numpy.cross`, written out because ``np.cross`` spends ~15 µs
    per call moving axes, two thirds of a detumbling step's time (the simulation calls it
    ten times per Runge–Kutta stage).
    """
    a0, a1, a2 = a[..., 0], a[..., 1], a[..., 2]
    b0, b1, b2 = b[..., 0], b[..., 1], b[..., 2]
    return np.stack([a1 * b2 - a2 * b1, a2 * b0 - a0 * b2, a0 * b1 - a1 * b0], axis=-1)


def rotate(q, v, sign):
    """v rotated by the quaternion q (sign +1, body → inertial) or by its conjugate (sign −1).

    q is normalised here; :func:`magbench.dynamics.rotate_to_inertial` and
    :func:`~magbench.dynamics.rotate_to_body` are the checked forms.
    """
    q = q / np.linalg.norm(q, axis=-1, keepdims=True)
    w, u = q[..., :1], sign * q[..., 1:]
    t = 2.0 * cross(u, v)
    return v + w * t + cross(u, t)


def quaternion_rate(q, rate):
    """q̇ = ½ q ⊗ (0, ω), ω = rate; the checked form is :func:`magbench.dynamics.quaternion_rate`."""
    zero = np.zeros(np.broadcast_shapes(q.shape[:-1], rate.shape[:-1]) + (1,))
    pure = np.concatenate([zero, np.broadcast_to(rate, zero.shape[:-1] + (3,))], axis=-1)
    q = np.broadcast_to(q, pure.shape)
    return 0.5 * hamilton_product(q.reshape(-1, 4), pure.reshape(-1, 4)).reshape(pure.shape)


def apply_inertia(j, v):
    """J v for principal moments j (..., 3) or a tensor j (3, 3); the checked inertia is
    :func:`magbench.dynamics.euler_rates`'s."""
    return v @ j.T if j.shape == (3, 3) else j * v


def euler_rates(rate, torque, j):
    """ω̇ = J⁻¹(τ − ω × Jω), ω = rate; the checked form is :func:`magbench.dynamics.euler_rates`."""
    rhs = torque - cross(rate, apply_inertia(j, rate))
    if j.shape == (3, 3):
        return np.linalg.solve(j, rhs[..., None])[..., 0] if rhs.ndim > 1 else np.linalg.solve(j, rhs)
    return rhs / j


def gravity_gradient_torque(radial, j, mean_motion):
    """3n² r̂ × J r̂; the checked form is :func:`magbench.dynamics.gravity_gradient_torque`."""
    rhat = radial / np.linalg.norm(radial, axis=-1, keepdims=True)
    return 3.0 * np.asarray(mean_motion)[..., None] ** 2 * cross(rhat, apply_inertia(j, rhat))


def gyrostat_rates(rate, torque, j, rotor_momentum):
    """ω̇ = I⁻¹(T − ω × (Iω + h e1)); the checked form is :func:`magbench.dynamics.gyrostat_rates`."""
    h = np.asarray(rotor_momentum, dtype=float)[..., None] * np.array([1.0, 0.0, 0.0])
    return euler_rates(rate, torque - cross(rate, h), j)


def gyrostat_rhs(state, dipole, field_orbital, j, rotor_momentum, mean_motion):
    """(q̇, ω̇) of the gyrostat on a circular orbit; the checked form is
    :func:`magbench.dynamics.gyrostat_rhs` (which documents the state and frames)."""
    q, w = state[..., :4], state[..., 4:]
    normal = rotate(q, np.broadcast_to(np.array([0.0, 1.0, 0.0]), w.shape), -1.0)
    radial = rotate(q, np.broadcast_to(np.array([0.0, 0.0, 1.0]), w.shape), -1.0)
    field = rotate(q, field_orbital, -1.0)
    torque = cross(dipole, field) + gravity_gradient_torque(radial, j, mean_motion)
    q_rate = quaternion_rate(q, w - mean_motion * normal)
    return np.concatenate([q_rate, gyrostat_rates(w, torque, j, rotor_momentum)], axis=-1)


def rod_moment(induction, rod_axes, volume):
    """Σ_k V_k B_k/μ0 r̂_k; the checked form is :func:`magbench.dynamics.hysteresis_rod_moment`."""
    return np.einsum("...k,kj->...j", induction * volume / MU_0, rod_axes)


def eddy_torque(rate, b, coefficient):
    """k (ω × B) × B, ω = rate; the checked form is :func:`magbench.dynamics.eddy_torque`."""
    return np.asarray(coefficient)[..., None] * cross(cross(rate, b), b)


def anisotropic_eddy_torque(rate, b, coefficients):
    """(Γ (ω × B)) × B, Γ = diag(coefficients); the checked form is
    :func:`magbench.dynamics.anisotropic_eddy_torque`."""
    return cross(coefficients * cross(rate, b), b)


def spherical_shell_eddy_torque(rate, b, coefficient, time_constant):
    """k [(ω × B) × B − τω² B⊥ × B]/(1 + ω²τ²); the checked form is
    :func:`magbench.dynamics.spherical_shell_eddy_torque`."""
    w2 = np.sum(rate * rate, axis=-1, keepdims=True)
    safe = np.where(w2 > 0.0, w2, 1.0)
    b_perp = b - np.sum(b * rate, axis=-1, keepdims=True) * rate / safe
    tau = np.asarray(time_constant)[..., None]
    k = np.asarray(coefficient)[..., None]
    return k * (cross(cross(rate, b), b) - tau * w2 * cross(b_perp, b)) / (1.0 + w2 * tau * tau)


def viscous_damper_torque(relative_rate, coefficient):
    """k ω_rel on the body; the checked form is :func:`magbench.dynamics.viscous_damper_torque`."""
    return np.asarray(coefficient)[..., None] * relative_rate


def dry_friction_damper_torque(relative_rate, b, friction_torque):
    """M_T ω_rel⊥/|ω_rel⊥| on the body (zero where ω_rel⊥ = 0); the checked form is
    :func:`magbench.dynamics.dry_friction_damper_torque`."""
    bhat = b / np.linalg.norm(b, axis=-1, keepdims=True)
    perp = relative_rate - np.sum(relative_rate * bhat, axis=-1, keepdims=True) * bhat
    scale = np.max(np.abs(perp), axis=-1, keepdims=True)  # scaled first: |perp|² may underflow
    unit = perp / np.where(scale > 0.0, scale, 1.0)
    unit = unit / np.where(scale > 0.0, np.linalg.norm(unit, axis=-1, keepdims=True), 1.0)
    return np.asarray(friction_torque)[..., None] * unit


def spherical_damper_rhs(state, body_torque, ball_torque, j, ball_inertia, coupling):
    """(ω̇, ω̇_d) of a body and a free spherical ball; the checked form is
    :func:`magbench.dynamics.spherical_damper_rhs` (which documents the state and frames)."""
    w, wd = state[..., :3], state[..., 3:]
    coupled = body_torque + coupling
    w_rate = euler_rates(w, coupled, j)
    wd_rate = (ball_torque - coupling) / np.asarray(ball_inertia)[..., None] - cross(w, wd)
    return np.concatenate([w_rate, wd_rate], axis=-1)


def libration_angles(q, orbital_axes):
    """(pitch, roll, total) of the body z axis from the local vertical, shape (..., 3); the
    checked form is :func:`magbench.dynamics.libration_angles`."""
    boom = rotate(q, np.array([0.0, 0.0, 1.0]), 1.0)
    b = np.einsum("...ij,...j->...i", orbital_axes, boom)
    return np.stack([np.arctan2(b[..., 0], b[..., 2]), np.arcsin(np.clip(b[..., 1], -1.0, 1.0)),
                     np.arccos(np.clip(b[..., 2], -1.0, 1.0))], axis=-1)


# The unused tensor slots of gyrostat_rates_scalar's inertia for principal moments.
_EYE = np.eye(3)


@njit(cache=True, error_model="numpy")
def gyrostat_turning_field_rhs(time, state, principal_inertia, rotor_momentum, damping_gain, field_rate):
    """Compiled twin of :func:`magbench.dynamics.gyrostat_turning_field_rhs` for one state (9,)."""
    w1, w2, w3, b1, b2, b3, n1, n2, n3 = (state[0], state[1], state[2], state[3], state[4], state[5], state[6],
                                          state[7], state[8])
    a, b, c = principal_inertia[0], principal_inertia[1], principal_inertia[2]
    h, k = rotor_momentum, damping_gain
    bb = b1 * b1 + b2 * b2 + b3 * b3
    wb = (w1 * b1 + w2 * b2 + w3 * b3) / bb
    t1, t2, t3 = -k * (w1 - wb * b1), -k * (w2 - wb * b2), -k * (w3 - wb * b3)
    out = np.empty(9)
    out[0], out[1], out[2] = gyrostat_rates_scalar((w1, w2, w3), (t1, t2, t3), (True, (a, b, c), _EYE, _EYE), h)
    out[3] = -(w2 * b3 - w3 * b2) + field_rate * (n2 * b3 - n3 * b2)
    out[4] = -(w3 * b1 - w1 * b3) + field_rate * (n3 * b1 - n1 * b3)
    out[5] = -(w1 * b2 - w2 * b1) + field_rate * (n1 * b2 - n2 * b1)
    out[6], out[7], out[8] = -(w2 * n3 - w3 * n2), -(w3 * n1 - w1 * n3), -(w1 * n2 - w2 * n1)
    return out


# The compiled twins of quaternion_rate and gyrostat_rates for one body in scalars (tuples
# in, a tuple out): the compiled simulation loops (detumbling, passive) form their members'
# right-hand sides from them, so the rigid body's equations are written once in numpy and
# once compiled.
__all__ += ["quaternion_rate_scalar", "gyrostat_rates_scalar"]


@njit(cache=True, error_model="numpy")
def quaternion_rate_scalar(q, rate):
    """Compiled twin of :func:`~magbench.dynamics.kernels.quaternion_rate` for one body: q
    (4-tuple, scalar first) and ω (3-tuple) in, q̇ (4-tuple) out.

    ½ q ⊗ (0, ω) as :func:`magbench.rotations.hamilton_product` forms it, without its
    products with the zero scalar part (they add exact zeros: the same numbers).
    """
    q0, q1, q2, q3 = q
    w0, w1, w2 = rate
    return (-0.5 * (q1 * w0 + q2 * w1 + q3 * w2), 0.5 * (q0 * w0 + q2 * w2 - q3 * w1),
            0.5 * (q0 * w1 - q1 * w2 + q3 * w0), 0.5 * (q0 * w2 + q1 * w1 - q2 * w0))


@njit(cache=True, error_model="numpy")
def gyrostat_rates_scalar(rate, torque, inertia, rotor_momentum):
    """Compiled twin of :func:`~magbench.dynamics.kernels.gyrostat_rates` (and, with
    ``rotor_momentum`` 0, of :func:`~magbench.dynamics.kernels.euler_rates`) for one body:
    ω̇ = J⁻¹((τ − ω × h e1) − ω × Jω) as a 3-tuple.

    ``inertia`` = (diag, j, jt, jinv): principal moments j (3-tuple) when ``diag``, else the
    tensor jt (3, 3) and its inverse jinv, which multiplies where the numpy kernel solves
    (equal to rounding; the principal form divides, as the numpy kernel does: equal to the
    last bit). The rotor's term ω × h e1 = (0, ω3 h, −ω2 h) is the numpy kernel's cross
    product without its products with zeros (an exact zero for a rigid body).
    """
    w0, w1, w2 = rate
    t0, t1, t2 = torque
    diag, j, jt, jinv = inertia
    j0, j1, j2 = j
    if diag:
        a0, a1, a2 = j0 * w0, j1 * w1, j2 * w2
    else:
        a0 = jt[0, 0] * w0 + jt[0, 1] * w1 + jt[0, 2] * w2
        a1 = jt[1, 0] * w0 + jt[1, 1] * w1 + jt[1, 2] * w2
        a2 = jt[2, 0] * w0 + jt[2, 1] * w1 + jt[2, 2] * w2
    t1, t2 = t1 - w2 * rotor_momentum, t2 + w1 * rotor_momentum
    g0, g1, g2 = t0 - (w1 * a2 - w2 * a1), t1 - (w2 * a0 - w0 * a2), t2 - (w0 * a1 - w1 * a0)
    if diag:
        return g0 / j0, g1 / j1, g2 / j2
    return (jinv[0, 0] * g0 + jinv[0, 1] * g1 + jinv[0, 2] * g2, jinv[1, 0] * g0 + jinv[1, 1] * g1 + jinv[1, 2] * g2,
            jinv[2, 0] * g0 + jinv[2, 1] * g1 + jinv[2, 2] * g2)


# Listed here, beside its function, so that other kernels added to this module merge cleanly.
__all__ += ["rotor_reduced_rates"]


def rotor_reduced_rates(x, t1, t2, t3, a):
    r"""The symmetric gyrostat's 5-state dimensionless model, numpy kernel; no checks.

    Parameters
    ----------
    x : ndarray, shape (5, ...)
        α, β [rad], h = H/(ω0 B), Ω2, Ω3 [-].
    t1, t2, t3 : ndarray
        Non-gravity torque in the semi-body frame divided by ω0² B, per axis [-].
    a : float or ndarray
        a = A/B [-].

    Returns
    -------
    ndarray, shape (5, ...)
        (α', β', h', Ω2', Ω3') [-] of :func:`magbench.dynamics.rotor_reduced_rhs`, its
        checked form.

    Notes
    -----
    Rotor slides, slide "Equations of motion in the semi-body frame" (seed lines 29–38)
    divided by B (``rotor_spin.md`` §4). A numpy kernel beside the compiled twins: the
    normalised simulations call it on (5, members) arrays, which vectorise.
    """
    alpha, beta, h, w2, w3 = x
    sa, ca, sb, cb = np.sin(alpha), np.cos(alpha), np.sin(beta), np.cos(beta)
    tb = sb / cb
    return np.stack(np.broadcast_arrays(
        w2 / cb - 1.0, w3, t1,
        -h * w3 + w2 * w3 * tb + t2 - 3.0 * (a - 1.0) * sa * ca * cb,
        h * w2 - w2**2 * tb + t3 + 3.0 * (a - 1.0) * sa**2 * sb * cb))


# The planar (pitch) motion of a body held along B on a magnetopolar orbit (Kovalenko §6.4).
__all__ += ["planar_rates"]


def planar_rates(state, field_angle, field_angle_acceleration, field_b, mean_motion, body, damper):
    """(γ̇, γ̈, γ̇1) of the planar model, state (..., 3) = (γ, γ̇, γ1), members on the leading
    axes; body = (J, L, ΔJ), damper = (k_д, M_T, friction_rate, c, L_y), each a scalar or an
    array over the members; no checks. The checked form, which documents the equations, is
    :func:`magbench.dynamics.planar_rhs`."""
    gamma, rate, gamma1 = state[..., 0], state[..., 1], state[..., 2]
    inertia, moment, inertia_difference = body
    viscous, friction, friction_rate, stiffness, damper_moment = damper
    elastic = np.asarray(damper_moment) > 0.0
    held = -viscous * rate - friction * np.tanh(rate / friction_rate)
    magnet = damper_moment * field_b * np.sin(gamma1)
    damper_torque = np.where(elastic, -magnet, held)
    safe = np.where(elastic, viscous, 1.0)
    # The magnet's drive g = L_y B sin γ1 − c(γ − γ1) is held by the friction up to M_T; only
    # the excess turns it against k_д (with M_T = 0, g − 0 = g exactly: the viscous case unchanged).
    drive = magnet - stiffness * (gamma - gamma1)
    excess = drive - np.clip(drive, -friction, friction)
    rate1 = np.where(elastic, rate - excess / safe, 0.0)
    torque = (-moment * field_b * np.sin(gamma)
              + 1.5 * mean_motion**2 * inertia_difference * np.sin(2.0 * (field_angle + gamma)) + damper_torque)
    acceleration = torque / inertia - field_angle_acceleration
    return np.stack(np.broadcast_arrays(rate, acceleration, rate1), axis=-1)
