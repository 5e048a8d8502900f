"""Hardware that makes or measures a field: windings (for now, of round turns).

Re-exports the public functions of its modules. The magnetorquer's sizing formulas
still live in :mod:`magbench.magnetorquer`.
"""

from .winding import winding_mass, winding_power, winding_resistance, winding_voltage

__all__ = ["winding_resistance", "winding_voltage", "winding_power", "winding_mass"]
