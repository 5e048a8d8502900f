"""Chapter 7: passive magnetic attitude in flight, TNS-0 (magnet + hysteresis rods).

TNS-0 preprint (Ilyin et al., Keldysh IAM preprint 2006-018): the averaged field cone (§1,
Fig. 3), Table 1's spin decay (Fig. 14), the one-orbit data of Table 2 and the conclusion's
"≈ 45°"; Kovalenko (1975) ch. 12 for the hysteresis rods. The chapter owns its inputs, the
capture Monte Carlo shared by its figure and its comparison rows, and its source checks.
"""

import numpy as np

from ...compare import make_row
from ...constants import EARTH_RADIUS
from ...errata import printed_check
from ...io import load_parameter_set, load_printed
from ...result_cache import cached_result
from .._base import Chapter, chapter_parameters
from .dispersion import CAPTURE, draw_momentum_direction
from ...units import DEG

__all__ = ["CHAPTER", "INPUTS", "capture_run", "decay_fits", "decay_balance", "full_run", "tns0_orbit",
           "tns0_satellite", "capture_rows", "full_run_rows", "session_fits", "cone_checks", "table_checks",
           "kovalenko_checks", "table2_hours"]


#: The chapter's inputs: names in ``magbench/data/tns0/params.toml``.
INPUTS = (
    # the orbit and the field (external: the ISS orbit, IGRF 2005)
    "orbit_inclination", "orbit_altitude", "earth_dipole_moment",
    # the body (external catalogue size and mass; inertia, magnet and rods ours)
    "mass", "length", "diameter", "transverse_inertia", "axial_inertia", "magnet_moment",
    "rod_coercivity", "rod_remanence", "rod_saturation", "rod_volume",
    # Kovalenko's Transit rods (external)
    "transit_loop_energy", "transit_field_amplitude",
    # the capture Monte Carlo (ours)
    "capture_initial_momentum", "capture_initial_nutation", "capture_duration", "capture_members",
    "capture_seed",
    # the full-dynamics run from session 1 (ours)
    "full_run_duration",
)

#: The parameters the orbit and the satellite read (:func:`tns0_orbit`, :func:`tns0_satellite`):
#: the simulations declare theirs from these, so that one reruns only when its own inputs change.
ORBIT_INPUTS = ("orbit_altitude", "orbit_inclination", "earth_dipole_moment")
SATELLITE_INPUTS = ("transverse_inertia", "axial_inertia", "magnet_moment", "rod_volume", "rod_coercivity",
                    "rod_remanence", "rod_saturation")

#: Samples per capture run are one a minute; the final regime is averaged over the last orbit.
SAMPLE_INTERVAL = 60.0
#: Samples of the full run from session 1: every 5 minutes (≈ 18 per orbit).
FULL_RUN_SAMPLE_INTERVAL = 300.0
#: Random (direction of L, spin axis in the body) pairs of the energy-balance decay line.
BALANCE_MEMBERS = 32


def _params(params):
    return params or chapter_parameters("ch07")


def tns0_orbit(params=None):
    """The circular orbit and direct dipole of a chapter-7 parameter set (SI).

    Parameters
    ----------
    params : dict, optional
        Chapter-7 parameters (SI); defaults from :func:`magbench.params.chapter_parameters`.
    """
    from ...earth import CircularOrbit

    p = _params(params)
    return CircularOrbit(EARTH_RADIUS + p["orbit_altitude"], p["orbit_inclination"], p["earth_dipole_moment"])


def tns0_satellite(params=None):
    """The passive satellite (magnet + two rods along body x and y) of a parameter set.

    Parameters
    ----------
    params : dict, optional
        Chapter-7 parameters (SI).
    """
    from ...sim import PassiveSatellite

    p = _params(params)
    return PassiveSatellite(p["transverse_inertia"], p["axial_inertia"], p["magnet_moment"],
                            rod_volume=p["rod_volume"], rod_coercivity=p["rod_coercivity"],
                            rod_remanence=p["rod_remanence"], rod_saturation=p["rod_saturation"])


