r"""Stability of the rotor spacecraft's reference motion: the linearised closed loop with
periodic coefficients, its monodromy, Floquet multipliers and the map over the gains.

Rotor slides, slide "Ensuring stability" (seed line 80: "considering the linearised system
with periodic coefficients one can choose gains that make the required motion
asymptotically stable") and the lost slide "Stability and choice of control parameters"
(seed lines 90–92), in the normalised model of ``shared/reference/rotor_spin.md`` §4 and
§7. The linearisation of the law of :mod:`magbench.control.spin` on the gyrostat of
:mod:`magbench.dynamics.gyrostat`, the monodromy by the one fixed-step
:func:`magbench.integrate.rk4_step` and the multipliers by
:func:`magbench.control.floquet_multipliers`. The nonlinear closed loop, which checks this
linearisation (its finite-difference monodromy), is a simulation:
:mod:`magbench.sim.spinning`.
"""

import math

import numpy as np

from .._docstrings import fill_docstring
from .._validate import as_finite, as_in_range, as_positive, as_positive_scalar, shown
from ..integrate import rk4_step
from .floquet import floquet_multipliers

__all__ = ["rotor_model_numbers", "rotor_linearised_matrices", "rotor_floquet_multipliers", "rotor_stability_map"]

#: The normalised model's numbers as :func:`rotor_model_numbers` checks them, described once for
#: every function that takes them (here and in :mod:`magbench.sim.rotor_normalised`).
ROTOR_MODEL_PARAMETERS = {
    "axial_ratio": """axial_ratio : float
    a = A/B > 0 [-].""",
    "momentum": """momentum : float
    c1 = H0/(ω0 B) [-].""",
    "inclination": """inclination : float
    i in [0, π] with sin i ≠ 0 [rad].""",
}
_document_model = fill_docstring(ROTOR_MODEL_PARAMETERS)


@_document_model
def rotor_model_numbers(axial_ratio, momentum, inclination):
    r"""The normalised model's numbers a, c1 and i, checked.

    Parameters
    ----------
    {axial_ratio, momentum, inclination}

    Returns
    -------
    tuple of float
        (a, c1, i) [-, -, rad].

    Raises
    ------
    ValueError
        Naming the parameter, its value and the range, when a is not positive, c1 is not
        finite or sin i = 0 (the law divides by sin i).

    Notes
    -----
    Rotor slides, slide "Choice of control" (seed lines 63–69: the law's M2 divides by
    B0 sin i), normalised as in ``rotor_spin.md`` §4. The linearisation here and the
    nonlinear normalised loop of :mod:`magbench.sim.spinning` check their numbers with it.
    """
    a = float(as_positive("axial_ratio", axial_ratio))
    c1 = float(as_finite("momentum", momentum))
    i = float(as_in_range("inclination", inclination, 0.0, math.pi, unit="rad"))
    if abs(math.sin(i)) < 1e-12:
        raise ValueError(f"inclination must have sin i != 0 (the law divides by sin i), got {shown(i)}")
    return a, c1, i


def _linearised(tau, a, c1, i):
    tau = np.asarray(tau, dtype=float)
    b1, b2, b3 = (np.sin(i) * np.cos(tau), np.cos(i) + 0.0 * tau, -2.0 * np.sin(i) * np.sin(tau))
    h = c1 * np.cos(tau) ** 2
    shape = tau.shape + (5, 5)
    a0, a1, a2 = np.zeros(shape), np.zeros(shape), np.zeros(shape)
    a0[..., 0, 3] = a0[..., 1, 4] = 1.0
    a0[..., 2, 0] = h
    a0[..., 3, 0] = -3.0 * (a - 1.0)
    a0[..., 3, 4] = -h
    a0[..., 4, 0] = -c1 * np.sin(2.0 * tau)
    a0[..., 4, 1] = -1.0 - c1 * np.cos(tau) / np.tan(i)
    a0[..., 4, 2] = 1.0
    a0[..., 4, 3] = h
    a1[..., 2, 0], a1[..., 2, 1] = b1 * b2, b1 * b3
    a1[..., 3, 0], a1[..., 3, 1] = -(b1**2 + b3**2), b2 * b3
    a1[..., 4, 0], a1[..., 4, 1] = b2 * b3, -(b1**2 + b2**2)
    b = np.stack([b1, b2, b3], axis=-1)
    p = np.eye(3) - b[..., :, None] * b[..., None, :] / np.sum(b * b, axis=-1)[..., None, None]
    d = np.zeros((3, 5))
    d[0, 1], d[0, 2], d[1, 3], d[2, 4] = -1.0, 1.0 / a, 1.0, 1.0
    a2[..., 2:, :] = -p @ d
    return a0, a1, a2


