"""The dispersion runner (magbench.sim.dispersion): per-member streams, chunks on any
executor, retries, streaming to a file, bootstrap intervals, and the studies' rows against
the simulators called directly."""

from concurrent.futures import Executor, Future, ThreadPoolExecutor
from dataclasses import replace
import numpy as np
import pytest
from numpy.testing import assert_allclose, assert_array_equal

from magbench.chapters import chapter_parameters, dispersion_studies, dispersion_study
from magbench.sim import (DispersedInput, DispersionError, DispersionStudy, DispersionTable, Outcome,
                          detumble_time, dispersion_statistics, member_generators, run_dispersion, simulate_detumble)

SHORT = {"envelope_duration": 900.0}      # detumble members that cost ~0.5 ms each


def _toy_parameters(overrides):
    p = {"scale": 2.0}
    for name, value in overrides.items():
        if name not in p:
            raise ValueError(f"unknown parameter {name!r} of toy; valid: scale")
        p[name] = value
    return p


def _toy_draw(p, rng):
    return {"x": rng.normal(), "y": rng.uniform()}


def _toy_simulate(p, columns, rngs):
    return {"z": p["scale"] * (3.0 + columns["x"]) + np.array([g.normal() for g in rngs])}


TOY = DispersionStudy("toy", "a normal and a uniform", "none",
                      (DispersedInput("x", "1", ("x",), "standard normal"), DispersedInput("y", "1", ("y",), "U(0, 1)")),
                      (Outcome("z", "1", "scale·(3 + x) + noise"),), _toy_parameters, _toy_draw, _toy_simulate)


def test_every_chapter_study_is_registered_with_named_columns_and_units():
    studies = dispersion_studies()
    assert {"bench", "detumble", "capture"} <= set(studies)
    for study in studies.values():
        params = chapter_parameters(study.chapter)
        assert study.columns[0] == "member" and len(set(study.columns)) == len(study.columns)
        for item in study.inputs:
            assert item.unit and item.distribution and all(n in params for n in item.parameters)
        assert all(o.unit and o.description for o in study.outcomes)


def test_a_member_draws_the_same_numbers_whatever_runs_beside_it():
    whole = [g.normal(size=3) for g in member_generators(11, 0, 50)]
    part = [g.normal(size=3) for g in member_generators(11, 20, 30)]
    assert_array_equal(np.array(whole[20:30]), np.array(part))
    # and the streams differ between members and between seeds
    assert not np.array_equal(whole[0], whole[1])
    assert not np.array_equal(whole[0], member_generators(12, 0, 1)[0].normal(size=3))


@pytest.mark.parametrize("name", ["detumble", "bench", "capture"])
def test_rows_do_not_depend_on_chunks_or_threads(name):
    # The chapters' simulators compute each member on its own: the same rows, bit for bit,
    # in one chunk, in chunks of 3, and on a thread pool (the CLI tests do processes and Dask).
    overrides = {"detumble": SHORT, "bench": {"bench_duration": 30.0, "bench_error_window": 10.0},
                 "capture": {"capture_duration": 3 * 5600.0}}[name]
    study = dispersion_study(name)
    one = run_dispersion(study, 7, 3, overrides=overrides)
    with ThreadPoolExecutor(2) as pool:
        many = run_dispersion(study, 7, 3, executor=pool, chunk=3, overrides=overrides)
    assert list(one.columns) == list(study.columns)
    for column in study.columns:
        assert_array_equal(one[column], many[column], err_msg=column)


def test_detumble_rows_agree_with_simulate_detumble_on_the_same_inputs():
    study = dispersion_study("detumble")
    table = run_dispersion(study, 6, 5, overrides=SHORT)
    p = study.parameters(SHORT)
    from magbench.chapters.ch05_detumbling.study import envelope_orbit, inertia

    orbit = envelope_orbit(p)
    for k in (0, 4):
        q = [table[c][k] for c in ("q_w", "q_x", "q_y", "q_z")]
        w = [table[c][k] for c in ("rate_x", "rate_y", "rate_z")]
        run = simulate_detumble(inertia(p), replace(orbit, argument_of_latitude0=table["orbit_phase"][k]), q, w,
                                p["envelope_duration"], gain=p["envelope_gain"], max_dipole=p["max_dipole"],
                                step=p["integration_step"])
        # one member alone against the same member among six: identical (no shared step)
        assert_array_equal(run.rate[..., -1].ravel(), [table["final_rate"][k]])
        assert_array_equal(detumble_time(run.time, run.rate.ravel(), p["detumble_threshold"]),
                           table["detumble_time"][k])


def test_the_envelope_distribution_is_the_detumble_studys_first_members():
    from magbench.chapters.ch05_detumbling.study import envelope_distribution

    p = chapter_parameters("ch05")
    env = envelope_distribution(p, members=4)
    table = run_dispersion(dispersion_study("detumble"), 4, int(p["envelope_seed"]))
    assert_array_equal(env["first"], table["detumble_time"])
    assert_array_equal(env["final_rate"], table["final_rate"])


def test_the_capture_run_is_the_capture_studys_first_members():
    from magbench.chapters.ch07_tns0 import _capture, tns0_orbit, tns0_satellite
    from magbench.sim import passive_final_regime

    short = dict(chapter_parameters("ch07"), capture_members=3.0, capture_duration=3 * 5600.0)
    final = passive_final_regime(_capture(short), tns0_satellite(short), tns0_orbit(short), orbits=3)
    table = run_dispersion(dispersion_study("capture"), 3, int(short["capture_seed"]),
                           overrides={"capture_duration": short["capture_duration"]})
    for name in ("final_angle", "final_rate", "final_momentum"):
        assert_array_equal(final[name], table[name], err_msg=name)


