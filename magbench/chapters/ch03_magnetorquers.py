"""Chapter 3: magnetic actuators, sizing the magnetorquers.

Thesis §3 (pp. 21–25) and Kovalenko (1975) chs. 1, 8–10 and 12: the design chain of
thesis eq. (32), the built coils beside their measurement, Kovalenko's actuator numbers.
"""

import numpy as np

from ..compare import make_row
from ..io import load_measurements, load_parameter_set
from ..errata import SourceCheck, kovalenko_page
from ._base import Chapter, chapter_parameters

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
    from .. import magnetorquer as mtq
    from ..io import load_measurements, load_wire_table

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


def magnetorquer_checks():
    """Thesis §3 (the magnetorquers) and Kovalenko's actuator examples: the printed
    values that do not reproduce (chapter 3 of the book walks through them)."""
    from .. import magnetorquer as mtq

    p = load_parameter_set("thesis")
    rho, u, side = p["copper_resistivity"].value_si, p["mtq_voltage"].value_si, p["mtq_side"].value_si
    m_req, n = p["mtq_moment"].value_si, p["mtq_turns"].value_si
    built = load_measurements("thesis")
    s_built = mtq.wire_area(built["mtq-wire-diameter"].value)
    s_design = mtq.wire_area_for_moment(m_req, u, side, rho)
    return [
        SourceCheck(
            id="thesis-mtq-built-moment", chapter="ch03", source="thesis",
            location="§3.3", quantity="Dipole moment of the built coil at 12 V (eq. 20)",
            printed=built["mtq-moment"].value, computed=float(mtq.moment_from_voltage(u, side, s_built, rho)),
            tolerance=0.005, unit="A m^2",
            explanation=("Eq. (20) with the 0.2 mm wire gives 0.539 A·m² for round and square turns "
                         "alike; 0.42 follows from mixing the square-turn resistance (53.5 Ω) with the "
                         "round-turn area πl²/4."),
            computation="magbench.magnetorquer.moment_from_voltage"),
        SourceCheck(
            id="thesis-mtq-current-for-moment", chapter="ch03", source="thesis",
            location="§4.1", quantity="Coil current for 0.4 A·m² (m = I S N, square, N = 240)",
            printed=0.24, computed=float(mtq.current_for_moment(m_req, n, mtq.turn_area(side, "square"))),
            tolerance=0.005, unit="A",
            explanation="I = m/(N l²) = 0.167 A; line 524 then says 0.25 A, which fits neither.",
            computation="magbench.magnetorquer.current_for_moment"),
        SourceCheck(
            id="thesis-mtq-winding-length", chapter="ch03", source="thesis",
            location="§3.2", quantity="Single-layer winding length N·√S_r at N = 240",
            printed=0.1, computed=float(mtq.winding_length(n, s_design)), tolerance=0.05, unit="m",
            explanation="N = L/√S_r (the thesis's own relation) gives L = 0.037 m, not ≈ 0.1 m.",
            computation="magbench.magnetorquer.winding_length"),
        SourceCheck(
            id="thesis-mtq-wire-area", chapter="ch03", source="thesis",
            location="§3.2", quantity="Conductor cross-section S_r = 4ρm/(Ul) (eq. 21)",
            printed=2.34e-8, computed=float(s_design), tolerance=0.005e-8, unit="m^2",
            explanation=("Eq. (21) gives 2.333·10⁻⁸ m², printed rounded up; the printed wire diameter "
                         "0.172 mm follows from 2.333 (2.34 would give 0.173 mm)."),
            computation="magbench.magnetorquer.wire_area_for_moment"),
        SourceCheck(
            id="kovalenko-e02-torque-per-mass", chapter="ch03", source="kovalenko",
            location="eq. (1.7), p. 30",
            quantity="Torque per kilogram of permanent magnet (B_r = 1.4 T, B = 0.5·10⁻⁴ T, γ = 7500 kg/m³)",
            printed=load_measurements("kovalenko")["kov-magnet-torque-per-mass"].value,
            computed=float(mtq.magnet_torque_per_mass(1.4, 0.5e-4, 7.5e3)),
            tolerance=0.005e-2, unit="N m/kg",
            explanation="B_r B/(μ0 γ) = 0.743·10⁻² N·m/kg, printed rounded up; 135 kg per N·m does reproduce.",
            computation="magbench.magnetorquer.magnet_torque_per_mass"),
    ]


