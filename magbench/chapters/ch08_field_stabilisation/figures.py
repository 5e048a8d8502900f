"""Figures of chapter 8: the magnetopolar orbit's field rotation, Kovalenko's Figs. 6.7 and 6.8
regenerated (estimate beside simulation), the dampers, the gravity-gradient boom with a
magnetic ball damper and the eddy-current shell against TNS-0's Fig. 14.

Kovalenko's plots survive only as captions: every curve here is computed, his printed
numbers are marked where the text gives them.
"""

import numpy as np

from ...io import load_printed
from . import (CHAPTER, DAMPING_FACTORS, E48_FRICTION_FACTORS, E48_STARTS, SETTLED_ANGLE, e47_case, e48_case, eddy_shell_match, error_sweep,
               libration_study, rod_pair_ratios)
from .._base import FigureInputs
from ..registry import FigureData, Series, FigureSpec, register

SOURCE = "Kovalenko (1975)"

#: Each figure's description of the chapter inputs it exposes: (description, bounds).
_INPUTS = {
    "earth_dipole_moment": ("the Earth's dipole (Kovalenko p. 34)", {}),
    "e47_altitude": ("E47: altitude of the magnetopolar orbit (printed ≈ 1000 km)", {}),
    "e47_transverse_inertia": ("E47: J about the transverse axes (printed)", {}),
    "e47_axial_inertia": ("E47: J about the orientation axis (printed)", {}),
    "e47_magnet_moment": ("E47: the magnet L (printed)", {}),
    "e47_damping": ("E47: the viscous damper k_d (printed)", {}),
    "e48_damper_moment": ("E48: the damper's magnet (printed L_y)", {}),
    "e48_friction": ("E48: the damper's dry friction (printed M_T)", {}),
    "e48_stiffness": ("E48: the elastic coupling c (printed)", {}),
    "e48_viscous": ("E48: a small viscous term beside the friction (ours)", {}),
    "sweep_frequency_min": ("lowest ω_c/ω0 of the sweep (ours)", {"low": 0.5}),
    "sweep_frequency_max": ("highest ω_c/ω0 of the sweep (ours)", {"high": 40.0}),
    "sweep_orbits": ("orbits per run of the sweep (ours)", {"low": 3.0, "high": 60.0}),
    "boom_transverse_inertia": ("boom: roll and pitch inertia (ours)", {}),
    "boom_axial_inertia": ("boom: inertia about the boom (ours)", {}),
    "ball_moment": ("the ball's magnet (ours)", {}),
    "ball_inertia": ("the ball's inertia (ours)", {}),
    "ball_damping": ("the ball's viscous coupling (ours)", {}),
    "libration_altitude": ("altitude of the circular orbit (ours)", {}),
    "libration_inclination": ("inclination (ours)", {}),
    "libration_initial_angle": ("initial pitch from the vertical (ours)", {}),
    "libration_orbits": ("length of the runs (ours)", {"low": 2.0, "high": 120.0}),
    "shell_conductivity": ("the shell's conductivity (aluminium, external)", {}),
}


FIGURE_INPUTS = FigureInputs(CHAPTER.key, CHAPTER.source, _INPUTS)
_with = FIGURE_INPUTS.merged


# --- §6.4: the field's rotation on a magnetopolar orbit ------------------------------------

def compute_field_rotation():
    """η − u, −η̈/ω0² and sin 2λ over half an orbit: exact, and Kovalenko's printed series."""
    from ...earth import (polar_field_direction_acceleration, polar_field_direction_angle, polar_gravity_factor)

    printed = load_printed("kovalenko")
    u = np.linspace(0.0, np.pi, 361)
    c = {k: printed[k].value for k in ("kov-polar-eta1", "kov-polar-eta2", "kov-polar-etaddot1", "kov-polar-etaddot2",
                                       "kov-polar-gravity1", "kov-polar-gravity2", "kov-polar-gravity3")}
    exact = {"eta": polar_field_direction_angle(u) - u, "acceleration": -polar_field_direction_acceleration(u),
             "gravity": polar_gravity_factor(u)}
    book = {"eta": c["kov-polar-eta1"] * np.sin(2 * u) + c["kov-polar-eta2"] * np.sin(4 * u),
            "acceleration": c["kov-polar-etaddot1"] * np.sin(2 * u) + c["kov-polar-etaddot2"] * np.sin(4 * u),
            "gravity": sum(c[f"kov-polar-gravity{n}"] * np.sin(2 * n * u) for n in (1, 2, 3))}
    return FigureData("", "", "", {}, [
        Series("exact (6.32)", {"u": ("rad", u), "eta": ("rad", exact["eta"]), "acceleration": ("1", exact["acceleration"]),
                                "gravity": ("1", exact["gravity"])}),
        Series("Kovalenko's printed series (6.33), (6.34), (6.61)",
               {"u": ("rad", u), "eta": ("rad", book["eta"]), "acceleration": ("1", book["acceleration"]),
                "gravity": ("1", book["gravity"])}),
    ])


