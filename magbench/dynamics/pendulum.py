r"""The mock-up on a thread (thesis §4.1, eqs. 33–36): its geometry (3-1-3 Euler angles,
centre of mass below the suspension point), the one-degree-of-freedom equations as
``solve_ivp`` right-hand sides and one held-moment sample of the bench (:func:`plant_step`),
and the exact period of the magnetic pendulum beside the small-angle thesis eq. (14). SI.
"""

from dataclasses import dataclass

import numpy as np
from scipy.constants import g as STANDARD_GRAVITY
from scipy.special import ellipk

from ..integrate import rk4_step
from .._validate import as_finite, as_in_range, as_nonnegative, as_positive, as_positive_scalar, shown

__all__ = ["two_coil_torque", "Mockup", "euler_313_matrix", "thread_center_of_mass", "mockup_loads", "body_rates_313",
           "pendulum_rhs", "two_coil_rhs", "mockup_rhs", "pendulum_energy", "natural_frequency",
           "small_angle_period", "pendulum_period", "pendulum_peak_rate", "field_for_period", "amplitude_for_period",
           "plant_step"]


def two_coil_torque(psi, moment_1, moment_2, field):
    r"""Torque about the vertical on the mock-up's two horizontal, orthogonal coils.

    Parameters
    ----------
    psi : array_like
        Angle ψ from the horizontal field to coil 1's dipole axis [rad].
    moment_1, moment_2 : array_like
        Dipole moments of coil 1 (along x') and coil 2 (along y') [A·m²].
    field : array_like
        Horizontal field magnitude B0 [T].

    Returns
    -------
    ndarray
        :math:`\tau_z = -B_0\,(m_1 \sin\psi + m_2 \cos\psi)` [N·m].

    Notes
    -----
    Thesis eq. (36) (the right-hand side of J ω̇ = τ_z); with
    m₂ = 0 it is the restoring torque of eqs. (34)–(35). No argument checks: this is the
    inner kernel of simulations that check their inputs once.

    Examples
    --------
    >>> float(two_coil_torque(0.5 * np.pi, 0.4, 0.0, 1e-4))
    -4e-05
    """
    return -field * (moment_1 * np.sin(psi) + moment_2 * np.cos(psi))


@dataclass(frozen=True)
class Mockup:
    """The mock-up turning about the vertical in a uniform horizontal field (eqs. 34–36).

    Attributes are SI: ``inertia`` J about the vertical [kg·m²] (> 0), ``field`` B0 [T]
    (≥ 0), ``moment_1`` and ``moment_2`` the dipoles of coil 1 (along x') and coil 2
    (along y') [A·m²], ``thread_stiffness`` the thread's torsion constant κ [N·m/rad]
    (≥ 0, default 0 as in the thesis's equations) and ``thread_neutral_angle`` the angle
    ψ at which the thread is untwisted [rad]. Checked once here, so the right-hand sides
    need no checks. Every attribute may be an array of Monte Carlo members.

    This is the one plant of chapter 4: the free swing (:func:`pendulum_rhs`), the coils
    at constant moments (:func:`two_coil_rhs`), and the PID loop and the bench of
    :mod:`magbench.sim`, which hold the coil moments over a sample
    (:func:`mockup_rhs`), all integrate it.
    """

    inertia: float
    field: float
    moment_1: float = 0.0
    moment_2: float = 0.0
    thread_stiffness: float = 0.0
    thread_neutral_angle: float = 0.0

    def __post_init__(self):
        as_positive("inertia", self.inertia, unit="kg·m²")
        as_nonnegative("field", self.field, unit="T")
        as_finite("moment_1", self.moment_1)
        as_finite("moment_2", self.moment_2)
        as_nonnegative("thread_stiffness", self.thread_stiffness, unit="N·m/rad")
        as_finite("thread_neutral_angle", self.thread_neutral_angle)


