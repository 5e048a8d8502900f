"""Simulations composed from the physics families: one integrator (:func:`rk4_step`), one
result type (:class:`SimulationResult`), the mock-up's PID loop (:mod:`.pid_loop`) and the
bench loop (:mod:`.bench`), B-dot detumbling on orbit (:mod:`.detumble`) and the passive magnetic satellite
(:mod:`.passive`).

Re-exports the integrator, the result type, detumbling and the passive satellite; the loops are imported from their
modules.
"""

from .detumble import DetumbleRun, detumble_monte_carlo, detumble_time, simulate_detumble
from .integrate import rk4_step
from .passive import PassiveRun, PassiveSatellite, initial_passive_state, simulate_passive
from .result import SimulationResult

__all__ = ["rk4_step", "SimulationResult", "DetumbleRun", "simulate_detumble", "detumble_time",
           "detumble_monte_carlo",
           "PassiveSatellite", "PassiveRun", "simulate_passive", "initial_passive_state"]
