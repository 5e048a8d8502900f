"""Figures of chapter 7: TNS-0's field cone, Fig. 14, the rods and the capture into rotation about B.

TNS-0 preprint (Ilyin et al. 2006) Figs. 3 and 14 regenerated, plus the analysis figures of
the chapter: the cone's deviation from the exact field, the Flatley–Henretty rod loops, the
decay fits, a session model (model only) and the capture Monte Carlo.
"""

import numpy as np

from ...constants import MU_0
from . import CHAPTER, SENSOR_NORMALS, capture_run, decay_balance, decay_fits, full_run, tns0_orbit, session_fits
from .._base import chapter_parameters
from ..registry import FigureData, FigureParameter, FigureSpec, Series, register
from ..._validate import shown
from ...units import DEG

SOURCE = "TNS-0 preprint (Ilyin et al. 2006)"


def _defaults():
    return chapter_parameters(CHAPTER.key, overrides="")


# --- TNS-0 Fig. 3: the field cone -------------------------------------------------------

def compute_fig03(inclination):
    """Exact direct-dipole field directions over half an orbit, the averaged cone and its axis."""
    from ...earth import cone_field_direction, field_cone_axis, field_cone_half_angle, orbit_field_direction

    u = np.linspace(0.0, np.pi, 181)
    exact = orbit_field_direction(inclination, u)
    model = cone_field_direction(inclination, u)
    axis = field_cone_axis(inclination)
    delta = float(field_cone_half_angle(inclination))

    def series(label, b):
        return Series(label, {"u": ("rad", u), "bx": ("1", b[:, 0]), "by": ("1", b[:, 1]), "bz": ("1", b[:, 2])})

    return FigureData("", "", "", {}, [
        series("exact direct dipole", exact), series("averaged cone model", model),
        Series("cone", {"half_angle": ("deg", [np.degrees(delta)]), "axis_x": ("1", [axis[0]]),
                        "axis_y": ("1", [axis[1]]), "axis_z": ("1", [axis[2]])})],
        extra={"delta": delta, "axis": axis, "inclination": inclination})


def plot_fig03(data):
    """The cone in 3D: the Earth's axis Z, the node X, the exact path and the model's circle."""
    import matplotlib.pyplot as plt

    exact, model = (np.stack([s.columns[k][1] for k in ("bx", "by", "bz")], -1) for s in data.series[:2])
    axis, delta = data.extra["axis"], data.extra["delta"]
    fig = plt.figure(figsize=(6.0, 5.0))
    ax = fig.add_subplot(projection="3d")
    # Generators of the cone, every 30° of azimuth.
    side = np.cross(axis, [1.0, 0.0, 0.0])
    side /= np.linalg.norm(side)
    for a in np.radians(np.arange(0, 360, 30)):
        g = np.cos(delta) * axis + np.sin(delta) * (np.cos(a) * side + np.sin(a) * np.array([1.0, 0.0, 0.0]))
        ax.plot(*np.stack([np.zeros(3), g]).T, color="0.8", linewidth=0.7)
    ax.plot(*model.T, "C1--", label="averaged model (uniform rate 2u)")
    ax.plot(*exact.T, "C0-", label="exact dipole field, u = 0 … π")
    ax.plot(*np.stack([np.zeros(3), axis]).T, "C3-", linewidth=1.5, label="cone axis")
    ax.plot([0, 0], [0, 0], [0, 1.1], "k-", linewidth=1.0)
    ax.text(0, 0, 1.15, "Z (Earth's axis)", fontsize=8)
    ax.plot([0, 0.8], [0, 0], [0, 0], "k-", linewidth=1.0)
    ax.text(0.85, 0, 0, "X (node)", fontsize=8)
    for k in (0, 45, 90, 135):
        ax.scatter(*exact[k], color="C0", s=12)
        ax.text(*(1.05 * exact[k]), f"u = {k}°", fontsize=7, color="C0")
    ax.set_xlabel("X")
    ax.set_ylabel("Y")
    ax.set_zlabel("Z")
    ax.set_box_aspect((1, 1, 1))
    ax.legend(loc="upper left", fontsize=7.5)
    ax.set_title(f"Field cone at i = {np.degrees(data.extra['inclination']):.1f}° (TNS-0 Fig. 3): "
                 f"Δ = {np.degrees(delta):.2f}°", fontsize=8.5)
    return fig


