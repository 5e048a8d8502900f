"""Unloading capacity: the closed forms against sympy, quadrature and CircularOrbit's field."""

import numpy as np
import pytest
import sympy as sp
from numpy.testing import assert_allclose
from scipy.integrate import quad

from magbench.constants import MU_0
from magbench.earth import CircularOrbit, mean_square_field, mean_square_perpendicular_field
from magbench.earth.unloading_capacity import (field_direction_second_moment, field_second_moment,
                                               unloadable_fraction, worst_unloading_direction)

RADIUS = 7.0e6      # m
MOMENT = 8.0e22     # A·m², about the Earth's
SAMPLES = 720       # instants over one period, the end excluded
INCLINATIONS = np.radians([0.0, 10.0, 30.0, 51.6, 70.0, 90.0, 97.3, 140.0, 180.0])


def _orbit(inclination):
    # A non-zero node checks the orbit axes built below; the axial dipole makes it irrelevant.
    return CircularOrbit(RADIUS, inclination, MOMENT, ascending_node=0.7)


def _orbit_axes(orbit):
    """Rows x̂ (ascending node), ŷ (90° ahead), n̂ (normal), inertial components."""
    node = orbit.position(0.0) / orbit.radius
    ahead = orbit.position(orbit.period / 4.0) / orbit.radius
    return np.stack([node, ahead, orbit.orbit_normal()])


def _sampled_field(inclination):
    """B/B0 in orbit axes at equally spaced instants over one period (end excluded)."""
    orbit = _orbit(inclination)
    b0 = MU_0 * MOMENT / (4.0 * np.pi * RADIUS**3)
    b = orbit.field(np.linspace(0.0, orbit.period, SAMPLES, endpoint=False))
    return b @ _orbit_axes(orbit).T / b0


@pytest.mark.parametrize("inclination", INCLINATIONS)
def test_second_moments_are_the_sampled_means(inclination):
    b = _sampled_field(inclination)
    b_hat = b / np.linalg.norm(b, axis=-1, keepdims=True)
    # Equally spaced samples average a trigonometric polynomial (degree 4 in u) exactly, and the
    # analytic 1/(1 + a sin²u) to far below rounding at 720 samples: rounding-level tolerances
    # (the orbit axes from positions carry ~1e-16 errors, the period ~1e-16 relative).
    assert_allclose(field_second_moment(inclination), np.einsum("ti,tj->ij", b, b) / SAMPLES, atol=1e-12)
    assert_allclose(field_direction_second_moment(inclination),
                    np.einsum("ti,tj->ij", b_hat, b_hat) / SAMPLES, atol=1e-12)
    assert_allclose(np.trace(field_second_moment(inclination)), 1.0 + 1.5 * np.sin(inclination) ** 2,
                    rtol=1e-14)  # the same closed form written twice: rounding


def test_second_moment_by_sympy():
    """The averages over u of the dipole field in orbit axes, symbolically."""
    u, i = sp.symbols("u i", real=True)
    b = sp.Matrix([3 * sp.sin(i) * sp.sin(u) * sp.cos(u), sp.sin(i) * (3 * sp.sin(u) ** 2 - 1), -sp.cos(i)])
    expected = sp.Matrix([[sp.Rational(9, 8) * sp.sin(i) ** 2, 0, 0],
                          [0, sp.Rational(11, 8) * sp.sin(i) ** 2, -sp.sin(i) * sp.cos(i) / 2],
                          [0, -sp.sin(i) * sp.cos(i) / 2, sp.cos(i) ** 2]])
    for row in range(3):
        for col in range(row, 3):
            mean = sp.integrate(sp.expand(b[row] * b[col]), (u, 0, 2 * sp.pi)) / (2 * sp.pi)
            assert sp.simplify(mean - expected[row, col]) == 0


def test_normalised_averages_by_quadrature_and_the_ordering_identity_by_sympy():
    for a in [0.1, 1.0, 2.5, 3.0]:
        q = np.sqrt(1.0 + a)
        mean = [quad(lambda x, p=p: np.sin(x) ** p / (1.0 + a * np.sin(x) ** 2), 0.0, 2 * np.pi,
                     epsabs=1e-14, epsrel=1e-13)[0] / (2 * np.pi) for p in (0, 2, 4)]
        # adaptive quadrature of a smooth periodic integrand, asked for 1e-13
        assert_allclose(mean, [1 / q, 1 / (q * (q + 1)), (q + 2) / (2 * q * (q + 1) ** 2)], rtol=1e-11)
    # λ₊ − xx ≥ 0 of the normalised matrix: P(q) − q(7q − 11)² = 8(q − 1)²(q − 2)².
    q = sp.symbols("q", positive=True)
    p = 8 * q**4 + q**3 - 50 * q**2 + 25 * q + 32
    assert sp.expand(p - q * (7 * q - 11) ** 2 - 8 * (q - 1) ** 2 * (q - 2) ** 2) == 0


