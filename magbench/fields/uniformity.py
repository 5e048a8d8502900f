"""How uniform the field of a coil pair is: in spheres, cylinders and along lines.

Kovalenko (1975) §3.4 (uniform volumes of coil systems) and thesis §2.3 (the uniform
zones read off COMSOL). SI throughout.
"""

import math

import numpy as np
from scipy import optimize

from ._inputs import TOLERANCE_DOC, _nonnegative_scalar, _positive_scalar, _tolerance
from ._search import _crossing_after_scan
from .loop import _coaxial_unit
from .._docstrings import fill_docstring
from .._validate import shown

__all__ = ["sphere_nonuniformity", "cylinder_nonuniformity", "uniform_sphere_radius", "uniform_cylinder",
           "optimal_separation", "pair_distance_to_h", "uniform_zone_length", "zone_tolerance_for_length"]

#: The pair and the tolerance, described once for every function that takes them.
_PAIR_PARAMETERS = {
    "radius": """radius : float
    Coil radius a [m], > 0.""",
    "separation": """separation : float
    Distance between the coil planes d [m], >= 0.""",
    "tolerance": TOLERANCE_DOC,
}
_document_pair = fill_docstring(_PAIR_PARAMETERS)


def _pair(radius, separation):
    """The checked radius a and separation d [m] of a symmetric pair."""
    return (_positive_scalar("radius", radius, unit="m"),
            _nonnegative_scalar("separation", separation, unit="m"))


def _pair_deviation(rho, z, separation_ratio):
    """| |B| − B0 | / B0 of a unit-radius symmetric pair at (ρ, z) in radii."""
    rho, z = np.broadcast_arrays(np.asarray(rho, dtype=float), np.asarray(z, dtype=float))
    pts = np.zeros((rho.size + 1, 3))
    pts[1:, 0] = rho.ravel()
    pts[1:, 2] = z.ravel()
    h = separation_ratio / 2.0
    b = _coaxial_unit(pts, [-h, h], [1.0, 1.0])
    mag = np.sqrt(np.sum(b * b, axis=-1))
    return np.abs(mag[1:] / mag[0] - 1.0).reshape(rho.shape)


#: Polar angles (by the pair's mirror symmetry, a quadrant suffices) and the fraction
#: of the meridian half-plane sampled on the cylinder's surface.
_THETA = np.linspace(0.0, np.pi / 2, 361)


_UNIT = np.linspace(0.0, 1.0, 201)


def _sphere_boundary_dev(s, ratio):
    """Largest deviation on the spheres of radii ``s`` (array or scalar, in radii)."""
    s = np.asarray(s, dtype=float)[..., None]
    return _pair_deviation(s * np.sin(_THETA), s * np.cos(_THETA), ratio).max(axis=-1)


def _cylinder_boundary_dev(c, aspect, ratio):
    """Largest deviation on the surfaces of cylinders of radii ``c``, half-length aspect·c."""
    c = np.asarray(c, dtype=float)[..., None]
    half = aspect * c
    rho = np.concatenate(np.broadcast_arrays(c + 0.0 * _UNIT, c * _UNIT), axis=-1)
    z = np.concatenate(np.broadcast_arrays(half * _UNIT, half + 0.0 * _UNIT), axis=-1)
    return _pair_deviation(rho, z, ratio).max(axis=-1)


#: Radii scanned (as fractions of the largest possible) before Brent's refinement.
_SCAN = np.unique(np.concatenate([np.geomspace(1e-4, 1.0, 80), np.linspace(0.0, 1.0, 201)[1:]]))


def _first_crossing(f, tol, s_max):
    """Smallest s in (0, s_max) with f(s) = tol, given f(0) = 0 (grid scan, then Brent).

    ``f`` is vectorised over s.
    """
    grid = _SCAN * s_max
    return _crossing_after_scan(f, tol, grid, f(grid), s_max, xtol=1e-12 * s_max, rtol=1e-13)


def _uniform_sphere(ratio, tol):
    """Radius, in coil radii, of the largest sphere within ``tol`` for the separation ratio d/a."""
    s_wire = math.hypot(1.0, ratio / 2.0)
    return _first_crossing(lambda s: _sphere_boundary_dev(s, ratio), tol, s_wire)


