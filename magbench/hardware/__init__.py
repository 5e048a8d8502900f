"""Hardware that makes or measures a field: turns and wires, air-core magnetorquers and
their design space, the bench's coil driver (full-scale moment, PWM duty), windings, cored
rods and electromagnets, permanent magnets, hysteresis rods and their design, and the sensors (datasheet
error models, cosine-law sun sensors).

Pure functions of numpy arrays, SI. Re-exports the public functions of its modules.
"""

from .sensors import (HMC5883L_GAINS, HMC5883L_MAX_COUNT, HMC5883L_MAX_OUTPUT_RATE, HMC5883L_NOISE_FLOOR, MPU6050_ACCEL_NOISE_DENSITY,
                      MPU6050_ACCEL_ZERO_G_TOLERANCE, MPU6050_DLPF_BANDWIDTH, MPU6050_GYRO_NOISE_DENSITY,
                      MPU6050_GYRO_TOTAL_RMS_NOISE, MPU6050_GYRO_ZRO_TOLERANCE, accelerometer_readings,
                      gyro_readings, heading_readings, magnetometer_full_scale, magnetometer_readings,
                      noise_std_from_density, roll_readings)
from .turn import SHAPES, Turn, WireSizes, awg_diameter, turn_area, turn_length, wire_area, wire_diameter
from .magnetorquer import (coil_current, coil_mass, coil_mass_for_moment, coil_resistance,
                           current_for_moment, dipole_moment, joule_power, joule_power_for_moment,
                           joule_power_for_winding_length, mass_power_product,
                           mass_power_product_kovalenko, moment_from_voltage, supply_voltage,
                           turn_resistance, turns_from_winding_length, winding_density, winding_length,
                           wire_area_for_moment)
from .coil_sizing import (turns_from_resistance, turns_per_layer, turns_per_volt_bounds, winding_band,
                          wire_diameter_from_resistance, wire_turn_limits)
from .driver import coil_full_scale_moment, quantise_duty
from .coil_design import binding_limit, coil_designs, design_magnetorquer
from .cores import (core_central_magnetization, effective_permeability, electromagnet_design, electromagnet_moment,
                    field_for_magnetization, magnetization_curve, rod_demagnetizing_factor)
from .magnets import (magnet_mass_for_torque, magnet_moment_per_mass, magnet_torque_per_mass,
                      permanent_magnet_min_mass)
from .eddy_losses import (rod_eddy_power, rod_eddy_profile_coefficient, rod_eddy_torque, rod_eddy_torque_from_field,
                          rod_to_shell_eddy_ratio, shell_eddy_torque, winding_damping_torque, winding_parameter)
from .hysteresis import (hysteresis_damping_torque, hysteresis_loop_energy, hysteresis_response,
                         hysteresis_slope, limb_constants, limb_induction, limiting_loop_energy,
                         rod_cycle_energy, settled_hysteresis_loop)
from .rod_design import (despin_torque_required, parallel_rod_demagnetizing_ratio, parallel_rod_mutual_factor,
                         prolate_demagnetizing_factor, rod_central_loop_energy, rod_count_required,
                         rod_optimal_elongation, rod_torque_per_length_cubed, rod_volume_required,
                         rayleigh_central_loop_energy, rayleigh_optimal_demagnetizing_factor)
from .winding import (ampere_turns_power, coaxial_system_scale_for_power, helmholtz_pair_power, winding_mass,
                      winding_power, winding_resistance, winding_voltage)

__all__ = ["rod_eddy_profile_coefficient", "rod_eddy_power", "rod_eddy_torque", "rod_eddy_torque_from_field",
           "shell_eddy_torque", "rod_to_shell_eddy_ratio", "winding_parameter", "winding_damping_torque",
           "limb_constants", "limb_induction", "hysteresis_slope", "hysteresis_response", "hysteresis_loop_energy",
           "rod_cycle_energy", "settled_hysteresis_loop", "limiting_loop_energy", "hysteresis_damping_torque",
           "rod_volume_required", "rod_count_required", "despin_torque_required", "rod_central_loop_energy",
           "rod_torque_per_length_cubed", "rod_optimal_elongation", "rayleigh_central_loop_energy",
           "rayleigh_optimal_demagnetizing_factor", "prolate_demagnetizing_factor",
           "parallel_rod_mutual_factor", "parallel_rod_demagnetizing_ratio",
           "SHAPES", "Turn", "WireSizes", "turn_area", "turn_length", "wire_area", "wire_diameter", "awg_diameter",
           "dipole_moment", "current_for_moment", "coil_current", "turn_resistance", "coil_resistance",
           "moment_from_voltage", "wire_area_for_moment", "joule_power", "joule_power_for_moment",
           "turns_from_winding_length", "winding_length", "joule_power_for_winding_length", "coil_mass",
           "coil_mass_for_moment", "mass_power_product", "winding_density", "mass_power_product_kovalenko",
           "supply_voltage", "turns_per_volt_bounds", "turns_from_resistance",
           "wire_diameter_from_resistance", "coil_full_scale_moment", "quantise_duty", "coil_designs", "binding_limit",
           "design_magnetorquer", "rod_demagnetizing_factor", "effective_permeability",
           "magnetization_curve", "field_for_magnetization", "core_central_magnetization",
           "electromagnet_design", "electromagnet_moment", "turns_per_layer", "winding_band", "wire_turn_limits",
           "magnet_torque_per_mass", "magnet_mass_for_torque",
           "magnet_moment_per_mass", "permanent_magnet_min_mass", "winding_resistance", "winding_voltage",
           "winding_power", "winding_mass", "ampere_turns_power", "coaxial_system_scale_for_power",
           "helmholtz_pair_power",
           "MPU6050_GYRO_NOISE_DENSITY", "MPU6050_GYRO_TOTAL_RMS_NOISE",
           "MPU6050_GYRO_ZRO_TOLERANCE", "MPU6050_ACCEL_NOISE_DENSITY", "MPU6050_ACCEL_ZERO_G_TOLERANCE",
           "MPU6050_DLPF_BANDWIDTH", "HMC5883L_NOISE_FLOOR", "HMC5883L_MAX_OUTPUT_RATE", "HMC5883L_GAINS", "HMC5883L_MAX_COUNT",
           "noise_std_from_density", "gyro_readings", "accelerometer_readings", "magnetometer_readings", "magnetometer_full_scale",
           "roll_readings", "heading_readings"]
from .sun_sensor import sun_sensor_signals
