r"""Closed-loop simulation of the thesis's bench experiments (thesis §4.2–4.4, Figs. 19–20).

The mock-up hangs on a thread inside the Helmholtz field simulator and turns about the
vertical only. This module puts the physics modules together into the loop that ran on
the bench's Arduino, one controller sample at a time, vectorised over Monte Carlo
members (every state is an array of shape ``(members,)``):

1. **Sensors** (:mod:`magbench.hardware.sensors`, MPU-6050 gyro and HMC5883L magnetometer). Both
   models are additive (reading = truth + error, the error independent of the truth),
   so their errors are drawn ahead, in blocks of samples, by calling the sensor
   functions on a zero signal; ``rng=None`` gives ideal sensors.
2. **Filter** (thesis eq. 39, :func:`magbench.estimation.complementary_filter_step`). The
   absolute reference is the magnetometer heading ψ_mag = atan2(−B_y', B_x'), *not* an
   accelerometer angle: gravity is parallel to the turning axis, so an accelerometer
   cannot observe this angle. The
   heading is unwrapped onto the branch of the current estimate, as firmware would.
3. **PID** (thesis eq. 37, :func:`magbench.control.pid_step`) on e = ψ_des − ψ̂ with
   de/dt = −ω_gyro, saturated at the coils' full-scale moment, with anti-windup.
4. **Allocation** (thesis §4.1): with b the measured unit field in
   body axes, M_x = −m_z b_y and M_y = m_z b_x for a torque −|B| m_z about the vertical;
   the PID output u is the torque per unit field, m_z = −u.
5. **Driver**: Arduino ``analogWrite`` sets an 8-bit duty (255 levels each way, the L298
   sets the sign); the coil's mean current is duty·(U − drop)/R, with each coil's
   measured resistance, and its moment follows from :mod:`magbench.hardware`.
   Assumptions (ours): the PWM period (≈ 2 ms at the Arduino's 490 Hz) is far longer
   than the coil's L/R time and far shorter than the motion, so the torque is that of
   the mean current; the controller knows the nominal full-scale moment, the coils may
   differ from it (Monte Carlo moment spread).
6. **Plant**: J ψ̈ = τ_coils + τ_thread, with τ_coils from thesis eq. (36) held over
   the sample (zero-order hold) and the thread's torsion τ_thread = −κ(ψ − ψ_thread):
   :func:`magbench.dynamics.mockup_rhs` of the setup's :attr:`BenchSetup.plant`. One
   :func:`magbench.integrate.rk4_step` per sample; :func:`simulate_bench_reference` integrates
   the same plant after the same :func:`controller_step` with
   :func:`scipy.integrate.solve_ivp` instead, as an oracle.

ψ is the angle from the horizontal field to coil 1's axis, counted positive in the
sense of the gyro's vertical axis. The field B0 is the magnitude of the horizontal
field the mock-up sees; :func:`horizontal_field` combines the simulator's field with a
horizontal background (the Earth's) at a given azimuth. That function, the coils'
full-scale moment, the PWM duty and the plant's step are physics and live in their
families (:mod:`magbench.fields`, :mod:`magbench.hardware`, :mod:`magbench.dynamics`);
they are re-exported here.

The thesis's gains (K_p = 0.1, K_d = 0.5, K_i = 0.5, thesis §4.4) make the loop
unstable when read in SI (the thesis states no units for them; see
:func:`magbench.control.integral_gain_limit`); the bench default gains here come from
:func:`magbench.control.pid_gains_for_triple_pole` with a bandwidth of ours.
"""

from dataclasses import dataclass, replace
from functools import cached_property

import numpy as np

from .. import control, estimation
from .._validate import as_count, as_finite, as_in_range, as_nonnegative, as_positive, check_member_steps, shown
from ..dynamics.pendulum import Mockup, mockup_rhs, plant_step
from ..fields.systems import horizontal_field
from ..hardware.driver import coil_full_scale_moment, quantise_duty
from ..rotations import wrap_angle
from ..integrate import rk4_step, solve_adaptive
from .result import SimulationResult

__all__ = ["BenchSetup", "controller_step", "horizontal_field", "coil_full_scale_moment",
           "quantise_duty", "plant_step", "simulate_bench", "simulate_bench_reference",
           "monte_carlo", "steady_error_band", "draw_sensor_errors", "ERROR_INPUTS"]

# Samples of sensor error drawn at once: bounds memory at members × block × 3 floats.
_BLOCK = 256


