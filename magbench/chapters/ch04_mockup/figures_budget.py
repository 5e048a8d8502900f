"""Figures of the bench's error budget (thesis §4.4, the measured 10°).

``ch04-budget-oat``: the final error band against each hardware error source across its
range, the others nominal, for both targets. ``ch04-budget-sobol``: first-order and
total Sobol indices of the error band (SALib) and its distribution over the whole
allowed space beside the thesis's 10°. The sources and their ranges are
``magbench/data/bench/error_sources.toml`` (:mod:`magbench.chapters.ch04_mockup.budget`); the
budget's runs are :mod:`magbench.sim.bench.budget`.
"""

import numpy as np

from ...io import measurement
from ...sim import bench
from . import budget
from .models import bench_setup
from ..registry import FigureData, FigureParameter, FigureSpec, Series, register
from .figures_bench import _input_parameters

SOURCE = ("Bui (2016), thesis §4.4 (measured 10°); the error sources' ranges from datasheets, the thesis "
          "and ours; the bench model is ours (chapter 4)")
TARGETS = (np.pi / 3.0, 2.0 * np.pi / 3.0)

#: Short labels of the sources on the figures.
LABELS = {
    "gyro_offset": "gyro zero-rate offset", "gyro_drift": "gyro offset drift over a run",
    "magnetometer_offset_x": "magnetometer hard iron, coil-1 axis",
    "magnetometer_offset_y": "magnetometer hard iron, coil-2 axis",
    "magnetometer_scale_difference": "magnetometer scale difference x/y",
    "magnetometer_cross_axis": "magnetometer cross-axis", "magnetometer_misalignment": "magnetometer misalignment",
    "background_h": "uncancelled lab field (across axis)", "background_azimuth": "lab field azimuth",
    "heading_ripple": "field non-uniformity over the swing", "coil_misalignment_1": "coil 1 axis misalignment",
    "coil_misalignment_2": "coil 2 axis misalignment", "coil_field_coupling": "coils' field at magnetometer",
    "thread_stiffness": "thread torsion stiffness", "thread_neutral_angle": "thread neutral angle",
    "filter_coefficient": "filter coefficient $A_f$", "sample_interval": "loop period $\\Delta t$",
    "pwm_levels": "PWM resolution", "moment_scale_1": "coil 1 moment", "moment_scale_2": "coil 2 moment",
    "release_angle": "release angle", "release_rate": "release rate",
}


def _budget_parameters(extra):
    params = dict(extra)
    params.update(_input_parameters())
    return params


def _common(p):
    setup = bench_setup(p)
    return setup, dict(duration=p["bench_duration"], window=p["bench_error_window"],
                       field_h=p["bench_field_h"])


def compute_oat(budget_points, **p):
    """Error band against each source across its range, both targets."""
    setup, kw = _common(p)
    sources = budget.load_error_sources()
    res = bench.one_at_a_time(setup, TARGETS, sources, points=int(round(budget_points)),
                              seed=int(p["bench_seed"]), **kw)
    series = []
    for k, target in enumerate(TARGETS):
        for name, (x, band, ind) in res.items():
            s = sources[name]
            series.append(Series(f"{name} @ {np.degrees(target):.0f}", {
                "value": (s.unit, s.to_display(x)), "error_band": ("deg", np.degrees(band[k])),
                "indicated_error_band": ("deg", np.degrees(ind[k]))}))
    return FigureData("", "", "", {}, series, extra={
        "measured_error": measurement("orientation-error").value, "names": list(sources),
        "sources": {k: (s.source, s.unit) for k, s in sources.items()}})


def oat_maxima(data):
    """Largest error band over each source's range [deg], both targets: {name: max}."""
    out = {}
    for s in data.series:
        name = s.label.split(" @ ")[0]
        out[name] = max(out.get(name, 0.0), float(np.max(s.columns["error_band"][1])))
    return out


def plot_oat(data):
    """Tornado: the largest error band over each source's range, log scale, 10° marked."""
    import matplotlib.pyplot as plt

    measured = np.degrees(data.extra["measured_error"])
    per_target = {}
    for s in data.series:
        name, target = s.label.split(" @ ")
        per_target.setdefault(target, {})[name] = float(np.max(s.columns["error_band"][1]))
    names = sorted(data.extra["names"], key=lambda n: max(v[n] for v in per_target.values()))
    fig, ax = plt.subplots(figsize=(7.0, 6.4), layout="constrained")
    y = np.arange(len(names))
    for k, (target, vals) in enumerate(sorted(per_target.items())):
        ax.barh(y + (k - 0.5) * 0.38, [vals[n] for n in names], height=0.38, color=f"C{k}",
                label=rf"$\psi_\mathrm{{des}}$ = {target}°")
    ax.axvline(measured, color="C3", linewidth=2, label=f"thesis: {measured:.0f}°")
    ax.set_yticks(y, [f"{LABELS.get(n, n)} ({data.extra['sources'][n][0]})" for n in names], fontsize=7.5)
    ax.set_xscale("log")
    ax.set_xlabel("largest final error band over the source's range, others nominal [deg]", fontsize=8)
    ax.tick_params(axis="x", labelsize=7.5)
    ax.legend(fontsize=7.5, loc="lower right")
    ax.set_title("One at a time: what each error source can do alone", fontsize=9)
    return fig