def euler_313_matrix(psi, theta, phi):
    r"""Rotation matrix from the body axes Ax'y'z' to the fixed axes Oxyz.

    Parameters
    ----------
    psi, theta, phi : array_like
        Euler angles of the 3-1-3 sequence: precession ψ, nutation θ, proper rotation φ
        [rad].

    Returns
    -------
    ndarray, shape (..., 3, 3)
        :math:`R = R_z(\psi) R_x(\theta) R_z(\varphi)`; its columns are the body axes
        in fixed axes, so the body z' axis is :math:`(\sin\theta\sin\psi,
        -\sin\theta\cos\psi, \cos\theta)`.

    Notes
    -----
    Thesis §4.1, Fig. 10: the angles whose rates give the thesis's
    p, q, r. The matrix itself is not printed; it is the one that reproduces the
    printed centre-of-mass velocity (thesis §4.1, the velocity of C before eq. (33)).

    Examples
    --------
    >>> np.round(euler_313_matrix(0.0, 0.5 * np.pi, 0.0) @ [0, 0, 1], 12) + 0.0
    array([ 0., -1.,  0.])
    """
    psi, theta, phi = np.broadcast_arrays(as_finite("psi", psi), as_finite("theta", theta),
                                          as_finite("phi", phi))

    def rz(a):
        c, s, z, o = np.cos(a), np.sin(a), np.zeros_like(a), np.ones_like(a)
        return np.stack([np.stack([c, -s, z], -1), np.stack([s, c, z], -1),
                         np.stack([z, z, o], -1)], -2)

    c, s, z, o = np.cos(theta), np.sin(theta), np.zeros_like(theta), np.ones_like(theta)
    rx = np.stack([np.stack([o, z, z], -1), np.stack([z, c, -s], -1), np.stack([z, s, c], -1)], -2)
    return rz(psi) @ rx @ rz(phi)


def thread_center_of_mass(x, y, psi, theta, cm_offset):
    r"""Position of the mock-up's centre of mass C in the fixed axes.

    Parameters
    ----------
    x, y : array_like
        Horizontal position of the suspension point A [m] (A stays in the plane z = 0).
    psi, theta : array_like
        Precession and nutation angles of the 3-1-3 sequence [rad].
    cm_offset : array_like
        Distance d from A down to C along the body axis z' [m], ≥ 0.

    Returns
    -------
    ndarray, shape (..., 3)
        :math:`\mathbf r_C = (x, y, 0) - d\,\mathbf e_{z'}`; its time derivative is the
        velocity printed in the thesis (checked symbolically in the tests).

    Notes
    -----
    Thesis §4.1 (C at (0, 0, −d) in Ax'y'z').

    Examples
    --------
    >>> np.round(thread_center_of_mass(0.0, 0.0, 0.0, 0.0, 0.1), 12) + 0.0
    array([ 0. ,  0. , -0.1])
    """
    d = as_nonnegative("cm_offset", cm_offset, unit="m")
    x, y, psi, theta = (as_finite(n, v) for n, v in (("x", x), ("y", y), ("psi", psi), ("theta", theta)))
    axis = np.stack(np.broadcast_arrays(np.sin(theta) * np.sin(psi), -np.sin(theta) * np.cos(psi),
                                        np.cos(theta)), -1)
    point = np.stack(np.broadcast_arrays(x, y, np.zeros_like(x)), -1)
    return point - np.asarray(d)[..., np.newaxis] * axis


def mockup_loads(psi, theta, phi, cm_offset, mass, field, moment):
    r"""Frames, forces and torques on the mock-up hanging from A at one attitude.

    Parameters
    ----------
    psi, theta, phi : array_like
        3-1-3 Euler angles [rad] (:func:`euler_313_matrix`), broadcast together.
    cm_offset : array_like
        Distance d from the suspension point A down to C along z' [m], ≥ 0.
    mass : float
        Mock-up mass M [kg], > 0.
    field : float
        Horizontal field B0 along the fixed x axis [T].
    moment : float
        Dipole of coil 1, along the body axis x' [A·m²].

    Returns
    -------
    dict of str to ndarray
        ``body_axes`` R (columns x', y', z' in fixed axes) [-]; ``center_of_mass`` C
        with A at the origin [m]; ``weight`` F_t = (0, 0, −Mg) at C [N] (the thread's
        reaction at A is −F_t); ``field`` (B0, 0, 0) [T]; ``dipole`` m = m1 e_x' [A·m²];
        ``magnetic_torque`` m × B0 and ``gravity_torque`` (C − A) × F_t about A [N·m].

    Notes
    -----
    Thesis §4.1, Figs. 10–11: gravity at C, the reaction at A (it does no work: A stays
    in its plane) and the coil's torque in the field.

    Examples
    --------
    >>> loads = mockup_loads(0.0, 0.0, 0.0, 0.05, 1.0, 1e-4, 0.4)
    >>> loads["magnetic_torque"] + 0.0, loads["gravity_torque"] + 0.0
    (array([0., 0., 0.]), array([0., 0., 0.]))
    """
    r = euler_313_matrix(psi, theta, phi)
    mass = as_positive_scalar("mass", mass, unit="kg")
    field = float(as_finite("field", field))
    moment = float(as_finite("moment", moment))
    c = thread_center_of_mass(0.0, 0.0, psi, theta, cm_offset)
    b0 = np.array([field, 0.0, 0.0])
    m_vec = moment * r[..., :, 0]                       # coil 1 along x'
    weight = np.array([0.0, 0.0, -mass * STANDARD_GRAVITY])
    return {"body_axes": r, "center_of_mass": c, "weight": weight, "field": b0, "dipole": m_vec,
            "magnetic_torque": np.cross(m_vec, b0), "gravity_torque": np.cross(c, weight)}