def _fig03_parameters():
    p = _defaults()
    return {"inclination": FigureParameter(p["orbit_inclination"], "rad", "orbit inclination i (the ISS orbit)")}


# --- the cone's deviation from the exact field --------------------------------------------

INCLINATIONS = (30.0, 51.6, 65.0, 80.0)


def compute_cone_deviation():
    """Off-cone angle and azimuth error of the exact field against the averaged model, for several i."""
    from ...earth import field_cone_deviation

    u = np.linspace(0.0, np.pi, 721)
    series = []
    for inc in INCLINATIONS:
        off, direction, phase = field_cone_deviation(np.radians(inc), u)
        series.append(Series(f"i = {inc:g}°", {"u": ("rad", u), "off_cone": ("deg", np.degrees(off)),
                                                "phase_error": ("deg", np.degrees(phase)),
                                                "direction_error": ("deg", np.degrees(direction))}))
    return FigureData("", "", "", {}, series)


def plot_cone_deviation(data):
    """Two panels over half an orbit: off-cone angle, and the model's direction error."""
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(1, 2, figsize=(6.8, 2.9))
    for s in data.series:
        u = np.degrees(s.columns["u"][1])
        axes[0].plot(u, s.columns["off_cone"][1], label=s.label)
        axes[1].plot(u, s.columns["direction_error"][1], label=s.label)
    axes[0].set_title("Exact direction outside the cone")
    axes[0].set_ylabel("angle from the cone [°]")
    axes[1].set_title("Exact direction vs uniform-rate model")
    axes[1].set_ylabel("angle between them [°]")
    for ax in axes:
        ax.set_xlabel("argument of latitude u [°]")
        ax.set_xticks([0, 45, 90, 135, 180])
        ax.grid(alpha=0.3)
    axes[1].legend(fontsize=7.5)
    return fig


# --- TNS-0 Fig. 14: Table 1's L against the hours since session 1 -------------------------

def compute_fig14():
    """Table 1's L at the hours since session 1 (exactly), with the linear and exponential fits."""
    hours, momentum, linear, exponential = decay_fits()
    t = np.linspace(0.0, 700.0, 141)
    return FigureData("", "", "", {}, [
        Series("Table 1", {"t": ("h", hours), "L": ("kg m^2/s", momentum)}),
        Series("linear fit", {"t": ("h", t), "L": ("kg m^2/s", linear.predict(t))}),
        Series("exponential fit", {"t": ("h", t), "L": ("kg m^2/s", exponential.predict(t))}),
    ], extra={"linear": linear, "exponential": exponential})


def plot_fig14(data):
    """Points of Table 1, the linear fit (line) and the exponential fit (dashed)."""
    import matplotlib.pyplot as plt

    lin, exp_ = data.extra["linear"], data.extra["exponential"]
    fig, ax = plt.subplots(figsize=(6.0, 3.4))
    pts, line, dashed = data.series
    ax.plot(line.columns["t"][1], line.columns["L"][1], "C0-",
            label=f"linear: $dK/dt$ = {lin.parameters['slope'] * 1e4:.3f}·10⁻⁴ kg·m²/s per h, AICc {lin.aicc:.1f}"
                  .replace("-", "−"))
    ax.plot(dashed.columns["t"][1], dashed.columns["L"][1], "C1--",
            label=f"exponential: τ = {exp_.parameters['time_constant']:.0f} h, AICc {exp_.aicc:.1f}")
    ax.plot(pts.columns["t"][1], pts.columns["L"][1], "ko", label="Table 1 (sessions 1–7)")
    ax.set_xlabel("hours since session 1 [h]")
    ax.set_ylabel("$K$ [kg·m²/s]")
    ax.set_ylim(0, None)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7.5)
    ax.set_title("Angular momentum of TNS-0 (TNS-0 Fig. 14, from Table 1 and the session stamps)")
    return fig


# --- the decay fits: residuals and a log scale ------------------------------------------

