r"""Compiled (numba) right-hand side of the rotor spacecraft's SI closed loop
(:func:`magbench.sim.simulate_rotor`): the gyrostat with gravity gradient in the real field
under the slides' law, written once in scalar ``math`` code.

Why compiled: five orbits at the spin the slides imply are about a million evaluations
inside :func:`scipy.integrate.solve_ivp`'s DOP853; in Python each costs ~12 µs, compiled
well under one. The same source runs uncompiled as ``rotor_rhs.py_func`` and
``rotor_controller.py_func``, the reference the tests hold the compiled code to (equal to
the last bit: no fast-math, so the operations and their order are Python's).

The constants of one spacecraft and orbit travel as one float64 vector (:func:`rotor_constants`).
``cache=True`` keeps the compiled code in ``__pycache__`` (see :mod:`magbench.sim._passive_kernel`).
"""

import math

import numpy as np
from numba import njit

from ..earth.kernels import orbital_dipole_b_scalar
from ..dynamics.kernels import gyrostat_rates_scalar, quaternion_rate_scalar

__all__ = ["rotor_constants", "rotor_controller", "rotor_rhs"]

# Layout of the constants vector: the inertia tensor J and its inverse (row-major), then
# the scalars in this order.
_SCALARS = ("n", "u0", "sin_i", "cos_i", "b0", "sin_tilt", "cos_tilt", "h0", "hr", "axial", "transverse", "k",
            "kw", "limit", "m2_scale", "node", "lambda0", "earth_rate", "momentum_damping")


def rotor_constants(inertia_matrix, orbit, axial_momentum, rotor_momentum, transverse_inertia, restoring_gain,
                    damping_gain, moment_limit, equatorial_b, momentum_damping):
    """The float64 vector the kernels read: J, J⁻¹ and the scalars of :data:`_SCALARS` [SI]."""
    j = np.asarray(inertia_matrix, dtype=float)
    n, inc = orbit.mean_motion, orbit.inclination
    scalars = (n, float(orbit.argument_of_latitude0), math.sin(inc), math.cos(inc), equatorial_b,
               math.sin(orbit.dipole_tilt), math.cos(orbit.dipole_tilt), axial_momentum, rotor_momentum, j[0, 0],
               transverse_inertia, restoring_gain, damping_gain, moment_limit,
               axial_momentum * n / (equatorial_b * math.sin(inc)), orbit.ascending_node, orbit.dipole_longitude,
               orbit.earth_rotation_rate, 1.0 if momentum_damping else 0.0)
    return np.concatenate([j.ravel(), np.linalg.inv(j).ravel(), np.array(scalars, dtype=float)])


