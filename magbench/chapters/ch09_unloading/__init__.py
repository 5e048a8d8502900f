"""Chapter 9: magnetic unloading of reaction wheels, and detumbling with the same coils.

Kovalenko (1975) ch. 5: the unloading laws of §5.2 and their stability argument, the
detumbling regime's equations (§5.4, (5.10)–(5.18)) and the two simulation studies of §5.5
(detumbling, Figs. 5.10–5.11; unloading, Figs. 5.12–5.15), whose figures survive only as
captions. The chapter owns its inputs (the §5.5 data and our choices, in
``magbench/data/kovalenko/params.toml``), the studies its figures and rows share, and its
source checks.
"""

import numpy as np

from ...compare import make_row
from ...constants import EARTH_GM, EARTH_RADIUS, MU_0
from ...errata import printed_check, source_check
from ...io import load_parameter_set, load_printed
from ...result_cache import cached_result
from ...units import SI_FACTORS
from .._base import Chapter, chapter_parameters

__all__ = ["CHAPTER", "INPUTS", "DETUMBLING_DIPOLE_FACTORS", "THRESHOLD_FACTORS", "detumbling_study",
           "unloading_study", "attitude_study", "duty_study", "capacity_study", "lyapunov_orbit", "comparison_rows",
           "peer_rows",
           "caption_checks", "constant_checks", "law_checks"]

#: The chapter's inputs: names in ``magbench/data/kovalenko/params.toml``.
INPUTS = (
    "earth_dipole_moment",
    # §5.5, detumbling (printed, and our gains)
    "det_altitude", "det_inclination", "det_inertia_x", "det_inertia_yz", "det_initial_momentum", "det_dipole",
    "det_threshold", "det_threshold_step", "det_gain", "det_ladder_dipole", "det_orbits",
    # §5.5, unloading (printed, and ours)
    "unl_altitude", "unl_inclination", "unl_dipole", "unl_disturbance", "unl_on_threshold", "unl_release",
    "unl_signal_dead_zone", "unl_signal_dead_zone_pole", "unl_orbits", "unl_linear_gain", "unl_sun_longitude",
    "unl_sun_longitude_514", "unl_sun_longitude_515", "ecliptic_obliquity",
    # the attitude loop and duty cycling (ours)
    "wheel_attitude_gain", "wheel_rate_gain", "duty_interval", "duty_off_time",
)

DETUMBLING_INPUTS = ("earth_dipole_moment", "det_altitude", "det_inclination", "det_inertia_x", "det_inertia_yz",
                     "det_initial_momentum", "det_dipole", "det_threshold", "det_threshold_step", "det_gain",
                     "det_ladder_dipole", "det_orbits")
UNLOADING_INPUTS = ("earth_dipole_moment", "unl_altitude", "unl_inclination", "unl_dipole", "unl_disturbance",
                    "unl_on_threshold", "unl_release", "unl_signal_dead_zone", "unl_signal_dead_zone_pole",
                    "unl_orbits", "unl_linear_gain", "unl_sun_longitude", "unl_sun_longitude_514",
                    "unl_sun_longitude_515", "ecliptic_obliquity")

#: Fig. 5.10's coils: L0 = 56.5 A·m² times these (the caption prints 56.5, 113, 169.5, 226).
DETUMBLING_DIPOLE_FACTORS = (1.0, 2.0, 3.0, 4.0)
#: Fig. 5.11's thresholds: K° = 0.98 N·m·s times these (printed 0.98, 1.96, 2.94, 3.92).
THRESHOLD_FACTORS = (1.0, 2.0, 3.0, 4.0)
#: Fig. 5.12's release thresholds K1° (printed data rows, curves 1–5).
RELEASE_ROWS = tuple(f"kov-unl-release-{i}" for i in range(1, 6))
#: Steps per orbit of the detumbling runs: the x rate, 0.033 rad/s, turns 0.18 rad a step;
#: RK4's numerical loss of |K| on the torque-free body is then 0.075 % over 20 orbits (2.3 %
#: with 500 steps). Step of the unloading and attitude runs [s].
DETUMBLING_STEPS_PER_ORBIT = 1000
UNLOADING_STEP, ATTITUDE_STEP = 5.0, 10.0
#: Wheel momentum at the start of the unloading runs, every axis [N·m·s] (ours: twice K2°,
#: so that the laws first bring it into the band).
INITIAL_WHEEL_MOMENTUM = 4.0
#: The detumbling is "done" when |K| falls below this fraction of its start.
DONE_FRACTION = 0.1
#: Orbits at the start of an unloading run left out of its steady state.
SETTLING_ORBITS = 2.0


def _params(params):
    return params or chapter_parameters("ch09")


