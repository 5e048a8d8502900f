r"""The bench's closed loop over Monte Carlo members (:func:`simulate_bench`): sensors,
filter, PID, allocation, PWM and the plant's RK4 step at every sample, as laid out in
:mod:`magbench.sim.bench`.

The sample loop runs in one of two engines with the same arithmetic, operation for
operation: compiled (:mod:`magbench.sim.bench._kernel`, the default) or numpy (the
reference the tests hold the compiled one to, bit for bit).
"""

from dataclasses import dataclass, replace

import numpy as np

from ...dynamics.pendulum import mockup_rhs
from ...integrate import rk4_step
from ..._validate import as_finite
from ...rotations import wrap_angle
from ..result import SimulationResult
from .config import BenchErrors, BenchSetup  # noqa: F401 - BenchSetup: doctests
from .controller import controller_step, draw_sensor_errors
from .inputs import _error_arrays, _loop_inputs, _member_array

__all__ = ["simulate_bench"]

# Samples of sensor error drawn at once: bounds memory at members × block × 3 floats.
_BLOCK = 256
# With one generator per member, each member's errors are drawn this many samples at a time
# (a few calls per member instead of one per member and block: the calls, not the numbers,
# were the cost). Part of what a seed means: a member's stream is gyro then magnetometer for
# each such block.
_MEMBER_BLOCK = 16 * _BLOCK

#: The sample loop: "compiled" (:mod:`magbench.sim.bench._kernel`, the default) or "numpy"
#: (the reference, operation for operation the same; the tests switch it to compare the two).
_ENGINE = "compiled"


@dataclass
class _Run:
    """A run's checked inputs, the plant and its records (arrays filled in place)."""

    setup: object
    psi_des: object
    steps: int
    window: float
    members: int
    every: int
    first_in_window: int
    psi: np.ndarray
    omega: np.ndarray
    kappa: np.ndarray
    scale: np.ndarray
    g_err: object
    m_err: object
    err: dict
    field: object
    plant: object
    coil_axes: object
    full_1: np.ndarray
    full_2: np.ndarray
    states: np.ndarray = None
    moments: np.ndarray = None
    estimates: np.ndarray = None
    band: np.ndarray = None
    band_est: np.ndarray = None

    def __post_init__(self):
        n_rec = self.steps // self.every + 1
        self.states = np.empty((2, n_rec, self.members))          # psi, rate
        self.moments = np.empty((2, n_rec, self.members))         # moment_1, moment_2
        self.estimates = np.empty((1, n_rec, self.members))
        self.band = np.zeros(self.members)
        self.band_est = np.zeros(self.members)


def _prepare(setup, psi_des, duration, members, release_angle, release_rate, errors, rng, sensor_errors,
             record_interval, window):
    """:func:`simulate_bench`'s inputs checked, and the plant and coils of each member."""
    psi_des = as_finite("psi_des", psi_des)
    if psi_des.ndim == 0:
        psi_des = float(psi_des)
    elif members is None:
        members = psi_des.size
    errors = BenchErrors() if errors is None else errors
    steps, window, members, psi, omega, kappa, scale, every, g_err, m_err = _loop_inputs(
        setup, duration, window, members, release_angle, release_rate, errors, rng, sensor_errors, record_interval)
    if not isinstance(psi_des, float):
        psi_des = _member_array("psi_des", psi_des, members)
    err = _error_arrays(members, errors)
    dt, b0 = setup.sample_interval, setup.field
    if err["field_scale"] is not None:
        b0 = b0 * err["field_scale"]
    plant = replace(setup.plant, thread_stiffness=kappa, field=b0)
    if err["thread_neutral_angle"] is not None:
        plant = replace(plant, thread_neutral_angle=err["thread_neutral_angle"])
    coil_axes = None
    if err["coil_misalignment"] is not None:
        eta = err["coil_misalignment"]
        # Body components of unit moments along each misaligned coil: coil 1 at η1 from x,
        # coil 2 at 90° + η2 (so that zero misalignment is the plant's (m1, m2) exactly).
        coil_axes = (np.cos(eta[:, 0]), np.sin(eta[:, 0]), -np.sin(eta[:, 1]), np.cos(eta[:, 1]))
    # Each member's actual full-scale moments (the controller divides by the nominal ones).
    full_actual = setup.full_scale_moments * scale                       # (members, 2)
    full_1, full_2 = np.ascontiguousarray(full_actual[:, 0]), np.ascontiguousarray(full_actual[:, 1])
    first_in_window = int(np.ceil((steps * dt - window) / dt - 1e-9))
    return _Run(setup=setup, psi_des=psi_des, steps=steps, window=window, members=members, every=every,
                first_in_window=first_in_window, psi=psi, omega=omega, kappa=kappa, scale=scale, g_err=g_err,
                m_err=m_err, err=err, field=b0, plant=plant, coil_axes=coil_axes, full_1=full_1, full_2=full_2)


