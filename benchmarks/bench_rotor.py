"""Benchmark: chapter 6's Floquet stability map and the 5-orbit spinning-spacecraft run.

Run as ``python benchmarks/bench_rotor.py [peer_points]`` (default 80).

1. The 40 × 40 map of max|ρ| over (κ, κ_w) by ``magbench.sim.rotor_stability_map`` (all
   1600 monodromies integrated together, RK4, 1000 steps per orbit, as the book's figure)
   against the usual way: one ``scipy.integrate.solve_ivp`` variational solve
   Φ' = A(τ)Φ per gain pair (DOP853, rtol 1e-10, atol 1e-12) with the same linearised
   matrices (``magbench.sim.rotor_linearised_matrices``). The peer loop over all 1600
   points takes minutes on a shared machine, so it is timed on ``peer_points`` grid points
   spread evenly over the grid and scaled to 1600 (its cost per point does not depend
   on the gains beyond the solver's step count, which the sample averages); the
   agreement is the largest relative difference of max|ρ| on those points. The map is
   timed at the figure's 1000 RK4 steps per orbit and at 500, the coarsest whose
   agreement is still within 1e-6.
2. The default asymmetric spacecraft over 5 orbits (``simulate_rotor``, DOP853) at
   rtol 1e-8 (the chapter's default), 1e-9 and 1e-6: wall time and the largest pointing
   error in each orbit, i.e. the tolerance study of ``rotor_spin.md`` §9. At rtol 1e-8
   the run is timed twice more: in the compiled twin of DOP853 (the library's default,
   compiled once beforehand) and in ``scipy.integrate.solve_ivp`` with the same compiled
   right-hand side (the peer), with the largest pointing-error difference between them.
"""

import os

os.environ.setdefault("OMP_NUM_THREADS", "1")
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

import math  # noqa: E402
import sys  # noqa: E402
import time  # noqa: E402

import numpy as np  # noqa: E402
from scipy.integrate import solve_ivp  # noqa: E402

from magbench.chapters.ch06_rotor import default_rotor_orbit, default_rotor_satellite, rotor_parameters  # noqa: E402
from magbench.sim import (pointing_error_orbit_maxima, rotor_dimensionless, rotor_linearised_matrices,  # noqa: E402
                          rotor_stability_map, simulate_rotor)
from magbench.sim import spinning  # noqa: E402

GRID = 40


def peer_max_multiplier(numbers, kappa, kappa_w):
    """max|ρ| of one gain pair by a variational solve_ivp (the loop a user would write)."""
    a, c1, i = numbers["axial_ratio"], numbers["momentum"], numbers["inclination"]

    def rhs(tau, y):
        a0, a1, a2 = rotor_linearised_matrices(tau, a, c1, i)
        return ((a0 + kappa * a1 + kappa_w * a2) @ y.reshape(5, 5)).ravel()

    sol = solve_ivp(rhs, (0.0, 2.0 * math.pi), np.eye(5).ravel(), method="DOP853", rtol=1e-10, atol=1e-12)
    return float(np.max(np.abs(np.linalg.eigvals(sol.y[:, -1].reshape(5, 5)))))