def compute_spin_decay():
    """Residuals of the linear and exponential fits, and ln L against t."""
    hours, momentum, linear, exponential = decay_fits()
    return FigureData("", "", "", {}, [
        Series("linear fit", {"t": ("h", hours), "residual": ("kg m^2/s", momentum - linear.predict(hours))}),
        Series("exponential fit", {"t": ("h", hours),
                                   "residual": ("kg m^2/s", momentum - exponential.predict(hours))}),
        Series("Table 1", {"t": ("h", hours), "L": ("kg m^2/s", momentum)}),
    ], extra={"linear": linear, "exponential": exponential})


def plot_spin_decay(data):
    """Left: residuals of both fits. Right: L on a log scale (an exponential decay is a straight line)."""
    import matplotlib.pyplot as plt

    lin, exp_ = data.extra["linear"], data.extra["exponential"]
    fig, axes = plt.subplots(1, 2, figsize=(6.8, 2.9))
    for s, style in zip(data.series[:2], ("C0o-", "C1s--")):
        axes[0].plot(s.columns["t"][1], s.columns["residual"][1] * 1e3, style, label=s.label)
    axes[0].axhline(0.0, color="0.5", linewidth=0.8)
    axes[0].set_ylabel("Table 1 − fit [10⁻³ kg·m²/s]")
    axes[0].set_title(f"Residuals (rms {lin.rms * 1e3:.2f} vs {exp_.rms * 1e3:.2f}·10⁻³)")
    axes[0].legend(fontsize=7.5)
    pts = data.series[2]
    t = np.linspace(0.0, 560.0, 113)
    axes[1].semilogy(pts.columns["t"][1], pts.columns["L"][1], "ko", label="Table 1")
    axes[1].semilogy(t, np.clip(lin.predict(t), 1e-3, None), "C0-", label="linear fit")
    axes[1].semilogy(t, exp_.predict(t), "C1--", label="exponential fit")
    axes[1].set_ylabel("$K$ [kg·m²/s] (log)")
    axes[1].set_title("On a log scale the data bend down")
    axes[1].legend(fontsize=7.5)
    for ax in axes:
        ax.set_xlabel("hours since session 1 [h]")
        ax.grid(alpha=0.3)
    return fig


# --- the hysteresis rods ---------------------------------------------------------------

AMPLITUDES = (6.0, 12.0, 20.0, 30.0, 60.0)


def compute_rod_loops(rod_coercivity, rod_remanence, rod_saturation, transit_field_amplitude,
                      transit_loop_energy, orbit_inclination, orbit_altitude, earth_dipole_moment):
    """Settled Flatley–Henretty loops at several amplitudes and the loop energy against the amplitude."""
    from ...earth import field_magnitude_range
    from ...hardware import limiting_loop_energy, rod_cycle_energy, settled_hysteresis_loop

    material = (rod_coercivity, rod_remanence, rod_saturation)
    h, b = settled_hysteresis_loop(np.array(AMPLITUDES), *material)
    series = [Series(f"Ha = {a:g} A/m", {"H": ("A/m", h[k]), "B": ("T", b[k])}) for k, a in enumerate(AMPLITUDES)]
    sweep = np.geomspace(1.0, 2000.0, 40)
    energy = rod_cycle_energy(sweep, *material)
    series.append(Series("loop energy", {"Ha": ("A/m", sweep), "W": ("J/m^3", energy),
                                         "W_limiting": ("J/m^3", limiting_loop_energy(sweep, *material))}))
    series.append(Series("Kovalenko: Transit rods", {"Ha": ("A/m", [transit_field_amplitude]),
                                                     "W": ("J/m^3", [transit_loop_energy])}))
    p = dict(orbit_inclination=orbit_inclination, orbit_altitude=orbit_altitude,
             earth_dipole_moment=earth_dipole_moment)
    return FigureData("", "", "", {}, series,
                      extra={"saturation_limit": 4.0 * rod_saturation * rod_coercivity,
                             "orbit_h": tuple(b / MU_0 for b in field_magnitude_range(tns0_orbit(p)))})