@_document_model
def rotor_linearised_matrices(tau, axial_ratio, momentum, inclination):
    r"""The linearised closed loop about the reference, split by gain: A = A0 + κ A1 + κ_w A2.

    Parameters
    ----------
    tau : float or array_like
        τ = u [-].
    {axial_ratio, momentum, inclination}

    Returns
    -------
    a0, a1, a2 : ndarray, shape (..., 5, 5)
        Jacobians [-] of :func:`magbench.sim.rotor_normalised_rhs` on the reference (0, 0, c1 cos²τ, 1, 0)
        in x = (α, β, δh, δΩ2, δΩ3); with h* = c1 cos²τ, b = b_o(τ), P = I − bbᵀ/|b|² and
        δw = (δh/a − β, δΩ2, δΩ3): the rows of ``rotor_spin.md`` §7.

    Notes
    -----
    Rotor slides, slide "Ensuring stability" (seed line 80: the linearised system with
    periodic coefficients); period 2π in τ. A test checks these against a numerical
    Jacobian of :func:`magbench.sim.rotor_normalised_rhs`.
    """
    a, c1, i = rotor_model_numbers(axial_ratio, momentum, inclination)
    return _linearised(as_finite("tau", tau), a, c1, i)


def _monodromy(a, c1, i, kappa, kappa_w, steps):
    kappa, kappa_w = np.broadcast_arrays(np.asarray(kappa, float), np.asarray(kappa_w, float))
    shape = kappa.shape
    k, kw = kappa.ravel(), kappa_w.ravel()
    h = 2.0 * math.pi / steps
    # A0, A1, A2 are the same for every gain pair: tabulate them once on the RK4 stage
    # times (half steps). Rows 0 and 1 of A are α' = δΩ2, β' = δΩ3 for every member, so
    # only rows 2-4 are multiplied out, with the members on the last axis (x[r, j, p] is
    # element (r, j) of Φ of member p) — several times faster than a batched
    # (m, 5, 5) @ (m, 5, 5) product.
    a0, a1, a2 = _linearised(np.arange(2 * steps + 1) * (0.5 * h), a, c1, i)
    # rows 2-4 of A0, A1, A2 side by side: table[n] @ (1, κ, κ_w) gives every member's rows
    table = np.ascontiguousarray(np.stack([a0[:, 2:, :], a1[:, 2:, :], a2[:, 2:, :]], axis=-1).reshape(-1, 15, 3))
    gains = np.stack([np.ones_like(k), k, kw])                # (3, m)

    def rhs(tau, x):
        c = (table[int(round(tau / (0.5 * h)))] @ gains).reshape(3, 5, -1)
        out = np.empty_like(x)
        out[0], out[1] = x[3], x[4]
        out[2:] = np.einsum("rjp,jcp->rcp", c, x)
        return out

    x = np.repeat(np.eye(5)[:, :, None], k.size, axis=2)
    for n in range(steps):
        x = rk4_step(rhs, n * h, x, h)
    return np.moveaxis(x, 2, 0).reshape(shape + (5, 5))


@_document_model
def rotor_floquet_multipliers(axial_ratio, momentum, restoring, damping, inclination, *, steps=1000):
    r"""Floquet multipliers of the linearised closed loop over one orbit.

    Parameters
    ----------
    {axial_ratio, momentum}
    restoring : float or array_like
        κ [-]; broadcasts with ``damping``.
    damping : float or array_like
        κ_w ≥ 0 [-].
    {inclination}
    steps : int, optional
        RK4 steps per orbit [-] (1000: max|ρ| to about 1e-7 relative).

    Returns
    -------
    ndarray, complex, shape (..., 5)
        ρ sorted by decreasing modulus [-]; stable when max|ρ| < 1, and max|ρ| is the
        slowest per-orbit contraction.

    Notes
    -----
    Rotor slides, slide "Ensuring stability" (seed line 80) and the lost slide "Stability
    and choice of control parameters" (seed lines 90–92): the monodromy Φ(2π) of
    Φ' = A(τ)Φ with :func:`rotor_linearised_matrices`, all gain pairs integrated together
    as one batched matrix equation by :func:`magbench.integrate.rk4_step`.
    """
    a, c1, i = rotor_model_numbers(axial_ratio, momentum, inclination)
    kappa = as_finite("restoring", restoring)
    kappa_w = as_in_range("damping", damping, 0.0, math.inf)
    n = int(as_positive_scalar("steps", steps))
    return floquet_multipliers(_monodromy(a, c1, i, kappa, kappa_w, n))


@_document_model
def rotor_stability_map(restoring, damping, *, axial_ratio, momentum, inclination, steps=1000):
    r"""The stability map: max|ρ| over a grid of (restoring, damping) gains.

    Parameters
    ----------
    restoring : array_like, shape (n_restoring,)
        κ values [-].
    damping : array_like, shape (n_damping,)
        κ_w values, ≥ 0 [-].
    {axial_ratio, momentum, inclination}
    steps : int, optional
        RK4 steps per orbit [-].

    Returns
    -------
    ndarray, shape (n_damping, n_restoring)
        max|ρ| [-]; < 1 is asymptotically stable.

    Notes
    -----
    Rotor slides, slide "Stability and choice of control parameters" (lost) (seed lines
    90–92), recomputed with :func:`rotor_floquet_multipliers` (``rotor_spin.md`` §7).
    """
    k = as_finite("restoring", restoring)
    kw = as_in_range("damping", damping, 0.0, math.inf)
    if k.ndim != 1 or kw.ndim != 1:
        raise ValueError(f"restoring and damping must be 1-D grids, got shapes {k.shape}, {kw.shape}")
    grid_k, grid_kw = np.meshgrid(k, kw)
    rho = rotor_floquet_multipliers(axial_ratio, momentum, grid_k, grid_kw, inclination, steps=steps)
    return np.abs(rho[..., 0])
