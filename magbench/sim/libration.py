r"""A gravity-gradient boom satellite with a magnetic libration damper (the GGSE/GEOS type):
the body librates about the local vertical (Kovalenko (1975) §4.2, eq. (4.18)) while a magnet
carried by a ball inside it, held along B by the field, dissipates the relative motion through
a viscous coupling (§5.4, eqs. (5.19)–(5.22)). Composed from the dynamics kernels and
:class:`magbench.earth.CircularOrbit`, stepped by :func:`magbench.integrate.rk4_step`.

State of one member (13 numbers): the body quaternion q (4, body → inertial), the body rate ω
(3, body axes), the ball's inertial rate ω_d written in body axes (3, as
:func:`magbench.dynamics.spherical_damper_rhs` takes it) and the ball magnet's direction e in
inertial axes (3). The ball is a sphere, so its attitude matters only through the direction of
its magnet: ė = Ω_d × e with Ω_d = C(q) ω_d its rate in inertial axes; e is renormalised where
it is used.
"""

from dataclasses import dataclass

import numpy as np
from scipy.spatial.transform import Rotation

from .._validate import (as_finite, as_inertia, as_nonnegative, as_positive, as_run_timing,
                         check_member_steps)
from ..dynamics import kernels
from ..earth import CircularOrbit
from ..integrate import rk4_step
from .result import SimulationResult

__all__ = ["LibrationSatellite", "simulate_libration"]


@dataclass(frozen=True)
class LibrationSatellite:
    r"""A gravity-gradient boom (along body z) with a magnetic ball damper.

    Parameters
    ----------
    inertia : tuple of float
        Principal moments (I_x roll, I_y pitch, I_z yaw/boom) [kg·m²].
    damper_moment : float or array_like, shape (M,)
        Dipole moment of the ball's magnet, ≥ 0 [A·m²] (0: the ball only couples viscously);
        one per member for a sweep.
    damper_inertia : float
        Moment of inertia J_d of the ball [kg·m²].
    damping : float or array_like, shape (M,)
        Viscous coupling k between ball and body, ≥ 0 [N·m·s]; one per member for a sweep.
    body_magnet : tuple of float, optional
        A magnet fixed in the body, body axes [A·m²].

    Notes
    -----
    Kovalenko (1975) §5.4, eqs. (5.19)–(5.22) (the spherical damper) and §4.2, eq. (4.18).
    """

    inertia: tuple
    damper_moment: float
    damper_inertia: float
    damping: float
    body_magnet: tuple = (0.0, 0.0, 0.0)

    def __post_init__(self):
        j = as_inertia("inertia", self.inertia)
        if j.shape != (3,):
            raise ValueError(f"inertia must be three principal moments [kg·m²], got shape {j.shape}")
        for name, unit in (("damper_moment", "A·m²"), ("damping", "N·m·s")):
            value = as_nonnegative(name, getattr(self, name), unit=unit)
            if value.ndim > 1:
                raise ValueError(f"{name} must be a scalar or one value per member, shape (M,), got shape "
                                 f"{value.shape}")
            object.__setattr__(self, name, value if value.ndim else float(value))
        if as_positive("damper_inertia", self.damper_inertia, unit="kg·m²").ndim:
            raise ValueError(f"damper_inertia must be a scalar, got {self.damper_inertia!r}")
        if as_finite("body_magnet", self.body_magnet).shape != (3,):
            raise ValueError(f"body_magnet must have shape (3,) [A·m²], got {self.body_magnet!r}")


def _rhs(time, state, orbit, sat, gravity):
    """(q̇, ω̇, ω̇_d, ė) of every member; state (M, 13)."""
    q, w, wd, e = state[:, :4], state[:, 4:7], state[:, 7:10], state[:, 10:]
    radial = kernels.rotate(q, orbit.orbital_axes(time)[..., 2, :], -1.0)
    b_inertial = orbit.field(time)
    b_body = kernels.rotate(q, b_inertial, -1.0)
    j = np.asarray(sat.inertia, dtype=float)
    torque = kernels.cross(np.asarray(sat.body_magnet, dtype=float), b_body)
    if gravity:
        torque = torque + kernels.gravity_gradient_torque(radial, j, orbit.mean_motion)
    e_unit = e / np.linalg.norm(e, axis=-1, keepdims=True)
    magnet = np.asarray(sat.damper_moment)[..., None]
    ball_torque = kernels.rotate(q, magnet * kernels.cross(e_unit, b_inertial), -1.0)
    coupling = kernels.viscous_damper_torque(wd - w, sat.damping)
    rates = kernels.spherical_damper_rhs(state[:, 4:10], torque, ball_torque, j, sat.damper_inertia, coupling)
    e_rate = kernels.cross(kernels.rotate(q, wd, 1.0), e)
    return np.concatenate([kernels.quaternion_rate(q, w), rates, e_rate], axis=-1)


def _initial_state(orbit, pitch, roll, rate):
    """Body at pitch θ (about Y) then roll φ (about the pitched x) from the orbital frame, rate
    n Y plus ``rate``; the ball turns with the orbital frame, its magnet along B."""
    axes = np.broadcast_to(orbit.orbital_axes(0.0), pitch.shape + (3, 3))
    turn = Rotation.from_euler("YX", np.stack([pitch, roll], axis=-1))
    body = np.swapaxes(axes, -1, -2) @ turn.as_matrix()
    q = Rotation.from_matrix(body).as_quat(scalar_first=True)
    orbital_rate = np.einsum("...ji,...j->...i", body, axes[..., 1, :]) * orbit.mean_motion
    b = np.broadcast_to(orbit.field(0.0), pitch.shape + (3,))
    return np.concatenate([q, orbital_rate + rate, orbital_rate, b / np.linalg.norm(b, axis=-1, keepdims=True)],
                          axis=-1)