def plot_rod_loops(data):
    """Left: loops in the H–B plane. Right: ∮H dB against Ha, log–log, with its two limits."""
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(1, 2, figsize=(6.8, 3.1))
    for s in data.series[:len(AMPLITUDES)]:
        axes[0].plot(s.columns["H"][1], s.columns["B"][1] * 1e3, label=s.label)
    axes[0].set_xlabel("$H$ [A/m]")
    axes[0].set_ylabel("$B$ [mT]")
    axes[0].set_title("Settled Flatley–Henretty loops")
    axes[0].legend(fontsize=7)
    e = data.series[len(AMPLITUDES)].columns
    ha, w = e["Ha"][1], e["W"][1]
    axes[1].loglog(ha, w, "C0-", label=r"settled loop $\oint H\,dB$")
    axes[1].loglog(ha, e["W_limiting"][1], "C2:", label="area between the limbs")
    axes[1].axhline(data.extra["saturation_limit"], color="0.5", linestyle="--", linewidth=0.8,
                    label="$4B_sH_c$")
    small = ha < 4.0
    axes[1].loglog(ha[small], w[small][0] * (ha[small] / ha[small][0]) ** 3, "k-", linewidth=0.8,
                   label=r"$\propto H_a^3$")
    k = data.series[-1].columns
    axes[1].loglog(k["Ha"][1], k["W"][1], "C3*", markersize=9, label="Kovalenko: Transit rods")
    lo, hi = data.extra["orbit_h"]
    axes[1].axvspan(lo, hi, color="C1", alpha=0.2, label="|H| along the orbit")
    axes[1].set_xlabel("amplitude $H_a$ [A/m]")
    axes[1].set_ylabel("$W$ [J/m³]")
    axes[1].set_title("Energy lost per cycle")
    axes[1].legend(fontsize=7, loc="lower right")
    for ax in axes:
        ax.grid(alpha=0.3)
    return fig


def _rod_parameters():
    p = _defaults()
    return {
        "rod_coercivity": FigureParameter(p["rod_coercivity"], "A/m", "apparent coercivity Hc (HyMu-80 CubeSat rods)"),
        "rod_remanence": FigureParameter(p["rod_remanence"], "T", "apparent remanence Br"),
        "rod_saturation": FigureParameter(p["rod_saturation"], "T", "apparent saturation Bs"),
        "transit_field_amplitude": FigureParameter(p["transit_field_amplitude"], "A/m",
                                                   "Kovalenko's Transit example: field amplitude"),
        "transit_loop_energy": FigureParameter(p["transit_loop_energy"], "J/m^3",
                                               "Kovalenko's Transit example: loss per cycle"),
        "orbit_inclination": FigureParameter(p["orbit_inclination"], "rad", "orbit inclination"),
        "orbit_altitude": FigureParameter(p["orbit_altitude"], "m", "orbit altitude"),
        "earth_dipole_moment": FigureParameter(p["earth_dipole_moment"], "A m^2", "Earth's dipole moment"),
    }


# --- a session model (model only) -------------------------------------------------------

def compute_session_model(row, duration, transverse_inertia, axial_inertia):
    """Euler-case model signals of ДС1–ДС3 for one Table 1 row (cosine law clipped at 0 + albedo)."""
    from ...dynamics import euler_case_matrix
    from ...hardware import sun_sensor_signals
    from ...io.tns0 import load_table1

    tab = load_table1()
    k = int(round(row)) - 1
    if not 0 <= k < tab.session.size:
        raise ValueError(f"row must be a Table 1 row in [1, {tab.session.size}], got {shown(row)}")

    def value(name, default=0.0):
        v = float(tab.values[name][k])
        return default if np.isnan(v) else v

    t = np.linspace(0.0, duration, 1201)
    r = euler_case_matrix(t, value("angular_momentum"), value("nutation"), transverse_inertia, axial_inertia,
                          start_time=value("start_time"), initial_precession=value("phase_a"),
                          initial_proper_rotation=value("phase_b"))
    sigma, eps, alpha = value("sun_angle"), value("earth_polar_angle"), value("earth_azimuth")
    sun = np.array([np.sin(sigma), 0.0, np.cos(sigma)])
    earth = np.array([np.sin(eps) * np.cos(alpha), np.sin(eps) * np.sin(alpha), np.cos(eps)])
    signal = sun_sensor_signals(r, SENSOR_NORMALS, sun, earth=earth, albedo_ratio=value("albedo_ratio"))
    cols = {"t": ("s", t)}
    cols.update({f"s{j + 1}": ("1", signal[:, j]) for j in range(3)})
    return FigureData("", "", "", {}, [Series(f"Table 1 row {k + 1}", cols)], extra={"row": k + 1})


