"""magbench.dynamics.pendulum: the one mock-up plant (tests of its other functions are in
tests/test_ch04_dynamics.py)."""

import numpy as np
import pytest
from numpy.testing import assert_allclose

from magbench import sim
from magbench.sim import bench
from magbench.dynamics import Mockup, mockup_rhs, pendulum_rhs, two_coil_rhs


def test_the_thread_adds_its_torsion():
    plant = Mockup(0.005, 1e-4, thread_stiffness=2e-5, thread_neutral_angle=0.1)
    free = Mockup(0.005, 1e-4)
    state = np.array([0.4, 0.01])
    diff = mockup_rhs(0.0, state, (0.3, -0.2), plant) - mockup_rhs(0.0, state, (0.3, -0.2), free)
    assert_allclose(diff, [0.0, -2e-5 * 0.3 / 0.005], rtol=1e-12)


def test_the_right_hand_sides_are_one_equation():
    plant = Mockup(0.005, 1e-4, 0.3, -0.2)
    state = np.array([[0.4, -1.0], [0.01, 0.0]])
    assert np.array_equal(two_coil_rhs(0.0, state, plant), mockup_rhs(0.0, state, (0.3, -0.2), plant))
    assert np.array_equal(pendulum_rhs(0.0, state, plant), mockup_rhs(0.0, state, (0.3, 0.0), plant))


def test_loops_carry_the_plant():
    loop = sim.PidLoop(0.005, 3.3e-4, 0.1, 0.001, 2.0)
    assert loop.plant == Mockup(0.005, 3.3e-4)
    setup = bench.BenchSetup(0.005, 3.3e-4, (55.0, 55.0), 240, 0.1, 12.0, 0.1, 0.001, 2.0, 0.98,
                             thread_stiffness=1e-6, thread_neutral_angle=0.2)
    assert setup.plant == Mockup(0.005, 3.3e-4, thread_stiffness=1e-6, thread_neutral_angle=0.2)


@pytest.mark.parametrize("kwargs, name", [({"thread_stiffness": -1.0}, "thread_stiffness"),
                                          ({"thread_neutral_angle": np.nan}, "thread_neutral_angle")])
def test_bad_thread(kwargs, name):
    with pytest.raises(ValueError, match=name):
        Mockup(0.005, 1e-4, **kwargs)
