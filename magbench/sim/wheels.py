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

from .._validate import (as_choice, as_finite, as_nonnegative, as_positive_scalar, as_run_timing, as_whole_steps,
                         check_member_steps, shown)
from ..control import kernels as laws
from ..dynamics import kernels
from ..earth import CircularOrbit
from ..integrate import rk4_step
from .result import SimulationResult

__all__ = ["WheelSatellite", "UnloadingLaw", "DisturbanceTorque", "simulate_unloading"]

LAWS = ("none", "linear", "product", "relay", "relay_coil")


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
    kind : {"none", "linear", "product", "relay", "relay_coil"}
        "linear": L = k (h × B)/B², eq. (5.1); "product": L = k (h × B), the per-axis
        products of eqs. (5.6), (5.11) without the division by B²; "relay": L = k F_K(h) × B,
        eq. (5.7); "relay_coil": L_i = L0 F_L(δ_i), δ = F_K(h) × B (Fig. 5.2); "none": coils
        off.
    gain : float, optional
        k ≥ 0 [1/s] ("linear"), k [A·m²/(N·m·s·T)] ("product"), k [A·m²/T] ("relay"), L0
        [A·m²] ("relay_coil").
    dead_zone : float or tuple of float, optional
        K°_i ≥ 0 of F_K [N·m·s]. For the relay laws the relay on each channel; for "linear"
        and "product" the switch of §5.3's system 3: the law acts while some channel's relay
        is on (default 0: always).
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


class _Path:
    """The orbit tabulated at every half step of a run: the inertial field (N, M, 3), the orbital
    axes (N, M, 3, 3) and the argument of latitude (N, M). None of it depends on the state, so
    it is evaluated once instead of four times a step."""

    def __init__(self, orbit, steps, step, members, axes=True):
        t = (np.arange(2 * steps + 1) * 0.5 * step)[:, None]
        n = t.shape[0]
        self.step, self.mean_motion = step, orbit.mean_motion
        self.field = np.broadcast_to(orbit.field(t), (n, members, 3))
        if axes:
            self.axes = np.broadcast_to(orbit.orbital_axes(t), (n, members, 3, 3))
            self.latitude = np.broadcast_to(np.asarray(orbit.argument_of_latitude(t), dtype=float), (n, members))

    def index(self, time):
        return int(round(2.0 * time / self.step))


def _orbital_in_body(q, path, time):
    """Rows: the orbital axes X, Y, Z in body components, (M, 3, 3)."""
    axes = path.axes[path.index(time)]
    return np.stack([kernels.rotate(q, axes[..., i, :], -1.0) for i in range(3)], axis=-2)


def _dipole(law, b, h, active):
    """The law's dipole and the relays' updated on/off state (M, 3): on above K°, off at or below K1°."""
    active = (np.abs(h) > np.asarray(law.dead_zone)) | (active & (np.abs(h) > np.asarray(law.release_zone)))
    relay = np.where(active, np.sign(h), 0.0)  # F_K(h) with hysteresis; the kernels' own relay passes it (zone ½)
    # the linear laws run while any channel's relay is on (§5.3, system 3: switched on when a |h_i|
    # passes its threshold); with zero dead zones that is whenever h ≠ 0
    gate = np.any(active, axis=-1, keepdims=True)
    if law.kind == "linear":
        return np.where(gate, laws.unloading_dipole(b, h, law.gain), 0.0), active
    if law.kind == "product":
        return np.where(gate, law.gain * kernels.cross(h, b), 0.0), active
    if law.kind == "relay":
        return laws.relay_unloading_dipole(b, relay, law.gain, 0.5), active
    if law.kind == "relay_coil":
        return laws.relay_coil_unloading_dipole(b, relay, law.gain, 0.5, law.signal_dead_zone), active
    return np.zeros_like(b), active


