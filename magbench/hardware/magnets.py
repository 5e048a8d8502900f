"""Permanent magnets: torque and moment per mass, and the least-mass magnet.

Kovalenko (1975) eq. (1.7) and §10.3 (eqs. 10.17–10.20). SI throughout.
"""

import numpy as np

from .._validate import as_nonnegative, as_positive
from ..constants import MU_0

__all__ = ["magnet_torque_per_mass", "magnet_mass_for_torque", "magnet_moment_per_mass",
           "permanent_magnet_min_mass"]


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
