"""`magbench montecarlo`: the same file, byte for byte, from one process, a local pool and a
local Dask cluster (a scheduler and two workers on 127.0.0.1, started and stopped here); its
errors; a worker that dies."""

import os
import signal
import socket
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest

from magbench.cli import _LocalPool, main
from magbench.sim import DispersedInput, DispersionError, DispersionStudy, Outcome, run_dispersion

BIN = Path(sys.executable).parent
ENV = dict(os.environ, OMP_NUM_THREADS="1", OPENBLAS_NUM_THREADS="1")


def _magbench(*args, timeout=300):
    return subprocess.run([sys.executable, "-m", "magbench.cli", "montecarlo", *args], capture_output=True,
                          text=True, timeout=timeout, env=ENV)


def _in_process(capsys, *args):
    """``magbench montecarlo ARGS`` through :func:`magbench.cli.main` in this process (the
    subprocess tests below prove the entry point; this saves an import per run): exit
    status, stdout, stderr."""
    try:
        status = main(["montecarlo", *map(str, args)])
    except SystemExit as exc:            # argparse's refusals
        status = exc.code
    out = capsys.readouterr()
    return status, out.out, out.err


def _free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


@pytest.fixture(scope="module")
def dask_scheduler():
    """A Dask scheduler and two one-thread workers on 127.0.0.1, for this module only."""
    pytest.importorskip("distributed")
    from distributed import Client

    address = f"tcp://127.0.0.1:{_free_port()}"
    common = dict(stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=ENV, start_new_session=True)
    procs = [subprocess.Popen([BIN / "dask", "scheduler", "--host", "127.0.0.1", "--port", address.rsplit(":", 1)[1],
                               "--no-dashboard", "--no-show"], **common)]
    try:
        for _ in range(2):
            procs.append(subprocess.Popen([BIN / "dask", "worker", address, "--nworkers", "1", "--nthreads", "1",
                                           "--no-dashboard", "--memory-limit", "0"], **common))
        with Client(address, timeout="30s", set_as_default=False) as client:
            client.wait_for_workers(2, timeout=60)
        yield address
    finally:
        for p in reversed(procs):
            try:
                os.killpg(p.pid, signal.SIGTERM)
            except ProcessLookupError:
                pass
        for p in procs:
            try:
                p.wait(timeout=20)
            except subprocess.TimeoutExpired:
                os.killpg(p.pid, signal.SIGKILL)


# the detumble case is the issue's own command; bench and capture are smaller, in several chunks
CASES = {"detumble": ("3000", "700", "700"), "bench": ("200", "70", "45"), "capture": ("40", "15", "11")}


@pytest.mark.parametrize("study", list(CASES))
def test_the_file_is_byte_identical_serial_pooled_and_on_dask(study, dask_scheduler, tmp_path, capsys):
    members, chunk, dask_chunk = CASES[study]
    common = (study, "--members", members, "--seed", "7")
    runs = {"one": _in_process(capsys, *common, "--workers", "1", "--out", tmp_path / "a.csv"),
            "pool": _in_process(capsys, *common, "--workers", "2", "--chunk", chunk, "--out", tmp_path / "b.csv"),
            "dask": _in_process(capsys, *common, "--scheduler", dask_scheduler, "--chunk", dask_chunk,
                                "--out", tmp_path / "c.csv")}
    for name, (status, _, err) in runs.items():
        assert status == 0, (name, err)
        assert err == ""            # no progress bar when stderr is not a terminal
    a, b, c = ((tmp_path / f).read_bytes() for f in ("a.csv", "b.csv", "c.csv"))
    assert a == b == c
    lines = a.decode().splitlines()
    assert len(lines) == int(members) + 1
    assert [int(line.split(",", 1)[0]) for line in lines[1:]] == list(range(int(members)))
    out = runs["one"][1]
    assert f"{study}: {members} members, seed 7" in out and "median" in out and "p95" in out


def test_list_names_every_study_its_inputs_provenance_and_outcomes():
    run = _magbench("--list")
    assert run.returncode == 0, run.stderr
    for text in ("detumble (chapter ch05)", "bench (chapter ch04)", "capture (chapter ch07)",
                 "rate [rad/s] -> columns rate_x, rate_y, rate_z", "envelope_rate_high = 0.261799 (SI; external:",
                 "detumble_time [s]", "error_band [rad]", "final_angle [rad]"):
        assert text in run.stdout, text