class _NumpyLoop:
    """simulate_bench's sample loop in numpy, the controller's memory kept between blocks
    of sensor errors: the reference of :class:`_CompiledLoop`."""

    def __init__(self, run):
        self.r = run
        self.estimate = None
        self.integral = np.zeros(run.members)
        self.applied = (np.zeros(run.members), np.zeros(run.members))   # body moments held before the first sample
        self.commanded = None

    def _readings(self, k, state, gyro_error, magnetometer_error):
        """The gyro and the magnetometer at sample k, every error source given applied."""
        err, b0, dt = self.r.err, self.r.field, self.r.setup.sample_interval
        psi, omega = state
        gyro = omega + gyro_error
        if err["gyro_offset"] is not None:
            gyro = gyro + err["gyro_offset"]
        if err["gyro_drift"] is not None:
            gyro = gyro + err["gyro_drift"] * (k * dt)
        bx, by = b0 * np.cos(psi), -b0 * np.sin(psi)
        m_rot, ripple, m_mat = err["magnetometer_misalignment"], err["heading_ripple"], err["magnetometer_matrix"]
        if m_rot is not None or ripple is not None:
            # The sensor reads the heading ψ + δ: the body field turned by −δ.
            delta = (0.0 if m_rot is None else m_rot) + (0.0 if ripple is None else ripple * np.sin(2 * psi))
            c, s = np.cos(delta), np.sin(delta)
            bx, by = bx * c + by * s, by * c - bx * s
        if m_mat is not None:
            bx, by = m_mat[:, 0, 0] * bx + m_mat[:, 0, 1] * by, m_mat[:, 1, 0] * bx + m_mat[:, 1, 1] * by
        if err["coil_field_coupling"] is not None:
            coupling = err["coil_field_coupling"]
            bx, by = bx + coupling * self.applied[0], by + coupling * self.applied[1]
        if err["magnetometer_offset"] is not None:
            bx, by = bx + err["magnetometer_offset"][:, 0], by + err["magnetometer_offset"][:, 1]
        return gyro, bx + magnetometer_error[:, 0], by + magnetometer_error[:, 1]

    def run(self, start, count, state, g_blk, m_blk):
        """Advance ``state`` (2, M) over samples start … start + count − 1; the new state."""
        r = self.r
        dt, azimuth, axes = r.setup.sample_interval, r.err["field_azimuth"], r.coil_axes
        ctrl_kw = {"filter_coefficient": r.err["filter_coefficient"], "pwm_levels": r.err["pwm_levels"]}
        for j in range(count):
            k = start + j
            psi = state[0]
            gyro, bx, by = self._readings(k, state, g_blk[j], m_blk[j])
            moment_1, moment_2, self.estimate, self.integral = controller_step(
                r.setup, r.psi_des, gyro, bx, by, self.estimate, self.integral, r.full_1, r.full_2, **ctrl_kw)
            self.commanded = (moment_1, moment_2)
            if k % r.every == 0:
                i = k // r.every
                r.states[:, i], r.estimates[0, i], r.moments[:, i] = state, self.estimate, self.commanded
            if k >= r.first_in_window:
                seen = psi if azimuth is None else psi + azimuth
                np.maximum(r.band, np.abs(wrap_angle(seen - r.psi_des)), out=r.band)
                np.maximum(r.band_est, np.abs(wrap_angle(self.estimate - r.psi_des)), out=r.band_est)
            if axes is not None:
                self.applied = (moment_1 * axes[0] + moment_2 * axes[2], moment_1 * axes[1] + moment_2 * axes[3])
            else:
                self.applied = self.commanded
            state = rk4_step(mockup_rhs, k * dt, state, dt, args=(self.applied, r.plant))
        return state


