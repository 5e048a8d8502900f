"""Figures of thesis chapter 1: the Earth's field and the principle of magnetic control."""

import numpy as np

from ...earth import igrf
from ... import dynamics
from ... import earth
from ...constants import EARTH_GM, EARTH_ROTATION_RATE
from ..._format import format_number
from . import CHAPTER
from .._base import chapter_parameters
from ..registry import FigureData, FigureParameter, FigureSpec, Series, register
from ..._validate import shown
from ...units import DEG

SOURCE = "Bui (2016), thesis §1.1–1.2"


def _defaults():
    return chapter_parameters(CHAPTER.key, overrides="")


def _dipole_parameters():
    p = _defaults()
    return {
        "earth_dipole_moment": FigureParameter(p["earth_dipole_moment"], "A m^2",
                                               "Earth dipole moment (thesis: 8.1e25 CGS)"),
        "geomagnetic_pole_latitude": FigureParameter(p["geomagnetic_pole_latitude"], "rad",
                                                     "latitude of the northern geomagnetic pole"),
        "geomagnetic_pole_longitude": FigureParameter(p["geomagnetic_pole_longitude"], "rad",
                                                      "east longitude of the northern geomagnetic pole"),
        "earth_radius": FigureParameter(p["earth_radius"], "m", "Earth radius"),
    }


# --- thesis Fig. 1: elements of the geomagnetic field ------------------------------------

def compute_fig01(earth_dipole_moment, geomagnetic_pole_latitude, geomagnetic_pole_longitude,
                  earth_radius, latitude, longitude, year):
    """Field elements X, Y, Z, H, T, D, J at one place: thesis dipole and IGRF-14."""
    b = earth.dipole_ned_b(latitude, longitude, earth_dipole_moment, geomagnetic_pole_latitude,
                           geomagnetic_pole_longitude, earth_radius)
    f = igrf.igrf_field(latitude, longitude, year)
    series = []
    for label, (x, y, z) in (("thesis dipole", b), (f"IGRF-14 {year:.0f}", (f.north, f.east, f.down))):
        h, total, declination, inclination = earth.field_elements(x, y, z)
        series.append(Series(label, {
            "X_north": ("uT", [x * 1e6]), "Y_east": ("uT", [y * 1e6]), "Z_down": ("uT", [z * 1e6]),
            "H": ("uT", [h * 1e6]), "T": ("uT", [total * 1e6]),
            "D": ("deg", [np.degrees(declination)]), "J": ("deg", [np.degrees(inclination)]),
        }))
    return FigureData("thesis-fig01", "Elements of the geomagnetic field", SOURCE, {}, series)


def plot_fig01(data):
    """Draw the field vector and its elements in the local north-east-down frame.

    The vertical axis points down, as the frame's z does, and the axes keep the true
    proportions of the vector, so the inclination is seen as it is.
    """
    import matplotlib.pyplot as plt

    def signed(value, fmt):
        return format(value, fmt).replace("-", "−")

    fig = plt.figure(figsize=(7.0, 4.4), layout="constrained")
    for k, s in enumerate(data.series):
        ax = fig.add_subplot(1, 2, k + 1, projection="3d")
        c = {name: vals[0] for name, (unit, vals) in s.columns.items()}
        x, y, z = c["X_north"], c["Y_east"], c["Z_down"]
        m = 1.35 * max(abs(x), abs(y), c["H"])
        bottom = 1.1 * max(z, 0.0) + 1e-9
        ax.quiver(0, 0, 0, x, y, z, color="C3", linewidth=2.5, arrow_length_ratio=0.08)
        ax.quiver(0, 0, 0, x, y, 0, color="C0", linewidth=2, arrow_length_ratio=0.15)
        for vec in ((x, 0, 0), (0, y, 0), (0, 0, z)):
            ax.quiver(0, 0, 0, *vec, color="0.35", linewidth=1.2, arrow_length_ratio=0.12)
        ax.plot([x, x], [y, y], [0, z], "k:", linewidth=0.8)
        labels = ((x, y, z, r"$B$", "C3"), (x, y, 0, r"$B_h$", "C0"), (x, 0, 0, r"$X$", "0.35"),
                  (0, y, 0, r"$Y$", "0.35"), (0, 0, z, r"$Z$", "0.35"))
        for px, py, pz, text, color in labels:
            ax.text(px, py, pz, " " + text, color=color, fontsize=10)
        ax.set_xlim(-m, m)
        ax.set_ylim(-m, m)
        ax.set_zlim(bottom, 0.0)                 # z down: larger Z lower on the page
        ax.set_box_aspect((2 * m, 2 * m, bottom), zoom=0.9)
        ax.view_init(elev=20, azim=-55)
        ax.set_xlabel(r"$X$ north [µT]", fontsize=7.5, labelpad=-2)
        ax.set_ylabel(r"$Y$ east [µT]", fontsize=7.5, labelpad=-2)
        ax.set_zlabel(r"$Z$ down [µT]", fontsize=7.5, labelpad=-2)
        ax.tick_params(labelsize=7, pad=0)
        for axis in (ax.xaxis, ax.yaxis):
            axis.set_major_locator(plt.MaxNLocator(3))
        ax.set_title(f"{s.label}: $T$ = {c['T']:.1f} µT, $H$ = {c['H']:.1f} µT\n"
                     f"$D$ = {signed(c['D'], '.1f')}°, $I$ = {signed(c['J'], '.1f')}°", fontsize=8)
    fig.suptitle("Elements of the Earth's field at the laboratory (thesis Fig. 1), true to scale;\n"
                 "red: total field $T$, blue: horizontal component $H$, grey: $X$, $Y$, $Z$", fontsize=8.5)
    return fig


