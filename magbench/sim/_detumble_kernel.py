r"""Compiled (numba) twin of :func:`magbench.sim.simulate_detumble`'s inner loop: the
same RK4 steps, law and schedule, members on the contiguous axis.

Why compiled: a step of the numpy loop is ~600 elementwise operations on arrays of M
members, and at the hundreds of members of chapter 5 numpy's per-call overhead, not the
arithmetic, sets the pace. Each operation here is the numpy loop's, in the same order and
without fast-math, so the two give the same numbers to the last bit for principal moments
(the tests hold them to it; for an inertia tensor the numpy loop solves J ω̇ = … where this
loop multiplies by J⁻¹, equal to rounding); the numpy loop stays as the reference and runs the one mode not compiled (duty
with the "propagate" estimator).

Why this layout: the step is the library's compiled RK4 (:func:`magbench._rk4_kernel.rk4_advance`)
of :func:`member_rates`, which runs one loop over the members in straight-line code (the
law, the gravity gradient and the inertia form are chosen by selects, not branches),
reading state, table and per-member data along their contiguous member axis. The stages
are arrays (7, M), allocated once per block; against the earlier loop that carried a
member's four stages in registers, this costs ~10 % at 200 members (0.55 s against 0.50 s
for 6000 s at 0.5 s steps), the price of one RK4. The schedule's sampling instants (a few
per hundred steps) run in their own scalar loop.

The inertial field, its rate and the radial direction come from the numpy loop's field
table (:class:`magbench.sim._detumble_loops._FieldTable`) one block of steps at a time.
``cache=True`` keeps the compiled code in ``__pycache__`` (see :mod:`magbench.sim._passive_kernel`).
"""

import math

import numpy as np
from numba import njit

from .._rk4_kernel import rk4_advance
from ..control.kernels import bdot_dipole_scalar
from ..dynamics.kernels import gyrostat_rates_scalar, quaternion_rate_scalar

__all__ = ["advance_block", "member_rates"]

#: How the coils are commanded (per member, kept across blocks): the law at every RK
#: stage, or a held dipole.
LAW, HELD = 0, 1


@njit(cache=True, error_model="numpy")
def _rows(q0, q1, q2, q3):
    """R(q/|q|)ᵀ as nine floats (body components of the inertial axes)."""
    s = 2.0 / (q0 * q0 + q1 * q1 + q2 * q2 + q3 * q3)
    xx, yy, zz, xy, xz, yz, wx, wy, wz = (s * q1 * q1, s * q2 * q2, s * q3 * q3, s * q1 * q2, s * q1 * q3,
                                          s * q2 * q3, s * q0 * q1, s * q0 * q2, s * q0 * q3)
    return (1.0 - yy - zz, xy + wz, xz - wy, xy - wz, 1.0 - xx - zz, yz + wx, xz + wy, yz - wx, 1.0 - xx - yy)


@njit(cache=True, error_model="numpy")
def _inertia_times(v0, v1, v2, diag, j0, j1, j2, jt):
    """J v: the member's principal moments (diag) or the shared tensor."""
    d = (j0 * v0, j1 * v1, j2 * v2)
    t = (jt[0, 0] * v0 + jt[0, 1] * v1 + jt[0, 2] * v2, jt[1, 0] * v0 + jt[1, 1] * v1 + jt[1, 2] * v2,
         jt[2, 0] * v0 + jt[2, 1] * v1 + jt[2, 2] * v2)
    return d if diag else t


