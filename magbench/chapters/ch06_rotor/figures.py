"""Figures of chapter 6: the spinning satellite with a rotor (rotor slides, Kovalenko ch. 7).

The ids are those of ``shared/reference/rotor_spin.md`` §14–§15. The two lost slides
('Stability and choice of control parameters', 'Simulation') are *reconstructions*: their titles and captions say so. Every
numeric default except the field and the inclination is ours (``data/rotor/params.toml``).
"""

import math

import numpy as np

from ...control.rotor_stability import rotor_floquet_multipliers, rotor_stability_map
from ...control.spin import (rotor_equilibrium_axial_momentum, rotor_equilibrium_dipole, rotor_program_field,
                             rotor_reference_torque, rotor_spin_reference)
from ...earth.dipole import dipole_equatorial_b
from ...io import load_printed
from ...result_cache import ChapterInputs, cached_result
from ...sim.rotor_variants import (maxima_per_orbit, pointing_error_orbit_maxima, reference_momentum_rate_offset,
                                   rotor_satellite_with_products, symmetric_rotor_orbit_maxima,
                                   tilted_dipole_pointing_error, transverse_asymmetry,
                                   transverse_inertia_with_asymmetry)
from ...sim.spin_correction import relay_spin_torque_over_turn
from ...sim.spinning import rotor_dimensionless, rotor_gain_scales, simulate_turning_field_gyrostat
from ...sim.turning_field import turning_field_kinetic_energy
from .._base import chapter_parameters
from ..registry import FigureData, FigureParameter, FigureSpec, Series, register
from . import CHAPTER, default_rotor_orbit, default_rotor_satellite, default_run, run_rotor
from ..._validate import shown
from ...units import DEG

SOURCE = "rotor slides (Ovchinnikov, Pen'kov, Roldugin, Tkachev)"
RPM = 2.0 * math.pi / 60.0


def _draw_slides_pointing_band(ax):
    """The slides' printed pointing accuracy (a range, data/rotor/printed.csv) as a band."""
    claim = load_printed("rotor")["rotor-pointing-accuracy"]
    ax.axhspan(claim.value_low, claim.value_high, color="C1", alpha=0.25,
               label=f"slides: {claim.value_low:g}–{claim.value_high:g}°")

def _defaults():
    return chapter_parameters(CHAPTER.key, overrides="")


def _numbers():
    p = _defaults()
    return rotor_dimensionless(default_rotor_satellite(p), default_rotor_orbit(p))


def _si_factors():
    """k per κ [A·m²/T] and k_w per κ_w [N·m·s] of the chapter's spacecraft."""
    p = chapter_parameters(CHAPTER.key)
    return rotor_gain_scales(default_rotor_satellite(p), default_rotor_orbit(p))


# --- the lost slide "Stability and choice of control parameters" (reconstruction) ------------

def _map_parameters():
    n = _numbers()
    return {
        "axial_ratio": FigureParameter(n["axial_ratio"], "1", "a = J_s/J_t (ours)"),
        "momentum": FigureParameter(n["momentum"], "1", "c1 = K_0/(ω0 J_t) (ours)"),
        "inclination": FigureParameter(n["inclination"], "rad", "orbit inclination i (51.6°, the ISS orbit)"),
        "restoring": FigureParameter(n["restoring"], "1", "chosen restoring gain κ (ours)"),
        "damping": FigureParameter(n["damping"], "1", "chosen damping gain κ_w (ours)"),
        "restoring_max": FigureParameter(10.0, "1", "largest κ of the grid (from κ_max/40)"),
        "damping_max": FigureParameter(5.0, "1", "largest κ_w of the grid (from κ_w,max/40)"),
        "grid_points": FigureParameter(40.0, "1", "grid points per axis", high=200.0, whole=True),
        "steps": FigureParameter(1000.0, "1", "RK4 steps per orbit of the monodromy", high=1e5, whole=True),
    }


def compute_stability_map(axial_ratio, momentum, inclination, restoring, damping, restoring_max, damping_max,
                          grid_points, steps):
    """max|ρ| over (κ, κ_w) (the lost stability slide)."""
    n = int(grid_points)
    if n < 2:
        raise ValueError(f"grid_points must be >= 2, got {shown(grid_points)}")
    kappa = np.linspace(restoring_max / n, restoring_max, n)
    kappa_w = np.linspace(damping_max / n, damping_max, n)
    rho = rotor_stability_map(kappa, kappa_w, axial_ratio=axial_ratio, momentum=momentum, inclination=inclination,
                              steps=int(steps))
    chosen = rotor_floquet_multipliers(axial_ratio, momentum, restoring, damping, inclination, steps=int(steps))
    k_per, kw_per = _si_factors()
    return FigureData("", "", "", {}, [
        Series("grid", {"restoring": ("1", kappa), "damping": ("1", kappa_w)}),
        Series("max |rho|", {"max_abs_multiplier": ("1", rho)}),
        Series("chosen gains", {"restoring": ("1", [restoring]), "damping": ("1", [damping]),
                                "max_abs_multiplier": ("1", [abs(chosen[0])])}),
    ], extra={"stable_fraction": float(np.mean(rho < 1.0)), "k_per_kappa": k_per, "kw_per_kappa_w": kw_per})


