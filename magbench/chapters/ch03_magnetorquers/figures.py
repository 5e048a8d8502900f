"""Figures of thesis chapter 3: the magnetorquers (eqs. 17–32, Fig. 9) and Kovalenko's actuators."""

import numpy as np

from ... import hardware
from ...constants import MU_0
from ...io import load_measurements, load_wire_table
from . import CHAPTER
from .._base import chapter_parameters
from ..registry import FigureData, FigureParameter, FigureSpec, Series, register
from ..._validate import shown

SOURCE = "Bui (2016), thesis §3"


def _defaults():
    return chapter_parameters(CHAPTER.key, overrides="")


def _wire_sizes():
    t = load_wire_table("iec60317")
    return np.array(t.nominal_diameter), np.array(t.max_overall_diameter), np.array(t.tolerance)


def _coil_parameters():
    p = _defaults()
    return {
        "mtq_moment": FigureParameter(p["mtq_moment"], "A m^2", "required dipole moment"),
        "mtq_voltage": FigureParameter(p["mtq_voltage"], "V", "supply voltage"),
        "mtq_side": FigureParameter(p["mtq_side"], "m", "side of the square turn"),
        "mtq_max_power": FigureParameter(p["mtq_max_power"], "W", "power limit per coil"),
        "mtq_max_mass": FigureParameter(p["mtq_max_mass"], "kg", "conductor mass limit per coil"),
        "copper_resistivity": FigureParameter(p["copper_resistivity"], "ohm m", "conductor resistivity"),
        "copper_density": FigureParameter(p["copper_density"], "kg/m^3", "conductor density"),
    }


# --- thesis Fig. 9: the mock-up with its coils -------------------------------------------

def compute_fig09(mtq_side, mtq_turns, wire_pitch, coils):
    """Outlines of the cube and of each coil's winding band, to scale.

    Each coil is a square winding of side ``mtq_side`` around one body axis (x, y, then z),
    a single layer of ``mtq_turns`` turns at ``wire_pitch`` centred on the cube: the
    thesis's assumption of a dense single-layer winding (thesis §3.2). Turns that do not
    fit in one layer across the side are wound in as many layers as they need (ours);
    ``extra["layers"]`` says how many, and the drawing's title names them.
    """
    n_coils = int(coils)
    if n_coils not in (2, 3) or n_coils != coils:
        raise ValueError(f"coils must be 2 or 3, got {shown(coils)}")
    if mtq_side <= 0 or mtq_turns < 1 or wire_pitch <= 0:
        raise ValueError(f"mtq_side, mtq_turns and wire_pitch must be positive, got "
                         f"{mtq_side!r}, {mtq_turns!r}, {wire_pitch!r}")
    h = mtq_side / 2.0
    if wire_pitch > mtq_side:
        raise ValueError(f"wire_pitch {shown(wire_pitch)} m is wider than the side mtq_side {shown(mtq_side)} m: "
                         "not one turn fits")
    layers, width = hardware.winding_band(mtq_turns, mtq_side, wire_pitch)
    corners = np.array([[-h, -h], [h, -h], [h, h], [-h, h], [-h, -h]])
    series = []
    # cube edges as one polyline per face pair
    for z in (-h, h):
        series.append(Series(f"cube face z = {z:+.3f}", {
            "x": ("m", corners[:, 0]), "y": ("m", corners[:, 1]), "z": ("m", np.full(5, z))}))
    for axis in range(n_coils):
        for offset in (-width / 2, width / 2):
            pts = np.zeros((5, 3))
            pts[:, axis] = offset
            others = [k for k in range(3) if k != axis]
            pts[:, others[0]], pts[:, others[1]] = corners[:, 0], corners[:, 1]
            series.append(Series(f"coil {'xyz'[axis]} edge {offset * 1e3:+.1f} mm", {
                "x": ("m", pts[:, 0]), "y": ("m", pts[:, 1]), "z": ("m", pts[:, 2])}))
    return FigureData("thesis-fig09", "", "", {}, series,
                      extra={"side": mtq_side, "width": width, "coils": n_coils, "layers": layers})


