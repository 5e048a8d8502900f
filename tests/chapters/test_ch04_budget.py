"""Chapter 4's error budget: the error sources in the bench's loop against closed forms,
limits and monotonicity; the Sobol wiring against the Ishigami function's analytic
indices; input validation."""

import numpy as np
import pytest
from numpy.testing import assert_allclose

from magbench import fields
from magbench.chapters.ch04_mockup import bench_setup, budget
from magbench.hardware import sensors
from magbench.params import chapter_parameters
from magbench.sim import bench

DEG = np.pi / 180


@pytest.fixture(scope="module")
def p():
    return chapter_parameters("ch04", overrides="")


@pytest.fixture(scope="module")
def setup(p):
    return bench_setup(p)


@pytest.fixture(scope="module")
def sources():
    return budget.load_error_sources()


# The chapter's run: released at the target at rest, ideal sensors, the band over the
# last 20 s of 120 s, when the loop (triple pole at 0.2 rad/s) has settled.
RUN = dict(duration=120.0, window=20.0)


@pytest.fixture(scope="module")
def closed_form_runs(setup):
    """One batch: gyro offsets, magnetometer misalignments, hard iron, soft iron, per member."""
    b = np.radians([2.0, -7.0, 20.0])                   # gyro offsets [rad/s]
    delta = np.radians([1.0, -4.0])                      # misalignments [rad]
    o = np.array([20e-6, -35e-6])                        # hard iron along coil 1 [T]
    s = np.array([0.05, -0.08])                          # scale difference
    targets = np.concatenate([np.full(3, np.pi / 3), np.full(2, 2 * np.pi / 3),
                              np.array([np.pi / 3, 2 * np.pi / 3]), np.array([np.pi / 3, 2 * np.pi / 3])])
    m = targets.size
    gyro = np.zeros(m); gyro[:3] = b
    mis = np.zeros(m); mis[3:5] = delta
    off = np.zeros((m, 2)); off[5:7, 0] = o
    mat = np.tile(np.eye(2), (m, 1, 1)); mat[7:9, 0, 0] = 1 + s; mat[7:9, 1, 1] = 1 - s
    errors = bench.BenchErrors(gyro_offset=gyro, magnetometer_misalignment=mis, magnetometer_offset=off,
                               magnetometer_matrix=mat)
    run = bench.simulate_bench(setup, targets, release_angle=targets, errors=errors,
                               record_interval=RUN["duration"], **RUN)
    return dict(run=run, b=b, delta=delta, o=o, s=s, targets=targets)


def test_gyro_offset_gives_the_filters_fixed_point(setup, closed_form_runs):
    """A constant gyro offset b holds the complementary filter's estimate A·b·Δt/(1−A) away
    from the magnetometer's heading at rest (fixed point of eq. 39); the loop holds the
    estimate on target, so the mock-up sits that far off it."""
    c = closed_form_runs
    a, dt = setup.filter_coefficient, setup.sample_interval
    expected = np.abs(a * c["b"] * dt / (1 - a))
    # atol 1e-4 rad (0.006°): the band is a max over the window and includes the small
    # limit cycle of the 8-bit duty quantisation (seen: 4e-5 rad), far below the effect.
    assert_allclose(c["run"].error_band[:3], expected, atol=1e-4)
    # The filtered angle, the one a log records, stays on target: the offset is invisible in it.
    assert np.all(c["run"].indicated_error_band[:3] < 0.01 * expected)


def test_magnetometer_misalignment_is_one_to_one(closed_form_runs):
    """A sensor turned by δ reads the heading ψ + δ; the loop holds that on target."""
    c = closed_form_runs
    # atol 1e-4 rad: settled residual and duty quantisation, far below the δ tested.
    assert_allclose(c["run"].error_band[3:5], np.abs(c["delta"]), atol=1e-4)


def test_hard_iron_offset_closed_form(setup, closed_form_runs):
    """Offset o along coil 1: atan2(B sin ψ, B cos ψ + o) = ψ_des gives
    sin(ψ − ψ_des) = (o/B) sin ψ_des."""
    c = closed_form_runs
    expected = np.abs(np.arcsin(c["o"] / setup.field * np.sin(c["targets"][5:7])))
    assert_allclose(c["run"].error_band[5:7], expected, atol=1e-4)


def test_soft_iron_scale_closed_form(closed_form_runs):
    """S = diag(1+s, 1−s): the heading is atan2((1−s) sin ψ, (1+s) cos ψ), so the loop
    settles at tan ψ = tan ψ_des (1+s)/(1−s)."""
    c = closed_form_runs
    t = c["targets"][7:9]
    psi = np.arctan2((1 + c["s"]) * np.sin(t), (1 - c["s"]) * np.cos(t))
    assert_allclose(c["run"].error_band[7:9], np.abs(psi - t), atol=1e-4)


