r"""Compiled (numba) integrator of the passive satellite: the same arithmetic as the numpy
reference in :mod:`magbench.sim.passive`, one member at a time in scalar code.

Why compiled: the spin-down from TNS-0's session 1 is ~10⁸ RK4 steps of a 7 + k state; numpy
spends ~0.3 ms per step on array overhead whatever the number of members, a scalar kernel a
fraction of a microsecond. The numpy path stays as the reference (``engine="numpy"``) and the
tests hold the two to 1e-10 on short spans.

Step rule, field, right-hand side and sampling are those of the numpy path: in each sample
interval the step is interval/n with n = ⌈interval·max(|ω|, |Ω_p|, 2n_orbit)/limit⌉ over all
members; the quaternion is renormalised after every step; the field is the centred dipole of
:meth:`magbench.earth.CircularOrbit.field_and_rate`, through its compiled twin
(:mod:`magbench.earth.kernels`).

``cache=True`` writes the compiled code next to this file (``__pycache__``, ignored by git) or,
if that folder is not writable, to numba's per-user cache; it only saves the ~10 s compilation
in later processes.
"""

import math

import numpy as np
from numba import njit

from ..constants import MU_0
from ..earth.kernels import dipole_field_rate_radial

_TWO_OVER_PI = 2.0 / math.pi
_INV_MU_0 = 1.0 / MU_0


@njit(cache=True, error_model="numpy")
def _field_trig(cu, su, cl, sl, geo, out):
    """Inertial B (out[0:3]) and dB/dt (out[3:6]), given cos/sin of u and of λ."""
    f = dipole_field_rate_radial(cu, su, cl, sl, geo)
    for c in range(6):
        out[c] = f[c]


@njit(cache=True, error_model="numpy")
def _field(t, u0, geo, out):
    """B and dB/dt at time t (argument of latitude u0 + n t)."""
    u = u0 + geo[0] * t
    lam = geo[10] + geo[11] * t
    _field_trig(math.cos(u), math.sin(u), math.cos(lam), math.sin(lam), geo, out)


@njit(cache=True, error_model="numpy")
def _to_body(w, x, y, z, v0, v1, v2):
    """v rotated by the conjugate of the unit quaternion (w, −x, −y, −z) given (inertial → body)."""
    t0 = 2.0 * (y * v2 - z * v1)
    t1 = 2.0 * (z * v0 - x * v2)
    t2 = 2.0 * (x * v1 - y * v0)
    return (v0 + w * t0 + (y * t2 - z * t1), v1 + w * t1 + (z * t0 - x * t2), v2 + w * t2 + (x * t1 - y * t0))


@njit(cache=True, error_model="numpy")
def _rhs(x, f, inertia, magnet, axes, volume, hc, bs, kk, dx):
    q0, q1, q2, q3 = x[0], x[1], x[2], x[3]
    # normalised for the rotation, as magbench.dynamics.kernels.rotate does
    norm = math.sqrt(q0 * q0 + q1 * q1 + q2 * q2 + q3 * q3)
    nw, nx, ny, nz = q0 / norm, -q1 / norm, -q2 / norm, -q3 / norm
    w0, w1, w2 = x[4], x[5], x[6]
    b0, b1, b2 = _to_body(nw, nx, ny, nz, f[0], f[1], f[2])
    m0, m1, m2 = 0.0, 0.0, magnet
    nrods = axes.shape[0]
    if volume > 0:
        half_pi_over_bs, inv_kk, inv_2hc = 0.5 * math.pi / bs, 1.0 / kk, 0.5 / hc
        gain, v_over_mu0 = _TWO_OVER_PI * bs * kk, volume * _INV_MU_0
        d0, d1, d2 = _to_body(nw, nx, ny, nz, f[3], f[4], f[5])
        d0 -= w1 * b2 - w2 * b1
        d1 -= w2 * b0 - w0 * b2
        d2 -= w0 * b1 - w1 * b0
        for k in range(nrods):
            h = (b0 * axes[k, 0] + b1 * axes[k, 1] + b2 * axes[k, 2]) * _INV_MU_0
            h_rate = (d0 * axes[k, 0] + d1 * axes[k, 1] + d2 * axes[k, 2]) * _INV_MU_0
            bk = x[7 + k]
            xx = half_pi_over_bs * bk
            sign = 1.0 if h_rate > 0 else (-1.0 if h_rate < 0 else 0.0)
            tx = math.tan(xx)
            h_from = tx * inv_kk - sign * hc
            r = (h - h_from) * inv_2hc
            # cos² x = 1/(1 + tan² x): one transcendental per rod and stage
            dx[7 + k] = gain / (1.0 + tx * tx) * (r * r) * h_rate
            scale = bk * v_over_mu0
            m0 += scale * axes[k, 0]
            m1 += scale * axes[k, 1]
            m2 += scale * axes[k, 2]
    else:
        for k in range(nrods):
            dx[7 + k] = 0.0
    tq0, tq1, tq2 = m1 * b2 - m2 * b1, m2 * b0 - m0 * b2, m0 * b1 - m1 * b0
    i0, i1, i2 = inertia[0], inertia[1], inertia[2]
    l0, l1, l2 = i0 * w0, i1 * w1, i2 * w2
    dx[4] = (tq0 - (w1 * l2 - w2 * l1)) / i0
    dx[5] = (tq1 - (w2 * l0 - w0 * l2)) / i1
    dx[6] = (tq2 - (w0 * l1 - w1 * l0)) / i2
    dx[0] = 0.5 * (q0 * 0.0 - q1 * w0 - q2 * w1 - q3 * w2)
    dx[1] = 0.5 * (q0 * w0 + q1 * 0.0 + q2 * w2 - q3 * w1)
    dx[2] = 0.5 * (q0 * w1 - q1 * w2 + q2 * 0.0 + q3 * w0)
    dx[3] = 0.5 * (q0 * w2 + q1 * w1 - q2 * w0 + q3 * 0.0)


