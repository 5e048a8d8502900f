r"""Fields of circular coils: single loops, the Helmholtz pair of the field simulator.

Thesis §2 (eq. 16). The exact off-axis loop field (complete elliptic integrals) is
the subject of the field-simulator chapter; until it lands, :func:`loop_b` and
:func:`helmholtz_b` raise ``NotImplementedError`` with their contract intact.
"""

import numpy as np

from ._validate import as_finite, as_positive

__all__ = ["loop_b", "helmholtz_b", "helmholtz_center_h"]


def loop_b(points, radius, current, turns=1):
    """Flux density of a thin circular loop in the plane z = 0, centred on the origin.

    Parameters
    ----------
    points : array_like, shape (..., 3)
        Observation points [m].
    radius : float
        Loop radius [m].
    current : float
        Current [A].
    turns : int, optional
        Number of turns [-].

    Returns
    -------
    ndarray, shape (..., 3)
        B [T].

    Notes
    -----
    Not in the thesis (it used COMSOL): Smythe, *Static and Dynamic Electricity*,
    §7.10. Not implemented yet: see the field-simulator chapter's issue.
    """
    raise NotImplementedError("loop_b arrives with the field-simulator chapter (thesis §2)")


def helmholtz_b(points, radius, separation, current, turns):
    """Flux density of two coaxial loops at z = ±separation/2 carrying equal currents.

    Parameters
    ----------
    points : array_like, shape (..., 3)
        Observation points [m].
    radius : float
        Coil radius a_c [m].
    separation : float
        Distance between the coil planes d_c [m].
    current : float
        Current in each coil [A].
    turns : int
        Turns per coil N [-].

    Returns
    -------
    ndarray, shape (..., 3)
        B [T].

    Notes
    -----
    Not in the thesis as a field map (its Figs. 5–7 are COMSOL results); thesis eq. (16)
    is the value at the centre. Not implemented yet: see the field-simulator chapter.
    """
    raise NotImplementedError("helmholtz_b arrives with the field-simulator chapter (thesis §2)")


def helmholtz_center_h(current, turns, radius, separation):
    r"""Axial field strength at the midpoint of a coaxial coil pair.

    Parameters
    ----------
    current : array_like
        Current in each coil I [A].
    turns : array_like
        Turns per coil N [-].
    radius : array_like
        Coil radius a_c [m].
    separation : array_like
        Distance between the coil planes d_c [m] (zero gives a single coil of 2N turns).

    Returns
    -------
    ndarray
        H at the midpoint [A/m].

    Notes
    -----
    Thesis eq. (16), seed line 263; exact for two thin loops (the on-axis field of
    each loop, μ0 N I a²/(2(a² + z²)^{3/2}), at z = d/2, doubled):

    .. math:: H = \frac{N I}{a_c\left[\left(\frac{d_c}{2a_c}\right)^2 + 1\right]^{3/2}}

    Examples
    --------
    >>> round(float(helmholtz_center_h(2.3, 110, 0.5, 0.5)), 1)
    362.1
    """
    i = as_finite("current", current)
    n = as_positive("turns", turns)
    a = as_positive("radius", radius, unit="m")
    d = as_finite("separation", separation)
    if np.any(d < 0):
        raise ValueError(f"separation must be >= 0 m, got {d[d < 0].ravel()[0]!r}")
    return n * i / (a * ((d / (2.0 * a)) ** 2 + 1.0) ** 1.5)