def plot_field_rotation(data):
    """Three panels over half an orbit: exact (solid) and the book's truncated series (dashed)."""
    import matplotlib.pyplot as plt

    exact, book = data.series
    fig, axes = plt.subplots(1, 3, figsize=(7.0, 2.8))
    titles = {"eta": ("η − u [°]", np.degrees), "acceleration": ("−η̈/ω0² [-]", lambda x: x),
              "gravity": ("sin 2λ [-]", lambda x: x)}
    u = np.degrees(exact.columns["u"][1])
    for ax, (key, (label, scale)) in zip(axes, titles.items()):
        ax.plot(u, scale(exact.columns[key][1]), "C0-", label="exact")
        ax.plot(u, scale(book.columns[key][1]), "C3--", label="book's series")
        ax.set_title(label, fontsize=9)
        ax.set_xlabel("u = ω0t [°]")
        ax.set_xticks([0, 45, 90, 135, 180])
        ax.grid(alpha=0.3)
    axes[0].legend(fontsize=7.5)
    return fig


# --- Fig. 6.7: E47's steady state ---------------------------------------------------------

_E47_NAMES = ("e47_altitude", "e47_transverse_inertia", "e47_axial_inertia", "e47_magnet_moment", "e47_damping")


def compute_fig6_7(**params):
    """E47: γ over ten orbits, its last two against u, the (6.75) bound and the linear solution."""
    case = e47_case(_with(params))
    run, n = case["run"], case["mean_motion"]
    u = n * run.time
    last = run.time > run.time[-1] - 2 * case["period"]
    k = np.arange(1, case["harmonic_amplitude"].shape[0] + 1)[:, None]
    ul = u[last]
    linear = np.sum(case["harmonic_amplitude"][:, None] * np.sin(2 * k * ul - case["harmonic_phase"][:, None]), axis=0)
    return FigureData("", "", "", {}, [
        Series("simulation, ten orbits", {"orbits": ("1", u / (2 * np.pi)), "gamma": ("deg", np.degrees(run.gamma[:, 0]))}),
        Series("simulation, last two orbits", {"u": ("deg", np.degrees(ul % (2 * np.pi))),
                                                "gamma": ("deg", np.degrees(run.gamma[last, 0]))}),
        Series("linearised steady solution (6.62)-(6.64)", {"u": ("deg", np.degrees(ul % (2 * np.pi))),
                                                             "gamma": ("deg", np.degrees(linear))}),
        Series("estimate (6.75)", {"gamma_max": ("deg", [np.degrees(case["estimate"])])}),
    ], extra={"simulated": case["simulated"], "simulated_u": case["simulated_u"], "estimate": case["estimate"]})


