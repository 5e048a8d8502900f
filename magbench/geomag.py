"""Compatibility module: the dipole field and geomagnetic coordinates moved to
:mod:`magbench.earth`, the magnetic torque to :mod:`magbench.dynamics`.

Every public name is re-exported here so existing code keeps working; new code imports
from the families. This module goes once the book and tests have moved.
"""

from .dynamics.torques import magnetic_torque, magnetic_torque_from_h, perpendicular_moment
from .earth.coordinates import geomagnetic_latitude, geomagnetic_longitude
from .earth.dipole import (dipole_b, dipole_equatorial_b, dipole_from_gauss_coefficients, dipole_horizontal_b,
                           dipole_inclination, dipole_mean_surface_b, dipole_rms_surface_b, dipole_total_b,
                           dipole_vertical_b, earth_dipole_moment_vector, lowes_spectrum)
from .earth.orbit import orbital_dipole_b

__all__ = ["geomagnetic_latitude", "geomagnetic_longitude", "dipole_equatorial_b", "dipole_vertical_b",
           "dipole_horizontal_b", "dipole_total_b", "dipole_inclination", "dipole_b",
           "earth_dipole_moment_vector", "dipole_from_gauss_coefficients", "orbital_dipole_b",
           "dipole_mean_surface_b", "dipole_rms_surface_b", "magnetic_torque", "magnetic_torque_from_h",
           "perpendicular_moment", "lowes_spectrum"]
