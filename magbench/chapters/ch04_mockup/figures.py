"""Figures of thesis chapter 4: the mock-up on a thread, its PID loop, the readings of the
printed gains and the small-angle allocation. The gain sweeps of thesis Figs. 15–18 and the
linear analysis of an SI design are in :mod:`.figures_pid`.

python-control (``control``) is imported inside the functions that use it: the block
diagram is drawn from its interconnection, and the gain readings' linear responses come
from it.
"""

import numpy as np

from ... import control
from ... import dynamics
from ... import sim
from ...constants import MU_0
from . import CHAPTER, PRINTED_SETS
from .._base import chapter_parameters
from ..registry import FigureData, FigureParameter, FigureSpec, Series, register
from ..._validate import shown
from ...units import DEG

SOURCE = "Bui (2016), thesis §4"
#: The gain sets of thesis Figs. 15–18 (thesis §4.1), as (kp, ki, kd).
STYLES = ("-", "--", ":")


def _defaults():
    return chapter_parameters(CHAPTER.key, overrides="")


def _plant_parameters():
    p = _defaults()
    return {
        "inertia": FigureParameter(p["mockup_inertia"], "kg m^2", "moment of inertia J about the vertical"),
        "field": FigureParameter(MU_0 * p["sim_design_h"], "T", "horizontal field B0 (μ0 · 250 A/m; never stated)"),
        "moment": FigureParameter(p["mtq_moment"], "A m^2", "coil-1 moment m1 / the coils' maximum moment"),
    }


# --- thesis Figs. 10–11: frames and forces of the mock-up on a thread --------------------

def compute_geometry(psi, theta, phi, cm_offset, mass, field, moment):
    """Frames, points and forces of the mock-up at one attitude (thesis Figs. 10–11,
    :func:`magbench.dynamics.mockup_loads`)."""
    loads = dynamics.mockup_loads(psi, theta, phi, cm_offset, mass, field, moment)
    r, weight = loads["body_axes"], loads["weight"]
    cols = {
        "A": ("m", np.zeros(3)), "C": ("m", loads["center_of_mass"]),
        "x_body": ("1", r[:, 0]), "y_body": ("1", r[:, 1]), "z_body": ("1", r[:, 2]),
        "gravity_F_t": ("N", weight), "reaction_N": ("N", -weight),
        "field_B0": ("T", loads["field"]), "dipole_m": ("A m^2", loads["dipole"]),
        "magnetic_torque": ("N m", loads["magnetic_torque"]), "gravity_torque_about_A": ("N m", loads["gravity_torque"]),
    }
    return FigureData("", "", "", {}, [Series("mock-up", cols)],
                      extra={"angles": (psi, theta, phi), "d": cm_offset})


def _arrow(ax, start, vec, color, label, scale=1.0, **kw):
    v = np.asarray(vec) * scale
    ax.quiver(*start, *v, color=color, arrow_length_ratio=0.12, **kw)
    ax.text(*(np.asarray(start) + 1.08 * v), label, color=color, fontsize=9)


def _frame_axes(ax, lim):
    ax.set_xlim(-lim, lim)
    ax.set_ylim(-lim, lim)
    ax.set_zlim(-1.6 * lim, 0.4 * lim)
    ax.set_xlabel("x [m]")
    ax.set_ylabel("y [m]")
    ax.set_zlabel("z [m]")


def plot_fig10(data):
    """Fixed axes Oxyz, body axes Ax'y'z' and the centre of mass C below A."""
    import matplotlib.pyplot as plt

    c = {k: v for k, (u, v) in data.series[0].columns.items()}
    d = data.extra["d"]
    fig = plt.figure(figsize=(6.4, 5.6))
    ax = fig.add_subplot(projection="3d")
    L = 1.2 * d
    origin = np.array([-0.8 * L, -0.8 * L, 0.25 * L])
    for k, name in enumerate("xyz"):
        _arrow(ax, origin, np.eye(3)[k], "0.4", name, scale=0.5 * L)
    ax.text(*origin, "O ", color="0.4", ha="right")
    for key, name, col in (("x_body", "x'", "C0"), ("y_body", "y'", "C2"), ("z_body", "z'", "C3")):
        _arrow(ax, c["A"], c[key], col, name, scale=0.8 * L)
    ax.plot(*np.stack([c["A"], c["A"] + [0, 0, 0.35 * L]]).T, "k-", linewidth=2)     # the thread
    ax.plot(*np.stack([c["A"], c["C"]]).T, "k--", linewidth=1)
    ax.scatter(*c["A"], color="k")
    ax.scatter(*c["C"], color="C1", s=40)
    ax.text(*c["A"], "  A", fontsize=8.5)
    ax.text(*c["C"], "  C (0, 0, −d)", fontsize=9, color="C1")
    _frame_axes(ax, L)
    psi, theta, phi = (np.degrees(v) for v in data.extra["angles"])
    ax.set_title(f"Frames (thesis Fig. 10): ψ = {psi:.0f}°, θ = {theta:.0f}°, φ = {phi:.0f}°, d = {d:.2g} m",
                 fontsize=8.5)
    return fig


