"""Readers with checksums: parameter sets, measurement and printed-value tables, wire
tables, bench logs, the BROAD recordings, the TNS-0 tables and peer libraries' runs.

Everything the library reads from a file comes through here, so the physics families
never touch a file (the import-layer contract in ``pyproject.toml`` forbids it).
"""

from .data import (DATA_DIR, WIRE_TABLES, DataError, Measurement, Parameter, WireTable, digit_resolution, load_measurements,
                   load_parameter_set, load_printed, load_wire_table, measurement, to_si, verify_checksum)
from .peers import BasiliskDetumbleRuns, load_basilisk_detumble_runs
from .tns0 import (TNS0_SOURCES, ColumnMeaning, Session, SessionTable, TableCell, load_sessions, load_table1,
                   load_table1_printed, load_table2, load_table2_printed, load_tns0_parameters, table1_hours)

__all__ = ["DATA_DIR", "WIRE_TABLES", "DataError", "Measurement", "Parameter", "WireTable", "digit_resolution", "load_measurements",
           "load_parameter_set", "load_printed", "load_wire_table", "measurement", "to_si", "verify_checksum",
           "BasiliskDetumbleRuns", "load_basilisk_detumble_runs", "TNS0_SOURCES", "ColumnMeaning", "Session", "SessionTable", "TableCell", "load_sessions", "load_table1",
           "load_table1_printed", "load_table2", "load_table2_printed", "load_tns0_parameters", "table1_hours"]