@_document_pair
def sphere_nonuniformity(radius, separation, sphere_radius):
    r"""Largest relative deviation of |B| from its centre value on a centred sphere.

    Parameters
    ----------
    {radius, separation}
    sphere_radius : float
        Radius of the sphere [m], >= 0 and inside the coils' wires.

    Returns
    -------
    float
        max | |B| − B0 | / B0 over the sphere's surface [-], B0 = |B| at the centre.

    Notes
    -----
    Not in the thesis as a formula: the thesis's requirement δ_m < 5 % in a sphere of
    10 cm (thesis §2.1) and its COMSOL "uniform lengths" (thesis §2.3).
    Sampled at 361 polar angles on a quadrant (the pair is mirror-symmetric).
    Independent of the current and of the length scale.

    Examples
    --------
    >>> float(sphere_nonuniformity(0.5, 0.51, 0.10)) < 0.005
    True
    """
    a, d = _pair(radius, separation)
    s = _nonnegative_scalar("sphere_radius", sphere_radius, unit="m")
    wire = np.hypot(a, d / 2.0)      # distance from the centre to every point of both wires
    if s >= wire:
        raise ValueError(f"sphere_radius must be < {wire:.6g} m (the distance to the wires, √(a² + d²/4)), "
                         f"got {shown(s)}")
    return float(_sphere_boundary_dev(s / a, d / a))


@_document_pair
def cylinder_nonuniformity(radius, separation, cylinder_radius, cylinder_length):
    r"""Largest relative deviation of |B| from its centre value in a coaxial cylinder.

    Parameters
    ----------
    {radius, separation}
    cylinder_radius : float
        Radius of the centred coaxial cylinder [m], >= 0.
    cylinder_length : float
        Its length along the axis [m], >= 0.

    Returns
    -------
    float
        max | |B| − B0 | / B0 over the solid cylinder [-].

    Notes
    -----
    Not in the thesis: Kovalenko (1975) §3.4, p. 60 — a Helmholtz pair (d = a)
    is uniform to "no more than 0.02 %" in a cylinder of radius 0.1a and length 0.2a.
    This function gives 0.0186 % there. Sampled on a 101 × 101 grid of the meridian
    rectangle plus its boundary at 201 points per side.

    Examples
    --------
    >>> round(100 * float(cylinder_nonuniformity(1.0, 1.0, 0.1, 0.2)), 4)
    0.0186
    """
    a, d = _pair(radius, separation)
    c = _nonnegative_scalar("cylinder_radius", cylinder_radius, unit="m") / a
    h = _nonnegative_scalar("cylinder_length", cylinder_length, unit="m") / (2.0 * a)
    g = np.linspace(0.0, 1.0, 101)
    rho, z = np.meshgrid(c * g, h * g)
    inner = float(_pair_deviation(rho, z, d / a).max())
    aspect = h / c if c > 0 else 0.0
    if c > 0:
        edge = float(_cylinder_boundary_dev(c, aspect, d / a))
    else:
        edge = float(_pair_deviation(0.0 * _UNIT, h * _UNIT, d / a).max())
    return max(inner, edge)


@_document_pair
def uniform_sphere_radius(radius, separation, tolerance):
    r"""Radius of the largest centred sphere in which |B| stays within a tolerance.

    Parameters
    ----------
    {radius, separation, tolerance}

    Returns
    -------
    float
        Sphere radius [m].

    Notes
    -----
    Not in the thesis (its requirement, thesis §2.1, is δ < 5 % in a sphere of radius
    10 cm). The radius is the first s at which the deviation on the sphere of radius s
    reaches δ (grid scan, then Brent's method to 1e-12 a), so every point of the ball
    is within δ.

    Examples
    --------
    >>> round(float(uniform_sphere_radius(1.0, 1.0, 0.01)), 3)   # Helmholtz, δ = 1 %
    0.314
    """
    a, d = _pair(radius, separation)
    tol = _tolerance(tolerance)
    return a * _uniform_sphere(d / a, tol)


@_document_pair
def uniform_cylinder(radius, separation, tolerance, aspect=1.0):
    r"""Largest centred coaxial cylinder of a given shape in which |B| stays within a tolerance.

    Parameters
    ----------
    {radius, separation, tolerance}
    aspect : float, optional
        Length / diameter of the cylinder [-], > 0 (1 is Kovalenko's 0.2a × 0.1a).

    Returns
    -------
    tuple of float
        (cylinder radius [m], cylinder length [m]).

    Notes
    -----
    Not in the thesis: Kovalenko (1975) §3.4 quotes uniformity in a cylinder. Same
    first-crossing search as :func:`uniform_sphere_radius` over cylinders of fixed shape.

    Examples
    --------
    >>> c, length = uniform_cylinder(1.0, 1.0, 2e-4)
    >>> c > 0.1 and length == 2 * c
    True
    """
    a, d = _pair(radius, separation)
    tol = _tolerance(tolerance)
    k = _positive_scalar("aspect", aspect)
    ratio = d / a
    # The cylinder's rim (ρ = c, z = k c) reaches the wire (1, ratio/2) at the latest
    # when c = 1 or k c = ratio/2 + 1.
    c_max = min(1.0, (ratio / 2.0 + 1.0) / k) * 0.999
    c = _first_crossing(lambda s: _cylinder_boundary_dev(s, k, ratio), tol, c_max)
    return a * c, 2.0 * k * a * c