@dataclass(frozen=True)
class BenchSetup:
    """The bench: mock-up, field, coils, driver, sensors and controller (SI values).

    The thesis's bench is :meth:`from_parameters` of the chapter-4 inputs; every field
    is documented with its unit and source there and in ``magbench/data/thesis/params.toml``.
    """

    inertia: float                      # J [kg m^2]
    field: float                        # horizontal field magnitude B0 [T]
    coil_resistance: tuple              # (R1, R2) [ohm]
    coil_turns: float                   # N [-]
    coil_side: float                    # square turn side l [m]
    supply_voltage: float               # U [V]
    kp: float                           # [A m^2/rad]
    ki: float                           # [A m^2/(rad s)]
    kd: float                           # [A m^2 s/rad]
    filter_coefficient: float           # A of eq. (39) [-]
    sample_interval: float = 0.01       # controller period [s]
    pwm_levels: int = 255               # duty steps each way (0: no quantisation) [-]
    driver_voltage_drop: float = 0.0    # L298 output-stage drop [V]
    thread_stiffness: float = 0.0       # torsion constant kappa [N m/rad]
    thread_neutral_angle: float = 0.0   # psi at which the thread is untwisted [rad]
    gyro_noise_density: float | None = None       # [rad/s/sqrt(Hz)]; None: datasheet
    gyro_bias: float = 0.0              # residual gyro offset after calibration [rad/s]
    magnetometer_noise: float | None = None       # per-sample std [T]; None: datasheet

    def __post_init__(self):
        as_positive("inertia", self.inertia, unit="kg·m²")
        as_positive("field", self.field, unit="T")
        r = as_positive("coil_resistance", self.coil_resistance, unit="Ω")
        if r.shape != (2,):
            raise ValueError(f"coil_resistance must hold two values (R1, R2) [Ω], got shape {r.shape}")
        as_positive("coil_turns", self.coil_turns)
        as_positive("coil_side", self.coil_side, unit="m")
        u = as_positive("supply_voltage", self.supply_voltage, unit="V")
        for name in ("kp", "ki", "kd", "thread_stiffness", "gyro_bias"):
            as_finite(name, getattr(self, name))
        for name in ("kp", "ki", "kd", "thread_stiffness"):
            as_nonnegative(name, getattr(self, name))
        as_in_range("filter_coefficient", self.filter_coefficient, 0.0, 1.0)
        as_positive("sample_interval", self.sample_interval, unit="s")
        levels = as_nonnegative("pwm_levels", self.pwm_levels)
        if float(levels) != int(levels):
            raise ValueError(f"pwm_levels must be a whole number of duty steps, got {shown(self.pwm_levels)}")
        as_in_range("driver_voltage_drop", self.driver_voltage_drop, 0.0, float(u), unit="V")
        if float(self.driver_voltage_drop) >= float(u):
            raise ValueError(f"driver_voltage_drop must be below supply_voltage ({float(u)} V), "
                             f"got {shown(self.driver_voltage_drop)}")
        as_finite("thread_neutral_angle", self.thread_neutral_angle)
        if self.gyro_noise_density is not None:
            as_nonnegative("gyro_noise_density", self.gyro_noise_density)
        if self.magnetometer_noise is not None:
            as_nonnegative("magnetometer_noise", self.magnetometer_noise, unit="T")

    @classmethod
    def from_parameters(cls, params, **changes):
        """The bench of a dict of the bench's inputs (SI; the mock-up chapter's inputs).

        Field: ``bench_field_h`` (the 262 A/m measured at the simulator's centre) combined
        with ``bench_background_h`` at ``bench_background_azimuth``; gains: the triple
        pole at ``bench_bandwidth``. ``changes`` replace single fields afterwards.
        """
        p = params
        b0 = horizontal_field(p["bench_field_h"], p["bench_background_h"],
                              p["bench_background_azimuth"])
        kp, ki, kd = control.pid_gains_for_triple_pole(p["mockup_inertia"], b0, p["bench_bandwidth"])
        setup = cls(
            inertia=p["mockup_inertia"], field=float(b0),
            coil_resistance=(p["bench_coil_resistance"], p["bench_coil_resistance"]),
            coil_turns=p["mtq_turns"], coil_side=p["mtq_side"], supply_voltage=p["mtq_voltage"],
            kp=float(kp), ki=float(ki), kd=float(kd),
            filter_coefficient=p["bench_filter_coefficient"],
            sample_interval=p["bench_sample_interval"], pwm_levels=int(p["bench_pwm_levels"]),
            thread_stiffness=p["bench_thread_stiffness"], gyro_bias=p["bench_gyro_bias"])
        return replace(setup, **changes) if changes else setup

    @property
    def plant(self):
        """The mock-up on its thread (:class:`magbench.dynamics.Mockup`) [SI]."""
        return Mockup(self.inertia, self.field, thread_stiffness=self.thread_stiffness,
                      thread_neutral_angle=self.thread_neutral_angle)

    # Cached on the (frozen) instance: the controller reads both at every sample, and
    # computing them again (with their argument checks) was half the time of a bench run.
    @cached_property
    def full_scale_moments(self):
        """Moments of the two coils at full duty, (m1, m2) [A·m²]."""
        return coil_full_scale_moment(self.supply_voltage - self.driver_voltage_drop,
                                      np.asarray(self.coil_resistance, float), self.coil_turns,
                                      self.coil_side)

    @cached_property
    def moment_limit(self):
        """Largest moment the controller commands: the weaker coil's full scale [A·m²]."""
        return float(np.min(self.full_scale_moments))