def plot_fig6_7(data):
    """Left: the transient over ten orbits. Right: the last two orbits against u with the estimate."""
    import matplotlib.pyplot as plt

    whole, last, linear, estimate = data.series
    printed = load_printed("kovalenko")
    fig, axes = plt.subplots(1, 2, figsize=(7.0, 3.0), gridspec_kw={"width_ratios": [1.0, 1.3]})
    axes[0].plot(whole.columns["orbits"][1], whole.columns["gamma"][1], "C0-", linewidth=0.8)
    axes[0].set_xlabel("orbits")
    axes[0].set_ylabel("ϑ, angle from B [°]")
    axes[0].set_title("From ϑ = 0 at the node", fontsize=9)
    order = np.argsort(last.columns["u"][1], kind="stable")
    u = last.columns["u"][1]
    axes[1].plot(u, last.columns["gamma"][1], "C0.", markersize=1.5, label="simulation (planar (6.39))")
    axes[1].plot(u[order], linear.columns["gamma"][1][order], "C2-", linewidth=0.9, label="linear solution (6.62)–(6.64), off scale")
    g = estimate.columns["gamma_max"][1][0]
    axes[1].axhspan(-g, g, color="C1", alpha=0.15, label=f"±ϑ_max by (6.75): {g:.1f}°")
    axes[1].plot([printed["kov-e47-simulated-angle"].value_as_printed], [printed["kov-e47-simulated-error"].value_as_printed],
                 "kx", markersize=7, label="Kovalenko's 'about 17° at ω0t ≈ 40°'")
    axes[1].set_xlabel("u = ω0t [°]")
    axes[1].set_xticks([0, 90, 180, 270, 360])
    axes[1].set_ylim(-30, 30)       # the linear solution runs off the scale: ω_c is near 4ω0, its second resonance
    axes[1].set_title("Steady state, last two orbits", fontsize=9)
    axes[1].legend(fontsize=7, loc="lower right")
    for ax in axes:
        ax.grid(alpha=0.3)
    return fig


def _e47_parameters():
    return FIGURE_INPUTS.table(_E47_NAMES)()


# --- Fig. 6.8: γ_max against ω_c/ω0 --------------------------------------------------------

_SWEEP_NAMES = ("e47_damping", "sweep_frequency_min", "sweep_frequency_max", "sweep_orbits")


def compute_fig6_8(**params):
    """γ_max against ω_c/ω0: the simulated (one curve per k_д), (6.75), and the linear solution's."""
    s = error_sweep(_with(params))
    series = [Series(f"simulated, k_d = {k:g} N·m·s", {"frequency": ("1", s["frequency"]),
                                                       "gamma_max": ("deg", np.degrees(row)),
                                                       "linear": ("deg", np.degrees(lin))})
              for k, row, lin in zip(s["damping"], s["simulated"], s["linear"])]
    series.append(Series("estimate (6.75)", {"frequency": ("1", s["frequency"]),
                                              "gamma_max": ("deg", np.degrees(s["estimate"]))}))
    case = e47_case(_with(params))
    return FigureData("", "", "", {}, series, extra={"e47_damping": float(s["damping"][DAMPING_FACTORS.index(1.0)]),
                                                     "e47_frequency": case["natural_frequency"]})


def plot_fig6_8(data):
    """Left: γ_max against ω_c/ω0. Right: the simulated over the estimate."""
    import matplotlib.pyplot as plt

    sims, est = data.series[:-1], data.series[-1]
    printed = load_printed("kovalenko")
    fig, axes = plt.subplots(1, 2, figsize=(7.0, 3.1))
    f = est.columns["frequency"][1]
    for i, s in enumerate(sims):
        axes[0].plot(f, s.columns["gamma_max"][1], "o-", color=f"C{i}", markersize=2.5, linewidth=0.8, label=s.label)
        axes[1].plot(f, s.columns["gamma_max"][1] / est.columns["gamma_max"][1], "o-", color=f"C{i}", markersize=2.5,
                     linewidth=0.8)
    axes[0].plot(f, est.columns["gamma_max"][1], "k--", label="estimate (6.75)")
    axes[0].plot([data.extra["e47_frequency"]], [printed["kov-e47-simulated-error"].value_as_printed], "kx", markersize=7,
                 label="Kovalenko's E47 (Fig. 6.7)")
    axes[0].set_yscale("log")
    axes[0].set_ylabel("ϑ_max [°]")
    axes[0].legend(fontsize=7)
    axes[1].axhline(1.0, color="k", linewidth=0.8)
    axes[1].axvline(4.0, color="0.5", linestyle=":", linewidth=1.0)
    axes[1].text(4.1, 0.55, "book: good\nabove 4ω0", fontsize=7, color="0.3")
    axes[1].set_yscale("log")
    axes[1].set_yticks([0.5, 1, 2, 3, 5, 8], ["0.5", "1", "2", "3", "5", "8"])
    axes[1].minorticks_off()
    axes[1].set_ylabel("simulated / (6.75)")
    for ax in axes:
        ax.set_xlabel("ω_c/ω0 = √(mB0/J)/ω0")
        ax.grid(alpha=0.3, which="both")
    return fig


