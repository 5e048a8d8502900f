"""The bench simulation (magbench.sim.bench): oracle, closed forms, seeds, bad input."""

from dataclasses import replace

import numpy as np
import pytest
from numpy.testing import assert_allclose

from magbench.chapters.ch04_mockup import bench_setup
from magbench.sim import bench
from magbench import hardware
from magbench.params import chapter_parameters

P = chapter_parameters("ch04", overrides="")
SETUP = bench_setup(P)


def test_vectorised_loop_matches_solve_ivp_member_by_member():
    # Ideal sensors and no PWM quantisation: the closed loop is then a deterministic
    # function of the state, and the only difference is the plant integrator (one RK4
    # step per 10 ms sample vs RK45 at rtol 1e-10).
    setup = replace(SETUP, pwm_levels=0)
    angles, rates = np.array([-0.4, 1.0, 2.8]), np.array([0.02, -0.05, 0.0])
    scale = np.array([[1.04, 0.96], [0.95, 1.0], [1.0, 1.05]])
    kappa = np.array([1e-7, 1e-6, 1e-5])
    run = bench.simulate_bench(setup, np.pi / 3, duration=20.0, release_angle=angles, release_rate=rates,
                               errors=bench.BenchErrors(moment_scale=scale, thread_stiffness=kappa))
    for j in range(3):
        ref = bench.simulate_bench_reference(
            setup, np.pi / 3, duration=20.0, release_angle=angles[j], release_rate=rates[j],
            moment_scale=scale[j], thread_stiffness=kappa[j])
        t, psi, omega, est = ref.time, ref.psi, ref.rate, ref.estimate
        assert_allclose(run.time, t, rtol=0, atol=1e-12)
        # RK4's local error is ~(omega_n dt)^5 ~ 1e-14 rad per step; solve_ivp's rtol
        # 1e-10 over 2000 intervals bounds the difference at ~1e-9 rad.
        assert_allclose(run.psi[:, j], psi, rtol=0, atol=1e-9)
        assert_allclose(run.rate[:, j], omega, rtol=0, atol=1e-9)
        assert_allclose(run.estimate[:, j], est, rtol=0, atol=1e-9)


def test_same_sensor_errors_give_the_same_run_in_both_implementations():
    # With noise and quantisation too, as long as both see the same sensor errors.
    steps = 500
    g, m = bench.draw_sensor_errors(SETUP, steps, 1, np.random.default_rng(3))
    run = bench.simulate_bench(SETUP, 2 * np.pi / 3, duration=5.0, release_angle=0.3, sensor_errors=(g, m),
                               window=1.0)
    psi = bench.simulate_bench_reference(SETUP, 2 * np.pi / 3, duration=5.0, release_angle=0.3,
                                         sensor_errors=(g[:, 0], m[:, 0])).psi
    assert_allclose(run.psi[:, 0], psi, rtol=0, atol=1e-9)   # as above


M5 = 5
_R = np.random.default_rng(12)


@pytest.mark.parametrize("options", [
    {},
    {"setup": replace(SETUP, pwm_levels=0), "psi_des": np.linspace(0.3, 2.5, M5)},
    {"gyro_offset": _R.normal(0.0, 0.01, M5), "gyro_drift": _R.normal(0.0, 1e-4, M5)},
    {"magnetometer_offset": _R.normal(0.0, 2e-6, (M5, 2)),
     "magnetometer_matrix": np.eye(2) + _R.normal(0.0, 0.02, (M5, 2, 2))},
    {"magnetometer_misalignment": _R.normal(0.0, 0.05, M5), "heading_ripple": _R.normal(0.0, 0.02, M5)},
    {"heading_ripple": 0.03},
    {"coil_misalignment": _R.normal(0.0, 0.05, (M5, 2)), "coil_field_coupling": _R.normal(0.0, 1e-5, M5),
     "field_scale": 1.0 + _R.normal(0.0, 0.05, M5), "field_azimuth": _R.normal(0.0, 0.1, M5)},
    {"thread_neutral_angle": _R.normal(0.0, 0.2, M5), "filter_coefficient": _R.uniform(0.9, 0.99, M5),
     "pwm_levels": np.array([1.0, 15.0, 63.0, 255.0, 1023.0]), "moment_scale": 1.0 + _R.normal(0.0, 0.05, (M5, 2)),
     "thread_stiffness": _R.uniform(0.0, 1e-5, M5)},
], ids=["nominal", "unquantised-targets", "gyro", "magnetometer", "heading", "ripple-only", "coils-field",
        "thread-filter-pwm"])
