"""Benchmark: a dispersion study scaled out over local workers, and its memory.

Run as ``python benchmarks/bench_dispersion.py [members] [scaling_members]`` (defaults
100000 and 4000). Three measurements of the ``detumble`` study (the 3U envelope, 12,000 s
per member, RK4 at 1 s), each through the command line as a user runs it
(``magbench montecarlo detumble ... --out FILE``), in a subprocess:

1. **Scaling**: ``scaling_members`` members on 1 and on 2 local workers (chunks of 1000);
   the throughput ratio is the peer comparison (one worker is the peer of two, in the same
   run). The two files must be identical.
2. **Scale**: ``members`` members on 2 workers, wall time; the issue asks ≤ 10 min.
3. **Memory**: the peak resident memory of the whole process tree (the command and its
   workers, summed, sampled every 0.2 s with psutil) for ``members`` and for a tenth of it;
   rows are streamed to the file chunk by chunk, so it should not grow with the members.
   The smaller file must be the first rows of the larger (the same seed).

Single-threaded BLAS is requested, as in the Makefile.
"""

import os

os.environ.setdefault("OMP_NUM_THREADS", "1")
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

import subprocess  # noqa: E402
import sys  # noqa: E402
import tempfile  # noqa: E402
import time  # noqa: E402
from pathlib import Path  # noqa: E402

import psutil  # noqa: E402


def _run(members, workers, out, seed=557):
    """Wall time [s] and peak summed RSS [bytes] of one ``magbench montecarlo`` run."""
    cmd = [sys.executable, "-m", "magbench.cli", "montecarlo", "detumble", "--members", str(members), "--seed",
           str(seed), "--workers", str(workers), "--out", str(out)]
    start = time.perf_counter()
    proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    root = psutil.Process(proc.pid)
    peak = 0
    while proc.poll() is None:
        try:
            tree = [root] + root.children(recursive=True)
            peak = max(peak, sum(p.memory_info().rss for p in tree if p.is_running()))
        except psutil.Error:
            pass
        time.sleep(0.2)
    wall = time.perf_counter() - start
    stdout, stderr = proc.communicate()
    if proc.returncode != 0:
        raise RuntimeError(f"{' '.join(cmd)} failed: {stderr}")
    return wall, peak, stdout


def main(members=100_000, scaling_members=4000):
    import numpy as np

    from magbench.chapters.ch05_detumbling.study import envelope_orbit
    from magbench.params import chapter_parameters

    load_before = os.getloadavg()[0]
    period = 2.0 * np.pi / envelope_orbit(chapter_parameters("ch05", overrides="")).mean_motion
    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        one, _, _ = _run(scaling_members, 1, tmp / "one.csv")
        two, _, _ = _run(scaling_members, 2, tmp / "two.csv")
        identical = (tmp / "one.csv").read_bytes() == (tmp / "two.csv").read_bytes()
        print(f"{scaling_members} members: 1 worker {one:.1f} s, 2 workers {two:.1f} s, "
              f"throughput x{one / two:.2f}, files identical: {identical}")
        small_wall, small_peak, _ = _run(members // 10, 2, tmp / "small.csv")
        big_wall, big_peak, stdout = _run(members, 2, tmp / "big.csv")
        with open(tmp / "small.csv", "rb") as s, open(tmp / "big.csv", "rb") as b:
            small = s.read()
            prefix = b.read(len(small)) == small
        print(f"{members // 10} members: {small_wall:.1f} s, peak {small_peak / 2**20:.0f} MiB")
        print(f"{members} members: {big_wall:.1f} s, peak {big_peak / 2**20:.0f} MiB "
              f"(x{big_peak / small_peak:.2f}); the smaller file is its first rows: {prefix}")
        print(stdout)
    return {
        "study": "detumble", "duration_s": 12000.0, "step_s": 1.0, "chunk": 1000,
        "scaling_members": scaling_members, "one_worker_seconds": one, "two_workers_seconds": two,
        "two_worker_throughput_ratio": one / two, "scaling_files_identical": identical,
        "members": members, "members_two_workers_seconds": big_wall,
        "orbit_period_s": period,
        "member_orbits_per_cpu_second": members * 12000.0 / period / (2 * big_wall),
        "peak_rss_mib": big_peak / 2**20, "tenth_members_peak_rss_mib": small_peak / 2**20,
        "peak_rss_ratio": big_peak / small_peak, "tenth_file_is_prefix": prefix,
        "statistics_stdout": stdout, "load_average_before": load_before,
        "peer": "the same study on one local worker (throughput ratio)",
    }


if __name__ == "__main__":
    main(*(int(a) for a in sys.argv[1:]))
