r"""The spinning spacecraft with a coaxial rotor, normalised: the slides' closed-loop
dimensionless model, its runs and its finite-difference monodromy.

Rotor slides (seed lines 11–102) with ``shared/reference/rotor_spin.md`` §4–§8: time in
orbits τ = ω0 t, the field in units of B0, the gains as the slides' dimensionless numbers.
Composes the reduced gyrostat (:func:`magbench.dynamics.kernels.rotor_reduced_rates`), the
program field and the projected damping of :mod:`magbench.control.kernels` and the one
fixed-step :func:`magbench.integrate.rk4_step`. The monodromy checks the linearisation of
:mod:`magbench.control.rotor_stability`. The loop runs compiled
(:mod:`magbench.sim._normalised_rotor_kernel`) with this module's numpy loop as its
reference, equal to the last bit.
"""

import math

import numpy as np

from .._docstrings import fill_docstring
from .._validate import as_finite, as_in_range, as_positive_scalar
from ..control.floquet import finite_difference_monodromy
from ..control.kernels import projected_dipole
from ..control.rotor_stability import ROTOR_MODEL_PARAMETERS, rotor_model_numbers
from ..dynamics.kernels import rotor_reduced_rates
from ..earth.dipole import dipole_equatorial_b
from ..earth.kernels import orbital_dipole_b as orbital_dipole_b_kernel
from ..earth.orbit import orbital_dipole_b
from ..integrate import rk4_step
from .result import SimulationResult

__all__ = ["rotor_normalised_rhs", "rotor_finite_difference_monodromy", "simulate_rotor_normalised"]

_document_model = fill_docstring(ROTOR_MODEL_PARAMETERS)


def _closed_loop(tau, x, a, c1, kappa, kappa_w, i, real=None):
    alpha, beta, h, w2, w3 = x
    # the law's program field (units of B0): the direct dipole, tilt 0
    bo = orbital_dipole_b_kernel(np.asarray(tau, dtype=float), i, 0.0, 0.0, 1.0)
    # the real field (units of B0): the program field, or a tilted dipole (tilt, node phase)
    br = bo if real is None else (orbital_dipole_b(tau, i, 1.0, 1.0, tilt=real[0], node_phase=real[1])
                                  / dipole_equatorial_b(1.0, 1.0))
    ca, sa, cb, sb = np.cos(alpha), np.sin(alpha), np.cos(beta), np.sin(beta)
    # b = R3(β) R2(α) b_real
    x1 = ca * br[..., 0] - sa * br[..., 2]
    b = np.stack(np.broadcast_arrays(cb * x1 + sb * br[..., 1], -sb * x1 + cb * br[..., 1],
                                     sa * br[..., 0] + ca * br[..., 2]), axis=-1)
    w = np.stack(np.broadcast_arrays((h - c1 * np.cos(tau) ** 2) / a - sb, w2 - cb, w3), axis=-1)
    m = np.asarray(kappa)[..., None] * bo + projected_dipole(b, w, kappa_w)
    m = m + np.stack(np.broadcast_arrays(0.0, c1 * np.cos(tau) / math.sin(i), 0.0), axis=-1)
    t = np.cross(m, b)
    return rotor_reduced_rates(x, t[..., 0], t[..., 1], t[..., 2], a)