def test_compiled_loop_equals_the_numpy_loop(monkeypatch, options):
    # Every operation of the compiled loop is the numpy loop's, in the same order and
    # without fast-math, and the heading's arctan2 is numpy's in both: equal to the last
    # bit under every error source, noise and quantisation included.
    from magbench.sim.bench import loop

    kw = dict(options)
    setup, psi_des = kw.pop("setup", SETUP), kw.pop("psi_des", np.pi / 3)
    runs = []
    for engine in ("numpy", "compiled"):
        monkeypatch.setattr(loop, "_ENGINE", engine)
        runs.append(bench.simulate_bench(setup, psi_des, duration=6.0, members=M5, record_interval=0.05, window=2.0,
                                         release_angle=np.linspace(-1.0, 2.0, M5), release_rate=0.05,
                                         rng=np.random.default_rng(4), errors=bench.BenchErrors(**kw)))
    for name in ("psi", "rate", "moment_1", "moment_2", "estimate", "error_band", "indicated_error_band"):
        np.testing.assert_array_equal(getattr(runs[1], name), getattr(runs[0], name), err_msg=name)


def test_pendulum_energy_is_conserved_with_a_held_moment():
    # Eq. (35): J psi'' + m B0 sin psi = 0 conserves E = J w^2/2 - m B0 cos psi.
    j, b0, m = 0.005, 3.29e-4, 0.4
    psi, omega = np.array([np.pi / 2, np.pi / 4, 3.0]), np.zeros(3)
    energy0 = 0.5 * j * omega**2 - m * b0 * np.cos(psi)
    for _ in range(10000):       # 100 s, about two periods
        psi, omega = bench.plant_step(psi, omega, m, 0.0, 0.01, field=b0, inertia=j)
    energy = 0.5 * j * omega**2 - m * b0 * np.cos(psi)
    # RK4 energy error per period ~ (omega_n dt)^4 ~ 1e-11 relative; scale m B0.
    assert_allclose(energy, energy0, rtol=0, atol=1e-10 * m * b0)


def test_without_control_or_thread_the_mock_up_keeps_its_rate():
    # Zero gains: the coils stay off whatever the sensors say, so no torque acts.
    setup = replace(SETUP, kp=0.0, ki=0.0, kd=0.0, thread_stiffness=0.0)
    run = bench.simulate_bench(setup, 1.0, duration=10.0, release_angle=0.5, release_rate=0.03,
                               rng=np.random.default_rng(1), window=1.0)
    assert np.all(run.inputs == 0.0)          # both coils' moments
    assert_allclose(run.rate[:, 0], 0.03, rtol=0, atol=1e-15)      # exactly: no force
    assert_allclose(run.psi[:, 0], 0.5 + 0.03 * run.time, rtol=0, atol=1e-13)  # summation rounding


def test_thread_torsion_alone_gives_the_closed_form_oscillation():
    # J psi'' = -kappa psi: psi = A cos(sqrt(kappa/J) t), period 2 pi sqrt(J/kappa).
    kappa = 2e-5
    setup = replace(SETUP, kp=0.0, ki=0.0, kd=0.0, thread_stiffness=kappa)
    run = bench.simulate_bench(setup, 0.0, duration=120.0, release_angle=0.8)
    w = np.sqrt(kappa / SETUP.inertia)
    # RK4 global phase error ~ T (w dt)^4 w / 120 ~ 1e-13 rad.
    assert_allclose(run.psi[:, 0], 0.8 * np.cos(w * run.time), rtol=0, atol=1e-10)


def test_residual_gyro_bias_shifts_the_true_angle_by_the_filter_fixed_point():
    # At rest the filter's fixed point is est = A(est + b dt) + (1 - A) psi, so with the
    # estimate held at the target the true angle sits A b dt / (1 - A) below it.
    bias, a, dt = np.radians(5.0), SETUP.filter_coefficient, SETUP.sample_interval
    setup = replace(SETUP, gyro_bias=bias, gyro_noise_density=0.0, magnetometer_noise=0.0, pwm_levels=0)
    run = bench.simulate_bench(setup, np.pi / 3, duration=120.0, rng=np.random.default_rng(0))
    expected = np.pi / 3 - a * bias * dt / (1.0 - a)
    # The triple pole at 0.2 rad/s has decayed to ~e^-24 of the initial 1 rad by 120 s.
    assert_allclose(run.psi[-1, 0], expected, rtol=0, atol=1e-7)
    assert_allclose(run.estimate[-1, 0], np.pi / 3, rtol=0, atol=1e-7)