def decay_fits():
    """Linear and exponential fits of Table 1's L against the hours since session 1 (Fig. 14).

    Returns
    -------
    hours : ndarray, shape (7,)
        Hours since session 1 from the printed stamps [h].
    momentum : ndarray, shape (7,)
        Table 1's L [kg·m²/s].
    linear, exponential : DecayFit
        The fits (slope in kg·m²/s per hour; time constant in hours).
    """
    from ...estimation import fit_exponential_decay, fit_linear_decay
    from ...io.tns0 import load_table1, table1_hours

    hours, momentum = table1_hours(), load_table1().angular_momentum
    return hours, momentum, fit_linear_decay(hours, momentum), fit_exponential_decay(hours, momentum)


@cached_result(maxsize=4, reads=ORBIT_INPUTS + SATELLITE_INPUTS + (
    "capture_seed", "capture_members", "capture_initial_momentum", "capture_initial_nutation", "capture_duration"))
def _capture(key):
    from ...sim import simulate_passive

    from ...sim import member_generators

    p = dict(key)
    members = int(p["capture_members"])
    if members < 1:
        raise ValueError(f"capture_members must be >= 1, got {members}")
    # one stream per member: the first members of the ``capture`` dispersion study
    directions = np.array([draw_momentum_direction(g) for g in member_generators(int(p["capture_seed"]), 0, members)])
    return simulate_passive(tns0_satellite(p), tns0_orbit(p), np.full(members, p["capture_initial_momentum"]),
                            p["capture_initial_nutation"], directions, p["capture_duration"],
                            sample_interval=SAMPLE_INTERVAL)


def capture_run(params=None):
    """The capture Monte Carlo: members over random initial directions of L (cached).

    Parameters
    ----------
    params : dict, optional
        Chapter-7 parameters (SI).

    Returns
    -------
    dict
        ``run`` (:class:`magbench.sim.PassiveRun`), ``final_angle`` (per member, the angle
        between B and the symmetry axis averaged over the last orbit) [rad], ``final_rate``
        (|ω| averaged likewise) [rad/s], ``final_momentum`` [kg·m²/s], ``mean_field`` (|B|
        averaged over an orbit) [T], ``final_drift`` (per member, the slope of a line through
        the angle's means over the last three orbits) [rad/s] and
        ``conical_angle`` (the relation
        Ω²(A − C) cos θ′ = mB at the final rate; NaN where it has no solution) [rad]
        (:func:`magbench.sim.passive_final_regime`).
    """
    from ...sim import passive_final_regime

    p = _params(params)
    run = _capture(p)
    final = passive_final_regime(run, tns0_satellite(p), tns0_orbit(p), orbits=3)
    return {"run": run, "final_angle": final["final_angle"], "final_rate": final["final_rate"],
            "final_drift": final["drift"], "final_momentum": final["final_momentum"],
            "mean_field": final["mean_field"], "conical_angle": final["conical_angle"]}


def decay_balance(params=None):
    """The energy-balance decay line: dL/dt of a flat spin from the rods' loss per revolution.

    :func:`magbench.sim.flat_spin_decay_rate` for :data:`BALANCE_MEMBERS` random directions of
    L (uniform on the sphere) and spin axes in the body's transverse plane (uniform angle),
    drawn from ``capture_seed``. The rate is proportional to the rod volume, so the volume that
    makes the mean equal Fig. 14's slope follows by one ratio.

    Parameters
    ----------
    params : dict, optional
        Chapter-7 parameters (SI).

    Returns
    -------
    dict
        ``rates`` (per member) and ``mean``, ``std`` [kg·m²/s per s]; ``fit_slope`` (Fig. 14's
        least-squares slope) [kg·m²/s per s]; ``calibrated_volume`` (per rod, the volume whose
        mean rate equals ``fit_slope``) [m³]; ``start`` (Table 1 row 1's L) [kg·m²/s].
    """
    from ...sim import flat_spin_decay_rate

    p = _params(params)
    rng = np.random.default_rng(int(p["capture_seed"]))
    directions = rng.normal(size=(BALANCE_MEMBERS, 3))
    angles = rng.uniform(0.0, 2.0 * np.pi, BALANCE_MEMBERS)
    rates = flat_spin_decay_rate(tns0_satellite(p), tns0_orbit(p), directions, angles)
    hours, momentum, linear, _ = decay_fits()
    slope = linear.parameters["slope"] / 3600.0
    mean = float(np.mean(rates))
    volume = p["rod_volume"] * slope / mean if mean < 0 else float("nan")
    return {"rates": rates, "mean": mean, "std": float(np.std(rates)), "fit_slope": slope,
            "calibrated_volume": volume, "start": float(momentum[0])}