def _law_groups(law, members):
    """The members each distinct law drives: [(law, index array)], from one law or a sequence of M."""
    if isinstance(law, UnloadingLaw):
        return [(law, np.arange(members))]
    laws_ = tuple(law) if isinstance(law, (list, tuple)) else None
    if laws_ is None or not laws_ or not all(isinstance(x, UnloadingLaw) for x in laws_):
        raise ValueError(f"law must be an UnloadingLaw or a sequence of them, one per member, got {type(law).__name__}")
    if len(laws_) != members:
        raise ValueError(f"law: a sequence needs one UnloadingLaw per member ({members}), got {len(laws_)}")
    groups = {}
    for i, x in enumerate(laws_):
        groups.setdefault(x, []).append(i)
    return [(x, np.asarray(i)) for x, i in groups.items()]


def _group_dipole(groups, b, h, active):
    """Every member's dipole and relay state, each group by its own law."""
    if len(groups) == 1:
        return _dipole(groups[0][0], b, h, active)
    m, on = np.zeros_like(b), np.zeros_like(active)
    for law, i in groups:
        m[i], on[i] = _dipole(law, b[i], h[i], active[i])
    return m, on


def _commands(time, state, path, sat, law, active):
    """(dipole, wheel torque, attitude error angle, flags (M, 3): torque, momentum, dipole limited)."""
    q, w, h = state[:, :4], state[:, 4:7], state[:, 7:]
    o = _orbital_in_body(q, path, time)
    theta = 0.5 * (np.cross(o[..., 0, :], [1.0, 0.0, 0.0]) + np.cross(o[..., 1, :], [0.0, 1.0, 0.0])
                   + np.cross(o[..., 2, :], [0.0, 0.0, 1.0]))
    angle = np.arccos(np.clip((o[..., 0, 0] + o[..., 1, 1] + o[..., 2, 2] - 1.0) / 2.0, -1.0, 1.0))
    rate_error = w - path.mean_motion * o[..., 1, :]
    wanted = sat.attitude_gain * theta + sat.rate_gain * rate_error  # u = −(body torque −k_p θ − k_d δω)
    u_max, h_max = np.asarray(sat.wheel_torque_limit), np.asarray(sat.wheel_momentum_limit)
    u = np.clip(wanted, -u_max, u_max)
    torque_limited = np.any(u != wanted, axis=-1)
    full = (np.abs(h) >= h_max) & (u * h > 0.0)
    u = np.where(full, 0.0, u)
    b = kernels.rotate(q, path.field[path.index(time)], -1.0)
    raw, active = _group_dipole(law, b, h, active)
    m_max = np.asarray(sat.dipole_limit)
    m = np.clip(raw, -m_max, m_max)
    flags = np.stack([torque_limited, np.any(full, axis=-1), np.any(m != raw, axis=-1)], axis=-1)
    return m, u, angle, flags, b, active


def _rhs(time, state, dipole, wheel_torque, path, sat, disturbance):
    """(q̇, ω̇, ḣ_w) of every member; state (M, 10)."""
    q, w, h = state[:, :4], state[:, 4:7], state[:, 7:]
    j = np.asarray(sat.inertia)
    k = path.index(time)
    b = kernels.rotate(q, path.field[k], -1.0)
    torque = kernels.cross(dipole + np.asarray(sat.residual_dipole), b) + np.asarray(disturbance.constant)
    if any(disturbance.periodic):
        u = path.latitude[k][..., None]
        torque = torque + np.asarray(disturbance.periodic) * np.cos(u + disturbance.phase)
    if disturbance.gravity_gradient:
        radial = kernels.rotate(q, path.axes[k][..., 2, :], -1.0)
        torque = torque + kernels.gravity_gradient_torque(radial, j, path.mean_motion)
    w_rate = kernels.euler_rates(w, torque - wheel_torque - kernels.cross(w, h), j)
    return np.concatenate([kernels.quaternion_rate(q, w), w_rate, wheel_torque], axis=-1)


