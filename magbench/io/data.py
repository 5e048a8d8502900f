"""Loading the project's data files, with checksums and provenance.

The data directory (``magbench/data/``, shipped as package data) holds only what a
source printed or a person measured, one folder per source (``thesis/``,
``kovalenko/``, ...) plus the wire tables (``wires/``) and bench logs (``bench/``).
Every file is listed in its folder's ``SHA256SUMS``; each read verifies the file's
sha256 first, so a tampered or accidentally edited file is an error, not a silently
different result. Nothing here writes to the data directory. A source's folder holds

* ``params.toml``: its parameter set, one table per value with provenance;
* ``measurements.csv``: values measured by a person or read off the source's figures;
* ``printed.csv``: printed values that the errata compare against.

Two formats:

* measurement tables (CSV with ``#`` comment lines): one row per printed value, with
  its source section, seed-text line, method and uncertainty;
* parameter sets (TOML): one table per parameter, value and unit as printed.

Values are converted to SI on loading (``value_si``); the printed value and unit stay
available for provenance.
"""

import csv
import hashlib
import io
import math
import tomllib
from dataclasses import dataclass
from functools import lru_cache
from importlib.resources import files
from pathlib import Path

__all__ = [
    "DATA_DIR",
    "DataError",
    "Measurement",
    "Parameter",
    "to_si",
    "verify_checksum",
    "load_measurements",
    "load_printed",
    "digit_resolution",
    "measurement",
    "load_parameter_set",
    "WireTable",
    "WIRE_TABLES",
    "load_wire_table",
]

#: The project's data directory: package data, so an installed package has it too.
DATA_DIR = Path(str(files("magbench") / "data"))

from ..units import SI_FACTORS as _TO_SI
from ..units import SI_UNIT_NAMES as _SI_UNIT


class DataError(ValueError):
    """A data file is missing, malformed, or does not match its recorded checksum."""


def to_si(value, unit):
    """Convert ``value`` printed in ``unit`` to SI; returns ``(value_si, si_unit)``.

    Examples
    --------
    >>> to_si(0.75, "mm")
    (0.00075, 'm')
    """
    if unit not in _TO_SI:
        raise DataError(f"unknown unit {unit!r}; known units: {', '.join(sorted(_TO_SI))}")
    return value * _TO_SI[unit], _SI_UNIT.get(unit, unit)


@dataclass(frozen=True)
class Measurement:
    """One printed or measured value with its provenance (a row of a measurement table)."""

    id: str
    quantity: str
    value_low: float
    value_high: float
    unit: str
    uncertainty: float | None
    kind: str
    source: str
    section: str
    seed_line: int
    method: str
    conditions: str
    resolution: float | None = None

    @property
    def printed(self):
        """The value as the source prints it, with its unit."""
        low, high = (f"{v:g}" for v in (self.value_low, self.value_high))
        text = low if low == high else f"{low}–{high}"
        if self.uncertainty is not None:
            text += f" ± {self.uncertainty:g}"
        return f"{text} {self.unit}"

    @property
    def value(self):
        """Printed value in SI; the midpoint where the source prints a range."""
        return to_si(0.5 * (self.value_low + self.value_high), self.unit)[0]

    @property
    def uncertainty_si(self):
        """Stated uncertainty in SI, or half the printed range, or ``None``."""
        if self.uncertainty is not None:
            return to_si(self.uncertainty, self.unit)[0]
        if self.value_high != self.value_low:
            return to_si(0.5 * (self.value_high - self.value_low), self.unit)[0]
        return None

    @property
    def si_unit(self):
        """The SI unit of :attr:`value`."""
        return to_si(1.0, self.unit)[1]

    @property
    def value_as_printed(self):
        """The printed value in its printed unit (:attr:`unit`); the midpoint of a range."""
        return 0.5 * (self.value_low + self.value_high)

    @property
    def resolution_si(self):
        """:attr:`resolution` (half a unit of the last printed digit) in SI, or ``None``."""
        return None if self.resolution is None else to_si(self.resolution, self.unit)[0]


@dataclass(frozen=True)
class Parameter:
    """One parameter of a parameter set, as printed, with provenance."""

    name: str
    value: float
    unit: str
    source: str
    section: str | None = None
    seed_line: int | None = None
    note: str | None = None

    @property
    def value_si(self):
        """The parameter in SI units."""
        return to_si(self.value, self.unit)[0]

    @property
    def unit_si(self):
        """The SI unit of :attr:`value_si` (``"rad/s"`` for a parameter printed in deg/s)."""
        return to_si(self.value, self.unit)[1]