def plot_stability_map(data):
    """log10 max|ρ| with the |ρ| = 1 contour, the chosen gains and SI gains on the top/right axes."""
    import matplotlib.pyplot as plt
    from matplotlib.colors import TwoSlopeNorm

    g, r, c = (s.columns for s in data.series)
    kappa, kappa_w = g["restoring"][1], g["damping"][1]
    logr = np.log10(r["max_abs_multiplier"][1])
    fig, ax = plt.subplots(figsize=(6.4, 4.6))
    lo, hi = min(float(logr.min()), -0.1), max(float(logr.max()), 0.1)
    mesh = ax.pcolormesh(kappa, kappa_w, logr, cmap="RdBu_r", norm=TwoSlopeNorm(0.0, lo, hi), shading="nearest")
    ax.contour(kappa, kappa_w, logr, levels=[0.0], colors="k", linewidths=1.2)
    ax.plot(c["restoring"][1], c["damping"][1], "k*", markersize=11,
            label=f"chosen $\\kappa$ = {c['restoring'][1][0]:g}, $\\kappa_w$ = {c['damping'][1][0]:g}: "
                  f"max|ρ| = {c['max_abs_multiplier'][1][0]:.3f}")
    fig.colorbar(mesh, ax=ax, label=r"$\log_{10}\max|\rho|$ (< 0: stable)")
    ax.set_xlabel(r"restoring gain $\kappa = kB_0^2/(\omega_0^2 J_t)$ [1]")
    ax.set_ylabel(r"damping gain $\kappa_w = k_w/(\omega_0 J_t)$ [1]")
    kp, kwp = data.extra["k_per_kappa"], data.extra["kw_per_kappa_w"]
    top = ax.secondary_xaxis("top", functions=(lambda x: x * kp, lambda x: x / kp))
    top.set_xlabel(r"$k$ [A·m²/T]")
    right = ax.secondary_yaxis("right", functions=(lambda y: y * kwp * 1e3, lambda y: y / (kwp * 1e3)))
    right.set_ylabel(r"$k_w$ [mN·m·s]")
    ax.legend(loc="upper left")
    ax.set_title("Reconstruction of the lost stability slide: Floquet map\n"
                 "blue: stable (black line: |ρ| = 1)")
    return fig


# --- max|ρ| against κ_w for a few κ ------------------------------------------------------------

def _slice_parameters():
    m = _map_parameters()
    return {name: m[name] for name in ("axial_ratio", "momentum", "inclination", "damping_max", "steps")} | {
        "damping_max": FigureParameter(8.0, "1", "largest κ_w of the slice")}


SLICE_RESTORING = (1.0, 4.0, 6.0, 10.0)


def compute_floquet_slice(axial_ratio, momentum, inclination, damping_max, steps):
    """max|ρ| against κ_w for κ = 1, 4, 6, 10 (rotor_spin.md §7: too much damping is unstable)."""
    kappa_w = np.linspace(damping_max / 160, damping_max, 160)
    rho = rotor_stability_map(np.array(SLICE_RESTORING), kappa_w, axial_ratio=axial_ratio, momentum=momentum,
                              inclination=inclination, steps=int(steps))
    return FigureData("", "", "", {}, [Series(f"$\\kappa$ = {k:g}", {"damping": ("1", kappa_w),
                                                             "max_abs_multiplier": ("1", rho[:, j])})
                                       for j, k in enumerate(SLICE_RESTORING)])


def plot_floquet_slice(data):
    """One line per κ, log scale, with the stability limit |ρ| = 1."""
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(6.4, 3.6))
    for s in data.series:
        ax.semilogy(s.columns["damping"][1], s.columns["max_abs_multiplier"][1], label=s.label)
    ax.axhline(1.0, color="k", linewidth=0.8, linestyle="--", label="|ρ| = 1")
    ax.set_xlabel(r"damping gain $\kappa_w$ [1]")
    ax.set_ylabel("max|ρ| per orbit [1]")
    ax.legend(ncols=2)
    ax.set_title("Both too little and too much projected damping are unstable")
    return fig


# --- the lost slide "Simulation (asymmetric spacecraft)" (reconstruction) ------------------------

