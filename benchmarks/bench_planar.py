"""Benchmark: chapter 8's largest planar sweep vectorised over members against a solve_ivp loop.

Run as ``python benchmarks/bench_planar.py [peer_members]`` (default: every member).
The sweep is the chapter's own regenerated Fig. 6.8 (:func:`magbench.chapters.ch08_field_stabilisation.error_sweep`),
read from the chapter's defaults: Kovalenko's E47 body (J = 650 kg·m², ΔJ = 400 kg·m², a 1000 km
circular magnetopolar orbit, the book's dipole) with magnets from ``sweep_frequency_min`` to
``sweep_frequency_max`` in ω_c/ω0 (ω_c² = L B0/J) × the chapter's four viscous dampers, from
rest along B at u = 0, ``sweep_orbits`` orbits with RK4 at the chapter's step, in one call
(:func:`magbench.sim.simulate_planar`). The peer is the obvious alternative: the same
right-hand side for one member at a time (:func:`magbench.dynamics.planar_rhs` with the field
from :mod:`magbench.earth`) with ``scipy.integrate.solve_ivp`` (RK45, rtol 1e-8, atol 1e-10
rad), sampled on the same times; timed on ``peer_members`` members spread over the grid and
extrapolated linearly when fewer. Both give the largest |γ| over the last orbit
(:func:`magbench.sim.planar_error_orbit_maxima`), compared member by member.

Single-threaded BLAS is requested (as in the Makefile) so that timings are reproducible
on the project's two-core machines.
"""

import os

os.environ.setdefault("OMP_NUM_THREADS", "1")
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

import sys  # noqa: E402
import time  # noqa: E402

import numpy as np  # noqa: E402
from scipy.integrate import solve_ivp  # noqa: E402

from magbench.dynamics import PlanarBody, PlanarDamper, planar_rhs  # noqa: E402
from magbench.earth import (polar_field_b, polar_field_direction_acceleration,  # noqa: E402
                            polar_field_direction_angle)
from magbench.sim import planar_error_orbit_maxima, simulate_planar  # noqa: E402

def _grid():
    """The chapter's sweep: ω0 [rad/s], B0 [T], the body, each member's L [A·m²] and k_д [N·m·s],
    the orbits and the steps per orbit."""
    from magbench.chapters import ch08_field_stabilisation as CH
    from magbench.earth import dipole_equatorial_b
    from magbench.params import chapter_parameters

    p = chapter_parameters("ch08", overrides="")
    orbit = CH.polar_orbit(p)
    n, b0 = float(orbit.mean_motion), float(dipole_equatorial_b(p["earth_dipole_moment"], orbit.radius))
    body = CH.e47_body(p)
    ratios = np.linspace(p["sweep_frequency_min"], p["sweep_frequency_max"], CH.SWEEP_MAGNETS)
    viscous = p["e47_damping"] * np.asarray(CH.DAMPING_FACTORS)
    moment = (ratios * n) ** 2 * body.inertia / b0
    return (n, b0, body, ratios, viscous, np.repeat(moment, viscous.size), np.tile(viscous, ratios.size),
            p["sweep_orbits"], CH.STEPS_PER_ORBIT)


def _peer(n, b0, e47, moment, viscous, time_grid):
    """One member with solve_ivp on planar_rhs, the field from the Earth family."""
    body, damper = PlanarBody(e47.inertia, moment, e47.inertia_difference), PlanarDamper(viscous=viscous)

    def rhs(t, x):
        u = n * t
        return planar_rhs(x, polar_field_direction_angle(u), polar_field_direction_acceleration(u, n),
                          polar_field_b(u, b0), n, body, damper)

    sol = solve_ivp(rhs, (0.0, time_grid[-1]), np.zeros(3), t_eval=time_grid, rtol=1e-8, atol=1e-10)
    if not sol.success:
        raise RuntimeError(f"solve_ivp failed for L = {moment} A·m², k_д = {viscous}: {sol.message}")
    return sol.y[0]


