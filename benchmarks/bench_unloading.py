"""Benchmark: chapter 9's largest study, the detumbling runs of Figs. 5.10–5.11, vectorised
over members against a solve_ivp loop.

Run as ``python benchmarks/bench_unloading.py [peer_members]`` (default: every member whose
law is continuous). The study is the chapter's own (:func:`magbench.chapters.ch09_unloading.detumbling_study`
at its defaults): Kovalenko's §5.5 body (J = 2950/12 800/12 800 kg·m², 400 km, 65°, 98 N·m·s on
each axis) under the linear law (5.1), the relay law (5.7) and the product law (5.11) for his
four coils, and the relay law for his four thresholds, 16 members over 20 orbits in one
:func:`magbench.sim.simulate_coil_detumbling` call (RK4, 1000 steps per orbit). The peer is
the obvious alternative: the same right-hand side (the library's rigid-body kernels, the
law's dipole clipped per axis, the field of :class:`magbench.earth.CircularOrbit`) for one
member at a time with ``scipy.integrate.solve_ivp`` (RK45, rtol 1e-8, atol 1e-8), on the
members whose law is continuous in the state (linear and product; a relay's jumps would
make an adaptive integrator crawl, which is no fair comparison); the time is extrapolated
to all 16 members per member. Both give |K| over the run; compared on the time to a tenth of
the start and on |K| after five orbits.

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


def _peer(inertia, orbit, law, limit, k0, time_grid):
    """One member with solve_ivp: state (q, ω), the dipole evaluated inside the right-hand side."""
    from magbench.control import kernels as laws
    from magbench.dynamics import kernels

    j = np.asarray(inertia)

    def rhs(t, x):
        q, w = x[None, :4], x[None, 4:]
        b = kernels.rotate(q, orbit.field(t)[None], -1.0)
        k = j * w
        if law.kind == "linear":
            m = laws.unloading_dipole(b, k, law.gain)
        else:                                        # "product": k (K × B)
            m = law.gain * np.cross(k, b)
        m = np.clip(m, -limit, limit)
        return np.concatenate([kernels.quaternion_rate(q, w), kernels.euler_rates(w, np.cross(m, b), j)], axis=-1)[0]

    x0 = np.concatenate([[1.0, 0.0, 0.0, 0.0], np.asarray(k0) / j])
    sol = solve_ivp(rhs, (0.0, time_grid[-1]), x0, t_eval=time_grid, rtol=1e-8, atol=1e-8)
    if not sol.success:
        raise RuntimeError(f"solve_ivp failed for {law}: {sol.message}")
    return np.linalg.norm(j[:, None] * sol.y[4:], axis=0)


def main(peer_members=None):
    from magbench.chapters import ch09_unloading as CH
    from magbench.params import chapter_parameters
    from magbench.sim import simulate_coil_detumbling

    load_before = os.getloadavg()[0]
    p = chapter_parameters("ch09", overrides="")
    # the study's arguments read from its run (which may come from the result cache); the
    # same call is then timed here
    study = CH.detumbling_study(p)
    run = study["run"]
    laws, orbit, limits = run.params["law"], run.params["orbit"], run.params["dipole_limit"]
    inertia, step = run.params["inertia"], run.params["step"]
    duration, record = float(run.time[-1]), float(run.time[1] - run.time[0])
    k0 = p["det_initial_momentum"]
    simulate_coil_detumbling(inertia, orbit, laws, 10 * step, step, step, initial_momentum=k0,
                             dipole_limit=limits)                                                 # warm-up
    t0 = time.perf_counter()
    ours_run = simulate_coil_detumbling(inertia, orbit, laws, duration, step, record, initial_momentum=k0,
                                        dipole_limit=limits)
    ours = time.perf_counter() - t0
    members = len(laws)
    continuous = [i for i, law in enumerate(laws) if law.kind in ("linear", "product")]
    chosen = continuous if peer_members is None else continuous[:peer_members]
    t0 = time.perf_counter()
    peer_k = {i: _peer(inertia, orbit, laws[i], limits[i], np.full(3, k0), ours_run.time) for i in chosen}
    peer_per_member = (time.perf_counter() - t0) / len(chosen)
    peer = peer_per_member * members
    ours_k = ours_run.momentum
    period = study["period"]
    five = int(np.argmin(np.abs(ours_run.time - 5 * period)))
    level = CH.DONE_FRACTION * ours_k[0, 0]

    def done(k):
        i = np.nonzero(k <= level)[0]
        return float(ours_run.time[i[0]] / period) if i.size else float("nan")

    done_ours = np.array([done(ours_k[:, i]) for i in chosen])
    done_peer = np.array([done(peer_k[i]) for i in chosen])
    five_diff = np.array([abs(ours_k[five, i] - peer_k[i][five]) for i in chosen])
    print(f"detumbling study, {members} members x {duration / period:.0f} orbits, RK4 at T/{CH.DETUMBLING_STEPS_PER_ORBIT}"
          f" = {step:.2f} s")
    print(f"  magbench.sim.simulate_coil_detumbling (vectorised): {ours:8.2f} s")
    print(f"  solve_ivp per member, {peer_per_member:6.2f} s/member x {members}: {peer:8.1f} s "
          f"(timed on the {len(chosen)} continuous-law members)")
    print(f"  speed-up: {peer / ours:8.1f} x; time to a tenth: largest difference "
          f"{np.nanmax(np.abs(done_ours - done_peer)):.3f} orbits; |K| after five orbits: largest difference "
          f"{five_diff.max():.3f} N·m·s")
    return {"members": members, "orbits": duration / period, "step_s": step, "source": "the chapter's detumbling_study defaults",
            "magbench_seconds": ours,
            "peer": "scipy.integrate.solve_ivp (RK45, rtol 1e-8, atol 1e-8) per member, the same kernels and clipped dipole",
            "peer_seconds": peer, "peer_seconds_per_member": peer_per_member, "peer_members_timed": len(chosen),
            "ratio": peer / ours,
            "orbits_to_a_tenth_magbench": done_ours.tolist(), "orbits_to_a_tenth_peer": done_peer.tolist(),
            "max_orbits_to_a_tenth_difference": float(np.nanmax(np.abs(done_ours - done_peer))),
            "max_momentum_difference_after_five_orbits_N_m_s": float(five_diff.max()),
            "load_average_1min_before": load_before, "load_average_1min_after": os.getloadavg()[0]}


if __name__ == "__main__":
    main(*[int(float(a)) for a in sys.argv[1:2]])
