"""magbench.sim.wheels: the wheel-stabilised body with magnetic unloading: momentum conservation,
the PD loop holding the orbital frame, the wheels' momentum under a constant disturbance with and
without unloading (closed forms), the limits recorded, members equal separate runs."""

import numpy as np
import pytest
from numpy.testing import assert_allclose

from magbench.earth import CircularOrbit
from magbench.earth import sun_ecliptic_axes
from magbench.sim.wheels import (DisturbanceTorque, UnloadingLaw, WheelSatellite, simulate_coil_detumbling,
                                  simulate_ideal_unloading,
                                  simulate_unloading)

SAT = WheelSatellite((10.0, 12.0, 8.0), 0.025, 0.7)  # ω_n ≈ 0.05 rad/s, ζ ≈ 0.7
ORBIT = CircularOrbit(6.83e6, np.radians(55.0), 8e22)
D = 1e-4


def test_total_momentum_is_conserved_without_external_torques():
    # body + wheels with only the motors' (internal) torques: H = C(q)(Jω + h_w) constant; RK4 at
    # 2 s on rates ~0.03 rad/s: ~1e-7 relative
    run = simulate_unloading(SAT, ORBIT, UnloadingLaw("none"), DisturbanceTorque(gravity_gradient=False), 1000.0,
                             2.0, 100.0, initial_rotation=[0.5, -0.3, 0.8], initial_rate=[0.01, 0.02, -0.01],
                             initial_wheel_momentum=[0.1, 0.0, 0.2])
    h = np.stack([run.momentum_x, run.momentum_y, run.momentum_z])
    assert_allclose(h, np.broadcast_to(h[:, :1], h.shape), atol=1e-6 * np.abs(h).max())


def test_pd_loop_holds_the_orbital_frame_without_disturbances():
    # error 0.14 rad decays at ζω_n = 0.035/s: after 1000 s the transient is e^{-35}-small; the
    # bound 1e-4 rad leaves room for the zero-order hold's offset (measured 2e-5 rad)
    run = simulate_unloading(SAT, ORBIT, UnloadingLaw("none"), DisturbanceTorque(gravity_gradient=False), 1500.0,
                             2.0, 100.0, initial_rotation=[0.1, -0.05, 0.08])
    assert run.attitude_error[0, 0] == pytest.approx(np.linalg.norm([0.1, -0.05, 0.08]), rel=1e-9)
    assert np.all(run.attitude_error[-5:] < 1e-4)


def test_wheel_momentum_without_unloading_follows_the_closed_form():
    # held in the orbital frame (ω = n Y), ḣ = d − n e_y × h: h_y = d t, and h_x + i h_z =
    # (d_x + i d_z)(e^{int} − 1)/(in) (bounded); the PD transient and hold leave < 1e-3 N·m·s of 0.56
    run = simulate_unloading(SAT, ORBIT, UnloadingLaw("none"), DisturbanceTorque(constant=(D, D, D)), ORBIT.period,
                             5.0, 50.0)
    n, t = ORBIT.mean_motion, run.time
    c = (D + 1j * D) * (np.exp(1j * n * t) - 1) / (1j * n)
    assert_allclose(run.wheel_momentum_y[:, 0], D * t, atol=1e-3)
    assert_allclose(run.wheel_momentum_x[:, 0], c.real, atol=1e-3)
    assert_allclose(run.wheel_momentum_z[:, 0], c.imag, atol=1e-3)


def test_linear_unloading_keeps_the_wheel_momentum_bounded():
    # the same disturbance with the linear law (5.1): the orbit-to-orbit peaks settle (within
    # 1 %) while without it h_y grows by d T ≈ 0.57 N·m·s per orbit
    run = simulate_unloading(SAT, ORBIT, UnloadingLaw("linear", 0.003), DisturbanceTorque(constant=(D, D, D)),
                             3 * ORBIT.period, 5.0, 50.0)
    per = int(ORBIT.period / 50.0)
    peaks = [run.wheel_momentum[i * per:(i + 1) * per, 0].max() for i in range(3)]
    assert peaks[2] == pytest.approx(peaks[1], rel=1e-2)
    assert peaks[2] < 0.5 * D * ORBIT.period
    # the dipole's torque is across B: the law leaves h_w·B̂ to the field's turning
    assert np.all(np.isfinite(run.wheel_momentum_along_field))


def test_limits_act_and_are_recorded():
    sat = WheelSatellite((10.0, 12.0, 8.0), 0.025, 0.7, wheel_torque_limit=1e-3, wheel_momentum_limit=0.2)
    run = simulate_unloading(sat, ORBIT, UnloadingLaw("none"), DisturbanceTorque(constant=(0.0, D, 0.0)), 3000.0,
                             5.0, 50.0, initial_rotation=[0.3, 0.0, 0.0])
    assert run.torque_limited[0, 0] == 1.0
    assert np.abs(run.wheel_torque_x).max() <= 1e-3
    # h_y = d t reaches 0.2 N·m·s at 2000 s; then the wheel stops absorbing
    assert run.first_momentum_limit_time[0] == pytest.approx(2000.0, abs=20.0)
    assert np.abs(run.wheel_momentum_y).max() <= 0.2 + 5.0 * 1e-3