def _orbit(p, prefix, phase=0.0):
    from ...earth import CircularOrbit

    return CircularOrbit(EARTH_RADIUS + p[f"{prefix}_altitude"], p[f"{prefix}_inclination"], p["earth_dipole_moment"],
                         phase)


def _inertia(p):
    return (p["det_inertia_x"], p["det_inertia_yz"], p["det_inertia_yz"])


# --- §5.5: detumbling (Figs. 5.10–5.11) -------------------------------------------------------

@cached_result(maxsize=2, reads=DETUMBLING_INPUTS)
def _detumbling(key):
    from ...earth import mean_square_field
    from ...sim import UnloadingLaw, simulate_coil_detumbling

    p = dict(key)
    orbit = _orbit(p, "det")
    period = orbit.period
    dipoles = p["det_dipole"] * np.asarray(DETUMBLING_DIPOLE_FACTORS)
    thresholds = p["det_threshold_step"] * np.asarray(THRESHOLD_FACTORS)
    # the product law (5.11) with the gain that equals the linear law's at the orbit's rms field;
    # the relay law with the same gain and F_K = ±K° (the seed's δ_z = k_γ K°(B_y − B_x), line 118)
    product_gain = p["det_gain"] / mean_square_field(orbit, duration=period, samples=2000)
    groups = {
        "linear": ([UnloadingLaw("linear", p["det_gain"])] * dipoles.size, dipoles),
        "relay": ([UnloadingLaw("relay", product_gain * p["det_threshold"], p["det_threshold"])] * dipoles.size,
                  dipoles),
        "product": ([UnloadingLaw("product", product_gain)] * dipoles.size, dipoles),
        "threshold": ([UnloadingLaw("relay", product_gain * k, k) for k in thresholds],
                      np.full(thresholds.size, p["det_ladder_dipole"])),
    }
    laws = [law for group, _ in groups.values() for law in group]
    limits = np.concatenate([lim for _, lim in groups.values()])
    orbits = p["det_orbits"]
    if orbits < 2:
        raise ValueError(f"det_orbits must be >= 2, got {orbits!r}")
    run = simulate_coil_detumbling(_inertia(p), orbit, laws, orbits * period, period / DETUMBLING_STEPS_PER_ORBIT,
                                   period / 50, initial_momentum=p["det_initial_momentum"], dipole_limit=limits)
    slices, start = {}, 0
    for name, (group, _) in groups.items():
        slices[name] = slice(start, start + len(group))
        start += len(group)
    return {"run": run, "period": period, "dipoles": dipoles, "thresholds": thresholds, "slices": slices,
            "product_gain": float(product_gain), "members": len(laws),
            "steps": int(round(orbits * DETUMBLING_STEPS_PER_ORBIT))}


def _crossing(time, values, level):
    """First time each column falls to ``level`` or below (NaN if never), linearly interpolated."""
    out = np.full(values.shape[1], np.nan)
    for j in range(values.shape[1]):
        below = np.nonzero(values[:, j] <= level)[0]
        if below.size and below[0] > 0:
            i = below[0]
            a, b = values[i - 1, j], values[i, j]
            out[j] = time[i - 1] + (time[i] - time[i - 1]) * (a - level) / (a - b)
    return out


def detumbling_study(params=None):
    """The regenerated Figs. 5.10 and 5.11: |K| of the §5.5 body under four laws (cached).

    Returns
    -------
    dict
        ``run`` (:func:`magbench.sim.simulate_coil_detumbling`, every member in one call),
        ``period`` [s], ``dipoles`` (4,) L0 [A·m²], ``thresholds`` (4,) K° [N·m·s],
        ``slices`` (members of each group: "linear" (5.1), "relay" (5.7) with K° = 9.8,
        "product" (5.11) and "threshold", the relay with Fig. 5.11's K°), ``done`` (M,)
        the time |K| first falls to :data:`DONE_FRACTION` of its start [s], ``residual``
        (M,) |K| at the end [N·m·s], ``level_time`` (M,) the time |K| first falls to
        4 K°_max, a level every Fig. 5.11 member passes [s], ``linear_fit`` (4,): R² of a
        straight line through |K|(t) of the linear-law members while their coils saturate.
    """
    out = dict(_detumbling(_params(params)))
    run = out["run"]
    k = run.momentum
    out["done"] = _crossing(run.time, k, DONE_FRACTION * k[0, 0])
    out["residual"] = k[-1]
    out["level_time"] = _crossing(run.time, k, 4.0 * out["thresholds"].max())
    fits = []
    for j in range(out["slices"]["linear"].start, out["slices"]["linear"].stop):
        use = run.time <= np.nan_to_num(out["done"][j], nan=run.time[-1])
        r = np.corrcoef(run.time[use], k[use, j])[0, 1]
        fits.append(r * r)
    out["linear_fit"] = np.asarray(fits)
    return out


