r"""A three-axis stabilised spacecraft with three reaction wheels whose momentum magnetorquers
unload (Kovalenko (1975) ch. 5): the body held in the orbital frame by a PD law acting through
the wheels, the wheels' momentum removed by one of the §5.2 unloading laws. Composed from the
dynamics and control kernels and :class:`magbench.earth.CircularOrbit`, stepped by
:func:`magbench.integrate.rk4_step`.

State of one member (10 numbers): the body quaternion q (4, body → inertial), the body rate ω
(3, body axes, inertial rate) and the wheels' momentum h_w (3, body axes; wheel i along body
axis i, h_w,i = J_w,i(ω_i + Ω_i)). The body with its wheels is a gyrostat:

    J ω̇ = T_ext − u − ω × (J ω + h_w),    ḣ_w = u,

u the wheels' motor torques (:func:`magbench.dynamics.euler_rates` with T_ext − u − ω × h_w);
T_ext = (L + L_res) × B + gravity gradient + disturbance. The commands (the PD torque, the
dipole) are formed from the state at the start of each step and held over it (a zero-order
hold).
"""

from dataclasses import dataclass

import numpy as np
from scipy.spatial.transform import Rotation

from .._validate import (as_choice, as_finite, as_nonnegative, as_positive_scalar, as_whole_steps, check_member_steps,
                         shown)
from ..control import kernels as laws
from ..dynamics import kernels
from ..earth import CircularOrbit
from ..integrate import rk4_step
from .result import SimulationResult

__all__ = ["WheelSatellite", "UnloadingLaw", "DisturbanceTorque", "simulate_unloading"]

LAWS = ("none", "linear", "relay", "relay_coil")


def _vector(name, value, unit, nonnegative=False):
    arr = (as_nonnegative(name, value, unit=unit) if nonnegative else as_finite(name, value))
    arr = np.broadcast_to(arr, (3,)) if arr.ndim == 0 else arr
    if arr.shape != (3,):
        raise ValueError(f"{name} must be a scalar or three components [{unit}], got shape {arr.shape}")
    return tuple(float(x) for x in arr)


@dataclass(frozen=True)
class WheelSatellite:
    r"""A rigid body with three reaction wheels along its principal axes and three magnetorquers.

    Parameters
    ----------
    inertia : tuple of float
        Principal moments of the body with its wheels (I_x, I_y, I_z) [kg·m²].
    attitude_gain : float
        k_p > 0 of the PD law (body torque −k_p θ − k_d δω) [N·m/rad].
    rate_gain : float
        k_d ≥ 0 [N·m·s/rad].
    wheel_torque_limit : float or tuple of float, optional
        |u_i| the motors can give [N·m] (default ∞).
    wheel_momentum_limit : float or tuple of float, optional
        |h_w,i| a wheel can store [N·m·s] (default ∞); at the limit a motor torque that would
        push further is cut to zero.
    dipole_limit : float or tuple of float, optional
        |L_i| the magnetorquers can give [A·m²] (default ∞).
    residual_dipole : tuple of float, optional
        A dipole fixed in the body, body axes [A·m²].

    Notes
    -----
    Kovalenko (1975) §5.4 (seed lines 114–116): the unloading regime's equations (5.35)–(5.44)
    hold the body with wheels and feed the magnetorquers from the wheels' momentum. Not in
    the sources: the PD law (any stabilisation loop; the seed's loop is not legible). The
    limits are explicit: the simulation records every step at which one acts.
    """

    inertia: tuple
    attitude_gain: float
    rate_gain: float
    wheel_torque_limit: float = np.inf
    wheel_momentum_limit: float = np.inf
    dipole_limit: float = np.inf
    residual_dipole: tuple = (0.0, 0.0, 0.0)

    def __post_init__(self):
        j = as_finite("inertia", self.inertia)
        if j.shape != (3,) or np.any(j <= 0):
            raise ValueError(f"inertia must be three positive principal moments [kg·m²], got {shown(self.inertia)}")
        object.__setattr__(self, "inertia", tuple(float(x) for x in j))
        object.__setattr__(self, "attitude_gain", float(as_positive_scalar("attitude_gain", self.attitude_gain,
                                                                             unit="N·m/rad")))
        k_d = as_nonnegative("rate_gain", self.rate_gain, unit="N·m·s/rad")
        if k_d.ndim:
            raise ValueError(f"rate_gain must be a scalar [N·m·s/rad], got shape {k_d.shape}")
        object.__setattr__(self, "rate_gain", float(k_d))
        for name, unit in (("wheel_torque_limit", "N·m"), ("wheel_momentum_limit", "N·m·s"), ("dipole_limit", "A·m²")):
            value = np.asarray(getattr(self, name), dtype=float) if not isinstance(getattr(self, name), str) else None
            if value is None or np.any(np.isnan(value)) or np.any(value <= 0):
                raise ValueError(f"{name} must be > 0 {unit} (inf allowed), got {shown(getattr(self, name))}")
            value = np.broadcast_to(value, (3,)) if value.ndim == 0 else value
            if value.shape != (3,):
                raise ValueError(f"{name} must be a scalar or three components [{unit}], got shape {value.shape}")
            object.__setattr__(self, name, tuple(float(x) for x in value))
        object.__setattr__(self, "residual_dipole", _vector("residual_dipole", self.residual_dipole, "A·m²"))


