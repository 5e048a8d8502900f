"""magbench.control.spin: the slides' equilibrium dipole, the damping projection and its
printed sign, the momentum-error variant."""

import itertools

import numpy as np
import pytest
import sympy as sp
from numpy.testing import assert_allclose
from scipy.integrate import solve_ivp

from magbench.control import (momentum_damping_dipole, projected_damping_dipole, rotor_equilibrium_axial_momentum,
                              rotor_equilibrium_dipole, rotor_program_field, rotor_reference_momentum,
                              rotor_spin_reference, slides_printed_damping_torque)
from magbench.dynamics import gyrostat_rates
from magbench.earth import CircularOrbit, dipole_equatorial_b, orbital_dipole_b

RNG = np.random.default_rng(61)
INC, B0, W0, H0 = np.radians(51.6), 24.97e-6, 1.10851e-3, 2.771e-4


def test_program_field_is_the_direct_dipole_of_the_orbit_module_and_of_the_orbit():
    u = np.linspace(0, 2 * np.pi, 37)
    orbit = CircularOrbit(6871e3, INC, 8.1e22)
    b0 = dipole_equatorial_b(8.1e22, 6871e3)
    # three independent codings of one formula: rounding only
    assert_allclose(rotor_program_field(u, INC, b0), orbital_dipole_b(u, INC, 6871e3, 8.1e22), rtol=1e-13, atol=1e-20)
    assert_allclose(rotor_program_field(u, INC, b0), orbit.field_orbital(u / orbit.mean_motion), rtol=1e-12,
                    atol=1e-18)


def test_the_slides_law_and_equilibrium_conditions_hold_identically():
    """Seed lines 45–69: with the printed M1, M2, M3 the conditions hold for all u, k, i, and
    the printed components equal the closed form k B_o + (0, C1 cos u/(B0 sin i), 0)."""
    u, i, k, b0, c1 = sp.symbols("u i k B_0 C_1", positive=True)
    f = -2 * sp.sin(i) * b0                                          # seed line 63
    m3 = k * f * sp.sin(u)
    m2 = (-sp.Rational(1, 2) * k * f * b0 * sp.cos(i) + c1 * sp.cos(u)) / (b0 * sp.sin(i))   # seed line 67
    m1 = -sp.Rational(1, 2) * k * f * sp.cos(u)                       # seed line 69
    b1, b2, b3 = b0 * sp.sin(i) * sp.cos(u), b0 * sp.cos(i), -2 * b0 * sp.sin(i) * sp.sin(u)
    h = c1 * sp.cos(u) ** 2
    assert sp.simplify(m2 * b3 - m3 * b2 + 2 * c1 * sp.sin(u) * sp.cos(u)) == 0        # seed line 51
    assert sp.simplify(-m1 * b3 + m3 * b1) == 0                                          # seed line 45
    assert sp.simplify(-h - (m1 * b2 - m2 * b1)) == 0                                    # seed line 47
    assert sp.simplify(sp.diff(h, u) - (m2 * b3 - m3 * b2)) == 0                         # H' = torque 1
    assert sp.simplify(m1 * b3 - b1 * m3) == 0                                           # M1 = B1 M3 / B3 (line 57)
    closed = [k * b1, k * b2 + c1 * sp.cos(u) / (b0 * sp.sin(i)), k * b3]
    for printed, ours in zip((m1, m2, m3), closed):
        assert sp.simplify(printed - ours) == 0


def test_only_the_velocity_normal_radial_out_axes_make_the_law_work():
    """Of the eight sign choices of the orbital axes only (+, +, +) keeps the conditions."""
    u = np.linspace(0.1, 6.2, 50)
    works = []
    for signs in itertools.product((1.0, -1.0), repeat=3):
        b = np.array(signs) * rotor_program_field(u, INC, 1.0)
        m = rotor_equilibrium_dipole(u, INC, 1.0, 3.0, 1.0, 1.0)
        t = np.cross(m, b)
        h = np.cos(u) ** 2
        ok = (np.allclose(t[:, 1], 0, atol=1e-12) and np.allclose(t[:, 0], -np.sin(2 * u), atol=1e-12)
              and np.allclose(t[:, 2], -h, atol=1e-12))
        works.append(ok)
    assert works == [True] + [False] * 7


@pytest.mark.parametrize("gain", [0.0, 500.0, 1970.7, 1e4])
def test_the_equilibrium_law_makes_exactly_the_needed_torque_along_whole_orbits(gain):
    u = np.linspace(0, 4 * np.pi, 2001)
    m = rotor_equilibrium_dipole(u, INC, B0, gain, H0, W0)
    t = np.cross(m, rotor_program_field(u, INC, B0))
    needed = np.stack([-H0 * W0 * np.sin(2 * u), 0 * u, -H0 * W0 * np.cos(u) ** 2], axis=1)
    # torques ~3e-7 N·m; the k-part (up to 0.25 A·m² × 50 µT) cancels to rounding: 1e-19 N·m
    assert_allclose(t, needed, atol=1e-19)
    # dH/dt = T1 with H = H0 cos²u (d/dt = ω0 d/du)
    h = rotor_equilibrium_axial_momentum(u, H0)
    # central differences on a 6.3e-3 rad grid: error h^2/6 |H'''| ~ 3e-5 H0 inside (first order at the ends)
    assert_allclose((np.gradient(h, u) * W0)[1:-1], t[1:-1, 0], atol=1e-4 * H0 * W0)


