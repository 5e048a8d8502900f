"""Figures of thesis chapter 4's PID gains: the sweeps of thesis Figs. 15–18, literally in
SI and under a unit hypothesis, and the linear analysis of a stable SI design (root locus,
margins, linear against nonlinear step responses).

python-control (``control``) is imported inside the functions that use it: the root
locus, margins and linear step responses come from it.
"""

import numpy as np

from ... import control
from ... import sim
from ...constants import MU_0
from ..._format import format_number
from . import KD_SWEEP, KP_SWEEP, PRINTED_SETS
from .figures import STYLES, _defaults, _plant_parameters
from ..registry import FigureData, FigureParameter, FigureSpec, Series, register
from ..._validate import shown
from ...units import DEG


# --- thesis Figs. 15–18: the gain sweeps, literally in SI and under a unit hypothesis -------

def compute_sweep(inertia, field, moment, initial_angle, duration, hypothesis_scale, sweep):
    """Closed-loop runs for one gain sweep: in SI (saturated at the coils' maximum) and with
    every gain and the limit multiplied by ``hypothesis_scale`` (a unit reading)."""
    if not 1.0 <= duration <= 3600.0:
        raise ValueError(f"duration must lie in [1, 3600] s, got {shown(duration)}")
    if not hypothesis_scale > 0:
        raise ValueError(f"hypothesis_scale must be > 0, got {shown(hypothesis_scale)}")
    series = []
    for tag, scale in (("SI", 1.0), ("hypothesis", hypothesis_scale)):
        for kp, ki, kd in sweep:
            loop = sim.PidLoop(inertia, field, scale * kp, scale * ki, scale * kd,
                                   moment_limit=scale * moment)
            # The large-gain readings are stiff (a real pole far beyond the oscillation).
            run = sim.simulate_pid(loop, initial_angle, 0.0, duration, output_interval=0.25,
                                       method="RK45" if scale < 100 else "LSODA")
            poles = control.closed_loop_poles(inertia, field, scale * kp, scale * ki, scale * kd)
            series.append(Series(f"{tag}: Kp = {kp:g}, Ki = {ki:g}, Kd = {kd:g}", {
                "t": ("s", run.time), "psi": ("rad", run.psi), "omega": ("rad/s", run.rate),
                "command_fraction": ("1", run.command / loop.moment_limit),
                "max_real_pole": ("1/s", [poles[0].real])}))
    return FigureData("", "", "", {}, series, extra={"scale": hypothesis_scale})


def _plot_sweep(data, key, ylabel, title):
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(1, 2, figsize=(7.0, 4.4), layout="constrained")
    half = len(data.series) // 2
    for ax, group, head in ((axes[0], data.series[:half], "literally in SI, |m| ≤ 0.4 A·m²\n(unstable)"),
                            (axes[1], data.series[half:], f"gains × {format_number(data.extra['scale'], 3)}\n(unit hypothesis)")):
        for s, style in zip(group, STYLES):
            gains = s.label.split(": ", 1)[1].replace("Kp", "$K_p$").replace("Ki", "$K_i$").replace("Kd", "$K_d$")
            lab = gains + f"\nmax Re $\\lambda$ = {s.columns['max_real_pole'][1][0]:+.3g} 1/s"
            ax.plot(s.columns["t"][1], s.columns[key][1], style, label=lab, linewidth=1.1)
        ax.set_title(head, fontsize=8)
        ax.set_xlabel("t [s]", fontsize=8)
        ax.tick_params(labelsize=7)
        ax.axhline(0, color="0.8", linewidth=0.6)
        # Below the axes: inside, the legend covered the oscillations it describes.
        ax.legend(fontsize=7, loc="upper center", bbox_to_anchor=(0.5, -0.18), frameon=False)
    axes[0].set_ylabel(ylabel, fontsize=8)
    fig.suptitle(title.replace("Kp", "$K_p$").replace("Ki", "$K_i$").replace("Kd", "$K_d$"), fontsize=8.5)
    return fig