def plot_fig09(data):
    """3-D drawing: the cube, the winding bands and the moment of each coil."""
    import matplotlib.pyplot as plt
    from mpl_toolkits.mplot3d.art3d import Poly3DCollection

    h, w, n = data.extra["side"] / 2, data.extra["width"], data.extra["coils"]
    fig = plt.figure(figsize=(6.4, 5.6))
    ax = fig.add_subplot(projection="3d")
    ax.computed_zorder = False          # the moments and their labels stay on top of the bands
    for s in data.series[:2]:
        c = s.columns
        ax.plot(c["x"][1], c["y"][1], c["z"][1], color="0.5", linewidth=0.8)
    for x in (-h, h):
        for y in (-h, h):
            ax.plot([x, x], [y, y], [-h, h], color="0.5", linewidth=0.8)
    colours = ("C3", "C0", "C2")
    for axis in range(n):
        quads = []
        others = [k for k in range(3) if k != axis]
        corners = [(-h, -h), (h, -h), (h, h), (-h, h), (-h, -h)]
        for (a0, b0), (a1, b1) in zip(corners[:-1], corners[1:]):
            quad = []
            for off, (a, b) in ((-w / 2, (a0, b0)), (-w / 2, (a1, b1)), (w / 2, (a1, b1)), (w / 2, (a0, b0))):
                p = [0.0, 0.0, 0.0]
                p[axis], p[others[0]], p[others[1]] = off, a, b
                quad.append(p)
            quads.append(quad)
        ax.add_collection3d(Poly3DCollection(quads, facecolor=colours[axis], alpha=0.35,
                                             edgecolor=colours[axis]))
        tip = [0.0, 0.0, 0.0]
        tip[axis] = 1.5 * h
        ax.quiver(0, 0, 0, *tip, color=colours[axis], linewidth=2.5, arrow_length_ratio=0.15, zorder=10)
        ax.text(*[1.2 * v for v in tip], rf"$\mathbf{{m}}_{'xyz'[axis]}$", color=colours[axis], fontsize=12,
                ha="center", va="center", zorder=11)
    lim = 1.9 * h
    ax.set_xlim(-lim, lim)
    ax.set_ylim(-lim, lim)
    ax.set_zlim(-lim, lim)
    ax.set_box_aspect((1, 1, 1), zoom=1.2)
    # The drawing is to scale and its size is in the title: axes, ticks and panes would only
    # compete with the moments' labels.
    ax.set_axis_off()
    layers = data.extra.get("layers", 1)
    kind = "single-layer" if layers == 1 else f"{layers}-layer"
    ax.set_title(f"1U mock-up, a {2 * h * 1e2:.0f} cm cube, with {n} orthogonal coils\n"
                 f"({kind} bands {w * 1e3:.0f} mm wide) and the moment $\\mathbf{{m}}$ of each", fontsize=9)
    return fig


def _fig09_parameters():
    p = _defaults()
    d, od, _ = _wire_sizes()
    return {
        "mtq_side": FigureParameter(p["mtq_side"], "m", "side of the cube and of the square turn"),
        "mtq_turns": FigureParameter(p["mtq_turns"], "1", "turns per coil", whole=True),
        "wire_pitch": FigureParameter(float(od[np.argmin(abs(d - 0.2e-3))]), "m",
                                      "winding pitch (IEC 60317 grade-1 overall diameter of 0.2 mm wire)"),
        "coils": FigureParameter(3.0, "1", "number of coils drawn (2 as built, 3 as in the caption)", whole=True),
    }


# --- the design space: power and mass against N and against the wire ------------------------

