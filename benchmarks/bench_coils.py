"""Benchmark: magbench.fields.helmholtz_b against magpylib's fastest path, same run.

Run as ``python benchmarks/bench_coils.py [n_points] [repeats]`` (defaults 10**6, 7).
Both codes evaluate the thesis's Helmholtz pair (a = 0.5 m, d = 0.5 m, 110 turns ×
2.3 A) at the same random points, uniform in the cube |x|, |y|, |z| < a. magpylib's
fastest path is ``magpylib.func.circle_field`` with the observers tiled once per coil
(one call for both loops) and the two halves summed. Prints the median wall time of
each, their ratio and the largest relative difference between the two results,
max |B_ours − B_magpylib| / |B_magpylib| over all points.

Errors are relative to the pair's |B| at each point. The largest ones (~1e-13 for both
codes) sit in the mid-plane outside the coils (ρ ≈ 1.26a at the cube's corners), where
the two coils' fields nearly cancel and |B| is ~1e-3 of its centre value, and close to
the wires, where the problem's condition number is ~a/δ.

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
from magbench.fields import helmholtz_b

A, D, CURRENT, TURNS = 0.5, 0.5, 2.3, 110


def magpylib_pair(points):
    import magpylib as magpy

    n = points.shape[0]
    observers = np.concatenate([points, points])
    positions = np.zeros_like(observers)
    positions[:n, 2] = -D / 2
    positions[n:, 2] = D / 2
    b = magpy.func.circle_field("B", observers, 2 * A, TURNS * CURRENT, positions=positions)
    return b[:n] + b[n:]


def ours(points):
    return helmholtz_b(points, A, D, CURRENT, TURNS)


def exact_pair(points, digits=50):
    """B [T] of the pair at the given (float) points in ``digits``-digit arithmetic."""
    import mpmath as mp

    out = []
    with mp.workdps(digits):
        for x, y, z in points:
            bx = by = bz = mp.mpf(0)
            for z0 in (-D / 2, D / 2):
                xx, yy, zz = mp.mpf(x) / A, mp.mpf(y) / A, (mp.mpf(z) - mp.mpf(z0)) / A
                r = mp.sqrt(xx * xx + yy * yy)
                a2, b2 = (1 - r) ** 2 + zz * zz, (1 + r) ** 2 + zz * zz
                m = 4 * r / b2
                k, e = mp.ellipk(m), mp.ellipe(m)
                bz += (k + (1 - r * r - zz * zz) / a2 * e) / (2 * mp.pi * mp.sqrt(b2))
                br_over_r = zz * (-k + (1 + r * r + zz * zz) / a2 * e) / (2 * mp.pi * r * r * mp.sqrt(b2))
                bx += br_over_r * xx
                by += br_over_r * yy
            out.append([float(bx), float(by), float(bz)])
    from magbench.constants import MU_0

    return MU_0 * TURNS * CURRENT / A * np.array(out)


def median_time(func, points, repeats):
    times = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        func(points)
        times.append(time.perf_counter() - t0)
    return float(np.median(times)), times


def main(n=10**6, repeats=7):
    import magpylib as magpy

    rng = np.random.default_rng(2016)
    points = rng.uniform(-A, A, (n, 3))
    b_ours = ours(points)            # warm-up and result
    b_ref = magpylib_pair(points)
    rel = np.max(np.abs(b_ours - b_ref), axis=-1) / np.linalg.norm(b_ref, axis=-1)
    # Interleave the two timings so that load from other processes hits both alike.
    t_ours, t_mag = [], []
    for _ in range(repeats):
        t_ours += median_time(ours, points, 1)[1]
        t_mag += median_time(magpylib_pair, points, 1)[1]
    m_ours, m_mag = float(np.median(t_ours)), float(np.median(t_mag))
    print(f"magbench {magbench.__file__}")
    print(f"python {platform.python_version()}, numpy {np.__version__}, magpylib {magpy.__version__}")
    print(f"Helmholtz pair, {n} random points, median of {repeats} interleaved runs")
    print(f"  magbench.fields.helmholtz_b        : {1e3 * m_ours:8.1f} ms")
    print(f"  magpylib.func.circle_field (x2)   : {1e3 * m_mag:8.1f} ms")
    print(f"  speed-up (magpylib / magbench)    : {m_mag / m_ours:8.2f} x")
    print(f"  max |dB| / |B| between the two    : {rel.max():8.1e}")
    # Distance to the nearer wire: near it the problem itself is ill-conditioned (~a/δ).
    rho = np.hypot(points[:, 0], points[:, 1])
    delta = np.min([np.hypot(rho - A, points[:, 2] - z0) for z0 in (-D / 2, D / 2)], axis=0) / A
    far = delta > 1e-2
    print(f"  ... for points > 0.01 a from a wire: {rel[far].max():8.1e}  (closest point: {delta.min():.1e} a)")
    result = {"n_points": n, "repeats": repeats, "magbench_seconds": m_ours,
              "peer": f"magpylib {magpy.__version__} func.circle_field", "peer_seconds": m_mag,
              "ratio": m_mag / m_ours, "max_relative_difference": float(rel.max())}
    try:
        import mpmath  # noqa: F401
    except ImportError:
        return result
    # Accuracy of both against 50-digit arithmetic at the 100 points where they differ
    # most (and 100 random ones), for the float inputs as given.
    idx = np.concatenate([np.argsort(rel)[-100:], rng.choice(n, 100, replace=False)])
    exact = exact_pair(points[idx])
    norm = np.linalg.norm(exact, axis=-1)
    err_ours = np.max(np.abs(b_ours[idx] - exact), axis=-1) / norm
    err_mag = np.max(np.abs(b_ref[idx] - exact), axis=-1) / norm
    print("  error vs 50-digit mpmath (max over 100 most-discrepant + 100 random points):")
    print(f"    magbench {err_ours.max():8.1e}   magpylib {err_mag.max():8.1e}")
    print(f"    median   {np.median(err_ours):8.1e}            {np.median(err_mag):8.1e}")
    result.update(mpmath_max_error=float(err_ours.max()), mpmath_max_error_peer=float(err_mag.max()),
                  mpmath_median_error=float(np.median(err_ours)),
                  mpmath_median_error_peer=float(np.median(err_mag)))
    return result


if __name__ == "__main__":
    args = [int(float(a)) for a in sys.argv[1:3]]
    main(*args)