def body_rates_313(psi, theta, phi, psi_rate, theta_rate, phi_rate):
    r"""Body-axis angular velocity (p, q, r) from 3-1-3 Euler angles and their rates.

    Parameters
    ----------
    psi, theta, phi : array_like
        Euler angles [rad].
    psi_rate, theta_rate, phi_rate : array_like
        Their time derivatives [rad/s].

    Returns
    -------
    ndarray, shape (..., 3)
        :math:`p = \dot\psi\sin\theta\sin\varphi + \dot\theta\cos\varphi`,
        :math:`q = \dot\psi\sin\theta\cos\varphi - \dot\theta\sin\varphi`,
        :math:`r = \dot\psi\cos\theta + \dot\varphi` [rad/s].

    Notes
    -----
    Thesis §4.1. With θ = 0 only r = ψ̇ + φ̇ survives: rotation about
    the vertical, the case of eqs. (34)–(36).

    Examples
    --------
    >>> body_rates_313(0.3, 0.0, 0.2, 0.1, 0.0, 0.05)
    array([0.  , 0.  , 0.15])
    """
    psi, theta, phi = (as_finite(n, v) for n, v in (("psi", psi), ("theta", theta), ("phi", phi)))
    dpsi, dth, dphi = (as_finite(n, v) for n, v in (("psi_rate", psi_rate), ("theta_rate", theta_rate),
                                                      ("phi_rate", phi_rate)))
    p = dpsi * np.sin(theta) * np.sin(phi) + dth * np.cos(phi)
    q = dpsi * np.sin(theta) * np.cos(phi) - dth * np.sin(phi)
    r = dpsi * np.cos(theta) + dphi
    return np.stack(np.broadcast_arrays(p, q, r), -1) + 0.0


def pendulum_rhs(t, state, params):
    r"""Right-hand side of eq. (35), the mock-up with one coil: a magnetic pendulum.

    Parameters
    ----------
    t : float
        Time [s] (unused: the system is autonomous; solve_ivp passes it).
    state : array_like, shape (2, ...)
        (ψ [rad], ω = ψ̇ [rad/s]).
    params : Mockup
        Plant [SI]: inertia J, field B0 and coil-1 moment m (``moment_2`` is ignored; the
        thread's torsion is added when the plant has one).

    Returns
    -------
    ndarray, shape (2, ...)
        :math:`(\omega,\ -m B_0 \sin\psi / J)` [rad/s, rad/s²].

    Notes
    -----
    Thesis eqs. (34)–(35). Use as
    ``solve_ivp(pendulum_rhs, (0, duration), (initial_angle, 0.0), args=(Mockup(...),))``.

    Examples
    --------
    >>> pendulum_rhs(0.0, [0.5 * np.pi, 0.0], Mockup(0.005, 1e-4, 0.4))
    array([ 0.   , -0.008])
    """
    return mockup_rhs(t, state, (params.moment_1, 0.0), params)


