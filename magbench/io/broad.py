r"""Real IMU recordings with optical ground truth: the BROAD dataset.

BROAD (Berlin Robust Orientation Estimation Assessment Dataset; Laidig, Caruso,
Cereatti & Seel 2021, Data 6(7):72, doi:10.3390/data6070072, CC BY 4.0) holds 39 trials
of a handheld IMU (gyro, accelerometer, magnetometer at about 286 Hz) with the
orientation measured by optical motion capture. magbench does not ship it: point the
environment variable ``MAGBENCH_BROAD_DIR`` at a folder with the trials' ``.mat`` files
(and ``trials.json``) from https://github.com/dlaidig/broad (folder ``data_mat``);
the default is ``<repository>/../shared/external/broad``.

The error metric replicates the dataset's own evaluation code
(``example_code/broad_utils.py`` in that repository, functions
``calculateErrorQuatEarth``, ``calculateInclinationError``, ``calculateRMSE``): the
error quaternion is taken in the Earth frame, :math:`q_e = q_{est}\otimes q_{ref}^{-1}`,
its inclination part is :math:`2\arccos\sqrt{w_e^2 + z_e^2}` (independent of any heading
offset, so heading-free estimates are scored fairly), and the RMSE runs over the samples
the dataset marks as movement, ignoring samples where the optical reference is missing
(NaN). The recordings are already synchronised and aligned to an ENU frame by the
dataset's authors; no further alignment is applied, as in their code.
"""

import json
import os
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from .. import estimation
from ..rotations import hamilton_product

__all__ = [
    "BROAD_DIR_ENV",
    "MISSING_MESSAGE",
    "BroadTrial",
    "broad_directory",
    "available_trials",
    "load_trial",
    "trial_groups",
    "error_quaternion_earth",
    "inclination_error",
    "heading_error",
    "inclination_rmse",
    "evaluate_trial",
]

#: Environment variable naming the folder that holds the BROAD ``.mat`` files.
BROAD_DIR_ENV = "MAGBENCH_BROAD_DIR"

#: What to tell a reader when the recordings are absent.
MISSING_MESSAGE = (
    "BROAD recordings not found: download the .mat files (and trials.json) from the "
    "folder data_mat of https://github.com/dlaidig/broad (CC BY 4.0, Laidig et al. 2021) "
    f"and set ${BROAD_DIR_ENV} to that folder (default: shared/external/broad beside the "
    "repository's folder)."
)


def broad_directory():
    """Folder of the BROAD recordings: ``$MAGBENCH_BROAD_DIR`` or the default beside the repository.

    A relative ``$MAGBENCH_BROAD_DIR`` is taken from the repository's folder, not from the
    current one: pytest runs at the root and the book's kernels in ``book/``, and both
    must read the same recordings.
    """
    repository = Path(__file__).resolve().parents[2]
    configured = os.environ.get(BROAD_DIR_ENV)
    if configured:
        return (repository / Path(configured).expanduser()).resolve()
    return repository.parent / "shared" / "external" / "broad"


def available_trials(directory=None):
    """Sorted names of the trials whose ``.mat`` file is present (empty if none)."""
    folder = broad_directory() if directory is None else Path(directory)
    if not folder.is_dir():
        return []
    return sorted(p.stem for p in folder.glob("*.mat"))


def trial_groups(directory=None):
    """``{trial name: description}`` from ``trials.json``, or ``{}`` when it is absent."""
    folder = broad_directory() if directory is None else Path(directory)
    path = folder / "trials.json"
    if not path.is_file():
        return {}
    info = json.loads(path.read_text(encoding="utf-8"))
    return {name: entry["description"] for name, entry in info["trials"].items()}


@dataclass(frozen=True)
class BroadTrial:
    """One BROAD trial in SI units (sensor frame for the IMU, ENU for the reference)."""

    name: str
    gyro: np.ndarray            #: angular rate [rad/s], (N, 3)
    accel: np.ndarray           #: specific force [m/s²], (N, 3)
    mag: np.ndarray             #: magnetic flux density [T], (N, 3)
    reference: np.ndarray       #: optical orientation, unit quaternions (w, x, y, z), NaN where missing
    movement: np.ndarray        #: True in the movement phases the metric uses, (N,)
    sampling_rate: float        #: [Hz]

    @property
    def dt(self):
        """Sample interval [s]."""
        return 1.0 / self.sampling_rate

    @property
    def duration(self):
        """Length of the record [s]."""
        return len(self.gyro) / self.sampling_rate


