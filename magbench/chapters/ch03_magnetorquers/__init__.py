"""Chapter 3: magnetic actuators, sizing the magnetorquers.

Thesis §3 (pp. 21–25) and Kovalenko (1975) chs. 1, 8–10 and 12: the design chain of
thesis eq. (32), the built coils beside their measurement, Kovalenko's actuator numbers.
"""

import numpy as np

from ... import hardware
from ...compare import make_row
from ...io import load_measurements, load_parameter_set, load_printed
from ...errata import kovalenko_page, printed_check, source_check
from ..._format import format_number
from .._base import Chapter, chapter_parameters

__all__ = ["CHAPTER", "INPUTS", "magnetorquer_rows", "magnetorquer_checks", "magnetorquer_design_checks",
           "kovalenko_actuator_checks"]


#: The chapter's inputs: names in the parameter set of its source.
INPUTS = ("copper_resistivity", "copper_density", "mtq_moment", "mtq_voltage", "mtq_side",
          "mtq_turns", "mtq_max_power", "mtq_max_mass", "aluminium_gamma_rho", "magnet_remanence",
          "magnet_density", "alnico_max_magnetization", "alnico_elongation", "permalloy_a",
          "permalloy_b", "permalloy_design_magnetization", "permalloy_design_field", "core_density",
          "core_averaging_factor", "em_fill_factor", "em_current_density", "em_elongation")


def magnetorquer_rows(params=None):
    """Chapter 3: the built magnetorquers beside the thesis's own formulas.

    Two rows: the coil's measured resistance (≈ 55 Ω) beside the model of the built
    winding (square turn of side l, N = 240, 0.2 mm wire), and the design's power limit
    (2 W, a design value) beside the built coil's power at 12 V with the measured
    resistance. The numbers the thesis computed and printed for the built coil (its
    resistance, moment, current and winding length) are source checks
    (:func:`magnetorquer_checks`, :func:`magnetorquer_design_checks`), not rows. The resistance's tolerance is the spread of the
    model over the wire standard's diameter tolerance (IEC 60317-0-1, ±3 µm at 0.2 mm)
    plus half a unit of the measured value's last digit; the power's is half a unit of
    the limit's printed digit.

    Parameters
    ----------
    params : dict, optional
        Chapter-3 parameters (SI); defaults from :func:`magbench.params.chapter_parameters`.
    """
    from ...io import load_wire_table

    p = params or chapter_parameters("ch03")
    rho, u, side, n = p["copper_resistivity"], p["mtq_voltage"], p["mtq_side"], p["mtq_turns"]
    built = load_measurements("thesis")
    d = built["mtq-wire-diameter"].value
    table = load_wire_table("iec60317")
    d_tol = table.tolerance[int(np.argmin(np.abs(np.array(table.nominal_diameter) - d)))]

    def resistance(diameter):
        return float(hardware.coil_resistance(n, side, hardware.wire_area(diameter), rho, "square"))

    r_model, r_meas = resistance(d), built["mtq-resistance"].value
    r_spread = max(abs(resistance(d - d_tol) - r_model), abs(resistance(d + d_tol) - r_model))
    src = "thesis"
    return [
        make_row("mtq-resistance", "Resistance of a built magnetorquer (0.2 mm wire, N = 240)",
                 f"{src} §3.3 (measured, ≈ 55 Ω)", r_meas, r_model, r_spread + 0.5,
                 unit="ohm", note=f"model spread over d ± {d_tol * 1e6:.0f} µm: ±{r_spread:.2f} Ω"),
        make_row("mtq-power", "Joule power of the built coil at 12 V (measured resistance)",
                 "thesis §3.2 (the design's 2 W)", p["mtq_max_power"],
                 hardware.joule_power(u, r_meas), 0.5, unit="W"),
    ]


