"""The field statistics along a circular orbit against the dipole's closed forms."""

import numpy as np
import pytest
from numpy.testing import assert_allclose

from magbench.earth import (CircularOrbit, dipole_max_field, field_direction_rate_range, field_square_ratio,
                            mean_square_field)

MOMENT = 8.0e22     # A·m², about the Earth's


def _orbit(inclination, **kw):
    return CircularOrbit(7.0e6, inclination, MOMENT, earth_rotation_rate=0.0, **kw)


def test_the_largest_field_is_reached_over_the_poles():
    orbit = _orbit(np.pi / 2)
    sampled = np.max(np.linalg.norm(orbit.field(np.linspace(0.0, orbit.period, 3601)), axis=-1))
    # the polar orbit passes exactly over both poles at sample points (0.25 and 0.75 of 3600 steps)
    assert_allclose(dipole_max_field(orbit), sampled, rtol=1e-14)
    assert dipole_max_field(_orbit(0.5)) > np.max(np.linalg.norm(_orbit(0.5).field(np.linspace(0, 6e3, 999)), axis=-1))


@pytest.mark.parametrize("inclination", [0.0, 0.3, 1.0, np.pi / 2])
def test_mean_square_field_is_the_closed_form(inclination):
    """⟨|B|²⟩ = B0²(1 + (3/2) sin² i) over whole orbits of a direct dipole."""
    orbit = _orbit(inclination)
    b0 = dipole_max_field(orbit) / 2.0
    # equally spaced samples of a trigonometric polynomial of degree 2 average it exactly (to rounding)
    assert_allclose(mean_square_field(orbit, duration=orbit.period, samples=400),
                    b0**2 * (1.0 + 1.5 * np.sin(inclination) ** 2), rtol=1e-12)


def test_the_field_square_varies_fourfold_on_a_polar_orbit_and_not_on_an_equatorial_one():
    # Kovalenko (1975) p. 99; samples fall on the poles and the equator crossings: exact to rounding
    assert_allclose(field_square_ratio(_orbit(np.pi / 2)), 4.0, rtol=1e-12)
    assert_allclose(field_square_ratio(_orbit(0.0)), 1.0, rtol=1e-12)


def test_the_field_direction_turns_between_1_5_and_3_orbital_rates_on_a_polar_orbit():
    """b̂ turns once per orbit in the orbital frame, at a rate from n/2 (equator) to 2n (pole), and
    the frame turns at n: from 1.5 n to 3 n, mean 2 n."""
    orbit = _orbit(np.pi / 2)
    low, mean, high = field_direction_rate_range(orbit, duration=orbit.period, step=1.0)
    n = orbit.mean_motion
    # central differences on 1 s steps: error ~ (n·1 s)² ~ 1e-6 relative
    assert_allclose([low / n, high / n], [1.5, 3.0], rtol=1e-5)
    # the mean of samples over a period excluding its end: within 1e-4 of the integral mean
    assert_allclose(mean / n, 2.0, rtol=1e-4)


@pytest.mark.parametrize("call, match", [
    (lambda: mean_square_field(_orbit(1.0), duration=0.0), "duration must be > 0"),
    (lambda: mean_square_field(_orbit(1.0), samples=1.5), "samples must be a whole number >= 2"),
    (lambda: field_square_ratio(_orbit(1.0), samples=1), "samples must be a whole number >= 2"),
    (lambda: field_direction_rate_range(_orbit(1.0), duration=10.0, step=10.0), "step must be below duration"),
    (lambda: field_direction_rate_range(_orbit(1.0), step=-1.0), "step must be > 0"),
])
def test_bad_input(call, match):
    with pytest.raises(ValueError, match=match):
        call()


@pytest.mark.parametrize("inclination", [0.0, 0.5, np.pi / 2])
def test_field_magnitude_range_spans_equator_to_highest_latitude(inclination):
    from magbench.earth import field_magnitude_range

    orbit = _orbit(inclination)
    b0 = dipole_max_field(orbit) / 2.0
    low, high = field_magnitude_range(orbit, samples=3601)
    assert_allclose([low, high], [b0, b0 * np.sqrt(1.0 + 3.0 * np.sin(inclination) ** 2)], rtol=1e-6)
