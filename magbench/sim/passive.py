r"""The passive magnetic satellite of TNS-0: an axisymmetric body with a permanent magnet on its
symmetry axis and hysteresis rods across it, on a circular orbit in a dipole field; Monte Carlo
members in one array.

TNS-0 preprint §3 (L392–L455: the magnet, the two orthogonal rods in the equatorial plane, the
equations of motion, lost in extraction) with Kovalenko (1975) ch. 12 (the rods' damping).
Composes :class:`magbench.earth.CircularOrbit`, the rigid body and torques of
:mod:`magbench.dynamics` and the Flatley–Henretty rods of :mod:`magbench.hardware`, integrated
by the one :func:`magbench.sim.rk4_step`. Pure numpy: one step costs ~0.3 ms whatever the
number of members, so spans of days at the session-1 spin rates are out of reach here (see the
shared reference's pitfalls); the capture phase (slow rotation) is cheap.
"""

from dataclasses import dataclass, replace

import numpy as np
from scipy.spatial.transform import Rotation

from .._validate import (as_axisymmetric_inertias, as_finite, as_in_range, as_nonnegative, as_positive_scalar,
                         as_vectors)
from ..constants import MU_0
from ..dynamics import kernels as dynamics_kernels
from ..dynamics.axisymmetric import body_rate_from_momentum
from ..earth.circular_orbit import CircularOrbit
from ..hardware import kernels as hardware_kernels
from ..hardware.hysteresis import limb_constants
from ._detumble_loops import _Field
from ..integrate import rk4_step
from .result import PassiveRun

__all__ = ["PassiveSatellite", "PassiveRun", "simulate_passive", "initial_passive_state"]


@dataclass(frozen=True)
class PassiveSatellite:
    r"""An axisymmetric satellite with a magnet along its symmetry axis z and hysteresis rods.

    Parameters
    ----------
    transverse_inertia : float
        A = B [kg·m²].
    axial_inertia : float
        C [kg·m²].
    magnet_moment : float
        Signed moment m of the magnet along +z [A·m²].
    rod_axes : tuple of 3-tuples, optional
        Unit vector of each rod in body axes [-]; by default x and y (TNS-0 preprint §3, L392).
    rod_volume : float, optional
        Volume of each rod, ≥ 0; 0 switches the rods off [m³].
    rod_coercivity : float, optional
        Flatley–Henretty Hc [A/m].
    rod_remanence : float, optional
        Flatley–Henretty Br [T].
    rod_saturation : float, optional
        Flatley–Henretty Bs [T].

    Notes
    -----
    TNS-0 preprint §3 (L392). The rod defaults are the apparent (rod-shape) values of HyMu-80
    CubeSat rods (Not in the sources: Gerhardt & Palo, SSC10, 2010), not TNS-0's unknown rods.
    """

    transverse_inertia: float
    axial_inertia: float
    magnet_moment: float
    rod_axes: tuple = ((1.0, 0.0, 0.0), (0.0, 1.0, 0.0))
    rod_volume: float = 0.0
    rod_coercivity: float = 12.0
    rod_remanence: float = 0.004
    rod_saturation: float = 0.025

    def __post_init__(self):
        a, c = as_axisymmetric_inertias(self.transverse_inertia, self.axial_inertia)
        if a.ndim or c.ndim:
            raise ValueError("transverse_inertia and axial_inertia must be scalars [kg·m²]")
        m = as_finite("magnet_moment", self.magnet_moment)
        if m.ndim:
            raise ValueError(f"magnet_moment must be a scalar [A·m²], got shape {m.shape}")
        axes = as_vectors("rod_axes", self.rod_axes)
        if axes.ndim != 2:
            raise ValueError(f"rod_axes must have shape (k, 3), got {axes.shape}")
        norm = np.linalg.norm(axes, axis=-1)
        if np.any(norm == 0):
            raise ValueError("rod_axes must not contain a zero vector")
        volume = as_nonnegative("rod_volume", self.rod_volume, unit="m³")
        if volume.ndim:
            raise ValueError(f"rod_volume must be a scalar (per rod) [m³], got shape {volume.shape}")
        limb_constants(self.rod_coercivity, self.rod_remanence, self.rod_saturation)
        object.__setattr__(self, "rod_axes", tuple(tuple(float(x) for x in r / n) for r, n in zip(axes, norm)))
        for name, value in (("transverse_inertia", a), ("axial_inertia", c), ("magnet_moment", m),
                            ("rod_volume", volume)):
            object.__setattr__(self, name, float(value))

    @property
    def inertia(self):
        """Principal moments (A, A, C) [kg·m²]."""
        return np.array([self.transverse_inertia, self.transverse_inertia, self.axial_inertia])