def load_trial(name, directory=None):
    """Load one trial (``name`` without ``.mat``); raises FileNotFoundError with :data:`MISSING_MESSAGE`."""
    from scipy.io import loadmat   # only here: importing magbench.io.broad must stay cheap

    folder = broad_directory() if directory is None else Path(directory)
    path = folder / f"{name}.mat"
    if not path.is_file():
        known = available_trials(folder)
        hint = f" Available here: {', '.join(known)}." if known else ""
        raise FileNotFoundError(f"{path} does not exist. {MISSING_MESSAGE}{hint}")
    data = loadmat(path)
    return BroadTrial(
        name=name,
        gyro=np.ascontiguousarray(data["imu_gyr"], dtype=float),
        accel=np.ascontiguousarray(data["imu_acc"], dtype=float),
        mag=np.ascontiguousarray(data["imu_mag"], dtype=float) * 1e-6,
        reference=np.ascontiguousarray(data["opt_quat"], dtype=float),
        movement=data["movement"].ravel().astype(bool),
        sampling_rate=float(data["sampling_rate"].item()),
    )


def _unit(q):
    q = np.asarray(q, dtype=float)
    return q / np.linalg.norm(q, axis=-1, keepdims=True)


def error_quaternion_earth(estimate, reference):
    r"""Error quaternion in the Earth frame, :math:`q_{est}\otimes q_{ref}^{-1}` (w, x, y, z).

    BROAD's ``calculateErrorQuatEarth``; rows where the reference is NaN stay NaN.
    """
    est, ref = _unit(estimate), _unit(reference)
    valid = np.all(np.isfinite(ref), axis=-1) & np.all(np.isfinite(est), axis=-1)
    out = np.full(np.broadcast_shapes(est.shape, ref.shape), np.nan)
    est_v = np.broadcast_to(est, out.shape)[valid]
    ref_v = np.broadcast_to(ref, out.shape)[valid]
    # q_est ⊗ conj(q_ref), as BROAD's quatmult(imu_quat, invquat(opt_quat)).
    product = hamilton_product(est_v, ref_v * [1.0, -1.0, -1.0, -1.0])
    out[valid] = product / np.linalg.norm(product, axis=-1, keepdims=True)
    return out


def inclination_error(estimate, reference):
    r"""Inclination error [rad]: :math:`2\arccos\sqrt{w_e^2+z_e^2}` (BROAD's ``calculateInclinationError``)."""
    err = error_quaternion_earth(estimate, reference)
    return 2.0 * np.arccos(np.clip(np.sqrt(err[..., 0] ** 2 + err[..., 3] ** 2), 0.0, 1.0))


def heading_error(estimate, reference):
    r"""Heading error [rad]: :math:`2\arctan|z_e/w_e|` (BROAD's ``calculateHeadingError``)."""
    err = error_quaternion_earth(estimate, reference)
    with np.errstate(divide="ignore"):
        return 2.0 * np.arctan(np.abs(err[..., 3] / err[..., 0]))


def inclination_rmse(estimate, reference, movement):
    """Inclination RMSE [rad] over the movement samples, NaN references ignored (BROAD's ``calculateRMSE``)."""
    mask = np.asarray(movement, dtype=bool)
    err = inclination_error(estimate, reference)[mask]
    return float(np.sqrt(np.nanmean(err**2)))


def evaluate_trial(trial, *, tau=3.0, order=2, rest_bias=True):
    """Inclination RMSE [rad] of :func:`~magbench.estimation.complementary_tilt`, of
    :func:`~magbench.estimation.offline_tilt` and of two baselines.

    Returns a dict with ``complementary`` (the filter with these options), ``offline``
    (:func:`~magbench.estimation.offline_tilt` with its defaults),
    ``accelerometer`` (:func:`~magbench.estimation.accelerometer_tilt` alone) and ``gyro``
    (:func:`~magbench.estimation.strapdown_orientation` of the raw gyro, started from the
    first accelerometer sample's tilt).
    """
    filtered = estimation.complementary_tilt(trial.gyro, trial.accel, trial.dt, tau=tau,
                                             order=order, rest_bias=rest_bias)
    accel_only = estimation.accelerometer_tilt(trial.accel)
    gyro_only = estimation.strapdown_orientation(trial.gyro, trial.dt, accel_only[0])
    return {
        "complementary": inclination_rmse(filtered, trial.reference, trial.movement),
        "offline": inclination_rmse(estimation.offline_tilt(trial.gyro, trial.accel, trial.dt),
                                    trial.reference, trial.movement),
        "accelerometer": inclination_rmse(accel_only, trial.reference, trial.movement),
        "gyro": inclination_rmse(gyro_only, trial.reference, trial.movement),
    }