def _member_count(orbit, law, arrays):
    """M, the members a run has: the orbit's phases, the laws and the arrays ``{name: value}``
    (one value or one per member on the first axis; a vector of 3 counts as one) must agree."""
    sizes = {"the orbit's phases": np.atleast_1d(np.asarray(orbit.argument_of_latitude0)).size}
    if isinstance(law, (list, tuple)):
        sizes["the laws"] = len(law)
    for name, value in arrays.items():
        shape = np.shape(value)
        if len(shape) == 2 or (name == "dipole_limit" and len(shape) == 1):
            sizes[name] = shape[0]
    members = max(sizes.values())
    if set(sizes.values()) - {1, members}:
        raise ValueError(f"{', '.join(sizes)} must agree on the members M, got "
                         + ", ".join(f"{v} ({k})" for k, v in sizes.items()))
    return members


def _dipole_limits(dipole_limit, members):
    """L0 per member, shape (M, 1) [A·m²]: a scalar or one per member, > 0 (inf allowed)."""
    limit = np.asarray(dipole_limit, dtype=float)
    if limit.ndim > 1 or np.any(np.isnan(limit)) or np.any(limit <= 0):
        raise ValueError(f"dipole_limit must be > 0 A·m² (inf allowed), a scalar or one per member, got "
                         f"{shown(dipole_limit)}")
    return np.broadcast_to(limit, (members,))[:, None]


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
    law : UnloadingLaw or sequence of UnloadingLaw
        The unloading law: kind, gain [1/s, A·m²/(N·m·s·T), A·m²/T or A·m²], dead zones
        [N·m·s, T]; or one law per member (M), e.g. a ladder of dead zones in one run.
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
                              ("disturbance", disturbance, DisturbanceTorque)):
        if not isinstance(value, kind):
            raise ValueError(f"{name} must be a {kind.__name__}, got {type(value).__name__}")
    total, h, every = as_run_timing(duration, step, record_interval)
    members = _member_count(orbit, law, {"initial_rotation": initial_rotation, "initial_rate": initial_rate,
                                         "initial_wheel_momentum": initial_wheel_momentum})
    groups = _law_groups(law, members)
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
    path = _Path(orbit, steps, h, members)
    for i in range(steps + 1):
        t = i * h
        m, u, angle, flag, b, active = _commands(t, state, path, satellite, groups, active)
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
            state = rk4_step(_rhs, t, state, h, (m, u, path, satellite, disturbance))
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


def _ideal_rhs(time, momentum, dipole, path, torque):
    """K̇ = L × B + M_B for a body fixed in inertial axes; momentum (M, 3)."""
    return kernels.cross(dipole, path.field[path.index(time)]) + torque


