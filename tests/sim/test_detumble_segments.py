"""Detumbling in segments: the step rule, and one segment is one run."""

import numpy as np
import pytest
from numpy.testing import assert_array_equal

from magbench.earth import CircularOrbit
from magbench.sim import DETUMBLE_STEPS, detumble_step, simulate_detumble, simulate_detumble_segments

J = np.array([0.0067, 0.042, 0.042])


@pytest.mark.parametrize("speed, largest, expected", [
    (0.0, 1.0, 1.0), (0.2, 1.0, 1.0), (0.2001, 1.0, 0.5), (1.0, 1.0, 0.2), (1.0, 0.15, 0.125),
    (100.0, 1.0, DETUMBLE_STEPS[-1]),
])
def test_the_step_is_the_largest_with_at_most_0_2_rad_per_step(speed, largest, expected):
    assert detumble_step(speed, largest) == expected


def _inputs(members=3, seed=1):
    rng = np.random.default_rng(seed)
    q = rng.normal(size=(members, 4))
    w = rng.normal(size=(members, 3)) * 0.1
    orbit = CircularOrbit(6.871e6, 1.2, 8.0e22)
    return orbit, q / np.linalg.norm(q, axis=-1, keepdims=True), w


def test_one_segment_is_one_run_of_simulate_detumble():
    orbit, q, w = _inputs()
    t, r = simulate_detumble_segments(J, orbit, q, w, 300.0, segment=1700.0, gain=5e4, max_dipole=0.2)
    run = simulate_detumble(J, orbit, q, w, 300.0, step=detumble_step(np.max(np.linalg.norm(w, axis=-1)), 1.0),
                            gain=5e4, max_dipole=0.2)
    assert_array_equal(t, run.time)
    assert_array_equal(r, run.rate)


def test_segments_continue_the_orbit_and_stop_at_the_threshold():
    orbit, q, w = _inputs()
    t, r = simulate_detumble_segments(J, orbit, q, w, 4000.0, segment=200.0, gain=5e4, max_dipole=0.2)
    assert_array_equal(np.diff(t), 1.0)                # records at 1 s across the segment joins
    assert t[-1] == 4000.0
    threshold = 0.9 * float(np.min(np.linalg.norm(w, axis=-1)))
    t2, r2 = simulate_detumble_segments(J, orbit, q, w, 4000.0, segment=200.0, threshold=threshold, gain=5e4,
                                        max_dipole=0.2)
    assert t2[-1] < 4000.0 and np.all(np.any(r2 <= threshold, axis=-1))
    assert_array_equal(r2, r[:, :t2.size])             # stopping early changes nothing before it


@pytest.mark.parametrize("kwargs, match", [
    (dict(duration=0.0), "duration must be > 0"), (dict(segment=-1.0), "segment must be > 0"),
    (dict(threshold=0.0), "threshold must be > 0"), (dict(largest_step=0.0), "largest_step must be > 0"),
])
def test_bad_input(kwargs, match):
    orbit, q, w = _inputs()
    args = dict(duration=100.0) | kwargs
    with pytest.raises(ValueError, match=match):
        simulate_detumble_segments(J, orbit, q, w, args.pop("duration"), gain=5e4, **args)
