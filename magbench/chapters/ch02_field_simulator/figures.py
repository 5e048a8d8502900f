"""Figures of thesis chapter 2: the Helmholtz-coil simulator of the geomagnetic field.

The thesis's Figs. 5–7 are COMSOL results and its Figs. 3 and 8 a sketch and a photo;
here every one is computed from the exact loop field of :mod:`magbench.fields`, for the
three coil spacings the thesis mentions (design d/a = 1.116, COMSOL 0.5 m, as built
≈ 0.51 m). The chapter-only figures show how the "uniform zone" depends on the
tolerance band, which explanations of the measured centre field survive, and a
three-axis simulator that cancels the laboratory's field.
"""

import numpy as np

from ...earth import igrf
from ... import fields
from ... import hardware
from ...chapters import ch02_field_simulator
from ...constants import MU_0
from ...hardware import HMC5883L_GAINS
from ...io import load_measurements
from . import CHAPTER
from .._base import chapter_parameters
from ..registry import FigureData, FigureParameter, FigureSpec, Series, register
from ..._validate import shown

SOURCE = "Bui (2016), thesis §2"


def _defaults():
    return chapter_parameters(CHAPTER.key, overrides="")


def _measured():
    return load_measurements("thesis")


# --- shared geometry ----------------------------------------------------------------------

def _geometry_parameters(tolerance=True):
    p = _defaults()
    params = {
        "turns": FigureParameter(p["sim_turns"], "1", "turns per coil", whole=True),
        "current": FigureParameter(p["sim_current"], "A", "current in each coil"),
        "coil_radius": FigureParameter(p["sim_built_radius"], "m", "coil radius (all geometries)"),
        "design_spacing_ratio": FigureParameter(p["sim_spacing_ratio"], "1", "design spacing d/a (thesis)"),
        "comsol_spacing": FigureParameter(p["sim_comsol_spacing"], "m", "spacing of the COMSOL model"),
        "built_spacing": FigureParameter(p["sim_built_spacing"], "m", "centre-to-centre spacing as built"),
    }
    if tolerance:
        params["tolerance"] = FigureParameter(0.01, "1", "uniform-zone band δ = | |H| − H0 | / H0")
    return params


def geometries(coil_radius, design_spacing_ratio, comsol_spacing, built_spacing):
    """The thesis's three coil spacings as ``[(label, separation [m]), ...]``."""
    d_design = design_spacing_ratio * coil_radius
    return [
        (f"design, d = {d_design * 100:.1f} cm (d/a = {design_spacing_ratio:.3f})", d_design),
        (f"COMSOL, d = {comsol_spacing * 100:.1f} cm", comsol_spacing),
        (f"as built, d = {built_spacing * 100:.1f} cm", built_spacing),
    ]


# --- thesis Fig. 5: field lines -----------------------------------------------------------

def compute_fig05(turns, current, coil_radius, design_spacing_ratio, comsol_spacing, built_spacing,
                  tolerance):
    """H on a grid of the meridian plane (x across, z along the axis) for each geometry."""
    a = coil_radius
    # Grids offset by a small fraction of a cell so that no node falls on a wire.
    x = np.linspace(-1.6 * a, 1.6 * a, 129) + 1.3e-3 * a
    z = np.linspace(-1.3 * a, 1.3 * a, 105) + 0.9e-3 * a
    xx, zz = np.meshgrid(x, z)
    pts = np.stack([xx, 0 * xx, zz], axis=-1)
    series = []
    for label, d in geometries(a, design_spacing_ratio, comsol_spacing, built_spacing):
        h = fields.helmholtz_b(pts, a, d, current, turns) / MU_0
        h0 = float(fields.helmholtz_center_h(current, turns, a, d))
        series.append(Series(label, {
            "x": ("m", xx), "z": ("m", zz), "H_x": ("A/m", h[..., 0]), "H_z": ("A/m", h[..., 2]),
            "|H|": ("A/m", np.linalg.norm(h, axis=-1)),
            "separation": ("m", [d]), "H_centre": ("A/m", [h0]),
            "uniform_sphere_radius": ("m", [fields.uniform_sphere_radius(a, d, tolerance)]),
        }))
    return FigureData("thesis-fig05", "", "", {}, series, extra={"shape": xx.shape, "radius": a,
                                                                 "tolerance": tolerance})


