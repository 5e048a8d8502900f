"""The mock-up's free swing (thesis eq. 35) integrated: the period against the closed
form, the energy held, and bad input named."""

import numpy as np
import pytest
from numpy.testing import assert_allclose

from magbench import dynamics, sim

PLANT = dynamics.Mockup(0.005, 3.14e-4, 0.4)   # the thesis's J, μ0·250 A/m, m1


@pytest.mark.parametrize("amplitude", [0.2, 1.0, 2.5, 3.0])
def test_integrated_period_is_the_elliptic_closed_form(amplitude):
    closed = dynamics.pendulum_period(amplitude, PLANT.inertia, PLANT.moment_1, PLANT.field)
    # rtol 1e-8: RK45 at rtol 1e-11 and the event's root finding; the period grows to 3x T0 at 3 rad.
    assert_allclose(sim.integrated_swing_period(PLANT, amplitude), closed, rtol=1e-8)


def test_free_swing_holds_its_energy_and_swings_between_the_amplitudes():
    period = dynamics.pendulum_period(np.pi / 2, PLANT.inertia, PLANT.moment_1, PLANT.field)
    run = sim.simulate_free_swing(PLANT, np.pi / 2, np.linspace(0.0, 3 * period, 3001))
    scale = PLANT.moment_1 * PLANT.field
    # 1e-8 of m·B0: RK45 at rtol 1e-10 over three periods.
    assert np.ptp(run.energy) < 1e-8 * scale
    assert_allclose([run.psi.max(), run.psi.min()], [np.pi / 2, -np.pi / 2], atol=1e-6)
    assert run.rate[0] == 0.0 and run.psi[0] == np.pi / 2


@pytest.mark.parametrize("call, match", [
    (lambda: sim.integrated_swing_period(PLANT, np.pi), "amplitude"),
    (lambda: sim.integrated_swing_period(PLANT, 0.0), "amplitude"),
    (lambda: sim.integrated_swing_period((0.005, 3e-4, 0.4), 1.0), "plant"),
    (lambda: sim.integrated_swing_period(dynamics.Mockup(0.005, 0.0, 0.4), 1.0), "field"),
    (lambda: sim.simulate_free_swing(PLANT, 1.0, [1.0, 2.0]), "time"),
    (lambda: sim.simulate_free_swing(PLANT, np.nan, [0.0, 1.0]), "initial_angle"),
])
def test_bad_input_is_named(call, match):
    with pytest.raises(ValueError, match=match):
        call()
