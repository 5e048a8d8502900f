"""Figures of the bench experiments (thesis §4.4, Figs. 19–20) and their Monte Carlo.

The thesis's Figs. 19–20 are measured angle traces whose data were never published.
``thesis-fig19`` and ``thesis-fig20`` therefore show what the model of
:mod:`magbench.sim.bench` predicts for those runs (nominal run, and the spread of a small
seeded Monte Carlo), with the thesis's 10° marked, and overlay any bench log found in
``magbench/data/bench/`` (:mod:`magbench.io.benchlog`). ``ch04-montecarlo`` is the distribution of
the final error over the uncertain inputs, for both targets.
"""

import numpy as np

from ...sim import bench
from ...io import benchlog
from ...io import load_parameter_set, measurement
from . import CHAPTER
from .models import bench_dispersion, bench_setup
from .._base import chapter_parameters
from ...rotations import wrap_angle
from ..registry import FigureData, FigureParameter, FigureSpec, Series, register
from ..._validate import shown

SOURCE = "Bui (2016), thesis §4.4, Figs. 19–20; the bench model is ours (chapter 4)"

#: Chapter-4 inputs the bench figures take as parameters (all of the bench's).
#: The bench's inputs (a subset of chapter 4's: the chapter's other sections have their own).
BENCH_INPUTS = [
    "mockup_inertia", "mtq_voltage", "mtq_turns", "mtq_side", "bench_field_h",
    "bench_background_h", "bench_background_azimuth", "bench_coil_resistance",
    "bench_moment_tolerance", "bench_pwm_levels", "bench_sample_interval", "bench_duration",
    "bench_error_window", "bench_filter_coefficient", "bench_bandwidth", "bench_thread_stiffness",
    "bench_thread_stiffness_factor", "bench_release_angle_spread", "bench_release_rate_std",
    "bench_gyro_bias", "bench_members", "bench_seed",
]

#: The bench inputs that set the figures' work or count something, and the values the figures
#: accept (see :class:`~magbench.chapters.registry.FigureParameter`); the others take any value
#: the model accepts.
BENCH_INPUT_BOUNDS = {"bench_duration": dict(high=3600.0), "bench_members": dict(high=2e4, whole=True),
                      "bench_seed": dict(whole=True), "bench_pwm_levels": dict(whole=True),
                      "mtq_turns": dict(whole=True)}


def _input_parameters():
    table = load_parameter_set("thesis")
    values = chapter_parameters(CHAPTER.key, overrides="")
    params = {}
    for name in BENCH_INPUTS:
        p = table[name]
        note = (p.note or p.source).split(";")[0]
        params[name] = FigureParameter(values[name], p.unit_si, note, **BENCH_INPUT_BOUNDS.get(name, {}))
    return params


def _setup(p):
    return bench_setup(p)


#: The targets of the thesis's bench runs (Figs. 19 and 20) [rad]: the book draws one
#: figure for each, and a log is drawn on the figure of its target.
BENCH_TARGETS = (np.pi / 3, 2 * np.pi / 3)
#: How close a log's stated psi_des must be to a figure's target to be drawn on it [rad].
TARGET_MATCH = 1e-6


def _same_target(a, b):
    return abs(wrap_angle(a - b)) <= TARGET_MATCH


def _logs_for(psi_des, alpha):
    """Series of the bench logs in magbench/data/bench whose target is psi_des (or
    unstated), and ``(file name, psi_des)`` of the logs whose target is none of the
    book's (:data:`BENCH_TARGETS`): they appear on no figure, so the figure says so."""
    series, elsewhere = [], []
    for log in benchlog.load_bench_logs():
        target = log.psi_des
        if target is not None and not _same_target(target, psi_des):
            if not any(_same_target(target, t) for t in BENCH_TARGETS):
                elsewhere.append((log.path.name, float(target)))
            continue
        series.append(Series(f"bench log {log.path.name}", {
            "time": ("s", log.time),
            "psi_filtered": ("deg", np.degrees(benchlog.log_filtered_angle(log, alpha)))}))
    return series, elsewhere


