"""magbench.dynamics.gyrostat: 2-3-1 angles, the semi-body frame, the SI gyrostat and the
slides' normalised equations, checked against scipy, sympy and conservation laws."""

import numpy as np
import pytest
import sympy as sp
from numpy.testing import assert_allclose
from scipy.integrate import solve_ivp
from scipy.spatial.transform import Rotation

from magbench.dynamics import (airplane_231_angles, airplane_231_matrix, euler_rates, gyrostat_kinetic_energy,
                               gyrostat_momentum, gyrostat_rates, gyrostat_rhs, rotor_dimensionless_numbers,
                               rotor_reduced_rhs, semi_body_axes, semi_body_field, semi_body_rhs)
from magbench.earth import orbital_dipole_b

RNG = np.random.default_rng(6)


def test_airplane_matrix_is_scipys_intrinsic_yzx_rotation_transposed():
    angles = RNG.uniform(-1.2, 1.2, (20, 3))
    c = airplane_231_matrix(*angles.T)
    active = Rotation.from_euler("YZX", angles).as_matrix()     # R2(α) R3(β) R1(γ), active
    # both exact up to rounding: 1e-14 is a few ulps of unit entries
    assert_allclose(c, active.transpose(0, 2, 1), atol=1e-14)
    assert_allclose(np.stack(airplane_231_angles(c), axis=1), angles, atol=1e-12)


def test_angles_rejects_a_wrong_shape():
    with pytest.raises(ValueError, match="matrix"):
        airplane_231_angles(np.eye(2))


def test_semi_body_axes_remove_gamma_and_field_components():
    alpha, beta, gamma = 0.4, -0.3, 2.1
    c = airplane_231_matrix(alpha, beta, gamma)
    s = semi_body_axes(c)
    # orbital -> semi-body is the matrix without γ (rounding only)
    assert_allclose(s @ c, airplane_231_matrix(alpha, beta, 0.0), atol=1e-14)
    b = np.array([1.0, -2.0, 0.5])
    assert_allclose(semi_body_field(b, alpha, beta), airplane_231_matrix(alpha, beta, 0.0) @ b, atol=1e-14)
    with pytest.raises(ValueError, match="singular"):
        semi_body_axes(airplane_231_matrix(0.0, np.pi / 2, 0.0))


def _sym_r1(g):
    return sp.Matrix([[1, 0, 0], [0, sp.cos(g), sp.sin(g)], [0, -sp.sin(g), sp.cos(g)]])


def _sym_r2(a):
    return sp.Matrix([[sp.cos(a), 0, -sp.sin(a)], [0, 1, 0], [sp.sin(a), 0, sp.cos(a)]])


def _sym_r3(b):
    return sp.Matrix([[sp.cos(b), sp.sin(b), 0], [-sp.sin(b), sp.cos(b), 0], [0, 0, 1]])