def _simulation_parameters():
    p = _defaults()
    return {
        "initial_alpha": FigureParameter(p["initial_alpha"], "rad", "α0, initial error about the orbit normal (ours)"),
        "initial_beta": FigureParameter(p["initial_beta"], "rad", "β0, initial error (ours)"),
        "orbits": FigureParameter(p["simulation_orbits"], "1", "orbits simulated", high=50.0),
    }


def compute_simulation(initial_alpha, initial_beta, orbits):
    """The asymmetric spacecraft from an initial pointing error (the lost simulation slide)."""
    p = chapter_parameters(CHAPTER.key)
    p.update(initial_alpha=initial_alpha, initial_beta=initial_beta, simulation_orbits=float(int(orbits)))
    run = default_run(p)
    w0 = default_rotor_orbit(p).mean_motion
    mean = float(np.mean(run.spin_rate))
    t = run.time * w0 / (2.0 * math.pi)
    return FigureData("", "", "", {}, [Series("run", {
        "time": ("orbit", t),
        "pointing_error": ("deg", np.degrees(run.pointing_error)),
        "spin_rate": ("rpm", run.spin_rate / RPM),
        "spin_deviation": ("omega0", (run.spin_rate - mean) / w0),
        "spin_reference_deviation": ("omega0", (run.spin_reference - mean) / w0),
        "dipole_magnitude": ("A m^2", np.linalg.norm(run.dipole, axis=1)),
    }), Series("orbit maxima", {"pointing_error": ("deg", np.degrees(pointing_error_orbit_maxima(run, w0)))})],
        extra={"mean_spin_rpm": mean / RPM})


def plot_simulation(data):
    """Pointing error with the slides' 10–15° band, spin deviation in ω0, and |m|."""
    import matplotlib.pyplot as plt

    c = data.series[0].columns
    t = c["time"][1]
    fig, axes = plt.subplots(3, 1, figsize=(6.4, 6.0), sharex=True)
    ax = axes[0]
    _draw_slides_pointing_band(ax)
    ax.plot(t, c["pointing_error"][1], "C0", linewidth=0.8, label="angle rotor axis – velocity")
    ax.set_ylabel("pointing error [deg]")
    ax.legend(loc="upper right")
    ax = axes[1]
    ax.plot(t, c["spin_deviation"][1], "C0", linewidth=0.6, label="spin − mean")
    ax.plot(t, c["spin_reference_deviation"][1], "C3--", linewidth=1.0,
            label=r"reference $s_\mathrm{ref}(u)$ − mean")
    ax.set_ylabel(r"spin deviation [$\omega_0$]")
    ax.legend(loc="upper right", ncols=2)
    sense = "−" if data.extra["mean_spin_rpm"] < 0 else "+"
    ax.set_title(f"mean spin {abs(data.extra['mean_spin_rpm']):.1f} rpm, about {sense}$x$ (the velocity axis)")
    ax = axes[2]
    ax.plot(t, c["dipole_magnitude"][1], "C2", linewidth=0.6)
    ax.set_ylabel("|m| [A·m²]")
    ax.set_xlabel("time [orbits]")
    fig.suptitle("Reconstruction of the lost simulation slide: the asymmetric spacecraft (parameters ours)")
    return fig


# --- the equilibrium law over one orbit ------------------------------------------------------------

def _law_parameters():
    p = _defaults()
    sat, orbit = default_rotor_satellite(p), default_rotor_orbit(p)
    return {
        "inclination": FigureParameter(orbit.inclination, "rad", "orbit inclination i"),
        "equatorial_b": FigureParameter(float(dipole_equatorial_b(orbit.earth_moment, orbit.radius)), "T",
                                        "B0 at the orbit radius"),
        "orbital_rate": FigureParameter(orbit.mean_motion, "rad/s", "ω0"),
        "gain": FigureParameter(sat.restoring_gain, "A m^2/T", "restoring gain k (ours, κ = 4)"),
        "axial_momentum": FigureParameter(sat.axial_momentum, "N m s", "K_0, axial angular momentum of body and rotor at u = 0 (ours, c1 = 1)"),
        "axial_inertia": FigureParameter(float(sat.inertia_matrix[0, 0]), "kg m^2", "J_s, about the spin axis (ours)"),
        "rotor_momentum": FigureParameter(sat.rotor_inertia * sat.rotor_rate, "N m s", "J_f ν (ours)"),
    }