@njit(cache=True, error_model="numpy")
def rotor_controller(t, q0, q1, q2, q3, w1, w2, w3, c):
    """The slides' dipole, the body field, the body's e3 in orbital axes and the orbit normal
    in body axes at time ``t`` [s] and state (q, ω): 12 floats (m, B_body, R row 2, o2)."""
    j00, j01, j02, j10, j11, j12, j20, j21, j22 = c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7], c[8]
    n, u0, si, ci, b0, sd, cd = c[18], c[19], c[20], c[21], c[22], c[23], c[24]
    h0, hr, a_ax, b_tr, k, kw, lim = c[25], c[26], c[27], c[28], c[29], c[30], c[31]
    m2_scale, node, lam0, earth, momentum = c[32], c[33], c[34], c[35], c[36]
    s = 2.0 / (q0 * q0 + q1 * q1 + q2 * q2 + q3 * q3)
    # R(q) (body -> orbital); body components of an orbital vector v are Rᵀ v.
    r00, r01, r02 = 1.0 - s * (q2 * q2 + q3 * q3), s * (q1 * q2 - q0 * q3), s * (q1 * q3 + q0 * q2)
    r10, r11, r12 = s * (q1 * q2 + q0 * q3), 1.0 - s * (q1 * q1 + q3 * q3), s * (q2 * q3 - q0 * q1)
    r20, r21, r22 = s * (q1 * q3 - q0 * q2), s * (q2 * q3 + q0 * q1), 1.0 - s * (q1 * q1 + q2 * q2)
    u = u0 + n * t
    su, cu = math.sin(u), math.cos(u)
    # real field: Kovalenko (1975) eq. (2.36), Λ = Ω − λ_N(t) − π/2
    lam = node - (lam0 + earth * t) - 0.5 * math.pi
    f1, f2, f3 = orbital_dipole_b_scalar(cu, su, math.cos(lam), math.sin(lam), (si, ci, sd, cd), b0)
    bb1 = r00 * f1 + r10 * f2 + r20 * f3
    bb2 = r01 * f1 + r11 * f2 + r21 * f3
    bb3 = r02 * f1 + r12 * f2 + r22 * f3
    # semi-body triad from the orbit normal o2 = C e2 (row 1 of R)
    o1, o2, o3 = r10, r11, r12
    nrm = math.sqrt(o2 * o2 + o3 * o3)
    if nrm > 1e-12:
        s3y, s3z = -o3 / nrm, o2 / nrm        # s3 = e1 × o2 / |·|, s2 = s3 × e1 = (0, s3z, −s3y)
    else:
        # rotor axis along the orbit normal (β = ±90°): the semi-body triad is undefined and
        # the law, made for small β, has no preferred s3; any unit vector across e1 keeps the
        # run going (a tumbling spacecraft at unstable gains can pass through it)
        s3y, s3z = 0.0, 1.0
    p1, p2, p3 = k * b0 * si * cu, k * b0 * ci + m2_scale * cu, -2.0 * k * b0 * si * su
    m1 = p1
    m2 = p2 * s3z + p3 * s3y
    m3 = -p2 * s3y + p3 * s3z
    href = h0 * cu * cu
    if momentum != 0.0:
        e1 = (j00 * w1 + j01 * w2 + j02 * w3 + hr - href - b_tr * n * o1) / b_tr
        e2 = (j10 * w1 + j11 * w2 + j12 * w3 - b_tr * n * o2) / b_tr
        e3 = (j20 * w1 + j21 * w2 + j22 * w3 - b_tr * n * o3) / b_tr
    else:
        e1 = w1 - n * o1 - (href - hr) / a_ax
        e2 = w2 - n * o2
        e3 = w3 - n * o3
    bsq = bb1 * bb1 + bb2 * bb2 + bb3 * bb3
    g = kw / bsq
    m1 += g * (e2 * bb3 - e3 * bb2)
    m2 += g * (e3 * bb1 - e1 * bb3)
    m3 += g * (e1 * bb2 - e2 * bb1)
    m1, m2, m3 = min(max(m1, -lim), lim), min(max(m2, -lim), lim), min(max(m3, -lim), lim)
    return m1, m2, m3, bb1, bb2, bb3, r20, r21, r22, o1, o2, o3


@njit(cache=True, error_model="numpy")
def rotor_rhs(t, y, c):
    """(q̇, ω̇) of the closed loop at time ``t`` [s], state y = (q, ω) (7,): a new array."""
    j00, j01, j02, j10, j11, j12, j20, j21, j22 = c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7], c[8]
    n, hr = c[18], c[26]
    n2 = 3.0 * n * n
    q0, q1, q2, q3, w1, w2, w3 = y[0], y[1], y[2], y[3], y[4], y[5], y[6]
    m1, m2, m3, bb1, bb2, bb3, x, yy, z, o1, o2, o3 = rotor_controller(t, q0, q1, q2, q3, w1, w2, w3, c)
    jr1, jr2, jr3 = j00 * x + j01 * yy + j02 * z, j10 * x + j11 * yy + j12 * z, j20 * x + j21 * yy + j22 * z
    t1 = m2 * bb3 - m3 * bb2 + n2 * (yy * jr3 - z * jr2)
    t2 = m3 * bb1 - m1 * bb3 + n2 * (z * jr1 - x * jr3)
    t3 = m1 * bb2 - m2 * bb1 + n2 * (x * jr2 - yy * jr1)
    v1, v2, v3 = w1 - n * o1, w2 - n * o2, w3 - n * o3
    out = np.empty(7)
    # the body: the family's compiled twins (attitude relative to the orbital frame, hence v)
    out[0], out[1], out[2], out[3] = quaternion_rate_scalar((q0, q1, q2, q3), (v1, v2, v3))
    tensor = (False, (1.0, 1.0, 1.0), c[0:9].reshape(3, 3), c[9:18].reshape(3, 3))
    out[4], out[5], out[6] = gyrostat_rates_scalar((w1, w2, w3), (t1, t2, t3), tensor, hr)
    return out