def plot_fig11(data):
    """Gravity at C, the thread's reaction at A, the field and the magnetic torque."""
    import matplotlib.pyplot as plt

    c = {k: v for k, (u, v) in data.series[0].columns.items()}
    d = data.extra["d"]
    L = 1.2 * d
    fig = plt.figure(figsize=(6.4, 5.6))
    ax = fig.add_subplot(projection="3d")
    fscale = 0.8 * L / np.linalg.norm(c["gravity_F_t"])
    ax.plot(*np.stack([c["A"], c["C"]]).T, "k--", linewidth=1)
    ax.plot(*np.stack([c["A"], c["A"] + [0, 0, 0.35 * L]]).T, "k-", linewidth=2)
    _arrow(ax, c["C"], c["gravity_F_t"], "C3", f"F_t = {np.linalg.norm(c['gravity_F_t']):.2f} N", fscale)
    _arrow(ax, c["A"], c["reaction_N"], "C0", "N", fscale)
    _arrow(ax, c["A"] + [-L, -0.6 * L, -0.2 * L], c["field_B0"] / np.linalg.norm(c["field_B0"]), "C2",
           f"B0 = {np.linalg.norm(c['field_B0']) * 1e6:.0f} µT", L)
    _arrow(ax, c["C"], c["dipole_m"] / np.linalg.norm(c["dipole_m"]), "C4", "m (coil 1)", 0.7 * L)
    tq = c["magnetic_torque"]
    _arrow(ax, c["C"], tq / np.linalg.norm(tq), "C1", f"m × B0 = {np.linalg.norm(tq) * 1e6:.0f} µN·m", 0.7 * L)
    ax.scatter(*c["A"], color="k")
    ax.scatter(*c["C"], color="k")
    ax.text(*c["A"], "  A")
    ax.text(*c["C"], "  C")
    _frame_axes(ax, L)
    ax.set_title("Forces and torque on the mock-up (thesis Fig. 11)\nN does no work: A stays in its plane",
                 fontsize=8.5)
    return fig


def _geometry_parameters():
    p = _defaults()
    pp = _plant_parameters()
    return {
        "psi": FigureParameter(35 * DEG, "rad", "precession angle ψ (illustrative)"),
        "theta": FigureParameter(20 * DEG, "rad", "nutation angle θ (illustrative)"),
        "phi": FigureParameter(15 * DEG, "rad", "proper rotation φ (illustrative)"),
        "cm_offset": FigureParameter(p["mockup_cm_offset"], "m", "d, centre of mass below the suspension point"),
        "mass": FigureParameter(p["mockup_mass"], "kg", "mock-up mass M"),
        "field": pp["field"], "moment": pp["moment"],
    }


# --- thesis Figs. 12–13: the free magnetic pendulum ---------------------------------------

def compute_free_pendulum(inertia, field, moment, initial_angle, initial_angle_alt, duration):
    """Eq. (35) from rest at both printed initial angles (:func:`magbench.sim.simulate_free_swing`)."""
    if not 1.0 <= duration <= 3600.0:
        raise ValueError(f"duration must lie in [1, 3600] s, got {shown(duration)}")
    plant = dynamics.Mockup(inertia, field, moment)
    t = np.linspace(0.0, duration, 3001)
    series = []
    for label, psi0 in (("ψ0 = π/2 (as printed, thesis §4.1)", initial_angle),
                        ("ψ0 = π/4 (as printed, thesis §4.1)", initial_angle_alt)):
        run = sim.simulate_free_swing(plant, psi0, t)
        series.append(Series(label, {"t": ("s", t), "psi": ("rad", run.psi), "omega": ("rad/s", run.rate),
                                     "energy_drift": ("1", (run.energy - run.energy[0]) / (moment * field))}))
    return FigureData("", "", "", {}, series, extra={
        "periods": [float(dynamics.pendulum_period(a, inertia, moment, field)) for a in (initial_angle, initial_angle_alt)],
        "small_angle_period": float(dynamics.small_angle_period(inertia, moment, field))})


