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


def test_mockup_loads_turning_about_the_vertical_give_eq_36s_torque():
    """Hanging straight (θ = 0) at heading ψ, coil 1 along (cos ψ, sin ψ, 0): the magnetic
    torque is vertical, −m B0 sin ψ (eq. 36 with one coil, two_coil_torque), and gravity,
    acting on the axis through A, has no torque."""
    from magbench.dynamics import mockup_loads, two_coil_torque

    psi = np.array([0.3, 1.2, 2.5])
    loads = mockup_loads(psi, 0.0, 0.0, 0.05, 1.2, 3e-4, 0.4)
    # atol 1e-18 N·m: rounding of products of order 1e-4 N·m.
    assert_allclose(loads["magnetic_torque"][:, 2], two_coil_torque(psi, 0.4, 0.0, 3e-4), atol=1e-18)
    assert_allclose(loads["magnetic_torque"][:, :2], 0.0, atol=1e-18)
    assert_allclose(loads["gravity_torque"], 0.0, atol=1e-15)
    # Tilted by θ, the weight pulls C back under A: torque −d M g sin θ about the nodal line.
    tilted = mockup_loads(0.0, 0.2, 0.0, 0.05, 1.2, 3e-4, 0.4)
    assert_allclose(tilted["gravity_torque"], [-0.05 * 1.2 * 9.80665 * np.sin(0.2), 0.0, 0.0], rtol=1e-12, atol=1e-18)


def test_mockup_loads_name_bad_input():
    from magbench.dynamics import mockup_loads

    with pytest.raises(ValueError, match="mass"):
        mockup_loads(0.0, 0.0, 0.0, 0.05, -1.0, 3e-4, 0.4)
    with pytest.raises(ValueError, match="cm_offset"):
        mockup_loads(0.0, 0.0, 0.0, -0.05, 1.0, 3e-4, 0.4)