def plot_fig05(data):
    """Field lines (streamlines of H) coloured by |H| relative to the centre, one panel per geometry."""
    import matplotlib.pyplot as plt
    from matplotlib.cm import ScalarMappable
    from matplotlib.colors import Normalize

    shape, a = data.extra["shape"], data.extra["radius"]
    norm = Normalize(0.0, 1.6)
    fig, axes = plt.subplots(1, len(data.series), figsize=(7.0, 3.3), sharey=True, layout="constrained")
    for ax, s in zip(axes, data.series):
        c = {k: np.reshape(v, shape) if np.size(v) > 1 else float(np.ravel(v)[0])
             for k, (u, v) in s.columns.items()}
        h0 = c["H_centre"]
        ax.streamplot(c["x"][0], c["z"][:, 0], c["H_x"], c["H_z"], color=c["|H|"] / h0, cmap="viridis",
                      norm=norm, density=1.1, linewidth=0.7, arrowsize=0.6)
        dev = np.abs(c["|H|"] / h0 - 1)
        ax.contour(c["x"], c["z"], dev, levels=[data.extra["tolerance"]], colors="C3", linewidths=1.2)
        d = c["separation"]
        ax.plot([-a, a, -a, a], [-d / 2, -d / 2, d / 2, d / 2], "ko", markersize=5)
        ax.set_title(f"{s.label.replace(' (', chr(10) + '(')}\n$H_0$ = {h0:.0f} A/m at the centre", fontsize=7.5)
        ax.set_aspect("equal")
        ax.set_xlabel("$x$ (across the axis) [m]", fontsize=8)
        ax.tick_params(labelsize=7)
    axes[0].set_ylabel("axis $z$ [m]", fontsize=8, labelpad=1)
    # Equal-aspect panels leave constrained layout no room for the left label: keep a margin.
    fig.get_layout_engine().set(rect=(0.03, 0.0, 0.97, 1.0))
    bar = fig.colorbar(ScalarMappable(norm=norm, cmap="viridis"), ax=axes, shrink=0.8, pad=0.02)
    bar.set_label("$|H|/H_0$", fontsize=8)
    bar.ax.tick_params(labelsize=7)
    fig.suptitle(f"Field lines of the coil pair (thesis Fig. 5); red: |H| within "
                 f"{100 * data.extra['tolerance']:.3g} % of the centre value", fontsize=8.5)
    return fig


# --- thesis Figs. 6 and 7: |H| along the lines through the centre --------------------------

def _compute_line(figure_id, direction, turns, current, coil_radius, design_spacing_ratio,
                  comsol_spacing, built_spacing, tolerance):
    a = coil_radius
    s = np.linspace(-1.2 * a, 1.2 * a, 481)
    series = []
    for label, d in geometries(a, design_spacing_ratio, comsol_spacing, built_spacing):
        pts = np.zeros((s.size, 3))
        pts[:, 2 if direction == "axial" else 0] = s
        length = fields.uniform_zone_length(a, d, tolerance, direction)
        series.append(Series(label, {
            "position": ("m", s), "|H|": ("A/m", fields.helmholtz_h_magnitude(pts, a, d, current, turns)),
            "separation": ("m", [d]), "zone_length": ("m", [length]),
            "H_centre": ("A/m", [float(fields.helmholtz_center_h(current, turns, a, d))]),
        }))
    m = _measured()
    return FigureData(figure_id, "", "", {}, series, extra={
        "direction": direction, "tolerance": tolerance, "measured": m["sim-center-h"].value,
        "comsol_max": m["comsol-max-h"].value,
        "thesis_zone": m["comsol-uniform-axial" if direction == "axial" else "comsol-uniform-transverse"].value})


def compute_fig06(turns, current, coil_radius, design_spacing_ratio, comsol_spacing, built_spacing,
                  tolerance):
    """|H| along a line through the centre parallel to the coil planes, per geometry."""
    return _compute_line("thesis-fig06", "transverse", turns, current, coil_radius, design_spacing_ratio,
                         comsol_spacing, built_spacing, tolerance)


def compute_fig07(turns, current, coil_radius, design_spacing_ratio, comsol_spacing, built_spacing,
                  tolerance):
    """|H| along the coil axis, per geometry."""
    return _compute_line("thesis-fig07", "axial", turns, current, coil_radius, design_spacing_ratio,
                         comsol_spacing, built_spacing, tolerance)


def plot_line(data):
    """|H| against position, the uniform zone of each geometry, and the thesis's readings."""
    import matplotlib.pyplot as plt

    e = data.extra
    fig, ax = plt.subplots(figsize=(7.0, 3.8))
    for k, s in enumerate(data.series):
        c = {name: np.asarray(v) for name, (u, v) in s.columns.items()}
        ax.plot(c["position"] * 100, c["|H|"], color=f"C{k}", label=s.label)
        half = float(c["zone_length"][0]) / 2
        h0 = float(c["H_centre"][0])
        ax.plot([-half * 100, half * 100], [h0, h0], color=f"C{k}", linewidth=5, alpha=0.35)
        if e["direction"] == "axial":
            d = float(c["separation"][0])
            ax.axvline(-d / 2 * 100, color=f"C{k}", linestyle=":", linewidth=0.8)
            ax.axvline(d / 2 * 100, color=f"C{k}", linestyle=":", linewidth=0.8)
    ax.axhline(e["measured"], color="k", linestyle="--", linewidth=1, label="measured at the centre (262 A/m)")
    ax.axhline(e["comsol_max"], color="0.5", linestyle="-.", linewidth=1, label="COMSOL maximum (271 A/m)")
    z = e["thesis_zone"] * 100
    ax.annotate("", (-z / 2, e["comsol_max"] - 12), (z / 2, e["comsol_max"] - 12),
                arrowprops={"arrowstyle": "<->", "color": "0.5"})
    ax.text(0, e["comsol_max"] - 30, f"thesis's uniform zone ≈ {z:.0f} cm", ha="center", color="0.4",
            fontsize=8)
    where = "on the coil axis" if e["direction"] == "axial" else "on a line through the centre, parallel to the coils"
    ax.set_xlabel(f"position {where} [cm]")
    ax.set_ylabel("|H| [A/m]")
    ax.set_ylim(0, None)
    ax.legend(fontsize=7, loc="lower center")
    fig_no = 7 if e["direction"] == "axial" else 6
    ax.set_title(f"|H| {where} (thesis Fig. {fig_no}); thick bars: zones within "
                 f"{100 * e['tolerance']:.3g} %", fontsize=9)
    return fig


# --- chapter 2: the uniform-zone length against the tolerance band --------------------------