def _plot_free(data, key, ylabel, title):
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(7.0, 3.6))
    for s, style, period in zip(data.series, ("-", "--"), data.extra["periods"]):
        ax.plot(s.columns["t"][1], s.columns[key][1], style, label=f"{s.label}: T = {period:.1f} s")
    ax.axhline(0, color="0.8", linewidth=0.6)
    ax.set_xlabel("t [s]")
    ax.set_ylabel(ylabel)
    ax.set_title(f"{title}; small-angle eq. (14): T0 = {data.extra['small_angle_period']:.1f} s", fontsize=8.5)
    ax.legend(fontsize=8, loc="upper right")
    return fig


def plot_fig12(data):
    """ω(t) of the free pendulum (thesis Fig. 12, captioned "Fig. 3" in the thesis)."""
    return _plot_free(data, "omega", "ω [rad/s]", "Angular velocity (thesis Fig. 12)")


def plot_fig13(data):
    """ψ(t) of the free pendulum (thesis Fig. 13)."""
    return _plot_free(data, "psi", "ψ [rad]", "Rotation angle (thesis Fig. 13)")


def _free_parameters():
    p = _defaults()
    params = _plant_parameters()
    params.update({
        "initial_angle": FigureParameter(p["mockup_initial_angle"], "rad", "ψ0 of the parameter list"),
        "initial_angle_alt": FigureParameter(p["mockup_initial_angle_alt"], "rad", "ψ0 of the discussion"),
        "duration": FigureParameter(150.0, "s", "time span (not stated in the thesis)", high=1e4),
    })
    return params


# --- the exact period against eq. (14) ------------------------------------------------------

def compute_period_ratio(inertia, moment, field, period, amplitude_checks):
    """T/T0 against the amplitude, solve_ivp spot checks, and the field for a given period."""
    n_checks = int(amplitude_checks)
    if not 0 <= n_checks <= 20:
        raise ValueError(f"amplitude_checks must lie in [0, 20], got {shown(amplitude_checks)}")
    amp = np.linspace(0.0, 0.999 * np.pi, 500)
    t0 = float(dynamics.small_angle_period(inertia, moment, field))
    ratio = dynamics.pendulum_period(amp, inertia, moment, field) / t0
    plant = dynamics.Mockup(inertia, field, moment)
    check_amp = np.linspace(0.2, 0.97 * np.pi, n_checks)
    check_ratio = [sim.integrated_swing_period(plant, a) / t0 for a in check_amp]
    h_exact = dynamics.field_for_period(period, amp, inertia, moment) / MU_0
    # Eq. (15) as the thesis uses it is linear in its amplitude factor A (zero at A = 0).
    h_eq15 = dynamics.oscillation_field_h(inertia, moment, period) * amp
    a60 = dynamics.amplitude_for_period(period, inertia, moment, field) if period > t0 else 0.0
    return FigureData("", "", "", {}, [
        Series("exact / eq. (14)", {"amplitude": ("deg", np.degrees(amp)), "ratio": ("1", ratio)}),
        Series("solve_ivp", {"amplitude": ("deg", np.degrees(check_amp)), "ratio": ("1", np.array(check_ratio))}),
        Series("field for the period", {"amplitude": ("deg", np.degrees(amp)), "H_exact": ("A/m", h_exact),
                                         "H_eq15_as_used": ("A/m", h_eq15)}),
    ], extra={"t0": t0, "period": period, "h_design": field / MU_0, "a_design": a60})


