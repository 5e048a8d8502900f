r"""The planar (pitch) motion of a spacecraft held along B by a magnet on a magnetopolar
orbit, with a viscous, a dry-friction or an elastically coupled magnetic damper.

Kovalenko (1975) §6.4, eqs. (6.28), (6.37)–(6.44) (seed lines 135–138). The body's magnet L
lies along its axis x; γ is the angle from B to x, η the angle from the along-track axis
x0 to B (:func:`magbench.earth.polar_field_direction_angle`), both turned in the sense of
the orbital motion (about the orbit normal r × v). SI, rad.
"""

from dataclasses import dataclass

import numpy as np

from .._validate import as_finite, as_nonnegative, as_positive
from . import kernels

__all__ = ["PlanarBody", "PlanarDamper", "planar_rhs", "planar_gravity_torque", "planar_energy"]


def _member_array(name, value, check, unit):
    arr = check(name, value, unit=unit)
    if arr.ndim > 1:
        raise ValueError(f"{name} must be a scalar or one value per member, shape (M,), got shape {arr.shape}")
    return float(arr) if arr.ndim == 0 else arr


@dataclass(frozen=True)
class PlanarBody:
    r"""The body of the planar model: inertia, magnet and the gravity-gradient inertia difference.

    Parameters
    ----------
    inertia : float or array_like, shape (M,)
        J, the moment of inertia about the orbit normal (a transverse axis) [kg·m²].
    moment : float or array_like, shape (M,)
        L, the body's magnet along its axis x, ≥ 0 [A·m²].
    inertia_difference : float or array_like, shape (M,), optional
        ΔJ = J_transverse − J_axial, the transverse (in-plane) moment minus that about the
        magnet's axis; positive for a body long across its magnet [kg·m²].

    Notes
    -----
    Kovalenko (1975) eqs. (6.28), (6.37) (seed lines 135–137: "ΔJ — the difference between
    the moments of inertia about the transverse and the longitudinal axes").
    """

    inertia: object
    moment: object
    inertia_difference: object = 0.0

    def __post_init__(self):
        object.__setattr__(self, "inertia", _member_array("inertia", self.inertia, as_positive, "kg·m²"))
        object.__setattr__(self, "moment", _member_array("moment", self.moment, as_nonnegative, "A·m²"))
        diff = as_finite("inertia_difference", self.inertia_difference)
        if diff.ndim > 1:
            raise ValueError(f"inertia_difference must be a scalar or shape (M,), got shape {diff.shape}")
        object.__setattr__(self, "inertia_difference", float(diff) if diff.ndim == 0 else diff)

    def as_tuple(self):
        """(J, L, ΔJ) as the kernel takes it [kg·m², A·m², kg·m²]."""
        return self.inertia, self.moment, self.inertia_difference


