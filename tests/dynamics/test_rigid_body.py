"""magbench.dynamics rigid body: quaternion rotations against scipy, Euler's equations'
conservation laws under the one rk4_step, and the gravity gradient's symmetries."""

import numpy as np
import pytest
from numpy.testing import assert_allclose
from scipy.spatial.transform import Rotation

from magbench.dynamics import (euler_rates, gravity_gradient_torque, quaternion_rate, rotate_to_body,
                               rotate_to_inertial)
from magbench.sim import rk4_step

RNG = np.random.default_rng(20160428)
Q = Rotation.random(20, rng=RNG).as_quat(scalar_first=True)
V = RNG.normal(size=(20, 3))
J_3U = np.array([0.00666667, 0.0418667, 0.0418667])


def test_rotations_match_scipy():
    rot = Rotation.from_quat(Q, scalar_first=True)
    # Peer: scipy's Rotation (body → inertial); rounding of a few products of unit numbers.
    assert_allclose(rotate_to_inertial(Q, V), rot.apply(V), atol=1e-14)
    assert_allclose(rotate_to_body(Q, V), rot.inv().apply(V), atol=1e-14)
    assert_allclose(rotate_to_body(Q, rotate_to_inertial(Q, V)), V, atol=1e-14)


def test_rotations_broadcast_members_and_times():
    vectors = RNG.normal(size=(5, 20, 3))
    out = rotate_to_body(Q, vectors)
    assert out.shape == (5, 20, 3)
    assert_allclose(out[2], rotate_to_body(Q, vectors[2]), rtol=0, atol=0)   # identical arithmetic


def test_quaternion_rate_matches_finite_difference_of_scipy():
    omega = RNG.normal(size=(20, 3)) * 0.3
    h = 1e-6
    rot = Rotation.from_quat(Q, scalar_first=True)
    ahead = (rot * Rotation.from_rotvec(omega * h)).as_quat(scalar_first=True)
    behind = (rot * Rotation.from_rotvec(-omega * h)).as_quat(scalar_first=True)
    # Keep the same sign (scipy canonicalises w ≥ 0).
    ahead *= np.sign(np.sum(ahead * Q, axis=-1, keepdims=True))
    behind *= np.sign(np.sum(behind * Q, axis=-1, keepdims=True))
    # Central difference of a body-frame rotation: error O(h²|ω|³) plus rounding 1e-16/h.
    assert_allclose(quaternion_rate(Q, omega), (ahead - behind) / (2 * h), atol=1e-9)


def _rigid_rhs(time, state, inertia):
    q, w = state[..., :4], state[..., 4:]
    return np.concatenate([quaternion_rate(q, w), euler_rates(w, np.zeros_like(w), inertia)], axis=-1)


@pytest.mark.parametrize("inertia", [J_3U, np.array([[0.03, 0.002, -0.001], [0.002, 0.04, 0.003],
                                                     [-0.001, 0.003, 0.05]])])
def test_torque_free_body_conserves_energy_and_momentum(inertia):
    w0 = np.radians([[0.1, 10.0, 10.0], [20.0, -5.0, 3.0], [1.0, 30.0, -40.0]])
    state = np.concatenate([Q[:3], w0], axis=-1)
    jw = lambda w: w @ inertia.T if inertia.shape == (3, 3) else inertia * w   # noqa: E731
    energy0 = 0.5 * np.sum(w0 * jw(w0), axis=-1)
    momentum0 = rotate_to_inertial(state[:, :4], jw(w0))
    step = 0.05
    for k in range(2000):   # 100 s, up to 14 turns
        state = rk4_step(_rigid_rhs, k * step, state, step, (inertia,))
    w = state[:, 4:]
    # RK4 at ≤ 0.04 rad per step: local error ~ (ωh)⁵/120 per step, 2000 steps → ≲ 1e-7 relative.
    assert_allclose(0.5 * np.sum(w * jw(w), axis=-1), energy0, rtol=1e-7)
    assert_allclose(rotate_to_inertial(state[:, :4], jw(w)), momentum0, rtol=0,
                    atol=1e-7 * np.max(np.abs(momentum0)))


def test_euler_rates_principal_equals_tensor_form():
    w = RNG.normal(size=(20, 3))
    tau = RNG.normal(size=(20, 3)) * 1e-3
    # diag(J) and J as a vector are the same body: rounding of a 3×3 solve only.
    assert_allclose(euler_rates(w, tau, J_3U), euler_rates(w, tau, np.diag(J_3U)), rtol=1e-12)


def test_euler_rates_symmetric_top_closed_form():
    # Symmetric top (J1 = J2): ω̇x = −(J3 − J1)/J1 ωy ωz, exactly.
    w = np.array([0.1, 0.2, 0.3])
    assert_allclose(euler_rates(w, [0, 0, 0], [1.0, 1.0, 3.0]), [-2.0 * 0.2 * 0.3, 2.0 * 0.1 * 0.3, 0.0],
                    rtol=1e-15)


