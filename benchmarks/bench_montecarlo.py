"""Benchmark: the bench Monte Carlo, vectorised over members, against a solve_ivp loop.

Run as ``python benchmarks/bench_montecarlo.py [members] [peer_members]`` (defaults
1000 and 2). magbench runs the whole Monte Carlo of the book (``bench.monte_carlo``:
``members`` members of 120 s at 100 Hz, datasheet sensor noise, 8-bit PWM, thread
torsion, moment spread) in one vectorised pass over time. The peer is the obvious
alternative: the same closed loop, one member at a time, with the plant integrated
by ``scipy.integrate.solve_ivp`` over each 10 ms zero-order-hold interval
(``bench.simulate_bench_reference``). The peer needs minutes per member, so it is timed
on ``peer_members`` members and extrapolated linearly to ``members``; the record says so
(``peer_extrapolated_from``).

Agreement: one member with identical sensor errors, run through both. With the PWM
quantisation on, a duty that lands on a rounding edge can round differently after a
1e-15 difference, so the comparison is reported with and without quantisation.

Single-threaded BLAS is requested (as in the Makefile) so that timings are
reproducible on the project's two-core machines.
"""

import os

os.environ.setdefault("OMP_NUM_THREADS", "1")
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

import platform  # noqa: E402
import sys  # noqa: E402
import time  # noqa: E402
from dataclasses import replace  # noqa: E402

import numpy as np  # noqa: E402

import magbench  # noqa: E402
from magbench.chapters.ch04_mockup import bench_dispersion, bench_setup  # noqa: E402
from magbench.sim import bench  # noqa: E402
from magbench.params import chapter_parameters  # noqa: E402


def _mc(setup, p, members, seed):
    return bench.monte_carlo(setup, np.pi / 3, members=members, seed=seed, duration=p["bench_duration"],
                             dispersion=bench_dispersion(p),
                             record_interval=0.1, window=p["bench_error_window"])


def _agreement(setup, p, duration):
    steps = int(round(duration / setup.sample_interval))
    g, m = bench.draw_sensor_errors(setup, steps, 1, np.random.default_rng(7))
    kwargs = dict(duration=duration, release_angle=-0.3, release_rate=0.01)
    spread = dict(moment_scale=[1.03, 0.97], thread_stiffness=p["bench_thread_stiffness"])
    vec = bench.simulate_bench(setup, np.pi / 3, sensor_errors=(g, m), errors=bench.BenchErrors(**spread), **kwargs)
    ref = bench.simulate_bench_reference(setup, np.pi / 3, sensor_errors=(g[:, 0], m[:, 0]), **kwargs, **spread)
    psi, omega = ref.psi, ref.rate
    return float(np.max(np.abs(vec.psi[:, 0] - psi))), float(np.max(np.abs(vec.rate[:, 0] - omega)))


def main(members=1000, peer_members=2, repeats=3):
    load_before = os.getloadavg()[0]
    p = chapter_parameters("ch04", overrides="")
    setup = bench_setup(p)
    _mc(setup, p, 10, 0)        # warm-up (imports, caches)
    times = []
    for k in range(repeats):
        t0 = time.perf_counter()
        run = _mc(setup, p, members, 2016 + k)
        times.append(time.perf_counter() - t0)
    ours = float(np.median(times))
    # The peer on the Monte Carlo's first members, with sensor errors from the same models.
    steps = int(round(p["bench_duration"] / setup.sample_interval))
    rng = np.random.default_rng(1)
    t0 = time.perf_counter()
    for j in range(peer_members):
        g, m = bench.draw_sensor_errors(setup, steps, 1, rng)
        bench.simulate_bench_reference(setup, np.pi / 3, duration=p["bench_duration"],
                                       release_angle=run.params["release_angle"][j],
                                       release_rate=run.params["release_rate"][j],
                                       moment_scale=run.params["moment_scale"][j],
                                       thread_stiffness=run.params["thread_stiffness"][j],
                                       sensor_errors=(g[:, 0], m[:, 0]))
    peer_per_member = (time.perf_counter() - t0) / peer_members
    peer = peer_per_member * members
    dpsi_q, domega_q = _agreement(setup, p, 30.0)
    dpsi, domega = _agreement(replace(setup, pwm_levels=0), p, 30.0)
    print(f"magbench {magbench.__file__}")
    print(f"python {platform.python_version()}, numpy {np.__version__}")
    print(f"bench Monte Carlo, {members} members x {p['bench_duration']:.0f} s at "
          f"{1 / setup.sample_interval:.0f} Hz, median of {repeats}")
    print(f"  magbench.sim.bench.monte_carlo (vectorised)     : {ours:8.2f} s  ({times})")
    print(f"  solve_ivp per member, {peer_per_member:6.2f} s/member x {members}: {peer:8.0f} s "
          f"(extrapolated from {peer_members} members)")
    print(f"  speed-up                                    : {peer / ours:8.0f} x")
    print(f"  one member, 30 s, same sensor errors: max |dpsi| = {dpsi:.1e} rad without PWM "
          f"quantisation, {dpsi_q:.1e} rad with it")
    return {"members": members, "duration_s": p["bench_duration"], "sample_rate_hz": 1 / setup.sample_interval,
            "repeats": repeats, "magbench_seconds": ours, "magbench_all_seconds": times,
            "peer": "scipy.integrate.solve_ivp (RK45, rtol 1e-10) per member and 10 ms interval",
            "peer_seconds": peer, "peer_seconds_per_member": peer_per_member,
            "peer_extrapolated_from": peer_members, "ratio": peer / ours,
            "agreement_max_abs_psi_rad": dpsi, "agreement_max_abs_rate_rad_s": domega,
            "agreement_max_abs_psi_rad_with_pwm": dpsi_q, "agreement_duration_s": 30.0,
            # Other jobs share the two cores; the load says how far the times are inflated.
            "load_average_1min_before": load_before, "load_average_1min_after": os.getloadavg()[0]}


if __name__ == "__main__":
    args = [int(float(a)) for a in sys.argv[1:3]]
    main(*args)