@dataclass(frozen=True)
class PlanarDamper:
    r"""The damper of the planar model: viscous, dry friction, or a magnet coupled elastically.

    Parameters
    ----------
    viscous : float or array_like, shape (M,), optional
        k_д, the viscous coefficient, ≥ 0 [N·m·s]: between the body and B (the damper's
        magnet held along B) or, with ``damper_moment`` > 0, between the body and the damper's
        magnet (then > 0).
    friction : float or array_like, shape (M,), optional
        M_T, the dry-friction torque, ≥ 0 [N·m]: between the body and B (the damper's magnet
        held along B) or, with ``damper_moment`` > 0, between the body (the damper's case) and
        the damper's magnet (then with ``viscous`` > 0 beside it; see Notes).
    friction_rate : float, optional
        ε > 0, the rate below which the dry friction is smoothed, M_T tanh(γ̇/ε) in place of
        M_T sign γ̇, with the magnet held along B; the elastic damper's friction is not
        smoothed (see Notes) [rad/s].
    stiffness : float or array_like, shape (M,), optional
        c, the elastic coupling of the damper's magnet to the body, ≥ 0 [N·m/rad].
    damper_moment : float or array_like, shape (M,), optional
        L_y, the damper magnet's moment, ≥ 0 [A·m²]; 0 holds the damper's magnet along B
        (a rigid link to the field: eq. (6.39)).

    Notes
    -----
    Kovalenko (1975) eqs. (6.39) (viscous, k_д γ̇), p. 137 (dry friction, M_T sign γ̇ in place
    of k_д γ̇) and (6.43)–(6.44) (the elastically coupled magnet, seed lines 137–138). The
    elastic damper with dry friction is the book's example on p. 150 (seed line 150, fig. 6.10:
    "a dry-friction damper with an elastic coupling to the body"): the friction acts between the
    magnet (the inner sphere of fig. 6.4) and the body's case, on the relative rate γ̇ − γ̇1, and
    (6.44) becomes c(γ − γ1) + k_д(γ̇ − γ̇1) + M_T sign(γ̇ − γ̇1) = L_y B sin γ1.

    Deviation from source: the dry friction is M_T tanh(γ̇/ε) (a smooth sign, so that the
    fixed-step integrator meets no discontinuity); it equals M_T sign γ̇ to 1 − tanh(5) =
    1.8e-4 relative where |γ̇| > 5ε, and it does not stick exactly: at rest under a torque
    below M_T the body creeps at γ̇ ≈ ε × torque/M_T.

    Deviation from source (elastic damper with dry friction): the book's magnet is massless
    (inertia term dropped, seed line 138) and its friction pure (no k_д). Massless and purely
    dry, the magnet's rate is not a function of the state: it sticks to the case while
    |L_y B sin γ1 − c(γ − γ1)| < M_T and jumps along the set where that drive equals ±M_T
    otherwise (a sweeping process, not an ODE); with the smoothed sign, ε artanh(g/M_T) is the
    rate and the equation is stiff beyond any fixed step (rate constant ∝ cosh²(slip/ε)).
    Here a viscous k_д > 0 is kept beside the dry friction, which makes the massless magnet's
    rate an explicit, Lipschitz function of the state with the exact (unsmoothed) sign:
    γ̇1 = γ̇ − [g − clip(g, −M_T, M_T)]/k_д, g = L_y B sin γ1 − c(γ − γ1) (stuck while
    |g| ≤ M_T). The book's pure dry friction is the limit k_д → 0; a small k_д (the damper's
    slip torque k_д × slip ≪ M_T) reproduces it, at a step below ~k_д/(c + L_y B) (the
    magnet's relaxation time during slip; RK4 is stable to 2.8 times it).
    """

    viscous: object = 0.0
    friction: object = 0.0
    friction_rate: float = 1e-6
    stiffness: object = 0.0
    damper_moment: object = 0.0

    def __post_init__(self):
        for name, unit in (("viscous", "N·m·s"), ("friction", "N·m"), ("stiffness", "N·m/rad"),
                           ("damper_moment", "A·m²")):
            object.__setattr__(self, name, _member_array(name, getattr(self, name), as_nonnegative, unit))
        object.__setattr__(self, "friction_rate", float(as_positive("friction_rate", self.friction_rate, unit="rad/s")))
        elastic = np.asarray(self.damper_moment) > 0
        if np.any(elastic & (np.asarray(self.viscous) <= 0)):
            raise ValueError("viscous must be > 0 N·m·s where damper_moment > 0 (the massless damper magnet "
                             "of eq. (6.44) moves at a rate set by k_д)")
        if np.any(~elastic & (np.asarray(self.stiffness) > 0)):
            raise ValueError("stiffness needs damper_moment > 0 (a spring to a magnet held along B is not modelled)")

    def as_tuple(self):
        """(k_д, M_T, ε, c, L_y) as the kernel takes it [SI]."""
        return self.viscous, self.friction, self.friction_rate, self.stiffness, self.damper_moment


