r"""Compiled (numba) twin of :func:`magbench.sim.bench.simulate_bench`'s sample loop: sensors,
filter, PID, allocation, PWM and the plant's RK4 step, members on the contiguous axis.

Why compiled: a sample of the numpy loop is ~150 small array operations, and at the bench's
one to a few hundred members numpy's per-call overhead (~300 µs a sample), not the
arithmetic, sets the pace. Each operation here is the numpy loop's, in the same order and
without fast-math, so the two give the same numbers to the last bit (the tests hold them to
it under every error source). One operation stays with numpy: the heading's arctan2, whose
float64 implementation in numpy differs from the C library's in the last bit for ~8 % of
arguments; the caller evaluates it between :func:`sense` and :func:`control_and_step`.

Per-member inputs come as the rows of one array ``member`` (:data:`ROWS`), with ``present``
saying which optional error sources are given: an absent source leaves the numpy loop's
arithmetic untouched, and so it does here. ``cache=True`` keeps the compiled code in
``__pycache__``.
"""

import math

import numpy as np
from numba import njit

from ..._rk4_kernel import rk4_advance

__all__ = ["ROWS", "sense", "control_and_step"]

#: Rows of ``member`` (each (M,)); the optional error sources are flagged in ``present``.
ROWS = ("psi_des", "field", "thread_stiffness", "thread_neutral_angle", "filter_coefficient", "pwm_levels",
        "full_1", "full_2", "gyro_offset", "gyro_drift", "magnetometer_misalignment", "heading_ripple",
        "matrix_00", "matrix_01", "matrix_10", "matrix_11", "coil_field_coupling", "offset_1", "offset_2",
        "field_azimuth", "axis_1x", "axis_1y", "axis_2x", "axis_2y")
(PSI_DES, FIELD, KAPPA, NEUTRAL, ALPHA, LEVELS, FULL_1, FULL_2, G_OFF, G_DRIFT, M_ROT, RIPPLE, M00, M01, M10, M11,
 COUPLING, OFF_1, OFF_2, AZIMUTH, AX_1X, AX_1Y, AX_2X, AX_2Y) = range(len(ROWS))
#: Flags in ``present``: which sources are given, and whether the duty is quantised.
(HAS_G_OFF, HAS_G_DRIFT, HAS_M_ROT, HAS_RIPPLE, HAS_MATRIX, HAS_COUPLING, HAS_OFFSET, HAS_AZIMUTH, HAS_AXES,
 QUANTISED) = range(10)
#: Scalars in ``setup``: sample interval, PID gains, moment limit, duty gains, inertia.
DT, KP, KI, KD, LIMIT, DUTY_1, DUTY_2, INERTIA = range(8)

_TWO_PI = 2.0 * np.pi
_HALF_OVER_PI = 0.5 / np.pi


@njit(cache=True, error_model="numpy")
def _wrap(angle):
    """magbench.rotations.wrap_angle, operation for operation."""
    return angle - _TWO_PI * np.rint(angle * _HALF_OVER_PI)


@njit(cache=True, error_model="numpy")
def sense(k, j, state, gyro_errors, magnetometer_errors, member, present, applied, dt, gyro, bxy):
    """The gyro and magnetometer readings of sample k (row j of the block's errors), into
    ``gyro`` (M,) and ``bxy`` (2, M)."""
    for m in range(state.shape[1]):
        psi = state[0, m]
        g = state[1, m] + gyro_errors[j, m]
        if present[HAS_G_OFF]:
            g = g + member[G_OFF, m]
        if present[HAS_G_DRIFT]:
            g = g + member[G_DRIFT, m] * (k * dt)
        b0 = member[FIELD, m]
        bx, by = b0 * math.cos(psi), -b0 * math.sin(psi)
        if present[HAS_M_ROT] or present[HAS_RIPPLE]:
            rot = member[M_ROT, m] if present[HAS_M_ROT] else 0.0
            rip = member[RIPPLE, m] * math.sin(2 * psi) if present[HAS_RIPPLE] else 0.0
            delta = rot + rip
            c, s = math.cos(delta), math.sin(delta)
            bx, by = bx * c + by * s, by * c - bx * s
        if present[HAS_MATRIX]:
            bx, by = member[M00, m] * bx + member[M01, m] * by, member[M10, m] * bx + member[M11, m] * by
        if present[HAS_COUPLING]:
            bx, by = bx + member[COUPLING, m] * applied[0, m], by + member[COUPLING, m] * applied[1, m]
        if present[HAS_OFFSET]:
            bx, by = bx + member[OFF_1, m], by + member[OFF_2, m]
        gyro[m] = g
        bxy[0, m], bxy[1, m] = bx + magnetometer_errors[j, m, 0], by + magnetometer_errors[j, m, 1]


