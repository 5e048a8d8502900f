r"""The mock-up's PID loop simulated: the loop's parameters, its torque, its right-hand
side for ``solve_ivp`` and a sampled simulation.

Thesis §4.1, eqs. (36)–(38) (Figs. 14–18). Composes :mod:`magbench.control` and the
mock-up's torque. SI.
"""

from dataclasses import dataclass

import numpy as np

from .._validate import as_finite, as_positive, shown
from ..dynamics.pendulum import Mockup, mockup_rhs, two_coil_torque
from ..control.allocation import ALLOCATIONS
from ..control.pid import pid_step
from ..integrate import rk4_step, solve_adaptive
from .result import SimulationResult

__all__ = ["PidLoop", "loop_torque", "pid_continuous_rhs", "simulate_pid"]


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

    @property
    def plant(self):
        """The mock-up this loop controls (:class:`magbench.dynamics.Mockup`, no thread) [SI]."""
        return Mockup(self.inertia, self.field)

    def __post_init__(self):
        as_positive("inertia", self.inertia, unit="kg·m²")
        as_positive("field", self.field, unit="T")
        for name in ("kp", "ki", "kd", "target"):
            as_finite(name, getattr(self, name))
        if not float(self.moment_limit) > 0:
            raise ValueError(f"moment_limit must be > 0 A·m² (inf for none), got {shown(self.moment_limit)}")
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
    Thesis eqs. (36)–(38) and §4.1. The sign m_z = −u makes
    e = ψ_des − ψ of eq. (37) a negative feedback, as eq. (38) intends. No checks: the
    inner kernel of the simulations.

    Examples
    --------
    >>> loop = PidLoop(0.005, 1e-4, 0.1, 0.0, 0.5)
    >>> round(float(loop_torque(0.3, 0.2, loop)), 12)
    2e-05
    """
    return two_coil_torque(psi, *_allocated_moments(psi, command, loop.allocation), loop.field)


def _allocated_moments(psi, command, allocation):
    """Coil moments (m1, m2) [A·m²] for the PID command u [A·m²] at angle ψ [rad]."""
    if allocation == "exact":
        bx, by = np.cos(psi), -np.sin(psi)
    else:
        bx, by = np.ones_like(psi), -np.asarray(psi)
    mz = -np.asarray(command)
    # M = (0, 0, m_z) × b with b_z = 0 (thesis §4.1): coil 1 gets −m_z b_y, coil 2 m_z b_x.
    return -mz * by, mz * bx


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
    Thesis eqs. (36)–(38): u = sat(K_p e + K_i ∫e + K_d ė),
    e = ψ_des − ψ, ė = −ω (the gyro rate: derivative on the measurement, no kick).
    Use as ``solve_ivp(pid_continuous_rhs, span, (initial_angle, initial_rate, 0.0), args=(loop,))``.
    The anti-windup scheme is ours (Åström and Hägglund, back-calculation); the thesis
    states none.

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


def simulate_pid(loop, initial_angle, initial_rate, duration, *, sample_interval=None, output_interval=0.1,
                 method="RK45"):
    r"""Run the closed loop from an initial state, continuous or sampled.

    Parameters
    ----------
    loop : PidLoop
        Loop parameters [SI].
    initial_angle, initial_rate : float
        Initial angle [rad] and rate [rad/s]; the integral starts at 0.
    duration : float
        Duration [s], > 0.
    sample_interval : float, optional
        Controller sample interval Δt [s] (the Arduino loop): the PID runs as
        :func:`pid_step` on samples of ψ and ω and its output is held (zero-order hold)
        while the plant is integrated (RK4, 4 sub-steps). Default: the continuous loop,
        :func:`pid_continuous_rhs` with solve_ivp (RK45, rtol 1e-9).
    output_interval : float, optional
        Spacing of the returned samples [s], > 0: the run is returned at
        ``round(duration / output_interval) + 1`` equally spaced instants from 0 to
        ``duration``, the same grid in both modes whatever the sample interval (between
        controller samples the sampled loop's state is integrated to the instant, with
        the held command).
    method : str, optional
        solve_ivp method for the continuous loop [-]; "LSODA" or "Radau" for stiff loops
        (gains so large that the real pole lies far beyond the oscillation).

    Returns
    -------
    SimulationResult
        Time series [SI]: states ``psi`` [rad], ``rate`` [rad/s] and ``integral``
        [rad·s], input ``command`` (the saturated PID output u) [A·m²], output
        ``torque`` about the vertical [N·m].

    Notes
    -----
    Thesis eqs. (36)–(38) and Figs. 15–18. Not in the thesis: it states neither the
    controller's sample interval nor an anti-windup scheme. The sampled loop's plant
    steps are :func:`magbench.sim.rk4_step`.

    Examples
    --------
    >>> loop = PidLoop(0.005, 3.14e-4, 0.12, 0.002, 2.4, moment_limit=0.4)
    >>> r = simulate_pid(loop, 0.05, 0.0, 300.0)
    >>> abs(float(r.psi[-1])) < 1e-3
    True
    """
    initial_angle = float(as_finite("initial_angle", initial_angle))
    initial_rate = float(as_finite("initial_rate", initial_rate))
    duration = float(as_positive("duration", duration, unit="s"))
    out = float(as_positive("output_interval", output_interval, unit="s"))
    t_out = np.linspace(0.0, duration, max(1, int(round(duration / out))) + 1)
    if sample_interval is None:
        t = t_out
        sol = solve_adaptive(pid_continuous_rhs, (0.0, duration), [initial_angle, initial_rate, 0.0],
                             args=(loop,), t_eval=t, rtol=1e-9, atol=1e-12, max_step=min(out, 1.0), method=method)
        psi, omega, integral = sol.y
        raw = loop.kp * (loop.target - psi) + loop.ki * integral - loop.kd * omega
        command = np.clip(raw, -loop.moment_limit, loop.moment_limit)
    else:
        dt = float(as_positive("sample_interval", sample_interval, unit="s"))
        x = np.array([initial_angle, initial_rate])
        integral_k, h, plant = 0.0, dt / 4, loop.plant
        rows, j, k = [], 0, 0
        # An output instant within 1e-9 of a sample interval of the next sample belongs
        # to that sample (floating-point multiples such as 12.5·0.04 s ≠ 0.5 s).
        slack = 1e-9 * dt
        while j < t_out.size:
            t_k = k * dt
            u, new_integral = pid_step(loop.target - x[0], -x[1], integral_k, dt, loop.kp, loop.ki,
                                       loop.kd, loop.moment_limit if loop.anti_windup or
                                       not np.isfinite(loop.moment_limit) else np.inf)
            if not loop.anti_windup:
                u = np.clip(u, -loop.moment_limit, loop.moment_limit)
            args = (u, loop.allocation, plant)
            while j < t_out.size and t_out[j] < t_k + dt - slack:
                x_out, part = x, t_out[j] - t_k
                if part > slack:    # between two samples: the plant integrated to the instant
                    for i in range(4):
                        x_out = rk4_step(_held_command_rhs, t_k + i * part / 4, x_out, part / 4, args=args)
                rows.append((t_out[j], x_out[0], x_out[1], integral_k, float(u)))
                j += 1
            for i in range(4):      # RK4 on the plant with the command held
                x = rk4_step(_held_command_rhs, t_k + i * h, x, h, args=args)
            integral_k = float(new_integral)
            k += 1
        t, psi, omega, integral, command = (np.array(c) for c in zip(*rows))
    return SimulationResult(t, np.array([psi, omega, integral]), command[np.newaxis],
                            loop_torque(psi, command, loop)[np.newaxis], ("psi", "rate", "integral"),
                            ("command",), ("torque",), params={"loop": loop})


def _held_command_rhs(t, state, command, allocation, plant):
    """The mock-up under :func:`simulate_pid`'s sampled loop, the PID command held."""
    return mockup_rhs(t, state, _allocated_moments(state[0], command, allocation), plant)