def _check_body_damper(body, damper):
    if not isinstance(body, PlanarBody):
        raise ValueError(f"body must be a magbench.dynamics.PlanarBody, got {type(body).__name__}")
    if not isinstance(damper, PlanarDamper):
        raise ValueError(f"damper must be a magbench.dynamics.PlanarDamper, got {type(damper).__name__}")


def planar_rhs(state, field_angle, field_angle_acceleration, field_b, mean_motion, body, damper):
    r"""Right-hand side of the planar (pitch) equation of a magnet-stabilised body.

    Parameters
    ----------
    state : array_like, shape (..., 3)
        (γ, γ̇, γ1): angle from B to the body's axis x [rad], its rate [rad/s], and the angle
        from B to the damper's magnet [rad] (ignored, and its rate 0, without an elastic
        damper); Monte Carlo members on the leading axes.
    field_angle : float or array_like
        η, the angle from the along-track axis to B [rad].
    field_angle_acceleration : float or array_like
        η̈ [rad/s²].
    field_b : float or array_like
        |B| [T].
    mean_motion : float or array_like
        ω0 [rad/s].
    body : PlanarBody
        J [kg·m²], L [A·m²], ΔJ [kg·m²].
    damper : PlanarDamper
        k_д [N·m·s], M_T [N·m], ε [rad/s], c [N·m/rad], L_y [A·m²].

    Returns
    -------
    ndarray, shape (..., 3)
        (γ̇ [rad/s], γ̈ [rad/s²], γ̇1 [rad/s]) with

        .. math::
           J\ddot\gamma = -J\ddot\eta - LB\sin\gamma + \tfrac32\omega_0^2\Delta J\sin 2(\eta+\gamma) + M_д,

        M_д = −k_д γ̇ − M_T tanh(γ̇/ε) with the damper's magnet held along B, or, with an
        elastic damper, M_д = −L_y B sin γ1 and γ̇1 = γ̇ − [g − clip(g, −M_T, M_T)]/k_д,
        g = L_y B sin γ1 − c(γ − γ1) (= γ̇ + [c(γ − γ1) − L_y B sin γ1]/k_д without friction).

    Notes
    -----
    Kovalenko (1975) eqs. (6.28), (6.38), (6.39), (6.42)–(6.44) (seed lines 135–138), for a
    circular orbit (ν̈ = 0; the eccentric terms of (6.39) are left out) and the dipole.
    The magnetic torque L x̂ × B = −LB sin γ is (6.42). The gravity term is
    :func:`planar_gravity_torque`.

    The elastic damper: the damper magnet (inertia J1, angle γ1 from B) obeys
    J1(γ̈1 + η̈) = −L_y B sin γ1 + c(γ − γ1) + k_д(γ̇ − γ̇1); the book neglects J1 ("the
    moment of inertia of the damper's moving part is several orders smaller than the
    spacecraft's", seed line 138), which leaves (6.44) c(γ − γ1) + k_д(γ̇ − γ̇1) = L_y B sin γ1,
    solved here for γ̇1 (Not in the sources: that first-order form). The torque of the
    coupling on the body, −c(γ − γ1) − k_д(γ̇ − γ̇1), then equals −L_y B sin γ1.

    With dry friction M_T between the magnet and the case (p. 150, fig. 6.10) the massless
    magnet's equation is c(γ − γ1) + k_д s + M_T sign s = L_y B sin γ1 = g + c(γ − γ1), s = γ̇ − γ̇1:
    the friction holds the drive g while |g| ≤ M_T (s = 0, the magnet turns with the body) and
    s = [g − M_T sign g]/k_д beyond; the body still feels −L_y B sin γ1. The power of the
    damper on the whole (body, magnet, spring) is −s g = −(k_д s² + M_T |s|) ≤ 0 in a fixed
    field. Deviation from source: k_д > 0 is needed beside M_T (see :class:`PlanarDamper`).

    Examples
    --------
    >>> body, damper = PlanarBody(650.0, 500.0), PlanarDamper(viscous=0.2)
    >>> planar_rhs([0.0, 0.01, 0.0], 0.0, 0.0, 2e-5, 1e-3, body, damper).tolist()
    [0.01, -3.076923076923077e-06, 0.0]
    """
    _check_body_damper(body, damper)
    x = as_finite("state", state)
    if x.ndim == 0 or x.shape[-1] != 3:
        raise ValueError(f"state must have shape (..., 3) (γ, γ̇, γ1), got shape {x.shape}")
    eta = as_finite("field_angle", field_angle)
    eta_acc = as_finite("field_angle_acceleration", field_angle_acceleration)
    b = as_positive("field_b", field_b, unit="T")
    n = as_positive("mean_motion", mean_motion, unit="rad/s")
    return kernels.planar_rates(x, eta, eta_acc, b, n, body.as_tuple(), damper.as_tuple())