def _fig01_parameters():
    p = _defaults()
    params = _dipole_parameters()
    params.update({
        "latitude": FigureParameter(p["laboratory_latitude"], "rad", "geographic latitude of the place"),
        "longitude": FigureParameter(p["laboratory_longitude"], "rad", "east longitude of the place"),
        "year": FigureParameter(p["thesis_epoch"], "year", "date of the IGRF field"),
    })
    return params


# --- thesis Fig. 2: geomagnetic coordinates and the tilted dipole -------------------------

def compute_fig02(earth_dipole_tilt, geomagnetic_latitude_deg_step):
    """Dipole field lines r = L cos²λ_m in the plane of the rotation and dipole axes.

    Coordinates are in Earth radii, with the rotation axis vertical and the geomagnetic
    axis tilted by ``earth_dipole_tilt``. Field lines are drawn for footpoint
    geomagnetic latitudes every ``geomagnetic_latitude_deg_step`` degrees.
    """
    step = float(geomagnetic_latitude_deg_step)
    if not 1.0 <= step <= 45.0:
        raise ValueError(f"geomagnetic_latitude_deg_step must lie in [1, 45] deg, got {shown(step)}")
    series = []
    lam = np.linspace(-np.pi / 2, np.pi / 2, 721)
    for foot in np.arange(step, 90.0, step):
        shell = float(earth.dipole_shell(np.radians(foot)))
        for side in (1.0, -1.0):
            x, z = earth.dipole_field_line(shell, lam, earth_dipole_tilt, side)
            series.append(Series(f"L = {shell:.3g} ({'east' if side > 0 else 'west'} side)",
                                 {"x": ("R_E", x), "z": ("R_E", z)}))
    return FigureData("thesis-fig02", "Geomagnetic coordinates: the tilted centred dipole", SOURCE,
                      {}, series, extra={"tilt": earth_dipole_tilt})


