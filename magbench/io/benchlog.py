r"""Bench logs: a documented CSV format for the raw records of a bench run, and its loader.

The thesis's Figs. 19–20 show angle traces of the bench, but their data were never
published. This module defines the format a bench run should be logged in so that the
book can set it beside the model: drop such a file into ``magbench/data/bench/`` (and run
``make checksums``, as for any data file) and the chapter overlays it on the prediction.

Format (``magbench/data/bench/README.md`` has the same text)
---------------------------------------------------
A UTF-8 CSV file. Lines starting with ``#`` are comments; a comment of the form
``# key: value`` before the header is metadata (``psi_des`` [rad], the target of the
run, selects the figure it is drawn on; other keys are kept as text). The first
non-comment line is the header, exactly these twelve columns, each ``name [unit]``::

    time [s], gyro_x [rad/s], gyro_y [rad/s], gyro_z [rad/s],
    accel_x [m/s^2], accel_y [m/s^2], accel_z [m/s^2],
    mag_x [T], mag_y [T], mag_z [T], coil_1 [duty], coil_2 [duty]

(written on one line, separated by commas). The coil commands are either both
``[duty]`` (signed PWM duty in [−1, 1]) or both ``[V]`` (signed voltage across the
coil). Body axes: x along coil 1's axis, y along coil 2's axis, z up, the axis the
mock-up turns about, so that ``gyro_z`` is dψ/dt and the magnetometer heading is
ψ = atan2(−mag_y, mag_x). Each following line is one sample: twelve finite numbers,
time strictly increasing. Raw sensor values are converted to SI by whoever writes
the log (the MPU-6050 and HMC5883L report counts).
"""

import csv
import io
import math
import re
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from .data import DATA_DIR, DataError, verify_checksum

__all__ = ["COLUMNS", "COIL_UNITS", "BenchLogError", "BenchLog", "load_bench_log",
           "bench_log_paths", "load_bench_logs", "log_heading", "log_filtered_angle"]

#: The columns of a bench log, in order, with their units (the coils' unit may vary).
COLUMNS = [("time", "s"), ("gyro_x", "rad/s"), ("gyro_y", "rad/s"), ("gyro_z", "rad/s"),
           ("accel_x", "m/s^2"), ("accel_y", "m/s^2"), ("accel_z", "m/s^2"),
           ("mag_x", "T"), ("mag_y", "T"), ("mag_z", "T"), ("coil_1", None), ("coil_2", None)]

#: Units allowed for the coil commands: signed PWM duty, or volts across the coil.
COIL_UNITS = ("duty", "V")

#: Where the book looks for bench logs.
BENCH_DIR = DATA_DIR / "bench"

_HEADER_CELL = re.compile(r"^\s*([A-Za-z0-9_]+)\s*\[([^\]]*)\]\s*$")


class BenchLogError(DataError):
    """A bench log does not follow the documented format (names file, line, column)."""


@dataclass
class BenchLog:
    """A loaded bench log, SI arrays with time along axis 0."""

    path: Path
    time: np.ndarray            # (N,) [s]
    gyro: np.ndarray            # (N, 3) [rad/s]
    accelerometer: np.ndarray   # (N, 3) [m/s^2]
    magnetometer: np.ndarray    # (N, 3) [T]
    coil: np.ndarray            # (N, 2) [duty] or [V]
    coil_unit: str
    metadata: dict = field(default_factory=dict)

    @property
    def psi_des(self):
        """The run's target angle from the metadata [rad], or None."""
        value = self.metadata.get("psi_des")
        return None if value is None else float(value)


def _expected_header():
    return ", ".join(f"{n} [{u or 'duty|V'}]" for n, u in COLUMNS)