# --- §5.5: unloading (Figs. 5.12–5.13) ---------------------------------------------------------

def _unloading_laws(p, dead_zone):
    """The members of one start: the relay law with each K1° of Fig. 5.12, without hysteresis,
    and the linear law switched by the same relay (§5.3, system 3) with K1° = unl_release."""
    from ...sim import UnloadingLaw

    printed = load_printed("kovalenko")
    on = p["unl_on_threshold"]
    releases = [printed[r].value for r in RELEASE_ROWS]
    laws = [UnloadingLaw("relay_coil", p["unl_dipole"], on, dead_zone, min(k, on)) for k in releases]
    laws.append(UnloadingLaw("relay_coil", p["unl_dipole"], on, dead_zone))
    laws.append(UnloadingLaw("linear", p["unl_linear_gain"], on, 0.0, min(p["unl_release"], on)))
    return laws, releases


@cached_result(maxsize=2, reads=UNLOADING_INPUTS)
def _unloading(key):
    from ...earth import sun_ecliptic_axes
    from ...sim import UnloadingLaw, simulate_ideal_unloading

    p = dict(key)
    equator, releases = _unloading_laws(p, p["unl_signal_dead_zone"])
    pole, _ = _unloading_laws(p, p["unl_signal_dead_zone_pole"])
    n = len(equator)
    on = p["unl_on_threshold"]
    sun = UnloadingLaw("relay_coil", p["unl_dipole"], on, p["unl_signal_dead_zone"], min(p["unl_release"], on))
    # over the equator; at the top of the orbit ("примерно над полярной областью"); Figs. 5.14–5.15 over the equator
    phase = np.concatenate([np.zeros(n), np.full(n, np.pi / 2), np.zeros(2)])
    longitude = np.concatenate([np.full(2 * n, p["unl_sun_longitude"]),
                                [p["unl_sun_longitude_514"], p["unl_sun_longitude_515"]]])
    axes = sun_ecliptic_axes(longitude, p["ecliptic_obliquity"])
    orbit = _orbit(p, "unl", phase)
    orbits = p["unl_orbits"]
    if orbits < SETTLING_ORBITS + 1:
        raise ValueError(f"unl_orbits must be >= {SETTLING_ORBITS + 1:g} (the first {SETTLING_ORBITS:g} are the "
                         f"transient), got {orbits!r}")
    duration = orbits * orbit.period
    step = UNLOADING_STEP
    run = simulate_ideal_unloading(orbit, equator + pole + [sun, sun], np.full(3, p["unl_disturbance"]),
                                   np.ceil(duration / step) * step, step, 12 * step,
                                   initial_wheel_momentum=INITIAL_WHEEL_MOMENTUM, dipole_limit=p["unl_dipole"],
                                   body_axes=axes)
    return {"run": run, "period": orbit.period, "releases": np.asarray(releases), "per_start": n,
            "sun_longitude": longitude, "members": 2 * n + 2, "steps": int(np.ceil(duration / step))}


def _band(run, period, settle=SETTLING_ORBITS):
    """Largest and smallest |K_i| per axis after ``settle`` orbits (3, M), and the coils' duty (M,)."""
    k = np.abs(np.stack([run.wheel_momentum_x, run.wheel_momentum_y, run.wheel_momentum_z]))
    late = run.time >= settle * period
    m = np.stack([run.dipole_x, run.dipole_y, run.dipole_z])
    duty = np.mean(np.any(m[:, late] != 0.0, axis=0), axis=0)
    return k[:, late].max(axis=1), k[:, late].min(axis=1), duty


def unloading_study(params=None):
    """The regenerated Figs. 5.12–5.13: §5.5's wheel unloading under ideal stabilisation (cached).

    The body fixed in the Sun–ecliptic frame (one axis on the Sun, the frame's annual turn
    neglected, as the source does; :func:`magbench.earth.sun_ecliptic_axes`), 10⁻⁴ N·m on
    every axis, the relay law with hysteresis (on above K2°,
    off at K1°) and the relay coils of Fig. 5.2 (L0 = 50 A·m², dead zone δ0); starting over
    the equator (δ0 = 5·10⁻⁶ T, Fig. 5.12) and at the top of the orbit (δ0 = 1.25·10⁻⁶ T,
    Fig. 5.13), from :data:`INITIAL_WHEEL_MOMENTUM` on every axis.

    Returns
    -------
    dict
        ``run`` (one :func:`magbench.sim.simulate_ideal_unloading` call: members 0–6 over the
        equator with ρ_c = 0, 7–13 at the top; in each, Fig. 5.12's five K1°, the relay
        without hysteresis and the switched linear law; 14 and 15 Figs. 5.14 and 5.15, ρ_c =
        225° and 45°, K1° = ``unl_release``), ``period`` [s], ``releases`` (5,) K1° [N·m·s],
        ``per_start``, ``sun_longitude`` (M,) ρ_c [rad]; ``band_max``, ``band_min`` (3, M), the largest and
        smallest |K_i| after the first two orbits [N·m·s]; ``duty`` (M,), the share of that
        time some coil is on [-]; ``entry`` (M,), the first time every |K_i| ≤ K2° [s].
    """
    p = _params(params)
    out = dict(_unloading(p))
    run = out["run"]
    out["band_max"], out["band_min"], out["duty"] = _band(run, out["period"])
    k = np.max(np.abs(np.stack([run.wheel_momentum_x, run.wheel_momentum_y, run.wheel_momentum_z])), axis=0)
    out["entry"] = _crossing(run.time, k, p["unl_on_threshold"])
    return out