def plot_period_ratio(data):
    """Left: T/T0 against amplitude. Right: the field that gives the period, exact and by eq. (15)."""
    import matplotlib.pyplot as plt

    fig, (a1, a2) = plt.subplots(1, 2, figsize=(7.0, 4.6))
    c, chk, h = ({k: v for k, (u, v) in s.columns.items()} for s in data.series)
    from matplotlib.ticker import FixedLocator, FuncFormatter, NullLocator

    a1.semilogy(c["amplitude"], c["ratio"], label=r"exact, $4\mathrm{K}(\sin^2(\psi_0/2))/\omega_\mathrm{p}$")
    a1.semilogy(chk["amplitude"], chk["ratio"], "o", mfc="none", label="direct integration")
    a1.axhline(1.0, color="0.5", linestyle=":", label="eq. (14)")
    a1.set_xlabel(r"amplitude $\psi_0$ [deg]")
    a1.set_ylabel(r"$T\,/\,T_0$")
    # Plain numbers on the log axis (its default labelled the minor ticks 2×10⁰, 3×10⁰, …).
    top = float(np.nanmax(np.asarray(c["ratio"], float)[np.isfinite(c["ratio"])]))
    ticks = [v for v in (1, 1.5, 2, 3, 5, 10, 20, 50, 100) if v <= 1.05 * top]
    a1.yaxis.set_major_locator(FixedLocator(ticks))
    a1.yaxis.set_minor_locator(NullLocator())
    a1.yaxis.set_major_formatter(FuncFormatter(lambda v, _: f"{v:g}"))
    a1.set_xlim(0, 180)
    a1.legend(fontsize=8)
    a1.set_title(r"Period against amplitude (diverges at $\psi_0$ = 180°)", fontsize=8.5)
    a2.semilogy(h["amplitude"], h["H_exact"], label=f"exact: T = {data.extra['period']:.0f} s")
    a2.semilogy(h["amplitude"], h["H_eq15_as_used"], "--", label=r"eq. (15) with $\psi_0$ (thesis)")
    a2.axhline(data.extra["h_design"], color="C3", linewidth=0.8, label=f"built design {data.extra['h_design']:.0f} A/m")
    if data.extra["a_design"] > 0:
        a2.axvline(np.degrees(data.extra["a_design"]), color="C3", linestyle=":", linewidth=0.8)
    a2.set_xlabel(r"amplitude $\psi_0$ [deg]")
    a2.set_ylabel("field strength H [A/m]")
    a2.set_xlim(0, 180)
    a2.set_ylim(1, 1e5)
    a2.legend(fontsize=8, loc="upper left")
    a2.set_title("Field needed for the design period", fontsize=8.5)
    return fig


def _period_parameters():
    p = _defaults()
    pp = _plant_parameters()
    return {"inertia": pp["inertia"], "moment": pp["moment"], "field": pp["field"],
            "period": FigureParameter(p["oscillation_period"], "s", "design period (thesis §2.1)"),
            "amplitude_checks": FigureParameter(8.0, "1", "number of solve_ivp spot checks", whole=True)}


# --- thesis Fig. 14: the loop, drawn from its python-control interconnection ---------------

def build_interconnection(inertia, field, kp, ki, kd, moment_limit):
    """The closed loop as a python-control interconnection of named blocks.

    The sensors and the complementary filter of thesis eq. (39) are a block of their
    own (``sensors``: ψ, ω → ψ̂, ω_g); in this continuous model they are ideal (ψ̂ = ψ,
    ω_g = ω), so the loop is the one :func:`magbench.sim.simulate_pid` integrates.
    """
    import control as ct

    loop = sim.PidLoop(inertia, field, kp, ki, kd, moment_limit=moment_limit)
    summing = ct.summing_junction(inputs=["psi_des", "-psi_hat"], output="e", name="sum")
    pid = ct.nlsys(lambda t, x, u, p: [u[0]], lambda t, x, u, p: [kp * u[0] + ki * x[0] - kd * u[1]],
                   inputs=["e", "omega_gyro"], outputs=["u"], states=["integral"],
                   name="pid")
    sat = ct.nlsys(None, lambda t, x, u, p: np.clip(u, -moment_limit, moment_limit), inputs=["u"],
                   outputs=["u_sat"], name="saturation")
    # m_z = −u; M = (0, 0, m_z) × (cos ψ, −sin ψ, 0) = (−u sin ψ, −u cos ψ, 0).
    alloc = ct.nlsys(None, lambda t, x, u, p: [-u[0] * np.sin(u[1]), -u[0] * np.cos(u[1])],
                     inputs=["u_sat", "psi"], outputs=["M_x", "M_y"], name="allocation")
    plant = ct.nlsys(lambda t, x, u, p: [x[1], float(dynamics.two_coil_torque(x[0], u[0], u[1], field)) / inertia],
                     lambda t, x, u, p: x, inputs=["M_x", "M_y"], outputs=["psi", "omega"],
                     states=["psi", "omega"], name="mockup")
    sensors = ct.nlsys(None, lambda t, x, u, p: [u[0], u[1]], inputs=["psi", "omega"],
                       outputs=["psi_hat", "omega_gyro"], name="sensors")
    system = ct.interconnect([summing, pid, sat, alloc, plant, sensors], inplist=["psi_des"],
                             outlist=["psi", "omega"], name="closed loop")
    return system, loop


