"""Coaxial pairs of circular coils: the Helmholtz pair of the field simulator.

Thesis §2.2, eq. (16) and Kovalenko (1975) §3.4 (eqs. 3.19–3.21). SI throughout.
"""

import math

import numpy as np
from scipy import optimize

from .._validate import as_finite, as_positive, shown
from ..constants import MU_0
from ._inputs import _finite_scalar, _nonnegative_scalar, _positive_scalar
from .loop import _coaxial_b

__all__ = ["helmholtz_b", "helmholtz_h_magnitude", "helmholtz_center_h", "helmholtz_center_h_spread",
           "helmholtz_ampere_turns", "pair_radius_for_center_h", "pair_peak_center_h", "planar_pair_center_h"]


def helmholtz_b(points, radius, separation, current, turns):
    r"""Flux density of two coaxial loops at z = ±separation/2 carrying equal currents.

    Parameters
    ----------
    points : array_like, shape (..., 3)
        Observation points [m].
    radius : float
        Coil radius a_c [m], > 0.
    separation : float
        Distance between the coil planes d_c [m], >= 0 (0 gives one coil of 2N turns).
    current : float
        Current in each coil I [A], same sense in both.
    turns : float
        Turns per coil N [-], > 0.

    Returns
    -------
    ndarray, shape (..., 3)
        B [T].

    Notes
    -----
    Not in the thesis as a field map (its Figs. 5–7 are COMSOL results); thesis eq. (16)
    is the value at the centre, μ0 times :func:`helmholtz_center_h`. Each coil is a thin
    loop evaluated as in :func:`loop_b` (same accuracy); the radial geometry is shared
    between the two coils.

    Examples
    --------
    >>> from magbench.constants import MU_0
    >>> b = helmholtz_b([0.0, 0.0, 0.0], 0.5, 0.5, 2.3, 110)
    >>> round(float(b[2] / MU_0), 1)
    362.1
    """
    a = _positive_scalar("radius", radius, unit="m")
    d = _nonnegative_scalar("separation", separation, unit="m")
    i = _finite_scalar("current", current)
    n = _positive_scalar("turns", turns)
    return _coaxial_b(points, a, [-d / 2.0, d / 2.0], n * i)


