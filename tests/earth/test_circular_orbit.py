"""magbench.earth.CircularOrbit: closed forms of a circular orbit and the dipole along it."""

import dataclasses

import numpy as np
import pytest
from numpy.testing import assert_allclose

from magbench.constants import EARTH_GM, EARTH_ROTATION_RATE, MU_0
from magbench.earth import CircularOrbit, orbital_dipole_b

TIMES = np.linspace(0.0, 12000.0, 41)


def _tilted():
    return CircularOrbit(6856e3, np.radians(97.3), 7.72e22, 0.4, ascending_node=1.3, dipole_tilt=np.radians(9.61),
                         dipole_longitude=-1.27, earth_rotation_rate=EARTH_ROTATION_RATE)


def test_period_is_kepler():
    orbit = CircularOrbit(7000e3, 0.9, 8e22)
    # Kepler's third law in closed form; both sides are one sqrt of the same numbers.
    assert_allclose(orbit.period, 2 * np.pi * np.sqrt(7000e3**3 / EARTH_GM), rtol=1e-15)
    # After one period the spacecraft is back where it started (rounding of u = n·T only).
    assert_allclose(orbit.position(orbit.period), orbit.position(0.0), atol=1e-6)


@pytest.mark.parametrize("orbit", [CircularOrbit(6871e3, np.radians(51.6), 7.7e22), _tilted()])
def test_radius_constant_velocity_perpendicular(orbit):
    r, v = orbit.position(TIMES), orbit.velocity(TIMES)
    # |r| = radius and |v| = n r exactly up to rounding (relative 1e-15 per operation).
    assert_allclose(np.linalg.norm(r, axis=-1), orbit.radius, rtol=1e-14)
    assert_allclose(np.linalg.norm(v, axis=-1), orbit.radius * orbit.mean_motion, rtol=1e-14)
    # r·v = 0: rounding of products of size r·v ≈ 5e10.
    assert_allclose(np.sum(r * v, axis=-1), 0.0, atol=1e-4)


def test_velocity_is_the_derivative_of_position():
    orbit = _tilted()
    h = 0.5
    diff = (orbit.position(TIMES + h) - orbit.position(TIMES - h)) / (2 * h)
    # Central difference error n²h²/6 · v ≈ 3e-7 relative of |v| ≈ 7.6 km/s.
    assert_allclose(diff, orbit.velocity(TIMES), atol=1e-2)


def test_orbital_axes_are_samsat_oxyz():
    orbit = _tilted()
    axes = orbit.orbital_axes(TIMES)
    r, v = orbit.position(TIMES), orbit.velocity(TIMES)
    # Orthonormal rows, right-handed (rounding only).
    assert_allclose(axes @ np.swapaxes(axes, -1, -2), np.broadcast_to(np.eye(3), axes.shape), atol=1e-15)
    assert_allclose(np.linalg.det(axes), 1.0, rtol=1e-14)
    # Z radial out, Y along r × v, X along v on a circular orbit (rounding only).
    assert_allclose(axes[:, 2], r / orbit.radius, atol=1e-15)
    h = np.cross(r, v)
    assert_allclose(axes[:, 1], h / np.linalg.norm(h, axis=-1, keepdims=True), atol=1e-15)
    assert_allclose(axes[:, 0], v / np.linalg.norm(v, axis=-1, keepdims=True), atol=1e-15)


@pytest.mark.parametrize("orbit", [CircularOrbit(6871e3, np.radians(51.6), 7.7e22, 0.2), _tilted(),
                                   CircularOrbit(7371e3, 0.0, 8.1e22, ascending_node=0.5, dipole_tilt=0.2,
                                                 dipole_longitude=2.0, earth_rotation_rate=1e-4)])
def test_field_orbital_is_kovalenko_2_36(orbit):
    u = orbit.argument_of_latitude(TIMES)
    node_phase = orbit.ascending_node - orbit.pole_longitude(TIMES) - np.pi / 2
    expected = orbital_dipole_b(u, orbit.inclination, orbit.radius, orbit.earth_moment, tilt=orbit.dipole_tilt,
                                node_phase=node_phase)
    # Two independent formulas for the same vector: rounding of ~20 operations on 5e-5 T.
    assert_allclose(orbit.field_orbital(TIMES), expected, rtol=0, atol=1e-18)


def test_field_rate_is_the_derivative_of_field():
    orbit = _tilted()
    h = 1.0
    diff = (orbit.field(TIMES + h) - orbit.field(TIMES - h)) / (2 * h)
    # Central difference error ≈ (2n)² h²/6 relative ≈ 1e-6 of |Ḃ| ≈ 1e-7 T/s.
    assert_allclose(orbit.field_rate(TIMES), diff, rtol=0, atol=1e-13)
    b, rate = orbit.field_and_rate(TIMES)
    # Two writings of the dipole formula (dipole_b and the analytic pair): rounding of 5e-5 T.
    assert_allclose(b, orbit.field(TIMES), rtol=0, atol=1e-18)


