r"""Feedback control of the mock-up: the PID law of thesis §4 and its discrete form.

Thesis eqs. (37)–(38). The controller output is the commanded dipole moment; the
coils' maximum moment saturates it, and the integral stops winding up while the output
is saturated. The dipole allocation M = m × b (exact, and with the thesis's small-angle
rotation), the closed loop as a solve_ivp right-hand side and as a sampled loop, and
the loop's linear analysis (poles, Routh–Hurwitz, Ziegler–Nichols, the readings of the
thesis's gain units) are here too; python-control is the peer in the tests.
"""

from dataclasses import dataclass

import numpy as np

from ._validate import as_finite, as_positive, as_vectors
from .attitude import two_coil_torque

__all__ = ["pid_step", "pid_gains_for_triple_pole", "body_field_exact", "body_field_small_angle",
           "dipole_allocation", "PidLoop", "loop_torque", "pid_continuous_rhs", "ClosedLoopResult",
           "simulate_pid", "closed_loop_polynomial", "closed_loop_poles", "integral_gain_limit",
           "critical_gain_scale", "ziegler_nichols_pid", "double_integrator_ultimate_gain",
           "GAIN_READINGS", "gain_reading_scale"]


def pid_step(error, error_rate, integral, dt, kp, ki, kd, output_limit=np.inf):
    r"""One step of the discrete PID with output saturation and anti-windup.

    Parameters
    ----------
    error : array_like
        Control error e = ψ_des − ψ at this step [rad].
    error_rate : array_like
        Its time derivative de/dt (from the gyro, not differenced) [rad/s].
    integral : array_like
        Integral of the error up to the previous step [rad·s].
    dt : array_like
        Controller sample interval [s].
    kp, ki, kd : array_like
        Proportional [A·m²/rad], integral [A·m²/(rad·s)] and derivative [A·m²·s/rad]
        gains, in the units of thesis eq. (37) read in SI.
    output_limit : array_like, optional
        Largest commanded moment magnitude [A·m²] (the coils' maximum); default: none.

    Returns
    -------
    output : ndarray
        Commanded moment :math:`\mathrm{sat}(K_p e + K_i \int e\,dt + K_d\,\dot e)` [A·m²].
    integral : ndarray
        The updated error integral [rad·s]. It is frozen (conditional integration) while
        the output is saturated and the error would drive it further into saturation.

    Notes
    -----
    Thesis eq. (37), seed lines 530–534, with rectangle-rule integration. The thesis does
    not state a sample time, derivative source or anti-windup (inventory gap G15); these
    choices are ours. No argument checks: the simulation that calls this checks its
    inputs once. Broadcasts over any shape (Monte Carlo members).

    Examples
    --------
    >>> u, i = pid_step(0.1, 0.0, 0.0, 0.01, kp=2.0, ki=1.0, kd=0.0, output_limit=0.4)
    >>> round(float(u), 6), round(float(i), 6)
    (0.201, 0.001)
    >>> u, i = pid_step(1.0, 0.0, 0.0, 0.01, kp=2.0, ki=1.0, kd=0.0, output_limit=0.4)
    >>> float(u), float(i)
    (0.4, 0.0)
    """
    candidate = integral + error * dt
    unsaturated = kp * error + ki * candidate + kd * error_rate
    output = np.clip(unsaturated, -output_limit, output_limit)
    winding_up = (output != unsaturated) & (np.sign(ki * error) == np.sign(unsaturated))
    return output, np.where(winding_up, integral, candidate)


def pid_gains_for_triple_pole(inertia, field, bandwidth):
    r"""PID gains that put the linearised loop's three poles at s = −ω_b.

    Parameters
    ----------
    inertia : array_like
        Moment of inertia J about the vertical [kg·m²], > 0.
    field : array_like
        Field magnitude B0 [T], > 0.
    bandwidth : array_like
        The triple pole's magnitude ω_b [rad/s], > 0.

    Returns
    -------
    kp, ki, kd : ndarray
        Gains [A·m²/rad], [A·m²/(rad·s)], [A·m²·s/rad] in the SI reading of eq. (37).

    Notes
    -----
    Not in the thesis: a starting point for stable SI gains. Eqs. (35)–(37) linearised
    about ψ = ψ_des give the characteristic polynomial
    :math:`J s^3 + B_0 K_d s^2 + B_0 K_p s + B_0 K_i`; matching it to
    :math:`J (s + \omega_b)^3` gives
    :math:`K_d = 3 J \omega_b / B_0`, :math:`K_p = 3 J \omega_b^2 / B_0`,
    :math:`K_i = J \omega_b^3 / B_0`.

    Examples
    --------
    >>> kp, ki, kd = pid_gains_for_triple_pole(0.005, 1e-4, 0.1)
    >>> [round(float(k), 9) for k in (kp, ki, kd)]
    [1.5, 0.05, 15.0]
    """
    j = as_positive("inertia", inertia, unit="kg·m²")
    b = as_positive("field", field, unit="T")
    w = as_positive("bandwidth", bandwidth, unit="rad/s")
    return 3.0 * j * w**2 / b, j * w**3 / b, 3.0 * j * w / b


