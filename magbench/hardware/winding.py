"""Electrics and mass of a winding: resistance, voltage, power, mass; the power of a coil
system of given ampere-turns and of a Helmholtz pair for a given midpoint field.

Thesis §2.2 (the winding formulas after eq. (16)): R = 2πaρN/S₀, U = RI, P = UI, and
eq. (24) for the mass. One API for every coil: the first argument is the turn's
geometry, a :class:`~magbench.hardware.turn.Turn` (round or square: a simulator coil
and a magnetorquer alike), or a number, read as the radius of a round turn (the
simulator coils of chapter 2). SI throughout.
"""

import numpy as np

from .. import fields
from ..constants import MU_0
from .._validate import as_finite, as_positive
from ._parameters import document_coil
from .magnetorquer import coil_mass, coil_resistance
from .turn import Turn, turn_length, wire_area


def _turn(turn):
    """A :class:`Turn` from a Turn or the radius of a round turn [m]."""
    if isinstance(turn, Turn):
        return turn
    return Turn.round(turn)

__all__ = ["winding_resistance", "winding_voltage", "winding_power", "winding_mass", "ampere_turns_power",
           "coaxial_system_scale_for_power"]


@document_coil
def winding_resistance(turn, turns, wire_diameter, resistivity):
    r"""Resistance of a winding (simulator coil or magnetorquer).

    Parameters
    ----------
    {turn, turns, wire_diameter, resistivity}

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


@document_coil
def winding_voltage(turn, turns, wire_diameter, resistivity, current):
    r"""Supply voltage of a winding at a given current.

    Parameters
    ----------
    {turn, turns, wire_diameter, resistivity, current}

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


@document_coil
def winding_power(turn, turns, wire_diameter, resistivity, current):
    r"""Ohmic power dissipated in a winding.

    Parameters
    ----------
    {turn, turns, wire_diameter, resistivity, current}

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


@document_coil
def winding_mass(turn, turns, wire_diameter, density):
    r"""Conductor mass of a winding.

    Parameters
    ----------
    {turn, turns, wire_diameter, density}

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


@document_coil
def ampere_turns_power(turn, ampere_turns, winding_area, resistivity):
    r"""Ohmic power of a winding that carries given ampere-turns in a given copper cross-section.

    Parameters
    ----------
    {turn}
    ampere_turns : array_like
        N·I of the winding [A].
    winding_area : array_like
        Copper cross-section of the whole winding A = N S₀ [m²], > 0.
    {resistivity}

    Returns
    -------
    ndarray
        P [W], whatever the split of N·I into turns and current.

    Notes
    -----
    Thesis §2.2 (R = 2πa_cρN/S₀, P = UI, after eq. (16)) with the winding's copper
    cross-section A = N S₀ held fixed: I = NI/N and R = ρ N ℓ / S₀ give

    .. math:: P = \frac{\rho\,\ell\,(NI)^2}{A},

    ℓ the length of one turn (2πa_c for a round coil).

    Examples
    --------
    >>> import numpy as np
    >>> area = 110 * np.pi * 0.75e-3**2 / 4
    >>> round(float(ampere_turns_power(0.5, 110 * 2.3, area, 0.0175e-6)), 1)   # = winding_power
    72.4
    """
    ni = as_finite("ampere_turns", ampere_turns)
    area = as_positive("winding_area", winding_area, unit="m²")
    rho = as_positive("resistivity", resistivity, unit="Ω·m")
    return rho * _turn(turn).length * ni**2 / area


