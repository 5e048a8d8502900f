"""magbench.sim.simulate_planar: the integrated planar model against its first integral, the
linearised forced response (6.62)–(6.64), the elastic damper's transfer function (6.66)–(6.67),
the Coulomb oscillator's amplitude loss and the elastic damper with dry friction (E48)."""

import functools

import numpy as np
import pytest
from numpy.testing import assert_allclose

from magbench.control import elastic_damper_response, polar_forced_response, polar_forcing_coefficients
from magbench.dynamics import PlanarBody, PlanarDamper, planar_energy
from magbench.sim import planar_error_orbit_maxima, simulate_planar

N0 = 1e-3            # mean motion [rad/s]
B0 = 2e-5            # equatorial field [T]


def test_energy_is_conserved_without_damper_in_a_constant_field():
    body = PlanarBody(650.0, 500.0)
    run = simulate_planar(body, PlanarDamper(), N0, B0, [0.5, 2.0, 3.0], [0.0, 1e-3, -2e-3], 5000.0, 10.0,
                          field="constant")
    energy = planar_energy(run.gamma, run.rate, 650.0, 500.0, B0)
    # RK4's energy drift over 500 steps at ω_c h ≈ 0.04: measured 2.4e-8 relative.
    assert_allclose(energy, np.broadcast_to(energy[:1], energy.shape), rtol=1e-7)
    assert run.gamma.shape == (501, 3) and run.field_b.shape == (501, 3)


def test_steady_forced_response_matches_the_linearised_solution():
    """(6.62)–(6.64) with the exact forcing (40 harmonics: near ω_c the 13th still moves γ by
    1e-7 rad): a stiff magnet (ω_c = 30 ω0, between the harmonics'
    resonances) keeps γ ≈ 2e-3 rad, so sin γ ≈ γ to 1e-6 relative; |B| held at B0
    (field="direction") as the linear model assumes; damping b = 2 ω0 lets the transient
    fall by e^(−bt) ≈ 1e-11 in two orbits."""
    j = 650.0
    m = 900.0 * N0**2 * j / B0
    kd = 2 * j * 2.0 * N0
    period = 2 * np.pi / N0
    run = simulate_planar(PlanarBody(j, m), PlanarDamper(viscous=kd), N0, B0, 0.0, 0.0, 3 * period, period / 600,
                          field="direction")
    amp, phase = polar_forced_response(j, m, B0, kd, N0, count=40)
    last = run.time > 2 * period
    t = run.time[last]
    linear = np.sum(amp[:, None] * np.sin(2 * np.arange(1, 41)[:, None] * N0 * t - phase[:, None]), axis=0)
    size = np.max(np.abs(linear))
    # Residual measured between 1e-6 and 1e-5 of the amplitude (nonlinearity γ²/6 ≈ 1e-6, RK4).
    assert_allclose(run.gamma[last, 0], linear, atol=1e-5 * size)
    assert size > 1e-3


def test_elastic_damper_steady_response_matches_the_transfer_function():
    """(6.65)–(6.69): the body without a magnet of its own, held by an elastically coupled damper
    magnet; the steady γ is the superposition of A_k |W(2kω0)| sin(2kω0t + φ_k) (40 harmonics:
    the 13th still moves γ by 1e-7 rad). Stiff
    enough (ω_yc² = 400 ω0², ω_c² = 900 ω0²) that γ1 ≈ 2e-3 rad and sin γ1 ≈ γ1; the
    slowest pole decays at 5.2 ω0 (e^(−5.2·4π) ≈ 1e-28 after two orbits)."""
    j = 150.0
    ly, c, kd = 900.0 * N0**2 * j / B0, 400.0 * N0**2 * j, 20.0 * N0 * j
    period = 2 * np.pi / N0
    run = simulate_planar(PlanarBody(j, 0.0), PlanarDamper(viscous=kd, stiffness=c, damper_moment=ly), N0, B0,
                          0.0, 0.0, 3 * period, period / 1200, field="direction")
    k = np.arange(1, 41)
    forcing = polar_forcing_coefficients(j, 0.0, N0, count=40)
    amp, phase = elastic_damper_response(forcing, 2 * k * N0, j, c, kd, ly, B0)
    last = run.time > 2 * period
    t = run.time[last]
    linear = np.sum(amp[:, None] * np.sin(2 * k[:, None] * N0 * t + phase[:, None]), axis=0)
    size = np.max(np.abs(linear))
    # Residual measured below 1e-5 of the amplitude (sin γ1 ≈ γ1 to 1e-6; RK4 at the fast pole, 54 ω0 h = 0.29).
    assert_allclose(run.gamma[last, 0], linear, atol=1e-5 * size)
    assert size > 1e-3