def initial_passive_state(satellite, angular_momentum, nutation, momentum_direction, proper_rotation=0.0):
    r"""Attitude and body rate of an axisymmetric body with given L (vector) and nutation.

    Parameters
    ----------
    satellite : PassiveSatellite
        Its inertia [-].
    angular_momentum : float or array_like, shape (M,)
        |L| [kg·m²/s].
    nutation : float or array_like, shape (M,)
        θ, angle between L and the symmetry axis [rad].
    momentum_direction : array_like, shape (3,) or (M, 3)
        Direction of L in inertial axes (normalised here) [-].
    proper_rotation : float or array_like, shape (M,), optional
        φ, the proper-rotation angle [rad].

    Returns
    -------
    attitude : ndarray, shape (M, 4)
        Quaternion, scalar first, body → inertial [-]: body → L-frame R_z(0) R_x(θ) R_z(φ), the
        L-frame turned onto L by the smallest rotation taking ẑ to L̂.
    body_rate : ndarray, shape (M, 3)
        ω in body axes [rad/s].

    Notes
    -----
    TNS-0 preprint §2 (L141–L157): the L-frame and the Euler angles of Table 1; the precession
    angle ψ0 is set to 0 (it only turns the body about L).
    """
    big_l = as_nonnegative("angular_momentum", angular_momentum, unit="kg·m²/s")
    theta = as_in_range("nutation", nutation, 0.0, np.pi, unit="rad")
    direction = as_vectors("momentum_direction", momentum_direction)
    norm = np.linalg.norm(direction, axis=-1, keepdims=True)
    if np.any(norm == 0):
        raise ValueError("momentum_direction must not be a zero vector")
    phi = as_finite("proper_rotation", proper_rotation)
    try:
        shape = np.broadcast_shapes(big_l.shape, theta.shape, direction.shape[:-1], phi.shape)
    except ValueError:
        raise ValueError(f"angular_momentum {big_l.shape}, nutation {theta.shape}, momentum_direction "
                         f"{direction.shape} and proper_rotation {phi.shape} must agree on the members") from None
    if len(shape) > 1:
        raise ValueError(f"members must lie on one leading axis, got shape {shape}")
    members = shape[0] if shape else 1
    big_l, theta, phi = (np.broadcast_to(x, shape).reshape(members) for x in (big_l, theta, phi))
    lhat = np.broadcast_to(direction / norm, shape + (3,)).reshape(members, 3)
    body_to_l = Rotation.from_euler("ZXZ", np.stack([np.zeros(members), theta, phi], axis=-1))
    zhat = np.array([0.0, 0.0, 1.0])
    axis = np.cross(zhat, lhat)
    sin_angle = np.linalg.norm(axis, axis=-1)
    angle = np.arctan2(sin_angle, lhat[:, 2])
    unit = np.where(sin_angle[:, None] > 1e-15, axis / np.where(sin_angle > 1e-15, sin_angle, 1.0)[:, None],
                    np.array([1.0, 0.0, 0.0]))
    l_to_n = Rotation.from_rotvec(unit * angle[:, None])
    attitude = (l_to_n * body_to_l).as_quat(scalar_first=True)
    rate = body_rate_from_momentum(big_l, theta, satellite.transverse_inertia, satellite.axial_inertia, phi)
    return attitude, rate


