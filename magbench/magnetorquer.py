r"""Magnetorquers: air-core coils (thesis §3, eqs. 17–32), cored rods and permanent magnets.

Thesis §3.1–3.3 (eqs. 17–32, seed lines 320–445) sizes the mock-up's two coils; Kovalenko
(1975) ch. 1, 8 and 9 supplies the general forms (fill factor, demagnetising factors of
rods, permanent-magnet torque per mass). Everything is SI: metres, A·m², ohms, watts,
kilograms, volts.

Geometry. A turn has the characteristic size ``side`` = l: the diameter of a round turn
(``shape="round"``, area πl²/4, length πl) or the side of a square turn
(``shape="square"``, area l², length 4l). Round and square formulas differ only by the
factor π/4 in the turn area and length, so one function with a ``shape`` keyword serves
both. The conductor is a round wire of bare diameter d and cross-section S_r = πd²/4.

What the thesis gets right and wrong (recomputed here; see the tests):

* The algebra of eqs. (17)–(31) is correct. Seed line 384 says the square formulas differ
  from "(23, 25, 26, 27)" by the factor π/4; in fact (28) = (π/4)·(22), (29) = (4/π)·(25),
  (31) = (4/π)·(27), and (30) is identical to (26): the mass × power product does not
  depend on the shape. (23) is cited where (22) is meant.
* Eq. (32) and the design at N = 240 (mass 0.02 kg, power 2 W, d = 0.172 mm, R = 53.5 Ω
  for the 0.2 mm wire) reproduce with the square-turn formulas. The printed
  S_r = 2.34·10⁻⁸ m² (seed line 431) is 2.333·10⁻⁸ m² rounded up; d = 0.172 mm follows from
  the exact value.
* The single-layer winding length "L ≈ 0.1 m" (seed line 434) is N√S_r ≈ 0.037 m.
* The built coil's moment "0.42 A·m²" (seed line 441) is 0.539 A·m² by eq. (20); 0.42 is
  obtained only by mixing the square-turn resistance with the round-turn area.
* The current "I₁ = 0.24 A" for 0.4 A·m² (seed line 516) is 0.167 A (square, N = 240).
* The built coil draws 12²/53.5 = 2.69 W, above the thesis's own 2 W limit (seed line 410).
"""

import math

import numpy as np

from ._validate import as_finite, as_in_range, as_nonnegative, as_positive
from .constants import MU_0

__all__ = [
    "SHAPES",
    "turn_area",
    "turn_length",
    "wire_area",
    "wire_diameter",
    "dipole_moment",
    "current_for_moment",
    "coil_current",
    "turn_resistance",
    "coil_resistance",
    "moment_from_voltage",
    "wire_area_for_moment",
    "joule_power",
    "joule_power_for_moment",
    "joule_power_for_winding_length",
    "turns_from_winding_length",
    "winding_length",
    "coil_mass",
    "coil_mass_for_moment",
    "mass_power_product",
    "winding_density",
    "mass_power_product_kovalenko",
    "supply_voltage",
    "turns_per_volt_bounds",
    "design_magnetorquer",
    "awg_diameter",
    "turns_from_resistance",
    "wire_diameter_from_resistance",
    "rod_demagnetizing_factor",
    "effective_permeability",
    "magnet_torque_per_mass",
    "magnet_mass_for_torque",
    "magnetization_curve",
    "field_for_magnetization",
    "core_central_magnetization",
    "electromagnet_design",
    "magnet_moment_per_mass",
    "permanent_magnet_min_mass",
]

#: The turn shapes understood by the ``shape`` keyword.
SHAPES = ("round", "square")

# Relative slack when an exactly-at-the-limit design (the thesis's N = 240) is compared
# with a limit after floating-point arithmetic.
_RTOL = 1e-12

# Largest number of (turns, wire) rows the design solver will enumerate.
_MAX_ROWS = 2_000_000


def _check_shape(shape):
    if not isinstance(shape, str) or shape not in SHAPES:
        raise ValueError(f"shape must be one of {SHAPES}, got {shape!r}")
    return shape


def _area_factor(shape):
    """S / l²: π/4 for a round turn, 1 for a square one."""
    return np.pi / 4.0 if _check_shape(shape) == "round" else 1.0


def _length_factor(shape):
    """Turn length / l: π for a round turn, 4 for a square one."""
    return np.pi if _check_shape(shape) == "round" else 4.0


def turn_area(side, shape="round"):
    r"""Area enclosed by one turn.

    Parameters
    ----------
    side : array_like
        Turn diameter (round) or side (square), thesis symbol l [m].
    shape : {"round", "square"}, optional
        Turn shape [-].

    Returns
    -------
    ndarray
        S = πl²/4 (round) or l² (square) [m²].

    Notes
    -----
    Thesis eq. (19), seed line 340 ("S = πl²/4"); the square area l² is implied by eqs. (28)–(31).

    Examples
    --------
    >>> float(turn_area(0.1, "square"))
    0.010000000000000002
    """
    k = _area_factor(shape)
    return k * as_positive("side", side, unit="m") ** 2


def turn_length(side, shape="round"):
    r"""Length of conductor in one turn.

    Parameters
    ----------
    side : array_like
        Turn diameter (round) or side (square) l [m].
    shape : {"round", "square"}, optional
        Turn shape [-].

    Returns
    -------
    ndarray
        πl (round) or 4l (square) [m].

    Notes
    -----
    Thesis eq. (19), seed line 338 (πl) and eq. (31), seed line 382 (4l).

    Examples
    --------
    >>> round(float(turn_length(0.1, "round")), 4)
    0.3142
    """
    k = _length_factor(shape)
    return k * as_positive("side", side, unit="m")


def wire_area(diameter):
    r"""Conductor cross-section of a round wire.

    Parameters
    ----------
    diameter : array_like
        Bare conductor diameter d [m].

    Returns
    -------
    ndarray
        S_r = πd²/4 [m²].

    Notes
    -----
    Thesis §3.2, seed line 431 (S_r "corresponds to d = 0.172 mm") and §3.3, seed line 439.

    Examples
    --------
    >>> round(float(wire_area(0.2e-3)) * 1e8, 4)
    3.1416
    """
    d = as_positive("diameter", diameter, unit="m")
    return np.pi * d**2 / 4.0


def wire_diameter(area):
    r"""Bare diameter of a round wire of a given conductor cross-section.

    Parameters
    ----------
    area : array_like
        Conductor cross-section S_r [m²].

    Returns
    -------
    ndarray
        d = √(4 S_r/π) [m].

    Notes
    -----
    Thesis §3.2, seed line 431: S_r "corresponds to d = 0.172 mm". The d = 0.172 mm follows
    from the exact S_r = 2.333·10⁻⁸ m² of eq. (21); the printed S_r = 2.34·10⁻⁸ m² is rounded
    up and would give 0.173 mm.

    Examples
    --------
    >>> round(float(wire_diameter(2.34e-8)) * 1e3, 3)
    0.173
    >>> round(float(wire_diameter(4 * 0.0175e-6 * 0.4 / 1.2)) * 1e3, 3)
    0.172
    """
    s = as_positive("area", area, unit="m²")
    return np.sqrt(4.0 * s / np.pi)


def dipole_moment(current, turns, area):
    r"""Magnetic dipole moment of a flat coil.

    Parameters
    ----------
    current : array_like
        Current I [A] (its sign gives the moment's sense).
    turns : array_like
        Number of turns N [-].
    area : array_like
        Area enclosed by one turn S [m²] (see :func:`turn_area`).

    Returns
    -------
    ndarray
        m = I S N [A·m²].

    Notes
    -----
    Thesis eq. (17), seed line 330 (Kovalenko 1975 eq. 8.2).

    Examples
    --------
    >>> round(float(dipole_moment(12 / 53.5, 240, turn_area(0.1, "square"))), 3)
    0.538
    """
    i = as_finite("current", current)
    n = as_positive("turns", turns)
    s = as_positive("area", area, unit="m²")
    return i * s * n


