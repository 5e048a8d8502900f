"""Figures of chapter 9: Kovalenko's Figs. 5.10–5.15 regenerated (detumbling with coils,
unloading of reaction wheels), the stability argument over an orbit, the unloading against
the attitude loop, duty cycling and the unloading capacity against inclination.

Kovalenko's plots survive only as captions: every curve here is computed; his printed
thresholds are marked.
"""

import numpy as np

from . import (CHAPTER, INITIAL_WHEEL_MOMENTUM, SETTLING_ORBITS, attitude_study, capacity_study, detumbling_study,
               duty_study, lyapunov_orbit, unloading_study)
from .._base import FigureInputs
from ..registry import FigureData, FigureSpec, Series, register

SOURCE = "Kovalenko (1975)"

#: Each figure's description of the chapter inputs it exposes: (description, bounds).
_INPUTS = {
    "det_initial_momentum": ("initial |K_i| on each axis (printed 98)", {}),
    "det_dipole": ("the smallest coil L0 of Fig. 5.10 (printed 56.5; the others 2–4 times it)", {}),
    "det_threshold": ("K° of Fig. 5.10's relay law (printed 9.8)", {}),
    "det_threshold_step": ("K° of Fig. 5.11's curve 1 (printed 0.98; the others 2–4 times it)", {}),
    "det_gain": ("k of the linear law (ours)", {}),
    "det_ladder_dipole": ("L0 of Fig. 5.11's runs (ours)", {}),
    "det_orbits": ("length of the detumbling runs (ours)", {"low": 2.0, "high": 60.0}),
    "unl_altitude": ("altitude of the unloading runs' orbit (printed 450 km)", {}),
    "unl_dipole": ("the relay coils' L0 (printed 50)", {}),
    "unl_disturbance": ("the constant disturbance on each axis (printed 1e-4)", {}),
    "unl_on_threshold": ("K2°, the relay's on-threshold (printed 1.96)", {}),
    "unl_release": ("K1° of Figs. 5.14–5.15 and the runs beside the ladder (printed 0.5)", {}),
    "unl_signal_dead_zone": ("δ0 of Fig. 5.12 (printed 5e-6)", {}),
    "unl_signal_dead_zone_pole": ("δ0 of Fig. 5.13 (printed 1.25e-6)", {}),
    "unl_orbits": ("length of the unloading runs (ours)", {"low": 3.0, "high": 40.0}),
    "unl_linear_gain": ("k of the switched linear law (ours)", {}),
    "wheel_attitude_gain": ("k_p of the attitude loop (ours)", {}),
    "wheel_rate_gain": ("k_d of the attitude loop (ours)", {}),
    "duty_interval": ("the coils' control interval (ours, SamSat-218D's 17 s)", {"low": 2.0, "high": 600.0}),
    "duty_off_time": ("the coils' off time per interval (ours, SamSat-218D's 1 s)", {"low": 0.25}),
}

_DETUMBLING_NAMES = ("det_initial_momentum", "det_dipole", "det_threshold", "det_gain", "det_orbits")
_THRESHOLD_NAMES = ("det_initial_momentum", "det_threshold_step", "det_ladder_dipole", "det_orbits")
_UNLOADING_NAMES = ("unl_dipole", "unl_disturbance", "unl_on_threshold", "unl_release", "unl_signal_dead_zone",
                    "unl_signal_dead_zone_pole", "unl_orbits", "unl_linear_gain")
_ATTITUDE_NAMES = _UNLOADING_NAMES + ("wheel_attitude_gain", "wheel_rate_gain")
_DUTY_NAMES = ("unl_dipole", "unl_disturbance", "unl_on_threshold", "unl_release", "unl_signal_dead_zone",
               "unl_linear_gain", "duty_interval", "duty_off_time")


FIGURE_INPUTS = FigureInputs(CHAPTER.key, CHAPTER.source, _INPUTS)
_with = FIGURE_INPUTS.merged


# --- Figs. 5.10–5.11: detumbling ----------------------------------------------------------------

