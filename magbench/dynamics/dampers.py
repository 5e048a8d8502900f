r"""Spherical magnetic dampers: a free inner sphere carrying a magnet, coupled to the body by
viscous friction (fluid and eddy currents) or by dry friction in bearings.

Kovalenko (1975) §5.4, eqs. (5.19)–(5.25), seed lines 108–117, and the flown dampers of the
introduction (В.4, seed lines 17–18). SI throughout. Conventions used by every function here:
**ω** is the body's angular velocity, **ω**_d the ball's, both absolute (inertial) rates
written in body axes; the relative rate is **ω**_rel = **ω**_d − **ω** (the ball relative to
the body). A coupling torque **M** acts on the body and −**M** on the ball, so the pair
exchanges angular momentum without creating any.
"""

import numpy as np

from .._validate import as_finite, as_inertia, as_nonnegative, as_positive, as_vectors
from . import kernels

__all__ = ["viscous_damper_torque", "dry_friction_damper_torque", "spherical_damper_rhs", "spherical_damper_energy"]


def viscous_damper_torque(relative_rate, coefficient):
    r"""Torque of a viscous spherical damper on the body.

    Parameters
    ----------
    relative_rate : array_like, shape (..., 3)
        **ω**_rel = **ω**_d − **ω**, the ball's rate relative to the body [rad/s].
    coefficient : float or array_like
        Damping coefficient k_ж ≥ 0 (fluid plus eddy currents) [N·m·s/rad].

    Returns
    -------
    ndarray, shape (..., 3)
        **M** = k_ж **ω**_rel on the body [N·m] (−**M** on the ball). The pair loses energy at
        the rate k_ж |**ω**_rel|².

    Notes
    -----
    Kovalenko (1975) eq. (5.19), seed line 111, the viscous coupling of Sadov's
    damper; the flown values k_ж = 0.7–16 N·cm/(rad/s) (0.007–0.16 N·m·s/rad) are at seed
    line 18 (p. 17). Deviation from source: (5.19) is garbled in the seed; the coupling is
    written here as the torque between two rigid bodies.

    Examples
    --------
    >>> viscous_damper_torque([0.0, 0.0, 0.1], 0.05).tolist()
    [0.0, 0.0, 0.005000000000000001]
    """
    w = as_vectors("relative_rate", relative_rate)
    k = as_nonnegative("coefficient", coefficient, unit="N·m·s/rad")
    return kernels.viscous_damper_torque(w, k)


def dry_friction_damper_torque(relative_rate, b, friction_torque):
    r"""Torque of a dry-friction magnetic damper on the body.

    Parameters
    ----------
    relative_rate : array_like, shape (..., 3)
        **ω**_rel = **ω**_d − **ω**, the magnet's rate relative to the body [rad/s].
    b : array_like, shape (..., 3)
        Flux density **B** in body axes, non-zero [T]; the magnet points along it.
    friction_torque : float or array_like
        Friction torque of the bearings M_T ≥ 0 [N·m].

    Returns
    -------
    ndarray, shape (..., 3)
        **M** = M_T **ω**_rel⊥/|**ω**_rel⊥| on the body [N·m], **ω**_rel⊥ = **B** × (**ω**_rel ×
        **B**)/B² the part of the relative rate across **B**; zero where **ω**_rel⊥ = 0.

    Notes
    -----
    Kovalenko (1975) eqs. (5.24), (5.25), seed line 112: the book writes
    **M** = −M_T **ω***_отн⊥/|**ω***_отн⊥| with **ω*** the body's rate relative to the magnet,
    i.e. −**ω**_rel here, and gives its direction as **B** × (**ω**_отн⊥ × **B**) (5.25). The
    pair loses energy at the rate M_T |**ω**_rel⊥|.

    The torque is discontinuous at **ω**_rel⊥ = 0 (Coulomb friction): there the bearings can
    hold any torque up to M_T and the magnet sticks. This function returns the centre of that
    set, zero, exactly there and nothing is smoothed or clipped elsewhere. A fixed-step
    integration through a sticking phase therefore chatters: **ω**_rel⊥ changes sign each step
    with an amplitude of order M_T h (1/J + 1/J_d), which the step h must make small (the tests
    show it).
    """
    w = as_vectors("relative_rate", relative_rate)
    bb = as_vectors("b", b)
    if np.any(np.sum(bb * bb, axis=-1) == 0):
        raise ValueError("b must be non-zero: the magnet's direction is undefined in zero field")
    m = as_nonnegative("friction_torque", friction_torque, unit="N·m")
    return kernels.dry_friction_damper_torque(w, bb, m)


