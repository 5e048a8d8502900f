"""Model beside measurement: one row per measured (or independently known) quantity.

A row holds the measured value with its source and uncertainty, the model's value,
their difference and the tolerance within which they count as agreeing. The verdict
is computed, never typed, and a disagreement is a finding, not an error.

Tolerances are never chosen to make a row agree: they come from the measurement's
stated uncertainty, or, where the model rests on rounded printed inputs, from the
spread of the model over those inputs' last printed digit.

Each chapter contributes a provider: a function ``(params) -> list[CompareRow]``
registered in :data:`PROVIDERS`.
"""

import itertools
from dataclasses import asdict, dataclass

import numpy as np

from . import geomag, igrf
from .constants import EARTH_RADIUS
from .params import chapter_parameters

__all__ = ["CompareRow", "PROVIDERS", "make_row", "all_rows", "geomagnetic_rows", "IGRF_NEWEST_EPOCH",
           "simulator_rows", "simulator_center_h_tolerance", "magnetorquer_rows",
           "bench_rows"]


@dataclass(frozen=True)
class CompareRow:
    """One model-vs-measurement comparison (SI values; ``unit`` names the display unit)."""

    id: str
    quantity: str
    source: str
    measured: float
    uncertainty: float | None
    unit: str
    model: float
    difference: float
    tolerance: float
    verdict: str
    note: str = ""

    def as_dict(self):
        """The row as a JSON-ready dict with the public keys."""
        d = asdict(self)
        d.pop("note")
        return d


def make_row(id, quantity, source, measured, model, tolerance, *, unit, uncertainty=None,
             scale=1.0, note=""):
    """Build a row; values are given in SI and divided by ``scale`` for display in ``unit``.

    The verdict is ``"agrees"`` when |model − measured| ≤ tolerance, else ``"disagrees"``.
    """
    diff = float(model) - float(measured)
    verdict = "agrees" if abs(diff) <= float(tolerance) else "disagrees"
    return CompareRow(
        id=id, quantity=quantity, source=source, measured=float(measured) / scale,
        uncertainty=None if uncertainty is None else float(uncertainty) / scale, unit=unit,
        model=float(model) / scale, difference=diff / scale, tolerance=float(tolerance) / scale,
        verdict=verdict, note=note,
    )


#: The newest epoch with a main-field model in IGRF-14 [decimal year]. Later years are
#: the secular-variation forecast, and a row dated by the build would change with it.
IGRF_NEWEST_EPOCH = 2025.0


def _printed_digit_spread(func, values, half_units):
    """Largest |func(perturbed) − func(values)| over the corners of the printed-digit box."""
    base = func(*values)
    spread = 0.0
    for signs in itertools.product((-1.0, 1.0), repeat=len(values)):
        moved = [v + s * d for v, s, d in zip(values, signs, half_units)]
        spread = max(spread, float(np.max(np.abs(func(*moved) - base))))
    return spread


