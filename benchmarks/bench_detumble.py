"""Benchmark: the detumbling Monte Carlo vectorised over members against a solve_ivp loop,
and the vectorised TRIAD against a loop of scipy's align_vectors.

Run as ``python benchmarks/bench_detumble.py [members] [peer_members]`` (defaults 1000
and 5). magbench runs the chapter-5 envelope (3U, 500 km, 51.6°, a tilted dipole turning
with the Earth, continuous B-dot k = 5e4 A·m²·s/T, ±0.2 A·m², gravity gradient, 12 000 s,
RK4 at 1 s) for ``members`` members in one array
(:func:`magbench.sim.detumble_monte_carlo`). The peer is the obvious alternative: the
same equations for one member at a time with ``scipy.integrate.solve_ivp`` (RK45, rtol
1e-8, atol 1e-10), timed on ``peer_members`` members and extrapolated linearly; both
give detumble times (first record with |ω| ≤ 0.5 °/s) on 1 s records, compared member
by member.

TRIAD: ``samples`` attitudes from noisy field/Sun pairs, :func:`magbench.estimation.triad_attitude`
in one call against a loop of ``Rotation.align_vectors`` with weights [inf, 1].

Single-threaded BLAS is requested (as in the Makefile) so that timings are reproducible
on the project's two-core machines.
"""

import os

os.environ.setdefault("OMP_NUM_THREADS", "1")
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

import sys  # noqa: E402
import time  # noqa: E402
from dataclasses import replace  # noqa: E402

import numpy as np  # noqa: E402
from scipy.integrate import solve_ivp  # noqa: E402

from magbench.chapters import chapter_parameters  # noqa: E402
from magbench.chapters.ch05_detumbling import study  # noqa: E402
from magbench.control import bdot_dipole  # noqa: E402
from magbench.dynamics import euler_rates, gravity_gradient_torque, quaternion_rate, rotate_to_body  # noqa: E402
from magbench.sim import detumble_monte_carlo, detumble_time  # noqa: E402


def _peer(inertia, orbit, q0, w0, duration, gain, max_dipole):
    """One member with solve_ivp: the same law (exact Ḃ), torques and kinematics."""
    n = orbit.mean_motion

    def rhs(t, x):
        q, w = x[:4], x[4:]
        b_n, b_rate_n = orbit.field_and_rate(t)
        b = rotate_to_body(q, b_n)
        m = bdot_dipole(rotate_to_body(q, b_rate_n) - np.cross(w, b), gain, max_dipole)
        torque = np.cross(m, b) + gravity_gradient_torque(rotate_to_body(q, orbit.position(t)), inertia, n)
        return np.concatenate([quaternion_rate(q, w), euler_rates(w, torque, inertia)])

    t_eval = np.arange(0.0, duration + 0.5, 1.0)
    sol = solve_ivp(rhs, (0.0, t_eval[-1]), np.concatenate([q0, w0]), t_eval=t_eval, rtol=1e-8, atol=1e-10)
    return sol.t, np.linalg.norm(sol.y[4:], axis=0)


def main(members=1000, peer_members=5, samples=20000):
    load_before = os.getloadavg()[0]
    p = chapter_parameters("ch05", overrides="")
    inertia = study.inertia(p)
    orbit = study.envelope_orbit(p)
    kwargs = dict(members=members, seed=int(p["envelope_seed"]), duration=p["envelope_duration"],
                  rate_range=(p["envelope_rate_low"], p["envelope_rate_high"]), gain=p["envelope_gain"],
                  max_dipole=p["max_dipole"], step=p["integration_step"])
    detumble_monte_carlo(inertia, orbit, **{**kwargs, "members": 4, "duration": 100.0})      # warm-up
    t0 = time.perf_counter()
    run = detumble_monte_carlo(inertia, orbit, **kwargs)
    ours = time.perf_counter() - t0
    threshold = p["detumble_threshold"]
    ours_times = detumble_time(run.time, run.rate, threshold)
    draws = run.inputs["draws"]
    t0 = time.perf_counter()
    peer_times = []
    for j in range(peer_members):
        member = replace(orbit, argument_of_latitude0=float(draws["argument_of_latitude0"][j]))
        t, rate = _peer(inertia, member, draws["attitude"][j], draws["rate"][j], p["envelope_duration"],
                        p["envelope_gain"], p["max_dipole"])
        peer_times.append(float(detumble_time(t, rate, threshold)))
    peer_per_member = (time.perf_counter() - t0) / peer_members
    peer = peer_per_member * members
    diff = np.abs(np.array(peer_times) - ours_times[:peer_members])

    triad = study.triad_vs_align_vectors(samples=samples)
    triad_ratio = triad["seconds_peer"] / triad["seconds_ours"]

    print(f"detumble Monte Carlo, {members} members x {p['envelope_duration']:.0f} s, RK4 at "
          f"{p['integration_step']:g} s")
    print(f"  magbench.sim.detumble_monte_carlo (vectorised): {ours:8.2f} s")
    print(f"  solve_ivp per member, {peer_per_member:6.2f} s/member x {members}: {peer:8.0f} s "
          f"(extrapolated from {peer_members} members)")
    print(f"  speed-up: {peer / ours:8.0f} x; detumble times {ours_times[:peer_members]} vs {peer_times}")
    print(f"TRIAD, {samples} attitudes: vectorised {triad['seconds_ours'] * 1e3:.2f} ms, align_vectors loop "
          f"{triad['seconds_peer']:.2f} s, speed-up {triad_ratio:.0f} x, max difference {triad['max_difference']:.1e}")
    return {"members": members, "duration_s": p["envelope_duration"], "step_s": p["integration_step"],
            "magbench_seconds": ours,
            "peer": "scipy.integrate.solve_ivp (RK45, rtol 1e-8, atol 1e-10) per member",
            "peer_seconds": peer, "peer_seconds_per_member": peer_per_member,
            "peer_extrapolated_from": peer_members, "ratio": peer / ours,
            "detumble_times_magbench": [float(x) for x in ours_times[:peer_members]],
            "detumble_times_peer": peer_times, "max_detumble_time_difference_s": float(np.max(diff)),
            "triad_samples": samples, "triad_seconds": triad["seconds_ours"],
            "align_vectors_seconds": triad["seconds_peer"], "triad_ratio": triad_ratio,
            "triad_max_difference": triad["max_difference"],
            # Other jobs share the two cores; the load says how far the times are inflated.
            "load_average_1min_before": load_before, "load_average_1min_after": os.getloadavg()[0]}


if __name__ == "__main__":
    args = [int(float(a)) for a in sys.argv[1:3]]
    main(*args)
