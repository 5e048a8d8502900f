"""Cosine-law sun sensors: the law itself at chosen angles, its invariance under a common
rotation of the frame, the albedo term, and bad input."""

import numpy as np
import pytest
from numpy.testing import assert_allclose
from scipy.spatial.transform import Rotation

from magbench.hardware import sun_sensor_signals

NORMALS = np.array([[1.0, 0.0, 0.0], [-1.0, 0.0, 0.0], [0.0, 0.0, 1.0]])


def test_the_cosine_law_clipped_at_zero():
    alpha = np.linspace(0.0, 2 * np.pi, 37)
    # the body turned about z by α: +x sees the Sun (along reference x) at angle α, −x opposite it
    r = Rotation.from_euler("z", alpha[:, None]).as_matrix()
    s = sun_sensor_signals(r, NORMALS, [1.0, 0.0, 0.0])
    assert_allclose(s[:, 0], np.maximum(np.cos(alpha), 0.0), rtol=0, atol=1e-15)   # rounding only
    assert_allclose(s[:, 1], np.maximum(-np.cos(alpha), 0.0), rtol=0, atol=1e-15)
    assert_allclose(s[:, 2], 0.0, rtol=0, atol=1e-15)                               # +z is edge-on


def test_a_common_rotation_of_the_frame_changes_nothing():
    rng = np.random.default_rng(0)
    r = Rotation.random(20, random_state=rng).as_matrix()
    q = Rotation.random(random_state=rng).as_matrix()
    sun, earth = np.array([0.0, 0.6, 0.8]), np.array([1.0, 0.0, 0.0])
    one = sun_sensor_signals(r, NORMALS, sun, earth=earth, albedo_ratio=0.3)
    two = sun_sensor_signals(q @ r, NORMALS, q @ sun, earth=q @ earth, albedo_ratio=0.3)
    assert_allclose(two, one, rtol=0, atol=1e-14)   # a few roundings of 3-term dot products


def test_albedo_adds_the_same_law_towards_the_earth():
    r = np.eye(3)
    sun, earth = np.array([0.0, 0.0, 1.0]), np.array([1.0, 0.0, 0.0])
    s = sun_sensor_signals(r, NORMALS, sun, earth=earth, albedo_ratio=0.4)
    assert_allclose(s, [0.4, 0.0, 1.0], rtol=0, atol=0)       # exact: cosines of 0 and π/2
    assert_allclose(sun_sensor_signals(r, NORMALS, sun), [0.0, 0.0, 1.0], rtol=0, atol=0)


@pytest.mark.parametrize("name, call", [
    ("rotation", lambda: sun_sensor_signals(np.eye(2), NORMALS, [1.0, 0.0, 0.0])),
    ("normals", lambda: sun_sensor_signals(np.eye(3), [1.0, 0.0], [1.0, 0.0, 0.0])),
    ("sun", lambda: sun_sensor_signals(np.eye(3), NORMALS, [2.0, 0.0, 0.0])),
    ("albedo_ratio", lambda: sun_sensor_signals(np.eye(3), NORMALS, [1.0, 0.0, 0.0], earth=[0.0, 0.0, 1.0],
                                                albedo_ratio=-1.0)),
])
def test_bad_input_is_refused_by_name(name, call):
    with pytest.raises(ValueError, match=name):
        call()