@njit(cache=True, error_model="numpy")
def _rhs(q, w, field, command, law_args, body):
    """(q̇, ω̇) of one member: the numpy loop's ``_Body.rhs``, operation for operation; the
    body's equations are the family's compiled twins (:mod:`magbench.dynamics.kernels`).

    q (4-tuple) and w (3-tuple) are the member's state; field = (B, Ḃ, r̂) inertial at the
    stage, command = (law, held dipole), law_args = (k, limits, projected) and body = (gg,
    diag, principal moments, tensor, inverse tensor), each vector a 3-tuple.
    """
    q0, q1, q2, q3 = q
    w0, w1, w2 = w
    (bn0, bn1, bn2), (br0, br1, br2), (ra0, ra1, ra2) = field
    law, (h0, h1, h2) = command
    k, (lim0, lim1, lim2), projected = law_args
    gg, diag, (j0, j1, j2), jt, jinv = body
    r00, r01, r02, r10, r11, r12, r20, r21, r22 = _rows(q0, q1, q2, q3)
    b0 = r00 * bn0 + r01 * bn1 + r02 * bn2
    b1 = r10 * bn0 + r11 * bn1 + r12 * bn2
    b2 = r20 * bn0 + r21 * bn1 + r22 * bn2
    # the on-board models: exact Ḃ in body axes (formed for every member, used where law)
    c0, c1, c2 = w1 * b2 - w2 * b1, w2 * b0 - w0 * b2, w0 * b1 - w1 * b0
    l0, l1, l2 = bdot_dipole_scalar((b0, b1, b2), ((r00 * br0 + r01 * br1 + r02 * br2) - c0,
                                                   (r10 * br0 + r11 * br1 + r12 * br2) - c1,
                                                   (r20 * br0 + r21 * br1 + r22 * br2) - c2), k, (lim0, lim1, lim2),
                                    projected)
    m0, m1, m2 = (l0, l1, l2) if law else (h0, h1, h2)
    t0, t1, t2 = m1 * b2 - m2 * b1, m2 * b0 - m0 * b2, m0 * b1 - m1 * b0
    p0 = r00 * ra0 + r01 * ra1 + r02 * ra2
    p1 = r10 * ra0 + r11 * ra1 + r12 * ra2
    p2 = r20 * ra0 + r21 * ra1 + r22 * ra2
    i0, i1, i2 = _inertia_times(p0, p1, p2, diag, j0, j1, j2, jt)
    g0, g1, g2 = t0 + gg * (p1 * i2 - p2 * i1), t1 + gg * (p2 * i0 - p0 * i2), t2 + gg * (p0 * i1 - p1 * i0)
    if gg > 0.0:
        t0, t1, t2 = g0, g1, g2
    d4, d5, d6 = gyrostat_rates_scalar((w0, w1, w2), (t0, t1, t2), (diag, (j0, j1, j2), jt, jinv), 0.0)
    d0, d1, d2, d3 = quaternion_rate_scalar((q0, q1, q2, q3), (w0, w1, w2))
    return d0, d1, d2, d3, d4, d5, d6


@njit(cache=True, error_model="numpy")
def _field_body(state, m, b, n):
    """The member's inertial field at table row n, in body axes."""
    r00, r01, r02, r10, r11, r12, r20, r21, r22 = _rows(state[0, m], state[1, m], state[2, m], state[3, m])
    bn0, bn1, bn2 = b[0, n, m], b[1, n, m], b[2, n, m]
    return (r00 * bn0 + r01 * bn1 + r02 * bn2, r10 * bn0 + r11 * bn1 + r12 * bn2, r20 * bn0 + r21 * bn1 + r22 * bn2)


@njit(cache=True, error_model="numpy")
def _sample(i, n, state, b, schedule, how, held, window, previous, gain, lim, projected):
    """The schedule at step i: a new held dipole or law where a sampling instant falls."""
    mode, per_sample, n_off, n_on = int(schedule[0]), int(schedule[1]), int(schedule[2]), int(schedule[3])
    hold, delta, t_off = schedule[4] != 0.0, schedule[5], schedule[6]
    phase_step = i % (n_off + n_on) if mode == 2 else -1
    if not ((mode == 1 and i % per_sample == 0) or phase_step == 0 or phase_step == n_off):
        return
    for m in range(state.shape[1]):
        k = gain[m]
        if mode == 1:
            s0, s1, s2 = _field_body(state, m, b, n)
            if previous[3, m] == 0.0:
                held[0, m], held[1, m], held[2, m] = 0.0, 0.0, 0.0
            else:
                held[0, m], held[1, m], held[2, m] = bdot_dipole_scalar(
                    (s0, s1, s2), ((s0 - previous[0, m]) / delta, (s1 - previous[1, m]) / delta,
                                   (s2 - previous[2, m]) / delta), k, (lim[0], lim[1], lim[2]), projected)
            previous[0, m], previous[1, m], previous[2, m], previous[3, m] = s0, s1, s2, 1.0
            how[m] = HELD
        elif phase_step == 0:
            window[0, m], window[1, m], window[2, m] = _field_body(state, m, b, n)
            held[0, m], held[1, m], held[2, m] = 0.0, 0.0, 0.0
            how[m] = HELD
        elif hold:
            e0, e1, e2 = _field_body(state, m, b, n)
            held[0, m], held[1, m], held[2, m] = bdot_dipole_scalar(
                (e0, e1, e2), ((e0 - window[0, m]) / t_off, (e1 - window[1, m]) / t_off, (e2 - window[2, m]) / t_off),
                k, (lim[0], lim[1], lim[2]), projected)
            how[m] = HELD
        else:
            how[m] = LAW