@dataclass(frozen=True)
class UnloadingLaw:
    r"""Which §5.2 unloading law feeds the magnetorquers, with its settings.

    Parameters
    ----------
    kind : {"none", "linear", "relay", "relay_coil"}
        "linear": L = k (h × B)/B², eq. (5.1); "relay": L = k F_K(h) × B, eq. (5.7);
        "relay_coil": L_i = L0 F_L(δ_i), δ = F_K(h) × B (Fig. 5.2); "none": coils off.
    gain : float, optional
        k ≥ 0 [1/s] ("linear"), k [A·m²/T] ("relay"), L0 [A·m²] ("relay_coil").
    dead_zone : float or tuple of float, optional
        K°_i ≥ 0 of F_K [N·m·s] (relay laws).
    signal_dead_zone : float, optional
        δ0 ≥ 0 of F_L [T] ("relay_coil").
    release_zone : float or tuple of float, optional
        K1°_i, 0 ≤ K1° ≤ K°: a relay switched on at |h_i| > K° stays on until |h_i| ≤ K1°
        (the hysteresis of Fig. 5.1b) [N·m·s]; default K° (no hysteresis).

    Notes
    -----
    Kovalenko (1975) §5.2, eqs. (5.1), (5.7); the laws are
    :func:`magbench.control.unloading_dipole`, :func:`~magbench.control.relay_unloading_dipole`
    and :func:`~magbench.control.relay_coil_unloading_dipole`. They act on the wheels'
    momentum h_w only (the source's remark after (5.47): with the rate gyros' information the
    law would have to subtract the orbital momentum J_y n).
    """

    kind: str = "linear"
    gain: float = 0.0
    dead_zone: float = 0.0
    signal_dead_zone: float = 0.0
    release_zone: float = None

    def __post_init__(self):
        as_choice("kind", self.kind, LAWS)
        gain = as_nonnegative("gain", self.gain)
        if gain.ndim:
            raise ValueError(f"gain must be a scalar, got shape {gain.shape}")
        object.__setattr__(self, "gain", float(gain))
        object.__setattr__(self, "dead_zone", _vector("dead_zone", self.dead_zone, "N·m·s", nonnegative=True))
        delta = as_nonnegative("signal_dead_zone", self.signal_dead_zone, unit="T")
        if delta.ndim:
            raise ValueError(f"signal_dead_zone must be a scalar [T], got shape {delta.shape}")
        object.__setattr__(self, "signal_dead_zone", float(delta))
        release = self.dead_zone if self.release_zone is None else self.release_zone
        release = _vector("release_zone", release, "N·m·s", nonnegative=True)
        if any(r > k for r, k in zip(release, self.dead_zone)):
            raise ValueError(f"release_zone must be <= dead_zone {self.dead_zone} N·m·s, got {release}")
        object.__setattr__(self, "release_zone", release)