def geomagnetic_rows(params=None, *, epochs=None):
    """Chapter 1: the thesis's dipole beside the IGRF-14 field.

    The "measured" side is IGRF-14, the field model fitted to observatory and
    satellite measurements; the "model" side is the thesis's dipole (moment 8.1·10²²
    A·m², pole 78.5° N 69° W). Tolerances are the thesis's printed-digit rounding.

    Parameters
    ----------
    params : dict, optional
        Chapter-1 parameters (SI); defaults from :func:`magbench.params.chapter_parameters`.
    epochs : sequence of float, optional
        Decimal years for the dipole rows; default 1960, the thesis's epoch and
        :data:`IGRF_NEWEST_EPOCH` (no row depends on the date of the build).
    """
    p = params or chapter_parameters("ch01")
    if epochs is None:
        epochs = (1960.0, p["thesis_epoch"], IGRF_NEWEST_EPOCH)
    m, tilt = p["earth_dipole_moment"], p["earth_dipole_tilt"]
    plat, plon = p["geomagnetic_pole_latitude"], p["geomagnetic_pole_longitude"]
    deg = np.pi / 180
    # Half a unit in the last printed digit: 8.1e25 CGS, 11.5°, 78.5° N, 69° W.
    half_m, half_tilt, half_plat, half_plon = 0.05e22, 0.05 * deg, 0.05 * deg, 0.5 * deg
    src = "IGRF-14 (ppigrf), degree 1"
    rows = []
    for year in epochs:
        d = igrf.igrf_dipole(year)
        tag = f"{year:.0f}" if float(year).is_integer() else f"{year:.2f}"
        rows += [
            make_row(f"dipole-moment-{tag}", f"Earth dipole moment, {tag}", src, d.moment, m, half_m,
                     unit="1e22 A m^2", scale=1e22),
            make_row(f"dipole-tilt-{tag}", f"Dipole tilt to the rotation axis, {tag}", src,
                     d.tilt, tilt, half_tilt, unit="deg", scale=deg),
            make_row(f"pole-latitude-{tag}", f"Northern geomagnetic pole latitude, {tag}", src,
                     d.pole_latitude, plat, half_plat, unit="deg", scale=deg),
            make_row(f"pole-longitude-{tag}", f"Northern geomagnetic pole longitude, {tag}", src,
                     d.pole_longitude, plon, half_plon, unit="deg", scale=deg),
        ]
    # The full field at the laboratory when the bench was built.
    lat, lon, year = p["laboratory_latitude"], p["laboratory_longitude"], p["thesis_epoch"]
    f = igrf.igrf_field(lat, lon, year)

    def lab_elements(moment, pole_lat, pole_lon):
        phi = geomag.geomagnetic_latitude(lat, lon, pole_lat, pole_lon)
        return np.array([geomag.dipole_total_b(phi, moment, p["earth_radius"]),
                         geomag.dipole_horizontal_b(phi, moment, p["earth_radius"]),
                         geomag.dipole_vertical_b(phi, moment, p["earth_radius"]),
                         geomag.dipole_inclination(phi)])

    model = lab_elements(m, plat, plon)
    spread = [_printed_digit_spread(lambda *v, k=k: lab_elements(*v)[k], (m, plat, plon),
                                    (half_m, half_plat, half_plon)) for k in range(4)]
    src_full = f"IGRF-14 (ppigrf), full field, {year:.0f}"
    rows += [
        make_row("lab-total-field", "Total field at the laboratory (St Petersburg)", src_full,
                 f.total, model[0], spread[0], unit="uT", scale=1e-6),
        make_row("lab-horizontal-field", "Horizontal field at the laboratory", src_full,
                 f.horizontal, model[1], spread[1], unit="uT", scale=1e-6),
        make_row("lab-vertical-field", "Vertical (downward) field at the laboratory", src_full,
                 f.down, model[2], spread[2], unit="uT", scale=1e-6),
        make_row("lab-inclination", "Inclination at the laboratory", src_full,
                 f.inclination, model[3], spread[3], unit="deg", scale=deg),
    ]
    # The equatorial dipole field the thesis prints (0.31 Oe) against the real dipole.
    d = igrf.igrf_dipole(year)
    b0_igrf = geomag.dipole_equatorial_b(d.moment, EARTH_RADIUS)
    b0_model = geomag.dipole_equatorial_b(m, p["earth_radius"])
    rows.append(make_row("equatorial-dipole-field", f"Dipole field on the equator, {year:.0f}",
                         src, b0_igrf, b0_model, b0_model * half_m / m, unit="uT", scale=1e-6))
    return rows


def simulator_center_h_tolerance(current, turns, radius, spacing_range=(0.50, 0.52), current_half_digit=0.05):
    """Spread of the as-built pair's centre field over what the thesis leaves open [A/m].

    The centre-to-centre spacing lies between the measured inner and outer distances
    (0.50–0.52 m, thesis §2.4) and the current is printed to 0.1 A (±0.05 A). The
    largest |ΔH| over the corners of that box, from its middle, is the tolerance.
    """
    from . import coils

    d_mid = 0.5 * (spacing_range[0] + spacing_range[1])
    base = float(coils.helmholtz_center_h(current, turns, radius, d_mid))
    return max(abs(float(coils.helmholtz_center_h(current + di, turns, radius, d)) - base)
               for di in (-current_half_digit, current_half_digit) for d in spacing_range)


#: The band that defines "uniform" for the COMSOL zone lengths: fixed before comparing
#: (a common engineering choice; the thesis names none). ch02-zone-criterion shows
#: how the lengths depend on it.
ZONE_TOLERANCE = 0.01