def plot_session_model(data):
    """Three model sensor signals against time."""
    import matplotlib.pyplot as plt

    c = data.series[0].columns
    fig, ax = plt.subplots(figsize=(6.4, 2.9))
    for j, name in enumerate(("DS1 (+x)", "DS2 (+z)", "DS3 (−x)")):
        ax.plot(c["t"][1], c[f"s{j + 1}"][1], label=name)
    ax.set_xlabel("time since t0 [s]")
    ax.set_ylabel("signal / its maximum")
    ax.set_title(f"Model only, Table 1 row {data.extra['row']}: measured traces not published; "
                 "sensor normals assumed")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7.5, loc="upper right")
    return fig


def _session_parameters():
    p = _defaults()
    return {"row": FigureParameter(1.0, "1", "Table 1 row (session)", whole=True),
            "duration": FigureParameter(60.0, "s", "length of the model trace", high=1e4),
            "transverse_inertia": FigureParameter(p["transverse_inertia"], "kg m^2", "A (ours)"),
            "axial_inertia": FigureParameter(p["axial_inertia"], "kg m^2", "C (ours)")}


# --- the session fit on a synthetic session ------------------------------------------------

def compute_session_fit(transverse_inertia, axial_inertia):
    """A synthetic session from Table 1 row 1 (+ noise) and the three methods' fits."""
    from ...estimation import euler_case_sun_signals, mirror_solution

    fits = session_fits({"transverse_inertia": transverse_inertia, "axial_inertia": axial_inertia})
    t, data, truth = fits["time"], fits["signals"], fits["truth"]
    a, c = transverse_inertia, axial_inertia

    def model(constants):
        return euler_case_sun_signals(t, constants, SENSOR_NORMALS, a, c)

    def cols(signals):
        out = {"t": ("s", t)}
        out.update({f"s{j + 1}": ("1", signals[j]) for j in range(3)})
        return out

    series = [Series("synthetic data", cols(data)), Series("truth", cols(model(truth))),
              Series("mirror of the truth", cols(model(mirror_solution(truth))))]
    for fit in fits["fits"]:
        series.append(Series(fit["method"], cols(model(fit["params"]))))
    series.append(Series("methods", {"rms": ("1", [f["rms"] for f in fits["fits"]]),
                                     "evaluations": ("1", [f["evaluations"] for f in fits["fits"]]),
                                     "recovered": ("1", [float(f["recovered"]) for f in fits["fits"]])}))
    return FigureData("", "", "", {}, series, extra={"names": [f["method"] for f in fits["fits"]],
                                                     "noise": float(np.std(data - model(truth)))})


def plot_session_fit(data):
    """Left: ДС1 and ДС2 over 20 s, data and fits. Right: rms residual of each method."""
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(1, 2, figsize=(6.8, 3.0), width_ratios=(1.7, 1.0))
    data_s, truth, _, *fits = data.series[:-1]
    t = data_s.columns["t"][1]
    show = t <= 20.0
    ax = axes[0]
    for j, offset in ((1, 0.0), (2, 1.3)):
        ax.plot(t[show], data_s.columns[f"s{j}"][1][show] + offset, ".", color="0.6", markersize=2,
                label="synthetic data" if j == 1 else None)
        for k, s in enumerate(fits):
            ax.plot(t[show], s.columns[f"s{j}"][1][show] + offset, color=f"C{k}", linewidth=0.9,
                    label=s.label if j == 1 else None)
    ax.set_yticks([0.0, 1.0, 1.3, 2.3], ["0", "1", "0", "1"])
    ax.text(0.2, 1.05, "DS1 (+x)", fontsize=7.5)
    ax.text(0.2, 2.35, "DS2 (+z)", fontsize=7.5)
    ax.set_xlabel("time [s]")
    ax.set_ylabel("signal (offset)")
    ax.set_title("Synthetic session from Table 1 row 1 (model only)", fontsize=8.5)
    ax.legend(fontsize=7, loc="lower right")
    m = data.series[-1].columns
    ax = axes[1]
    ax.bar(range(len(m["rms"][1])), m["rms"][1], color=[f"C{k}" for k in range(len(m["rms"][1]))])
    ax.axhline(data.extra["noise"], color="k", linestyle="--", linewidth=0.8, label="noise level")
    ax.set_xticks(range(len(m["rms"][1])), ["grid", "multi-start", "frequency"], fontsize=7.5)
    ax.set_ylabel("rms residual")
    ax.set_yscale("log")
    ax.set_title("Fit quality", fontsize=8.5)
    ax.legend(fontsize=7)
    for ax in axes:
        ax.grid(alpha=0.3)
    return fig