def magnetorquer_design_checks():
    """Thesis §3.2–3.3: the design chain of eq. (32), the chosen coil and the built one.

    The printed numbers that reproduce are listed too, so the chapter's table shows the
    whole chain; those that do not are the errata of :func:`magnetorquer_checks` and the
    built coil's power against the 2 W limit the thesis set itself.
    """
    from .. import magnetorquer as mtq

    p = load_parameter_set("thesis")
    rho, gamma = p["copper_resistivity"].value_si, p["copper_density"].value_si
    u, side, m_req = p["mtq_voltage"].value_si, p["mtq_side"].value_si, p["mtq_moment"].value_si
    w_max, m_max, n = p["mtq_max_power"].value_si, p["mtq_max_mass"].value_si, p["mtq_turns"].value_si
    built = load_measurements("thesis")
    s_built = mtq.wire_area(built["mtq-wire-diameter"].value)
    s_design = mtq.wire_area_for_moment(m_req, u, side, rho)
    lo, hi = mtq.turns_per_volt_bounds(m_req, side, w_max, m_max, rho, gamma, "square")
    r_built = float(mtq.coil_resistance(n, side, s_built, rho, "square"))
    r_meas = built["mtq-resistance"].value
    sq = "square turn of side l = 0.1 m (eqs. 28–31)"

    def check(id, location, quantity, printed, computed, tolerance, unit, explanation, computation):
        return SourceCheck(id=id, chapter="ch03", source="thesis", location=location,
                           quantity=quantity, printed=printed, computed=float(computed),
                           tolerance=tolerance, unit=unit, explanation=explanation,
                           computation=f"magbench.magnetorquer.{computation}")

    return [
        check("thesis-mtq-rho-rho", "§3.2, eq. (32)", "Product ρρ̃ of copper", 0.156e-3,
              rho * gamma, 0.0005e-3, "ohm kg/m^2", "0.0175·10⁻⁶ × 8.9·10³.", "mass_power_product"),
        check("thesis-mtq-eq32-mass", "§3.2, eq. (32)", "Mass coefficient 16ρρ̃m in M = c·N/U",
              1e-3, mtq.coil_mass_for_moment(m_req, 1.0, 1.0, rho, gamma, "square"), 0.5e-3, "kg V",
              f"0.997·10⁻³ with the {sq}.", "coil_mass_for_moment"),
        check("thesis-mtq-eq32-power", "§3.2, eq. (32)", "Power coefficient m/l² in W = c·U/N",
              40.0, mtq.joule_power_for_moment(m_req, 1.0, 1.0, side, "square"), 0.5, "W/V",
              f"m/l² = 40 with the {sq}.", "joule_power_for_moment"),
        check("thesis-mtq-turns-min", "§3.2", "Fewest turns for W ≤ 2 W at 12 V",
              240.0, lo * u, 6.0, "1", "12 V × the printed N/U ≥ 20; tolerance 12 × half a unit of 20.",
              "turns_per_volt_bounds"),
        check("thesis-mtq-turns-max", "§3.2", "Most turns for M ≤ 0.1 kg at 12 V",
              1200.0, hi * u, 6.0, "1", "1203.8: the thesis rounded 16ρρ̃m = 0.997·10⁻³ to 10⁻³.",
              "turns_per_volt_bounds"),
        check("thesis-mtq-design-mass", "§3.2", "Conductor mass at N = 240", 0.02,
              mtq.coil_mass_for_moment(m_req, u, n, rho, gamma, "square"), 0.005, "kg",
              f"Eq. (29), {sq}; a round turn would give 0.0157 kg.", "coil_mass_for_moment"),
        check("thesis-mtq-design-power", "§3.2", "Joule power at N = 240", 2.0,
              mtq.joule_power_for_moment(m_req, u, n, side, "square"), 0.5, "W", "Eq. (28).",
              "joule_power_for_moment"),
        check("thesis-mtq-wire-diameter", "§3.2", "Wire diameter for S_r of eq. (21)",
              0.172e-3, mtq.wire_diameter(s_design), 0.0005e-3, "m", "√(4S_r/π) with S_r = 2.333·10⁻⁸ m².",
              "wire_diameter"),
        check("thesis-mtq-resistance", "§3.3", "Resistance of the built coil (0.2 mm, N = 240)",
              built["mtq-resistance-computed"].value, r_built, 0.05, "ohm",
              f"N·ρ·4l/S_r with the {sq}; 42.0 Ω if the turn were round.", "coil_resistance"),
        check("thesis-mtq-resistance-excess", "§3.3",
              "Excess of the measured ≈ 55 Ω over the computed resistance", 3.0,
              100.0 * (r_meas - r_built) / r_built, 0.5, "%", "(55 − 53.48)/53.48.", "coil_resistance"),
        check("thesis-mtq-built-power", "§3.2–3.3",
              "Joule power of the built coil at 12 V, against the design's 2 W", 2.0,
              mtq.joule_power(u, r_built), 0.5, "W",
              ("The 0.2 mm wire (thicker than the 0.172 mm design) at N = 240 draws 12²/53.5 = 2.69 W, "
               "above the W ≤ 2 W limit the thesis set itself; N ≥ 324 turns would keep it."),
              "joule_power"),
        check("thesis-mtq-current-025", "§4.1", "Coil current for 0.4 A·m² (second value)",
              0.25, mtq.current_for_moment(m_req, n, mtq.turn_area(side, "square")), 0.005, "A",
              "I = m/(N l²) = 0.167 A; line 516 says 0.24 A for the same moment.", "current_for_moment"),
    ]