def test_gravity_gradient_zero_when_a_principal_axis_is_radial():
    for axis in np.eye(3):
        # J r̂ ∥ r̂ exactly: the cross product of parallel vectors is an exact zero.
        assert_allclose(gravity_gradient_torque(axis * 7e6, J_3U, 1.1e-3), 0.0, atol=0)


def test_gravity_gradient_pitch_closed_form_and_symmetry():
    n, theta = 1.1e-3, 0.3
    radial = np.array([np.sin(theta), 0.0, np.cos(theta)])   # pitched by θ about y
    jx, jy, jz = J_3U
    tau = gravity_gradient_torque(radial, J_3U, n)
    # Closed form 3n²(Jx − Jz) sinθ cosθ about y (Kovalenko 4.18 in the pitch plane); rounding only.
    assert_allclose(tau, [0.0, 3 * n**2 * (jx - jz) * np.sin(theta) * np.cos(theta), 0.0], atol=1e-22)
    # Symmetry: r̂ → −r̂ leaves the torque unchanged; it is perpendicular to r̂.
    assert_allclose(gravity_gradient_torque(-radial, J_3U, n), tau, rtol=1e-15)
    assert_allclose(np.dot(tau, radial), 0.0, atol=1e-22)


@pytest.mark.parametrize("call, match", [
    (lambda: rotate_to_body([1.0, 0.0, 0.0], [1.0, 0.0, 0.0]), "quaternion must have shape"),
    (lambda: rotate_to_body([0.0, 0.0, 0.0, 0.0], [1.0, 0.0, 0.0]), "zero quaternion"),
    (lambda: rotate_to_inertial([1.0, 0, 0, 0], [np.nan, 0.0, 0.0]), "vectors must be finite"),
    (lambda: euler_rates([0, 0, 1.0], [0, 0, 0], [1.0, -1.0, 1.0]), "inertia must be > 0"),
    (lambda: euler_rates([0, 0, 1.0], [0, 0, 0], [[1.0, 2.0], [2.0, 1.0]]), "inertia must have shape"),
    (lambda: euler_rates([0, 0, 1.0], [0, 0, 0], [[1, 1, 0], [0, 1, 0], [0, 0, 1.0]]), "symmetric"),
    (lambda: gravity_gradient_torque([0.0, 0.0, 0.0], J_3U, 1e-3), "radial_body must not"),
    (lambda: gravity_gradient_torque([1.0, 0.0, 0.0], J_3U, -1e-3), "mean_motion must be > 0"),
])
def test_bad_input(call, match):
    with pytest.raises(ValueError, match=match):
        call()


def test_the_written_out_cross_product_is_numpys():
    from magbench.dynamics.kernels import cross

    a, b = RNG.normal(size=(4, 1, 3)), RNG.normal(size=(5, 3))
    # Same three products and differences per component: bit-for-bit.
    assert_allclose(cross(a, b), np.cross(a, b), rtol=0, atol=0)


def test_scalar_body_twins_equal_the_numpy_kernels():
    # The compiled loops' rigid body (quaternion_rate_scalar, gyrostat_rates_scalar) against the
    # family's numpy kernels: the same operations in the same order for principal moments
    # (equal to the last bit); a tensor is inverted once where numpy solves (rounding).
    from magbench.dynamics import kernels

    rng = np.random.default_rng(11)
    q = rng.normal(size=(20, 4))
    w, torque = rng.normal(size=(20, 3)), rng.normal(scale=1e-3, size=(20, 3))
    j = np.array([0.0067, 0.042, 0.041])
    tensor = np.diag(j) + np.array([[0.0, 1e-4, -2e-4], [1e-4, 0.0, 3e-4], [-2e-4, 3e-4, 0.0]])
    twin_q = np.array([kernels.quaternion_rate_scalar(tuple(a), tuple(b)) for a, b in zip(q, w)])
    np.testing.assert_array_equal(twin_q, kernels.quaternion_rate(q, w))
    for h in (0.0, 2e-3):
        principal = (True, tuple(j), np.eye(3), np.eye(3))
        twin = np.array([kernels.gyrostat_rates_scalar(tuple(a), tuple(b), principal, h) for a, b in zip(w, torque)])
        np.testing.assert_array_equal(twin, kernels.gyrostat_rates(w, torque, j, h))
        full = (False, (1.0, 1.0, 1.0), tensor, np.linalg.inv(tensor))
        twin = np.array([kernels.gyrostat_rates_scalar(tuple(a), tuple(b), full, h) for a, b in zip(w, torque)])
        # J⁻¹ multiplied against LAPACK's solve: a few ulps of rates of order 1-10 rad/s²
        assert_allclose(twin, kernels.gyrostat_rates(w, torque, tensor, h), rtol=1e-13, atol=1e-13)