@_document_pair
def optimal_separation(radius, tolerance):
    r"""Coil spacing that maximises the centred sphere of uniform |B|.

    Parameters
    ----------
    {radius}
    tolerance : float
        Allowed relative deviation δ [-], in (0, 0.5].

    Returns
    -------
    float
        Separation d [m] maximising :func:`uniform_sphere_radius`.

    Notes
    -----
    Not in the thesis, which chose d = 1.116a citing its ref. [1] (Pastena & Grassi
    2002, unverified). Above d = a the axial field dips at the centre and rises
    off-centre, so the sphere radius (as a function of d) has a kinked maximum where the
    limiting direction changes. Found by a scan of d/a over [0.9, 1.3] in steps of 0.01,
    then a bounded Brent search (which needs no smoothness) to 1e-7 a in the best
    bracket. Gives d/a = 1.0089 (δ = 0.1 %), 1.0234 (1 %), 1.0332 (5 %) for the
    deviation of |B| (the vector deviation |B − B0|/B0 gives the same to 1e-4).

    Examples
    --------
    >>> round(float(optimal_separation(1.0, 0.01)), 4)
    1.0234
    """
    a = _positive_scalar("radius", radius, unit="m")
    tol = _positive_scalar("tolerance", tolerance)
    if tol > 0.5:
        raise ValueError(f"tolerance must lie in (0, 0.5], got {shown(tol)}")

    ratios = np.arange(0.9, 1.3 + 1e-9, 0.01)
    sizes = np.array([_uniform_sphere(r, tol) for r in ratios])
    j = int(np.argmax(sizes))
    if j == len(ratios) - 1 or j == 0:
        raise ValueError(f"tolerance {shown(tol)} puts the optimum outside d/a in [0.9, 1.3]")
    best = optimize.minimize_scalar(
        lambda r: -_uniform_sphere(r, tol), bounds=(ratios[j - 1], ratios[j + 1]), method="bounded",
        options={"xatol": 1e-7},
    )
    return a * float(best.x)


_DIRECTIONS = ("axial", "transverse")


def _line_deviation(direction, ratio):
    """Deviation of |B| from the centre value along the axis or the mid-plane line."""
    if direction not in _DIRECTIONS:
        raise ValueError(f"direction must be one of {_DIRECTIONS}, got {direction!r}")
    if direction == "axial":
        return lambda s: _pair_deviation(0.0 * np.asarray(s, dtype=float), s, ratio)
    return lambda s: _pair_deviation(s, 0.0 * np.asarray(s, dtype=float), ratio)


@_document_pair
def pair_distance_to_h(center_fraction, radius, separation, direction):
    r"""Distance from the midpoint of a coil pair at which |B| first falls to a fraction
    of its centre value, along the axis or along a line in the mid-plane.

    Parameters
    ----------
    center_fraction : float
        |B| / |B(centre)| to reach [-], in (0, 1).
    {radius}
    separation : float
        Distance between the coil planes d [m], > 0.
    direction : {"axial", "transverse"}
        The coil axis, or a line through the centre parallel to the coil planes [-].

    Returns
    -------
    float
        Distance from the centre [m].

    Notes
    -----
    Not in the thesis: used to ask how far from the centre a probe would have to sit
    to read the measured 262 A/m (thesis §2.4). The first point where
    | |B|/B0 − 1 | = 1 − fraction, found as in :func:`uniform_sphere_radius`; for
    d > a the axial field first rises, so only a fall below the centre value counts.

    Examples
    --------
    >>> from magbench.fields import helmholtz_b
    >>> s = pair_distance_to_h(0.5, 1.0, 1.0, "axial")
    >>> b = helmholtz_b([0.0, 0.0, s], 1.0, 1.0, 1.0, 1)[2] / helmholtz_b([0.0, 0.0, 0.0], 1.0, 1.0, 1.0, 1)[2]
    >>> round(float(b), 12)
    0.5
    """
    frac = _positive_scalar("center_fraction", center_fraction)
    if frac >= 1.0:
        raise ValueError(f"center_fraction must lie in (0, 1), got {shown(frac)}")
    a = _positive_scalar("radius", radius, unit="m")
    d = _positive_scalar("separation", separation, unit="m")
    dev = _line_deviation(direction, d / a)
    ratio = d / a
    if direction == "axial":
        b0 = np.linalg.norm(_coaxial_unit(np.zeros((1, 3)), [-ratio / 2, ratio / 2], [1.0, 1.0])[0])

        def fall(s):
            shape = np.shape(s)
            pts = np.zeros((int(np.prod(shape)), 3))
            pts[:, 2] = np.ravel(s)
            b = np.linalg.norm(_coaxial_unit(pts, [-ratio / 2, ratio / 2], [1.0, 1.0]), axis=-1)
            return np.maximum(1.0 - b / b0, 0.0).reshape(shape)
        return a * _first_crossing(fall, 1.0 - frac, 50.0)
    return a * _first_crossing(dev, 1.0 - frac, 3.0)