def test_si_body_model_reduces_term_by_term_to_the_slides_equations():
    """The SI gyrostat (I ω̇ = m × B + 3ω0² r × I r − ω × (Iω + J_f ν e1)), written with
    ω = ω0 R1(γ)ᵀ... in semi-body rates Ω, time τ = ω0 t and torques / ω0², is the slides'
    seed lines 29–38 exactly: every residual simplifies to 0."""
    al, be, ga, w1, w2, w3, d1, d2, d3 = sp.symbols("alpha beta gamma W1 W2 W3 dW1 dW2 dW3", real=True)
    A, B, Jf, nu, w0 = sp.symbols("A B J_f nu omega_0", positive=True)
    M1, M2, M3, B1, B2, B3 = sp.symbols("M1 M2 M3 B1 B2 B3", real=True)
    c = _sym_r1(ga) * _sym_r3(be) * _sym_r2(al)
    big_omega = sp.Matrix([w1, w2, w3])
    # slides' kinematics (seed line 38), in τ
    dga = w1 - w2 * sp.tan(be)
    # body rate and its time derivative: ω = ω0 R1(γ)ᵀ... R1(γ) maps S to body
    rot = _sym_r1(ga)
    omega = w0 * rot * big_omega
    omega_dot = w0**2 * (rot.diff(ga) * dga * big_omega + rot * sp.Matrix([d1, d2, d3]))
    inertia = sp.diag(A, B, B)
    rotor = Jf * nu * w0 * sp.Matrix([1, 0, 0])          # J_f ν_SI e1, ν_SI = ν ω0
    field_s = _sym_r3(be) * _sym_r2(al) * sp.Matrix([B1, B2, B3])
    dipole_body = w0**2 * rot * sp.Matrix([M1, M2, M3])  # slides' M = m/ω0²
    field_body = rot * field_s
    r = c * sp.Matrix([0, 0, 1])
    torque = dipole_body.cross(field_body) + 3 * w0**2 * r.cross(inertia * r)
    euler = inertia * omega_dot - torque + omega.cross(inertia * omega + rotor)
    lhs = sp.simplify(rot.T * euler / w0**2)
    abar, wf = A - Jf, w1 + nu
    bs = [B1 * sp.sin(al) + B3 * sp.cos(al),
          B1 * sp.cos(al) * sp.sin(be) - B2 * sp.cos(be) - B3 * sp.sin(al) * sp.sin(be),
          B1 * sp.cos(al) * sp.cos(be) + B2 * sp.sin(be) - B3 * sp.sin(al) * sp.cos(be)]
    slides = [  # seed lines 30–37, as "left − right"
        abar * d1 + Jf * d1 - (M2 * bs[0] + M3 * bs[1]),
        B * d2 + (abar - B) * w1 * w3 + Jf * wf * w3
        - (-3 * (A - B) * sp.sin(al) * sp.cos(al) * sp.cos(be) - M1 * bs[0] + M3 * bs[2]
           - B * w3 * (w1 - w2 * sp.tan(be))),
        B * d3 + (B - abar) * w1 * w2 - Jf * wf * w2
        - (-3 * (B - A) * sp.sin(al) ** 2 * sp.sin(be) * sp.cos(be) - M1 * bs[1] - M2 * bs[2]
           + B * w2 * (w1 - w2 * sp.tan(be))),
    ]
    for k in range(3):
        assert sp.simplify(lhs[k] - slides[k]) == 0, k
    # the brackets are the semi-body field: M × B_s (seed lines 31–37)
    torque_s = sp.Matrix([M1, M2, M3]).cross(field_s)
    assert sp.simplify(torque_s[0] - (M2 * bs[0] + M3 * bs[1])) == 0
    # kinematics (seed line 38): Ċ = −[ω_rel×] C with ω_rel = ω − ω0 C e2, in τ
    da, db = w2 / sp.cos(be) - 1, w3
    c_dot = c.diff(al) * da + c.diff(be) * db + c.diff(ga) * dga
    rel = omega / w0 - c * sp.Matrix([0, 1, 0])
    skew = sp.Matrix([[0, -rel[2], rel[1]], [rel[2], 0, -rel[0]], [-rel[1], rel[0], 0]])
    assert sp.simplify(c_dot + skew * c) == sp.zeros(3, 3)


def test_semi_body_rhs_is_the_printed_equations():
    # the code against the same printed equations (seed lines 29–38) at random points
    x = RNG.uniform(-0.8, 0.8, (6, 5))
    x[3] += 20.0
    torque = RNG.normal(size=(5, 3))
    a, b, jf, nu = 0.2, 0.25, 0.001, 500.0
    d = semi_body_rhs(0.0, x, torque, a, b, jf, nu)
    al, be, ga, w1, w2, w3 = x
    abar, wf = a - jf, w1 + nu
    t1, t2, t3 = torque.T
    assert_allclose(abar * d[3] + jf * d[3], t1, rtol=1e-13)        # rounding only
    assert_allclose(b * d[4] + (abar - b) * w1 * w3 + jf * wf * w3,
                    -3 * (a - b) * np.sin(al) * np.cos(al) * np.cos(be) + t2 - b * w3 * (w1 - w2 * np.tan(be)),
                    rtol=1e-12, atol=1e-12)
    assert_allclose(b * d[5] + (b - abar) * w1 * w2 - jf * wf * w2,
                    -3 * (b - a) * np.sin(al) ** 2 * np.sin(be) * np.cos(be) + t3 + b * w2 * (w1 - w2 * np.tan(be)),
                    rtol=1e-12, atol=1e-12)
    assert_allclose(d[:3], [w2 / np.cos(be) - 1, w3, w1 - w2 * np.tan(be)], rtol=1e-14)


