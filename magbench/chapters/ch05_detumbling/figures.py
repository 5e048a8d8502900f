"""Figures of chapter 5: SamSat-218D Figs. 1–2 as reconstructions, and the analysis figures.

Each figure is a ``compute_*`` (numbers, tested) and ``plot_*`` (drawing) pair. The
simulations live in :mod:`.study`, cached, so the book, the command line and the tests
share one run. Figures whose defaults take more than 3 s say so in their title (which
``magbench figures`` lists).
"""

from functools import partial

import numpy as np

from .._base import chapter_parameters
from ...control import kovalenko_detumble_time
from ...earth import dipole_max_field, field_direction_rate_range, mean_square_field
from ..registry import FigureData, FigureParameter, FigureSpec, Series, register
from ...units import DEG
from ...result_cache import ChapterInputs
from . import study

SOURCE = "Kramlikh & Melnik (2016), SamSat-218D"
ESTIMATORS = ("model", "hold", "propagate")

def _defaults():
    return chapter_parameters("ch05", overrides="")


#: The chapter's inputs that set a figure's work or count something, and the values the figures
#: accept (see :class:`~magbench.chapters.registry.FigureParameter`); the others take any value
#: the model accepts.
INPUT_BOUNDS = {"fig2_members": dict(high=100.0, whole=True), "fig2_seed": dict(whole=True),
                "envelope_members": dict(high=1e4, whole=True), "envelope_seed": dict(whole=True),
                "dispersion_members": dict(low=100.0, high=2e4, whole=True),
                "envelope_duration": dict(high=1e5), "integration_step": dict(low=0.01)}


def _parameters(*names, **extra):
    from ...io import load_parameter_set

    p, sources = _defaults(), load_parameter_set("samsat")
    out = {name: FigureParameter(p[name], sources[name].unit_si, f"{name.replace('_', ' ')} ({sources[name].source})",
                                 **INPUT_BOUNDS.get(name, {}))
           for name in names}
    out.update(extra)
    return out


def _key(**params):
    """The chapter's defaults with a figure's parameters over them, as a cache key."""
    p = _defaults()
    return ChapterInputs(p, **{k: v for k, v in params.items() if k in p})


_ORBIT = ("orbit_altitude", "orbit_inclination", "earth_radius", "dipole_g10", "dipole_g11", "dipole_h11",
          "earth_rotation_rate")
_DUTY = ("inertia_x", "inertia_y", "inertia_z", *_ORBIT, "max_dipole", "initial_rate_x", "initial_rate_y",
         "fig2_rate_min", "fig2_rate_max", "fig2_rate_step", "on_time", "off_time", "detumble_threshold",
         "fig2_members", "fig2_seed")
_ENVELOPE = ("inertia_x", "inertia_y", "inertia_z", "max_dipole", "detumble_threshold", "earth_rotation_rate",
             "envelope_rate_low", "envelope_rate_high", "envelope_altitude", "envelope_inclination",
             "envelope_dipole_field", "envelope_dipole_tilt", "envelope_gain", "envelope_members", "envelope_seed",
             "envelope_duration", "integration_step")


def _new_figure(height=3.4, ncols=1, width=6.4):
    import matplotlib.pyplot as plt

    return plt.subplots(1, ncols, figsize=(width, height))


# --- SamSat Fig. 1: the gain against the initial rates -----------------------------------

def compute_fig1(**params):
    """k = L_max/(|ω₀| B_max) for ω₀ = (ωx, w, w), w over Fig. 2's axis (SS L245–253)."""
    p = {**_defaults(), **params}
    orbit = study.samsat_orbit(p)
    b_max = dipole_max_field(orbit)
    w = np.linspace(p["fig2_rate_min"], p["fig2_rate_max"], 81)
    ticks = study.rate_grid(p["fig2_rate_min"], p["fig2_rate_max"], p["fig2_rate_step"])
    default = study.fig1_gains(p["max_dipole"], p["initial_rate_x"], p["initial_rate_y"], b_max)
    return FigureData("", "", "", {}, [
        Series(r"$k$ ($\boldsymbol{\omega}_\mathrm{i}$ = (0.1, w, w) °/s)", {"initial_rate": ("deg/s", w / DEG),
                                              "gain": ("A m^2 s/T", study.fig1_gains(p["max_dipole"],
                                                                                      p["initial_rate_x"], w, b_max))}),
        Series("Fig. 2's rates", {"initial_rate": ("deg/s", ticks / DEG),
                                  "gain": ("A m^2 s/T", study.fig1_gains(p["max_dipole"], p["initial_rate_x"],
                                                                          ticks, b_max))}),
        Series("default (0.1, 10, 10) °/s", {"initial_rate": ("deg/s", [p["initial_rate_y"] / DEG]),
                                             "gain": ("A m^2 s/T", default)}),
    ], extra={"b_max": b_max, "max_dipole": p["max_dipole"]})