def simulator_rows(params=None):
    """Chapter 2: the field simulator as measured and as COMSOL-modelled, beside the
    exact thin-loop model (:mod:`magbench.coils`).

    Parameters
    ----------
    params : dict, optional
        Chapter-2 parameters (SI); defaults from :func:`magbench.params.chapter_parameters`.
    """
    from . import coils
    from .data import load_measurements

    p = params or chapter_parameters("ch02")
    m = load_measurements("thesis")
    n, i = p["sim_turns"], p["sim_current"]
    a, d_built, d_comsol = p["sim_built_radius"], p["sim_built_spacing"], p["sim_comsol_spacing"]
    src = "thesis §2.4 (measured)"
    centre = m["sim-center-h"]
    h_built = float(coils.helmholtz_center_h(i, n, a, d_built))
    h_comsol = float(coils.helmholtz_center_h(i, n, a, d_comsol))
    tol_built = simulator_center_h_tolerance(i, n, a)
    tol_comsol = max(abs(float(coils.helmholtz_center_h(i + s * 0.05, n, a, d_comsol)) - h_comsol)
                     for s in (-1, 1))
    res = m["sim-coil-resistance"]
    r_model = float(coils.winding_resistance(a, n, p["sim_wire_diameter"], p["copper_resistivity"]))
    r_tol = 0.5 * (res.value_high - res.value_low) + res.uncertainty     # range plus the stated ±1 Ω
    rows = [
        make_row("sim-center-h", "Field at the centre of the built simulator, 2.3 A per coil", src,
                 centre.value, h_built, tol_built, unit="A/m",
                 note="model: exact thin loops, a = 0.5 m, d = 0.51 m, 110 turns; tolerance: d in "
                      "0.50-0.52 m and I to its printed digit"),
        make_row("comsol-max-h", "Largest field in the COMSOL model (d = 0.5 m)", "thesis §2.3 (COMSOL)",
                 m["comsol-max-h"].value, h_comsol, tol_comsol, unit="A/m",
                 note="the exact field's maximum on both lines is its centre value"),
        make_row("sim-coil-resistance", "Resistance of each simulator coil", src, res.value, r_model, r_tol,
                 unit="ohm", uncertainty=res.uncertainty,
                 note="model: R = 2 pi a rho N / S0 with the thesis's copper"),
    ]
    for key, direction, fig in (("comsol-uniform-transverse", "transverse", 6), ("comsol-uniform-axial", "axial", 7)):
        row = m[key]
        length = coils.uniform_zone_length(a, d_comsol, ZONE_TOLERANCE, direction)
        rows.append(make_row(
            key, f"Uniform zone {'across the axis' if direction == 'transverse' else 'on the axis'} "
                 f"(Fig. {fig}), within {100 * ZONE_TOLERANCE:g} %", "thesis §2.3 (COMSOL, read off)",
            row.value, length, 0.05, unit="cm", scale=0.01,
            note="tolerance: 'of order' read as +-5 cm"))
    return rows


def magnetorquer_rows(params=None):
    """Chapter 3: the built magnetorquers beside the thesis's own formulas.

    One row is a measurement (the coil's resistance, ≈ 55 Ω); the others set a number the
    thesis printed for the built coil beside what its own equations give for it (square
    turn of side l, N = 240, 0.2 mm wire, 12 V). The resistance's tolerance is the spread
    of the model over the wire standard's diameter tolerance (IEC 60317-0-1, ±3 µm at
    0.2 mm) plus half a unit of the measured value's last digit; the others use half a unit
    of the printed value's last digit.

    Parameters
    ----------
    params : dict, optional
        Chapter-3 parameters (SI); defaults from :func:`magbench.params.chapter_parameters`.
    """
    from . import magnetorquer as mtq
    from .data import load_measurements, load_wire_table

    p = params or chapter_parameters("ch03")
    rho, u, side, n = p["copper_resistivity"], p["mtq_voltage"], p["mtq_side"], p["mtq_turns"]
    built = load_measurements("thesis")
    d = built["mtq-wire-diameter"].value
    table = load_wire_table("iec60317")
    d_tol = table.tolerance[int(np.argmin(np.abs(np.array(table.nominal_diameter) - d)))]

    def resistance(diameter):
        return float(mtq.coil_resistance(n, side, mtq.wire_area(diameter), rho, "square"))

    r_model, r_meas = resistance(d), built["mtq-resistance"].value
    r_spread = max(abs(resistance(d - d_tol) - r_model), abs(resistance(d + d_tol) - r_model))
    src = "thesis"
    square = mtq.turn_area(side, "square")
    s_design = mtq.wire_area_for_moment(p["mtq_moment"], u, side, rho)
    return [
        make_row("mtq-resistance", "Resistance of a built magnetorquer (0.2 mm wire, N = 240)",
                 f"{src} §3.3 (measured, ≈ 55 Ω)", r_meas, r_model, r_spread + 0.5,
                 unit="ohm", note=f"model spread over d ± {d_tol * 1e6:.0f} µm: ±{r_spread:.2f} Ω"),
        make_row("mtq-resistance-computed", "Resistance the thesis computed for the built coil",
                 f"{src} §3.3 (printed)", built["mtq-resistance-computed"].value, r_model,
                 0.05, unit="ohm"),
        make_row("mtq-moment", "Dipole moment of the built coil at 12 V (eq. 20)",
                 f"{src} §3.3 (printed)", built["mtq-moment"].value,
                 mtq.moment_from_voltage(u, side, mtq.wire_area(d), rho), 0.005, unit="A m^2",
                 note=f"with the measured resistance: {u / r_meas * n * float(square):.3f} A·m²"),
        make_row("mtq-power", "Joule power of the built coil at 12 V (measured resistance)",
                 "thesis §3.2 (the design's 2 W)", p["mtq_max_power"],
                 mtq.joule_power(u, r_meas), 0.5, unit="W"),
        make_row("mtq-current-for-moment", "Coil current for 0.4 A·m² (square, N = 240)",
                 "thesis §4.1 (printed)", 0.24,
                 mtq.current_for_moment(p["mtq_moment"], n, square), 0.005, unit="A"),
        make_row("mtq-winding-length", "Single-layer winding length N·√S_r at N = 240",
                 "thesis §3.2 (printed, ≈ 0.1 m)", 0.1,
                 mtq.winding_length(n, s_design), 0.05, unit="m"),
    ]