def compute_trace(psi_des, release_angle, release_rate, envelope_members, **p):
    """Predicted angle traces of one bench run, a Monte Carlo envelope and any logs."""
    setup = _setup(p)
    seed = int(p["bench_seed"])
    run = bench.simulate_bench(setup, psi_des, duration=p["bench_duration"], release_angle=release_angle,
                               release_rate=release_rate, rng=np.random.default_rng(seed),
                               window=p["bench_error_window"])
    n_env = int(round(envelope_members))
    if n_env < 2:
        raise ValueError(f"envelope_members must be >= 2, got {shown(envelope_members)}")
    # The envelope's members are released about the nominal run's own release angle and
    # rate (not about the target, as in ch04-montecarlo), so that the nominal run, whose
    # moments and thread are the centres of the members' spreads, is one of them.
    mc = bench.monte_carlo(setup, psi_des, members=n_env, seed=seed + 1, duration=p["bench_duration"],
                           dispersion=bench_dispersion(p),
                           record_interval=0.1, window=p["bench_error_window"],
                           release_angle=release_angle, release_rate=release_rate)
    # Each member is shifted by the whole turns that bring its final angle nearest the
    # target (a member that turned the other way round ends a turn below it), once for
    # its whole trace, so the traces, and their percentiles, stay continuous in time.
    turns = np.rint((psi_des - mc.psi[-1]) / (2.0 * np.pi))
    lo, hi = np.percentile(np.degrees(mc.psi + 2.0 * np.pi * turns), [5.0, 95.0], axis=1)
    series = [
        Series("nominal run", {"time": ("s", run.time), "psi": ("deg", np.degrees(run.psi[:, 0])),
                               "psi_filtered": ("deg", np.degrees(run.estimate[:, 0])),
                               "moment_1": ("A m^2", run.moment_1[:, 0]),
                               "moment_2": ("A m^2", run.moment_2[:, 0])}),
        Series(f"Monte Carlo, {n_env} members, 5-95 %", {
            "time": ("s", mc.time), "psi_low": ("deg", lo), "psi_high": ("deg", hi)}),
    ]
    logs, unplotted = _logs_for(psi_des, p["bench_filter_coefficient"])
    error = measurement("orientation-error")
    return FigureData("", "", "", {}, series + logs, extra={
        "psi_des": psi_des, "measured_error": error.value, "error_band": float(run.error_band[0]),
        "indicated_error_band": float(run.indicated_error_band[0]), "n_logs": len(logs),
        "unplotted_logs": unplotted,
        "window": p["bench_error_window"], "mc_error_band": mc.error_band})


def plot_trace(data):
    """Angle against time with the ±10° band about the target, and the coil moments."""
    import matplotlib.pyplot as plt

    e = data.extra
    target, tol = np.degrees(e["psi_des"]), np.degrees(e["measured_error"])
    nominal, envelope = data.series[0], data.series[1]
    c = {k: v for k, (u, v) in nominal.columns.items()}
    fig, (a1, a2) = plt.subplots(2, 1, figsize=(7.0, 6.0), sharex=True, layout="constrained",
                                 gridspec_kw={"height_ratios": [2.2, 1.0]})
    env = {k: v for k, (u, v) in envelope.columns.items()}
    a1.fill_between(env["time"], env["psi_low"], env["psi_high"], color="C0", alpha=0.2,
                    label=envelope.label)
    a1.axhspan(target - tol, target + tol, color="C3", alpha=0.08,
               label=f"target ± {tol:.0f}° (thesis's error)")
    a1.axhline(target, color="C3", linewidth=0.8)
    a1.plot(c["time"], c["psi"], color="C0", label="nominal run: true angle")
    a1.plot(c["time"], c["psi_filtered"], color="C1", linestyle="--", linewidth=0.9,
            label="nominal run: filtered angle (eq. 39)")
    for s in data.series[2:]:
        cols = {k: v for k, (u, v) in s.columns.items()}
        a1.plot(cols["time"], cols["psi_filtered"], color="k", linewidth=1.0, label=s.label)
    unplotted = e.get("unplotted_logs", [])
    if unplotted:
        names = ", ".join(f"{name} (ψ_des = {np.degrees(t):.1f}°)" for name, t in unplotted)
        a1.text(0.99, 0.03, f"on no figure (target neither 60° nor 120°): {names}",
                transform=a1.transAxes, ha="right", va="bottom", fontsize=7, color="C3", wrap=True)
    elif not e["n_logs"]:
        a1.text(0.99, 0.03, "no bench log: the thesis's traces are unpublished",
                transform=a1.transAxes, ha="right", va="bottom", fontsize=8, color="0.3")
    a1.set_ylabel("ψ, angle from field to coil 1 [°]", fontsize=8)
    # Above the axes: inside, the legend covered the Monte Carlo band.
    a1.legend(fontsize=7, loc="lower center", bbox_to_anchor=(0.5, 1.0), ncol=2, frameon=False)
    fig.suptitle(rf"The bench as designed, $\psi_\mathrm{{des}}$ = {target:.0f}° (thesis Fig. "
                 f"{19 if abs(target - 60.0) < 1e-6 else 20 if abs(target - 120.0) < 1e-6 else '19-20'})",
                 fontsize=8.5)
    a2.plot(c["time"], c["moment_1"], label="coil 1")
    a2.plot(c["time"], c["moment_2"], label="coil 2")
    a2.set_xlabel("time since release [s]", fontsize=8)
    a2.set_ylabel("moment [A·m²]", fontsize=8)
    a2.legend(fontsize=7, ncol=2, loc="lower right")
    for ax in (a1, a2):
        ax.tick_params(labelsize=7)
    return fig