def _rhs(time, state, fields, inertia, magnet, axes, volume, material):
    q, w, rods = state[:, :4], state[:, 4:7], state[:, 7:]
    b_n, b_rate_n, _ = fields(time)
    b = dynamics_kernels.rotate(q, b_n, -1.0)
    moment = np.zeros_like(w)
    moment[:, 2] = magnet
    rods_rate = np.zeros_like(rods)
    if volume > 0:
        b_rate = dynamics_kernels.rotate(q, b_rate_n, -1.0) - dynamics_kernels.cross(w, b)
        h = b @ axes.T / MU_0
        h_rate = b_rate @ axes.T / MU_0
        hc, bs, k = material
        rods_rate = hardware_kernels.hysteresis_slope(rods, h, np.sign(h_rate), hc, bs, k) * h_rate
        moment = moment + dynamics_kernels.rod_moment(rods, axes, volume)
    w_rate = dynamics_kernels.euler_rates(w, dynamics_kernels.cross(moment, b), inertia)
    return np.concatenate([dynamics_kernels.quaternion_rate(q, w), w_rate, rods_rate], axis=-1)


def _passive_members(satellite, orbit, angular_momentum, nutation, momentum_direction, proper_rotation):
    """Initial attitudes (M, 4) and body rates (M, 3) of :func:`simulate_passive`, the orbit
    phases, the number of members M and whether any argument has a member axis (without one
    the run's signals drop it)."""
    q0, w0 = initial_passive_state(satellite, angular_momentum, nutation, momentum_direction, proper_rotation)
    phase = np.asarray(orbit.argument_of_latitude0)
    if phase.ndim > 1 or (phase.ndim == 1 and q0.shape[0] not in (1, phase.size)):
        raise ValueError(f"orbit.argument_of_latitude0 {phase.shape} must agree with the {q0.shape[0]} members")
    members = max(q0.shape[0], phase.size if phase.ndim else 1)
    has_members = members > 1 or any(np.ndim(x) >= 1 for x in (angular_momentum, nutation, proper_rotation)) \
        or np.ndim(momentum_direction) == 2 or phase.ndim == 1
    return q0, w0, phase, members, has_members


def _recorder(records, inertia, orbit, members):
    """The function ``record(j, t, x)`` that writes sample j of states x (M, 7 + rods) at time
    t into ``records[j]``: |L|, nutation, axis–B angle, L–B angle and |ω| (the numpy loop's;
    the compiled kernel records the same quantities itself)."""

    def record(j, t, x):
        q, w = x[:, :4], x[:, 4:7]
        momentum = inertia * w
        big_l = np.linalg.norm(momentum, axis=-1)
        b = dynamics_kernels.rotate(q, np.broadcast_to(orbit.field(t), (members, 3)), -1.0)
        b_norm = np.linalg.norm(b, axis=-1)
        safe = np.where(big_l > 0, big_l, 1.0)
        records[j] = [big_l, np.arccos(np.clip(momentum[:, 2] / safe, -1.0, 1.0)),
                      np.arccos(np.clip(b[:, 2] / b_norm, -1.0, 1.0)),
                      np.arccos(np.clip(np.sum(momentum * b, axis=-1) / (safe * b_norm), -1.0, 1.0)),
                      np.linalg.norm(w, axis=-1)]

    return record