def compute_design_space(mtq_moment, mtq_voltage, mtq_side, mtq_max_power, mtq_max_mass,
                         copper_resistivity, copper_density):
    """W(N), M(N) for the eq. (21) wire; feasible N for every IEC wire (square turn)."""
    m, u, l, rho, g = mtq_moment, mtq_voltage, mtq_side, copper_resistivity, copper_density
    s_design = float(hardware.wire_area_for_moment(m, u, l, rho))
    n = np.arange(100, 1501)
    power = hardware.joule_power_for_moment(m, u, n, l, "square")
    mass = hardware.coil_mass_for_moment(m, u, n, rho, g, "square")
    lo, hi = hardware.turns_per_volt_bounds(m, l, mtq_max_power, mtq_max_mass, rho, g, "square")
    d, od, _ = _wire_sizes()
    s_r = np.pi * d**2 / 4
    n_min_power, n_max_mass = hardware.wire_turn_limits(u, l, s_r, mtq_max_power, mtq_max_mass, rho, g, "square")
    wires = {
        "wire_diameter": ("mm", d * 1e3),
        "moment": ("A m^2", hardware.moment_from_voltage(u, l, s_r, rho)),
        "n_min_power": ("1", n_min_power), "n_max_mass": ("1", n_max_mass),
        "n_max_single_layer": ("1", hardware.turns_per_layer(l, od)),
    }
    res = hardware.design_magnetorquer(m, u, hardware.Turn.square(l), mtq_max_power, mtq_max_mass,
                                       hardware.WireSizes(d, rho, g, overall_diameters=od), require_fit=True)
    best = res["min_mass"] or {}
    return FigureData("ch03-design-space", "", "", {}, [
        Series("eq. (21) wire", {"turns": ("1", n), "power": ("W", power), "mass": ("kg", mass)}),
        Series("IEC 60317 wires", wires)],
        extra={"n_lo": float(lo * u), "n_hi": float(hi * u), "d_design": float(hardware.wire_diameter(s_design)),
               # the built coil at this voltage across its measured resistance (thesis §3.3, ≈ 55 Ω)
               "built_power": float(u**2 / load_measurements("thesis")["mtq-resistance"].value),
               "best": best, "moment": m, "max_power": mtq_max_power, "max_mass": mtq_max_mass})


def plot_design_space(data):
    """Left: W and M against N, feasible band shaded. Right: feasible N for each wire."""
    import matplotlib.pyplot as plt

    e = data.extra
    c = {k: v for k, (unit, v) in data.series[0].columns.items()}
    w = {k: v for k, (unit, v) in data.series[1].columns.items()}
    fig, (a1, a3) = plt.subplots(1, 2, figsize=(7.0, 4.3))
    a1.plot(c["turns"], c["power"], "C3", label="power $P$ (eq. 28)")
    a1.axhline(e["max_power"], color="C3", linestyle=":", linewidth=0.8)
    a1.axvspan(e["n_lo"], e["n_hi"], color="C2", alpha=0.12, label="feasible ($P$, $m_c$ within limits)")
    a1.plot([240], [2.0], "o", color="C3", mfc="none", label="thesis design, N = 240 (2 W)")
    a1.plot([240], [e["built_power"]], "x", color="k", label=f"built coil, 0.2 mm wire\n({e['built_power']:.2f} W with its measured $R$)")
    a1.set_xlabel("turns N")
    a1.set_ylabel("Joule power [W]", color="C3")
    a1.set_ylim(0, 5)
    a2 = a1.twinx()
    a2.plot(c["turns"], c["mass"] * 1e3, "C0", label="mass $m_c$ (eq. 29)")
    a2.axhline(e["max_mass"] * 1e3, color="C0", linestyle=":", linewidth=0.8)
    a2.plot([240], [c["mass"][c["turns"] == 240][0] * 1e3], "o", color="C0", mfc="none")
    a2.set_ylabel("conductor mass [g]", color="C0")
    a2.set_ylim(0, 125)
    h1, l1 = a1.get_legend_handles_labels()
    h2, l2 = a2.get_legend_handles_labels()
    # On the twin axes, so that no line is drawn over it; above the mass line, right of the power curve.
    a2.legend(h1 + h2, l1 + l2, fontsize=7, loc="upper left", bbox_to_anchor=(0.1, 1.0), framealpha=0.95)
    a1.set_title(f"wire of eq. (21), d = {e['d_design'] * 1e3:.3f} mm", fontsize=8.5)
    d = w["wire_diameter"]
    ok = w["moment"] >= e["moment"]
    top = np.minimum(w["n_max_mass"], w["n_max_single_layer"])
    for k in np.flatnonzero(ok):
        if top[k] >= w["n_min_power"][k]:
            a3.plot([d[k], d[k]], [w["n_min_power"][k], top[k]], color="C2", linewidth=6, alpha=0.6)
    a3.plot(d, w["n_min_power"], "C3v", markersize=4, label="fewest turns for $P$ ≤ limit")
    a3.plot(d, w["n_max_mass"], "C0^", markersize=4, label="most turns for $m_c$ ≤ limit")
    a3.plot(d, w["n_max_single_layer"], "k_", markersize=8, label="most turns in one layer")
    a3.plot(d[~ok], w["n_min_power"][~ok], "x", color="0.5", label="moment below the requirement")
    if e["best"]:
        a3.plot([e["best"]["wire_diameter"] * 1e3], [e["best"]["turns"]], "*", color="C1", markersize=12,
                label=f"least mass: N = {e['best']['turns']}, d = {e['best']['wire_diameter'] * 1e3:.2f} mm")
    a3.set_yscale("log")
    a3.set_xlabel("bare wire diameter d [mm]\n(IEC 60317 sizes)")
    a3.set_ylabel("turns N")
    a3.set_ylim(10, 1e4)
    a3.legend(fontsize=7, loc="upper left")
    a3.set_title("feasible turns for each standard wire\n(green bars)", fontsize=8.5)
    return fig