# --- beyond the source: the attitude loop, duty cycling, capacity against inclination -----------

ATTITUDE_INPUTS = UNLOADING_INPUTS + ("det_inertia_x", "det_inertia_yz", "wheel_attitude_gain", "wheel_rate_gain")


@cached_result(maxsize=2, reads=ATTITUDE_INPUTS)
def _attitude(key):
    from ...sim import DisturbanceTorque, UnloadingLaw, WheelSatellite, simulate_unloading

    p = dict(key)
    on, off = p["unl_on_threshold"], min(p["unl_release"], p["unl_on_threshold"])
    laws = [UnloadingLaw("relay_coil", p["unl_dipole"], on, p["unl_signal_dead_zone"], off),
            UnloadingLaw("linear", p["unl_linear_gain"], on, 0.0, off), UnloadingLaw("none")]
    phase = np.repeat([0.0, np.pi / 2], len(laws))
    orbit = _orbit(p, "unl", phase)
    sat = WheelSatellite(_inertia(p), p["wheel_attitude_gain"], p["wheel_rate_gain"], dipole_limit=p["unl_dipole"])
    duration = np.ceil(p["unl_orbits"] * orbit.period / ATTITUDE_STEP) * ATTITUDE_STEP
    run = simulate_unloading(sat, orbit, laws * 2, DisturbanceTorque(constant=(p["unl_disturbance"],) * 3), duration,
                             ATTITUDE_STEP, 6 * ATTITUDE_STEP, initial_wheel_momentum=INITIAL_WHEEL_MOMENTUM)
    return {"run": run, "period": orbit.period, "laws": ("relay", "linear", "none"), "members": 2 * len(laws),
            "steps": int(round(duration / ATTITUDE_STEP))}


def attitude_study(params=None):
    """The unloading with the body held in the orbital frame by a PD loop through the wheels (cached).

    Returns
    -------
    dict
        ``run`` (:func:`magbench.sim.simulate_unloading`, six members: the relay law, the
        switched linear law and no unloading, each starting over the equator (0–2) and at the
        top of the orbit (3–5)), ``laws``, ``period`` [s]; ``band_max``, ``band_min`` (3, M)
        [N·m·s]; ``duty`` (M,) [-]; ``error`` (M,), the largest attitude error after two
        orbits [rad]; ``error_rms`` (M,) [rad].
    """
    out = dict(_attitude(_params(params)))
    run = out["run"]
    out["band_max"], out["band_min"], out["duty"] = _band(run, out["period"])
    late = run.time >= SETTLING_ORBITS * out["period"]
    out["error"] = run.attitude_error[late].max(axis=0)
    out["error_rms"] = np.sqrt(np.mean(run.attitude_error[late] ** 2, axis=0))
    return out


DUTY_INPUTS = UNLOADING_INPUTS + ("duty_interval", "duty_off_time")
#: Orbits of the duty-cycling comparison (its 1 s step makes it the chapter's longest loop).
DUTY_ORBITS = 6.0


@cached_result(maxsize=2, reads=DUTY_INPUTS)
def _duty(key):
    from ...sim import UnloadingLaw, simulate_ideal_unloading

    p = dict(key)
    on, off = p["unl_on_threshold"], min(p["unl_release"], p["unl_on_threshold"])
    laws = [UnloadingLaw("relay_coil", p["unl_dipole"], on, p["unl_signal_dead_zone"], off),
            UnloadingLaw("linear", p["unl_linear_gain"], on, 0.0, off)]
    orbit = _orbit(p, "unl")
    # the largest step, at most 1 s, that divides the interval and the off time (to the millisecond)
    ms = [int(round(1000 * v)) for v in (p["duty_interval"], p["duty_off_time"]) if v > 0]
    step = min(float(np.gcd.reduce(ms)) / 1000.0, 1.0)
    duration = np.ceil(DUTY_ORBITS * orbit.period / p["duty_interval"]) * p["duty_interval"]
    torque = np.full(3, p["unl_disturbance"])
    common = dict(initial_wheel_momentum=INITIAL_WHEEL_MOMENTUM, dipole_limit=p["unl_dipole"])
    # every step recorded: a sample each interval would always fall in the coils' off time
    continuous = simulate_ideal_unloading(orbit, laws, torque, duration, step, step, **common)
    cycled = simulate_ideal_unloading(orbit, laws, torque, duration, step, step, control_interval=p["duty_interval"],
                                      off_time=p["duty_off_time"], **common)
    return {"continuous": continuous, "cycled": cycled, "period": orbit.period, "laws": ("relay", "linear"),
            "step": step}


