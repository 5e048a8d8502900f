"""The field cone: closed form against a direct sweep of the dipole field along the orbit."""

import numpy as np
import pytest
from numpy.testing import assert_allclose

from magbench.earth import (CircularOrbit, cone_field_direction, field_cone_axis, field_cone_deviation,
                            field_cone_half_angle, orbit_field_direction)

INCLINATIONS = np.radians([0.0, 10.0, 30.0, 51.6, 65.0, 89.0, 90.0, 97.3, 130.0, 180.0])


def _swept_directions(inclination, samples=20001):
    """Unit field directions over one orbit, from CircularOrbit's dipole field (no cone formula)."""
    orbit = CircularOrbit(6721e3, inclination, 7.766e22)
    t = np.linspace(0.0, orbit.period, samples)
    b = orbit.field(t)
    return b / np.linalg.norm(b, axis=-1, keepdims=True), orbit.argument_of_latitude(t)


@pytest.mark.parametrize("inclination", INCLINATIONS)
def test_closed_form_half_angle_is_the_swept_cone_through_node_and_apex(inclination):
    b, _ = _swept_directions(inclination)
    axis = field_cone_axis(inclination)
    angles = np.arccos(np.clip(b @ axis, -1.0, 1.0))
    delta = field_cone_half_angle(inclination)
    # The cone passes through the directions at u = 0 and u = π/2 and no swept direction lies
    # inside it: its half-angle is the sweep's smallest angle to the axis.
    assert_allclose(angles.min(), delta, atol=1e-7)  # arccos near its minimum: ~sqrt(eps) resolution
    assert_allclose(angles[0], delta, atol=1e-7)     # same: u = 0 is a sample
    # The exact direction leaves the cone by at most ~1.1° (reference §2: 0 … 1.09° at 51.6°).
    assert angles.max() - delta < np.radians(1.1)


def test_half_angle_limits_and_the_tns0_value():
    assert_allclose(field_cone_half_angle([0.0, np.pi / 2, np.pi]), [0.0, np.pi / 2, 0.0], atol=1e-7)  # sqrt(eps) of arccos at ±1
    assert_allclose(np.degrees(field_cone_half_angle(np.radians(51.6))), 59.991, atol=5e-4)  # printed to 3 decimals
    # The equivalent tangent form of the reference (§2).
    i = INCLINATIONS[1:6]
    s2 = np.sin(i) ** 2
    tan_form = np.arctan2(3 * np.sin(2 * i), 2 * (1 - 3 * s2 + np.sqrt(1 + 3 * s2)))
    assert_allclose(field_cone_half_angle(i), tan_form, rtol=1e-12)  # two exact forms: rounding only


@pytest.mark.parametrize("inclination", INCLINATIONS)
def test_exact_direction_matches_the_orbit_field(inclination):
    b, u = _swept_directions(inclination, 2001)
    assert_allclose(orbit_field_direction(inclination, u), b, atol=1e-14)  # same formula, two codings


def test_uniform_rate_model_touches_the_exact_direction_at_node_and_apex_only():
    i = np.radians(51.6)
    u = np.array([0.0, np.pi / 2, np.pi, 3 * np.pi / 2])
    assert_allclose(cone_field_direction(i, u), orbit_field_direction(i, u), atol=1e-14)  # exact points
    assert_allclose(np.linalg.norm(cone_field_direction(i, np.linspace(0, 7, 50)), axis=-1), 1.0, rtol=1e-14)


def test_worst_deviation_at_51_6_degrees():
    u = np.linspace(0.0, np.pi, 200001)
    off_cone, direction_error, phase_error = field_cone_deviation(np.radians(51.6), u)
    # The reference (§2) quotes the sweep to two decimals: 1.09° off-cone, 12.9° direction error.
    assert_allclose(np.degrees(off_cone.max()), 1.09, atol=0.005)
    assert_allclose(np.degrees(direction_error.max()), 12.9, atol=0.05)
    assert off_cone.min() > -1e-7  # never inside the cone (arccos resolution)
    assert_allclose(phase_error[[0, -1]], 0.0, atol=1e-12)  # node: both azimuths zero


def test_bad_inclination_is_refused():
    with pytest.raises(ValueError, match=r"inclination must lie in \[0.0, 3.14"):
        field_cone_half_angle(4.0)
    with pytest.raises(ValueError, match="argument_of_latitude must be finite"):
        orbit_field_direction(0.9, np.nan)


def test_the_exact_direction_goes_round_the_cone_at_twice_the_orbital_rate_on_average():
    from magbench.earth import field_cone_rate

    u = np.linspace(0.0, np.pi, 4001)
    rate = field_cone_rate(np.radians(51.6), u)
    # once round per half orbit: the mean of dφ/du over [0, π] is 2π/π
    assert_allclose(np.trapezoid(rate, u) / np.pi, 2.0, rtol=1e-6)
    assert rate.min() < 1.9 and rate.max() > 2.5                   # not uniform
    with pytest.raises(ValueError, match="argument_of_latitude"):
        field_cone_rate(0.5, u[::-1])
