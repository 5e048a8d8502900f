r"""Compiled (numba) integrator of the passive satellite: the same arithmetic as the numpy
reference in :mod:`magbench.sim.passive`, members on the contiguous axis.

Why compiled: the spin-down from TNS-0's session 1 is ~10⁸ RK4 steps of a 7 + k state; numpy
spends ~0.3 ms per step on array overhead whatever the number of members, this kernel under a
microsecond. The numpy path stays as the reference (``engine="numpy"``) and the tests hold the
two to 1e-10 on short spans.

Step rule, field, right-hand side and sampling are those of the numpy path: in each sample
interval the step is interval/n with n = ⌈interval·max(|ω|, |Ω_p|, 2n_orbit)/limit⌉ over all
members; the quaternion is renormalised after every step; the field is the centred dipole of
:meth:`magbench.earth.CircularOrbit.field_and_rate`, through its compiled twin
(:mod:`magbench.earth.kernels`).

Why this layout: the step is the library's compiled RK4 (:func:`magbench._rk4_kernel.rk4_advance`)
of :func:`member_rates`, which runs one loop over the members in straight-line code. The state
is the (7 + k, M) array flattened (component i of member m at i·M + m): members contiguous,
and the RK4 stages one-dimensional arrays, which numba forms faster than two-dimensional ones.
The cos/sin of the orbit phase u and of the pole's longitude λ at the stage times come from
rotating through half a step (one cos/sin per sample interval, not per stage), a recurrence
that a right-hand side of ``(time, state)`` cannot carry: each block of steps first fills a
table of B and dB/dt at its step ends and midpoints by that recurrence, and
:func:`member_rates` reads its row from the time. Blocks of at most :data:`TABLE_VALUES`
entries bound the table whatever the step count. The rods' axes come as a tuple, not an
array: every array argument costs the right-hand side reference counting at each stage.

Cost of the one RK4: each step passes its arrays (state, stages, table) to the right-hand
side four times, with numba's reference counting each time. At one member (the full run from
session 1, 9.7e7 steps) the run takes 43 s against 34 s for the earlier loop that kept the
stages in scalars; at the 64 members of the capture Monte Carlo the member loop amortises it
and the run is twice as fast as that loop (0.43 s against 0.88 s), measured on two cores.
The step allocates nothing (:func:`magbench._rk4_kernel.rk4_advance` works on stages
allocated once per run).

``cache=True`` writes the compiled code next to this file (``__pycache__``, ignored by git) or,
if that folder is not writable, to numba's per-user cache; it only saves the ~10 s compilation
in later processes (one compilation per number of rods).
"""

import math

import numpy as np
from numba import njit

from .._rk4_kernel import rk4_advance
from ..constants import MU_0
from ..dynamics.kernels import gyrostat_rates_scalar, quaternion_rate_scalar
from ..earth.kernels import dipole_field_rate_radial

__all__ = ["member_rates", "run_passive"]

_TWO_OVER_PI = 2.0 / math.pi
_INV_MU_0 = 1.0 / MU_0
_EYE = np.eye(3)     # the twin's tensor slot, unused for principal moments
#: Largest field table of a block of steps (floats): 6 · (2·steps + 1) · members.
TABLE_VALUES = 1 << 15


@njit(cache=True, error_model="numpy")
def _to_body(w, x, y, z, v0, v1, v2):
    """v rotated by the conjugate of the unit quaternion (w, −x, −y, −z) given (inertial → body)."""
    t0 = 2.0 * (y * v2 - z * v1)
    t1 = 2.0 * (z * v0 - x * v2)
    t2 = 2.0 * (x * v1 - y * v0)
    return (v0 + w * t0 + (y * t2 - z * t1), v1 + w * t1 + (z * t0 - x * t2), v2 + w * t2 + (x * t1 - y * t0))


