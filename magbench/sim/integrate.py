r"""The fixed-step integrator every simulation in :mod:`magbench.sim` shares."""

__all__ = ["rk4_step"]


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