def simulate_ideal_unloading(orbit, law, disturbance, duration, step, record_interval=None,
                             initial_wheel_momentum=0.0, dipole_limit=np.inf, control_interval=None, off_time=0.0,
                             body_axes=None):
    r"""Unload the wheels of an ideally stabilised body fixed in inertial space: K̇ = L × B + M_B.

    Parameters
    ----------
    orbit : magbench.earth.CircularOrbit
        The orbit and its field; an array ``argument_of_latitude0`` (M,) gives each member
        its own phase [rad].
    law : UnloadingLaw or sequence of UnloadingLaw
        The unloading law: kind, gain [1/s, A·m²/(N·m·s·T), A·m²/T or A·m²], dead zones
        [N·m·s, T]; or one law per member (M), e.g. a ladder of dead zones in one run.
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
    dipole_limit : float or array_like, shape (M,), optional
        |L_i| the coils can give, per member [A·m²] (default ∞); the clipped steps are
        counted.
    control_interval : float, optional
        Duty cycling (not in Kovalenko: SamSat-218D's scheme, chapter 5, and his §3.7 on a
        magnetometer beside the coils): every ``control_interval`` [s] the coils are off for
        ``off_time``, the field and momentum are read at the start of that gap, and the
        dipole the law gives for them is held for the rest of the interval. Both must be
        whole numbers of steps; default: the law acts on every step's reading, coils always
        available.
    off_time : float, optional
        The coils' off time at the start of each interval, 0 ≤ off_time < control_interval
        [s].
    body_axes : array_like, shape (3, 3) or (M, 3, 3), optional
        The body's axes as rows in inertial components, a rotation (e.g.
        :func:`magbench.earth.sun_ecliptic_axes` for the source's Sun-pointing body); default
        the inertial axes themselves [-]. The disturbance and the momentum are body axes.

    Returns
    -------
    SimulationResult
        States ``wheel_momentum_x..z`` [N·m·s]; inputs ``dipole_x..z`` [A·m²]; outputs
        ``wheel_momentum`` |K| and ``wheel_momentum_along_field`` K·B/|B| [N·m·s]; each (K, M).
        Summary ``dipole_limited_fraction`` (M,) [-] and ``on_fraction``, the share of the
        run's steps at which the coils may act [-].

    Notes
    -----
    Kovalenko (1975) §5.5 (seed lines 121–122): "the problem was solved assuming ideal
    stabilisation ... the rotation of the base (Sun–ecliptic) frame not counted, nor the
    Earth's daily rotation; the dynamic equations took the form K̇_i = M_ctrl,i + M_B,i".
    The source's body points one axis at the Sun in the Sun–ecliptic frame, fixed because the
    frame's annual rotation is neglected (``body_axes``); the field is the library's dipole
    along the orbit.

    Examples
    --------
    >>> run = simulate_ideal_unloading(CircularOrbit(6.83e6, 0.96, 8e22), UnloadingLaw("linear", 0.002), 1e-4,
    ...                                600.0, 10.0, 60.0)
    >>> run.wheel_momentum.shape
    (11, 1)
    """
    if not isinstance(orbit, CircularOrbit):
        raise ValueError(f"orbit must be a magbench.earth.CircularOrbit, got {type(orbit).__name__}")
    total, h, every = as_run_timing(duration, step, record_interval)
    cycle, gap = _duty(control_interval, off_time, h)
    members = _member_count(orbit, law, {"disturbance": disturbance, "initial_wheel_momentum": initial_wheel_momentum,
                                         "dipole_limit": dipole_limit})
    groups = _law_groups(law, members)
    limit = _dipole_limits(dipole_limit, members)
    torque = _members("disturbance", disturbance, members, (3,))
    state = _members("initial_wheel_momentum", initial_wheel_momentum, members, (3,))
    steps = int(np.ceil(total / h - 1e-9))
    check_member_steps(members, steps)
    active = np.zeros((members, 3), dtype=bool)
    states, inputs, fields = [], [], []
    clipped, on_steps = np.zeros(members), 0
    held = np.zeros((members, 3))
    path = _Path(orbit, steps, h, members, axes=False)
    if body_axes is not None:
        axes = as_finite("body_axes", body_axes)
        if axes.shape not in ((3, 3), (members, 3, 3)) or not np.allclose(
                axes @ np.swapaxes(axes, -1, -2), np.eye(3), atol=1e-9) or np.any(np.linalg.det(axes) < 0):
            raise ValueError(f"body_axes must be a rotation matrix, shape (3, 3) or ({members}, 3, 3), got shape "
                             f"{axes.shape}")
        path.field = np.einsum("...ij,...j->...i", axes, path.field)
    for i in range(steps + 1):
        t = i * h
        b = path.field[2 * i]
        if cycle is None:
            raw, active = _group_dipole(groups, b, state, active)
            m = np.clip(raw, -limit, limit)
        else:
            if i % cycle == 0:          # the reading, coils off: the law's dipole for the rest of the interval
                raw, active = _group_dipole(groups, b, state, active)
                held = np.clip(raw, -limit, limit)
            m = held if i % cycle >= gap else np.zeros_like(held)
        if i % every == 0:
            states.append(state)
            inputs.append(m)
            fields.append(b)
        if i < steps:
            if cycle is None or i % cycle >= gap:
                on_steps += 1
                clipped += np.any(m != raw, axis=-1)
            state = rk4_step(_ideal_rhs, t, state, h, (m, path, torque))
    record, field = np.stack(states), np.stack(fields)
    time = np.arange(record.shape[0]) * every * h
    along = np.sum(record * field, axis=-1) / np.linalg.norm(field, axis=-1)
    return SimulationResult(time, np.moveaxis(record, -1, 0), np.moveaxis(np.stack(inputs), -1, 0),
                            np.stack([np.linalg.norm(record, axis=-1), along]),
                            ("wheel_momentum_x", "wheel_momentum_y", "wheel_momentum_z"),
                            ("dipole_x", "dipole_y", "dipole_z"), ("wheel_momentum", "wheel_momentum_along_field"),
                            params={"orbit": orbit, "law": law, "disturbance": torque, "step": h,
                                    "control_interval": control_interval, "off_time": off_time},
                            summary={"dipole_limited_fraction": clipped / max(steps, 1),
                                     "on_fraction": on_steps / max(steps, 1)})