def compute_zone_criterion(coil_radius, design_spacing_ratio, comsol_spacing, built_spacing):
    """Zone lengths on the axis and across it against δ; the δ that matches each reading."""
    a = coil_radius
    tol = np.geomspace(1e-4, 0.1, 61)
    m = _measured()
    readings = {"transverse": m["comsol-uniform-transverse"].value, "axial": m["comsol-uniform-axial"].value}
    series, matches = [], {}
    for label, d in geometries(a, design_spacing_ratio, comsol_spacing, built_spacing):
        cols = {"tolerance": ("1", tol)}
        for direction, reading in readings.items():
            lengths = np.array([fields.uniform_zone_length(a, d, t, direction) for t in tol])
            cols[f"{direction}_length"] = ("m", lengths)
            matches[(label, direction)] = fields.zone_tolerance_for_length(a, d, reading, direction, tol)
            cols[f"{direction}_matching_tolerance"] = ("1", [matches[(label, direction)]])
        series.append(Series(label, cols))
    return FigureData("ch02-zone-criterion", "", "", {}, series, extra={"readings": readings})


def plot_zone_criterion(data):
    """Zone length against δ (log), both lines, with the thesis's readings."""
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(1, 2, figsize=(7.0, 3.6), sharey=True)
    for ax, direction in zip(axes, ("transverse", "axial")):
        reading = data.extra["readings"][direction]
        for k, s in enumerate(data.series):
            c = {n: np.asarray(v) for n, (u, v) in s.columns.items()}
            ax.semilogx(c["tolerance"] * 100, c[f"{direction}_length"] * 100, color=f"C{k}", label=s.label)
            t = float(c[f"{direction}_matching_tolerance"][0])
            if np.isfinite(t):
                ax.plot(t * 100, reading * 100, "o", color=f"C{k}")
        ax.axhline(reading * 100, color="k", linestyle="--", linewidth=1,
                   label=f"thesis reading ≈ {reading * 100:.0f} cm")
        ax.set_xlabel("tolerance band δ [%]")
        ax.set_title("line across the axis (Fig. 6)" if direction == "transverse" else "coil axis (Fig. 7)",
                     fontsize=8.5)
        ax.grid(True, which="both", linewidth=0.3)
    axes[0].set_ylabel("length of the uniform zone [cm]")
    axes[0].legend(fontsize=7)
    return fig


# --- thesis Fig. 8: the built simulator -----------------------------------------------------

def compute_fig08(coil_radius, built_spacing, tolerance, cube_side):
    """Coil rings of the as-built pair, the uniform sphere and the mock-up cube."""
    if not 0 < cube_side < coil_radius:
        raise ValueError(f"cube_side must lie in (0, coil_radius = {coil_radius}) m, got {shown(cube_side)}")
    a, d = coil_radius, built_spacing
    t = np.linspace(0, 2 * np.pi, 181)
    series = [Series(f"coil at x = {sx * d / 2 * 100:+.1f} cm", {
        "x": ("m", np.full_like(t, sx * d / 2)), "y": ("m", a * np.cos(t)), "z": ("m", a * np.sin(t))})
        for sx in (-1.0, 1.0)]
    r_u = fields.uniform_sphere_radius(a, d, tolerance)
    worst = fields.sphere_nonuniformity(a, d, np.sqrt(3) * cube_side / 2)
    series.append(Series("uniform sphere", {"radius": ("m", [r_u]),
                                            "cube_circumsphere_nonuniformity": ("1", [worst])}))
    return FigureData("thesis-fig08", "", "", {}, series,
                      extra={"tolerance": tolerance, "cube_side": cube_side, "radius": a, "separation": d})


def plot_fig08(data):
    """3-D view: both rings, the uniform sphere and the 1U mock-up."""
    import matplotlib.pyplot as plt

    e = data.extra
    fig = plt.figure(figsize=(7.0, 6.0))
    ax = fig.add_subplot(projection="3d")
    for s in data.series[:2]:
        c = {n: np.asarray(v) for n, (u, v) in s.columns.items()}
        ax.plot(c["x"], c["y"], c["z"], color="C1", linewidth=4)
    r_u = float(data.series[2].columns["radius"][1][0])
    u, v = np.meshgrid(np.linspace(0, 2 * np.pi, 40), np.linspace(0, np.pi, 20))
    ax.plot_surface(r_u * np.cos(u) * np.sin(v), r_u * np.sin(u) * np.sin(v), r_u * np.cos(v),
                    color="C0", alpha=0.25, linewidth=0)
    h = e["cube_side"] / 2
    for p in (-h, h):
        for q in (-h, h):
            ax.plot([-h, h], [p, p], [q, q], "k", linewidth=0.8)
            ax.plot([p, p], [-h, h], [q, q], "k", linewidth=0.8)
            ax.plot([p, p], [q, q], [-h, h], "k", linewidth=0.8)
    a = e["radius"]
    ax.quiver(-0.6 * a, 0, 0, 1.2 * a, 0, 0, color="C3", arrow_length_ratio=0.08)
    ax.text(0.65 * a, 0, 0.05, "H", color="C3")
    lim = 1.05 * a
    ax.set_xlim(-lim, lim)
    ax.set_ylim(-lim, lim)
    ax.set_zlim(-lim, lim)
    ax.set_box_aspect((1, 1, 1))
    ax.set_xlabel("x (coil axis) [m]")
    ax.set_ylabel("y [m]")
    ax.set_zlabel("z [m]")
    ax.set_title(f"The built simulator (thesis Fig. 8): a = {a * 100:.0f} cm, d = {e['separation'] * 100:.0f} cm;\n"
                 f"blue: |H| within {100 * e['tolerance']:.3g} % (radius {r_u * 100:.1f} cm); "
                 f"black: the {e['cube_side'] * 100:.0f} cm mock-up", fontsize=9)
    return fig