def spherical_damper_rhs(time, state, inertia, ball_inertia, coefficient, body_torque=(0.0, 0.0, 0.0),
                         ball_torque=(0.0, 0.0, 0.0), *, friction_torque=0.0, b=(0.0, 0.0, 1.0)):
    r"""Rates of a rigid body carrying a free spherical damper ball.

    Parameters
    ----------
    time : float
        Time [s] (unused: the torques are held over the step), as :func:`scipy.integrate.solve_ivp`
        and :func:`magbench.integrate.rk4_step` pass it.
    state : array_like, shape (..., 6)
        (**ω**, **ω**_d): body and ball absolute rates in body axes [rad/s].
    inertia : array_like, shape (3,) or (3, 3)
        Body inertia J, principal moments or tensor, without the ball [kg·m²].
    ball_inertia : float or array_like
        Moment of inertia of the ball about any axis through its centre, J_d > 0 [kg·m²].
    coefficient : float or array_like
        Viscous coupling k_ж ≥ 0 [N·m·s/rad].
    body_torque : array_like, shape (..., 3), optional
        External torque on the body, body axes [N·m].
    ball_torque : array_like, shape (..., 3), optional
        External torque on the ball (its magnet: **L** × **B**), body axes [N·m].
    friction_torque : float or array_like, optional
        Dry friction M_T ≥ 0 across ``b`` (:func:`dry_friction_damper_torque`) [N·m].
    b : array_like, shape (..., 3), optional
        Flux density in body axes, the direction of the dry friction's plane [T].

    Returns
    -------
    ndarray, shape (..., 6)
        (d**ω**/dt, d**ω**_d/dt) in body axes [rad/s²]:
        J **ω̇** + **ω** × J**ω** = **M**_body + **M**,
        J_d(**ω̇**_d + **ω** × **ω**_d) = **M**_ball − **M**, with **M** the coupling torque on
        the body (viscous plus dry).

    Notes
    -----
    Kovalenko (1975) eqs. (5.19)–(5.22), seed line 111: the relative
    motion of the damper's sphere. Deviation from source: the book writes the relative motion
    with the magnet tied to **B**; here the ball has its own inertia, so that the exchange of
    angular momentum can be checked. The ball is spherical, so its Euler equation has no
    gyroscopic term of its own; **ω** × **ω**_d converts its inertial derivative to body axes.
    """
    x = as_finite("state", state)
    if x.ndim == 0 or x.shape[-1] != 6:
        raise ValueError(f"state must have shape (..., 6) (body rate, ball rate), got shape {x.shape}")
    j = as_inertia("inertia", inertia)
    jd = as_positive("ball_inertia", ball_inertia, unit="kg·m²")
    k = as_nonnegative("coefficient", coefficient, unit="N·m·s/rad")
    mb = as_vectors("body_torque", body_torque)
    md = as_vectors("ball_torque", ball_torque)
    rel = x[..., 3:] - x[..., :3]
    coupling = kernels.viscous_damper_torque(rel, k)
    if np.any(np.asarray(friction_torque) != 0):
        coupling = coupling + dry_friction_damper_torque(rel, b, friction_torque)
    return kernels.spherical_damper_rhs(x, mb, md, j, jd, coupling)


def spherical_damper_energy(state, inertia, ball_inertia):
    r"""Kinetic energy and angular momentum of a body with a spherical damper ball.

    Parameters
    ----------
    state : array_like, shape (..., 6)
        (**ω**, **ω**_d) in body axes [rad/s].
    inertia : array_like, shape (3,) or (3, 3)
        Body inertia J [kg·m²].
    ball_inertia : float or array_like
        Ball inertia J_d > 0 [kg·m²].

    Returns
    -------
    energy : ndarray
        ½ **ω**·J**ω** + ½ J_d |**ω**_d|² [J].
    momentum : ndarray, shape (..., 3)
        J**ω** + J_d **ω**_d in body axes [kg·m²/s].

    Notes
    -----
    Kovalenko (1975) §5.4, seed lines 108–117: the damper's purpose is this energy's decay.
    Not in the sources: the two-body totals (any mechanics text).
    """
    x = as_finite("state", state)
    if x.ndim == 0 or x.shape[-1] != 6:
        raise ValueError(f"state must have shape (..., 6) (body rate, ball rate), got shape {x.shape}")
    j = as_inertia("inertia", inertia)
    jd = as_positive("ball_inertia", ball_inertia, unit="kg·m²")
    w, wd = x[..., :3], x[..., 3:]
    jw = kernels.apply_inertia(j, w)
    jd = np.asarray(jd)[..., None]
    energy = 0.5 * np.sum(w * jw, axis=-1) + 0.5 * jd[..., 0] * np.sum(wd * wd, axis=-1)
    return energy, jw + jd * wd