def duty_study(params=None):
    """§3.7's duty cycling (SamSat-218D's 16 s on, 1 s off) against continuous unloading (cached).

    Returns
    -------
    dict
        ``continuous``, ``cycled`` (runs of :func:`magbench.sim.simulate_ideal_unloading`, the
        relay and the switched linear law, from over the equator), ``period`` [s], ``step``
        [s]; for each run ``<run>_band_max`` (3, 2) [N·m·s] and ``<run>_duty`` (2,) [-];
        ``on_fraction``, the share of the time the cycled coils may act [-].
    """
    out = dict(_duty(_params(params)))
    for name in ("continuous", "cycled"):
        out[f"{name}_band_max"], _, out[f"{name}_duty"] = _band(out[name], out["period"])
    out["on_fraction"] = out["cycled"].summary["on_fraction"]
    return out


#: Inclinations of the capacity study's simulated points [deg].
CAPACITY_INCLINATIONS = (0.0, 30.0, 55.0, 90.0)


@cached_result(maxsize=2, reads=("earth_dipole_moment", "unl_altitude"))
def _capacity(key):
    from ...earth import CircularOrbit, mean_square_field
    from ...earth import field_second_moment, unloadable_fraction, worst_unloading_direction
    from ...sim import UnloadingLaw, simulate_ideal_unloading

    p = dict(key)
    inclination = np.radians(np.linspace(0.0, 90.0, 91))
    radius = EARTH_RADIUS + p["unl_altitude"]
    points = np.radians(np.asarray(CAPACITY_INCLINATIONS))
    simulated = []
    for i in points:
        orbit = CircularOrbit(radius, float(i), p["earth_dipole_moment"])
        # the worst direction, in inertial axes: the orbit axes (node, 90° ahead, normal) are
        # the inertial x, (0, cos i, sin i), (0, −sin i, cos i) for a node on the x axis
        e = worst_unloading_direction(float(i))
        basis = np.array([[1.0, 0.0, 0.0], [0.0, np.cos(i), np.sin(i)], [0.0, -np.sin(i), np.cos(i)]])
        direction = e @ basis
        b2 = mean_square_field(orbit, duration=orbit.period, samples=2000)
        gain = 0.2 / (b2 * orbit.period)          # a slow law: the decay over one orbit is a small exponent
        run = simulate_ideal_unloading(orbit, UnloadingLaw("product", gain), 0.0, orbit.period, orbit.period / 720,
                                       orbit.period / 720, initial_wheel_momentum=direction)
        k = np.stack([run.wheel_momentum_x, run.wheel_momentum_y, run.wheel_momentum_z], axis=-1)[:, 0]
        along = k[-1] @ direction
        simulated.append(-np.log(along) / (gain * b2 * orbit.period))
    return {"inclination": inclination, "worst": unloadable_fraction(inclination),
            "worst_normalised": unloadable_fraction(inclination, normalised=True),
            "second_moment": field_second_moment(inclination), "points": points, "simulated": np.asarray(simulated)}


def capacity_study(params=None):
    """How much of the wheels' momentum the coils can unload, against the orbit's inclination.

    Returns
    -------
    dict
        ``inclination`` (91,) [rad]; ``worst`` and ``worst_normalised`` (91,), the unloadable
        fraction of the worst-placed momentum for the law without and with the division by B²
        (closed forms, :mod:`magbench.earth.unloading_capacity`) [-]; ``points`` [rad] and
        ``simulated``, the same fraction read off one orbit of the law without division
        (:func:`magbench.sim.simulate_ideal_unloading`) [-].
    """
    return _capacity(_params(params))


def lyapunov_orbit(params=None):
    """One orbit of the linear law (5.1) without disturbances: |K| falls, K's part along B stays.

    Returns
    -------
    dict
        ``run`` (:func:`magbench.sim.simulate_ideal_unloading`), ``period`` [s]; ``momentum``
        |K| and ``along`` K·B/|B| (K,) [N·m·s]; ``largest_rise``, the largest increase of |K|
        between samples [N·m·s].
    """
    from ...sim import UnloadingLaw, simulate_ideal_unloading

    p = _params(params)
    orbit = _orbit(p, "unl")
    start = np.full(3, INITIAL_WHEEL_MOMENTUM) / np.sqrt(3.0)
    run = simulate_ideal_unloading(orbit, UnloadingLaw("linear", p["unl_linear_gain"]), 0.0, orbit.period,
                                   orbit.period / 1000, orbit.period / 500, initial_wheel_momentum=start)
    k = run.wheel_momentum[:, 0]
    return {"run": run, "period": orbit.period, "momentum": k, "along": run.wheel_momentum_along_field[:, 0],
            "largest_rise": float(np.max(np.diff(k)))}