#: What each block of the interconnection computes (the drawing's labels, mathtext).
BLOCK_LABELS = {
    "sum": r"$\Sigma$",
    "pid": "PID, eq. (37)\n" + r"$u = K_p e + K_i \int e\,\mathrm{d}t$" + "\n" + r"$-\,K_d\,\omega_g$",
    "saturation": "saturation\n" + r"$|u| \leq m_\max$",
    "allocation": "allocation\n" + r"$m_1 = -u\sin\psi$" + "\n" + r"$m_2 = -u\cos\psi$",
    "mockup": "mock-up, eq. (36)\n" + r"$J\dot\omega = -B_0\,(m_1\sin\psi$" + "\n" + r"$+\ m_2\cos\psi)$",
    "sensors": "gyro, magnetometer and filter, eq. (39)\n"
               + r"$\hat\psi_k = A_f(\hat\psi_{k-1} + \omega_g\Delta t) + (1 - A_f)\,\psi_m$",
}

#: Where each block sits in the drawing [in]: (left, bottom, width, height). The forward
#: path runs along the top row, the plant and the sensors back along the bottom row.
_BLOCK_BOXES = {
    "sum": (0.45, 2.75, 0.55, 0.7), "pid": (1.45, 2.55, 1.65, 1.1), "saturation": (3.5, 2.65, 1.1, 0.9),
    "allocation": (5.0, 2.55, 1.5, 1.1), "mockup": (4.55, 0.35, 1.95, 1.1), "sensors": (0.45, 0.35, 3.55, 1.1),
}

_SIGNALS = {"psi_des": r"$\psi_\mathrm{des}$", "e": "$e$", "u": "$u$", "u_sat": r"$u_\mathrm{sat}$",
            "M_x": "$m_1$", "M_y": "$m_2$", "psi": r"$\psi$", "omega": r"$\omega$",
            "psi_hat": r"$\hat\psi$", "omega_gyro": r"$\omega_g$"}


def compute_block_diagram(inertia, field, moment):
    """Blocks and signals of the interconnection (names, inputs, outputs, wiring)."""
    p = _defaults()
    system, _ = build_interconnection(inertia, field, p["pid_kp"], p["pid_ki"], p["pid_kd"], moment)
    blocks = [(s.name, list(s.input_labels), list(s.output_labels)) for s in system.syslist]
    producer = {out: k for k, (_, _, outs) in enumerate(blocks) for out in outs}
    edges = [(producer.get(sig, -1), k, sig) for k, (_, ins, _) in enumerate(blocks) for sig in ins]
    return FigureData("", "", "", {}, [Series("edges", {
        "from_block": ("1", np.array([e[0] for e in edges], float)),
        "to_block": ("1", np.array([e[1] for e in edges], float))})],
        extra={"blocks": blocks, "edges": edges})