def compute_equilibrium_law(inclination, equatorial_b, orbital_rate, gain, axial_momentum, axial_inertia,
                            rotor_momentum):
    """The slides' dipole (slide 'Choice of control') for k and 2k, its torque on the reference, H and s_ref."""
    u = np.linspace(0.0, 2.0 * math.pi, 361)
    field = rotor_program_field(u, inclination, equatorial_b)
    series = []
    for factor in (1.0, 2.0):
        m = rotor_equilibrium_dipole(u, inclination, equatorial_b, factor * gain, axial_momentum, orbital_rate)
        torque = np.cross(m, field)
        series.append(Series(f"$k$ × {factor:g}", {"u": ("deg", np.degrees(u)), "dipole": ("A m^2", m),
                                                 "torque": ("N m", torque)}))
    h = rotor_equilibrium_axial_momentum(u, axial_momentum)
    s = rotor_spin_reference(u, axial_momentum, rotor_momentum, axial_inertia)
    series.append(Series("reference", {"u": ("deg", np.degrees(u)), "axial_momentum_ratio": ("1", h / axial_momentum),
                                       "spin_reference_deviation": ("omega0", (s - s.mean()) / orbital_rate)}))
    diff = float(np.max(np.abs(series[1].columns["torque"][1] - series[0].columns["torque"][1])))
    need = rotor_reference_torque(u, axial_momentum, orbital_rate)
    residual = float(np.max(np.abs(series[0].columns["torque"][1] - need)))
    return FigureData("", "", "", {}, series, extra={"torque_gain_difference": diff, "torque_residual": residual,
                                                     "torque_scale": axial_momentum * orbital_rate})


def plot_equilibrium_law(data):
    """Dipole components (two gains), the torque (the same for both) and H/H0, s_ref."""
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(3, 1, figsize=(6.4, 6.2), sharex=True)
    for s, style in zip(data.series[:2], ("-", "--")):
        u, m, tq = s.columns["u"][1], s.columns["dipole"][1], s.columns["torque"][1]
        for j in range(3):
            axes[0].plot(u, m[:, j], f"C{j}{style}", label=f"$m_{j + 1}$, {s.label}")
            axes[1].plot(u, tq[:, j] * 1e9, f"C{j}{style}", label=f"$L_{j + 1}$, {s.label}")
    axes[0].set_ylabel("dipole [A·m²]")
    axes[0].legend(ncols=3)
    axes[1].set_ylabel("torque [nN·m]")
    axes[1].legend(ncols=3)
    axes[1].set_title(f"the torque does not depend on $k$ (largest difference "
                      f"{data.extra['torque_gain_difference']:.1e} N·m)")
    r = data.series[2].columns
    axes[2].plot(r["u"][1], r["axial_momentum_ratio"][1], "C0", label=r"$K_1/K_0 = \cos^2 u$")
    axes[2].plot(r["u"][1], r["spin_reference_deviation"][1], "C3--", label=r"$s_\mathrm{ref}$ − mean [$\omega_0$]")
    axes[2].legend()
    axes[2].set_xlabel("argument of latitude u [deg]")
    axes[2].set_xticks(np.arange(0, 361, 60))
    fig.suptitle("The slides' equilibrium law over one orbit, semi-body axes on the reference")
    return fig


# --- the damping sign (erratum) -------------------------------------------------------------------

def _damping_parameters():
    p = _defaults()
    sat, orbit = default_rotor_satellite(p), default_rotor_orbit(p)
    return {
        "damping_gain": FigureParameter(sat.damping_gain, "N m s", "k_w (ours, κ_w = 2)"),
        "rotor_momentum": FigureParameter(sat.rotor_inertia * sat.rotor_rate, "N m s", "J_f ν (ours)"),
        "initial_rate": FigureParameter(0.2, "rad/s", "each body-axis rate at the start (illustrative)"),
        "field_rate": FigureParameter(orbit.mean_motion, "rad/s", "turn rate of the field in inertial space (ω0)"),
        "equatorial_b": FigureParameter(float(dipole_equatorial_b(orbit.earth_moment, orbit.radius)), "T",
                                        "field magnitude B0"),
        # The wrong-sign damping run diverges and the solver's steps shrink with it: 3000 s take
        # 11 s, 5000 s over 5 min (measured), so this figure's bound is below the usual 1e4 s.
        "duration": FigureParameter(1500.0, "s", "simulated time", high=3000.0),
    }


def _energy_run(law, gain, rotor_momentum, initial_rate, field_rate, b0, duration):
    """½ωᵀIω of the chapter's gyrostat (default inertia) in a field turning about an inertial axis.

    The run is :func:`magbench.sim.spinning.simulate_turning_field_gyrostat`; the torques are
    those of :func:`magbench.control.spin.projected_damping_dipole` (corrected) and
    :func:`magbench.control.spin.slides_printed_damping_torque` (printed): −k_w w⊥ and
    +k_w w⊥ with w = ω (the tests hold the kernel's torque to both).
    """
    inertia = default_rotor_satellite(_defaults()).inertia_matrix
    # the printed projection, read as a torque, is the damping torque with the sign reversed
    k = float(gain) * (1.0 if law == "corrected" else -1.0)
    run = simulate_turning_field_gyrostat(inertia, rotor_momentum, k, field_rate, [initial_rate] * 3,
                                          [b0, 0.0, 0.0], [0.0, 1.0, 0.0], duration)
    return run.time, turning_field_kinetic_energy(run)


