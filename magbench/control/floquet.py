r"""Floquet analysis of periodic systems: multipliers from a monodromy matrix, the
finite-difference monodromy of a nonlinear flow, the degree of stability.

Rotor slides, slide "Ensuring stability" (seed line 80: "considering the linearised
system with periodic coefficients one can choose gains that make the required motion
asymptotically stable") and the lost slide "Stability and choice of control parameters"
(seed lines 90–92). The rotor's own linearisation, monodromy and stability map are in
:mod:`magbench.control.rotor_stability`. Pure linear algebra.
"""

import numpy as np

from .._validate import as_finite, as_positive

__all__ = ["floquet_multipliers", "finite_difference_monodromy", "degree_of_stability"]


def floquet_multipliers(monodromy):
    r"""Floquet multipliers: the eigenvalues of a monodromy matrix, largest modulus first.

    Parameters
    ----------
    monodromy : array_like, shape (..., n, n)
        Φ(T), the state-transition matrix over one period [-].

    Returns
    -------
    ndarray, complex, shape (..., n)
        ρ sorted by decreasing |ρ| [-]; the periodic solution is asymptotically stable
        when every |ρ| < 1.

    Notes
    -----
    Not in the sources: Floquet's theorem (Yakubovich & Starzhinskii, *Linear
    Differential Equations with Periodic Coefficients*, 1975, ch. II); the rotor slides use
    it on the linearised periodic system (seed line 80).

    Examples
    --------
    >>> np.abs(floquet_multipliers(np.diag([0.5, -2.0]))).tolist()
    [2.0, 0.5]
    """
    m = as_finite("monodromy", monodromy)
    if m.ndim < 2 or m.shape[-1] != m.shape[-2]:
        raise ValueError(f"monodromy must have shape (..., n, n), got shape {m.shape}")
    rho = np.linalg.eigvals(m).astype(complex)
    order = np.argsort(-np.abs(rho), axis=-1, kind="stable")
    return np.take_along_axis(rho, order, axis=-1)


def finite_difference_monodromy(flow, state, step):
    r"""Monodromy of a nonlinear periodic flow by central differences about a periodic state.

    Parameters
    ----------
    flow : callable
        ``flow(states)`` maps initial states of shape (m, n) to the states one period later,
        shape (m, n) [state units].
    state : array_like, shape (n,)
        A point of the periodic solution at the start of the period [state units].
    step : float or array_like
        Perturbation of each component, scalar or (n,) [state units], > 0.

    Returns
    -------
    ndarray, shape (n, n)
        Column j = (flow(x + δ e_j) − flow(x − δ e_j)) / 2δ [-]; error O(δ²) plus the
        flow's own error divided by δ.

    Notes
    -----
    Not in the sources: the variational definition of the monodromy (Yakubovich &
    Starzhinskii, 1975, ch. II) evaluated by differences, a check on the linearisation
    that does not use it.
    """
    x = as_finite("state", state)
    if x.ndim != 1:
        raise ValueError(f"state must have shape (n,), got shape {x.shape}")
    n = x.size
    d = np.broadcast_to(as_positive("step", step), (n,))
    offsets = np.diag(d)
    out = np.asarray(flow(np.concatenate([x + offsets, x - offsets])), dtype=float)
    if out.shape != (2 * n, n):
        raise ValueError(f"flow must map shape (m, {n}) to (m, {n}), got {out.shape}")
    return ((out[:n] - out[n:]) / (2.0 * d[:, None])).T


def degree_of_stability(multipliers, period):
    r"""Slowest decay rate of a periodic linear system.

    Parameters
    ----------
    multipliers : array_like, shape (..., n)
        Floquet multipliers [-].
    period : float
        The period T [s] (2π in normalised time τ = ω0 t [-]).

    Returns
    -------
    ndarray
        −ln max|ρ| / T [1/s] (positive when stable): errors shrink at least as
        exp(−σ t) over whole periods.

    Notes
    -----
    Not in the sources: the degree of stability of a periodic system (Yakubovich &
    Starzhinskii, 1975); the rotor slides pick gains from the stability region (seed
    lines 90–92).
    """
    rho = np.abs(np.asarray(multipliers))
    if rho.ndim == 0 or rho.shape[-1] == 0:
        raise ValueError(f"multipliers must have shape (..., n), got shape {rho.shape}")
    t = float(as_positive("period", period))
    return -np.log(np.max(rho, axis=-1)) / t