@_document_model
def rotor_normalised_rhs(tau, state, axial_ratio, momentum, restoring, damping, inclination):
    r"""Closed-loop dimensionless model of the symmetric rotor spacecraft.

    Parameters
    ----------
    tau : float
        τ = ω0 t = u, the argument of latitude [-].
    state : array_like, shape (5, ...)
        α, β [rad], h = H/(ω0 B), Ω2, Ω3 [-].
    {axial_ratio, momentum}
    restoring : float or array_like
        κ = k B0²/(ω0² B) [-]; broadcasts against the trailing axes of ``state``.
    damping : float or array_like
        κ_w = k_w/(ω0 B) ≥ 0 [-]; broadcasts likewise.
    {inclination}

    Returns
    -------
    ndarray, shape (5, ...)
        d/dτ of the state [-], with m̃ = κ b_o + (0, c1 cos τ/sin i, 0) + κ_w (w × b)/|b|²,
        b = R3(β)R2(α) b_o, w = ((h − c1 cos²τ)/a − sin β, Ω2 − cos β, Ω3) and the torque
        m̃ × b in :func:`magbench.dynamics.rotor_reduced_rhs`. The reference
        (0, 0, c1 cos²τ, 1, 0) is an exact solution.

    Notes
    -----
    Rotor slides, slides "Equations of motion" to "Control implementation" (seed lines
    29–87): the equilibrium law (seed lines 63–69) with
    :func:`magbench.control.rotor_equilibrium_dipole` at B0 = ω0 = 1 and the damping of
    :func:`magbench.control.projected_damping_dipole` (``rotor_spin.md`` §4).
    """
    x = as_finite("state", state)
    if x.shape[:1] != (5,):
        raise ValueError(f"state must have shape (5, ...) (α, β, h, Ω2, Ω3), got shape {x.shape}")
    a, c1, i = rotor_model_numbers(axial_ratio, momentum, inclination)
    kappa = as_finite("restoring", restoring)
    kappa_w = as_in_range("damping", damping, 0.0, math.inf)
    return _closed_loop(float(as_finite("tau", tau)), x, a, c1, kappa, kappa_w, i)


#: The normalised loop: "compiled" (:mod:`magbench.sim._normalised_rotor_kernel`) or
#: "numpy" (the reference, the same operations; the tests switch it to compare the two).
_NORMALISED_ENGINE = "compiled"


def _normalised_flow(a, c1, kappa, kappa_w, i, steps, orbits=1, record=False, real=None):
    h = 2.0 * math.pi / steps

    def flow(x):
        out = [x] if record else None
        for n in range(steps * orbits):
            x = rk4_step(_closed_loop, n * h, x, h, args=(a, c1, kappa, kappa_w, i, real))
            if record:
                out.append(x)
        return np.stack(out, axis=1) if record else x

    def compiled_flow(x):
        from ._normalised_rotor_kernel import normalised_flow

        x = np.asarray(x, dtype=float)
        shape = np.broadcast_shapes(x.shape[1:], np.shape(kappa), np.shape(kappa_w))
        members = int(np.prod(shape))
        state = np.array(np.broadcast_to(x, (5,) + shape), dtype=float, order="C").reshape(5, members)   # a writable C copy
        gains = [np.array(np.broadcast_to(g, shape), dtype=float).reshape(members) for g in (kappa, kappa_w)]
        n = steps * orbits
        out = np.empty((5, n + 1, members) if record else (0, 0, 0))
        if real is None:
            field = np.zeros(7)
        else:
            # the twin's inputs, with numpy's sines and cosines as orbital_dipole_b takes them
            tilt, lam = real
            field = np.array([np.sin(i), np.cos(i), np.sin(tilt), np.cos(tilt), np.cos(lam), np.sin(lam),
                              dipole_equatorial_b(1.0, 1.0)], dtype=float)
        normalised_flow(state, n, h, float(a), float(c1), gains[0], gains[1], float(i), real is not None, field,
                        record, out)
        if record:
            return out.reshape((5, n + 1) + shape)
        return state.reshape((5,) + shape)

    return compiled_flow if _NORMALISED_ENGINE == "compiled" else flow


