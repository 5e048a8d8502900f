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


def _friction_states():
    """States of the elastic dry-friction damper on both sides of the stick limit |g| = M_T:
    g = L_y B sin γ1 − c(γ − γ1) within ±1.1e-3 N·m against M_T = 3e-4 N·m."""
    rng = np.random.default_rng(48)
    return _state(rng.uniform(-0.1, 0.1, 200), rng.uniform(-2e-3, 2e-3, 200), rng.uniform(-0.1, 0.1, 200))


def test_elastic_damper_without_friction_is_unchanged():
    """M_T = 0 gives the viscous elastic damper's γ̇1 = γ̇ + [c(γ − γ1) − L_y B sin γ1]/k_д bit for bit."""
    state, b = _friction_states(), 2.2e-5
    out = planar_rhs(state, 0.3, 1e-6, b, 1e-3, PlanarBody(150.0, 0.0),
                     PlanarDamper(viscous=0.05, stiffness=4e-3, damper_moment=120.0))
    g, w, g1 = state[:, 0], state[:, 1], state[:, 2]
    # The formula before dry friction was added, evaluated in its order: equal to the last bit.
    np.testing.assert_array_equal(out[:, 2], w + (4e-3 * (g - g1) - 120.0 * b * np.sin(g1)) / 0.05)


def test_elastic_dry_friction_sticks_below_m_t_and_slips_beyond():
    """c(γ − γ1) + k_д s + M_T sign s = L_y B sin γ1 with s = γ̇ − γ̇1 (sign s ∈ [−1, 1] at s = 0)."""
    state, b, mt, kd = _friction_states(), 2.2e-5, 3e-4, 1e-2
    damper = PlanarDamper(viscous=kd, friction=mt, stiffness=4e-3, damper_moment=120.0)
    out = planar_rhs(state, 0.0, 0.0, b, 1e-3, PlanarBody(150.0, 0.0), damper)
    g, w, g1 = state[:, 0], state[:, 1], state[:, 2]
    drive = 120.0 * b * np.sin(g1) - 4e-3 * (g - g1)
    slip = w - out[:, 2]
    stuck = np.abs(drive) <= mt
    assert 20 < stuck.sum() < 180                 # both regimes are exercised
    # Stuck: the magnet turns with the body exactly (γ̇1 = γ̇, s = 0).
    np.testing.assert_array_equal(slip[stuck], 0.0)
    # Slipping: (6.44) with M_T sign s; rounding of terms ≈ 3e-3 N·m.
    assert_allclose((4e-3 * (g - g1) + kd * slip + mt * np.sign(slip))[~stuck], (120.0 * b * np.sin(g1))[~stuck],
                    atol=1e-17)
    # The body still feels the magnet's torque −L_y B sin γ1 (rounding only).
    assert_allclose(out[:, 1] * 150.0, -120.0 * b * np.sin(g1), atol=1e-18)


def test_elastic_dry_friction_never_adds_energy():
    """In a fixed field (η̈ = 0, ΔJ = 0) the power of the damper on body + magnet + spring,
    d/dt[Jγ̇²/2 + LB(1 − cos γ) + L_yB(1 − cos γ1) + c(γ − γ1)²/2], is −(k_д s² + M_T|s|) ≤ 0."""
    state, b, mt, kd, c, ly, j, m = _friction_states(), 2.2e-5, 3e-4, 1e-2, 4e-3, 120.0, 150.0, 30.0
    out = planar_rhs(state, 0.0, 0.0, b, 1e-3, PlanarBody(j, m),
                     PlanarDamper(viscous=kd, friction=mt, stiffness=c, damper_moment=ly))
    g, w, g1 = state[:, 0], state[:, 1], state[:, 2]
    w1, acc = out[:, 2], out[:, 1]
    power = j * w * acc + m * b * np.sin(g) * w + ly * b * np.sin(g1) * w1 + c * (g - g1) * (w - w1)
    slip = w - w1
    # Terms ≈ 1e-5 W cancel: rounding ≈ 1e-21 W.
    assert_allclose(power, -(kd * slip**2 + mt * np.abs(slip)), atol=1e-20)
    assert np.all(power <= 1e-20) and np.any(power < -1e-8)


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
    (lambda: PlanarDamper(friction=1e-4, stiffness=1e-3, damper_moment=10.0), "viscous must be > 0"),
    (lambda: PlanarDamper(stiffness=1e-3), "stiffness"),
    (lambda: PlanarDamper(friction_rate=0.0), "friction_rate"),
    (lambda: planar_rhs([0.0, 0.0], 0.0, 0.0, 2e-5, 1e-3, PlanarBody(1.0, 1.0), PlanarDamper()), "state"),
    (lambda: planar_rhs([0.0, 0.0, 0.0], 0.0, 0.0, 0.0, 1e-3, PlanarBody(1.0, 1.0), PlanarDamper()), "field_b"),
    (lambda: planar_rhs([0.0, 0.0, 0.0], 0.0, 0.0, 1e-5, 1e-3, (1.0, 1.0, 0.0), PlanarDamper()), "body"),
])
def test_bad_input_is_refused_by_name(make, match):
    with pytest.raises(ValueError, match=match):
        make()