def plot_fig1(data):
    fig, ax = _new_figure(3.2)
    line, ticks, default = data.series
    ax.plot(*(line.columns[c][1] for c in ("initial_rate", "gain")), "C0-", label=line.label)
    ax.plot(*(ticks.columns[c][1] for c in ("initial_rate", "gain")), "C0o", ms=4, label=ticks.label)
    ax.plot(*(default.columns[c][1] for c in ("initial_rate", "gain")), "C3s", ms=6, label=default.label)
    ax.set_xlabel("initial rate w about y and z [°/s]")
    ax.set_ylabel(r"$k$ [A·m²·s/T]")
    ax.set_title(f"Reconstruction of SamSat-218D Fig. 1: $k$ for {data.extra['max_dipole']:g} A·m² at "
                 f"$B_\\mathrm{{max}}$ = {data.extra['b_max'] * 1e6:.1f} µT")
    ax.legend()
    ax.grid(alpha=0.3)
    return fig


# --- SamSat Fig. 2 and the estimators -----------------------------------------------------

def _estimator(code):
    index = int(round(code))
    if index not in range(len(ESTIMATORS)) or abs(code - index) > 1e-9:
        raise ValueError(f"estimator must be 0 (model), 1 (hold) or 2 (propagate), got {code!r}")
    return ESTIMATORS[index]


def _duty_label(p):
    """The duty cycle as run (the parameters' values, not the source's 16 s / 1 s)."""
    return f"discrete ({p['on_time']:g} s on / {p['off_time']:g} s off)"


def compute_fig2(estimator=0.0, **params):
    """Median detumble time, continuous and duty-cycled, over Fig. 2's initial rates."""
    name = _estimator(estimator)
    p = {**_defaults(), **params}
    d = study.duty_study(_key(**params), (name,))
    w = d["rates"] / DEG
    damped = np.isfinite(d["median"][name])      # rates the discrete mode does not damp are left out
    return FigureData("", "", "", {}, [
        Series("continuous", {"initial_rate": ("deg/s", w), "duration": ("s", d["median"]["continuous"])}),
        Series(_duty_label(p), {"initial_rate": ("deg/s", w[damped]), "duration": ("s", d["median"][name][damped])}),
    ], extra={"estimator": name, "members": d["members"], "gain": d["gain"],
              "threshold": p["detumble_threshold"] / DEG})


def plot_fig2(data):
    fig, ax = _new_figure(3.3)
    for s, style in zip(data.series, ("C0o-", "C1s--")):
        ax.plot(s.columns["initial_rate"][1], np.asarray(s.columns["duration"][1]) / 3600.0, style, label=s.label)
    ax.set_xlabel(r"initial rate w, $\boldsymbol{\omega}_\mathrm{i}$ = (0.1, w, w) [°/s]")
    ax.set_ylabel(f"time to {data.extra['threshold']:g} °/s [h]")
    ax.set_title(f"Reconstruction of SamSat-218D Fig. 2: median of {data.extra['members']} attitudes, $k$ = "
                 f"{data.extra['gain']:.0f} A·m²·s/T, estimator '{data.extra['estimator']}'")
    ax.legend()
    ax.grid(alpha=0.3)
    return fig


