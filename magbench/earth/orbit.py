r"""The dipole field seen along a circular orbit, in orbital axes.

Kovalenko (1975) eqs. (2.36) (tilted dipole, rotating with the Earth) and (2.40) (the
direct dipole). SI throughout.
"""

import numpy as np

from .._validate import as_finite, as_in_range
from . import kernels
from .dipole import dipole_equatorial_b

__all__ = ["orbital_dipole_b"]


def orbital_dipole_b(argument_of_latitude, inclination, orbit_radius, moment, *,
                     tilt=0.0, node_phase=0.0):
    r"""Dipole field seen by a spacecraft on a circular orbit, in orbital axes.

    Parameters
    ----------
    argument_of_latitude : array_like
        Argument of latitude u, angle from the ascending node [rad].
    inclination : array_like
        Orbit inclination i to the geographic equator [rad].
    orbit_radius : array_like
        Distance from the Earth's centre r [m].
    moment : array_like
        Earth dipole moment magnitude M_З [A·m²].
    tilt : array_like, optional
        Dipole tilt δ to the rotation axis [rad]; 0 gives the direct (axial) dipole.
    node_phase : array_like, optional
        Kovalenko's angle λ − ωt between the ascending node and the meridian of the
        geomagnetic pole, advancing at minus the Earth's rate [rad].

    Returns
    -------
    ndarray, shape (..., 3)
        B in orbital axes [T]: x along the velocity, y along the orbit normal
        (angular momentum), z radially outwards.

    Notes
    -----
    Kovalenko (1975) eq. (2.36) (inclined dipole) and its δ = 0 case (2.40),
    converted to SI with B = μ0 H:

    .. math::
       \mathbf B = \frac{\mu_0 M}{4\pi r^3}
       \begin{bmatrix}
       \cos u\,(\sin i\cos\delta - \cos i\sin\delta\cos\Lambda) + \sin u\sin\delta\sin\Lambda\\
       \sin i\sin\delta\cos\Lambda + \cos i\cos\delta\\
       -2\,[\sin u\,(\sin i\cos\delta - \cos i\sin\delta\cos\Lambda) - \cos u\sin\delta\sin\Lambda]
       \end{bmatrix},\qquad \Lambda = \lambda - \omega t.

    Kovalenko's i = 0 special case (2.39) has a different phase convention; this
    function uses (2.36) for every inclination (see the errata chapter).

    Examples
    --------
    >>> import numpy as np
    >>> b = orbital_dipole_b(np.array([0.0, np.pi / 2]), np.pi / 2, 7371e3, 8.1e22)
    >>> ratio = np.sum(b[1] ** 2) / np.sum(b[0] ** 2)   # geopolar orbit: B² varies 4×
    >>> round(float(ratio), 12)
    4.0
    """
    u = as_finite("argument_of_latitude", argument_of_latitude)
    i = as_in_range("inclination", inclination, 0.0, np.pi, unit="rad")
    d = as_in_range("tilt", tilt, 0.0, np.pi, unit="rad")
    lam = as_finite("node_phase", node_phase)
    return kernels.orbital_dipole_b(u, i, d, lam, dipole_equatorial_b(moment, orbit_radius))