def _fig08_parameters():
    p = _defaults()
    return {
        "coil_radius": FigureParameter(p["sim_built_radius"], "m", "coil radius as built"),
        "built_spacing": FigureParameter(p["sim_built_spacing"], "m", "centre-to-centre spacing as built"),
        "tolerance": FigureParameter(0.01, "1", "band of the drawn uniform sphere"),
        "cube_side": FigureParameter(0.1, "m", "side of the mock-up (1U CubeSat, thesis §2.3)"),
    }


# --- thesis Fig. 3: candidate coil systems at equal power ----------------------------------

def coil_systems():
    """Kovalenko's and the thesis's candidate systems at unit size.

    Returns ``[(name, shapes, sizes, positions, relative ampere-turns)]``; circles have
    radius 1 (the largest), squares side 1.
    """
    half_sq = float(fields.square_pair_spacing(1.0)) / 2
    r1 = np.sqrt(4 / 7)
    return [
        ("Helmholtz pair, d = a", ["round"] * 2, [1.0, 1.0], [-0.5, 0.5], [1.0, 1.0]),
        ("thesis pair, d = 1.116a", ["round"] * 2, [1.0, 1.0], [-0.558, 0.558], [1.0, 1.0]),
        ("square pair, d = 0.5445 l", ["square"] * 2, [1.0, 1.0], [-half_sq, half_sq], [1.0, 1.0]),
        ("Maxwell, three circles", ["round"] * 3, [r1, 1.0, r1], [-np.sqrt(3 / 7), 0.0, np.sqrt(3 / 7)],
         [49.0, 64.0, 49.0]),
        ("three circles (Kovalenko)", ["round"] * 3, [1 / 1.0055, 1.0, 1 / 1.0055],
         [-0.7599 / 1.0055, 0.0, 0.7599 / 1.0055], [50.0, 27.0, 50.0]),
        ("four circles (Kovalenko)", ["round"] * 4, [1.0] * 4, [-1.0, -0.25, 0.25, 1.0], [7.0, 3.0, 3.0, 7.0]),
        ("Rubens, five squares", ["square"] * 5, [1.0] * 5, [-0.5, -0.25, 0.0, 0.25, 0.5],
         [19.0, 4.0, 10.0, 4.0, 19.0]),
    ]


def compute_fig03(tolerance, center_h, power, winding_area, copper_resistivity):
    """Each system scaled to the same centre field and the same total power.

    Every coil's winding has the same copper cross-section ``winding_area`` (one kind of
    former for all coils, as in the thesis); the size L at which each system makes the
    centre field at the power is :func:`magbench.hardware.coaxial_system_scale_for_power`,
    and its uniform sphere is s_δ L.
    """
    if not 0 < tolerance < 0.5:
        raise ValueError(f"tolerance must lie in (0, 0.5), got {shown(tolerance)}")
    for name, value in (("center_h", center_h), ("power", power), ("winding_area", winding_area),
                        ("copper_resistivity", copper_resistivity)):
        if value <= 0:
            raise ValueError(f"{name} must be > 0, got {shown(value)}")
    series = []
    for name, shapes, sizes, positions, weights in coil_systems():
        w = np.asarray(weights) / max(weights)
        s_unit = fields.coaxial_system_uniform_radius(shapes, sizes, positions, w, tolerance)
        scale, ampere_turns = hardware.coaxial_system_scale_for_power(shapes, sizes, positions, w, center_h, power,
                                                                      winding_area, copper_resistivity)
        series.append(Series(name, {
            "shape_is_square": ("1", [1.0 if s == "square" else 0.0 for s in shapes]),
            "size": ("m", np.asarray(sizes) * scale), "position": ("m", np.asarray(positions) * scale),
            "ampere_turns": ("A", ampere_turns),
            "scale": ("m", [scale]), "uniform_radius": ("m", [s_unit * scale]),
            "uniform_radius_per_size": ("1", [s_unit]),
            "half_length": ("m", [float(np.max(np.abs(positions))) * scale]),
        }))
    return FigureData("thesis-fig03", "", "", {}, series,
                      extra={"tolerance": tolerance, "power": power, "center_h": center_h})


