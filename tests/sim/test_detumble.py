"""magbench.sim detumbling: a peer (Basilisk 2.12.1 times of the shared reference §6.1),
dissipation, the modes' defining properties, member independence, detumble_time and bad input."""

import dataclasses

import numpy as np
import pytest
from numpy.testing import assert_allclose
from scipy.spatial.transform import Rotation

from magbench.constants import MU_0
from magbench.dynamics import euler_rates, quaternion_rate
from magbench.earth import CircularOrbit
from magbench.sim import (DetumbleRun, SimulationResult, detumble_monte_carlo, detumble_time, rk4_step,
                          simulate_detumble)

J_3U = np.array([0.00666667, 0.0418667, 0.0418667])
SAMSAT = CircularOrbit(6856e3, np.radians(97.3), 7.72e22, np.linspace(0, 2 * np.pi, 8, endpoint=False))
ONE = dataclasses.replace(SAMSAT, argument_of_latitude0=0.3)
Q8 = Rotation.random(8, rng=np.random.default_rng(1)).as_quat(scalar_first=True)

# Four of Basilisk 2.12.1's 18 runs (data/peers/basilisk_detumble.csv: 3U, inertially fixed
# dipole 31.2 µT tilted 11°, 10 Hz sampled B-dot k = 5e4, ±0.2 A·m², no gravity gradient):
# one start of each of four attitudes, all ending within 3300 s.
BASILISK_RUNS = [0, 3, 9, 16]


def _basilisk():
    from magbench.io import load_basilisk_detumble_runs

    runs = load_basilisk_detumble_runs()
    moment = 4 * np.pi * 6371e3**3 * 31.2e-6 / MU_0
    orbit = CircularOrbit(6871e3, np.radians(51.6), moment, dipole_tilt=np.radians(11.0))
    pick = BASILISK_RUNS
    return orbit, runs.attitude_quaternion()[pick], runs.initial_rate[pick], runs.detumble_time[pick]


def test_continuous_law_matches_basilisk():
    orbit, q, w, expected = _basilisk()
    run = simulate_detumble([0.0418667, 0.0418667, 0.00666667], orbit, q, w, 3300.0, gain=5e4, max_dipole=0.2,
                            gravity_gradient=False)
    # Shared reference §6.1: "the continuous law (exact Ḃ) with RK4 at 0.5–2 s stays within
    # 1.05 % of these" (10 Hz sampling vs exact Ḃ), plus 1 s of record resolution.
    assert_allclose(detumble_time(run.time, run.rate), expected, rtol=0.0105, atol=1.0)


def test_sampled_law_matches_basilisk_at_10_hz():
    orbit, q, w, expected = _basilisk()
    run = simulate_detumble([0.0418667, 0.0418667, 0.00666667], orbit, q[2:3], w[2:3], 1620.0, gain=5e4,
                            max_dipole=0.2, mode="sampled", gravity_gradient=False)
    # The same law, sampling and hold as Basilisk's: an independent RK4 matched all 18 to ≤ 3 s.
    assert_allclose(detumble_time(run.time, run.rate), expected[2:3], atol=3.0)


def test_bdot_never_increases_kinetic_energy_while_tumbling():
    """Continuous mode, no gravity gradient: power ω·(m × B) = −Σ sat(kḂ_i)Ḃ_i − m·RᵀḂ_N, the
    second term ≲ 2n/|ω| ≈ 1 % of the first at these rates. Runs chained 10 s at a time."""
    w0 = np.radians([[0.1, 10.0, 10.0], [20.0, -5.0, 3.0], [1.0, 30.0, -40.0]])
    q, w, orbit = Q8[:3], w0, dataclasses.replace(SAMSAT, argument_of_latitude0=SAMSAT.argument_of_latitude0[:3])
    energy = [0.5 * np.sum(J_3U * w * w, axis=-1)]
    for _ in range(30):
        run = simulate_detumble(J_3U, orbit, q, w, 10.0, gain=1.691e4, max_dipole=0.2, gravity_gradient=False,
                                record_interval=10.0)
        q, w = run.attitude, run.omega
        orbit = dataclasses.replace(orbit, argument_of_latitude0=orbit.argument_of_latitude0 + orbit.mean_motion * 10)
        energy.append(0.5 * np.sum(J_3U * w * w, axis=-1))
    energy = np.array(energy)
    # Strictly decreasing: RK4's energy error (≲ 1e-10 relative per chunk, see the rigid-body
    # test) is far below the ≥ 1e-4 relative drop per 10 s at these rates.
    assert np.all(np.diff(energy, axis=0) < 0)


def test_sampled_mode_is_torque_free_before_the_second_sample():
    w0 = np.radians([[3.0, 10.0, -7.0]])
    run = simulate_detumble(J_3U, ONE, Q8[:1], w0, 0.1, gain=1e6, max_dipole=0.2, mode="sampled",
                            gravity_gradient=False, record_interval=0.1)
    state = np.concatenate([Q8[:1], w0], axis=-1)
    free = rk4_step(lambda t, x: np.concatenate([quaternion_rate(x[:, :4], x[:, 4:]),
                                                 euler_rates(x[:, 4:], np.zeros((1, 3)), J_3U)], axis=-1),
                    0.0, state, 0.1)
    # One torque-free RK4 step computed two ways: identical arithmetic up to the normalisation.
    assert_allclose(run.omega, free[:, 4:], rtol=1e-14)


