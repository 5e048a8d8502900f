"""The sampled PID loop's output grid (magbench.sim.pid_loop.simulate_pid)."""

import numpy as np
import pytest
from numpy.testing import assert_allclose
from scipy.integrate import solve_ivp

from magbench import sim
from magbench.sim.pid_loop import _held_command_rhs

J, B0 = 0.005, 3.14e-4          # the mock-up's inertia [kg m²] and design field [T] (thesis §4)


@pytest.mark.parametrize("dt", [0.02, 0.04, 0.03, 0.07])
def test_output_grid_does_not_depend_on_the_sample_interval(dt):
    # A 0.04 s controller and 0.5 s outputs once gave samples every 0.48 s (12 whole
    # samples): the grid is the continuous loop's, whatever the controller's interval.
    loop = sim.PidLoop(J, B0, 0.12, 0.002, 2.4, moment_limit=0.4)
    cont = sim.simulate_pid(loop, 0.3, 0.0, 10.0, output_interval=0.5)
    samp = sim.simulate_pid(loop, 0.3, 0.0, 10.0, sample_interval=dt, output_interval=0.5)
    assert_allclose(samp.time, np.linspace(0.0, 10.0, 21), rtol=0, atol=0)
    assert_allclose(cont.time, samp.time, rtol=0, atol=0)


def test_state_between_samples_is_the_plant_under_the_held_command():
    # Between controller samples the command is held (zero-order hold): the state at an
    # output instant 0.02 s after the 0.48 s sample is scipy's integration of the plant
    # from that sample with that command. Tolerance: RK4 with 4 steps of 5 ms against
    # solve_ivp at rtol 1e-11 (local error ~ (5 ms)^5 · |ψ^(5)|, far below 1e-9 rad).
    loop = sim.PidLoop(J, B0, 0.12, 0.002, 2.4, moment_limit=0.4)
    dt = 0.04
    fine = sim.simulate_pid(loop, 0.3, 0.0, 0.48, sample_interval=dt, output_interval=dt)
    x48, u48 = np.array([fine.psi[-1], fine.rate[-1]]), float(fine.command[-1])
    ref = solve_ivp(_held_command_rhs, (0.48, 0.5), x48, args=(u48, loop.allocation, loop.plant),
                    rtol=1e-11, atol=1e-14).y[:, -1]
    coarse = sim.simulate_pid(loop, 0.3, 0.0, 1.0, sample_interval=dt, output_interval=0.5)
    assert_allclose([coarse.psi[1], coarse.rate[1]], ref, rtol=0, atol=1e-9)
    assert coarse.command[1] == u48           # the held command of the 0.48 s sample
