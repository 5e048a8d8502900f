"""Simulations composed from the physics families: one integrator (:func:`rk4_step`), one
result type (:class:`SimulationResult`), the mock-up's PID loop (:mod:`.pid_loop`) and the
bench loop (:mod:`.bench`), and B-dot detumbling on orbit (:mod:`.detumble`).

Re-exports the integrator, the result type and detumbling; the loops are imported from their
modules.
"""

from .detumble import DetumbleRun, detumble_monte_carlo, detumble_time, simulate_detumble
from .integrate import rk4_step
from .result import SimulationResult

__all__ = ["rk4_step", "SimulationResult", "DetumbleRun", "simulate_detumble", "detumble_time",
           "detumble_monte_carlo"]