def test_duty_model_damps_and_hold_fails_above_the_held_limit():
    """Shared reference §2: at (0.1, 10, 10) °/s, |ω| = 14.1 °/s > π/17 s = 10.6 °/s, the held
    dipole anti-damps; the on-board models ("model") and "propagate" damp."""
    w0 = np.radians([0.1, 10.0, 10.0])
    median = {}
    for estimator in ("model", "hold", "propagate"):
        run = simulate_detumble(J_3U, SAMSAT, Q8, w0, 1000.0, gain=1.691e4, max_dipole=0.2, mode="duty",
                                estimator=estimator, record_interval=17.0 / 4)
        median[estimator] = np.median(run.rate[:, -1])
    start = np.linalg.norm(w0)
    # Medians over 8 members (single members scatter, §7): a trend of ≥ 10 %, not a number.
    assert median["model"] < 0.8 * start and median["propagate"] < 0.8 * start
    assert median["hold"] > start


def test_duty_windows_are_torque_free():
    """The first off_time of every cycle has the coils off: without gravity gradient the
    body's kinetic energy is conserved there (to RK4's error)."""
    w0 = np.radians([[0.1, 10.0, 10.0]])
    run = simulate_detumble(J_3U, ONE, Q8[:1], w0, 1.0, gain=1.691e4, max_dipole=0.2, mode="duty",
                            gravity_gradient=False, record_interval=1.0)
    energy = lambda w: 0.5 * np.sum(J_3U * w * w, axis=-1)   # noqa: E731
    # 4 RK4 steps of 0.06 rad each: energy error ≲ 1e-9 relative.
    assert_allclose(energy(run.omega), energy(w0), rtol=1e-9)


def test_members_are_independent():
    w0 = np.radians([[0.1, 10.0, 10.0], [5.0, -3.0, 1.0]])
    orbit = dataclasses.replace(SAMSAT, argument_of_latitude0=[0.0, 1.0])
    together = simulate_detumble(J_3U, orbit, Q8[:2], w0, 30.0, gain=1.691e4, max_dipole=0.2, step=0.25)
    for i in range(2):
        alone = simulate_detumble(J_3U, dataclasses.replace(SAMSAT, argument_of_latitude0=float(i)), Q8[i], w0[i],
                                  30.0, gain=1.691e4, max_dipole=0.2, step=0.25)
        # Same arithmetic per member; array reductions may associate differently (1 ulp).
        assert_allclose(together.rate[i], alone.rate[0], rtol=1e-13)


TENSOR = np.array([[0.0067, 1e-4, 0.0], [1e-4, 0.0419, 2e-4], [0.0, 2e-4, 0.042]])


@pytest.mark.parametrize("inertia", [J_3U, TENSOR, J_3U * np.linspace(0.5, 2.0, 8)[:, None]],
                         ids=["principal", "tensor", "per-member"])
@pytest.mark.parametrize("options", [
    {}, {"law": "projected", "gain": 2e-4, "max_dipole": np.inf}, {"mode": "sampled", "step": 0.1},
    {"mode": "duty", "estimator": "model"}, {"mode": "duty", "estimator": "hold", "gravity_gradient": False},
    {"gain": np.linspace(1e4, 3e4, 8)}, {"orbit": dataclasses.replace(SAMSAT, argument_of_latitude0=np.arange(8.0))},
    {"orbit": dataclasses.replace(SAMSAT, argument_of_latitude0=np.arange(8.0)), "mode": "sampled", "step": 0.1},
], ids=["continuous", "projected-unlimited", "sampled", "duty-model", "duty-hold-no-gg", "member-gains",
        "member-phases", "member-phases-sampled"])
def test_compiled_loop_equals_the_numpy_loop(inertia, options):
    # Every operation of the compiled loop is the numpy loop's, in the same order and without
    # fast-math: equal to the last bit, whatever the mode, law or member axis (member phases:
    # the compiled field table too), for principal moments. For a tensor the numpy loop's
    # Euler equation is dynamics.kernels.euler_rates, which solves J ω̇ = …, where the compiled
    # twin multiplies by J⁻¹: equal to rounding (≤ 1e-14 of the largest value measured over these
    # runs; 1e-13 allows for another BLAS).
    kw = {"gain": 1.691e4, "max_dipole": 0.2, **options}
    orbit = kw.pop("orbit", SAMSAT)
    w0 = np.radians([[0.1, 10.0, 10.0]]) * np.linspace(0.5, 3.0, 8)[:, None]
    runs = [simulate_detumble(inertia, orbit, Q8, w0, 40.0, engine=engine, **kw) for engine in ("numpy", "compiled")]
    for name in ("rate", "omega", "attitude"):
        actual, desired = getattr(runs[1], name), getattr(runs[0], name)
        if np.shape(inertia) == (3, 3):
            assert_allclose(actual, desired, rtol=0.0, atol=1e-13 * np.abs(desired).max(), err_msg=name)
        else:
            np.testing.assert_array_equal(actual, desired, err_msg=name)


