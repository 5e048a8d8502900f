"""Simulations composed from the physics families: one integrator (:func:`rk4_step`), one
result type (:class:`SimulationResult`), the mock-up's free swing (:mod:`.free_swing`), its PID loop
(:mod:`.pid_loop`) and the
bench loop (the :mod:`.bench` package), B-dot detumbling on orbit (:mod:`.detumble`, in segments
whose step follows the rate: :mod:`.detumble_segments`), the spinning spacecraft with a coaxial rotor
(:mod:`.spinning`, its normalised model :mod:`.rotor_normalised`, the turning-field run
:mod:`.turning_field`, its variants beyond the slides :mod:`.rotor_variants`), Kovalenko's relay spin
correction (:mod:`.spin_correction`) and the passive magnetic satellite (:mod:`.passive`, its flat
spin's energy balance :mod:`.passive_balance`, its final regime :mod:`.passive_regime`), and the planar pitch motion of a magnet-held body on a
magnetopolar orbit (:mod:`.planar`), and the gravity-gradient boom with a magnetic libration
damper (:mod:`.libration`), and the wheel-stabilised spacecraft whose wheels magnetorquers
unload (:mod:`.wheels`); and the dispersion studies that run any of them over many members
on any executor (:mod:`.dispersion`).

Re-exports the integrator, the result type, the mock-up's PID loop, detumbling, the spinning
spacecraft and the passive satellite; the bench loop is imported from its package.
"""

from .detumble import DetumbleRun, detumble_monte_carlo, detumble_time, draw_detumble_member, simulate_detumble
from .dispersion import (DispersedInput, DispersionError, DispersionStudy, DispersionTable, Outcome,
                         dispersion_statistics, member_generators, run_dispersion)
from .detumble_segments import DETUMBLE_STEPS, detumble_step, simulate_detumble_segments
from ..integrate import rk4_step
from .free_swing import integrated_swing_period, simulate_free_swing
from .pid_loop import PidLoop, loop_torque, pid_continuous_rhs, simulate_pid
from .passive import PassiveRun, PassiveSatellite, initial_passive_state, simulate_passive
from .passive_regime import orbit_mean_field, passive_final_regime, passive_transition_times
from .passive_balance import flat_spin_decay_rate
from .libration import LibrationSatellite, simulate_libration
from .planar import planar_error_orbit_maxima, simulate_planar
from .result import SimulationResult
from .spinning import (RotorRun, RotorSatellite, rotor_body_rhs, rotor_dimensionless, rotor_finite_difference_monodromy,
                       rotor_floquet_multipliers, rotor_gain_scales, rotor_linearised_matrices, rotor_normalised_rhs,
                       rotor_satellite_from_dimensionless, rotor_stability_map, simulate_rotor,
                       simulate_rotor_normalised, simulate_turning_field_gyrostat)
from .rotor_variants import (maxima_per_orbit, normalised_pointing_error, pointing_error_orbit_maxima,
                             reference_momentum_rate_offset, rotor_satellite_with_products,
                             symmetric_rotor_orbit_maxima, tilted_dipole_pointing_error, transverse_asymmetry,
                             transverse_inertia_with_asymmetry)
from .spin_correction import relay_spin_correction, relay_spin_torque_over_turn
from .wheels import (DisturbanceTorque, UnloadingLaw, WheelSatellite, simulate_coil_detumbling, simulate_ideal_unloading,
                     simulate_unloading)
from .turning_field import turning_field_kinetic_energy

__all__ = ["rk4_step", "SimulationResult", "simulate_free_swing", "integrated_swing_period", "PidLoop", "loop_torque", "pid_continuous_rhs", "simulate_pid", "DetumbleRun", "simulate_detumble", "detumble_time",
           "detumble_monte_carlo", "draw_detumble_member", "DispersedInput", "Outcome", "DispersionStudy",
           "DispersionTable", "DispersionError", "member_generators", "run_dispersion", "dispersion_statistics",
           "DETUMBLE_STEPS", "detumble_step", "simulate_detumble_segments",
           "PassiveSatellite", "PassiveRun", "simulate_passive", "initial_passive_state", "flat_spin_decay_rate",
           "orbit_mean_field", "passive_final_regime", "passive_transition_times",
           "RotorSatellite", "RotorRun", "rotor_dimensionless", "rotor_gain_scales",
           "rotor_satellite_from_dimensionless", "rotor_normalised_rhs", "rotor_linearised_matrices",
           "rotor_floquet_multipliers", "rotor_stability_map", "rotor_finite_difference_monodromy",
           "simulate_rotor_normalised", "rotor_body_rhs", "simulate_rotor", "simulate_turning_field_gyrostat",
           "turning_field_kinetic_energy", "transverse_asymmetry", "transverse_inertia_with_asymmetry",
           "rotor_satellite_with_products", "reference_momentum_rate_offset", "normalised_pointing_error",
           "maxima_per_orbit", "pointing_error_orbit_maxima", "tilted_dipole_pointing_error",
           "symmetric_rotor_orbit_maxima", "relay_spin_correction", "relay_spin_torque_over_turn",
           "simulate_planar", "planar_error_orbit_maxima", "LibrationSatellite", "simulate_libration",
           "WheelSatellite", "UnloadingLaw", "DisturbanceTorque", "simulate_unloading",
           "simulate_ideal_unloading", "simulate_coil_detumbling"]
