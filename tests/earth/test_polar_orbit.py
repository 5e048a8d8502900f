"""magbench.earth.polar_orbit: the field direction on a magnetopolar orbit against closed forms,
the dipole itself, finite differences and quadrature; Kovalenko's printed series (E50)."""

import numpy as np
import pytest
from numpy.testing import assert_allclose
from scipy.integrate import quad

from magbench.constants import MU_0
from magbench.earth import (CircularOrbit, polar_eccentric_coefficients, polar_field_b, polar_field_direction_acceleration,
                            polar_field_direction_angle, polar_field_direction_rate, polar_fourier_coefficients,
                            polar_gravity_factor, polar_orbit_acceleration, polar_orbit_rate)

U = np.linspace(-7.0, 7.0, 2001)


def test_tan_eta_is_twice_tan_u_and_eta_is_continuous():
    eta = polar_field_direction_angle(U)
    away = np.abs(np.cos(U)) > 1e-3
    # (6.32) tan η = 2 tan u; rounding of tan near its poles is excluded above.
    assert_allclose(np.tan(eta[away]), 2 * np.tan(U[away]), rtol=1e-9, atol=1e-12)
    # (6.32) arccos form on [0, π]: cos η = cos u/√(1 + 3 sin²u).
    assert_allclose(np.cos(eta), np.cos(U) / np.sqrt(1 + 3 * np.sin(U) ** 2), atol=1e-14)
    # Unwrapped: steps of the grid (0.007 rad) times the largest rate 2 (plus nothing).
    assert np.all(np.diff(eta) > 0) and np.max(np.diff(eta)) < 2.01 * np.diff(U)[0]


def test_eta_is_the_dipole_field_angle_on_a_polar_orbit():
    """η from an independent path: CircularOrbit's dipole field in orbital axes (X along
    track, Z radial up): B_X ∝ cos u, B_Z ∝ −2 sin u, η the angle from X toward −Z."""
    orbit = CircularOrbit(7000e3, np.pi / 2, 8e22)
    t = np.linspace(0.0, orbit.period, 97)
    b = orbit.field_orbital(t)
    u = orbit.argument_of_latitude(t)
    angle = np.unwrap(np.arctan2(-b[:, 2], b[:, 0]))
    # Rounding of the field's components (relative 1e-15) only.
    assert_allclose(angle, polar_field_direction_angle(u), atol=1e-12)
    # |B| = B0 √(1 + 3 sin²u), B0 = μ0 M/(4π r³): rounding only.
    b0 = MU_0 * 8e22 / (4 * np.pi * 7000e3**3)
    assert_allclose(np.linalg.norm(b, axis=-1), polar_field_b(u, b0), rtol=1e-13)


def test_rate_and_acceleration_are_derivatives_of_eta():
    h = 1e-4
    eta = polar_field_direction_angle
    # Central differences: truncation h²/6 η''' ≈ 1e-8·(|η'''| ≤ 20), rounding 1e-16/h².
    assert_allclose((eta(U + h) - eta(U - h)) / (2 * h), polar_field_direction_rate(U), atol=1e-7)
    second = (eta(U + h) - 2 * eta(U) + eta(U - h)) / h**2
    # Second difference: truncation h²/12 η'''' ≈ 1e-8·100, rounding 4e-16/h² ≈ 4e-8.
    assert_allclose(second, polar_field_direction_acceleration(U), atol=2e-6)
    # The reference's reconstruction of (6.34a) in its own words: −6 sin 2u/(1 + 3 sin²u)².
    assert_allclose(polar_field_direction_acceleration(U, 1e-3),
                    -6e-6 * np.sin(2 * U) / (1 + 3 * np.sin(U) ** 2) ** 2, rtol=1e-14)