def _sweep_parameters():
    return FIGURE_INPUTS.table(_SWEEP_NAMES)()


# --- Fig. 6.10: E48 ---------------------------------------------------------------------------

_E48_NAMES = ("e48_damper_moment", "e48_friction", "e48_stiffness", "e48_viscous")


def compute_fig6_10(**params):
    """E48: ϑ over three orbits from six starts, the friction sweep, the two estimates."""
    case = e48_case(_with(params))
    orbits = case["time"] / case["period"]
    series = [Series(f"start {np.degrees(a):g}°, {r:+g} ω0", {"orbits": ("1", orbits),
                                                             "gamma": ("deg", np.degrees(case["gamma"][:, k]))})
              for k, (a, r) in enumerate(E48_STARTS)]
    series.append(Series("largest |ϑ| per orbit", {"orbit": ("1", np.arange(1.0, case["orbit_maxima"].shape[0] + 1)),
                                                   "mean": ("deg", np.degrees(case["orbit_maxima"].mean(axis=1))),
                                                   "locked": ("deg", np.degrees(case["locked_maxima"]))}))
    series.append(Series("friction sweep", {"friction": ("N m", case["friction"]),
                                            "simulated": ("deg", np.degrees(case["friction_maxima"][1:].max(axis=0))),
                                            "estimate_678": ("deg", np.degrees(case["friction_estimate"]))}))
    series.append(Series("estimates", {"674": ("deg", [np.degrees(case["estimate_674"])]),
                                       "678": ("deg", [np.degrees(case["estimate_678"])]),
                                       "locked": ("deg", [np.degrees(case["locked_maxima"][1:].max())]),
                                       "friction": ("N m", [case["friction"][E48_FRICTION_FACTORS.index(1.0)]])}))
    return FigureData("", "", "", {}, series)


def plot_fig6_10(data):
    """γ over three orbits; the estimates and Kovalenko's range as bands."""
    import matplotlib.pyplot as plt

    printed = load_printed("kovalenko")["kov-e48-simulated-error"]
    runs, sweep, est = data.series[:-3], data.series[-2], data.series[-1]
    fig, (ax, right) = plt.subplots(1, 2, figsize=(7.0, 3.3), gridspec_kw={"width_ratios": [1.5, 1.0]})
    for k, s in enumerate(runs):
        ax.plot(s.columns["orbits"][1], s.columns["gamma"][1], color=f"C{k}", linewidth=0.7,
                label=f"{len(runs)} starts (ours)" if k == 0 else None)
    lo, hi = printed.value_low, printed.value_high
    for sign in (1, -1):
        ax.axhspan(sign * lo, sign * hi, color="k", alpha=0.15, label="Kovalenko's run: 5.5–7.5°" if sign > 0 else None)
        ax.axhline(sign * est.columns["674"][1][0], color="C3", linestyle="--", linewidth=0.9,
                   label="estimate (6.74)" if sign > 0 else None)
        ax.axhline(sign * est.columns["678"][1][0], color="C4", linestyle=":", linewidth=0.9,
                   label="estimate (6.78)" if sign > 0 else None)
    ax.set_xlabel("orbits")
    ax.set_ylabel("ϑ, angle from B [°]")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7, loc="upper right")
    ax.set_ylim(None, 1.45 * ax.get_ylim()[1])
    friction = sweep.columns["friction"][1] * 1e4
    right.plot(friction, sweep.columns["simulated"][1], "ko-", markersize=3, label="simulated, orbits 2–3")
    right.plot(friction, sweep.columns["estimate_678"][1], "C4s:", markersize=3, label="estimate (6.78)")
    right.axhline(est.columns["674"][1][0], color="C3", linestyle="--", linewidth=0.9, label="estimate (6.74)")
    right.axhline(est.columns["locked"][1][0], color="0.5", linewidth=0.9, label="magnet locked to the body")
    m = est.columns["friction"][1][0] * 1e4
    right.plot([m, m], [lo, hi], color="k", linewidth=4, alpha=0.3, label="Kovalenko's run")
    right.set_xscale("log")
    right.set_xticks(friction, [f"{v:g}" for v in friction])
    right.minorticks_off()
    right.set_xlabel("dry friction L_f [10⁻⁴ N·m]")
    right.set_ylabel("ϑ_max [°]")
    right.grid(alpha=0.3, which="both")
    right.legend(fontsize=7, loc="center right")
    return fig


