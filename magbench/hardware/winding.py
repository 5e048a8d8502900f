"""Electrics and mass of a winding: resistance, voltage, power, mass.

Thesis §2.2 (the winding formulas after eq. (16)): R = 2πaρN/S₀, U = RI, P = UI, and
eq. (24) for the mass. One API for every coil: the first argument is the turn's
geometry, a :class:`~magbench.hardware.turn.Turn` (round or square: a simulator coil
and a magnetorquer alike), or a number, read as the radius of a round turn (the
simulator coils of chapter 2). SI throughout.
"""

from .._validate import as_finite, as_positive
from .magnetorquer import coil_mass, coil_resistance
from .turn import Turn, wire_area


def _turn(turn):
    """A :class:`Turn` from a Turn or the radius of a round turn [m]."""
    if isinstance(turn, Turn):
        return turn
    return Turn.round(turn)

__all__ = ["winding_resistance", "winding_voltage", "winding_power", "winding_mass"]


def winding_resistance(turn, turns, wire_diameter, resistivity):
    r"""Resistance of a winding (simulator coil or magnetorquer).

    Parameters
    ----------
    turn : Turn or array_like
        The turn's geometry (:class:`~magbench.hardware.turn.Turn`), or the coil radius
        a_c of a round turn [m], > 0.
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
    t = _turn(turn)
    return coil_resistance(turns, t.side, wire_area(as_positive("wire_diameter", wire_diameter, unit="m")),
                           resistivity, shape=t.shape)


def winding_voltage(turn, turns, wire_diameter, resistivity, current):
    r"""Supply voltage of a winding at a given current.

    Parameters
    ----------
    turn : Turn or array_like
        The turn's geometry (:class:`~magbench.hardware.turn.Turn`), or the coil radius
        a_c of a round turn [m], > 0.
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
    return winding_resistance(turn, turns, wire_diameter, resistivity) * i


def winding_power(turn, turns, wire_diameter, resistivity, current):
    r"""Ohmic power dissipated in a winding.

    Parameters
    ----------
    turn : Turn or array_like
        The turn's geometry (:class:`~magbench.hardware.turn.Turn`), or the coil radius
        a_c of a round turn [m], > 0.
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
    return winding_resistance(turn, turns, wire_diameter, resistivity) * i * i


def winding_mass(turn, turns, wire_diameter, density):
    r"""Conductor mass of a winding.

    Parameters
    ----------
    turn : Turn or array_like
        The turn's geometry (:class:`~magbench.hardware.turn.Turn`), or the coil radius
        a_c of a round turn [m], > 0.
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
    t = _turn(turn)
    return coil_mass(turns, t.side, wire_area(as_positive("wire_diameter", wire_diameter, unit="m")),
                     density, shape=t.shape)
