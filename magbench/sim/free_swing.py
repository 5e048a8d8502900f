r"""The mock-up's free swing with one coil (thesis eq. 35, Figs. 12–13) integrated: the run
from rest and its period by direct integration (a check of the closed form
:func:`magbench.dynamics.pendulum_period`). SI.
"""

import numpy as np

from .._validate import as_finite, as_positive
from ..dynamics.pendulum import Mockup, pendulum_energy, pendulum_rhs, small_angle_period
from ..integrate import solve_adaptive
from .result import SimulationResult

__all__ = ["simulate_free_swing", "integrated_swing_period"]


def _checked_plant(plant):
    if not isinstance(plant, Mockup):
        raise ValueError(f"plant must be a magbench.dynamics.Mockup, got {type(plant).__name__}")
    return plant


def simulate_free_swing(plant, initial_angle, time):
    r"""The free swing of eq. (35) released at rest (solve_ivp, RK45, rtol 1e-10).

    Parameters
    ----------
    plant : magbench.dynamics.Mockup
        Inertia J [kg·m²], field B0 [T] and coil-1 moment m [A·m²] (no thread for a
        pure pendulum).
    initial_angle : float
        ψ0 [rad], released at rest.
    time : array_like, shape (K,)
        Increasing instants from 0 [s] at which the run is returned.

    Returns
    -------
    SimulationResult
        States ``psi`` [rad] and ``rate`` [rad/s]; output ``energy``
        :math:`J\omega^2/2 - m B_0\cos\psi` [J] (constant but for the integrator's error).

    Notes
    -----
    Thesis eq. (35) and Figs. 12–13 (the free mock-up with one coil).

    Examples
    --------
    >>> run = simulate_free_swing(Mockup(0.005, 1e-4, 0.4), 0.5, np.linspace(0.0, 10.0, 11))
    >>> bool(np.ptp(run.energy) < 1e-12)
    True
    """
    plant = _checked_plant(plant)
    psi0 = float(as_finite("initial_angle", initial_angle))
    t = as_finite("time", time)
    if t.ndim != 1 or t.size < 2 or t[0] != 0.0 or np.any(np.diff(t) <= 0):
        raise ValueError(f"time must be increasing instants from 0 s, shape (K,) with K >= 2, got shape {t.shape}")
    sol = solve_adaptive(pendulum_rhs, (0.0, t[-1]), [psi0, 0.0], args=(plant,), t_eval=t,
                         method="RK45", rtol=1e-10, atol=1e-13)
    energy = pendulum_energy(sol.y[0], sol.y[1], plant.inertia, plant.moment_1, plant.field)
    return SimulationResult(t, sol.y, np.empty((0, t.size)), energy[np.newaxis], ("psi", "rate"), (), ("energy",),
                            params={"plant": plant, "initial_angle": psi0})


def integrated_swing_period(plant, amplitude):
    r"""Period of the free swing from rest at ``amplitude``, by integrating eq. (35).

    Parameters
    ----------
    plant : magbench.dynamics.Mockup
        Inertia J [kg·m²], field B0 [T] and coil-1 moment m [A·m²].
    amplitude : float
        ψ0 [rad], in (0, π).

    Returns
    -------
    float
        Twice the time to the far turning point [s] (the rate's first upward zero
        crossing; solve_ivp, RK45, rtol 1e-11, within 50 small-angle periods).

    Notes
    -----
    Thesis eq. (35); the closed form it checks, :math:`4K(\sin^2(\psi_0/2))/\omega_p`, is
    :func:`magbench.dynamics.pendulum_period` (not in the thesis, which uses the
    small-angle eq. 14).

    Examples
    --------
    >>> from magbench.dynamics import pendulum_period
    >>> p = Mockup(0.005, 1e-4, 0.4)
    >>> bool(np.isclose(integrated_swing_period(p, 1.0), pendulum_period(1.0, 0.005, 0.4, 1e-4), rtol=1e-8))
    True
    """
    plant = _checked_plant(plant)
    as_positive("field", plant.field, unit="T")
    a = float(as_finite("amplitude", amplitude))
    if not 0.0 < a < np.pi:
        raise ValueError(f"amplitude must lie in (0, π) rad (at 0 and π the mock-up never swings), got {a}")
    t0 = float(small_angle_period(plant.inertia, plant.moment_1, plant.field))

    def turn(t, y, p):
        return y[1]
    turn.direction = 1.0
    sol = solve_adaptive(pendulum_rhs, (0, 50 * t0), [a, 0.0], args=(plant,), events=turn,
                         method="RK45", rtol=1e-11, atol=1e-13)
    if not sol.t_events[0].size:
        raise ValueError(f"amplitude {a} rad: no turning point within 50 small-angle periods")
    return 2 * sol.t_events[0][0]