def simulate_passive(satellite, orbit, angular_momentum, nutation, momentum_direction, duration, *,
                     proper_rotation=0.0, sample_interval=60.0, max_rate_step=0.04, engine="compiled"):
    r"""Simulate the passive magnetic satellite (magnet + hysteresis rods) from a Table 1 state.

    Parameters
    ----------
    satellite : PassiveSatellite
        Inertia, magnet and rods [-].
    orbit : CircularOrbit
        Orbit and field (TNS-0: a direct dipole, 51.6°); an array ``argument_of_latitude0``
        (M,) gives each member its orbit phase [-].
    angular_momentum : float or array_like, shape (M,)
        Initial |L| (Table 1 column 1) [kg·m²/s].
    nutation : float or array_like, shape (M,)
        Initial nutation θ (Table 1 column 2) [rad].
    momentum_direction : array_like, shape (3,) or (M, 3)
        Initial direction of L in inertial axes (unknown for TNS-0: a Monte Carlo draw) [-].
    duration : float
        Simulated time; the run ends at the first sample time ≥ duration [s].
    proper_rotation : float or array_like, shape (M,), optional
        Initial proper-rotation angle φ [rad].
    sample_interval : float, optional
        Interval between samples; each member's step is re-chosen in each interval from its
        own rates [s].
    max_rate_step : float, optional
        Largest h·max(|ω|, |Ω_p|, 2n) of an RK4 step, Ω_p = (C − A)ω3/A the body precession
        rate, n the mean motion [rad].
    engine : {"compiled", "numpy"}, optional
        ``"compiled"``: the numba kernel of :mod:`magbench.sim._passive_kernel` (the same
        RK4 step, compiled; ~10³ times faster per step at one member); ``"numpy"``: the
        vectorised reference. Both take the same steps and agree to rounding (tested to 1e-10
        on short spans) [-].

    Returns
    -------
    PassiveRun
        ``time`` (n,), ``angular_momentum``, ``nutation``, ``axis_field_angle``,
        ``momentum_field_angle``, ``rate`` of shape (M, n) — or (n,) when no argument has
        members — and the final state.

    Notes
    -----
    TNS-0 preprint §3 (L392–L455; its equations (6)–(8) were lost in extraction): magnet torque
    m ẑ × B and rod torque Σ V B_k/μ0 r̂_k × B in body axes (Kovalenko (1975) §12.1 for the
    rods' damping), Euler's equations (SamSat-218D §"Equations of motion"), quaternion
    kinematics, one Flatley–Henretty state per rod driven by Ḣ = (RᵀḂ_N − ω × B)·r̂/μ0.
    Gravity gradient and aerodynamics are left out (the preprint's model has neither).
    Pitfall (shared reference §7): RK4 at h·ω = 0.15 removes |L| faster than the rods do;
    ``max_rate_step`` = 0.04 keeps the numerical loss below 1e-4 per day.

    Examples
    --------
    >>> sat = PassiveSatellite(0.0406, 0.00625, 0.35)
    >>> orbit = CircularOrbit(6721e3, np.radians(51.6), 7.766e22)
    >>> run = simulate_passive(sat, orbit, 1e-3, np.pi / 2, [1.0, 0.0, 0.0], 120.0)
    >>> run.time.tolist(), run.angular_momentum.shape
    ([0.0, 60.0, 120.0], (3,))
    """
    if not isinstance(satellite, PassiveSatellite):
        raise ValueError(f"satellite must be a magbench.sim.PassiveSatellite, got {type(satellite).__name__}")
    if not isinstance(orbit, CircularOrbit):
        raise ValueError(f"orbit must be a magbench.earth.CircularOrbit, got {type(orbit).__name__}")
    span = as_positive_scalar("duration", duration, unit="s")
    interval = as_positive_scalar("sample_interval", sample_interval, unit="s")
    limit = as_positive_scalar("max_rate_step", max_rate_step, unit="rad")
    if engine not in ("compiled", "numpy"):
        raise ValueError(f"engine must be 'compiled' or 'numpy', got {engine!r}")
    q0, w0, phase, members, has_members = _passive_members(satellite, orbit, angular_momentum, nutation,
                                                           momentum_direction, proper_rotation)
    axes = np.array(satellite.rod_axes)
    state = np.concatenate([np.broadcast_to(q0, (members, 4)), np.broadcast_to(w0, (members, 3)),
                            np.zeros((members, axes.shape[0]))], axis=-1)
    hc, _, bs, k = limb_constants(satellite.rod_coercivity, satellite.rod_remanence, satellite.rod_saturation)
    inertia = satellite.inertia
    a, c = satellite.transverse_inertia, satellite.axial_inertia
    n_samples = int(np.ceil(span / interval - 1e-9))
    times = interval * np.arange(n_samples + 1)
    records = np.empty((n_samples + 1, 5, members))
    phases = np.broadcast_to(phase, (members,))
    # Member by member: each member's step follows its own rates, so a member's run does not
    # depend on the members beside it (a dispersion study splits members across workers).
    steps = np.zeros(members, dtype=int)
    finals = []
    for m in range(members):
        own = replace(orbit, argument_of_latitude0=float(phases[m]))
        part = np.empty((n_samples + 1, 5, 1))
        if engine == "compiled":
            steps[m], final = _run_compiled(satellite, own, state[m:m + 1], phases[m:m + 1], axes, (hc, bs, k),
                                            interval, n_samples, limit, part)
        else:
            args = (_Field(own), inertia, satellite.magnet_moment, axes, satellite.rod_volume, (hc, bs, k))
            steps[m], final = _run_numpy(state[m:m + 1], times, _recorder(part, inertia, own, 1), args, interval,
                                         limit, own, a, c)
        records[:, :, m] = part[:, :, 0]
        finals.append(final)
    state = np.concatenate(finals)
    squeeze = (lambda x: x) if has_members else (lambda x: x[0])
    # Contiguous copies, not strided views: a run loaded from the result cache is contiguous,
    # and numpy sums the two layouts in different orders (a mean then differs in its last digit).
    signals = [squeeze(np.ascontiguousarray(records[:, i, :].T)) for i in range(5)]
    inputs = {"angular_momentum": angular_momentum, "nutation": nutation, "momentum_direction": momentum_direction,
              "duration": span, "proper_rotation": proper_rotation, "sample_interval": interval,
              "max_rate_step": limit, "engine": engine, "steps": squeeze(steps), "initial_attitude": q0, "initial_body_rate": w0}
    return PassiveRun(times, *signals, attitude=squeeze(state[:, :4]), body_rate=squeeze(state[:, 4:7]),
                      rod_induction=squeeze(state[:, 7:]), inputs=inputs)


