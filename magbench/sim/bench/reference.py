r"""The oracle of the bench's loop (:func:`simulate_bench_reference`): the same controller,
one member, the plant integrated by scipy's ``solve_ivp`` over each held-moment interval
instead of one RK4 step.
"""

from dataclasses import replace

import numpy as np

from ...dynamics.pendulum import mockup_rhs
from ...integrate import solve_adaptive
from ..result import SimulationResult
from .config import BenchSetup  # noqa: F401 - doctests
from .controller import controller_step

__all__ = ["simulate_bench_reference"]


def simulate_bench_reference(setup, psi_des, *, duration, release_angle=0.0, release_rate=0.0,
                             moment_scale=1.0, thread_stiffness=None, sensor_errors=None,
                             rtol=1e-10, atol=1e-12):
    r"""The same closed loop for one member, the plant integrated by scipy's solve_ivp.

    Parameters
    ----------
    setup : BenchSetup
        The bench [-].
    psi_des : float
        Target angle [rad].
    duration : float
        Simulated time [s], a whole number of samples.
    release_angle, release_rate : float, optional
        Angle [rad] and rate [rad/s] at release.
    moment_scale : array_like, optional
        Factor on each coil's full-scale moment, shape (2,) or scalar [-].
    thread_stiffness : float, optional
        Torsion constant [N·m/rad]; default ``setup.thread_stiffness``.
    sensor_errors : tuple of ndarray, optional
        (gyro (steps,) [rad/s], magnetometer (steps, 2) [T]) errors; default ideal sensors.
    rtol, atol : float, optional
        Tolerances of solve_ivp (RK45) on each held-moment interval [-], [rad or rad/s].

    Returns
    -------
    SimulationResult
        At every sample and the final time: states ``psi`` [rad] and ``rate`` [rad/s],
        inputs ``moment_1``, ``moment_2`` [A·m²] (the last held to the end), output
        ``estimate`` [rad], as :func:`simulate_bench` returns them for one member.

    Notes
    -----
    Not in the thesis: the oracle for :func:`simulate_bench`'s integrator. The same
    :func:`controller_step` sets the moments; the plant is integrated by one
    :func:`scipy.integrate.solve_ivp` call per sample instead of the fixed-step RK4 (the
    moments jump at each sample, so one call per interval is the way to integrate a
    zero-order hold exactly). It is slow: the benchmark times it on a few members.

    Examples
    --------
    >>> from magbench.chapters.ch04_mockup import bench_setup
    >>> from magbench.params import chapter_parameters
    >>> s = bench_setup(chapter_parameters("ch04"))
    >>> simulate_bench_reference(s, 1.0, duration=0.05).psi.shape
    (6,)
    """
    dt = setup.sample_interval
    steps = int(round(float(duration) / dt))
    kappa = setup.thread_stiffness if thread_stiffness is None else float(thread_stiffness)
    scale = np.broadcast_to(np.asarray(moment_scale, float), (2,))
    full_actual = setup.full_scale_moments * scale
    g_err, m_err = sensor_errors if sensor_errors is not None else (np.zeros(steps), np.zeros((steps, 2)))
    b0, plant = setup.field, replace(setup.plant, thread_stiffness=kappa)
    state = np.array([float(release_angle), float(release_rate)])
    out = np.empty((steps + 1, 5))          # psi, rate, moment_1, moment_2, estimate
    estimate, integral = None, 0.0
    for k in range(steps):
        psi, omega = state
        gyro = omega + g_err[k]
        bx = b0 * np.cos(psi) + m_err[k, 0]
        by = -b0 * np.sin(psi) + m_err[k, 1]
        m1, m2, estimate, integral = controller_step(setup, psi_des, gyro, bx, by, estimate, integral,
                                                     full_actual[0], full_actual[1])
        out[k] = psi, omega, m1, m2, estimate
        sol = solve_adaptive(mockup_rhs, (k * dt, (k + 1) * dt), state, args=((float(m1), float(m2)), plant),
                             method="RK45", rtol=rtol, atol=atol)
        state = sol.y[:, -1]
    out[steps] = state[0], state[1], out[steps - 1, 2], out[steps - 1, 3], estimate
    return SimulationResult(np.arange(steps + 1) * dt, out[:, :2].T, out[:, 2:4].T, out[:, 4:].T,
                            ("psi", "rate"), ("moment_1", "moment_2"), ("estimate",),
                            params={"psi_des": psi_des})
