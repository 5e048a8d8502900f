"""Data files: checksums, provenance, clear errors for tampered or malformed files."""

import shutil
from pathlib import Path

import pytest
from numpy.testing import assert_allclose

from magbench import data
from magbench.data import DATA_DIR, DataError


def test_every_data_file_is_listed_and_verified():
    listed = {line.split()[1] for line in (DATA_DIR / "SHA256SUMS").read_text().splitlines() if line}
    present = {p.relative_to(DATA_DIR).as_posix() for p in DATA_DIR.rglob("*")
               if p.is_file() and p.name != "SHA256SUMS"}
    assert listed == present
    for name in listed:
        data.verify_checksum(DATA_DIR / name)


def test_thesis_measurements_have_provenance():
    rows = data.load_measurements("thesis")
    # Everything of the inventory's §4.1 (bench values and COMSOL's simulated numbers).
    for key in ("sim-coil-resistance", "sim-center-h", "mtq-resistance", "mtq-moment",
                "orientation-error", "comsol-max-h"):
        assert key in rows
    assert rows["comsol-max-h"].kind == "simulated"
    assert rows["sim-center-h"].kind == "measured"
    seed = (Path(__file__).resolve().parents[2] / "shared" / "seeds" / "thesis_bui_2016.txt")
    if seed.is_file():
        lines = seed.read_text(encoding="utf-8").splitlines()
        # The seed line of each row must contain the printed number (decimal point or comma).
        for row in rows.values():
            text = lines[row.seed_line - 1]
            printed = f"{row.value_low:g}"
            assert printed in text or printed.replace(".", ",") in text, row.id


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

    lines = []
    for p in sorted(target.rglob("*")):
        if p.is_file() and p.name != "SHA256SUMS":
            lines.append(f"{hashlib.sha256(p.read_bytes()).hexdigest()}  {p.relative_to(target).as_posix()}")
    (target / "SHA256SUMS").write_text("\n".join(lines) + "\n")


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
    ("\n[broken\n", r"thesis.toml: .*line"),                                   # TOML syntax
    ('\n[extra]\nvalue = 1.0\nsource = "ours"\n', r"\[extra\] needs value, unit and source"),
])
def test_malformed_parameter_file_names_file(tmp_path, appended, match):
    target = _copy_data(tmp_path)
    path = target / "params" / "thesis.toml"
    path.write_text(path.read_text() + appended)
    _rehash(target)
    with pytest.raises(DataError, match=match):
        data.load_parameter_set("thesis", data_dir=target)


def test_file_outside_manifest_is_rejected(tmp_path):
    target = _copy_data(tmp_path)
    (target / "extra.csv").write_text("x\n")
    with pytest.raises(DataError, match="not listed"):
        data.verify_checksum(target / "extra.csv", data_dir=target)