@njit(cache=True, error_model="numpy")
def member_rates(time, x, out, clock, table, command, law_args, body):
    """(q̇, ω̇) of every member into out, x and out (7, M): :func:`_rhs` member by member.

    The field table (b, b_rate, radial) holds the field at the block's step ends and
    midpoints, so the row of ``time`` is its count of half steps from the block's start:
    clock = (t_block, h/2). command = (how, held), law_args = (gain, lim, projected) and
    body = (gg, diag, jd, jt, jinv) as :func:`advance_block` takes them.
    """
    t_block, half = clock
    b, b_rate, radial = table
    how, held = command
    gain, lim, projected = law_args
    gg, diag, jd, jt, jinv = body
    n = int(math.floor((time - t_block) / half + 0.5))
    lim0, lim1, lim2 = lim[0], lim[1], lim[2]
    for m in range(x.shape[1]):
        out[0, m], out[1, m], out[2, m], out[3, m], out[4, m], out[5, m], out[6, m] = _rhs(
            (x[0, m], x[1, m], x[2, m], x[3, m]), (x[4, m], x[5, m], x[6, m]),
            ((b[0, n, m], b[1, n, m], b[2, n, m]), (b_rate[0, n, m], b_rate[1, n, m], b_rate[2, n, m]),
             (radial[0, n, m], radial[1, n, m], radial[2, n, m])),
            (how[m] == LAW, (held[0, m], held[1, m], held[2, m])), (gain[m], (lim0, lim1, lim2), projected),
            (gg, diag, (jd[0, m], jd[1, m], jd[2, m]), jt, jinv))


@njit(cache=True, error_model="numpy")
def advance_block(state, start, count, h, table, schedule, command, law_args, body, stride, rates):
    """Advance every member over steps ``start`` … ``start + count − 1`` in place, by the
    library's compiled RK4 step (:func:`magbench._rk4_kernel.rk4_advance`) of :func:`member_rates`.

    state (7, M); table = (b, b_rate, radial), each (3, 2·count + 1, M): the field table of
    the block; schedule = (mode, per_sample, n_off, n_on, hold, delta, t_off) with mode
    0/1/2 for continuous/sampled/duty and hold 1 for the "hold" estimator; command = (how
    (M,), held, window (3, M), previous (4, M)): each member's command (kept across blocks;
    previous[3] = 1 once sampled); law_args = (gain (M,), lim (3,), projected); body = (gg,
    diag, jd (3, M) principal moments (diag), jt, jinv (3, 3)); rates (M, K) |ω| at every
    ``stride`` steps.
    """
    b, b_rate, radial = table
    how, held, window, previous = command
    gain, lim, projected = law_args
    gg, diag, jd, jt, jinv = body
    members = state.shape[1]
    args = ((start * h, 0.5 * h), table, (how, held), law_args, body)
    stages = np.empty((5,) + state.shape)
    for i in range(start, start + count):
        _sample(i, 2 * (i - start), state, b, schedule, how, held, window, previous, gain, lim, projected)
        rk4_advance(member_rates, i * h, state, h, args, stages)
        for m in range(members):
            y0, y1, y2, y3 = state[0, m], state[1, m], state[2, m], state[3, m]
            norm = math.sqrt(y0 * y0 + y1 * y1 + y2 * y2 + y3 * y3)
            state[0, m], state[1, m], state[2, m], state[3, m] = y0 / norm, y1 / norm, y2 / norm, y3 / norm
        if (i + 1) % stride == 0:
            for m in range(members):
                rates[m, (i + 1) // stride] = math.sqrt(state[4, m] * state[4, m] + state[5, m] * state[5, m]
                                                        + state[6, m] * state[6, m])