def magnetorquer_checks():
    """Thesis §3 (the magnetorquers) and Kovalenko's actuator examples: the printed
    values that do not reproduce (chapter 3 of the book walks through them)."""

    p = load_parameter_set("thesis")
    rho, u, side = p["copper_resistivity"].value_si, p["mtq_voltage"].value_si, p["mtq_side"].value_si
    m_req, n = p["mtq_moment"].value_si, p["mtq_turns"].value_si
    built, printed = load_measurements("thesis"), load_printed("thesis")
    s_built = hardware.wire_area(built["mtq-wire-diameter"].value)
    s_design = hardware.wire_area_for_moment(m_req, u, side, rho)
    m_built = float(hardware.moment_from_voltage(u, side, s_built, rho))
    r_square = float(hardware.coil_resistance(n, side, s_built, rho, "square"))
    m_mixed = u / r_square * n * float(hardware.turn_area(side, "round"))      # square-turn R, round-turn area
    i_for_m = float(hardware.current_for_moment(m_req, n, hardware.turn_area(side, "square")))
    length = float(hardware.winding_length(n, s_design))
    d_design, d_printed_area = float(hardware.wire_diameter(s_design)), float(hardware.wire_diameter(printed["thesis-mtq-wire-area"].value))
    kov_torque = float(hardware.magnet_torque_per_mass(1.4, 0.5e-4, 7.5e3))
    return [
        source_check(
            id="thesis-mtq-built-moment", chapter="ch03", source="thesis",
            location="§3.3", quantity="Dipole moment of the built coil at 12 V (eq. 20)",
            printed=printed["mtq-moment"].value, computed=m_built,
            tolerance=printed["mtq-moment"].resolution, unit="A m^2",
            explanation=(f"Eq. (20) with the {built['mtq-wire-diameter'].value * 1e3:g} mm wire gives {m_built:.3f} A·m² "
                         f"for round and square turns alike; {m_mixed:.2f} follows from mixing the square-turn "
                         f"resistance ({r_square:.1f} Ω) with the round-turn area πl²/4."),
            computation="magbench.hardware.moment_from_voltage"),
        source_check(
            id="thesis-mtq-current-for-moment", chapter="ch03", source="thesis",
            location="§4.1", quantity="Coil current for 0.4 A·m² (m = I S N, square, N = 240)",
            printed=printed["thesis-mtq-current-024"].value, computed=i_for_m,
            tolerance=printed["thesis-mtq-current-024"].resolution, unit="A",
            explanation=(f"I = m/(N l²) = {i_for_m:.3f} A; §4.1 then says "
                         f"{printed['thesis-mtq-current-025'].value:g} A, which fits neither."),
            computation="magbench.hardware.current_for_moment"),
        source_check(
            id="thesis-mtq-winding-length", chapter="ch03", source="thesis",
            location="§3.2", quantity="Single-layer winding length N·√S_r at N = 240",
            printed=printed["thesis-mtq-winding-length"].value, computed=length,
            tolerance=printed["thesis-mtq-winding-length"].resolution, unit="m",
            explanation=(f"N = L/√S_r (the thesis's own relation) gives L = {length:.3f} m, not "
                         f"≈ {printed['thesis-mtq-winding-length'].value:g} m."),
            computation="magbench.hardware.winding_length"),
        source_check(
            id="thesis-mtq-wire-area", chapter="ch03", source="thesis",
            location="§3.2", quantity="Conductor cross-section S_r = 4ρm/(Ul) (eq. 21)",
            printed=printed["thesis-mtq-wire-area"].value, computed=float(s_design),
            tolerance=printed["thesis-mtq-wire-area"].resolution, unit="m^2",
            explanation=(f"Eq. (21) gives {format_number(s_design, 4)} m², printed rounded up; the printed wire "
                         f"diameter {printed['thesis-mtq-wire-diameter'].value_as_printed:g} mm follows from "
                         f"{s_design * 1e8:.3f} ({d_design * 1e3:.3f} mm; 2.34 would give {d_printed_area * 1e3:.3f} mm)."),
            computation="magbench.hardware.wire_area_for_moment"),
        source_check(
            id="kovalenko-e02-torque-per-mass", chapter="ch03", source="kovalenko",
            location="eq. (1.7), p. 30",
            quantity="Torque per kilogram of permanent magnet (B_r = 1.4 T, B = 0.5·10⁻⁴ T, γ = 7500 kg/m³)",
            printed=load_printed("kovalenko")["kov-magnet-torque-per-mass"].value, computed=kov_torque,
            tolerance=load_printed("kovalenko")["kov-magnet-torque-per-mass"].resolution, unit="N m/kg",
            explanation=(f"B_r B/(μ0 γ) = {kov_torque * 1e2:.3f}·10⁻² N·m/kg, printed rounded up; "
                         f"{load_printed('kovalenko')['kov-magnet-mass-per-torque'].value:g} kg per N·m does reproduce."),
            computation="magbench.hardware.magnet_torque_per_mass"),
    ]