@cached_result(maxsize=2, reads=ORBIT_INPUTS + SATELLITE_INPUTS + ("capture_seed", "full_run_duration"))
def _full(key):
    from ...io.tns0 import load_table1
    from ...sim import member_generators, simulate_passive

    p = dict(key)
    direction = draw_momentum_direction(member_generators(int(p["capture_seed"]), 0, 1)[0])
    t1 = load_table1()
    run = simulate_passive(tns0_satellite(p), tns0_orbit(p), float(t1.angular_momentum[0]), float(t1.nutation[0]),
                           direction, p["full_run_duration"], sample_interval=FULL_RUN_SAMPLE_INTERVAL)
    return run, direction


def full_run(params=None):
    """The full-dynamics run from session 1 through the capture into rotation about B (cached).

    One member: Table 1 row 1's L and nutation, the direction of L the first draw of
    ``capture_seed`` (the capture Monte Carlo's first member), ``full_run_duration`` long.

    Parameters
    ----------
    params : dict, optional
        Chapter-7 parameters (SI).

    Returns
    -------
    dict
        ``run`` (:class:`magbench.sim.PassiveRun`), ``hours`` [h]; ``session_hours`` and
        ``session_momentum`` (the simulated L at Table 1's hours) [h], [kg·m²/s];
        ``relaxed_hours`` (first time the nutation is within 1° of π/2, NaN if never) [h];
        ``capture_hours`` (first time L falls to twice its final value, NaN if never) [h]
        (:func:`magbench.sim.passive_transition_times`);
        ``final_angle``, ``final_rate``, ``final_momentum`` (means over the last orbit) [rad],
        [rad/s], [kg·m²/s]; ``conical_angle`` (Ω²(A − C) cos θ′ = mB at the final rate and the
        orbit-mean |B|; NaN without a solution) [rad]; ``final_orbit_means`` (the angle
        between B and the axis averaged over each of the last :data:`FINAL_ORBITS` orbits)
        [rad]; ``direction`` (initial L̂) [-].
    """
    from ...io.tns0 import table1_hours
    from ...sim import passive_final_regime, passive_transition_times

    p = _params(params)
    run, direction = _full(p)
    final = passive_final_regime(run, tns0_satellite(p), tns0_orbit(p), orbits=FINAL_ORBITS)
    hours = run.time / 3600.0
    final_l = float(final["final_momentum"])
    relaxed, captured = passive_transition_times(run, final_l)
    session_hours = table1_hours()
    return {"run": run, "hours": hours, "session_hours": session_hours,
            "session_momentum": np.interp(session_hours, hours, run.angular_momentum),
            "relaxed_hours": float(relaxed / 3600.0), "capture_hours": float(captured / 3600.0),
            "final_angle": float(final["final_angle"]), "final_rate": float(final["final_rate"]),
            "final_orbit_means": final["orbit_means"], "final_momentum": final_l, "mean_field": final["mean_field"],
            "direction": direction, "conical_angle": float(final["conical_angle"])}


#: Orbits at the end of the full run whose mean angles show how settled its final regime is.
FINAL_ORBITS = 12


def table2_hours():
    """Hours from session 1 to the one orbit of Table 2 (a date without a time: ±12 h)."""
    from ...io.tns0 import load_sessions

    sessions = load_sessions()
    return (sessions[-1].time - sessions[0].time).total_seconds() / 3600.0


