"""Compatibility module: the bench loop moved to :mod:`magbench.sim.bench`."""

from .sim.bench import *  # noqa: F403 - the re-export is the point
from .sim.bench import __all__ as _moved
from .sim.result import SimulationResult as BenchRun  # the old name of the one result type

__all__ = [*_moved, "BenchRun"]