def magnetorquer_design_checks():
    """Thesis §3.2–3.3: the design chain of eq. (32), the chosen coil and the built one.

    The printed numbers that reproduce are listed too, so the chapter's table shows the
    whole chain; those that do not are the errata of :func:`magnetorquer_checks` and the
    built coil's power against the 2 W limit the thesis set itself.
    """

    p = load_parameter_set("thesis")
    rho, gamma = p["copper_resistivity"].value_si, p["copper_density"].value_si
    u, side, m_req = p["mtq_voltage"].value_si, p["mtq_side"].value_si, p["mtq_moment"].value_si
    w_max, m_max, n = p["mtq_max_power"].value_si, p["mtq_max_mass"].value_si, p["mtq_turns"].value_si
    built, printed = load_measurements("thesis"), load_printed("thesis")
    s_built = hardware.wire_area(built["mtq-wire-diameter"].value)
    s_design = hardware.wire_area_for_moment(m_req, u, side, rho)
    lo, hi = hardware.turns_per_volt_bounds(m_req, side, w_max, m_max, rho, gamma, "square")
    r_built = float(hardware.coil_resistance(n, side, s_built, rho, "square"))
    r_round = float(hardware.coil_resistance(n, side, s_built, rho, "round"))
    r_meas = built["mtq-resistance"].value
    mass_coefficient = float(hardware.coil_mass_for_moment(m_req, 1.0, 1.0, rho, gamma, "square"))
    power_coefficient = float(hardware.joule_power_for_moment(m_req, 1.0, 1.0, side, "square"))
    mass_round = float(hardware.coil_mass_for_moment(m_req, u, n, rho, gamma, "round"))
    p_built = float(hardware.joule_power(u, r_built))
    # The fewest turns that keep the built wire within the power limit: W = U²/R, R ∝ N.
    n_for_limit = int(hardware.wire_turn_limits(u, side, s_built, w_max, m_max, rho, gamma, "square")[0])
    sq = f"square turn of side l = {side:g} m (eqs. 28–31)"

    def check(id, row, location, computed, unit, explanation, computation, *, quantity=None, scale=1.0):
        return printed_check(printed[row], id=id, chapter="ch03", location=location,
                                        quantity=quantity, computed=computed, unit=unit, scale=scale,
                                        explanation=explanation,
                                        computation=f"magbench.hardware.{computation}")

    return [
        check("thesis-mtq-rho-rho", "thesis-mtq-rho-rho", "§3.2, eq. (32)", rho * gamma, "ohm kg/m^2",
              f"{rho * 1e6:g}·10⁻⁶ × {gamma / 1e3:g}·10³.", "mass_power_product",
              quantity="Product ργ of copper (the thesis writes ρρ̃)"),
        check("thesis-mtq-eq32-mass", "thesis-mtq-eq32-mass", "§3.2, eq. (32)", mass_coefficient, "kg V",
              f"{mass_coefficient * 1e3:.3f}·10⁻³ with the {sq}.", "coil_mass_for_moment",
              quantity="Mass coefficient 16ργm in m_c = c·N/U"),
        check("thesis-mtq-eq32-power", "thesis-mtq-eq32-power", "§3.2, eq. (32)", power_coefficient, "W/V",
              f"m/l² = {power_coefficient:g} with the {sq}.", "joule_power_for_moment",
              quantity="Power coefficient m/l² in P = c·U/N"),
        check("thesis-mtq-turns-min", "thesis-mtq-turns-min", "§3.2", lo * u, "1",
              f"{u:g} V × the printed N/U ≥ {lo:.0f}; tolerance {u:g} × half a unit of {lo:.0f}.",
              "turns_per_volt_bounds", quantity=f"Fewest turns for P ≤ {w_max:g} W at {u:g} V"),
        check("thesis-mtq-turns-max", "thesis-mtq-turns-max", "§3.2", hi * u, "1",
              f"{hi * u:.1f}: the thesis rounded 16ργm = {mass_coefficient * 1e3:.3f}·10⁻³ to 10⁻³.",
              "turns_per_volt_bounds", quantity=f"Most turns for m_c ≤ {m_max:g} kg at {u:g} V"),
        check("thesis-mtq-design-mass", "thesis-mtq-design-mass", "§3.2",
              hardware.coil_mass_for_moment(m_req, u, n, rho, gamma, "square"), "kg",
              f"Eq. (29), {sq}; a round turn would give {mass_round:.4f} kg.", "coil_mass_for_moment",
              quantity=f"Conductor mass at N = {n:.0f}"),
        check("thesis-mtq-design-power", "thesis-mtq-design-power", "§3.2",
              hardware.joule_power_for_moment(m_req, u, n, side, "square"), "W", "Eq. (28).",
              "joule_power_for_moment", quantity=f"Joule power at N = {n:.0f}"),
        check("thesis-mtq-wire-diameter", "thesis-mtq-wire-diameter", "§3.2", hardware.wire_diameter(s_design), "m",
              f"√(4S_r/π) with S_r = {format_number(s_design, 4)} m².", "wire_diameter"),
        check("thesis-mtq-resistance", "mtq-resistance-computed", "§3.3", r_built, "ohm",
              f"N·ρ·4l/S_r with the {sq}; {r_round:.1f} Ω if the turn were round.", "coil_resistance",
              quantity=f"Resistance of the built coil ({built['mtq-wire-diameter'].value * 1e3:g} mm, N = {n:.0f})"),
        check("thesis-mtq-resistance-excess", "thesis-mtq-resistance-excess", "§3.3",
              100.0 * (r_meas - r_built) / r_built, "%", f"({r_meas:g} − {r_built:.2f})/{r_built:.2f}.",
              "coil_resistance",
              quantity=f"Excess of the measured ≈ {r_meas:g} Ω over the computed resistance"),
        check("thesis-mtq-built-power", "thesis-mtq-design-power", "§3.2–3.3", p_built, "W",
              (f"The {built['mtq-wire-diameter'].value * 1e3:g} mm wire (thicker than the {d_mm(s_design)} mm "
               f"design) at N = {n:.0f} draws {u:g}²/{r_built:.1f} = {p_built:.2f} W with the computed "
               f"resistance ({float(hardware.joule_power(u, r_meas)):.2f} W with the measured ≈ {r_meas:g} Ω), "
               f"above the P ≤ {w_max:g} W limit the thesis set itself; N ≥ {n_for_limit} turns would keep it."),
              "joule_power",
              quantity=f"Joule power of the built coil at {u:g} V, against the design's {w_max:g} W"),
        check("thesis-mtq-current-025", "thesis-mtq-current-025", "§4.1",
              hardware.current_for_moment(m_req, n, hardware.turn_area(side, "square")), "A",
              (f"I = m/(N l²) = {float(hardware.current_for_moment(m_req, n, hardware.turn_area(side, 'square'))):.3f} A; "
               f"§4.1 says {printed['thesis-mtq-current-024'].value:g} A a few lines earlier for the same moment."),
              "current_for_moment", quantity=f"Coil current for {m_req:g} A·m² (second value)"),
    ]