# --- the field in body axes and the dipole allocation of thesis §4.1 ---------------------

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
    Thesis §4.1, seed line 561, with the exact rotation instead of the small-angle
    matrix (inventory gap G20). For B⁰ = (B0, 0, 0) it is B0 (cos ψ, −sin ψ, 0), the
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
    Thesis §4.1, seed lines 561–563. The thesis then divides by :math:`|\mathbf B^0|`,
    not by the length of this vector, so the "unit" vector it allocates with is
    :math:`\sqrt{1+\psi^2}` long. Valid only while ψ² ≪ 1; the bench targets π/3 and
    2π/3 (inventory gap G20).

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
    Thesis §4.1, seed lines 545–557. With a unit b perpendicular to z, the torque of M
    is :math:`(\mathbf M\times\mathbf B)_z = -|\mathbf B|\,m_z`: the demand is realised
    exactly, with a minus sign that eq. (38) compensates by flipping the sign of (37)
    (inventory audit A38).

    Examples
    --------
    >>> dipole_allocation([0.0, 0.0, 0.2], [0.0, -1.0, 0.0])
    array([0.2, 0. , 0. ])
    """
    return np.cross(as_vectors("desired_moment", desired_moment),
                    as_vectors("field_direction", field_direction)) + 0.0


# --- the closed loop of thesis §4.1: PID, allocation, saturation --------------------------

ALLOCATIONS = ("exact", "small-angle")


@dataclass(frozen=True)
class PidLoop:
    """The mock-up under the PID of eqs. (37)–(38), gains read in SI.

    ``inertia`` J [kg·m²], ``field`` B0 [T] (horizontal, along the fixed x axis),
    ``kp`` [A·m²/rad], ``ki`` [A·m²/(rad·s)], ``kd`` [A·m²·s/rad], ``target`` ψ_des
    [rad], ``moment_limit`` the largest dipole demand |m_z| [A·m²] (the coils' maximum;
    |M_x|, |M_y| ≤ |m_z| then holds for either coil), ``allocation`` "exact" or
    "small-angle" (the thesis's matrix), ``anti_windup``: conditional integration in the
    sampled loop (:func:`pid_step`), back-calculation with ``tracking_time`` T_t [s]
    (default √(K_d/K_i), Åström and Hägglund's rule of thumb √(T_i T_d)) in the continuous
    one, where conditional integration would chatter along the saturation boundary.
    Checked once here.
    """

    inertia: float
    field: float
    kp: float
    ki: float
    kd: float
    target: float = 0.0
    moment_limit: float = np.inf
    allocation: str = "exact"
    anti_windup: bool = True
    tracking_time: float | None = None

    @property
    def tracking(self):
        """Back-calculation time T_t [s] of the continuous anti-windup."""
        if self.tracking_time is not None:
            return float(self.tracking_time)
        return float(np.sqrt(self.kd / self.ki)) if self.kd > 0 and self.ki > 0 else 1.0

    def __post_init__(self):
        as_positive("inertia", self.inertia, unit="kg·m²")
        as_positive("field", self.field, unit="T")
        for name in ("kp", "ki", "kd", "target"):
            as_finite(name, getattr(self, name))
        if not float(self.moment_limit) > 0:
            raise ValueError(f"moment_limit must be > 0 A·m² (inf for none), got {self.moment_limit!r}")
        if self.tracking_time is not None:
            as_positive("tracking_time", self.tracking_time, unit="s")
        if self.allocation not in ALLOCATIONS:
            raise ValueError(f"allocation must be one of {ALLOCATIONS}, got {self.allocation!r}")


def loop_torque(psi, command, loop):
    r"""Torque about the vertical produced by a PID command through the allocation.

    Parameters
    ----------
    psi : array_like
        Body angle from the field [rad].
    command : array_like
        PID output u (already saturated) [A·m²]; the allocated demand is m_z = −u.
    loop : PidLoop
        Loop parameters [SI].

    Returns
    -------
    ndarray
        τ_z [N·m]: coil moments :math:`M = (0, 0, -u)\times\mathbf b` with b exact or
        small-angle, then eq. (36). Exact allocation gives τ = B0·u; the small-angle one
        :math:`B_0 u(\psi\sin\psi + \cos\psi)`.

    Notes
    -----
    Thesis eqs. (36)–(38) and §4.1 (seed lines 508–563). The sign m_z = −u makes
    e = ψ_des − ψ of eq. (37) a negative feedback, as eq. (38) intends. No checks: the
    inner kernel of the simulations.

    Examples
    --------
    >>> loop = PidLoop(0.005, 1e-4, 0.1, 0.0, 0.5)
    >>> round(float(loop_torque(0.3, 0.2, loop)), 12)
    2e-05
    """
    if loop.allocation == "exact":
        bx, by = np.cos(psi), -np.sin(psi)
    else:
        bx, by = np.ones_like(psi), -np.asarray(psi)
    mz = -np.asarray(command)
    # M = (0, 0, m_z) × b with b_z = 0 (seed line 557): coil 1 gets −m_z b_y, coil 2 m_z b_x.
    return two_coil_torque(psi, -mz * by, mz * bx, loop.field)


def pid_continuous_rhs(t, state, loop):
    r"""Right-hand side of the continuous closed loop: plant (36) plus PID (37) with its integral.

    Parameters
    ----------
    t : float
        Time [s] (unused; solve_ivp passes it).
    state : array_like, shape (3, ...)
        (ψ [rad], ω [rad/s], ∫e dt [rad·s]).
    loop : PidLoop
        Loop parameters [SI].

    Returns
    -------
    ndarray, shape (3, ...)
        (ω, τ/J, d∫e/dt) [rad/s, rad/s², rad]. With anti-windup the integral is
        back-calculated, :math:`\dot I = e + (u - u_{raw})/(K_i T_t)`, which bleeds it
        off while the command is saturated and is smooth, so solve_ivp does not chatter.

    Notes
    -----
    Thesis eqs. (36)–(38), seed lines 508–541: u = sat(K_p e + K_i ∫e + K_d ė),
    e = ψ_des − ψ, ė = −ω (the gyro rate: derivative on the measurement, no kick).
    Use as ``solve_ivp(pid_continuous_rhs, span, (psi0, omega0, 0.0), args=(loop,))``.
    The anti-windup scheme is ours (Åström and Hägglund, back-calculation); the thesis
    states none (inventory gap G16).

    Examples
    --------
    >>> loop = PidLoop(0.005, 1e-4, 0.1, 0.5, 0.5, moment_limit=0.4)
    >>> pid_continuous_rhs(0.0, [0.1, 0.0, 0.0], loop)
    array([ 0.    , -0.0002, -0.1   ])
    """
    psi, omega, integral = state[0], state[1], state[2]
    error = loop.target - psi
    raw = loop.kp * error + loop.ki * integral - loop.kd * omega
    command = np.clip(raw, -loop.moment_limit, loop.moment_limit)
    rate = error
    if loop.anti_windup and loop.ki != 0:
        rate = error + (command - raw) / (loop.ki * loop.tracking)
    return np.array([omega, loop_torque(psi, command, loop) / loop.inertia, rate])


@dataclass(frozen=True)
class ClosedLoopResult:
    """A closed-loop run: arrays over time (SI)."""

    t: np.ndarray          #: time [s]
    psi: np.ndarray        #: angle from the field [rad]
    omega: np.ndarray      #: rate [rad/s]
    integral: np.ndarray   #: error integral [rad·s]
    command: np.ndarray    #: saturated PID output u [A·m²]
    torque: np.ndarray     #: torque about the vertical [N·m]


def simulate_pid(loop, psi0, omega0, t_end, *, sample_interval=None, output_interval=0.1,
                 method="RK45"):
    r"""Run the closed loop from an initial state, continuous or sampled.

    Parameters
    ----------
    loop : PidLoop
        Loop parameters [SI].
    psi0, omega0 : float
        Initial angle [rad] and rate [rad/s]; the integral starts at 0.
    t_end : float
        Duration [s], > 0.
    sample_interval : float, optional
        Controller sample interval Δt [s] (the Arduino loop): the PID runs as
        :func:`pid_step` on samples of ψ and ω and its output is held (zero-order hold)
        while the plant is integrated (RK4, 4 sub-steps). Default: the continuous loop,
        :func:`pid_continuous_rhs` with solve_ivp (RK45, rtol 1e-9).
    output_interval : float, optional
        Spacing of the returned samples [s], > 0 (rounded to whole controller samples).
    method : str, optional
        solve_ivp method for the continuous loop [-]; "LSODA" or "Radau" for stiff loops
        (gains so large that the real pole lies far beyond the oscillation).

    Returns
    -------
    ClosedLoopResult
        Time series [SI].

    Notes
    -----
    Thesis eqs. (36)–(38) and Figs. 15–18. Not in the thesis: the sample interval and
    anti-windup (inventory gaps G15–G17).

    Examples
    --------
    >>> loop = PidLoop(0.005, 3.14e-4, 0.12, 0.002, 2.4, moment_limit=0.4)
    >>> r = simulate_pid(loop, 0.05, 0.0, 300.0)
    >>> abs(float(r.psi[-1])) < 1e-3
    True
    """
    from scipy.integrate import solve_ivp

    psi0, omega0 = float(as_finite("psi0", psi0)), float(as_finite("omega0", omega0))
    t_end = float(as_positive("t_end", t_end, unit="s"))
    out = float(as_positive("output_interval", output_interval, unit="s"))
    if sample_interval is None:
        t = np.linspace(0.0, t_end, int(round(t_end / out)) + 1)
        sol = solve_ivp(pid_continuous_rhs, (0.0, t_end), [psi0, omega0, 0.0], args=(loop,),
                        t_eval=t, rtol=1e-9, atol=1e-12, max_step=min(out, 1.0), method=method)
        if not sol.success:
            raise RuntimeError(f"solve_ivp failed: {sol.message}")
        psi, omega, integral = sol.y
        raw = loop.kp * (loop.target - psi) + loop.ki * integral - loop.kd * omega
        command = np.clip(raw, -loop.moment_limit, loop.moment_limit)
    else:
        dt = float(as_positive("sample_interval", sample_interval, unit="s"))
        n = int(round(t_end / dt))
        every = max(1, int(round(out / dt)))
        x = np.array([psi0, omega0])
        integral_k, h = 0.0, dt / 4
        rows = []
        for k in range(n + 1):
            u, new_integral = pid_step(loop.target - x[0], -x[1], integral_k, dt, loop.kp, loop.ki,
                                       loop.kd, loop.moment_limit if loop.anti_windup or
                                       not np.isfinite(loop.moment_limit) else np.inf)
            if not loop.anti_windup:
                u = np.clip(u, -loop.moment_limit, loop.moment_limit)
            if k % every == 0:
                rows.append((k * dt, x[0], x[1], integral_k, float(u)))
            if k == n:
                break

            def f(y, u=u):
                return np.array([y[1], loop_torque(y[0], u, loop) / loop.inertia])

            for _ in range(4):      # RK4 on the plant with the command held
                k1 = f(x)
                k2 = f(x + 0.5 * h * k1)
                k3 = f(x + 0.5 * h * k2)
                k4 = f(x + h * k3)
                x = x + h / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
            integral_k = float(new_integral)
        t, psi, omega, integral, command = (np.array(c) for c in zip(*rows))
    return ClosedLoopResult(t, psi, omega, integral, command, loop_torque(psi, command, loop))


# --- linear analysis of the loop (numpy; python-control is the tests' and figures' peer) ---

def closed_loop_polynomial(inertia, field, kp, ki, kd):
    r"""Characteristic polynomial of the linearised closed loop.

    Parameters
    ----------
    inertia : float
        J [kg·m²], > 0.
    field : float
        B0 [T], > 0.
    kp, ki, kd : float
        Gains [A·m²/rad], [A·m²/(rad·s)], [A·m²·s/rad].

    Returns
    -------
    ndarray, shape (4,)
        Coefficients of :math:`J s^3 + B_0 K_d s^2 + B_0 K_p s + B_0 K_i` (highest first).

    Notes
    -----
    Thesis eqs. (36)–(38) linearised about ψ = ψ_des with exact allocation and no
    saturation: the plant is a pure double integrator :math:`B_0/(J s^2)` (inventory
    audit A40).

    Examples
    --------
    >>> closed_loop_polynomial(0.005, 1e-4, 0.1, 0.5, 0.5)
    array([5.e-03, 5.e-05, 1.e-05, 5.e-05])
    """
    j = float(as_positive("inertia", inertia, unit="kg·m²"))
    b = float(as_positive("field", field, unit="T"))
    kp, ki, kd = (float(as_finite(n, v)) for n, v in (("kp", kp), ("ki", ki), ("kd", kd)))
    return np.array([j, b * kd, b * kp, b * ki])


def closed_loop_poles(inertia, field, kp, ki, kd):
    r"""Poles of the linearised closed loop.

    Parameters
    ----------
    inertia : float
        J [kg·m²], > 0.
    field : float
        B0 [T], > 0.
    kp, ki, kd : float
        Gains [A·m²/rad], [A·m²/(rad·s)], [A·m²·s/rad].

    Returns
    -------
    ndarray, shape (3,)
        Roots of :func:`closed_loop_polynomial` [1/s], sorted by real part (most
        unstable first).

    Notes
    -----
    Thesis eqs. (36)–(38) linearised (inventory audit A40).

    Examples
    --------
    >>> p = closed_loop_poles(0.005, 3.14e-4, 0.1, 0.5, 0.5)   # a printed gain set, in SI
    >>> round(float(p[0].real), 3), round(float(p[2].real), 3)     # unstable pair, stable real pole
    (0.144, -0.319)
    """
    roots = np.roots(closed_loop_polynomial(inertia, field, kp, ki, kd))
    return roots[np.argsort(-roots.real, kind="stable")]


def integral_gain_limit(inertia, field, kp, kd):
    r"""Largest integral gain for which the linearised loop is stable (Routh–Hurwitz).

    Parameters
    ----------
    inertia : array_like
        J [kg·m²], > 0.
    field : array_like
        B0 [T], > 0.
    kp, kd : array_like
        Proportional [A·m²/rad] and derivative [A·m²·s/rad] gains, > 0.

    Returns
    -------
    ndarray
        :math:`K_{i,max} = B_0 K_p K_d / J` [A·m²/(rad·s)]: the cubic
        :math:`J s^3 + B_0K_d s^2 + B_0K_p s + B_0K_i` is Hurwitz iff all coefficients are
        positive and :math:`K_i < K_{i,max}`.

    Notes
    -----
    Not in the thesis: the stability condition its gains (seed lines 565–579) violate in
    SI by a factor of 25–160 (inventory audit A40).

    Examples
    --------
    >>> round(float(integral_gain_limit(0.005, 1e-4, 0.1, 0.5)), 12)
    0.001
    """
    return (as_positive("field", field, unit="T") * as_positive("kp", kp, unit="A·m²/rad")
            * as_positive("kd", kd, unit="A·m²·s/rad") / as_positive("inertia", inertia, unit="kg·m²"))


def critical_gain_scale(inertia, field, kp, ki, kd):
    r"""Common factor on all three gains at which the linearised loop becomes stable.

    Parameters
    ----------
    inertia : array_like
        J [kg·m²], > 0.
    field : array_like
        B0 [T], > 0.
    kp, ki, kd : array_like
        Gains [A·m²/rad], [A·m²/(rad·s)], [A·m²·s/rad], > 0.

    Returns
    -------
    ndarray
        :math:`s_c = J K_i / (B_0 K_p K_d)` [-]: the loop with gains s·K is stable iff
        s > s_c. Any reading of the thesis's gain units that multiplies them by a
        constant factor s (degrees, normalised outputs, other field units) is stable
        iff s > s_c; for a stable design, s_c < 1 is its lower gain margin.

    Notes
    -----
    Not in the thesis: Routh–Hurwitz (:func:`integral_gain_limit`) with every gain
    scaled by s, since K_i < B0 s K_p K_d / J ⇔ s > s_c.

    Examples
    --------
    >>> round(float(critical_gain_scale(0.005, 1e-4, 1.5, 0.05, 15.0)), 12)   # triple pole: 1/9
    0.111111111111
    """
    ki = as_positive("ki", ki, unit="A·m²/(rad·s)")
    return ki / integral_gain_limit(inertia, field, kp, kd)


def ziegler_nichols_pid(ultimate_gain, ultimate_period):
    r"""Classic Ziegler–Nichols PID gains from the ultimate gain and period.

    Parameters
    ----------
    ultimate_gain : array_like
        K_u, the P gain at which the loop oscillates steadily [A·m²/rad], > 0.
    ultimate_period : array_like
        T_u, the period of that oscillation [s], > 0.

    Returns
    -------
    kp, ki, kd : ndarray
        :math:`K_p = 0.6K_u`, :math:`K_i = 1.2K_u/T_u`, :math:`K_d = 0.075K_uT_u`
        (T_i = T_u/2, T_d = T_u/8) in the units of K_u.

    Notes
    -----
    Not in the thesis's text: its reference [11], Ziegler and Nichols (1942), table of
    the "ultimate sensitivity" method. For the double-integrator plant of the mock-up
    every P gain is ultimate (:func:`double_integrator_ultimate_gain`).

    Examples
    --------
    >>> [round(float(k), 12) for k in ziegler_nichols_pid(1.0, 10.0)]
    [0.6, 0.12, 0.75]
    """
    ku = as_positive("ultimate_gain", ultimate_gain, unit="A·m²/rad")
    tu = as_positive("ultimate_period", ultimate_period, unit="s")
    return 0.6 * ku, 1.2 * ku / tu, 0.075 * ku * tu


def double_integrator_ultimate_gain(inertia, field, period):
    r"""P gain at which the P-only loop on the mock-up oscillates with a chosen period.

    Parameters
    ----------
    inertia : array_like
        J [kg·m²], > 0.
    field : array_like
        B0 [T], > 0.
    period : array_like
        Oscillation period [s], > 0.

    Returns
    -------
    ndarray
        :math:`K_u = J(2\pi/T)^2/B_0` [A·m²/rad]. The P-only loop
        :math:`J s^2 + B_0 K_p = 0` oscillates undamped for *every* K_p > 0, so the
        Ziegler–Nichols experiment has no unique ultimate point: the period is a free
        choice and fixes K_u.

    Notes
    -----
    Not in the thesis: follows from eqs. (36)–(38) with K_i = K_d = 0.

    Examples
    --------
    >>> round(float(double_integrator_ultimate_gain(0.005, 1e-4, 2 * np.pi)), 12)
    50.0
    """
    j = as_positive("inertia", inertia, unit="kg·m²")
    w = 2.0 * np.pi / as_positive("period", period, unit="s")
    return j * w**2 / as_positive("field", field, unit="T")


#: Readings of the thesis's unit-less gains, each a constant factor on all three gains
#: that converts them to the SI reading (A·m² per rad, per rad·s, per rad/s).
GAIN_READINGS = {
    "si": "gains in SI: m [A·m²], e [rad], t [s], B [T] (the literal reading)",
    "per-degree": "error in degrees: K_SI = K·180/π",
    "normalised": "output as a fraction of the coils' maximum moment: K_SI = K·m_max",
    "per-degree-normalised": "error in degrees and output normalised: K_SI = K·m_max·180/π",
    "field-in-gauss": "B0 entered in gauss (CGS, as eq. 5 suggests): K_SI = K·10⁴",
    "field-in-A/m": "B0 entered as H in A/m (eq. 5 read in SI): K_SI = K/μ0",
    "torque-output": "output is a torque [N·m], not a dipole: K_SI = K/B0",
}


def gain_reading_scale(reading, field, moment_limit):
    r"""Factor that turns the thesis's printed gains into SI gains under one reading.

    Parameters
    ----------
    reading : str
        A key of :data:`GAIN_READINGS` [-].
    field : float
        B0 [T], > 0 (the true field: used by the torque-output reading).
    moment_limit : float
        The coils' maximum moment [A·m²], > 0 (used by the normalised readings).

    Returns
    -------
    float
        s [-] with K_SI = s·K_printed for all three gains.

    Notes
    -----
    Not in the thesis: it never states the units of K_p, K_i, K_d (seed lines 530–579;
    inventory gap G15). Every candidate reading is a constant factor, so
    :func:`critical_gain_scale` decides its stability at once.

    Examples
    --------
    >>> round(gain_reading_scale("per-degree", 3e-4, 0.4), 6)
    57.29578
    """
    from .constants import MU_0

    b = float(as_positive("field", field, unit="T"))
    m = float(as_positive("moment_limit", moment_limit, unit="A·m²"))
    scales = {"si": 1.0, "per-degree": 180.0 / np.pi, "normalised": m,
              "per-degree-normalised": m * 180.0 / np.pi, "field-in-gauss": 1e4,
              "field-in-A/m": 1.0 / MU_0, "torque-output": 1.0 / b}
    if reading not in scales:
        raise ValueError(f"reading must be one of {', '.join(GAIN_READINGS)}, got {reading!r}")
    return scales[reading]