def plot_block_diagram(data):
    """The loop's blocks on two rows (forward path on top, plant and sensors below) and
    every signal of the interconnection as an arrow; all text at 9 pt."""
    import matplotlib.pyplot as plt
    from matplotlib.patches import FancyBboxPatch

    blocks, edges = data.extra["blocks"], data.extra["edges"]
    names = [b[0] for b in blocks]
    fig = plt.figure(figsize=(7.0, 4.0))
    ax = fig.add_axes((0.0, 0.0, 1.0, 1.0))      # the drawing's own inch grid fills the figure
    ax.set_xlim(0, 7.0)
    ax.set_ylim(0, 4.0)
    ax.set_axis_off()
    box = {n: _BLOCK_BOXES[n] for n in names}
    for n in names:
        x0, y0, w, h = box[n]
        ax.add_patch(FancyBboxPatch((x0, y0), w, h, boxstyle="round,pad=0.03",
                                    fc="#fdf0d5" if n == "sensors" else "0.95", ec="k"))
        ax.text(x0 + w / 2, y0 + h / 2, BLOCK_LABELS.get(n, n), ha="center", va="center", fontsize=9,
                linespacing=1.5)
    arrow = {"arrowstyle": "->", "linewidth": 0.9, "shrinkA": 0, "shrinkB": 0}
    mid = lambda n: (box[n][0] + box[n][2] / 2, box[n][1] + box[n][3] / 2)   # noqa: E731

    def line(points, label, at, ha="left", va="bottom"):
        xs, ys = zip(*points)
        ax.plot(xs[:-1], ys[:-1], "k-", linewidth=0.9)
        ax.annotate("", points[-1], points[-2], arrowprops=arrow)
        ax.text(*at, label, fontsize=9, ha=ha, va=va)

    for src, dst, sig in edges:
        d = names[dst]
        label = _SIGNALS.get(sig, sig)
        if src < 0:                                   # the external input, the target
            y = mid(d)[1]
            line([(0.02, y), (box[d][0], y)], label, (0.05, y + 0.08))
            continue
        s = names[src]
        if box[s][1] > 2 and box[d][1] > 2:          # along the top row
            y = mid(d)[1]
            line([(box[s][0] + box[s][2], y), (box[d][0], y)], label, (box[s][0] + box[s][2] + 0.04, y + 0.06))
        elif s == "allocation" and d == "mockup":     # down into the plant, one arrow per coil
            x = mid(d)[0] + (0.35 if sig == "M_x" else 0.75)
            line([(x, box[s][1]), (x, box[d][1] + box[d][3])], label, (x + 0.05, 2.0))
        elif s == "mockup" and d == "allocation":     # ψ back up the right-hand side
            x = 6.8
            line([(box[s][0] + box[s][2], 0.75), (x, 0.75), (x, 3.1), (box[d][0] + box[d][2], 3.1)],
                 label, (x + 0.04, 2.0))
        elif s == "mockup" and d == "sensors":        # ψ, ω back along the bottom row
            y = mid(s)[1] + (0.2 if sig == "psi" else -0.2)
            line([(box[s][0], y), (box[d][0] + box[d][2], y)], label, (box[d][0] + box[d][2] + 0.08, y + 0.03))
        elif s == "sensors" and d == "sum":           # ψ̂ up to the comparison
            x = mid(d)[0]
            line([(x, box[s][1] + box[s][3]), (x, box[d][1])], label, (x + 0.06, 2.0))
        elif s == "sensors" and d == "pid":           # the gyro rate up to the derivative term
            x = mid(d)[0]
            line([(x, box[s][1] + box[s][3]), (x, box[d][1])], label, (x + 0.06, 2.0))
        else:                                          # any other wiring: a straight arrow
            ax.annotate("", mid(d), mid(s), arrowprops=arrow)
    ax.text(0.5 + 0.55 / 2 + 0.12, 2.75 - 0.05, "−", fontsize=11, ha="left", va="top")
    return fig


# --- which reading of the gain units gives damped curves? ----------------------------------

def reading_evidence(inertia, field, moment, initial_angle, duration=300.0):
    """One row per reading of the thesis's gain units: stability, damping and demand.

    For each reading (a factor s on the printed gains, :data:`magbench.control.GAIN_READINGS`)
    and each of the six printed gain sets: the linearised poles, the damping ratio and
    2 % settling time (4/|Re λ|) of the slowest mode, and the peak PID output of the
    unsaturated linear loop released at ``initial_angle`` [rad], as a fraction of the
    coils' maximum in the reading's own units (the thesis says the gains were chosen to
    stay below it, thesis §4.1) and in SI (what the coils can do).
    """
    import control as ct

    rows = []
    t = np.linspace(0.0, duration, 6001)
    for reading in control.GAIN_READINGS:
        s = control.gain_reading_scale(reading, field, moment)
        per_set = []
        for kp, ki, kd in PRINTED_SETS:
            kp_, ki_, kd_ = s * kp, s * ki, s * kd
            poles = control.closed_loop_poles(inertia, field, kp_, ki_, kd_)
            slow = poles[0]
            zeta = -slow.real / abs(slow)
            stable = bool(np.all(poles.real < 0))
            # Linear loop from rest at ψ0: states (ψ, ω, ∫e), output u = −Kp ψ + Ki ∫e − Kd ω.
            a, c = control.closed_loop_state_space(inertia, field, kp_, ki_, kd_)
            sys = ct.ss(a, np.zeros((3, 1)), c, [[0]])
            u = ct.initial_response(sys, t, [initial_angle, 0, 0]).outputs if stable else np.array([np.inf])
            peak = float(np.max(np.abs(u)))
            per_set.append((stable, zeta, 4 / abs(slow.real) if stable else np.inf, peak))
        stable = [p for p in per_set if p[0]]
        field_reading = {"field-in-gauss": 1e4 * field, "field-in-A/m": field / MU_0}.get(reading, field)
        rows.append({
            "reading": reading, "scale": s, "stable_sets": len(stable),
            "zeta_min": min((p[1] for p in stable), default=np.nan),
            "zeta_max": max((p[1] for p in stable), default=np.nan),
            "settling_max": max((p[2] for p in stable), default=np.nan),
            "demand_own_units": max((p[3] / s / moment for p in stable), default=np.nan),
            "demand_si": max((p[3] / moment for p in stable), default=np.nan),
            "free_period": float(dynamics.pendulum_period(initial_angle, inertia, moment, field_reading)),
            "critical_scale_max": max(float(control.critical_gain_scale(inertia, field, *g)) for g in PRINTED_SETS),
        })
    return rows