# --- the capture Monte Carlo ------------------------------------------------------------

_CAPTURE_NAMES = ("magnet_moment", "rod_volume", "capture_initial_momentum", "capture_initial_nutation",
                  "capture_duration", "capture_members", "capture_seed")


def compute_capture(**params):
    """The capture Monte Carlo (a few seconds compiled): angle between B and the axis over time, final angles."""
    p = _defaults()
    p.update(params)
    cap = capture_run(p)
    run = cap["run"]
    hours = run.time / 3600.0
    series = [Series(f"member {k + 1}", {"t": ("h", hours), "angle": ("deg", np.degrees(run.axis_field_angle[k])),
                                         "L": ("kg m^2/s", run.angular_momentum[k])})
              for k in range(run.angular_momentum.shape[0])]
    series.append(Series("final regime", {"angle": ("deg", np.degrees(cap["final_angle"])),
                                          "rate": ("rad/s", cap["final_rate"])}))
    # Only the members whose final rate admits a conical rotation (the relation has a solution).
    ok = np.isfinite(cap["conical_angle"])
    series.append(Series("conical relation", {"member": ("1", np.flatnonzero(ok) + 1.0),
                                              "angle": ("deg", np.degrees(cap["final_angle"][ok])),
                                              "conical_angle": ("deg", np.degrees(cap["conical_angle"][ok]))}))
    return FigureData("", "", "", {}, series)


def plot_capture(data):
    """Left: angle(B, axis) over time with Table 2 and 'about 45°'. Right: final angle vs the conical relation."""
    import matplotlib.pyplot as plt
    from scipy.ndimage import uniform_filter1d

    from ...io import load_printed

    printed = load_printed("tns0")
    fig, axes = plt.subplots(1, 2, figsize=(6.8, 3.1), width_ratios=(1.6, 1.0))
    members, final, cone = data.series[:-2], data.series[-2].columns, data.series[-1].columns
    for k, s in enumerate(members):
        t, a = s.columns["t"][1], s.columns["angle"][1]
        axes[0].plot(t, uniform_filter1d(a, 31, mode="nearest"), color=f"C{k % 10}", linewidth=0.9)
    axes[0].axhline(np.degrees(printed["tns0-table2-nutation"].value), color="k", linestyle="--", linewidth=1.0,
                    label="Table 2: 0.85 rad")
    axes[0].axhline(np.degrees(printed["tns0-final-angle"].value), color="0.5", linestyle=":", linewidth=1.0,
                    label="conclusion: ≈ 45°")
    axes[0].set_xlabel("time [h]")
    axes[0].set_ylabel("angle(B, symmetry axis) [°]")
    axes[0].set_title("Capture runs (30-min running mean)")
    axes[0].legend(fontsize=7.5, loc="upper right")
    axes[1].plot(cone["conical_angle"][1], cone["angle"][1], "C0o", label="members")
    lim = [0.0, 90.0]
    axes[1].plot(lim, lim, "k-", linewidth=0.8, label="equal")
    axes[1].set_xlim(*lim)
    axes[1].set_ylim(*lim)
    axes[1].set_xlabel(r"$\theta'$ from $\Omega^2(J_t - J_s)\cos\theta' = mB$ [°]")
    axes[1].set_ylabel("simulated, last orbit [°]")
    axes[1].set_title(f"Final angle ({len(cone['angle'][1])} of {len(final['angle'][1])} have a solution)")
    axes[1].legend(fontsize=7.5)
    for ax in axes:
        ax.grid(alpha=0.3)
    return fig