def draw_sensor_errors(setup, steps, members, rng):
    r"""Additive errors of the gyro (vertical axis) and magnetometer (two horizontal axes).

    Parameters
    ----------
    setup : BenchSetup
        The bench (noise levels; None picks the datasheet defaults) [-].
    steps : int
        Number of samples [-].
    members : int
        Number of Monte Carlo members [-].
    rng : numpy.random.Generator or None
        Source of randomness [-]; None gives ideal sensors (zero errors).

    Returns
    -------
    gyro : ndarray, shape (steps, members)
        Gyro error about the vertical [rad/s].
    magnetometer : ndarray, shape (steps, members, 2)
        Magnetometer errors along coil 1's and coil 2's axes [T].

    Notes
    -----
    Not in the thesis: the errors are what :func:`magbench.hardware.sensors.gyro_readings` and
    :func:`magbench.hardware.sensors.magnetometer_readings` add to a zero signal; since both models
    add errors independent of the signal, truth + these errors is exactly their reading.

    Examples
    --------
    >>> g, m = draw_sensor_errors(None, 3, 2, None)
    >>> g.shape, m.shape, float(abs(g).max() + abs(m).max())
    ((3, 2), (3, 2, 2), 0.0)
    """
    if rng is None:
        return np.zeros((steps, members)), np.zeros((steps, members, 2))
    from ..hardware import sensors

    dt = setup.sample_interval
    gkw = {} if setup.gyro_noise_density is None else {"noise_density": setup.gyro_noise_density}
    mkw = {} if setup.magnetometer_noise is None else {"noise_std": setup.magnetometer_noise}
    gyro = sensors.gyro_readings(np.zeros((steps, members)), dt, rng=rng, bias=setup.gyro_bias, **gkw)
    mag = sensors.magnetometer_readings(np.zeros((steps, members, 2)), dt, rng=rng, **mkw)
    return gyro, mag


def _member_array(name, value, members):
    arr = as_finite(name, value)
    try:
        return np.array(np.broadcast_to(arr, (members,)), dtype=float)
    except ValueError:
        raise ValueError(f"{name} must be a scalar or have shape ({members},), got shape {arr.shape}") from None


def controller_step(setup, psi_des, gyro, bx, by, estimate, integral, full_1, full_2, *,
                    filter_coefficient=None, pwm_levels=None):
    r"""One sample of the bench's controller: filter, PID, allocation and PWM (pure).

    Parameters
    ----------
    setup : BenchSetup
        The bench: sample interval, filter coefficient, gains, moment limit, PWM levels
        and nominal full-scale moments [-].
    psi_des : float
        Target angle [rad].
    gyro : array_like
        Gyro reading [rad/s], per member.
    bx, by : array_like
        Magnetometer reading along coil 1 and coil 2 [T], per member.
    estimate : array_like or None
        The filter's angle before this sample [rad]; None at the first sample, where the
        filter starts from the magnetometer heading.
    integral : array_like
        The PID integral before this sample [rad·s].
    full_1, full_2 : array_like
        Each coil's actual full-scale moment [A·m²], per member.
    filter_coefficient : array_like, optional
        A of eq. (39) per member [-]; default ``setup.filter_coefficient``.
    pwm_levels : array_like, optional
        Duty steps each way per member [-], > 0; default ``setup.pwm_levels``.

    Returns
    -------
    moment_1, moment_2, estimate, integral : ndarray
        The coils' moments held until the next sample [A·m²], the filter's new angle
        [rad] and the new integral [rad·s].

    Notes
    -----
    Thesis §4.1–4.2: eq. (39) on the magnetometer heading (the reference unwrapped to
    within half a turn of the estimate), the PID of eqs. (37)–(38) on the wrapped error
    (the shorter way round, our choice), and the thesis's allocation with m_z = −u:
    M_x = u b_y, M_y = −u b_x (torque B₀u), each duty cycle quantised to the PWM levels.
    """
    heading = np.arctan2(-by, bx)
    if estimate is None:
        estimate = heading
    reference = estimate + wrap_angle(heading - estimate)
    alpha = setup.filter_coefficient if filter_coefficient is None else filter_coefficient
    estimate = estimation.complementary_filter_step(estimate, gyro, reference, setup.sample_interval, alpha)
    error = wrap_angle(psi_des - estimate)
    u, integral = control.pid_step(error, -gyro, integral, setup.sample_interval, setup.kp, setup.ki,
                                   setup.kd, setup.moment_limit)
    u_over_b = u / np.sqrt(bx * bx + by * by)
    duty_gain = 1.0 / setup.full_scale_moments
    levels = int(setup.pwm_levels) if pwm_levels is None else pwm_levels
    moment_1 = quantise_duty(u_over_b * by * duty_gain[0], levels) * full_1
    moment_2 = quantise_duty(u_over_b * bx * -duty_gain[1], levels) * full_2
    return moment_1, moment_2, estimate, integral