def compute_rate_decay(**params):
    """|ω|(t) of the first member at the default rates (0.1, 10, 10) °/s, both modes."""
    p = {**_defaults(), **params}
    d = study.duty_study(_key(**params), ("model",))
    index = int(np.argmin(np.abs(d["rates"] - p["initial_rate_y"])))
    series = []
    for name, label in (("continuous", "continuous"), ("model", f"{_duty_label(p)}, 'model'")):
        t = d["time"][name]
        series.append(Series(label, {"time": ("s", t), "rate": ("deg/s", d["rate"][name][index, 0] / DEG)}))
    low, mean, high = field_direction_rate_range(study.samsat_orbit(p))
    return FigureData("", "", "", {}, series, extra={"threshold": p["detumble_threshold"] / DEG,
                                                      "w": d["rates"][index] / DEG,
                                                      "field_rate": (low / DEG, mean / DEG, high / DEG)})


def plot_rate_decay(data):
    fig, ax = _new_figure(3.2)
    for s, style in zip(data.series, ("C0-", "C1-")):
        ax.semilogy(s.columns["time"][1] / 3600.0, s.columns["rate"][1], style, lw=1, label=s.label)
    ax.axhline(data.extra["threshold"], color="k", ls=":", lw=1, label=f"{data.extra['threshold']:g} °/s (damped)")
    low, mean, high = data.extra["field_rate"]
    ax.axhspan(low, high, color="0.5", alpha=0.25, lw=0,
               label="rate of the field's direction (B-dot's end state)")
    ax.axhline(mean, color="0.5", ls="--", lw=1, label=r"its mean, $\approx 2\omega_0$")
    ax.set_xlabel("t [h]")
    ax.set_ylabel(r"$|\boldsymbol{\omega}|$ [°/s]")
    ax.set_title(f"Rate decay from $\\boldsymbol{{\\omega}}_\\mathrm{{i}}$ = (0.1, {data.extra['w']:g}, {data.extra['w']:g}) °/s, one attitude")
    ax.legend()
    ax.grid(alpha=0.3, which="both")
    return fig


def compute_duty_estimators(span=1020.0, **params):
    """The share of the continuous mode's damping each estimator keeps over the first
    ``span``, against the initial rate (median over the members)."""
    key = _key(**params)
    d = study.duty_damping(key, span)
    series = [Series(name, {"initial_rate": ("deg/s", d["rates"] / DEG),
                            "ratio": ("1", np.median(d["ratio"][name], axis=-1))}) for name in ESTIMATORS]
    limit = study.held_limit(dict(key)) / DEG
    return FigureData("", "", "", {}, series, extra={"held_limit": limit, "held_limit_w": limit / np.sqrt(2.0),
                                                     "span": span})


def plot_duty_estimators(data):
    fig, ax = _new_figure(3.3)
    for s, style in zip(data.series, ("C1s-", "C2^--", "C4v:")):
        ax.plot(s.columns["initial_rate"][1], s.columns["ratio"][1], style, label=f"discrete, '{s.label}'")
    ax.axvline(data.extra["held_limit_w"], color="k", ls=":", lw=1,
               label=f"$|\\boldsymbol{{\\omega}}_\\mathrm{{i}}| = \\pi/(T_\\mathrm{{on}} + T_\\mathrm{{off}})$ = "
                     f"{data.extra['held_limit']:.1f} °/s")
    ax.axhline(16 / 17, color="0.5", ls="--", lw=1, label="16/17 (the on-time fraction)")
    ax.set_xlabel(r"initial rate w, $\boldsymbol{\omega}_\mathrm{i}$ = (0.1, w, w) [°/s]")
    ax.axhline(0.0, color="k", lw=0.8)
    ax.set_ylabel(r"drop of $|\boldsymbol{\omega}|$, discrete / continuous [1]")
    ax.set_title(f"Damping kept by each Ḃ estimator over the first {data.extra['span']:.0f} s (below 0: spin-up)")
    ax.legend(loc="lower left")
    ax.grid(alpha=0.3)
    return fig


# --- peers ------------------------------------------------------------------------------