#: What the chapter's inputs mean on the capture and full-run figures, and the values the
#: figures accept for those that set their work or count something (see
#: :class:`~magbench.chapters.registry.FigureParameter`); units come from the parameter set.
_INPUTS = {"magnet_moment": ("magnet moment m (ours)", {}),
           "rod_volume": ("volume of each rod (ours, calibrated)", {}),
           "capture_initial_momentum": ("initial |L|", {}), "capture_initial_nutation": ("initial nutation", {}),
           "capture_duration": ("length of each run", dict(high=1e7)),
           "capture_members": ("Monte Carlo members", dict(high=1e4, whole=True)),
           "capture_seed": ("seed of the directions of L", dict(whole=True)),
           "full_run_duration": ("length of the run from session 1", dict(high=3e7))}


def _input_parameters(names):
    from ...io import load_parameter_set

    p, table = _defaults(), load_parameter_set(CHAPTER.source)
    return {name: FigureParameter(p[name], table[name].unit_si, _INPUTS[name][0], **_INPUTS[name][1])
            for name in names}


def _capture_parameters():
    return _input_parameters(_CAPTURE_NAMES)


# --- the full run from session 1, with the energy-balance line ---------------------------

_FULL_NAMES = ("magnet_moment", "rod_volume", "full_run_duration", "capture_seed")


def compute_full_run(**params):
    """Full dynamics from session 1 (slow: ~30–70 s): L, nutation and angle(B, axis) over time."""
    from ...io import load_printed
    from ...io.tns0 import load_table1

    p = _defaults()
    p.update(params)
    full, balance = full_run(p), decay_balance(p)
    run, hours = full["run"], full["hours"]
    t1 = load_table1()
    printed = load_printed("tns0")
    line_t = np.linspace(0.0, min(hours[-1], -balance["start"] / balance["mean"] / 3600.0), 50)
    line = balance["start"] + balance["mean"] * line_t * 3600.0
    band = balance["std"] * line_t * 3600.0
    # L cannot be negative: the band of the line's spread over directions stops at zero.
    low, high = np.clip(line - band, 0.0, None), np.clip(line + band, 0.0, None)
    return FigureData("", "", "", {}, [
        Series("simulation", {"t": ("h", hours), "L": ("kg m^2/s", run.angular_momentum),
                              "theta": ("deg", np.degrees(run.nutation)),
                              "axis_field_angle": ("deg", np.degrees(run.axis_field_angle))}),
        Series("Table 1", {"t": ("h", full["session_hours"]), "L": ("kg m^2/s", t1.angular_momentum),
                           "theta": ("deg", np.degrees(t1.nutation))}),
        Series("energy balance", {"t": ("h", line_t), "L": ("kg m^2/s", line), "L_low": ("kg m^2/s", low),
                                  "L_high": ("kg m^2/s", high)}),
        Series("Table 2", {"angle": ("deg", [np.degrees(printed["tns0-table2-nutation"].value)]),
                           "L": ("kg m^2/s", [printed["tns0-table2-angular-momentum"].value])}),
    ], extra={"orbit_samples": max(2, int(np.ceil(tns0_orbit(p).period / 300.0))),
              "capture_hours": full["capture_hours"], "relaxed_hours": full["relaxed_hours"],
              "conclusion": float(np.degrees(printed["tns0-final-angle"].value))})


