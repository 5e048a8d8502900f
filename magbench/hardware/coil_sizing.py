r"""Sizing an air-core magnetorquer: the turns and wire that limits allow, and how they lie.

Thesis §3.2, eqs. (26)–(32) read backwards (the turns per volt a power and a mass limit leave,
the turns or wire a measured resistance implies) and the winding's geometry (turns per layer,
the band the turns occupy), with Kovalenko (1975) ch. 8. Built on the forward formulas of
:mod:`magbench.hardware.magnetorquer`. SI throughout.
"""

import math

import numpy as np

from .._validate import as_finite, as_positive, shown
from ._parameters import document_coil
from .magnetorquer import coil_mass_for_moment, joule_power_for_moment, turn_resistance
from .turn import turn_length, wire_area

__all__ = ["turns_per_volt_bounds", "turns_from_resistance", "wire_diameter_from_resistance", "turns_per_layer",
           "winding_band", "wire_turn_limits"]

# Relative slack when an exactly-at-the-limit design (the thesis's N = 240) is compared
# with a limit after floating-point arithmetic.
_RTOL = 1e-12


@document_coil
def turns_per_volt_bounds(moment, side, max_power, max_mass, resistivity, density, shape="round"):
    r"""Range of turns per volt N/U allowed by a power limit and a mass limit.

    Parameters
    ----------
    {moment, side, max_power, max_mass, resistivity, density, shape}

    Returns
    -------
    low, high : ndarray
        W ≤ W_max needs N/U ≥ low; M ≤ M_max needs N/U ≤ high [1/V]. The design is
        impossible where low > high, i.e. where the mass × power product (26)/(30)
        exceeds M_max·W_max.

    Notes
    -----
    Thesis eq. (32) (with the square formulas (28)–(29)); the thesis
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


@document_coil
def turns_from_resistance(resistance, side, wire_area, resistivity, shape="round"):
    r"""Number of turns that gives a coil a given resistance.

    Parameters
    ----------
    {resistance, side, wire_area, resistivity, shape}

    Returns
    -------
    ndarray
        N = R/r with r from eq. (19) [-] (not rounded).

    Notes
    -----
    Thesis §3.3: the thesis explains the measured ≈ 55 Ω (53.5 Ω
    computed) by extra turns wound by hand; this is the count that explanation needs.

    Examples
    --------
    >>> round(float(turns_from_resistance(55.0, 0.1, wire_area(0.2e-3), 0.0175e-6, "square")), 1)
    246.8
    """
    r = as_positive("resistance", resistance, unit="Ω")
    return r / turn_resistance(side, wire_area, resistivity, shape)


@document_coil
def wire_diameter_from_resistance(resistance, turns, side, resistivity, shape="round"):
    r"""Bare wire diameter that gives a coil of N turns a given resistance.

    Parameters
    ----------
    {resistance, turns, side, resistivity, shape}

    Returns
    -------
    ndarray
        d = √(4ρPN/(πR)), P the turn length [m].

    Notes
    -----
    Thesis §3.3, the other explanation of the measured 55 Ω: a wire
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


def turns_per_layer(side, wire_pitch):
    r"""Turns of a wire that fit side by side in one layer across a former.

    Parameters
    ----------
    side : array_like
        Width available for the winding, the turn's side l [m], > 0.
    wire_pitch : array_like
        Distance between neighbouring turns, the insulated wire's overall diameter [m], > 0.

    Returns
    -------
    ndarray
        ⌊l / pitch⌋ [-].

    Notes
    -----
    Thesis §3.2 (its dense single-layer winding, N = L/√S_r along the side) with the
    insulated diameter as the pitch.

    Examples
    --------
    >>> float(turns_per_layer(0.1, 0.226e-3))
    442.0
    """
    l = as_positive("side", side, unit="m")
    pitch = as_positive("wire_pitch", wire_pitch, unit="m")
    return np.floor(l / pitch)


def winding_band(turns, side, wire_pitch):
    r"""Layers and width of the band a winding of N turns makes on a former of side l.

    Parameters
    ----------
    turns : float
        Number of turns N [-], >= 1.
    side : float
        Width available across the former, the turn's side l [m], > 0.
    wire_pitch : float
        Distance between neighbouring turns [m], > 0 and at most ``side``.

    Returns
    -------
    layers : int
        ⌈N / n₁⌉ layers, n₁ = :func:`turns_per_layer` [-].
    width : float
        Band width ⌈N / layers⌉ · pitch [m]: the turns shared evenly between the layers.

    Notes
    -----
    Thesis §3.2 assumes a dense single layer (N·pitch ≤ l); turns that do not fit are
    wound in as many layers as they need (not in the thesis).

    Examples
    --------
    >>> winding_band(1000, 0.1, 0.226e-3)
    (3, 0.075484)
    """
    n = float(as_finite("turns", turns))
    if n < 1:
        raise ValueError(f"turns must be >= 1 [-], got {shown(n)}")
    l = float(as_positive("side", side, unit="m"))
    pitch = float(as_positive("wire_pitch", wire_pitch, unit="m"))
    per_layer = math.floor(l / pitch)
    if per_layer < 1:
        raise ValueError(f"wire_pitch {shown(pitch)} m is wider than the side {shown(l)} m: not one turn fits")
    layers = math.ceil(n / per_layer)
    return layers, math.ceil(n / layers) * pitch


@document_coil
def wire_turn_limits(voltage, side, wire_area, max_power, max_mass, resistivity, density, shape="round"):
    r"""Fewest turns that keep a coil within its power limit, and most within its mass limit.

    Parameters
    ----------
    {voltage, side, wire_area, max_power, max_mass, resistivity, density, shape}

    Returns
    -------
    fewest, most : ndarray
        ⌈U² / (R₁ W_max)⌉ and ⌊M_max / (ρ̃ ℓ S_r)⌋ turns [-], R₁ = ρℓ/S_r the resistance of
        one turn of length ℓ. The wire is feasible where fewest ≤ most.

    Notes
    -----
    Thesis eqs. (22)–(24) and (28)–(29) for a given wire (rather than the wire of eq.
    (21)): P = U²/(N R₁) falls and M = N ρ̃ ℓ S_r grows with N.

    Examples
    --------
    >>> lo, hi = wire_turn_limits(12.0, 0.1, wire_area(0.2e-3), 2.0, 0.1, 0.0175e-6, 8.9e3, "square")
    >>> float(lo), float(hi)
    (324.0, 894.0)
    """
    u = as_finite("voltage", voltage)
    s_r = as_positive("wire_area", wire_area, unit="m²")
    w_max = as_positive("max_power", max_power, unit="W")
    m_max = as_positive("max_mass", max_mass, unit="kg")
    rho = as_positive("resistivity", resistivity, unit="Ω·m")
    g = as_positive("density", density, unit="kg/m³")
    perim = turn_length(side, shape)
    r_turn = rho * perim / s_r
    return np.ceil(u**2 / (r_turn * w_max)), np.floor(m_max / (g * perim * s_r))