def compute_fig15(inertia, field, moment, initial_angle, duration, hypothesis_scale):
    """The K_p sweep of thesis Figs. 15–16."""
    return compute_sweep(inertia, field, moment, initial_angle, duration, hypothesis_scale, KP_SWEEP)


def compute_fig17(inertia, field, moment, initial_angle, duration, hypothesis_scale):
    """The K_d sweep of thesis Figs. 17–18."""
    return compute_sweep(inertia, field, moment, initial_angle, duration, hypothesis_scale, KD_SWEEP)


def plot_fig15(data):
    """ω(t), K_d = K_i = 0.5, K_p = 0.1/0.2/0.3 (thesis Fig. 15)."""
    return _plot_sweep(data, "omega", "ω [rad/s]", "Angular velocity, Kd = Ki = 0.5 (thesis Fig. 15)")


def plot_fig16(data):
    """ψ(t), same gains (thesis Fig. 16)."""
    return _plot_sweep(data, "psi", "ψ [rad]", "Rotation angle, Kd = Ki = 0.5 (thesis Fig. 16)")


def plot_fig17(data):
    """ω(t), K_p = 0.1, K_i = 0.5, K_d = 1/2/3 (thesis Fig. 17)."""
    return _plot_sweep(data, "omega", "ω [rad/s]", "Angular velocity, Kp = 0.1, Ki = 0.5 (thesis Fig. 17)")


def plot_fig18(data):
    """ψ(t), same gains (thesis Fig. 18)."""
    return _plot_sweep(data, "psi", "ψ [rad]", "Rotation angle, Kp = 0.1, Ki = 0.5 (thesis Fig. 18)")


def _sweep_parameters():
    p = _defaults()
    params = _plant_parameters()
    params.update({
        "initial_angle": FigureParameter(p["mockup_initial_angle"], "rad", "ψ0 (Figs. 12–13's value; not stated for 15–18)"),
        "duration": FigureParameter(300.0, "s", "time span (not stated)", high=1e4),
        "hypothesis_scale": FigureParameter(1.0 / MU_0, "1", "factor on the printed gains (default: B0 entered as H in A/m)"),
    })
    return params


# --- linear analysis: root locus, margins, linear against nonlinear -----------------------

def _design_gains(inertia, field, bandwidth):
    return tuple(float(k) for k in control.pid_gains_for_triple_pole(inertia, field, bandwidth))


def compute_root_locus(inertia, field, bandwidth):
    """Root locus of our SI design over a common loop gain k, with the printed sets' poles."""
    import control as ct

    kp, ki, kd = _design_gains(inertia, field, bandwidth)
    loop = ct.tf(*control.open_loop_transfer(inertia, field, kp, ki, kd))
    gains = np.concatenate([np.logspace(-3, 3, 600), [1.0 / 9.0]])
    gains.sort()
    rl = ct.root_locus_map(loop, gains)
    loci = rl.loci
    series = [Series(f"branch {k + 1}", {"gain": ("1", gains), "re": ("1/s", loci[:, k].real),
                                         "im": ("1/s", loci[:, k].imag)}) for k in range(loci.shape[1])]
    printed = np.array([control.closed_loop_poles(inertia, field, *g) for g in PRINTED_SETS]).ravel()
    series.append(Series("printed gain sets, SI", {"re": ("1/s", printed.real), "im": ("1/s", printed.imag)}))
    design = control.closed_loop_poles(inertia, field, kp, ki, kd)
    series.append(Series("design k = 1", {"re": ("1/s", design.real), "im": ("1/s", design.imag)}))
    gm, pm, _, wg, wp, _ = ct.stability_margins(loop)
    return FigureData("", "", "", {}, series, extra={"gm": gm, "pm": pm, "wg": wg, "wp": wp,
                                                      "gains": (kp, ki, kd)})