def compute_fig5_10(**params):
    """|K| against orbits for the four coils of Fig. 5.10 under the linear, relay and product laws."""
    s = detumbling_study(_with(params))
    run, orbits = s["run"], s["run"].time / s["period"]
    series = []
    for law, label in (("linear", "linear law (5.1)"), ("relay", "relay law (5.7), K° = {:g}"),
                       ("product", "product law (5.11), no 1/B²")):
        for j, member in enumerate(range(s["slices"][law].start, s["slices"][law].stop)):
            text = label.format(_with(params)["det_threshold"]) if "{" in label else label
            series.append(Series(f"{text}, L0 = {s['dipoles'][j]:g} A·m²",
                                 {"orbits": ("1", orbits), "momentum": ("N m s", run.momentum[:, member]),
                                  "done_orbits": ("1", [s["done"][member] / s["period"]])}))
    return FigureData("", "", "", {}, series, extra={"dipoles": s["dipoles"]})


def plot_fig5_10(data):
    """Left: |K| against orbits. Right: the time to a tenth of the start against L0."""
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(1, 2, figsize=(7.0, 3.1), gridspec_kw={"width_ratios": [1.4, 1.0]})
    dipoles = data.extra["dipoles"]
    styles = {"linear": "-", "relay": "--", "product": ":"}
    done = {k: [] for k in styles}
    for s in data.series:
        law = s.label.split(" ")[0]
        j = len(done[law])
        done[law].append(s.columns["done_orbits"][1][0])
        if law != "product":
            axes[0].plot(s.columns["orbits"][1], s.columns["momentum"][1], styles[law], color=f"C{j}", linewidth=1.0,
                         label=f"L0 = {dipoles[j]:g} A·m²" if law == "linear" else None)
    axes[0].plot([], [], "k-", label="linear law (5.1)")
    axes[0].plot([], [], "k--", label="relay law (5.7)")
    axes[0].set_xlabel("orbits")
    axes[0].set_ylabel("|K| [N·m·s]")
    axes[0].legend(fontsize=7)
    for law, marker in (("linear", "o-"), ("relay", "s--"), ("product", "^:")):
        axes[1].plot(dipoles, done[law], marker, color="k", markersize=4, linewidth=0.9,
                     label={"linear": "linear (5.1)", "relay": "relay (5.7)", "product": "product (5.11)"}[law])
    scale = done["linear"][0] * dipoles[0]
    grid = np.linspace(dipoles.min(), dipoles.max(), 50)
    axes[1].plot(grid, scale / grid, color="C7", linewidth=2.5, alpha=0.5, label="∝ 1/L0")
    axes[1].set_xlabel("L0 [A·m²]")
    axes[1].set_ylabel("orbits to |K| = 0.1 |K|₀")
    axes[1].legend(fontsize=7)
    for ax in axes:
        ax.grid(alpha=0.3)
    return fig


def compute_fig5_11(**params):
    """|K| against orbits for the four thresholds K° of Fig. 5.11 (relay law)."""
    s = detumbling_study(_with(params))
    run, orbits = s["run"], s["run"].time / s["period"]
    members = range(s["slices"]["threshold"].start, s["slices"]["threshold"].stop)
    return FigureData("", "", "", {}, [
        Series(f"K° = {k:g} N·m·s", {"orbits": ("1", orbits), "momentum": ("N m s", run.momentum[:, m]),
                                     # empty where the run never reaches the level (K° = 0.98 N·m·s)
                                     "level_orbits": ("1", [s["level_time"][m] / s["period"]]
                                                      if np.isfinite(s["level_time"][m]) else []),
                                     "residual": ("N m s", [s["residual"][m]])})
        for k, m in zip(s["thresholds"], members)], extra={"level": 4.0 * float(s["thresholds"].max())})