def test_symmetries():
    eta = polar_field_direction_angle
    # η − u is odd and π-periodic; η̈ is odd; sin 2λ is odd (rounding only).
    assert_allclose(eta(-U), -eta(U), atol=1e-15)
    assert_allclose(eta(U + np.pi) - (U + np.pi), eta(U) - U, atol=1e-13)
    assert_allclose(polar_field_direction_acceleration(-U), -polar_field_direction_acceleration(U), atol=1e-15)
    # λ = η (6.60): sin 2λ = sin 2η (rounding only).
    assert_allclose(polar_gravity_factor(U), np.sin(2 * eta(U)), atol=1e-14)


def _quadrature(f, n):
    return 2 / np.pi * quad(lambda u: f(u) * np.sin(2 * n * u), 0.0, np.pi, epsabs=1e-13, limit=200)[0]


@pytest.mark.parametrize("n", [1, 2, 3, 4, 5])
def test_fourier_coefficients_against_quadrature(n):
    angle, acceleration, gravity = (c[n - 1] for c in polar_fourier_coefficients(5))
    # quad's absolute error request 1e-13, times 2/π.
    assert_allclose(_quadrature(lambda u: polar_field_direction_angle(u) - u, n), angle, atol=1e-12)
    assert_allclose(_quadrature(polar_field_direction_acceleration, n), acceleration, atol=1e-12)
    assert_allclose(_quadrature(polar_gravity_factor, n), gravity, atol=1e-12)


def test_fourier_series_rebuild_the_functions():
    angle, acceleration, gravity = polar_fourier_coefficients(40)
    s = np.sin(2 * np.outer(np.arange(1, 41), U))
    # Truncation after 40 terms: 40·(1/3)^41 < 1e-17.
    assert_allclose(angle @ s, polar_field_direction_angle(U) - U, atol=1e-14)
    assert_allclose(acceleration @ s, polar_field_direction_acceleration(U), atol=1e-13)
    assert_allclose(gravity @ s, polar_gravity_factor(U), atol=1e-14)


# Kovalenko (1975) E50: printed coefficients (seed lines 136–137, 144), tolerance half a unit of
# the last printed digit. Those that reproduce pass; those that do not are strict xfails that
# assert the printed value, each beside the computed one above.
PRINTED = [  # (series, index, printed, resolution)
    ("angle", 0, 0.34, 0.005), ("angle", 1, 0.075, 0.0005),
    ("acceleration", 0, -1.36, 0.005), ("acceleration", 1, -1.20, 0.005),
    ("gravity", 0, 0.88, 0.005), ("gravity", 1, 0.27, 0.005), ("gravity", 2, 0.08, 0.005),
]
_REASONS = {
    ("angle", 0): "exact 1/3 = 0.3333; 0.34 is 0.0067 off (> 0.005)",
    ("angle", 1): "exact 1/18 = 0.0556; 0.075 is 35 % off",
    ("acceleration", 0): "exact 4/3 = 1.3333; 1.36 is 0.027 off (2 %, follows from 0.34·4)",
    ("acceleration", 1): "exact 8/9 = 0.889; 1.20 follows from 0.075·16",
    ("gravity", 0): "exact 8/9 = 0.8889; 0.88 is 0.0089 off (> 0.005)",
    ("gravity", 1): "exact 8/27 = 0.2963; 0.27 is 0.026 off",
    ("gravity", 2): "exact 8/81 = 0.0988; 0.08 is 0.019 off",
}


@pytest.mark.parametrize("series, index, printed, resolution", [
    pytest.param(*row, marks=pytest.mark.xfail(strict=True, reason=_REASONS[row[:2]])) for row in PRINTED])
def test_kovalenko_printed_series(series, index, printed, resolution):
    coefficients = dict(zip(("angle", "acceleration", "gravity"), polar_fourier_coefficients(3)))
    assert_allclose(coefficients[series][index], printed, atol=resolution)


def test_computed_series_values():
    angle, acceleration, gravity = polar_fourier_coefficients(3)
    # The exact fractions, to rounding.
    assert_allclose(angle, [1 / 3, 1 / 18, 1 / 81], rtol=1e-15)
    assert_allclose(acceleration, [-4 / 3, -8 / 9, -4 / 9], rtol=1e-15)
    assert_allclose(gravity, [8 / 9, 8 / 27, 8 / 81], rtol=1e-15)