def mockup_rhs(t, state, moments, plant):
    r"""Right-hand side of eq. (36) with the coil moments as inputs, plus the thread's torsion.

    Parameters
    ----------
    t : float
        Time [s] (unused; solve_ivp passes it).
    state : array_like, shape (2, ...)
        (ψ [rad], ω [rad/s]); ψ is the angle from the field to coil 1's axis.
    moments : tuple of array_like
        (m₁, m₂): the moments of coil 1 and coil 2 [A·m²], held while this is integrated
        (the controller's zero-order hold).
    plant : Mockup
        Plant [SI]: inertia, field and thread (its ``moment_1``, ``moment_2`` are ignored).

    Returns
    -------
    ndarray, shape (2, ...)
        :math:`(\omega,\ [-B_0(m_1\sin\psi + m_2\cos\psi) - \kappa(\psi - \psi_t)]/J)`
        [rad/s, rad/s²].

    Notes
    -----
    Thesis eq. (36), J ω̇ = −B0(m1 sin ψ + m2 cos ψ), plus the torsion −κ(ψ − ψ_t) of
    the thread, which the thesis names as a cause of the bench's error (thesis §4.4) but
    does not quantify. Use as ``solve_ivp(mockup_rhs, span, (angle, rate),
    args=((m1, m2), plant))`` or with :func:`magbench.sim.rk4_step`.

    Examples
    --------
    >>> mockup_rhs(0.0, [0.1, 0.0], (0.0, 0.0), Mockup(0.005, 1e-4, thread_stiffness=1e-4))
    array([ 0.   , -0.002])
    """
    psi, rate = state[0], state[1]
    m1, m2 = moments
    twist = psi - plant.thread_neutral_angle
    torque = two_coil_torque(psi, m1, m2, plant.field) - plant.thread_stiffness * twist
    return np.array([rate, torque / plant.inertia])


def two_coil_rhs(t, state, params):
    r"""Right-hand side of eq. (36): the mock-up with two orthogonal coils at constant moments.

    Parameters
    ----------
    t : float
        Time [s] (unused; solve_ivp passes it).
    state : array_like, shape (2, ...)
        (ψ [rad], ω [rad/s]); ψ is the angle from the field to coil 1's axis.
    params : Mockup
        Plant [SI]: inertia, field, both coil moments and the thread.

    Returns
    -------
    ndarray, shape (2, ...)
        :math:`(\omega,\ -B_0(m_1\sin\psi + m_2\cos\psi)/J)` [rad/s, rad/s²] (the
        thread's torsion added when ``params`` has one).

    Notes
    -----
    Thesis eq. (36): :func:`mockup_rhs` with the plant's own moments. The equilibrium
    is ψ = −atan2(m₂, m₁): the net dipole lines up with the field.

    Examples
    --------
    >>> two_coil_rhs(0.0, [0.0, 0.0], Mockup(0.005, 1e-4, 0.0, 0.4))
    array([ 0.   , -0.008])
    """
    return mockup_rhs(t, state, (params.moment_1, params.moment_2), params)


def pendulum_energy(psi, rate, inertia, moment, field):
    r"""Total energy of the one-coil mock-up, conserved by eq. (35).

    Parameters
    ----------
    psi : array_like
        Angle from the field to the dipole [rad].
    rate : array_like
        Rate ω about the vertical [rad/s].
    inertia : array_like
        J [kg·m²].
    moment : array_like
        Dipole m [A·m²].
    field : array_like
        B0 [T].

    Returns
    -------
    ndarray
        :math:`E = \tfrac12 J\omega^2 - m B_0\cos\psi` [J].

    Notes
    -----
    Thesis §4.1 (T = Cr²/2, Π = −mB0 cos ψ); the first
    integral of eq. (35).

    Examples
    --------
    >>> round(float(pendulum_energy(0.0, 0.2, 0.005, 0.4, 1e-4)), 12)   # ½Jω² − mB
    6e-05
    """
    return 0.5 * inertia * np.asarray(rate) ** 2 - moment * field * np.cos(psi)


def natural_frequency(inertia, moment, field):
    r"""Small-oscillation angular frequency of the magnetic pendulum.

    Parameters
    ----------
    inertia : array_like
        J [kg·m²], > 0.
    moment : array_like
        Dipole m [A·m²], > 0.
    field : array_like
        B0 [T], > 0.

    Returns
    -------
    ndarray
        :math:`\omega_0 = \sqrt{m B_0 / J}` [rad/s].

    Notes
    -----
    Thesis eq. (14).

    Examples
    --------
    >>> float(natural_frequency(0.005, 0.4, 1.25e-4))
    0.1
    """
    return np.sqrt(as_positive("moment", moment, unit="A·m²") * as_positive("field", field, unit="T")
                   / as_positive("inertia", inertia, unit="kg·m²"))