def test_equatorial_orbit_is_rejected():
    with pytest.raises(ValueError, match="inclination"):
        rotor_equilibrium_dipole(0.3, 0.0, B0, 1.0, H0, W0)
    with pytest.raises(ValueError, match="inclination"):
        rotor_equilibrium_dipole(0.3, np.pi, B0, 1.0, H0, W0)


def test_spin_reference():
    s, a, jf = -np.pi, 0.2, 1e-3
    nu = (H0 - a * s) / jf
    assert_allclose(rotor_spin_reference(0.0, H0, jf * nu, a), s, rtol=1e-14)
    u = np.linspace(0, np.pi, 7)
    # swing H0/A twice per orbit
    assert_allclose(rotor_spin_reference(u, H0, jf * nu, a) - s, H0 * (np.cos(u) ** 2 - 1) / a, atol=1e-15)


def test_damping_torque_is_minus_gain_times_rate_across_the_field():
    b, w = RNG.normal(size=(50, 3)) * 3e-5, RNG.normal(size=(50, 3)) * 1e-3
    kw = 5.5e-4
    m = projected_damping_dipole(b, w, kw)
    t = np.cross(m, b)
    perp = w - np.sum(w * b, axis=1, keepdims=True) * b / np.sum(b * b, axis=1, keepdims=True)
    assert_allclose(t, -kw * perp, rtol=1e-12, atol=1e-20)                 # rounding only
    assert np.all(np.sum(w * t, axis=1) <= 1e-24)                           # power never positive
    assert_allclose(slides_printed_damping_torque(b, w, kw), kw * perp, rtol=1e-12, atol=1e-20)


def _spin_down(torque_law, duration=200.0):
    """A torque-free gyrostat (with rotor) in a field turning in body axes, under a damping law."""
    j, h, kw = np.array([0.2, 0.1875, 0.3125]), 0.02, 5e-3

    def field(t):
        return 3e-5 * np.array([np.cos(0.05 * t), np.sin(0.05 * t) * 0.8, 0.5 + 0.3 * np.sin(0.02 * t)])

    def rhs(t, w):
        return gyrostat_rates(w, torque_law(field(t), w, kw), j, h)

    t = np.linspace(0, duration, 401)
    sol = solve_ivp(rhs, (0, duration), [0.05, -0.1, 0.08], method="DOP853", rtol=1e-11, atol=1e-14, t_eval=t)
    return 0.5 * np.einsum("in,i,in->n", sol.y, j, sol.y)


def test_energy_never_rises_with_the_damping_law_and_rises_with_the_printed_sign():
    """E = ½ωᵀIω (conserved without torque, see the gyrostat tests): dE/dt = −k_w|w⊥|² ≤ 0."""
    damped = _spin_down(lambda b, w, kw: np.cross(projected_damping_dipole(b, w, kw), b))
    # allow the integrator's rounding (rtol 1e-11 of E ~ 1e-3 J)
    assert np.all(np.diff(damped) <= 1e-14)
    assert damped[-1] < 0.01 * damped[0]
    pumped = _spin_down(lambda b, w, kw: slides_printed_damping_torque(b, w, kw), duration=100.0)
    assert pumped[-1] > 10 * pumped[0]


def test_printed_form_read_as_a_dipole_does_no_work():
    b, w = RNG.normal(size=(20, 3)), RNG.normal(size=(20, 3))
    dipole = -np.cross(np.cross(w, b), b) / np.sum(b * b, axis=1, keepdims=True)    # seed line 86 as a dipole
    power = np.sum(w * np.cross(dipole, b), axis=1)             # the dipole is k_w w⊥: torque ⊥ w
    assert_allclose(power, 0.0, atol=1e-14)                     # rounding of O(1) numbers


def test_momentum_damping_matches_the_rate_form_for_a_symmetric_body_transversally():
    b_tr, a, jf_nu, s = 0.25, 0.2, 0.6, -np.pi
    o2 = np.array([0.0, 1.0, 0.0])
    w = np.array([s + 1e-3, W0 + 2e-4, -3e-4])
    k = np.array([a, b_tr, b_tr]) * w + np.array([jf_nu, 0, 0])
    h_ref = a * s + jf_nu                                          # reference axial momentum here
    dk = k - rotor_reference_momentum(h_ref, o2, b_tr, W0)
    field = np.array([1e-5, 2e-5, -3e-5])
    m = momentum_damping_dipole(field, dk, 5e-4, b_tr)
    rate_error = np.array([(a / b_tr) * 1e-3, 2e-4, -3e-4])       # axis 1 weighted by a = A/B
    assert_allclose(m, projected_damping_dipole(field, rate_error, 5e-4), rtol=1e-9, atol=1e-15)   # rounding of s ± 1e-3 (m ~ 1e-2 A·m²)


@pytest.mark.parametrize("call, name", [
    (lambda: projected_damping_dipole([0, 0, 0], [1, 0, 0], 1.0), "field"),
    (lambda: projected_damping_dipole([1, 0, 0], [1, 0, 0], -1.0), "gain"),
    (lambda: slides_printed_damping_torque([1, 0, 0], [1, 0], 1.0), "rate_error"),
    (lambda: rotor_equilibrium_dipole(0.0, INC, -1.0, 1.0, H0, W0), "equatorial_b"),
    (lambda: rotor_program_field(0.0, 4.0, B0), "inclination"),
    (lambda: momentum_damping_dipole([1, 0, 0], [1, 0, 0], 1.0, 0.0), "transverse_inertia"),
])
def test_bad_input_names_the_parameter(call, name):
    with pytest.raises(ValueError, match=name):
        call()