@dataclass(frozen=True)
class DisturbanceTorque:
    r"""External torques besides the magnetorquers': gravity gradient and a disturbance.

    Parameters
    ----------
    constant : tuple of float, optional
        A torque fixed in body axes [N·m].
    periodic : tuple of float, optional
        Amplitudes of a torque a_i cos(u + φ), u the argument of latitude, body axes [N·m].
    phase : float, optional
        φ [rad].
    gravity_gradient : bool, optional
        Include 3n² r̂ × J r̂ (Kovalenko eq. (4.18)) [-].

    Notes
    -----
    Kovalenko (1975) §5.4–5.5 (seed lines 116, 122): the disturbances other than gravity
    M_B (constant in body axes, "by misalignment of the dynamic axes with the sensors'") and
    the §5.5 runs' 10⁻⁴ N·m on every axis.
    """

    constant: tuple = (0.0, 0.0, 0.0)
    periodic: tuple = (0.0, 0.0, 0.0)
    phase: float = 0.0
    gravity_gradient: bool = True

    def __post_init__(self):
        object.__setattr__(self, "constant", _vector("constant", self.constant, "N·m"))
        object.__setattr__(self, "periodic", _vector("periodic", self.periodic, "N·m"))
        phase = as_finite("phase", self.phase)
        if phase.ndim:
            raise ValueError(f"phase must be a scalar [rad], got shape {phase.shape}")
        object.__setattr__(self, "phase", float(phase))
        object.__setattr__(self, "gravity_gradient", bool(self.gravity_gradient))


def _orbital_in_body(q, orbit, time):
    """Rows: the orbital axes X, Y, Z in body components, (M, 3, 3)."""
    axes = np.broadcast_to(orbit.orbital_axes(time), q.shape[:-1] + (3, 3))
    return np.stack([kernels.rotate(q, axes[..., i, :], -1.0) for i in range(3)], axis=-2)


def _dipole(law, b, h, active):
    """The law's dipole and the relays' updated on/off state (M, 3): on above K°, off at or below K1°."""
    active = (np.abs(h) > np.asarray(law.dead_zone)) | (active & (np.abs(h) > np.asarray(law.release_zone)))
    relay = np.where(active, np.sign(h), 0.0)  # F_K(h) with hysteresis; the kernels' own relay passes it (zone ½)
    if law.kind == "linear":
        return laws.unloading_dipole(b, h, law.gain), active
    if law.kind == "relay":
        return laws.relay_unloading_dipole(b, relay, law.gain, 0.5), active
    if law.kind == "relay_coil":
        return laws.relay_coil_unloading_dipole(b, relay, law.gain, 0.5, law.signal_dead_zone), active
    return np.zeros_like(b), active


def _commands(time, state, orbit, sat, law, active):
    """(dipole, wheel torque, attitude error angle, flags (M, 3): torque, momentum, dipole limited)."""
    q, w, h = state[:, :4], state[:, 4:7], state[:, 7:]
    o = _orbital_in_body(q, orbit, time)
    theta = 0.5 * (np.cross(o[..., 0, :], [1.0, 0.0, 0.0]) + np.cross(o[..., 1, :], [0.0, 1.0, 0.0])
                   + np.cross(o[..., 2, :], [0.0, 0.0, 1.0]))
    angle = np.arccos(np.clip((o[..., 0, 0] + o[..., 1, 1] + o[..., 2, 2] - 1.0) / 2.0, -1.0, 1.0))
    rate_error = w - orbit.mean_motion * o[..., 1, :]
    wanted = sat.attitude_gain * theta + sat.rate_gain * rate_error  # u = −(body torque −k_p θ − k_d δω)
    u_max, h_max = np.asarray(sat.wheel_torque_limit), np.asarray(sat.wheel_momentum_limit)
    u = np.clip(wanted, -u_max, u_max)
    torque_limited = np.any(u != wanted, axis=-1)
    full = (np.abs(h) >= h_max) & (u * h > 0.0)
    u = np.where(full, 0.0, u)
    b = kernels.rotate(q, orbit.field(time), -1.0)
    raw, active = _dipole(law, b, h, active)
    m_max = np.asarray(sat.dipole_limit)
    m = np.clip(raw, -m_max, m_max)
    flags = np.stack([torque_limited, np.any(full, axis=-1), np.any(m != raw, axis=-1)], axis=-1)
    return m, u, angle, flags, b, active


