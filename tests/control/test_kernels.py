"""magbench.control.kernels: the unchecked kernels of the rotor's laws against closed forms
and against the checked functions that call them."""

import numpy as np
from numpy.testing import assert_allclose, assert_array_equal

from magbench.control import projected_damping_dipole, relay_spin_dipole, rotor_program_field
from magbench.control.kernels import projected_dipole, relay_dipole
from magbench.earth.kernels import orbital_dipole_b

RNG = np.random.default_rng(612)
INC, B0 = np.radians(51.6), 24.97e-6


def test_program_field_is_the_untilted_dipole_and_has_the_dipole_magnitude():
    u = np.linspace(0.0, 2.0 * np.pi, 41)
    b = orbital_dipole_b(u, INC, 0.0, 0.0, B0)
    # the law's program field is the Earth kernel at tilt 0, only checked: equal to the last bit
    assert_array_equal(b, rotor_program_field(u, INC, B0))
    # |B| of a direct dipole along a circular orbit: B0 sqrt(1 + 3 sin²i sin²u) (Kovalenko (1975) eq. (2.40));
    # rounding of a few products of order B0
    assert_allclose(np.linalg.norm(b, axis=-1), B0 * np.sqrt(1.0 + 3.0 * np.sin(INC) ** 2 * np.sin(u) ** 2),
                    rtol=1e-14)


def test_projected_dipole_torque_is_minus_gain_times_the_perpendicular_error():
    b = RNG.normal(size=(50, 3)) * 3e-5
    e = RNG.normal(size=(50, 3)) * 1e-2
    k = RNG.uniform(0.0, 2.0, 50)
    m = projected_dipole(b, e, k)
    assert_array_equal(m, projected_damping_dipole(b, e, k))
    perp = e - np.sum(e * b, -1, keepdims=True) * b / np.sum(b * b, -1, keepdims=True)
    # m × B = k ((e × B) × B)/|B|² = −k e⊥ exactly; rounding of products of order k|e|
    assert_allclose(np.cross(m, b), -k[:, None] * perp, rtol=1e-12, atol=1e-15)


def test_relay_dipole_torque_is_kovalenko_712():
    b = RNG.normal(size=(200, 3))
    for direction in (1.0, -1.0):
        m = relay_dipole(b, 2.5, direction)
        assert_array_equal(m[:, 2], 0.0)                     # the coils lie across the spin axis
        assert_array_equal(np.abs(m[:, :2]), 2.5)           # a relay: full dipole, never less
        # (L × B)_z = −L0 sign Δω (|B_x| + |B_y|): sums of two products, rounding only
        assert_allclose(np.cross(m, b)[:, 2], -2.5 * direction * (np.abs(b[:, 0]) + np.abs(b[:, 1])), rtol=1e-14)
        assert_array_equal(relay_spin_dipole(b, 2.5, 0.3 * direction), m)
    # no dead zone: a field component of zero switches as +0
    assert_array_equal(relay_dipole(np.array([0.0, 0.0, 1.0]), 1.0, 1.0), [-1.0, 1.0, 0.0])
    # no spin error, nothing to correct
    assert_array_equal(relay_spin_dipole(b, 2.5, 0.0), 0.0 * b)


def test_bdot_twin_equals_the_numpy_laws():
    # The detumbling kernel's law (bdot_dipole_scalar) against the numpy kernels the checked
    # laws and the numpy loop call: the same operations in the same order, equal to the last
    # bit, the saturation included (limits that clip some components, not all).
    from magbench.control.kernels import bdot_dipole, bdot_dipole_projected, bdot_dipole_scalar

    rng = np.random.default_rng(3)
    b, rate = rng.normal(scale=3e-5, size=(50, 3)), rng.normal(scale=1e-6, size=(50, 3))
    limit = np.array([0.05, 0.1, 0.2])
    # gains [N·m·s] that put the dipoles around the limits: k Ḃ for the per-axis law,
    # k Ḃ/|B|² (|B|² ~ 3e-9 T²) for the projected one
    for projected, gain in ((False, rng.uniform(1e3, 1e5, size=50)), (True, rng.uniform(1e-5, 1e-3, size=50))):
        twin = np.array([bdot_dipole_scalar(tuple(x), tuple(d), k, tuple(limit), projected)
                         for x, d, k in zip(b, rate, gain)])
        expected = (bdot_dipole_projected(b, rate, gain[:, None], limit) if projected
                    else bdot_dipole(rate, gain[:, None], limit))
        assert 0.1 < np.mean(np.abs(expected) == limit) < 0.9
        np.testing.assert_array_equal(twin, expected)
