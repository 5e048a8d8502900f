r"""The library's two integrators: one classical RK4 step (every fixed-step simulation and
the hysteresis response take it) and one adaptive solve over :func:`scipy.integrate.solve_ivp`
that raises when the solver fails. Nothing else in the library integrates.

The base layer: physics families, simulations and chapters may import it; it imports
only numpy and scipy.
"""

__all__ = ["rk4_step", "solve_adaptive"]


def rk4_step(rhs, time, state, step, args=()):
    r"""Advance ẋ = f(t, x, \*args) by one step of the classical fourth-order Runge–Kutta method.

    Parameters
    ----------
    rhs : callable
        Right-hand side ``rhs(time, state, *args)`` returning an array shaped like
        ``state`` [state units per s], as :func:`scipy.integrate.solve_ivp` takes it.
    time : float
        Time at the start of the step [s].
    state : ndarray
        State at ``time`` [state units]; any shape the right-hand side accepts (for the
        mock-up (2, members): angle and rate of every Monte Carlo member).
    step : float
        Step h [s].
    args : tuple, optional
        Further arguments of ``rhs`` (inputs held over the step, parameters) [-].

    Returns
    -------
    ndarray
        :math:`x + \tfrac{h}{6}\,(k_1 + 2(k_2 + k_3) + k_4)` [state units], with
        :math:`k_1 = f(t, x)`, :math:`k_2 = f(t + h/2, x + h k_1/2)`,
        :math:`k_3 = f(t + h/2, x + h k_2/2)`, :math:`k_4 = f(t + h, x + h k_3)`.

    Notes
    -----
    Not in the sources: the classical Runge–Kutta method (Hairer, Nørsett and Wanner,
    *Solving Ordinary Differential Equations I*, 2nd ed., 1993, §II.1, Table 1.2). Local
    error O(h⁵). A piecewise-constant input (a controller's zero-order hold) is exact
    to this order when the steps end at the input's jumps. No argument checks: the
    simulations check their inputs once.

    Examples
    --------
    >>> import numpy as np
    >>> x = rk4_step(lambda t, x: -x, 0.0, np.array([1.0]), 0.1)
    >>> bool(abs(x[0] - np.exp(-0.1)) < 1e-7)
    True
    """
    half = 0.5 * step
    k1 = rhs(time, state, *args)
    k2 = rhs(time + half, state + half * k1, *args)
    k3 = rhs(time + half, state + half * k2, *args)
    k4 = rhs(time + step, state + step * k3, *args)
    return state + step / 6.0 * (k1 + 2.0 * (k2 + k3) + k4)


def solve_adaptive(rhs, span, initial_state, *, args=(), method="DOP853", rtol=1e-9, atol=1e-12, **options):
    r"""Integrate ẋ = f(t, x, \*args) with an adaptive method of :func:`scipy.integrate.solve_ivp`.

    Parameters
    ----------
    rhs : callable
        Right-hand side ``rhs(time, state, *args)`` [state units per s].
    span : tuple of float
        (t0, t1) [s].
    initial_state : array_like
        x(t0) [state units].
    args : tuple, optional
        Further arguments of ``rhs`` [-].
    method : str, optional
        solve_ivp's method [-]; default DOP853 (eighth order, for the long smooth runs).
    rtol, atol : float, optional
        Relative [-] and absolute [state units] tolerances.
    options : dict
        Further keywords of solve_ivp (``t_eval``, ``events``, ``max_step``, ``dense_output``) [-].

    Returns
    -------
    scipy.integrate.OdeResult
        solve_ivp's result (``t``, ``y``, ``t_events``, …), only when it succeeded.

    Raises
    ------
    RuntimeError
        When the solver stops short of t1 without an event: the message names the method,
        the time reached and the solver's reason (a silent short result would be read as a
        whole run).

    Notes
    -----
    Not in the sources: Dormand and Prince's methods as scipy implements them (Hairer,
    Nørsett and Wanner, *Solving Ordinary Differential Equations I*, 2nd ed., 1993, §II.5
    and §II.10).

    Examples
    --------
    >>> import numpy as np
    >>> sol = solve_adaptive(lambda t, x: -x, (0.0, 1.0), [1.0], rtol=1e-10, atol=1e-12)
    >>> bool(abs(sol.y[0, -1] - np.exp(-1.0)) < 1e-9)
    True
    """
    from scipy.integrate import solve_ivp

    sol = solve_ivp(rhs, span, initial_state, method=method, args=args if args else None, rtol=rtol, atol=atol,
                    **options)
    if not sol.success:
        reached = float(sol.t[-1]) if sol.t.size else float(span[0])
        raise RuntimeError(f"{method} integration stopped at t = {reached:g} of ({span[0]:g}, {span[1]:g}): "
                           f"{sol.message}")
    return sol
