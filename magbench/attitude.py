"""Compatibility module: the rotational dynamics moved to :mod:`magbench.dynamics`
(``energy_exchange`` and ``pendulum``).

Every public name is re-exported here so existing code keeps working; new code imports
from the family. This module goes once the book and tests have moved.
"""

from .dynamics.energy_exchange import momentum_exchange_energy_ratio, thesis_energy_ratio
from .dynamics.pendulum import (Mockup, amplitude_for_period, body_rates_313, euler_313_matrix,
                                field_for_period, natural_frequency, pendulum_energy, pendulum_peak_rate,
                                pendulum_period, pendulum_rhs, small_angle_period, thread_center_of_mass,
                                two_coil_rhs, two_coil_torque)

__all__ = ["momentum_exchange_energy_ratio", "thesis_energy_ratio", "two_coil_torque", "Mockup",
           "euler_313_matrix", "thread_center_of_mass", "body_rates_313", "pendulum_rhs", "two_coil_rhs",
           "pendulum_energy", "natural_frequency", "small_angle_period", "pendulum_period",
           "pendulum_peak_rate", "field_for_period", "amplitude_for_period"]