def test_background_field_turns_the_reference(setup, sources, p):
    """A background H_b across the simulator's axis turns the field by atan(H_b/H_s): the
    error seen against the simulator's axis is that angle, the loop's error zero."""
    hb = sources["background_h"].high
    band, ind = bench.source_error_bands(setup, np.pi / 3, {"background_h": np.array([hb, 0.5 * hb])},
                                           field_h=p["bench_field_h"], **RUN)
    expected = np.arctan(np.array([hb, 0.5 * hb]) / p["bench_field_h"])
    assert_allclose(band, expected, atol=1e-4)


def test_explicit_zero_errors_reproduce_the_nominal_model_exactly(setup):
    """Every error source at its no-error value: bit-identical to the run without them."""
    kw = dict(duration=5.0, window=1.0, release_angle=[0.0, 0.5], record_interval=0.5)
    a = bench.simulate_bench(setup, np.pi / 3, rng=np.random.default_rng(5), **kw)
    zero = bench.BenchErrors(
        moment_scale=[1.0, 1.0], thread_stiffness=setup.thread_stiffness, gyro_offset=0.0, gyro_drift=0.0,
        magnetometer_offset=[0.0, 0.0], magnetometer_matrix=np.eye(2), magnetometer_misalignment=0.0,
        heading_ripple=0.0, coil_misalignment=[0.0, 0.0], coil_field_coupling=0.0, field_scale=1.0,
        field_azimuth=0.0, thread_neutral_angle=setup.thread_neutral_angle,
        filter_coefficient=setup.filter_coefficient, pwm_levels=setup.pwm_levels)
    z = bench.simulate_bench(setup, np.pi / 3, rng=np.random.default_rng(5), errors=zero, **kw)
    for name in ("psi", "rate", "moment_1", "moment_2", "estimate"):
        assert np.array_equal(getattr(a, name), getattr(z, name)), name
    assert np.array_equal(a.error_band, z.error_band)


def test_budget_nominal_values_reproduce_the_bench_as_designed(setup, p):
    """source_error_bands at the nominal values is simulate_bench released at the target (the
    budget's thread is untwisted there: its neutral angle is counted from the target)."""
    band, _ = bench.source_error_bands(setup, np.pi / 3, {}, field_h=p["bench_field_h"], **RUN)
    ref = bench.simulate_bench(setup, np.pi / 3, release_angle=np.pi / 3,
                               errors=bench.BenchErrors(thread_neutral_angle=np.pi / 3), **RUN)
    assert np.array_equal(band, ref.error_band)


def test_band_grows_with_each_heading_error_away_from_zero(setup, sources, p):
    """Monotonicity: the band grows with |gyro offset| and |misalignment| on each side of zero."""
    some = {k: sources[k] for k in ("gyro_offset", "magnetometer_misalignment")}
    res = bench.one_at_a_time(setup, [np.pi / 3], some, points=7, field_h=p["bench_field_h"], **RUN)
    for name, (x, band, _) in res.items():
        b = band[0]
        assert np.all(np.diff(b[3:]) > 0) and np.all(np.diff(b[:4]) < 0), name


def test_gyro_offset_range_is_the_datasheets(sources):
    """The budget's gyro range is the ±20 °/s the sensor model takes from Table 6.1."""
    s = sources["gyro_offset"]
    assert_allclose([s.low, s.high], [-sensors.MPU6050_GYRO_ZRO_TOLERANCE, sensors.MPU6050_GYRO_ZRO_TOLERANCE],
                    rtol=1e-12)   # the same printed number converted twice
    assert s.source == "datasheet" and "Table 6.1" in s.reference


def test_every_source_says_where_its_range_comes_from(sources):
    assert len(sources) >= 20
    for s in sources.values():
        assert s.source in ("datasheet", "thesis", "ours", "computed"), s.name
        assert s.reference and s.note, s.name
        assert s.low < s.high, s.name


def _ishigami(x, a=7.0, b=0.1):
    return np.sin(x[0]) + a * np.sin(x[1]) ** 2 + b * x[2] ** 4 * np.sin(x[0])


def test_sobol_wiring_on_the_ishigami_function():
    """SALib through sobol_design/sobol_analysis recovers Ishigami's analytic indices
    (Ishigami and Homma 1990; a = 7, b = 0.1 on [−π, π]³)."""
    a, b = 7.0, 0.1
    src = {n: budget.ErrorSource(n, -np.pi, np.pi, "rad", "linear", "ours", "test", "test")
           for n in ("x1", "x2", "x3")}
    problem, values = bench.sobol_design(src, base_samples=4096, seed=7)
    y = _ishigami([values["x1"], values["x2"], values["x3"]])
    # sobol_analysis works on radians and converts to degrees: a linear scale leaves indices alone.
    res = bench.sobol_analysis(problem, values, np.radians(y), np.radians(y), threshold=np.radians(10.0), seed=7)
    v1 = 0.5 * (1 + b * np.pi ** 4 / 5) ** 2
    v2 = a ** 2 / 8
    v13 = b ** 2 * np.pi ** 8 * (1 / 18 - 1 / 50)
    v = v1 + v2 + v13
    # atol 0.03: at N = 4096 SALib's 95 % bootstrap half-widths are ≈ 0.01–0.02.
    assert_allclose([res["S1"][k] for k in ("x1", "x2", "x3")], [v1 / v, v2 / v, 0.0], atol=0.03)
    assert_allclose([res["ST"][k] for k in ("x1", "x2", "x3")], [(v1 + v13) / v, v2 / v, v13 / v], atol=0.03)
    # The independent points are uniform on the cube: P(Y >= 10) of Ishigami by brute force.
    rng = np.random.default_rng(1)
    brute = np.mean(_ishigami(rng.uniform(-np.pi, np.pi, (3, 200_000))) >= 10.0)
    lo, hi = res["fraction_ci"]
    assert lo <= brute <= hi


