"""Spherical magnetic dampers (Kovalenko 1975 §5.4, eqs. (5.19)–(5.25)): a free ball coupled
to the body by viscous or dry friction loses energy at the closed-form rate and the pair keeps
its angular momentum; dry friction's discontinuity is explicit."""

import numpy as np
import pytest
from numpy.testing import assert_allclose

from magbench import dynamics
from magbench.integrate import rk4_step

J = np.array([0.04, 0.05, 0.06])   # kg·m², a small satellite (ours)
JD = 2e-3                          # kg·m², a 3 kg ball of Ø 13 cm: (2/5)·3·0.065² ≈ 5e-3 solid, less as a shell (ours)
K = 0.01                           # N·m·s/rad, 1 N·cm/(rad/s): inside the flown 0.7–16 (E01c)


def _energy_rate(state, rates, ball_inertia=JD):
    """d/dt(½ω·Jω + ½J_d|ω_d|²) from the rhs (ω_d·(ω × ω_d) = 0, so body-axis rates suffice)."""
    w, wd = state[..., :3], state[..., 3:]
    return np.sum(w * J * rates[..., :3], axis=-1) + ball_inertia * np.sum(wd * rates[..., 3:], axis=-1)


def test_viscous_coupling_loses_energy_at_k_times_the_relative_rate_squared():
    rng = np.random.default_rng(3)
    state = rng.normal(size=(40, 6))
    rel = state[:, 3:] - state[:, :3]
    rate = _energy_rate(state, dynamics.spherical_damper_rhs(0.0, state, J, JD, K))
    # two routes to the same algebra: rounding only
    assert_allclose(rate, -K * np.sum(rel ** 2, axis=-1), rtol=1e-12)
    assert np.all(rate <= 0)


def test_dry_friction_loses_energy_at_the_friction_torque_times_the_relative_rate_across_b():
    rng = np.random.default_rng(4)
    state, b = rng.normal(size=(40, 6)), rng.normal(size=(40, 3)) * 3e-5
    mt = 2e-4
    rel = state[:, 3:] - state[:, :3]
    bhat = b / np.linalg.norm(b, axis=-1, keepdims=True)
    rel_perp = rel - np.sum(rel * bhat, axis=-1, keepdims=True) * bhat
    rate = _energy_rate(state, dynamics.spherical_damper_rhs(0.0, state, J, JD, 0.0, friction_torque=mt, b=b))
    assert_allclose(rate, -mt * np.linalg.norm(rel_perp, axis=-1), rtol=1e-12)
    torque = dynamics.dry_friction_damper_torque(rel, b, mt)
    assert_allclose(np.linalg.norm(torque, axis=-1), mt, rtol=1e-14)
    # direction (5.25): B × (ω_rel × B), across B
    assert_allclose(np.sum(torque * b, axis=-1), 0.0, atol=1e-14 * mt * 3e-5)


def test_dry_friction_is_zero_exactly_at_zero_relative_rate_across_b_and_full_just_beside_it():
    b = np.array([0.0, 0.0, 3e-5])
    assert np.all(dynamics.dry_friction_damper_torque([0.0, 0.0, 0.3], b, 1e-3) == 0.0)  # along B only
    assert_allclose(dynamics.dry_friction_damper_torque([1e-300, 0.0, 0.3], b, 1e-3), [1e-3, 0.0, 0.0], rtol=1e-15)


def _full_rhs(time, x, friction_torque=0.0, coefficient=K, b_inertial=np.array([2e-5, 0.0, 3e-5])):
    q, s = x[:4], x[4:]
    b = dynamics.rotate_to_body(q, b_inertial)
    rates = dynamics.spherical_damper_rhs(time, s, J, JD, coefficient, friction_torque=friction_torque, b=b)
    return np.concatenate([dynamics.quaternion_rate(q, s[:3]), rates])


def _run(friction_torque, coefficient, steps, h):
    x = np.concatenate([[1.0, 0.0, 0.0, 0.0], [0.3, -0.2, 0.5], [0.0, 0.0, 0.0]])
    out = [x]
    for i in range(steps):
        x = rk4_step(_full_rhs, i * h, x, h, args=(friction_torque, coefficient))
        out.append(x)
    return np.array(out)


def _inertial_momentum(run):
    _, h_body = dynamics.spherical_damper_energy(run[:, 4:], J, JD)
    return dynamics.rotate_to_inertial(run[:, :4], h_body)


