"""magbench.dynamics aerodynamic angles: SamSat-218D's B1, its inverse, and the corrected
kinematics against finite differences of the attitude on a real orbit."""

import numpy as np
import pytest
from numpy.testing import assert_allclose
from scipy.spatial.transform import Rotation

from magbench.dynamics import aerodynamic_angles, aerodynamic_attitude_matrix, aerodynamic_body_rates
from magbench.earth import CircularOrbit

RNG = np.random.default_rng(218)


def test_matrix_is_x_y_x_sequence():
    a, f, g = RNG.uniform(-3, 3, size=(3, 50))
    # Peer: scipy's intrinsic x-y-x Euler sequence; B1 is the passive (transposed) matrix.
    expected = Rotation.from_euler("XYX", np.stack([g, a, f], axis=-1)).as_matrix().swapaxes(-1, -2)
    assert_allclose(aerodynamic_attitude_matrix(a, f, g), expected, atol=1e-15)


def test_angles_round_trip():
    a = RNG.uniform(0.01, np.pi - 0.01, 200)
    f, g = RNG.uniform(-np.pi, np.pi, size=(2, 200))
    back = aerodynamic_angles(aerodynamic_attitude_matrix(a, f, g))
    # arccos near 0.01 rad loses digits: error ≈ 1e-16 / sin(0.01) ≈ 1e-14.
    assert_allclose(back, [a, f, g], atol=1e-12)


def _orbit_to_inertial_body(orbit, angles, time):
    """Body axes as rows in inertial components: B1 · (orbital axes)."""
    return aerodynamic_attitude_matrix(*angles) @ orbit.orbital_axes(time)


def test_corrected_kinematics_match_finite_differences_on_an_orbit():
    orbit = CircularOrbit(6856e3, np.radians(97.3), 7.72e22, 0.7, ascending_node=0.3)
    start = np.array([0.8, -0.5, 2.0])
    rates = np.radians([3.0, -7.0, 5.0])
    for time in (0.0, 100.0, 1234.5):
        c = lambda t: _orbit_to_inertial_body(orbit, start + rates * t, t)   # noqa: E731
        h = 1e-3
        # ω× = −Ċ Cᵀ for C mapping inertial to body components.
        skew = -(c(time + h) - c(time - h)) / (2 * h) @ c(time).T
        omega = np.array([skew[2, 1], skew[0, 2], skew[1, 0]])
        got = aerodynamic_body_rates(*(start + rates * time), *rates, orbit.mean_motion)
        # Central difference error ≈ |ω|³h²/6 ≈ 1e-10 rad/s; rounding 1e-16/h ≈ 1e-13.
        assert_allclose(got, omega, atol=1e-9)


def test_printed_row_form_is_off_by_the_orbital_rate():
    """The erratum in numbers: SamSat's printed ω0·(b21, b22, b23) is not the body rate."""
    a, f, g = 0.8, -0.5, 2.0
    w0 = 1.1e-3
    b1 = aerodynamic_attitude_matrix(a, f, g)
    corrected = aerodynamic_body_rates(a, f, g, 0.0, 0.0, 0.0, w0)
    assert_allclose(corrected, w0 * b1[:, 1], rtol=1e-15)
    assert np.linalg.norm(corrected - w0 * b1[1, :]) > 0.5 * w0


def test_broadcasting():
    out = aerodynamic_body_rates(np.zeros((4, 1)), np.zeros(5), 0.0, 0.0, 0.0, 0.0, 1e-3)
    assert out.shape == (4, 5, 3)


@pytest.mark.parametrize("call, match", [
    (lambda: aerodynamic_attitude_matrix(np.nan, 0.0, 0.0), "attack_angle must be finite"),
    (lambda: aerodynamic_angles(np.eye(2)), "matrix must have shape"),
    (lambda: aerodynamic_angles(2 * np.eye(3)), "rotation matrix"),
    (lambda: aerodynamic_angles(-np.eye(3)), "rotation matrix"),
    (lambda: aerodynamic_body_rates(0, 0, 0, 0, 0, 0, np.inf), "orbital_rate must be finite"),
])
def test_bad_input(call, match):
    with pytest.raises(ValueError, match=match):
        call()