def _rhs(time, state, dipole, wheel_torque, orbit, sat, disturbance):
    """(q̇, ω̇, ḣ_w) of every member; state (M, 10)."""
    q, w, h = state[:, :4], state[:, 4:7], state[:, 7:]
    j = np.asarray(sat.inertia)
    b = kernels.rotate(q, orbit.field(time), -1.0)
    torque = kernels.cross(dipole + np.asarray(sat.residual_dipole), b) + np.asarray(disturbance.constant)
    if any(disturbance.periodic):
        u = np.asarray(orbit.argument_of_latitude(time), dtype=float)[..., None]
        torque = torque + np.asarray(disturbance.periodic) * np.cos(u + disturbance.phase)
    if disturbance.gravity_gradient:
        radial = kernels.rotate(q, np.broadcast_to(orbit.orbital_axes(time)[..., 2, :], w.shape), -1.0)
        torque = torque + kernels.gravity_gradient_torque(radial, j, orbit.mean_motion)
    w_rate = kernels.euler_rates(w, torque - wheel_torque - kernels.cross(w, h), j)
    return np.concatenate([kernels.quaternion_rate(q, w), w_rate, wheel_torque], axis=-1)


def _members(name, value, members, shape):
    arr = as_finite(name, value)
    try:
        return np.broadcast_to(arr[..., None] if arr.ndim == 0 else arr, (members,) + shape).copy()
    except ValueError:
        raise ValueError(f"{name} must be a scalar, shape {shape} or ({members},) + {shape}, got shape "
                         f"{arr.shape}") from None