def full_run_rows(params=None):
    """Chapter 7: the full run's final angle and L beside Table 2 and the conclusion (one member).

    Calibrated: the rod volume (on Fig. 14's slope) and the magnet moment (chosen); the
    direction of L is one random draw, so the tolerance is the spread the capture Monte
    Carlo's random directions make (its standard deviation). The chapter page shows these
    rows; the book-wide comparisons use the faster Monte Carlo rows (:func:`capture_rows`).

    Parameters
    ----------
    params : dict, optional
        Chapter-7 parameters (SI).
    """
    printed = load_printed("tns0")
    p = _params(params)
    run = full_run(p)
    cap = capture_run(p)
    spread_angle, spread_l = float(np.std(cap["final_angle"])), float(np.std(cap["final_momentum"]))
    note = (f"consistency check, not a test: one {p['full_run_duration'] / 3600:g} h full-dynamics run from "
            "session 1 (Table 1 row 1), mean over its last orbit; one random direction of K; rod volume "
            f"calibrated on Fig. 14, magnet moment chosen. Over its last {FINAL_ORBITS} orbits the orbit-mean angle "
            f"scatters between {np.degrees(run['final_orbit_means'].min()):.0f} and "
            f"{np.degrees(run['final_orbit_means'].max()):.0f}° without a trend; the run stops at "
            f"{p['full_run_duration'] / 3600:g} h, the flight value is from about {table2_hours():.0f} h after session 1")
    return [
        make_row("tns0-full-run-angle-table2", "Angle between B and the symmetry axis after capture (full run)",
                 "TNS-0 Table 2 (fit of one orbit of flight data)", printed["tns0-table2-nutation"].value,
                 run["final_angle"], spread_angle, unit="deg", scale=DEG, note=note),
        make_row("tns0-full-run-angle-conclusion", "Angle between B and the symmetry axis after capture (full run)",
                 "TNS-0 conclusions (flight data)", printed["tns0-final-angle"].value, run["final_angle"], spread_angle,
                 unit="deg", scale=DEG, note=note),
        make_row("tns0-full-run-momentum-table2", "Angular momentum after capture (full run)",
                 "TNS-0 Table 2 (fit of one orbit of flight data)", printed["tns0-table2-angular-momentum"].value,
                 run["final_momentum"], spread_l, unit="kg m^2/s", note=note),
    ]


#: Sun-sensor normals ДС1–ДС3 in body axes (+x, +z, −x; ours: only n1 = −n3 is in the text).
SENSOR_NORMALS = np.array([[1.0, 0.0, 0.0], [0.0, 0.0, 1.0], [-1.0, 0.0, 0.0]])

#: The synthetic session (ours): length, sampling, noise and its seed; row 1's lost second
#: phase is set to 1 rad (any value would do: the fit does not know it).
SESSION_DURATION, SESSION_RATE, SESSION_NOISE, SESSION_SEED, SESSION_LOST_PHASE = 60.0, 10.0, 0.01, 1, 1.0


@cached_result(maxsize=2)
def _session_fits(a, c):
    from ...estimation import (fit_frequency_first, fit_multistart, fit_nested_grid, fold_start_time,
                               session_identifiability, session_recovered, synthetic_session)
    from ...io.tns0 import load_table1

    t1 = load_table1()

    def value(name, default):
        v = float(t1.values[name][0])
        return default if np.isnan(v) else v

    t0 = value("start_time", 0.0)
    printed = np.array([value("angular_momentum", 0.0), value("nutation", 0.0), value("phase_a", 0.0),
                        value("phase_b", SESSION_LOST_PHASE), value("sun_angle", 0.0)])
    # Table 1's t0 folded into the phases: the same motion with t0 = 0 (t0 is not identifiable).
    truth = fold_start_time(printed, t0, a, c)
    time, signals = synthetic_session(truth, SENSOR_NORMALS, a, c, duration=SESSION_DURATION, rate=SESSION_RATE,
                                      noise=SESSION_NOISE, seed=SESSION_SEED)
    fits = [f(time, signals, SENSOR_NORMALS, a, c) for f in (fit_nested_grid, fit_multistart, fit_frequency_first)]
    for fit in fits:
        fit["recovered"] = session_recovered(fit, truth)
    return {"truth": truth, "printed": printed, "start_time": t0, "time": time, "signals": signals, "fits": fits,
            "singular_values": session_identifiability(truth, time, SENSOR_NORMALS, a, c)}


def session_fits(params=None):
    """Table 1 row 1 as a synthetic session, fitted by the three methods (cached).

    Parameters
    ----------
    params : dict, optional
        Chapter-7 parameters (SI): the inertia A and C.

    Returns
    -------
    dict
        ``truth`` (the five constants with t0 folded into the phases), ``printed`` (row 1's,
        the lost phase set to :data:`SESSION_LOST_PHASE`), ``start_time`` (row 1's t0) [s],
        ``time`` (n,) [s], ``signals`` (3, n) [-], ``fits`` (one dict per method: ``method``,
        ``params``, ``rms``, ``evaluations``, ``seconds``, ``recovered``) and
        ``singular_values`` of the Jacobian in (L, θ, ψ0, φ0, σ, t0).
    """
    p = _params(params)
    return _session_fits(float(p["transverse_inertia"]), float(p["axial_inertia"]))