def test_members_equal_separate_runs():
    phases = np.array([0.0, 1.0])
    rot = np.array([[0.1, 0.0, 0.0], [0.0, -0.2, 0.1]])
    law, dist = UnloadingLaw("relay_coil", 50.0, 0.05, 1e-6), DisturbanceTorque(constant=(D, D, D))
    both = simulate_unloading(SAT, CircularOrbit(6.83e6, 0.96, 8e22, phases), law, dist, 500.0, 5.0, 50.0,
                              initial_rotation=rot)
    for i in range(2):
        one = simulate_unloading(SAT, CircularOrbit(6.83e6, 0.96, 8e22, phases[i]), law, dist, 500.0, 5.0, 50.0,
                                 initial_rotation=rot[i])
        # same arithmetic per member: rounding only
        assert_allclose(both.states[..., i], one.states[..., 0], rtol=1e-12, atol=1e-15)


@pytest.mark.parametrize("call, match", [
    (lambda: WheelSatellite((10.0, -1.0, 8.0), 0.1, 0.1), "inertia must be three positive"),
    (lambda: WheelSatellite((10.0, 1.0, 8.0), 0.0, 0.1), "attitude_gain must be > 0"),
    (lambda: WheelSatellite((10.0, 1.0, 8.0), 0.1, 0.1, wheel_momentum_limit=-1.0), "wheel_momentum_limit must be > 0"),
    (lambda: UnloadingLaw("magic"), "kind"),
    (lambda: UnloadingLaw("linear", -1.0), "gain must be >= 0"),
    (lambda: DisturbanceTorque(constant=(1.0, 2.0)), "constant must be a scalar or three components"),
    (lambda: simulate_unloading(SAT, ORBIT, UnloadingLaw(), DisturbanceTorque(), 10.0, 0.0), "step must be > 0"),
    (lambda: simulate_unloading(SAT, ORBIT, UnloadingLaw(), DisturbanceTorque(), 10.0, 1.0, 1.5),
     "record_interval must be a whole number"),
    (lambda: simulate_unloading(SAT, ORBIT, "linear", DisturbanceTorque(), 10.0, 1.0), "law must be an UnloadingLaw or a sequence"),
    (lambda: simulate_unloading(SAT, ORBIT, UnloadingLaw(), DisturbanceTorque(), 10.0, 1.0,
                                initial_rate=np.zeros((2, 2))), "initial_rate must be"),
])
def test_bad_input(call, match):
    with pytest.raises(ValueError, match=match):
        call()


E20_ORBIT = CircularOrbit(6371e3 + 450e3, np.radians(55.0), 8.1e22)


def test_ideal_unloading_without_coils_integrates_the_disturbance_exactly():
    # K̇ = M_B constant: RK4 is exact on a linear function of time (rounding only)
    run = simulate_ideal_unloading(E20_ORBIT, UnloadingLaw("none"), [1e-4, -2e-4, 3e-4], 3000.0, 10.0, 100.0)
    assert_allclose(run.wheel_momentum_y[:, 0], -2e-4 * run.time, atol=1e-13)


def test_relay_hysteresis_keeps_the_coils_on_down_to_the_release_threshold():
    # one axis above K° = 1: without hysteresis the relay stops at the first |K_x| ≤ K°, the others
    # still inside their dead zone, so K freezes; the last held step moves K_x by at most
    # L0 (|B_y| + |B_z|) h ≤ 50·2·4.5e-5·10 = 0.045. With K1° = 0.2 (Fig. 5.1b) it goes on past K°,
    # and the y and z relays, fed by the cross terms, switch on in turn (the source's coupling of
    # the channels, seed line 121)
    start = [1.5, 0.0, 0.0]
    plain = simulate_ideal_unloading(E20_ORBIT, UnloadingLaw("relay_coil", 50.0, 1.0, 1e-6), 0.0, 3000.0, 10.0,
                                     initial_wheel_momentum=start)
    assert 1.0 - 0.045 <= plain.wheel_momentum_x[-1, 0] <= 1.0
    assert np.all(np.abs(plain.states[1:, -1, 0]) < 1.0)
    assert_allclose(plain.states[:, -1], plain.states[:, -50], rtol=0, atol=0)
    held = simulate_ideal_unloading(E20_ORBIT, UnloadingLaw("relay_coil", 50.0, 1.0, 1e-6, 0.2), 0.0, 3000.0, 10.0,
                                    initial_wheel_momentum=start)
    assert held.wheel_momentum_x[:, 0].min() < 0.5