def small_angle_period(inertia, moment, field):
    r"""Period of the magnetic pendulum in the small-angle limit.

    Parameters
    ----------
    inertia : array_like
        J [kg·m²], > 0.
    moment : array_like
        Dipole m [A·m²], > 0.
    field : array_like
        B0 [T], > 0.

    Returns
    -------
    ndarray
        :math:`T_0 = 2\pi\sqrt{J/(m B_0)}` [s], independent of the amplitude.

    Notes
    -----
    Thesis eq. (14). The thesis sizes the simulator and the coils with
    it at an amplitude of π (thesis §2.1), where it does not hold
    (see :func:`pendulum_period`).

    Examples
    --------
    >>> round(float(small_angle_period(0.005, 0.4, 1.25e-4)), 6)
    62.831853
    """
    return 2.0 * np.pi / natural_frequency(inertia, moment, field)


def pendulum_period(amplitude, inertia, moment, field):
    r"""Exact period of the magnetic pendulum at any amplitude.

    Parameters
    ----------
    amplitude : array_like
        Largest angle ψ_max from the field [rad], in [0, π].
    inertia : array_like
        J [kg·m²], > 0.
    moment : array_like
        Dipole m [A·m²], > 0.
    field : array_like
        B0 [T], > 0.

    Returns
    -------
    ndarray
        :math:`T = \frac{4}{\omega_0} K\!\left(\sin^2\frac{\psi_{max}}{2}\right)` [s],
        with K the complete elliptic integral of the first kind (parameter convention of
        scipy.special.ellipk). Infinite at ψ_max = π: released upside down, the
        pendulum never leaves (the separatrix).

    Notes
    -----
    Not in the thesis: the exact solution of eq. (35), which the thesis replaces by the
    small-angle eq. (14) even at amplitude π.

    Examples
    --------
    >>> T0 = float(small_angle_period(0.005, 0.4, 1.25e-4))
    >>> round(float(pendulum_period(0.5 * np.pi, 0.005, 0.4, 1.25e-4)) / T0, 6)
    1.180341
    """
    a = as_in_range("amplitude", amplitude, 0.0, np.pi, unit="rad")
    with np.errstate(divide="ignore"):
        k = ellipk(np.sin(0.5 * a) ** 2)
    return 4.0 * k / natural_frequency(inertia, moment, field)


def pendulum_peak_rate(amplitude, inertia, moment, field):
    r"""Largest rate of the magnetic pendulum, reached when it crosses the field.

    Parameters
    ----------
    amplitude : array_like
        Largest angle ψ_max [rad], in [0, π].
    inertia : array_like
        J [kg·m²], > 0.
    moment : array_like
        Dipole m [A·m²], > 0.
    field : array_like
        B0 [T], > 0.

    Returns
    -------
    ndarray
        :math:`\omega_{max} = 2\omega_0 \sin(\psi_{max}/2)` [rad/s] (energy conservation).

    Notes
    -----
    Not in the thesis: follows from the energy integral of eq. (35).

    Examples
    --------
    >>> round(float(pendulum_peak_rate(np.pi, 0.005, 0.4, 1.25e-4)), 12)
    0.2
    """
    a = as_in_range("amplitude", amplitude, 0.0, np.pi, unit="rad")
    return 2.0 * natural_frequency(inertia, moment, field) * np.sin(0.5 * a)


def field_for_period(period, amplitude, inertia, moment):
    r"""Field that gives the magnetic pendulum a period at a given amplitude.

    Parameters
    ----------
    period : array_like
        Wanted period T [s], > 0.
    amplitude : array_like
        Amplitude ψ_max [rad], in [0, π].
    inertia : array_like
        J [kg·m²], > 0.
    moment : array_like
        Dipole m [A·m²], > 0.

    Returns
    -------
    ndarray
        :math:`B_0 = \frac{J}{m}\left(\frac{4K(\sin^2(\psi_{max}/2))}{T}\right)^2` [T];
        infinite at ψ_max = π. At ψ_max → 0 it is the thesis's eq. (15) without its
        amplitude factor.

    Notes
    -----
    Not in the thesis: eq. (35) solved exactly for the field. Compare the thesis's
    eq. (15) as used, :math:`B = 4\pi^2 J A/(m T^2)`.

    Examples
    --------
    >>> round(float(field_for_period(2 * np.pi * 10, 0.0, 0.005, 0.4)), 12)
    0.000125
    """
    t = as_positive("period", period, unit="s")
    a = as_in_range("amplitude", amplitude, 0.0, np.pi, unit="rad")
    j = as_positive("inertia", inertia, unit="kg·m²")
    m = as_positive("moment", moment, unit="A·m²")
    with np.errstate(divide="ignore"):
        k = ellipk(np.sin(0.5 * a) ** 2)
    return j / m * (4.0 * k / t) ** 2