def d_mm(area):
    """Wire diameter [mm, 3 decimals] of a conductor cross-section [m²], for explanations."""

    return f"{float(hardware.wire_diameter(area)) * 1e3:.3f}"


def kovalenko_actuator_checks():
    """Kovalenko's (1975) worked examples on magnets and cored rods (his §1.3, ch. 9, 10, 12)."""

    kov = load_printed("kovalenko")
    p = load_parameter_set("thesis")
    j_al, p0 = p["alnico_max_magnetization"].value_si, p["alnico_elongation"].value_si
    length1, diameter1, _ = hardware.permanent_magnet_min_mass(1.0, j_al, p0, 1.0)
    table5_p = kov["kov-table5-p75"].value
    calc = 4 * np.pi * float(hardware.rod_demagnetizing_factor(table5_p))
    measured40, computed40 = kov["kov-table5-measured-p40"].value, kov["kov-table5-computed-p40"].value
    mass_per_torque = float(hardware.magnet_mass_for_torque(1.0, 1.4, 0.5e-4, 7.5e3))
    transit = float(hardware.rod_demagnetizing_factor(248.0))

    def check(id, row, quantity, computed, unit, explanation, computation, scale=1.0):
        r = kov[row]
        return printed_check(r, id=id, chapter="ch03", location=f"§{r.section}, p. {kovalenko_page(r.seed_line)}",
                                        quantity=quantity, computed=computed, unit=unit, scale=scale,
                                        explanation=explanation, computation=f"magbench.hardware.{computation}")

    return [
        check("kovalenko-e02-mass-per-torque", "kov-magnet-mass-per-torque",
              "Magnet mass per N·m of torque (B_r = 1.4 T, B = 0.5·10⁻⁴ T, γ = 7500 kg/m³)",
              mass_per_torque, "kg/(N m)", f"μ0 γ/(B_r B) = {mass_per_torque:.1f} kg per N·m.",
              "magnet_mass_for_torque"),
        check("kovalenko-e36-length-coefficient", "kov-pm-length-coefficient",
              f"Least-mass magnet: l = c·∛m, coefficient c (YuN13DK25BA AlNiCo, p₀ = {p0:g})", length1,
              "m/(A m^2)^(1/3)",
              f"(4p₀²/(π J_c max))^(1/3) = {length1:.5f} with J_c max = {j_al / 1e5:.1f}·10⁵ A/m.",
              "permanent_magnet_min_mass"),
        check("kovalenko-e36-diameter-ratio", "kov-pm-diameter-ratio",
              "Least-mass magnet: d/l = 1/p₀", diameter1 / length1, "1", f"1/{p0:g} = {1 / p0:.4f}.",
              "permanent_magnet_min_mass"),
        check("kovalenko-table5-power-law", "kov-table5-calc-p75",
              f"Table 5, central demagnetising factor 4πN_c by (9.25) at p = {table5_p:g} (the row that deviates most)", calc, "1",
              (f"4π·0.93·p^−1.7 = {calc:.5f}. The whole 'computed' column deviates from the formula by "
               "0.2–1.4 % (slide-rule arithmetic, presumably); (9.25) still fits the measured column "
               "within 5 %."), "rod_demagnetizing_factor"),
        check("kovalenko-table5-nu-p40", "kov-table5-nu-p40",
              "Table 5, deviation ν at p = 40", 100 * (computed40 - measured40) / measured40, "%",
              (f"({computed40:g} − {measured40:g})/{measured40:g} = "
               f"{100 * (computed40 - measured40) / measured40:.2f} %: a misplaced decimal point.")
              .replace("-", "−"), "rod_demagnetizing_factor"),
        check("kovalenko-e45-transit-rod", "kov-transit-rod-demag",
              "Central demagnetising factor of the Transit rods, p = 248 (9.25)",
              transit, "1", f"0.93·248^−1.7 = {transit * 1e4:.3f}·10⁻⁴.", "rod_demagnetizing_factor"),
    ]


