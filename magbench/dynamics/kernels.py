r"""Compiled (numba) twins of the dynamics family's array kernels, for the solvers that call a
right-hand side once per stage from Python (:func:`scipy.integrate.solve_ivp`): there a
numpy kernel on one state spends its time in per-call overhead, a compiled one in arithmetic.

Each twin repeats its numpy kernel's operations in the same order, without fast-math, and the
tests hold the two equal to the last bit. ``cache=True`` keeps the compiled code in
``__pycache__``.
"""

import numpy as np
from numba import njit

__all__ = ["gyrostat_turning_field_rhs"]


@njit(cache=True, error_model="numpy")
def gyrostat_turning_field_rhs(time, state, principal_inertia, rotor_momentum, damping_gain, field_rate):
    """Compiled twin of :func:`magbench.dynamics.gyrostat_turning_field_rhs` for one state (9,)."""
    w1, w2, w3, b1, b2, b3, n1, n2, n3 = (state[0], state[1], state[2], state[3], state[4], state[5], state[6],
                                          state[7], state[8])
    a, b, c = principal_inertia[0], principal_inertia[1], principal_inertia[2]
    h, k = rotor_momentum, damping_gain
    bb = b1 * b1 + b2 * b2 + b3 * b3
    wb = (w1 * b1 + w2 * b2 + w3 * b3) / bb
    t1, t2, t3 = -k * (w1 - wb * b1), -k * (w2 - wb * b2), -k * (w3 - wb * b3)
    k1, k2, k3 = a * w1 + h, b * w2, c * w3
    out = np.empty(9)
    out[0], out[1], out[2] = (t1 - (w2 * k3 - w3 * k2)) / a, (t2 - (w3 * k1 - w1 * k3)) / b, (t3 - (w1 * k2 - w2 * k1)) / c
    out[3] = -(w2 * b3 - w3 * b2) + field_rate * (n2 * b3 - n3 * b2)
    out[4] = -(w3 * b1 - w1 * b3) + field_rate * (n3 * b1 - n1 * b3)
    out[5] = -(w1 * b2 - w2 * b1) + field_rate * (n1 * b2 - n2 * b1)
    out[6], out[7], out[8] = -(w2 * n3 - w3 * n2), -(w3 * n1 - w1 * n3), -(w1 * n2 - w2 * n1)
    return out


# Listed here, beside its function, so that other kernels added to this module merge cleanly.
__all__ += ["rotor_reduced_rates"]


def rotor_reduced_rates(x, t1, t2, t3, a):
    r"""The symmetric gyrostat's 5-state dimensionless model, numpy kernel; no checks.

    Parameters
    ----------
    x : ndarray, shape (5, ...)
        α, β [rad], h = H/(ω0 B), Ω2, Ω3 [-].
    t1, t2, t3 : ndarray
        Non-gravity torque in the semi-body frame divided by ω0² B, per axis [-].
    a : float or ndarray
        a = A/B [-].

    Returns
    -------
    ndarray, shape (5, ...)
        (α', β', h', Ω2', Ω3') [-] of :func:`magbench.dynamics.rotor_reduced_rhs`, its
        checked form.

    Notes
    -----
    Rotor slides, slide "Equations of motion in the semi-body frame" (seed lines 29–38)
    divided by B (``rotor_spin.md`` §4). A numpy kernel beside the compiled twins: the
    normalised simulations call it on (5, members) arrays, which vectorise.
    """
    alpha, beta, h, w2, w3 = x
    sa, ca, sb, cb = np.sin(alpha), np.cos(alpha), np.sin(beta), np.cos(beta)
    tb = sb / cb
    return np.stack(np.broadcast_arrays(
        w2 / cb - 1.0, w3, t1,
        -h * w3 + w2 * w3 * tb + t2 - 3.0 * (a - 1.0) * sa * ca * cb,
        h * w2 - w2**2 * tb + t3 + 3.0 * (a - 1.0) * sa**2 * sb * cb))
