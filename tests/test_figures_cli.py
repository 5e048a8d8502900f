"""The figure registry and the command line (contract shapes)."""

import json
import os
import re
import subprocess
import sys

import matplotlib.pyplot as plt
import numpy as np
import pytest

from magbench import earth
from magbench import figures
from magbench.cli import main


@pytest.mark.parametrize("figure_id", figures.figure_ids())
def test_every_figure_computes_and_draws(figure_id):
    fig, data = figures.render(figure_id)
    d = data.to_json_dict()
    assert set(d) == {"id", "title", "source", "parameters", "series"}
    assert d["id"] == figure_id and d["series"]
    for s in d["series"]:
        for col in s["columns"].values():
            assert set(col) == {"unit", "values"} and np.isfinite(col["values"]).all()
    plt.close(fig)


def test_fig02_lines_are_field_lines():
    # Along each computed line the tangent is parallel to the dipole field (thesis Fig. 2).

    data = figures.compute("thesis-fig02", earth_dipole_tilt=0.0)
    s = data.series[0]
    x, z = s.columns["x"][1], s.columns["z"][1]
    pts = np.stack([x, np.zeros_like(x), z], axis=1)
    b = earth.dipole_b(pts, [0.0, 0.0, -1.0])
    tangent = np.gradient(pts, axis=0)
    cross = np.linalg.norm(np.cross(tangent[1:-1], b[1:-1]), axis=1)
    rel = cross / (np.linalg.norm(tangent[1:-1], axis=1) * np.linalg.norm(b[1:-1], axis=1))
    assert np.max(rel) < 1e-3     # finite-difference tangent on 721 points


def test_cli_figure_with_set_out_and_data(tmp_path, capsys):
    out, js = tmp_path / "f.svg", tmp_path / "f.json"
    assert main(["figure", "ch01-orbit-field", "--set", "orbit_altitude=5e5",
                 "--out", str(out), "--data", str(js)]) == 0
    d = json.loads(js.read_text())
    assert d["parameters"]["orbit_altitude"] == 5e5
    assert out.stat().st_size > 0
    assert "orbit_altitude = 500000 m" in capsys.readouterr().out


@pytest.mark.parametrize("argv, message", [
    (["figure", "no-such-fig"], "valid ids"),
    (["figure", "ch01-orbit-field", "--set", "no_param=1"], "valid: "),
    (["figure", "ch01-orbit-field", "--set", "orbit_altitude=high"], "cannot parse"),
    (["figure", "ch01-orbit-field", "--set", "orbit_altitude=-5"], "orbit_altitude"),
    (["figure", "ch01-orbit-field", "--out", "x.gif"], "--out must end"),
])
def test_cli_errors(argv, message, capsys):
    assert main(argv) != 0
    assert message in capsys.readouterr().err


def test_cli_names_the_figures_parameter_and_a_plain_number_when_a_library_check_fails(capsys):
    # The library's check names its own argument (radius); the reader typed coil_radius. Before
    # the fix the one line was "radius must be > 0 m, got np.float64(-0.5)".
    assert main(["figure", "thesis-fig05", "--set", "coil_radius=-0.5"]) == 2
    err = capsys.readouterr().err.strip()
    assert err == "magbench figure: thesis-fig05 with coil_radius=-0.5: radius must be > 0 m, got -0.5"


def test_cli_figures_and_compare(capsys):
    assert main(["figures"]) == 0
    assert "thesis-fig01" in capsys.readouterr().out
    assert main(["compare", "--json"]) == 0
    rows = json.loads(capsys.readouterr().out)
    assert rows and {"id", "kind", "verdict", "tolerance"} <= set(rows[0])
    from magbench.compare import ROW_KINDS
    assert {r["kind"] for r in rows} <= set(ROW_KINDS) and "consistency" in {r["kind"] for r in rows}
    assert main(["compare"]) == 0
    summary = capsys.readouterr().out.strip().splitlines()[-1]
    assert "counted" in summary and "consistency checks, not counted" in summary


def test_listing_figures_reads_no_file():
    """Registering and listing every figure opens no data file: defaults are read on first use.
    (Code caches are not data: numba looks for its compiled kernels in ``__pycache__``.)"""
    code = (
        "import sys\n"
        "opened = []\n"
        "def hook(event, args):\n"
        "    if event == 'open' and isinstance(args[0], str) and '/magbench/' in args[0] \\\n"
        "            and not args[0].endswith(('.py', '.pyc', '.so')) and '/__pycache__' not in args[0]:\n"
        "        opened.append(args[0])\n"
        "sys.addaudithook(hook)\n"
        "from magbench import figures\n"
        "ids = figures.figure_ids()\n"
        "assert len(ids) >= 38, ids\n"
        "print(sorted(set(opened)))\n"
        "sys.exit(1 if opened else 0)\n"
        "figures.get_spec(ids[0]).parameters\n")
    result = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                            env={**os.environ, "MPLBACKEND": "Agg"})
    assert result.returncode == 0, result.stdout + result.stderr


def test_a_figures_defaults_are_read_on_first_use():
    from magbench import figures

    spec = figures.get_spec("thesis-fig05")
    assert spec.parameters is spec.parameters          # read once, then cached
    assert all(isinstance(p, figures.FigureParameter) for p in spec.parameters.values())