@pytest.mark.parametrize("kw, match", [
    ({"filter_coefficient": 1.5}, "filter_coefficient"),
    ({"pwm_levels": 0}, "pwm_levels"),
    ({"pwm_levels": 2.5}, "pwm_levels"),
    ({"field_scale": -1.0}, "field_scale"),
    ({"magnetometer_matrix": [[1.0, 1.0], [1.0, 1.0]]}, "magnetometer_matrix"),
    ({"magnetometer_misalignment": 4.0}, "magnetometer_misalignment"),
    ({"coil_misalignment": [1.0, 0.0]}, "coil_misalignment"),
    ({"magnetometer_offset": [1e-6, 1e-6, 1e-6]}, "magnetometer_offset"),
    ({"gyro_offset": np.nan}, "gyro_offset"),
    ({"gyro_drift": [0.0, 0.0, 0.0]}, "gyro_drift"),
])
def test_bad_error_inputs_are_named(setup, kw, match):
    with pytest.raises(ValueError, match=match):
        bench.simulate_bench(setup, 1.0, duration=0.1, window=0.05, members=2, errors=bench.BenchErrors(**kw))


def test_bad_budget_inputs_are_named(setup, sources):
    with pytest.raises(ValueError, match="base_samples"):
        bench.sobol_design(sources, base_samples=100, seed=1)
    with pytest.raises(ValueError, match="unknown"):
        bench.sobol_design(sources, base_samples=8, seed=1, fixed={"gyro_ofset": 0.0})
    with pytest.raises(ValueError, match="points"):
        bench.one_at_a_time(setup, [1.0], sources, points=1, duration=1.0, window=0.5, field_h=262.0)
    with pytest.raises(ValueError, match="shape"):
        bench.from_unit_cube(np.zeros((3, 2)), sources)
    with pytest.raises(ValueError, match=r"\[0, 1\]"):
        bench.from_unit_cube(np.full((1, len(sources)), 1.5), sources)


def test_coil_field_range_is_the_square_coils_centre_field(sources, p):
    """The coils' field at the magnetometer runs from none to a square coil's centre field
    per unit moment, 2√2·μ0·N·I/(π·l) over m = N·I·l² (closed form; Griffiths eq. 5.37
    summed over four sides), not the far-field dipole μ0/(2π r³)."""
    from magbench.constants import MU_0

    s = sources["coil_field_coupling"]
    side = p["mtq_side"]
    # rtol 1e-12: Biot–Savart over four straight sides is exact at the centre; only rounding.
    assert_allclose([s.low, s.high], [0.0, 2 * np.sqrt(2) * MU_0 / (np.pi * side ** 3)], rtol=1e-12, atol=0)
    assert s.source == "computed" and "magbench" not in s.reference
    with pytest.raises(ValueError, match="side"):
        fields.square_loop_center_b_per_moment(-0.1)


def test_no_reader_facing_reference_names_code(sources):
    """The table of sources is read on the book page: no parameter keys or dotted paths."""
    for s in sources.values():
        assert "magbench" not in s.reference and "_" not in s.reference, (s.name, s.reference)


def test_budget_rows_are_the_gyro_offsets_consistency_rows(p):
    """Only the gyro offset's two rows remain (the 'largest other source' rows were an
    elimination, not a comparison, and were removed); each equals the filter's fixed
    point A_f·b·Δt/(1−A_f) at the datasheet bound."""
    from magbench.chapters import ch04_mockup

    rows = ch04_mockup.budget_rows(p)
    assert [r.id for r in rows] == ["bench-budget-gyro-pi3", "bench-budget-gyro-2pi3"]
    expected = np.degrees(ch04_mockup.gyro_offset_error(sensors.MPU6050_GYRO_ZRO_TOLERANCE,
                                                        p["bench_filter_coefficient"], p["bench_sample_interval"]))
    # atol 0.03°: the band is a max over the final window with datasheet sensor noise and
    # the duty's limit cycle on top of the fixed point (seen: ≤ 0.02°).
    assert_allclose([r.model for r in rows], expected, atol=0.03)
    assert all("could explain" in r.note for r in rows)
    with pytest.raises(ValueError, match="filter_coefficient"):
        ch04_mockup.gyro_offset_error(0.1, 1.0, 0.01)
