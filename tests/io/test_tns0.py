"""TNS-0 data: Table 1 and 2 cells against the preprint text, the interpretation, the
session stamps, the parameter set's provenance, clear errors for malformed files."""

import shutil
from pathlib import Path

import numpy as np
import pytest
from numpy.testing import assert_allclose

from magbench.io import data
from magbench.io import (DATA_DIR, DataError, load_printed, load_sessions, load_table1, load_table1_printed,
                         load_table2, load_table2_printed, load_tns0_parameters, table1_hours)

SEED = Path(__file__).resolve().parents[3] / "shared" / "seeds" / "tns0_flight_2006.txt"
needs_seed = pytest.mark.skipif(not SEED.is_file(), reason="the preprint's text is not in ../shared/seeds")


def _seed_lines():
    return SEED.read_text(encoding="utf-8").splitlines()


@needs_seed
def test_every_table1_cell_is_the_preprint_text_at_its_line():
    lines = _seed_lines()
    cells = load_table1_printed()
    assert len(cells) == 63
    for cell in cells:
        if cell.status == "lost":
            continue
        assert lines[cell.seed_line - 1].strip() == cell.text, (cell.row, cell.position)
    # Each row begins with its number on the line before its first cell (rows 1-7).
    for row in range(1, 8):
        first = next(c for c in cells if c.row == row and c.position == 1)
        assert lines[first.seed_line - 3].strip() == str(row)


def test_row1_keeps_its_lost_cell_missing():
    cells = {(c.row, c.position): c for c in load_table1_printed()}
    lost = [key for key, c in cells.items() if c.status == "lost"]
    assert lost == [(1, 9)]
    assert cells[(1, 9)].text == "" and cells[(1, 9)].seed_line is None and np.isnan(cells[(1, 9)].value)
    assert [cells[(1, p)].text for p in (6, 7, 8)] == ["-", "-", "-"]


def test_table1_interpretation():
    t = load_table1()
    assert_allclose(t.angular_momentum, [0.0936, 0.0644, 0.0562, 0.0535, 0.0517, 0.0431, 0.017], rtol=0, atol=0)
    assert np.all(np.diff(t.angular_momentum) < 0), "L decays (Fig. 14)"
    assert_allclose(t.nutation[1:], 1.571, rtol=0, atol=0)
    # Row 1: the lost cell is read as the second phase, so 20.36 is t0 and 0.80 the Sun angle.
    assert np.isnan(t.phase_b[0]) and t.start_time[0] == 20.36 and t.sun_angle[0] == 0.80
    assert np.isnan(t.earth_polar_angle[0]) and np.isnan(t.albedo_ratio[0])
    # Every angle the interpretation calls an angle lies in [0, 2π): 20.36 could not.
    for q in ("phase_a", "phase_b", "sun_angle", "earth_polar_angle", "earth_azimuth"):
        v = t.values[q][~np.isnan(t.values[q])]
        assert np.all((v >= 0) & (v < 2 * np.pi)), q
    assert {m.confidence for m in t.meaning.values()} <= {"high", "medium", "low"}
    assert t.meaning["angular_momentum"].confidence == "high"


@needs_seed
def test_table2_cells_and_interpretation():
    lines = _seed_lines()
    for cell in load_table2_printed():
        assert lines[cell.seed_line - 1].strip() == cell.text
    t = load_table2()
    assert_allclose([t.angular_momentum[0], t.nutation[0], t.albedo_ratio[0]], [7.2e-4, 0.85, 0.6], rtol=0, atol=0)


@needs_seed
def test_session_stamps_as_printed():
    lines = _seed_lines()
    sessions = load_sessions()
    assert len(sessions) == 8
    for s in sessions:
        assert s.printed in lines[s.seed_line - 1], s.session
    # Hours since session 1 from the minute stamps (tns0_passive.md §1 lists the same).
    assert_allclose(table1_hours(), [0, 220.383, 258.350, 281.367, 293.417, 347.450, 522.317],
                    atol=5e-4)  # the reference prints three decimals of an hour
    assert sessions[-1].resolution_hours == 24.0


def test_parameters_carry_their_provenance():
    params = load_tns0_parameters()
    assert {p.source for p in params.values()} <= {"tns0", "external", "ours"}
    assert params["orbit_inclination"].source == "external"
    assert_allclose(params["orbit_inclination"].value_si, np.radians(51.6), rtol=1e-15)  # unit conversion only
    assert params["magnet_moment"].source == "ours" and params["rod_volume"].source == "ours"
    assert all(p.note for p in params.values() if p.source != "tns0")


@needs_seed
def test_printed_values_are_at_their_lines():
    lines = _seed_lines()
    printed = load_printed("tns0")
    assert {"tns0-table2-nutation", "tns0-final-angle"} <= set(printed)
    for row in printed.values():
        text = lines[row.seed_line - 1]
        # A value stated in words ("удвоенной", twice) is found by the words its method quotes.
        quoted = row.method.split("'")[1] if row.method.count("'") >= 2 else None
        assert (f"{row.value_low:g}" in text or str(row.value_low) in text or "7.2e-004" in text
                or (quoted is not None and quoted in text)), row.id
    assert printed["tns0-final-angle"].resolution == 5.0


def _copy(tmp_path):
    root = tmp_path / "data"
    shutil.copytree(DATA_DIR / "tns0", root / "tns0")
    return root


def _rewrite(root, name, old, new):
    path = root / "tns0" / name
    path.write_text(path.read_text(encoding="utf-8").replace(old, new, 1), encoding="utf-8")
    import hashlib
    sums = root / "tns0" / "SHA256SUMS"
    lines = []
    for line in sums.read_text().splitlines():
        digest, fname = line.split()
        if fname == name:
            digest = hashlib.sha256(path.read_bytes()).hexdigest()
        lines.append(f"{digest}  {fname}")
    sums.write_text("\n".join(lines) + "\n")
    data._manifest.cache_clear()  # the manifest is cached per folder


def test_a_tampered_file_is_refused(tmp_path):
    root = _copy(tmp_path)
    path = root / "tns0" / "table1_printed.csv"
    path.write_text(path.read_text(encoding="utf-8").replace("0.0936", "0.0937"), encoding="utf-8")
    with pytest.raises(DataError, match="checksum"):
        load_table1_printed(root)


def test_a_malformed_cell_names_file_line_and_column(tmp_path):
    root = _copy(tmp_path)
    _rewrite(root, "table1_printed.csv", "2,1,0.0644,207,number", "2,1,O.0644,207,number")
    with pytest.raises(DataError, match=r"table1_printed\.csv:\d+: column 'text'"):
        load_table1_printed(root)


def test_a_bad_confidence_and_a_bad_source_are_refused(tmp_path):
    root = _copy(tmp_path)
    _rewrite(root, "table1_interpretation.csv", ",high,", ",certain,")
    with pytest.raises(DataError, match=r"table1_interpretation\.csv:\d+: column 'confidence'"):
        load_table1(root)
    _rewrite(root, "params.toml", 'source = "ours"', 'source = "guess"')
    with pytest.raises(DataError, match=r"params\.toml: \[\w+\] source must be one of"):
        load_tns0_parameters(root)
