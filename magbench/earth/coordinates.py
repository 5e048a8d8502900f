"""Geomagnetic coordinates of a place from its geographic coordinates and the pole's.

Thesis §1.1 (the unnumbered formulas before eq. (1)). Angles in radians.
"""

import numpy as np

from .._validate import as_finite, as_in_range

__all__ = ["geomagnetic_latitude", "geomagnetic_longitude", "sun_ecliptic_axes"]


def _unit_vector(latitude, longitude):
    """Earth-centred, Earth-fixed unit vector for a latitude and east longitude [rad]."""
    clat = np.cos(latitude)
    return np.stack(
        np.broadcast_arrays(clat * np.cos(longitude), clat * np.sin(longitude), np.sin(latitude)),
        axis=-1,
    )


def geomagnetic_latitude(latitude, longitude, pole_latitude, pole_longitude):
    r"""Geomagnetic latitude of a place.

    Parameters
    ----------
    latitude : array_like
        Geographic latitude φ [rad].
    longitude : array_like
        Geographic longitude λ, east positive [rad].
    pole_latitude : array_like
        Geographic latitude φ0 of the northern geomagnetic pole [rad].
    pole_longitude : array_like
        Geographic longitude λ0 of the northern geomagnetic pole, east positive [rad].

    Returns
    -------
    ndarray
        Geomagnetic latitude Φ [rad], in [-π/2, π/2].

    Notes
    -----
    Thesis §1.1, the unnumbered formula before eq. (1) (from Kovalenko 1975, p. 34):

    .. math:: \sin\Phi = \sin\varphi\sin\varphi_0 + \cos\varphi\cos\varphi_0\cos(\lambda_0-\lambda)

    Examples
    --------
    >>> import numpy as np
    >>> phi = geomagnetic_latitude(np.radians(59.94), np.radians(30.31),
    ...                            np.radians(78.5), np.radians(-69.0))
    >>> round(float(np.degrees(phi)), 2)
    56.3
    """
    lat = as_in_range("latitude", latitude, -np.pi / 2, np.pi / 2, unit="rad")
    lon = as_finite("longitude", longitude)
    plat = as_in_range("pole_latitude", pole_latitude, -np.pi / 2, np.pi / 2, unit="rad")
    plon = as_finite("pole_longitude", pole_longitude)
    s = np.sin(lat) * np.sin(plat) + np.cos(lat) * np.cos(plat) * np.cos(plon - lon)
    # Rounding can push |s| a few ulp past 1 at the pole itself.
    return np.arcsin(np.clip(s, -1.0, 1.0))


def geomagnetic_longitude(latitude, longitude, pole_latitude, pole_longitude):
    r"""Geomagnetic longitude of a place, in the full range (-π, π].

    Parameters
    ----------
    latitude : array_like
        Geographic latitude φ [rad].
    longitude : array_like
        Geographic longitude λ, east positive [rad].
    pole_latitude : array_like
        Geographic latitude φ0 of the northern geomagnetic pole [rad].
    pole_longitude : array_like
        Geographic longitude λ0 of the northern geomagnetic pole, east positive [rad].

    Returns
    -------
    ndarray
        Geomagnetic longitude Λ [rad], counted from the geomagnetic meridian that
        passes through the geographic north pole.

    Notes
    -----
    Thesis §1.1, the second unnumbered formula before eq. (1):

    .. math:: \sin\Lambda = \cos\varphi\,\frac{\sin(\lambda_0-\lambda)}{\cos\Phi}

    Deviation from source: the printed relation gives only sin Λ, which leaves the
    quadrant open. The function computes both the sine and the cosine of Λ from the
    rotation into geomagnetic axes, so that sin Λ agrees with the printed formula
    everywhere and Λ is unambiguous.
    """
    lat = as_in_range("latitude", latitude, -np.pi / 2, np.pi / 2, unit="rad")
    lon = as_finite("longitude", longitude)
    plat = as_in_range("pole_latitude", pole_latitude, -np.pi / 2, np.pi / 2, unit="rad")
    plon = as_finite("pole_longitude", pole_longitude)
    r = _unit_vector(lat, lon)
    n = _unit_vector(plat, plon)
    z_geo = np.array([0.0, 0.0, 1.0])
    # x' points from the geomagnetic pole towards the geographic pole along their
    # common meridian; y' = n × x' makes sin Λ match the thesis's sign.
    x = z_geo - np.sum(z_geo * n, axis=-1, keepdims=True) * n
    x = x / np.linalg.norm(x, axis=-1, keepdims=True)
    y = np.cross(n, x)
    return np.arctan2(np.sum(r * y, axis=-1), np.sum(r * x, axis=-1))


def sun_ecliptic_axes(sun_longitude, obliquity):
    r"""Axes of Kovalenko's Sun–ecliptic frame, in geocentric inertial axes.

    Parameters
    ----------
    sun_longitude : float or array_like
        ρ_c, the Sun's ecliptic longitude from the vernal equinox [rad].
    obliquity : float
        ε, the obliquity of the ecliptic, in [0, π/2] [rad].

    Returns
    -------
    ndarray, shape (..., 3, 3)
        Rows x_c, y_c, z_c in inertial components (X to the vernal equinox, Z to the north
        pole): z_c toward the Sun, y_c the ecliptic's north pole, x_c = y_c × z_c. A vector's
        components in the frame are ``axes @ v``.

    Notes
    -----
    Kovalenko (1975) §2.3, Figs. 2.4–2.5 and eq. (2.29) (seed lines 45–48): the frame "c" has
    y_c along the Earth's annual rotation and z_c "along the line Earth–Sun", turned from the
    equatorial frame by ε about the equinox line and by ρ_c (+ the annual rate × t, neglected
    in §5.5) about y_c. The printed matrices are garbled in the seed: the signs here are
    reconstructed from that geometry (the Sun at ecliptic longitude ρ_c, z_c on it).

    Examples
    --------
    >>> (sun_ecliptic_axes(0.0, np.radians(23.45)).round(3) + 0.0).tolist()
    [[0.0, 0.917, 0.398], [0.0, -0.398, 0.917], [1.0, 0.0, 0.0]]
    """
    rho = as_finite("sun_longitude", sun_longitude)
    eps = as_in_range("obliquity", obliquity, 0.0, np.pi / 2, unit="rad")
    if eps.ndim:
        raise ValueError(f"obliquity must be a scalar [rad], got shape {eps.shape}")
    sun = np.stack([np.cos(rho), np.sin(rho) * np.cos(eps), np.sin(rho) * np.sin(eps)], axis=-1)
    pole = np.broadcast_to(np.array([0.0, -np.sin(eps), np.cos(eps)]), sun.shape)
    return np.stack([np.cross(pole, sun), pole, sun], axis=-2)
