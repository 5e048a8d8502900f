r"""The coils' driver on the bench: the moment of a square magnetorquer at full drive from
its measured resistance, and the signed PWM duty an 8-bit ``analogWrite`` and an L298
bridge deliver (thesis §3.3 and §4.2). SI throughout: volts, ohms, A·m².
"""

import numpy as np

from .._validate import as_positive, shown
from .magnetorquer import coil_current, dipole_moment
from .turn import turn_area

__all__ = ["coil_full_scale_moment", "quantise_duty"]


def coil_full_scale_moment(voltage, resistance, turns, side):
    r"""Dipole moment of a square magnetorquer at full drive, from its measured resistance.

    Parameters
    ----------
    voltage : array_like
        Voltage across the coil [V].
    resistance : array_like
        The coil's measured resistance R [Ω] (the thesis: ≈ 55 Ω).
    turns : array_like
        Number of turns N [-].
    side : array_like
        Side of the square turn l [m].

    Returns
    -------
    ndarray
        m = N (U/R) l² [A·m²], through :func:`magbench.hardware.coil_current` and
        :func:`magbench.hardware.dipole_moment`.

    Notes
    -----
    Thesis eq. (17)–(18) with the measured resistance (thesis §3.3): 0.524 A·m² for
    12 V, 55 Ω, N = 240, l = 0.1 m. If the extra 1.5 Ω were extra turns (the thesis's
    explanation), eq. (20) would give 0.539 A·m² whatever N; the Monte Carlo's ±5 %
    moment spread covers the difference.

    Examples
    --------
    >>> round(float(coil_full_scale_moment(12.0, 55.0, 240, 0.1)), 4)
    0.5236
    """
    r = as_positive("resistance", resistance, unit="Ω")
    n = as_positive("turns", turns)
    current = coil_current(voltage, r / n, n)
    return dipole_moment(current, n, turn_area(side, "square"))


def quantise_duty(duty, levels):
    r"""Signed PWM duty as the Arduino's ``analogWrite`` and the L298 deliver it.

    Parameters
    ----------
    duty : array_like
        Requested duty in [−1, 1] [-]; the sign selects the L298's bridge direction.
    levels : int
        Duty steps each way [-]: 255 for ``analogWrite``'s 8 bits; 0 for no quantisation.

    Returns
    -------
    ndarray
        sign(d)·round(|d|·levels)/levels [-] (round half to even, as numpy rounds; the
        firmware's rounding is not known).

    Notes
    -----
    Not in the thesis: it names the L298 module (thesis §4.2) but not the resolution.

    Examples
    --------
    >>> quantise_duty([0.5, -0.001, 0.003], 255).round(6).tolist()
    [0.501961, -0.0, 0.003922]
    """
    d = np.asarray(duty, dtype=float)
    if np.ndim(levels) == 0 and not levels:
        return d
    steps = np.asarray(levels, dtype=float)
    if np.any(~np.isfinite(steps) | (steps < 1) | (steps != np.rint(steps))):
        bad = steps[~np.isfinite(steps) | (steps < 1) | (steps != np.rint(steps))].ravel()[0]
        raise ValueError(f"levels must be a whole number of duty steps >= 1, or 0 for none, got {shown(bad)}")
    return np.rint(d * steps) / steps
