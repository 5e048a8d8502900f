r"""Compiled (numba) twin of :func:`magbench.sim.simulate_detumble`'s inner loop: the
same RK4 steps, law and schedule, one member at a time in scalar code.

Why compiled: a step of the numpy loop is ~600 elementwise operations on arrays of M
members, and at the hundreds of members of chapter 5 numpy's per-call overhead, not the
arithmetic, sets the pace. Each operation here is the numpy loop's, in the same order and
without fast-math, so the two give the same numbers to the last bit (the tests hold them
to it); the numpy loop stays as the reference and runs the one mode not compiled (duty
with the "propagate" estimator).

The inertial field, its rate and the radial direction come from the numpy loop's field
table (:class:`magbench.sim.detumble._FieldTable`) one block of steps at a time.
``cache=True`` keeps the compiled code in ``__pycache__`` (see :mod:`magbench.sim._passive_kernel`).
"""

import math

import numpy as np
from numba import njit

__all__ = ["advance_block"]

#: How the coils are commanded (per member, kept across blocks): the law at every RK
#: stage, or a held dipole.
LAW, HELD = 0, 1


@njit(cache=True, error_model="numpy")
def _dipole(b0, b1, b2, d0, d1, d2, k, lim, projected):
    """m = sat(−kḂ) or the projected law, per axis clipped to ±lim (control.bdot)."""
    if projected:
        bb = b0 * b0 + b1 * b1 + b2 * b2
        along = (b0 * d0 + b1 * d1 + b2 * d2) / bb
        scale = -k / bb
        return (min(max(scale * (d0 - b0 * along), -lim[0]), lim[0]),
                min(max(scale * (d1 - b1 * along), -lim[1]), lim[1]),
                min(max(scale * (d2 - b2 * along), -lim[2]), lim[2]))
    return (min(max(-k * d0, -lim[0]), lim[0]), min(max(-k * d1, -lim[1]), lim[1]),
            min(max(-k * d2, -lim[2]), lim[2]))


@njit(cache=True, error_model="numpy")
def _rows(x):
    """R(q/|q|)ᵀ as nine floats (body components of the inertial axes)."""
    w, qx, qy, qz = x[0], x[1], x[2], x[3]
    s = 2.0 / (w * w + qx * qx + qy * qy + qz * qz)
    xx, yy, zz, xy, xz, yz, wx, wy, wz = (s * qx * qx, s * qy * qy, s * qz * qz, s * qx * qy, s * qx * qz,
                                          s * qy * qz, s * w * qx, s * w * qy, s * w * qz)
    return (1.0 - yy - zz, xy + wz, xz - wy, xy - wz, 1.0 - xx - zz, yz + wx, xz + wy, yz - wx, 1.0 - xx - yy)


@njit(cache=True, error_model="numpy")
def _inertia_times(v0, v1, v2, diag, jd, jt):
    if diag:
        return jd[0] * v0, jd[1] * v1, jd[2] * v2
    return (jt[0, 0] * v0 + jt[0, 1] * v1 + jt[0, 2] * v2, jt[1, 0] * v0 + jt[1, 1] * v1 + jt[1, 2] * v2,
            jt[2, 0] * v0 + jt[2, 1] * v1 + jt[2, 2] * v2)


@njit(cache=True, error_model="numpy")
def _inertia_solve(v0, v1, v2, diag, jd, jinv):
    if diag:
        return v0 / jd[0], v1 / jd[1], v2 / jd[2]
    return (jinv[0, 0] * v0 + jinv[0, 1] * v1 + jinv[0, 2] * v2, jinv[1, 0] * v0 + jinv[1, 1] * v1
            + jinv[1, 2] * v2, jinv[2, 0] * v0 + jinv[2, 1] * v1 + jinv[2, 2] * v2)