def test_reduced_model_is_the_semi_body_model_divided_by_b():
    x = RNG.uniform(-0.5, 0.5, (6, 4))
    x[3] += 30.0
    torque = RNG.normal(size=(4, 3))
    a, b, jf, nu = 0.2, 0.25, 0.001, -600.0
    full = semi_body_rhs(0.0, x, torque, a, b, jf, nu)
    h = ((a - jf) * x[3] + jf * (x[3] + nu)) / b
    reduced = rotor_reduced_rhs(0.0, np.array([x[0], x[1], h, x[4], x[5]]), torque / b, a / b)
    # same arithmetic in another order: rounding of terms of size |h Ω| ~ 1e2
    assert_allclose(reduced, [full[0], full[1], a * full[3] / b, full[4], full[5]], rtol=1e-11, atol=1e-11)


def test_gyrostat_without_rotor_is_the_rigid_body():
    w, t, j = RNG.normal(size=(4, 3)), RNG.normal(size=(4, 3)), [0.2, 0.25, 0.3]
    assert_allclose(gyrostat_rates(w, t, j, 0.0), euler_rates(w, t, j), rtol=1e-15)


def test_torque_free_gyrostat_keeps_momentum_and_body_energy():
    """No torque, constant ν: |K| and ½ωᵀIω are conserved (K̇ = −ω × K in body axes)."""
    j = np.array([[0.2, 0.01, -0.005], [0.01, 0.25, 0.002], [-0.005, 0.002, 0.3]])
    h = 0.05

    def rhs(t, w):
        return gyrostat_rates(w, np.zeros(3), j, h)

    sol = solve_ivp(rhs, (0, 200.0), [0.3, -0.2, 0.1], method="DOP853", rtol=1e-12, atol=1e-14,
                    t_eval=np.linspace(0, 200, 50))
    k = np.linalg.norm(gyrostat_momentum(sol.y.T, j, h), axis=1)
    e = 0.5 * np.einsum("ni,ij,nj->n", sol.y.T, j, sol.y.T)
    # integrator error at rtol 1e-12 over ~50 nutation periods
    assert_allclose(k, k[0], rtol=1e-10)
    assert_allclose(e, e[0], rtol=1e-10)
    total = gyrostat_kinetic_energy(sol.y.T, j, h, 0.001)
    assert_allclose(total - h * sol.y[0] - 0.5 * h**2 / 0.001, e, rtol=1e-12)


def test_symmetric_gyrostat_nutation_closed_form():
    """A = I11, B = I22 = I33: ω1 constant, the transverse rate turns at λ = ((A − B)ω1 + J_f ν)/B."""
    a, b, h, w1 = 0.2, 0.25, 0.03, 0.7
    lam = ((a - b) * w1 + h) / b
    t = np.linspace(0, 30, 31)
    sol = solve_ivp(lambda t, w: gyrostat_rates(w, np.zeros(3), [a, b, b], h), (0, 30), [w1, 0.1, 0.0],
                    method="DOP853", rtol=1e-12, atol=1e-14, t_eval=t)
    # sign: ω̇2 = −λ ω3, ω̇3 = λ ω2 (integrator error only)
    assert_allclose(sol.y[0], w1, rtol=1e-12)
    assert_allclose(sol.y[1], 0.1 * np.cos(lam * t), atol=1e-10)
    assert_allclose(sol.y[2], 0.1 * np.sin(lam * t), atol=1e-10)