def test_dry_friction_removes_the_coulomb_amplitude():
    """Half a swing from rest at γ0 in a constant field loses M_T(γ0 + γ1) of energy:
    LB(cos γ1 − cos γ0) = M_T(γ0 + γ1) fixes the far turning point γ1."""
    j, m, mt, g0 = 150.0, 120.0, 3e-4, 1.0
    damper = PlanarDamper(friction=mt, friction_rate=1e-7)
    run = simulate_planar(PlanarBody(j, m), damper, N0, B0, g0, 0.0, 1200.0, 0.5, field="constant")
    turn = np.argmax(np.diff(np.sign(run.rate[1:, 0])) > 0) + 1      # first stop after the swing
    g1 = -run.gamma[turn, 0]
    from scipy.optimize import brentq
    exact = brentq(lambda x: m * B0 * (np.cos(x) - np.cos(g0)) - mt * (g0 + x), 0.0, g0)
    # The smoothed sign (ε = 1e-7 rad/s against rates ~3e-3) and the sampling of the turn
    # (step 0.5 s at γ̈ ≈ 1e-5 rad/s²): ~1e-6 rad.
    assert_allclose(g1, exact, atol=2e-5)
    assert g1 < g0 - 0.1


def test_members_equal_separate_runs():
    body = PlanarBody(np.array([650.0, 300.0]), 500.0, np.array([400.0, 0.0]))
    both = simulate_planar(body, PlanarDamper(viscous=0.2), N0, B0, [0.1, -0.2], 0.0, 3000.0, 10.0)
    for i, (j, dj, g0) in enumerate([(650.0, 400.0, 0.1), (300.0, 0.0, -0.2)]):
        one = simulate_planar(PlanarBody(j, 500.0, dj), PlanarDamper(viscous=0.2), N0, B0, g0, 0.0, 3000.0, 10.0)
        # The same operations member by member: equal to rounding.
        assert_allclose(both.gamma[:, i], one.gamma[:, 0], rtol=1e-13, atol=1e-16)


@pytest.mark.parametrize("kwargs, match", [
    (dict(field="tilted"), "field"),
    (dict(step=0.0), "step"),
    (dict(body=(1.0, 1.0)), "body"),
    (dict(initial_angle=np.zeros((2, 2))), "initial_angle"),
])
def test_bad_input_is_refused(kwargs, match):
    args = dict(body=PlanarBody(1.0, 1.0), damper=PlanarDamper(), mean_motion=N0, equatorial_b=B0,
                initial_angle=0.0, initial_rate=0.0, duration=10.0, step=1.0)
    args.update(kwargs)
    with pytest.raises(ValueError, match=match):
        simulate_planar(**args)


@functools.lru_cache(maxsize=1)
def _e47_run():
    """E47 (seed line 147): h ≈ 1000 km, J = 650 / 250 kg·m², L = 500 A·m², k_д = 0.2 N·m·s;
    Kovalenko's dipole 8.1e22 A·m²; ten orbits (the damping time 2J/k_д is one orbit)."""
    from magbench.constants import EARTH_GM, EARTH_RADIUS, MU_0

    r = EARTH_RADIUS + 1000e3
    n, b0 = np.sqrt(EARTH_GM / r**3), MU_0 * 8.1e22 / (4 * np.pi * r**3)
    period = 2 * np.pi / n
    run = simulate_planar(PlanarBody(650.0, 500.0, 400.0), PlanarDamper(viscous=0.2), n, b0, 0.0, 0.0,
                          10 * period, period / 200)
    last = run.time > 8 * period
    i = np.argmax(np.abs(run.gamma[last, 0]))
    return np.degrees(abs(run.gamma[last, 0][i])), np.degrees((n * run.time[last][i]) % np.pi)


