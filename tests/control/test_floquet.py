"""magbench.control.floquet: multipliers, finite-difference monodromy and the degree of
stability against closed forms (constant systems, Liouville's formula, the Mathieu
equation's known stability)."""

import numpy as np
import pytest
from numpy.testing import assert_allclose
from scipy.integrate import solve_ivp
from scipy.linalg import expm

from magbench.control import degree_of_stability, finite_difference_monodromy, floquet_multipliers


def test_constant_system_multipliers_are_exponentials_of_the_eigenvalues():
    a = np.array([[0.0, 1.0, 0.0], [-4.0, -0.3, 0.2], [0.1, 0.0, -1.0]])
    period = 2.0
    rho = floquet_multipliers(expm(a * period))
    expected = np.exp(np.linalg.eigvals(a) * period)
    # expm and eig: rounding only (a conjugate pair has no order by modulus: compare as sets)
    assert_allclose(np.sort_complex(rho), np.sort_complex(expected), rtol=1e-12)
    assert np.all(np.diff(np.abs(rho)) <= 0)


def test_multipliers_broadcast_over_leading_axes():
    m = np.stack([np.diag([0.5, 2.0]), np.diag([-3.0, 0.1])])
    assert_allclose(np.abs(floquet_multipliers(m)), [[2.0, 0.5], [3.0, 0.1]])


def _mathieu_flow(delta, eps, damping=0.0):
    def rhs(t, y):
        x, v = y[:2], y[2:]
        return np.concatenate([v, -(delta + eps * np.cos(t)) * x - 2 * damping * v])

    def flow(states):
        out = []
        for s in states:
            y = solve_ivp(lambda t, y: rhs(t, y), (0, 2 * np.pi), [s[0], 0.0, s[1], 0.0], method="DOP853",
                          rtol=1e-12, atol=1e-14).y[:, -1]
            out.append([y[0], y[2]])
        return np.array(out)

    return flow


def test_finite_difference_monodromy_of_a_linear_flow_is_exact():
    m = np.array([[1.0, 2.0], [-0.5, 0.3]])
    fd = finite_difference_monodromy(lambda xs: xs @ m.T, np.array([0.2, -0.1]), 1e-3)
    assert_allclose(fd, m, rtol=1e-12)                           # linear: differences are exact up to rounding


def test_mathieu_equation_liouville_and_known_stability():
    """x'' + 2ζx' + (δ + ε cos t)x = 0: det Φ(2π) = exp(−4πζ) (Liouville); δ = 0.25 + small
    ε sits in the first resonance tongue (unstable), δ = 0.6 between tongues (stable)."""
    for delta, unstable in ((0.25, True), (0.6, False)):
        phi = finite_difference_monodromy(_mathieu_flow(delta, 0.1, 0.0), np.zeros(2), 1e-4)
        rho = floquet_multipliers(phi)
        # Liouville without damping: det = 1 (integrator error at rtol 1e-12, linear flow)
        assert_allclose(np.prod(rho).real, 1.0, rtol=1e-9)
        assert bool(np.abs(rho[0]) > 1 + 1e-3) is unstable
    phi = finite_difference_monodromy(_mathieu_flow(0.6, 0.1, 0.05), np.zeros(2), 1e-4)
    assert_allclose(np.linalg.det(phi), np.exp(-4 * np.pi * 0.05), rtol=1e-9)


def test_degree_of_stability():
    rho = np.array([0.1424, 0.05, 1e-3])
    assert_allclose(degree_of_stability(rho, 2 * np.pi), -np.log(0.1424) / (2 * np.pi), rtol=1e-15)
    assert degree_of_stability([1.5, 0.2], 1.0) < 0


@pytest.mark.parametrize("call, name", [
    (lambda: floquet_multipliers(np.ones((2, 3))), "monodromy"),
    (lambda: finite_difference_monodromy(lambda x: x, np.zeros((2, 2)), 1e-3), "state"),
    (lambda: finite_difference_monodromy(lambda x: x, np.zeros(2), 0.0), "step"),
    (lambda: finite_difference_monodromy(lambda x: x[:, :1], np.zeros(2), 1e-3), "flow"),
    (lambda: degree_of_stability([0.5], -1.0), "period"),
])
def test_bad_input_names_the_parameter(call, name):
    with pytest.raises(ValueError, match=name):
        call()
