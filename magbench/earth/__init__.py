"""The Earth's field: the centred dipole and geomagnetic coordinates, the field along an
orbit (and a circular orbit with the dipole field along it, the cone its direction sweeps, the field's direction on a magnetopolar orbit), and the IGRF-14 model (through ppigrf). Pure functions of numpy arrays, SI.

Re-exports the public names of its modules.
"""

from .circular_orbit import CircularOrbit
from .coordinates import geomagnetic_latitude, geomagnetic_longitude, sun_ecliptic_axes
from .dipole import (dipole_b, dipole_elements, dipole_equatorial_b, dipole_field_line, dipole_from_gauss_coefficients,
                     dipole_horizontal_b, dipole_inclination, dipole_mean_surface_b, dipole_ned_b,
                     dipole_rms_surface_b, dipole_shell, dipole_total_b, dipole_vertical_b,
                     earth_dipole_moment_vector, field_elements, lowes_spectrum)
from .orbit import orbital_dipole_b
from .field_statistics import (dipole_max_field, field_direction_rate_range, field_magnitude_range,
                               field_square_ratio, mean_square_field, mean_square_perpendicular_field)
from .field_cone import (cone_field_direction, field_cone_axis, field_cone_deviation, field_cone_half_angle,
                         field_cone_rate, orbit_field_direction)
from .polar_orbit import (polar_eccentric_coefficients, polar_field_b, polar_field_direction_acceleration, polar_field_direction_angle,
                          polar_field_direction_rate, polar_fourier_coefficients, polar_gravity_factor,
                          polar_orbit_acceleration, polar_orbit_rate)
from .igrf import (IgrfDipole, IgrfField, decimal_year_to_datetime, igrf_dipole, igrf_field,
                   igrf_gauss_coefficients, igrf_mean_surface_b)
from .unloading_capacity import (field_direction_second_moment, field_second_moment, unloadable_fraction,
                                 worst_unloading_direction)

__all__ = ["geomagnetic_latitude", "geomagnetic_longitude", "sun_ecliptic_axes", "dipole_equatorial_b", "dipole_vertical_b",
           "dipole_horizontal_b", "dipole_total_b", "dipole_inclination", "dipole_b",
           "earth_dipole_moment_vector", "dipole_elements", "dipole_ned_b", "field_elements", "dipole_shell", "dipole_field_line",
           "dipole_from_gauss_coefficients", "dipole_mean_surface_b",
           "dipole_rms_surface_b", "lowes_spectrum", "orbital_dipole_b", "IgrfDipole", "IgrfField",
           "decimal_year_to_datetime", "igrf_dipole", "igrf_field", "igrf_mean_surface_b",
           "igrf_gauss_coefficients", "CircularOrbit", "field_cone_half_angle", "field_cone_axis",
           "orbit_field_direction", "cone_field_direction", "field_cone_deviation", "field_cone_rate",
           "dipole_max_field", "mean_square_field", "mean_square_perpendicular_field", "field_square_ratio",
           "field_direction_rate_range", "field_magnitude_range", "polar_field_direction_angle", "polar_field_direction_rate",
           "polar_field_direction_acceleration", "polar_field_b", "polar_gravity_factor", "polar_fourier_coefficients",
           "polar_orbit_rate", "polar_orbit_acceleration", "polar_eccentric_coefficients"]

__all__ += ["field_second_moment", "field_direction_second_moment", "unloadable_fraction", "worst_unloading_direction"]