def compute_gain_readings(inertia, field, moment):
    """Largest real part of the closed-loop poles against a common factor on the gains."""
    scales = np.logspace(-1, 6.5, 400)
    series = []
    for kp, ki, kd in PRINTED_SETS:
        worst = [control.closed_loop_poles(inertia, field, s * kp, s * ki, s * kd)[0] for s in scales]
        worst = np.array(worst)
        series.append(Series(f"Kp = {kp:g}, Ki = {ki:g}, Kd = {kd:g}", {
            "scale": ("1", scales), "max_real": ("1/s", worst.real),
            "zeta": ("1", -worst.real / np.abs(worst))}))
    marks = {r: control.gain_reading_scale(r, field, moment) for r in control.GAIN_READINGS}
    return FigureData("", "", "", {}, series, extra={"marks": marks})


#: The readings of the gains' units in words (the figure's key; the chapter's table uses the same).
READING_WORDS = {
    "si": "SI, as printed", "per-degree": "error in degrees", "normalised": "output / coils' maximum",
    "per-degree-normalised": "both of these", "field-in-gauss": "field in gauss",
    "field-in-A/m": "field as H in A/m", "torque-output": "output a torque"}


def plot_gain_readings(data):
    """Two panels: max Re λ and the slowest mode's damping against the gain factor."""
    import matplotlib.pyplot as plt

    fig, (a1, a2) = plt.subplots(1, 2, figsize=(7.0, 4.2), sharex=True)
    for k, s in enumerate(data.series):
        c = {n: v for n, (u, v) in s.columns.items()}
        style = STYLES[k % 3]
        color = "C0" if k < 3 else "C1"
        a1.semilogx(c["scale"], c["max_real"], style, color=color,
                    label=s.label.replace("Kp", "$K_p$").replace("Ki", "$K_i$").replace("Kd", "$K_d$"))
        a2.semilogx(c["scale"], c["zeta"], style, color=color)
    # The readings sit close together on the log axis: number them, name them below.
    low, top = a1.get_ylim()
    marks = sorted(data.extra["marks"].items(), key=lambda item: item[1])
    for k, (name, scale) in enumerate(marks, 1):
        for ax in (a1, a2):
            ax.axvline(scale, color="0.6", linewidth=0.7)
        a1.text(scale, top - (0.04 + 0.07 * (k % 2)) * (top - low), str(k), fontsize=7, ha="center",
                va="center", bbox={"boxstyle": "circle,pad=0.15", "fc": "white", "ec": "0.6", "lw": 0.6})
    names = [f"{k} {READING_WORDS.get(name, name)}" for k, (name, _) in enumerate(marks, 1)]
    readings = ";  ".join(names[:4]) + ";\n" + ";  ".join(names[4:])
    a1.axhline(0, color="k", linewidth=0.7)
    a1.set_ylabel(r"largest Re $\lambda$ [1/s] (> 0: unstable)")
    a2.set_ylabel("damping ratio of the slowest mode")
    a2.axhline(0, color="k", linewidth=0.7)
    for ax in (a1, a2):
        ax.set_xlabel(r"factor $k$ on the printed gains ($K_\mathrm{SI} = k\,K$)")
    a1.legend(fontsize=7, loc="lower left")
    fig.suptitle("The printed gain sets under every reading of their units (vertical lines):\n" + readings,
                 fontsize=8)
    return fig


# --- the small-angle allocation ---------------------------------------------------------------