def _si_and_normalised_runs(orbits):
    """The SI body-axes model and the slides' semi-body model from one start, one dipole."""
    a, b, jf, s = 0.2, 0.25, 0.001, -0.05
    n, inc, radius, moment = 1.1085e-3, np.radians(51.6), 6871e3, 8.1e22
    nu = (0.3e-3 - a * s) / jf                          # rotor rate relative to the body, H0 = 3e-4 N·m·s [rad/s]
    dipole_s = np.array([0.02, -0.01, 0.015])          # a fixed dipole in the semi-body frame [A·m²]

    def field(t):
        return orbital_dipole_b(n * t, inc, radius, moment)

    def si(t, y):
        c = Rotation.from_quat(y[:4], scalar_first=True).as_matrix().T
        m_body = semi_body_axes(c).T @ dipole_s
        return gyrostat_rhs(t, y, m_body, field(t), [a, b, b], jf * nu, n)

    def normalised(tau, x):
        bs = semi_body_field(field(tau / n), x[0], x[1])
        return semi_body_rhs(tau, x, np.cross(dipole_s, bs) / n**2, a, b, jf, nu / n)

    alpha0, beta0, gamma0 = 0.2, -0.15, 0.3
    c0 = airplane_231_matrix(alpha0, beta0, gamma0)
    w_s = np.array([s / n + np.sin(beta0), 1.05 * np.cos(beta0), 0.02])   # Ω in units of ω0
    w_body = n * (airplane_231_matrix(0.0, 0.0, gamma0) @ w_s)
    q0 = Rotation.from_matrix(c0.T).as_quat(scalar_first=True)
    duration = orbits * 2 * np.pi / n
    t = np.linspace(0, duration, 41)
    y = solve_ivp(si, (0, duration), np.concatenate([q0, w_body]), method="DOP853", rtol=1e-11, atol=1e-13,
                  t_eval=t).y
    x = solve_ivp(normalised, (0, n * duration), [alpha0, beta0, gamma0, *w_s], method="DOP853", rtol=1e-11,
                  atol=1e-13, t_eval=n * t).y
    c = Rotation.from_quat(y[:4].T, scalar_first=True).as_matrix().transpose(0, 2, 1)
    return np.stack(airplane_231_angles(c)), x


def test_si_model_and_normalised_model_agree_over_two_orbits():
    angles, x = _si_and_normalised_runs(2)
    # both integrated at rtol 1e-11; 1e-6 rad (6e-5°) is well above their errors and far below any effect
    difference = np.angle(np.exp(1j * (angles - x[:3])))     # angles compared modulo 2π
    assert_allclose(difference[:2], 0.0, atol=1e-6)
    # γ carries the fast spin (about 1400 rad over the run): 1e-5 rad is a 1e-8 relative error
    assert_allclose(difference[2], 0.0, atol=1e-5)
    assert np.ptp(x[0]) > 1.0          # not trivial: the open-loop body tumbles in α


def test_dimensionless_numbers():
    d = rotor_dimensionless_numbers(0.2, 0.25, 2.771e-4, 1970.7, 5.542e-4, 1.10851e-3, 24.97e-6)
    # closed forms of rotor_spin.md §4; the inputs are the §10 values at 4-5 digits
    assert_allclose([d["axial_ratio"], d["momentum"], d["restoring"], d["damping"]], [0.8, 1.0, 4.0, 2.0], rtol=1e-3)


@pytest.mark.parametrize("call, name", [
    (lambda: semi_body_rhs(0.0, np.zeros(5), np.zeros(3), 0.2, 0.25, 0.001, 1.0), "state"),
    (lambda: semi_body_rhs(0.0, np.zeros(6), np.zeros(3), 0.2, 0.25, 0.3, 1.0), "rotor_inertia"),
    (lambda: rotor_reduced_rhs(0.0, np.zeros(5), np.zeros(3), -1.0), "axial_ratio"),
    (lambda: gyrostat_rhs(0.0, np.zeros(7), np.zeros(3), np.zeros(3), [1, 1, 1], 0.0, 1e-3), "quaternion"),
    (lambda: gyrostat_rhs(0.0, np.ones(6), np.zeros(3), np.zeros(3), [1, 1, 1], 0.0, 1e-3), "state"),
    (lambda: rotor_dimensionless_numbers(0.2, 0.25, 1e-4, 1.0, 1.0, -1e-3, 2e-5), "orbital_rate"),
])
def test_bad_input_names_the_parameter(call, name):
    with pytest.raises(ValueError, match=name):
        call()