def _loop_inputs(setup, duration, window, members, release_angle, release_rate, moment_scale,
                 thread_stiffness, rng, sensor_errors, record_interval):
    """Checked inputs of :func:`simulate_bench`: steps, window, members, initial state,
    stiffness, moment scale, recording stride and sensor errors (None: draw them)."""
    if not isinstance(setup, BenchSetup):
        raise ValueError(f"setup must be a BenchSetup, got {type(setup).__name__}")
    dt = setup.sample_interval
    steps_f = float(as_positive("duration", duration, unit="s")) / dt
    steps = int(round(steps_f))
    if abs(steps - steps_f) > 1e-6 * max(1.0, steps_f):
        raise ValueError(f"duration must be a whole number of samples of {dt} s, got {shown(duration)}")
    window = float(as_in_range("window", window, 0.0, steps * dt, unit="s"))
    if members is None:
        sizes = [np.size(v) for v in (release_angle, release_rate, thread_stiffness) if v is not None]
        if np.ndim(moment_scale) == 2:
            sizes.append(np.shape(moment_scale)[0])
        if sensor_errors is not None:
            sizes.append(np.shape(sensor_errors[0])[-1])
        members = max(sizes + [1])
    members = as_count("members", members)
    check_member_steps(members, steps)
    psi = _member_array("release_angle", release_angle, members)
    omega = _member_array("release_rate", release_rate, members)
    kappa = _member_array("thread_stiffness",
                          setup.thread_stiffness if thread_stiffness is None else thread_stiffness, members)
    as_nonnegative("thread_stiffness", kappa)
    scale = as_positive("moment_scale", moment_scale)
    try:
        scale = np.broadcast_to(scale, (members, 2))
    except ValueError:
        raise ValueError(f"moment_scale must broadcast to ({members}, 2), got shape {scale.shape}") from None
    every = 1 if record_interval is None else float(as_positive("record_interval", record_interval, unit="s")) / dt
    if abs(every - round(every)) > 1e-6 or round(every) < 1:
        raise ValueError(f"record_interval must be a multiple of the sample interval {dt} s, got {shown(record_interval)}")
    every = int(round(every))
    g_err = m_err = None
    if sensor_errors is not None:
        if rng is not None:
            raise ValueError("give either rng or sensor_errors, not both")
        g_err, m_err = (as_finite("sensor_errors", e) for e in sensor_errors)
        if g_err.shape != (steps, members) or m_err.shape != (steps, members, 2):
            raise ValueError(f"sensor_errors must have shapes ({steps}, {members}) and ({steps}, {members}, 2), "
                             f"got {g_err.shape} and {m_err.shape}")
    elif rng is not None and not isinstance(rng, np.random.Generator):
        raise ValueError(f"rng must be a numpy.random.Generator or None, got {type(rng).__name__}")
    return steps, window, members, psi, omega, kappa, scale, every, g_err, m_err


#: The hardware error sources :func:`simulate_bench` takes as keywords: name -> (unit,
#: trailing shape per member, what the default leaves out). Chapter 4's error budget
#: (magbench.chapters.ch04_mockup.budget) sets them per Monte Carlo member.
ERROR_INPUTS = {
    "gyro_offset": ("rad/s", (), "a constant gyro zero-rate offset added to setup.gyro_bias"),
    "gyro_drift": ("rad/s^2", (), "a linear drift of the gyro offset, offset + drift·t"),
    "magnetometer_offset": ("T", (2,), "hard-iron offset along coil 1 and coil 2"),
    "magnetometer_matrix": ("1", (2, 2), "soft-iron, scale and cross-axis matrix S: reading = S·b + offset"),
    "magnetometer_misalignment": ("rad", (), "rotation of the magnetometer from coil 1's axis about the vertical"),
    "heading_ripple": ("rad", (), "field direction at the magnetometer off the axis's by a·sin 2ψ (non-uniformity)"),
    "coil_misalignment": ("rad", (2,), "rotation of coil 1's and coil 2's axes from their body axes"),
    "coil_field_coupling": ("T/(A m^2)", (), "coils' own field at the magnetometer per unit moment, k·(M_x, M_y)"),
    "field_scale": ("1", (), "factor on the horizontal field B0 (uncancelled background, non-uniformity)"),
    "field_azimuth": ("rad", (), "angle from the bench's reference axis to the field; the error is scored from that axis"),
    "thread_neutral_angle": ("rad", (), "angle at which the thread is untwisted (default setup's)"),
    "filter_coefficient": ("1", (), "A of eq. (39) (default setup's)"),
    "pwm_levels": ("1", (), "duty steps each way, > 0 (default setup's)"),
}


#: The sample loop: "compiled" (:mod:`magbench.sim._bench_kernel`, the default) or "numpy"
#: (the reference, operation for operation the same; the tests switch it to compare the two).
_ENGINE = "compiled"