def _duty(control_interval, off_time, step):
    """(steps per interval, off steps) of duty cycling, or (None, 0) without it."""
    if control_interval is None:
        if off_time:
            raise ValueError(f"off_time needs a control_interval, got off_time={shown(off_time)} s alone")
        return None, 0
    cycle = as_whole_steps("control_interval", as_positive_scalar("control_interval", control_interval, unit="s"),
                           step)
    off = as_nonnegative("off_time", off_time, unit="s")
    if off.ndim:
        raise ValueError(f"off_time must be a scalar [s], got shape {off.shape}")
    gap = 0 if float(off) == 0.0 else as_whole_steps("off_time", float(off), step)
    if gap >= cycle:
        raise ValueError(f"off_time must be < control_interval = {cycle * step:g} s, got {float(off):g} s")
    return cycle, gap


__all__ += ["simulate_coil_detumbling"]


def _detumble_rhs(time, state, dipole, path, inertia):
    """(q̇, ω̇) of a rigid body under its coils' torque L × B only; state (M, 7)."""
    q, w = state[:, :4], state[:, 4:]
    b = kernels.rotate(q, path.field[path.index(time)], -1.0)
    return np.concatenate([kernels.quaternion_rate(q, w),
                           kernels.euler_rates(w, kernels.cross(dipole, b), inertia)], axis=-1)