def _e48_parameters():
    return FIGURE_INPUTS.table(_E48_NAMES)()


# --- §6.5: dry against viscous damping ----------------------------------------------------

def compute_damper_decay():
    """The relative rate under a viscous and a dry-friction damper with equal initial torques."""
    t = np.linspace(0.0, 8.0, 401)           # in units of J/(k_д) = J ω_н/M_T
    viscous = np.exp(-t)
    dry = np.clip(1.0 - t, 0.0, None)
    return FigureData("", "", "", {}, [
        Series("viscous (6.45)", {"time": ("1", t), "rate": ("1", viscous)}),
        Series("dry friction (6.50)", {"time": ("1", t), "rate": ("1", dry)}),
    ])


def plot_damper_decay(data):
    """Rate over initial rate against time in J/k_д, log scale."""
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(5.0, 2.8))
    for s, style in zip(data.series, ("C0-", "C3-")):
        rate = s.columns["rate"][1]
        keep = rate > 0
        ax.plot(s.columns["time"][1][keep], rate[keep], style, label=s.label)
    ax.axhline(1e-3, color="0.5", linestyle=":")
    ax.text(0.1, 1.3e-3, "0.001 ω_i (the book's case)", fontsize=7)
    ax.set_yscale("log")
    ax.set_ylim(5e-4, 1.5)
    ax.set_xlabel("t k_d/J (= t L_f/(J ω_i))")
    ax.set_ylabel("ω/ω_i")
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=7.5)
    return fig


# --- the gravity-gradient boom with a magnetic ball damper ----------------------------------

_LIBRATION_NAMES = ("ball_moment", "ball_damping", "libration_initial_angle", "libration_orbits")


def compute_libration(**params):
    """The largest libration over each orbit: undamped, and with the ball at the default coupling."""
    s = libration_study(_with(params))
    from . import LIBRATION_DAMPING_FACTORS

    base = 1 + LIBRATION_DAMPING_FACTORS.index(1.0)
    orbits = np.arange(1, s["envelope"].shape[0] + 1, dtype=float)
    series = [Series(f"{label}, phase {k + 1}", {"orbit": ("1", orbits),
                                                 "envelope": ("deg", np.degrees(s["envelope"][:, d, k]))})
              for d, label in ((0, "undamped"), (base, "ball damper")) for k in range(s["envelope"].shape[2])]
    t = s["time"] / s["period"]
    series.append(Series("pitch, ball damper, phase 1", {"orbit": ("1", t),
                                                         "pitch": ("deg", np.degrees(s["pitch"][:, base, 0]))}))
    return FigureData("", "", "", {}, series)


def plot_libration(data):
    """Left: pitch over the run. Right: the per-orbit envelope, undamped and damped."""
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(1, 2, figsize=(7.0, 3.0))
    pitch = data.series[-1]
    axes[0].plot(pitch.columns["orbit"][1], pitch.columns["pitch"][1], "C0-", linewidth=0.6)
    axes[0].set_ylabel("pitch from the local vertical [°]")
    axes[0].set_title("With the ball damper (one phase)", fontsize=9)
    for s in data.series[:-1]:
        color = "C3" if s.label.startswith("undamped") else "C0"
        axes[1].plot(s.columns["orbit"][1], s.columns["envelope"][1], "o-", color=color, markersize=2,
                     linewidth=0.7, label=s.label.split(",")[0])
    handles, labels = axes[1].get_legend_handles_labels()
    unique = dict(zip(labels, handles))
    axes[1].legend(unique.values(), unique.keys(), fontsize=7)
    axes[1].set_ylabel("largest libration per orbit [°]")
    axes[1].set_ylim(0, None)
    for ax in axes:
        ax.set_xlabel("orbits")
        ax.grid(alpha=0.3)
    return fig


def _libration_parameters():
    return FIGURE_INPUTS.table(_LIBRATION_NAMES)()