def planar_gravity_torque(pitch_angle, mean_motion, inertia_difference):
    r"""Gravity-gradient torque about the orbit normal on a body pitched in the orbit plane.

    Parameters
    ----------
    pitch_angle : array_like
        θ = η + γ, the angle from the along-track axis x0 to the body's axis x, turned toward
        the nadir [rad].
    mean_motion : array_like
        ω0 [rad/s].
    inertia_difference : array_like
        ΔJ = J_transverse − J_axial [kg·m²].

    Returns
    -------
    ndarray
        M_в = (3/2) ω0² ΔJ sin 2θ [N·m], about the orbit normal r × v (positive turns x
        toward the nadir).

    Notes
    -----
    Kovalenko (1975) eq. (6.38) (seed line 137), from (4.18) 3ω0² r̂ × J r̂. Derived here:
    with x = cos θ x0 + sin θ n (n the nadir), the radial r̂ = −n has body components
    (−sin θ, −cos θ) on (x, z); the normal component of r̂ × J r̂ about y = z × x is
    sin θ cos θ (J_axial − J_transverse), and y = −(x0 × n) = −(r × v)/|r × v|, so about the
    orbit normal the torque is +(3/2) ω0² (J_transverse − J_axial) sin 2θ — Kovalenko's sign
    and his ΔJ. The result does not depend on the sense chosen for θ (both sides are odd).
    A body whose magnet axis has the least inertia (ΔJ > 0) is pushed from the horizontal
    toward the vertical.
    """
    theta = as_finite("pitch_angle", pitch_angle)
    n = as_positive("mean_motion", mean_motion, unit="rad/s")
    diff = as_finite("inertia_difference", inertia_difference)
    return 1.5 * n**2 * diff * np.sin(2.0 * theta)


def planar_energy(angle, rate, inertia, moment, field_b):
    r"""Energy of the planar pendulum in a constant field: the integral of the undamped motion.

    Parameters
    ----------
    angle : array_like
        γ [rad].
    rate : array_like
        γ̇ [rad/s].
    inertia : array_like
        J [kg·m²].
    moment : array_like
        L [A·m²].
    field_b : array_like
        |B|, constant [T].

    Returns
    -------
    ndarray
        E = J γ̇²/2 + L B (1 − cos γ) [J]; constant when η̈ = 0, ΔJ = 0 and no damper.

    Notes
    -----
    Kovalenko (1975) §6.5, the first integral before (6.53) (seed line 142):
    J γ̇²/2 + LB(cos γ − cos γ0) = 0 for a start at rest from γ0.
    """
    g = as_finite("angle", angle)
    w = as_finite("rate", rate)
    j = as_positive("inertia", inertia, unit="kg·m²")
    m = as_nonnegative("moment", moment, unit="A·m²")
    b = as_positive("field_b", field_b, unit="T")
    return 0.5 * j * w**2 + m * b * (1.0 - np.cos(g))
