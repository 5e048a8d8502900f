r"""Feedback control of the mock-up: laws as pure step functions and their linear analysis.

Thesis §4.1, eqs. (37)–(38): the PID law (:mod:`.pid`), the dipole allocation
L = m × B (:mod:`.allocation`), the loop's poles and limits (:mod:`.linear`) and the
readings of the thesis's unit-less gains (:mod:`.gain_readings`), and B-dot detumbling
(:mod:`.bdot`, SamSat-218D and Kovalenko ch. 6), the rotor spacecraft's spin laws (:mod:`.spin`,
rotor slides, and Kovalenko's relay spin law), Floquet analysis of periodic systems
(:mod:`.floquet`), stabilisation along B with Kovalenko's §6.5 estimates
(:mod:`.field_stabilisation`), Kovalenko's laws for unloading reaction wheels
(:mod:`.unloading`) and the rotor's stability map (:mod:`.rotor_stability`); their unchecked
array kernels are in :mod:`.kernels`. Re-exports the public names of its modules. The
simulated loop moved to :mod:`magbench.sim.pid_loop`; its names are still served from here,
imported on use.
"""

from .allocation import ALLOCATIONS, body_field_exact, body_field_small_angle, dipole_allocation
from .bdot import (avanzini_giulietti_gain, bdot_dipole, bdot_dipole_projected, held_bdot_rate_limit,
                   kovalenko_detumble_time, samsat_gain)
from .field_stabilisation import (capture_momentum, dry_detumble_time, dry_friction_torque, dry_transient_time,
                                   elastic_damper_response, orienting_dipole, orienting_dipole_per_axis,
                                   orienting_torque, pointing_dipole, pointing_torque, polar_disturbance_peak,
                                   polar_disturbance_ratio, polar_error_factor,
                                   polar_forced_response, polar_forcing_coefficients, steady_state_error_closed_form,
                                   steady_state_error_estimate, viscous_detumble_time)
from .floquet import degree_of_stability, finite_difference_monodromy, floquet_multipliers
from .gain_readings import GAIN_READINGS, gain_reading_scale
from .linear import (closed_loop_poles, closed_loop_polynomial, closed_loop_state_space, closed_loop_transfer,
                     critical_gain_scale, double_integrator_ultimate_gain, integral_gain_limit, open_loop_transfer)
from .pid import pid_gains_for_triple_pole, pid_step, ziegler_nichols_pid
from .rotor_stability import (rotor_floquet_multipliers, rotor_linearised_matrices, rotor_model_numbers,
                              rotor_stability_map)
from .unloading import (pulsed_unloading_dipole, relay_coil_unloading_dipole, relay_unloading_dipole, unloading_dipole,
                        unloading_torque)
from .spin import (momentum_damping_dipole, projected_damping_dipole, relay_spin_dipole,
                   rotor_equilibrium_axial_momentum, rotor_equilibrium_dipole, rotor_program_field,
                   rotor_reference_momentum, rotor_reference_torque, rotor_spin_reference,
                   slides_printed_damping_torque)

__all__ = ["pid_step", "pid_gains_for_triple_pole", "ALLOCATIONS", "body_field_exact", "body_field_small_angle",
           "dipole_allocation", "closed_loop_polynomial", "closed_loop_poles", "open_loop_transfer",
           "closed_loop_transfer", "closed_loop_state_space",
           "integral_gain_limit", "critical_gain_scale", "ziegler_nichols_pid",
           "double_integrator_ultimate_gain", "GAIN_READINGS", "gain_reading_scale", "bdot_dipole",
           "bdot_dipole_projected", "avanzini_giulietti_gain", "samsat_gain", "kovalenko_detumble_time",
           "held_bdot_rate_limit",
           "rotor_program_field", "rotor_equilibrium_dipole", "rotor_equilibrium_axial_momentum",
           "rotor_reference_torque", "rotor_spin_reference", "projected_damping_dipole", "slides_printed_damping_torque",
           "rotor_reference_momentum", "momentum_damping_dipole", "relay_spin_dipole", "floquet_multipliers",
           "finite_difference_monodromy", "degree_of_stability", "rotor_model_numbers", "rotor_linearised_matrices",
           "rotor_floquet_multipliers", "rotor_stability_map", "orienting_dipole", "orienting_torque", "pointing_dipole", "pointing_torque",
           "polar_disturbance_ratio",
           "orienting_dipole_per_axis", "viscous_detumble_time", "dry_detumble_time", "dry_friction_torque",
           "capture_momentum", "dry_transient_time", "polar_forcing_coefficients", "polar_forced_response",
           "elastic_damper_response", "polar_error_factor", "polar_disturbance_peak", "steady_state_error_estimate",
           "steady_state_error_closed_form", "unloading_dipole", "unloading_torque", "relay_unloading_dipole",
           "relay_coil_unloading_dipole", "pulsed_unloading_dipole"]