def compute_libration_trade():
    """Settling time and residual libration against the ball's coupling (three phases each)."""
    s = libration_study(FIGURE_INPUTS.defaults())
    k = s["damping"][1:]
    series = []
    for j in range(s["residual"].shape[1]):
        settled = np.isfinite(s["settling_orbits"][1:, j])       # the couplings that settled within the run
        series.append(Series(f"phase {j + 1}", {"damping": ("N m s/rad", k),
                                                "residual": ("deg", np.degrees(s["residual"][1:, j]))}))
        series.append(Series(f"phase {j + 1}, settled", {"damping": ("N m s/rad", k[settled]),
                                                         "settling": ("1", s["settling_orbits"][1:, j][settled])}))
    return FigureData("", "", "", {}, series, extra={"threshold": float(np.degrees(SETTLED_ANGLE)),
                                                     "orbits": s["envelope"].shape[0]})


def plot_libration_trade(data):
    """Orbits to settle below the threshold (left) and the last orbit's libration (right)."""
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(1, 2, figsize=(7.0, 2.9))
    for j, (whole, settled) in enumerate(zip(data.series[::2], data.series[1::2])):
        axes[0].plot(settled.columns["damping"][1] * 1e4, settled.columns["settling"][1], "o-", color=f"C{j}",
                     markersize=3, label=whole.label)
        axes[1].plot(whole.columns["damping"][1] * 1e4, whole.columns["residual"][1], "o-", color=f"C{j}",
                     markersize=3, label=whole.label)
    axes[0].set_ylabel(f"orbits to stay below {data.extra['threshold']:g}°")
    axes[0].set_title(f"missing: not settled in {data.extra['orbits']} orbits", fontsize=8)
    axes[1].set_ylabel("largest libration, last orbit [°]")
    k = data.series[0].columns["damping"][1] * 1e4
    for ax in axes:
        ax.set_xscale("log")
        ax.set_xticks(k, [f"{v:g}" for v in k])
        ax.minorticks_off()
        ax.set_xlabel("ball coupling k [10⁻⁴ N·m·s]")
        ax.grid(alpha=0.3)
    axes[1].legend(fontsize=7)
    return fig


# --- eddy currents against TNS-0's Fig. 14 ---------------------------------------------------

def compute_eddy_shell(shell_conductivity):
    """The spin-decay time constant of TNS-0 in an aluminium shell against the wall thickness."""
    m = eddy_shell_match({"shell_conductivity": shell_conductivity})
    wall = np.geomspace(1e-4, 0.1, 61)
    return FigureData("", "", "", {}, [
        Series("open cylinder 0.3 m × 0.1 m", {"thickness": ("m", wall), "tau": ("h", m["cylinder_tau_1mm"] * 1e-3 / wall / 3600)}),
        Series("sphere of the same radius", {"thickness": ("m", wall), "tau": ("h", m["sphere_tau_1mm"] * 1e-3 / wall / 3600)}),
        Series("Fig. 14", {"tau_fit": ("h", [m["time_constant_fit"] / 3600]),
                           "tau_slope": ("h", [m["time_constant_slope"] / 3600])}),
    ], extra=m)


def plot_eddy_shell(data):
    """τ against the wall thickness, log-log, with the two Fig. 14 time constants."""
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(5.6, 3.2))
    for s, style in zip(data.series[:2], ("C0-", "C2--")):
        ax.plot(s.columns["thickness"][1] * 1e3, s.columns["tau"][1], style, label=s.label)
    fig14 = data.series[2].columns
    ax.axhline(fig14["tau_fit"][1][0], color="C3", linewidth=1.0, label="Fig. 14: exponential fit's τ")
    ax.axhline(fig14["tau_slope"][1][0], color="C3", linestyle=":", linewidth=1.0, label="Fig. 14: L₁/|slope|")
    m = data.extra
    ax.plot([m["cylinder_thickness_fit"] * 1e3], [fig14["tau_fit"][1][0]], "ko", markersize=4)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("wall thickness [mm]")
    ax.set_ylabel("spin-decay time constant τ [h]")
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=7)
    return fig


def _eddy_parameters():
    return FIGURE_INPUTS.table(("shell_conductivity",))()


# --- §12.2: two parallel rods -----------------------------------------------------------------