# --- model beside the source's statements ---------------------------------------------------------

def comparison_rows(params=None):
    """The unloading runs' steady wheel momentum beside the band the source designed (K2°)."""
    p = _params(params)
    s = unloading_study(p)
    n = s["per_start"]
    release = load_printed("kovalenko")
    k1 = float(p["unl_release"])
    idx = [i for i, r in enumerate(RELEASE_ROWS) if np.isclose(release[r].value, k1)]
    j = idx[0] if idx else 0
    rows = []
    for name, member, where in (("equator", j, "over the equator (Fig. 5.12)"),
                                ("pole", n + j, "at the top of the orbit (Fig. 5.13)")):
        rows.append(make_row(
            f"kov-unl-band-{name}", f"§5.5 unloading, start {where}: largest |K_i| of the wheels in the steady state",
            "Kovalenko (1975) §5.5, p. 123: the relay's on-threshold K2° = 1.96 N·m·s, the band the law is "
            "designed to hold", p["unl_on_threshold"], float(s["band_max"][:, member].max()), 0.005,
            unit="N·m·s", note=(f"the relay law with hysteresis (K1° = {s['releases'][j]:g} N·m·s), relay coils of "
                                f"{p['unl_dipole']:g} A·m²; ideal stabilisation, the body Sun-pointing; orbits "
                                f"{SETTLING_ORBITS:g}–{p['unl_orbits']:g} of the run. The tolerance is the printed value's "
                                "last digit: K2° is the source's design choice, which the system should keep")))
    return rows + peer_rows()


#: Basilisk's unit test of its torque-to-dipole mapping (AVSLab/basilisk,
#: src/fswAlgorithms/effectorInterfaces/torque2Dipole/_UnitTest/test_torque2Dipole.py, stored
#: version 0773ee82): inputs b = (10⁻⁵, 0, 0) T and τ = (10, 20, 30) mN·m; the expected dipole is
#: the test's own formula, cross(b, τ)/(b·b), compared at its accuracy 10⁻¹² A·m². The momentum
#: law behind it, mtbMomentumManagementSimple, asks τ = −K_p h_w: the pair is Kovalenko's (5.1)
#: with k = K_p and K = h_w.
BASILISK_FIELD = (1e-5, 0.0, 0.0)
BASILISK_TORQUE = (10e-3, 20e-3, 30e-3)
BASILISK_ACCURACY = 1e-12


def peer_rows():
    """Kovalenko's linear law (5.1) beside Basilisk's momentum-management chain on its own test case."""
    from ...control import unloading_dipole

    b, tau = np.asarray(BASILISK_FIELD), np.asarray(BASILISK_TORQUE)
    expected = np.cross(b, tau) / np.dot(b, b)      # the test's formula, as it states it
    gain = 3e-3                      # any K_p: the dipole does not depend on it (τ fixes K_p h_w)
    ours = unloading_dipole(b, -tau / gain, gain)
    note = ("Basilisk's torque2Dipole unit test: b = (10⁻⁵, 0, 0) T, τ = (10, 20, 30) mN·m, expected dipole its own "
            "formula (b × τ)/|b|² evaluated on them; ours: (5.1) with K = −τ/k, i.e. mtbMomentumManagementSimple's "
            "τ = −K_p h_w. Tolerance: the test's accuracy, 10⁻¹² A·m²")
    return [make_row(f"basilisk-torque2dipole-{axis}", f"Unloading dipole, {axis} component, Basilisk's test case",
                     "Basilisk torque2Dipole unit test (its expected value)", float(expected[i]), float(ours[i]),
                     BASILISK_ACCURACY, unit="A·m²", note=note)
            for i, axis in ((1, "y"), (2, "z"))]


# --- source checks -------------------------------------------------------------------------------

_G = 9.80665            # standard gravity [m/s²]: the book's kgf·m·s become N·m·s with g = 9.8


