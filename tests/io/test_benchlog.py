"""Bench-log format and loader (magbench.io.benchlog), on synthetic logs in tmp_path.

Every log here is synthetic, written by the test into a temporary directory; nothing
is written under data/.
"""

import numpy as np
import pytest
from numpy.testing import assert_allclose

from magbench.io import benchlog
from magbench.io.benchlog import COLUMNS, BenchLogError

HEADER = ",".join(f"{name} [{unit or 'duty'}]" for name, unit in COLUMNS)


def synthetic_rows(n=600, dt=0.01, rate=0.05, psi0=0.2, b0=3.29e-4):
    """A noise-free log of a mock-up turning at a constant rate (clearly synthetic)."""
    t = np.arange(n) * dt
    psi = psi0 + rate * t
    cols = [t, np.zeros(n), np.zeros(n), np.full(n, rate), np.zeros(n), np.zeros(n), np.full(n, 9.81),
            b0 * np.cos(psi), -b0 * np.sin(psi), np.full(n, 5e-5), np.full(n, 0.25), np.full(n, -0.5)]
    return np.column_stack(cols), psi


def write_log(path, header=HEADER, rows=None, meta=("# synthetic log written by tests", "# psi_des: 1.0")):
    if rows is None:
        rows, _ = synthetic_rows()
    lines = list(meta) + [header] + [",".join(repr(float(v)) if not isinstance(v, str) else v for v in r)
                                     for r in rows]
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return path


def test_valid_log_loads_with_metadata_and_si_arrays(tmp_path):
    rows, psi = synthetic_rows()
    log = benchlog.load_bench_log(write_log(tmp_path / "run.csv", rows=rows))
    assert log.psi_des == 1.0 and log.coil_unit == "duty"
    assert log.gyro.shape == (600, 3) and log.coil.shape == (600, 2)
    assert_allclose(log.time, rows[:, 0], rtol=0, atol=0)
    # Heading = atan2(-mag_y, mag_x) recovers the synthetic angle (float rounding only).
    assert_allclose(benchlog.log_heading(log), psi, rtol=0, atol=1e-12)
    # Noise-free gyro and heading: the filter starts A*rate*dt = 4.9e-4 rad ahead and that
    # offset decays as A^k; after 400 samples 0.98^400 * 4.9e-4 = 1.5e-7 rad remain.
    assert_allclose(benchlog.log_filtered_angle(log, 0.98)[400:], psi[400:], rtol=0, atol=2e-7)


def test_volts_are_accepted_for_both_coils(tmp_path):
    header = HEADER.replace("coil_1 [duty]", "coil_1 [V]").replace("coil_2 [duty]", "coil_2 [V]")
    rows, _ = synthetic_rows(n=3)
    rows[:, 10] = 12.0     # volts may exceed 1
    assert benchlog.load_bench_log(write_log(tmp_path / "v.csv", header=header, rows=rows)).coil_unit == "V"


def test_directory_listing_loads_every_csv(tmp_path):
    write_log(tmp_path / "b.csv")
    write_log(tmp_path / "a.csv")
    (tmp_path / "notes.txt").write_text("not a log")
    assert [p.name for p in benchlog.bench_log_paths(tmp_path)] == ["a.csv", "b.csv"]
    assert len(benchlog.load_bench_logs(tmp_path)) == 2
    assert benchlog.bench_log_paths(tmp_path / "missing") == []


def test_the_shipped_data_folder_holds_no_log():
    # The thesis's traces are unpublished: magbench/data/bench has its README and nothing else.
    assert benchlog.bench_log_paths() == []
    assert (benchlog.BENCH_DIR / "README.md").is_file()


def _bad(tmp_path, **kwargs):
    return write_log(tmp_path / "bad.csv", **kwargs)