def plot_fig5_11(data):
    """Left: |K| against orbits, log scale. Right: time to a common level and the residual, against K°."""
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(1, 2, figsize=(7.0, 3.1), gridspec_kw={"width_ratios": [1.4, 1.0]})
    k0 = []
    for j, s in enumerate(data.series):
        axes[0].semilogy(s.columns["orbits"][1], s.columns["momentum"][1], color=f"C{j}", linewidth=1.0, label=s.label)
        k0.append(float(s.label.split("= ")[1].split(" ")[0]))
    axes[0].axhline(data.extra["level"], color="k", linestyle=":", linewidth=0.8)
    axes[0].set_xlabel("orbits")
    axes[0].set_ylabel("|K| [N·m·s]")
    axes[0].legend(fontsize=7)
    reached = [(k, s.columns["level_orbits"][1][0]) for k, s in zip(k0, data.series) if len(s.columns["level_orbits"][1])]
    residual = [s.columns["residual"][1][0] for s in data.series]
    axes[1].plot(*zip(*reached), "ko-", markersize=4, label=f"orbits to |K| = {data.extra['level']:.1f} N·m·s")
    twin = axes[1].twinx()
    twin.plot(k0, residual, "s--", color="C3", markersize=4, label="|K| at the end")
    axes[1].set_xlabel("K° [N·m·s]")
    axes[1].set_ylabel("orbits")
    twin.set_ylabel("|K| at the end [N·m·s]", color="C3")
    lines = axes[1].get_legend_handles_labels()[0] + twin.get_legend_handles_labels()[0]
    axes[1].legend(lines, [ln.get_label() for ln in lines], fontsize=7, loc="center right")
    axes[0].grid(alpha=0.3, which="both")
    axes[1].grid(alpha=0.3)
    return fig


# --- Figs. 5.12–5.15: unloading -----------------------------------------------------------------

def _unloading_series(s, members, labels):
    run, orbits = s["run"], s["run"].time / s["period"]
    return [Series(label, {"orbits": ("1", orbits), "kx": ("N m s", run.wheel_momentum_x[:, m]),
                           "ky": ("N m s", run.wheel_momentum_y[:, m]), "kz": ("N m s", run.wheel_momentum_z[:, m])})
            for m, label in zip(members, labels)]


def _compute_ladder(params, start):
    p = _with(params)
    s = unloading_study(p)
    first = 0 if start == "equator" else s["per_start"]
    labels = [f"K1° = {k:g} N·m·s" for k in s["releases"]]
    return FigureData("", "", "", {}, _unloading_series(s, range(first, first + len(labels)), labels),
                      extra={"on": p["unl_on_threshold"]})


def compute_fig5_12(**params):
    """Wheel momentum per axis, the relay law with Fig. 5.12's five K1°, starting over the equator."""
    return _compute_ladder(params, "equator")


def compute_fig5_13(**params):
    """The same, starting at the top of the orbit with δ0 = 1.25·10⁻⁶ T (Fig. 5.13)."""
    return _compute_ladder(params, "pole")


def plot_unloading(data):
    """Three panels, K_x, K_y, K_z against orbits; the on-threshold ±K2° dotted."""
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(3, 1, figsize=(7.0, 5.2), sharex=True)
    for j, s in enumerate(data.series):
        for ax, key in zip(axes, ("kx", "ky", "kz")):
            ax.plot(s.columns["orbits"][1], s.columns[key][1], color=f"C{j}", linewidth=0.8,
                    label=s.label if key == "kx" else None)
    for ax, name in zip(axes, ("K_x", "K_y", "K_z")):
        for sign in (-1, 1):
            ax.axhline(sign * data.extra["on"], color="k", linestyle=":", linewidth=0.8)
        ax.set_ylabel(f"{name} [N·m·s]")
        ax.grid(alpha=0.3)
    axes[0].legend(fontsize=7, ncol=3, loc="upper right")
    axes[-1].set_xlabel("orbits")
    return fig


