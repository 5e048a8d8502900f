"""Compatibility module: the magnetorquer formulas moved to :mod:`magbench.hardware`
(``turn``, ``magnetorquer``, ``coil_design``, ``cores``, ``magnets``).

Every public name is re-exported here so existing code keeps working; new code imports
from the family. This module goes once the book and tests have moved.
"""

from .hardware import *  # noqa: F403 - the re-export is the point
from .hardware.coil_design import __all__ as _design
from .hardware.cores import __all__ as _cores
from .hardware.magnetorquer import __all__ as _magnetorquer
from .hardware.magnets import __all__ as _magnets
from .hardware.turn import __all__ as _turn

__all__ = [*_turn, *_magnetorquer, *_design, *_cores, *_magnets]