@njit(cache=True, error_model="numpy")
def member_rates(time, x, out, clock, table, body, rods):
    """(q̇, ω̇, Ḃ of the rods) of every member into out: the numpy reference's right-hand side.

    x and out are the flattened (7 + k, M) states (component i of member m at
    i·M + m). The field table (6, rows, M) holds inertial B and dB/dt at the block's step
    ends and midpoints, so the row of ``time`` is its count of half steps from the block's
    start: clock = (t_block, h/2). body = (i0, i1, i2, magnet): the principal moments and
    the magnet's moment along z; rods = (axes, volume, hc, bs, kk): the k rods' unit vectors
    (a tuple of 3-tuples), their volume and Flatley–Henretty constants.
    """
    t_block, half = clock
    i0, i1, i2, magnet = body
    axes, volume, hc, bs, kk = rods
    row = int(math.floor((time - t_block) / half + 0.5))
    M = table.shape[2]
    nrods = len(axes)
    principal = (True, (i0, i1, i2), _EYE, _EYE)
    for m in range(M):
        q0, q1, q2, q3 = x[0 * M + m], x[1 * M + m], x[2 * M + m], x[3 * M + m]
        # normalised for the rotation, as magbench.dynamics.kernels.rotate does
        norm = math.sqrt(q0 * q0 + q1 * q1 + q2 * q2 + q3 * q3)
        nw, nx, ny, nz = q0 / norm, -q1 / norm, -q2 / norm, -q3 / norm
        w0, w1, w2 = x[4 * M + m], x[5 * M + m], x[6 * M + m]
        b0, b1, b2 = _to_body(nw, nx, ny, nz, table[0, row, m], table[1, row, m], table[2, row, m])
        m0, m1, m2 = 0.0, 0.0, magnet
        if volume > 0:
            half_pi_over_bs, inv_kk, inv_2hc = 0.5 * math.pi / bs, 1.0 / kk, 0.5 / hc
            gain, v_over_mu0 = _TWO_OVER_PI * bs * kk, volume * _INV_MU_0
            d0, d1, d2 = _to_body(nw, nx, ny, nz, table[3, row, m], table[4, row, m], table[5, row, m])
            d0 -= w1 * b2 - w2 * b1
            d1 -= w2 * b0 - w0 * b2
            d2 -= w0 * b1 - w1 * b0
            for k in range(nrods):
                a0, a1, a2 = axes[k][0], axes[k][1], axes[k][2]
                h = (b0 * a0 + b1 * a1 + b2 * a2) * _INV_MU_0
                h_rate = (d0 * a0 + d1 * a1 + d2 * a2) * _INV_MU_0
                bk = x[(7 + k) * M + m]
                xx = half_pi_over_bs * bk
                sign = 1.0 if h_rate > 0 else (-1.0 if h_rate < 0 else 0.0)
                tx = math.tan(xx)
                h_from = tx * inv_kk - sign * hc
                r = (h - h_from) * inv_2hc
                # cos² x = 1/(1 + tan² x): one transcendental per rod and stage
                out[(7 + k) * M + m] = gain / (1.0 + tx * tx) * (r * r) * h_rate
                scale = bk * v_over_mu0
                m0 += scale * a0
                m1 += scale * a1
                m2 += scale * a2
        else:
            for k in range(nrods):
                out[(7 + k) * M + m] = 0.0
        torque = (m1 * b2 - m2 * b1, m2 * b0 - m0 * b2, m0 * b1 - m1 * b0)
        # the body: the family's compiled twins (principal moments)
        out[4 * M + m], out[5 * M + m], out[6 * M + m] = gyrostat_rates_scalar((w0, w1, w2), torque, principal, 0.0)
        out[0 * M + m], out[1 * M + m], out[2 * M + m], out[3 * M + m] = quaternion_rate_scalar((q0, q1, q2, q3),
                                                                                              (w0, w1, w2))


@njit(cache=True, error_model="numpy")
def _fill(table, row, m, cu, su, cl, sl, geo):
    """table[:, row, m] = inertial B and dB/dt, given cos/sin of u and of λ."""
    f = dipole_field_rate_radial(cu, su, cl, sl, geo)
    for c in range(6):
        table[c, row, m] = f[c]


@njit(cache=True, error_model="numpy")
def _record(x, m, t, u0, geo, inertia, records, j):
    """records[j, :, m]: |L|, nutation, axis–B angle, L–B angle and |ω| of member m (flattened
    states x) at time t."""
    M = records.shape[2]
    u = u0 + geo[0] * t
    lam = geo[10] + geo[11] * t
    f = dipole_field_rate_radial(math.cos(u), math.sin(u), math.cos(lam), math.sin(lam), geo)
    x0, x1, x2, x3 = x[0 * M + m], x[1 * M + m], x[2 * M + m], x[3 * M + m]
    norm = math.sqrt(x0 * x0 + x1 * x1 + x2 * x2 + x3 * x3)
    b0, b1, b2 = _to_body(x0 / norm, -x1 / norm, -x2 / norm, -x3 / norm, f[0], f[1], f[2])
    w0, w1, w2 = x[4 * M + m], x[5 * M + m], x[6 * M + m]
    l0, l1, l2 = inertia[0] * w0, inertia[1] * w1, inertia[2] * w2
    big_l = math.sqrt(l0 * l0 + l1 * l1 + l2 * l2)
    b_norm = math.sqrt(b0 * b0 + b1 * b1 + b2 * b2)
    safe = big_l if big_l > 0 else 1.0
    records[j, 0, m] = big_l
    records[j, 1, m] = math.acos(min(1.0, max(-1.0, l2 / safe)))
    records[j, 2, m] = math.acos(min(1.0, max(-1.0, b2 / b_norm)))
    records[j, 3, m] = math.acos(min(1.0, max(-1.0, (l0 * b0 + l1 * b1 + l2 * b2) / (safe * b_norm))))
    records[j, 4, m] = math.sqrt(w0 * w0 + w1 * w1 + w2 * w2)