def current_for_moment(moment, turns, area):
    r"""Current that gives a coil a required dipole moment.

    Parameters
    ----------
    moment : array_like
        Required dipole moment m [A·m²].
    turns : array_like
        Number of turns N [-].
    area : array_like
        Area enclosed by one turn S [m²].

    Returns
    -------
    ndarray
        I = m/(S N) [A].

    Notes
    -----
    Thesis eq. (17), seed line 330, solved for I. The thesis's "I₁ = 0.24 A" for
    m₁ = 0.4 A·m² (seed line 516) is not reproduced: the square 0.1 m coil of N = 240
    needs 0.167 A (0.212 A if the turn were round).

    Examples
    --------
    >>> round(float(current_for_moment(0.4, 240, turn_area(0.1, "square"))), 4)
    0.1667
    """
    m = as_finite("moment", moment)
    n = as_positive("turns", turns)
    s = as_positive("area", area, unit="m²")
    return m / (s * n)


def coil_current(voltage, turn_resistance, turns):
    r"""Current drawn by a coil from a voltage source.

    Parameters
    ----------
    voltage : array_like
        Supply voltage U [V].
    turn_resistance : array_like
        Resistance of one turn r [Ω] (see :func:`turn_resistance`).
    turns : array_like
        Number of turns N [-].

    Returns
    -------
    ndarray
        I = U/(r N) [A].

    Notes
    -----
    Thesis eq. (18), seed line 334.

    Examples
    --------
    >>> round(float(coil_current(12.0, 53.5 / 240, 240)), 4)
    0.2243
    """
    u = as_finite("voltage", voltage)
    r = as_positive("turn_resistance", turn_resistance, unit="Ω")
    n = as_positive("turns", turns)
    return u / (r * n)


def turn_resistance(side, wire_area, resistivity, shape="round"):
    r"""Resistance of one turn.

    Parameters
    ----------
    side : array_like
        Turn diameter (round) or side (square) l [m].
    wire_area : array_like
        Conductor cross-section S_r [m²].
    resistivity : array_like
        Conductor resistivity ρ [Ω·m] (the thesis's copper: 0.0175·10⁻⁶).
    shape : {"round", "square"}, optional
        Turn shape [-].

    Returns
    -------
    ndarray
        r = ρ πl/S_r (round) or ρ 4l/S_r (square) [Ω].

    Notes
    -----
    Thesis eq. (19), seed line 338 (round); the square form is the r inside eq. (31),
    seed line 382.

    Examples
    --------
    >>> round(float(turn_resistance(0.1, wire_area(0.2e-3), 0.0175e-6, "square")), 4)
    0.2228
    """
    length = turn_length(side, shape)
    s = as_positive("wire_area", wire_area, unit="m²")
    rho = as_positive("resistivity", resistivity, unit="Ω·m")
    return rho * length / s


def coil_resistance(turns, side, wire_area, resistivity, shape="round"):
    r"""Resistance of a coil of N turns.

    Parameters
    ----------
    turns : array_like
        Number of turns N [-].
    side : array_like
        Turn diameter (round) or side (square) l [m].
    wire_area : array_like
        Conductor cross-section S_r [m²].
    resistivity : array_like
        Conductor resistivity ρ [Ω·m].
    shape : {"round", "square"}, optional
        Turn shape [-].

    Returns
    -------
    ndarray
        R = N r [Ω], with r from eq. (19).

    Notes
    -----
    Thesis §3.3, seed line 439 ("R = N·r = 53.5 Ω" for 0.2 mm wire, N = 240); reproduced with the
    square turn (42.0 Ω if the turn were round).

    Examples
    --------
    >>> round(float(coil_resistance(240, 0.1, wire_area(0.2e-3), 0.0175e-6, "square")), 2)
    53.48
    """
    n = as_positive("turns", turns)
    return n * turn_resistance(side, wire_area, resistivity, shape)


def moment_from_voltage(voltage, side, wire_area, resistivity):
    r"""Dipole moment of a coil driven at a fixed voltage.

    Parameters
    ----------
    voltage : array_like
        Supply voltage U [V].
    side : array_like
        Turn diameter (round) or side (square) l [m].
    wire_area : array_like
        Conductor cross-section S_r [m²].
    resistivity : array_like
        Conductor resistivity ρ [Ω·m].

    Returns
    -------
    ndarray
        m = U l S_r/(4ρ) [A·m²], whatever the number of turns.

    Notes
    -----
    Thesis eq. (20), seed line 342. It holds unchanged for round and square turns (the
    factor π/4 cancels between area and length), so there is no ``shape`` keyword. The
    thesis's "0.42 A·m²" for the built coil (seed line 441: U = 12 V, 0.2 mm wire,
    l = 0.1 m) is not reproduced: eq. (20) gives 0.539 A·m².

    Examples
    --------
    >>> round(float(moment_from_voltage(12.0, 0.1, wire_area(0.2e-3), 0.0175e-6)), 3)
    0.539
    """
    u = as_finite("voltage", voltage)
    l = as_positive("side", side, unit="m")
    s = as_positive("wire_area", wire_area, unit="m²")
    rho = as_positive("resistivity", resistivity, unit="Ω·m")
    return u * l * s / (4.0 * rho)


def wire_area_for_moment(moment, voltage, side, resistivity):
    r"""Conductor cross-section that gives a required moment at a fixed voltage.

    Parameters
    ----------
    moment : array_like
        Required dipole moment m [A·m²].
    voltage : array_like
        Supply voltage U [V].
    side : array_like
        Turn diameter (round) or side (square) l [m].
    resistivity : array_like
        Conductor resistivity ρ [Ω·m].

    Returns
    -------
    ndarray
        S_r = 4ρm/(U l) [m²], for either turn shape.

    Notes
    -----
    Thesis eq. (21), seed line 346. The thesis prints S_r = 2.34·10⁻⁸ m² (seed line 431) for
    m = 0.4 A·m², U = 12 V, l = 0.1 m; the value is 2.333·10⁻⁸ m² (rounded up by 0.3 %).

    Examples
    --------
    >>> round(float(wire_area_for_moment(0.4, 12.0, 0.1, 0.0175e-6)) * 1e8, 3)
    2.333
    """
    m = as_positive("moment", moment, unit="A·m²")
    u = as_positive("voltage", voltage, unit="V")
    l = as_positive("side", side, unit="m")
    rho = as_positive("resistivity", resistivity, unit="Ω·m")
    return 4.0 * rho * m / (u * l)


def joule_power(voltage, resistance):
    r"""Joule power dissipated by a coil at a fixed voltage.

    Parameters
    ----------
    voltage : array_like
        Supply voltage U [V].
    resistance : array_like
        Coil resistance R = rN [Ω].

    Returns
    -------
    ndarray
        W = U²/R [W].

    Notes
    -----
    Thesis eq. (TH-W), seed line 348: W = U²/(rN).

    Examples
    --------
    >>> round(float(joule_power(12.0, 53.5)), 2)   # the built coil, above the 2 W limit
    2.69
    """
    u = as_finite("voltage", voltage)
    r = as_positive("resistance", resistance, unit="Ω")
    return u**2 / r


def joule_power_for_moment(moment, voltage, turns, side, shape="round"):
    r"""Joule power of a coil sized by eq. (21) for a required moment.

    Parameters
    ----------
    moment : array_like
        Dipole moment m [A·m²].
    voltage : array_like
        Supply voltage U [V].
    turns : array_like
        Number of turns N [-].
    side : array_like
        Turn diameter (round) or side (square) l [m].
    shape : {"round", "square"}, optional
        Turn shape [-].

    Returns
    -------
    ndarray
        W = (4m/(πl²))·U/N (round) or (m/l²)·U/N (square) [W]: m U/(S N).

    Notes
    -----
    Thesis eq. (22), seed line 350 (round) and eq. (28), seed line 376 (square); the
    square value is π/4 times the round one, not the reverse as seed line 384 reads.

    Examples
    --------
    >>> round(float(joule_power_for_moment(0.4, 12.0, 240, 0.1, "square")), 6)
    2.0
    """
    m = as_positive("moment", moment, unit="A·m²")
    u = as_positive("voltage", voltage, unit="V")
    n = as_positive("turns", turns)
    return m * u / (turn_area(side, shape) * n)


