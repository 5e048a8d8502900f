r"""Compiled (numba) twin of the rotor spacecraft's dimensionless closed loop advanced by
RK4 (:func:`magbench.sim.simulate_rotor_normalised`, the Floquet finite-difference check):
the program field, the real (optionally tilted) dipole, the slides' law and the reduced
equations of :func:`magbench.dynamics.rotor_reduced_rhs`, per member in scalar code.

Why compiled: the numpy loop spends ~450 µs a right-hand side on array overhead at a few
members, and a run is thousands of RK4 steps. Each operation here is the numpy loop's, in
the same order and without fast-math; the C library's sine and cosine, which numba calls,
equal numpy's float64 ones to the last bit (the tests hold the two loops equal to the last
bit). ``cache=True`` keeps the compiled code in ``__pycache__``.
"""

import math

import numpy as np
from numba import njit

from .._rk4_kernel import rk4_advance
from ..earth.kernels import orbital_dipole_b_scalar

__all__ = ["normalised_flow"]


@njit(cache=True, error_model="numpy")
def _rhs(tau, x, plant, gains, field):
    """d/dτ of x = (α, β, h, Ω2, Ω3): rotor_normalised._closed_loop for one member, operation
    for operation; plant = (a, c1), gains = (κ, κ_w), field = (sin i, cos i, real, real_field)."""
    x0, x1, x2, x3, x4 = x
    a, c1 = plant
    kappa, kappa_w = gains
    si, ci, real, real_field = field
    su, cu = math.sin(tau), math.cos(tau)
    # the law's program field: the Earth kernel's dipole at tilt 0 (units of B0)
    bo0, bo1, bo2 = orbital_dipole_b_scalar(cu, su, 1.0, 0.0, (si, ci, 0.0, 1.0), 1.0)
    if real:
        # orbital_dipole_b(τ, i, 1, 1, tilt, Λ) / dipole_equatorial_b(1, 1); real_field =
        # (sin i, cos i, sin δ, cos δ, cos Λ, sin Λ, b0), numpy's sines and cosines
        b0 = real_field[6]
        f0, f1, f2 = orbital_dipole_b_scalar(cu, su, real_field[4], real_field[5],
                                             (real_field[0], real_field[1], real_field[2], real_field[3]), b0)
        br0, br1, br2 = f0 / b0, f1 / b0, f2 / b0
    else:
        br0, br1, br2 = bo0, bo1, bo2
    ca, sa, cb, sb = math.cos(x0), math.sin(x0), math.cos(x1), math.sin(x1)
    y1 = ca * br0 - sa * br2
    b0_, b1_, b2_ = cb * y1 + sb * br1, -sb * y1 + cb * br1, sa * br0 + ca * br2
    w0, w1, w2 = (x2 - c1 * (cu * cu)) / a - sb, x3 - cb, x4
    bb = (b0_ * b0_ + b1_ * b1_) + b2_ * b2_
    c0, c1_, c2 = w1 * b2_ - w2 * b1_, w2 * b0_ - w0 * b2_, w0 * b1_ - w1 * b0_
    m0 = kappa * bo0 + (kappa_w * c0) / bb
    m1 = kappa * bo1 + (kappa_w * c1_) / bb
    m2 = kappa * bo2 + (kappa_w * c2) / bb
    m0, m1, m2 = m0 + 0.0, m1 + c1 * cu / si, m2 + 0.0
    t0, t1, t2 = m1 * b2_ - m2 * b1_, m2 * b0_ - m0 * b2_, m0 * b1_ - m1 * b0_
    tb = sb / cb
    return (x3 / cb - 1.0, x4, t0,
            -x2 * x4 + x3 * x4 * tb + t1 - 3.0 * (a - 1.0) * sa * ca * cb,
            x2 * x3 - (x3 * x3) * tb + t2 + 3.0 * (a - 1.0) * (sa * sa) * sb * cb)


@njit(cache=True, error_model="numpy")
def closed_loop_rates(tau, x, out, a, c1, kappa, kappa_w, si, ci, real, real_field):
    """d/dτ of the states x (5, M) of every member, each by :func:`_rhs`, into out (5, M)."""
    for m in range(x.shape[1]):
        out[0, m], out[1, m], out[2, m], out[3, m], out[4, m] = _rhs(
            tau, (x[0, m], x[1, m], x[2, m], x[3, m], x[4, m]), (a, c1), (kappa[m], kappa_w[m]),
            (si, ci, real, real_field))


@njit(cache=True, error_model="numpy")
def normalised_flow(state, steps, h, a, c1, kappa, kappa_w, inclination, real, real_field, record, out):
    """Advance state (5, M) in place by ``steps`` RK4 steps of h (the library's compiled
    step, :func:`magbench._rk4_kernel.rk4_advance`); when ``record``, out (5, steps + 1, M)
    receives every state from the first."""
    args = (a, c1, kappa, kappa_w, math.sin(inclination), math.cos(inclination), real, real_field)
    stages = np.empty((5,) + state.shape)
    if record:
        out[:, 0, :] = state
    for n in range(steps):
        rk4_advance(closed_loop_rates, n * h, state, h, args, stages)
        if record:
            out[:, n + 1, :] = state