def _run_compiled(satellite, orbit, state, phase, axes, rod_constants, interval, n_samples, limit, records):
    """The numba loop (:func:`magbench.sim._passive_kernel.run_passive`, ``engine="compiled"``)
    over the members of ``state`` (:func:`simulate_passive` gives it one at a time); it fills
    ``records`` and returns the steps taken and the final states (M, 7 + rods)."""
    from ..earth.kernels import orbit_geometry
    from ._passive_kernel import run_passive

    hc, bs, k = rod_constants
    members = state.shape[0]
    columns = np.ascontiguousarray(state.T, dtype=float)    # the kernel's layout (7 + k, M)
    # a writable copy whether or not the phase has members: one compiled signature
    u0 = np.array(np.broadcast_to(phase, (members,)), dtype=float)
    # the axes as a tuple: the kernel's right-hand side takes them by value
    rods = (tuple(tuple(float(v) for v in a) for a in axes), float(satellite.rod_volume), float(hc), float(bs),
            float(k))
    steps = run_passive(columns, u0, orbit_geometry(orbit), satellite.inertia, float(satellite.magnet_moment), rods,
                        float(interval), n_samples, float(limit), records)
    return steps, np.ascontiguousarray(columns.T)


def _run_numpy(state, times, record, args, interval, limit, orbit, a, c):
    """The vectorised reference loop (``engine="numpy"``) over the members of ``state``
    (:func:`simulate_passive` gives it one at a time); returns the steps and the final states."""
    steps = 0
    record(0, 0.0, state)
    for j in range(times.size - 1):
        w = state[:, 4:7]
        fastest = max(np.max(np.linalg.norm(w, axis=-1)), np.max(np.abs((c - a) * w[:, 2] / a)),
                      2.0 * orbit.mean_motion)
        n = max(1, int(np.ceil(interval * fastest / limit)))
        h = interval / n
        t = times[j]
        for s in range(n):
            state = rk4_step(_rhs, t + s * h, state, h, args)
            state[:, :4] /= np.linalg.norm(state[:, :4], axis=-1, keepdims=True)
        steps += n
        record(j + 1, times[j + 1], state)
    return steps, state