@pytest.mark.parametrize("header, message", [
    (HEADER.rsplit(",", 1)[0], r"bad.csv:3: header has 11 columns"),
    (HEADER.replace("gyro_y", "gyro_q"), r"bad.csv:3: column 3 must be 'gyro_y \[unit\]'"),
    (HEADER.replace("mag_x [T]", "mag_x"), r"bad.csv:3: column 8 must be 'mag_x \[unit\]'"),
    (HEADER.replace("gyro_z [rad/s]", "gyro_z [deg/s]"), r"bad.csv:3: column 4 \(gyro_z\) unit must be 'rad/s'"),
    (HEADER.replace("mag_z [T]", "mag_z [uT]"), r"column 10 \(mag_z\) unit must be 'T'"),
    (HEADER.replace("coil_1 [duty]", "coil_1 [%]"), r"column 11 \(coil_1\) unit must be one of duty, V"),
    (HEADER.replace("coil_2 [duty]", "coil_2 [V]"), r"column 12 \(coil_2\) unit 'V' differs"),
])
def test_malformed_header_names_file_line_and_column(tmp_path, header, message):
    with pytest.raises(BenchLogError, match=message):
        benchlog.load_bench_log(_bad(tmp_path, header=header))


def test_non_monotonic_time_is_rejected(tmp_path):
    rows, _ = synthetic_rows(n=10)
    rows[5, 0] = rows[4, 0]
    with pytest.raises(BenchLogError, match=r"bad.csv:9: column 'time \[s\]' must increase strictly"):
        benchlog.load_bench_log(_bad(tmp_path, rows=rows))


@pytest.mark.parametrize("column, value, message", [
    (7, "nan", r"bad.csv:6: column 'mag_x \[T\]' must be finite, got 'nan'"),
    (3, "inf", r"column 'gyro_z \[rad/s\]' must be finite"),
    (5, "abc", r"bad.csv:6: column 'accel_y \[m/s\^2\]' must be a number, got 'abc'"),
    (11, "1.5", r"column 'coil_2 \[duty\]' must lie in \[-1, 1\]"),
])
def test_bad_values_name_file_line_and_column(tmp_path, column, value, message):
    rows, _ = synthetic_rows(n=5)
    rows = rows.astype(object)
    rows[2, column] = value
    with pytest.raises(BenchLogError, match=message):
        benchlog.load_bench_log(_bad(tmp_path, rows=rows))


def test_short_rows_missing_header_and_single_sample_are_rejected(tmp_path):
    rows, _ = synthetic_rows(n=3)
    path = _bad(tmp_path, rows=rows)
    lines = path.read_text().splitlines()
    lines[4] = lines[4].rsplit(",", 1)[0]
    path.write_text("\n".join(lines) + "\n")
    with pytest.raises(BenchLogError, match=r"bad.csv:5: expected 12 values, got 11"):
        benchlog.load_bench_log(path)
    path.write_text("# only comments\n")
    with pytest.raises(BenchLogError, match="no header line"):
        benchlog.load_bench_log(path)
    with pytest.raises(BenchLogError, match="at least 2 samples"):
        benchlog.load_bench_log(_bad(tmp_path, rows=rows[:1]))
    with pytest.raises(BenchLogError, match="psi_des must be a finite number"):
        benchlog.load_bench_log(_bad(tmp_path, meta=("# psi_des: sixty degrees",)))
    with pytest.raises(BenchLogError, match="does not exist"):
        benchlog.load_bench_log(tmp_path / "absent.csv")


def test_log_inside_data_must_be_in_the_checksum_manifest(tmp_path, monkeypatch):
    # A log dropped into data/ without `make checksums` is refused, like any data file.
    from magbench.io import data

    target = tmp_path / "data"
    (target / "bench").mkdir(parents=True)
    (target / "bench" / "SHA256SUMS").write_text("")
    data._manifest.cache_clear()
    monkeypatch.setattr(benchlog, "DATA_DIR", target)
    monkeypatch.setattr(data, "DATA_DIR", target)
    path = write_log(target / "bench" / "run.csv")
    try:
        with pytest.raises(data.DataError, match="is not listed in"):
            benchlog.load_bench_log(path)
    finally:
        data._manifest.cache_clear()