def test_run_shapes_inputs_and_result_view():
    run = simulate_detumble(J_3U, SAMSAT, Q8, np.radians([0.1, 10.0, 10.0]), 20.0, gain=1.691e4, max_dipole=0.2,
                            record_interval=2.0)
    assert isinstance(run, DetumbleRun)
    assert run.time.tolist() == list(np.arange(0.0, 21.0, 2.0))
    assert run.rate.shape == (8, 11) and run.omega.shape == (8, 3) and run.attitude.shape == (8, 4)
    assert run.inputs["mode"] == "continuous" and run.inputs["step"] == 0.5
    result = run.to_result()
    assert isinstance(result, SimulationResult) and result.rate.shape == (11, 8)
    assert_allclose(np.linalg.norm(run.attitude, axis=-1), 1.0, rtol=1e-15)   # renormalised every step


def test_monte_carlo_is_reproducible():
    kwargs = dict(members=3, seed=7, duration=10.0, rate_range=np.radians([5.0, 15.0]), gain=1.691e4,
                  max_dipole=0.2)
    a, b = detumble_monte_carlo(J_3U, ONE, **kwargs), detumble_monte_carlo(J_3U, ONE, **kwargs)
    assert_allclose(a.rate, b.rate, rtol=0, atol=0)
    assert np.all((a.rate[:, 0] >= np.radians(5.0)) & (a.rate[:, 0] <= np.radians(15.0)))


@pytest.mark.parametrize("rate, dwell, expected", [
    ([[0.1, 0.0, 0.0, 0.0]], 0.0, [1.0]),
    ([[0.1, 0.0, 0.1, 0.0]], 0.0, [1.0]),
    ([[0.1, 0.0, 0.1, 0.0]], 1.0, [np.nan]),     # re-crosses; the last dwell would end past the run
    ([[0.1, 0.0, 0.1, 0.0, 0.0]], 1.0, [3.0]),
    ([[0.1, 0.1, 0.1, 0.1]], 0.0, [np.nan]),
])
def test_detumble_time_cases(rate, dwell, expected):
    time = np.arange(len(rate[0]), dtype=float)
    assert_allclose(detumble_time(time, rate, 0.05, dwell), expected)


@pytest.mark.parametrize("change, match", [
    ({"law": "pd"}, "law must be one of"), ({"mode": "discrete"}, "mode must be one of"),
    ({"estimator": "kalman"}, "estimator must be one of"), ({"gain": -1.0}, "gain must be > 0"),
    ({"max_dipole": 0.0}, "max_dipole must be > 0"), ({"mode": "duty", "step": 0.3}, "off_time must be a whole"),
    ({"mode": "sampled", "record_interval": 0.75}, "record_interval must be a whole"),
    ({"duration": np.nan}, "duration"),
    ({"rate": [0.1, 0.2]}, "rate must have shape"), ({"attitude": [1.0, 0.0, 0.0]}, "attitude must have shape"),
    ({"orbit": "LEO"}, "orbit must be"), ({"attitude": Q8[:3]}, "must agree on the number of members"),
    ({"inertia": [1.0, 0.0, 1.0]}, "inertia must be > 0"), ({"engine": "numba"}, "engine must be 'compiled' or"),
])
def test_bad_input(change, match):
    args = dict(inertia=J_3U, orbit=SAMSAT, attitude=Q8, rate=np.radians([0.1, 10.0, 10.0]), duration=10.0,
                gain=1.691e4, max_dipole=0.2)
    args.update(change)
    with pytest.raises(ValueError, match=match):
        simulate_detumble(**args)


def test_detumble_time_bad_input():
    with pytest.raises(ValueError, match="time must be a 1-D increasing"):
        detumble_time([0.0, 0.0], [0.1, 0.1])
    with pytest.raises(ValueError, match="rate must have shape"):
        detumble_time([0.0, 1.0], [0.1, 0.1, 0.1])


def test_inner_loop_laws_equal_the_control_laws():
    """The simulation's component-array laws give the numbers of magbench.control's."""
    from magbench.control import bdot_dipole, bdot_dipole_projected
    from magbench.sim._detumble_loops import _law_bdot, _law_projected

    rng = np.random.default_rng(3)
    b, b_rate = rng.normal(size=(2, 50, 3)) * np.array([3e-5, 1e-6])[:, None, None]
    k, limit = rng.uniform(1e3, 1e5, 50), np.array([0.2, 0.1, 0.3])
    ours = np.stack(_law_bdot(tuple(b.T), tuple(b_rate.T), k, limit), axis=-1)
    assert_allclose(ours, bdot_dipole(b_rate, k, limit), rtol=1e-15, atol=0)
    ours = np.stack(_law_projected(tuple(b.T), tuple(b_rate.T), k * 1e-9, limit), axis=-1)
    assert_allclose(ours, bdot_dipole_projected(b, b_rate, k * 1e-9, limit), rtol=1e-14, atol=1e-30)
