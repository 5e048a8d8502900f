"""Chapter 7's dispersion study ``capture``: TNS-0's magnet and hysteresis rods from a flat
spin at Table 1's first angular momentum, over the unknown initial direction of L
(:mod:`magbench.sim.dispersion`). Its first ``capture_members`` members are the book's
capture Monte Carlo (:func:`magbench.chapters.ch07_tns0.capture_run`)."""

from functools import partial

import numpy as np

from ...sim import passive_final_regime, simulate_passive
from ...sim.dispersion import DispersedInput, DispersionStudy, Outcome
from .._base import study_parameters

__all__ = ["CAPTURE", "draw_momentum_direction"]


def draw_momentum_direction(rng):
    """One member's initial direction of L: uniform on the sphere, a unit vector [-]."""
    v = rng.normal(size=3)
    return v / np.linalg.norm(v)


def _draw(p, rng):
    u = draw_momentum_direction(rng)
    return {"L_x": u[0], "L_y": u[1], "L_z": u[2]}


def _simulate(p, columns, rngs):
    from . import SAMPLE_INTERVAL, tns0_orbit, tns0_satellite

    direction = np.stack([columns["L_x"], columns["L_y"], columns["L_z"]], axis=-1)
    members = direction.shape[0]
    satellite, orbit = tns0_satellite(p), tns0_orbit(p)
    run = simulate_passive(satellite, orbit, np.full(members, p["capture_initial_momentum"]),
                           p["capture_initial_nutation"], direction, p["capture_duration"],
                           sample_interval=SAMPLE_INTERVAL)
    final = passive_final_regime(run, satellite, orbit, orbits=3)
    return {"final_angle": np.atleast_1d(final["final_angle"]), "final_rate": np.atleast_1d(final["final_rate"]),
            "final_momentum": np.atleast_1d(final["final_momentum"])}


CAPTURE = DispersionStudy(
    name="capture",
    description=("TNS-0's passive system (a magnet and four hysteresis rods) from a flat spin at "
                 "capture_initial_momentum, capture_duration long, over the unknown initial direction of L"),
    chapter="ch07",
    inputs=(DispersedInput("momentum_direction", "1", ("L_x", "L_y", "L_z"),
                           "unit vector uniform on the sphere, inertial axes"),),
    outcomes=(
        Outcome("final_angle", "rad", "angle between B and the symmetry axis, mean over the last orbit"),
        Outcome("final_rate", "rad/s", "|ω|, mean over the last orbit"),
        Outcome("final_momentum", "kg m^2/s", "|L|, mean over the last orbit"),
    ),
    parameters=partial(study_parameters, "ch07"),
    draw=_draw,
    simulate=_simulate,
)