def plot_fig02(data):
    """Draw field lines, the Earth, both axes and both equators."""
    import matplotlib.pyplot as plt

    tilt = data.extra["tilt"]
    fig, ax = plt.subplots(figsize=(6.4, 6.0))
    for s in data.series:
        ax.plot(s.columns["x"][1], s.columns["z"][1], color="C0", linewidth=0.8)
    t = np.linspace(0, 2 * np.pi, 400)
    ax.fill(np.cos(t), np.sin(t), color="0.92", zorder=0)
    ax.plot(np.cos(t), np.sin(t), color="0.3", linewidth=1)
    ax.plot([0, 0], [-1.6, 1.6], "k--", linewidth=1, label="rotation axis")
    ax.plot([-1.6 * np.sin(tilt), 1.6 * np.sin(tilt)], [-1.6 * np.cos(tilt), 1.6 * np.cos(tilt)],
            color="C3", linewidth=1.5, label=f"geomagnetic axis (tilt {np.degrees(tilt):.1f}°)")
    ax.plot([-1, 1], [0, 0], "k:", linewidth=0.8, label="geographic equator")
    ax.plot([-np.cos(tilt), np.cos(tilt)], [np.sin(tilt), -np.sin(tilt)], color="C3", linestyle=":",
            linewidth=0.8, label="geomagnetic equator")
    ax.annotate("N (geographic)", (0, 1.0), (0.1, 1.15))
    ax.annotate("geomagnetic N pole", (np.sin(tilt), np.cos(tilt)), (0.35, 1.3), color="C3",
                arrowprops={"arrowstyle": "->", "color": "C3"})
    ax.set_aspect("equal")
    ax.set_xlim(-3.2, 3.2)
    ax.set_ylim(-3.2, 3.2)
    ax.set_xlabel("distance from the rotation axis [Earth radii]")
    ax.set_ylabel("along the rotation axis [Earth radii]")
    ax.legend(loc="lower left", fontsize=8)
    ax.set_title("Field lines of the tilted centred dipole (thesis Fig. 2)")
    return fig


def _fig02_parameters():
    p = _defaults()
    return {
        "earth_dipole_tilt": FigureParameter(p["earth_dipole_tilt"], "rad", "dipole tilt to the rotation axis"),
        "geomagnetic_latitude_deg_step": FigureParameter(10.0, "deg", "spacing of field-line footpoints"),
    }


# --- chapter 1: field elements against geomagnetic latitude ------------------------------

def compute_elements(earth_dipole_moment, earth_radius):
    """T, Z, H and J of the centred dipole against geomagnetic latitude (eqs. 1–3)."""
    phi = np.linspace(-np.pi / 2, np.pi / 2, 181)
    m, r = earth_dipole_moment, earth_radius
    cols = {
        "geomagnetic_latitude": ("deg", np.degrees(phi)),
        "T": ("uT", earth.dipole_total_b(phi, m, r) * 1e6),
        "Z": ("uT", earth.dipole_vertical_b(phi, m, r) * 1e6),
        "H": ("uT", earth.dipole_horizontal_b(phi, m, r) * 1e6),
        "J": ("deg", np.degrees(earth.dipole_inclination(phi))),
    }
    return FigureData("ch01-field-elements", "Dipole field elements against geomagnetic latitude",
                      "Bui (2016) eqs. (1)–(3); Kovalenko (1975) eqs. (2.1)–(2.3)", {},
                      [Series("centred dipole", cols)])


def plot_elements(data):
    """Two panels: the field components, and the inclination."""
    import matplotlib.pyplot as plt

    c = {k: v for k, (u, v) in data.series[0].columns.items()}
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(7.0, 4.2))
    for key, style, label in (("T", "-", "total $B$"), ("Z", "--", "vertical $Z$"), ("H", ":", "horizontal $B_h$")):
        a1.plot(c["geomagnetic_latitude"], c[key], style, label=label)
    a1.set_xlabel("geomagnetic latitude Φ [deg]")
    a1.set_ylabel("field [µT]")
    a1.axhline(0, color="0.7", linewidth=0.6)
    a1.legend()
    a2.plot(c["geomagnetic_latitude"], c["J"], label="tan I = 2 tan Φ (correct)")
    a2.plot(c["geomagnetic_latitude"], -c["J"], "C3--", label="tan I = −2 tan Φ (as printed)")
    a2.set_xlabel("geomagnetic latitude Φ [deg]")
    a2.set_ylabel("inclination I [deg]")
    a2.legend(fontsize=8)
    return fig


def _elements_parameters():
    p = _dipole_parameters()
    return {k: p[k] for k in ("earth_dipole_moment", "earth_radius")}


# --- chapter 1: the field along a circular orbit ------------------------------------------