def capture_rows(params=None):
    """Chapter 7: the simulated final angle between B and the axis beside Table 2 and the conclusion.

    The model is the capture Monte Carlo (:func:`capture_run`): its members differ only in
    the unknown initial direction of L; the value is their mean final angle and the
    tolerance their standard deviation (the spread the unknown direction alone makes). The
    rod volume was calibrated on the Fig. 14 slope and the magnet moment chosen within its
    plausible range so that the full simulation reproduces Table 2 (parameter notes): these
    rows test consistency, not an independent prediction.

    Parameters
    ----------
    params : dict, optional
        Chapter-7 parameters (SI).
    """
    printed = load_printed("tns0")
    cap = capture_run(params)
    angle = cap["final_angle"]
    mean, spread = float(np.mean(angle)), float(np.std(angle))
    fall = -float(np.degrees(np.mean(cap["final_drift"])) * 3600.0)
    note = (f"consistency check, not a test: mean ± sd over {angle.size} members of a "
            f"{_params(params)['capture_duration'] / 3600:g} h capture run from a random direction of K (rod volume "
            f"calibrated on Fig. 14; magnet moment chosen). The angle is still falling by about {fall:.0f}°/h on "
            f"average at the stop, and the flight value is from about {table2_hours():.0f} h after session 1: the model value "
            "depends on where the runs stop")
    table2, words = printed["tns0-table2-nutation"], printed["tns0-final-angle"]
    return [
        make_row("tns0-final-angle-table2", "Angle between B and the symmetry axis in the final regime",
                 "TNS-0 Table 2 (fit of one orbit of flight data)", table2.value, mean, spread,
                 unit="deg", scale=DEG, note=note),
        make_row("tns0-final-angle-conclusion", "Angle between B and the symmetry axis (in words, 'about 45°')",
                 "TNS-0 conclusions (flight data)", words.value, mean, spread, unit="deg", scale=DEG, note=note),
    ]


def cone_checks():
    """TNS-0 §1: the averaged field model's 'constant rate, twice the orbital rate', on the
    source's own inclination (the ISS orbit; never on overridden parameters)."""
    from ...earth import field_cone_deviation, field_cone_half_angle, field_cone_rate

    p = {name: par.value_si for name, par in load_parameter_set("tns0").items()}
    i = p["orbit_inclination"]
    u = np.linspace(0.0, np.pi, 20001)
    off_cone, direction_error, _ = field_cone_deviation(i, u)
    rate = field_cone_rate(i, u)
    row = load_printed("tns0")["tns0-cone-rate"]
    return [printed_check(
        row, id="tns0-field-cone-rate", chapter="ch07", location="§1 (Fig. 3)",
        quantity=(f"Mean rate of the field direction around the cone over half an orbit at i = {np.degrees(i):.1f}°, "
                  "in units of the orbital rate (the averaged model: 'twice the orbital rate')"),
        computed=float(np.mean(rate)),
        explanation=(f"The preprint uses the cone for averaging over an orbit, so its rate is the mean rate: the exact "
                     f"direct-dipole direction goes round the cone once per half orbit, at {np.mean(rate):.3f} times "
                     f"the orbital rate on average, and stays within {np.degrees(off_cone.max()):.2f}° of the cone of "
                     f"half-angle {np.degrees(field_cone_half_angle(i)):.3f}°. The rate is not constant: it runs "
                     f"between {rate.min():.2f} and {rate.max():.2f} times the orbital rate, so the uniform model's "
                     f"direction is off by up to {np.degrees(direction_error.max()):.2f}° at an instant; that matters "
                     "only to someone who would use it as an instantaneous field."),
        computation="magbench.earth.field_cone_deviation")]


def table_checks():
    """TNS-0 Tables 1 and 2 against what the text says of them (printed values only)."""
    from ...io.tns0 import load_table2

    printed = load_printed("tns0")
    flat, words = printed["tns0-table1-flat-nutation"], printed["tns0-final-angle"]
    theta = float(load_table2().nutation[0])
    return [
        printed_check(
            flat, id="tns0-table1-nutation-half-pi", chapter="ch07", location="Table 1",
            computed=float(np.pi / 2),
            explanation=(f"Sessions 2–7 print {flat.value_as_printed:g} rad, which is π/2 = {np.pi / 2:.4f} rad to the "
                         "printed digits: the value the text derives for session 2 from sun sensor 1 never seeing the Sun "
                         "(no proper rotation). A flat spin about a transverse axis is also where energy "
                         "dissipation drives a prolate body (J_t > J_s) at constant |K|."),
            computation="numpy.pi / 2"),
        printed_check(
            words, id="tns0-table2-angle-in-degrees", chapter="ch07", location="Conclusions",
            quantity="Table 2's angle between B and the symmetry axis, in degrees, beside the conclusion's 'about 45°'",
            computed=float(np.degrees(theta)),
            explanation=(f"Table 2's {theta:g} rad is {np.degrees(theta):.1f}°, within the ±{words.resolution:g}° that "
                         "'about 45°' allows: the conclusion rounds the table's value."),
            computation="numpy.degrees"),
    ]


