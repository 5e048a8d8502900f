"""Benchmark: chapter 4's error budget, members vectorised against a loop of single runs.

Run as ``python benchmarks/bench_budget.py [base_samples] [loop_members]`` (defaults 32
and 8). The budget evaluates Saltelli's design (``bench.sobol_design``, N·(D + 2)
points over the 22 error sources) with ``bench.source_error_bands``: members sharing a
controller period run in one vectorised pass over time. The peer is the same function
called once per member (the obvious loop over a design), timed on ``loop_members``
points of the same design and extrapolated linearly to the whole design; the record
says so (``loop_extrapolated_from``). Ideal sensors (no noise) in both, so the two must
give the same error bands: the largest difference is recorded.

Single-threaded BLAS is requested (as in the Makefile) so that timings are
reproducible on the project's two-core machines.
"""

import os

os.environ.setdefault("OMP_NUM_THREADS", "1")
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

import platform  # noqa: E402
import sys  # noqa: E402
import time  # noqa: E402

import numpy as np  # noqa: E402

import magbench  # noqa: E402
from magbench.chapters.ch04_mockup import bench_setup, budget  # noqa: E402
from magbench.params import chapter_parameters  # noqa: E402
from magbench.sim import bench  # noqa: E402


def main(base_samples=32, loop_members=8):
    load_before = os.getloadavg()[0]
    p = chapter_parameters("ch04", overrides="")
    setup = bench_setup(p)
    kw = dict(duration=p["bench_duration"], window=p["bench_error_window"], field_h=p["bench_field_h"])
    sources = budget.load_error_sources()
    _, values = bench.sobol_design(sources, base_samples=base_samples, seed=1)
    members = len(next(iter(values.values())))
    t0 = time.perf_counter()
    band, _ = bench.source_error_bands(setup, np.pi / 3, values, **kw)
    ours = time.perf_counter() - t0
    # The loop on evenly spread points of the design (both controller periods occur).
    picks = np.linspace(0, members - 1, loop_members).astype(int)
    single = np.empty(loop_members)
    t0 = time.perf_counter()
    for j, i in enumerate(picks):
        single[j] = bench.source_error_bands(setup, np.pi / 3, {k: v[i:i + 1] for k, v in values.items()}, **kw)[0][0]
    loop_per_member = (time.perf_counter() - t0) / loop_members
    loop = loop_per_member * members
    diff = float(np.max(np.abs(single - band[picks])))
    print(f"magbench {magbench.__file__}")
    print(f"python {platform.python_version()}, numpy {np.__version__}")
    print(f"error budget, {members} members (N = {base_samples}) x {p['bench_duration']:.0f} s")
    print(f"  source_error_bands, vectorised       : {ours:8.2f} s")
    print(f"  one call per member, {loop_per_member:5.2f} s x {members}: {loop:8.0f} s "
          f"(extrapolated from {loop_members})")
    print(f"  speed-up                             : {loop / ours:8.0f} x")
    print(f"  largest band difference, same points : {diff:.1e} rad")
    return {"members": members, "base_samples": base_samples, "duration_s": p["bench_duration"],
            "magbench_seconds": ours, "loop_seconds": loop, "loop_seconds_per_member": loop_per_member,
            "loop_extrapolated_from": loop_members, "ratio": loop / ours,
            "agreement_max_abs_band_rad": diff,
            # Other jobs share the two cores; the load says how far the times are inflated.
            "load_average_1min_before": load_before, "load_average_1min_after": os.getloadavg()[0]}


if __name__ == "__main__":
    args = [int(float(a)) for a in sys.argv[1:3]]
    main(*args)