def test_polar_normalised_value_and_the_basic_average_by_sympy():
    """On a polar orbit ⟨B̂x²⟩ = ⟨B̂y²⟩ = 1/2 exactly, so the worst u₁ is 1/2; and
    ⟨1/(1 + a sin²u)⟩ = 1/√(1 + a)."""
    # The integrands depend on sin²u only (period π, even about π/2): the mean over a period is
    # the mean over [0, π/2), where t = tan u makes them rational in t (sympy integrates fast).
    t = sp.symbols("t", nonnegative=True)
    a = sp.symbols("a", positive=True)
    s2 = t**2 / (1 + t**2)

    def mean(integrand):
        return 2 / sp.pi * sp.integrate(sp.cancel(integrand / (1 + t**2)), (t, 0, sp.oo))

    for numerator in (9 * s2 * (1 - s2), (3 * s2 - 1) ** 2):
        assert sp.simplify(mean(numerator / (1 + 3 * s2)) - sp.Rational(1, 2)) == 0
    assert sp.simplify(mean(1 / (1 + a * s2)) - 1 / sp.sqrt(1 + a)) == 0


@pytest.mark.parametrize("normalised", [False, True])
def test_worst_fraction_is_the_largest_eigenvalue(normalised):
    i = np.radians(np.linspace(0.0, 180.0, 181))
    moment = field_direction_second_moment(i) if normalised else field_second_moment(i)
    values, vectors = np.linalg.eigh(moment)
    trace = np.trace(moment, axis1=-2, axis2=-1)
    # closed form against LAPACK's eigenvalues of the same matrix: rounding
    assert_allclose(unloadable_fraction(i, normalised=normalised), 1.0 - values[:, -1] / trace, atol=1e-14)
    worst = worst_unloading_direction(i, normalised=normalised)
    assert_allclose(np.linalg.norm(worst, axis=-1), 1.0, rtol=1e-15)  # sin² + cos²: rounding
    assert_allclose(unloadable_fraction(i, worst, normalised=normalised),
                    unloadable_fraction(i, normalised=normalised), atol=1e-14)  # rounding
    # the eigenvector (up to sign) where the largest eigenvalue is single, i.e. off the polar
    # orbit of the normalised matrix, where x̂ and ŷ tie
    single = values[:, -1] - values[:, -2] > 1e-6
    assert_allclose(np.abs(np.sum(worst * vectors[:, :, -1], axis=-1))[single], 1.0, atol=1e-9)  # gap ≥ 1e-6
    # it is the largest eigenvalue of the (ŷ, n̂) block, never the xx entry
    assert np.all(values[:, -1] >= moment[:, 0, 0] - 1e-15)


@pytest.mark.parametrize("inclination", [0.3, np.radians(51.6), np.pi / 2, np.radians(97.3)])
def test_no_division_fraction_is_the_field_statistics_ratio(inclination):
    orbit = _orbit(inclination)
    axes = _orbit_axes(orbit)
    total = mean_square_field(orbit, duration=orbit.period, samples=SAMPLES)
    rng = np.random.default_rng(5)
    for e in [np.eye(3)[0], np.eye(3)[1], np.eye(3)[2], worst_unloading_direction(inclination),
              *rng.normal(size=(3, 3))]:
        across = mean_square_perpendicular_field(orbit, axes.T @ e, duration=orbit.period, samples=SAMPLES)
        # exact averages of trigonometric polynomials by equal sampling: rounding
        assert_allclose(unloadable_fraction(inclination, e), across / total, rtol=1e-12, atol=1e-14)


@pytest.mark.parametrize("inclination", [0.3, np.radians(51.6), np.pi / 2, np.radians(130.0)])
def test_normalised_fraction_is_the_sampled_mean(inclination):
    b = _sampled_field(inclination)
    b_hat = b / np.linalg.norm(b, axis=-1, keepdims=True)
    directions = np.random.default_rng(7).normal(size=(200, 3))
    directions /= np.linalg.norm(directions, axis=-1, keepdims=True)
    sampled = 1.0 - np.mean((b_hat @ directions.T) ** 2, axis=0)
    fractions = unloadable_fraction(inclination, directions, normalised=True)
    # analytic periodic integrand, 720 equal samples: rounding
    assert_allclose(fractions, sampled, atol=1e-12)
    assert np.all(fractions >= unloadable_fraction(inclination, normalised=True) - 1e-15)  # the worst is a minimum


def test_limits():
    # exact values, computed through sin/cos of 0 and π/2: rounding tolerances
    for normalised in (False, True):
        assert_allclose(unloadable_fraction([0.0, np.pi], normalised=normalised), 0.0, atol=1e-15)
        assert_allclose(unloadable_fraction(0.0, [0.0, 0.0, 1.0], normalised=normalised), 0.0, atol=1e-15)
        assert_allclose(unloadable_fraction(np.pi / 2, [0.0, 0.0, 1.0], normalised=normalised), 1.0, atol=1e-15)
        assert_allclose(worst_unloading_direction([0.0, np.pi / 2], normalised=normalised),
                        [[0.0, 0.0, 1.0], [0.0, 1.0, 0.0]], atol=1e-15)
    assert_allclose(unloadable_fraction(np.pi / 2), 9.0 / 20.0, rtol=1e-15)
    assert_allclose(unloadable_fraction(np.pi / 2, [0.0, 1.0, 0.0]), 9.0 / 20.0, rtol=1e-15)  # the dipole axis
    assert_allclose(unloadable_fraction(np.pi / 2, normalised=True), 0.5, rtol=1e-15)
    assert_allclose(unloadable_fraction(np.pi / 2, [1.0, 1.0, 0.0], normalised=True), 0.5, rtol=1e-15)
    # equatorial: B along the normal, so everything across it (x̂, ŷ) is fully unloadable
    assert_allclose(unloadable_fraction(0.0, np.eye(3)[:2]), 1.0, atol=1e-15)