def turns_from_winding_length(winding_length, wire_area):
    r"""Turns of a dense single-layer winding of a given length.

    Parameters
    ----------
    winding_length : array_like
        Axial length of the winding L [m].
    wire_area : array_like
        Conductor cross-section S_r [m²]; √S_r stands for the wire pitch.

    Returns
    -------
    ndarray
        N = L/√S_r [-] (not rounded to an integer).

    Notes
    -----
    Thesis eq. (TH-N), seed line 352. The pitch √S_r = 0.886 d ignores the enamel; a real
    winding of pitch d + 2t has fewer turns (see :func:`design_magnetorquer`).

    Examples
    --------
    >>> round(float(turns_from_winding_length(0.1, 2.34e-8)))
    654
    """
    length = as_positive("winding_length", winding_length, unit="m")
    s = as_positive("wire_area", wire_area, unit="m²")
    return length / np.sqrt(s)


def winding_length(turns, wire_area):
    r"""Axial length of a dense single-layer winding of N turns.

    Parameters
    ----------
    turns : array_like
        Number of turns N [-].
    wire_area : array_like
        Conductor cross-section S_r [m²].

    Returns
    -------
    ndarray
        L = N√S_r [m].

    Notes
    -----
    Thesis eq. (TH-N), seed line 352, solved for L. The thesis's "L ≈ 0.1 m" for N = 240
    and S_r = 2.34·10⁻⁸ m² (seed line 434) is not reproduced: L = 0.037 m.

    Examples
    --------
    >>> round(float(winding_length(240, 2.34e-8)), 4)
    0.0367
    """
    n = as_positive("turns", turns)
    s = as_positive("wire_area", wire_area, unit="m²")
    return n * np.sqrt(s)


def joule_power_for_winding_length(moment, voltage, winding_length, wire_area, side, shape="round"):
    r"""Joule power of a dense single-layer coil of a given winding length.

    Parameters
    ----------
    moment : array_like
        Dipole moment m [A·m²].
    voltage : array_like
        Supply voltage U [V].
    winding_length : array_like
        Axial length of the winding L [m].
    wire_area : array_like
        Conductor cross-section S_r [m²].
    side : array_like
        Turn diameter (round) or side (square) l [m].
    shape : {"round", "square"}, optional
        Turn shape [-].

    Returns
    -------
    ndarray
        W = (4m/(πl²))·U√S_r/L (round; m/l² instead of 4m/(πl²) for a square turn) [W].

    Notes
    -----
    Thesis eq. (23), seed line 354: eq. (22) with N = L/√S_r.

    Examples
    --------
    >>> w = joule_power_for_winding_length(0.4, 12.0, 0.1, 2.34e-8, 0.1, "square")
    >>> round(float(w), 3)
    0.734
    """
    n = turns_from_winding_length(winding_length, wire_area)
    return joule_power_for_moment(moment, voltage, n, side, shape)


def coil_mass(turns, side, wire_area, density, shape="round"):
    r"""Mass of the conductor in a coil.

    Parameters
    ----------
    turns : array_like
        Number of turns N [-].
    side : array_like
        Turn diameter (round) or side (square) l [m].
    wire_area : array_like
        Conductor cross-section S_r [m²].
    density : array_like
        Conductor density ρ̃ [kg/m³] (the thesis's copper: 8.9·10³).
    shape : {"round", "square"}, optional
        Turn shape [-].

    Returns
    -------
    ndarray
        M = ρ̃ πl S_r N (round) or ρ̃ 4l S_r N (square) [kg]; enamel and former excluded.

    Notes
    -----
    Thesis eq. (24), seed line 358 (round); the square form is the one behind eq. (29).

    Examples
    --------
    >>> round(float(coil_mass(240, 0.1, wire_area(0.2e-3), 8.9e3, "square")), 4)
    0.0268
    """
    n = as_positive("turns", turns)
    s = as_positive("wire_area", wire_area, unit="m²")
    g = as_positive("density", density, unit="kg/m³")
    return g * turn_length(side, shape) * s * n


def coil_mass_for_moment(moment, voltage, turns, resistivity, density, shape="round"):
    r"""Conductor mass of a coil sized by eq. (21) for a required moment.

    Parameters
    ----------
    moment : array_like
        Dipole moment m [A·m²].
    voltage : array_like
        Supply voltage U [V].
    turns : array_like
        Number of turns N [-].
    resistivity : array_like
        Conductor resistivity ρ [Ω·m].
    density : array_like
        Conductor density ρ̃ [kg/m³].
    shape : {"round", "square"}, optional
        Turn shape [-].

    Returns
    -------
    ndarray
        M = 4π ρ̃ρ m N/U (round) or 16 ρρ̃ m N/U (square) [kg], independent of l.

    Notes
    -----
    Thesis eq. (25), seed line 362 (round) and eq. (29), seed line 378 (square).

    Examples
    --------
    >>> round(float(coil_mass_for_moment(0.4, 12.0, 240, 0.0175e-6, 8.9e3, "square")), 4)
    0.0199
    """
    m = as_positive("moment", moment, unit="A·m²")
    u = as_positive("voltage", voltage, unit="V")
    n = as_positive("turns", turns)
    rho = as_positive("resistivity", resistivity, unit="Ω·m")
    g = as_positive("density", density, unit="kg/m³")
    return 4.0 * _length_factor(shape) * g * rho * m * n / u


def mass_power_product(moment, side, resistivity, density):
    r"""Product of conductor mass and Joule power of a coil of given moment.

    Parameters
    ----------
    moment : array_like
        Dipole moment m [A·m²].
    side : array_like
        Turn diameter (round) or side (square) l [m].
    resistivity : array_like
        Conductor resistivity ρ [Ω·m].
    density : array_like
        Conductor density ρ̃ [kg/m³].

    Returns
    -------
    ndarray
        M·W = 16 m² ρ̃ρ/l² [kg·W], independent of N, U and the turn shape.

    Notes
    -----
    Thesis eq. (26), seed line 366 (round) and eq. (30), seed line 380 (square); the two
    are identical, contrary to the "factor π/4" of seed line 384. Kovalenko's form with a
    fill factor is :func:`mass_power_product_kovalenko`.

    Examples
    --------
    >>> round(float(mass_power_product(0.4, 0.1, 0.0175e-6, 8.9e3)), 4)
    0.0399
    """
    m = as_positive("moment", moment, unit="A·m²")
    l = as_positive("side", side, unit="m")
    rho = as_positive("resistivity", resistivity, unit="Ω·m")
    g = as_positive("density", density, unit="kg/m³")
    return 16.0 * m**2 * g * rho / l**2


def winding_density(fill_factor, conductor_density, insulation_density):
    r"""Mean density of a winding of conductor, insulation and compound.

    Parameters
    ----------
    fill_factor : array_like
        Winding fill factor k_з = conductor volume / winding volume [-], in (0, 1].
    conductor_density : array_like
        Conductor density γ_п [kg/m³].
    insulation_density : array_like
        Density of the insulation and compound γ_н [kg/m³].

    Returns
    -------
    ndarray
        γ_к = k_з γ_п + (1 − k_з) γ_н [kg/m³].

    Notes
    -----
    Not in the thesis: Kovalenko (1975) eq. (8.5), p. 170.

    Examples
    --------
    >>> float(winding_density(0.5, 8.9e3, 1.8e3))
    5350.0
    """
    k = as_in_range("fill_factor", fill_factor, 0.0, 1.0)
    if np.any(k == 0):
        raise ValueError("fill_factor must lie in (0, 1] [-], got 0.0")
    gp = as_positive("conductor_density", conductor_density, unit="kg/m³")
    gn = as_nonnegative("insulation_density", insulation_density, unit="kg/m³")
    return k * gp + (1.0 - k) * gn


