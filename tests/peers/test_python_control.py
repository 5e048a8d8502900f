"""Peer cross-checks against python-control (poles, margins, responses of the PID loop).

Each test calls ``_ct()``, which skips that test alone when python-control is missing;
the chapter-4 tests without a peer live in tests/chapters/test_ch04_mockup.py.
"""

import numpy as np
import pytest
from numpy.testing import assert_allclose

from magbench import control
from magbench import sim
from magbench.constants import MU_0

J, M1 = 0.005, 0.4                  # thesis seed line 516
B0 = MU_0 * 250.0                   # design field (inventory G18)
PRINTED_SETS = [(0.1, 0.5, 0.5), (0.2, 0.5, 0.5), (0.3, 0.5, 0.5),
                (0.1, 0.5, 1.0), (0.1, 0.5, 2.0), (0.1, 0.5, 3.0)]   # (kp, ki, kd), L565-579


def _ct():
    return pytest.importorskip("control")


@pytest.mark.parametrize("gains", PRINTED_SETS + [(1e3, 5e3, 5e3)])      # the last one is stable
def test_poles_against_python_control(gains):
    ct = _ct()
    kp, ki, kd = gains
    loop = ct.tf(B0 * np.array([kd, kp, ki]), [J, 0, 0, 0])
    ref = np.sort_complex(ct.poles(ct.feedback(loop, 1)))
    ours = np.sort_complex(control.closed_loop_poles(J, B0, kp, ki, kd))
    assert_allclose(ours, ref, rtol=1e-9)   # np.roots vs state-space eigenvalues, distinct roots
    routh_stable = ki < control.integral_gain_limit(J, B0, kp, kd)
    assert routh_stable == bool(np.all(ref.real < 0))


def test_critical_gain_scale_is_the_stability_boundary_and_the_gain_margin():
    ct = _ct()
    for kp, ki, kd in PRINTED_SETS:
        s = float(control.critical_gain_scale(J, B0, kp, ki, kd))
        assert control.closed_loop_poles(J, B0, *(1.001 * s * np.array([kp, ki, kd])))[0].real < 0
        assert control.closed_loop_poles(J, B0, *(0.999 * s * np.array([kp, ki, kd])))[0].real > 0
    kp, ki, kd = control.pid_gains_for_triple_pole(J, B0, 0.05)
    gm, pm, *_ = ct.stability_margins(ct.tf(B0 * np.array([kd, kp, ki]), [J, 0, 0, 0]))
    assert_allclose(gm, control.critical_gain_scale(J, B0, kp, ki, kd), rtol=1e-9)
    assert_allclose(gm, 1 / 9, rtol=1e-9)              # triple pole: closed form 1/9


def test_ziegler_nichols_on_a_double_integrator():
    ct = _ct()
    for period in (20.0, 80.0):
        ku = control.double_integrator_ultimate_gain(J, B0, period)
        p_only = ct.poles(ct.feedback(ct.tf([B0 * ku], [J, 0, 0]), 1))
        assert_allclose(p_only, [2j * np.pi / period, -2j * np.pi / period], atol=1e-12)
        poles = control.closed_loop_poles(J, B0, *control.ziegler_nichols_pid(ku, period))
        # Scale-free: the Z–N loop is the same shape at every chosen period.
        assert_allclose(np.sort_complex(poles * period / (2 * np.pi)),
                        np.sort_complex(np.roots([1, 0.075 * 2 * np.pi, 0.6, 1.2 / (2 * np.pi)])), rtol=1e-9)
        assert np.all(poles.real < 0)


def test_linear_step_response_matches_python_control():
    ct = _ct()
    kp, ki, kd = control.pid_gains_for_triple_pole(J, B0, 0.05)
    loop = sim.PidLoop(J, B0, kp, ki, kd, target=0.01)       # exact allocation, unsaturated
    run = sim.simulate_pid(loop, 0.0, 0.0, 300.0, output_interval=0.5)
    # Derivative on the measurement: r → ψ is B0 (Kp s + Ki) / (J s³ + B0 Kd s² + B0 Kp s + B0 Ki).
    sys = ct.tf(B0 * np.array([kp, ki]), control.closed_loop_polynomial(J, B0, kp, ki, kd))
    ref = ct.forced_response(sys, run.time, 0.01 * np.ones_like(run.time)).outputs
    assert_allclose(run.psi, ref, atol=1e-9)       # solve_ivp rtol 1e-9 on a 0.01 rad step


def test_interconnection_matches_simulate_pid():
    ct = _ct()
    from magbench.chapters.ch04_mockup import figures as thesis_ch4

    kp, ki, kd = control.pid_gains_for_triple_pole(J, B0, 0.05)
    system, loop = thesis_ch4.build_interconnection(J, B0, kp, ki, kd, 0.4)
    t = np.linspace(0.0, 200.0, 401)
    ref = ct.input_output_response(system, t, 0.1 * np.ones_like(t), X0=np.zeros(3),
                                   solve_ivp_kwargs={"rtol": 1e-10, "atol": 1e-13, "max_step": 0.5})
    ours = sim.simulate_pid(sim.PidLoop(J, B0, kp, ki, kd, target=0.1, moment_limit=0.4),
                                0.0, 0.0, 200.0, output_interval=0.5)
    # Unsaturated (Kp·0.1 ≪ 0.4), so the anti-windup schemes do not enter; solver tolerances.
    assert_allclose(ours.psi, ref.outputs[0], atol=1e-7)
