r"""A circular orbit and the dipole field along it, in inertial and orbital axes.

SamSat-218D §"Coordinate systems" (seed lines 55–59: the orbital frame OXYZ) and
Kovalenko (1975) eqs. (2.36)–(2.40) (the dipole seen along a circular orbit). The
inertial frame has Z along the Earth's axis and X toward the ascending node when
``ascending_node`` is 0. SI throughout.
"""

from dataclasses import KW_ONLY, dataclass

import numpy as np

from .._validate import as_finite, as_in_range, as_positive
from ..constants import EARTH_GM, MU_0
from .dipole import dipole_b

__all__ = ["CircularOrbit"]


def _scalar_or_array(arr):
    return float(arr) if arr.ndim == 0 else arr


@dataclass(frozen=True)
class CircularOrbit:
    r"""A circular Keplerian orbit around a centred (optionally tilted, rotating) dipole Earth.

    Parameters
    ----------
    radius : float
        Orbit radius r from the Earth's centre [m].
    inclination : float
        Inclination i to the geographic equator, in [0, π] [rad].
    earth_moment : float
        Magnitude M of the Earth's dipole moment [A·m²].
    argument_of_latitude0 : float or array_like, optional
        Argument of latitude u at time 0 [rad]; an array (M,) gives each Monte Carlo member
        its own orbit phase.
    ascending_node : float, optional
        Inertial longitude Ω of the ascending node [rad].
    dipole_tilt : float, optional
        Colatitude δ of the northern geomagnetic pole (angle between the dipole axis and the
        rotation axis), in [0, π] [rad]; 0 is the direct, axial dipole.
    dipole_longitude : float, optional
        Inertial longitude λ_N0 of the northern geomagnetic pole at time 0 [rad].
    earth_rotation_rate : float, optional
        Rate ω_E at which the pole's inertial longitude advances [rad/s]; 0 keeps the dipole
        fixed in inertial space (``magbench.constants.EARTH_ROTATION_RATE`` makes it turn
        with the Earth).

    Attributes
    ----------
    mean_motion : float
        n = √(GM/r³) [rad/s], GM = ``magbench.constants.EARTH_GM``.
    period : float
        2π/n [s].

    Notes
    -----
    SamSat-218D §"Coordinate systems" (seed line 55): the orbital frame has OZ radial, away
    from the Earth, OY along the orbit normal r × v and OX = OY × OZ (along track on a
    circular orbit) — the axes of :func:`magbench.earth.orbital_dipole_b`. Position
    (Not in the sources: Vallado, *Fundamentals of Astrodynamics*, 4th ed., §2.6, for the
    perifocal-to-inertial rotation of a circular orbit):

    .. math::
       \mathbf r = r\,[\cos u\cos\Omega - \sin u\cos i\sin\Omega,\;
       \cos u\sin\Omega + \sin u\cos i\cos\Omega,\; \sin u\sin i],\qquad u = u_0 + n t.

    The field is that of a point dipole −M p̂(t) at the centre, p̂ the northern geomagnetic
    pole at colatitude δ and inertial longitude λ_N0 + ω_E t. In orbital axes it equals
    Kovalenko (1975) eq. (2.36) with Λ = Ω − λ_N(t) − π/2.

    Examples
    --------
    >>> orbit = CircularOrbit(6871e3, np.radians(51.6), 7.72e22)
    >>> round(orbit.period)
    5668
    >>> np.allclose(np.linalg.norm(orbit.position([0.0, 100.0]), axis=-1), 6871e3)
    True
    """

    radius: float
    inclination: float
    earth_moment: float
    argument_of_latitude0: float = 0.0
    _: KW_ONLY
    ascending_node: float = 0.0
    dipole_tilt: float = 0.0
    dipole_longitude: float = 0.0
    earth_rotation_rate: float = 0.0

    def __post_init__(self):
        checks = {
            "radius": as_positive("radius", self.radius, unit="m"),
            "inclination": as_in_range("inclination", self.inclination, 0.0, np.pi, unit="rad"),
            "earth_moment": as_positive("earth_moment", self.earth_moment, unit="A·m²"),
            "argument_of_latitude0": as_finite("argument_of_latitude0", self.argument_of_latitude0),
            "ascending_node": as_finite("ascending_node", self.ascending_node),
            "dipole_tilt": as_in_range("dipole_tilt", self.dipole_tilt, 0.0, np.pi, unit="rad"),
            "dipole_longitude": as_finite("dipole_longitude", self.dipole_longitude),
            "earth_rotation_rate": as_finite("earth_rotation_rate", self.earth_rotation_rate),
        }
        for name, arr in checks.items():
            if name != "argument_of_latitude0" and arr.ndim != 0:
                raise ValueError(f"{name} must be a scalar, got shape {arr.shape}")
            object.__setattr__(self, name, _scalar_or_array(arr))

    @property
    def mean_motion(self):
        """Mean motion n = √(GM/r³) [rad/s] (Kovalenko (1975) eq. (2.10); GM from IERS 2010)."""
        return float(np.sqrt(EARTH_GM / self.radius**3))

    @property
    def period(self):
        """Orbital period 2π/n [s]."""
        return 2.0 * np.pi / self.mean_motion

    # -- geometry -------------------------------------------------------------------------
    def argument_of_latitude(self, time):
        r"""Argument of latitude u = u0 + n t.

        Parameters
        ----------
        time : float or array_like
            Time since epoch [s]; broadcasts against an array ``argument_of_latitude0``.

        Returns
        -------
        ndarray
            u [rad] (not wrapped).

        Notes
        -----
        Kovalenko (1975) eq. (2.12) (u = ω + v) for a circular orbit.
        """
        t = as_finite("time", time)
        return self.argument_of_latitude0 + self.mean_motion * t

    def _node_axes(self):
        """Unit vectors toward the ascending node and 90° ahead of it in the orbit plane."""
        ci, si = np.cos(self.inclination), np.sin(self.inclination)
        co, so = np.cos(self.ascending_node), np.sin(self.ascending_node)
        return np.array([co, so, 0.0]), np.array([-ci * so, ci * co, si])

    def _unit_radial_along(self, time):
        u = self.argument_of_latitude(time)[..., None]
        node, ahead = self._node_axes()
        cu, su = np.cos(u), np.sin(u)
        return cu * node + su * ahead, -su * node + cu * ahead

    def position(self, time):
        r"""Inertial position on the orbit.

        Parameters
        ----------
        time : float or array_like
            Time since epoch [s].

        Returns
        -------
        ndarray, shape (..., 3)
            r [m], |r| = ``radius``.

        Notes
        -----
        Not in the sources: Vallado (2013) §2.6, the rotation R3(−Ω) R1(−i) R3(−u) of the
        perifocal vector (r, 0, 0).
        """
        return self.radius * self._unit_radial_along(time)[0]

    def velocity(self, time):
        r"""Inertial velocity on the orbit.

        Parameters
        ----------
        time : float or array_like
            Time since epoch [s].

        Returns
        -------
        ndarray, shape (..., 3)
            v = n r × (unit along-track) [m/s], perpendicular to the position.

        Notes
        -----
        Not in the sources: the time derivative of :meth:`position` (Vallado (2013) §2.6).
        """
        return self.radius * self.mean_motion * self._unit_radial_along(time)[1]

    def orbit_normal(self):
        r"""Unit orbit normal r × v / |r × v| in inertial axes.

        Returns
        -------
        ndarray, shape (3,)
            (sin i sin Ω, −sin i cos Ω, cos i) [-].

        Notes
        -----
        SamSat-218D §"Coordinate systems" (seed line 55): OY along the rate of true anomaly.
        """
        node, ahead = self._node_axes()
        return np.cross(node, ahead)

    def orbital_axes(self, time):
        r"""The orbital frame OXYZ as rows, in inertial components.

        Parameters
        ----------
        time : float or array_like
            Time since epoch [s].

        Returns
        -------
        ndarray, shape (..., 3, 3)
            Rows X (along track), Y (orbit normal r × v), Z (radial, away from the Earth):
            ``orbital_axes(t) @ v_inertial`` gives orbital components [-].

        Notes
        -----
        SamSat-218D §"Coordinate systems" (seed line 55); the frame turns about +Y at the
        mean motion.
        """
        radial, along = self._unit_radial_along(time)
        normal = np.broadcast_to(self.orbit_normal(), radial.shape)
        return np.stack([along, normal, radial], axis=-2)

    # -- field ----------------------------------------------------------------------------
    def _pole(self, time):
        t = np.asarray(time, dtype=float)
        lam = self.dipole_longitude + self.earth_rotation_rate * t
        sd, cd = np.sin(self.dipole_tilt), np.cos(self.dipole_tilt)
        pole = np.stack(np.broadcast_arrays(sd * np.cos(lam), sd * np.sin(lam), cd + 0.0 * lam), axis=-1)
        pole_rate = self.earth_rotation_rate * np.stack(
            np.broadcast_arrays(-sd * np.sin(lam), sd * np.cos(lam), 0.0 * lam), axis=-1)
        return pole, pole_rate

    def pole_longitude(self, time):
        r"""Inertial longitude λ_N of the northern geomagnetic pole.

        Parameters
        ----------
        time : float or array_like
            Time since epoch [s].

        Returns
        -------
        ndarray
            λ_N0 + ω_E t [rad].

        Notes
        -----
        Kovalenko (1975) eq. (2.36): the pole's meridian advances with the Earth's rotation.
        """
        return self.dipole_longitude + self.earth_rotation_rate * as_finite("time", time)

    def field(self, time):
        r"""Dipole field at the spacecraft, in inertial axes.

        Parameters
        ----------
        time : float or array_like
            Time since epoch [s].

        Returns
        -------
        ndarray, shape (..., 3)
            B [T] = ``dipole_b(position, −M p̂(t))``.

        Notes
        -----
        Kovalenko (1975) eq. (2.36) in inertial axes; the vector dipole formula is
        :func:`magbench.earth.dipole_b`.
        """
        pole, _ = self._pole(as_finite("time", time))
        return dipole_b(self.position(time), -self.earth_moment * pole)

    def field_and_rate(self, time):
        r"""Dipole field and its time derivative along the orbit, in inertial axes.

        Parameters
        ----------
        time : float or array_like
            Time since epoch [s].

        Returns
        -------
        field : ndarray, shape (..., 3)
            B [T].
        field_rate : ndarray, shape (..., 3)
            dB/dt [T/s], analytic.

        Notes
        -----
        Not in the sources: the time derivative of Jackson's dipole field (eq. 5.56) at
        constant |r|, with ṙ̂ = v/r and ṁ = −M dp̂/dt:

        .. math::
           \dot{\mathbf B} = \frac{\mu_0}{4\pi r^3}\big[3(\dot{\mathbf m}\cdot\hat{\mathbf r}
           + \mathbf m\cdot\dot{\hat{\mathbf r}})\hat{\mathbf r}
           + 3(\mathbf m\cdot\hat{\mathbf r})\dot{\hat{\mathbf r}} - \dot{\mathbf m}\big].
        """
        return self.field_rate_and_position(time)[:2]

    def field_rate_and_position(self, time):
        r""":meth:`field_and_rate` and :meth:`position` at once (one evaluation of the
        orbit's geometry: a simulation's field table needs all three).

        Parameters
        ----------
        time : float or array_like
            Time since epoch [s].

        Returns
        -------
        field, field_rate, position : ndarray, shape (..., 3)
            B [T], dB/dt [T/s] and r [m], each equal to the separate method's.
        """
        t = as_finite("time", time)
        radial, along = self._unit_radial_along(t)
        radial_rate = self.mean_motion * along
        pole, pole_rate = self._pole(t)
        m, m_rate = -self.earth_moment * pole, -self.earth_moment * pole_rate
        scale = MU_0 / (4.0 * np.pi * self.radius**3)
        m_r = np.sum(m * radial, axis=-1, keepdims=True)
        b = scale * (3.0 * m_r * radial - m)
        m_r_rate = np.sum(m_rate * radial, axis=-1, keepdims=True) + np.sum(m * radial_rate, axis=-1, keepdims=True)
        b_rate = scale * (3.0 * m_r_rate * radial + 3.0 * m_r * radial_rate - m_rate)
        return b, b_rate, self.radius * radial

    def field_rate(self, time):
        r"""Time derivative of the dipole field along the orbit, in inertial axes.

        Parameters
        ----------
        time : float or array_like
            Time since epoch [s].

        Returns
        -------
        ndarray, shape (..., 3)
            dB/dt [T/s], analytic (see :meth:`field_and_rate`).

        Notes
        -----
        Not in the sources: the derivative of Jackson (1999) eq. (5.56) along the orbit;
        the field itself is Kovalenko (1975) eq. (2.36).
        """
        return self.field_and_rate(time)[1]

    def field_orbital(self, time):
        r"""Dipole field at the spacecraft, in orbital axes OXYZ.

        Parameters
        ----------
        time : float or array_like
            Time since epoch [s].

        Returns
        -------
        ndarray, shape (..., 3)
            ``orbital_axes(t) @ field(t)`` [T]; equal to
            ``orbital_dipole_b(u, i, r, M, tilt=δ, node_phase=Ω − λ_N(t) − π/2)``.

        Notes
        -----
        Kovalenko (1975) eq. (2.36), computed from the inertial field.
        """
        return np.einsum("...ij,...j->...i", self.orbital_axes(time), self.field(time))
