"""The IGRF-14 adapter against published numbers and its own closed forms."""

import numpy as np
import pytest
from numpy.testing import assert_allclose

from magbench import geomag, igrf


def test_dipole_1960_matches_thesis_pole():
    # domain_anchors §3.3 (IGRF-14 n = 1, 1960): 8.028e22 A m², tilt 11.49°, pole 78.51N 69.47W.
    d = igrf.igrf_dipole(1960.0)
    assert_allclose(d.moment, 8.028e22, rtol=0.0005 / 8.028)   # 4 printed digits
    assert_allclose(np.degrees([d.tilt, d.pole_latitude, d.pole_longitude]),
                    [11.49, 78.51, -69.47], atol=0.005)        # 2 printed decimals


def test_field_at_laboratory_2016():
    # IGRF-14 at St Petersburg on 2016-05-01 (domain_anchors §3.2): F = 52 514.6 nT,
    # I = 73.578°, D = +10.542°.
    f = igrf.igrf_field(np.radians(59.94), np.radians(30.31), 2016 + 121 / 366)
    assert_allclose(f.total, 52514.6e-9, atol=0.05e-9)
    assert_allclose(np.degrees(f.inclination), 73.578, atol=0.0005)
    assert_allclose(np.degrees(f.declination), 10.542, atol=0.0005)


def test_degree_one_field_equals_dipole_formula():
    # The n = 1 part of ppigrf's synthesis is a centred dipole: compare its magnitude
    # with dipole_b at a geocentric point (geodetic latitude 0: same radius only on the equator).
    d = igrf.igrf_dipole(2016.0)
    f = igrf.igrf_field(0.0, np.radians(10.0), 2016.0, max_degree=1)
    r = 6378.137e3    # WGS-84 equatorial radius: geodetic = geocentric on the equator
    m_vec = geomag.earth_dipole_moment_vector(d.moment, d.pole_latitude, d.pole_longitude)
    b = geomag.dipole_b(r * np.array([np.cos(np.radians(10)), np.sin(np.radians(10)), 0.0]), m_vec)
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