def simulate_unloading(satellite, orbit, law, disturbance, duration, step, record_interval=None,
                       initial_rotation=0.0, initial_rate=0.0, initial_wheel_momentum=0.0):
    r"""Integrate a wheel-stabilised spacecraft whose wheels magnetorquers unload.

    Parameters
    ----------
    satellite : WheelSatellite
        Inertia [kg·m²], PD gains, wheel and coil limits, residual dipole.
    orbit : magbench.earth.CircularOrbit
        The orbit and its field (inertial axes); an array ``argument_of_latitude0`` (M,) gives
        each member its own phase [rad].
    law : UnloadingLaw
        The unloading law: kind, gain [1/s or A·m²/T or A·m²], dead zones [N·m·s, T].
    disturbance : DisturbanceTorque
        Gravity gradient on or off, constant and orbit-periodic torques [N·m].
    duration : float
        Length of the run [s].
    step : float
        RK4 step, also the commands' hold [s]; keep it well below the PD loop's time
        constants √(I/k_p) and I/k_d.
    record_interval : float, optional
        Sampling interval, a whole number of steps [s] (default: every step).
    initial_rotation : float or array_like, shape (3,) or (M, 3), optional
        Rotation vector from the orbital frame to the body at time 0, body axes [rad].
    initial_rate : float or array_like, shape (3,) or (M, 3), optional
        Body rate added to the orbital frame's rate n Y at time 0, body axes [rad/s].
    initial_wheel_momentum : float or array_like, shape (3,) or (M, 3), optional
        h_w at time 0, body axes [N·m·s].

    Returns
    -------
    SimulationResult
        States ``q0..q3`` [-], ``rate_x..z`` [rad/s], ``wheel_momentum_x..z`` [N·m·s]; inputs
        ``dipole_x..z`` [A·m²] and ``wheel_torque_x..z`` [N·m] (the commands held from each
        sample); outputs ``attitude_error`` (angle from the orbital frame) [rad],
        ``wheel_momentum`` |h_w| and ``wheel_momentum_along_field`` h_w·B/|B| [N·m·s],
        ``momentum_x..z`` (body + wheels, inertial axes) [N·m·s] and ``torque_limited``,
        ``momentum_limited``, ``dipole_limited`` (1 when a limit acted at some step since the
        previous sample, else 0) [-]; each (K, M). Summary: ``first_momentum_limit_time``
        [s] per member (NaN if never) and ``limited_fraction`` (3, M): the fraction of steps
        at which each limit acted [-].

    Notes
    -----
    Kovalenko (1975) §5.4, the unloading regime (5.35)–(5.44) (seed lines 114–116), with
    the laws of §5.2. The body's attitude error is the rotation from the orbital frame; the
    PD law's error vector θ = ½ Σ_i o_i × e_i (o_i the orbital axes, e_i the body axes) is
    the rotation vector to first order. Not in the sources: the PD law, the zero-order hold.

    Examples
    --------
    >>> sat = WheelSatellite((10.0, 12.0, 8.0), 0.01, 0.4)
    >>> run = simulate_unloading(sat, CircularOrbit(6.83e6, 0.96, 8e22), UnloadingLaw("linear", 0.002),
    ...                          DisturbanceTorque(constant=(0.0, 1e-5, 0.0)), 600.0, 5.0, 60.0)
    >>> run.wheel_momentum.shape
    (11, 1)
    """
    for name, value, kind in (("satellite", satellite, WheelSatellite), ("orbit", orbit, CircularOrbit),
                              ("law", law, UnloadingLaw), ("disturbance", disturbance, DisturbanceTorque)):
        if not isinstance(value, kind):
            raise ValueError(f"{name} must be a {kind.__name__}, got {type(value).__name__}")
    total = as_positive_scalar("duration", duration, unit="s")
    h = as_positive_scalar("step", step, unit="s")
    every = 1 if record_interval is None else as_whole_steps(
        "record_interval", as_positive_scalar("record_interval", record_interval, unit="s"), h)
    phase = np.atleast_1d(np.asarray(orbit.argument_of_latitude0, dtype=float))
    sizes = {phase.size} | {np.asarray(v).shape[0] for v in (initial_rotation, initial_rate, initial_wheel_momentum)
                            if np.ndim(v) == 2}
    members = max(sizes)
    if sizes - {1, members}:
        raise ValueError(f"the orbit's phases ({phase.size}), initial_rotation, initial_rate and "
                         f"initial_wheel_momentum must agree on the members M, got {sorted(sizes)}")
    rotation = _members("initial_rotation", initial_rotation, members, (3,))
    rate = _members("initial_rate", initial_rate, members, (3,))
    wheels = _members("initial_wheel_momentum", initial_wheel_momentum, members, (3,))
    steps = int(np.ceil(total / h - 1e-9))
    check_member_steps(members, steps)
    axes = np.broadcast_to(orbit.orbital_axes(0.0), (members, 3, 3))
    body = np.swapaxes(axes, -1, -2) @ Rotation.from_rotvec(rotation).as_matrix()
    q = Rotation.from_matrix(body).as_quat(scalar_first=True)
    orbital_rate = np.einsum("...ji,...j->...i", body, axes[..., 1, :]) * orbit.mean_motion
    state = np.concatenate([q, orbital_rate + rate, wheels], axis=-1)
    states, inputs, angles, fields, flags = [], [], [], [], []
    pending = np.zeros((members, 3), dtype=bool)
    counts = np.zeros((members, 3))
    first = np.full(members, np.nan)
    active = np.zeros((members, 3), dtype=bool)
    for i in range(steps + 1):
        t = i * h
        m, u, angle, flag, b, active = _commands(t, state, orbit, satellite, law, active)
        pending |= flag
        if i < steps:
            counts += flag
            first = np.where(np.isnan(first) & flag[:, 1], t, first)
        if i % every == 0:
            states.append(state)
            inputs.append(np.concatenate([m, u], axis=-1))
            angles.append(angle)
            fields.append(b)
            flags.append(pending)
            pending = np.zeros((members, 3), dtype=bool)
        if i < steps:
            state = rk4_step(_rhs, t, state, h, (m, u, orbit, satellite, disturbance))
    record, field = np.stack(states), np.stack(fields)
    time = np.arange(record.shape[0]) * every * h
    hw = record[..., 7:]
    along = np.sum(hw * field, axis=-1) / np.linalg.norm(field, axis=-1)
    momentum = kernels.rotate(record[..., :4], np.asarray(satellite.inertia) * record[..., 4:7] + hw, 1.0)
    outputs = np.concatenate([np.stack(angles)[None], np.linalg.norm(hw, axis=-1)[None], along[None],
                              np.moveaxis(momentum, -1, 0), np.moveaxis(np.stack(flags), -1, 0).astype(float)])
    labels = ("q0", "q1", "q2", "q3", "rate_x", "rate_y", "rate_z", "wheel_momentum_x", "wheel_momentum_y",
              "wheel_momentum_z")
    return SimulationResult(
        time, np.moveaxis(record, -1, 0), np.moveaxis(np.stack(inputs), -1, 0), outputs, labels,
        ("dipole_x", "dipole_y", "dipole_z", "wheel_torque_x", "wheel_torque_y", "wheel_torque_z"),
        ("attitude_error", "wheel_momentum", "wheel_momentum_along_field", "momentum_x", "momentum_y", "momentum_z",
         "torque_limited", "momentum_limited", "dipole_limited"),
        params={"satellite": satellite, "orbit": orbit, "law": law, "disturbance": disturbance, "step": h},
        summary={"first_momentum_limit_time": first, "limited_fraction": (counts / max(steps, 1)).T})


