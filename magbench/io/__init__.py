"""Readers with checksums: parameter sets, measurement and printed-value tables, wire
tables, bench logs and the BROAD recordings.

Everything the library reads from a file comes through here, so the physics families
never touch a file (the import-layer contract in ``pyproject.toml`` forbids it).
"""

from .data import (DATA_DIR, WIRE_TABLES, DataError, Measurement, Parameter, WireTable, digit_resolution, load_measurements,
                   load_parameter_set, load_printed, load_wire_table, measurement, to_si, verify_checksum)

__all__ = ["DATA_DIR", "WIRE_TABLES", "DataError", "Measurement", "Parameter", "WireTable", "digit_resolution", "load_measurements",
           "load_parameter_set", "load_printed", "load_wire_table", "measurement", "to_si", "verify_checksum"]