@njit(cache=True, error_model="numpy")
def run_passive(state, u0, geo, inertia, magnet, rods, interval, n_samples, limit, records):
    """Advance every member over n_samples intervals; fill records (n+1, 5, M); return the steps.

    state (7 + k, M) is advanced in place, by the library's compiled RK4 step
    (:func:`magbench._rk4_kernel.rk4_advance`) of :func:`member_rates`; u0 (M,) the members'
    orbit phases; rods = (axes, volume, Hc, Bs, k_shape) with axes a tuple of k unit
    3-tuples, unpacked once here.
    """
    axes, volume, hc, bs, kk = rods
    members = state.shape[1]
    M = members
    a, c = inertia[0], inertia[2]
    two_n = 2.0 * geo[0]
    block = max(1, (TABLE_VALUES // (6 * members) - 1) // 2)
    table = np.empty((6, 2 * block + 1, members))
    cu, su, cl, sl = np.empty(members), np.empty(members), np.empty(members), np.empty(members)
    x = state.copy().reshape(state.size)
    stages = np.empty((5, x.size))
    for m in range(members):
        _record(x, m, 0.0, u0[m], geo, inertia, records, 0)
    steps = 0
    for j in range(n_samples):
        fastest = two_n
        for m in range(members):
            w0, w1, w2 = x[4 * M + m], x[5 * M + m], x[6 * M + m]
            fastest = max(fastest, math.sqrt(w0 * w0 + w1 * w1 + w2 * w2), abs((c - a) * w2 / a))
        n = max(1, int(math.ceil(interval * fastest / limit)))
        h = interval / n
        half = 0.5 * h
        t = interval * j
        # cos/sin of u and λ at the stage times by rotation through half a step, exact again
        # at every sample (drift ~ steps·1e-16, far below the 1e-10 agreement with numpy)
        du, dl = geo[0] * half, geo[11] * half
        cdu, sdu, cdl, sdl = math.cos(du), math.sin(du), math.cos(dl), math.sin(dl)
        for m in range(members):
            u, lam = u0[m] + geo[0] * t, geo[10] + geo[11] * t
            cu[m], su[m], cl[m], sl[m] = math.cos(u), math.sin(u), math.cos(lam), math.sin(lam)
        for start in range(0, n, block):
            count = min(block, n - start)
            # the block's table: row r at r half steps from its start (row 0 = the previous
            # block's last row, the same numbers), the rotation carried across blocks
            for m in range(members):
                cu_m, su_m, cl_m, sl_m = cu[m], su[m], cl[m], sl[m]
                _fill(table, 0, m, cu_m, su_m, cl_m, sl_m, geo)
                for r in range(1, 2 * count + 1):
                    cu_m, su_m = cu_m * cdu - su_m * sdu, su_m * cdu + cu_m * sdu
                    cl_m, sl_m = cl_m * cdl - sl_m * sdl, sl_m * cdl + cl_m * sdl
                    _fill(table, r, m, cu_m, su_m, cl_m, sl_m, geo)
                cu[m], su[m], cl[m], sl[m] = cu_m, su_m, cl_m, sl_m
            t_block = t + start * h
            args = ((t_block, half), table, (inertia[0], inertia[1], inertia[2], magnet), (axes, volume, hc, bs, kk))
            for s in range(count):
                rk4_advance(member_rates, t_block + s * h, x, h, args, stages)
                for m in range(members):
                    x0, x1, x2, x3 = x[0 * M + m], x[1 * M + m], x[2 * M + m], x[3 * M + m]
                    norm = math.sqrt(x0 * x0 + x1 * x1 + x2 * x2 + x3 * x3)
                    for i in range(4):
                        x[i * M + m] /= norm
        for m in range(members):
            _record(x, m, interval * (j + 1), u0[m], geo, inertia, records, j + 1)
        steps += n
    state[:] = x.reshape(state.shape)
    return steps
