r"""The library's two integrators: one classical RK4 step (every fixed-step simulation and
the hysteresis response take it) and one adaptive solve over :func:`scipy.integrate.solve_ivp`
that raises when the solver fails, with a compiled twin of its DOP853 for compiled
right-hand sides (:mod:`magbench._dop853_kernel`). Nothing else in the library integrates.

The base layer: physics families, simulations and chapters may import it; it imports
only numpy, scipy and (for the compiled twin) numba.
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


def solve_adaptive(rhs, span, initial_state, *, args=(), method="DOP853", rtol=1e-9, atol=1e-12, engine="scipy",
                   **options):
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
    engine : {"scipy", "compiled"}, optional
        ``"compiled"`` runs DOP853 in the compiled twin of solve_ivp's (same tableau, step
        control and dense output, summed in order instead of by BLAS: equal to rounding);
        ``rhs`` must then be a numba function of (time, state, \*args) returning a new
        array, and only ``t_eval``, ``max_step`` and ``first_step`` are accepted [-].
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
    ValueError
        When ``engine="compiled"`` is asked for what only scipy offers (another method,
        events, a backward span, a Python right-hand side).

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
    if engine == "compiled":
        sol = _solve_compiled(rhs, span, initial_state, args, method, rtol, atol, options)
    elif engine == "scipy":
        from scipy.integrate import solve_ivp

        sol = solve_ivp(rhs, span, initial_state, method=method, args=args if args else None, rtol=rtol, atol=atol,
                        **options)
    else:
        raise ValueError(f"engine must be 'scipy' or 'compiled', got {engine!r}")
    if not sol.success:
        reached = float(sol.t[-1]) if sol.t.size else float(span[0])
        raise RuntimeError(f"{method} integration stopped at t = {reached:g} of ({span[0]:g}, {span[1]:g}): "
                           f"{sol.message}")
    return sol


_COMPILED_OPTIONS = ("t_eval", "max_step", "first_step")


def _solve_compiled(rhs, span, initial_state, args, method, rtol, atol, options):
    """The compiled DOP853 twin, with solve_ivp's result fields (``t``, ``y``, ``nfev``, …)."""
    import numpy as np
    from scipy.integrate import DOP853
    from scipy.optimize import OptimizeResult

    if method != "DOP853":
        raise ValueError(f"engine='compiled' integrates with DOP853 only, got method={method!r}")
    unknown = sorted(set(options) - set(_COMPILED_OPTIONS))
    if unknown:
        raise ValueError(f"engine='compiled' accepts only {', '.join(_COMPILED_OPTIONS)}, got {', '.join(unknown)}")
    if not hasattr(rhs, "py_func"):
        raise ValueError(f"engine='compiled' needs a numba (njit) right-hand side, got {rhs!r}")
    t0, t1 = float(span[0]), float(span[1])
    if not t1 > t0:
        raise ValueError(f"span must run forward with engine='compiled', got ({t0:g}, {t1:g})")
    for name, value in (("rtol", rtol), ("atol", atol)):
        if not (np.ndim(value) == 0 and value > 0):
            raise ValueError(f"{name} must be one positive number with engine='compiled', got {value!r}")
    t_eval = np.asarray(options.get("t_eval", ()), dtype=float)
    if t_eval.size and (t_eval[0] < t0 or t_eval[-1] > t1 or np.any(np.diff(t_eval) <= 0)):
        raise ValueError(f"t_eval must increase strictly within span ({t0:g}, {t1:g})")
    from ._dop853_kernel import dop853

    y0 = np.array(initial_state, dtype=float)
    times, states, status, reached, nfev = dop853(
        rhs, tuple(args), t0, t1, y0, float(rtol), float(atol), float(options.get("max_step", np.inf)),
        float(options.get("first_step") or 0.0), t_eval,
        (DOP853.A, DOP853.B, DOP853.C, DOP853.E3, DOP853.E5, DOP853.D, DOP853.A_EXTRA, DOP853.C_EXTRA))
    message = ("The solver successfully reached the end of the integration interval." if status == 0 else
               f"Required step size is less than spacing between numbers (at t = {reached:g}).")
    return OptimizeResult(t=times, y=states.T, sol=None, t_events=None, y_events=None, nfev=int(nfev), njev=0,
                          nlu=0, status=int(status), message=message, success=status == 0)