def test_duty_cycling_with_no_gap_and_a_one_step_interval_is_the_continuous_law():
    # reading every step and never switching off is the continuous law: rounding only
    law = UnloadingLaw("linear", 2e-3)
    cont = simulate_ideal_unloading(E20_ORBIT, law, 1e-4, 2000.0, 5.0, 50.0, initial_wheel_momentum=1.0)
    cyc = simulate_ideal_unloading(E20_ORBIT, law, 1e-4, 2000.0, 5.0, 50.0, initial_wheel_momentum=1.0,
                                   control_interval=5.0)
    assert_allclose(cyc.states, cont.states, rtol=0, atol=1e-15)
    off = simulate_ideal_unloading(E20_ORBIT, law, 1e-4, 1700.0, 1.0, 17.0, initial_wheel_momentum=1.0,
                                   control_interval=17.0, off_time=1.0)
    assert_allclose(off.summary["on_fraction"], 16 / 17, rtol=1e-12)
    assert np.all(off.inputs[:, :, 0] == 0.0)        # every sample falls on a reading, coils off


def test_linear_law_is_covariant_under_the_body_axes():
    # rotating the body axes by R turns the field, the disturbance and the momentum by R: the
    # linear law (cross products) commutes with R, so K_body = R K_inertial to rounding
    r = sun_ecliptic_axes(np.radians(225.0), np.radians(23.45))
    k0, torque = np.array([0.5, -1.0, 0.8]), np.array([1e-4, 2e-4, -1e-4])
    law = UnloadingLaw("linear", 2e-3)
    inertial = simulate_ideal_unloading(E20_ORBIT, law, torque, 3000.0, 10.0, 100.0, initial_wheel_momentum=k0)
    body = simulate_ideal_unloading(E20_ORBIT, law, r @ torque, 3000.0, 10.0, 100.0, initial_wheel_momentum=r @ k0,
                                    body_axes=r)
    assert_allclose(body.states[..., 0].T, (r @ inertial.states[..., 0]).T, rtol=0, atol=1e-12)


def test_per_member_laws_equal_separate_runs():
    laws = [UnloadingLaw("relay_coil", 50.0, 1.0, 1e-6, 0.3), UnloadingLaw("product", 1e6)]
    both = simulate_ideal_unloading(E20_ORBIT, laws, 1e-4, 3000.0, 10.0, 100.0, initial_wheel_momentum=1.5)
    for i, law in enumerate(laws):
        one = simulate_ideal_unloading(E20_ORBIT, law, 1e-4, 3000.0, 10.0, 100.0, initial_wheel_momentum=1.5)
        assert_allclose(both.states[..., i], one.states[..., 0], rtol=0, atol=1e-15)


def test_coil_detumbling_without_coils_keeps_momentum_and_energy_to_fourth_order():
    # torque-free rigid body: |K| and ½ω·Jω are invariants; RK4's loss of them shrinks at least as
    # h⁴ (halving the step divides it by 16 or more; measured 32, an h⁵ loss; 12–40 allows both)
    j = np.array([2950.0, 12800.0, 12800.0])
    loss = []
    for step in (10.0, 5.0):
        run = simulate_coil_detumbling(j, E20_ORBIT, UnloadingLaw("none"), 3000.0, step, 100.0,
                                       initial_momentum=[98.0, 98.0, 98.0])
        w = np.stack([run.rate_x[:, 0], run.rate_y[:, 0], run.rate_z[:, 0]], axis=-1)
        energy = 0.5 * np.sum(j * w * w, axis=-1)
        loss.append((abs(run.momentum[-1, 0] / run.momentum[0, 0] - 1), abs(energy[-1] / energy[0] - 1)))
    (k1, e1), (k2, e2) = loss
    assert 12 < k1 / k2 < 40 and 12 < e1 / e2 < 40
    assert k2 < 2e-5 and e2 < 2e-5


@pytest.mark.parametrize("call, match", [
    (lambda: simulate_ideal_unloading(E20_ORBIT, UnloadingLaw(), 0.0, 100.0, 1.0, body_axes=2 * np.eye(3)),
     "body_axes must be a rotation"),
    (lambda: simulate_ideal_unloading(E20_ORBIT, UnloadingLaw(), 0.0, 100.0, 1.0, off_time=1.0),
     "off_time needs a control_interval"),
    (lambda: simulate_ideal_unloading(E20_ORBIT, UnloadingLaw(), 0.0, 100.0, 1.0, control_interval=5.0, off_time=5.0),
     "off_time must be < control_interval"),
    (lambda: simulate_ideal_unloading(E20_ORBIT, [UnloadingLaw()] * 2, np.zeros((3, 3)), 100.0, 1.0),
     "must agree on the members"),
    (lambda: simulate_coil_detumbling((1.0, 1.0), E20_ORBIT, UnloadingLaw(), 100.0, 1.0), "inertia must be three"),
    (lambda: simulate_coil_detumbling((1.0, 1.0, 1.0), E20_ORBIT, UnloadingLaw(), 100.0, 1.0, dipole_limit=-1.0),
     "dipole_limit must be > 0"),
])
def test_bad_input_of_the_ideal_and_detumbling_runs(call, match):
    with pytest.raises(ValueError, match=match):
        call()