def compute_damping_sign(damping_gain, rotor_momentum, initial_rate, field_rate, equatorial_b, duration):
    """½ωᵀIω of the gyrostat under the corrected projection and under the printed one (slide 'Control implementation')."""
    series = []
    for law, label in (("corrected", r"$\mathbf{m} = k_w (\mathbf{w} \times \mathbf{B})/|\mathbf{B}|^2$ (damps)"),
                       ("printed", r"printed $-k_w (\mathbf{w} \times \mathbf{B}) \times \mathbf{B}/|\mathbf{B}|^2$ "
                                   "as a torque")):
        t, energy = _energy_run(law, damping_gain, rotor_momentum, initial_rate, field_rate, equatorial_b, duration)
        series.append(Series(label, {"time": ("s", t), "energy": ("J", energy)}))
    return FigureData("", "", "", {}, series)


def plot_damping_sign(data):
    """Energy on a log scale: the printed sign pumps it up, the corrected one drains it."""
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(6.4, 3.6))
    for s, style in zip(data.series, ("C0-", "C3--")):
        ax.semilogy(s.columns["time"][1], s.columns["energy"][1], style, label=s.label)
    ax.set_xlabel("time [s]")
    ax.set_ylabel(r"$\frac{1}{2}\,\boldsymbol{\omega}^\mathsf{T}\mathbf{J}\,\boldsymbol{\omega}$ [J]")
    ax.legend()
    ax.set_title("Erratum: the damping projection as printed pumps energy")
    return fig


register(FigureSpec("rotor-stability-map", "Stability in the gains (reconstruction of the lost slide)",
                    f"{SOURCE}, slide 'Stability and choice of control parameters' (lost)",
                    compute_stability_map, plot_stability_map, _map_parameters))
register(FigureSpec("rotor-simulation", "The asymmetric spacecraft simulated (reconstruction of the lost slide)",
                    f"{SOURCE}, slide 'Simulation (asymmetric spacecraft)' (lost)",
                    compute_simulation, plot_simulation, _simulation_parameters, slow=True))
register(FigureSpec("rotor-equilibrium-law", "The equilibrium dipole law over one orbit",
                    f"{SOURCE}, slides 'Creating the equilibrium' and 'Choice of control'",
                    compute_equilibrium_law, plot_equilibrium_law, _law_parameters))
register(FigureSpec("rotor-damping-sign", "The damping projection: corrected sign against the printed one",
                    f"{SOURCE}, slide 'Control implementation'; Kovalenko (1975) eqs. (4.30)–(4.32)",
                    compute_damping_sign, plot_damping_sign, _damping_parameters))
register(FigureSpec("rotor-floquet-slice", "Floquet multiplier against the damping gain",
                    f"{SOURCE}, slide 'Ensuring stability'",
                    compute_floquet_slice, plot_floquet_slice, _slice_parameters))


# --- beyond the slides: robustness (ours, rotor_spin.md §9) -------------------------------------

def _thesis_tilt():
    from ...io import load_parameter_set

    return load_parameter_set("thesis")["earth_dipole_tilt"].value_si


def _field_model_parameters():
    return {
        "real_tilt": FigureParameter(_thesis_tilt(), "rad", "tilt of the real dipole (the thesis's printed 11.5°)"),
        "small_tilt": FigureParameter(1.0 * DEG, "rad", "a small tilt for the error per degree (ours)"),
        "orbits": FigureParameter(2.0, "1", "orbits simulated per run (normalised model, RK4 at 1000 steps per orbit)", high=50.0),
    }


def _pointing_series(label, run, w0):
    return Series(label, {"time": ("orbit", run.time * w0 / (2.0 * math.pi)),
                          "pointing_error": ("deg", np.degrees(run.pointing_error)),
                          "orbit_maxima": ("deg", np.degrees(pointing_error_orbit_maxima(run, w0)))})


def _whole_orbits(orbits):
    n = int(orbits)
    if n < 1:
        raise ValueError(f"orbits must be >= 1, got {shown(orbits)}")
    return n