# --- the W·M product: coil size, material, shape ------------------------------------------

def compute_wm_product(mtq_moment, mtq_side, mtq_voltage, copper_resistivity, copper_density,
                       aluminium_gamma_rho, turns_per_volt):
    """M·W = 16 m² γρ/l² against l for copper and aluminium; W and M at fixed N/U by shape."""
    side = np.linspace(0.03, 0.3, 271)
    cu = copper_resistivity * copper_density
    # only the product γρ enters M·W (eq. 26/30), so the density argument is 1
    product = {"side": ("m", side),
               "copper": ("kg W", hardware.mass_power_product(mtq_moment, side, cu, 1.0)),
               "aluminium": ("kg W", hardware.mass_power_product(mtq_moment, side, aluminium_gamma_rho, 1.0))}
    n = turns_per_volt * mtq_voltage
    shapes = {"side": ("m", side)}
    for shape in hardware.SHAPES:
        shapes[f"power_{shape}"] = ("W", hardware.joule_power_for_moment(mtq_moment, mtq_voltage, n, side, shape))
        shapes[f"mass_{shape}"] = ("kg", hardware.coil_mass_for_moment(mtq_moment, mtq_voltage, n, copper_resistivity,
                                                                  copper_density, shape) * np.ones_like(side))
    return FigureData("ch03-wm-product", "", "", {},
                      [Series("mass x power", product), Series("shape at fixed N/U", shapes)],
                      extra={"side0": mtq_side, "n": n})


def plot_wm_product(data):
    """Left: the product against size for both metals. Right: round vs square at fixed N/U."""
    import matplotlib.pyplot as plt

    p = {k: v for k, (u, v) in data.series[0].columns.items()}
    s = {k: v for k, (u, v) in data.series[1].columns.items()}
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(7.0, 4.6))
    a1.loglog(p["side"], p["copper"], "C1", label=r"copper (the thesis's $\gamma\rho$)")
    a1.loglog(p["side"], p["aluminium"], "C0", label=r"aluminium (Kovalenko's $\gamma\rho$)")
    a1.axvline(data.extra["side0"], color="0.6", linestyle=":", label="mock-up coil, l = 0.1 m")
    a1.set_xlabel("coil size l [m]")
    a1.set_ylabel("$m_c P$ [kg·W]")
    from matplotlib.ticker import FixedLocator, NullFormatter, ScalarFormatter
    a1.xaxis.set_major_locator(FixedLocator([0.03, 0.05, 0.1, 0.2, 0.3]))
    a1.xaxis.set_major_formatter(ScalarFormatter())
    a1.xaxis.set_minor_formatter(NullFormatter())     # the log axis labelled its minor ticks on top of each other
    a1.legend(fontsize=8)
    a1.set_title(r"$m_c P = 16 m^2 \gamma\rho / l^2$, any $N$, $U$ and shape", fontsize=8.5)
    for shape, style in (("round", "--"), ("square", "-")):
        a2.plot(s["side"], s[f"power_{shape}"], "C3" + style, label=f"power, {shape}")
    a2.set_xlabel("coil size l [m]")
    a2.set_ylabel("Joule power [W]", color="C3")
    a2.set_yscale("log")
    a3 = a2.twinx()
    for shape, style in (("round", "--"), ("square", "-")):
        a3.plot(s["side"], s[f"mass_{shape}"] * 1e3, "C0" + style, label=f"mass, {shape}")
    a3.set_ylabel("conductor mass [g]", color="C0")
    a3.set_ylim(0, 1.5 * np.max(s["mass_square"]) * 1e3)
    h1, l1 = a2.get_legend_handles_labels()
    h2, l2 = a3.get_legend_handles_labels()
    a2.legend(h1 + h2, l1 + l2, fontsize=8)
    a2.set_title(f"round vs square turn, copper, N = {data.extra['n']:.0f}", fontsize=8.5)
    return fig


