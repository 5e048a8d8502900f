"""The rotor spacecraft's variants (magbench.sim.rotor_variants) and the small rotor helpers
beside them: gain scales, the reference torque, the relay law over a turn, the turning-field energy."""

import math

import numpy as np
import pytest
from numpy.testing import assert_allclose

from magbench.chapters.ch06_rotor.defaults import default_rotor_orbit, default_rotor_satellite
from magbench.control import rotor_equilibrium_dipole, rotor_program_field, rotor_reference_torque
from magbench.earth.dipole import dipole_equatorial_b
from magbench.sim import (maxima_per_orbit, normalised_pointing_error, reference_momentum_rate_offset,
                          relay_spin_torque_over_turn, rotor_dimensionless, rotor_gain_scales,
                          rotor_satellite_with_products, simulate_turning_field_gyrostat, transverse_asymmetry,
                          transverse_inertia_with_asymmetry, turning_field_kinetic_energy)


def test_asymmetry_round_trip_keeps_the_mean_transverse_inertia():
    i2, i3 = transverse_inertia_with_asymmetry(0.2, 0.3, 0.25)
    assert_allclose([i2 + i3, transverse_asymmetry(i2, i3)], [0.5, 0.25], rtol=1e-15)
    with pytest.raises(ValueError, match="asymmetry"):
        transverse_inertia_with_asymmetry(0.2, 0.3, 1.0)          # I22 would be zero
    with pytest.raises(ValueError, match="transverse_inertia_2"):
        transverse_asymmetry(0.0, 0.3)


def test_rate_offset_vanishes_for_a_symmetric_body_and_gives_the_reference_momentum_with_products():
    orbit = default_rotor_orbit()
    sat = default_rotor_satellite({"transverse_inertia_2": 0.25, "transverse_inertia_3": 0.25})
    assert_allclose(reference_momentum_rate_offset(sat, orbit, (0.0, 0.0, 0.0)), 0.0, atol=1e-15)
    angles = (0.3, -0.2, 0.1)
    tilted = rotor_satellite_with_products(sat, 0.002)
    offset = reference_momentum_rate_offset(tilted, orbit, angles)
    # with the offset the start's momentum I ω + J_f ν e1 is the reference's H0 e1 + B ω0 C0 e2
    from magbench.dynamics import airplane_231_matrix

    c0 = airplane_231_matrix(*angles)
    e1, w0, hr = np.eye(3)[0], orbit.mean_motion, sat.rotor_inertia * sat.rotor_rate
    rate = w0 * c0[:, 1] + (sat.axial_momentum - hr) / sat.inertia_matrix[0, 0] * e1 + offset
    assert_allclose(tilted.inertia_matrix @ rate + hr * e1,
                    sat.axial_momentum * e1 + sat.transverse_inertia * w0 * c0[:, 1], rtol=1e-12)
    assert tilted.restoring_gain == sat.restoring_gain and tilted.inertia_matrix[0, 1] == 0.002
    with pytest.raises(ValueError, match="initial_angles"):
        reference_momentum_rate_offset(sat, orbit, (0.0, 0.0))


def test_maxima_per_orbit_counts_whole_orbits():
    t = np.linspace(0.0, 2.0, 9)
    v = np.array([5.0, 1.0, 2.0, 3.0, 0.5, 4.0, 1.0, 0.0, 9.0])
    assert maxima_per_orbit(t, v).tolist() == [5.0, 4.0]           # t = 2 starts a third orbit, not counted
    assert maxima_per_orbit(t, v, 3).tolist() == [5.0, 4.0, 9.0]
    with pytest.raises(ValueError, match="time_orbits"):
        maxima_per_orbit(t, v[:-1])


def test_normalised_pointing_error_is_the_angle_from_the_velocity():
    assert_allclose(normalised_pointing_error([0.0, 0.3, 0.0], [0.0, 0.0, -0.4]), [0.0, 0.3, 0.4], atol=1e-15)


def test_gain_scales_invert_the_dimensionless_numbers():
    sat, orbit = default_rotor_satellite(), default_rotor_orbit()
    k_per, kw_per = rotor_gain_scales(sat, orbit)
    n = rotor_dimensionless(sat, orbit)
    assert_allclose([n["restoring"] * k_per, n["damping"] * kw_per], [sat.restoring_gain, sat.damping_gain],
                    rtol=1e-12)


def test_the_equilibrium_dipole_makes_exactly_the_reference_torque_for_any_gain():
    orbit = default_rotor_orbit()
    b0 = float(dipole_equatorial_b(orbit.earth_moment, orbit.radius))
    u = np.linspace(0.0, 2.0 * math.pi, 73)
    field = rotor_program_field(u, orbit.inclination, b0)
    need = rotor_reference_torque(u, 0.05, orbit.mean_motion)
    for gain in (0.0, 3.0e4):
        torque = np.cross(rotor_equilibrium_dipole(u, orbit.inclination, b0, gain, 0.05, orbit.mean_motion), field)
        assert_allclose(torque, need, rtol=0, atol=1e-12 * 0.05 * orbit.mean_motion)


def test_relay_law_over_a_turn_has_mean_moment_four_over_pi():
    angle, torque = relay_spin_torque_over_turn(4096)
    assert angle.shape == torque.shape == (4096,)
    assert_allclose(np.mean(np.abs(torque)), 4 / math.pi, rtol=1e-6)
    with pytest.raises(ValueError, match="samples"):
        relay_spin_torque_over_turn(4)


def test_turning_field_energy_falls_under_damping_and_rises_under_the_printed_sign():
    inertia = default_rotor_satellite().inertia_matrix
    runs = [simulate_turning_field_gyrostat(inertia, 0.01, k, 1e-3, [0.05] * 3, [3e-5, 0.0, 0.0], [0.0, 1.0, 0.0],
                                            600.0, samples=5) for k in (1e-3, -1e-3)]
    damped, pumped = (turning_field_kinetic_energy(r) for r in runs)
    w0 = np.full(3, 0.05)
    assert_allclose(damped[0], 0.5 * w0 @ inertia @ w0, rtol=1e-12)
    assert damped[-1] < damped[0] < pumped[-1]