@njit(cache=True, error_model="numpy")
def _rhs(x, bn, br, ra, how, held, k, lim, projected, gg, diag, jd, jt, jinv, out):
    """(q̇, ω̇) of one member: the numpy loop's ``_Body.rhs``, operation for operation."""
    r00, r01, r02, r10, r11, r12, r20, r21, r22 = _rows(x)
    w0, w1, w2 = x[4], x[5], x[6]
    b0 = r00 * bn[0] + r01 * bn[1] + r02 * bn[2]
    b1 = r10 * bn[0] + r11 * bn[1] + r12 * bn[2]
    b2 = r20 * bn[0] + r21 * bn[1] + r22 * bn[2]
    if how == LAW:                   # the on-board models: exact Ḃ in body axes
        c0, c1, c2 = w1 * b2 - w2 * b1, w2 * b0 - w0 * b2, w0 * b1 - w1 * b0
        m0, m1, m2 = _dipole(b0, b1, b2, (r00 * br[0] + r01 * br[1] + r02 * br[2]) - c0,
                             (r10 * br[0] + r11 * br[1] + r12 * br[2]) - c1,
                             (r20 * br[0] + r21 * br[1] + r22 * br[2]) - c2, k, lim, projected)
    else:
        m0, m1, m2 = held[0], held[1], held[2]
    t0, t1, t2 = m1 * b2 - m2 * b1, m2 * b0 - m0 * b2, m0 * b1 - m1 * b0
    if gg > 0.0:
        p0 = r00 * ra[0] + r01 * ra[1] + r02 * ra[2]
        p1 = r10 * ra[0] + r11 * ra[1] + r12 * ra[2]
        p2 = r20 * ra[0] + r21 * ra[1] + r22 * ra[2]
        i0, i1, i2 = _inertia_times(p0, p1, p2, diag, jd, jt)
        t0, t1, t2 = t0 + gg * (p1 * i2 - p2 * i1), t1 + gg * (p2 * i0 - p0 * i2), t2 + gg * (p0 * i1 - p1 * i0)
    h0, h1, h2 = _inertia_times(w0, w1, w2, diag, jd, jt)
    out[4], out[5], out[6] = _inertia_solve(t0 - (w1 * h2 - w2 * h1), t1 - (w2 * h0 - w0 * h2),
                                            t2 - (w0 * h1 - w1 * h0), diag, jd, jinv)
    qw, qx, qy, qz = x[0], x[1], x[2], x[3]
    out[0] = -0.5 * (qx * w0 + qy * w1 + qz * w2)
    out[1] = 0.5 * (qw * w0 + qy * w2 - qz * w1)
    out[2] = 0.5 * (qw * w1 - qx * w2 + qz * w0)
    out[3] = 0.5 * (qw * w2 + qx * w1 - qy * w0)


@njit(cache=True, error_model="numpy")
def _field_body(x, bn):
    r00, r01, r02, r10, r11, r12, r20, r21, r22 = _rows(x)
    return (r00 * bn[0] + r01 * bn[1] + r02 * bn[2], r10 * bn[0] + r11 * bn[1] + r12 * bn[2],
            r20 * bn[0] + r21 * bn[1] + r22 * bn[2])


@njit(cache=True, error_model="numpy")
def _load(b, b_rate, radial, n, col, bn, br, ra):
    for c in range(3):
        bn[c], br[c], ra[c] = b[c, n, col], b_rate[c, n, col], radial[c, n, col]


