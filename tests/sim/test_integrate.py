"""magbench.integrate: the fixed-step RK4 step and the checked adaptive solve."""

import numpy as np
from numpy.testing import assert_allclose

from numba import njit

from magbench._rk4_kernel import rk4_advance
from magbench.dynamics import Mockup, mockup_rhs
from magbench.sim import rk4_step


def test_rk4_is_fourth_order_on_the_harmonic_oscillator():
    def rhs(t, x):
        return np.array([x[1], -x[0]])

    errors = []
    for n in (50, 100):
        x, h = np.array([1.0, 0.0]), 1.0 / n
        for k in range(n):
            x = rk4_step(rhs, k * h, x, h)
        errors.append(abs(x[0] - np.cos(1.0)))
    assert 14.0 < errors[0] / errors[1] < 18.0          # 2^4 = 16


def test_rk4_uses_time_and_passes_args():
    # x' = a t^3 is integrated exactly by RK4 (Simpson's rule).
    x = rk4_step(lambda t, x, a: a * t**3 * np.ones_like(x), 1.0, np.zeros(1), 0.5, args=(4.0,))
    assert_allclose(x, [1.5**4 - 1.0], rtol=1e-14)


def _old_bench_step(psi, omega, m1, m2, h, b0, j, kappa, neutral):
    # The bench's component-wise RK4 before the one rk4_step (magbench 37e46d7).
    def acc(p, w):
        return (-b0 * (m1 * np.sin(p) + m2 * np.cos(p)) - kappa * (p - neutral)) / j

    k1p, k1w = omega, acc(psi, omega)
    k2p = omega + 0.5 * h * k1w
    k2w = acc(psi + 0.5 * h * k1p, k2p)
    k3p = omega + 0.5 * h * k2w
    k3w = acc(psi + 0.5 * h * k2p, k3p)
    k4p = omega + h * k3w
    k4w = acc(psi + h * k3p, k4p)
    return (psi + h / 6.0 * (k1p + 2.0 * (k2p + k3p) + k4p),
            omega + h / 6.0 * (k1w + 2.0 * (k2w + k3w) + k4w))


def test_rk4_on_the_mock_up_is_bit_for_bit_the_bench_step_it_replaced():
    rng = np.random.default_rng(5)
    psi, omega = rng.uniform(-3, 3, 64), rng.normal(0, 0.1, 64)
    m1, m2, kappa = rng.uniform(-0.5, 0.5, 64), rng.uniform(-0.5, 0.5, 64), rng.uniform(0, 1e-5, 64)
    plant = Mockup(0.005, 3.3e-4, thread_stiffness=kappa, thread_neutral_angle=0.2)
    new = rk4_step(mockup_rhs, 0.0, np.array([psi, omega]), 0.01, args=((m1, m2), plant))
    old = _old_bench_step(psi, omega, m1, m2, 0.01, 3.3e-4, 0.005, kappa, 0.2)
    assert np.array_equal(new[0], old[0]) and np.array_equal(new[1], old[1])


def _damped_pendulum_rates(t, x, damping, drive):
    # (angle, rate) over members on the last axis, with a time-dependent drive
    return np.stack((x[1], -np.sin(x[0]) - damping * x[1] + drive * np.cos(t)))


@njit(error_model="numpy")
def _damped_pendulum_rates_into(t, x, out, damping, drive):
    for m in range(x.shape[1]):
        out[0, m] = x[1, m]
        out[1, m] = -np.sin(x[0, m]) - damping[m] * x[1, m] + drive * np.cos(t)


@njit(error_model="numpy")
def _compiled_steps(x, n, h, args):
    stages = np.empty((5,) + x.shape)
    for k in range(n):
        rk4_advance(_damped_pendulum_rates_into, k * h, x, h, args, stages)
    return x


def test_compiled_rk4_twin_is_bit_for_bit_the_numpy_step():
    # The compiled simulation loops take their steps with the twin; its stages must be the
    # numpy step's operations in the same order (no fast-math), so equal to the last bit.
    rng = np.random.default_rng(7)
    x0 = np.stack((rng.uniform(-3, 3, 16), rng.normal(0, 0.5, 16)))
    args = (rng.uniform(0, 0.3, 16), 0.4)
    x = x0
    for k in range(200):
        x = rk4_step(_damped_pendulum_rates, k * 0.05, x, 0.05, args=args)
    assert np.array_equal(_compiled_steps(x0.copy(), 200, 0.05, args), x)


def test_adaptive_solve_matches_the_closed_form_and_raises_when_the_solver_stops():
    import pytest

    from magbench.integrate import solve_adaptive

    sol = solve_adaptive(lambda t, x, k: -k * x, (0.0, 2.0), [1.0], args=(0.5,), rtol=1e-11, atol=1e-14)
    assert_allclose(sol.y[0, -1], np.exp(-1.0), rtol=1e-10)     # DOP853 at rtol 1e-11
    # x' = x² from x(0) = 1 blows up at t = 1: the solver stops short of t = 2, and says so
    stopped = r"DOP853 integration stopped at t = (0\.9\d*|1) of \(0, 2\): Required step size"
    with pytest.raises(RuntimeError, match=stopped):
        solve_adaptive(lambda t, x: x * x, (0.0, 2.0), [1.0])