def plot_full_run(data):
    """Three panels over time: L with Table 1 and the balance line; the nutation; angle(B, axis)."""
    import matplotlib.pyplot as plt
    from scipy.ndimage import uniform_filter1d

    sim, tab, line, tab2 = (s.columns for s in data.series)
    fig, axes = plt.subplots(3, 1, figsize=(6.4, 6.6), sharex=True)
    t = sim["t"][1]
    ax = axes[0]
    ax.fill_between(line["t"][1], line["L_low"][1], line["L_high"][1], color="C1", alpha=0.2)
    ax.plot(line["t"][1], line["L"][1], "C1--", label="energy balance (mean ± sd over directions, ≥ 0)")
    ax.plot(t, sim["L"][1], "C0-", label=r"full dynamics (one direction of $\mathbf{K}$)")
    ax.plot(tab["t"][1], tab["L"][1], "ko", label="Table 1")
    ax.set_ylabel("$K$ [kg·m²/s]")
    ax.legend(fontsize=7.5)
    ax = axes[1]
    ax.plot(t, sim["theta"][1], "C0-", label="full dynamics")
    ax.plot(tab["t"][1], tab["theta"][1], "ko", label="Table 1")
    ax.set_ylabel(r"nutation $\theta$ [°]")
    ax.legend(fontsize=7.5)
    ax = axes[2]
    ax.plot(t, uniform_filter1d(sim["axis_field_angle"][1], data.extra["orbit_samples"], mode="nearest"), "C0-",
            label="full dynamics (one-orbit running mean)")
    ax.axhline(tab2["angle"][1][0], color="k", linestyle="--", linewidth=1.0, label="Table 2: 0.85 rad")
    ax.axhline(data.extra["conclusion"], color="0.5", linestyle=":", linewidth=1.0, label="conclusion: ≈ 45°")
    ax.axvline(data.extra["capture_hours"], color="C3", linewidth=0.8, label="capture ($K$ at twice its final value)")
    ax.set_ylabel("angle(B, axis) [°]")
    ax.set_xlabel("hours since session 1 [h]")
    ax.set_ylim(0.0, 200.0)
    ax.legend(fontsize=7, loc="upper right", ncol=2)
    for ax in axes:
        ax.grid(alpha=0.3)
    axes[0].set_title("From session 1 to the capture about B (model: rods calibrated, magnet chosen)", fontsize=9)
    return fig


def _full_parameters():
    return _input_parameters(_FULL_NAMES)


register(FigureSpec("tns0-fig03", "The field cone at the ISS inclination (TNS-0 Fig. 3)", f"{SOURCE}, §1, Fig. 3",
                    compute_fig03, plot_fig03, _fig03_parameters))
register(FigureSpec("tns0-cone-deviation", "The exact field against the averaged cone model",
                    f"{SOURCE}, §1 (its averaged model); exact dipole field", compute_cone_deviation,
                    plot_cone_deviation, {}))
register(FigureSpec("tns0-fig14", "TNS-0's angular momentum against time (TNS-0 Fig. 14)",
                    f"{SOURCE}, Table 1, session stamps, Fig. 14", compute_fig14, plot_fig14, {}))
register(FigureSpec("tns0-spin-decay", "Linear against exponential decay of Table 1's L",
                    f"{SOURCE}, Table 1", compute_spin_decay, plot_spin_decay, {}))
register(FigureSpec("tns0-rod-loops", "Hysteresis-rod loops and the energy lost per cycle",
                    "Flatley & Henretty (1995); Kovalenko (1975) §12.1, p. 229", compute_rod_loops, plot_rod_loops,
                    _rod_parameters))
register(FigureSpec("tns0-session-model", "Euler-case sun-sensor model for a Table 1 row (model only)",
                    f"{SOURCE}, §2, Table 1 (sensor normals ours)", compute_session_model, plot_session_model,
                    _session_parameters))
register(FigureSpec("tns0-session-fit", "Fitting a session: three methods on a synthetic session from Table 1 row 1",
                    f"{SOURCE}, §2, Table 1 (synthetic data; sensor normals ours)", compute_session_fit,
                    plot_session_fit, lambda: {k: v for k, v in _session_parameters().items()
                                               if k in ("transverse_inertia", "axial_inertia")}))
register(FigureSpec("tns0-capture", "Capture into rotation about B, Monte Carlo",
                    f"{SOURCE}, Table 2, conclusions", compute_capture, plot_capture, _capture_parameters, slow=True))
register(FigureSpec("tns0-full-run", "From session 1 to the capture about B: full dynamics and the energy balance",
                    f"{SOURCE}, Tables 1 and 2, Fig. 14", compute_full_run, plot_full_run,
                    _full_parameters, slow=True))