def _parse(text, path):
    metadata = {}
    header_seen = False
    coil_unit = None
    rows = []
    previous_time = None
    for lineno, line in enumerate(text.splitlines(), start=1):
        if not line.strip():
            continue
        if line.lstrip().startswith("#"):
            if not header_seen:
                body = line.lstrip()[1:].strip()
                if ":" in body:
                    key, value = body.split(":", 1)
                    if re.fullmatch(r"[A-Za-z_][A-Za-z0-9_]*", key.strip()):
                        metadata[key.strip()] = value.strip()
            continue
        cells = next(csv.reader(io.StringIO(line)))
        if not header_seen:
            if len(cells) != len(COLUMNS):
                raise BenchLogError(f"{path}:{lineno}: header has {len(cells)} columns, expected "
                                    f"{len(COLUMNS)}: {_expected_header()}")
            for k, (cell, (name, unit)) in enumerate(zip(cells, COLUMNS), start=1):
                match = _HEADER_CELL.match(cell)
                if not match or match.group(1) != name:
                    raise BenchLogError(f"{path}:{lineno}: column {k} must be '{name} [unit]', "
                                        f"got {cell.strip()!r}; expected header: {_expected_header()}")
                got = match.group(2).strip()
                if unit is None:
                    if got not in COIL_UNITS:
                        raise BenchLogError(f"{path}:{lineno}: column {k} ({name}) unit must be one of "
                                            f"{', '.join(COIL_UNITS)}, got {got!r}")
                    if coil_unit not in (None, got):
                        raise BenchLogError(f"{path}:{lineno}: column {k} ({name}) unit {got!r} differs "
                                            f"from coil_1's {coil_unit!r}; both coils use one unit")
                    coil_unit = got
                elif got != unit:
                    raise BenchLogError(f"{path}:{lineno}: column {k} ({name}) unit must be {unit!r} (SI), "
                                        f"got {got!r}")
            header_seen = True
            continue
        if len(cells) != len(COLUMNS):
            raise BenchLogError(f"{path}:{lineno}: expected {len(COLUMNS)} values, got {len(cells)}")
        values = []
        for (name, unit), cell in zip(COLUMNS, cells):
            label = f"{name} [{unit or coil_unit}]"
            try:
                value = float(cell)
            except ValueError:
                raise BenchLogError(f"{path}:{lineno}: column {label!r} must be a number, "
                                    f"got {cell.strip()!r}") from None
            if not math.isfinite(value):
                raise BenchLogError(f"{path}:{lineno}: column {label!r} must be finite, got {cell.strip()!r}")
            if unit is None and coil_unit == "duty" and abs(value) > 1.0:
                raise BenchLogError(f"{path}:{lineno}: column {label!r} must lie in [-1, 1], got {value!r}")
            values.append(value)
        if previous_time is not None and values[0] <= previous_time:
            raise BenchLogError(f"{path}:{lineno}: column 'time [s]' must increase strictly, "
                                f"got {values[0]!r} after {previous_time!r}")
        previous_time = values[0]
        rows.append(values)
    if not header_seen:
        raise BenchLogError(f"{path}: no header line; expected: {_expected_header()}")
    if len(rows) < 2:
        raise BenchLogError(f"{path}: needs at least 2 samples, got {len(rows)}")
    if "psi_des" in metadata:
        try:
            if not math.isfinite(float(metadata["psi_des"])):
                raise ValueError
        except ValueError:
            raise BenchLogError(f"{path}: metadata psi_des must be a finite number [rad], "
                                f"got {metadata['psi_des']!r}") from None
    return np.array(rows), coil_unit, metadata


def load_bench_log(path):
    """Load and validate a bench log (format in the module docstring).

    Parameters
    ----------
    path : str or Path
        The CSV file. A file inside the data directory is checked against its folder's ``SHA256SUMS``
        first, like every data file.

    Returns
    -------
    BenchLog

    Raises
    ------
    BenchLogError
        If the file breaks the format; the message names the file, the line and the
        column.

    Examples
    --------
    >>> import tempfile
    >>> header = ",".join(f"{n} [{u or 'duty'}]" for n, u in COLUMNS)
    >>> with tempfile.TemporaryDirectory() as d:
    ...     p = Path(d) / "synthetic.csv"
    ...     _ = p.write_text(header + "\\n" + "0,0,0,0,0,0,9.8,3e-4,0,0,0,0\\n"
    ...                      + "0.01,0,0,0,0,0,9.8,3e-4,0,0,0.5,0\\n")
    ...     log = load_bench_log(p)
    >>> log.time.tolist(), log.coil_unit
    ([0.0, 0.01], 'duty')
    """
    path = Path(path)
    try:
        inside_data = path.resolve().is_relative_to(DATA_DIR.resolve())
    except OSError:
        inside_data = False
    if inside_data:
        content = verify_checksum(path)
    else:
        if not path.is_file():
            raise BenchLogError(f"bench log {path} does not exist")
        content = path.read_bytes()
    try:
        text = content.decode("utf-8")
    except UnicodeDecodeError as exc:
        raise BenchLogError(f"{path}: not UTF-8 text ({exc})") from None
    table, coil_unit, metadata = _parse(text, path)
    return BenchLog(path=path, time=table[:, 0], gyro=table[:, 1:4], accelerometer=table[:, 4:7],
                    magnetometer=table[:, 7:10], coil=table[:, 10:12], coil_unit=coil_unit,
                    metadata=metadata)


def bench_log_paths(directory=None):
    """The bench logs (``*.csv``) in ``directory`` (default ``magbench/data/bench``), sorted."""
    directory = Path(directory) if directory is not None else BENCH_DIR
    return sorted(directory.glob("*.csv")) if directory.is_dir() else []


def load_bench_logs(directory=None):
    """Every bench log in ``directory`` (default ``magbench/data/bench``), loaded and validated."""
    return [load_bench_log(p) for p in bench_log_paths(directory)]


def log_heading(log):
    """Magnetometer heading ψ = atan2(−mag_y, mag_x) of a log, unwrapped [rad]."""
    return np.unwrap(np.arctan2(-log.magnetometer[:, 1], log.magnetometer[:, 0]))


def log_filtered_angle(log, alpha):
    """The angle the bench's eq. (39) filter makes of a log (gyro_z with the heading) [rad].

    The sample interval before the first sample is taken equal to the next one.
    """
    from ..estimation import complementary_filter

    dt = np.diff(log.time)
    dt = np.concatenate([dt[:1], dt])
    return complementary_filter(log.gyro[:, 2], log_heading(log), dt, alpha)