@cached_result(maxsize=8)
def tilted_si_run(items, tilt, orbits):
    """The default spacecraft made symmetric (I22 = I33 = B, so that the reference is an exact solution)
    from the reference under a real dipole tilted by ``tilt``: the SI model (DOP853 at the chapter's
    tolerance; the tests' check of :func:`tilted_normalised_run`)."""
    p = _with_asymmetry(dict(items), 0.0)
    orbit = default_rotor_orbit({**p, "dipole_tilt": tilt})
    return run_rotor(p, default_rotor_satellite(p), orbit, orbits * 2.0 * math.pi / orbit.mean_motion)


@cached_result(maxsize=8)
def tilted_normalised_run(items, tilt, orbits, steps_per_orbit=1000):
    """As :func:`tilted_si_run` by the five-state normalised model
    (:func:`magbench.sim.tilted_dipole_pointing_error`): exact for the symmetric body, whose spin
    drops out. Returns τ/2π [orbits] and the pointing error [deg] (cached: the figure, its style
    check and the chapter's tests share the runs)."""
    p = _with_asymmetry(dict(items), 0.0)
    t, error = tilted_dipole_pointing_error(default_rotor_satellite(p), default_rotor_orbit(p), tilt, orbits,
                                            steps_per_orbit=steps_per_orbit)
    return t, np.degrees(error)


def compute_field_model(real_tilt, small_tilt, orbits):
    """Program field = the direct dipole, real field = a tilted dipole: our spacecraft made symmetric
    (I22 = I33 = B; for the asymmetric one the reference is not an exact solution) and started on the
    reference, so every pointing error is the mismatch's. The normalised model (exact for this body;
    the tests check it against the SI run)."""
    n = _whole_orbits(orbits)
    p = chapter_parameters(CHAPTER.key)
    items = ChapterInputs(p)
    series = []
    for tilt in (small_tilt, real_tilt):
        t, error = tilted_normalised_run(items, float(tilt), n)
        series.append(Series(f"real dipole tilted {math.degrees(tilt):.1f}°", {
            "time": ("orbit", t), "pointing_error": ("deg", error),
            "orbit_maxima": ("deg", maxima_per_orbit(t, error, n))}))
    small_last = float(series[0].columns["orbit_maxima"][1][-1])
    return FigureData("", "", "", {}, series,
                      extra={"per_degree": small_last / math.degrees(small_tilt) if small_tilt else math.nan})


def _plot_pointing_runs(data, colours, legend_location, title):
    """Pointing error of each run in ``data.series`` against time, with the slides' 10–15° band."""
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(6.4, 3.6))
    _draw_slides_pointing_band(ax)
    for s, colour in zip(data.series, colours):
        ax.plot(s.columns["time"][1], s.columns["pointing_error"][1], colour, linewidth=0.7, label=s.label)
    ax.set_xlabel("time [orbits]")
    ax.set_ylabel("pointing error [deg]")
    ax.legend(loc=legend_location)
    ax.set_title(title)
    return fig


def plot_field_model(data):
    """Pointing error for the two tilts, with the slides' 10–15° band."""
    return _plot_pointing_runs(data, ("C0", "C3"), "upper left", "Program field: direct dipole; real field: "
                               "tilted dipole\n(symmetric body, start on the reference)")


def _inertia_parameters():
    return {
        "product_of_inertia": FigureParameter(0.002, "kg m^2", "I12 = I13 (ours, 0.8 % of B)"),
        "orbits": FigureParameter(2.0, "1", "orbits simulated per run", high=50.0),
    }


@cached_result(maxsize=8)
def _inertia_run(items, product, orbits, damping):
    """The default spacecraft with products of inertia from (α0, β0) with the momentum the reference
    needs (cached like :func:`tilted_normalised_run`); returns the run and the start's rate offset [rad/s]."""
    p = dict(items)
    orbit = default_rotor_orbit(p)
    sat = rotor_satellite_with_products(default_rotor_satellite(p), product)
    angles = (p["initial_alpha"], p["initial_beta"], p["initial_gamma"])
    offset = reference_momentum_rate_offset(sat, orbit, angles)
    run = run_rotor(p, sat, orbit, orbits * 2.0 * math.pi / orbit.mean_motion, initial_angles=angles,
                    initial_rate_error=offset, damping=damping)
    return run, float(np.linalg.norm(offset))


def compute_products_of_inertia(product_of_inertia, orbits):
    """Rate-error damping (the slides) against momentum-error damping (Kovalenko (4.30)–(4.32), (7.5)) when the
    rotor axis is not a principal axis.

    Both start turned by the chapter's (α0, β0) with the momentum the reference needs,
    I ω + J_f ν e1 = H0 e1 + B ω0 o2 (with products of inertia the rate ω0 o2 + s e1 would
    carry a transverse momentum s I12 several times H0, and the body would cone at once).
    """
    n = _whole_orbits(orbits)
    p = chapter_parameters(CHAPTER.key)
    w0 = default_rotor_orbit(p).mean_motion
    series = []
    for damping, label in (("rate", "rate error damped (slides)"), ("momentum", "momentum error damped (Kovalenko)")):
        run, offset = _inertia_run(ChapterInputs(p), float(product_of_inertia), n, damping)
        series.append(_pointing_series(label, run, w0))
    return FigureData("", "", "", {}, series, extra={"rate_offset": offset / w0})