@njit(cache=True, error_model="numpy")
def _quantised(duty, levels, quantised):
    return np.rint(duty * levels) / levels if quantised else duty


@njit(cache=True, error_model="numpy")
def _accel(psi, rate, a1, a2, b0, kappa, neutral, inertia):
    """mockup_rhs: (ψ̇, ω̇) with two_coil_torque and the thread."""
    torque = -b0 * (a1 * math.sin(psi) + a2 * math.cos(psi)) - kappa * (psi - neutral)
    return rate, torque / inertia


@njit(cache=True, error_model="numpy")
def plant_rates(time, x, out, applied, field, kappa, neutral, inertia):
    """(ψ̇, ω̇) of every member into out, x and out (2, M), the coils' body moments ``applied``
    (2, M) held: :func:`_accel` member by member."""
    for m in range(x.shape[1]):
        out[0, m], out[1, m] = _accel(x[0, m], x[1, m], applied[0, m], applied[1, m], field[m], kappa[m],
                                      neutral[m], inertia)


@njit(cache=True, error_model="numpy")
def control_and_step(k, heading, gyro, bxy, state, member, present, setup, memory, held, records, stride):
    """controller_step on the readings and the numpy ``heading``, the records, the error
    bands, and the plant's step over the sample with the new moments held (the library's
    compiled RK4, :func:`magbench._rk4_kernel.rk4_advance`, of :func:`plant_rates`).

    Grouped arrays (numba takes tuples of arrays; each is written in place): ``memory``
    (estimate, integral, band, band_est), each (M,); ``held`` (commanded, applied), the
    coils' moments and their body components, each (2, M); ``records`` (states, moments,
    estimates); ``stride`` (first sample in the error window, recording stride)."""
    estimate, integral, band, band_est = memory
    commanded, applied = held
    states, moments, estimates = records
    first_in_window, every = stride
    dt = setup[DT]
    for m in range(state.shape[1]):
        psi, rate = state[0, m], state[1, m]
        g, bx, by = gyro[m], bxy[0, m], bxy[1, m]
        h = heading[m]
        est = h if k == 0 else estimate[m]
        reference = est + _wrap(h - est)
        alpha = member[ALPHA, m]
        est = alpha * (est + g * dt) + (1.0 - alpha) * reference
        psi_des = member[PSI_DES, m]
        error = _wrap(psi_des - est)
        candidate = integral[m] + error * dt
        unsaturated = setup[KP] * error + setup[KI] * candidate + setup[KD] * -g
        u = np.minimum(np.maximum(unsaturated, -setup[LIMIT]), setup[LIMIT])   # np.clip, NaN and all
        if not (u != unsaturated and np.sign(setup[KI] * error) == np.sign(unsaturated)):
            integral[m] = candidate
        u_over_b = u / math.sqrt(bx * bx + by * by)
        levels, quantised = member[LEVELS, m], present[QUANTISED]
        m1 = _quantised(u_over_b * by * setup[DUTY_1], levels, quantised) * member[FULL_1, m]
        m2 = _quantised(u_over_b * bx * -setup[DUTY_2], levels, quantised) * member[FULL_2, m]
        estimate[m] = est
        if k % every == 0:
            i = k // every
            states[0, i, m], states[1, i, m], estimates[0, i, m] = psi, rate, est
            moments[0, i, m], moments[1, i, m] = m1, m2
        if k >= first_in_window:
            seen = psi + member[AZIMUTH, m] if present[HAS_AZIMUTH] else psi
            band[m] = np.maximum(band[m], abs(_wrap(seen - psi_des)))
            band_est[m] = np.maximum(band_est[m], abs(_wrap(est - psi_des)))
        if present[HAS_AXES]:
            a1 = m1 * member[AX_1X, m] + m2 * member[AX_2X, m]
            a2 = m1 * member[AX_1Y, m] + m2 * member[AX_2Y, m]
        else:
            a1, a2 = m1, m2
        commanded[0, m], commanded[1, m] = m1, m2
        applied[0, m], applied[1, m] = a1, a2
    plant = (applied, member[FIELD], member[KAPPA], member[NEUTRAL], setup[INERTIA])
    rk4_advance(plant_rates, k * dt, state, dt, plant, np.empty((5,) + state.shape))