def simulate_libration(satellite, orbit, initial_pitch, initial_roll, duration, step, record_interval=None,
                       initial_rate=0.0, gravity_gradient=True):
    r"""Integrate a gravity-gradient boom with a magnetic ball damper on a circular orbit.

    Parameters
    ----------
    satellite : LibrationSatellite
        Inertia [kg·m²], ball magnet [A·m²], ball inertia [kg·m²], coupling [N·m·s].
    orbit : magbench.earth.CircularOrbit
        The orbit and its field; an array ``argument_of_latitude0`` (M,) gives each member
        its own phase [rad].
    initial_pitch, initial_roll : float or array_like, shape (M,)
        The boom's start from the local vertical: a turn about the orbit normal, then about
        the body x axis [rad].
    duration : float
        Length of the run [s].
    step : float
        RK4 step [s]; keep it below J_d/k and the libration period over 20.
    record_interval : float, optional
        Sampling interval of the result, a whole number of steps [s] (default: every step).
    initial_rate : float or array_like, shape (M, 3), optional
        Body rate added to the orbital frame's rate at time 0, body axes [rad/s].
    gravity_gradient : bool, optional
        False drops the gravity-gradient torque (a check of momentum conservation) [-].

    Returns
    -------
    SimulationResult
        States ``q0..q3`` [-], ``rate_x..z`` [rad/s], ``ball_rate_x..z`` [rad/s] and
        ``ball_magnet_x..z`` [-]; outputs ``pitch``, ``roll``, ``libration`` (the total angle
        of the boom from the local vertical) [rad] and ``momentum_x..z``, the body + ball
        angular momentum in inertial axes [N·m·s]; each of shape (K, M).

    Notes
    -----
    Kovalenko (1975) §4.2 eq. (4.18) (gravity gradient, through
    :func:`magbench.dynamics.gravity_gradient_torque`) and §5.4 eqs. (5.19)–(5.22) (the body
    and the free ball coupled by k(ω_d − ω), :func:`magbench.dynamics.spherical_damper_rhs`);
    the ball's magnet feels m_d e × B.

    Examples
    --------
    >>> sat = LibrationSatellite((2.0, 2.0, 0.02), 0.0, 0.01, 0.0)
    >>> run = simulate_libration(sat, CircularOrbit(7e6, 1.0, 8e22), 0.1, 0.0, 600.0, 10.0)
    >>> run.pitch.shape
    (61, 1)
    """
    if not isinstance(satellite, LibrationSatellite):
        raise ValueError(f"satellite must be a LibrationSatellite, got {type(satellite).__name__}")
    if not isinstance(orbit, CircularOrbit):
        raise ValueError(f"orbit must be a magbench.earth.CircularOrbit, got {type(orbit).__name__}")
    total, h, every = as_run_timing(duration, step, record_interval)
    phase = np.atleast_1d(np.asarray(orbit.argument_of_latitude0, dtype=float))
    pitch0 = np.atleast_1d(as_finite("initial_pitch", initial_pitch))
    roll0 = np.atleast_1d(as_finite("initial_roll", initial_roll))
    rate0 = as_finite("initial_rate", initial_rate)
    try:
        pitch, roll = np.broadcast_arrays(pitch0, roll0, phase, satellite.damper_moment, satellite.damping)[:2]
        rate = np.broadcast_to(rate0[..., None] if rate0.ndim == 0 else rate0, pitch.shape + (3,))
    except ValueError:
        raise ValueError(f"initial_pitch {pitch0.shape}, initial_roll {roll0.shape}, the orbit's phases "
                         f"{phase.shape}, the satellite's damper_moment {np.shape(satellite.damper_moment)} and "
                         f"damping {np.shape(satellite.damping)} and initial_rate {rate0.shape} (scalar, (3,) or "
                         "(M, 3)) must agree on the members M") from None
    if pitch.ndim != 1:
        raise ValueError(f"initial_pitch and initial_roll must be scalars or shape (M,), got shape {pitch.shape}")
    steps = int(np.ceil(total / h - 1e-9))
    check_member_steps(pitch.size, steps)
    state = _initial_state(orbit, pitch, roll, rate)
    samples = [state]
    for i in range(steps):
        state = rk4_step(_rhs, i * h, state, h, (orbit, satellite, bool(gravity_gradient)))
        if (i + 1) % every == 0:
            samples.append(state)
    record = np.stack(samples)
    time = np.arange(record.shape[0]) * every * h
    angles = kernels.libration_angles(record[..., :4], orbit.orbital_axes(time[:, None]))
    j = np.asarray(satellite.inertia, dtype=float)
    momentum = kernels.rotate(record[..., :4], j * record[..., 4:7] + satellite.damper_inertia * record[..., 7:10],
                              1.0)
    labels = ("q0", "q1", "q2", "q3", "rate_x", "rate_y", "rate_z", "ball_rate_x", "ball_rate_y", "ball_rate_z",
              "ball_magnet_x", "ball_magnet_y", "ball_magnet_z")
    outputs = np.concatenate([np.moveaxis(angles, -1, 0), np.moveaxis(momentum, -1, 0)])
    return SimulationResult(time, np.moveaxis(record, -1, 0), np.empty((0, time.size)), outputs, labels, (),
                            ("pitch", "roll", "libration", "momentum_x", "momentum_y", "momentum_z"),
                            params={"satellite": satellite, "orbit": orbit, "step": h,
                                    "gravity_gradient": bool(gravity_gradient)})