def compute_orbit_field(earth_dipole_moment, earth_radius, orbit_altitude, orbit_inclination,
                        earth_dipole_tilt, orbits):
    """Field in orbital axes over ``orbits`` revolutions: direct and inclined dipole.

    The inclined dipole turns with the Earth: Kovalenko's λ − ωt falls at the Earth's
    rate while the argument of latitude grows at the orbital rate.
    """
    if not 0.1 <= orbits <= 50:
        raise ValueError(f"orbits must lie in [0.1, 50], got {shown(orbits)}")
    r = earth_radius + orbit_altitude
    if orbit_altitude <= 0:
        raise ValueError(f"orbit_altitude must be > 0 m, got {shown(orbit_altitude)}")
    n = np.sqrt(EARTH_GM / r**3)                  # orbital rate [rad/s]
    t = np.linspace(0.0, orbits * 2 * np.pi / n, int(400 * orbits) + 1)
    u = n * t
    series = []
    for label, tilt in (("direct dipole", 0.0), ("inclined dipole", earth_dipole_tilt)):
        b = earth.orbital_dipole_b(u, orbit_inclination, r, earth_dipole_moment, tilt=tilt,
                                    node_phase=-EARTH_ROTATION_RATE * t)
        series.append(Series(label, {
            "time": ("min", t / 60), "B_x": ("uT", b[:, 0] * 1e6), "B_y": ("uT", b[:, 1] * 1e6),
            "B_z": ("uT", b[:, 2] * 1e6), "|B|": ("uT", np.linalg.norm(b, axis=1) * 1e6)}))
    return FigureData("ch01-orbit-field", "The dipole field seen along a circular orbit",
                      "Kovalenko (1975) eqs. (2.36), (2.40)", {}, series)


def plot_orbit_field(data):
    """Components in orbital axes against time, one panel per field model."""
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(1, len(data.series), figsize=(7.0, 3.6), sharey=True, layout="constrained")
    for ax, s in zip(np.atleast_1d(axes), data.series):
        c = {k: v for k, (u, v) in s.columns.items()}
        for key, style, label in (("B_x", "-", "$B_x$"), ("B_y", "--", "$B_y$"), ("B_z", "-.", "$B_z$"),
                                  ("|B|", "k-", r"$|\mathbf{B}|$")):
            ax.plot(c["time"], c[key], style, label=label, linewidth=1.0)
        ax.set_title(s.label)
        ax.set_xlabel("time [min]")
        ax.axhline(0, color="0.8", linewidth=0.6)
    np.atleast_1d(axes)[0].set_ylabel(r"$\mathbf{B}$ in orbital axes [µT]")
    # Below the panels: inside, the legend covered the curves.
    fig.legend(*np.atleast_1d(axes)[0].get_legend_handles_labels(), loc="outside lower center", ncol=4,
               fontsize=7.5, frameon=False)
    return fig


def _orbit_parameters():
    p = _defaults()
    dp = _dipole_parameters()
    return {
        "earth_dipole_moment": dp["earth_dipole_moment"], "earth_radius": dp["earth_radius"],
        "orbit_altitude": FigureParameter(p["orbit_altitude"], "m", "circular orbit altitude"),
        "orbit_inclination": FigureParameter(p["orbit_inclination"], "rad", "orbit inclination"),
        "earth_dipole_tilt": FigureParameter(p["earth_dipole_tilt"], "rad", "dipole tilt"),
        "orbits": FigureParameter(2.0, "1", "number of revolutions shown", high=50.0),
    }


# --- chapter 1: reachable torques lie in the plane normal to B ----------------------------

def compute_torque_plane(field_elevation, samples):
    """Torques L = m × B of many random unit moments m, for a field of 1 T (eqs. 4, 8).

    Columns in the book's symbols (the thesis writes M = L × B): ``L_x``, ``L_y``,
    ``L_z`` and ``L_norm`` [N m], ``L_dot_b`` [N m] (the torque along B), ``m_perp``
    [A m²] (the moment's part normal to B).
    """
    count = int(samples)
    if not 10 <= count <= 100_000:
        raise ValueError(f"samples must lie in [10, 100000], got {shown(samples)}")
    rng = np.random.default_rng(20160601)      # fixed seed: the figure is reproducible
    moments = rng.normal(size=(count, 3))
    moments /= np.linalg.norm(moments, axis=1, keepdims=True)
    b = np.array([np.cos(field_elevation), 0.0, np.sin(field_elevation)])
    torques = dynamics.magnetic_torque(moments, b)
    along = torques @ b
    perp = np.linalg.norm(dynamics.perpendicular_moment(moments, b), axis=1)
    return FigureData("ch01-torque-plane", "Magnetic torques are confined to the plane normal to B",
                      "Bui (2016) eqs. (4)–(8)", {}, [Series("random unit moments", {
                          "L_x": ("N m", torques[:, 0]), "L_y": ("N m", torques[:, 1]),
                          "L_z": ("N m", torques[:, 2]), "L_dot_b": ("N m", along),
                          "m_perp": ("A m^2", perp), "L_norm": ("N m", np.linalg.norm(torques, axis=1))})],
                      extra={"b": b})