class _CompiledLoop:
    """simulate_bench's sample loop in compiled code: the member inputs gathered once into
    the kernel's rows, the controller's memory kept between blocks of sensor errors."""

    def __init__(self, setup, psi_des, field, plant, err, coil_axes, full_1, full_2, members):
        from . import _bench_kernel as kernel

        self.kernel = kernel
        rows = {"psi_des": psi_des, "field": field, "thread_stiffness": plant.thread_stiffness,
                "thread_neutral_angle": plant.thread_neutral_angle,
                "filter_coefficient": (setup.filter_coefficient if err["filter_coefficient"] is None
                                       else err["filter_coefficient"]),
                "pwm_levels": int(setup.pwm_levels) if err["pwm_levels"] is None else err["pwm_levels"],
                "full_1": full_1, "full_2": full_2}
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
        if coil_axes is not None:
            present[kernel.HAS_AXES] = True
            rows.update(zip(("axis_1x", "axis_1y", "axis_2x", "axis_2y"), coil_axes))
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

    def run(self, start, count, state, g_blk, m_blk, band, band_est, first_in_window, every, states, moments,
            estimates):
        """Advance ``state`` (2, M) in place over samples start … start + count − 1."""
        sense, control_and_step = self.kernel.sense, self.kernel.control_and_step
        g_blk = np.ascontiguousarray(g_blk, dtype=float)
        m_blk = np.ascontiguousarray(m_blk, dtype=float)
        dt = self.setup[0]
        for j in range(count):
            k = start + j
            sense(k, j, state, g_blk, m_blk, self.member, self.present, self.applied, dt, self.gyro, self.bxy)
            # numpy's arctan2, not the C library's: they differ in the last bit (see the kernel)
            heading = np.arctan2(-self.bxy[1], self.bxy[0])
            control_and_step(k, heading, self.gyro, self.bxy, state, self.member, self.present, self.setup,
                             self.estimate, self.integral, self.commanded, self.applied, band, band_est,
                             first_in_window, every, states, moments, estimates)


def _error_arrays(members, values):
    """Checked per-member arrays of the error sources given (None: left out)."""
    out = {}
    for name, value in values.items():
        if value is None:
            out[name] = None
            continue
        unit, shape, _ = ERROR_INPUTS[name]
        arr = as_finite(name, value)
        try:
            arr = np.array(np.broadcast_to(arr, (members,) + shape), dtype=float)
        except ValueError:
            raise ValueError(f"{name} [{unit}] must broadcast to shape {(members,) + shape}, "
                             f"got shape {arr.shape}") from None
        out[name] = arr
    if out.get("field_scale") is not None:
        as_positive("field_scale", out["field_scale"])
    if out.get("filter_coefficient") is not None:
        as_in_range("filter_coefficient", out["filter_coefficient"], 0.0, 1.0)
    if out.get("pwm_levels") is not None:
        lv = out["pwm_levels"]
        if np.any(lv < 1) or np.any(lv != np.rint(lv)):
            bad = lv[(lv < 1) | (lv != np.rint(lv))].ravel()[0]
            raise ValueError(f"pwm_levels must be whole numbers of duty steps >= 1, got {shown(bad)}")
    if out.get("magnetometer_matrix") is not None:
        det = np.linalg.det(out["magnetometer_matrix"])
        if np.any(det <= 0):
            raise ValueError("magnetometer_matrix must have a positive determinant (a sensor, not a "
                             f"mirror or a collapse), got determinant {shown(float(det[det <= 0].ravel()[0]))}")
    for name in ("magnetometer_misalignment", "heading_ripple", "field_azimuth"):
        if out.get(name) is not None:
            as_in_range(name, out[name], -np.pi, np.pi, unit="rad")
    if out.get("coil_misalignment") is not None:
        as_in_range("coil_misalignment", out["coil_misalignment"], -np.pi / 4, np.pi / 4, unit="rad")
    return out


