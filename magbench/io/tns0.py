"""Readers of the TNS-0 data (``data/tns0/``): Tables 1 and 2 as printed and as interpreted,
the session time stamps, the parameter set and the printed values.

TNS-0 preprint (Ilyin et al., Keldysh IAM preprint 2006-018), Tables 1 and 2 and the session
headings. Every file is checksummed (:func:`magbench.io.verify_checksum`) before it is read;
a malformed file raises :class:`magbench.io.DataError` naming the file, the line and the
column. The printed tables keep every cell as extracted (a lost cell stays missing); what each
column means is a separate, labelled interpretation (ours, with a confidence per column).
"""

import math
from dataclasses import dataclass
from datetime import datetime
from pathlib import Path

import numpy as np

from .data import DATA_DIR, DataError, _csv_records, _number, load_parameter_set, to_si, verify_checksum

__all__ = ["TableCell", "ColumnMeaning", "SessionTable", "Session", "TNS0_SOURCES", "load_table1_printed",
           "load_table1", "load_table2_printed", "load_table2", "load_sessions", "load_tns0_parameters",
           "table1_hours"]

#: The provenance a TNS-0 parameter may carry (``data/tns0/params.toml``).
TNS0_SOURCES = ("tns0", "external", "ours")

_STATUSES = ("number", "dash", "lost")
_CONFIDENCE = ("high", "medium", "low")


@dataclass(frozen=True)
class TableCell:
    """One cell of a printed table, exactly as extracted.

    ``text`` is the cell as printed (``"-"`` for a dash, ``""`` for a lost cell); ``value``
    is its number or NaN; ``seed_line`` is the 1-based line of the seed text (``None`` for
    a lost cell).
    """

    row: int
    position: int
    text: str
    seed_line: int | None
    status: str

    @property
    def value(self):
        """The printed number, NaN for a dash or a lost cell."""
        return float(self.text) if self.status == "number" else math.nan


@dataclass(frozen=True)
class ColumnMeaning:
    """Our interpretation of one printed column: quantity, SI unit, where, how sure, why."""

    quantity: str
    unit: str
    position: int
    confidence: str
    inference: str
    row1_position: int | None = None


@dataclass(frozen=True)
class SessionTable:
    """A fitted table, interpreted: one array per quantity (rows = sessions), SI, NaN = not given.

    ``values[q]`` has one entry per table row; ``meaning[q]`` says how the column was read.
    """

    session: np.ndarray
    values: dict
    meaning: dict

    def __getattr__(self, name):
        values = self.__dict__.get("values", {})
        if name in values:
            return values[name]
        raise AttributeError(f"{type(self).__name__!r} has no quantity {name!r}; known: {', '.join(values)}")


@dataclass(frozen=True)
class Session:
    """A session heading as printed, its parsed time (zone unknown) and its resolution."""

    session: int
    printed: str
    figure: int
    seed_line: int
    time: datetime
    resolution_hours: float


def _dir(data_dir):
    return Path(data_dir or DATA_DIR) / "tns0"


def _int(text, path, lineno, column, *, optional=False):
    value = _number(text, path, lineno, column, optional=optional)
    if value is None:
        return None
    if value != int(value):
        raise DataError(f"{path}:{lineno}: column {column!r} must be a whole number, got {text!r}")
    return int(value)


def _lines(path, data_dir):
    return verify_checksum(path, data_dir).decode("utf-8").splitlines()


def _cell(rec, path, lineno, row):
    position = _int(rec["position"], path, lineno, "position")
    status = rec.get("status")
    text = rec["text"].strip()
    if status is None:
        status = "dash" if text == "-" else "number"
    if status not in _STATUSES:
        raise DataError(f"{path}:{lineno}: column 'status' must be one of {', '.join(_STATUSES)}, got {status!r}")
    seed_line = _int(rec["seed_line"], path, lineno, "seed_line", optional=True)
    if status == "number":
        _number(text, path, lineno, "text")
    elif status == "dash" and text != "-":
        raise DataError(f"{path}:{lineno}: column 'text' must be '-' for a dash cell, got {text!r}")
    elif status == "lost" and (text or seed_line is not None):
        raise DataError(f"{path}:{lineno}: a lost cell has empty 'text' and 'seed_line', got {text!r}, {seed_line!r}")
    if status != "lost" and (seed_line is None or seed_line < 1):
        raise DataError(f"{path}:{lineno}: column 'seed_line' must be a line number >= 1, got {rec['seed_line']!r}")
    return TableCell(row=row, position=position, text=text, seed_line=seed_line, status=status)