def test_e47_fig_6_7_computed():
    largest, where = _e47_run()
    # Our run: 16.47° at u = 39.6° (mod 180°); step halved changes it by 1e-3°.
    assert_allclose(largest, 16.47, atol=0.01)
    assert_allclose(where, 40, atol=0.5)          # printed "ω0t ≈ 40°": agrees


def test_e47_fig_6_7_printed_17_degrees():
    """Kovalenko's 'about 17°' is read off his Fig. 6.7, a computer run like ours: it is held to
    the precision of reading a printed curve, one unit of the printed digit (chapter 8's row
    kov-e47-fig6-7-error does the same). Ours: 16.47°."""
    assert_allclose(_e47_run()[0], 17, atol=1.0)


def _elastic_energy(run, j, ly, c, b):
    """Jγ̇²/2 + L_yB(1 − cos γ1) + c(γ − γ1)²/2 [J]: the body without a magnet, the damper's
    magnet in a fixed field and the spring between them."""
    g, g1 = run.gamma, run.damper_angle
    return 0.5 * j * run.rate**2 + ly * b * (1 - np.cos(g1)) + 0.5 * c * (g - g1) ** 2


def test_elastic_dry_friction_never_adds_energy_along_a_run():
    """In a constant field the energy only falls (power −(k_д s² + M_T|s|)); three starts."""
    j, ly, c, kd, mt = 150.0, 120.0, 4e-3, 1e-2, 3e-4
    damper = PlanarDamper(viscous=kd, friction=mt, stiffness=c, damper_moment=ly)
    run = simulate_planar(PlanarBody(j, 0.0), damper, N0, B0, [0.3, 1.0, -2.0], [0.0, 1e-3, 0.0], 6000.0, 0.5,
                          field="constant")
    energy = _elastic_energy(run, j, ly, c, B0)
    rise = np.diff(energy, axis=0).max()
    # RK4's local error at h = 0.5 s against the slip's relaxation (c + L_yB)/k_д = 0.64 /s:
    # any rise is below 1e-9 of the starting energy (≈ 1e-4 J).
    assert rise < 1e-9 * energy[0].min()
    assert np.all(energy[-1] < 0.2 * energy[0])


def test_elastic_dry_friction_limits():
    """M_T → 0 gives the viscous elastic damper; M_T above any drive locks the magnet to the body
    (γ − γ1 = γ(0), γ1(0) = 0), which then swings as a pendulum of moment L_y without loss."""
    j, ly, c, kd = 150.0, 120.0, 4e-3, 1e-2
    args = (N0, B0, [0.3, 1.0], 0.0, 3000.0, 0.5)
    viscous = simulate_planar(PlanarBody(j, 0.0), PlanarDamper(viscous=kd, stiffness=c, damper_moment=ly), *args,
                              field="constant")
    tiny = simulate_planar(PlanarBody(j, 0.0), PlanarDamper(viscous=kd, friction=1e-12, stiffness=c,
                                                            damper_moment=ly), *args, field="constant")
    # A friction 1e-12 N·m against drives ≈ 1e-3 N·m moves the magnet by ≈ 1e-12/k_д × t ≈ 3e-7 rad at most.
    assert_allclose(tiny.gamma, viscous.gamma, atol=3e-7)
    locked = simulate_planar(PlanarBody(j, 0.0), PlanarDamper(viscous=kd, friction=1.0, stiffness=c,
                                                              damper_moment=ly), *args, field="constant")
    # Stuck: γ̇1 = γ̇ exactly, so γ − γ1 keeps its start to rounding of RK4's sums (≈ 1e-16 rad).
    assert_allclose(locked.gamma - locked.damper_angle, np.broadcast_to([0.3, 1.0], locked.gamma.shape), atol=1e-14)
    energy = 0.5 * j * locked.rate**2 + ly * B0 * (1 - np.cos(locked.damper_angle))
    # The conservative pendulum's RK4 drift at ω h = 1.3e-3: below 1e-10 relative.
    assert_allclose(energy, np.broadcast_to(energy[:1], energy.shape), rtol=1e-10)