def compute_fig5_14_15(**params):
    """Wheel momentum per axis for the Sun at ρ_c = 0, 225° (Fig. 5.14) and 45° (Fig. 5.15), K1° = 0.5."""
    p = _with(params)
    s = unloading_study(p)
    n = s["per_start"]
    releases = list(s["releases"])
    first = releases.index(p["unl_release"]) if p["unl_release"] in releases else 0
    members = [first, 2 * n, 2 * n + 1]
    labels = [f"ρc = {np.degrees(s['sun_longitude'][m]):g}°" + (" (Fig. 5.12's curve)" if m == first else
                                                              " (Fig. 5.14)" if m == 2 * n else " (Fig. 5.15)")
              for m in members]
    return FigureData("", "", "", {}, _unloading_series(s, members, labels), extra={"on": p["unl_on_threshold"]})


def compute_band(**params):
    """The steady band of |K_i| and the coils' duty for every law and start of the unloading runs."""
    p = _with(params)
    s = unloading_study(p)
    n = s["per_start"]
    names = [f"K1° = {k:g}" for k in s["releases"]] + ["no hysteresis", "linear, switched"]
    series = []
    for start, first in (("over the equator", 0), ("at the top", n)):
        m = np.arange(first, first + n)
        series.append(Series(f"start {start}", {"law": ("1", np.arange(n)),
                                                "band_max": ("N m s", s["band_max"][:, m].max(axis=0)),
                                                "band_min": ("N m s", s["band_min"][:, m].min(axis=0)),
                                                "duty": ("1", s["duty"][m])}))
    return FigureData("", "", "", {}, series, extra={"names": names, "on": p["unl_on_threshold"],
                                                     "releases": s["releases"]})


def plot_band(data):
    """Left: the largest and smallest |K_i| per law. Right: the coils' duty."""
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(1, 2, figsize=(7.0, 3.2), gridspec_kw={"width_ratios": [1.5, 1.0]})
    names = data.extra["names"]
    x = np.arange(len(names))
    for j, (s, dx) in enumerate(zip(data.series, (-0.15, 0.15))):
        axes[0].vlines(x + dx, s.columns["band_min"][1], s.columns["band_max"][1], color=f"C{j}", linewidth=3,
                       label=s.label)
        axes[1].bar(x + dx, 100 * s.columns["duty"][1], width=0.3, color=f"C{j}", label=s.label)
    axes[0].plot(x[:len(data.extra["releases"])], data.extra["releases"], "k_", markersize=12, label="K1°")
    axes[0].axhline(data.extra["on"], color="k", linestyle=":", linewidth=0.8, label="K2°")
    axes[0].set_ylabel("min and max of |K_i| [N·m·s]")
    axes[0].set_ylim(0.0, 1.5 * data.extra["on"])
    axes[1].set_ylabel("coils on [% of the time]")
    for ax in axes:
        ax.set_xticks(x)
        ax.set_xticklabels(names, rotation=60, ha="right", fontsize=7.5)
        ax.grid(alpha=0.3, axis="y")
    axes[0].legend(fontsize=7, ncol=2, loc="upper center")
    return fig


# --- beyond the source -------------------------------------------------------------------------

def compute_lyapunov(**params):
    """|K| and its part along B over one orbit of the linear law, no disturbance."""
    s = lyapunov_orbit(_with(params))
    orbits = s["run"].time / s["period"]
    return FigureData("", "", "", {}, [
        Series("|K|", {"orbits": ("1", orbits), "momentum": ("N m s", s["momentum"])}),
        Series("K·B/|B|", {"orbits": ("1", orbits), "momentum": ("N m s", s["along"])}),
    ])


def plot_lyapunov(data):
    """Both curves against the orbit fraction."""
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(5.6, 3.0))
    for s, style in zip(data.series, ("C0-", "C3--")):
        ax.plot(s.columns["orbits"][1], s.columns["momentum"][1], style, label=s.label)
    ax.axhline(0.0, color="k", linewidth=0.6)
    ax.set_xlabel("orbits")
    ax.set_ylabel("[N·m·s]")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7.5)
    return fig


