"""Equations of motion and what follows from them: the mock-up on a thread (thesis §4.1),
the swing of a suspended magnet (thesis §2.1), torques on a dipole (thesis §1.2), and the
exchange of momentum and energy with the Earth (thesis §1.3), and the rigid spacecraft on
orbit with SamSat-218D's attitude angles (chapter 5), the gyrostat with a coaxial rotor of the
rotor slides (chapter 6), the axisymmetric body of TNS-0 (chapter 7), the planar motion of a magnet-stabilised body on a
magnetopolar orbit (Kovalenko §6.4). Pure functions, SI.

Re-exports the public names of its modules.
"""

from .aerodynamic_angles import aerodynamic_angles, aerodynamic_attitude_matrix, aerodynamic_body_rates
from .gyrostat import (airplane_231_angles, airplane_231_matrix, gyrostat_kinetic_energy, gyrostat_momentum,
                       gyrostat_rates, gyrostat_rhs, gyrostat_turning_field_rhs, rotor_dimensionless_numbers,
                       rotor_reduced_rhs, semi_body_axes, semi_body_field, semi_body_rhs)
from .eddy import (anisotropic_eddy_torque, cylinder_eddy_coefficients, eddy_despin_time_constant, eddy_torque,
                   eddy_torque_components, shell_despin_time_constant, solid_sphere_eddy_coefficient,
                   spherical_shell_eddy_coefficient,
                   spherical_shell_eddy_torque, spherical_shell_time_constant)
from .dampers import (dry_friction_damper_torque, spherical_damper_energy, spherical_damper_rhs,
                      viscous_damper_torque)
from .energy_exchange import momentum_exchange_energy_ratio, thesis_energy_ratio
from .pendulum import (Mockup, amplitude_for_period, body_rates_313, euler_313_matrix, field_for_period,
                       mockup_loads, mockup_rhs, natural_frequency, pendulum_energy, pendulum_peak_rate, pendulum_period, pendulum_rhs,
                       plant_step, small_angle_period, thread_center_of_mass, two_coil_rhs, two_coil_torque)
from .libration import libration_angles
from .planar import PlanarBody, PlanarDamper, planar_energy, planar_gravity_torque, planar_rhs
from .rigid_body import euler_rates, gravity_gradient_torque, quaternion_rate, rotate_to_body, rotate_to_inertial
from .swing import oscillation_field_h, oscillation_moment
from .torques import (axial_magnet_torque, hysteresis_rod_moment, magnetic_torque, magnetic_torque_from_h,
                      perpendicular_moment)
from .axisymmetric import (body_rate_from_momentum, conical_rotation_angle, conical_rotation_rate, euler_case_angles,
                           euler_case_matrix, euler_case_rates, momentum_and_nutation)

__all__ = ["libration_angles", "momentum_exchange_energy_ratio", "thesis_energy_ratio", "two_coil_torque", "Mockup",
           "euler_313_matrix", "thread_center_of_mass", "mockup_loads", "body_rates_313", "pendulum_rhs", "two_coil_rhs", "mockup_rhs", "plant_step",
           "pendulum_energy", "natural_frequency", "small_angle_period", "pendulum_period",
           "pendulum_peak_rate", "field_for_period", "amplitude_for_period", "magnetic_torque",
           "magnetic_torque_from_h", "perpendicular_moment", "oscillation_field_h", "oscillation_moment",
           "rotate_to_body", "rotate_to_inertial", "quaternion_rate", "euler_rates", "gravity_gradient_torque",
           "aerodynamic_attitude_matrix", "aerodynamic_angles", "aerodynamic_body_rates", "hysteresis_rod_moment",
           "axial_magnet_torque", "euler_case_rates", "euler_case_angles", "euler_case_matrix",
           "body_rate_from_momentum", "momentum_and_nutation", "conical_rotation_angle", "conical_rotation_rate",
           "airplane_231_matrix", "airplane_231_angles", "semi_body_axes", "semi_body_field", "gyrostat_rates",
           "gyrostat_rhs", "gyrostat_turning_field_rhs", "gyrostat_kinetic_energy", "gyrostat_momentum", "semi_body_rhs", "rotor_reduced_rhs",
           "rotor_dimensionless_numbers", "eddy_torque", "eddy_torque_components", "anisotropic_eddy_torque",
           "spherical_shell_eddy_coefficient", "spherical_shell_time_constant", "spherical_shell_eddy_torque",
           "solid_sphere_eddy_coefficient", "cylinder_eddy_coefficients", "eddy_despin_time_constant",
           "shell_despin_time_constant",
           "viscous_damper_torque", "dry_friction_damper_torque", "spherical_damper_rhs", "spherical_damper_energy",
           "PlanarBody", "PlanarDamper", "planar_rhs", "planar_gravity_torque", "planar_energy"]