def test_thesis_gains_violate_routh_and_do_not_settle():
    # Routh-Hurwitz for J s^3 + B0 Kd s^2 + B0 Kp s + B0 Ki needs Ki < (B0/J) Kp Kd.
    kp, ki, kd = 0.1, 0.5, 0.5
    assert ki > SETUP.field / SETUP.inertia * kp * kd
    run = bench.simulate_bench(replace(SETUP, kp=kp, ki=ki, kd=kd), np.pi / 3, duration=120.0)
    assert run.error_band[0] > np.radians(90.0)


def test_monte_carlo_is_reproducible_from_its_seed():
    kw = dict(members=5, duration=2.0, window=1.0,
              dispersion=bench.BenchDispersion(moment_tolerance=0.05, release_angle_spread=1.0,
                                               release_rate_std=0.02, thread_stiffness_factor=10.0))
    a = bench.monte_carlo(SETUP, 1.0, seed=11, **kw)
    b = bench.monte_carlo(SETUP, 1.0, seed=11, **kw)
    c = bench.monte_carlo(SETUP, 1.0, seed=12, **kw)
    assert np.array_equal(a.psi, b.psi) and np.array_equal(a.error_band, b.error_band)
    assert not np.array_equal(a.psi, c.psi)
    assert np.all(np.abs(a.params["moment_scale"] - 1.0) <= 0.05)
    assert np.all(np.abs(a.params["release_angle"] - 1.0) <= 1.0)


def test_monte_carlo_release_centre_and_mean_rate():
    kw = dict(members=200, duration=0.1, window=0.05,
              dispersion=bench.BenchDispersion(moment_tolerance=0.05, release_angle_spread=0.5,
                                               release_rate_std=0.01, thread_stiffness_factor=2.0))
    run = bench.monte_carlo(SETUP, 2.0, seed=3, release_angle=-0.4, release_rate=0.1, **kw)
    assert np.all(np.abs(run.params["release_angle"] + 0.4) <= 0.5)
    assert abs(np.mean(run.params["release_rate"]) - 0.1) < 0.005
    # The default centre is the target, as before.
    default = bench.monte_carlo(SETUP, 2.0, seed=3, **kw)
    assert np.all(np.abs(default.params["release_angle"] - 2.0) <= 0.5)


@pytest.mark.parametrize("figure_id", ["thesis-fig19", "thesis-fig20"])
def test_bench_trace_envelope_contains_its_nominal_run(figure_id):
    # The envelope's members are released about the nominal run's release angle, so the
    # nominal run starts inside the 5-95 % band and both end on the target.
    from magbench import figures

    data = figures.compute(figure_id, envelope_members=40, bench_duration=60.0)
    nominal = {k: v for k, (u, v) in data.series[0].columns.items()}
    band = {k: v for k, (u, v) in data.series[1].columns.items()}
    start = np.interp(band["time"], nominal["time"], nominal["psi"])
    assert band["psi_low"][0] < start[0] < band["psi_high"][0]
    target = np.degrees(data.extra["psi_des"])
    assert abs(band["psi_low"][-1] - target) < 1.0 and abs(band["psi_high"][-1] - target) < 1.0


def test_full_scale_moment_from_measured_resistance():
    # m = N (U/R) l^2; with R = N r (no extra resistance) it must equal eq. (20).
    assert_allclose(bench.coil_full_scale_moment(12.0, 55.0, 240, 0.1), 240 * 12.0 / 55.0 * 0.01, rtol=1e-15)
    s = hardware.wire_area(0.2e-3)
    r = hardware.coil_resistance(240, 0.1, s, 0.0175e-6, "square")
    assert_allclose(bench.coil_full_scale_moment(12.0, r, 240, 0.1),
                    hardware.moment_from_voltage(12.0, 0.1, s, 0.0175e-6), rtol=1e-13)