def plot_torque_plane(data):
    """3-D scatter of the torques with B, and |L| against |m_perp|, in the book's symbols."""
    import matplotlib.pyplot as plt

    c = {k: v for k, (u, v) in data.series[0].columns.items()}
    b = data.extra["b"]
    fig = plt.figure(figsize=(7.0, 3.6), layout="constrained")
    ax = fig.add_subplot(1, 2, 1, projection="3d")
    ax.scatter(c["L_x"], c["L_y"], c["L_z"], s=2, alpha=0.35, color="C0", label=r"torques $\mathbf{L}$")
    ax.quiver(0, 0, 0, *(1.2 * b), color="C3", linewidth=2.5, arrow_length_ratio=0.15)
    ax.text(*(1.2 * b + [0.0, 0.0, 0.2]), r"$\mathbf{B}$", color="C3", fontsize=11)
    ax.set_box_aspect((1, 1, 1))
    ax.view_init(elev=12, azim=-60)
    for lim, ticks in ((ax.set_xlim, ax.set_xticks), (ax.set_ylim, ax.set_yticks), (ax.set_zlim, ax.set_zticks)):
        lim(-1.4, 1.4)
        ticks([-1, 0, 1])
    for setter, name in ((ax.set_xlabel, "x"), (ax.set_ylabel, "y"), (ax.set_zlabel, "z")):
        setter(f"$L_{name}$ [N·m]", fontsize=8, labelpad=0)
    ax.tick_params(labelsize=7, pad=0)
    ax.set_title(r"$\mathbf{L} = \mathbf{m}\times\mathbf{B}$ for $|\mathbf{m}|$ = 1 A·m², $|\mathbf{B}|$ = 1 T:"
                 "\nevery torque lies in the plane normal to $\\mathbf{B}$", fontsize=8.5)
    a2 = fig.add_subplot(1, 2, 2)
    a2.plot(c["m_perp"], c["L_norm"], ".", markersize=2)
    a2.set_xlabel(r"$|\mathbf{m}_\perp|$, part of the moment normal to $\mathbf{B}$ [A·m²]", fontsize=8)
    a2.set_ylabel(r"$|\mathbf{L}|$ [N·m]", fontsize=8)
    a2.tick_params(labelsize=7.5)
    a2.set_aspect("equal")
    a2.set_title(r"$|\mathbf{L}| = |\mathbf{m}_\perp|\,|\mathbf{B}|$: only $\mathbf{m}_\perp$ acts", fontsize=8.5)
    return fig


register(FigureSpec("thesis-fig01", "Elements of the geomagnetic field (thesis Fig. 1)",
                    "Bui (2016), Fig. 1; IGRF-14", compute_fig01, plot_fig01, _fig01_parameters))
register(FigureSpec("thesis-fig02", "Geomagnetic coordinates (thesis Fig. 2)", "Bui (2016), Fig. 2",
                    compute_fig02, plot_fig02, _fig02_parameters))
register(FigureSpec("ch01-field-elements", "Dipole field elements against geomagnetic latitude",
                    "Bui (2016) eqs. (1)–(3)", compute_elements, plot_elements, _elements_parameters))
register(FigureSpec("ch01-orbit-field", "The dipole field along a circular orbit",
                    "Kovalenko (1975) eqs. (2.36), (2.40)", compute_orbit_field, plot_orbit_field,
                    _orbit_parameters))
register(FigureSpec("ch01-torque-plane", "Reachable magnetic torques", "Bui (2016) eqs. (4)–(8)",
                    compute_torque_plane, plot_torque_plane,
                    {"field_elevation": FigureParameter(0.6, "rad", "elevation of B above the x axis"),
                     "samples": FigureParameter(2000.0, "1", "number of random moments", high=1e5, whole=True)}))