class _CompiledLoop:
    """simulate_bench's sample loop in compiled code: the member inputs gathered once into
    the kernel's rows, the controller's memory kept between blocks of sensor errors."""

    def __init__(self, run):
        from . import _kernel as kernel

        self.kernel, self.r = kernel, run
        setup, err, plant, members = run.setup, run.err, run.plant, run.members
        rows = {"psi_des": run.psi_des, "field": run.field, "thread_stiffness": plant.thread_stiffness,
                "thread_neutral_angle": plant.thread_neutral_angle,
                "filter_coefficient": (setup.filter_coefficient if err["filter_coefficient"] is None
                                       else err["filter_coefficient"]),
                "pwm_levels": int(setup.pwm_levels) if err["pwm_levels"] is None else err["pwm_levels"],
                "full_1": run.full_1, "full_2": run.full_2}
        present = np.zeros(10, dtype=np.bool_)
        for flag, name in ((kernel.HAS_G_OFF, "gyro_offset"), (kernel.HAS_G_DRIFT, "gyro_drift"),
                           (kernel.HAS_M_ROT, "magnetometer_misalignment"), (kernel.HAS_RIPPLE, "heading_ripple"),
                           (kernel.HAS_COUPLING, "coil_field_coupling"), (kernel.HAS_AZIMUTH, "field_azimuth")):
            if err[name] is not None:
                present[flag], rows[name] = True, err[name]
        if err["magnetometer_matrix"] is not None:
            present[kernel.HAS_MATRIX] = True
            for i, row in enumerate(("matrix_00", "matrix_01", "matrix_10", "matrix_11")):
                rows[row] = err["magnetometer_matrix"][:, i // 2, i % 2]
        if err["magnetometer_offset"] is not None:
            present[kernel.HAS_OFFSET] = True
            rows["offset_1"], rows["offset_2"] = err["magnetometer_offset"][:, 0], err["magnetometer_offset"][:, 1]
        if run.coil_axes is not None:
            present[kernel.HAS_AXES] = True
            rows.update(zip(("axis_1x", "axis_1y", "axis_2x", "axis_2y"), run.coil_axes))
        present[kernel.QUANTISED] = err["pwm_levels"] is not None or bool(setup.pwm_levels)
        self.member = np.zeros((len(kernel.ROWS), members))
        for name, value in rows.items():
            self.member[kernel.ROWS.index(name)] = value
        duty_gain = 1.0 / setup.full_scale_moments
        self.setup = np.array([setup.sample_interval, setup.kp, setup.ki, setup.kd, setup.moment_limit,
                               duty_gain[0], duty_gain[1], plant.inertia], dtype=float)
        self.present = present
        self.gyro, self.bxy = np.empty(members), np.empty((2, members))
        self.estimate, self.integral = np.empty(members), np.zeros(members)
        self.commanded, self.applied = np.zeros((2, members)), np.zeros((2, members))

    def run(self, start, count, state, g_blk, m_blk):
        """Advance ``state`` (2, M) in place over samples start … start + count − 1; the state."""
        r, sense, control_and_step = self.r, self.kernel.sense, self.kernel.control_and_step
        g_blk = np.ascontiguousarray(g_blk, dtype=float)
        m_blk = np.ascontiguousarray(m_blk, dtype=float)
        dt = self.setup[0]
        for j in range(count):
            k = start + j
            sense(k, j, state, g_blk, m_blk, self.member, self.present, self.applied, dt, self.gyro, self.bxy)
            # numpy's arctan2, not the C library's: they differ in the last bit (see the kernel)
            heading = np.arctan2(-self.bxy[1], self.bxy[0])
            control_and_step(k, heading, self.gyro, self.bxy, state, self.member, self.present, self.setup,
                             (self.estimate, self.integral, r.band, r.band_est), (self.commanded, self.applied),
                             (r.states, r.moments, r.estimates), (r.first_in_window, r.every))
        return state


def _result(run, state, estimate, commanded, release_angle, release_rate):
    """The records with the final state appended (when it falls on the recording stride),
    the final error band and the run's parameters, as one :class:`SimulationResult`."""
    states, estimates, moments, band = run.states, run.estimates, run.moments, run.band
    azimuth, psi_des = run.err["field_azimuth"], run.psi_des
    if run.steps % run.every == 0:
        states[:, -1], estimates[0, -1], moments[:, -1] = state, estimate, commanded
    else:
        states, estimates, moments = states[:, :-1], estimates[:, :-1], moments[:, :-1]
    np.maximum(band, np.abs(wrap_angle(state[0] + (0.0 if azimuth is None else azimuth) - psi_des)), out=band)
    time = np.arange(states.shape[1]) * run.every * run.setup.sample_interval
    params = {"psi_des": psi_des, "window": run.window,
              "release_angle": _member_array("release_angle", release_angle, run.members),
              "release_rate": _member_array("release_rate", release_rate, run.members),
              "moment_scale": np.array(run.scale), "thread_stiffness": run.kappa}
    return SimulationResult(time, states, moments, estimates, ("psi", "rate"), ("moment_1", "moment_2"),
                            ("estimate",), params=params,
                            summary={"error_band": band, "indicated_error_band": run.band_est})


def simulate_bench(setup, psi_des, *, duration, release_angle=0.0, release_rate=0.0, members=None, errors=None,
                   rng=None, sensor_errors=None, record_interval=None, window=20.0):
    r"""Simulate the bench's closed loop, vectorised over Monte Carlo members.

    Parameters
    ----------
    setup : BenchSetup
        The bench [-].
    psi_des : float or array_like
        Target angle ψ_des from the field to coil 1 [rad] (Figs. 19–20: π/3, 2π/3), one
        for all or one per member.
    duration : float
        Simulated time [s], a whole number of samples.
    release_angle, release_rate : array_like, optional
        True angle [rad] and rate [rad/s] at release, per member.
    members : int, optional
        Number of members [-]; default: the length of the per-member inputs (or 1).
    errors : BenchErrors, optional
        How each member's bench departs from ``setup`` [SI, per field]: moment scale,
        thread stiffness and the hardware error sources; default none.
    rng : numpy.random.Generator or list of them, optional
        Source of sensor noise [-]: one generator, or one per member (its noise then does
        not depend on the other members); None (default) for ideal sensors.
    sensor_errors : tuple of ndarray, optional
        Explicit (gyro (steps, members) [rad/s], magnetometer (steps, members, 2) [T])
        errors instead of drawing them; excludes ``rng``.
    record_interval : float, optional
        Spacing of the recorded traces [s], a multiple of the sample interval; default
        every sample.
    window : float, optional
        Length of the final window over which the error band is taken [s].

    Returns
    -------
    SimulationResult
        Traces every ``record_interval``, each of shape (K, members): states ``psi`` (the
        true angle) [rad] and ``rate`` [rad/s], inputs ``moment_1`` and ``moment_2`` (the
        coils' moments applied from that sample on) [A·m²], output ``estimate`` (the
        filtered angle) [rad]; ``params``: ``psi_des``, ``window`` and the per-member
        ``release_angle``, ``release_rate``, ``moment_scale``, ``thread_stiffness``;
        ``summary``: per member, ``error_band`` max |ψ − ψ_des| over the final window and
        ``indicated_error_band``, the same for the filtered angle [rad].

    Notes
    -----
    Not in the thesis: the loop of thesis §4 (eqs. 36, 37, 39 and the allocation of
    thesis §4.1) as laid out in :mod:`magbench.sim.bench`. At each sample k the
    sensors read the state at t_k, the controller sets the moments, and the plant
    advances to t_{k+1} with them held. The error band is
    max |ψ(t) − ψ_des| over the samples with t ≥ duration − window (and the final
    state): the thesis does not say what its 10° measures.

    Examples
    --------
    >>> from magbench.chapters.ch04_mockup import bench_setup
    >>> from magbench.params import chapter_parameters
    >>> s = bench_setup(chapter_parameters("ch04"))
    >>> run = simulate_bench(s, np.pi / 3, duration=120.0)
    >>> bool(run.error_band[0] < np.radians(1.0))
    True
    """
    run = _prepare(setup, psi_des, duration, members, release_angle, release_rate, errors, rng, sensor_errors,
                   record_interval, window)
    loop = _CompiledLoop(run) if _ENGINE == "compiled" else _NumpyLoop(run)
    state = np.array([run.psi, run.omega])
    per_member = isinstance(rng, (list, tuple))
    for start in range(0, run.steps, _BLOCK):
        count = min(_BLOCK, run.steps - start)
        if run.g_err is not None:
            g_blk, m_blk = run.g_err[start:start + count], run.m_err[start:start + count]
        elif per_member:
            offset = start % _MEMBER_BLOCK
            if offset == 0:
                g_big, m_big = draw_sensor_errors(setup, min(_MEMBER_BLOCK, run.steps - start), run.members, rng)
            g_blk, m_blk = g_big[offset:offset + count], m_big[offset:offset + count]
        else:
            g_blk, m_blk = draw_sensor_errors(setup, count, run.members, rng)
        state = loop.run(start, count, state, g_blk, m_blk)
    return _result(run, state, loop.estimate, loop.commanded, release_angle, release_rate)
