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

from dataclasses import dataclass, field

import numpy as np
from scipy.spatial.transform import Rotation

from .._validate import (as_axisymmetric_inertias, as_count, as_finite, as_in_range, as_nonnegative, as_positive,
                         as_positive_scalar, as_vectors, shown)
from ..constants import MU_0
from ..dynamics import kernels as dynamics_kernels
from ..dynamics.axisymmetric import body_rate_from_momentum, conical_rotation_angle
from ..earth.circular_orbit import CircularOrbit
from ..hardware import kernels as hardware_kernels
from ..hardware.hysteresis import limb_constants, rod_cycle_energy
from .detumble import _Field
from ..integrate import rk4_step
from .result import SimulationResult

__all__ = ["PassiveSatellite", "PassiveRun", "simulate_passive", "initial_passive_state", "flat_spin_decay_rate",
           "orbit_mean_field", "passive_final_regime"]


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


@dataclass(frozen=True)
class PassiveRun:
    r"""A passive-satellite run: samples of the quantities TNS-0's tables report.

    Attributes
    ----------
    time : ndarray, shape (n,)
        Sample times [s].
    angular_momentum : ndarray, shape (members, n) or (n,)
        |L| [kg·m²/s].
    nutation : ndarray, shape like ``angular_momentum``
        Angle between L and the symmetry axis [rad].
    axis_field_angle : ndarray, shape like ``angular_momentum``
        Angle between B and the symmetry axis (Table 2's 0.85 rad) [rad].
    momentum_field_angle : ndarray, shape like ``angular_momentum``
        Angle between B and L [rad].
    rate : ndarray, shape like ``angular_momentum``
        |ω| [rad/s].
    attitude : ndarray, shape (members, 4) or (4,)
        Final quaternion, scalar first, body → inertial [-].
    body_rate : ndarray, shape (members, 3) or (3,)
        Final angular velocity in body axes [rad/s].
    rod_induction : ndarray, shape (members, k) or (k,)
        Final induction of each rod [T].
    inputs : dict
        The run's arguments, the initial state and the steps used [SI].

    Notes
    -----
    TNS-0 preprint Table 1 (L, nutation) and Table 2 (the angle between B and the symmetry
    axis); the names are the chapter-7 contract's.
    """

    time: np.ndarray
    angular_momentum: np.ndarray
    nutation: np.ndarray
    axis_field_angle: np.ndarray
    momentum_field_angle: np.ndarray
    rate: np.ndarray
    attitude: np.ndarray
    body_rate: np.ndarray
    rod_induction: np.ndarray
    inputs: dict = field(default_factory=dict)

    def to_result(self):
        """The run as a :class:`~magbench.sim.SimulationResult`: states of shape (n, members)."""
        names = ("angular_momentum", "nutation", "axis_field_angle", "momentum_field_angle", "rate")
        states = np.stack([np.asarray(getattr(self, n)).T for n in names])
        k = self.time.size
        return SimulationResult(self.time, states, np.empty((0, k)), np.empty((0, k)), names, (), (),
                                params=dict(self.inputs),
                                summary={"final_attitude": self.attitude, "final_body_rate": self.body_rate,
                                         "final_rod_induction": self.rod_induction})


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
        Interval between samples; the step is re-chosen in each interval [s].
    max_rate_step : float, optional
        Largest h·max(|ω|, |Ω_p|, 2n) of an RK4 step, Ω_p = (C − A)ω3/A the body precession
        rate, n the mean motion [rad].
    engine : {"compiled", "numpy"}, optional
        ``"compiled"``: the numba kernel of :mod:`magbench.sim._passive_kernel` (one member at
        a time, ~10³ times faster per step); ``"numpy"``: the vectorised reference. Both take
        the same steps and agree to rounding (tested to 1e-10 on short spans) [-].

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
    q0, w0 = initial_passive_state(satellite, angular_momentum, nutation, momentum_direction, proper_rotation)
    phase = np.asarray(orbit.argument_of_latitude0)
    if phase.ndim > 1 or (phase.ndim == 1 and q0.shape[0] not in (1, phase.size)):
        raise ValueError(f"orbit.argument_of_latitude0 {phase.shape} must agree with the {q0.shape[0]} members")
    members = max(q0.shape[0], phase.size if phase.ndim else 1)
    has_members = members > 1 or any(np.ndim(x) >= 1 for x in (angular_momentum, nutation, proper_rotation)) \
        or np.ndim(momentum_direction) == 2 or phase.ndim == 1
    axes = np.array(satellite.rod_axes)
    state = np.concatenate([np.broadcast_to(q0, (members, 4)), np.broadcast_to(w0, (members, 3)),
                            np.zeros((members, axes.shape[0]))], axis=-1)
    hc, _, bs, k = limb_constants(satellite.rod_coercivity, satellite.rod_remanence, satellite.rod_saturation)
    inertia = satellite.inertia
    a, c = satellite.transverse_inertia, satellite.axial_inertia
    args = (_Field(orbit), inertia, satellite.magnet_moment, axes, satellite.rod_volume, (hc, bs, k))
    n_samples = int(np.ceil(span / interval - 1e-9))
    times = interval * np.arange(n_samples + 1)
    records = np.empty((n_samples + 1, 5, members))

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

    if engine == "compiled":
        from ..earth.kernels import orbit_geometry
        from ._passive_kernel import run_passive

        state = np.ascontiguousarray(state, dtype=float)
        u0 = np.ascontiguousarray(np.broadcast_to(phase, (members,)), dtype=float)
        steps = run_passive(state, u0, orbit_geometry(orbit), inertia, float(satellite.magnet_moment),
                            np.ascontiguousarray(axes, dtype=float), float(satellite.rod_volume), float(hc),
                            float(bs), float(k), float(interval), n_samples, float(limit), records)
    else:
        steps, state = _run_numpy(state, times, records, record, args, interval, limit, orbit, inertia, a, c)
    squeeze = (lambda x: x) if has_members else (lambda x: x[0])
    # Contiguous copies, not strided views: a run loaded from the result cache is contiguous,
    # and numpy sums the two layouts in different orders (a mean then differs in its last digit).
    signals = [squeeze(np.ascontiguousarray(records[:, i, :].T)) for i in range(5)]
    inputs = {"angular_momentum": angular_momentum, "nutation": nutation, "momentum_direction": momentum_direction,
              "duration": span, "proper_rotation": proper_rotation, "sample_interval": interval,
              "max_rate_step": limit, "engine": engine, "steps": steps, "initial_attitude": q0, "initial_body_rate": w0}
    return PassiveRun(times, *signals, attitude=squeeze(state[:, :4]), body_rate=squeeze(state[:, 4:7]),
                      rod_induction=squeeze(state[:, 7:]), inputs=inputs)