# The compiled DOP853 twin (engine="compiled"): the same method as solve_ivp's, summed in
# order instead of by BLAS. Where the error estimate is far above rounding the two take
# the same steps; both are held to the closed form and to each other at the tolerance.

def _oscillator():
    from numba import njit

    @njit
    def rhs(t, x, omega):
        out = np.empty(2)
        out[0] = x[1]
        out[1] = -omega * omega * x[0]
        return out

    return rhs


def test_compiled_dop853_meets_the_closed_form_and_scipy_on_the_same_samples():
    from magbench.integrate import solve_adaptive

    rhs, times = _oscillator(), np.linspace(0.0, 20.0, 201)
    runs = {engine: solve_adaptive(rhs, (0.0, 20.0), [1.0, 0.0], args=(2.0,), t_eval=times, rtol=1e-10,
                                   atol=1e-12, engine=engine) for engine in ("compiled", "scipy")}
    compiled, scipy_run = runs["compiled"], runs["scipy"]
    assert_allclose(compiled.t, times, rtol=0, atol=0)
    # 40 periods at rtol 1e-10: the global error grows to a few 1e-9 (DOP853's own, in both)
    assert_allclose(compiled.y[0], np.cos(2.0 * times), atol=2e-8)
    assert_allclose(compiled.y, scipy_run.y, atol=2e-8)
    # the same method: the step count agrees within a few rejected or re-sized steps
    assert abs(compiled.nfev - scipy_run.nfev) <= 0.02 * scipy_run.nfev


def test_compiled_dop853_takes_scipys_steps_when_the_error_is_above_rounding():
    from magbench.integrate import solve_adaptive

    rhs = _oscillator()
    # rtol 1e-6: the same accepted steps; their ends differ by 2e-10 (the first steps' error
    # estimates are near rounding, and a step factor is err^(−1/8) of them)
    compiled, scipy_run = (solve_adaptive(rhs, (0.0, 10.0), [1.0, 0.0], args=(2.0,), rtol=1e-6, atol=1e-9,
                                          engine=engine) for engine in ("compiled", "scipy"))
    assert compiled.nfev == scipy_run.nfev and compiled.t.size == scipy_run.t.size
    assert compiled.t[0] == 0.0 and compiled.t[-1] == 10.0
    assert_allclose(compiled.t, scipy_run.t, rtol=1e-9)
    # 1e-9: three orders below the global error of either (1e-6 against cos 2t)
    assert_allclose(compiled.y, scipy_run.y, rtol=0, atol=1e-9)


def test_compiled_dop853_on_the_rotor_loop_equals_scipy_to_rounding():
    import math

    from magbench.chapters import ch06_rotor
    from magbench.sim import spinning

    sat, orbit = ch06_rotor.default_rotor_satellite(), ch06_rotor.default_rotor_orbit()
    runs = {}
    for engine in ("compiled", "scipy"):
        spinning._ADAPTIVE_ENGINE = engine
        try:
            runs[engine] = spinning.simulate_rotor(sat, orbit, 0.3 * orbit.period, sample_interval=30.0,
                                                   initial_angles=(math.radians(20.0), math.radians(-15.0), 0.0))
        finally:
            spinning._ADAPTIVE_ENGINE = "compiled"
    compiled, scipy_run = runs["compiled"], runs["scipy"]
    assert compiled.inputs["nfev"] == scipy_run.inputs["nfev"]       # the same steps
    # rtol 1e-8 per step; the two differ by rounding carried along: 1e-10 rad is 1e4 ulps of π
    assert_allclose(compiled.angles, scipy_run.angles, rtol=0, atol=1e-10)
    assert_allclose(compiled.omega, scipy_run.omega, rtol=0, atol=1e-12)


def test_compiled_dop853_refuses_what_only_scipy_offers_and_raises_when_it_stops():
    import pytest
    from numba import njit

    from magbench.integrate import solve_adaptive

    rhs = _oscillator()
    with pytest.raises(ValueError, match="method='RK45'"):
        solve_adaptive(rhs, (0.0, 1.0), [1.0, 0.0], args=(1.0,), method="RK45", engine="compiled")
    with pytest.raises(ValueError, match="accepts only t_eval, max_step, first_step, got events"):
        solve_adaptive(rhs, (0.0, 1.0), [1.0, 0.0], args=(1.0,), events=lambda t, x, w: x[0], engine="compiled")
    with pytest.raises(ValueError, match="numba"):
        solve_adaptive(lambda t, x: -x, (0.0, 1.0), [1.0], engine="compiled")
    with pytest.raises(ValueError, match="forward"):
        solve_adaptive(rhs, (1.0, 0.0), [1.0, 0.0], args=(1.0,), engine="compiled")
    with pytest.raises(ValueError, match="engine must be"):
        solve_adaptive(rhs, (0.0, 1.0), [1.0, 0.0], args=(1.0,), engine="fortran")

    @njit
    def blow_up(t, x):
        return x * x

    # x' = x² from 1 leaves every float before t = 1, as in the scipy test above
    with pytest.raises(RuntimeError, match=r"DOP853 integration stopped at t = (0\.9\d*|1) of \(0, 2\)"):
        solve_adaptive(blow_up, (0.0, 2.0), [1.0], engine="compiled")