def plot_root_locus(data):
    """Loci of the three closed-loop poles; the printed SI gain sets in the right half-plane.
    Left: everything; right: the design's locus near the origin, enlarged."""
    import matplotlib.pyplot as plt

    fig, (ax, zoom) = plt.subplots(1, 2, figsize=(7.0, 4.4), layout="constrained",
                                   gridspec_kw={"width_ratios": [1.0, 1.0]})
    pr, de = data.series[-2], data.series[-1]
    spread = max(float(np.max(np.abs(de.columns["re"][1]))), 1e-6)
    for a in (ax, zoom):
        for s in data.series[:-2]:
            a.plot(s.columns["re"][1], s.columns["im"][1], color="C0", linewidth=1)
        a.plot(pr.columns["re"][1], pr.columns["im"][1], "x", color="C3", label="printed gain sets, in SI")
        a.plot(de.columns["re"][1], de.columns["im"][1], "o", mfc="none", color="C2",
               label="our design (triple pole)")
        a.axvline(0, color="k", linewidth=0.6)
        a.axhline(0, color="0.7", linewidth=0.6)
        a.set_xlabel("Re $s$ [1/s]")
        a.tick_params(labelsize=8)
    ax.set_xlim(-0.4, 0.2)
    ax.set_ylim(-0.3, 0.3)
    ax.set_ylabel("Im $s$ [1/s]")
    # The design's locus spans about its own pole's distance from the origin.
    zoom.set_xlim(-1.6 * spread, 0.4 * spread)
    zoom.set_ylim(-spread, spread)
    ax.indicate_inset_zoom(zoom, edgecolor="0.4")
    ax.set_title("all poles", fontsize=9)
    zoom.set_title("the design's locus, enlarged", fontsize=9)
    ax.legend(fontsize=8, loc="lower left")
    kp, ki, kd = data.extra["gains"]
    fig.suptitle(rf"Root locus of $k\,C(s)\,B_0/(J s^2)$: $K_p$ = {kp:.3g}, $K_i$ = {ki:.3g}, $K_d$ = {kd:.3g};\n"
                 f"lower gain margin {data.extra['gm']:.3f} (= 1/9), phase margin {data.extra['pm']:.1f}°",
                 fontsize=9)
    return fig


def _root_locus_parameters():
    p = _defaults()
    pp = _plant_parameters()
    return {"inertia": pp["inertia"], "field": pp["field"],
            "bandwidth": FigureParameter(p["pid_bandwidth"], "rad/s", "triple-pole magnitude of our SI design")}


def compute_step_response(inertia, field, moment, bandwidth, sample_interval, small_step, large_step, duration):
    """Linear (python-control) against the nonlinear, saturated loop for a small and a large step."""
    import control as ct

    if not 0 < small_step <= np.pi and 0 < large_step <= np.pi:
        raise ValueError(f"steps must lie in (0, π] rad, got {shown(small_step)} and {shown(large_step)}")
    kp, ki, kd = _design_gains(inertia, field, bandwidth)
    closed = ct.tf(*control.closed_loop_transfer(inertia, field, kp, ki, kd))
    series = []
    for name, step in (("small", small_step), ("large", large_step)):
        runs = {
            "linear (python-control)": None,
            "nonlinear, saturated": sim.PidLoop(inertia, field, kp, ki, kd, target=step, moment_limit=moment),
            "sampled, saturated": sim.PidLoop(inertia, field, kp, ki, kd, target=step, moment_limit=moment),
            "small-angle allocation": sim.PidLoop(inertia, field, kp, ki, kd, target=step, moment_limit=moment,
                                                      allocation="small-angle"),
        }
        for label, loop in runs.items():
            if loop is None:
                t = np.linspace(0.0, duration, int(duration / 0.5) + 1)
                psi = ct.forced_response(closed, t, step * np.ones_like(t)).outputs
                u = np.full_like(t, np.nan)
            else:
                r = sim.simulate_pid(loop, 0.0, 0.0, duration, output_interval=0.5,
                                         sample_interval=sample_interval if label.startswith("sampled") else None)
                t, psi, u = r.time, r.psi, r.command
            cols = {"t": ("s", t), "psi": ("rad", psi)}
            if loop is not None:
                cols["command"] = ("A m^2", u)
            series.append(Series(f"{name} step: {label}", cols))
    return FigureData("", "", "", {}, series, extra={"steps": (small_step, large_step), "gains": (kp, ki, kd)})


