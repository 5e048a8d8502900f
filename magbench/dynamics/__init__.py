"""Equations of motion and what follows from them: torques on a dipole, the swing of a
suspended magnet (thesis §2.1). Re-exports the public functions of its modules.

The mock-up's equations of motion still live in :mod:`magbench.attitude`.
"""

from .swing import oscillation_field_h
from .torques import magnetic_torque, magnetic_torque_from_h, perpendicular_moment

__all__ = ["oscillation_field_h", "magnetic_torque", "magnetic_torque_from_h", "perpendicular_moment"]
