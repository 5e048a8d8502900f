r"""Air-core magnetorquers: moment, current, resistance, power and mass of a coil.

Thesis §3.1–3.3, eqs. (17)–(32), and Kovalenko (1975) ch. 8 (the general forms with a
fill factor). Round and square formulas differ only by the factor π/4 in the turn area
and length, so one function with a ``shape`` keyword serves both (see
:mod:`magbench.hardware.turn`). SI throughout: metres, A·m², ohms, watts, kilograms, volts.

What the thesis gets right and wrong (recomputed here; see the tests): the algebra of
eqs. (17)–(31) is correct; thesis §3.2 says the square formulas differ from "(23, 25, 26,
27)" by the factor π/4, but (28) = (π/4)·(22), (29) = (4/π)·(25), (31) = (4/π)·(27) and
(30) is identical to (26): the mass × power product does not depend on the shape.
"""

import numpy as np

from .._validate import as_finite, as_in_range, as_nonnegative, as_positive
from ._parameters import document_coil
from .turn import _length_factor, turn_area, turn_length, wire_area  # noqa: F401 - wire_area: doctests

__all__ = ["dipole_moment", "current_for_moment", "coil_current", "turn_resistance", "coil_resistance",
           "moment_from_voltage", "wire_area_for_moment", "joule_power", "joule_power_for_moment",
           "turns_from_winding_length", "winding_length", "joule_power_for_winding_length", "coil_mass",
           "coil_mass_for_moment", "mass_power_product", "winding_density", "mass_power_product_kovalenko",
           "supply_voltage"]




@document_coil
def dipole_moment(current, turns, area):
    r"""Magnetic dipole moment of a flat coil.

    Parameters
    ----------
    current : array_like
        Current I [A] (its sign gives the moment's sense).
    {turns}
    area : array_like
        Area enclosed by one turn S [m²] (see :func:`turn_area`).

    Returns
    -------
    ndarray
        m = I S N [A·m²].

    Notes
    -----
    Thesis eq. (17) (Kovalenko 1975 eq. 8.2).

    Examples
    --------
    >>> round(float(dipole_moment(12 / 53.5, 240, turn_area(0.1, "square"))), 3)
    0.538
    """
    i = as_finite("current", current)
    n = as_positive("turns", turns)
    s = as_positive("area", area, unit="m²")
    return i * s * n