@_document_pair
def uniform_zone_length(radius, separation, tolerance, direction):
    r"""Length of the uniform stretch of a line through the centre of a coil pair.

    Parameters
    ----------
    {radius, separation, tolerance}
    direction : {"axial", "transverse"}
        The coil axis (thesis Fig. 7) or a line through the centre parallel to the coil
        planes (thesis Fig. 6) [-].

    Returns
    -------
    float
        Length [m] of the centred interval in which the deviation stays within δ.

    Notes
    -----
    Not in the thesis as a definition: its "uniform zone of order 25 cm" (Fig. 6) and
    "30 cm" (Fig. 7), thesis §2.3, read off COMSOL curves without a criterion.
    The interval ends where the deviation first reaches δ (grid scan and Brent's
    method, as in :func:`uniform_sphere_radius`); by the pair's symmetry it is centred.

    Examples
    --------
    >>> round(float(uniform_zone_length(0.5, 0.5, 0.01, "axial")), 3)
    0.314
    """
    a, d = _pair(radius, separation)
    tol = _tolerance(tolerance)
    dev = _line_deviation(direction, d / a)
    return 2.0 * a * _first_crossing(dev, tol, 3.0)


@_document_pair
def zone_tolerance_for_length(radius, separation, length, direction, tolerances):
    r"""Smallest tolerance band whose uniform zone on a line through a coil pair reaches a length.

    Parameters
    ----------
    {radius, separation}
    length : float
        Zone length to reach [m], > 0 (e.g. one read off a plot).
    direction : {"axial", "transverse"}
        The coil axis or a line through the centre parallel to the coil planes [-].
    tolerances : array_like, shape (n,)
        Increasing bands δ to scan [-], each in (0, 1).

    Returns
    -------
    float
        δ [-] at which :func:`uniform_zone_length` first equals ``length``: the first
        scanned band whose zone reaches it brackets it with the band before, and Brent's
        method refines it to 1e-9. NaN when no scanned band reaches the length, or the
        first one already does (the answer lies outside the scan).

    Notes
    -----
    Not in the thesis: its uniform zones "of order 25 cm" and "30 cm" (thesis §2.3,
    Figs. 6–7) name no band; this asks which band each reading implies. The zone length
    grows with δ but not continuously (a zone can jump where the deviation has a local
    maximum below δ), so the scan finds the first bracket before the refinement.

    Examples
    --------
    >>> t = zone_tolerance_for_length(0.5, 0.5, 0.314, "axial", np.geomspace(1e-4, 0.1, 61))
    >>> round(t, 4)
    0.01
    """
    a, d = _pair(radius, separation)
    target = _positive_scalar("length", length, unit="m")
    tol = np.asarray(tolerances, dtype=float)
    if tol.ndim != 1 or tol.size < 2 or np.any(~np.isfinite(tol)) or np.any(np.diff(tol) <= 0):
        raise ValueError(f"tolerances must be an increasing 1-D array of at least two values, got {shown(tol)}")
    if tol[0] <= 0.0 or tol[-1] >= 1.0:
        raise ValueError(f"tolerances must lie in (0, 1), got {shown(tol[0])} … {shown(tol[-1])}")
    lengths = np.array([uniform_zone_length(a, d, t, direction) for t in tol])
    if not np.any(lengths >= target):
        return float("nan")
    j = int(np.argmax(lengths >= target))
    if j == 0:
        return float("nan")
    return float(optimize.brentq(lambda t: uniform_zone_length(a, d, t, direction) - target, tol[j - 1], tol[j],
                                 xtol=1e-9))
