"""Physical constants in SI units, each with its source.

Values that a *source document* chose (the thesis's Earth dipole moment, its copper
resistivity, ...) are not constants: they live in ``magbench/data/<source>/params.toml`` with provenance.
"""

import scipy.constants as _sc

#: Vacuum permeability [H/m]; CODATA 2018 via scipy (not 4e-7*pi, which is no longer exact).
MU_0 = _sc.mu_0

#: Mean Earth radius [m]; the value the thesis (thesis §1.1) and Kovalenko (1975, p. 35) use.
EARTH_RADIUS = 6371.0e3

#: Reference radius of the IGRF spherical-harmonic expansion [m] (IAGA, IGRF-14).
IGRF_REFERENCE_RADIUS = 6371.2e3

#: Earth's sidereal rotation rate [rad/s] (IERS Conventions 2010, Table 1.1).
EARTH_ROTATION_RATE = 7.292115e-5

#: Earth's polar moment of inertia C [kg m^2]; C/(M a^2) = 0.3307 (Williams 1994,
#: "Contributions to the Earth's obliquity rate, precession, and nutation", AJ 108, 711),
#: with M = 5.9722e24 kg and a = 6378.137 km.
EARTH_POLAR_MOMENT_OF_INERTIA = 0.3307 * 5.9722e24 * 6378.137e3**2

#: Earth's gravitational parameter GM [m^3/s^2] (IERS Conventions 2010, Table 1.1).
EARTH_GM = 3.986004418e14