def _wm_parameters():
    p = _defaults()
    c = _coil_parameters()
    return {
        "mtq_moment": c["mtq_moment"], "mtq_side": c["mtq_side"], "mtq_voltage": c["mtq_voltage"],
        "copper_resistivity": c["copper_resistivity"], "copper_density": c["copper_density"],
        "aluminium_gamma_rho": FigureParameter(p["aluminium_gamma_rho"], "ohm kg/m^2",
                                               "density × resistivity of aluminium (Kovalenko p. 173)"),
        "turns_per_volt": FigureParameter(20.0, "1/V", "N/U for the right panel (the thesis's lower bound)"),
    }


# --- three actuators for the same moment --------------------------------------------------

def _air_core_row(p):
    """The least-mass air-core coil on the IEC wire table that meets the moment, power and mass."""
    d, od, _ = _wire_sizes()
    coil = hardware.design_magnetorquer(p["mtq_moment"], p["mtq_voltage"], hardware.Turn.square(p["mtq_side"]),
                                        p["mtq_max_power"], p["mtq_max_mass"],
                                        hardware.WireSizes(d, p["copper_resistivity"], p["copper_density"],
                                                           overall_diameters=od),
                                        require_fit=True)["min_mass"]
    row = ("air-core coil (IEC wire, least mass)", coil["mass"] if coil else np.nan,
           coil["power"] if coil else np.nan, p["mtq_side"], p["mtq_moment"] if coil is None else coil["moment"], 1.0)
    return row, coil


def _electromagnet_row(p):
    """Kovalenko's rod electromagnet (9.63)–(9.73), with the moment its winding's field
    actually gives on the magnetisation curve (9.21)."""
    j_design, a = p["permalloy_design_magnetization"], p["permalloy_a"]
    # electromagnet_design takes J° and H° as given; the curve (9.21) J = aH/(b + H) never
    # reaches a, so a design magnetisation at or above it is no state of this material.
    if not 0 < j_design < a:
        raise ValueError(f"permalloy_design_magnetization must lie in (0, permalloy_a = {a:g}) A/m, "
                         f"below the saturation of the magnetisation curve (Kovalenko 9.21), "
                         f"got {shown(j_design)}")
    em = hardware.electromagnet_design(p["mtq_moment"], p["em_elongation"], j_design, p["permalloy_design_field"],
                                       p["core_averaging_factor"], p["em_current_density"], p["em_fill_factor"],
                                       p["copper_resistivity"], p["core_density"], p["copper_density"],
                                       p["mtq_voltage"])
    # saturation check: the central magnetisation the winding's field actually produces
    j_c = float(hardware.core_central_magnetization(em["coil_field"], em["demagnetizing_factor"], a,
                                                    p["permalloy_b"]))
    em_moment = float(hardware.electromagnet_moment(j_c, em["core_diameter"], em["length"],
                                                    p["core_averaging_factor"]))
    return ("rod electromagnet, permalloy 50N", em["mass"], em["power"], em["length"], em_moment, 1.0), em, j_c


def _magnet_rows(p):
    """Least-mass permanent magnets (10.17)–(10.20): the best remanence, and the AlNiCo alloy."""
    m = p["mtq_moment"]
    rows = []
    for label, j in (("permanent magnet, B_r = %.2g T" % p["magnet_remanence"], p["magnet_remanence"] / MU_0),
                     ("permanent magnet, AlNiCo YuN13DK25BA", p["alnico_max_magnetization"])):
        length, dia, mass = hardware.permanent_magnet_min_mass(m, j, p["alnico_elongation"], p["magnet_density"])
        rows.append((label, float(mass), 0.0, float(length), m, 0.0))
    return rows


