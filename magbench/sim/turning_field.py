r"""A damped gyrostat in a field turning about a fixed inertial axis: the run behind chapter 6's
damping-sign erratum (the slides' printed sign pumps energy in, the corrected sign drains it).

Composes :func:`magbench.dynamics.gyrostat_turning_field_rhs` (its compiled twin
:func:`magbench.dynamics.kernels.gyrostat_turning_field_rhs`) and
:func:`magbench.integrate.solve_adaptive`.
"""

import numpy as np

from .._validate import as_count, as_finite, as_positive_scalar, shown
from ..dynamics.kernels import gyrostat_turning_field_rhs
from ..integrate import solve_adaptive
from .result import SimulationResult

__all__ = ["simulate_turning_field_gyrostat", "turning_field_kinetic_energy"]


def simulate_turning_field_gyrostat(inertia, rotor_momentum, damping_gain, field_rate, initial_rate, initial_field,
                                    field_axis, duration, *, samples=301):
    r"""Simulate a damped gyrostat in a field that turns about a fixed inertial axis (no attitude needed).

    Parameters
    ----------
    inertia : array_like, shape (3,) or (3, 3)
        Principal moments of body + rotor (rotor counted as rigid), axis 1 the rotor axis;
        a (3, 3) tensor must be diagonal [kg·m²].
    rotor_momentum : float
        J_f ν along body axis 1 [N·m·s].
    damping_gain : float
        k in the torque −k w⊥ [N·m·s]: k > 0 is the damping of
        :func:`magbench.control.projected_damping_dipole`, k < 0 the slides' printed sign
        read as a torque (:func:`magbench.control.slides_printed_damping_torque`).
    field_rate : float
        Ω_f, the field's turning rate in inertial space [rad/s].
    initial_rate : array_like, shape (3,)
        ω at t = 0, body axes [rad/s].
    initial_field : array_like, shape (3,)
        B at t = 0, body axes, not zero [T].
    field_axis : array_like, shape (3,)
        The unit axis the field turns about, body axes at t = 0 [-].
    duration : float
        Simulated time [s].
    samples : int, optional
        Number of equally spaced samples from 0 to ``duration``, ≥ 2 [-].

    Returns
    -------
    SimulationResult
        ``time`` [s]; states ``rate_x`` … ``rate_z`` [rad/s], ``field_x`` … ``field_z`` [T],
        ``axis_x`` … ``axis_z`` [-], body axes, one row each.

    Notes
    -----
    Rotor slides, slide "Control implementation" (seed lines 85–87): the damping and its
    printed sign on the gyrostat of :func:`magbench.dynamics.gyrostat_turning_field_rhs`
    (its compiled twin), the field turning as a circular orbit's does at Ω_f = ω0
    (``rotor_spin.md`` §9). DOP853 through :func:`magbench.integrate.solve_adaptive` in
    scipy, rtol 1e-9, atol 1e-12: the power −k |w⊥|² is then resolved to well below the
    energy's change over the run.
    """
    j = as_finite("inertia", inertia)
    if j.shape == (3, 3):
        if np.any(j != np.diag(np.diag(j))):
            raise ValueError(f"inertia must be diagonal (principal axes) [kg·m²], got {j.tolist()}")
        j = np.diag(j).copy()
    if j.shape != (3,) or np.any(j <= 0):
        raise ValueError(f"inertia must be three positive principal moments [kg·m²], got {j.tolist()}")
    h = float(as_finite("rotor_momentum", rotor_momentum))
    k = float(as_finite("damping_gain", damping_gain))
    rate = float(as_finite("field_rate", field_rate))
    vectors = []
    for name, value in (("initial_rate", initial_rate), ("initial_field", initial_field), ("field_axis", field_axis)):
        v = as_finite(name, value)
        if v.shape != (3,):
            raise ValueError(f"{name} must have shape (3,), got shape {v.shape}")
        vectors.append(v)
    if not np.any(vectors[1]):
        raise ValueError("initial_field must not be zero (the damping divides by |B|²)")
    norm = float(np.linalg.norm(vectors[2]))
    if abs(norm - 1.0) > 1e-9:
        raise ValueError(f"field_axis must be a unit vector, got |field_axis| = {shown(norm)}")
    t_end = as_positive_scalar("duration", duration, unit="s")
    n = int(as_count("samples", samples, minimum=2))

    time = np.linspace(0.0, t_end, n)
    sol = solve_adaptive(gyrostat_turning_field_rhs, (0.0, t_end), np.concatenate(vectors), t_eval=time, rtol=1e-9,
                         atol=1e-12, method="DOP853", args=(j, h, k, rate))
    labels = tuple(f"{kind}_{axis}" for kind in ("rate", "field", "axis") for axis in "xyz")
    return SimulationResult(time, sol.y, np.empty((0, n)), np.empty((0, n)), labels, (), (),
                            params={"inertia": j, "rotor_momentum": h, "damping_gain": k, "field_rate": rate,
                                    "duration": t_end, "nfev": int(sol.nfev)})


def turning_field_kinetic_energy(run):
    r"""Kinetic energy ½ωᵀJω of the body rates along a turning-field run.

    Parameters
    ----------
    run : SimulationResult
        A run of :func:`simulate_turning_field_gyrostat` (its rates and principal inertia J) [SI].

    Returns
    -------
    ndarray, shape (K,)
        ½ωᵀJω at each sample [J], J of body + rotor counted as rigid (the rotor's own spin
        relative to the body is constant and left out).

    Notes
    -----
    Rotor slides, slide "Control implementation" (seed lines 85–87): the energy whose sign of
    change tells damping from pumping (its power is −k |w⊥|², ``rotor_spin.md`` §9).
    """
    if not isinstance(run, SimulationResult) or "inertia" not in run.params or len(run.states) != 9:
        raise ValueError("run must be a result of simulate_turning_field_gyrostat")
    w = run.states[:3].T
    inertia = np.diag(run.params["inertia"])
    return 0.5 * np.einsum("ni,ij,nj->n", w, inertia, w)