@njit(cache=True, error_model="numpy")
def _record(x, t, u0, geo, inertia, out):
    f = np.empty(6)
    _field(t, u0, geo, f)
    norm = math.sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2] + x[3] * x[3])
    b0, b1, b2 = _to_body(x[0] / norm, -x[1] / norm, -x[2] / norm, -x[3] / norm, f[0], f[1], f[2])
    l0, l1, l2 = inertia[0] * x[4], inertia[1] * x[5], inertia[2] * x[6]
    big_l = math.sqrt(l0 * l0 + l1 * l1 + l2 * l2)
    b_norm = math.sqrt(b0 * b0 + b1 * b1 + b2 * b2)
    safe = big_l if big_l > 0 else 1.0
    out[0] = big_l
    out[1] = math.acos(min(1.0, max(-1.0, l2 / safe)))
    out[2] = math.acos(min(1.0, max(-1.0, b2 / b_norm)))
    out[3] = math.acos(min(1.0, max(-1.0, (l0 * b0 + l1 * b1 + l2 * b2) / (safe * b_norm))))
    out[4] = math.sqrt(x[4] * x[4] + x[5] * x[5] + x[6] * x[6])


@njit(cache=True, error_model="numpy")
def run_passive(state, u0, geo, inertia, magnet, rods, interval, n_samples, limit, records):
    """Advance every member over n_samples intervals; fill records (n+1, 5, M); return the steps.

    state (M, 7 + k) is advanced in place; u0 (M,) the members' orbit phases; rods = (axes
    (k, 3), volume, Hc, Bs, k_shape), unpacked once here.
    """
    axes, volume, hc, bs, kk = rods
    members, size = state.shape
    a, c = inertia[0], inertia[2]
    two_n = 2.0 * geo[0]
    k1, k2, k3, k4 = np.empty(size), np.empty(size), np.empty(size), np.empty(size)
    tmp, f_mid, f_end = np.empty(size), np.empty(6), np.empty(6)
    for m in range(members):
        _record(state[m], 0.0, u0[m], geo, inertia, records[0, :, m])
    steps = 0
    for j in range(n_samples):
        fastest = two_n
        for m in range(members):
            w0, w1, w2 = state[m, 4], state[m, 5], state[m, 6]
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
            x = state[m]
            u, lam = u0[m] + geo[0] * t, geo[10] + geo[11] * t
            cu, su, cl, sl = math.cos(u), math.sin(u), math.cos(lam), math.sin(lam)
            _field_trig(cu, su, cl, sl, geo, f_end)
            for s in range(n):
                _rhs(x, f_end, inertia, magnet, axes, volume, hc, bs, kk, k1)
                cu, su = cu * cdu - su * sdu, su * cdu + cu * sdu
                cl, sl = cl * cdl - sl * sdl, sl * cdl + cl * sdl
                _field_trig(cu, su, cl, sl, geo, f_mid)
                for i in range(size):
                    tmp[i] = x[i] + half * k1[i]
                _rhs(tmp, f_mid, inertia, magnet, axes, volume, hc, bs, kk, k2)
                for i in range(size):
                    tmp[i] = x[i] + half * k2[i]
                _rhs(tmp, f_mid, inertia, magnet, axes, volume, hc, bs, kk, k3)
                cu, su = cu * cdu - su * sdu, su * cdu + cu * sdu
                cl, sl = cl * cdl - sl * sdl, sl * cdl + cl * sdl
                _field_trig(cu, su, cl, sl, geo, f_end)
                for i in range(size):
                    tmp[i] = x[i] + h * k3[i]
                _rhs(tmp, f_end, inertia, magnet, axes, volume, hc, bs, kk, k4)
                for i in range(size):
                    x[i] = x[i] + h / 6.0 * (k1[i] + 2.0 * (k2[i] + k3[i]) + k4[i])
                norm = math.sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2] + x[3] * x[3])
                for i in range(4):
                    x[i] /= norm
            _record(x, interval * (j + 1), u0[m], geo, inertia, records[j + 1, :, m])
        steps += n
    return steps