def mass_power_product_kovalenko(moment, diameter, resistivity, density, fill_factor=1.0):
    r"""Kovalenko's mass × power product of a flat air-core coil, with a fill factor.

    Parameters
    ----------
    moment : array_like
        Dipole moment L_K [A·m²].
    diameter : array_like
        Mean winding diameter D [m] (for a square coil: the side, as in eq. (30)).
    resistivity : array_like
        Conductor resistivity ρ [Ω·m].
    density : array_like
        Mean winding density γ_к [kg/m³] (see :func:`winding_density`; with
        ``fill_factor=1`` it is the conductor density).
    fill_factor : array_like, optional
        Winding fill factor k_з [-], in (0, 1].

    Returns
    -------
    ndarray
        m_к P_K = 16 γ_к ρ L_K²/(k_з D²) [kg·W], independent of the current density,
        the number of turns and the voltage.

    Notes
    -----
    Not in the thesis: Kovalenko (1975) eqs. (8.9) × (8.11), pp. 170–171 (the product itself
    is not printed there): m_к = 4γ_к L_K/(D k_з j) and P_K = 4ρ j L_K/D.

    With k_з = 1, γ_к = ρ̃ and D = l it is the thesis's eq. (26)/(30),
    M_K W = 16 m² ρ̃ρ/l² (:func:`mass_power_product`). The fill factor enters through
    the winding mass (insulation and voids) at a fixed conductor current density; for a
    real winding γ_к/k_з > γ_п, so the thesis's expression is a lower bound.

    Examples
    --------
    >>> round(float(mass_power_product_kovalenko(0.4, 0.1, 0.0175e-6, 8.9e3)), 4)
    0.0399
    >>> g = winding_density(0.5, 8.9e3, 1.8e3)
    >>> round(float(mass_power_product_kovalenko(0.4, 0.1, 0.0175e-6, g, 0.5)), 4)
    0.0479
    """
    m = as_positive("moment", moment, unit="A·m²")
    d = as_positive("diameter", diameter, unit="m")
    rho = as_positive("resistivity", resistivity, unit="Ω·m")
    g = as_positive("density", density, unit="kg/m³")
    k = as_in_range("fill_factor", fill_factor, 0.0, 1.0)
    if np.any(k == 0):
        raise ValueError("fill_factor must lie in (0, 1] [-], got 0.0")
    return 16.0 * g * rho * m**2 / (k * d**2)


def supply_voltage(current, turns, side, wire_area, resistivity, shape="round"):
    r"""Voltage that drives a given current through a coil.

    Parameters
    ----------
    current : array_like
        Current I [A].
    turns : array_like
        Number of turns N [-].
    side : array_like
        Turn diameter (round) or side (square) l [m].
    wire_area : array_like
        Conductor cross-section S_r [m²].
    resistivity : array_like
        Conductor resistivity ρ [Ω·m].
    shape : {"round", "square"}, optional
        Turn shape [-].

    Returns
    -------
    ndarray
        U = I r N = ρ (πl/S_r) I N (round) or ρ (4l/S_r) I N (square) [V].

    Notes
    -----
    Thesis eq. (27), seed line 372 (round) and eq. (31), seed line 382 (square).

    Examples
    --------
    >>> u = supply_voltage(0.4 / (0.01 * 240), 240, 0.1, 2.34e-8, 0.0175e-6, "square")
    >>> round(float(u), 2)
    11.97
    """
    i = as_finite("current", current)
    return i * coil_resistance(turns, side, wire_area, resistivity, shape)


def turns_per_volt_bounds(moment, side, max_power, max_mass, resistivity, density, shape="round"):
    r"""Range of turns per volt N/U allowed by a power limit and a mass limit.

    Parameters
    ----------
    moment : array_like
        Required dipole moment m [A·m²].
    side : array_like
        Turn diameter (round) or side (square) l [m].
    max_power : array_like
        Joule power limit W_max [W].
    max_mass : array_like
        Conductor mass limit M_max [kg].
    resistivity : array_like
        Conductor resistivity ρ [Ω·m].
    density : array_like
        Conductor density ρ̃ [kg/m³].
    shape : {"round", "square"}, optional
        Turn shape [-].

    Returns
    -------
    low, high : ndarray
        W ≤ W_max needs N/U ≥ low; M ≤ M_max needs N/U ≤ high [1/V]. The design is
        impossible where low > high, i.e. where the mass × power product (26)/(30)
        exceeds M_max·W_max.

    Notes
    -----
    Thesis eq. (32), seed lines 420–426 (with the square formulas (28)–(29)); the thesis
    rounds 16ρρ̃m = 0.997·10⁻³ kg·V to 10⁻³ and so prints 20 ≤ N/U ≤ 100.

    Examples
    --------
    >>> lo, hi = turns_per_volt_bounds(0.4, 0.1, 2.0, 0.1, 0.0175e-6, 8.9e3, "square")
    >>> round(float(lo), 3), round(float(hi), 2)
    (20.0, 100.32)
    """
    w_max = as_positive("max_power", max_power, unit="W")
    m_max = as_positive("max_mass", max_mass, unit="kg")
    # Power and mass per unit of U/N and N/U (the coefficients 40 and 10⁻³ of eq. 32).
    power_coef = joule_power_for_moment(moment, 1.0, 1.0, side, shape)
    mass_coef = coil_mass_for_moment(moment, 1.0, 1.0, resistivity, density, shape)
    return power_coef / w_max, m_max / mass_coef


