"""magbench.dynamics.planar: the pitch equation's terms against the 3-D torques they come from."""

import numpy as np
import pytest
from numpy.testing import assert_allclose

from magbench.dynamics import (PlanarBody, PlanarDamper, gravity_gradient_torque, magnetic_torque, planar_energy,
                               planar_gravity_torque, planar_rhs)

THETA = np.linspace(-4.0, 4.0, 81)


def _plane(angle):
    """Unit vectors of the orbit plane: x0 along track, n the nadir, and the orbit normal
    h = x0 × n (= r × v); the body axis x at ``angle`` from x0 toward n."""
    x0, n = np.array([1.0, 0.0, 0.0]), np.array([0.0, 0.0, -1.0])
    x = np.cos(angle)[:, None] * x0 + np.sin(angle)[:, None] * n
    return x0, n, np.cross(x0, n), x


def test_gravity_torque_is_the_3d_gravity_gradient_about_the_orbit_normal():
    """(6.38) against dynamics.gravity_gradient_torque = 3n² r̂ × J r̂ (Kovalenko (4.18)),
    for an axisymmetric body: J_axial along x, J_transverse across."""
    j_axial, j_transverse, n = 250.0, 650.0, 1e-3
    x0, nadir, normal, x = _plane(THETA)
    z = np.cross(x, np.broadcast_to(-normal, x.shape))   # in-plane transverse axis, y = −normal
    y = np.broadcast_to(-normal, x.shape)
    body = np.stack([x, y, z], axis=-2)                   # rows: body axes in plane components
    radial_body = np.einsum("kij,j->ki", body, -nadir)
    torque_body = gravity_gradient_torque(radial_body, [j_axial, j_transverse, j_transverse], n)
    about_normal = np.einsum("ki,kij,j->k", torque_body, body, normal)
    # Same formula through a different path: rounding of products of size 3n²J ≈ 2e-3.
    assert_allclose(about_normal, planar_gravity_torque(THETA, n, j_transverse - j_axial), atol=1e-17)


def test_magnetic_torque_is_minus_lb_sin_gamma():
    """(6.42): the magnet L x̂ in B at γ from x, about the orbit normal: −L B sin γ."""
    eta = 0.3
    x0, nadir, normal, x = _plane(eta + THETA)
    b = 2e-5 * (np.cos(eta) * x0 + np.sin(eta) * nadir)
    torque = magnetic_torque(500.0 * x, b) @ normal
    # Rounding of L·B ≈ 1e-2.
    assert_allclose(torque, -500.0 * 2e-5 * np.sin(THETA), atol=1e-17)


def _state(gamma, rate, gamma1=0.0):
    return np.stack(np.broadcast_arrays(gamma, rate, gamma1), axis=-1)


def test_rhs_terms():
    body = PlanarBody(650.0, 500.0, 400.0)
    n, b, eta, eta_acc = 1e-3, 2e-5, 0.4, -2e-6
    gamma, rate = np.array([0.0, 0.2, -1.0]), np.array([0.0, 1e-3, -2e-3])
    out = planar_rhs(_state(gamma, rate), eta, eta_acc, b, n, body, PlanarDamper(viscous=0.2))
    expected = (-500 * b * np.sin(gamma) + 1.5 * n**2 * 400 * np.sin(2 * (eta + gamma)) - 0.2 * rate) / 650 - eta_acc
    # The same sum written out; rounding only.
    assert_allclose(out[:, 1], expected, rtol=1e-14, atol=1e-20)
    assert_allclose(out[:, 0], rate, rtol=0)
    assert_allclose(out[:, 2], 0.0, atol=0)