def load_table1_printed(data_dir=None):
    """TNS-0 Table 1 as printed: every cell as extracted, in row and position order.

    Parameters
    ----------
    data_dir : str or Path, optional
        Data directory; defaults to :data:`magbench.io.DATA_DIR`.

    Returns
    -------
    tuple of TableCell
        7 rows × 9 positions; row 1's ninth cell is lost (``status == "lost"``).
    """
    path = _dir(data_dir) / "table1_printed.csv"
    cells = []
    for lineno, rec in _csv_records(_lines(path, data_dir), ["row", "position", "text", "seed_line", "status"], path):
        row = _int(rec["row"], path, lineno, "row")
        cells.append(_cell(rec, path, lineno, row))
    seen = {(c.row, c.position) for c in cells}
    if len(seen) != len(cells):
        raise DataError(f"{path}: duplicate (row, position) cells")
    rows = sorted({c.row for c in cells})
    positions = sorted({c.position for c in cells})
    if seen != {(r, p) for r in rows for p in positions}:
        raise DataError(f"{path}: every row must list every position {positions} (a lost cell as status 'lost')")
    return tuple(sorted(cells, key=lambda c: (c.row, c.position)))


def _meanings(path, data_dir, columns):
    meaning = {}
    for lineno, rec in _csv_records(_lines(path, data_dir), columns, path):
        if rec["confidence"] not in _CONFIDENCE:
            raise DataError(f"{path}:{lineno}: column 'confidence' must be one of {', '.join(_CONFIDENCE)}, "
                            f"got {rec['confidence']!r}")
        try:
            to_si(1.0, rec["unit"])
        except DataError:
            raise DataError(f"{path}:{lineno}: column 'unit' has an unknown unit {rec['unit']!r}") from None
        if rec["quantity"] in meaning:
            raise DataError(f"{path}:{lineno}: duplicate quantity {rec['quantity']!r}")
        row1 = _int(rec["row1_position"], path, lineno, "row1_position", optional=True) \
            if "row1_position" in rec else None
        meaning[rec["quantity"]] = ColumnMeaning(
            quantity=rec["quantity"], unit=rec["unit"], position=_int(rec["position"], path, lineno, "position"),
            confidence=rec["confidence"], inference=rec["inference"], row1_position=row1)
    return meaning


def load_table1(data_dir=None):
    """TNS-0 Table 1 interpreted: one array per quantity over the seven sessions, SI.

    Parameters
    ----------
    data_dir : str or Path, optional
        Data directory; defaults to :data:`magbench.io.DATA_DIR`.

    Returns
    -------
    SessionTable
        ``angular_momentum`` [kg·m²/s], ``nutation`` [rad], ``phase_a``, ``phase_b`` [rad],
        ``start_time`` [s], ``sun_angle``, ``earth_polar_angle``, ``earth_azimuth`` [rad],
        ``albedo_ratio`` [1], each of shape (7,); NaN where the table gives no number (row 1's
        lost cell, its dashes). The interpretation (``meaning``) is ours: see
        ``data/tns0/table1_interpretation.csv``.
    """
    cells = load_table1_printed(data_dir)
    path = _dir(data_dir) / "table1_interpretation.csv"
    meaning = _meanings(path, data_dir, ["quantity", "unit", "position", "row1_position", "confidence", "inference"])
    by_key = {(c.row, c.position): c for c in cells}
    rows = sorted({c.row for c in cells})
    values = {}
    for q, m in meaning.items():
        column = []
        for r in rows:
            pos = m.row1_position if r == 1 else m.position
            column.append(math.nan if pos is None else by_key[(r, pos)].value)
        values[q] = np.array(column) * to_si(1.0, m.unit)[0]
    return SessionTable(session=np.array(rows), values=values, meaning=meaning)


def load_table2_printed(data_dir=None):
    """TNS-0 Table 2 as printed: the five cells of the one-orbit model, as extracted.

    Parameters
    ----------
    data_dir : str or Path, optional
        Data directory; defaults to :data:`magbench.io.DATA_DIR`.

    Returns
    -------
    tuple of TableCell
        Five cells (row 1), in position order.
    """
    path = _dir(data_dir) / "table2_printed.csv"
    cells = [_cell(rec, path, lineno, 1)
             for lineno, rec in _csv_records(_lines(path, data_dir), ["position", "text", "seed_line"], path)]
    return tuple(sorted(cells, key=lambda c: c.position))