def _e48_orbit():
    """E48 (seed line 150): h ≈ 800 km, L_y = 120 A·m², M_T = 3e-4 N·m, c = 4e-3 N·m/rad,
    J = 150 kg·m²; the body has no magnet of its own (its fixed magnets only make the coupling,
    seed line 131) and no ΔJ is printed (0). Kovalenko's dipole 8.1e22 A·m²."""
    from magbench.constants import EARTH_GM, EARTH_RADIUS, MU_0

    r = EARTH_RADIUS + 800e3
    return np.sqrt(EARTH_GM / r**3), MU_0 * 8.1e22 / (4 * np.pi * r**3)


@functools.lru_cache(maxsize=2)      # two tests read one run
def _e48_maxima(viscous=1e-2, step=1.0):
    n, b0 = _e48_orbit()
    damper = PlanarDamper(viscous=viscous, friction=3e-4, stiffness=4e-3, damper_moment=120.0)
    run = simulate_planar(PlanarBody(150.0, 0.0), damper, n, b0, 0.0, 0.0, 4 * np.pi / n, step)
    return np.degrees(planar_error_orbit_maxima(run, n)[:, 0])


def test_e48_fig_6_10_computed():
    """The book's pure dry friction is the limit k_д → 0: k_д = 1e-2 N·m·s (slip torque
    k_д × slip ≈ 2e-6 N·m ≪ M_T) at h = 1 s (h (c + L_yB)/k_д ≤ 0.93 with B ≤ 2B0; RK4 is stable to 2.8)."""
    first, second = _e48_maxima()
    # Our run from rest along B: 21.87° over the first orbit, 28.87° over the second;
    # k_д = 1e-3 at h = 0.1 s gives 21.97° and 29.15° (the limit is within 0.3°).
    assert_allclose([first, second], [21.87, 28.87], atol=0.01)


@pytest.mark.xfail(strict=True, reason="E48: the integrated model gives γ_max ≈ 28–32° over the second and third "
                                       "orbits from six starts (k_д → 0 moves it by 0.3°), not the printed "
                                       "5.5–7.5° read off fig. 6.10; even the magnet locked to the body "
                                       "(M_T = 1e-3 N·m) leaves 11°, as a rigid 120 A·m² magnet at ω_c ≈ 4ω0 would")
def test_e48_fig_6_10_printed_range():
    assert 5.5 - 0.5 <= _e48_maxima()[1] <= 7.5 + 0.5


def test_orbit_maxima_are_the_largest_angle_of_each_orbit():
    run = simulate_planar(PlanarBody(650.0, 500.0), PlanarDamper(viscous=0.2), N0, B0, [0.0, 0.3], 0.0,
                          3 * 2 * np.pi / N0, 10.0)
    maxima = planar_error_orbit_maxima(run, N0)
    k = np.floor(run.time * N0 / (2 * np.pi) * (1 + 1e-12))
    expected = np.array([np.abs(run.gamma[k == i]).max(axis=0) for i in range(3)])
    # The same samples selected the same way: equal.
    np.testing.assert_array_equal(maxima, expected)
    np.testing.assert_array_equal(planar_error_orbit_maxima(run, N0, last=2), expected[1:])
    with pytest.raises(ValueError, match="last"):
        planar_error_orbit_maxima(run, N0, last=4)
    with pytest.raises(ValueError, match="whole orbit"):
        planar_error_orbit_maxima(run, N0 / 10)
    with pytest.raises(ValueError, match="run"):
        planar_error_orbit_maxima(run.gamma, N0)