def _turning_field_states():
    rng = np.random.default_rng(7)
    n = rng.normal(size=(6, 3))
    n /= np.linalg.norm(n, axis=-1, keepdims=True)
    return np.concatenate([rng.normal(scale=0.2, size=(6, 3)), rng.normal(scale=3e-5, size=(6, 3)), n], axis=-1)


TURNING = (np.array([0.04, 0.07, 0.09]), 0.6, 5.5e-4, 1.1e-3)   # A, B, C; J_f ν; k; Ω_f (chapter 6's scale)


def test_turning_field_rhs_compiled_twin_equals_the_numpy_kernel():
    from magbench.dynamics import gyrostat_turning_field_rhs
    from magbench.dynamics.kernels import gyrostat_turning_field_rhs as compiled

    states = _turning_field_states()
    for k in (TURNING[2], -TURNING[2]):
        args = (TURNING[0], TURNING[1], k, TURNING[3])
        expected = gyrostat_turning_field_rhs(0.0, states, *args)
        # the same operations in the same order, without fast-math: equal to the last bit
        np.testing.assert_array_equal(np.array([compiled(0.0, s, *args) for s in states]), expected)


def test_turning_field_rhs_power_invariants_and_torque():
    from magbench.control.spin import projected_damping_dipole, slides_printed_damping_torque
    from magbench.dynamics import gyrostat_turning_field_rhs

    states = _turning_field_states()
    j, h, k, rate = TURNING
    w, b, n = states[:, :3], states[:, 3:6], states[:, 6:]
    for gain, torque in ((k, np.cross(projected_damping_dipole(b, w, k), b)), (-k, slides_printed_damping_torque(b, w, k))):
        d = gyrostat_turning_field_rhs(0.0, states, j, h, gain, rate)
        # Euler's equation with the rotor: J ω̇ + ω × (Jω + h e1) is the law's torque
        lhs = j * d[:, :3] + np.cross(w, j * w + h * np.array([1.0, 0.0, 0.0]))
        assert_allclose(lhs, torque, rtol=1e-12, atol=1e-12 * np.abs(torque).max())  # rounding of a few terms
        # power ω·T = −k|w⊥|² (the printed sign pumps energy at the same rate)
        perp = w - np.sum(w * b, -1, keepdims=True) * b / np.sum(b * b, -1, keepdims=True)
        assert_allclose(np.sum(w * j * d[:, :3], -1), -gain * np.sum(perp * perp, -1), rtol=1e-10)
        # the field and its axis only turn: |B|, |n| and n·B are invariants
        for rate_of in (np.sum(b * d[:, 3:6], -1) / np.sum(b * b, -1), np.sum(n * d[:, 6:], -1),
                        (np.sum(n * d[:, 3:6], -1) + np.sum(b * d[:, 6:], -1)) / np.linalg.norm(b, axis=-1)):
            assert_allclose(rate_of, 0.0, atol=1e-15)   # relative to rates of order 0.3 rad/s


def test_reduced_rates_kernel_is_the_checked_model_and_keeps_the_spin_reference():
    from magbench.dynamics.kernels import rotor_reduced_rates

    x = np.vstack([RNG.uniform(-0.5, 0.5, (2, 30)), RNG.uniform(-3.0, 3.0, (3, 30))])
    t = RNG.normal(size=(30, 3))
    # the checked function only adds checks: equal to the last bit
    np.testing.assert_array_equal(rotor_reduced_rates(x, t[:, 0], t[:, 1], t[:, 2], 1.4),
                                  rotor_reduced_rhs(0.0, x, t, 1.4))
    # on α = β = 0, Ω2 = 1, Ω3 = 0 without torque only Ω3 moves, at h (the rotor's gyroscopic
    # term h Ω2): exact in floating point (products with 0 and 1)
    h = np.linspace(-2.0, 2.0, 5)
    ref = np.stack([0.0 * h, 0.0 * h, h, 1.0 + 0.0 * h, 0.0 * h])
    np.testing.assert_array_equal(rotor_reduced_rates(ref, 0.0, 0.0, 0.0, 1.4), np.stack([0 * h, 0 * h, 0 * h, 0 * h, h]))
