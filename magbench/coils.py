"""Compatibility module: the coil fields moved to :mod:`magbench.fields`, the windings to
:mod:`magbench.hardware`, the swing field of thesis eq. (15) to :mod:`magbench.dynamics`
and the thesis's slipped eq. (16) to :mod:`magbench.chapters.ch02_field_simulator`.

Every public name is re-exported here so existing code keeps working; new code imports
from the families. This module goes once the book and tests have moved.
"""

from .dynamics.swing import oscillation_field_h
from .fields import *  # noqa: F403 - the re-export is the point
from .fields import __all__ as _fields_all
from .fields.systems import _DIRS  # noqa: F401 - used by the chapter-2 figures
from .hardware.winding import winding_mass, winding_power, winding_resistance, winding_voltage



def __getattr__(name):
    # Imported on use only: the chapter layer reads data files, which physics must not.
    if name == "thesis_printed_ampere_turns":
        from .chapters.ch02_field_simulator import thesis_printed_ampere_turns

        return thesis_printed_ampere_turns
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


__all__ = [*_fields_all, "thesis_printed_ampere_turns", "oscillation_field_h", "winding_resistance",
           "winding_voltage", "winding_power", "winding_mass"]
