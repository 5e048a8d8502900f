r"""The planar (pitch) motion of a magnet-stabilised body on a circular magnetopolar orbit,
integrated over Monte Carlo members: Kovalenko's §6.4 model (eqs. (6.28), (6.38)–(6.44))
composed from :func:`magbench.earth.polar_field_direction_angle` and its derivatives and
:func:`magbench.dynamics.kernels.planar_rates`, stepped by :func:`magbench.integrate.rk4_step`.
"""

import numpy as np

from .._validate import as_choice, as_count, as_finite, as_positive_scalar, check_member_steps
from ..dynamics.kernels import planar_rates
from ..dynamics.planar import PlanarBody, PlanarDamper
from ..earth.polar_orbit import polar_field_b, polar_field_direction_acceleration, polar_field_direction_angle
from ..integrate import rk4_step
from .result import SimulationResult
from .rotor_variants import maxima_per_orbit

__all__ = ["simulate_planar", "planar_error_orbit_maxima"]

_FIELDS = ("polar", "direction", "constant")


def _field(time, mean_motion, equatorial_b, phase, field):
    """η [rad], η̈ [rad/s²] and |B| [T] at ``time``, from the Earth family's functions."""
    if field == "constant":
        return 0.0, 0.0, equatorial_b
    u = phase + mean_motion * np.asarray(time)
    b = polar_field_b(u, equatorial_b) if field == "polar" else equatorial_b
    return polar_field_direction_angle(u), polar_field_direction_acceleration(u, mean_motion), b


def _rhs(time, state, mean_motion, equatorial_b, phase, field, body, damper):
    eta, eta_acc, b = _field(time, mean_motion, equatorial_b, phase, field)
    return planar_rates(state, eta, eta_acc, b, mean_motion, body, damper)


def simulate_planar(body, damper, mean_motion, equatorial_b, initial_angle, initial_rate, duration, step,
                    field="polar", argument_of_latitude0=0.0):
    r"""Integrate the planar pitch equation of a magnet-held body on a magnetopolar orbit.

    Parameters
    ----------
    body : magbench.dynamics.PlanarBody
        J [kg·m²], L [A·m²], ΔJ [kg·m²] (scalars or one per member, shape (M,)).
    damper : magbench.dynamics.PlanarDamper
        k_д [N·m·s], M_T [N·m], ε [rad/s], c [N·m/rad], L_y [A·m²].
    mean_motion : float
        ω0 > 0 [rad/s].
    equatorial_b : float
        B0 > 0, the field over the magnetic equator at the orbit's radius [T].
    initial_angle : float or array_like, shape (M,)
        γ(0), the body's angle from B; the damper's magnet starts along B (γ1(0) = 0) [rad].
    initial_rate : float or array_like, shape (M,)
        γ̇(0) [rad/s].
    duration : float
        Length of the run [s].
    step : float
        RK4 step [s]; the run takes ceil(duration/step) steps and records every one.
    field : {"polar", "direction", "constant"}, optional
        "polar": η(u) and B = B0 √(1 + 3 sin²u) along the orbit; "direction": η(u) with
        |B| = B0 (the linearised model's constant ω_c); "constant": a fixed field B0 (η = 0,
        no field rotation) [-].
    argument_of_latitude0 : float, optional
        u at time 0 [rad].

    Returns
    -------
    SimulationResult
        States ``gamma`` [rad], ``rate`` [rad/s] and ``damper_angle`` γ1 [rad], each of shape
        (K, M); outputs ``field_angle`` η [rad] and ``field_b`` |B| [T] of shape (K, M).

    Notes
    -----
    Kovalenko (1975) eqs. (6.28), (6.38)–(6.44) (seed lines 135–138) on a circular orbit
    (the book's figs. 6.7 and 6.10 are runs of this model); the right-hand side is
    :func:`magbench.dynamics.planar_rhs`'s kernel, the integrator the library's one RK4.

    Examples
    --------
    >>> run = simulate_planar(PlanarBody(650.0, 500.0), PlanarDamper(viscous=0.2), 1e-3, 2e-5,
    ...                       [0.0, 0.1], 0.0, 600.0, 10.0)
    >>> run.gamma.shape
    (61, 2)
    """
    if not isinstance(body, PlanarBody):
        raise ValueError(f"body must be a magbench.dynamics.PlanarBody, got {type(body).__name__}")
    if not isinstance(damper, PlanarDamper):
        raise ValueError(f"damper must be a magbench.dynamics.PlanarDamper, got {type(damper).__name__}")
    n = as_positive_scalar("mean_motion", mean_motion, unit="rad/s")
    b0 = as_positive_scalar("equatorial_b", equatorial_b, unit="T")
    total = as_positive_scalar("duration", duration, unit="s")
    h = as_positive_scalar("step", step, unit="s")
    field = as_choice("field", field, _FIELDS)
    phase = float(as_finite("argument_of_latitude0", argument_of_latitude0))
    gamma0, rate0 = np.broadcast_arrays(np.atleast_1d(as_finite("initial_angle", initial_angle)),
                                        np.atleast_1d(as_finite("initial_rate", initial_rate)))
    if gamma0.ndim != 1:
        raise ValueError(f"initial_angle and initial_rate must be scalars or shape (M,), got shape {gamma0.shape}")
    steps = int(np.ceil(total / h - 1e-9))
    check_member_steps(gamma0.size, steps)
    members = np.broadcast_shapes(gamma0.shape, *(np.shape(v) for v in body.as_tuple() + damper.as_tuple()))
    state = np.zeros(members + (3,))
    state[..., 0], state[..., 1] = gamma0, rate0
    args = (n, b0, phase, field, body.as_tuple(), damper.as_tuple())
    time = np.arange(steps + 1) * h
    record = np.empty((steps + 1,) + state.shape)
    record[0] = state
    for i in range(steps):
        state = rk4_step(_rhs, time[i], state, h, args)
        record[i + 1] = state
    eta, _, b = _field(time, n, b0, phase, field)
    shape = (steps + 1,) + members
    outputs = np.stack([np.broadcast_to(np.reshape(eta, (-1, 1)) if np.ndim(eta) else eta, shape),
                        np.broadcast_to(np.reshape(b, (-1, 1)) if np.ndim(b) else b, shape)])
    return SimulationResult(time, np.moveaxis(record, -1, 0), np.empty((0, steps + 1)), outputs,
                            ("gamma", "rate", "damper_angle"), (), ("field_angle", "field_b"),
                            params={"body": body, "damper": damper, "mean_motion": n, "equatorial_b": b0,
                                    "field": field, "argument_of_latitude0": phase, "step": h})


