"""Peer libraries' numbers, as data: runs that another library made of the book's cases.

``peers/basilisk_detumble.csv``: 18 detumbling runs of Basilisk 2.12.1 of chapter 5's
envelope case (the set-up in the file's header and in ``shared/reference/bdot_triad.md``
§6.1). Read here with the folder's checksum, like every data file; the chapter and the
tests take them from :func:`load_basilisk_detumble_runs` instead of typing them.
"""

from dataclasses import dataclass
from pathlib import Path

import numpy as np

from .data import DATA_DIR, _csv_records, _number, verify_checksum

__all__ = ["BasiliskDetumbleRuns", "load_basilisk_detumble_runs"]

_COLUMNS = ("run", "sigma_1", "sigma_2", "sigma_3", "omega_x", "omega_y", "omega_z", "detumble_time", "rate_12000s")


@dataclass(frozen=True)
class BasiliskDetumbleRuns:
    """Basilisk's detumbling runs, one row per run.

    Attributes
    ----------
    attitude_mrp : ndarray, shape (n, 3)
        σ_BN, the modified Rodrigues parameters of the start (body → inertial) [-].
    initial_rate : ndarray, shape (n, 3)
        ω₀ in body axes [rad/s].
    detumble_time : ndarray, shape (n,)
        First 1 s log sample with |ω| ≤ 0.5 °/s [s].
    late_rate : ndarray, shape (n,)
        |ω| at 12 000 s [rad/s].
    path : Path
        The file read.
    """

    attitude_mrp: np.ndarray
    initial_rate: np.ndarray
    detumble_time: np.ndarray
    late_rate: np.ndarray
    path: Path

    def attitude_quaternion(self):
        """The starts as unit quaternions, scalar first (q = ((1 − σ²)/(1 + σ²), 2σ/(1 + σ²))) [-]."""
        s2 = np.sum(self.attitude_mrp**2, axis=-1, keepdims=True)
        return np.concatenate([(1 - s2) / (1 + s2), 2 * self.attitude_mrp / (1 + s2)], axis=-1)


def load_basilisk_detumble_runs(data_dir=None):
    """Basilisk 2.12.1's 18 detumbling runs of chapter 5's envelope case (checksum-verified).

    Parameters
    ----------
    data_dir : str or Path, optional
        Data directory; defaults to :data:`magbench.io.DATA_DIR`.

    Returns
    -------
    BasiliskDetumbleRuns
        The runs, in SI (the file's deg/s column converted to rad/s).

    Raises
    ------
    DataError
        When the file fails its checksum, its header is not the expected columns or a cell
        is not a finite number (the message names the file, line and column).
    """
    path = Path(data_dir or DATA_DIR) / "peers" / "basilisk_detumble.csv"
    lines = verify_checksum(path, data_dir).decode("utf-8").splitlines()
    rows = [[_number(rec[column], path, lineno, column) for column in _COLUMNS[1:]]
            for lineno, rec in _csv_records(lines, list(_COLUMNS), path)]
    table = np.array(rows)
    return BasiliskDetumbleRuns(attitude_mrp=table[:, 0:3], initial_rate=table[:, 3:6], detumble_time=table[:, 6],
                                late_rate=np.radians(table[:, 7]), path=path)