def simulate_bench(setup, psi_des, *, duration, release_angle=0.0, release_rate=0.0, members=None,
                   moment_scale=1.0, thread_stiffness=None, rng=None, sensor_errors=None,
                   record_interval=None, window=20.0, gyro_offset=None, gyro_drift=None,
                   magnetometer_offset=None, magnetometer_matrix=None, magnetometer_misalignment=None,
                   heading_ripple=None, coil_misalignment=None, coil_field_coupling=None,
                   field_scale=None, field_azimuth=None, thread_neutral_angle=None,
                   filter_coefficient=None, pwm_levels=None):
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
    moment_scale : array_like, optional
        Factor on each coil's full-scale moment [-], broadcast to (members, 2): a scalar
        for all, shape (2,) per coil, (members, 1) per member, (members, 2) for each.
    thread_stiffness : array_like, optional
        Torsion constant per member [N·m/rad]; default ``setup.thread_stiffness``.
    rng : numpy.random.Generator, optional
        Source of sensor noise [-]; None (default) for ideal sensors.
    sensor_errors : tuple of ndarray, optional
        Explicit (gyro (steps, members) [rad/s], magnetometer (steps, members, 2) [T])
        errors instead of drawing them; excludes ``rng``.
    record_interval : float, optional
        Spacing of the recorded traces [s], a multiple of the sample interval; default
        every sample.
    window : float, optional
        Length of the final window over which the error band is taken [s].
    gyro_offset, gyro_drift : array_like, optional
        Per member: constant gyro offset [rad/s] (on top of ``setup.gyro_bias``) and its
        linear drift [rad/s²]; the gyro reads ω + offset + drift·t + noise.
    magnetometer_offset : array_like, optional
        Hard-iron offset along coil 1 and coil 2 [T], shape (members, 2) or (2,).
    magnetometer_matrix : array_like, optional
        Soft-iron, scale-factor and cross-axis matrix S [-], shape (members, 2, 2) or
        (2, 2), det S > 0: the magnetometer reads S·b + offset.
    magnetometer_misalignment : array_like, optional
        Angle by which the magnetometer's heading exceeds coil 1's [rad], in [−π, π].
    heading_ripple : array_like, optional
        Amplitude a [rad] of the field direction's deviation at the magnetometer,
        a·sin 2ψ (the second-order non-uniformity of a coil pair sampled on a circle).
    coil_misalignment : array_like, optional
        Rotation of each coil's axis from its body axis about the vertical [rad],
        shape (members, 2) or (2,), within ±π/4.
    coil_field_coupling : array_like, optional
        The coils' own field at the magnetometer per unit moment [T/(A·m²)]: it reads
        k·(M_x, M_y) of the moments held since the last sample.
    field_scale : array_like, optional
        Factor on ``setup.field`` per member [-], > 0.
    field_azimuth : array_like, optional
        Angle from the bench's reference axis (the simulator's) to the field the mock-up
        sees [rad], counted like ψ; the error band is then max |ψ + field_azimuth − ψ_des|,
        the error an observer sees against the bench.
    thread_neutral_angle : array_like, optional
        Angle at which the thread is untwisted, per member [rad]; default the setup's.
    filter_coefficient : array_like, optional
        A of eq. (39) per member, in [0, 1] [-]; default the setup's.
    pwm_levels : array_like, optional
        Duty steps each way per member, whole numbers ≥ 1 [-]; default the setup's.

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
    thesis §4.1) as laid out in the module docstring. At each sample k the
    sensors read the state at t_k, the controller sets the moments, and the plant
    advances to t_{k+1} with them held. The error band is
    max |ψ(t) − ψ_des| over the samples with t ≥ duration − window (and the final
    state): the thesis does not say what its 10° measures.

    Examples
    --------
    >>> from magbench.io import load_parameter_set
    >>> s = BenchSetup.from_parameters({k: p.value_si for k, p in load_parameter_set("thesis").items()})
    >>> run = simulate_bench(s, np.pi / 3, duration=120.0)
    >>> bool(run.error_band[0] < np.radians(1.0))
    True
    """
    psi_des = as_finite("psi_des", psi_des)
    if psi_des.ndim == 0:
        psi_des = float(psi_des)
    elif members is None:
        members = psi_des.size
    steps, window, members, psi, omega, kappa, scale, every, g_err, m_err = _loop_inputs(
        setup, duration, window, members, release_angle, release_rate, moment_scale, thread_stiffness,
        rng, sensor_errors, record_interval)
    if not isinstance(psi_des, float):
        psi_des = _member_array("psi_des", psi_des, members)
    err = _error_arrays(members, {
        "gyro_offset": gyro_offset, "gyro_drift": gyro_drift, "magnetometer_offset": magnetometer_offset,
        "magnetometer_matrix": magnetometer_matrix, "magnetometer_misalignment": magnetometer_misalignment,
        "heading_ripple": heading_ripple, "coil_misalignment": coil_misalignment,
        "coil_field_coupling": coil_field_coupling, "field_scale": field_scale,
        "field_azimuth": field_azimuth, "thread_neutral_angle": thread_neutral_angle,
        "filter_coefficient": filter_coefficient, "pwm_levels": pwm_levels})
    dt, b0 = setup.sample_interval, setup.field
    if err["field_scale"] is not None:
        b0 = b0 * err["field_scale"]
    plant = replace(setup.plant, thread_stiffness=kappa, field=b0)
    if err["thread_neutral_angle"] is not None:
        plant = replace(plant, thread_neutral_angle=err["thread_neutral_angle"])
    # Error sources as the loop applies them (None: the nominal model's arithmetic, untouched).
    g_off, g_drift = err["gyro_offset"], err["gyro_drift"]
    m_off, m_mat, m_rot, ripple = (err["magnetometer_offset"], err["magnetometer_matrix"],
                                   err["magnetometer_misalignment"], err["heading_ripple"])
    coupling, azimuth = err["coil_field_coupling"], err["field_azimuth"]
    coil_axes = None
    if err["coil_misalignment"] is not None:
        eta = err["coil_misalignment"]
        # Body components of unit moments along each misaligned coil: coil 1 at η1 from x,
        # coil 2 at 90° + η2 (so that zero misalignment is the plant's (m1, m2) exactly).
        coil_axes = (np.cos(eta[:, 0]), np.sin(eta[:, 0]), -np.sin(eta[:, 1]), np.cos(eta[:, 1]))
    ctrl_kw = {"filter_coefficient": err["filter_coefficient"], "pwm_levels": err["pwm_levels"]}
    applied = (np.zeros(members), np.zeros(members))   # body moments held before the first sample
    # Each member's actual full-scale moments (the controller divides by the nominal ones).
    full_actual = setup.full_scale_moments * scale                       # (members, 2)
    full_1, full_2 = np.ascontiguousarray(full_actual[:, 0]), np.ascontiguousarray(full_actual[:, 1])

    n_rec = steps // every + 1
    states = np.empty((2, n_rec, members))          # psi, rate
    moments = np.empty((2, n_rec, members))         # moment_1, moment_2
    estimates = np.empty((1, n_rec, members))
    band = np.zeros(members)
    band_est = np.zeros(members)
    first_in_window = int(np.ceil((steps * dt - window) / dt - 1e-9))
    estimate = None
    integral = np.zeros(members)
    state = np.array([psi, omega])
    loop = _CompiledLoop(setup, psi_des, b0, plant, err, coil_axes, full_1, full_2, members) \
        if _ENGINE == "compiled" else None
    for start in range(0, steps, _BLOCK):
        count = min(_BLOCK, steps - start)
        if sensor_errors is not None:
            g_blk, m_blk = g_err[start:start + count], m_err[start:start + count]
        else:
            g_blk, m_blk = draw_sensor_errors(setup, count, members, rng)
        if loop is not None:
            loop.run(start, count, state, g_blk, m_blk, band, band_est, first_in_window, every, states, moments,
                     estimates)
            estimate, (moment_1, moment_2) = loop.estimate, loop.commanded
            continue
        for j in range(count):
            k = start + j
            psi, omega = state
            gyro = omega + g_blk[j]
            if g_off is not None:
                gyro = gyro + g_off
            if g_drift is not None:
                gyro = gyro + g_drift * (k * dt)
            bx, by = b0 * np.cos(psi), -b0 * np.sin(psi)
            if m_rot is not None or ripple is not None:
                # The sensor reads the heading ψ + δ: the body field turned by −δ.
                delta = (0.0 if m_rot is None else m_rot) + (0.0 if ripple is None else ripple * np.sin(2 * psi))
                c, s = np.cos(delta), np.sin(delta)
                bx, by = bx * c + by * s, by * c - bx * s
            if m_mat is not None:
                bx, by = m_mat[:, 0, 0] * bx + m_mat[:, 0, 1] * by, m_mat[:, 1, 0] * bx + m_mat[:, 1, 1] * by
            if coupling is not None:
                bx, by = bx + coupling * applied[0], by + coupling * applied[1]
            if m_off is not None:
                bx, by = bx + m_off[:, 0], by + m_off[:, 1]
            bx, by = bx + m_blk[j, :, 0], by + m_blk[j, :, 1]
            moment_1, moment_2, estimate, integral = controller_step(
                setup, psi_des, gyro, bx, by, estimate, integral, full_1, full_2, **ctrl_kw)
            if k % every == 0:
                i = k // every
                states[:, i], estimates[0, i], moments[:, i] = state, estimate, (moment_1, moment_2)
            if k >= first_in_window:
                seen = psi if azimuth is None else psi + azimuth
                np.maximum(band, np.abs(wrap_angle(seen - psi_des)), out=band)
                np.maximum(band_est, np.abs(wrap_angle(estimate - psi_des)), out=band_est)
            if coil_axes is not None:
                applied = (moment_1 * coil_axes[0] + moment_2 * coil_axes[2],
                           moment_1 * coil_axes[1] + moment_2 * coil_axes[3])
            else:
                applied = (moment_1, moment_2)
            state = rk4_step(mockup_rhs, k * dt, state, dt, args=(applied, plant))
    if steps % every == 0:
        states[:, -1], estimates[0, -1], moments[:, -1] = state, estimate, (moment_1, moment_2)
    else:
        states, estimates, moments = states[:, :-1], estimates[:, :-1], moments[:, :-1]
    np.maximum(band, np.abs(wrap_angle(state[0] + (0.0 if azimuth is None else azimuth) - psi_des)), out=band)
    time = np.arange(states.shape[1]) * every * dt
    params = {"psi_des": psi_des, "window": window,
              "release_angle": _member_array("release_angle", release_angle, members),
              "release_rate": _member_array("release_rate", release_rate, members),
              "moment_scale": np.array(scale), "thread_stiffness": kappa}
    return SimulationResult(time, states, moments, estimates, ("psi", "rate"), ("moment_1", "moment_2"),
                            ("estimate",), params=params,
                            summary={"error_band": band, "indicated_error_band": band_est})


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
    >>> from magbench.io import load_parameter_set
    >>> s = BenchSetup.from_parameters({k: p.value_si for k, p in load_parameter_set("thesis").items()})
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


def monte_carlo(setup, psi_des, *, members, seed, duration, moment_tolerance, release_angle_spread,
                release_rate_std, thread_stiffness_factor, record_interval=None, window=20.0,
                release_angle=None, release_rate=0.0):
    r"""Seeded Monte Carlo of the bench over its uncertain inputs.

    Parameters
    ----------
    setup : BenchSetup
        The nominal bench [-].
    psi_des : float
        Target angle [rad].
    members : int
        Number of members [-].
    seed : int
        Seed of :func:`numpy.random.default_rng` [-]; the same seed gives the same run.
    duration : float
        Simulated time [s].
    moment_tolerance : float
        Each coil's moment is uniform in nominal·(1 ± tolerance) [-] (thesis: σ = 5 %).
    release_angle_spread : float
        Release angle uniform in centre ± spread [rad] (ours: the mock-up is turned by hand).
    release_rate_std : float
        Release rate normal about ``release_rate`` with this standard deviation [rad/s] (ours).
    thread_stiffness_factor : float
        Thread stiffness log-uniform in nominal ×/÷ factor [-], ≥ 1 (ours).
    record_interval : float, optional
        Spacing of the recorded traces [s].
    window : float, optional
        Final window of the error band [s].
    release_angle : float, optional
        Centre of the release angles [rad]; default ψ_des. A nominal run released at
        ``release_angle`` with ``release_rate`` is then the centre of the members' inputs.
    release_rate : float, optional
        Mean of the release rates [rad/s]; default 0.

    Returns
    -------
    SimulationResult
        All members, as :func:`simulate_bench` returns them; ``params`` holds the drawn
        values.

    Notes
    -----
    Not in the thesis: the thesis reports single runs with unstated initial conditions.
    Sensor noise is drawn from the same generator after the inputs.

    Examples
    --------
    >>> from magbench.io import load_parameter_set
    >>> s = BenchSetup.from_parameters({k: p.value_si for k, p in load_parameter_set("thesis").items()})
    >>> a = monte_carlo(s, 1.0, members=3, seed=1, duration=1.0, moment_tolerance=0.05,
    ...                 release_angle_spread=0.5, release_rate_std=0.01, thread_stiffness_factor=3.0,
    ...                 window=0.5)
    >>> b = monte_carlo(s, 1.0, members=3, seed=1, duration=1.0, moment_tolerance=0.05,
    ...                 release_angle_spread=0.5, release_rate_std=0.01, thread_stiffness_factor=3.0,
    ...                 window=0.5)
    >>> bool(np.array_equal(a.psi, b.psi))
    True
    """
    members = as_count("members", members)
    # Before the draws: a billion members would spend minutes drawing inputs first.
    check_member_steps(members, float(as_positive("duration", duration, unit="s")) / setup.sample_interval)
    tol = float(as_in_range("moment_tolerance", moment_tolerance, 0.0, 0.5))
    spread = float(as_in_range("release_angle_spread", release_angle_spread, 0.0, np.pi, unit="rad"))
    rate_std = float(as_nonnegative("release_rate_std", release_rate_std, unit="rad/s"))
    factor = float(as_in_range("thread_stiffness_factor", thread_stiffness_factor, 1.0, 1e6))
    centre = psi_des if release_angle is None else float(as_finite("release_angle", release_angle))
    mean_rate = float(as_finite("release_rate", release_rate))
    rng = np.random.default_rng(seed)
    scale = rng.uniform(1.0 - tol, 1.0 + tol, (members, 2))
    angle = centre + rng.uniform(-spread, spread, members)
    rate = mean_rate + rate_std * rng.standard_normal(members)
    stiffness = setup.thread_stiffness * np.exp(rng.uniform(-np.log(factor), np.log(factor), members))
    return simulate_bench(setup, psi_des, duration=duration, release_angle=angle, release_rate=rate,
                          members=members, moment_scale=scale, thread_stiffness=stiffness, rng=rng,
                          record_interval=record_interval, window=window)


def steady_error_band(run, quantile=None):
    r"""The error band of a run: per member, or a quantile over members.

    Parameters
    ----------
    run : SimulationResult
        A run of :func:`simulate_bench` [-].
    quantile : float, optional
        Quantile over members in [0, 1] [-]; default: the per-member values.

    Returns
    -------
    ndarray or float
        max |ψ − ψ_des| over the final window [rad].

    Notes
    -----
    Not in the thesis: the thesis's "absolute orientation error of 10°" (thesis §4.4)
    has no stated metric; this is the one used here.

    Examples
    --------
    >>> r = SimulationResult(np.zeros(1), np.zeros((0, 1, 2)), np.zeros((0, 1, 2)), np.zeros((0, 1, 2)),
    ...                      (), (), (), summary={"error_band": np.array([0.1, 0.3])})
    >>> round(float(steady_error_band(r, 0.5)), 6)
    0.2
    """
    if quantile is None:
        return run.error_band
    q = float(as_in_range("quantile", quantile, 0.0, 1.0))
    return float(np.quantile(run.error_band, q))
