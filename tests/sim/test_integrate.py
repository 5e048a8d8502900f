"""magbench.integrate: the fixed-step RK4 step and the checked adaptive solve."""

import numpy as np
from numpy.testing import assert_allclose

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


def test_adaptive_solve_matches_the_closed_form_and_raises_when_the_solver_stops():
    import pytest

    from magbench.integrate import solve_adaptive

    sol = solve_adaptive(lambda t, x, k: -k * x, (0.0, 2.0), [1.0], args=(0.5,), rtol=1e-11, atol=1e-14)
    assert_allclose(sol.y[0, -1], np.exp(-1.0), rtol=1e-10)     # DOP853 at rtol 1e-11
    # x' = x² from x(0) = 1 blows up at t = 1: the solver stops short of t = 2, and says so
    stopped = r"DOP853 integration stopped at t = (0\.9\d*|1) of \(0, 2\): Required step size"
    with pytest.raises(RuntimeError, match=stopped):
        solve_adaptive(lambda t, x: x * x, (0.0, 2.0), [1.0])