@pytest.mark.parametrize("args, message", [
    (("nosuch", "--members", "3", "--seed", "1", "--out", "x.csv"), "unknown study 'nosuch'; known: bench, detumble, capture"),
    (("detumble", "--members", "0", "--seed", "1", "--out", "x.csv"), "--members: must be a whole number >= 1, got '0'"),
    (("detumble", "--members", "1.5", "--seed", "1", "--out", "x.csv"), "--members: must be a whole number >= 1, got '1.5'"),
    (("detumble", "--members", "3", "--seed", "1", "--set", "envelope_gian=1", "--out", "x.csv"),
     "unknown parameter 'envelope_gian' of ch05; valid:"),
    (("detumble", "--members", "3", "--seed", "1", "--workers", "2", "--scheduler", "tcp://127.0.0.1:1",
      "--out", "x.csv"), "give --workers or --scheduler, not both"),
    (("detumble", "--members", "3", "--seed", "1"), "--members, --seed and --out are required"),
])
def test_bad_input_exits_2_with_one_line_naming_it(args, message, tmp_path, monkeypatch, capsys):
    monkeypatch.chdir(tmp_path)
    status, _, err = _in_process(capsys, *args)
    assert status == 2
    assert message in err
    assert not (tmp_path / "x.csv").exists()


def test_bad_input_through_the_installed_command():
    run = _magbench("detumble", "--members", "0", "--seed", "1", "--out", "x.csv")
    assert run.returncode == 2 and "--members: must be a whole number >= 1, got '0'" in run.stderr


def test_an_unreachable_scheduler_is_one_line_within_ten_seconds(tmp_path):
    # Run alone (not beside the module's pools): the 10 s include starting Python and
    # importing the library, which a loaded machine slows (10.1 s once, in the background).
    start = time.monotonic()
    run = _magbench("detumble", "--members", "3", "--seed", "1", "--scheduler", f"tcp://127.0.0.1:{_free_port()}",
                    "--out", tmp_path / "x.csv", timeout=30)
    assert time.monotonic() - start < 10.0
    assert run.returncode == 2
    assert run.stderr.startswith("magbench montecarlo: cannot reach the Dask scheduler at tcp://127.0.0.1:")
    assert run.stderr.count("\n") == 1 and not (tmp_path / "x.csv").exists()


# -- a worker that dies ------------------------------------------------------------------

def _toy_parameters(overrides):
    return {}


def _toy_draw(p, rng):
    return {"x": rng.normal()}


def _dying_simulate(p, columns, rngs):
    # The process running member 8 dies (os._exit): the first time only, or ("always") every time.
    marker = Path(os.environ["MAGBENCH_TEST_DEATH_MARKER"])
    if any(tuple(g.bit_generator.seed_seq.entropy) == (5, 8) for g in rngs):
        state = marker.read_text() if marker.exists() else ""
        if state != "died":
            if state == "":
                marker.write_text("died")
            os._exit(1)
    return {"y": 2.0 * columns["x"]}


DYING = DispersionStudy("dying", "a worker dies at member 8", "none", (DispersedInput("x", "1", ("x",), "N(0, 1)"),),
                        (Outcome("y", "1", "2x"),), _toy_parameters, _toy_draw, _dying_simulate)


def test_a_dead_worker_costs_its_chunk_one_retry(tmp_path, monkeypatch):
    monkeypatch.setenv("MAGBENCH_TEST_DEATH_MARKER", str(tmp_path / "marker"))
    pool = _LocalPool(2)
    try:
        table = run_dispersion(DYING, 20, 5, executor=pool, chunk=4, out=tmp_path / "t.csv")
    finally:
        pool.shutdown()
    assert (tmp_path / "marker").read_text() == "died"
    assert table["member"].tolist() == list(range(20))
    assert np.array_equal(table["y"], run_dispersion(DYING, 20, 5)["y"])    # here: the marker says "died"


def test_a_worker_that_dies_twice_fails_the_study_and_leaves_no_file(tmp_path, monkeypatch):
    marker = tmp_path / "marker"
    marker.write_text("always")
    monkeypatch.setenv("MAGBENCH_TEST_DEATH_MARKER", str(marker))
    pool = _LocalPool(2)
    try:
        # the pool breaks for every chunk in flight, so the chunk named may be one beside it
        with pytest.raises(DispersionError, match=r"chunk \d \(members \d+-\d+\) failed twice: BrokenProcessPool"):
            run_dispersion(DYING, 20, 5, executor=pool, chunk=4, out=tmp_path / "t.csv")
    finally:
        pool.shutdown()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["marker"]