@lru_cache(maxsize=16)
def _manifest(folder):
    path = Path(folder) / "SHA256SUMS"
    if not path.is_file():
        raise DataError(f"checksum manifest {path} is missing")
    sums = {}
    for lineno, line in enumerate(path.read_text(encoding="utf-8").splitlines(), start=1):
        if not line.strip():
            continue
        parts = line.split()
        if len(parts) != 2 or len(parts[0]) != 64:
            raise DataError(f"{path}:{lineno}: expected '<sha256>  <path>', got {line!r}")
        sums[parts[1]] = parts[0]
    return sums


def verify_checksum(path, data_dir=None):
    """Read a data file's bytes after checking them against its folder's ``SHA256SUMS``.

    Each first-level folder of the data directory (a source, ``wires``, ``bench``) has its
    own manifest, so adding a source's folder touches no other file.

    Parameters
    ----------
    path : str or Path
        File inside a folder of the data directory.
    data_dir : str or Path, optional
        Data directory; defaults to :data:`DATA_DIR`.

    Returns
    -------
    bytes
        The file's content.
    """
    data_dir = Path(data_dir or DATA_DIR).resolve()
    path = Path(path).resolve()
    try:
        parts = path.relative_to(data_dir).parts
    except ValueError:
        raise DataError(f"{path} is not inside the data directory {data_dir}") from None
    if len(parts) < 2:
        raise DataError(f"{path} must lie in a folder of the data directory {data_dir} (one per source)")
    folder = data_dir / parts[0]
    rel = "/".join(parts[1:])
    sums = _manifest(str(folder))
    if rel not in sums:
        raise DataError(f"{path} is not listed in {folder / 'SHA256SUMS'}")
    if not path.is_file():
        raise DataError(f"data file {path} is missing")
    content = path.read_bytes()
    digest = hashlib.sha256(content).hexdigest()
    if digest != sums[rel]:
        raise DataError(
            f"{path} does not match its checksum (expected {sums[rel]}, got {digest}): "
            "data files are never edited in place; restore it from version control"
        )
    return content


def _number(text, path, lineno, column, *, optional=False):
    text = text.strip()
    if optional and text == "":
        return None
    try:
        value = float(text)
    except ValueError:
        raise DataError(f"{path}:{lineno}: column {column!r} must be a number, got {text!r}") from None
    if not math.isfinite(value):
        raise DataError(f"{path}:{lineno}: column {column!r} must be finite, got {text!r}")
    return value


_MEASUREMENT_COLUMNS = ["id", "quantity", "value_low", "value_high", "unit", "uncertainty",
                        "kind", "section", "seed_line", "method", "conditions"]
_PRINTED_COLUMNS = [*_MEASUREMENT_COLUMNS, "resolution"]
_KINDS = {"measured", "printed", "simulated"}


def digit_resolution(text):
    """Half a unit of the last digit of a printed number: ``"12.4"`` -> 0.05, ``"2.34e-8"`` -> 5e-11.

    The tolerance a printed value carries when the source states none: any value that
    rounds to the printed digits is the printed value.

    Examples
    --------
    >>> digit_resolution("258"), digit_resolution("0.5445"), digit_resolution("2.34e-8")
    (0.5, 5e-05, 5e-11)
    """
    mantissa, _, exponent = text.strip().lower().partition("e")
    decimals = len(mantissa.partition(".")[2])
    return 0.5 * 10.0 ** (int(exponent or 0) - decimals)


def load_printed(name="thesis", data_dir=None):
    """Load a source's printed values ``<name>/printed.csv`` of the data directory.

    The numbers the source prints as its own computations or design values, which the
    errata set beside what the source's formulas and inputs give. Each row carries its
    ``resolution``, half a unit of the last printed digit (stated in the file where the
    digits alone would mislead, such as "≈ 200").

    Parameters
    ----------
    name : str
        Source key: its folder in the data directory (``"thesis"``).
    data_dir : str or Path, optional
        Data directory; defaults to :data:`DATA_DIR`.

    Returns
    -------
    dict of str to Measurement
        Rows (``kind == "printed"``) keyed by their id, in file order.
    """
    path = Path(data_dir or DATA_DIR) / name / "printed.csv"
    return _load_rows(path, name, data_dir, _PRINTED_COLUMNS, {"printed"})