def main(argv=()):
    argv = list(argv)
    peer_points = int(argv[0]) if argv else 80
    p = rotor_parameters()
    orbit, sat = default_rotor_orbit(p), default_rotor_satellite(p)
    numbers = rotor_dimensionless(sat, orbit)
    kappa = np.linspace(10.0 / GRID, 10.0, GRID)
    kappa_w = np.linspace(5.0 / GRID, 5.0, GRID)
    kw = dict(axial_ratio=numbers["axial_ratio"], momentum=numbers["momentum"], inclination=numbers["inclination"])

    flat = np.linspace(0, GRID * GRID - 1, peer_points).round().astype(int)
    t0 = time.perf_counter()
    peer = np.array([peer_max_multiplier(numbers, kappa[j % GRID], kappa_w[j // GRID]) for j in flat])
    peer_per_point = (time.perf_counter() - t0) / peer_points
    loop_s = peer_per_point * GRID * GRID
    maps = {}
    for steps in (1000, 500):
        times = []
        for _ in range(3):
            t0 = time.perf_counter()
            rho = rotor_stability_map(kappa, kappa_w, steps=steps, **kw)
            times.append(time.perf_counter() - t0)
        map_s = float(np.median(times))
        agreement = float(np.max(np.abs(rho.ravel()[flat] - peer) / peer))
        maps[str(steps)] = {"steps": steps, "map_s": map_s, "speedup": loop_s / map_s,
                            "max_relative_difference": agreement, "stable_fraction": float(np.mean(rho < 1.0))}
        print(f"40 x 40 map, {steps} RK4 steps: {map_s:.2f} s; solve_ivp loop: {peer_per_point * 1e3:.0f} ms per "
              f"point, {loop_s:.0f} s for 1600 (from {peer_points} points); ratio {loop_s / map_s:.0f}x; largest "
              f"relative difference of max|rho| {agreement:.1e}")

    period = 2.0 * math.pi / orbit.mean_motion
    angles = (p["initial_alpha"], p["initial_beta"], p["initial_gamma"])
    runs = {}
    # compiled once before timing (the DOP853 twin is compiled per process, ~5 s)
    simulate_rotor(sat, orbit, 0.01 * period, initial_angles=angles, sample_interval=p["sample_interval"])
    for rtol in (1e-8, 1e-9, 1e-6):
        t0 = time.perf_counter()
        run = simulate_rotor(sat, orbit, p["simulation_orbits"] * period, initial_angles=angles,
                             sample_interval=p["sample_interval"], rtol=rtol, atol=1e-2 * rtol)
        wall = time.perf_counter() - t0
        maxima = np.degrees(pointing_error_orbit_maxima(run, orbit.mean_motion))
        runs[f"{rtol:.0e}"] = {"rtol": rtol, "atol": 1e-2 * rtol, "wall_s": wall, "nfev": run.inputs["nfev"],
                               "orbit_maxima_deg": [float(m) for m in maxima]}
        print(f"5 orbits at rtol {rtol:.0e}: {wall:.1f} s, nfev {run.inputs['nfev']}, orbit maxima "
              + ", ".join(f"{m:.2f}" for m in maxima) + " deg")
    engines = {}
    for engine in ("compiled", "scipy"):
        spinning._ADAPTIVE_ENGINE = engine
        try:
            t0 = time.perf_counter()
            run = simulate_rotor(sat, orbit, p["simulation_orbits"] * period, initial_angles=angles,
                                 sample_interval=p["sample_interval"], rtol=1e-8, atol=1e-10)
            engines[engine] = (time.perf_counter() - t0, run)
        finally:
            spinning._ADAPTIVE_ENGINE = "compiled"
    (own_s, own), (peer_s, peer_run) = engines["compiled"], engines["scipy"]
    difference = float(np.max(np.abs(own.pointing_error - peer_run.pointing_error)))
    print(f"5 orbits at rtol 1e-08: compiled DOP853 {own_s:.2f} s, solve_ivp DOP853 {peer_s:.1f} s "
          f"(ratio {peer_s / own_s:.0f}x); nfev {own.inputs['nfev']} and {peer_run.inputs['nfev']}; largest "
          f"pointing-error difference {difference:.1e} rad")
    last = {k: v["orbit_maxima_deg"][-2:] for k, v in runs.items()}
    return {"grid": GRID, "maps": maps, "steps": 1000, "map_s": maps["1000"]["map_s"],
            "speedup": maps["1000"]["speedup"], "max_relative_difference": maps["1000"]["max_relative_difference"],
            "peer": "scipy.integrate.solve_ivp DOP853 rtol 1e-10",
            "peer_points": peer_points, "peer_per_point_s": peer_per_point, "peer_loop_s": loop_s,
            "simulation_orbits": p["simulation_orbits"], "simulation": runs,
            "simulation_s": runs["1e-08"]["wall_s"],
            "simulation_engines": {"compiled_s": own_s, "solve_ivp_s": peer_s, "speedup": peer_s / own_s,
                                   "nfev": [own.inputs["nfev"], peer_run.inputs["nfev"]],
                                   "max_pointing_difference_rad": difference,
                                   "peer": "scipy.integrate.solve_ivp DOP853, the same compiled right-hand side"},
            "late_maximum_deg": {k: float(max(v)) for k, v in last.items()}}


if __name__ == "__main__":
    main(sys.argv[1:])