def test_dry_friction_is_a_smoothed_sign():
    body, n = PlanarBody(150.0, 0.0), 1e-3
    rate = np.array([-1e-3, -1e-5, 1e-5, 1e-3])
    damper = PlanarDamper(friction=3e-4, friction_rate=1e-6)
    out = planar_rhs(_state(0.0, rate), 0.0, 0.0, 2e-5, n, body, damper)
    # |γ̇| ≥ 10 ε: tanh(10) = 1 − 4e-9.
    assert_allclose(out[:, 1], -3e-4 * np.sign(rate) / 150.0, rtol=1e-8)
    # Below ε the torque goes smoothly through zero (no chattering sign).
    small = planar_rhs(_state(0.0, [1e-7]), 0.0, 0.0, 2e-5, n, body, damper)[0, 1]
    assert_allclose(small, -3e-4 * np.tanh(0.1) / 150.0, rtol=1e-14)


def test_elastic_damper_obeys_6_44():
    """c(γ − γ1) + k_д(γ̇ − γ̇1) = L_y B sin γ1, and the coupling's torque on the body."""
    body = PlanarBody(150.0, 0.0)
    damper = PlanarDamper(viscous=0.05, stiffness=4e-3, damper_moment=120.0)
    b = 2.2e-5
    state = _state(np.array([0.1, -0.3]), np.array([1e-3, 2e-4]), np.array([0.05, 0.1]))
    out = planar_rhs(state, 0.0, 0.0, b, 1e-3, body, damper)
    g, w, g1, w1 = state[:, 0], state[:, 1], state[:, 2], out[:, 2]
    # (6.44), rounding of terms ≈ 3e-3.
    assert_allclose(4e-3 * (g - g1) + 0.05 * (w - w1), 120.0 * b * np.sin(g1), atol=1e-17)
    # The body feels −c(γ − γ1) − k_д(γ̇ − γ̇1) (6.43).
    assert_allclose(out[:, 1] * 150.0, -4e-3 * (g - g1) - 0.05 * (w - w1), atol=1e-17)


def test_energy_integral():
    # E = Jγ̇²/2 + LB(1 − cos γ): zero at rest along B, LB(1 − cos γ0) at rest at γ0.
    assert planar_energy(0.0, 0.0, 650.0, 500.0, 2e-5) == 0.0
    assert_allclose(planar_energy(1.0, 0.0, 650.0, 500.0, 2e-5), 1e-2 * (1 - np.cos(1.0)), rtol=1e-15)


def test_members_broadcast():
    body = PlanarBody(np.array([100.0, 200.0]), 500.0)
    out = planar_rhs(_state(np.array([0.1, 0.1]), 0.0), 0.0, 0.0, 2e-5, 1e-3, body, PlanarDamper())
    # Torque −LB sin γ over each member's J, rounding only.
    assert_allclose(out[:, 1], -1e-2 * np.sin(0.1) / np.array([100.0, 200.0]), rtol=1e-14)


@pytest.mark.parametrize("make, match", [
    (lambda: PlanarBody(-1.0, 1.0), "inertia"),
    (lambda: PlanarBody(1.0, -1.0), "moment"),
    (lambda: PlanarDamper(viscous=-0.1), "viscous"),
    (lambda: PlanarDamper(damper_moment=10.0), "viscous must be > 0"),
    (lambda: PlanarDamper(viscous=0.1, friction=1e-4, damper_moment=10.0), "friction must be 0"),
    (lambda: PlanarDamper(stiffness=1e-3), "stiffness"),
    (lambda: PlanarDamper(friction_rate=0.0), "friction_rate"),
    (lambda: planar_rhs([0.0, 0.0], 0.0, 0.0, 2e-5, 1e-3, PlanarBody(1.0, 1.0), PlanarDamper()), "state"),
    (lambda: planar_rhs([0.0, 0.0, 0.0], 0.0, 0.0, 0.0, 1e-3, PlanarBody(1.0, 1.0), PlanarDamper()), "field_b"),
    (lambda: planar_rhs([0.0, 0.0, 0.0], 0.0, 0.0, 1e-5, 1e-3, (1.0, 1.0, 0.0), PlanarDamper()), "body"),
])
def test_bad_input_is_refused_by_name(make, match):
    with pytest.raises(ValueError, match=match):
        make()