def load_table2(data_dir=None):
    """TNS-0 Table 2 interpreted: the one-orbit model's constants, SI.

    Parameters
    ----------
    data_dir : str or Path, optional
        Data directory; defaults to :data:`magbench.io.DATA_DIR`.

    Returns
    -------
    SessionTable
        One session (8, the one-orbit data of 02.06.05): ``angular_momentum`` [kg·m²/s],
        ``nutation`` (angle between B and the symmetry axis) [rad], ``phase_a``, ``phase_b``
        [rad], ``albedo_ratio`` [1], each of shape (1,).
    """
    cells = {c.position: c for c in load_table2_printed(data_dir)}
    path = _dir(data_dir) / "table2_interpretation.csv"
    meaning = _meanings(path, data_dir, ["quantity", "unit", "position", "confidence", "inference"])
    values = {}
    for q, m in meaning.items():
        if m.position not in cells:
            raise DataError(f"{path}: quantity {q!r} names position {m.position}, which table2_printed.csv lacks")
        values[q] = np.array([cells[m.position].value]) * to_si(1.0, m.unit)[0]
    return SessionTable(session=np.array([8]), values=values, meaning=meaning)


def _parse_stamp(text, path, lineno):
    for fmt, resolution in (("%y-%m-%d, %H:%M", 1.0 / 60.0), ("%d.%m.%y", 24.0)):
        try:
            return datetime.strptime(text, fmt), resolution
        except ValueError:
            continue
    raise DataError(f"{path}:{lineno}: column 'printed' must read 'YY-MM-DD, HH:MM' or 'DD.MM.YY', got {text!r}")


def load_sessions(data_dir=None):
    """The TNS-0 session stamps as printed, parsed (time zone unknown).

    Parameters
    ----------
    data_dir : str or Path, optional
        Data directory; defaults to :data:`magbench.io.DATA_DIR`.

    Returns
    -------
    tuple of Session
        Sessions 1–7 (Table 1, stamps to the minute) and 8 (the one-orbit data of Table 2, a
        date only: its time is taken as 00:00 and ``resolution_hours`` is 24).
    """
    path = _dir(data_dir) / "sessions.csv"
    out = []
    for lineno, rec in _csv_records(_lines(path, data_dir), ["session", "printed", "figure", "seed_line"], path):
        time, resolution = _parse_stamp(rec["printed"], path, lineno)
        out.append(Session(session=_int(rec["session"], path, lineno, "session"), printed=rec["printed"],
                           figure=_int(rec["figure"], path, lineno, "figure"),
                           seed_line=_int(rec["seed_line"], path, lineno, "seed_line"), time=time,
                           resolution_hours=resolution))
    if [s.session for s in out] != list(range(1, len(out) + 1)):
        raise DataError(f"{path}: sessions must be numbered 1, 2, ... in order")
    return tuple(out)


def table1_hours(data_dir=None):
    """Hours since the first session of each Table 1 session (the abscissa of TNS-0 Fig. 14).

    Parameters
    ----------
    data_dir : str or Path, optional
        Data directory; defaults to :data:`magbench.io.DATA_DIR`.

    Returns
    -------
    ndarray, shape (7,)
        Hours [h] from the printed stamps (minute resolution; the unknown time zone cancels).
    """
    sessions = [s for s in load_sessions(data_dir) if s.resolution_hours < 1.0]
    first = sessions[0].time
    return np.array([(s.time - first).total_seconds() / 3600.0 for s in sessions])


def load_tns0_parameters(data_dir=None):
    """The TNS-0 parameter set, each value's source checked to be tns0, external or ours.

    Parameters
    ----------
    data_dir : str or Path, optional
        Data directory; defaults to :data:`magbench.io.DATA_DIR`.

    Returns
    -------
    dict of str to Parameter
        As :func:`magbench.io.load_parameter_set` (``value_si`` in SI).
    """
    params = load_parameter_set("tns0", data_dir)
    path = _dir(data_dir) / "params.toml"
    for key, p in params.items():
        if p.source not in TNS0_SOURCES:
            raise DataError(f"{path}: [{key}] source must be one of {', '.join(TNS0_SOURCES)}, got {p.source!r}")
        if p.source != "tns0" and not p.note:
            raise DataError(f"{path}: [{key}] is {p.source}: it needs a note saying where it comes from")
    return params