@njit(cache=True, error_model="numpy")
def advance_block(state, start, count, h, b, b_rate, radial, schedule, how, held, window, previous, gain, lim,
                  projected, gg, diag, jd, jt, jinv, stride, rates):
    """Advance every member over steps ``start`` … ``start + count − 1`` in place.

    state (M, 7); b, b_rate, radial (3, 2·count + 1, M or 1): the field table of the block;
    schedule = (mode, per_sample, n_off, n_on, hold, delta, t_off) with mode 0/1/2 for
    continuous/sampled/duty and hold 1 for the "hold" estimator; how, held, window,
    previous: each member's command (kept across blocks; previous[m, 3] = 1 once sampled);
    gain (M,); jd (M, 3) principal moments (diag) or jt, jinv (3, 3); rates (M, K) |ω| at
    every ``stride`` steps.
    """
    members = state.shape[0]
    mode, per_sample, n_off, n_on = int(schedule[0]), int(schedule[1]), int(schedule[2]), int(schedule[3])
    hold, delta, t_off = schedule[4] != 0.0, schedule[5], schedule[6]
    shared = b.shape[2] == 1
    k1, k2, k3, k4, tmp = np.empty(7), np.empty(7), np.empty(7), np.empty(7), np.empty(7)
    bn, br, ra = np.empty(3), np.empty(3), np.empty(3)
    half = 0.5 * h
    sixth = h / 6.0
    # steps outer, members inner: the field table is read along its contiguous member axis
    for i in range(start, start + count):
        n = 2 * (i - start)
        for m in range(members):
            x = state[m]
            col = 0 if shared else m
            k = gain[m]
            jm = jd[m]
            if mode == 1 and i % per_sample == 0:
                _load(b, b_rate, radial, n, col, bn, br, ra)
                s0, s1, s2 = _field_body(x, bn)
                if previous[m, 3] == 0.0:
                    held[m, 0], held[m, 1], held[m, 2] = 0.0, 0.0, 0.0
                else:
                    held[m, 0], held[m, 1], held[m, 2] = _dipole(
                        s0, s1, s2, (s0 - previous[m, 0]) / delta, (s1 - previous[m, 1]) / delta,
                        (s2 - previous[m, 2]) / delta, k, lim, projected)
                previous[m, 0], previous[m, 1], previous[m, 2], previous[m, 3] = s0, s1, s2, 1.0
                how[m] = HELD
            elif mode == 2:
                phase_step = i % (n_off + n_on)
                if phase_step == 0:
                    _load(b, b_rate, radial, n, col, bn, br, ra)
                    window[m, 0], window[m, 1], window[m, 2] = _field_body(x, bn)
                    held[m, 0], held[m, 1], held[m, 2] = 0.0, 0.0, 0.0
                    how[m] = HELD
                elif phase_step == n_off:
                    if hold:
                        _load(b, b_rate, radial, n, col, bn, br, ra)
                        e0, e1, e2 = _field_body(x, bn)
                        held[m, 0], held[m, 1], held[m, 2] = _dipole(
                            e0, e1, e2, (e0 - window[m, 0]) / t_off, (e1 - window[m, 1]) / t_off,
                            (e2 - window[m, 2]) / t_off, k, lim, projected)
                        how[m] = HELD
                    else:
                        how[m] = LAW
            _load(b, b_rate, radial, n, col, bn, br, ra)
            _rhs(x, bn, br, ra, how[m], held[m], k, lim, projected, gg, diag, jm, jt, jinv, k1)
            _load(b, b_rate, radial, n + 1, col, bn, br, ra)
            for j in range(7):
                tmp[j] = x[j] + half * k1[j]
            _rhs(tmp, bn, br, ra, how[m], held[m], k, lim, projected, gg, diag, jm, jt, jinv, k2)
            for j in range(7):
                tmp[j] = x[j] + half * k2[j]
            _rhs(tmp, bn, br, ra, how[m], held[m], k, lim, projected, gg, diag, jm, jt, jinv, k3)
            _load(b, b_rate, radial, n + 2, col, bn, br, ra)
            for j in range(7):
                tmp[j] = x[j] + h * k3[j]
            _rhs(tmp, bn, br, ra, how[m], held[m], k, lim, projected, gg, diag, jm, jt, jinv, k4)
            for j in range(7):
                x[j] = x[j] + sixth * (k1[j] + 2.0 * (k2[j] + k3[j]) + k4[j])
            norm = math.sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2] + x[3] * x[3])
            for j in range(4):
                x[j] = x[j] / norm
            if (i + 1) % stride == 0:
                rates[m, (i + 1) // stride] = math.sqrt(x[4] * x[4] + x[5] * x[5] + x[6] * x[6])
