"""The tilted dipole at a place (north-east-down), the field elements, and dipole field lines.

Checked against the thesis's closed forms (eqs. 1–3, with the corrected sign of eq. 3),
rotation invariance, a Pythagorean triple and the field-line condition dr × B = 0.
"""

import numpy as np
import pytest
from numpy.testing import assert_allclose

from magbench import earth

M, R = 8.1e22, 6371.2e3
PLACE = (np.radians(59.94), np.radians(30.31))
POLE = (np.radians(78.5), np.radians(-69.0))


def test_at_the_geomagnetic_pole_the_field_is_vertical_and_twice_the_equatorial():
    b = earth.dipole_ned_b(*POLE, M, *POLE, R)
    b0 = float(earth.dipole_equatorial_b(M, R))
    # Closed form 2 B0 downwards; the horizontal part vanishes up to rounding of the
    # rotations (a few ulp of B0).
    assert_allclose(b, [0.0, 0.0, 2 * b0], atol=1e-12 * b0)


@pytest.mark.parametrize("lat, lon", [(0.3, 1.0), (-1.2, -2.5), (1.5, 0.0)])
def test_axial_dipole_reduces_to_eqs_1_and_2(lat, lon):
    # With the pole on the rotation axis, Φ is the latitude: X = H (eq. 1), Y = 0, Z (eq. 2).
    b = earth.dipole_ned_b(lat, lon, M, np.pi / 2, 0.0, R)
    expected = [earth.dipole_horizontal_b(lat, M, R), 0.0, earth.dipole_vertical_b(lat, M, R)]
    assert_allclose(b, expected, atol=1e-12 * float(earth.dipole_equatorial_b(M, R)))   # rounding only


def test_tilted_dipole_magnitude_and_inclination_follow_the_geomagnetic_latitude():
    # |B| and the inclination depend on Φ only (the field is symmetric about the dipole
    # axis): eqs. (1)–(3) at Φ, with tan I = +2 tan Φ. Rounding only.
    phi = earth.geomagnetic_latitude(*PLACE, *POLE)
    b = earth.dipole_ned_b(*PLACE, M, *POLE, R)
    h, total, _, inclination = earth.field_elements(*b)
    assert_allclose(total, earth.dipole_total_b(phi, M, R), rtol=1e-12)
    assert_allclose(inclination, earth.dipole_inclination(phi), rtol=1e-12)


def test_field_elements_pythagorean_and_quadrants():
    h, t, d, i = earth.field_elements(3.0, 4.0, 12.0)
    assert_allclose([h, t], [5.0, 13.0], rtol=1e-15)                      # 3-4-5 and 5-12-13 exactly
    assert_allclose([np.tan(d), np.tan(i)], [4 / 3, 12 / 5], rtol=1e-14)  # rounding of atan2 and tan
    # West of north: negative declination; field pointing up: negative inclination.
    _, _, d, i = earth.field_elements(1.0, -1.0, -1.0)
    assert_allclose([d, i], [-np.pi / 4, -np.arctan(1 / np.sqrt(2))], rtol=1e-15)


def test_field_elements_turn_with_the_horizontal_axes():
    # Turning X, Y by α about the vertical adds α to D and leaves H, T, I: rounding only.
    x, y, z, alpha = 16e-6, -6e-6, 52e-6, 0.4
    ca, sa = np.cos(alpha), np.sin(alpha)
    a = earth.field_elements(x, y, z)
    b = earth.field_elements(ca * x - sa * y, sa * x + ca * y, z)
    assert_allclose([b[0], b[1], b[2] - alpha, b[3]], [a[0], a[1], a[2], a[3]], rtol=1e-13)