CHAPTER = Chapter(
    key="ch03", title="Magnetic actuators: sizing the magnetorquers",
    short_title="the magnetorquers",
    pages=("book/ch03-magnetorquers",), source="thesis", inputs=INPUTS,
    figure_modules=("magbench.chapters.ch03_magnetorquers.figures",),
    comparisons=magnetorquer_rows,
    row_kinds=(("mtq-resistance", "measurement"), ("mtq-power", "design")),
    check_classes=(
        ("thesis-mtq-built-moment", "printed", "downstream"),
        ("thesis-mtq-current-for-moment", "printed", "contained"),
        ("thesis-mtq-current-025", "printed", "contained"),
        ("thesis-mtq-winding-length", "printed", "contained"),
        ("thesis-mtq-built-power", "printed", "conclusion"),          # the built coil breaks the design limit
        ("thesis-mtq-", "printed", None),
        ("kovalenko-table5-nu-p40", "printed", "contained"),          # a misplaced decimal point
        ("kovalenko-table5-", "printed", None, "hand table"),
        ("kovalenko-", "printed", None),
    ),
    source_checks=(magnetorquer_checks, magnetorquer_design_checks, kovalenko_actuator_checks),
    concordance=(
        ("thesis", "§3.1–3.2, eqs. (17)–(32)", "sizing a magnetorquer",
         "{ref}`ch03`, {eq}`eq-ch03-moment`, {eq}`eq-ch03-eq20`, {eq}`eq-ch03-wm`, {numref}`ch03-design-space`, "
         "{numref}`ch03-wm-product`"),
        ("thesis", "§3.3, Fig. 9", "the built coils on the mock-up", "{numref}`thesis-fig09`"),
        ("kovalenko", "ch. 8–11", "magnets, rods and coils as actuators", "{ref}`ch03`"),
    ),
    cites="thesis §3, eqs. (17)–(32), Fig. 9; Kovalenko ch. 8–11",
    finds=("which magnetorquer designs real wire allows, and whether the built coils meet the thesis's own limits"),
    source_names=(("thesis", "thesis"), ("kovalenko", "Kovalenko (1975)")),
    discussed_in=(("mtq-resistance", "ch03-built"), ("mtq-power", "ch03-built"),
                  ("thesis-mtq-resistance", "ch03-built"), ("thesis-mtq-resistance-excess", "ch03-built"),
                  ("thesis-mtq-built-", "ch03-built"), ("thesis-mtq-current-", "ch03-built"),
                  ("thesis-mtq-", "ch03-derivation"), ("kovalenko-", "ch03-kovalenko")),
)