@_document_model
def rotor_finite_difference_monodromy(axial_ratio, momentum, restoring, damping, inclination, *, steps=2000,
                                      perturbation=1e-6):
    r"""Monodromy of the nonlinear closed loop by central differences about the reference.

    Parameters
    ----------
    {axial_ratio, momentum}
    restoring : float
        κ [-].
    damping : float
        κ_w ≥ 0 [-].
    {inclination}
    steps : int, optional
        RK4 steps of the nonlinear model per orbit [-].
    perturbation : float, optional
        δ of each state component [-].

    Returns
    -------
    ndarray, shape (5, 5)
        Φ(2π) [-], independent of :func:`magbench.control.rotor_linearised_matrices`.

    Notes
    -----
    Rotor slides, slide "Ensuring stability" (seed line 80): a check of the linearisation
    with :func:`magbench.control.finite_difference_monodromy` on
    :func:`rotor_normalised_rhs` started at (0, 0, c1, 1, 0), τ = 0.
    """
    a, c1, i = rotor_model_numbers(axial_ratio, momentum, inclination)
    kappa = float(as_finite("restoring", restoring))
    kappa_w = float(as_in_range("damping", damping, 0.0, math.inf))
    n = int(as_positive_scalar("steps", steps))
    flow = _normalised_flow(a, c1, kappa, kappa_w, i, n)
    return finite_difference_monodromy(lambda xs: flow(xs.T).T, np.array([0.0, 0.0, c1, 1.0, 0.0]),
                                       perturbation)


@_document_model
def simulate_rotor_normalised(axial_ratio, momentum, restoring, damping, inclination, initial_state, orbits, *,
                              steps_per_orbit=1000, real_dipole_tilt=0.0, real_node_phase=0.0):
    r"""Simulate the dimensionless closed loop for many members at once (RK4).

    Parameters
    ----------
    {axial_ratio, momentum}
    restoring : float or array_like
        κ [-]; per member if an array (M,).
    damping : float or array_like
        κ_w ≥ 0 [-]; per member if an array (M,).
    {inclination}
    initial_state : array_like, shape (5,) or (5, M)
        (α, β, h, Ω2, Ω3) at τ = 0 [rad, -].
    orbits : int
        Number of orbits [-].
    steps_per_orbit : int, optional
        RK4 steps per orbit, also the samples [-].
    real_dipole_tilt : float, optional
        δ of the real dipole, in [0, π] [rad]; 0 (default): the real field is the program field.
        Otherwise the torque and the damping see the tilted dipole of
        :func:`magbench.earth.orbital_dipole_b` (Kovalenko (1975) eq. (2.36)) while the restoring
        term keeps the direct dipole (a program-vs-real field mismatch, ``rotor_spin.md`` §9).
    real_node_phase : float, optional
        Λ of that dipole, constant (non-rotating Earth) [rad].

    Returns
    -------
    SimulationResult
        ``time`` τ [-]; states ``alpha``, ``beta``, ``h``, ``rate_2``, ``rate_3`` of shape
        (K, M) (or (K,)).

    Notes
    -----
    Rotor slides, slides "Equations of motion" to "Control implementation" (seed lines 29–87), in the normalised form of ``rotor_spin.md`` §4, Monte
    Carlo members on the trailing axis of the state (the model's (5, ...) layout).
    """
    a, c1, i = rotor_model_numbers(axial_ratio, momentum, inclination)
    kappa = as_finite("restoring", restoring)
    kappa_w = as_in_range("damping", damping, 0.0, math.inf)
    x0 = as_finite("initial_state", initial_state)
    if x0.shape[:1] != (5,):
        raise ValueError(f"initial_state must have shape (5,) or (5, M), got shape {x0.shape}")
    n_orbits = int(as_positive_scalar("orbits", orbits))
    steps = int(as_positive_scalar("steps_per_orbit", steps_per_orbit))
    tilt = float(as_in_range("real_dipole_tilt", real_dipole_tilt, 0.0, math.pi, unit="rad"))
    real = None if tilt == 0.0 else (tilt, float(as_finite("real_node_phase", real_node_phase)))
    states = _normalised_flow(a, c1, kappa, kappa_w, i, steps, n_orbits, record=True, real=real)(x0)
    time = np.arange(steps * n_orbits + 1) * (2.0 * math.pi / steps)
    return SimulationResult(time, states, np.empty((0, time.size)), np.empty((0, time.size)),
                            ("alpha", "beta", "h", "rate_2", "rate_3"), (), (),
                            params={"axial_ratio": a, "momentum": c1, "restoring": kappa, "damping": kappa_w,
                                    "inclination": i, "real_dipole_tilt": tilt,
                                    "real_node_phase": float(real_node_phase)})