def test_eccentric_terms_are_kovalenkos_first_order_expansion():
    n, e = 1e-3, 1e-3
    t = np.linspace(0.0, 2 * np.pi / n, 201)
    # Exact true-anomaly rate from Kepler's equation, against (6.30): error O(e²) = 1e-6 of n.
    mean = n * t
    ecc = mean.copy()
    for _ in range(30):
        ecc = mean + e * np.sin(ecc)
    nu = 2 * np.arctan2(np.sqrt(1 + e) * np.sin(ecc / 2), np.sqrt(1 - e) * np.cos(ecc / 2))
    exact_rate = n * (1 + e * np.cos(nu)) ** 2 / (1 - e**2) ** 1.5
    assert_allclose(polar_orbit_rate(t, n, e), exact_rate, atol=5 * e**2 * n)
    h = 1.0
    derivative = (polar_orbit_rate(t + h, n, e) - polar_orbit_rate(t - h, n, e)) / (2 * h)
    # (6.31) is the derivative of (6.30): central-difference truncation (nh)²/6 relative.
    assert_allclose(polar_orbit_acceleration(t, n, e), derivative, atol=1e-12)


def test_bad_input_is_refused():
    with pytest.raises(ValueError, match="eccentricity"):
        polar_orbit_rate(0.0, 1e-3, 1.0)
    with pytest.raises(ValueError, match="equatorial_b"):
        polar_field_b(0.0, -1.0)
    with pytest.raises(ValueError, match="count"):
        polar_fourier_coefficients(0)


def _kepler_field_angle_acceleration(e, samples=4096):
    """η̈/ω0² over one orbit of an ellipse with the perigee at the node (u = true anomaly), by
    second differences of η(u(t)) with u from Kepler's equation."""
    t = np.arange(samples) * 2 * np.pi / samples
    h = 1e-4

    def eta_of(time):
        ecc = time.copy()
        for _ in range(60):
            ecc = time + e * np.sin(ecc)
        nu = 2 * np.arctan2(np.sqrt(1 + e) * np.sin(ecc / 2), np.sqrt(1 - e) * np.cos(ecc / 2))
        return polar_field_direction_angle(nu)

    return (eta_of(t + h) - 2 * eta_of(t) + eta_of(t - h)) / h**2


def test_eccentric_terms_against_keplers_equation():
    e = 1e-4
    first = (_kepler_field_angle_acceleration(e) - _kepler_field_angle_acceleration(0.0)) / e
    coefficients = -2 / first.size * np.fft.rfft(first).imag      # sine coefficients b_m
    # −η̈/ω0² = … + e Σ c_k sin (2k+1)ω0t: the odd harmonics; O(e) = 1e-4 relative and the
    # second differences' rounding (1e-16/h²/e ≈ 1e-4).
    assert_allclose(-coefficients[1:9:2], polar_eccentric_coefficients(4), atol=2e-3)
    assert_allclose(coefficients[2:9:2], 0.0, atol=2e-3)


@pytest.mark.parametrize("index, printed", [
    pytest.param(0, 4.0, marks=pytest.mark.xfail(strict=True, reason="exact 4/3 = 1.333 (perigee at the node); "
                                                 "4.0 follows from dropping the shift u = M + 2e sin M")),
    pytest.param(1, 5.8, marks=pytest.mark.xfail(strict=True, reason="exact 4.0")),
    pytest.param(2, 2.4, marks=pytest.mark.xfail(strict=True, reason="exact 100/27 = 3.70")),
])
def test_kovalenko_printed_eccentric_terms(index, printed):
    # Printed to one decimal: half a unit 0.05.
    assert_allclose(polar_eccentric_coefficients(3)[index], printed, atol=0.05)