def bench_rows(params=None):
    """Chapter 4, the bench: the predicted final error band beside the thesis's 10°.

    The model is a nominal run of :func:`magbench.bench.simulate_bench` (release along
    the field at rest, datasheet sensor noise seeded with ``bench_seed``) for each of
    the thesis's two targets; its value is max |ψ − ψ_des| over the last
    ``bench_error_window`` of the run. The thesis prints "10 град. (~ 0.17 рад)" (seed
    line 616) without an uncertainty or a metric, so the tolerance is half a unit of
    its last printed digit, 0.5°.

    Parameters
    ----------
    params : dict, optional
        Chapter-4 parameters (SI); defaults from :func:`magbench.params.chapter_parameters`.
    """
    from . import bench
    from .data import measurement

    p = params or chapter_parameters("ch04")
    setup = bench.BenchSetup.from_parameters(p)
    measured = measurement("orientation-error")
    deg = np.pi / 180
    rows = []
    for tag, label, target in (("pi3", "π/3 (Fig. 19)", np.pi / 3), ("2pi3", "2π/3 (Fig. 20)", 2 * np.pi / 3)):
        run = bench.simulate_bench(setup, target, duration=p["bench_duration"],
                                   rng=np.random.default_rng(int(p["bench_seed"])),
                                   window=p["bench_error_window"])
        rows.append(make_row(
            f"bench-error-{tag}", f"Orientation error on the bench, ψ_des = {label}",
            "thesis §4.4 (measured; metric not stated)", measured.value,
            float(run.error_band[0]), 0.5 * deg, unit="deg", scale=deg,
            note="model: error band of the last window of a nominal simulated run"))
    return rows


#: Row providers by chapter, in book order.
PROVIDERS = {"ch01": geomagnetic_rows, "ch02": simulator_rows, "ch03": magnetorquer_rows,
             "ch04": bench_rows}


def all_rows():
    """Every model-vs-measurement row of the project, in chapter order."""
    rows = []
    for provider in PROVIDERS.values():
        rows.extend(provider())
    return rows


#: What the value a row compares with is (its ``measured`` column): a measurement, an
#: independent reference (a model fitted to measurements, such as IGRF), the source's
#: own simulation, or a value the source printed as its design or calculation.
ROW_KINDS = {
    "measurement": "measured by a person (on the bench or the coils)",
    "reference": "independent reference (IGRF-14, fitted to observatory and satellite data)",
    "simulation": "the source's own simulation (COMSOL)",
    "printed": "printed design or calculated value of the source",
}

_KIND_BY_ID = (
    ("dipole-", "reference"), ("pole-", "reference"), ("lab-", "reference"),
    ("equatorial-dipole-field", "reference"),
    ("comsol-", "simulation"),
    ("sim-center-h", "measurement"), ("sim-coil-resistance", "measurement"),
    ("mtq-resistance-computed", "printed"), ("mtq-resistance", "measurement"),
    ("mtq-moment", "printed"), ("mtq-power", "printed"), ("mtq-current-for-moment", "printed"),
    ("mtq-winding-length", "printed"),
    ("bench-error-", "measurement"),
)


def row_kind(row):
    """The kind of value a row's ``measured`` column holds: a key of :data:`ROW_KINDS`.

    A row whose id is not classified raises ``KeyError``: every new row must say
    whether it compares with a measurement, a reference, a simulation or a printed value.
    """
    for prefix, kind in _KIND_BY_ID:
        if row.id == prefix or (prefix.endswith("-") and row.id.startswith(prefix)):
            return kind
    raise KeyError(f"compare row {row.id!r} has no kind; add it to compare._KIND_BY_ID "
                   f"as one of {', '.join(ROW_KINDS)}")
