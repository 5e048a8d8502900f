r"""The dipole field along a circular orbit: compiled (numba) twin of
:meth:`magbench.earth.CircularOrbit.field_rate_and_position` (the centred, tilted, rotating
dipole's field, its rate and the radial direction in inertial axes, from the cosines and
sines of the argument of latitude u and of the pole's inertial longitude λ), and the same
field in orbital axes (:func:`magbench.earth.orbital_dipole_b`) with its compiled twin.

Unchecked kernels, SI. The trigonometric functions are left to the caller: numpy's and the
C library's sine may differ in the last bit, so a caller that must equal the numpy method
to the last bit (the detumbling simulator's field table) passes numpy's cosines and sines;
every other operation is the method's, in its order and without fast-math (the tests hold
:func:`field_table` to the method with ``assert_array_equal``). ``cache=True`` keeps the
compiled code in ``__pycache__``.

Kovalenko (1975) eq. (2.36) for the field; its time derivative at constant |r| as in the
method's notes (Jackson (1999) eq. (5.56) differentiated).
"""

import numpy as np
from numba import njit

from ..constants import MU_0

__all__ = ["orbit_geometry", "dipole_field_rate_radial", "field_table", "orbital_dipole_b", "orbital_dipole_b_scalar"]


def orbit_geometry(orbit):
    """The float64 vector ``geo`` the kernels read, for a circular orbit (a checked
    :class:`~magbench.earth.CircularOrbit`; the kernels repeat
    :meth:`magbench.earth.CircularOrbit.field_rate_and_position`).

    Parameters
    ----------
    orbit : CircularOrbit
        The orbit and its dipole [SI].

    Returns
    -------
    ndarray, shape (13,)
        geo = (n, μ0/(4π r³), node[3], ahead[3], sin δ, cos δ, λ0, ω_E, M): the mean motion
        [rad/s], the field scale [T/(A·m²)], the unit vectors toward the ascending node and
        90° ahead of it [-], the dipole tilt's sine and cosine [-], the pole's longitude at
        time 0 [rad], the Earth's rotation rate [rad/s] and its dipole moment [A·m²].

    Notes
    -----
    Not in the sources: the terms of :meth:`magbench.earth.CircularOrbit.field_rate_and_position`
    (Kovalenko (1975) eq. (2.36)) that do not depend on time.
    """
    ci, si = np.cos(orbit.inclination), np.sin(orbit.inclination)
    co, so = np.cos(orbit.ascending_node), np.sin(orbit.ascending_node)
    return np.array([orbit.mean_motion, MU_0 / (4.0 * np.pi * orbit.radius**3), co, so, 0.0, -ci * so, ci * co, si,
                     np.sin(orbit.dipole_tilt), np.cos(orbit.dipole_tilt), orbit.dipole_longitude,
                     orbit.earth_rotation_rate, orbit.earth_moment], dtype=float)


@njit(cache=True, error_model="numpy")
def dipole_field_rate_radial(cu, su, cl, sl, geo):
    """Inertial B [T], dB/dt [T/s] and r̂ [-] (nine floats), given cos/sin of u and λ: one
    instant of :meth:`magbench.earth.CircularOrbit.field_rate_and_position`."""
    n, scale = geo[0], geo[1]
    r0 = cu * geo[2] + su * geo[5]
    r1 = cu * geo[3] + su * geo[6]
    r2 = cu * geo[4] + su * geo[7]
    a0 = -su * geo[2] + cu * geo[5]
    a1 = -su * geo[3] + cu * geo[6]
    a2 = -su * geo[4] + cu * geo[7]
    rr0, rr1, rr2 = n * a0, n * a1, n * a2
    sd, cd, big_m, erate = geo[8], geo[9], geo[12], geo[11]
    m0, m1, m2 = -big_m * (sd * cl), -big_m * (sd * sl), -big_m * cd
    md0, md1, md2 = -big_m * (erate * (-sd * sl)), -big_m * (erate * (sd * cl)), -big_m * (erate * 0.0)
    m_r = m0 * r0 + m1 * r1 + m2 * r2
    m_r_rate = (md0 * r0 + md1 * r1 + md2 * r2) + (m0 * rr0 + m1 * rr1 + m2 * rr2)
    return (scale * (3.0 * m_r * r0 - m0), scale * (3.0 * m_r * r1 - m1), scale * (3.0 * m_r * r2 - m2),
            scale * (3.0 * m_r_rate * r0 + 3.0 * m_r * rr0 - md0),
            scale * (3.0 * m_r_rate * r1 + 3.0 * m_r * rr1 - md1),
            scale * (3.0 * m_r_rate * r2 + 3.0 * m_r * rr2 - md2), r0, r1, r2)


@njit(cache=True, error_model="numpy")
def field_table(cos_u, sin_u, cos_lam, sin_lam, geo, radius, b, b_rate, radial):
    """Fill b, b_rate and radial, each (3, T, M), for times T and members M: the values of
    :meth:`magbench.earth.CircularOrbit.field_rate_and_position` at every instant.

    cos_u, sin_u (T, M): the argument of latitude's; cos_lam, sin_lam (T,): the pole
    longitude's. ``radial`` is the position divided by ``radius``, as the simulator forms
    it from the method's position [-].
    """
    for i in range(cos_u.shape[0]):
        for m in range(cos_u.shape[1]):
            f = dipole_field_rate_radial(cos_u[i, m], sin_u[i, m], cos_lam[i], sin_lam[i], geo)
            for c in range(3):
                b[c, i, m] = f[c]
                b_rate[c, i, m] = f[3 + c]
                radial[c, i, m] = (radius * f[6 + c]) / radius


def orbital_dipole_b(u, inclination, tilt, node_phase, b0):
    """The tilted dipole's field in orbital axes (..., 3) [T] at argument of latitude u
    [rad] (arrays broadcasting); no checks. The checked form, which documents it (Kovalenko
    (1975) eq. (2.36)), is :func:`magbench.earth.orbital_dipole_b`."""
    a = np.sin(inclination) * np.cos(tilt) - np.cos(inclination) * np.sin(tilt) * np.cos(node_phase)
    s = np.sin(tilt) * np.sin(node_phase)
    bx = np.cos(u) * a + np.sin(u) * s
    by = np.sin(inclination) * np.sin(tilt) * np.cos(node_phase) + np.cos(inclination) * np.cos(tilt)
    bz = -2.0 * (np.sin(u) * a - np.cos(u) * s)
    return np.asarray(b0)[..., None] * np.stack(np.broadcast_arrays(bx, by, bz), axis=-1)


@njit(cache=True, error_model="numpy")
def orbital_dipole_b_scalar(cos_u, sin_u, cos_lam, sin_lam, angles, b0):
    """Compiled twin of :func:`~magbench.earth.kernels.orbital_dipole_b` for one instant:
    the cosines and sines of u and of the node phase Λ, ``angles`` = (sin i, cos i, sin δ,
    cos δ) and b0 [T]; (Bx, By, Bz) [T]. The trigonometric functions are the caller's (see
    the module notes); every other operation is the numpy kernel's, in its order."""
    si, ci, sd, cd = angles
    a = si * cd - ci * sd * cos_lam
    s = sd * sin_lam
    return (b0 * (cos_u * a + sin_u * s), b0 * (si * sd * cos_lam + ci * cd), b0 * (-2.0 * (sin_u * a - cos_u * s)))
