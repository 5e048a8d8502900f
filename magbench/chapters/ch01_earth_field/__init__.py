"""Chapter 1: the Earth's magnetic field and the principle of magnetic control.

Thesis §1 (pp. 4–11) and Kovalenko (1975) ch. 2: the thesis's dipole beside IGRF-14,
Kovalenko's field numbers, and the printed numbers of §1 beside their formulas.
"""

import itertools

import numpy as np

from ...earth import igrf
from ... import dynamics
from ... import earth
from ...compare import make_row
from ...constants import EARTH_POLAR_MOMENT_OF_INERTIA, EARTH_RADIUS, EARTH_ROTATION_RATE, MU_0
from ...io import load_parameter_set, load_printed
from ...errata import source_check
from ...units import DEG, ampere_per_meter_to_oersted, tesla_to_oersted
from ..._format import format_number
from .._base import Chapter, chapter_parameters

__all__ = ["CHAPTER", "INPUTS", "IGRF_NEWEST_EPOCH", "geomagnetic_rows", "geomagnetic_checks",
           "kovalenko_field_checks"]


#: The chapter's inputs: names in the parameter set of its source.
INPUTS = ("earth_dipole_moment", "earth_dipole_tilt", "geomagnetic_pole_latitude",
          "geomagnetic_pole_longitude", "earth_radius", "laboratory_latitude",
          "laboratory_longitude", "thesis_epoch", "orbit_altitude", "orbit_inclination",
          "mockup_inertia", "mockup_initial_rate")


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
        Decimal years for the dipole rows; default 1960 (the dipole the thesis copied) and
        the thesis's epoch. No row depends on the date of the build; the field of later
        years (up to :data:`IGRF_NEWEST_EPOCH`) is no test of a 2016 thesis and is left to
        the book's prose.
    """
    p = params or chapter_parameters("ch01")
    if epochs is None:
        epochs = (1960.0, p["thesis_epoch"])
    m, tilt = p["earth_dipole_moment"], p["earth_dipole_tilt"]
    plat, plon = p["geomagnetic_pole_latitude"], p["geomagnetic_pole_longitude"]
    # Half a unit in the last printed digit: 8.1e25 CGS, 11.5°, 78.5° N, 69° W.
    half_m, half_tilt, half_plat, half_plon = 0.05e22, 0.05 * DEG, 0.05 * DEG, 0.5 * DEG
    src = "IGRF-14 (ppigrf), degree 1"
    rows = []
    for year in epochs:
        d = igrf.igrf_dipole(year)
        tag = f"{year:.0f}" if float(year).is_integer() else f"{year:.2f}"
        rows += [
            make_row(f"dipole-moment-{tag}", f"Earth dipole moment, {tag}", src, d.moment, m, half_m,
                     unit="1e22 A m^2", scale=1e22),
            make_row(f"dipole-tilt-{tag}", f"Dipole tilt to the rotation axis, {tag}", src,
                     d.tilt, tilt, half_tilt, unit="deg", scale=DEG),
            make_row(f"pole-latitude-{tag}", f"Northern geomagnetic pole latitude, {tag}", src,
                     d.pole_latitude, plat, half_plat, unit="deg", scale=DEG),
            make_row(f"pole-longitude-{tag}", f"Northern geomagnetic pole longitude, {tag}", src,
                     d.pole_longitude, plon, half_plon, unit="deg", scale=DEG),
        ]
    # The full field at the laboratory when the bench was built.
    lat, lon, year = p["laboratory_latitude"], p["laboratory_longitude"], p["thesis_epoch"]
    f = igrf.igrf_field(lat, lon, year)

    def lab_elements(moment, pole_lat, pole_lon):
        return np.array(earth.dipole_elements(lat, lon, moment, pole_lat, pole_lon, p["earth_radius"]))

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
                 f.inclination, model[3], spread[3], unit="deg", scale=DEG),
    ]
    # The equatorial dipole field the thesis prints (0.31 Oe) against the real dipole.
    d = igrf.igrf_dipole(year)
    b0_igrf = earth.dipole_equatorial_b(d.moment, EARTH_RADIUS)
    b0_model = earth.dipole_equatorial_b(m, p["earth_radius"])
    rows.append(make_row("equatorial-dipole-field", f"Dipole field on the equator, {year:.0f}",
                         src, b0_igrf, b0_model, b0_model * half_m / m, unit="uT", scale=1e-6))
    return rows


def geomagnetic_checks():
    """Chapter 1: thesis §1 and Kovalenko ch. 2 (the dipole values), always on the
    thesis's own parameter set: overrides of a whole-book build change the chapter's
    figures and rows, never which printed numbers count as errata."""
    p = {name: par.value_si for name, par in load_parameter_set("thesis").items()}
    printed, kov = load_printed("thesis"), load_printed("kovalenko")
    m, r = p["earth_dipole_moment"], p["earth_radius"]
    lat, lon = p["laboratory_latitude"], p["laboratory_longitude"]
    phi = earth.geomagnetic_latitude(lat, lon, p["geomagnetic_pole_latitude"],
                                      p["geomagnetic_pole_longitude"])
    printed_j = float(np.arctan(-2.0 * np.tan(phi)))     # thesis eq. (3) as printed
    pole_h = float(tesla_to_oersted(earth.dipole_total_b(np.pi / 2, m, r)))

    g10, g11, h11 = (kov[k].value for k in ("kov-g10-1965", "kov-g11-1965", "kov-h11-1965"))
    b0_1965 = float(np.sqrt(g10**2 + g11**2 + h11**2))
    mean_dipole = float(tesla_to_oersted(earth.dipole_mean_surface_b(b0_1965)))

    jc, wc = p["mockup_inertia"], p["mockup_initial_rate"]
    exact = abs(float(dynamics.momentum_exchange_energy_ratio(
        jc, wc, -wc, EARTH_POLAR_MOMENT_OF_INERTIA, EARTH_ROTATION_RATE)))
    thesis_ratio = float(dynamics.thesis_energy_ratio(jc, EARTH_POLAR_MOMENT_OF_INERTIA))

    moment_l, field_h = p["mtq_moment"], p["sim_design_h"]      # thesis design values (§2.1 and §3.2)
    inclination_igrf = float(np.degrees(igrf.igrf_field(lat, lon, p["thesis_epoch"]).inclination))
    printed_m = load_parameter_set("thesis")["earth_dipole_moment"]
    cgs_moment = format_number(printed_m.value, 2)
    b0_printed = tuple(kov[k].value_as_printed for k in ("kov-g10-1965", "kov-g11-1965", "kov-h11-1965"))
    return [
        source_check(
            id="thesis-eq3-inclination-sign", chapter="ch01", source="thesis",
            location="§1.1, eqs. (1), (3) (from Kovalenko eq. 2.3)",
            quantity="Inclination I at the laboratory (St Petersburg) from eq. (3) (the thesis's J)",
            printed=float(np.degrees(printed_j)),
            computed=float(np.degrees(earth.dipole_inclination(phi))),
            tolerance=0.05, unit="deg",
            explanation=("Printed tan J = −2 tan Φ (and Z = −2M cos θ_M/R³) makes the field point "
                         "upwards in the northern hemisphere, against the thesis's own axes "
                         "(z down, J > 0 in the north). The magnitudes are right; the sign is not. "
                         f"IGRF gives {inclination_igrf:+.1f}° at the laboratory."),
            computation="magbench.earth.dipole_inclination",
        ),
        source_check(
            id="thesis-equator-field", chapter="ch01", source="thesis",
            location="§1.1, after eq. (3) (copied from Kovalenko p. 35)",
            quantity="Dipole field at the equator, M/R³",
            printed=printed["thesis-equator-field"].value_as_printed,
            computed=float(tesla_to_oersted(earth.dipole_equatorial_b(m, r))),
            tolerance=printed["thesis-equator-field"].resolution, unit="Oe",
            explanation=f"M/R³ with M = {cgs_moment} CGS and R = {r / 1e3:.0f} km.",
            computation="magbench.earth.dipole_equatorial_b",
        ),
        source_check(
            id="thesis-pole-field-rounding", chapter="ch01", source="thesis",
            location="§1.1, after eq. (3) (copied from Kovalenko p. 35)",
            quantity="Dipole field at the poles, 2M/R³",
            printed=printed["thesis-pole-field"].value_as_printed, computed=pole_h,
            tolerance=printed["thesis-pole-field"].resolution, unit="Oe",
            explanation=(f"2M/R³ with M = {cgs_moment} CGS and R = {r / 1e3:.0f} km is {pole_h:.4f} Oe, which "
                         f"rounds to {pole_h:.2f}; the printed {printed['thesis-pole-field'].value_as_printed:g} is "
                         f"twice the rounded equatorial {printed['thesis-equator-field'].value_as_printed:g}."),
            computation="magbench.earth.dipole_total_b",
        ),
        source_check(
            id="thesis-eq5-cgs-torque", chapter="ch01", source="thesis",
            location="§1.2, eq. (5)",
            quantity=f"Torque on a {moment_l:g} A·m² dipole across H = {field_h:g} A/m from eq. (5) as printed (M = L × H)",
            printed=moment_l * field_h,
            computed=float(np.linalg.norm(dynamics.magnetic_torque_from_h(
                [moment_l, 0.0, 0.0], [0.0, field_h, 0.0]))),
            tolerance=0.0, unit="N m",
            explanation=("M = L × H holds only in CGS units, where B = H in vacuum. In SI the "
                         "torque is μ0 L × H; read literally with SI inputs, eq. (5) is off by "
                         f"a factor 1/μ0 ≈ {format_number(1 / MU_0, 1)}."),
            computation="magbench.dynamics.magnetic_torque_from_h",
        ),
        source_check(
            id="thesis-eq12a-energy-ratio", chapter="ch01", source="thesis",
            location="§1.3",
            quantity="Energy handed to the Earth per unit lost by a despinning mock-up, ΔE_E/ΔE_c",
            printed=thesis_ratio, computed=exact, tolerance=0.0, unit="1",
            explanation=("The thesis sets ΔT_E/ΔT_c = |Δω_E/Δω_c| = J_c/J_E by treating Δ(ω²) as "
                         "(Δω)². Because the Earth already rotates, ΔT_E ≈ ω_E ΔK_E, and the exact "
                         "ratio is ≈ ω_E/ω̄_c: some 37 orders of magnitude larger than J_c/J_E, yet "
                         "still ≪ 1, so the conclusion (the Earth takes momentum, not energy) holds."),
            computation="magbench.dynamics.momentum_exchange_energy_ratio",
        ),
        source_check(
            id="kovalenko-mean-dipole-field", chapter="ch01", source="kovalenko",
            location="§2.2, p. 40",
            quantity="Mean dipole field over the Earth's surface, from the book's own Table 1",
            printed=float(ampere_per_meter_to_oersted(kov["kov-mean-field-dipole"].value)), computed=mean_dipole,
            tolerance=kov["kov-mean-field-dipole"].resolution, unit="Oe",
            explanation=("The closed-form surface mean of the dipole field with Table 1's g10, g11, "
                         f"h11 ({', '.join(f'{g:.0f}'.replace('-', '−') for g in b0_printed)} γ) is {mean_dipole:.4f} Oe; the book "
                         f"prints {kov['kov-mean-field-dipole'].value_as_printed:g}."),
            computation="magbench.earth.dipole_mean_surface_b",
        ),
    ]


def kovalenko_field_checks():
    """Kovalenko's (1975) mean and rms surface fields against IGRF-14 at 1965.0.

    The book computed them from the International Analytical Field 1965.0; IGRF-14's
    1965 model is the same field re-fitted (its dipole differs by 0.02 %), so the
    printed-digit tolerance applies.
    """
    from ...earth import igrf
    from ...constants import IGRF_REFERENCE_RADIUS

    kov = load_printed("kovalenko")
    g, h = igrf.igrf_gauss_coefficients(1965.0, max_degree=6)
    r_e = 6371.0e3                     # the book's Earth radius (p. 35)
    checks = []
    radii = {"R": r_e, "R1000": r_e + 1.0e6, "R2000": r_e + 2.0e6, "1.5R": 1.5 * r_e}
    for tag, radius in radii.items():
        spectrum = earth.lowes_spectrum(g, h, IGRF_REFERENCE_RADIUS / radius)
        for kind, value in (("field", np.sqrt(spectrum.sum())), ("dipole", np.sqrt(spectrum[0]))):
            row = kov[f"kov-rms-{kind}-{tag}"]
            checks.append(source_check(
                id=f"kovalenko-rms-{kind}-{tag}", chapter="ch01", source="kovalenko",
                location="Table 2, p. 40",
                quantity=f"RMS {'total' if kind == 'field' else 'dipole'} field at {row.conditions}",
                printed=float(ampere_per_meter_to_oersted(row.value)), computed=float(tesla_to_oersted(value)),
                tolerance=row.resolution, unit="Oe",
                explanation=("Lowes spectrum of IGRF-14 1965.0 up to degree 6 at the book's "
                             "R = 6371 km. Where the printed value is lower (R + 1000 km, 1.5R) the "
                             "table disagrees with itself too: its n = 1 entry at R + 1000 km (793.8) "
                             "is 0.6 % below the (R/r)⁶ scaling of its own entry at R (1915.3)."),
                computation="magbench.earth.lowes_spectrum"))
    mean6 = float(tesla_to_oersted(igrf.igrf_mean_surface_b(1965.0, max_degree=6)))
    mean1 = float(tesla_to_oersted(igrf.igrf_mean_surface_b(1965.0, max_degree=1)))
    checks += [
        source_check(id="kovalenko-mean-field-n6", chapter="ch01", source="kovalenko",
                    location="§2.2, p. 40",
                    quantity="Mean total field over the Earth's surface, degrees n ≤ 6",
                    printed=float(ampere_per_meter_to_oersted(kov["kov-mean-field-n6"].value)), computed=mean6,
                    tolerance=kov["kov-mean-field-n6"].resolution,
                    unit="Oe", explanation="Gauss–Legendre surface mean of |B| of IGRF-14 1965.0.",
                    computation="magbench.earth.igrf.igrf_mean_surface_b"),
        source_check(id="kovalenko-dipole-accuracy", chapter="ch01", source="kovalenko",
                    location="§2.2, p. 41",
                    quantity="Accuracy of the dipole approximation A₁ = T₁c/T_c",
                    printed=kov["kov-dipole-accuracy"].value * 100, computed=100 * mean1 / mean6,
                    tolerance=kov["kov-dipole-accuracy"].resolution, unit="%",
                    explanation="Ratio of the two surface means.",
                    computation="magbench.earth.igrf.igrf_mean_surface_b"),
    ]
    b = earth.orbital_dipole_b(np.linspace(0, 2 * np.pi, 3601), np.pi / 2, 7371e3, 8.1e22)
    b2 = np.sum(b**2, axis=-1)
    checks.append(source_check(
        id="kovalenko-polar-orbit-b2-ratio", chapter="ch01", source="kovalenko",
        location="p. 99", quantity="Largest/smallest B² on a circular geopolar orbit",
        printed=kov["kov-polar-orbit-b2-ratio"].value, computed=float(b2.max() / b2.min()),
        tolerance=kov["kov-polar-orbit-b2-ratio"].resolution, unit="1",
        explanation="Eq. (2.40) with i = 90°: |B|² ∝ 1 + 3 sin²u.",
        computation="magbench.earth.orbital_dipole_b"))
    return checks


CHAPTER = Chapter(
    key="ch01", title="The Earth's magnetic field and the principle of magnetic control",
    short_title="the Earth's field",
    pages=("book/ch01-earth-field",), source="thesis", inputs=INPUTS,
    figure_modules=("magbench.chapters.ch01_earth_field.figures",),
    comparisons=geomagnetic_rows,
    row_kinds=(("dipole-", "reference"), ("pole-", "reference"), ("lab-", "reference"),
               ("equatorial-dipole-field", "reference")),
    check_classes=(
        ("thesis-eq3-inclination-sign", "evaluated", "conclusion"),   # sign: the field points up
        ("thesis-equator-field", "printed", None),
        ("thesis-pole-field-rounding", "printed", None),
        ("thesis-eq5-cgs-torque", "evaluated", "conclusion"),          # missing µ0, the law the thesis uses
        ("thesis-eq12a-energy-ratio", "evaluated", "contained"),       # wrong formula, conclusion holds
        ("kovalenko-mean-dipole-field", "printed", None, "hand table"),
        ("kovalenko-rms-", "printed", None, "hand table"),
        ("kovalenko-mean-field-n6", "printed", None, "hand table"),
        ("kovalenko-dipole-accuracy", "printed", None, "hand table"),
        ("kovalenko-polar-orbit-b2-ratio", "printed", None),
    ),
    source_checks=(geomagnetic_checks, kovalenko_field_checks),
    concordance=(
        ("thesis", "§1.1, eqs. (1)–(3), Fig. 1", "field elements of a centred dipole; inclination",
         "{ref}`ch01`, {eq}`eq-ch01-elements`, {eq}`eq-ch01-inclination`, {numref}`thesis-fig01`, "
         "{numref}`ch01-field-elements`"),
        ("thesis", "§1.1, Fig. 2", "geomagnetic coordinates", "{numref}`thesis-fig02`"),
        ("thesis", "§1.2, eqs. (4)–(8)", "torque on a dipole, $\\mathbf L = \\mathbf m\\times\\mathbf B$",
         "{eq}`eq-ch01-torque`, {numref}`ch01-torque-plane`"),
        ("thesis", "§1.3, eqs. (9)–(12)", "energy exchanged with the Earth", "{ref}`ch01`"),
        ("kovalenko", "§2.2, Tables 1–2", "the geomagnetic field's coefficients and mean fields",
         "{ref}`ch01`"),
        ("kovalenko", "eqs. (2.36), (2.40)", "the dipole field along an orbit",
         "{eq}`eq-ch01-orbit`, {numref}`ch01-orbit-field`"),
    ),
    cites="thesis §1, eqs. (1)–(12), Figs. 1–2; Kovalenko ch. 1–2",
    finds=("how far the thesis's dipole is from the real field at the laboratory in 2016; which of Kovalenko's field numbers reproduce"),
    source_names=(("thesis", "thesis"), ("kovalenko", "Kovalenko (1975)")),
    discussed_in=(("dipole-", "ch01-dipole-quality"), ("pole-", "ch01-dipole-quality"),
                  ("lab-", "ch01-dipole-quality"), ("equatorial-dipole-field", "ch01-dipole-quality"),
                  ("thesis-eq3-inclination-sign", "ch01-elements"), ("thesis-equator-field", "ch01-elements"),
                  ("thesis-pole-field-rounding", "ch01-elements"), ("thesis-eq5-cgs-torque", "ch01-torque"),
                  ("thesis-eq12a-energy-ratio", "ch01-energy"), ("kovalenko-polar-orbit-b2-ratio", "ch01-orbit"),
                  ("kovalenko-", "ch01-kovalenko")),
)