__all__ += ["simulate_ideal_unloading"]


def _ideal_rhs(time, momentum, dipole, orbit, torque):
    """K̇ = L × B + M_B for a body fixed in inertial axes; momentum (M, 3)."""
    return kernels.cross(dipole, np.broadcast_to(orbit.field(time), momentum.shape)) + torque


def simulate_ideal_unloading(orbit, law, disturbance, duration, step, record_interval=None,
                             initial_wheel_momentum=0.0, dipole_limit=np.inf):
    r"""Unload the wheels of an ideally stabilised, inertially fixed body: K̇ = L × B + M_B.

    Parameters
    ----------
    orbit : magbench.earth.CircularOrbit
        The orbit and its field; the body axes are the inertial axes; an array
        ``argument_of_latitude0`` (M,) gives each member its own phase [rad].
    law : UnloadingLaw
        The unloading law: kind, gain [1/s or A·m²/T or A·m²], dead zones [N·m·s, T].
    disturbance : float or array_like, shape (3,) or (M, 3)
        M_B, a constant torque, body (= inertial) axes [N·m].
    duration : float
        Length of the run [s].
    step : float
        RK4 step, also the dipole's hold [s].
    record_interval : float, optional
        Sampling interval, a whole number of steps [s] (default: every step).
    initial_wheel_momentum : float or array_like, shape (3,) or (M, 3), optional
        K at time 0 [N·m·s].
    dipole_limit : float, optional
        |L_i| the coils can give [A·m²] (default ∞); the clipped steps are counted.

    Returns
    -------
    SimulationResult
        States ``wheel_momentum_x..z`` [N·m·s]; inputs ``dipole_x..z`` [A·m²]; outputs
        ``wheel_momentum`` |K| and ``wheel_momentum_along_field`` K·B/|B| [N·m·s]; each (K, M).
        Summary ``dipole_limited_fraction`` (M,) [-].

    Notes
    -----
    Kovalenko (1975) §5.5 (seed lines 121–122): "the problem was solved assuming ideal
    stabilisation ... the rotation of the base (Sun–ecliptic) frame not counted, nor the
    Earth's daily rotation; the dynamic equations took the form K̇_i = M_ctrl,i + M_B,i".
    Reconstructed: the body axes are taken as the inertial axes (the source's angles ρ_c and
    λ_Ω fix the Sun direction relative to the orbit; ρ_c = λ_Ω = 0 is not legible further),
    and the field is the library's dipole along the orbit.

    Examples
    --------
    >>> run = simulate_ideal_unloading(CircularOrbit(6.83e6, 0.96, 8e22), UnloadingLaw("linear", 0.002), 1e-4,
    ...                                600.0, 10.0, 60.0)
    >>> run.wheel_momentum.shape
    (11, 1)
    """
    if not isinstance(orbit, CircularOrbit):
        raise ValueError(f"orbit must be a magbench.earth.CircularOrbit, got {type(orbit).__name__}")
    if not isinstance(law, UnloadingLaw):
        raise ValueError(f"law must be a UnloadingLaw, got {type(law).__name__}")
    total = as_positive_scalar("duration", duration, unit="s")
    h = as_positive_scalar("step", step, unit="s")
    every = 1 if record_interval is None else as_whole_steps(
        "record_interval", as_positive_scalar("record_interval", record_interval, unit="s"), h)
    limit = np.asarray(dipole_limit, dtype=float)
    if limit.ndim or np.isnan(limit) or limit <= 0:
        raise ValueError(f"dipole_limit must be a scalar > 0 A·m² (inf allowed), got {shown(dipole_limit)}")
    phase = np.atleast_1d(np.asarray(orbit.argument_of_latitude0, dtype=float))
    sizes = {phase.size} | {np.asarray(v).shape[0] for v in (disturbance, initial_wheel_momentum) if np.ndim(v) == 2}
    members = max(sizes)
    if sizes - {1, members}:
        raise ValueError(f"the orbit's phases ({phase.size}), disturbance and initial_wheel_momentum must agree on "
                         f"the members M, got {sorted(sizes)}")
    torque = _members("disturbance", disturbance, members, (3,))
    state = _members("initial_wheel_momentum", initial_wheel_momentum, members, (3,))
    steps = int(np.ceil(total / h - 1e-9))
    check_member_steps(members, steps)
    active = np.zeros((members, 3), dtype=bool)
    states, inputs, fields = [], [], []
    clipped = np.zeros(members)
    for i in range(steps + 1):
        t = i * h
        b = np.broadcast_to(orbit.field(t), state.shape)
        raw, active = _dipole(law, b, state, active)
        m = np.clip(raw, -limit, limit)
        if i % every == 0:
            states.append(state)
            inputs.append(m)
            fields.append(b)
        if i < steps:
            clipped += np.any(m != raw, axis=-1)
            state = rk4_step(_ideal_rhs, t, state, h, (m, orbit, torque))
    record, field = np.stack(states), np.stack(fields)
    time = np.arange(record.shape[0]) * every * h
    along = np.sum(record * field, axis=-1) / np.linalg.norm(field, axis=-1)
    return SimulationResult(time, np.moveaxis(record, -1, 0), np.moveaxis(np.stack(inputs), -1, 0),
                            np.stack([np.linalg.norm(record, axis=-1), along]),
                            ("wheel_momentum_x", "wheel_momentum_y", "wheel_momentum_z"),
                            ("dipole_x", "dipole_y", "dipole_z"), ("wheel_momentum", "wheel_momentum_along_field"),
                            params={"orbit": orbit, "law": law, "disturbance": torque, "step": h},
                            summary={"dipole_limited_fraction": clipped / max(steps, 1)})