def kovalenko_checks():
    """Kovalenko (1975) ch. 12: the rods' numbers in SI, from the oersted and gauss-oersted he prints."""
    from ...units import oersted_to_ampere_per_meter

    printed = load_printed("kovalenko")
    field, loop, test = (printed[k] for k in ("kov-transit-field-si", "kov-transit-loop-si", "kov-kphi-test-field-si"))
    gauss_oersted = 1e-4 * oersted_to_ampere_per_meter(1.0)     # 1 G·Oe = 1e-4 T × 1000/4π A/m [J/m³]
    return [
        printed_check(field, id="kovalenko-transit-field-si", chapter="ch07", location="§12.2, p. 229",
                      computed=float(oersted_to_ampere_per_meter(0.3)),
                      explanation="0.3 Oe × 1000/4π A/m per Oe: the book's 'about 24 A/m' rounds it correctly.",
                      computation="magbench.units.oersted_to_ampere_per_meter"),
        printed_check(loop, id="kovalenko-transit-loop-si", chapter="ch07", location="§12.2, p. 229",
                      computed=float(450.0 * gauss_oersted),
                      explanation=("450 G·Oe × 10⁻⁴ T/G × 1000/4π A/m per Oe; the book's 'about 3.6' rounds it "
                                   "correctly. This is the loss per cycle the chapter uses for the Transit rods."),
                      computation="magbench.units.oersted_to_ampere_per_meter"),
        printed_check(test, id="kovalenko-kphi-test-field-si", chapter="ch07", location="§12.1, p. 221",
                      computed=float(oersted_to_ampere_per_meter(0.068)),
                      explanation=(f"68 mOe is {float(oersted_to_ampere_per_meter(0.068)):.2f} A/m, which rounds to "
                                   "5.4, not the printed 'about 5.5' A/m: a rounding slip of under 2 % in a number "
                                   "the book only quotes; nothing in it depends on the value."),
                      computation="magbench.units.oersted_to_ampere_per_meter"),
    ]


CHAPTER = Chapter(
    key="ch07", title="Passive magnetic attitude in flight: TNS-0's magnet and hysteresis rods",
    short_title="TNS-0's passive attitude",
    pages=("book/ch07-tns0",), source="tns0",
    inputs=INPUTS,
    figure_modules=("magbench.chapters.ch07_tns0.figures",),
    comparisons=capture_rows,
    row_kinds=(("tns0-final-angle-", "consistency"), ("tns0-full-run-", "consistency")),
    check_classes=(
        ("tns0-", "printed", None),
        ("kovalenko-", "printed", None),
    ),
    source_checks=(cone_checks, table_checks, kovalenko_checks),
    cites="TNS-0 preprint (Ilyin et al. 2006), §1–§4, Tables 1–2, Figs. 3 and 14; Kovalenko ch. 12",
    finds=("how far the averaged field cone is from the real field, that Table 1's spin decays linearly "
           "(the signature of rate-independent hysteresis) and what rod volume that implies, and whether a "
           "magnet with two rods ends up rotating about B with its axis near Table 2's 0.85 rad"),
    source_names=(("tns0", "the TNS-0 preprint"), ("kovalenko", "Kovalenko (1975)")),
    discussed_in=(("tns0-final-angle-", "ch07-capture"), ("tns0-full-run-", "ch07-full-run"),
                  ("tns0-field-cone-rate", "ch07-cone"), ("tns0-table1-nutation-half-pi", "ch07-full-run"),
                  ("tns0-table2-angle-in-degrees", "ch07-capture"), ("kovalenko-transit-", "ch07-rods"),
                  ("kovalenko-kphi-test-field-si", "ch07-rods")),
    dispersions=(CAPTURE,),
)