def compute_rod_interaction():
    """N_c∞/N_c0 of two parallel rods against their distance: measured (E47b) and reconstructed."""
    r = rod_pair_ratios()
    a = 2.0 * r["curve_gap"] / r["length"]
    return FigureData("", "", "", {}, [
        Series("measured (Kovalenko p. 239)", {"a": ("1", 2.0 * r["gap"] / r["length"]), "ratio": ("1", r["measured"])}),
        Series("reconstruction, the measured rods", {"a": ("1", a), "ratio": ("1", r["curve"])}),
        Series("reconstruction, the book's spheroids (p = 300)", {"a": ("1", a), "ratio": ("1", r["curve_book"])}),
        Series("coincident rods", {"text": ("1", [r["text_estimate"]]), "merged": ("1", [r["merged"]])}),
    ])


def plot_rod_interaction(data):
    """Ratio against a = 2Δ/l, log abscissa."""
    import matplotlib.pyplot as plt

    measured, ours, book, coincident = data.series
    fig, ax = plt.subplots(figsize=(5.6, 3.2))
    ax.plot(ours.columns["a"][1], ours.columns["ratio"][1], "C0-", label=ours.label)
    ax.plot(book.columns["a"][1], book.columns["ratio"][1], "C2--", label=book.label)
    ax.plot(measured.columns["a"][1], measured.columns["ratio"][1], "ko", label=measured.label)
    ax.axhline(coincident.columns["text"][1][0], color="C3", linestyle=":", label="the text's (√2)^1.7 for coincident rods")
    ax.set_xscale("log")
    ax.set_xlabel("a = 2Δ/l")
    ax.set_ylabel("N_c∞ / N_c0")
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=7)
    return fig


register(FigureSpec("kov-field-rotation", "The field's rotation on a circular magnetopolar orbit: exact against "
                    "the printed series", f"{SOURCE} §6.4, eqs. (6.32)–(6.34); §6.5, eq. (6.61)",
                    compute_field_rotation, plot_field_rotation, {}))
register(FigureSpec("kov-fig6-7", "E47: the steady state of a magnet with a viscous damper (Kovalenko Fig. 6.7, "
                    "regenerated)", f"{SOURCE} §6.5, p. 147, Fig. 6.7 (caption only)", compute_fig6_7, plot_fig6_7,
                    _e47_parameters))
register(FigureSpec("kov-fig6-8", "Largest steady-state error against the natural frequency: simulation and "
                    "estimate (Kovalenko Fig. 6.8, regenerated)", f"{SOURCE} §6.5, eq. (6.75), Fig. 6.8 (caption only)",
                    compute_fig6_8, plot_fig6_8, _sweep_parameters))
register(FigureSpec("kov-fig6-10", "E48: a dry-friction damper whose magnet is coupled elastically to the body "
                    "(Kovalenko Fig. 6.10, regenerated)", f"{SOURCE} §6.5, p. 150, Fig. 6.10 (caption only)",
                    compute_fig6_10, plot_fig6_10, _e48_parameters))
register(FigureSpec("kov-damper-decay", "Detumbling with a viscous and a dry-friction damper", f"{SOURCE} §6.5, "
                    "eqs. (6.45), (6.50)", compute_damper_decay, plot_damper_decay, {}))
register(FigureSpec("kov-libration", "A gravity-gradient boom with a magnetic ball damper: libration decay",
                    f"{SOURCE} §4.2 eq. (4.18), §5.4 eqs. (5.19)–(5.22) (the satellite ours)", compute_libration,
                    plot_libration, _libration_parameters))
register(FigureSpec("kov-libration-trade", "The ball damper's coupling against settling time and residual "
                    "libration", f"{SOURCE} §5.4 (the satellite ours)", compute_libration_trade, plot_libration_trade,
                    {}))
register(FigureSpec("kov-eddy-shell", "Eddy-current spin decay of TNS-0 in a conducting shell, against Fig. 14",
                    f"{SOURCE} §4.2, eqs. (4.23)–(4.26); TNS-0 preprint Table 1, Fig. 14", compute_eddy_shell,
                    plot_eddy_shell, _eddy_parameters))
register(FigureSpec("kov-rod-interaction", "Two parallel hysteresis rods: the mean demagnetising factor against "
                    "their distance (Kovalenko Fig. 12.9, regenerated)", f"{SOURCE} §12.2, p. 239, Fig. 12.9 (caption only)",
                    compute_rod_interaction, plot_rod_interaction, {}))