def test_a_file_holds_the_rows_in_member_order_with_repr_floats(tmp_path):
    out = tmp_path / "toy.csv"
    table = run_dispersion(TOY, 25, 1, chunk=4, out=out)
    lines = out.read_text().splitlines()
    assert lines[0] == "member,x,y,z"
    assert len(lines) == 26 and not (tmp_path / "toy.csv.part").exists()
    rows = [line.split(",") for line in lines[1:]]
    assert [int(r[0]) for r in rows] == list(range(25))
    full = run_dispersion(TOY, 25, 1)
    assert [float(r[3]) for r in rows] == full["z"].tolist()          # repr reads back exactly
    assert set(table.columns) == {"member", "z"}                        # the inputs are in the file


class _FlakyExecutor(Executor):
    """Runs chunks here; the chunk starting at ``bad`` fails its first ``failures`` times."""

    def __init__(self, bad, failures):
        self.bad, self.left, self.calls = bad, failures, []

    def submit(self, fn, *args):
        future = Future()
        start = args[3]
        self.calls.append(start)
        if start == self.bad and self.left > 0:
            self.left -= 1
            future.set_exception(RuntimeError("worker died"))
        else:
            future.set_result(fn(*args))
        return future


def test_a_failed_chunk_is_submitted_once_more():
    executor = _FlakyExecutor(bad=8, failures=1)
    table = run_dispersion(TOY, 20, 2, executor=executor, chunk=4)
    assert executor.calls.count(8) == 2
    assert_array_equal(table["z"], run_dispersion(TOY, 20, 2)["z"])


def test_a_chunk_that_fails_twice_fails_the_study_naming_it_and_leaves_no_file(tmp_path):
    out = tmp_path / "toy.csv"
    with pytest.raises(DispersionError, match=r"chunk 2 \(members 8-11\) failed twice: RuntimeError: worker died"):
        run_dispersion(TOY, 20, 2, executor=_FlakyExecutor(bad=8, failures=2), chunk=4, out=out)
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize("kwargs, message", [
    (dict(members=0), "members must be a whole number >= 1, got 0"),
    (dict(members=2.5), "members must be a whole number >= 1, got 2.5"),
    (dict(seed=-1), "seed must be a whole number >= 0, got -1"),
    (dict(chunk=0), "chunk must be a whole number >= 1, got 0"),
    (dict(overrides={"nope": 1.0}), "unknown parameter 'nope' of toy; valid: scale"),
    (dict(overrides={"scale": "x"}), "override scale must be a number"),
    (dict(executor=object()), "executor must be a concurrent.futures.Executor or None, got object"),
    (dict(until_ci=0.0), "until_ci must be a relative width > 0"),
])
def test_bad_input_names_the_parameter(kwargs, message):
    args = dict(members=5, seed=1)
    args.update(kwargs)
    with pytest.raises(ValueError, match=message.replace("(", r"\(").replace(")", r"\)").replace(".", r"\.")):
        run_dispersion(TOY, args.pop("members"), args.pop("seed"), **args)


def test_an_unknown_chapter_parameter_is_refused_naming_it():
    with pytest.raises(ValueError, match="unknown parameter 'envelope_gian' of ch05; valid: .*envelope_gain"):
        run_dispersion(dispersion_study("detumble"), 2, 1, overrides={"envelope_gian": 1.0})


@pytest.mark.parametrize("statistic, q", [("median", 0.5), ("p95", 0.95)])
def test_bootstrap_interval_ends_are_the_binomial_order_statistics(statistic, q):
    # The bootstrap distribution of a sample quantile (no interpolation) is known in closed
    # form: a resample's quantile is at or below the j-th order statistic when at least
    # ceil(q·n) of the n draws are, Binomial(n, j/n). So the percentile interval's ends are
    # the order statistics near ranks Binomial(n, q)'s 2.5 % and 97.5 % points. Tolerance:
    # half the binomial's standard deviation in ranks, for 999 resamples' estimate of a 2.5 %
    # point (observed: at most 5 ranks over ten samples).
    from scipy.stats import binom

    n = 4000
    x = np.random.default_rng(3).standard_normal(n)
    table = DispersionTable(TOY, 0, {}, {"member": np.arange(n), "z": x})
    row = next(r for r in dispersion_statistics(table) if r["statistic"] == statistic)
    ranks = np.searchsorted(np.sort(x), [row["low"], row["high"]])
    assert_allclose(ranks, binom.ppf([0.025, 0.975], n, q), atol=0.5 * np.sqrt(n * q * (1 - q)))
    assert row["value"] == np.quantile(x, q, method="inverted_cdf") and row["members"] == n


def test_members_not_reached_count_as_beyond_every_number():
    t = np.array([1.0, 2.0, 3.0, np.nan, np.nan] * 40)
    table = DispersionTable(TOY, 0, {}, {"member": np.arange(t.size), "z": t})
    stats = {s["statistic"]: s for s in dispersion_statistics(table)}
    assert stats["median"]["value"] == 3.0 and stats["median"]["missing"] == 80
    assert stats["p95"]["value"] == np.inf


def test_until_ci_stops_at_a_chunk_boundary_with_every_interval_narrow():
    full = run_dispersion(TOY, 4000, 9, chunk=100)
    table = run_dispersion(TOY, 4000, 9, chunk=100, until_ci=0.2)
    assert table.members % 100 == 0 and table.members < 4000
    for s in dispersion_statistics(table):
        assert s["high"] - s["low"] < 0.2 * abs(s["value"])
    assert_array_equal(table["z"], full["z"][:table.members])