@pytest.mark.parametrize("argv, message", [
    (["figure", "ch01-field-elements", "--out", "{tmp}/missing/x.png"], "--out {tmp}/missing/x.png: folder {tmp}/missing does not exist"),
    (["figure", "ch01-field-elements", "--data", "{tmp}"], "--data {tmp}: is a folder, not a file"),
    (["figure", "ch04-step-response", "--set", "duration=1e7"],
     "parameter duration of ch04-step-response must be <= 10000 s"),
])
def test_cli_refuses_before_computing(argv, message, tmp_path, capsys, monkeypatch):
    # Each of these used to compute first (minutes for the last, which never ended) and
    # then fail with a traceback; now one line, exit 2, and nothing is computed.
    from magbench import figures

    def computed(*args, **kwargs):
        raise AssertionError("computed before the check")

    monkeypatch.setattr(figures, "compute", computed)
    monkeypatch.setattr(figures, "render", computed)
    argv = [a.replace("{tmp}", str(tmp_path)) for a in argv]
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and err.startswith("magbench figure: "), err
    assert message.replace("{tmp}", str(tmp_path)) in err


def test_cli_names_a_missing_parameter_file_in_one_line(tmp_path, capsys, monkeypatch):
    monkeypatch.setenv("MAGBENCH_PARAMS", str(tmp_path / "nope.toml"))
    assert main(["compare"]) == 2
    err = capsys.readouterr().err
    assert err == f"magbench compare: parameter file {tmp_path / 'nope.toml'} (from $MAGBENCH_PARAMS) does not exist\n"


def test_cli_quiet_when_the_reader_closes_the_pipe():
    # The reader (`true`) leaves before anything is printed, as `head` does after its lines;
    # the listing's flush then used to end in "Exception ignored ... BrokenPipeError" and
    # status 120. Now: nothing on stderr, status 0 (PIPESTATUS gives magbench's own).
    import subprocess
    import sys

    proc = subprocess.run(["bash", "-c", f"'{sys.executable}' -m magbench.cli figures | true; "
                           "echo ${PIPESTATUS[0]} >&2"], capture_output=True, text=True, timeout=120)
    assert proc.stderr == "0\n", proc.stderr


#: Names of inputs that count something, and of inputs that set a figure's work: a figure
#: parameter so named must declare itself whole, or bounded above (a new figure cannot forget).
COUNT_NAME = re.compile(r"(^|_)(members|seed|samples|steps|points|turns|coils|order|row|levels|checks|estimator)$")
WORK_NAME = re.compile(r"(^|_)(members|samples|steps|points|orbits|duration|span)$")


def test_counts_are_whole_and_work_is_bounded_on_every_figure():
    from magbench import figures

    missing = []
    for fid in figures.figure_ids():
        for name, p in figures.get_spec(fid).parameters.items():
            if COUNT_NAME.search(name) and not p.whole:
                missing.append(f"{fid}: {name} counts something but is not declared whole")
            if WORK_NAME.search(name) and p.high is None:
                missing.append(f"{fid}: {name} sets the figure's work but has no upper bound")
    assert not missing, "\n".join(missing)


def test_each_figures_bounds_hold():
    # Every figure's defaults lie inside its bounds (a build must not trip them); just past
    # a bound, or a count with a fraction, is refused naming the figure's parameter.
    from magbench import figures

    checked = 0
    for fid in figures.figure_ids():
        defaults = figures.resolve_parameters(fid)
        for name, p in figures.get_spec(fid).parameters.items():
            for bound, beyond in ((p.low, 0.5), (p.high, 2.0)):
                if bound is not None:
                    checked += 1
                    with pytest.raises(ValueError, match=f"parameter {name} of {fid} must be"):
                        figures.resolve_parameters(fid, {name: bound * beyond})
            if p.whole:
                assert defaults[name] == round(defaults[name]), (fid, name, defaults[name])
                with pytest.raises(ValueError, match="whole number"):
                    figures.resolve_parameters(fid, {name: defaults[name] + 0.5})
    assert checked > 40


def test_a_figure_input_from_the_parameter_set_has_the_parameter_sets_unit():
    """A figure input that is a chapter input (same name, same default) shows the SI unit of
    the parameter set's entry: a unit retyped by hand cannot drift from the data."""
    from magbench.chapters import CHAPTERS, chapter_parameters
    from magbench.io import load_parameter_set

    wrong, seen = [], 0
    for ch in CHAPTERS:
        table, values = load_parameter_set(ch.source), chapter_parameters(ch.key, overrides="")
        for fid in figures.figure_ids():
            spec = figures.get_spec(fid)
            if spec.compute.__module__ not in ch.figure_modules:
                continue
            for name, p in spec.parameters.items():
                if name in values and p.default == values[name]:
                    seen += 1
                    if p.unit != table[name].unit_si:
                        wrong.append(f"{fid}: {name} in {p.unit!r}, the parameter set's SI unit is "
                                     f"{table[name].unit_si!r}")
    assert seen > 100 and not wrong, (seen, wrong)


def test_caption_provenance_shows_a_changed_input_with_its_unit_and_a_pure_number_bare():
    # "1" is the parameter tables' mark of a pure number: "orbits = 3", not "orbits = 3 1"
    assert figures.caption_provenance("ch01-orbit-field", {"orbits": 3.0}).endswith("; orbits = 3.")
    spec = figures.get_spec("ch01-orbit-field")
    name, p = next((n, p) for n, p in spec.parameters.items() if p.unit not in ("", "1", "-"))
    assert f"{name} = {2.0 * p.default:.6g} {p.unit}" in figures.caption_provenance(
        "ch01-orbit-field", {name: 2.0 * p.default})
    assert "all parameters at their defaults" in figures.caption_provenance("ch01-orbit-field", {"orbits": 2.0})