def planar_error_orbit_maxima(run, mean_motion, last=None):
    r"""Largest |γ| of a planar run in each whole orbit (orbit k: k T ≤ t < (k + 1) T), per member.

    Parameters
    ----------
    run : SimulationResult
        A run of :func:`simulate_planar` (states ``gamma`` of shape (K, M)) [rad].
    mean_motion : float
        ω0 > 0, the orbit's mean motion; T = 2π/ω0 [rad/s].
    last : int, optional
        Keep only the last ``last`` whole orbits (≥ 1, at most the run's whole orbits); by
        default every whole orbit of the run [-].

    Returns
    -------
    ndarray, shape (orbits, M)
        max |γ| over each orbit, oldest first [rad]. A run of a whole number of orbits ends
        with a sample at t = N T, which opens orbit N and is left out.

    Notes
    -----
    Kovalenko (1975) §6.5 reads the steady stabilisation error γ_max of a run over an orbit
    (E47 fig. 6.7, seed line 147; E48 fig. 6.10, seed line 150: "the process settles by the
    end of the orbit, where γ_max ≈ 5.5–7.5°"). Orbits are cut by
    :func:`magbench.sim.maxima_per_orbit`'s rule.

    Examples
    --------
    >>> from magbench.dynamics import PlanarBody, PlanarDamper
    >>> run = simulate_planar(PlanarBody(650.0, 500.0), PlanarDamper(viscous=0.2), 1e-3, 2e-5,
    ...                       [0.0, 0.1], 0.0, 4 * np.pi / 1e-3, 10.0)
    >>> planar_error_orbit_maxima(run, 1e-3).shape
    (2, 2)
    """
    if not isinstance(run, SimulationResult) or "gamma" not in run.state_labels:
        raise ValueError(f"run must be a SimulationResult of simulate_planar (with state 'gamma'), "
                         f"got {type(run).__name__}")
    n = as_positive_scalar("mean_motion", mean_motion, unit="rad/s")
    gamma = np.abs(np.asarray(run.gamma))
    orbits_in_run = int(np.floor(run.time[-1] * n / (2.0 * np.pi) * (1.0 + 1e-12)))
    if orbits_in_run < 1:
        raise ValueError(f"run must span at least one whole orbit of 2π/mean_motion = {2 * np.pi / n:.6g} s, "
                         f"got {run.time[-1]:.6g} s")
    time_orbits = run.time * n / (2.0 * np.pi)
    maxima = np.stack([maxima_per_orbit(time_orbits, gamma[:, i], orbits_in_run) for i in range(gamma.shape[1])],
                      axis=-1)
    if last is None:
        return maxima
    keep = as_count("last", last)
    if keep > orbits_in_run:
        raise ValueError(f"last must be between 1 and the run's {orbits_in_run} whole orbits, got {keep}")
    return maxima[-keep:]
