"""Chapter 4's factory: the bench of the chapter's parameter set as model objects.

The bench (:class:`magbench.sim.bench.BenchSetup`) and its spreads
(:class:`magbench.sim.bench.BenchDispersion`) are data with SI fields; which entries of the
thesis's parameter set fill them, and how the gains follow from the bandwidth, is this
chapter's knowledge, not the simulator's.
"""

from dataclasses import replace

from ... import control, fields
from ...sim.bench import BenchDispersion, BenchSetup

__all__ = ["bench_setup", "bench_dispersion"]


def bench_setup(params, **changes):
    """The bench of a dict of chapter 4's inputs (SI).

    Field: ``bench_field_h`` (the 262 A/m measured at the simulator's centre) combined
    with ``bench_background_h`` at ``bench_background_azimuth``; gains: the triple pole at
    ``bench_bandwidth`` (:func:`magbench.control.pid_gains_for_triple_pole`). ``changes``
    replace single fields afterwards.

    Parameters
    ----------
    params : mapping
        Chapter-4 parameters (SI), e.g. :func:`magbench.params.chapter_parameters` ``("ch04")``.
    **changes
        :class:`~magbench.sim.bench.BenchSetup` fields to replace [SI].

    Returns
    -------
    BenchSetup
    """
    p = params
    b0 = fields.horizontal_field(p["bench_field_h"], p["bench_background_h"], p["bench_background_azimuth"])
    kp, ki, kd = control.pid_gains_for_triple_pole(p["mockup_inertia"], b0, p["bench_bandwidth"])
    setup = BenchSetup(
        inertia=p["mockup_inertia"], field=float(b0),
        coil_resistance=(p["bench_coil_resistance"], p["bench_coil_resistance"]),
        coil_turns=p["mtq_turns"], coil_side=p["mtq_side"], supply_voltage=p["mtq_voltage"],
        kp=float(kp), ki=float(ki), kd=float(kd),
        filter_coefficient=p["bench_filter_coefficient"],
        sample_interval=p["bench_sample_interval"], pwm_levels=int(p["bench_pwm_levels"]),
        thread_stiffness=p["bench_thread_stiffness"], gyro_bias=p["bench_gyro_bias"])
    return replace(setup, **changes) if changes else setup


def bench_dispersion(params):
    """How the Monte Carlo members' benches spread, from chapter 4's ``bench_moment_tolerance``,
    ``bench_release_angle_spread``, ``bench_release_rate_std`` and
    ``bench_thread_stiffness_factor`` (SI).

    Parameters
    ----------
    params : mapping
        Chapter-4 parameters (SI).

    Returns
    -------
    BenchDispersion
    """
    return BenchDispersion(moment_tolerance=params["bench_moment_tolerance"],
                           release_angle_spread=params["bench_release_angle_spread"],
                           release_rate_std=params["bench_release_rate_std"],
                           thread_stiffness_factor=params["bench_thread_stiffness_factor"])
