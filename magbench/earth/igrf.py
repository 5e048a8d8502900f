"""The real geomagnetic field from IGRF-14, through ppigrf.

This is an adapter around an external model, kept apart from the pure physics in
:mod:`magbench.earth`: it reads ppigrf's coefficient file. Dates outside the model's
validity (1900–2030 for IGRF-14) are rejected instead of being silently frozen, which
is what ppigrf itself does past its last epoch.

Not in the thesis: Alken et al. (2021), "International Geomagnetic Reference Field:
the thirteenth generation", Earth Planets Space 73:49, and the IGRF-14 release
(IAGA V-MOD, 2024); ppigrf by Laundal et al. (IAGA-VMOD/ppigrf).
"""

import datetime as _dt
from dataclasses import dataclass
from functools import lru_cache

import numpy as np

from .._validate import as_finite, as_in_range, shown
from ..constants import IGRF_REFERENCE_RADIUS
from .dipole import dipole_from_gauss_coefficients

__all__ = ["IgrfDipole", "IgrfField", "decimal_year_to_datetime", "igrf_dipole", "igrf_field",
           "igrf_mean_surface_b", "igrf_gauss_coefficients"]


@lru_cache(maxsize=1)
def _coefficients():
    from ppigrf.ppigrf import read_shc

    g, h = read_shc()   # IGRF-14, shipped with ppigrf; index: epochs
    return g, h


def _valid_range():
    g, _ = _coefficients()
    return g.index[0].to_pydatetime(), g.index[-1].to_pydatetime()


def decimal_year_to_datetime(year):
    """Convert a decimal year (2016.5) to a naive UTC ``datetime``.

    Not in the sources: the decimal-year convention of IGRF (a year's fraction of its
    own length).

    Parameters
    ----------
    year : float
        Decimal year [year].

    Returns
    -------
    datetime.datetime
        The instant, naive UTC.

    Examples
    --------
    >>> decimal_year_to_datetime(2016.0)
    datetime.datetime(2016, 1, 1, 0, 0)
    """
    year = float(as_finite("year", year))
    whole = int(np.floor(year))
    start = _dt.datetime(whole, 1, 1)
    length = _dt.datetime(whole + 1, 1, 1) - start
    return start + (year - whole) * length


def _seconds(date):
    # IGRF epochs are naive UTC datetimes: count seconds without a local time zone.
    return (date - _dt.datetime(1970, 1, 1)).total_seconds()


def _check_date(date):
    first, last = _valid_range()
    if not first <= date <= last:
        raise ValueError(f"date must lie within IGRF-14's validity {first:%Y-%m-%d} to "
                         f"{last:%Y-%m-%d}, got {date:%Y-%m-%d}")


@dataclass(frozen=True)
class IgrfDipole:
    """The degree-1 (dipole) part of IGRF at one date."""

    date: _dt.datetime
    g10: float          #: [T]
    g11: float          #: [T]
    h11: float          #: [T]
    moment: float       #: dipole moment [A·m²]
    tilt: float         #: angle of the dipole axis to the rotation axis [rad]
    pole_latitude: float    #: northern geomagnetic pole latitude [rad]
    pole_longitude: float   #: northern geomagnetic pole east longitude [rad]


def igrf_dipole(year):
    """The IGRF-14 dipole at a date.

    Parameters
    ----------
    year : float
        Decimal year, within 1900–2030 [year].

    Returns
    -------
    IgrfDipole
        Coefficients interpolated linearly in time (as IGRF prescribes and ppigrf does),
        and the moment, tilt and pole derived from them.

    Notes
    -----
    Not in the thesis: IGRF-14 degree-1 coefficients, converted with
    :func:`magbench.earth.dipole_from_gauss_coefficients`.

    Examples
    --------
    >>> d = igrf_dipole(1960.0)
    >>> round(d.moment / 1e22, 3)    # the thesis quotes 8.1e22 A·m²
    8.028
    """
    date = decimal_year_to_datetime(year)
    _check_date(date)
    g, h = igrf_gauss_coefficients(year, max_degree=1)
    g10, g11, h11 = g[1, 0], g[1, 1], h[1, 1]
    moment, tilt, plat, plon = dipole_from_gauss_coefficients(g10, g11, h11, IGRF_REFERENCE_RADIUS)
    return IgrfDipole(date, float(g10), float(g11), float(h11), float(moment), float(tilt),
                      float(plat), float(plon))


@dataclass(frozen=True)
class IgrfField:
    """The full IGRF field at one place and date, in the local north-east-down frame."""

    date: _dt.datetime
    north: float        #: X [T]
    east: float         #: Y [T]
    down: float         #: Z [T]

    @property
    def horizontal(self):
        """Horizontal intensity H [T]."""
        return float(np.hypot(self.north, self.east))

    @property
    def total(self):
        """Total intensity F [T]."""
        return float(np.sqrt(self.north**2 + self.east**2 + self.down**2))

    @property
    def inclination(self):
        """Inclination I, positive downwards [rad]."""
        return float(np.arctan2(self.down, self.horizontal))

    @property
    def declination(self):
        """Declination D, positive east of true north [rad]."""
        return float(np.arctan2(self.east, self.north))


#: Lowest altitude :func:`igrf_field` accepts [m]: the core-mantle boundary, 3480 km from
#: the centre (PREM), below the 6371.2 km reference radius. The expansion describes the
#: field outside its sources, which lie in the core; heights above the ellipsoid differ
#: from the sphere's by at most 21 km, which this bound does not need to resolve.
LOWEST_ALTITUDE = 3480e3 - IGRF_REFERENCE_RADIUS