@pytest.mark.parametrize("call, name", [
    (lambda: earth.field_elements(np.nan, 0.0, 0.0), "north"),
    (lambda: earth.dipole_ned_b(2.0, 0.0, M, *POLE, R), "latitude"),
    (lambda: earth.dipole_ned_b([0.1, 0.2], 0.0, M, *POLE, R), "scalars"),
    (lambda: earth.dipole_ned_b(*PLACE, M, *POLE, 0.0), "radius"),
    (lambda: earth.dipole_ned_b(*PLACE, -M, *POLE, R), "moment"),
    (lambda: earth.dipole_shell(np.pi / 2), "footpoint_latitude"),
    (lambda: earth.dipole_field_line(0.5, [0.0]), "shell"),
    (lambda: earth.dipole_field_line(2.0, [0.0], side=2.0), "side"),
    (lambda: earth.dipole_field_line(2.0, [2.0]), "magnetic_latitude"),
])
def test_bad_input(call, name):
    with pytest.raises(ValueError, match=name):
        call()


def test_shell_closed_form():
    # L = 1/cos²λ: 1 on the equator, 4 at 60°, 2 at 45° (rounding only).
    assert_allclose(earth.dipole_shell(np.radians([0.0, 45.0, 60.0, -60.0])), [1.0, 2.0, 4.0, 4.0], rtol=1e-14)


def test_field_line_is_tangent_to_the_dipole_field():
    # Along r = L cos²λ the tangent must be parallel to B (the definition of a field line).
    # Central differences on a step of 1e-3 rad leave an O(1e-6) direction error.
    lam = np.linspace(-1.0, 1.0, 2001)
    x, z = earth.dipole_field_line(3.0, lam)
    tangent = np.stack([x[2:] - x[:-2], z[2:] - z[:-2]], axis=-1)
    pts = np.stack([x[1:-1], np.zeros(x.size - 2), z[1:-1]], axis=-1)
    b = earth.dipole_b(pts, [0.0, 0.0, -1.0])[:, [0, 2]]
    cross = tangent[:, 0] * b[:, 1] - tangent[:, 1] * b[:, 0]
    sine = cross / (np.linalg.norm(tangent, axis=-1) * np.linalg.norm(b, axis=-1))
    assert_allclose(sine, 0.0, atol=1e-5)
    assert np.all(x**2 + z**2 >= 1.0)


def test_field_line_tilt_is_a_rotation_and_side_a_mirror():
    lam = np.linspace(-np.pi / 2, np.pi / 2, 721)
    x0, z0 = earth.dipole_field_line(2.5, lam)
    x1, z1 = earth.dipole_field_line(2.5, lam, tilt=0.2)
    xw, zw = earth.dipole_field_line(2.5, lam, side=-1.0)
    # Rotation keeps distances and turns every point by −0.2 rad; rounding only.
    assert_allclose(np.hypot(x1, z1), np.hypot(x0, z0), rtol=1e-14)
    assert_allclose(np.angle(x1 + 1j * z1), np.angle(x0 + 1j * z0) - 0.2, atol=1e-14)
    assert_allclose([xw, zw], [-x0, z0], rtol=0)


@pytest.mark.parametrize("place, pole", [(PLACE, POLE), ((-0.7, 2.0), (1.2, 0.5)), ((0.1, -3.0), (-1.3, 1.0))])
def test_dipole_elements_closed_forms_equal_the_vector_field(place, pole):
    # Two routes: eqs. (1)–(3) at Φ, and the vector dipole resolved on north-east-down.
    # Independent arithmetic, so rounding only (1e-12; the inclination absolutely, it can be ~0).
    t, h, z, i = earth.dipole_elements(*place, M, *pole, R)
    x, y, down = earth.dipole_ned_b(*place, M, *pole, R)
    hv, tv, _, iv = earth.field_elements(x, y, down)
    assert_allclose([t, h, z], [tv, hv, down], rtol=1e-12, atol=1e-12 * float(earth.dipole_equatorial_b(M, R)))
    assert_allclose(i, iv, atol=1e-12)


def test_dipole_elements_broadcast_and_check():
    t, h, z, i = earth.dipole_elements(np.array([0.0, 0.5]), 0.0, M, np.pi / 2, 0.0, R)
    assert t.shape == (2,)
    with pytest.raises(ValueError, match="latitude"):
        earth.dipole_elements(2.0, 0.0, M, *POLE, R)