def _run_numpy(state, times, records, record, args, interval, limit, orbit, inertia, a, c):
    """The vectorised reference loop: all members in each RK4 step (``engine="numpy"``)."""
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


def flat_spin_decay_rate(satellite, orbit, momentum_direction, spin_axis_angle, *, orbit_samples=12):
    r"""dL/dt of a flat spin from the rods' energy per revolution (the energy balance).

    Parameters
    ----------
    satellite : PassiveSatellite
        Rods (axes, volume, material) [-].
    orbit : CircularOrbit
        Orbit and field; a scalar ``argument_of_latitude0`` [-].
    momentum_direction : array_like, shape (3,) or (M, 3)
        Direction of L in inertial axes (normalised here) [-].
    spin_axis_angle : float or array_like, shape (M,)
        Angle β of the spin axis from body x in the body's transverse plane: the body spins
        about ŝ = (cos β, sin β, 0) [rad].
    orbit_samples : int, optional
        Points of the argument of latitude over half an orbit, ≥ 4 (the direct dipole's field
        repeats every half orbit) [-].

    Returns
    -------
    ndarray, shape () or (M,)
        dL/dt [kg·m²/s per s], ≤ 0; independent of the spin rate.

    Notes
    -----
    Not in the sources (ours; TNS-0 preprint Fig. 14 and Kovalenko (1975) §12.1, eq. (12.1)
    for the loss per cycle). With θ = π/2 (Table 1 rows 2–7) L is fixed in space (the magnet's
    spin-averaged torque m cos θ L̂ × B vanishes) and the body turns about ŝ ∥ L at Ω ≫ n, so
    rod k sees H_k = c_k (H·L̂) + (1 − c_k²)^½ |H⊥| cos Ωt, c_k = r̂_k·ŝ: one loop of
    amplitude (1 − c_k²)^½|H⊥| about the bias c_k H·L̂ per revolution, losing
    V·:func:`~magbench.hardware.rod_cycle_energy`. The body's energy L²/2A falls by that per
    revolution, so Ω dL/dt = −(Ω/2π) Σ_k V W_k: dL/dt = −⟨Σ_k V W_k⟩/2π, averaged over the
    orbit — constant, hence a straight line in L(t). The rods' effect on the field they see
    and their torque's periodic part are neglected (quasi-static: Ω ≫ 2n).

    Examples
    --------
    >>> sat = PassiveSatellite(0.0406, 0.00625, 0.35, rod_volume=2.4e-6)
    >>> orbit = CircularOrbit(6721e3, np.radians(51.6), 7.766e22)
    >>> rate = flat_spin_decay_rate(sat, orbit, [1.0, 0.0, 0.0], np.pi / 4)
    >>> bool(-1e-7 < rate < 0)
    True
    """
    if not isinstance(satellite, PassiveSatellite):
        raise ValueError(f"satellite must be a magbench.sim.PassiveSatellite, got {type(satellite).__name__}")
    if not isinstance(orbit, CircularOrbit):
        raise ValueError(f"orbit must be a magbench.earth.CircularOrbit, got {type(orbit).__name__}")
    if np.ndim(orbit.argument_of_latitude0):
        raise ValueError("orbit.argument_of_latitude0 must be a scalar here (the balance averages over the orbit)")
    direction = as_vectors("momentum_direction", momentum_direction)
    norm = np.linalg.norm(direction, axis=-1, keepdims=True)
    if np.any(norm == 0):
        raise ValueError("momentum_direction must not be a zero vector")
    beta = as_finite("spin_axis_angle", spin_axis_angle)
    samples = int(orbit_samples)
    if samples != orbit_samples or samples < 4:
        raise ValueError(f"orbit_samples must be an integer >= 4, got {shown(orbit_samples)}")
    lhat, beta = np.broadcast_arrays(direction / norm, beta[..., None])
    beta = beta[..., 0]
    if satellite.rod_volume == 0:
        return np.zeros(beta.shape)
    times = np.arange(samples) / samples * (0.5 * orbit.period)
    h = orbit.field(times) / MU_0                                       # (S, 3)
    along = np.einsum("sj,...j->...s", h, lhat)                         # (..., S)
    across = np.sqrt(np.maximum(np.sum(h * h, axis=-1) - along**2, 0.0))
    spin = np.stack([np.cos(beta), np.sin(beta), np.zeros(beta.shape)], axis=-1)
    cosines = np.einsum("kj,...j->...k", np.array(satellite.rod_axes), spin)   # (..., k)
    amplitude = np.sqrt(1.0 - np.minimum(cosines**2, 1.0))[..., None] * across[..., None, :]
    bias = cosines[..., None] * along[..., None, :]                     # (..., k, S)
    # A rod along the spin axis (zero amplitude) is not driven round a loop: no loss.
    driven = amplitude > 0
    w = rod_cycle_energy(np.where(driven, amplitude, 1.0), satellite.rod_coercivity, satellite.rod_remanence,
                         satellite.rod_saturation, bias=bias)
    loss = satellite.rod_volume * np.sum(np.where(driven, w, 0.0), axis=-2).mean(axis=-1)
    return -loss / (2.0 * np.pi)