def plot_products_of_inertia(data):
    """Pointing error of the two damping variants."""
    return _plot_pointing_runs(data, ("C3", "C0"), "upper right", "Rotor axis not principal: which error to damp")


def _relay_parameters():
    return {"samples": FigureParameter(720.0, "1", "points over one turn of the transverse field", high=1e5, whole=True)}


def compute_spin_relay(samples):
    """Kovalenko's relay spin law (7.12) over a turn of the transverse field: its spin-axis torque per L0 B⊥."""
    alpha, torque = relay_spin_torque_over_turn(samples)
    return FigureData("", "", "", {}, [Series("relay (7.12)", {"angle": ("deg", np.degrees(alpha)),
                                                               "torque": ("1", torque)})],
                      extra={"mean": float(np.mean(np.abs(torque)))})


def plot_spin_relay(data):
    """|(L × B)_z|/(L0 B⊥) against the field's angle, its mean and 4/π."""
    import matplotlib.pyplot as plt

    c = data.series[0].columns
    fig, ax = plt.subplots(figsize=(6.4, 3.2))
    ax.plot(c["angle"][1], np.abs(c["torque"][1]), "C0", label="|cos α| + |sin α| (relay law (7.12))")
    ax.axhline(data.extra["mean"], color="C3", linestyle="--", label=f"mean over a turn {data.extra['mean']:.4f}")
    ax.axhline(4 / math.pi, color="k", linewidth=0.6, linestyle=":", label="4/π")
    ax.set_xlabel("angle α of the transverse field [deg]")
    ax.set_ylabel(r"spin torque / $(m_0 B_\perp)$ [1]")
    ax.set_xticks(np.arange(0, 361, 90))
    ax.set_ylim(0.6, 1.5)
    ax.legend(loc="lower center", ncols=2)
    ax.set_title(r"Kovalenko (7.26): the relay law's mean moment is $(4/\pi)\,m_0$")
    return fig


register(FigureSpec("rotor-field-model", "Program field against the real one: a tilted dipole (beyond the slides)",
                    f"ours, beyond the {SOURCE}; Kovalenko (1975) eq. (2.36) for the tilted dipole",
                    compute_field_model, plot_field_model, _field_model_parameters))
register(FigureSpec("rotor-products-of-inertia", "Products of inertia: rate damping against momentum damping "
                    "(beyond the slides; slow)",
                    f"ours, beyond the {SOURCE}; Kovalenko (1975) eqs. (4.30)–(4.32), (7.5)",
                    compute_products_of_inertia, plot_products_of_inertia, _inertia_parameters, slow=True))
register(FigureSpec("kovalenko-spin-relay", "Kovalenko's relay spin law over a turn of the field",
                    "Kovalenko (1975) §7.3, eqs. (7.12), (7.26)", compute_spin_relay, plot_spin_relay,
                    _relay_parameters))


# --- pointing error against the transverse asymmetry (rotor_spin.md §8, §14) -------------------

def _asymmetry(params):
    """ε = (I33 − I22)/(I33 + I22) of a parameter set [-]."""
    return transverse_asymmetry(params["transverse_inertia_2"], params["transverse_inertia_3"])


def _asymmetry_parameters():
    return {
        "largest_asymmetry": FigureParameter(0.35, "1", "largest ε = (I33 − I22)/(I33 + I22) of the sweep (ours, "
                                                        "beyond the default 0.25)"),
        "orbits": FigureParameter(2.0, "1", "orbits per run and asymmetric body", high=50.0),
    }


def _with_asymmetry(params, asymmetry):
    """The parameters with I22 = B(1 − ε), I33 = B(1 + ε), B = (I22 + I33)/2 and everything else held."""
    i2, i3 = transverse_inertia_with_asymmetry(params["transverse_inertia_2"], params["transverse_inertia_3"],
                                               asymmetry)
    return {**params, "transverse_inertia_2": i2, "transverse_inertia_3": i3}