def test_field_rate_and_position_at_once_equal_the_separate_methods():
    orbit = dataclasses.replace(_tilted(), argument_of_latitude0=np.array([0.0, 1.0, 2.0]))
    t = TIMES[:, None]
    b, rate, position = orbit.field_rate_and_position(t)
    # One geometry for the three: the same operations as each method alone, bit for bit.
    for got, expected in zip((b, rate, position), (*orbit.field_and_rate(t), orbit.position(t))):
        np.testing.assert_array_equal(got, expected)


def test_compiled_field_table_equals_the_method_bit_for_bit():
    from magbench.earth.kernels import field_table, orbit_geometry

    # Tilted, rotating, off-node orbits with per-member phases: every term of the kernel is
    # exercised. Given numpy's sines and cosines, every other operation is the method's, in
    # its order, so the compiled table must agree to the last bit (the detumbling simulator's
    # figures depend on it).
    for orbit in (dataclasses.replace(_tilted(), argument_of_latitude0=np.array([0.0, 1.0, 2.0, -0.7])),
                  CircularOrbit(6771e3, 1.7, 7.7e22, np.linspace(0.0, 6.0, 5), ascending_node=2.1,
                                dipole_tilt=3.0, dipole_longitude=-1.2)):
        t = TIMES[:, None]
        b, rate, position = orbit.field_rate_and_position(t)
        u = orbit.argument_of_latitude(t)
        lam = orbit.dipole_longitude + orbit.earth_rotation_rate * TIMES
        got = [np.empty((3,) + u.shape) for _ in range(3)]
        field_table(np.cos(u), np.sin(u), np.cos(lam), np.sin(lam), orbit_geometry(orbit), orbit.radius, *got)
        for table, expected in zip(got, (b, rate, position / orbit.radius)):
            np.testing.assert_array_equal(np.moveaxis(table, 0, -1), expected)


def test_members_on_the_leading_axis():
    phases = np.array([0.0, 1.0, 2.0])
    orbit = CircularOrbit(6871e3, 1.0, 7.7e22, phases)
    one = [CircularOrbit(6871e3, 1.0, 7.7e22, p).field(10.0) for p in phases]
    assert orbit.field(10.0).shape == (3, 3)
    assert_allclose(orbit.field(10.0), one, rtol=1e-15)   # identical arithmetic per member


def test_defaults_are_a_direct_fixed_dipole():
    orbit = CircularOrbit(7000e3, 0.0, 8e22)
    # Equatorial orbit, axial dipole: B is along −Z·(−1) = +Z (north), magnitude B0, constant.
    b = orbit.field(TIMES)
    b0 = MU_0 / (4 * np.pi) * 8e22 / 7000e3**3
    assert_allclose(b, np.broadcast_to([0.0, 0.0, b0], b.shape), rtol=1e-14, atol=1e-22)
    assert_allclose(orbit.field_rate(TIMES), 0.0, atol=1e-25)


@pytest.mark.parametrize("change, match", [
    ({"radius": -1.0}, "radius must be > 0"), ({"inclination": 4.0}, "inclination must lie in"),
    ({"earth_moment": np.nan}, "earth_moment must be finite"), ({"dipole_tilt": -0.1}, "dipole_tilt"),
    ({"ascending_node": [0.0, 1.0]}, "ascending_node must be a scalar"),
])
def test_bad_input(change, match):
    with pytest.raises(ValueError, match=match):
        dataclasses.replace(CircularOrbit(7000e3, 0.5, 8e22), **change)


def test_frozen_and_keyword_only():
    orbit = CircularOrbit(7000e3, 0.5, 8e22)
    with pytest.raises(dataclasses.FrozenInstanceError):
        orbit.radius = 1.0
    with pytest.raises(TypeError):
        CircularOrbit(7000e3, 0.5, 8e22, 0.0, 1.0)   # ascending_node is keyword-only


def test_orbital_dipole_twin_equals_the_numpy_kernel():
    # The rotor kernels' field (orbital_dipole_b_scalar) against the numpy kernel the checked
    # orbital_dipole_b calls: given numpy's sines and cosines, the same operations in the same
    # order, equal to the last bit (tilted dipole, several node phases and inclinations).
    from magbench.earth.kernels import orbital_dipole_b, orbital_dipole_b_scalar

    u = np.linspace(0.0, 2.0 * np.pi, 37)
    for inclination, tilt, node in ((1.2, 0.2, 0.3), (np.radians(51.6), np.radians(11.5), -2.0), (0.0, 0.0, 0.0)):
        angles = (np.sin(inclination), np.cos(inclination), np.sin(tilt), np.cos(tilt))
        twin = np.array([orbital_dipole_b_scalar(c, s, np.cos(node), np.sin(node), angles, 2.4e-5)
                         for c, s in zip(np.cos(u), np.sin(u))])
        np.testing.assert_array_equal(twin, orbital_dipole_b(u, inclination, tilt, node, 2.4e-5))