def helmholtz_h_magnitude(points, radius, separation, current, turns):
    r"""Field strength |H| = |B|/μ0 of a coaxial coil pair at given points.

    Parameters
    ----------
    points : array_like, shape (..., 3)
        Observation points, the pair's axis along z [m].
    radius : float
        Coil radius a_c [m], > 0.
    separation : float
        Distance between the coil planes d_c [m], >= 0.
    current : float
        Current in each coil I [A].
    turns : float
        Turns per coil N [-], > 0.

    Returns
    -------
    ndarray, shape (...)
        |H| [A/m].

    Notes
    -----
    Not in the thesis as a field map: its Figs. 6–7 (§2.3) plot |H| along lines through the
    centre from COMSOL; this is :func:`helmholtz_b` over μ0 (thesis eq. (16) at the centre).

    Examples
    --------
    >>> round(float(helmholtz_h_magnitude([0.0, 0.0, 0.0], 0.5, 0.5, 2.3, 110)), 1)
    362.1
    """
    return np.linalg.norm(helmholtz_b(points, radius, separation, current, turns), axis=-1) / MU_0


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
    Thesis eq. (16); exact for two thin loops (the on-axis field of
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
        raise ValueError(f"separation must be >= 0 m, got {shown(d[d < 0].ravel()[0])}")
    return n * i / (a * ((d / (2.0 * a)) ** 2 + 1.0) ** 1.5)


def helmholtz_center_h_spread(current, turns, radius, separation_range, current_spread):
    r"""Largest change of a coil pair's midpoint field over a box of spacings and currents.

    Parameters
    ----------
    current : float
        Nominal current in each coil I [A].
    turns : float
        Turns per coil N [-], > 0.
    radius : float
        Coil radius a_c [m], > 0.
    separation_range : tuple of float
        (low, high) centre-to-centre spacing d_c [m], 0 <= low <= high.
    current_spread : float
        Half-width ΔI of the current's interval [A], >= 0.

    Returns
    -------
    float
        max |H(I ± ΔI, d) − H(I, d_mid)| over d in ``separation_range`` [A/m], d_mid its middle.

    Notes
    -----
    Thesis eq. (16) (:func:`helmholtz_center_h`) at the corners of the box; the field is
    monotonic in I and in d over it, so the corners bound it. Thesis §2.4: the as-built pair
    with 0.50–0.52 m spacing and a current printed to 0.1 A.

    Examples
    --------
    >>> round(helmholtz_center_h_spread(2.3, 110, 0.5, (0.50, 0.52), 0.05), 2)
    12.22
    """
    separations = as_finite("separation_range", separation_range)
    if separations.shape != (2,):
        raise ValueError(f"separation_range must be (low, high) [m], got shape {separations.shape}")
    low, high = float(separations[0]), float(separations[1])
    if not 0.0 <= low <= high:
        raise ValueError(f"separation_range must be (low, high) with 0 <= low <= high [m], got ({low!r}, {high!r})")
    spread = float(as_finite("current_spread", current_spread))
    if spread < 0.0:
        raise ValueError(f"current_spread must be >= 0 A, got {shown(current_spread)}")
    base = float(helmholtz_center_h(current, turns, radius, 0.5 * (low + high)))
    return max(abs(float(helmholtz_center_h(current + di, turns, radius, d)) - base)
               for di in (-spread, spread) for d in (low, high))


def helmholtz_ampere_turns(center_h, radius, separation):
    r"""Ampere-turns per coil that give a target field at the midpoint of a coil pair.

    Parameters
    ----------
    center_h : array_like
        Target axial field strength at the midpoint H [A/m].
    radius : array_like
        Coil radius a_c [m], > 0.
    separation : array_like
        Distance between the coil planes d_c [m], >= 0.

    Returns
    -------
    ndarray
        N·I per coil [A].

    Notes
    -----
    Thesis eq. (16), solved for NI:

    .. math:: NI = H a_c\left[\left(\frac{d_c}{2a_c}\right)^2 + 1\right]^{3/2}

    With the thesis's design values H = 250 A/m, a_c = 0.5 m, d_c = 1.116 a_c this is
    187.7 A; the thesis prints 258 (see :func:`thesis_printed_ampere_turns`).

    Examples
    --------
    >>> round(float(helmholtz_ampere_turns(250.0, 0.5, 1.116 * 0.5)), 1)
    187.7
    """
    h = as_finite("center_h", center_h)
    a = as_positive("radius", radius, unit="m")
    d = as_finite("separation", separation)
    if np.any(d < 0):
        raise ValueError(f"separation must be >= 0 m, got {shown(d[d < 0].ravel()[0])}")
    return h * a * ((d / (2.0 * a)) ** 2 + 1.0) ** 1.5


def pair_radius_for_center_h(center_h, ampere_turns, separation):
    r"""Coil radius at which a coaxial pair gives a stated field at its midpoint.

    Parameters
    ----------
    center_h : float
        Field at the midpoint H [A/m], > 0.
    ampere_turns : float
        N·I per coil [A], > 0.
    separation : float
        Distance between the coil planes d [m], > 0.

    Returns
    -------
    float
        The radius a [m] on the branch a ≥ d/√2.

    Notes
    -----
    Not in the thesis: eq. (16), H = NI a²/(a² + d²/4)^{3/2}, solved for a (Brent's
    method). As a function of a, H rises from 0, peaks at a = d/√2 and falls like NI/a,
    so a field below the peak has two radii; the larger one (coils wider than
    d/√2, as in any Helmholtz-like pair) is returned. A field above the peak,
    H(d/√2) = 4NI/(3√3 d), has no solution and raises ``ValueError``.

    Examples
    --------
    >>> a = pair_radius_for_center_h(362.0641269167659, 253.0, 0.5)
    >>> round(float(a), 6)
    0.5
    """
    h = _positive_scalar("center_h", center_h, unit="A/m")
    ni = _positive_scalar("ampere_turns", ampere_turns, unit="A")
    d = _positive_scalar("separation", separation, unit="m")

    def field(a):
        return ni * a * a / (a * a + d * d / 4.0) ** 1.5

    a_peak = d / math.sqrt(2.0)
    if h > field(a_peak):
        raise ValueError(f"center_h must be <= {shown(field(a_peak))} A/m (the largest midpoint field of "
                         f"NI = {shown(ni)} A at separation {shown(d)} m), got {shown(h)}")
    hi = a_peak
    while field(hi) > h:
        hi *= 2.0
    return float(optimize.brentq(lambda a: field(a) - h, a_peak, hi, xtol=1e-15, rtol=1e-15))


def pair_peak_center_h(ampere_turns, separation):
    r"""Largest midpoint field a coaxial pair of given spacing and ampere-turns gives, over all radii.

    Parameters
    ----------
    ampere_turns : array_like
        N·I per coil [A].
    separation : array_like
        Distance between the coil planes d [m], > 0.

    Returns
    -------
    ndarray
        H at the midpoint for the best radius a = d/√2 [A/m].

    Notes
    -----
    Not in the thesis: the maximum over a of thesis eq. (16),
    H(a) = NI a²/(a² + d²/4)^{3/2}, reached at a = d/√2:

    .. math:: H_\text{peak} = \frac{4 NI}{3\sqrt3\,d}.

    No coil radius gives a larger midpoint field (:func:`pair_radius_for_center_h`
    raises above it).

    Examples
    --------
    >>> round(float(pair_peak_center_h(253.0, 0.51)), 1)
    381.9
    """
    ni = as_finite("ampere_turns", ampere_turns)
    d = as_positive("separation", separation, unit="m")
    return 4.0 * ni / (3.0 * np.sqrt(3.0) * d)


def planar_pair_center_h(ampere_turns, radius, separation):
    r"""Midpoint field of a coil pair's cross-section treated as four infinite wires.

    Parameters
    ----------
    ampere_turns : array_like
        N·I per coil [A].
    radius : array_like
        Coil radius a [m], > 0.
    separation : array_like
        Distance between the coil planes d [m], >= 0.

    Returns
    -------
    ndarray
        H at the midpoint [A/m] of the two-dimensional planar model.

    Notes
    -----
    Not in the thesis: a hypothesis for its COMSOL result (thesis §2.3). A planar 2-D
    model of the meridian cross-section replaces each coil by two infinite straight
    wires at (±a, ±d/2) carrying ±NI; each contributes NI/(2πr) at the midpoint,
    r² = a² + d²/4, of which the axial part a/r adds up:

    .. math:: H = \frac{2 NI a}{\pi\,(a^2 + d^2/4)} .

    The real (axisymmetric) pair gives eq. (16) instead.

    Examples
    --------
    >>> round(float(planar_pair_center_h(253.0, 0.5, 0.5)), 1)
    257.7
    """
    ni = as_finite("ampere_turns", ampere_turns)
    a = as_positive("radius", radius, unit="m")
    d = as_finite("separation", separation)
    if np.any(d < 0):
        raise ValueError(f"separation must be >= 0 m, got {shown(d[d < 0].ravel()[0])}")
    return 2.0 * ni * a / (np.pi * (a * a + d * d / 4.0))