def compute_actuators(**params):
    """Mass, power and size of an air-core coil, a rod electromagnet and permanent magnets
    for one moment; ``params`` are the figure's inputs, declared with their units in
    :func:`_actuator_parameters` (the coil's, the electromagnet's and the magnets')."""
    p = {**_defaults(), **params}
    coil_row, coil = _air_core_row(p)
    em_row, em, j_c = _electromagnet_row(p)
    rows = [coil_row, em_row, *_magnet_rows(p)]
    cols = {
        "mass": ("kg", [r[1] for r in rows]), "power": ("W", [r[2] for r in rows]),
        "length": ("m", [r[3] for r in rows]), "moment": ("A m^2", [r[4] for r in rows]),
        "controllable": ("1", [r[5] for r in rows]),
    }
    return FigureData("ch03-actuators", "", "", {}, [Series("actuators", cols)],
                      extra={"labels": [r[0] for r in rows], "coil": coil, "electromagnet": em,
                             "em_central_magnetization": j_c})


def plot_actuators(data):
    """Mass and power of each actuator for the same moment (bars)."""
    import matplotlib.pyplot as plt

    c = {k: np.asarray(v, float) for k, (u, v) in data.series[0].columns.items()}
    labels = data.extra["labels"]
    y = np.arange(len(labels))
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(7.0, 3.7), sharey=True)
    a1.barh(y, c["mass"] * 1e3, color=["C1", "C2", "C0", "C0"])
    a1.set_yticks(y, labels, fontsize=8)
    a1.set_xlabel("mass [g] (conductor, core or magnet)")
    a1.invert_yaxis()
    a2.barh(y, c["power"], color=["C1", "C2", "C0", "C0"])
    a2.set_xlabel("power while on [W]")
    for k in y:
        a2.text(c["power"][k], k, "  fixed moment, no control" if not c["controllable"][k]
                else f"  {c['power'][k]:.3g} W", va="center", fontsize=8)
    fig.suptitle("Actuators for the mock-up's moment", fontsize=8.5)
    return fig


def _actuator_parameters():
    p = _defaults()
    params = _coil_parameters()
    for name, unit, text in (
            ("em_elongation", "1", "core elongation l/D1"),
            ("permalloy_design_magnetization", "A/m", "core magnetisation near saturation J°"),
            ("permalloy_design_field", "A/m", "field in the core at J°, H°"),
            ("permalloy_a", "A/m", "magnetisation-curve constant a (9.21)"),
            ("permalloy_b", "A/m", "magnetisation-curve constant b (9.21)"),
            ("core_averaging_factor", "1", "k, mean over central magnetisation of the core"),
            ("em_current_density", "A/m^2", "winding current density"),
            ("em_fill_factor", "1", "winding fill factor"),
            ("core_density", "kg/m^3", "core density"),
            ("magnet_remanence", "T", "remanence of the best magnet material (Kovalenko E02)"),
            ("magnet_density", "kg/m^3", "magnet density"),
            ("alnico_max_magnetization", "A/m", "largest mean magnetisation of YuN13DK25BA (an AlNiCo alloy)"),
            ("alnico_elongation", "1", "elongation at which it is reached")):
        params[name] = FigureParameter(p[name], unit, text)
    return params


register(FigureSpec("thesis-fig09", "The mock-up with its coils (thesis Fig. 9)", "Bui (2016), Fig. 9",
                    compute_fig09, plot_fig09, _fig09_parameters))
register(FigureSpec("ch03-design-space", "Power and mass of the magnetorquer against turns and wire",
                    "Bui (2016) eqs. (20)–(32)", compute_design_space, plot_design_space, _coil_parameters))
register(FigureSpec("ch03-wm-product", "The mass × power product against coil size, material and shape",
                    "Bui (2016) eqs. (26), (30); Kovalenko (1975) p. 173", compute_wm_product,
                    plot_wm_product, _wm_parameters))
register(FigureSpec("ch03-actuators", "Air-core coil, rod electromagnet and permanent magnet for one moment",
                    "Kovalenko (1975) eqs. (1.7), (9.63)–(9.73), (10.17)–(10.20)", compute_actuators,
                    plot_actuators, _actuator_parameters))