def compute_allocation_error():
    """Exact against the thesis's small-angle allocation, over the body angle ψ."""
    psi = np.linspace(0.0, np.pi, 721)
    world = np.array([1.0, 0.0, 0.0])
    loop = sim.PidLoop(1.0, 1.0, 0.0, 0.0, 0.0, allocation="small-angle")
    gain = sim.loop_torque(psi, 1.0, loop)                    # torque per unit command, B0 = 1
    b_small = control.body_field_small_angle(psi, world)
    b_exact = control.body_field_exact(psi, world)
    coils = control.dipole_allocation(np.array([0.0, 0.0, 1.0]), b_small)
    angle_err = np.arctan2(np.cross(b_exact, b_small)[:, 2], np.sum(b_exact * b_small, axis=1))
    zero = float(psi[np.argmax(gain < 0)]) if np.any(gain < 0) else np.nan
    return FigureData("", "", "", {}, [Series("small-angle / exact", {
        "psi": ("deg", np.degrees(psi)), "torque_ratio": ("1", gain),
        "coil_moment_ratio": ("1", np.linalg.norm(coils, axis=1)),
        "direction_error": ("deg", np.degrees(angle_err))})], extra={"sign_flip": zero})


def plot_allocation_error(data):
    """Torque gain, coil demand and field-direction error of the small-angle allocation."""
    import matplotlib.pyplot as plt

    c = {k: v for k, (u, v) in data.series[0].columns.items()}
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(7.0, 4.5))
    a1.plot(c["psi"], c["torque_ratio"], label="torque / commanded (ψ sinψ + cosψ)")
    a1.plot(c["psi"], c["coil_moment_ratio"], "--", label="|coil moments| / |m_z| (√(1+ψ²))")
    a1.axhline(1.0, color="0.5", linestyle=":")
    a1.axhline(0.0, color="k", linewidth=0.6)
    a1.set_ylabel("ratio to the exact allocation")
    a2.plot(c["psi"], c["direction_error"], color="C2")
    a2.set_ylabel("error of the field direction b [deg]")
    for ax in (a1, a2):
        for target, name in ((60, "π/3"), (120, "2π/3")):
            ax.axvline(target, color="C3", linewidth=0.7, linestyle=":")
            ax.text(target, ax.get_ylim()[1], f" ψ_des = {name}", fontsize=7, va="top", color="C3")
        ax.set_xlabel("body angle ψ from the field [deg]")
    a1.legend(fontsize=8, loc="lower left")
    fig.suptitle("The thesis's small-angle field rotation used for the allocation M = m × b", fontsize=8.5)
    return fig




_GEO = _geometry_parameters     # read on first use: listing figures reads no file
register(FigureSpec("thesis-fig10", "Frames of the mock-up on a thread (thesis Fig. 10)", "Bui (2016), Fig. 10",
                    compute_geometry, plot_fig10, _GEO))
register(FigureSpec("thesis-fig11", "Forces on the mock-up (thesis Fig. 11)", "Bui (2016), Fig. 11",
                    compute_geometry, plot_fig11, _GEO))
register(FigureSpec("thesis-fig12", "Angular velocity of the free mock-up (thesis Fig. 12)",
                    "Bui (2016), Fig. 12, eq. (35)", compute_free_pendulum, plot_fig12, _free_parameters))
register(FigureSpec("thesis-fig13", "Rotation angle of the free mock-up (thesis Fig. 13)",
                    "Bui (2016), Fig. 13, eq. (35)", compute_free_pendulum, plot_fig13, _free_parameters))
register(FigureSpec("ch04-period-ratio", "Exact pendulum period against eq. (14)", "Bui (2016) eqs. (14), (15), (35)",
                    compute_period_ratio, plot_period_ratio, _period_parameters, slow=True))
register(FigureSpec("thesis-fig14", "The PID loop (thesis Fig. 14)", "Bui (2016), Fig. 14, eqs. (36)–(38)",
                    compute_block_diagram, plot_block_diagram,
                    _plant_parameters))
register(FigureSpec("ch04-gain-readings", "The printed gains under every reading of their units",
                    "Bui (2016) eqs. (37)–(38), Figs. 15–18", compute_gain_readings, plot_gain_readings,
                    _plant_parameters))
register(FigureSpec("ch04-allocation-error", "Error of the small-angle allocation", "Bui (2016) §4.1, the allocation after eq. (38)",
                    compute_allocation_error, plot_allocation_error, {}))