def plot_step_response(data):
    """ψ/ψ_des for both steps (left, middle) and the commands of the large step (right)."""
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(1, 3, figsize=(7.0, 3.4))
    styles = ("k-", "C0--", "C1:", "C2-.")
    for ax, name, step in zip(axes[:2], ("small", "large"), data.extra["steps"]):
        for s, st in zip([s for s in data.series if s.label.startswith(name)], styles):
            ax.plot(s.columns["t"][1], s.columns["psi"][1] / step, st, label=s.label.split(": ")[1], linewidth=1.1)
        ax.set_title(f"step of {np.degrees(step):.0f}°", fontsize=8.5)
        ax.set_xlabel("t [s]")
        ax.set_ylabel("ψ / ψ_des")
        ax.axhline(1.0, color="0.8", linewidth=0.6)
    axes[0].legend(fontsize=7)
    for s, st in zip([s for s in data.series if s.label.startswith("large") and "command" in s.columns], styles[1:]):
        axes[2].plot(s.columns["t"][1], s.columns["command"][1], st, label=s.label.split(": ")[1], linewidth=1.1)
    axes[2].set_title("PID output u, large step", fontsize=8.5)
    axes[2].set_xlabel("t [s]")
    axes[2].set_ylabel("u [A·m²]")
    axes[2].legend(fontsize=7)
    return fig


def _step_parameters():
    p = _defaults()
    params = _root_locus_parameters()
    params["bandwidth"] = FigureParameter(2 * p["pid_bandwidth"], "rad/s",
                                          "triple-pole magnitude: twice the chapter's design, so that the large step saturates")
    params.update({
        "moment": _plant_parameters()["moment"],
        "sample_interval": FigureParameter(p["pid_sample_interval"], "s", "controller interval of the sampled loop"),
        "small_step": FigureParameter(5 * DEG, "rad", "small target step"),
        "large_step": FigureParameter(2 * np.pi / 3, "rad", "large target step (the bench's 2π/3)"),
        "duration": FigureParameter(300.0, "s", "time span", high=1e4),
    })
    return params


_SWEEP = _sweep_parameters
register(FigureSpec("thesis-fig15", "Angular velocity, Kp sweep (thesis Fig. 15)", "Bui (2016), Fig. 15",
                    compute_fig15, plot_fig15, _SWEEP))
register(FigureSpec("thesis-fig16", "Rotation angle, Kp sweep (thesis Fig. 16)", "Bui (2016), Fig. 16",
                    compute_fig15, plot_fig16, _SWEEP))
register(FigureSpec("thesis-fig17", "Angular velocity, Kd sweep (thesis Fig. 17)", "Bui (2016), Fig. 17",
                    compute_fig17, plot_fig17, _SWEEP))
register(FigureSpec("thesis-fig18", "Rotation angle, Kd sweep (thesis Fig. 18)", "Bui (2016), Fig. 18",
                    compute_fig17, plot_fig18, _SWEEP))
register(FigureSpec("ch04-root-locus", "Root locus and margins of a stable SI design", "Not in the thesis",
                    compute_root_locus, plot_root_locus, _root_locus_parameters))
register(FigureSpec("ch04-step-response", "Linear against nonlinear closed loop", "Not in the thesis",
                    compute_step_response, plot_step_response, _step_parameters, slow=True))
