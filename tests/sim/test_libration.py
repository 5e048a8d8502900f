"""magbench.sim.simulate_libration: the linearised libration frequencies of a gravity-gradient
body, the magnetic ball damper's decay, members against separate runs, and momentum
conservation with the external torques off. Satellite parameters are ours (a 1–2 m boom of a
few kg·m²), not a source's."""

import numpy as np
import pytest
from numpy.testing import assert_allclose

from magbench.dynamics import kernels, libration_angles
from magbench.earth import CircularOrbit
from magbench.sim import LibrationSatellite, simulate_libration

INERTIA = (2.0, 2.0, 0.02)     # roll, pitch, yaw (boom) [kg·m²]: ours


def _frequency(time, angle):
    """Mean angular frequency from linearly interpolated zero crossings [rad/s]."""
    i = np.where(np.diff(np.sign(angle)) != 0)[0]
    crossings = time[i] - angle[i] * (time[i + 1] - time[i]) / (angle[i + 1] - angle[i])
    return np.pi / np.mean(np.diff(crossings))


def _jacobi(run, orbit):
    """The body's Jacobi integral in the orbital frame [J]: ½ ω_relᵀIω_rel + (3/2)n² ẑᵀIẑ
    − ½ n² ŷᵀIŷ, ω_rel = ω − n ŷ, ẑ the local vertical and ŷ the orbit normal in body axes
    (Hughes (1986) §9.2; constant for the undamped body). Shape (K, M)."""
    n, j = orbit.mean_motion, np.asarray(run.satellite.inertia)
    q = np.moveaxis(run.states[:4], 0, -1)
    axes = orbit.orbital_axes(run.time[:, None])
    y, z = kernels.rotate(q, axes[..., 1, :], -1.0), kernels.rotate(q, axes[..., 2, :], -1.0)
    w = np.moveaxis(run.states[4:7], 0, -1) - n * y
    return 0.5 * np.sum(j * w * w, -1) + 1.5 * n**2 * np.sum(j * z * z, -1) - 0.5 * n**2 * np.sum(j * y * y, -1)


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
    jacobi = _jacobi(pitch_run, orbit)
    # RK4 at ω h ≈ 0.04 over 3 orbits; the libration part of the integral is ~1e-9 J.
    assert_allclose(jacobi, np.broadcast_to(jacobi[:1], jacobi.shape), rtol=0, atol=1e-3 * np.ptp(
        _jacobi(simulate_libration(sat, orbit, 0.0, 0.0, 200.0, 20.0), orbit)) + 1e-14)
    assert np.max(np.abs(pitch_run.roll)) < 1e-9 and np.max(np.abs(roll_run.pitch)) < 0.05 * 0.05


def test_magnetic_damper_brings_20_degrees_down_tenfold_in_24_orbits():
    """Acceptance: a 2 kg·m² boom (I_z = 0.02 kg·m²), ball magnet 0.2 A·m², J_d = 0.05 kg·m²,
    k = 1.5e-4 N·m·s (all ours; J_d/k = 330 s ≫ h = 40 s, the ball's field frequency
    √(m_d B/J_d) ≈ 0.01 rad/s) on a 7000 km orbit inclined 0.6 rad. Three orbit phases in one
    call. The field's turning drags the ball, so a forced libration of ~1–2° remains: a
    larger k damps faster but leaves more (k = 3e-4 at 1.2 rad: 6°). Measured: 20° → 1.2–1.6°
    over the 24th orbit; the orbit-mean Jacobi integral (above its value at rest on the
    vertical) falls by 78–115 (asserted: more than 50)."""
    orbit = CircularOrbit(7.0e6, 0.6, 8.0e22, argument_of_latitude0=np.array([0.0, 2.0, 4.0]))
    sat = LibrationSatellite(INERTIA, 0.2, 0.05, 1.5e-4)
    run = simulate_libration(sat, orbit, np.radians(20), 0.0, 24 * orbit.period, 40.0, record_interval=80.0)
    per = int(orbit.period / 80.0)
    first, last = np.max(run.libration[:per], axis=0), np.max(run.libration[-per:], axis=0)
    assert_allclose(first, np.radians(20), rtol=0.08)
    assert np.all(last <= first / 10), np.degrees(last)
    energy = _jacobi(run, orbit) - _jacobi(simulate_libration(sat, orbit, 0.0, 0.0, 80.0, 40.0), orbit)[:1]
    assert np.all(np.mean(energy[-per:], axis=0) < 0.02 * np.mean(energy[:per], axis=0))


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
    with pytest.raises(ValueError, match="must agree on the members"):
        simulate_libration(sat, orbit, [0.1, 0.2], [0.0, 0.1, 0.2], 100.0, 10.0)
    with pytest.raises(ValueError, match="initial_rate"):
        simulate_libration(sat, orbit, 0.1, 0.0, 100.0, 10.0, initial_rate=[1.0, 2.0])
    with pytest.raises(ValueError, match="satellite must be a LibrationSatellite"):
        simulate_libration(INERTIA, orbit, 0.1, 0.0, 100.0, 10.0)


def test_a_damping_sweep_in_one_call_equals_separate_runs():
    """One member per damper (coupling and magnet): the same numbers as one run each."""
    orbit = CircularOrbit(7.0e6, 0.6, 8.0e22)
    damping, moment = np.array([0.5e-4, 1e-4, 3e-4]), np.array([0.1, 0.2, 0.3])
    together = simulate_libration(LibrationSatellite(INERTIA, moment, 0.05, damping), orbit, np.radians(20), 0.0,
                                  2000.0, 40.0, record_interval=400.0)
    for i in range(3):
        alone = simulate_libration(LibrationSatellite(INERTIA, moment[i], 0.05, damping[i]), orbit, np.radians(20),
                                   0.0, 2000.0, 40.0, record_interval=400.0)
        assert_allclose(together.states[:, :, i], alone.states[:, :, 0], rtol=1e-12, atol=1e-15)
    with pytest.raises(ValueError, match="damping"):
        simulate_libration(LibrationSatellite(INERTIA, 0.2, 0.05, damping), orbit, [0.1, 0.2], 0.0, 100.0, 10.0)
    with pytest.raises(ValueError, match="damping must be a scalar or one value per member"):
        LibrationSatellite(INERTIA, 0.2, 0.05, np.ones((2, 2)))