def compute_distribution(**params):
    """Detumble times of the 3U envelope's members beside Cp557 and Kovalenko (6.50)."""
    from . import CP557

    key = _key(**params)
    p = dict(key)
    env = study.envelope_distribution(key)
    blanked = study.envelope_distribution(key, blanking=(9.0, 1.0))["held"]
    estimate = kovalenko_detumble_time(max(p["inertia_y"], p["inertia_z"]), p["envelope_gain"],
                                        mean_square_field(env["orbit"]), env["initial_rate"],
                                        p["detumble_threshold"])
    return FigureData("", "", "", {}, [
        Series("simulated (held 30 s)", {"detumble_time": ("s", env["held"][np.isfinite(env["held"])]),
                                         "initial_rate": ("deg/s", env["initial_rate"][np.isfinite(env["held"])]
                                                          / DEG)}),
        Series("Kovalenko (6.50)", {"detumble_time": ("s", estimate),
                                    "initial_rate": ("deg/s", env["initial_rate"] / DEG)}),
        Series("Cp557/detumble README", {"median": ("s", [CP557["median"]]), "p95": ("s", [CP557["p95"]])}),
        Series("simulated, coils blanked 10 %", {"median": ("s", [float(np.nanmedian(blanked))])}),
    ], extra={"members": env["held"].size, "threshold": p["detumble_threshold"] / DEG,
              "rates": (p["envelope_rate_low"] / DEG, p["envelope_rate_high"] / DEG)})


def plot_distribution(data):
    fig, (ax, bx) = _new_figure(3.3, 2)
    sim, kov, cp, blank = data.series
    t = np.sort(sim.columns["detumble_time"][1])
    ax.hist(t, bins=40, color="C0", alpha=0.7, label=sim.label)
    for value, style, label in ((np.median(t), "C0-", "median"), (np.percentile(t, 95), "C0--", "p95"),
                                (blank.columns["median"][1][0], "C1-", "median, coils blanked 10 %"),
                (cp.columns["median"][1][0], "C3-", "Cp557 median"),
                                (cp.columns["p95"][1][0], "C3--", "Cp557 p95"),
                                (np.median(kov.columns["detumble_time"][1]), "C2:", "Kovalenko (6.50) median")):
        ax.axvline(value, color=style[:2], ls=style[2:], lw=1.2, label=label)
    ax.set_xlabel(f"time to {data.extra['threshold']:g} °/s [s]")
    ax.set_ylabel("members")
    ax.set_title("{} members, {:g}–{:g} °/s".format(data.extra["members"], *data.extra["rates"]))
    ax.set_ylim(top=1.9 * ax.get_ylim()[1])        # room for the legend above the bars
    ax.legend(fontsize=7, loc="upper left")
    bx.plot(sim.columns["initial_rate"][1], sim.columns["detumble_time"][1], "C0.", ms=2, label="simulated")
    order = np.argsort(kov.columns["initial_rate"][1])
    bx.plot(kov.columns["initial_rate"][1][order], kov.columns["detumble_time"][1][order], "C2-", label="(6.50)")
    bx.set_xlabel(r"initial $|\boldsymbol{\omega}|$ [°/s]")
    bx.set_ylabel("time [s]")
    bx.set_title("against the initial rate")
    bx.legend()
    return fig


#: The prefixes of the dispersion study at which its statistics are shown (members).
CONVERGENCE_MEMBERS = (100, 200, 500, 1000, 2000, 5000, 10000, 20000)


def compute_convergence(**params):
    """The detumble study's median and 95th percentile (held 30 s) with 95 % bootstrap
    intervals over its first n members, for growing n (each prefix is a study of its own:
    member k's draws do not depend on how many members run)."""
    from ...sim import DispersionTable, dispersion_statistics

    key = _key(**params)
    rows = study.envelope_dispersion(key)
    sizes = [n for n in CONVERGENCE_MEMBERS if n < rows.members] + [rows.members]
    stats = {name: {f: [] for f in ("value", "low", "high")} for name in ("median", "p95")}
    missing = []
    for n in sizes:
        part = DispersionTable(rows.study, rows.seed, rows.parameters,
                               {"member": rows["member"][:n], "held_time": rows["held_time"][:n]})
        for row in dispersion_statistics(part, outcomes=("held_time",)):
            for f in ("value", "low", "high"):
                stats[row["statistic"]][f].append(row[f])
        missing.append(int(np.count_nonzero(np.isnan(rows["held_time"][:n]))))
    series = [Series(name, {"members": ("1", np.array(sizes, dtype=float)),
                            **{f: ("s", np.array(v[f])) for f in ("value", "low", "high")}})
              for name, v in stats.items()]
    series.append(Series("not detumbled", {"members": ("1", np.array(sizes, dtype=float)),
                                           "count": ("1", np.array(missing, dtype=float))}))
    return FigureData("", "", "", {}, series, extra={"seed": rows.seed})


