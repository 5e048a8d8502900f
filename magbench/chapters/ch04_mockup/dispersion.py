"""Chapter 4's dispersion study ``bench``: the mock-up's closed loop (Fig. 19's target,
ψ_des = π/3) over its coils' moments, the hand release and the thread's stiffness, with
datasheet sensor noise (:mod:`magbench.sim.dispersion`)."""

from functools import partial

import numpy as np

from ...sim.bench import BenchErrors, draw_bench_member, simulate_bench
from ...sim.dispersion import DispersedInput, DispersionStudy, Outcome
from .._base import study_parameters
from .models import bench_dispersion, bench_setup

__all__ = ["BENCH", "TARGET"]

#: The target of the study: Fig. 19's ψ_des [rad].
TARGET = np.pi / 3.0


def _draw(p, rng):
    scale, angle, rate, stiffness = draw_bench_member(rng, bench_dispersion(p), TARGET, 0.0,
                                                      p["bench_thread_stiffness"])
    return {"moment_scale_1": scale[0], "moment_scale_2": scale[1], "release_angle": angle, "release_rate": rate,
            "thread_stiffness": stiffness}


def _simulate(p, columns, rngs):
    scale = np.stack([columns["moment_scale_1"], columns["moment_scale_2"]], axis=-1)
    run = simulate_bench(bench_setup(p), TARGET, duration=p["bench_duration"], release_angle=columns["release_angle"],
                         release_rate=columns["release_rate"], members=len(rngs),
                         errors=BenchErrors(moment_scale=scale, thread_stiffness=columns["thread_stiffness"]),
                         rng=list(rngs), record_interval=p["bench_duration"], window=p["bench_error_window"])
    return {"error_band": run.error_band, "indicated_error_band": run.indicated_error_band}


BENCH = DispersionStudy(
    name="bench",
    description=("the mock-up's closed loop (thesis §4: complementary filter, PID, two coils, PWM) released by hand "
                 "near ψ_des = 60° (Fig. 19), bench_duration long, with datasheet sensor noise"),
    chapter="ch04",
    inputs=(
        DispersedInput("moment_scale", "1", ("moment_scale_1", "moment_scale_2"),
                       "each coil's moment over its nominal, uniform in 1 ± bench_moment_tolerance",
                       ("bench_moment_tolerance",)),
        DispersedInput("release_angle", "rad", ("release_angle",),
                       "uniform in ψ_des ± bench_release_angle_spread", ("bench_release_angle_spread",)),
        DispersedInput("release_rate", "rad/s", ("release_rate",), "normal, mean 0, std bench_release_rate_std",
                       ("bench_release_rate_std",)),
        DispersedInput("thread_stiffness", "N m/rad", ("thread_stiffness",),
                       "log-uniform in bench_thread_stiffness ×/÷ bench_thread_stiffness_factor",
                       ("bench_thread_stiffness", "bench_thread_stiffness_factor")),
    ),
    outcomes=(
        Outcome("error_band", "rad", "max |ψ − ψ_des| over the final bench_error_window"),
        Outcome("indicated_error_band", "rad", "the same for the filter's estimate of ψ"),
    ),
    parameters=partial(study_parameters, "ch04"),
    draw=_draw,
    simulate=_simulate,
)