def caption_checks():
    """§5.5's captions: the ladders of L0 and K°, and the momenta as kgf·m·s converted."""
    printed = load_printed("kovalenko")
    p = {name: par.value_si for name, par in load_parameter_set("kovalenko").items()}
    checks = []
    for f, key in zip(DETUMBLING_DIPOLE_FACTORS[1:], ("kov-det-dipole-2", "kov-det-dipole-3", "kov-det-dipole-4")):
        checks.append(printed_check(printed[key], id=key, chapter="ch09", location="§5.5, Fig. 5.10, p. 119",
                                    computed=f * p["det_dipole"],
                                    explanation=(f"{f:g} × the first curve's 56.5 A·m² = {f * p['det_dipole']:g}: the "
                                                 "caption's four coils are one to four times the smallest."),
                                    computation="arithmetic"))
    for f, key in zip(THRESHOLD_FACTORS[1:], ("kov-det-threshold-2", "kov-det-threshold-3", "kov-det-threshold-4")):
        checks.append(printed_check(printed[key], id=key, chapter="ch09", location="§5.5, Fig. 5.11, p. 120",
                                    computed=f * p["det_threshold_step"],
                                    explanation=(f"{f:g} × 0.98 = {f * p['det_threshold_step']:.2f} N·m·s, i.e. "
                                                 f"{0.1 * f:.1f} kgf·m·s × g: the thresholds are round numbers in the "
                                                 "book's kgf·m·s."),
                                    computation="arithmetic"))
    checks.append(printed_check(printed["kov-unl-gm"], id="kov-unl-gm", chapter="ch09",
                                location="§5.4, eq. (5.18), p. 110", computed=EARTH_GM,
                                explanation=(f"IERS 2010's GM = {EARTH_GM:.6e} m³/s² rounds to the printed "
                                             "3.986·10¹⁴."),
                                computation="magbench.constants.EARTH_GM"))
    return checks


def constant_checks():
    """§5.5's conversions: the momenta in kgf·m·s and the dead zone in oersted."""
    printed = load_printed("kovalenko")
    params = load_parameter_set("kovalenko")
    out = []
    for name, kgf, where, what in (
            ("det_initial_momentum", 10.0, "p. 118", "Detumbling runs' initial momentum per axis"),
            ("det_threshold", 1.0, "p. 118", "Fig. 5.10's relay threshold K°"),
            ("det_threshold_step", 0.1, "Fig. 5.11, p. 120", "Fig. 5.11's smallest threshold K°"),
            ("unl_on_threshold", 0.2, "p. 124", "The unloading relay's on-threshold K2°")):
        par = params[name]
        out.append(source_check(
            id=f"kov-{name.replace('_', '-')}-kgf", chapter="ch09", source="kovalenko", location=f"§5.5, {where}",
            quantity=f"{what}: {par.value:g} kg·m²·s⁻¹ as a round number of kgf·m·s",
            printed=par.value, computed=kgf * _G, tolerance=0.5 * 10.0 ** np.floor(np.log10(abs(par.value)) - 1),
            unit="kg m^2/s",
            explanation=(f"{kgf:g} kgf·m·s × g = {kgf * _G:.4f} N·m·s; the book converts with g = 9.8 and prints "
                         "two significant digits."),
            computation="standard gravity 9.80665 m/s²"))
    oe = printed["kov-unl-dead-zone-oersted"]
    field = params["unl_signal_dead_zone"].value_si / MU_0            # B/μ0 [A/m]
    computed = field / SI_FACTORS["Oe"]
    out.append(printed_check(oe, id="kov-unl-dead-zone-oersted", chapter="ch09", location="§5.5, p. 124",
                             computed=computed, unit="Oe",
                             explanation=(f"5·10⁻⁶ T is B/μ0 = {field:.3f} A/m = {computed:.3f} Oe, not 0.95: the seed's "
                                          "'0,95' is an OCR misreading of 0,05 or a slip of the book; the tesla value "
                                          "is the one the runs use."),
                             computation="magbench.constants.MU_0"))
    return out


