"""Compatibility module: the sensor models moved to :mod:`magbench.hardware.sensors`."""

from .hardware.sensors import *  # noqa: F403 - the re-export is the point
from .hardware.sensors import __all__
