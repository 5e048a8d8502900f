"""offline_tilt on the BROAD recordings: against the peer vqf.offlineVQF (Laidig & Seel's
reference implementation) and against the targets of issue 14.

Every test skips with BROAD's download instructions when the recordings are absent, and
the peer tests skip when vqf is not installed.
"""

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from magbench import estimation
from magbench.io import broad

TRIALS = broad.available_trials()
needs_data = pytest.mark.skipif(not TRIALS, reason=broad.MISSING_MESSAGE)


def _vqf():
    return pytest.importorskip("vqf")


def _up(q):
    return Rotation.from_quat(q, scalar_first=True).inv().apply([0.0, 0.0, 1.0])


@pytest.mark.broad
@needs_data
@pytest.mark.parametrize("name", TRIALS)
def test_offline_tilt_agrees_with_vqf_offline(name):
    vqf = _vqf()
    trial = broad.load_trial(name)
    ours = estimation.offline_tilt(trial.gyro, trial.accel, trial.dt)
    peer = vqf.offlineVQF(np.ascontiguousarray(trial.gyro), np.ascontiguousarray(trial.accel), None,
                          trial.dt)["quat6D"]
    # Same structure (gyro integral, zero-phase 2nd-order Butterworth, tau 3 s) but VQF's
    # bias is a forward/backward Kalman estimate that also learns during motion, ours one
    # constant from the rest periods, and the filters' ends differ. Measured: at most 0.04°
    # apart on any sample and 0.0005° apart in RMSE; the tolerances leave room for rounding
    # across platforms but not for a different filter (the causal one is 0.03-0.38° worse in RMSE).
    gap = np.degrees(np.arccos(np.clip(np.sum(_up(ours) * _up(peer), axis=1), -1.0, 1.0)))
    assert gap.max() < 0.1, gap.max()
    ours_rmse = np.degrees(broad.inclination_rmse(ours, trial.reference, trial.movement))
    peer_rmse = np.degrees(broad.inclination_rmse(peer, trial.reference, trial.movement))
    assert abs(ours_rmse - peer_rmse) < 0.005, (ours_rmse, peer_rmse)


@pytest.mark.broad
@needs_data
def test_offline_tilt_meets_the_targets_on_every_available_trial():
    # Issue 14's targets with default settings: every trial at most 1.0°, the mean below
    # 0.53° (vqf.offlineVQF: 0.533° mean, 0.99° max on 30 public trials). The mean target is
    # only meaningful over many trials; with fewer than 10 present only the per-trial one runs.
    rmse = {}
    for name in TRIALS:
        trial = broad.load_trial(name)
        q = estimation.offline_tilt(trial.gyro, trial.accel, trial.dt)
        rmse[name] = np.degrees(broad.inclination_rmse(q, trial.reference, trial.movement))
    worst = max(rmse, key=rmse.get)
    assert rmse[worst] <= 1.0, (worst, rmse[worst])
    if len(rmse) >= 10:
        assert np.mean(list(rmse.values())) < 0.53, rmse


@pytest.mark.broad
@needs_data
def test_offline_beats_causal_on_every_available_trial():
    # Using the future can only help a smoother whose forward half is the causal filter: on
    # each trial the offline RMSE is below complementary_tilt's (measured 0.03-0.38° lower).
    for name in TRIALS:
        trial = broad.load_trial(name)
        rmse = broad.evaluate_trial(trial)
        assert rmse["offline"] < rmse["complementary"], (name, rmse)


@pytest.mark.broad
@needs_data
def test_timing_diagnostic_is_the_metric_at_zero_shift_and_whole_sample_shifts_are_index_shifts():
    # The figure's interpolation must not move the metric: at s = 0 it is BROAD's RMSE, and
    # at s = 1 it is the estimate one index later (no interpolation between samples then).
    from magbench import figures

    data = figures.compute("ch04-offline-timing", earliest_shift=0.0, latest_shift=1.0, shift_step=1.0)
    trial = broad.load_trial(TRIALS[0])
    q = estimation.offline_tilt(trial.gyro, trial.accel, trial.dt)
    at = data.series[0].columns["trial_0"][1]
    # 1e-12 rad: slerp at the nodes returns the node's rotation up to rounding.
    np.testing.assert_allclose(at[0], broad.inclination_rmse(q, trial.reference, trial.movement), atol=1e-12)
    later = np.concatenate([q[1:], q[-1:]])      # the last sample is held (clipped), as in the figure
    np.testing.assert_allclose(at[1], broad.inclination_rmse(later, trial.reference, trial.movement), atol=1e-12)