def kovalenko_actuator_checks():
    """Kovalenko's (1975) worked examples on magnets and cored rods (his §1.3, ch. 9, 10, 12)."""
    from .. import magnetorquer as mtq

    kov = load_measurements("kovalenko")
    p = load_parameter_set("thesis")
    j_al, p0 = p["alnico_max_magnetization"].value_si, p["alnico_elongation"].value_si
    length1, diameter1, _ = mtq.permanent_magnet_min_mass(1.0, j_al, p0, 1.0)
    table5_p = 75.63
    calc = 4 * np.pi * float(mtq.rod_demagnetizing_factor(table5_p))

    def check(id, row, quantity, computed, tolerance, unit, explanation, computation, scale=1.0):
        r = kov[row]
        return SourceCheck(id=id, chapter="ch03", source="kovalenko",
                           location=f"§{r.section}, p. {kovalenko_page(r.seed_line)}", quantity=quantity,
                           printed=r.value * scale, computed=float(computed), tolerance=tolerance,
                           unit=unit, explanation=explanation,
                           computation=f"magbench.magnetorquer.{computation}")

    return [
        check("kovalenko-e02-mass-per-torque", "kov-magnet-mass-per-torque",
              "Magnet mass per N·m of torque (B_r = 1.4 T, B = 0.5·10⁻⁴ T, γ = 7500 kg/m³)",
              mtq.magnet_mass_for_torque(1.0, 1.4, 0.5e-4, 7.5e3), 0.5, "kg/(N m)",
              "μ0 γ/(B_r B) = 134.6 kg per N·m.", "magnet_mass_for_torque"),
        check("kovalenko-e36-length-coefficient", "kov-pm-length-coefficient",
              "Least-mass magnet: l = c·∛L, coefficient c (ЮН13ДК25БА, p₀ = 7)", length1, 0.0005,
              "m/(A m^2)^(1/3)", "(4p₀²/(π J_c max))^(1/3) = 0.04203 with J_c max = 8.4·10⁵ A/m.",
              "permanent_magnet_min_mass"),
        check("kovalenko-e36-diameter-ratio", "kov-pm-diameter-ratio",
              "Least-mass magnet: d/l = 1/p₀", diameter1 / length1, 0.0005, "1", "1/7 = 0.1429.",
              "permanent_magnet_min_mass"),
        check("kovalenko-table5-power-law", "kov-table5-calc-p75",
              "Table 5, 4πN_ц by (9.25) at p = 75.63 (the row that deviates most)", calc, 0.000005, "1",
              ("4π·0.93·p^−1.7 = 0.00748. The whole 'computed' column deviates from the formula by "
               "0.2–1.4 % (slide-rule arithmetic, presumably); (9.25) still fits the measured column "
               "within 5 %."), "rod_demagnetizing_factor"),
        check("kovalenko-table5-nu-p40", "kov-table5-nu-p40",
              "Table 5, deviation ν at p = 40", 100 * (0.0218 - 0.0223) / 0.0223, 0.005, "%",
              "(0.0218 − 0.0223)/0.0223 = −2.24 %: a misplaced decimal point.", "rod_demagnetizing_factor",
              scale=100.0),
        check("kovalenko-e45-transit-rod", "kov-transit-rod-demag",
              "Central demagnetising factor of the Transit rods, p = 248 (9.25)",
              mtq.rod_demagnetizing_factor(248.0), 0.005e-4, "1", "0.93·248^−1.7 = 0.791·10⁻⁴.",
              "rod_demagnetizing_factor"),
    ]


CHAPTER = Chapter(
    key="ch03", title="Magnetic actuators: sizing the magnetorquers",
    short_title="the magnetorquers",
    pages=("book/ch03-magnetorquers",), source="thesis", inputs=INPUTS,
    figure_modules=("magbench.figures.thesis_ch3",),
    comparisons=magnetorquer_rows,
    row_kinds=(("mtq-resistance-computed", "printed"), ("mtq-resistance", "measurement"),
               ("mtq-moment", "printed"), ("mtq-power", "printed"),
               ("mtq-current-for-moment", "printed"), ("mtq-winding-length", "printed")),
    source_checks=(magnetorquer_checks, magnetorquer_design_checks, kovalenko_actuator_checks),
)