def compute_attitude(**params):
    """Wheel momentum, coil dipole and attitude error with the PD loop, for three laws and two starts."""
    s = attitude_study(_with(params))
    run, orbits = s["run"], s["run"].time / s["period"]
    series = []
    for m in range(s["members"]):
        law, start = s["laws"][m % 3], ("equator", "top")[m // 3]
        series.append(Series(f"{law}, start {start}", {
            "orbits": ("1", orbits), "wheel_momentum": ("N m s", run.wheel_momentum[:, m]),
            "attitude_error": ("deg", np.degrees(run.attitude_error[:, m])),
            "dipole": ("A m^2", np.sqrt(run.dipole_x[:, m] ** 2 + run.dipole_y[:, m] ** 2 + run.dipole_z[:, m] ** 2))}))
    return FigureData("", "", "", {}, series)


def plot_attitude(data):
    """|h_w| and the attitude error against orbits, starts over the equator (the top's are alike)."""
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(2, 1, figsize=(7.0, 4.4), sharex=True)
    for j, s in enumerate(data.series[:3]):
        style = dict(color=f"C{j}", linewidth=0.8, label=s.label.replace(", start equator", ""))
        axes[0].plot(s.columns["orbits"][1], s.columns["wheel_momentum"][1], **style)
        axes[1].plot(s.columns["orbits"][1], s.columns["attitude_error"][1], **style)
    axes[0].set_ylabel("|h_w| [N·m·s]")
    axes[0].set_yscale("log")
    axes[1].set_ylabel("attitude error [°]")
    axes[1].set_xlabel("orbits")
    axes[0].legend(fontsize=7, title="unloading law", title_fontsize=7)
    for ax in axes:
        ax.grid(alpha=0.3, which="both")
    return fig


def compute_duty(**params):
    """The largest |K_i| over time, coils always available against duty-cycled."""
    s = duty_study(_with(params))
    series = []
    for name in ("continuous", "cycled"):
        run = s[name]
        k = np.max(np.abs(np.stack([run.wheel_momentum_x, run.wheel_momentum_y, run.wheel_momentum_z])), axis=0)
        for j, law in enumerate(s["laws"]):
            series.append(Series(f"{law}, {name}", {"orbits": ("1", run.time / s["period"]),
                                                    "largest": ("N m s", k[:, j])}))
    return FigureData("", "", "", {}, series, extra={"on_fraction": s["on_fraction"]})


def plot_duty(data):
    """max_i |K_i| against orbits for both laws, continuous (solid) and cycled (dashed)."""
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(7.0, 3.0))
    for s in data.series:
        law, mode = s.label.split(", ")
        ax.plot(s.columns["orbits"][1], s.columns["largest"][1], "-" if mode == "continuous" else "--",
                color="C0" if law == "relay" else "C2", linewidth=0.8, label=s.label)
    ax.set_xlabel("orbits")
    ax.set_ylabel("max |K_i| [N·m·s]")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7, ncol=2)
    return fig


def compute_capacity(**params):
    """The unloadable fraction of the worst-placed momentum against inclination."""
    s = capacity_study(_with(params))
    i = np.degrees(s["inclination"])
    return FigureData("", "", "", {}, [
        Series("law without 1/B² (5.6): closed form", {"inclination": ("deg", i), "fraction": ("1", s["worst"])}),
        Series("law (5.1), with 1/B²: closed form", {"inclination": ("deg", i),
                                                      "fraction": ("1", s["worst_normalised"])}),
        Series("law without 1/B²: one orbit simulated", {"inclination": ("deg", np.degrees(s["points"])),
                                                         "fraction": ("1", s["simulated"])}),
    ])


