"""Simulations composed from the physics families: one integrator (:func:`rk4_step`), one
result type (:class:`SimulationResult`), the mock-up's PID loop (:mod:`.pid_loop`) and the
bench loop (:mod:`.bench`).

Re-exports the integrator and the result type; the loops are imported from their modules.
"""

from .integrate import rk4_step
from .result import SimulationResult

__all__ = ["rk4_step", "SimulationResult"]
