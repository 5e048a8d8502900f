r"""Compiled (numba) twin of :func:`scipy.integrate.solve_ivp` with ``method="DOP853"``: the
same tableau (scipy's ``DOP853`` class attributes), initial step, step control, error norm,
dense output and ``t_eval`` sampling, one step after another in scalar code.

Why compiled: a rotor run of chapter 6 takes ~10⁵ steps, and scipy spends ~80 µs of Python
and small-array overhead on each (twelve right-hand sides and their sums), against ~1 µs of
arithmetic. Not bit for bit: scipy sums the stages with BLAS (``np.dot``, which fuses
multiply-adds and reorders the sums); this kernel sums them in order. Both are the same
method; the results agree to rounding, and the tests hold them to it
(``tests/test_integrate.py``).

Not cached on disk: numba keys a function that takes another function on that function's
identity, which is new in every process (a cache would only grow); the compilation takes
~5 s once per process and right-hand side.

Only forward integration with scalar tolerances; no events. :func:`magbench.integrate.solve_adaptive`
checks that and is the only caller.
"""

import math

import numpy as np
from numba import njit

__all__ = ["dop853"]

SAFETY = 0.9        # scipy.integrate._ivp.rk: the step factor's safety, bounds
MIN_FACTOR = 0.2
MAX_FACTOR = 10.0
ERROR_EXPONENT = -1.0 / 8.0   # −1/(error estimator order 7 + 1)
N_STAGES = 12


@njit(cache=True, error_model="numpy")
def _rms(x, scale):
    """‖x/scale‖₂/√n (scipy's ``common.norm``)."""
    acc = 0.0
    for i in range(x.size):
        v = x[i] / scale[i]
        acc += v * v
    return math.sqrt(acc) / math.sqrt(x.size)


@njit(cache=True, error_model="numpy")
def _stage_sum(K, a, s, h, y, out):
    """out = y + h Σ_{j<s} a_j K_j."""
    for i in range(y.size):
        acc = 0.0
        for j in range(s):
            acc += K[j, i] * a[j]
        out[i] = y[i] + acc * h


@njit(cache=True, error_model="numpy")
def _error_norm(K, E5, E3, y, y_new, rtol, atol, h):
    """scipy's ``DOP853._estimate_error_norm`` of the step just taken (stages in K)."""
    n = y.size
    n5 = 0.0
    n3 = 0.0
    for i in range(n):
        scale = atol + max(abs(y[i]), abs(y_new[i])) * rtol
        e5, e3 = 0.0, 0.0
        for j in range(N_STAGES + 1):
            e5 += K[j, i] * E5[j]
            e3 += K[j, i] * E3[j]
        e5, e3 = e5 / scale, e3 / scale
        n5 += e5 * e5
        n3 += e3 * e3
    n5, n3 = math.sqrt(n5) ** 2, math.sqrt(n3) ** 2      # scipy squares np.linalg.norm
    if n5 == 0.0 and n3 == 0.0:
        return 0.0
    return abs(h) * n5 / math.sqrt((n5 + 0.01 * n3) * n)


@njit(cache=True, error_model="numpy")
def _interpolant(K, D, y_old, y, f, h, F):
    """F of scipy's ``Dop853DenseOutput`` for the step (all 16 stages in K)."""
    for i in range(y.size):
        delta = y[i] - y_old[i]
        F[0, i] = delta
        F[1, i] = h * K[0, i] - delta
        F[2, i] = 2.0 * delta - h * (f[i] + K[0, i])
        for r in range(4):
            acc = 0.0
            for j in range(16):
                acc += D[r, j] * K[j, i]
            F[3 + r, i] = h * acc


@njit(cache=True, error_model="numpy")
def _interpolated(F, x, y_old, out):
    """The dense output at x = (t − t_old)/h (Horner in x and 1 − x, as scipy)."""
    for i in range(y_old.size):
        v = 0.0
        for r in range(7):
            v += F[6 - r, i]
            v *= x if r % 2 == 0 else 1.0 - x
        out[i] = v + y_old[i]


@njit(cache=True, error_model="numpy")
def _doubled(ts, ys):
    """The step buffers, twice as long (the first half copied)."""
    grown_t, grown_y = np.empty(2 * ts.size), np.empty((2 * ts.size, ys.shape[1]))
    grown_t[:ts.size] = ts
    grown_y[:ts.size] = ys
    return grown_t, grown_y