@document_coil
def current_for_moment(moment, turns, area):
    r"""Current that gives a coil a required dipole moment.

    Parameters
    ----------
    {moment, turns}
    area : array_like
        Area enclosed by one turn S [m²].

    Returns
    -------
    ndarray
        I = m/(S N) [A].

    Notes
    -----
    Thesis eq. (17), solved for I. The thesis's "I₁ = 0.24 A" for
    m₁ = 0.4 A·m² (thesis §4.1) is not reproduced: the square 0.1 m coil of N = 240
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


@document_coil
def coil_current(voltage, turn_resistance, turns):
    r"""Current drawn by a coil from a voltage source.

    Parameters
    ----------
    {voltage}
    turn_resistance : array_like
        Resistance of one turn r [Ω] (see :func:`turn_resistance`).
    {turns}

    Returns
    -------
    ndarray
        I = U/(r N) [A].

    Notes
    -----
    Thesis eq. (18).

    Examples
    --------
    >>> round(float(coil_current(12.0, 53.5 / 240, 240)), 4)
    0.2243
    """
    u = as_finite("voltage", voltage)
    r = as_positive("turn_resistance", turn_resistance, unit="Ω")
    n = as_positive("turns", turns)
    return u / (r * n)


@document_coil
def turn_resistance(side, wire_area, resistivity, shape="round"):
    r"""Resistance of one turn.

    Parameters
    ----------
    {side, wire_area}
    resistivity : array_like
        Conductor resistivity ρ [Ω·m] (the thesis's copper: 0.0175·10⁻⁶).
    {shape}

    Returns
    -------
    ndarray
        r = ρ πl/S_r (round) or ρ 4l/S_r (square) [Ω].

    Notes
    -----
    Thesis eq. (19) (round); the square form is the r inside eq. (31),
    thesis §3.1.

    Examples
    --------
    >>> round(float(turn_resistance(0.1, wire_area(0.2e-3), 0.0175e-6, "square")), 4)
    0.2228
    """
    length = turn_length(side, shape)
    s = as_positive("wire_area", wire_area, unit="m²")
    rho = as_positive("resistivity", resistivity, unit="Ω·m")
    return rho * length / s


@document_coil
def coil_resistance(turns, side, wire_area, resistivity, shape="round"):
    r"""Resistance of a coil of N turns.

    Parameters
    ----------
    {turns, side, wire_area, resistivity, shape}

    Returns
    -------
    ndarray
        R = N r [Ω], with r from eq. (19).

    Notes
    -----
    Thesis §3.3 ("R = N·r = 53.5 Ω" for 0.2 mm wire, N = 240); reproduced with the
    square turn (42.0 Ω if the turn were round).

    Examples
    --------
    >>> round(float(coil_resistance(240, 0.1, wire_area(0.2e-3), 0.0175e-6, "square")), 2)
    53.48
    """
    n = as_positive("turns", turns)
    return n * turn_resistance(side, wire_area, resistivity, shape)


@document_coil
def moment_from_voltage(voltage, side, wire_area, resistivity):
    r"""Dipole moment of a coil driven at a fixed voltage.

    Parameters
    ----------
    {voltage, side, wire_area, resistivity}

    Returns
    -------
    ndarray
        m = U l S_r/(4ρ) [A·m²], whatever the number of turns.

    Notes
    -----
    Thesis eq. (20). It holds unchanged for round and square turns (the
    factor π/4 cancels between area and length), so there is no ``shape`` keyword. The
    thesis's "0.42 A·m²" for the built coil (thesis §3.3: U = 12 V, 0.2 mm wire,
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


@document_coil
def wire_area_for_moment(moment, voltage, side, resistivity):
    r"""Conductor cross-section that gives a required moment at a fixed voltage.

    Parameters
    ----------
    {moment, voltage, side, resistivity}

    Returns
    -------
    ndarray
        S_r = 4ρm/(U l) [m²], for either turn shape.

    Notes
    -----
    Thesis eq. (21). The thesis prints S_r = 2.34·10⁻⁸ m² for
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


@document_coil
def joule_power(voltage, resistance):
    r"""Joule power dissipated by a coil at a fixed voltage.

    Parameters
    ----------
    {voltage}
    resistance : array_like
        Coil resistance R = rN [Ω].

    Returns
    -------
    ndarray
        W = U²/R [W].

    Notes
    -----
    Thesis §3.1 (unnumbered): W = U²/(rN).

    Examples
    --------
    >>> round(float(joule_power(12.0, 53.5)), 2)   # the built coil, above the 2 W limit
    2.69
    """
    u = as_finite("voltage", voltage)
    r = as_positive("resistance", resistance, unit="Ω")
    return u**2 / r


@document_coil
def joule_power_for_moment(moment, voltage, turns, side, shape="round"):
    r"""Joule power of a coil sized by eq. (21) for a required moment.

    Parameters
    ----------
    {moment, voltage, turns, side, shape}

    Returns
    -------
    ndarray
        W = (4m/(πl²))·U/N (round) or (m/l²)·U/N (square) [W]: m U/(S N).

    Notes
    -----
    Thesis eq. (22) (round) and eq. (28) (square); the
    square value is π/4 times the round one, not the reverse as thesis §3.1 reads.

    Examples
    --------
    >>> round(float(joule_power_for_moment(0.4, 12.0, 240, 0.1, "square")), 6)
    2.0
    """
    m = as_positive("moment", moment, unit="A·m²")
    u = as_positive("voltage", voltage, unit="V")
    n = as_positive("turns", turns)
    return m * u / (turn_area(side, shape) * n)


@document_coil
def turns_from_winding_length(winding_length, wire_area):
    r"""Turns of a dense single-layer winding of a given length.

    Parameters
    ----------
    {winding_length}
    wire_area : array_like
        Conductor cross-section S_r [m²]; √S_r stands for the wire pitch.

    Returns
    -------
    ndarray
        N = L/√S_r [-] (not rounded to an integer).

    Notes
    -----
    Thesis §3.2 (the unnumbered N = L/√S_r). The pitch √S_r = 0.886 d ignores the enamel; a real
    winding of pitch d + 2t has fewer turns (see :func:`design_magnetorquer`).

    Examples
    --------
    >>> round(float(turns_from_winding_length(0.1, 2.34e-8)))
    654
    """
    length = as_positive("winding_length", winding_length, unit="m")
    s = as_positive("wire_area", wire_area, unit="m²")
    return length / np.sqrt(s)


@document_coil
def winding_length(turns, wire_area):
    r"""Axial length of a dense single-layer winding of N turns.

    Parameters
    ----------
    {turns, wire_area}

    Returns
    -------
    ndarray
        L = N√S_r [m].

    Notes
    -----
    Thesis §3.2 (the unnumbered N = L/√S_r), solved for L. The thesis's "L ≈ 0.1 m" for N = 240
    and S_r = 2.34·10⁻⁸ m² (thesis §3.2) is not reproduced: L = 0.037 m.

    Examples
    --------
    >>> round(float(winding_length(240, 2.34e-8)), 4)
    0.0367
    """
    n = as_positive("turns", turns)
    s = as_positive("wire_area", wire_area, unit="m²")
    return n * np.sqrt(s)


@document_coil
def joule_power_for_winding_length(moment, voltage, winding_length, wire_area, side, shape="round"):
    r"""Joule power of a dense single-layer coil of a given winding length.

    Parameters
    ----------
    {moment, voltage, winding_length, wire_area, side, shape}

    Returns
    -------
    ndarray
        W = (4m/(πl²))·U√S_r/L (round; m/l² instead of 4m/(πl²) for a square turn) [W].

    Notes
    -----
    Thesis eq. (23): eq. (22) with N = L/√S_r.

    Examples
    --------
    >>> w = joule_power_for_winding_length(0.4, 12.0, 0.1, 2.34e-8, 0.1, "square")
    >>> round(float(w), 3)
    0.734
    """
    n = turns_from_winding_length(winding_length, wire_area)
    return joule_power_for_moment(moment, voltage, n, side, shape)


@document_coil
def coil_mass(turns, side, wire_area, density, shape="round"):
    r"""Mass of the conductor in a coil.

    Parameters
    ----------
    {turns, side, wire_area}
    density : array_like
        Conductor density ρ̃ [kg/m³] (the thesis's copper: 8.9·10³).
    {shape}

    Returns
    -------
    ndarray
        M = ρ̃ πl S_r N (round) or ρ̃ 4l S_r N (square) [kg]; enamel and former excluded.

    Notes
    -----
    Thesis eq. (24) (round); the square form is the one behind eq. (29).

    Examples
    --------
    >>> round(float(coil_mass(240, 0.1, wire_area(0.2e-3), 8.9e3, "square")), 4)
    0.0268
    """
    n = as_positive("turns", turns)
    s = as_positive("wire_area", wire_area, unit="m²")
    g = as_positive("density", density, unit="kg/m³")
    return g * turn_length(side, shape) * s * n


@document_coil
def coil_mass_for_moment(moment, voltage, turns, resistivity, density, shape="round"):
    r"""Conductor mass of a coil sized by eq. (21) for a required moment.

    Parameters
    ----------
    {moment, voltage, turns, resistivity, density, shape}

    Returns
    -------
    ndarray
        M = 4π ρ̃ρ m N/U (round) or 16 ρρ̃ m N/U (square) [kg], independent of l.

    Notes
    -----
    Thesis eq. (25) (round) and eq. (29) (square).

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


@document_coil
def mass_power_product(moment, side, resistivity, density):
    r"""Product of conductor mass and Joule power of a coil of given moment.

    Parameters
    ----------
    {moment, side, resistivity, density}

    Returns
    -------
    ndarray
        M·W = 16 m² ρ̃ρ/l² [kg·W], independent of N, U and the turn shape.

    Notes
    -----
    Thesis eq. (26) (round) and eq. (30) (square); the two
    are identical, contrary to the "factor π/4" of thesis §3.1. Kovalenko's form with a
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


@document_coil
def mass_power_product_kovalenko(moment, diameter, resistivity, density, fill_factor=1.0):
    r"""Kovalenko's mass × power product of a flat air-core coil, with a fill factor.

    Parameters
    ----------
    moment : array_like
        Dipole moment L_K [A·m²].
    diameter : array_like
        Mean winding diameter D [m] (for a square coil: the side, as in eq. (30)).
    {resistivity}
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


@document_coil
def supply_voltage(current, turns, side, wire_area, resistivity, shape="round"):
    r"""Voltage that drives a given current through a coil.

    Parameters
    ----------
    {current, turns, side, wire_area, resistivity, shape}

    Returns
    -------
    ndarray
        U = I r N = ρ (πl/S_r) I N (round) or ρ (4l/S_r) I N (square) [V].

    Notes
    -----
    Thesis eq. (27) (round) and eq. (31) (square).

    Examples
    --------
    >>> u = supply_voltage(0.4 / (0.01 * 240), 240, 0.1, 2.34e-8, 0.0175e-6, "square")
    >>> round(float(u), 2)
    11.97
    """
    i = as_finite("current", current)
    return i * coil_resistance(turns, side, wire_area, resistivity, shape)