def simulate_coil_detumbling(inertia, orbit, law, duration, step, record_interval=None, initial_momentum=0.0,
                             dipole_limit=np.inf):
    r"""Detumble a rigid body with magnetorquers driven by the momentum laws of §5.2.

    Parameters
    ----------
    inertia : array_like, shape (3,)
        Principal moments J_x, J_y, J_z > 0 [kg·m²].
    orbit : magbench.earth.CircularOrbit
        The orbit and its field (inertial axes); an array ``argument_of_latitude0`` (M,)
        gives each member its own phase [rad].
    law : UnloadingLaw or sequence of UnloadingLaw
        The law acting on the body's momentum K = J ω (body axes): one, or one per member
        (M) [-].
    duration : float
        Length of the run [s].
    step : float
        RK4 step, also the dipole's hold [s]; keep it well below the spin period 2π/|ω|.
    record_interval : float, optional
        Sampling interval, a whole number of steps [s] (default: every step).
    initial_momentum : float or array_like, shape (3,) or (M, 3), optional
        K = J ω at time 0, body axes [N·m·s]; the body starts aligned with the inertial axes.
    dipole_limit : float or array_like, shape (M,), optional
        L0: |L_i| the coils can give, per member [A·m²] (default ∞).

    Returns
    -------
    SimulationResult
        States ``q0..q3`` [-] and ``rate_x..z`` [rad/s]; inputs ``dipole_x..z`` [A·m²] (held
        from each sample); outputs ``momentum`` |K| [N·m·s], ``momentum_along_field`` K·B/|B|
        [N·m·s] and ``dipole_limited`` (1 when a coil was at L0 at some step since the previous
        sample) [-]; each (K, M).

    Notes
    -----
    Kovalenko (1975) §5.4, eqs. (5.10)–(5.18) (seed lines 108–109), the detumbling regime:
    the wheels are off and the disturbances neglected, so J ω̇ + ω × J ω = L × B, with L from
    (5.11) (or any law of §5.2) and |L_i| ≤ L0. The orbital frame's rate is neglected as
    the source does ("Ω ≈ ω", since the body turns many times faster): the law acts on the
    inertial K. The field is the library's dipole along the orbit (the source uses (2.36)–
    (2.40)). Composed from :func:`magbench.dynamics.euler_rates` and the §5.2 kernels.

    Examples
    --------
    >>> orbit = CircularOrbit(6.771e6, np.radians(65.0), 8.1e22)
    >>> run = simulate_coil_detumbling((2950.0, 12800.0, 12800.0), orbit, UnloadingLaw("linear", 1e-3),
    ...                                600.0, 5.0, 60.0, initial_momentum=98.0, dipole_limit=113.0)
    >>> bool(run.momentum[-1, 0] < run.momentum[0, 0])
    True
    """
    j = as_finite("inertia", inertia)
    if j.shape != (3,) or np.any(j <= 0):
        raise ValueError(f"inertia must be three positive principal moments [kg·m²], got {shown(inertia)}")
    if not isinstance(orbit, CircularOrbit):
        raise ValueError(f"orbit must be a magbench.earth.CircularOrbit, got {type(orbit).__name__}")
    total, h, every = as_run_timing(duration, step, record_interval)
    members = _member_count(orbit, law, {"initial_momentum": initial_momentum, "dipole_limit": dipole_limit})
    groups = _law_groups(law, members)
    limit = _dipole_limits(dipole_limit, members)
    momentum = _members("initial_momentum", initial_momentum, members, (3,))
    steps = int(np.ceil(total / h - 1e-9))
    check_member_steps(members, steps)
    q = np.tile([1.0, 0.0, 0.0, 0.0], (members, 1))
    state = np.concatenate([q, momentum / j], axis=-1)
    active = np.zeros((members, 3), dtype=bool)
    states, inputs, fields, flags = [], [], [], []
    pending = np.zeros(members, dtype=bool)
    path = _Path(orbit, steps, h, members, axes=False)
    for i in range(steps + 1):
        t = i * h
        b = kernels.rotate(state[:, :4], path.field[2 * i], -1.0)
        raw, active = _group_dipole(groups, b, j * state[:, 4:], active)
        m = np.clip(raw, -limit, limit)
        pending |= np.any(np.abs(raw) >= limit, axis=-1)
        if i % every == 0:
            states.append(state)
            inputs.append(m)
            fields.append(b)
            flags.append(pending)
            pending = np.zeros(members, dtype=bool)
        if i < steps:
            state = rk4_step(_detumble_rhs, t, state, h, (m, path, j))
    record, field = np.stack(states), np.stack(fields)
    k = j * record[..., 4:]
    time = np.arange(record.shape[0]) * every * h
    along = np.sum(k * field, axis=-1) / np.linalg.norm(field, axis=-1)
    return SimulationResult(
        time, np.moveaxis(record, -1, 0), np.moveaxis(np.stack(inputs), -1, 0),
        np.stack([np.linalg.norm(k, axis=-1), along, np.stack(flags).astype(float)]),
        ("q0", "q1", "q2", "q3", "rate_x", "rate_y", "rate_z"), ("dipole_x", "dipole_y", "dipole_z"),
        ("momentum", "momentum_along_field", "dipole_limited"),
        params={"inertia": tuple(float(x) for x in j), "orbit": orbit, "law": law, "step": h,
                "dipole_limit": limit[:, 0]})
