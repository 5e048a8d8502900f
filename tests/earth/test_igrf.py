"""The IGRF-14 adapter against published numbers and its own closed forms."""

import numpy as np
import pytest
from numpy.testing import assert_allclose

from magbench.earth import igrf
from magbench import earth


def test_dipole_1960_from_the_published_coefficients():
    # IGRF-14's DGRF 1960 prints g10 = -30421, g11 = -2169, h11 = 5791 nT. The centred
    # dipole from them in closed form: B0 = √(g10² + g11² + h11²), m = 4π a³ B0 / μ0 with
    # a = 6371.2 km, the pole (antipode of the dipole axis) at colatitude arccos(-g10/B0)
    # and longitude atan2(h11, g11) + π. Tolerances: float rounding of the same formulas.
    g10, g11, h11 = -30421e-9, -2169e-9, 5791e-9
    b0 = np.sqrt(g10**2 + g11**2 + h11**2)
    moment = 4 * np.pi * 6371.2e3**3 * b0 / (4e-7 * np.pi)
    pole_lat = np.pi / 2 - np.arccos(-g10 / b0)
    pole_lon = np.arctan2(-h11, -g11)
    d = igrf.igrf_dipole(1960.0)
    assert_allclose(d.moment, moment, rtol=1e-9)     # μ0 as 4π·10⁻⁷ against CODATA's: 1e-10
    assert_allclose([d.pole_latitude, d.pole_longitude], [pole_lat, pole_lon], rtol=0, atol=1e-12)
    assert_allclose(d.tilt, np.pi / 2 - pole_lat, rtol=0, atol=1e-12)


def _reference_field(lat, lon, year):
    """IGRF-14 by direct spherical-harmonic synthesis, independent of ppigrf's code: the
    published coefficients (ppigrf's copy of the IAGA table) linearly interpolated in
    time, Schmidt semi-normalised Legendre functions from scipy, the WGS84 geodetic
    position converted to geocentric and the vector rotated back. Returns (north, east,
    down) [T] at the ellipsoid's surface."""
    import pandas as pd
    from math import factorial

    from ppigrf.ppigrf import read_shc
    from scipy.special import lpmv

    g, h = read_shc()
    epochs = np.array([t.year for t in g.index], dtype=float)
    k = np.searchsorted(epochs, year) - 1
    w = (year - epochs[k]) / (epochs[k + 1] - epochs[k])
    gi = (1 - w) * g.iloc[k] + w * g.iloc[k + 1]
    hi = (1 - w) * h.iloc[k] + w * h.iloc[k + 1]
    a_wgs, f = 6378.137, 1 / 298.257223563
    e2 = f * (2 - f)
    n_rad = a_wgs / np.sqrt(1 - e2 * np.sin(lat) ** 2)
    x, z = n_rad * np.cos(lat), n_rad * (1 - e2) * np.sin(lat)
    r, theta = np.hypot(x, z), np.arctan2(x, z)
    a = 6371.2

    def schmidt(n, m, th):
        norm = 1.0 if m == 0 else np.sqrt(2.0 * factorial(n - m) / factorial(n + m))
        return norm * (-1) ** m * lpmv(m, n, np.cos(th))     # scipy includes Condon–Shortley

    br = bt = bp = 0.0
    for (n, m), gnm in gi.items():
        hnm, ratio = hi[(n, m)], (a / r) ** (n + 2)
        cos_m, sin_m = np.cos(m * lon), np.sin(m * lon)
        p = schmidt(n, m, theta)
        dp = (schmidt(n, m, theta + 1e-6) - schmidt(n, m, theta - 1e-6)) / 2e-6
        br += (n + 1) * ratio * (gnm * cos_m + hnm * sin_m) * p
        bt -= ratio * (gnm * cos_m + hnm * sin_m) * dp
        bp -= ratio * m * (-gnm * sin_m + hnm * cos_m) * p / np.sin(theta)
    delta = lat - (np.pi / 2 - theta)          # geodetic minus geocentric latitude
    north_gc, up_gc = -bt, br
    north = north_gc * np.cos(delta) - up_gc * np.sin(delta)
    down = -(up_gc * np.cos(delta) + north_gc * np.sin(delta))
    return np.array([north, bp, down]) * 1e-9


def test_field_at_laboratory_against_an_independent_synthesis():
    # St Petersburg, 1 May 2016 (the thesis's laboratory and year). Tolerance: the
    # central difference of the Legendre functions (step 1e-6 rad, error ~1e-12 relative)
    # and the decimal-year conversion (a day is 2.7e-3 yr, ~0.1 nT of secular variation
    # at most): 0.5 nT of 52 µT, and 2e-6 rad (0.1 nT across 52 µT) in direction.
    lat, lon, year = np.radians(59.94), np.radians(30.31), 2016 + 121 / 366
    north, east, down = _reference_field(lat, lon, year)
    f = igrf.igrf_field(lat, lon, year)
    assert_allclose(f.total, np.sqrt(north**2 + east**2 + down**2), rtol=0, atol=0.5e-9)
    assert_allclose(f.inclination, np.arctan2(down, np.hypot(north, east)), rtol=0, atol=2e-6)
    assert_allclose(f.declination, np.arctan2(east, north), rtol=0, atol=2e-6)


def test_degree_one_field_equals_dipole_formula():
    # The n = 1 part of ppigrf's synthesis is a centred dipole: compare its magnitude
    # with dipole_b at a geocentric point (geodetic latitude 0: same radius only on the equator).
    d = igrf.igrf_dipole(2016.0)
    f = igrf.igrf_field(0.0, np.radians(10.0), 2016.0, max_degree=1)
    r = 6378.137e3    # WGS-84 equatorial radius: geodetic = geocentric on the equator
    m_vec = earth.earth_dipole_moment_vector(d.moment, d.pole_latitude, d.pole_longitude)
    b = earth.dipole_b(r * np.array([np.cos(np.radians(10)), np.sin(np.radians(10)), 0.0]), m_vec)
    assert_allclose(f.total, np.linalg.norm(b), rtol=1e-9)   # ppigrf works in km/nT floats


def test_mean_field_quadrature_converged():
    # 48 Gauss–Legendre nodes against 96: the mean of the smooth |B| has converged.
    assert_allclose(igrf.igrf_mean_surface_b(1965.0, max_degree=6),
                    igrf.igrf_mean_surface_b(1965.0, max_degree=6, nodes=96), rtol=1e-8)


@pytest.mark.parametrize("call, match", [
    (lambda: igrf.igrf_dipole(1850.0), "date must lie within"),
    (lambda: igrf.igrf_field(np.pi / 2, 0.0, 2016.0), "latitude"),
    (lambda: igrf.igrf_field(0.1, 0.0, 2016.0, max_degree=20), "max_degree"),
])
def test_bad_input(call, match):
    with pytest.raises(ValueError, match=match):
        call()