def plot_fig03(data):
    """Meridian sections of every system at equal power, and their uniform radii."""
    import matplotlib.pyplot as plt

    n = len(data.series)
    columns = 4
    rows = -(-n // columns)
    fig = plt.figure(figsize=(7.0, 1.75 * rows + 2.6), layout="constrained")
    grid = fig.add_gridspec(rows + 1, columns, height_ratios=[1.0] * rows + [1.15])
    lim = max(float(np.max(np.asarray(s.columns["size"][1]))) for s in data.series) * 1.1
    for k, s in enumerate(data.series):
        ax = fig.add_subplot(grid[k // columns, k % columns])
        c = {key: np.asarray(v) for key, (u, v) in s.columns.items()}
        for sq, size, z in zip(c["shape_is_square"], c["size"], c["position"]):
            r = size / 2 if sq else size
            ax.plot([-r, r], [z, z], "-", color="0.75", linewidth=1)
            ax.plot([-r, r], [z, z], "s" if sq else "o", color="C1", markersize=4)
        ru = float(c["uniform_radius"][0])
        ax.add_patch(plt.Circle((0, 0), ru, color="C0", alpha=0.3))
        ax.set_xlim(-lim, lim)
        ax.set_ylim(-lim, lim)
        ax.set_aspect("equal")
        ax.set_title(s.label.replace(" (Kovalenko)", "\n(Kovalenko)").replace(", ", ",\n", 1)
                     if len(s.label) > 18 else s.label, fontsize=7.5)
        ax.tick_params(labelsize=7)
    bar = fig.add_subplot(grid[rows, :])
    names = [s.label for s in data.series]
    radii = [float(np.asarray(s.columns["uniform_radius"][1])[0]) * 100 for s in data.series]
    bar.barh(range(n), radii, color="C0")
    for k, radius in enumerate(radii):
        bar.text(radius, k, f" {radius:.1f}", va="center", fontsize=7)
    bar.set_yticks(range(n))
    bar.set_yticklabels(names, fontsize=7.5)
    bar.invert_yaxis()
    bar.set_xlim(0, max(radii) * 1.15)
    bar.set_xlabel("radius of the sphere where |H| stays within the tolerance [cm]", fontsize=8)
    e = data.extra
    fig.suptitle(f"Coil systems at equal power ({e['power']:.0f} W) and centre field "
                 f"({e['center_h']:.0f} A/m); blue: |H| within {100 * e['tolerance']:.3g} %;\n"
                 "axes in metres, coil axis vertical", fontsize=8.5)
    return fig


def _fig03_parameters():
    p = _defaults()
    a, area = p["sim_coil_radius"], p["sim_turns"] * np.pi * p["sim_wire_diameter"] ** 2 / 4
    power = hardware.helmholtz_pair_power(p["sim_design_h"], a, p["sim_spacing_ratio"] * a, area,
                                          p["copper_resistivity"])
    return {
        "tolerance": FigureParameter(0.01, "1", "uniformity band δ"),
        "center_h": FigureParameter(p["sim_design_h"], "A/m", "field at the centre"),
        "power": FigureParameter(power, "W", "total power (default: the thesis's design pair at 250 A/m)"),
        "winding_area": FigureParameter(area, "m^2", "copper cross-section of every coil's winding"),
        "copper_resistivity": FigureParameter(p["copper_resistivity"], "ohm m", "copper resistivity"),
    }


# --- chapter 2: what explains the measured centre field? -----------------------------------

def hypotheses(turns, current, coil_radius, built_spacing, wire_diameter, copper_resistivity,
               measured_center_h, resistance_range, earth_h, tolerance_h):
    """Each explanation of the measured centre field, with what it predicts or needs.

    Returns a list of dicts with keys ``id``, ``hypothesis``; ``predicted_h`` [A/m], the
    centre field the hypothesis predicts (NaN when its free parameter is solved for);
    ``needed`` and ``needed_unit``, the value of that free parameter that reproduces
    the measurement (NaN when there is none); ``constraint``, ``constraint_unit``,
    ``constraint_what`` (what the second number is, in words) and ``allowed`` (low, high),
    a second observable the hypothesis predicts and the range the thesis's measurements
    allow for it (NaN/None when there is none); and
    ``excluded``: True when the prediction misses the measurement by more than
    ``tolerance_h``, the constraint falls outside its allowed range, or no value of the
    free parameter reproduces the measurement (``needed`` NaN: a field above the largest
    any coil radius gives, a probe offset or tilt that would have to raise the reading).
    """
    a, d, n, i = coil_radius, built_spacing, turns, current
    h_model = float(fields.helmholtz_center_h(i, n, a, d))
    frac = measured_center_h / h_model
    r_lo, r_hi = resistance_range

    def resistance(radius, n_turns):
        return float(hardware.winding_resistance(radius, n_turns, wire_diameter, copper_resistivity))

    def row(id_, text, predicted=np.nan, needed=np.nan, unit="", constraint=np.nan, c_unit="", c_what="",
            allowed=None):
        excluded = bool(np.isfinite(predicted) and abs(predicted - measured_center_h) > tolerance_h)
        excluded |= bool(unit) and not np.isfinite(needed)     # solved for, and no value fits
        if allowed is not None and np.isfinite(constraint):
            excluded |= not allowed[0] <= constraint <= allowed[1]
        return {"id": id_, "hypothesis": text, "predicted_h": float(predicted), "needed": float(needed),
                "needed_unit": unit, "constraint": float(constraint), "constraint_unit": c_unit,
                "constraint_what": c_what, "allowed": allowed, "excluded": excluded}

    r_turn = resistance(a, 1.0)
    n_eff = n * frac
    # Above the peak field 4NI/(3√3 d) no radius gives the measurement; the probe's
    # offset and tilt are solved for a reading below the model's only (a tilt cannot
    # raise it): when the measurement is not below, those hypotheses are excluded.
    h_peak = float(fields.pair_peak_center_h(n * i, d))
    a_eff = fields.pair_radius_for_center_h(measured_center_h, n * i, d) if measured_center_h <= h_peak else np.nan
    reading_lower = 0.0 < frac < 1.0
    reversed_h = float(np.linalg.norm(fields.coaxial_system_b(
        np.zeros(3), ["round"] * 2, [a, a], [-d / 2, d / 2], [n * i, -n * i]))) / MU_0
    return [
        row("exact", "exact field of the pair as built", predicted=h_model),
        row("fewer-turns", "fewer effective turns per coil", needed=n_eff, unit="turns",
            constraint=resistance(a, n_eff), c_unit="ohm", c_what="resistance", allowed=(r_lo, r_hi)),
        row("resistance-turns", "the fewest turns the measured resistance allows",
            predicted=float(fields.helmholtz_center_h(i, r_lo / r_turn, a, d)), needed=r_lo / r_turn,
            unit="turns"),
        row("lower-current", "a lower current than the stated one", needed=i * frac, unit="A"),
        row("larger-radius", "larger coils", needed=a_eff, unit="m",
            constraint=resistance(a_eff, n) if np.isfinite(a_eff) else np.nan, c_unit="ohm", c_what="resistance",
            allowed=(r_lo, r_hi)),
        row("one-coil-off", "one coil unpowered", predicted=h_model / 2),
        row("one-coil-reversed", "one coil reversed", predicted=reversed_h),
        row("earth-field", "the Earth's field against the coils' (at most)", predicted=h_model - earth_h),
        row("probe-axial", "probe displaced along the axis",
            needed=fields.pair_distance_to_h(frac, a, d, "axial") if reading_lower else np.nan,
            unit="m", constraint=d / 2, c_unit="m", c_what="coil plane at"),
        row("probe-transverse", "probe displaced across the axis",
            needed=fields.pair_distance_to_h(frac, a, d, "transverse") if reading_lower else np.nan, unit="m",
            constraint=a, c_unit="m", c_what="coil radius"),
        row("probe-tilt", "single-axis probe tilted from the coil axis",
            needed=float(np.degrees(np.arccos(frac))) if reading_lower else np.nan, unit="deg"),
    ]


def hmc5883l_full_scale():
    """``[(range [G], gain [counts/G], full scale [A/m])]`` of each HMC5883L gain setting
    (:data:`magbench.hardware.HMC5883L_GAINS`)."""
    return [(rng, gain, float(hardware.magnetometer_full_scale(gain * 1e4)) / MU_0) for rng, gain in HMC5883L_GAINS]


def compute_hypotheses(turns, current, coil_radius, built_spacing, wire_diameter, copper_resistivity):
    """Centre field against turns and probe offset, and each hypothesis's prediction."""
    m = _measured()
    p = _defaults()
    measured = m["sim-center-h"].value
    r_lo, r_hi = resistance_range(m["sim-coil-resistance"])
    f = igrf.igrf_field(p["laboratory_latitude"], p["laboratory_longitude"], p["thesis_epoch"])
    earth_h = f.total / MU_0
    tolerance = ch02_field_simulator.simulator_center_h_tolerance(current, turns, coil_radius)
    rows = hypotheses(turns, current, coil_radius, built_spacing, wire_diameter, copper_resistivity,
                      measured, (r_lo, r_hi), earth_h, tolerance)
    a, d = coil_radius, built_spacing
    n_axis = np.linspace(40, 150, 111)
    s = np.linspace(0.0, 0.6, 241)
    axial = np.zeros((s.size, 3))
    axial[:, 2] = s
    across = np.zeros((s.size, 3))
    across[:, 0] = s
    r_turn = float(hardware.winding_resistance(a, 1.0, wire_diameter, copper_resistivity))
    series = [
        Series("centre field against turns", {
            "turns": ("1", n_axis), "H_centre": ("A/m", fields.helmholtz_center_h(current, n_axis, a, d))}),
        Series("|H| against probe offset", {
            "offset": ("m", s), "axial": ("A/m", fields.helmholtz_h_magnitude(axial, a, d, current, turns)),
            "transverse": ("A/m", fields.helmholtz_h_magnitude(across, a, d, current, turns))}),
        Series("hypotheses", {
            "predicted_h": ("A/m", [np.nan_to_num(r["predicted_h"], nan=-1.0) for r in rows])}),
    ]
    return FigureData("ch02-hypotheses", "", "", {}, series, extra={
        "rows": rows, "measured": measured, "tolerance": tolerance, "turns_band": (r_lo / r_turn, r_hi / r_turn),
        "separation": d, "radius": a, "turns": turns})


def resistance_range(row):
    """A measured range widened by its stated ± uncertainty (SI): (low, high).

    For the coil resistance, 12–13 Ω ± 1 Ω gives (11, 14) Ω.
    """
    low = row.value - 0.5 * (row.value_high - row.value_low) * (row.value / ((row.value_low + row.value_high) / 2))
    high = 2 * row.value - low
    unc = row.uncertainty if row.uncertainty is not None else 0.0
    scale = row.value / ((row.value_low + row.value_high) / 2)     # printed unit -> SI
    return low - unc * scale, high + unc * scale


def plot_hypotheses(data):
    """Three panels: turns (with the resistance band), probe offset, and the predictions."""
    import textwrap

    import matplotlib.pyplot as plt

    e = data.extra
    meas, tol = e["measured"], e["tolerance"]
    fig = plt.figure(figsize=(7.0, 7.0), layout="constrained")
    grid = fig.add_gridspec(2, 2, height_ratios=[1.0, 1.0])
    a1, a2, a3 = fig.add_subplot(grid[0, 0]), fig.add_subplot(grid[0, 1]), fig.add_subplot(grid[1, :])
    c = {k: np.asarray(v) for k, (u, v) in data.series[0].columns.items()}
    a1.plot(c["turns"], c["H_centre"], "C0", label="centre field")
    lo, hi = e["turns_band"]
    a1.axvspan(lo, hi, color="C2", alpha=0.2, label="turns the measured\nresistance allows")
    a1.axvline(e["turns"], color="0.4", linestyle=":", label=f"{e['turns']:.0f} turns (stated)")
    a1.axhline(meas, color="k", linestyle="--", label=f"measured {meas:.0f} A/m")
    a1.set_xlabel("effective turns per coil", fontsize=9)
    a1.set_ylabel("$H$ at the centre [A/m]", fontsize=9)
    a1.legend(fontsize=7.5, loc="upper left", framealpha=0.9)
    a1.set_ylim(top=1.35 * float(np.max(c["H_centre"])))
    c = {k: np.asarray(v) for k, (u, v) in data.series[1].columns.items()}
    a2.plot(c["offset"] * 100, c["axial"], label="along the axis")
    a2.plot(c["offset"] * 100, c["transverse"], label="across the axis")
    a2.axhline(meas, color="k", linestyle="--")
    a2.axvline(e["separation"] / 2 * 100, color="C0", linestyle=":", label="coil plane")
    a2.axvline(e["radius"] * 100, color="C1", linestyle=":", label="coil radius")
    a2.set_xlabel("probe offset from the centre [cm]", fontsize=9)
    a2.set_ylabel("$|H|$ [A/m]", fontsize=9)
    a2.legend(fontsize=7.5, loc="lower left", framealpha=0.9)
    rows = [r for r in e["rows"] if np.isfinite(r["predicted_h"])]
    values = [r["predicted_h"] for r in rows]
    colours = ["0.55" if r["id"] == "exact" else "C0" for r in rows]
    names = ["none: the exact field of the pair as built" if r["id"] == "exact" else r["hypothesis"]
             for r in rows]
    y = np.arange(len(rows))
    a3.barh(y, values, color=colours, height=0.6)
    a3.axvspan(meas - tol, meas + tol, color="k", alpha=0.12, lw=0)
    a3.axvline(meas, color="k", linestyle="--")
    top = 1.2 * max(max(values), meas)
    for yi, v, r in zip(y, values, rows):
        # A bar end marker, so that a zero-length bar stays visible.
        a3.plot([v], [yi], "D" if v < 0.01 * top else "|", color="k", markersize=7 if v < 0.01 * top else 14,
                clip_on=False, zorder=3)
        note = " (the coils cancel at the centre)" if r["id"] == "one-coil-reversed" else ""
        a3.text(v + 0.015 * top, yi, f" {v:.0f} A/m{note}", va="center", fontsize=8.5)
    a3.set_xlim(0, top)
    a3.set_yticks(y)
    a3.set_yticklabels([textwrap.fill(n, 26) for n in names], fontsize=8.5)
    a3.invert_yaxis()
    a3.set_xlabel(f"predicted centre field [A/m]; dashed, grey band: measured {meas:.0f} ± {tol:.0f} A/m",
                  fontsize=9)
    for ax in (a1, a2, a3):
        ax.tick_params(labelsize=8)
    fig.suptitle(f"No fixed hypothesis (bottom) reaches the measured {meas:.0f} A/m;\n"
                 "fewer turns would, but their resistance is too low (top left); a displaced probe could (top right)",
                 fontsize=9)
    return fig


def _hypotheses_parameters():
    p = _defaults()
    return {
        "turns": FigureParameter(p["sim_turns"], "1", "turns per coil (as stated)", whole=True),
        "current": FigureParameter(p["sim_current"], "A", "current in each coil (as stated)"),
        "coil_radius": FigureParameter(p["sim_built_radius"], "m", "coil radius as built"),
        "built_spacing": FigureParameter(p["sim_built_spacing"], "m", "centre-to-centre spacing as built"),
        "wire_diameter": FigureParameter(p["sim_wire_diameter"], "m", "bare copper diameter"),
        "copper_resistivity": FigureParameter(p["copper_resistivity"], "ohm m", "copper resistivity"),
    }


# --- chapter 2: a three-axis simulator ------------------------------------------------------

def compute_three_axis(radius_north, radius_east, radius_down, turns, target_h_north, target_h_east,
                       target_h_down, latitude, longitude, year, tolerance):
    """Currents of three Helmholtz pairs (axes north, east, down) for a target and for zero.

    The background is the IGRF field at the place and date. Each pair has d = a.
    """
    if not 0 < tolerance < 0.5:
        raise ValueError(f"tolerance must lie in (0, 0.5), got {shown(tolerance)}")
    radii = np.array([radius_north, radius_east, radius_down])
    f = igrf.igrf_field(latitude, longitude, year)
    background = np.array([f.north, f.east, f.down])
    cases = [("target", MU_0 * np.array([target_h_north, target_h_east, target_h_down])),
             ("cancel the Earth's field", np.zeros(3))]
    series = []
    for label, target in cases:
        i = fields.three_axis_pair_currents(target, background, radii, radii, turns)
        r_u = fields.three_axis_uniform_radius(i, radii, radii, turns, background, target, tolerance)
        series.append(Series(label, {
            "current": ("A", i), "target": ("T", target), "background": ("T", background),
            "centre_field": ("T", background + fields.three_axis_pair_b(np.zeros(3), i, radii, radii, turns)),
            "uniform_radius": ("m", [r_u]),
            "radii": ("m", radii)}))
    return FigureData("ch02-three-axis", "", "", {}, series, extra={"tolerance": tolerance})


def plot_three_axis(data):
    """3-D view of the three nested pairs, and the currents each case needs."""
    import matplotlib.pyplot as plt

    fig = plt.figure(figsize=(7.0, 3.9))
    ax = fig.add_subplot(1, 2, 1, projection="3d")
    c0 = {k: np.asarray(v) for k, (u, v) in data.series[0].columns.items()}
    t = np.linspace(0, 2 * np.pi, 121)
    axes = np.eye(3)
    for k, r in enumerate(c0["radii"]):
        n = axes[k]
        e1 = axes[(k + 1) % 3]
        e2 = axes[(k + 2) % 3]
        for sgn in (-1, 1):
            ring = sgn * r / 2 * n + r * (np.cos(t)[:, None] * e1 + np.sin(t)[:, None] * e2)
            ax.plot(ring[:, 0], ring[:, 1], -ring[:, 2], color=f"C{k}")
    ru = float(c0["uniform_radius"][0])
    u, v = np.meshgrid(np.linspace(0, 2 * np.pi, 30), np.linspace(0, np.pi, 15))
    ax.plot_surface(ru * np.cos(u) * np.sin(v), ru * np.sin(u) * np.sin(v), ru * np.cos(v), color="0.5",
                    alpha=0.3, linewidth=0)
    ax.set_xlabel("north [m]")
    ax.set_ylabel("east [m]")
    ax.set_zlabel("up [m]")
    ax.set_box_aspect((1, 1, 1))
    ax.set_title("three Helmholtz pairs (d = a);\ngrey: target within "
                 f"{100 * data.extra['tolerance']:.3g} %", fontsize=8)
    a2 = fig.add_subplot(1, 2, 2)
    width = 0.38
    for j, s in enumerate(data.series):
        c = {k: np.asarray(v) for k, (u, v) in s.columns.items()}
        a2.bar(np.arange(3) + (j - 0.5) * width, c["current"], width,
               label=f"{s.label}\n(uniform radius {float(c['uniform_radius'][0]) * 100:.1f} cm)")
    a2.set_xticks(range(3))
    a2.set_xticklabels(["north pair", "east pair", "down pair"])
    a2.set_ylabel("current per coil [A]")
    a2.yaxis.set_label_position("right")     # clear of the 3-D panel's axis labels
    a2.yaxis.tick_right()
    a2.axhline(0, color="0.5", linewidth=0.6)
    a2.legend(fontsize=7)
    return fig


def _three_axis_parameters():
    p = _defaults()
    return {
        "radius_north": FigureParameter(0.50, "m", "radius of the north pair"),
        "radius_east": FigureParameter(0.55, "m", "radius of the east pair (nested outside)"),
        "radius_down": FigureParameter(0.60, "m", "radius of the vertical pair (outermost)"),
        "turns": FigureParameter(p["sim_turns"], "1", "turns per coil", whole=True),
        "target_h_north": FigureParameter(p["sim_design_h"], "A/m", "wanted field, north"),
        "target_h_east": FigureParameter(0.0, "A/m", "wanted field, east"),
        "target_h_down": FigureParameter(0.0, "A/m", "wanted field, down"),
        "latitude": FigureParameter(p["laboratory_latitude"], "rad", "latitude of the laboratory"),
        "longitude": FigureParameter(p["laboratory_longitude"], "rad", "east longitude of the laboratory"),
        "year": FigureParameter(p["thesis_epoch"], "year", "date of the IGRF background"),
        "tolerance": FigureParameter(0.01, "1", "uniformity band δ = |B − B_target| / |B_target|"),
    }


register(FigureSpec("thesis-fig03", "Candidate coil systems at equal power (thesis Fig. 3)",
                    "Bui (2016) Fig. 3; Kovalenko (1975) §3.4", compute_fig03, plot_fig03, _fig03_parameters, slow=True))
register(FigureSpec("thesis-fig05", "Field lines of the coil pair (thesis Fig. 5)", "Bui (2016) Fig. 5",
                    compute_fig05, plot_fig05, _geometry_parameters))
register(FigureSpec("thesis-fig06", "|H| across the axis (thesis Fig. 6)", "Bui (2016) Fig. 6", compute_fig06, plot_line,
                    _geometry_parameters))
register(FigureSpec("thesis-fig07", "|H| on the coil axis (thesis Fig. 7)", "Bui (2016) Fig. 7",
                    compute_fig07, plot_line, _geometry_parameters))
register(FigureSpec("thesis-fig08", "The built simulator (thesis Fig. 8)", "Bui (2016) §2.4, Fig. 8",
                    compute_fig08, plot_fig08, _fig08_parameters))
register(FigureSpec("ch02-zone-criterion", "Uniform-zone length against the tolerance band",
                    "Bui (2016) §2.3", compute_zone_criterion, plot_zone_criterion,
                    lambda: {k: v for k, v in _geometry_parameters(tolerance=False).items()
                             if k in ("coil_radius", "design_spacing_ratio", "comsol_spacing", "built_spacing")}))
register(FigureSpec("ch02-hypotheses", "Explanations of the measured centre field", "Bui (2016) §2.4",
                    compute_hypotheses, plot_hypotheses, _hypotheses_parameters))
register(FigureSpec("ch02-three-axis", "A three-axis simulator for the laboratory",
                    "Not in the thesis (its ref. [1])", compute_three_axis, plot_three_axis,
                    _three_axis_parameters))