def compute_montecarlo(**p):
    """Final error band of a seeded Monte Carlo for ψ_des = π/3 and 2π/3."""
    setup = _setup(p)
    series = []
    for k, target in enumerate((np.pi / 3.0, 2.0 * np.pi / 3.0)):
        run = bench.monte_carlo(setup, target, members=int(round(p["bench_members"])),
                                seed=int(p["bench_seed"]) + 10 * (k + 1), duration=p["bench_duration"],
                                dispersion=bench_dispersion(p),
                                record_interval=p["bench_duration"], window=p["bench_error_window"])
        series.append(Series(f"ψ_des = {np.degrees(target):.0f}°", {
            "error_band": ("deg", np.degrees(run.error_band)),
            "indicated_error_band": ("deg", np.degrees(run.indicated_error_band)),
            "release_angle": ("deg", np.degrees(run.params["release_angle"])),
            "thread_stiffness": ("N m/rad", run.params["thread_stiffness"])}))
    return FigureData("", "", "", {}, series,
                      extra={"measured_error": measurement("orientation-error").value})


def plot_montecarlo(data):
    """Histograms of the final error band (log scale) with the thesis's 10° marked."""
    import matplotlib.pyplot as plt

    measured = np.degrees(data.extra["measured_error"])
    values = [s.columns["error_band"][1] for s in data.series]
    low = min(float(np.min(v)) for v in values)
    edges = np.logspace(np.floor(np.log10(max(low, 1e-6))), np.log10(3.0 * measured), 60)
    fig, ax = plt.subplots(figsize=(7.0, 4.2))
    for s, v in zip(data.series, values):
        ax.hist(v, bins=edges, histtype="step", linewidth=1.4,
                label=s.label.replace("ψ_des", r"$\psi_\mathrm{des}$")
                + f": median {np.median(v):.3g}°, 99 % ≤ {np.percentile(v, 99):.3g}°")
    ax.axvline(measured, color="C3", linewidth=2, label=f"thesis: {measured:.0f}° (metric not stated)")
    ax.set_xscale("log")
    ax.set_xlabel(r"final error band max $|\psi - \psi_\mathrm{des}|$ over the last window [deg]")
    ax.set_ylabel("members")
    ax.legend(fontsize=8, loc="upper left", bbox_to_anchor=(0.42, 0.98))
    ax.set_title(f"The bench's noise floor: Monte Carlo, {len(values[0])} members per target")
    return fig


def _trace_parameters(psi_des):
    params = {"psi_des": FigureParameter(psi_des, "rad", "target angle from the field to coil 1"),
              "release_angle": FigureParameter(0.0, "rad", "true angle at release (ours: along the field)"),
              "release_rate": FigureParameter(0.0, "rad/s", "rate at release (ours)"),
              "envelope_members": FigureParameter(100.0, "1", "Monte Carlo members of the envelope", high=1e4, whole=True)}
    params.update(_input_parameters())
    return params


register(FigureSpec("thesis-fig19", "Bench run for ψ_des = π/3: model prediction (thesis Fig. 19)",
                    SOURCE, compute_trace, plot_trace, lambda: _trace_parameters(np.pi / 3.0)))
register(FigureSpec("thesis-fig20", "Bench run for ψ_des = 2π/3: model prediction (thesis Fig. 20)",
                    SOURCE, compute_trace, plot_trace, lambda: _trace_parameters(2.0 * np.pi / 3.0)))
register(FigureSpec("ch04-montecarlo", "Monte Carlo of the bench's final error",
                    SOURCE, compute_montecarlo, plot_montecarlo, _input_parameters, slow=True))