def orbit_mean_field(orbit, *, samples=720):
    r"""|B| averaged over one orbit: the field a slow conical rotation about B sees on average.

    Parameters
    ----------
    orbit : CircularOrbit
        Orbit and field [-].
    samples : int, optional
        Equally spaced times over one period (the end point, the start again, left out), >= 1 [-].

    Returns
    -------
    float
        Mean |B| [T].

    Notes
    -----
    Not in the sources: the mean that :func:`magbench.dynamics.conical_rotation_angle` takes for
    the final regime of the TNS-0 preprint §4 (L554–L580).
    """
    if not isinstance(orbit, CircularOrbit):
        raise ValueError(f"orbit must be a magbench.earth.CircularOrbit, got {type(orbit).__name__}")
    samples = as_count("samples", samples)
    sweep = np.linspace(0.0, orbit.period, samples + 1)[:-1]
    return float(np.mean(np.linalg.norm(orbit.field(sweep), axis=-1)))


def passive_final_regime(run, satellite, orbit, *, orbits=3):
    r"""The final regime of a passive run: means over its last orbit, the trend of its last orbits,
    and the conical rotation about B that the final rate implies.

    Parameters
    ----------
    run : PassiveRun
        A run of :func:`simulate_passive` (its ``inputs`` name the sample interval) [-].
    satellite : PassiveSatellite
        The satellite of the run (magnet and inertia) [-].
    orbit : CircularOrbit
        The orbit of the run [-].
    orbits : int, optional
        Last orbits whose means of the angle between B and the axis are returned, >= 2, at most
        the run's whole orbits [-].

    Returns
    -------
    dict
        ``orbit_samples`` (samples per orbit, at least 2) [-]; per member (or scalars for one):
        ``final_angle`` (angle between B and the symmetry axis, mean over the last orbit) [rad],
        ``final_rate`` (|ω|, likewise) [rad/s], ``final_momentum`` (|L|, likewise) [kg·m²/s],
        ``orbit_means`` (the angle's means over each of the last ``orbits`` orbits, on the last
        axis) [rad], ``drift`` (slope of the least-squares line through them) [rad/s],
        ``conical_angle`` (Ω²(A − C) cos θ′ = mB at the final rate and the orbit-mean |B|; NaN
        without a solution) [rad]; and ``mean_field`` (:func:`orbit_mean_field`) [T].

    Notes
    -----
    Not in the sources: what the TNS-0 preprint's Table 2 (one orbit of flight data fitted,
    §4, L554–L580) reports, taken from a simulated run; the drift tells whether the run has
    settled (a regime still changing at the stop gives a value that depends on the stop).
    """
    if not isinstance(run, PassiveRun):
        raise ValueError(f"run must be a magbench.sim.PassiveRun, got {type(run).__name__}")
    if not isinstance(satellite, PassiveSatellite):
        raise ValueError(f"satellite must be a magbench.sim.PassiveSatellite, got {type(satellite).__name__}")
    mean_field = orbit_mean_field(orbit)
    last = max(2, int(np.ceil(orbit.period / run.inputs["sample_interval"])))
    orbits = as_count("orbits", orbits, minimum=2)
    if orbits * last > run.time.size:
        raise ValueError(f"orbits must be at most the run's whole orbits ({run.time.size // last}), got {orbits}")
    angle = run.axis_field_angle
    final_rate = run.rate[..., -last:].mean(axis=-1)
    means = angle[..., -orbits * last:].reshape(angle.shape[:-1] + (orbits, last)).mean(axis=-1)
    # the trend at the stop: a line through the orbit means, one per member
    drift = np.polyfit(np.arange(orbits) * (run.time[-1] - run.time[-1 - last]), np.moveaxis(means, -1, 0), 1)[0]
    return {"orbit_samples": last, "final_angle": angle[..., -last:].mean(axis=-1), "final_rate": final_rate,
            "final_momentum": run.angular_momentum[..., -last:].mean(axis=-1), "orbit_means": means,
            "drift": drift, "mean_field": mean_field,
            "conical_angle": conical_rotation_angle(final_rate, mean_field, satellite.magnet_moment,
                                                    satellite.transverse_inertia, satellite.axial_inertia)}