def design_magnetorquer(
    moment,
    voltage,
    side,
    shape,
    max_power,
    max_mass,
    wire_diameters,
    resistivity,
    density,
    enamel_thickness=10e-6,
    *,
    winding_length=None,
    max_layers=1,
    require_fit=False,
    overall_diameters=None,
):
    r"""Every feasible (turns, wire) design of an air-core magnetorquer, and the best two.

    A coil of N turns of wire of bare diameter d, driven at the voltage U, has
    R = N ρ P/S_r (P the turn length), draws I = U/R and W = U²/R, weighs
    M = ρ̃ P S_r N and has the moment m = I S N = U l S_r/(4ρ), independent of N (eq. 20).
    So the wire fixes the moment, and N trades power against mass. A design is feasible
    when its moment is at least ``moment``, W ≤ ``max_power`` and M ≤ ``max_mass``; every
    integer N for every listed wire is tried.

    Parameters
    ----------
    moment : float
        Required dipole moment m [A·m²].
    voltage : float
        Supply voltage U [V].
    side : float
        Turn diameter (round) or side (square) l [m].
    shape : {"round", "square"}
        Turn shape [-].
    max_power : float
        Joule power limit per coil W_max [W].
    max_mass : float
        Conductor mass limit per coil M_max [kg].
    wire_diameters : array_like, shape (k,)
        Bare conductor diameters available [m] (a wire table).
    resistivity : float
        Conductor resistivity ρ [Ω·m].
    density : float
        Conductor density ρ̃ [kg/m³].
    enamel_thickness : float, optional
        Radial thickness of the enamel t [m]; the wire pitch is d + 2t. Used only for the
        winding-fit check. The default 10 µm is an order of magnitude, not a standard
        value: 0.100 mm grade-1 enamelled wire measures 0.108–0.117 mm overall (4–8.5 µm
        radial; Elektrisola data quoted at enameled-wires.com, Technical-Documentation/341),
        thicker wires carry somewhat more. Take the value from the wire's datasheet.
    winding_length : float, optional
        Axial length available for one layer [m]; default ``side``, the thesis's
        assumption of a single-layer winding as long as the face (seed line 434).
    max_layers : int, optional
        Number of layers the former can hold [-].
    require_fit : bool, optional
        If true, designs whose winding does not fit are not feasible [-].
    overall_diameters : array_like, shape (k,), optional
        Overall (enamelled) diameter of each wire of ``wire_diameters`` [m], e.g. the
        maximum overall diameter of a wire standard's table; when given it is the winding
        pitch and ``enamel_thickness`` is not used. Each must exceed its bare diameter.

    Returns
    -------
    dict
        ``"turns"`` (int), ``"wire_diameter"`` [m], ``"wire_area"`` [m²], ``"resistance"``
        [Ω], ``"current"`` [A], ``"power"`` [W], ``"mass"`` [kg], ``"moment"`` [A·m²],
        ``"pitch"`` (d + 2t, or the overall diameter) [m], ``"layer_length"``
        (single-layer winding length N·pitch) [m], ``"layers"`` (int), ``"fits"`` (bool)
        and ``"fill_factor"`` (conductor cross-section N S_r over the winding window
        ``winding_length`` × layers·pitch it occupies) [-]: one array entry per feasible
        design, ordered by wire diameter then turns. ``"min_power"`` and ``"min_mass"``: the feasible design of
        least power and of least mass, each a dict of scalars, or None. ``"feasible"``
        (bool), ``"binding_limit"`` (None, ``"moment"``, ``"power and mass"``,
        ``"integer turns"`` or ``"winding fit"``) and ``"explanation"`` (str).

    Notes
    -----
    Not in the thesis: an enumeration over a wire table of thesis eqs. (17)–(31); the
    thesis solves the continuous problem (eq. 32) and then picks 0.2 mm wire at N = 240,
    which this solver rejects (2.69 W > 2 W). The infeasibility test is the mass × power
    product, eq. (26)/(30): with the thinnest adequate wire, M·W = 16ρρ̃m_w²/l² must not
    exceed M_max·W_max, where m_w ≥ m is that wire's moment.

    Examples
    --------
    >>> res = design_magnetorquer(0.4, 12.0, 0.1, "square", 2.0, 0.1, [0.18e-3, 0.2e-3],
    ...                           0.0175e-6, 8.9e3)
    >>> best = res["min_mass"]
    >>> int(best["turns"]), round(best["wire_diameter"] * 1e3, 2), round(best["power"], 3)
    (262, 0.18, 1.998)
    >>> design_magnetorquer(0.4, 12.0, 0.1, "square", 1.0, 0.02, [0.2e-3], 0.0175e-6,
    ...                     8.9e3)["binding_limit"]
    'power and mass'
    """
    m_req = float(as_positive("moment", moment, unit="A·m²"))
    u = float(as_positive("voltage", voltage, unit="V"))
    l = float(as_positive("side", side, unit="m"))
    _check_shape(shape)
    w_max = float(as_positive("max_power", max_power, unit="W"))
    m_max = float(as_positive("max_mass", max_mass, unit="kg"))
    d_all = np.atleast_1d(as_positive("wire_diameters", wire_diameters, unit="m"))
    if d_all.ndim != 1 or d_all.size == 0:
        raise ValueError(
            f"wire_diameters must be a non-empty 1-D array, got shape {d_all.shape}"
        )
    if overall_diameters is None:
        d_all = np.unique(d_all)
        od_all = d_all + 2.0 * float(as_nonnegative("enamel_thickness", enamel_thickness, unit="m"))
    else:
        od_all = np.atleast_1d(as_positive("overall_diameters", overall_diameters, unit="m"))
        if od_all.shape != d_all.shape:
            raise ValueError(f"overall_diameters must have the shape of wire_diameters {d_all.shape}, "
                             f"got {od_all.shape}")
        if np.any(od_all <= d_all):
            k = int(np.argmax(od_all <= d_all))
            raise ValueError(f"overall_diameters must exceed the bare diameters, got {od_all[k]!r} m "
                             f"for wire_diameters {d_all[k]!r} m")
        if np.unique(d_all).size != d_all.size:
            raise ValueError("wire_diameters must not repeat a size when overall_diameters are given")
        order = np.argsort(d_all)
        d_all, od_all = d_all[order], od_all[order]
    rho = float(as_positive("resistivity", resistivity, unit="Ω·m"))
    gamma = float(as_positive("density", density, unit="kg/m³"))
    as_nonnegative("enamel_thickness", enamel_thickness, unit="m")   # checked even when unused
    length_avail = l if winding_length is None else float(
        as_positive("winding_length", winding_length, unit="m"))
    if isinstance(max_layers, bool) or not isinstance(max_layers, (int, np.integer)) or max_layers < 1:
        raise ValueError(f"max_layers must be an integer >= 1, got {max_layers!r}")

    area = float(turn_area(l, shape))
    perimeter = float(turn_length(l, shape))

    cols = {k: [] for k in ("turns", "wire_diameter", "wire_area", "resistance", "current",
                            "power", "mass", "moment", "pitch", "layer_length", "layers", "fits",
                            "fill_factor")}
    adequate = []          # wires that reach the moment: (d, n_lo, n_hi)
    n_rows = 0
    any_power_mass = False
    for d, pitch in zip(d_all, od_all):
        s_r = math.pi * d**2 / 4.0
        r = rho * perimeter / s_r
        m_wire = u * l * s_r / (4.0 * rho)
        if m_wire < m_req * (1.0 - _RTOL):
            continue
        n_lo = max(1, math.ceil(u**2 / (r * w_max) * (1.0 - _RTOL)))
        n_hi = math.floor(m_max / (gamma * perimeter * s_r) * (1.0 + _RTOL))
        adequate.append((d, n_lo, n_hi))
        if n_hi < n_lo:
            continue
        any_power_mass = True
        n_rows += n_hi - n_lo + 1
        if n_rows > _MAX_ROWS:
            raise ValueError(
                f"max_mass = {m_max!r} kg admits more than {_MAX_ROWS} (turns, wire) designs; "
                "tighten the limits or shorten wire_diameters"
            )
        n = np.arange(n_lo, n_hi + 1)
        per_layer = math.floor(length_avail / pitch * (1.0 + _RTOL))
        if per_layer >= 1:
            layers = -(-n // per_layer)
        else:
            layers = np.full(n.shape, np.iinfo(np.int64).max)
        fits = layers <= max_layers
        resistance = n * r
        cols["turns"].append(n)
        cols["wire_diameter"].append(np.full(n.shape, d))
        cols["wire_area"].append(np.full(n.shape, s_r))
        cols["resistance"].append(resistance)
        cols["current"].append(u / resistance)
        cols["power"].append(u**2 / resistance)
        cols["mass"].append(gamma * perimeter * s_r * n)
        cols["moment"].append(u / resistance * area * n)
        cols["pitch"].append(np.full(n.shape, pitch))
        cols["layer_length"].append(n * pitch)
        cols["layers"].append(layers)
        cols["fits"].append(fits)
        # conductor over the window the layers occupy (layers·pitch deep); 0 if nothing fits
        depth = np.where(per_layer >= 1, layers * pitch, np.inf)
        cols["fill_factor"].append(n * s_r / (length_avail * depth))

    dtypes = {"turns": np.int64, "layers": np.int64, "fits": bool}
    out = {k: (np.concatenate(v) if v else np.array([], dtype=dtypes.get(k, float)))
           for k, v in cols.items()}
    if require_fit:
        keep = out["fits"]
        out = {k: v[keep] for k, v in out.items()}

    feasible = out["turns"].size > 0
    out["feasible"] = feasible
    out["min_power"] = out["min_mass"] = None
    out["binding_limit"] = None
    if feasible:
        keys = [k for k in cols]
        for label, col in (("min_power", "power"), ("min_mass", "mass")):
            i = int(np.argmin(out[col]))
            out[label] = {k: out[k][i].item() for k in keys}
        out["explanation"] = (
            f"{out['turns'].size} feasible designs; least power "
            f"{out['min_power']['power']:.4g} W at N = {out['min_power']['turns']}, "
            f"d = {out['min_power']['wire_diameter'] * 1e3:.4g} mm; least mass "
            f"{out['min_mass']['mass'] * 1e3:.4g} g at N = {out['min_mass']['turns']}, "
            f"d = {out['min_mass']['wire_diameter'] * 1e3:.4g} mm"
        )
        return out

    if not adequate:
        s_need = 4.0 * rho * m_req / (u * l)
        d_max = d_all[-1]
        m_best = u * l * (math.pi * d_max**2 / 4.0) / (4.0 * rho)
        out["binding_limit"] = "moment"
        out["explanation"] = (
            f"moment: no wire reaches {m_req:.4g} A·m² at {u:.4g} V. By eq. (20) the thickest "
            f"wire, d = {d_max * 1e3:.4g} mm, gives {m_best:.4g} A·m² whatever the turns; "
            f"eq. (21) needs S_r >= {s_need:.4g} m² (d >= "
            f"{math.sqrt(4.0 * s_need / math.pi) * 1e3:.4g} mm) or a higher voltage"
        )
    elif not any_power_mass:
        d, n_lo, n_hi = adequate[0]          # thinnest adequate wire: least mass × power
        s_r = math.pi * d**2 / 4.0
        m_wire = u * l * s_r / (4.0 * rho)
        product = 16.0 * rho * gamma * m_wire**2 / l**2
        if product > m_max * w_max * (1.0 + _RTOL):
            out["binding_limit"] = "power and mass"
            out["explanation"] = (
                f"power and mass together: with the thinnest adequate wire, d = {d * 1e3:.4g} mm "
                f"(moment {m_wire:.4g} A·m²), W <= {w_max:.4g} W needs N >= {n_lo} but "
                f"M <= {m_max:.4g} kg allows N <= {n_hi}. Their product, eq. (26)/(30), "
                f"M·W = 16ρρ̃m²/l² = {product:.4g} kg·W whatever N and U, exceeds "
                f"max_mass·max_power = {m_max * w_max:.4g} kg·W; raise a limit, enlarge the "
                f"coil or use a thinner wire closer to the required moment"
            )
        else:
            out["binding_limit"] = "integer turns"
            out["explanation"] = (
                f"integer turns: for d = {d * 1e3:.4g} mm the limits allow "
                f"{u**2 / (rho * perimeter / s_r * w_max):.6g} <= N <= "
                f"{m_max / (gamma * perimeter * s_r):.6g}, which holds no integer"
            )
    else:
        out["binding_limit"] = "winding fit"
        out["explanation"] = (
            f"winding fit: designs meet the moment, power and mass limits, but none fits in "
            f"{max_layers} layer(s) over {length_avail:.4g} m at the wires' pitch (enamel included)"
        )
    return out


def rod_demagnetizing_factor(elongation, formula="power"):
    r"""Central demagnetising factor of a long cylindrical rod (χ → ∞), in SI.

    Parameters
    ----------
    elongation : array_like
        Length over diameter p = l/d [-], at least 10.
    formula : {"power", "rosenblat"}, optional
        Which fit [-]: ``"power"``, Kovalenko's N ≈ 0.93 p^-1.7 (9.25); ``"rosenblat"``,
        N = (ln 1.2p − 1)/p² (9.24).

    Returns
    -------
    ndarray
        N_ц [-] in SI (N_x + N_y + N_z = 1 for an ellipsoid); Kovalenko's Table 5 lists
        4πN, the CGS value.

    Notes
    -----
    Not in the thesis: Kovalenko (1975) eq. (9.25), p. 184 (and eq. (9.24), Rosenblat,
    valid for p = 10–250).

    Deviation from source: the OCR of (9.24) lost the prefactor; it is reconstructed as
    1/p² in SI, which matches Table 5's measured column within 3 %. Table 5's "расч"
    column differs from 4π·0.93 p^-1.7 by up to 1.4 % (e.g. p = 75.63: printed 0.00738,
    formula 0.00748).

    Examples
    --------
    >>> import numpy as np
    >>> [round(float(4 * np.pi * rod_demagnetizing_factor(p)), 4) for p in (20, 30)]
    [0.0718, 0.036]
    >>> round(float(4 * np.pi * rod_demagnetizing_factor(20, "rosenblat")), 4)
    0.0684
    """
    p = as_finite("elongation", elongation)
    if np.any(p < 10):
        raise ValueError(f"elongation must be >= 10 [-] (long rods), got {p[p < 10].ravel()[0]!r}")
    if formula == "power":
        return 0.93 * p**-1.7
    if formula == "rosenblat":
        return (np.log(1.2 * p) - 1.0) / p**2
    raise ValueError(f"formula must be one of ('power', 'rosenblat'), got {formula!r}")


def effective_permeability(permeability, demagnetizing_factor):
    r"""Apparent (rod) permeability of a core of finite length.

    Parameters
    ----------
    permeability : array_like
        Relative permeability of the material μ [-], at least 1.
    demagnetizing_factor : array_like
        Demagnetising factor N in SI [-], in [0, 1].

    Returns
    -------
    ndarray
        μ_eff = μ/(1 + N(μ − 1)) [-]: B = μ0 μ_eff H_к in the core for an applied field H_к.

    Notes
    -----
    Not in the thesis: Kovalenko (1975) eq. (9.5), p. 179, H = H_к − N J with
    J = (μ − 1)H for a linear, unsaturated material, solved for B = μ0 μ H. For μ → ∞,
    μ_eff → 1/N: the shape, not the material, limits a long core. Saturation is ignored;
    Kovalenko's (9.21)–(9.23) model it.

    Examples
    --------
    >>> n = rod_demagnetizing_factor(50.0)
    >>> round(float(effective_permeability(1e5, n)))
    824
    """
    mu = as_finite("permeability", permeability)
    if np.any(mu < 1):
        raise ValueError(f"permeability must be >= 1 [-], got {mu[mu < 1].ravel()[0]!r}")
    n = as_in_range("demagnetizing_factor", demagnetizing_factor, 0.0, 1.0)
    return mu / (1.0 + n * (mu - 1.0))


def magnet_torque_per_mass(remanence, field, density):
    r"""Largest torque per unit mass of a permanent magnet.

    Parameters
    ----------
    remanence : array_like
        Remanent induction B_r [T].
    field : array_like
        External flux density B, perpendicular to the magnet [T].
    density : array_like
        Magnet density γ_м [kg/m³].

    Returns
    -------
    ndarray
        M/m = B_r B/(μ0 γ_м) [N·m/kg] (the remanent magnetisation J_r = B_r/μ0, with no
        demagnetisation).

    Notes
    -----
    Not in the thesis: Kovalenko (1975) eq. (1.7), p. 30. His example (B = 0.5·10⁻⁴ T,
    B_r = 1.4 T, γ = 7.5·10³ kg/m³) prints "≈ 0.75·10⁻²" N·m/kg; the value is
    7.43·10⁻³ (and 134.6 ≈ 135 kg per N·m).

    Examples
    --------
    >>> round(float(magnet_torque_per_mass(1.4, 0.5e-4, 7.5e3)) * 1e3, 2)
    7.43
    """
    br = as_positive("remanence", remanence, unit="T")
    b = as_nonnegative("field", field, unit="T")
    g = as_positive("density", density, unit="kg/m³")
    return br * b / (MU_0 * g)


def magnet_mass_for_torque(torque, remanence, field, density):
    r"""Permanent-magnet mass that yields a given torque.

    Parameters
    ----------
    torque : array_like
        Required torque M [N·m].
    remanence : array_like
        Remanent induction B_r [T].
    field : array_like
        External flux density B, perpendicular to the magnet [T].
    density : array_like
        Magnet density γ_м [kg/m³].

    Returns
    -------
    ndarray
        m = μ0 γ_м M/(B_r B) [kg].

    Notes
    -----
    Not in the thesis: Kovalenko (1975) eq. (1.7), p. 30, solved for the mass
    ("m [кг] ≈ 135 M [Н·м]").

    Examples
    --------
    >>> round(float(magnet_mass_for_torque(1.0, 1.4, 0.5e-4, 7.5e3)), 1)
    134.6
    """
    tq = as_nonnegative("torque", torque, unit="N·m")
    b = as_positive("field", field, unit="T")
    return tq / magnet_torque_per_mass(remanence, b, density)


# --- Wire sizes and the built coil's resistance ------------------------------------------

def awg_diameter(gauge):
    r"""Bare diameter of an American Wire Gauge size.

    Parameters
    ----------
    gauge : array_like
        AWG number n [-]; 0000, 000, 00 and 0 are −3, −2, −1 and 0. At least −3.

    Returns
    -------
    ndarray
        d = 0.127 mm × 92^((36 − n)/39) [m], exact by the gauge's definition (36 AWG is
        0.005 in and 0000 AWG is 0.46 in, with 38 geometric steps between them).

    Notes
    -----
    Not in the thesis: ASTM B258, the definition of the American Wire Gauge. The thesis's
    0.2 mm wire lies between 32 AWG (0.202 mm) and 33 AWG (0.180 mm).

    Examples
    --------
    >>> round(float(awg_diameter(36)) * 1e3, 4), round(float(awg_diameter(-3)) / 0.0254, 4)
    (0.127, 0.46)
    >>> round(float(awg_diameter(32)) * 1e3, 4)
    0.2019
    """
    n = as_finite("gauge", gauge)
    if np.any(n < -3):
        raise ValueError(f"gauge must be >= -3 (0000 AWG) [-], got {n[n < -3].ravel()[0]!r}")
    return 0.127e-3 * 92.0 ** ((36.0 - n) / 39.0)


def turns_from_resistance(resistance, side, wire_area, resistivity, shape="round"):
    r"""Number of turns that gives a coil a given resistance.

    Parameters
    ----------
    resistance : array_like
        Coil resistance R [Ω].
    side : array_like
        Turn diameter (round) or side (square) l [m].
    wire_area : array_like
        Conductor cross-section S_r [m²].
    resistivity : array_like
        Conductor resistivity ρ [Ω·m].
    shape : {"round", "square"}, optional
        Turn shape [-].

    Returns
    -------
    ndarray
        N = R/r with r from eq. (19) [-] (not rounded).

    Notes
    -----
    Thesis §3.3, seed lines 439–441: the thesis explains the measured ≈ 55 Ω (53.5 Ω
    computed) by extra turns wound by hand; this is the count that explanation needs.

    Examples
    --------
    >>> round(float(turns_from_resistance(55.0, 0.1, wire_area(0.2e-3), 0.0175e-6, "square")), 1)
    246.8
    """
    r = as_positive("resistance", resistance, unit="Ω")
    return r / turn_resistance(side, wire_area, resistivity, shape)


def wire_diameter_from_resistance(resistance, turns, side, resistivity, shape="round"):
    r"""Bare wire diameter that gives a coil of N turns a given resistance.

    Parameters
    ----------
    resistance : array_like
        Coil resistance R [Ω].
    turns : array_like
        Number of turns N [-].
    side : array_like
        Turn diameter (round) or side (square) l [m].
    resistivity : array_like
        Conductor resistivity ρ [Ω·m].
    shape : {"round", "square"}, optional
        Turn shape [-].

    Returns
    -------
    ndarray
        d = √(4ρPN/(πR)), P the turn length [m].

    Notes
    -----
    Thesis §3.3, seed lines 439–441, the other explanation of the measured 55 Ω: a wire
    thinner than its nominal 0.2 mm, within the wire standard's diameter tolerance.

    Examples
    --------
    >>> round(float(wire_diameter_from_resistance(55.0, 240, 0.1, 0.0175e-6, "square")) * 1e3, 4)
    0.1972
    """
    r = as_positive("resistance", resistance, unit="Ω")
    n = as_positive("turns", turns)
    rho = as_positive("resistivity", resistivity, unit="Ω·m")
    return np.sqrt(4.0 * rho * turn_length(side, shape) * n / (np.pi * r))


# --- Cored electromagnets: saturation (Kovalenko ch. 9) ------------------------------------

def magnetization_curve(field, a, b):
    r"""Magnetisation of a soft core material, with saturation.

    Parameters
    ----------
    field : array_like
        Field strength inside the material H [A/m], at least 0.
    a : array_like
        Saturation magnetisation of the fit, J(H → ∞) [A/m].
    b : array_like
        Field of half saturation [A/m].

    Returns
    -------
    ndarray
        J = aH/(H + b) [A/m].

    Notes
    -----
    Not in the thesis: Kovalenko (1975) eq. (9.21), p. 183, with a = 1.25·10⁶ A/m,
    b = 40 A/m for permalloy 50Н and a = 1.92·10⁶, b = 170 A/m for permendur.

    Examples
    --------
    >>> round(float(magnetization_curve(500.0, 1.25e6, 40.0)) / 1e6, 3)
    1.157
    """
    h = as_nonnegative("field", field, unit="A/m")
    a_ = as_positive("a", a, unit="A/m")
    b_ = as_positive("b", b, unit="A/m")
    return a_ * h / (h + b_)


def field_for_magnetization(magnetization, a, b):
    r"""Field that magnetises a soft core material to a given magnetisation.

    Parameters
    ----------
    magnetization : array_like
        Magnetisation J [A/m], in [0, a).
    a : array_like
        Saturation magnetisation of the fit [A/m].
    b : array_like
        Field of half saturation [A/m].

    Returns
    -------
    ndarray
        H = bJ/(a − J) [A/m].

    Notes
    -----
    Not in the thesis: Kovalenko (1975) eq. (9.22), p. 183, the inverse of (9.21).

    Examples
    --------
    >>> round(float(field_for_magnetization(1.1e6, 1.25e6, 40.0)), 1)
    293.3
    """
    j = as_nonnegative("magnetization", magnetization, unit="A/m")
    a_ = as_positive("a", a, unit="A/m")
    b_ = as_positive("b", b, unit="A/m")
    if np.any(j >= a_):
        raise ValueError(f"magnetization must be below the saturation a = {np.max(a_)!r} A/m, "
                         f"got {np.max(j)!r}")
    return b_ * j / (a_ - j)


def core_central_magnetization(coil_field, demagnetizing_factor, a, b):
    r"""Magnetisation of a rod core's central section in a coil's field, with saturation.

    Parameters
    ----------
    coil_field : array_like
        Field of the magnetising winding H_к [A/m], at least 0.
    demagnetizing_factor : array_like
        Central demagnetising factor N_ц in SI [-], in (0, 1].
    a : array_like
        Saturation magnetisation of the material's curve (9.21) [A/m].
    b : array_like
        Field of half saturation of the curve [A/m].

    Returns
    -------
    ndarray
        J_ц = [(H_к + N_ц a + b) − √((H_к + N_ц a + b)² − 4 N_ц a H_к)]/(2N_ц) [A/m]: the
        smaller root of J = aH/(H + b) with H = H_к − N_ц J (the physical one, J < a).

    Notes
    -----
    Not in the thesis: Kovalenko (1975) eq. (9.23), p. 183 (the minus root; OCR
    reconstructed). For a weak field it is the linear result H_к/(N_ц + b/a); for
    H_к → ∞ it tends to a (saturation).

    Examples
    --------
    >>> n = rod_demagnetizing_factor(40.0)
    >>> round(float(core_central_magnetization(2434.0, n, 1.25e6, 40.0)) / 1e6, 3)
    1.143
    """
    hk = as_nonnegative("coil_field", coil_field, unit="A/m")
    n = as_in_range("demagnetizing_factor", demagnetizing_factor, 0.0, 1.0)
    if np.any(n == 0):
        raise ValueError("demagnetizing_factor must lie in (0, 1] [-], got 0.0")
    a_ = as_positive("a", a, unit="A/m")
    b_ = as_positive("b", b, unit="A/m")
    c = hk + n * a_ + b_
    # c − √(c² − 4nah) loses digits for a weak field: use the equal form 4nah/(c + √…)
    return 2.0 * a_ * hk / (c + np.sqrt(c**2 - 4.0 * n * a_ * hk))


def electromagnet_design(moment, elongation, design_magnetization, design_field,
                         averaging_factor, current_density, fill_factor, resistivity,
                         core_density, conductor_density, voltage):
    r"""A rod electromagnet sized for a moment at a near-saturation core state.

    Parameters
    ----------
    moment : float
        Required moment L_p [A·m²].
    elongation : float
        Core elongation p = l/D₁ [-], at least 10.
    design_magnetization : float
        Central magnetisation chosen near saturation J° [A/m].
    design_field : float
        Field inside the core at that state H° [A/m].
    averaging_factor : float
        k = J_c/J_ц, mean over central magnetisation [-], in (0, 1].
    current_density : float
        Current density in the winding j [A/m²].
    fill_factor : float
        Winding fill factor k_з [-], in (0, 1].
    resistivity : float
        Conductor resistivity ρ [Ω·m].
    core_density : float
        Core density γ_c [kg/m³].
    conductor_density : float
        Conductor density γ_м [kg/m³].
    voltage : float
        Supply voltage U [V] (sets the wire diameter only).

    Returns
    -------
    dict
        ``core_diameter`` D₁ (9.64) [m], ``length`` l (9.65) [m], ``demagnetizing_factor``
        N_ц (9.25) [-], ``coil_field`` H_к = H° + N_ц J° (9.63) [A/m],
        ``winding_outer_diameter`` D₂ (9.72) [m], ``power`` P = (π/4) l ρ j² k_з (D₂² − D₁²)
        (9.56) [W], ``current`` P/U [A], ``wire_diameter`` √(4P/(πjU)) (9.73) [m],
        ``core_mass`` γ_c π D₁² l/4 [kg], ``conductor_mass`` P γ_м/(j²ρ) (9.38) [kg],
        ``mass`` (core + conductor; insulation, casing and supply excluded, as for the
        air-core coil) [kg].

    Notes
    -----
    Not in the thesis: Kovalenko (1975) §9.3, eqs. (9.63)–(9.65), (9.72), (9.56), (9.38),
    (9.73), pp. 193–198, the "simplified design" in which the core is taken to a chosen
    state near saturation. The winding's own moment (two orders smaller, (9.33)) is
    neglected, as Kovalenko does. :func:`core_central_magnetization` checks the state
    against the material's curve.

    Examples
    --------
    >>> em = electromagnet_design(0.4, 40.0, 1.1e6, 500.0, 0.79, 2e6, 0.5, 0.0175e-6,
    ...                           8.0e3, 8.9e3, 12.0)
    >>> round(em["length"], 4), round(em["power"], 3), round(em["mass"] * 1e3, 1)
    (0.0979, 0.128, 19.9)
    """
    lp = float(as_positive("moment", moment, unit="A·m²"))
    p = float(as_finite("elongation", elongation))
    if p < 10:
        raise ValueError(f"elongation must be >= 10 [-] (long rods), got {p!r}")
    j0 = float(as_positive("design_magnetization", design_magnetization, unit="A/m"))
    h0 = float(as_nonnegative("design_field", design_field, unit="A/m"))
    k = float(as_in_range("averaging_factor", averaging_factor, 0.0, 1.0))
    kz = float(as_in_range("fill_factor", fill_factor, 0.0, 1.0))
    for name, value in (("averaging_factor", k), ("fill_factor", kz)):
        if value == 0:
            raise ValueError(f"{name} must lie in (0, 1] [-], got 0.0")
    j = float(as_positive("current_density", current_density, unit="A/m²"))
    rho = float(as_positive("resistivity", resistivity, unit="Ω·m"))
    g_c = float(as_positive("core_density", core_density, unit="kg/m³"))
    g_m = float(as_positive("conductor_density", conductor_density, unit="kg/m³"))
    u = float(as_positive("voltage", voltage, unit="V"))
    d1 = (4.0 * lp / (math.pi * k * j0 * p)) ** (1.0 / 3.0)              # (9.64)
    length = p * d1                                                        # (9.65)
    n_c = float(rod_demagnetizing_factor(p))                               # (9.25)
    h_k = h0 + n_c * j0                                                    # (9.63)
    d2 = d1 + h_k / (0.5 * j * kz)                                         # (9.72)
    power = math.pi / 4.0 * length * rho * j**2 * kz * (d2**2 - d1**2)     # (9.56)
    core_mass = g_c * math.pi * d1**2 * length / 4.0
    conductor_mass = power * g_m / (j**2 * rho)                            # (9.38)
    return {
        "core_diameter": d1, "length": length, "demagnetizing_factor": n_c, "coil_field": h_k,
        "winding_outer_diameter": d2, "power": power, "current": power / u,
        "wire_diameter": math.sqrt(4.0 * power / (math.pi * j * u)),       # (9.73)
        "core_mass": core_mass, "conductor_mass": conductor_mass,
        "mass": core_mass + conductor_mass,
    }


# --- Permanent magnets (Kovalenko ch. 1 and 10) ----------------------------------------------

def magnet_moment_per_mass(magnetization, density):
    r"""Magnetic moment per unit mass of a uniformly magnetised magnet.

    Parameters
    ----------
    magnetization : array_like
        Mean magnetisation J_c [A/m] (at most the remanent J_r = B_r/μ0, reached by a
        long magnet).
    density : array_like
        Magnet density γ [kg/m³].

    Returns
    -------
    ndarray
        L/m = J_c/γ [A·m²/kg].

    Notes
    -----
    Not in the thesis: Kovalenko (1975) eq. (10.1) L = J_c V divided by the mass γV; with
    J_c = B_r/μ0 it is the moment behind eq. (1.7).

    Examples
    --------
    >>> from magbench.constants import MU_0
    >>> round(float(magnet_moment_per_mass(1.4 / MU_0, 7.5e3)), 1)
    148.5
    """
    j = as_positive("magnetization", magnetization, unit="A/m")
    g = as_positive("density", density, unit="kg/m³")
    return j / g


def permanent_magnet_min_mass(moment, magnetization, elongation, density):
    r"""Least-mass cylindrical permanent magnet for a moment (Kovalenko's case 1).

    Parameters
    ----------
    moment : array_like
        Required moment L_п.р [A·m²].
    magnetization : array_like
        Largest mean magnetisation of the material J_c max [A/m], reached at the
        elongation below.
    elongation : array_like
        Length over diameter p₀ at which J_c max is reached [-].
    density : array_like
        Magnet density γ_п [kg/m³].

    Returns
    -------
    length, diameter, mass : ndarray
        l = (4p₀² L/(π J_c))^(1/3) (10.18) [m], d = l/p₀ (10.19) [m] and
        m = γ L/J_c (10.20) [kg].

    Notes
    -----
    Not in the thesis: Kovalenko (1975) eqs. (10.17)–(10.20), pp. 209–210. With
    ЮН13ДК25БА (J_c max ≈ 8.4·10⁵ A/m at p₀ = 7) he prints l ≈ 0.042 ∛L m,
    d ≈ 0.143 l and m ≈ 0.875·10⁻² L kg (the last implies γ ≈ 7350 kg/m³, not printed).

    Examples
    --------
    >>> l, d, m = permanent_magnet_min_mass(1.0, 8.4e5, 7.0, 7350.0)
    >>> round(float(l), 4), round(float(d / l), 3), round(float(m) * 1e2, 3)
    (0.042, 0.143, 0.875)
    """
    lp = as_positive("moment", moment, unit="A·m²")
    j = as_positive("magnetization", magnetization, unit="A/m")
    p = as_positive("elongation", elongation)
    g = as_positive("density", density, unit="kg/m³")
    length = (4.0 * p**2 * lp / (np.pi * j)) ** (1.0 / 3.0)
    return length, length / p, g * lp / j