def plot_convergence(data):
    fig, (ax, bx) = _new_figure(3.3, 2)
    first = None
    beyond = False
    for s, color in zip(data.series[:2], ("C0", "C3")):
        n, v, lo, hi = (np.asarray(s.columns[f][1], dtype=float) for f in ("members", "value", "low", "high"))
        # a statistic or an end of its interval among the members not detumbled is +inf:
        # such points are left out, and the figure says so
        ok = np.isfinite(v) & np.isfinite(lo) & np.isfinite(hi) & (v > 0)
        beyond |= not ok.all()
        label = "median" if s.label == "median" else "95th percentile"
        ax.errorbar(n[ok], v[ok], yerr=[v[ok] - lo[ok], hi[ok] - v[ok]], fmt="o-", color=color, capsize=3, ms=4,
                    label=label)
        rel = (hi[ok] - lo[ok]) / v[ok]
        bx.loglog(n[ok], rel, "o-", color=color, ms=4, label=label)
        if first is None and rel.size:
            first = (n[ok], rel[0])
    if first is not None:
        n, width0 = first
        bx.loglog(n, width0 * np.sqrt(n[0] / n), "k:", lw=1, label=r"$\propto 1/\sqrt{N}$")
    if beyond:
        ax.text(0.02, 0.02, "points left out: the statistic or its interval\nlies among members not detumbled",
                transform=ax.transAxes, fontsize=7, va="bottom")
    ax.set_xscale("log")
    ax.set_xlabel("members N")
    ax.set_ylabel("detumble time, held [s]")
    ax.set_title("statistic and its 95 % interval")
    ax.legend(fontsize=8)
    bx.set_xlabel("members N")
    bx.set_ylabel("interval width / statistic [1]")
    bx.set_title("relative width of the interval")
    bx.legend(fontsize=8)
    for axis in (ax, bx):
        axis.grid(alpha=0.3, which="both")
    return fig


def compute_basilisk(**params):
    """The 18 Basilisk runs beside the library (10 Hz sampled and continuous law)."""
    key = _key(**params)
    sampled = study.basilisk_peer(key, mode="sampled")
    continuous = study.basilisk_peer(key)
    return FigureData("", "", "", {}, [
        Series("10 Hz sampled (Basilisk's law)", {"basilisk_time": ("s", sampled["basilisk"]),
                                                  "time": ("s", sampled["ours"])}),
        Series("continuous (exact Ḃ)", {"basilisk_time": ("s", continuous["basilisk"]),
                                        "time": ("s", continuous["ours"])}),
    ])


def plot_basilisk(data):
    fig, (ax, bx) = _new_figure(3.2, 2)
    for s, style in zip(data.series, ("C0o", "C1x")):
        ref, ours = (np.asarray(s.columns[c][1]) for c in ("basilisk_time", "time"))
        ax.plot(ref, ours, style, label=s.label)
        bx.plot(ref, ours - ref, style, label=s.label)
    lim = [1000, 5600]
    ax.plot(lim, lim, "k:", lw=1)
    ax.set_xlabel("Basilisk 2.12.1 [s]")
    ax.set_ylabel("this book's simulation [s]")
    ax.set_title("Detumble time, 18 runs")
    ax.legend()
    bx.axhline(0, color="k", lw=0.8)
    bx.set_xlabel("Basilisk 2.12.1 [s]")
    bx.set_ylabel("this book − Basilisk [s]")
    bx.set_title("difference")
    return fig