def _check_degree(max_degree):
    """A whole number of degrees in [1, 13]; 1.5 is refused rather than truncated to 1."""
    if isinstance(max_degree, bool) or not np.isfinite(float(max_degree)) \
            or float(max_degree) != int(max_degree) or not 1 <= int(max_degree) <= 13:
        raise ValueError(f"max_degree must be a whole number in [1, 13], got {shown(max_degree)}")


def igrf_field(latitude, longitude, year, *, altitude=0.0, max_degree=13):
    """The IGRF-14 field at a geodetic position and date.

    Parameters
    ----------
    latitude : float
        Geodetic latitude, strictly inside (-π/2, π/2) [rad] (ppigrf divides by
        sin θ and returns NaN exactly at the poles).
    longitude : float
        East longitude [rad].
    year : float
        Decimal year within 1900–2030 [year].
    altitude : float, optional
        Height above the WGS-84 ellipsoid [m], > :data:`LOWEST_ALTITUDE` (−2891.2 km: about
        the core-mantle boundary; the ellipsoid's height differs from the reference
        sphere's by at most 21 km).
    max_degree : int, optional
        Highest spherical-harmonic degree (1 gives the dipole part only), a whole number
        in [1, 13] [-].

    Returns
    -------
    IgrfField

    Notes
    -----
    Not in the thesis: IGRF-14 via ``ppigrf.igrf``.
    """
    for name, value in (("latitude", latitude), ("longitude", longitude), ("altitude", altitude)):
        if np.ndim(value) != 0:
            raise ValueError(f"{name} must be a scalar (igrf_field evaluates one point; call it per point "
                             f"or use ppigrf.igrf for grids), got shape {np.shape(value)}")
    lat = as_in_range("latitude", latitude, -np.pi / 2, np.pi / 2, unit="rad")
    if abs(float(lat)) >= np.pi / 2:
        raise ValueError(f"latitude must lie strictly inside (-π/2, π/2) rad, got {shown(float(lat))}")
    lon = as_finite("longitude", longitude)
    alt = float(as_finite("altitude", altitude))
    if alt <= LOWEST_ALTITUDE:
        raise ValueError(f"altitude must be > {LOWEST_ALTITUDE:g} m (the core-mantle boundary: the expansion "
                         f"holds only outside its sources), got {shown(alt)}")
    _check_degree(max_degree)
    date = decimal_year_to_datetime(year)
    _check_date(date)
    import ppigrf

    be, bn, bu = ppigrf.igrf(np.degrees(lon), np.degrees(lat), alt / 1e3, date, max_degree=int(max_degree))
    return IgrfField(date, float(np.ravel(bn)[0]) * 1e-9, float(np.ravel(be)[0]) * 1e-9,
                     -float(np.ravel(bu)[0]) * 1e-9)


def igrf_mean_surface_b(year, *, max_degree=13, nodes=48):
    """Area-mean |B| of IGRF over the sphere of radius 6371.2 km.

    Parameters
    ----------
    year : float
        Decimal year within 1900–2030 [year].
    max_degree : int, optional
        Highest spherical-harmonic degree kept [-].
    nodes : int, optional
        Gauss–Legendre nodes in colatitude (2·nodes in longitude) [-]; the default
        integrates the smooth |B| to better than 1e-6 relative.

    Returns
    -------
    float
        Mean total intensity [T].

    Notes
    -----
    Kovalenko (1975) p. 40 defines the mean field T_c = (1/4π) ∮ T dΩ and evaluates
    it for the 1965 field with n ≤ 6 (0.436 Oe). Not in the thesis.
    """
    _check_degree(max_degree)
    if isinstance(nodes, bool) or not float(nodes) == int(nodes) or int(nodes) < 1:
        raise ValueError(f"nodes must be a whole number >= 1, got {shown(nodes)}")
    date = decimal_year_to_datetime(year)
    _check_date(date)
    import ppigrf

    x, w = np.polynomial.legendre.leggauss(int(nodes))
    theta = np.degrees(np.arccos(x))
    phi = np.linspace(0.0, 360.0, 2 * int(nodes), endpoint=False)
    th, ph = np.meshgrid(theta, phi, indexing="ij")
    br, bt, bp = ppigrf.igrf_gc(IGRF_REFERENCE_RADIUS / 1e3, th, ph, date, max_degree=int(max_degree))
    total = np.sqrt(br[0] ** 2 + bt[0] ** 2 + bp[0] ** 2) * 1e-9
    return float(np.sum(w[:, None] * total) / (2.0 * 2 * int(nodes)))


def igrf_gauss_coefficients(year, *, max_degree=13):
    """IGRF-14 Gauss coefficients at a date, as square arrays.

    Parameters
    ----------
    year : float
        Decimal year within 1900–2030 [year].
    max_degree : int, optional
        Highest degree returned [-].

    Returns
    -------
    g, h : ndarray, shape (max_degree + 1, max_degree + 1)
        ``g[n, m]``, ``h[n, m]`` [T], interpolated linearly between IGRF epochs.

    Notes
    -----
    Not in the thesis: IGRF-14 as shipped with ppigrf.
    """
    _check_degree(max_degree)
    date = decimal_year_to_datetime(year)
    _check_date(date)
    gdf, hdf = _coefficients()
    t = np.array([_seconds(ts) for ts in gdf.index.to_pydatetime()])
    x = _seconds(date)
    size = int(max_degree) + 1
    g = np.zeros((size, size))
    h = np.zeros((size, size))
    for (n, m) in gdf.columns:
        if n <= max_degree:
            g[n, m] = np.interp(x, t, gdf[(n, m)].to_numpy(dtype=float)) * 1e-9
            h[n, m] = np.interp(x, t, hdf[(n, m)].to_numpy(dtype=float)) * 1e-9
    return g, h
