"""The axisymmetric body: the Euler case against rk4_step, L and nutation, the conical relation."""

import numpy as np
import pytest
from numpy.testing import assert_allclose
from scipy.spatial.transform import Rotation

from magbench.dynamics import (axial_magnet_torque, body_rate_from_momentum, conical_rotation_angle,
                               conical_rotation_rate, euler_case_matrix, euler_case_rates, euler_rates,
                               hysteresis_rod_moment, magnetic_torque, momentum_and_nutation, quaternion_rate)
from magbench.sim import rk4_step

A, C = 0.0406, 0.00625  # the uniform cylinder of data/tns0/params.toml (ours)


def _torque_free(t, x):
    q, w = x[:4], x[4:]
    return np.concatenate([quaternion_rate(q, w), euler_rates(w, np.zeros(3), [A, A, C])])


def test_euler_case_is_the_torque_free_motion():
    big_l, theta, phi0 = 0.0936, 1.086, 0.4   # Table 1 row 1's L and nutation
    r0 = euler_case_matrix(0.0, big_l, theta, A, C, initial_proper_rotation=phi0)
    x = np.concatenate([Rotation.from_matrix(r0).as_quat(scalar_first=True),
                        body_rate_from_momentum(big_l, theta, A, C, phi0)])
    h, steps = 0.002, 2500                      # 5 s, h·|ω| ≈ 0.015
    energy0 = 0.5 * np.sum(np.array([A, A, C]) * x[4:] ** 2)
    for k in range(steps):
        x = rk4_step(_torque_free, k * h, x, h)
    r_num = Rotation.from_quat(x[:4] / np.linalg.norm(x[:4]), scalar_first=True).as_matrix()
    r_exact = euler_case_matrix(steps * h, big_l, theta, A, C, initial_proper_rotation=phi0)
    assert_allclose(r_num, r_exact, atol=1e-8)  # RK4 O(h⁴) over 2500 steps at h·ω = 0.015
    big_l_num, theta_num = momentum_and_nutation(x[4:], A, C)
    assert_allclose([big_l_num, theta_num], [big_l, theta], rtol=1e-10)  # conserved to RK4's local error
    assert_allclose(0.5 * np.sum(np.array([A, A, C]) * x[4:] ** 2), energy0, rtol=1e-10)  # same


def test_rates_of_the_flat_spin():
    psi_rate, phi_rate = euler_case_rates(0.0644, np.pi / 2, A, C)
    assert_allclose([psi_rate, phi_rate], [0.0644 / A, 0.0], atol=1e-14)  # cos(π/2) = 6e-17, times L(1/C − 1/A)


def test_momentum_and_nutation_round_trip():
    big_l = np.array([0.0936, 0.017, 7.2e-4])
    theta = np.array([1.086, np.pi / 2, 0.85])
    w = body_rate_from_momentum(big_l, theta, A, C, [0.0, 1.0, 2.0])
    assert_allclose(momentum_and_nutation(w, A, C), [big_l, theta], rtol=1e-14)  # algebraic inverse


def test_conical_relation_both_ways():
    b, m = 35e-6, 0.35
    angle = np.radians([10.0, 45.0, 80.0])
    rate = conical_rotation_rate(angle, b, m, A, C)
    assert_allclose(rate**2 * (A - C) * np.cos(angle), m * b, rtol=1e-14)  # the relation itself
    assert_allclose(conical_rotation_angle(rate, b, m, A, C), angle, rtol=1e-12)  # inverse
    slow = np.sqrt(m * b / (A - C)) * 0.9  # below the rate at θ′ = 0: the magnet simply aligns
    assert np.isnan(conical_rotation_angle(slow, b, m, A, C))


def test_magnet_and_rod_torques():
    b = np.array([1e-5, -2e-5, 3e-5])
    assert_allclose(axial_magnet_torque(0.35, b), magnetic_torque([0, 0, 0.35], b), rtol=1e-15)  # same law
    m = hysteresis_rod_moment([0.01, -0.02], [[2.0, 0, 0], [0, 1.0, 0]], 2.4e-6)
    assert_allclose(m, [0.01 * 2.4e-6 / (4e-7 * np.pi), -0.02 * 2.4e-6 / (4e-7 * np.pi), 0.0], rtol=1e-9)  # μ0 of 2019 SI


def test_bad_input_is_refused():
    with pytest.raises(ValueError, match="nutation must lie in"):
        euler_case_rates(0.1, 4.0, A, C)
    with pytest.raises(ValueError, match="axial_inertia must be <= 2"):
        euler_case_rates(0.1, 1.0, 0.01, 0.03)
    with pytest.raises(ValueError, match="rotation_rate must be non-zero"):
        conical_rotation_angle(0.0, 3e-5, 0.35, A, C)