def coaxial_system_scale_for_power(shapes, sizes, positions, weights, center_h, power, winding_area,
                                   resistivity):
    r"""Size and ampere-turns at which a coaxial coil system gives a centre field at a given power.

    Parameters
    ----------
    shapes : sequence of {"round", "square"}
        Shape of each coil [-].
    sizes : array_like, shape (n,)
        Radius of each round coil, side of each square, at the reference size [m], > 0.
    positions : array_like, shape (n,)
        z of each coil's plane at the reference size [m].
    weights : array_like, shape (n,)
        Relative ampere-turns of the coils [-] (only the ratios count).
    center_h : float
        Field wanted at the centre H₀ [A/m], > 0.
    power : float
        Total power of all coils P [W], > 0.
    winding_area : float
        Copper cross-section of every coil's winding A [m²], > 0 (one kind of former for all).
    resistivity : float
        Conductor resistivity ρ [Ω·m], > 0.

    Returns
    -------
    scale : float
        Factor L [-] by which every length of the reference system is multiplied.
    ampere_turns : ndarray, shape (n,)
        N·I of each coil [A] at that size.

    Notes
    -----
    Not in the thesis: its Fig. 3 and Kovalenko (1975) §3.4 compare candidate systems;
    this puts them on an equal footing. With ampere-turns w_k X the system of size L
    dissipates P = ρ X² L Σ w_k² ℓ_k / A (:func:`ampere_turns_power`, ℓ_k the turn
    lengths at the reference size) and gives H₀ = h₀ X / L (h₀ the centre field of the
    reference system per unit weight, :func:`magbench.fields.coaxial_system_b`), so

    .. math:: L = \left(\frac{P A h_0^2}{\rho H_0^2 \sum_k w_k^2 \ell_k}\right)^{1/3},
              \qquad X = H_0 L / h_0 .

    Examples
    --------
    >>> scale, ni = coaxial_system_scale_for_power(["round"] * 2, [1.0, 1.0], [-0.5, 0.5], [1.0, 1.0],
    ...                                            250.0, 100.0, 1e-4, 0.0175e-6)
    >>> round(scale, 3), np.round(ni, 1).tolist()
    (0.72, [251.4, 251.4])
    """
    w = as_finite("weights", weights)
    h0_target = float(as_positive("center_h", center_h, unit="A/m"))
    p = float(as_positive("power", power, unit="W"))
    area = float(as_positive("winding_area", winding_area, unit="m²"))
    rho = float(as_positive("resistivity", resistivity, unit="Ω·m"))
    h0 = float(np.linalg.norm(fields.coaxial_system_b(np.zeros(3), shapes, sizes, positions, w))) / MU_0
    if h0 == 0.0:
        raise ValueError("weights must not make the centre field zero (the system cannot reach center_h)")
    lengths = np.array([turn_length(2.0 * size if shape == "round" else size, shape)
                        for shape, size in zip(shapes, as_positive("sizes", sizes, unit="m"))])
    c = float(np.sum(w**2 * lengths))
    scale = (p * area * h0**2 / (rho * h0_target**2 * c)) ** (1 / 3)
    return scale, w * h0_target * scale / h0


def helmholtz_pair_power(center_h, radius, separation, winding_area, resistivity):
    r"""Ohmic power of both coils of a pair that gives a field at its midpoint.

    Parameters
    ----------
    center_h : float
        Field wanted at the midpoint H [A/m].
    radius : float
        Coil radius a_c [m], > 0.
    separation : float
        Distance between the coil planes d_c [m], >= 0.
    winding_area : float
        Copper cross-section of each coil's winding A = N S₀ [m²], > 0.
    resistivity : float
        Conductor resistivity ρ [Ω·m], > 0.

    Returns
    -------
    float
        P of the two coils [W], whatever the split of N·I into turns and current.

    Notes
    -----
    Thesis §2.2: eq. (16)'s ampere-turns (:func:`magbench.fields.helmholtz_ampere_turns`) in
    each coil's winding, P = 2 ρ ℓ (NI)²/A (:func:`ampere_turns_power`).

    Examples
    --------
    >>> area = 110 * np.pi * 0.75e-3**2 / 4
    >>> round(helmholtz_pair_power(250.0, 0.5, 1.116 * 0.5, area, 0.0175e-6), 1)
    79.7
    """
    ni = float(fields.helmholtz_ampere_turns(center_h, radius, separation))
    return 2 * float(ampere_turns_power(radius, ni, winding_area, resistivity))
