"""The bench as data: its setup (:class:`BenchSetup`: mock-up, field, coils, driver, sensors
and controller) and how each Monte Carlo member's bench departs from it
(:class:`BenchErrors`: the coils' moments, the thread and the hardware error sources of
:data:`ERROR_INPUTS`). SI values throughout.
"""

from dataclasses import dataclass
from functools import cached_property

import numpy as np

from ... import hardware
from ..._validate import as_finite, as_in_range, as_nonnegative, as_positive, shown
from ...dynamics.pendulum import Mockup

__all__ = ["BenchSetup", "BenchErrors", "ERROR_INPUTS"]


@dataclass(frozen=True)
class BenchSetup:
    """The bench: mock-up, field, coils, driver, sensors and controller (SI values).

    The thesis's bench is :func:`magbench.chapters.ch04_mockup.bench_setup` of the chapter-4
    inputs; every field is documented with its unit and source there and in
    ``magbench/data/thesis/params.toml``.
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
        return hardware.coil_full_scale_moment(self.supply_voltage - self.driver_voltage_drop,
                                               np.asarray(self.coil_resistance, float), self.coil_turns,
                                               self.coil_side)

    @cached_property
    def moment_limit(self):
        """Largest moment the controller commands: the weaker coil's full scale [A·m²]."""
        return float(np.min(self.full_scale_moments))


@dataclass(frozen=True)
class BenchErrors:
    r"""How each member's bench departs from its :class:`BenchSetup` (per member, SI).

    Every field is a scalar for all members or an array with the members on its leading
    axis; :func:`simulate_bench` checks each against the number of members it runs.
    ``None`` leaves a source out, and the loop's arithmetic is then the nominal model's,
    untouched. The error budget (:mod:`magbench.sim.bench.budget`) sets them per Monte
    Carlo member.

    Parameters
    ----------
    moment_scale : array_like, optional
        Factor on each coil's full-scale moment [-], broadcast to (members, 2): a scalar
        for all, shape (2,) per coil, (members, 1) per member, (members, 2) for each.
    thread_stiffness : array_like, optional
        Torsion constant per member [N·m/rad]; default ``setup.thread_stiffness``.
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

    Notes
    -----
    Not in the thesis: the thesis names the thread, the sensors and the coils as causes
    of its 10° (thesis §4.4) without quantifying any. A frozen group, so that
    :func:`simulate_bench` takes one ``errors`` argument instead of fifteen keywords.
    """

    moment_scale: object = 1.0
    thread_stiffness: object = None
    gyro_offset: object = None
    gyro_drift: object = None
    magnetometer_offset: object = None
    magnetometer_matrix: object = None
    magnetometer_misalignment: object = None
    heading_ripple: object = None
    coil_misalignment: object = None
    coil_field_coupling: object = None
    field_scale: object = None
    field_azimuth: object = None
    thread_neutral_angle: object = None
    filter_coefficient: object = None
    pwm_levels: object = None

    def sources(self):
        """The error sources of :data:`ERROR_INPUTS` given here, name -> value (None: left out)."""
        return {name: getattr(self, name) for name in ERROR_INPUTS}


#: The hardware error sources of :class:`BenchErrors` (beside its moment scale and thread
#: stiffness): name -> (unit, trailing shape per member, what the default leaves out).
#: The error budget (magbench.sim.bench.budget) sets them per Monte Carlo member.
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