def test_horizontal_field_adds_the_background_as_a_vector():
    mu0 = 4e-7 * np.pi * (1 + 5.5e-10)      # CODATA mu0 to the digits that matter here
    assert_allclose(bench.horizontal_field(262.0, 10.0, 0.0), mu0 * 272.0, rtol=1e-9)
    assert_allclose(bench.horizontal_field(262.0, 10.0, np.pi / 2), mu0 * np.hypot(262.0, 10.0), rtol=1e-9)


def test_quantised_duty_is_within_half_a_step():
    d = np.linspace(-1.0, 1.0, 10001)
    q = bench.quantise_duty(d, 255)
    assert np.max(np.abs(q - d)) <= 0.5 / 255 + 1e-15
    assert_allclose(q * 255, np.round(q * 255), atol=1e-12)   # on the 8-bit grid
    assert np.array_equal(bench.quantise_duty(d, 0), d)


@pytest.mark.parametrize("changes, message", [
    ({"inertia": -1.0}, "inertia"),
    ({"filter_coefficient": 1.5}, "filter_coefficient"),
    ({"coil_resistance": (55.0,)}, "coil_resistance"),
    ({"pwm_levels": 2.5}, "pwm_levels"),
    ({"driver_voltage_drop": 12.0}, "driver_voltage_drop"),
    ({"kd": -0.1}, "kd"),
    ({"field": float("nan")}, "field"),
])
def test_bad_setup_is_rejected(changes, message):
    with pytest.raises(ValueError, match=message):
        replace(SETUP, **changes)


@pytest.mark.parametrize("kwargs, message", [
    ({"duration": 1.005}, "whole number of samples"),
    ({"duration": -1.0}, "duration"),
    ({"duration": 1.0, "window": 2.0}, "window"),
    ({"duration": 1.0, "window": 0.5, "release_angle": [0.0, 1.0], "release_rate": [0.0, 0.0, 0.0]}, "release_angle"),
    ({"duration": 1.0, "window": 0.5, "errors": bench.BenchErrors(moment_scale=[[1.0, 1.0, 1.0]])}, "moment_scale"),
    ({"duration": 1.0, "window": 0.5, "errors": bench.BenchErrors(moment_scale=-1.0)}, "moment_scale"),
    ({"duration": 1.0, "window": 0.5, "errors": {"moment_scale": 1.0}}, "errors"),
    ({"duration": 1.0, "window": 0.5, "rng": 42}, "rng"),
    ({"duration": 1.0, "window": 0.5, "record_interval": 0.015}, "record_interval"),
    ({"duration": 1.0, "window": 0.5, "sensor_errors": (np.zeros((5, 1)), np.zeros((5, 1, 2)))}, "sensor_errors"),
    ({"duration": 1.0, "window": 0.5, "errors": bench.BenchErrors(thread_stiffness=-1e-6)}, "thread_stiffness"),
])
def test_bad_simulation_input_is_rejected(kwargs, message):
    with pytest.raises(ValueError, match=message):
        bench.simulate_bench(SETUP, 1.0, **kwargs)


def test_bad_monte_carlo_input_is_rejected():
    spread = dict(moment_tolerance=0.05, release_angle_spread=1.0, release_rate_std=0.02,
                  thread_stiffness_factor=10.0)
    with pytest.raises(ValueError, match="moment_tolerance"):
        bench.BenchDispersion(**{**spread, "moment_tolerance": 0.9})
    with pytest.raises(ValueError, match="thread_stiffness_factor"):
        bench.BenchDispersion(**{**spread, "thread_stiffness_factor": 0.5})
    with pytest.raises(ValueError, match="dispersion"):
        bench.monte_carlo(SETUP, 1.0, members=2, seed=1, duration=1.0, window=0.5, dispersion=spread)
    with pytest.raises(ValueError, match="setup"):
        bench.simulate_bench("not a setup", 1.0, duration=1.0, window=0.5)


def test_bench_inputs_are_chapter_4_inputs():
    """The bench figures' parameters are declared chapter inputs, so overrides reach them."""
    from magbench.chapters.ch04_mockup.figures_bench import BENCH_INPUTS
    from magbench.params import CHAPTER_INPUTS

    assert set(BENCH_INPUTS) <= set(CHAPTER_INPUTS["ch04"])