def test_body_and_viscous_ball_keep_their_angular_momentum_and_the_energy_only_falls():
    run = _run(0.0, K, 600, 0.1)          # 60 s; the relative rate decays in ~ J_d/k = 0.2 s… then follows
    h = _inertial_momentum(run)
    # RK4 at h = 0.1 s on rates ≤ 0.6 rad/s and a 0.2 s coupling time (h/τ = 0.5): the momentum's
    # drift is the scheme's local error summed, measured ~1e-7 of |H|; 1e-6 leaves room
    assert_allclose(h, np.broadcast_to(h[0], h.shape), atol=1e-6 * np.linalg.norm(h[0]))
    energy, _ = dynamics.spherical_damper_energy(run[:, 4:], J, JD)
    assert np.all(np.diff(energy) <= 1e-15)
    assert energy[-1] < 0.99 * energy[0]


def test_with_an_isotropic_body_the_relative_rate_decays_exponentially():
    jiso = np.full(3, 0.05)
    s = np.array([0.3, -0.2, 0.5, 0.0, 0.1, 0.0])
    rate = K * (1 / 0.05 + 1 / JD)
    h = 0.002
    for i in range(500):
        s = rk4_step(lambda t, y: dynamics.spherical_damper_rhs(t, y, jiso, JD, K), i * h, s, h)
    # d(ω_d − ω)/dt = −k(1/J + 1/J_d)(ω_d − ω) in inertial axes; the norm is frame-free.
    # RK4 with h·rate = 0.01: relative error ~ 500·(0.01)⁵/120 ~ 4e-11
    assert_allclose(np.linalg.norm(s[3:] - s[:3]), np.linalg.norm([-0.3, 0.3, -0.5]) * np.exp(-rate * 1.0), rtol=1e-8)


def test_dry_friction_keeps_momentum_and_sticks_with_a_chatter_set_by_the_step():
    mt, h = 2e-4, 0.05
    run = _run(mt, 0.0, 2000, h)          # 100 s: the ball catches up in ~ J_d|ω|/M_T ≈ 6 s
    hm = _inertial_momentum(run)
    # each stage's friction torque is equal and opposite on body and ball, so the coupling creates
    # no momentum; the drift is RK4's error on the turning axes (ω × terms, the quaternion) and on
    # the jumps of the torque inside steps while sticking: measured 1.7e-7 of |H|, 1e-6 allowed
    assert_allclose(hm, np.broadcast_to(hm[0], hm.shape), atol=1e-6 * np.linalg.norm(hm[0]))
    energy, _ = dynamics.spherical_damper_energy(run[:, 4:], J, JD)
    assert energy[-1] < energy[0]
    q, s = run[-200:, :4], run[-200:, 4:]
    b = dynamics.rotate_to_body(q, np.array([2e-5, 0.0, 3e-5]))
    bhat = b / np.linalg.norm(b, axis=-1, keepdims=True)
    rel = s[:, 3:] - s[:, :3]
    rel_perp = np.linalg.norm(rel - np.sum(rel * bhat, axis=-1, keepdims=True) * bhat, axis=-1)
    # stuck: the relative rate across B is bounded by one step's kick M_T h (1/J_min + 1/J_d)
    bound = mt * h * (1 / J.min() + 1 / JD)
    assert rel_perp.max() <= bound


@pytest.mark.parametrize("call, name", [
    (lambda: dynamics.viscous_damper_torque([0, 0, 1.0], -1.0), "coefficient"),
    (lambda: dynamics.dry_friction_damper_torque([0, 0, 1.0], [0, 0, 0.0], 1e-4), "b must be non-zero"),
    (lambda: dynamics.dry_friction_damper_torque([0, 0, 1.0], [0, 0, 1e-5], -1e-4), "friction_torque"),
    (lambda: dynamics.spherical_damper_rhs(0.0, np.zeros(5), J, JD, K), "state"),
    (lambda: dynamics.spherical_damper_rhs(0.0, np.zeros(6), J, 0.0, K), "ball_inertia"),
    (lambda: dynamics.spherical_damper_energy(np.zeros(6), [0.04, -1.0, 0.05], JD), "inertia"),
])
def test_bad_input_names_the_parameter(call, name):
    with pytest.raises(ValueError, match=name):
        call()


def test_the_flown_spherical_damper_coefficients_in_si():
    """E01c (seed line 18): 0.7–16.0 N·cm/(rad/s) is 0.007–0.16 N·m·s/rad; K above lies inside."""
    from magbench.io import load_printed

    row = load_printed("kovalenko")["kovalenko-damper-sphere-coefficient"]
    low, high = (dynamics.viscous_damper_torque([0.0, 0.0, 1.0], v * 1e-2)[2] for v in (row.value_low, row.value_high))
    assert_allclose([low, high], [0.007, 0.16], rtol=1e-14)     # 1 N·cm = 1e-2 N·m, exact up to rounding
    assert low <= K <= high