@cached_result(maxsize=8)
def asymmetric_si_maxima(items, asymmetry, orbits):
    """Largest pointing error per orbit [deg] of the SI model (DOP853 at the chapter's tolerance) from
    the chapter's start (α0, β0, γ0), transverse asymmetry ε; ``items`` = sorted chapter parameters.

    The default ε reuses :func:`default_run` (its first orbits: the run is converged at this tolerance).
    Not a fixed-step RK4 over the members at once: the asymmetric body's transient needs the spin
    resolved (measured on the 1 rpm variant of our spacecraft: 10, 20 and 40 RK4 steps per spin turn
    give orbit-2 maxima 18.5, 18.3 and 21.2° against DOP853's 21.4°), and at 30 rpm 40 steps per turn
    are 113 000 steps per orbit at 65–100 µs per vectorised numpy call: slower than DOP853 per member.
    """
    p = dict(items)
    w0 = default_rotor_orbit(p).mean_motion
    if math.isclose(asymmetry, _asymmetry(p), rel_tol=0.0, abs_tol=1e-12) and orbits <= p["simulation_orbits"]:
        return np.degrees(pointing_error_orbit_maxima(default_run(p), w0))[:orbits]
    p = _with_asymmetry(p, asymmetry)
    run = run_rotor(p, default_rotor_satellite(p), default_rotor_orbit(p), orbits * 2.0 * math.pi / w0,
                    initial_angles=(p["initial_alpha"], p["initial_beta"], p["initial_gamma"]))
    return np.degrees(pointing_error_orbit_maxima(run, w0))


@cached_result(maxsize=8)
def symmetric_normalised_maxima(items, orbits, steps_per_orbit=1000):
    """Largest pointing error per orbit [deg] of the symmetric body (ε = 0) from the chapter's start,
    by the five-state normalised model (:func:`magbench.sim.symmetric_rotor_orbit_maxima`): for
    I22 = I33 the SI model reduces exactly to it, the spin drops out of the transverse dynamics.
    """
    p = _with_asymmetry(dict(items), 0.0)
    return np.degrees(symmetric_rotor_orbit_maxima(default_rotor_satellite(p), default_rotor_orbit(p),
                                                   p["initial_alpha"], p["initial_beta"], orbits,
                                                   steps_per_orbit=steps_per_orbit))


def _asymmetric_run(items, asymmetry, orbits):
    return symmetric_normalised_maxima(items, orbits) if asymmetry == 0.0 else \
        asymmetric_si_maxima(items, asymmetry, orbits)


def asymmetry_members(default, largest):
    """The ε of the sweep: symmetric, 0.4 of the default, the default and ``largest`` [-]."""
    if not 0.0 <= largest < 1.0:
        raise ValueError(f"largest_asymmetry must be in [0, 1) (I22 > 0), got {shown(largest)}")
    return tuple(sorted({0.0, round(0.4 * default, 12), float(default), float(largest)}))


def compute_asymmetry(largest_asymmetry, orbits):
    """Largest pointing error per orbit against ε = (I33 − I22)/(I33 + I22), from the chapter's start."""
    n = _whole_orbits(orbits)
    p = chapter_parameters(CHAPTER.key)
    items = ChapterInputs(p)
    eps = asymmetry_members(_asymmetry(p), float(largest_asymmetry))
    maxima = np.array([_asymmetric_run(items, e, n) for e in eps])          # (members, orbits)
    return FigureData("", "", "", {}, [Series(f"orbit {k + 1}", {"asymmetry": ("1", np.array(eps)),
                                                                "pointing_error": ("deg", maxima[:, k])})
                                       for k in range(n)],
                      extra={"default_asymmetry": _asymmetry(p)})


def plot_asymmetry(data):
    """Per-orbit maxima from orbit 2 on against ε, orbit 1 (the start's error) as a line, the default ε
    marked, with the slides' 10–15° band."""
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(6.4, 3.6))
    _draw_slides_pointing_band(ax)
    first = data.series[0].columns
    ax.plot(first["asymmetry"][1], first["pointing_error"][1], color="0.4", linestyle="--",
            label="largest error in orbit 1 (the start's)")
    for k, s in enumerate(data.series[1:]):
        ax.plot(s.columns["asymmetry"][1], s.columns["pointing_error"][1], f"C{k % 10}o-",
                label=f"largest error in {s.label}")
    ax.axvline(data.extra["default_asymmetry"], color="k", linewidth=0.8, linestyle=":", label="our spacecraft")
    ax.set_xlabel(r"transverse asymmetry $(J_z - J_y)/(J_z + J_y)$ [1]")
    ax.set_ylabel("pointing error [deg]")
    ax.set_ylim(bottom=0.0)
    ax.legend(loc="upper left")
    ax.set_title("More asymmetry, slower convergence from the same start (parameters ours)")
    return fig


register(FigureSpec("rotor-asymmetry", "Pointing error against the transverse asymmetry (slow)",
                    f"{SOURCE}, slide 'Simulation (asymmetric spacecraft)' (lost); the sweep is ours",
                    compute_asymmetry, plot_asymmetry, _asymmetry_parameters, slow=True))
