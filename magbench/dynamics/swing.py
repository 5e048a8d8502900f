"""The field a suspended magnet needs to swing with a given period.

Thesis §2.1, eqs. (13)–(15). SI throughout.
"""

import numpy as np

from .._validate import as_positive
from ..constants import MU_0

__all__ = ["oscillation_field_h", "oscillation_moment"]


def oscillation_field_h(inertia, moment, period, amplitude=1.0):
    r"""Field strength that makes a magnet-carrying mock-up swing with a given period.

    Parameters
    ----------
    inertia : array_like
        Moment of inertia of the mock-up about its suspension axis J [kg m²], > 0.
    moment : array_like
        Dipole moment of the mock-up's magnet m [A m²], > 0.
    period : array_like
        Small-oscillation period T [s], > 0.
    amplitude : array_like, optional
        The factor A [rad] that the thesis defines as the oscillation amplitude, > 0.
        1 gives eq. (15) exactly as printed.

    Returns
    -------
    ndarray
        H [A/m].

    Notes
    -----
    Thesis eqs. (13)–(15). The small-angle torque mBφ (13) gives
    ω = 2π/T = √(mB/J) (14), so

    .. math:: H = \frac{B}{\mu_0} = \frac{4\pi^2 J A}{\mu_0 m T^2}.

    Deviation from source: the printed eq. (15) has no A; with the thesis's J = 0.005
    kg m², m = 0.6 A m², T = 60 s it gives 72.7 A/m, while the thesis's "≈ 200 A/m"
    needs A = π (228.5 A/m). A small-oscillation period does not depend on the
    amplitude, so the factor has no physical basis; it is offered here to reproduce
    the printed number.

    Examples
    --------
    >>> round(float(oscillation_field_h(0.005, 0.6, 60.0)), 1)
    72.7
    >>> round(float(oscillation_field_h(0.005, 0.6, 60.0, amplitude=np.pi)), 1)
    228.5
    """
    return _swing_quotient(inertia, as_positive("moment", moment, unit="A m^2"), period, amplitude)


def oscillation_moment(inertia, field_h, period, amplitude=1.0):
    r"""Dipole moment that makes a mock-up swing with a given period in a given field.

    Parameters
    ----------
    inertia : array_like
        Moment of inertia of the mock-up about its suspension axis J [kg m²], > 0.
    field_h : array_like
        Field strength H [A/m], > 0.
    period : array_like
        Small-oscillation period T [s], > 0.
    amplitude : array_like, optional
        The factor A [rad] that the thesis defines as the oscillation amplitude, > 0.
        1 gives the small-oscillation moment of eq. (14).

    Returns
    -------
    ndarray
        m [A m²].

    Notes
    -----
    Thesis §3.2, an unnumbered formula at the start of the section: eq. (15) solved for the
    moment, printed with the factor A,

    .. math:: m = \frac{4\pi^2 J A}{\mu_0 H T^2}.

    Deviation from source: with the thesis's own inputs (J = 0.005 kg m², A = π,
    H = 250 A/m) this gives 0.548 A m² at T = 60 s, not the printed "≈ 0.4", and
    0.0219 A m² at T = 5 min (printed "≈ 0.02"). As for :func:`oscillation_field_h`, a
    small-oscillation period does not depend on the amplitude; A = 1 is the physical
    value.

    Examples
    --------
    >>> round(float(oscillation_moment(0.005, 250.0, 60.0, amplitude=np.pi)), 3)
    0.548
    >>> round(float(oscillation_moment(0.005, 250.0, 300.0, amplitude=np.pi)), 4)
    0.0219
    """
    return _swing_quotient(inertia, as_positive("field_h", field_h, unit="A/m"), period, amplitude)


def _swing_quotient(inertia, known, period, amplitude):
    """4π²JA/(μ0 x T²): the field for a known moment, or the moment for a known field
    (m and H enter eq. (14) only as their product)."""
    j = as_positive("inertia", inertia, unit="kg m^2")
    t = as_positive("period", period, unit="s")
    amp = as_positive("amplitude", amplitude, unit="rad")
    return 4.0 * np.pi**2 * j * amp / (MU_0 * known * t**2)
