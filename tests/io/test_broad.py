"""The BROAD metric against the dataset's published formulas, and the filter on real data."""

import numpy as np
import pytest
from numpy.testing import assert_allclose
from scipy.spatial.transform import Rotation

from magbench.io import broad

TRIALS = broad.available_trials()
needs_data = pytest.mark.skipif(not TRIALS, reason=broad.MISSING_MESSAGE)


def _quatmult(q1, q2):
    # Written out from the Hamilton product, independently of magbench (BROAD's quatmult).
    w1, x1, y1, z1 = q1.T
    w2, x2, y2, z2 = q2.T
    return np.stack([w1 * w2 - x1 * x2 - y1 * y2 - z1 * z2, w1 * x2 + x1 * w2 + y1 * z2 - z1 * y2,
                     w1 * y2 - x1 * z2 + y1 * w2 + z1 * x2, w1 * z2 + x1 * y2 - y1 * x2 + z1 * w2], 1)


def test_inclination_error_matches_broad_formula():
    est = Rotation.random(500, random_state=1).as_quat(scalar_first=True)
    ref = Rotation.random(500, random_state=2).as_quat(scalar_first=True)
    conj = ref * [1, -1, -1, -1]
    diff = _quatmult(est, conj)
    expected_incl = 2 * np.arccos(np.clip(np.sqrt(diff[:, 0] ** 2 + diff[:, 3] ** 2), 0, 1))
    expected_head = 2 * np.arctan(np.abs(diff[:, 3] / diff[:, 0]))
    # arccos near 1 amplifies rounding: 1e-7 rad (2e-5 degrees) is far below any result quoted.
    assert_allclose(broad.inclination_error(est, ref), expected_incl, atol=1e-7)
    assert_allclose(broad.heading_error(est, ref), expected_head, atol=1e-7)


def test_inclination_ignores_heading_offset_and_nan_reference():
    ref = Rotation.random(200, random_state=3)
    tilt = Rotation.from_rotvec(np.tile([0.02, 0.0, 0.0], (200, 1)))
    heading = Rotation.from_rotvec(np.tile([0.0, 0.0, 1.3], (200, 1)))
    est = (heading * tilt * ref).as_quat(scalar_first=True)
    reference = ref.as_quat(scalar_first=True)
    reference[::7] = np.nan
    movement = np.ones(200, bool)
    # A pure 0.02 rad tilt in the Earth frame, whatever the heading offset; NaN rows skipped.
    assert_allclose(broad.inclination_rmse(est, reference, movement), 0.02, rtol=1e-6)


def test_missing_data_is_explained(tmp_path):
    assert broad.available_trials(tmp_path / "nowhere") == []
    with pytest.raises(FileNotFoundError, match="github.com/dlaidig/broad"):
        broad.load_trial("01_undisturbed_slow_rotation_A", directory=tmp_path)


def test_directory_from_environment(monkeypatch, tmp_path):
    monkeypatch.setenv(broad.BROAD_DIR_ENV, str(tmp_path))
    assert broad.broad_directory() == tmp_path


@pytest.mark.broad
@needs_data
@pytest.mark.parametrize("name", TRIALS)
def test_default_filter_on_real_recordings(name):
    trial = broad.load_trial(name)
    assert trial.gyro.shape == trial.accel.shape == (len(trial.movement), 3)
    rmse = {k: np.degrees(v) for k, v in broad.evaluate_trial(trial).items()}
    # The brief's bound for every BROAD trial with default settings (state of the art:
    # 0.6–1.1°); the baselines are several times worse on real motion.
    assert rmse["complementary"] <= 1.5, rmse
    assert rmse["accelerometer"] > 3 * rmse["complementary"], rmse
    assert rmse["gyro"] > 2 * rmse["complementary"], rmse