def compute_sobol(budget_base_samples, budget_seed, **p):
    """Sobol indices and the distribution of the error band over the allowed space (ψ_des = π/3),
    and the same distribution with the gyro's offset and drift held at zero (N/2)."""
    setup, kw = _common(p)
    sources = budget.load_error_sources()
    threshold = measurement("orientation-error").value
    n = int(round(budget_base_samples))
    seed = int(round(budget_seed))
    problem, values = bench.sobol_design(sources, base_samples=n, seed=seed)
    problem_ng, values_ng = bench.sobol_design(sources, base_samples=max(2, n // 2), seed=seed + 1,
                                               fixed={"gyro_offset": 0.0, "gyro_drift": 0.0})
    # Both designs in one batch of members: the runs' cost is mostly per time step.
    m = len(next(iter(values.values())))
    both = {k: np.concatenate([values[k], values_ng[k]]) for k in values}
    band, ind = bench.source_error_bands(setup, TARGETS[0], both, seed=seed, **kw)
    res = bench.sobol_analysis(problem, values, band[:m], ind[:m], threshold=threshold, seed=seed)
    no_gyro = bench.sobol_analysis(problem_ng, values_ng, band[m:], ind[m:], threshold=threshold, seed=seed)
    names = res["names"]
    series = [
        Series("Sobol indices", {
            "S1": ("1", np.array([res["S1"][k] for k in names])),
            "S1_conf": ("1", np.array([res["S1_conf"][k] for k in names])),
            "ST": ("1", np.array([res["ST"][k] for k in names])),
            "ST_conf": ("1", np.array([res["ST_conf"][k] for k in names]))}),
        Series("all sources", {"error_band": ("deg", np.degrees(res["band"])),
                               "indicated_error_band": ("deg", np.degrees(res["indicated"]))}),
        Series("no gyro offset, drift", {"error_band": ("deg", np.degrees(no_gyro["band"])),
                                              "indicated_error_band": ("deg", np.degrees(no_gyro["indicated"]))}),
    ]
    return FigureData("", "", "", {}, series, extra={
        "names": names, "measured_error": threshold, "fraction": res["fraction"],
        "fraction_ci": res["fraction_ci"], "runs": res["runs"], "fraction_no_gyro": no_gyro["fraction"],
        "fraction_no_gyro_ci": no_gyro["fraction_ci"], "runs_no_gyro": no_gyro["runs"],
        "values": res["values"], "base_samples": n})


def plot_sobol(data):
    """Left: S1 and ST with 95 % intervals for the leading sources; right: distribution."""
    import matplotlib.pyplot as plt

    e = data.extra
    cols = {k: v for k, (u, v) in data.series[0].columns.items()}
    order = np.argsort(cols["ST"])[::-1][:8][::-1]
    names = [e["names"][i] for i in order]
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(7.0, 4.0), layout="constrained",
                                 gridspec_kw={"width_ratios": [1.15, 1.0]})
    y = np.arange(len(names))
    a1.barh(y + 0.2, cols["S1"][order], 0.38, xerr=cols["S1_conf"][order], color="C0", label="first order $S_1$",
            error_kw={"linewidth": 0.8})
    a1.barh(y - 0.2, cols["ST"][order], 0.38, xerr=cols["ST_conf"][order], color="C1", label="total $S_T$",
            error_kw={"linewidth": 0.8})
    a1.set_yticks(y, [LABELS.get(n, n) for n in names], fontsize=7.5)
    a1.set_xlabel("Sobol index of the error band (95 % interval)", fontsize=8)
    a1.axvline(0.0, color="0.5", linewidth=0.6)
    a1.legend(fontsize=7.5, loc="lower right")
    a1.tick_params(axis="x", labelsize=7.5)
    measured = np.degrees(e["measured_error"])
    allv = [s.columns["error_band"][1] for s in data.series[1:]]
    low = min(float(np.min(v)) for v in allv)
    edges = np.logspace(np.floor(np.log10(max(low, 1e-4))), np.log10(5.0 * measured), 40)
    for s, v, c in zip(data.series[1:], allv, ("C0", "C2")):
        a2.hist(v, bins=edges, histtype="step", linewidth=1.4, color=c, density=False,
                label=f"{s.label} ({v.size})")
    a2.axvline(measured, color="C3", linewidth=2, label=f"thesis: {measured:.0f}°")
    a2.set_xscale("log")
    a2.set_xlabel(r"final error band, $\psi_\mathrm{des}$ = 60° [deg]", fontsize=8)
    a2.set_ylabel("runs", fontsize=8)
    a2.tick_params(labelsize=7.5)
    a2.legend(fontsize=7, loc="upper left", frameon=False)
    fig.suptitle(f"Over the whole allowed space (N = {e['base_samples']}, {e['runs']} runs for the indices)",
                 fontsize=9)
    return fig


register(FigureSpec("ch04-budget-oat", "Error budget: each source alone across its range",
                    SOURCE, compute_oat, plot_oat, lambda: _budget_parameters({
                        "budget_points": FigureParameter(5.0, "1", "values per source, ends included", high=20.0, whole=True)}), slow=True))
register(FigureSpec("ch04-budget-sobol", "Error budget: Sobol indices and the error over the allowed space",
                    SOURCE, compute_sobol, plot_sobol, lambda: _budget_parameters({
                        "budget_base_samples": FigureParameter(128.0, "1", "N of Saltelli's sample (power of 2)", high=1024.0, whole=True),
                        "budget_seed": FigureParameter(14.0, "1", "seed of the Sobol sequence and noise", whole=True)}), slow=True))
