"""Data files: checksums, provenance, clear errors for tampered or malformed files."""

import shutil
from pathlib import Path

import pytest
from numpy.testing import assert_allclose

from magbench.io import data
from magbench.io import DATA_DIR, DataError


def test_every_data_file_is_listed_and_verified():
    # One manifest per folder (a source, the wire tables, the bench logs), none at the top.
    folders = sorted(p for p in DATA_DIR.iterdir() if p.is_dir() and p.name != "__pycache__")
    assert {p.name for p in folders} >= {"thesis", "kovalenko", "wires", "bench"}
    assert not [p for p in DATA_DIR.iterdir() if p.is_file()], "files belong in a source's folder"
    for folder in folders:
        listed = {line.split()[1] for line in (folder / "SHA256SUMS").read_text().splitlines() if line}
        present = {p.relative_to(folder).as_posix() for p in folder.rglob("*")
                   if p.is_file() and p.name != "SHA256SUMS"}
        assert listed == present, folder.name
        for name in listed:
            data.verify_checksum(folder / name)


def _significant_digits(value):
    """'0.000156' -> '156', '2.34e-8' -> '234': the digits a source prints, in any notation."""
    return f"{abs(value):.6e}".split("e")[0].rstrip("0").rstrip(".").replace(".", "")


def _digits(text):
    """A seed line without decimal separators and spaces ('0,0223' and '0.0223' alike; the OCR
    also reads a decimal comma as ';', as in E44's '(1;4^2,8)-10^', seed line 228)."""
    return text.replace(".", "").replace(",", "").replace(";", "").replace(" ", "")


def test_thesis_measurements_have_provenance():
    measured, printed = data.load_measurements("thesis"), data.load_printed("thesis")
    # Everything of the inventory's §4.1 (bench values and COMSOL's simulated numbers).
    for key in ("sim-coil-resistance", "sim-center-h", "mtq-resistance", "orientation-error", "comsol-max-h"):
        assert key in measured
    assert "mtq-moment" in printed and printed["mtq-moment"].kind == "printed"
    assert measured["comsol-max-h"].kind == "simulated"
    assert measured["sim-center-h"].kind == "measured"
    assert not set(measured) & set(printed), "an id names one value"


def test_thesis_values_are_on_their_line():
    # The seed line of each row must contain the printed number (decimal point or comma).
    seed = Path(__file__).resolve().parents[3] / "shared" / "seeds" / "thesis_bui_2016.txt"
    if not seed.is_file():
        pytest.skip(f"the thesis transcription is not at {seed}")
    rows = {**data.load_measurements("thesis"), **data.load_printed("thesis")}
    lines = seed.read_text(encoding="utf-8").splitlines()
    for row in rows.values():
        assert _significant_digits(row.value_low) in _digits(lines[row.seed_line - 1]), row.id


def test_printed_values_carry_their_digits():
    printed = data.load_printed("thesis")
    # Half a unit of the last printed digit, unless the file states it ("≈ 200": one digit).
    assert printed["thesis-sim-coil-resistance"].resolution == 0.05
    assert printed["thesis-sim-ampere-turns"].resolution == 0.5
    assert printed["thesis-eq15-field"].resolution == 50.0
    assert_allclose(printed["thesis-mtq-wire-diameter"].resolution_si, 0.5e-6, rtol=1e-12)   # float of mm -> m
    assert data.digit_resolution("0.79e-4") == 0.5e-6


def test_kovalenko_printed_values_are_on_their_page():
    seed = Path(__file__).resolve().parents[3] / "shared" / "seeds" / "kovalenko_1975_magnetic_control_systems.txt"
    if not seed.is_file():
        pytest.skip(f"the Kovalenko transcription is not at {seed}")
    lines = seed.read_text(encoding="utf-8").splitlines()
    for row in data.load_printed("kovalenko").values():
        assert _significant_digits(row.value_low) in _digits(lines[row.seed_line - 1]), row.id