def law_checks():
    """§5.2's derivations evaluated on sample states: (5.5) from (5.1), (5.9) from (5.8)."""
    from ...control import pulsed_unloading_dipole, unloading_torque

    rng = np.random.default_rng(5)
    b = rng.normal(size=(200, 3)) * 3e-5
    k = rng.normal(size=(200, 3))
    gain = 2e-3
    # (5.5): d|K|/dt = −k [1 − cos²(K, B)] |K| under the linear law's torque
    torque = unloading_torque(b, k, gain)
    rate = np.sum(torque * k, axis=-1) / np.linalg.norm(k, axis=-1)
    cos2 = (np.sum(k * b, axis=-1) / (np.linalg.norm(k, axis=-1) * np.linalg.norm(b, axis=-1))) ** 2
    printed55 = -gain * (1.0 - cos2) * np.linalg.norm(k, axis=-1)
    # (5.9): with B_x = 0 and the x coil off, M_x = −k' K_x (B_y² + B_z²), M_y = M_z = 0 (k' = k/B²)
    b0 = b.copy()
    b0[:, 0] = 0.0
    m = pulsed_unloading_dipole(b0, k, gain, 0, 0.0)
    torque59 = np.cross(m, b0)
    b2 = np.sum(b0 * b0, axis=-1)
    printed59 = -(gain / b2) * k[:, 0] * (b0[:, 1] ** 2 + b0[:, 2] ** 2)
    return [
        source_check(id="kov-unloading-rate-55", chapter="ch09", source="kovalenko", location="§5.2, eqs. (5.3)–(5.5), p. 98",
                     quantity="Largest |d|K|/dt − (−k[1 − cos²(K, B)]|K|)| over 200 random states, per k|K|",
                     printed=0.0, computed=float(np.max(np.abs(rate - printed55) / (gain * np.linalg.norm(k, axis=-1)))),
                     tolerance=1e-12, unit="1",
                     explanation=("(5.5) as the seed prints it is garbled ('k+kY [1 − cos²(K, B)]K = 0'); read as "
                                  "d|K|/dt = −k[1 − cos²(K, B)]|K| it follows from (5.3) exactly (to rounding), so "
                                  "|K| never grows and stops falling only where K ∥ B."),
                     computation="magbench.control.unloading_torque"),
        source_check(id="kov-pulsed-torque-59", chapter="ch09", source="kovalenko", location="§5.2, eqs. (5.8)–(5.9), p. 101",
                     quantity="Largest difference between the pulsed law's torque and (5.9), per k|K_x|, over 200 "
                              "random states with B_x = 0",
                     printed=0.0, computed=float(np.max(np.abs(torque59[:, 0] - printed59) / (gain * np.abs(k[:, 0])))
                                                 + np.max(np.abs(torque59[:, 1:])) / gain),
                     tolerance=1e-12, unit="1",
                     explanation=("With B_x = 0 and the x coil off, (5.8) leaves L_y = −k' K_x B_z, L_z = k' K_x B_y, "
                                  "whose torque is (5.9): M_x = −k' K_x (B_y² + B_z²), M_y = M_z = 0. The library's "
                                  "pulsed law (the linear law restricted to K_x, k' = k/B²) gives the same torque."),
                     computation="magbench.control.pulsed_unloading_dipole"),
    ]


CHAPTER = Chapter(
    key="ch09", title="Unloading reaction wheels, and detumbling, with magnetorquers",
    short_title="unloading reaction wheels",
    pages=("book/ch09-unloading",), source="kovalenko",
    inputs=INPUTS,
    figure_modules=("magbench.chapters.ch09_unloading.figures",),
    comparisons=comparison_rows,
    row_kinds=(("kov-unl-band-", "design"), ("basilisk-torque2dipole-", "claim")),
    check_classes=(
        ("kov-det-", "printed", None),
        ("kov-unl-gm", "printed", None),
        ("kov-unl-dead-zone-oersted", "printed", "lost"),
        ("kov-unl-on-threshold-kgf", "printed", None),
        ("kov-unloading-rate-55", "evaluated", None),
        ("kov-pulsed-torque-59", "evaluated", None),
    ),
    source_checks=(caption_checks, constant_checks, law_checks),
    concordance=(
        ("kovalenko", "§5.2, eqs. (5.1)–(5.9)", "the unloading laws and their stability", "{ref}`ch09-laws`"),
        ("kovalenko", "§5.3, Figs. 5.3–5.8", "unloading systems: continuous, switched, relay", "{ref}`ch09-laws`"),
        ("kovalenko", "§5.4, eqs. (5.10)–(5.18)", "the detumbling regime's equations", "{ref}`ch09-detumbling`"),
        ("kovalenko", "§5.4, eqs. (5.35)–(5.47)", "the unloading regime's equations", "{ref}`ch09-unloading`"),
        ("kovalenko", "§5.5, Figs. 5.10–5.11", "detumbling runs", "{ref}`ch09-detumbling`"),
        ("kovalenko", "§5.5, Figs. 5.12–5.15", "unloading runs", "{ref}`ch09-unloading`"),
        ("kovalenko", "§3.7, p. 75", "measuring while the coils are off", "{ref}`ch09-duty`"),
    ),
    cites="Kovalenko (1975) §§5.2–5.5 (eqs. (5.1)–(5.18), (5.35)–(5.47), Figs. 5.10–5.13), §3.7",
    finds=("whether Kovalenko's unloading laws hold a wheel's momentum in the band his dead zones set, how his "
           "detumbling runs depend on the coil and the threshold, how much momentum an orbit of given inclination "
           "lets coils unload, and what the unloading costs the attitude loop"),
    source_names=(("kovalenko", "Kovalenko (1975)"),),
    discussed_in=(("kov-det-", "ch09-detumbling"), ("kov-unl-", "ch09-unloading"), ("basilisk-", "ch09-peer"),
                  ("kov-unloading-rate-55", "ch09-laws"), ("kov-pulsed-torque-59", "ch09-laws")),
)