def amplitude_for_period(period, inertia, moment, field):
    r"""Amplitude at which the magnetic pendulum has a given period.

    Parameters
    ----------
    period : float
        Wanted period T [s], at least the small-angle period :func:`small_angle_period`.
    inertia : float
        J [kg·m²], > 0.
    moment : float
        Dipole m [A·m²], > 0.
    field : float
        B0 [T], > 0.

    Returns
    -------
    float
        ψ_max in [0, π) [rad] with :func:`pendulum_period` (ψ_max) = T (Brent's method
        on the monotone period).

    Notes
    -----
    Not in the thesis: inverts the exact period, to ask at which amplitude the sized
    design (thesis §2.1) really swings with its design period.

    Examples
    --------
    >>> T = float(pendulum_period(0.5 * np.pi, 0.005, 0.4, 1.25e-4))
    >>> round(amplitude_for_period(T, 0.005, 0.4, 1.25e-4) / np.pi, 12)
    0.5
    """
    from scipy.optimize import brentq

    t = float(as_positive("period", period, unit="s"))
    t0 = float(small_angle_period(inertia, moment, field))
    if t < t0:
        raise ValueError(f"period must be >= the small-angle period {t0:.6g} s, got {shown(t)}")
    if t == t0:
        return 0.0
    # T grows monotonically from T0 at 0 to infinity at π: a bracketing root finder is safe.
    return brentq(lambda a: float(pendulum_period(a, inertia, moment, field)) - t,
                  0.0, np.nextafter(np.pi, 0.0), xtol=1e-14, rtol=1e-14)


def plant_step(psi, rate, moment_1, moment_2, dt, *, field, inertia, thread_stiffness=0.0,
               thread_neutral_angle=0.0):
    r"""Advance the mock-up by one sample with the coil moments held (classical RK4).

    Parameters
    ----------
    psi : array_like
        Angle from the field to coil 1's axis [rad].
    rate : array_like
        Rate ω about the vertical [rad/s].
    moment_1, moment_2 : array_like
        Moments of coil 1 and coil 2, held over the step [A·m²].
    dt : float
        Step [s].
    field : array_like
        Horizontal field B0 [T].
    inertia : array_like
        Moment of inertia J about the vertical [kg·m²].
    thread_stiffness : array_like, optional
        Torsion constant κ of the thread [N·m/rad].
    thread_neutral_angle : array_like, optional
        Angle at which the thread is untwisted [rad].

    Returns
    -------
    psi, rate : ndarray
        State after the step [rad], [rad/s].

    Notes
    -----
    Thesis eq. (36), J ω̇ = −B0(m1 sin ψ + m2 cos ψ), plus the torsion −κ(ψ − ψ_thread)
    that the thesis names as a cause of the bench's error (thesis §4.4) but does not
    quantify: :func:`magbench.dynamics.mockup_rhs` advanced by
    :func:`magbench.integrate.rk4_step`, the step :func:`magbench.sim.bench.simulate_bench`
    takes at every sample. The local error is O((ω_n dt)⁵) with ω_n ≈ 0.2 rad/s: ~1e-14 rad per 10 ms
    step.

    Examples
    --------
    >>> p, w = plant_step(0.0, 0.0, 0.0, 0.4, 0.01, field=3e-4, inertia=0.005)
    >>> round(float(w), 8)   # torque -B0 m2 = -1.2e-4 N m for 10 ms
    -0.00024
    """
    plant = Mockup(inertia, field, thread_stiffness=thread_stiffness, thread_neutral_angle=thread_neutral_angle)
    state = np.array(np.broadcast_arrays(psi, rate), dtype=float)
    new = rk4_step(mockup_rhs, 0.0, state, dt, args=((moment_1, moment_2), plant))
    return new[0], new[1]