def load_measurements(name="thesis", data_dir=None):
    """Load a measurement table ``<name>/measurements.csv`` of the data directory.

    Parameters
    ----------
    name : str
        Source key: its folder in the data directory (``"thesis"``).
    data_dir : str or Path, optional
        Data directory; defaults to :data:`DATA_DIR`.

    Returns
    -------
    dict of str to Measurement
        Rows keyed by their id, in file order.
    """
    path = Path(data_dir or DATA_DIR) / name / "measurements.csv"
    return _load_rows(path, name, data_dir, _MEASUREMENT_COLUMNS, _KINDS)


def _load_rows(path, name, data_dir, columns, kinds):
    lines = verify_checksum(path, data_dir).decode("utf-8").splitlines()
    rows = {}
    for lineno, rec in _csv_records(lines, columns, path):
        low = _number(rec["value_low"], path, lineno, "value_low")
        high = _number(rec["value_high"], path, lineno, "value_high")
        if high < low:
            raise DataError(f"{path}:{lineno}: value_high ({high}) is below value_low ({low})")
        unc = _number(rec["uncertainty"], path, lineno, "uncertainty", optional=True)
        if rec["kind"] not in kinds:
            raise DataError(f"{path}:{lineno}: kind must be one of {sorted(kinds)}, got {rec['kind']!r}")
        resolution = None
        if "resolution" in rec:
            resolution = _number(rec["resolution"], path, lineno, "resolution", optional=True)
            if resolution is None:
                resolution = digit_resolution(rec["value_low"])
            elif resolution <= 0:
                raise DataError(f"{path}:{lineno}: resolution must be > 0, got {resolution}")
        if rec["unit"] not in _TO_SI:
            raise DataError(f"{path}:{lineno}: unknown unit {rec['unit']!r}")
        if rec["id"] in rows:
            raise DataError(f"{path}:{lineno}: duplicate id {rec['id']!r}")
        rows[rec["id"]] = Measurement(
            id=rec["id"], quantity=rec["quantity"], value_low=low, value_high=high,
            unit=rec["unit"], uncertainty=unc, kind=rec["kind"], source=name,
            section=rec["section"], seed_line=int(_number(rec["seed_line"], path, lineno, "seed_line")),
            method=rec["method"], conditions=rec["conditions"], resolution=resolution,
        )
    return rows


def _csv_rows(lines):
    """Yield (1-based line number, fields) for the non-comment lines of a CSV file."""
    for lineno, line in enumerate(lines, start=1):
        if not line.strip() or line.startswith("#"):
            continue
        yield lineno, next(csv.reader(io.StringIO(line)))


def _csv_records(lines, columns, path):
    """Yield (line number, {column: text}) for a CSV whose first row must be ``columns``.

    Raises DataError naming the file and line for a wrong header, a row with the wrong
    number of fields, or a file without a header.
    """
    header = None
    for lineno, fields in _csv_rows(lines):
        if header is None:
            if fields != columns:
                raise DataError(f"{path}:{lineno}: header must be {','.join(columns)}")
            header = fields
            continue
        if len(fields) != len(header):
            raise DataError(f"{path}:{lineno}: expected {len(header)} columns, got {len(fields)}")
        yield lineno, dict(zip(header, fields))
    if header is None:
        raise DataError(f"{path}: no header row")


def measurement(measurement_id, name="thesis"):
    """One row of a measurement table, by id (raises ``KeyError`` listing the ids)."""
    rows = load_measurements(name)
    if measurement_id not in rows:
        raise KeyError(f"unknown measurement id {measurement_id!r}; known: {', '.join(rows)}")
    return rows[measurement_id]


_PARAMETER_KEYS = {"value", "unit", "source", "section", "seed_line", "note"}


