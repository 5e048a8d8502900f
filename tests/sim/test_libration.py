"""magbench.sim.simulate_libration: the linearised libration frequencies of a gravity-gradient
body, the magnetic ball damper's decay, members against separate runs, and momentum
conservation with the external torques off. Satellite parameters are ours (a 1–2 m boom of a
few kg·m²), not a source's."""

import numpy as np
import pytest
from numpy.testing import assert_allclose

from magbench.dynamics import libration_angles
from magbench.earth import CircularOrbit
from magbench.sim import LibrationSatellite, simulate_libration

INERTIA = (2.0, 2.0, 0.02)     # roll, pitch, yaw (boom) [kg·m²]: ours


def _frequency(time, angle):
    """Mean angular frequency from linearly interpolated zero crossings [rad/s]."""
    i = np.where(np.diff(np.sign(angle)) != 0)[0]
    crossings = time[i] - angle[i] * (time[i + 1] - time[i]) / (angle[i + 1] - angle[i])
    return np.pi / np.mean(np.diff(crossings))


@pytest.fixture(scope="module")
def orbit():
    return CircularOrbit(7.0e6, 1.0, 8.0e22)


def test_pitch_and_roll_frequencies_match_the_linearised_equations(orbit):
    """Undamped, no magnet. Pitch: ω_p = ω0 √(3 (I_x − I_z)/I_y); roll/yaw: the characteristic
    equation s⁴ + (1 + 3k_R + k_R k_Y) ω0² s² + 4 k_R k_Y ω0⁴ = 0 with k_R = (I_y − I_z)/I_x,
    k_Y = (I_y − I_x)/I_z (Hughes, Spacecraft Attitude Dynamics (1986), §9.3; Wertz (1978)
    §18.3); here I_x = I_y so k_Y = 0 and the roll mode is ω0 √(1 + 3k_R) ≈ 2ω0. Tolerance 2e-3
    relative: a 0.05 rad amplitude shifts the frequency by ~θ²/16 ≈ 2e-4, the zero crossings
    are interpolated linearly between 20 s samples (ω h ≈ 0.04) over three orbits, measured
    6e-4 and 3e-4."""
    sat = LibrationSatellite(INERTIA, 0.0, 0.01, 0.0)
    n = orbit.mean_motion
    pitch_run = simulate_libration(sat, orbit, 0.05, 0.0, 3 * orbit.period, 20.0)
    roll_run = simulate_libration(sat, orbit, 0.0, 0.05, 3 * orbit.period, 20.0)
    ix, iy, iz = INERTIA
    assert_allclose(_frequency(pitch_run.time, pitch_run.pitch[:, 0]), n * np.sqrt(3 * (ix - iz) / iy), rtol=2e-3)
    assert_allclose(_frequency(roll_run.time, roll_run.roll[:, 0]), n * np.sqrt(1 + 3 * (iy - iz) / ix), rtol=2e-3)
    assert np.max(np.abs(pitch_run.roll)) < 1e-9 and np.max(np.abs(roll_run.pitch)) < 0.05 * 0.05


def test_momentum_is_conserved_without_gravity_gradient_and_magnets():
    """No external torque (gravity gradient switched off, both magnets 0): the viscous coupling
    trades momentum between body and ball, and their sum in inertial axes stays. The drift is
    RK4's truncation (body rates up to 0.03 rad/s): measured 1.3e-4, 8.0e-6 and 5.3e-7 of |H|
    at steps of 10, 5 and 2.5 s (fourth order), so 2e-6 at 2.5 s."""
    orbit = CircularOrbit(7.0e6, 1.0, 8.0e22, argument_of_latitude0=np.array([0.0, 1.0]))
    sat = LibrationSatellite((2.0, 1.5, 0.5), 0.0, 0.01, 2e-4)
    run = simulate_libration(sat, orbit, [0.3, -0.2], [0.1, 0.4], 3000.0, 2.5, record_interval=100.0,
                             initial_rate=[[0.01, -0.02, 0.03], [0.0, 0.01, -0.01]], gravity_gradient=False)
    h = np.stack([run.momentum_x, run.momentum_y, run.momentum_z], axis=-1)
    assert_allclose(h, np.broadcast_to(h[:1], h.shape), rtol=0, atol=2e-6 * np.max(np.abs(h)))


def test_members_equal_separate_runs():
    phases = np.array([0.0, 1.5, 3.0])
    sat = LibrationSatellite(INERTIA, 0.2, 0.05, 1e-4)
    together = simulate_libration(sat, CircularOrbit(7.0e6, 0.6, 8.0e22, argument_of_latitude0=phases),
                                  np.radians(20), 0.0, 2000.0, 40.0, record_interval=400.0)
    for i, u in enumerate(phases):
        alone = simulate_libration(sat, CircularOrbit(7.0e6, 0.6, 8.0e22, argument_of_latitude0=u),
                                   np.radians(20), 0.0, 2000.0, 40.0, record_interval=400.0)
        assert_allclose(together.states[:, :, i], alone.states[:, :, 0], rtol=1e-12, atol=1e-15)
    assert together.libration.shape == (6, 3)


def test_libration_angles_of_a_pitched_and_rolled_boom():
    half = 0.5 * 0.3
    q = [np.cos(half), 0.0, np.sin(half), 0.0]          # 0.3 rad about Y = orbit normal
    assert_allclose(libration_angles(q, np.eye(3)), [0.3, 0.0, 0.3], atol=1e-15)
    q = [np.cos(half), np.sin(half), 0.0, 0.0]          # 0.3 rad about X: boom toward −Y
    assert_allclose(libration_angles(q, np.eye(3)), [0.0, -0.3, 0.3], atol=1e-15)


@pytest.mark.parametrize("kwargs, message", [
    (dict(inertia=(2.0, -1.0, 0.1)), "inertia must be > 0"),
    (dict(damper_inertia=0.0), "damper_inertia must be > 0"),
    (dict(damping=-1.0), "damping must be >= 0"),
    (dict(damper_moment=np.nan), "damper_moment must be finite"),
])
def test_bad_satellite_is_refused_by_name(kwargs, message):
    args = dict(inertia=INERTIA, damper_moment=1.0, damper_inertia=0.01, damping=1e-4) | kwargs
    with pytest.raises(ValueError, match=message):
        LibrationSatellite(**args)


def test_bad_run_is_refused_by_name(orbit):
    sat = LibrationSatellite(INERTIA, 0.0, 0.01, 0.0)
    with pytest.raises(ValueError, match="record_interval must be a whole number of steps"):
        simulate_libration(sat, orbit, 0.1, 0.0, 100.0, 10.0, record_interval=15.0)
    with pytest.raises(ValueError, match="step must be > 0"):
        simulate_libration(sat, orbit, 0.1, 0.0, 100.0, -1.0)
    with pytest.raises(ValueError, match="satellite must be a LibrationSatellite"):
        simulate_libration(INERTIA, orbit, 0.1, 0.0, 100.0, 10.0)