def plot_capacity(data):
    """Two closed-form curves and the simulated points."""
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(5.6, 3.2))
    ax.plot(data.series[0].columns["inclination"][1], data.series[0].columns["fraction"][1], "C0-",
            label=data.series[0].label)
    ax.plot(data.series[1].columns["inclination"][1], data.series[1].columns["fraction"][1], "C2--",
            label=data.series[1].label)
    ax.plot(data.series[2].columns["inclination"][1], data.series[2].columns["fraction"][1], "ko", markersize=4,
            label=data.series[2].label)
    ax.set_xlabel("inclination to the dipole's equator [°]")
    ax.set_ylabel("unloadable fraction, worst direction")
    ax.set_xticks([0, 15, 30, 45, 60, 75, 90])
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7)
    return fig


register(FigureSpec("kov-fig5-10", "Detumbling with coils: the momentum for four coil dipoles, linear and relay "
                    "laws (Kovalenko Fig. 5.10, regenerated)", f"{SOURCE} §5.5, Fig. 5.10 (caption only); eqs. "
                    "(5.10)–(5.18)", compute_fig5_10, plot_fig5_10, FIGURE_INPUTS.table(_DETUMBLING_NAMES)))
register(FigureSpec("kov-fig5-11", "Detumbling with the relay law: the momentum for four thresholds K° "
                    "(Kovalenko Fig. 5.11, regenerated)", f"{SOURCE} §5.5, Fig. 5.11 (caption only)", compute_fig5_11,
                    plot_fig5_11, FIGURE_INPUTS.table(_THRESHOLD_NAMES)))
register(FigureSpec("kov-fig5-12", "Unloading the wheels, start over the equator: momentum per axis for five "
                    "release thresholds (Kovalenko Fig. 5.12, regenerated)", f"{SOURCE} §5.5, Fig. 5.12 (caption "
                    "only)", compute_fig5_12, plot_unloading, FIGURE_INPUTS.table(_UNLOADING_NAMES)))
register(FigureSpec("kov-fig5-13", "Unloading the wheels, start at the top of the orbit (Kovalenko Fig. 5.13, "
                    "regenerated)", f"{SOURCE} §5.5, Fig. 5.13 (caption only)", compute_fig5_13, plot_unloading,
                    FIGURE_INPUTS.table(_UNLOADING_NAMES)))
register(FigureSpec("kov-fig5-14-15", "Unloading the wheels with the Sun elsewhere on the ecliptic (Kovalenko Figs. "
                    "5.14–5.15, regenerated)", f"{SOURCE} §5.5, Figs. 5.14–5.15 (captions only); §2.3 (2.29)",
                    compute_fig5_14_15, plot_unloading, FIGURE_INPUTS.table(_UNLOADING_NAMES)))
register(FigureSpec("kov-unloading-band", "The steady band of wheel momentum and the coils' duty for every "
                    "unloading law", f"{SOURCE} §5.5 (the runs of Figs. 5.12–5.13)", compute_band, plot_band,
                    FIGURE_INPUTS.table(_UNLOADING_NAMES)))
register(FigureSpec("kov-unloading-lyapunov", "The linear law over one orbit: |K| never grows, its part along B "
                    "is not removed", f"{SOURCE} §5.2, eqs. (5.1)–(5.5)", compute_lyapunov, plot_lyapunov,
                    FIGURE_INPUTS.table(("unl_linear_gain",))))
register(FigureSpec("kov-unloading-attitude", "Unloading with the body held in the orbital frame by its wheels",
                    f"{SOURCE} §5.4, eqs. (5.35)–(5.47) (the attitude loop ours)", compute_attitude, plot_attitude,
                    FIGURE_INPUTS.table(_ATTITUDE_NAMES)))
register(FigureSpec("kov-unloading-duty", "Unloading with the coils off while the magnetometer reads",
                    f"{SOURCE} §3.7, p. 75; SamSat-218D's duty cycle", compute_duty, plot_duty,
                    FIGURE_INPUTS.table(_DUTY_NAMES)))
register(FigureSpec("kov-unloading-capacity", "How much momentum coils can unload, against the orbit's inclination",
                    "ours (derived); Kovalenko (1975) §5.2, eq. (2.36)", compute_capacity, plot_capacity,
                    FIGURE_INPUTS.table(("unl_altitude",))))