def main(peer_members=None):
    load_before = os.getloadavg()[0]
    n, b0, e47, RATIOS, VISCOUS, moment, viscous, ORBITS, STEPS_PER_ORBIT = _grid()
    peer_members = moment.size if peer_members is None else peer_members
    period = 2 * np.pi / n
    body = PlanarBody(e47.inertia, moment, e47.inertia_difference)
    damper = PlanarDamper(viscous=viscous)
    args = (n, b0, 0.0, 0.0, ORBITS * period, period / STEPS_PER_ORBIT)
    simulate_planar(body, damper, n, b0, 0.0, 0.0, period / 10, period / STEPS_PER_ORBIT)     # warm-up
    t0 = time.perf_counter()
    run = simulate_planar(body, damper, *args)
    ours = time.perf_counter() - t0
    ours_max = planar_error_orbit_maxima(run, n, last=1)[0]

    members = moment.size
    chosen = np.unique(np.linspace(0, members - 1, min(peer_members, members)).round().astype(int))
    t0 = time.perf_counter()
    peer_max = []
    for i in chosen:
        gamma = _peer(n, b0, e47, moment[i], viscous[i], run.time)
        peer_max.append(float(np.max(np.abs(gamma[run.time * n / (2 * np.pi) >= ORBITS - 1 - 1e-9][:-1]))))
    peer_per_member = (time.perf_counter() - t0) / chosen.size
    peer = peer_per_member * members
    peer_max = np.array(peer_max)
    diff = np.degrees(np.abs(peer_max - ours_max[chosen]))
    # The weakest magnets do not hold the body (it turns over and γ grows without bound);
    # their trajectories are chaotic and the two integrators part, so the agreement is read
    # on the members held within 90° of B by both.
    held = (ours_max[chosen] < np.pi / 2) & (peer_max < np.pi / 2)
    held_diff = diff[held]

    print(f"planar sweep, {members} members ({RATIOS.size} magnets x {VISCOUS.size} dampers) x {ORBITS} orbits, "
          f"RK4 at T/{STEPS_PER_ORBIT} = {period / STEPS_PER_ORBIT:.2f} s")
    print(f"  magbench.sim.simulate_planar (vectorised): {ours:8.2f} s")
    print(f"  solve_ivp per member, {peer_per_member:6.3f} s/member x {members}: {peer:8.1f} s "
          f"(timed on {chosen.size} members)")
    print(f"  speed-up: {peer / ours:8.1f} x; max|γ| over the last orbit on the {held.sum()} of {chosen.size} "
          f"members held within 90°: largest difference {held_diff.max():.2e}°, median {np.median(held_diff):.2e}° "
          f"(values {np.degrees(ours_max[chosen][held].min()):.2f}–{np.degrees(ours_max[chosen][held].max()):.2f}°)")
    worst = chosen[held][np.argmax(held_diff)]
    return {"members": members, "magnets": RATIOS.size, "dampers": VISCOUS.size,
            "natural_frequency_ratios": [float(RATIOS[0]), float(RATIOS[-1])], "source": "the chapter's error_sweep defaults",
            "viscous_N_m_s": VISCOUS.tolist(), "orbits": ORBITS, "step_s": period / STEPS_PER_ORBIT,
            "mean_motion_rad_s": n, "equatorial_b_T": b0,
            "magbench_seconds": ours,
            "peer": "scipy.integrate.solve_ivp (RK45, rtol 1e-8, atol 1e-10) per member on magbench.dynamics.planar_rhs",
            "peer_seconds": peer, "peer_seconds_per_member": peer_per_member,
            "peer_members_timed": int(chosen.size), "ratio": peer / ours,
            "last_orbit_max_gamma_deg_magbench": np.degrees(ours_max[chosen]).tolist(),
            "last_orbit_max_gamma_deg_peer": np.degrees(peer_max).tolist(),
            "held_members": int(held.sum()),
            "turning_over_members": int((~held).sum()),
            "turning_over_ratios": sorted({float(np.sqrt(moment[i] * b0 / e47.inertia) / n) for i in chosen[~held]}),
            "max_last_orbit_max_gamma_difference_deg": float(held_diff.max()),
            "median_last_orbit_max_gamma_difference_deg": float(np.median(held_diff)),
            "worst_member": {"ratio": float(np.sqrt(moment[worst] * b0 / e47.inertia) / n),
                             "viscous_N_m_s": float(viscous[worst])},
            # Other jobs share the two cores; the load says how far the times are inflated.
            "load_average_1min_before": load_before, "load_average_1min_after": os.getloadavg()[0]}


if __name__ == "__main__":
    main(*[int(float(a)) for a in sys.argv[1:2]])
