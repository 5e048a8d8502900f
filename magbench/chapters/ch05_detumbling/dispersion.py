"""Chapter 5's dispersion study ``detumble``: the 3U envelope of Basilisk and Cp557 over
random attitudes, initial rates and orbit phases (:mod:`magbench.sim.dispersion`).

Its first members are the book's envelope distribution (:func:`.study.envelope_distribution`
draws them from the same per-member streams at ``envelope_seed``).
"""

from dataclasses import replace
from functools import partial

import numpy as np

from ...sim import detumble_time, draw_detumble_member, simulate_detumble
from ...sim.dispersion import DispersedInput, DispersionStudy, Outcome
from .._base import study_parameters

__all__ = ["DETUMBLE", "HOLD"]

#: How long |ω| must stay under the threshold for ``held_time`` [s] (the envelope's dwell).
HOLD = 30.0


def _draw(p, rng):
    q, w, phase = draw_detumble_member(rng, (p["envelope_rate_low"], p["envelope_rate_high"]))
    return {"q_w": q[0], "q_x": q[1], "q_y": q[2], "q_z": q[3], "rate_x": w[0], "rate_y": w[1], "rate_z": w[2],
            "orbit_phase": phase}


def _simulate(p, columns, rngs):
    from .study import envelope_orbit, inertia

    orbit = envelope_orbit(p)
    attitude = np.stack([columns[c] for c in ("q_w", "q_x", "q_y", "q_z")], axis=-1)
    rate = np.stack([columns[c] for c in ("rate_x", "rate_y", "rate_z")], axis=-1)
    run = simulate_detumble(inertia(p), replace(orbit, argument_of_latitude0=orbit.argument_of_latitude0
                                                + columns["orbit_phase"]),
                            attitude, rate, p["envelope_duration"], gain=p["envelope_gain"],
                            max_dipole=p["max_dipole"], step=p["integration_step"])
    threshold = p["detumble_threshold"]
    return {"detumble_time": detumble_time(run.time, run.rate, threshold),
            "held_time": detumble_time(run.time, run.rate, threshold, HOLD),
            "final_rate": run.rate[:, -1]}


DETUMBLE = DispersionStudy(
    name="detumble",
    description=("B-dot detumbling of the 3U envelope (Basilisk's and Cp557's): continuous law, saturated "
                 "torquers, gravity gradient, a tilted dipole turning with the Earth; random attitude, rate "
                 "axis, rate magnitude and orbit phase"),
    chapter="ch05",
    inputs=(
        DispersedInput("attitude", "1", ("q_w", "q_x", "q_y", "q_z"),
                       "uniform on the rotations (scipy's Rotation.random), scalar first"),
        DispersedInput("rate", "rad/s", ("rate_x", "rate_y", "rate_z"),
                       "axis uniform on the sphere, |ω| uniform in [envelope_rate_low, envelope_rate_high]",
                       ("envelope_rate_low", "envelope_rate_high")),
        DispersedInput("orbit_phase", "rad", ("orbit_phase",), "argument of latitude at t = 0, uniform in [0, 2π)"),
    ),
    outcomes=(
        Outcome("detumble_time", "s", "first time |ω| ≤ detumble_threshold (NaN: not within envelope_duration)"),
        Outcome("held_time", "s", f"first time |ω| ≤ detumble_threshold and stays there {HOLD:g} s"),
        Outcome("final_rate", "rad/s", "|ω| at envelope_duration"),
    ),
    parameters=partial(study_parameters, "ch05"),
    draw=_draw,
    simulate=_simulate,
)