def test_symmetry_of_retrograde_orbits():
    i = np.radians([5.0, 30.0, 51.6, 80.0])
    flip = np.diag([1.0, 1.0, -1.0])
    for moment in (field_second_moment, field_direction_second_moment):
        # sin(π − i) = sin i and cos(π − i) = −cos i to rounding
        assert_allclose(moment(np.pi - i), flip @ moment(i) @ flip, atol=1e-15)
    e = np.array([0.3, -0.5, 0.8])
    for normalised in (False, True):
        assert_allclose(unloadable_fraction(np.pi - i, normalised=normalised),
                        unloadable_fraction(i, normalised=normalised), atol=1e-14)  # rounding
        assert_allclose(unloadable_fraction(np.pi - i, e, normalised=normalised),
                        unloadable_fraction(i, flip @ e, normalised=normalised), atol=1e-14)  # rounding


def test_vectorised_shapes_and_broadcasting():
    i = np.radians([[10.0, 50.0, 90.0], [100.0, 140.0, 170.0]])
    assert field_second_moment(i).shape == (2, 3, 3, 3)
    assert field_direction_second_moment(i).shape == (2, 3, 3, 3)
    assert unloadable_fraction(i).shape == (2, 3)
    assert worst_unloading_direction(i, normalised=True).shape == (2, 3, 3)
    directions = np.array([[1.0, 0.0, 0.0], [0.0, 2.0, 0.0], [0.0, 0.0, 3.0]])
    values = unloadable_fraction(i, directions)
    assert values.shape == (2, 3)
    expected = [[unloadable_fraction(i[r, c], directions[c]) for c in range(3)] for r in range(2)]
    assert_allclose(values, expected, rtol=1e-15)  # the same arithmetic element by element
    assert np.ndim(unloadable_fraction(0.4)) == 0


def test_averaged_decay_rates_match_one_orbit_of_the_laws():
    """Over one orbit with slow unloading, the momentum maps by ≈ exp(−k T (rate matrix))."""
    inclination = np.radians(51.6)
    b = _sampled_field(inclination)                          # B/B0 in orbit axes
    steps, period = SAMPLES, 1.0                             # time in periods, B in B0
    gain = 0.01                                              # k B0² T = 0.01 (5.6); k T = 0.01 (5.1)
    for normalised in (False, True):
        f = b / np.linalg.norm(b, axis=-1, keepdims=True) if normalised else b
        step_maps = np.eye(3) - gain * period / steps * (np.sum(f * f, axis=-1)[:, None, None] * np.eye(3)
                                                          - np.einsum("ti,tj->tij", f, f))
        transition = np.eye(3)
        for m in step_maps:                                  # explicit Euler: O(k dt) per orbit
            transition = m @ transition
        worst = worst_unloading_direction(inclination, normalised=normalised)
        scale = 1.0 if normalised else 1.0 + 1.5 * np.sin(inclination) ** 2    # ⟨B²⟩/B0²
        rate = gain * scale * unloadable_fraction(inclination, normalised=normalised)
        # The one-orbit map is exp(−kT⟨A⟩) up to O((kT)²) commutator terms (plus Euler's, of the
        # same order): at kT = 0.01 about 1e-5 of the rate here; 1e-3 leaves room, 1 % would not
        # tell a wrong fraction from a right one reliably.
        assert_allclose(-np.log(worst @ transition @ worst) / period, rate, rtol=1e-3)


def test_bad_input_names_the_parameter():
    for bad in (-0.1, 3.5, np.nan, [0.2, 4.0]):
        with pytest.raises(ValueError, match="inclination"):
            field_second_moment(bad)
        with pytest.raises(ValueError, match="inclination"):
            field_direction_second_moment(bad)
        with pytest.raises(ValueError, match="inclination"):
            unloadable_fraction(bad)
        with pytest.raises(ValueError, match="inclination"):
            worst_unloading_direction(bad)
    with pytest.raises(ValueError, match=r"inclination must lie in \[0.0, 3.14159.*\] rad, got -0.1"):
        unloadable_fraction(-0.1)
    with pytest.raises(ValueError, match="direction must be non-zero"):
        unloadable_fraction(0.5, [0.0, 0.0, 0.0])
    with pytest.raises(ValueError, match=r"direction must have shape \(\.\.\., 3\)"):
        unloadable_fraction(0.5, [1.0, 0.0])
    with pytest.raises(ValueError, match="direction must be finite"):
        unloadable_fraction(0.5, [1.0, np.inf, 0.0])