def load_parameter_set(name="thesis", data_dir=None):
    """Load a source's parameter set ``<name>/params.toml`` of the data directory.

    Parameters
    ----------
    name : str
        Source key: its folder in the data directory (``"thesis"``).
    data_dir : str or Path, optional
        Data directory; defaults to :data:`DATA_DIR`.

    Returns
    -------
    dict of str to Parameter
    """
    path = Path(data_dir or DATA_DIR) / name / "params.toml"
    content = verify_checksum(path, data_dir).decode("utf-8")
    try:
        tables = tomllib.loads(content)
    except tomllib.TOMLDecodeError as exc:
        raise DataError(f"{path}: {exc}") from None
    params = {}
    for key, table in tables.items():
        where = f"{path}: [{key}]"
        if not isinstance(table, dict):
            raise DataError(f"{where} must be a table with value and unit")
        unknown = set(table) - _PARAMETER_KEYS
        if unknown or "value" not in table or "unit" not in table or "source" not in table:
            raise DataError(f"{where} needs value, unit and source (allowed keys: "
                            f"{', '.join(sorted(_PARAMETER_KEYS))}); got {', '.join(sorted(table))}")
        value = table["value"]
        if isinstance(value, bool) or not isinstance(value, int | float) or not math.isfinite(value):
            raise DataError(f"{where}: value must be a finite number, got {value!r}")
        if table["unit"] not in _TO_SI:
            raise DataError(f"{where}: unknown unit {table['unit']!r}")
        params[key] = Parameter(name=key, value=float(value), unit=table["unit"],
                                source=table["source"], section=table.get("section"),
                                seed_line=table.get("seed_line"), note=table.get("note"))
    return params


#: Wire tables in the data directory's ``wires/``: name -> file stem. ``iec60228`` is kept as an alias of the
#: enamelled-wire table because the ``design-coil`` command's contract names it; IEC 60228
#: itself specifies cable conductors by cross-section, not winding-wire diameters.
WIRE_TABLES = {"iec60317": "iec60317_grade1", "iec60228": "iec60317_grade1"}

_WIRE_COLUMNS = ["nominal_diameter", "tolerance", "min_increase_grade1", "max_overall_grade1",
                 "status", "provenance"]


@dataclass(frozen=True)
class WireTable:
    """A table of enamelled round wires, in SI (metres), one entry per size.

    ``status`` is ``"verified"`` (read from a public copy of the standard's table) or
    ``"recalled"`` (enamel figures as recalled; see the file's header) for each size.
    """

    name: str
    nominal_diameter: tuple
    tolerance: tuple
    min_overall_diameter: tuple
    max_overall_diameter: tuple
    status: tuple
    provenance: tuple


def load_wire_table(name="iec60317", data_dir=None):
    """Load a wire table from the data directory's ``wires/`` (sizes in mm in the file, metres here).

    Parameters
    ----------
    name : str
        A key of :data:`WIRE_TABLES` (``"iec60317"``; ``"iec60228"`` is an alias).
    data_dir : str or Path, optional
        Data directory; defaults to :data:`DATA_DIR`.

    Returns
    -------
    WireTable
        Sizes sorted by nominal diameter.

    Examples
    --------
    >>> t = load_wire_table("iec60317")
    >>> t.nominal_diameter[9], t.tolerance[9], t.max_overall_diameter[9]
    (0.0002, 3e-06, 0.000226)
    """
    if name not in WIRE_TABLES:
        raise DataError(f"unknown wire table {name!r}; known: {', '.join(WIRE_TABLES)}")
    path = Path(data_dir or DATA_DIR) / "wires" / f"{WIRE_TABLES[name]}.csv"
    lines = verify_checksum(path, data_dir).decode("utf-8").splitlines()
    rows = []
    for lineno, rec in _csv_records(lines, _WIRE_COLUMNS, path):
        d, tol, inc, od = (_number(rec[c], path, lineno, c) for c in _WIRE_COLUMNS[:4])
        if not (d > 0 and 0 <= tol < d and inc > 0 and od >= d + inc):
            raise DataError(f"{path}:{lineno}: inconsistent sizes (need d > 0, 0 <= tolerance < d, "
                            f"increase > 0, overall >= d + increase), got {d}, {tol}, {inc}, {od}")
        if rec["status"] not in ("verified", "recalled"):
            raise DataError(f"{path}:{lineno}: status must be verified or recalled, got {rec['status']!r}")
        rows.append((d, tol, inc, od, rec["status"], rec["provenance"]))
    if not rows:
        raise DataError(f"{path}: no wire sizes")
    rows.sort()
    mm = 1e-3
    return WireTable(
        name=name,
        nominal_diameter=tuple(round(r[0] * mm, 12) for r in rows),
        tolerance=tuple(round(r[1] * mm, 12) for r in rows),
        min_overall_diameter=tuple(round((r[0] + r[2]) * mm, 12) for r in rows),
        max_overall_diameter=tuple(round(r[3] * mm, 12) for r in rows),
        status=tuple(r[4] for r in rows),
        provenance=tuple(r[5] for r in rows),
    )