@njit(error_model="numpy")
def _initial_step(rhs, args, t0, y0, f0, t_bound, max_step, rtol, atol):
    """scipy's ``common.select_initial_step`` for order 7; returns (h, one function call)."""
    n = y0.size
    scale = np.empty(n)
    for i in range(n):
        scale[i] = atol + abs(y0[i]) * rtol
    interval = abs(t_bound - t0)
    d0, d1 = _rms(y0, scale), _rms(f0, scale)
    h0 = 1e-6 if (d0 < 1e-5 or d1 < 1e-5) else 0.01 * d0 / d1
    h0 = min(h0, interval)
    y1 = y0 + h0 * f0
    f1 = rhs(t0 + h0, y1, *args)
    d2 = _rms(f1 - f0, scale) / h0
    if d1 <= 1e-15 and d2 <= 1e-15:
        h1 = max(1e-6, h0 * 1e-3)
    else:
        h1 = (0.01 / max(d1, d2)) ** (1.0 / 8.0)
    return min(100.0 * h0, h1, interval, max_step)


@njit(error_model="numpy")
def dop853(rhs, args, t0, t_bound, y0, rtol, atol, max_step, first_step, t_eval, tableau):
    """Integrate rhs(t, y, *args) from t0 to t_bound (> t0); ``tableau`` is scipy's DOP853
    (A, B, C, E3, E5, D, A_EXTRA, C_EXTRA).

    Returns (times, states (k, n), status (0 finished, −1 step too small), nfev): the
    states at ``t_eval``, or at every step end (from t0) when ``t_eval`` is empty.
    """
    A, B, C, E3, E5, D, A_EX, C_EX = tableau
    n = y0.size
    every_step = t_eval.size == 0
    ts = np.empty(64 if every_step else t_eval.size)
    ys = np.empty((ts.size, n))
    count = 0
    if every_step:
        ts[0] = t0
        ys[0] = y0
        count = 1
    K = np.empty((16, n))
    F = np.empty((7, n))
    stage = np.empty(n)
    t = t0
    y = y0.copy()
    f = rhs(t, y, *args)
    nfev = 1
    if first_step > 0.0:
        h_abs = first_step
    else:
        h_abs = _initial_step(rhs, args, t0, y, f, t_bound, max_step, rtol, atol)
        nfev += 1
    status = 1
    next_eval = 0
    while status == 1:
        min_step = 10.0 * abs(np.nextafter(t, np.inf) - t)
        if h_abs > max_step:
            h_abs = max_step
        elif h_abs < min_step:
            h_abs = min_step
        accepted = False
        rejected = False
        y_new = y
        f_new = f
        t_new = t
        h = 0.0
        while not accepted:
            if h_abs < min_step:
                status = -1
                break
            h = h_abs
            t_new = t + h
            if t_new - t_bound > 0:
                t_new = t_bound
            h = t_new - t
            h_abs = abs(h)
            K[0] = f
            for s in range(1, N_STAGES):
                _stage_sum(K, A[s], s, h, y, stage)
                K[s] = rhs(t + C[s] * h, stage, *args)
            _stage_sum(K, B, N_STAGES, h, y, stage)
            y_new = stage.copy()
            f_new = rhs(t + h, y_new, *args)
            K[N_STAGES] = f_new
            nfev += N_STAGES
            error_norm = _error_norm(K, E5, E3, y, y_new, rtol, atol, h)
            if error_norm < 1.0:
                factor = MAX_FACTOR if error_norm == 0.0 else min(MAX_FACTOR, SAFETY * error_norm ** ERROR_EXPONENT)
                if rejected:
                    factor = min(1.0, factor)
                h_abs *= factor
                accepted = True
            else:
                h_abs *= max(MIN_FACTOR, SAFETY * error_norm ** ERROR_EXPONENT)
                rejected = True
        if status == -1:
            break
        t_old, y_old = t, y
        t, y, f = t_new, y_new, f_new
        if t - t_bound >= 0:
            status = 0
        if every_step:
            if count == ts.size:
                ts, ys = _doubled(ts, ys)
            ts[count] = t
            ys[count] = y
            count += 1
        elif next_eval < t_eval.size and t_eval[next_eval] <= t:
            # the dense output of the step (three more stages), as scipy's Dop853DenseOutput
            for s in range(N_STAGES + 1, 16):
                _stage_sum(K, A_EX[s - N_STAGES - 1], s, h, y_old, stage)
                K[s] = rhs(t_old + C_EX[s - N_STAGES - 1] * h, stage, *args)
            nfev += 3
            _interpolant(K, D, y_old, y, f, h, F)
            while next_eval < t_eval.size and t_eval[next_eval] <= t:
                _interpolated(F, (t_eval[next_eval] - t_old) / h, y_old, ys[next_eval])
                ts[next_eval] = t_eval[next_eval]
                next_eval += 1
            count = next_eval
    return ts[:count].copy(), ys[:count].copy(), status, t, nfev