def test_si_conversion_and_printed_form():
    r = data.measurement("sim-coil-resistance")
    assert r.printed == "12–13 ± 1 ohm"
    assert_allclose(r.value, 12.5, rtol=0)
    assert_allclose(data.measurement("orientation-error").value, 10 * 3.141592653589793 / 180, rtol=1e-15)
    assert data.measurement("mtq-wire-diameter").si_unit == "m"


def test_unknown_id_lists_valid_ones():
    with pytest.raises(KeyError, match="sim-center-h"):
        data.measurement("no-such-value")


def _copy_data(tmp_path):
    target = tmp_path / "data"
    shutil.copytree(DATA_DIR, target)
    return target


def test_tampered_file_is_rejected(tmp_path):
    target = _copy_data(tmp_path)
    path = target / "thesis" / "measurements.csv"
    path.write_text(path.read_text().replace(",262,262,", ",250,250,"))
    with pytest.raises(DataError, match="does not match its checksum"):
        data.load_measurements("thesis", data_dir=target)


def _rehash(target):
    import hashlib

    for folder in (p for p in target.iterdir() if p.is_dir()):
        lines = [f"{hashlib.sha256(p.read_bytes()).hexdigest()}  {p.relative_to(folder).as_posix()}"
                 for p in sorted(folder.rglob("*")) if p.is_file() and p.name != "SHA256SUMS"]
        (folder / "SHA256SUMS").write_text("\n".join(lines) + "\n")


def test_malformed_row_names_file_and_line(tmp_path):
    target = _copy_data(tmp_path)
    path = target / "thesis" / "measurements.csv"
    lines = path.read_text().splitlines()
    bad = next(i for i, line in enumerate(lines) if line.startswith("sim-center-h,"))
    lines[bad] = lines[bad].replace(",262,262,", ",two hundred,262,")
    path.write_text("\n".join(lines) + "\n")
    _rehash(target)
    with pytest.raises(DataError, match=rf"measurements.csv:{bad + 1}: column 'value_low'"):
        data.load_measurements("thesis", data_dir=target)


@pytest.mark.parametrize("appended, match", [
    ("\n[broken\n", r"thesis/params.toml: .*line"),                                   # TOML syntax
    ('\n[extra]\nvalue = 1.0\nsource = "ours"\n', r"\[extra\] needs value, unit and source"),
])
def test_malformed_parameter_file_names_file(tmp_path, appended, match):
    target = _copy_data(tmp_path)
    path = target / "thesis" / "params.toml"
    path.write_text(path.read_text() + appended)
    _rehash(target)
    with pytest.raises(DataError, match=match):
        data.load_parameter_set("thesis", data_dir=target)


def test_file_outside_manifest_is_rejected(tmp_path):
    target = _copy_data(tmp_path)
    (target / "thesis" / "extra.csv").write_text("x\n")
    with pytest.raises(DataError, match="not listed"):
        data.verify_checksum(target / "thesis" / "extra.csv", data_dir=target)
    (target / "loose.csv").write_text("x\n")
    with pytest.raises(DataError, match="must lie in a folder"):
        data.verify_checksum(target / "loose.csv", data_dir=target)


def test_the_wheel_ships_the_data_with_its_checksums(tmp_path):
    """An installed (non-editable) package has its data: every data file and every folder's
    SHA256SUMS is in the wheel built from pyproject.toml."""
    import subprocess
    import sys
    import zipfile

    root = Path(__file__).resolve().parents[2]
    result = subprocess.run([sys.executable, "-m", "pip", "wheel", "--quiet", "--no-deps", "--no-build-isolation",
                             "--wheel-dir", str(tmp_path), str(root)], capture_output=True, text=True)
    assert result.returncode == 0, result.stderr
    (wheel,) = tmp_path.glob("magbench-*.whl")
    shipped = {n for n in zipfile.ZipFile(wheel).namelist() if n.startswith("magbench/data/")}
    expected = {f"magbench/data/{p.relative_to(DATA_DIR).as_posix()}" for p in DATA_DIR.rglob("*")
                if p.is_file() and "__pycache__" not in p.parts}
    assert expected <= shipped, sorted(expected - shipped)
    assert "magbench/data/thesis/SHA256SUMS" in shipped
