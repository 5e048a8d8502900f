"""Electrics and mass of a winding of round turns: resistance, voltage, power, mass.

Thesis §2.2 (the winding formulas after eq. (16)): R = 2πaρN/S₀, U = RI, P = UI. SI
throughout.
"""

from .._validate import as_finite, as_positive
from .magnetorquer import coil_mass, coil_resistance
from .turn import wire_area

__all__ = ["winding_resistance", "winding_voltage", "winding_power", "winding_mass"]


def winding_resistance(radius, turns, wire_diameter, resistivity):
    r"""Resistance of a circular winding.

    Parameters
    ----------
    radius : array_like
        Coil radius a_c [m], > 0.
    turns : array_like
        Number of turns N [-], > 0.
    wire_diameter : array_like
        Bare conductor diameter d_w [m], > 0.
    resistivity : array_like
        Conductor resistivity ρ [Ω·m], > 0.

    Returns
    -------
    ndarray
        R [Ω].

    Notes
    -----
    Thesis §2.2 (unnumbered, after eq. (16)):

    .. math:: R = \frac{2\pi a_c}{S_0}\rho N,\qquad S_0 = \frac{\pi d_w^2}{4}.

    The thesis prints 12.4 Ω for its coils (N = 110, d_w = 0.75 mm, ρ = 0.0175e-6 Ω·m);
    the formula gives 13.69 Ω, and 12.44 Ω for N = 100 (an earlier design).

    Examples
    --------
    >>> round(float(winding_resistance(0.5, 110, 0.75e-3, 0.0175e-6)), 2)
    13.69
    """
    # A circular winding of radius a is the magnetorquer's round coil of turn diameter 2a.
    a = as_positive("radius", radius, unit="m")
    return coil_resistance(turns, 2.0 * a, wire_area(as_positive("wire_diameter", wire_diameter, unit="m")),
                           resistivity, shape="round")


def winding_voltage(radius, turns, wire_diameter, resistivity, current):
    r"""Supply voltage of a circular winding at a given current.

    Parameters
    ----------
    radius : array_like
        Coil radius a_c [m], > 0.
    turns : array_like
        Number of turns N [-], > 0.
    wire_diameter : array_like
        Conductor diameter d_w [m], > 0.
    resistivity : array_like
        Conductor resistivity ρ [Ω·m], > 0.
    current : array_like
        Current I [A].

    Returns
    -------
    ndarray
        U [V].

    Notes
    -----
    Thesis §2.2 (unnumbered, after eq. (16)): U = RI = (2πa_c/S_0)ρNI. It depends
    on N·I only; the printed 32 V matches NI = 258 A (and 31.5 V for N = 110, I = 2.3 A).

    Examples
    --------
    >>> round(float(winding_voltage(0.5, 110, 0.75e-3, 0.0175e-6, 2.3)), 1)
    31.5
    """
    i = as_finite("current", current)
    return winding_resistance(radius, turns, wire_diameter, resistivity) * i


def winding_power(radius, turns, wire_diameter, resistivity, current):
    r"""Ohmic power dissipated in a circular winding.

    Parameters
    ----------
    radius : array_like
        Coil radius a_c [m], > 0.
    turns : array_like
        Number of turns N [-], > 0.
    wire_diameter : array_like
        Conductor diameter d_w [m], > 0.
    resistivity : array_like
        Conductor resistivity ρ [Ω·m], > 0.
    current : array_like
        Current I [A].

    Returns
    -------
    ndarray
        P [W].

    Notes
    -----
    Thesis §2.2 (unnumbered, after eq. (16)): P = UI = (2πa_c/S_0)ρNI·I. The thesis
    prints 83 W; N = 110, I = 2.3 A gives 72.4 W, and 82.8 W is N = 100, I = 2.58 A.

    Examples
    --------
    >>> round(float(winding_power(0.5, 110, 0.75e-3, 0.0175e-6, 2.3)), 1)
    72.4
    """
    i = as_finite("current", current)
    return winding_resistance(radius, turns, wire_diameter, resistivity) * i * i


def winding_mass(radius, turns, wire_diameter, density):
    r"""Conductor mass of a circular winding.

    Parameters
    ----------
    radius : array_like
        Coil radius a_c [m], > 0.
    turns : array_like
        Number of turns N [-], > 0.
    wire_diameter : array_like
        Conductor diameter d_w [m], > 0.
    density : array_like
        Conductor density ρ̃ [kg/m³], > 0.

    Returns
    -------
    ndarray
        Mass of the conductor (no insulation, no former) [kg].

    Notes
    -----
    Thesis eq. (24), M_K = ρ̃πlS_rN (written there for the magnetorquer,
    turn diameter l), applied here to the simulator coil with l = 2a_c.

    Examples
    --------
    >>> round(float(winding_mass(0.5, 110, 0.75e-3, 8.9e3)), 2)
    1.36
    """
    a = as_positive("radius", radius, unit="m")
    return coil_mass(turns, 2.0 * a, wire_area(as_positive("wire_diameter", wire_diameter, unit="m")),
                     density, shape="round")
