r"""Closed-loop simulation of the thesis's bench experiments (thesis §4.2–4.4, Figs. 19–20).

The mock-up hangs on a thread inside the Helmholtz field simulator and turns about the
vertical only. This package puts the physics modules together into the loop that ran on
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
horizontal background (the Earth's) at a given azimuth.

The thesis's gains (K_p = 0.1, K_d = 0.5, K_i = 0.5, thesis §4.4) make the loop
unstable when read in SI (the thesis states no units for them; see
:func:`magbench.control.integral_gain_limit`); the bench default gains here come from
:func:`magbench.control.pid_gains_for_triple_pole` with a bandwidth of ours.

The package's modules: :mod:`.config` (the bench as data: :class:`BenchSetup`,
:class:`BenchErrors`), :mod:`.controller` (one sample of the controller, the sensors'
errors), :mod:`.loop` (:func:`simulate_bench` and its compiled twin's driver),
:mod:`.reference` (the solve_ivp oracle), :mod:`.dispersion` (the Monte Carlo), :mod:`.budget`
(the error budget over scalar hardware error sources: one at a time and Sobol indices). The
physics it composes lives in the families: :func:`magbench.fields.horizontal_field`,
:func:`magbench.hardware.coil_full_scale_moment`, :func:`magbench.hardware.quantise_duty`,
:func:`magbench.dynamics.plant_step`; they are re-exported here.
"""

from ...dynamics.pendulum import plant_step
from ...fields.systems import horizontal_field
from ...hardware.driver import coil_full_scale_moment, quantise_duty
from .budget import (SAMPLE_INTERVALS, from_unit_cube, nominal_source_values, one_at_a_time, sobol_analysis,
                     sobol_budget, sobol_design, source_error_bands)
from .config import ERROR_INPUTS, BenchErrors, BenchSetup
from .controller import controller_step, draw_sensor_errors
from .dispersion import BenchDispersion, draw_bench_member, monte_carlo, steady_error_band
from .loop import simulate_bench
from .reference import simulate_bench_reference

__all__ = ["BenchSetup", "BenchErrors", "BenchDispersion", "controller_step", "horizontal_field",
           "coil_full_scale_moment", "quantise_duty", "plant_step", "simulate_bench", "simulate_bench_reference",
           "monte_carlo", "draw_bench_member", "steady_error_band", "draw_sensor_errors", "ERROR_INPUTS", "SAMPLE_INTERVALS",
           "nominal_source_values", "source_error_bands", "one_at_a_time", "from_unit_cube", "sobol_design",
           "sobol_analysis", "sobol_budget"]