def compute_gain_sweep(**params):
    """Against k/k*, projected law, 3U and cube: the unsaturated decay rate of |ω| (the
    quantity k* optimises) and the saturated median time from 10 °/s to the threshold."""
    key = _key(**params)
    d = study.gain_sweep(key)
    r = study.decay_rate_sweep(key)
    series = []
    for name in r["median"]:
        ok = np.isfinite(r["median"][name])
        series.append(Series(f"{name}: decay rate, coils unlimited (k* = {r['k_star'][name]:.3g} N·m·s)",
                             {"gain_ratio": ("1", r["ratios"][ok]), "decay_rate": ("1/s", r["median"][name][ok])}))
    # Gains at which a member is not damped within the run have no median: left out.
    for name in d["median"]:
        ok = np.isfinite(d["median"][name])
        series.append(Series(f"{name}: median time, ±0.2 A·m² rods",
                             {"gain_ratio": ("1", d["ratios"][ok]), "duration": ("s", d["median"][name][ok])}))
    return FigureData("", "", "", {}, series, extra={"band": tuple(b / DEG for b in r["band"]),
                                                     "start": d["initial_rate"] / DEG,
                                                     "threshold": dict(key)["detumble_threshold"] / DEG})


def plot_gain_sweep(data):
    fig, (left, right) = _new_figure(3.4, ncols=2, width=7.0)
    for s, style in zip(data.series[:2], ("C0o-", "C1s--")):
        left.semilogx(s.columns["gain_ratio"][1], 1e3 * s.columns["decay_rate"][1], style,
                      label=s.label.split(":")[0])
    for s, style in zip(data.series[2:], ("C0o-", "C1s--")):
        right.semilogx(s.columns["gain_ratio"][1], s.columns["duration"][1], style, label=s.label.split(":")[0])
    for ax in (left, right):
        ax.axvline(1.0, color="k", ls=":", lw=1)
        ax.set_xlabel(r"gain $k\,/\,k^*$")
        ax.grid(alpha=0.3, which="both")
        ax.legend()
    left.set_ylabel(r"decay rate of $|\boldsymbol{\omega}|$, " + "{:g} → {:g} °/s".format(*data.extra["band"])
                    + r" [10$^{-3}$/s]")
    left.set_title("unsaturated: what $k^*$ optimises")
    right.set_ylabel(f"median time {data.extra['start']:g} → {data.extra['threshold']:g} °/s [s]")
    right.set_title("rods ±0.2 A·m² (gaps: not damped)")
    return fig


# --- TRIAD --------------------------------------------------------------------------------

def compute_triad_geometry(field_sigma, sun_sigma):
    """TRIAD's rms error against angle(H, S): Monte Carlo and Shuster–Oh."""
    d = study.triad_geometry(field_sigma, sun_sigma)
    a = d["angle"] / DEG
    return FigureData("", "", "", {}, [
        Series("Monte Carlo (2000 attitudes)", {"angle": ("deg", a), "rms_error": ("deg", d["monte_carlo"] / DEG)}),
        Series("Shuster & Oh (1981)", {"angle": ("deg", a), "rms_error": ("deg", d["shuster_oh"] / DEG)}),
    ])


def plot_triad_geometry(data):
    fig, ax = _new_figure(3.2)
    for s, style in zip(data.series, ("C0o", "k-")):
        ax.semilogy(s.columns["angle"][1], s.columns["rms_error"][1], style, ms=3, label=s.label)
    ax.set_xlabel("angle between field and Sun [°]")
    ax.set_ylabel("rms attitude error [°]")
    ax.set_title("TRIAD with the field primary")
    ax.legend()
    ax.grid(alpha=0.3, which="both")
    return fig


def compute_triad_rejection(**params):
    """Error CDFs of TRIAD on a synthetic mix, without and with the modulus tests."""
    d = study.triad_rejection(_key(**params))
    e = d["error"] / DEG
    kept = d["field_ok"] & d["sun_ok"]
    clean = ~(d["gross"] | d["albedo"])
    series = []
    for label, mask in (("no test", np.ones_like(kept)), ("modulus tests (field and Sun)", kept),
                        ("clean samples only", clean)):
        x = np.sort(e[mask])
        series.append(Series(label, {"error": ("deg", x), "fraction": ("1", np.arange(1, x.size + 1) / x.size)}))
    return FigureData("", "", "", {}, series)


def plot_triad_rejection(data):
    fig, ax = _new_figure(3.2)
    for s, style in zip(data.series, ("C3-", "C0-", "k--")):
        ax.semilogx(s.columns["error"][1], s.columns["fraction"][1], style, label=s.label)
    ax.set_xlabel("attitude error [°]")
    ax.set_ylabel("fraction of samples")
    ax.set_xlim(0.1, 180)
    ax.set_title("TRIAD on a synthetic mix with gross field errors and albedo (ours)")
    ax.legend()
    ax.grid(alpha=0.3, which="both")
    return fig


register(FigureSpec("samsat-fig1", "Gain k against the initial separation rates (SamSat-218D Fig. 1, reconstruction)",
                    f"{SOURCE}, Fig. 1", compute_fig1, plot_fig1,
                    partial(_parameters, "max_dipole", "initial_rate_x", "initial_rate_y", "fig2_rate_min",
                            "fig2_rate_max", "fig2_rate_step", *_ORBIT)))
register(FigureSpec("samsat-fig2", "Damping time, continuous and discrete modes (SamSat-218D Fig. 2, "
                    "reconstruction)", f"{SOURCE}, Fig. 2", compute_fig2, plot_fig2,
                    partial(_parameters, *_DUTY, estimator=FigureParameter(
                        0.0, "1", "Ḃ estimator of the discrete mode: 0 model, 1 hold, 2 propagate", whole=True)), slow=True))
register(FigureSpec("ch05-rate-decay", "Rate decay, continuous and discrete", f"{SOURCE}, Rate damping",
                    compute_rate_decay, plot_rate_decay,
                    partial(_parameters, *_DUTY), slow=True))
register(FigureSpec("ch05-duty-estimators", "Damping kept by each duty-cycle estimator",
                    f"{SOURCE}, Rate damping (the estimators are ours)", compute_duty_estimators, plot_duty_estimators,
                    partial(_parameters, *_DUTY, span=FigureParameter(
                        1020.0, "s", "span over which |ω| drops (60 cycles; ours)", high=1e5)), slow=True))
register(FigureSpec("ch05-detumble-distribution", "3U envelope: detumble times beside Cp557 and Kovalenko (6.50)",
                    "Cp557/detumble; Kovalenko (1975) eq. (6.50)", compute_distribution, plot_distribution,
                    partial(_parameters, *_ENVELOPE), slow=True))
register(FigureSpec("ch05-dispersion-convergence",
                    "Detumble dispersion study: median and 95th percentile with bootstrap intervals as members grow",
                    "ours (the 3U envelope of Cp557/detumble)", compute_convergence, plot_convergence,
                    partial(_parameters, *_ENVELOPE, "dispersion_members"), slow=True))
register(FigureSpec("ch05-basilisk-peer", "Detumble times beside Basilisk's 18 runs",
                    "Basilisk 2.12.1, 18 runs of the same case", compute_basilisk, plot_basilisk,
                    partial(_parameters, "inertia_x", "inertia_y", "inertia_z", "max_dipole", "detumble_threshold",
                                "envelope_altitude", "envelope_inclination", "envelope_dipole_field",
                                "envelope_dipole_tilt", "envelope_gain"), slow=True))
register(FigureSpec("ch05-gain-sweep", "Projected B-dot: unsaturated decay rate and saturated detumble time against k/k*",
                    "Avanzini & Giulietti (2012); Kovalenko (1975) eq. (6.7)", compute_gain_sweep, plot_gain_sweep,
                    partial(_parameters, "inertia_x", "inertia_y", "inertia_z", "max_dipole", "detumble_threshold",
                                "earth_rotation_rate", "envelope_altitude", "envelope_inclination",
                                "envelope_dipole_field", "envelope_dipole_tilt", "envelope_seed",
                                "integration_step"), slow=True))
register(FigureSpec("ch05-triad-geometry", "TRIAD's error against the field–Sun angle", f"{SOURCE}, Attitude "
                    "determination; Shuster & Oh (1981)", compute_triad_geometry, plot_triad_geometry,
                    partial(_parameters, "field_sigma", "sun_sigma")))
register(FigureSpec("ch05-triad-rejection", "TRIAD with and without the modulus tests",
                    f"{SOURCE}, Attitude determination (the rejection tests)", compute_triad_rejection, plot_triad_rejection,
                    partial(_parameters, *_ORBIT, "rejection_margin", "magnetometer_noise", "field_model_error")))
