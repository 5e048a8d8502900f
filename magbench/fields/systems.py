"""Systems of coils: three orthogonal pairs, and coaxial systems of circles and squares.

Kovalenko (1975) §3.4 (Maxwell's, Rubens' and the four-coil systems) and the thesis's
ref. [1] (three-axis simulators), and the horizontal field a simulator and a background
make together at the bench (thesis §4.4). SI throughout.
"""

import numpy as np

from ..constants import MU_0
from .._docstrings import fill_docstring
from .._validate import as_finite, as_nonnegative, as_positive, as_vectors, shown
from ._inputs import TOLERANCE_DOC, _center, _nonnegative_scalar, _tolerance
from ._search import _crossing_after_scan
from .loop import loop_b_posed
from .square import square_loop_b

__all__ = ["SPHERE_DIRECTIONS", "three_axis_pair_b", "three_axis_pair_currents", "three_axis_uniform_radius",
           "coaxial_system_b",
           "coaxial_system_sphere_nonuniformity", "coaxial_system_cylinder_nonuniformity",
           "coaxial_system_uniform_radius", "horizontal_field"]

#: The three pairs and the coaxial systems, described once for every function that takes them.
_SYSTEM_PARAMETERS = {
    "radii": """radii : array_like, shape (3,) or scalar
    Coil radius of each pair [m], > 0.""",
    "separations": """separations : array_like, shape (3,) or scalar
    Distance between the coil planes of each pair [m], > 0.""",
    "turns": """turns : array_like, shape (3,) or scalar
    Turns per coil of each pair [-], > 0.""",
    "shapes": """shapes : sequence of {"round", "square"}
    Shape of each coil [-].""",
    "sizes": """sizes : array_like, shape (n,)
    Radius of each round coil, side of each square [m], > 0.""",
    "positions": """positions : array_like, shape (n,)
    z of each coil's plane [m].""",
    "ampere_turns": """ampere_turns : array_like, shape (n,)
    N·I of each coil [A] (sign gives the sense).""",
    "tolerance": TOLERANCE_DOC,
}
_document_system = fill_docstring(_SYSTEM_PARAMETERS)


def _pair_axes(axes):
    ax = as_vectors("axes", axes)
    if ax.shape != (3, 3):
        raise ValueError(f"axes must be three 3-vectors, shape (3, 3), got shape {ax.shape}")
    norms = np.linalg.norm(ax, axis=-1)
    if np.any(norms == 0.0):
        raise ValueError("axes must be non-zero 3-vectors")
    return ax / norms[:, None]


def _three(name, value, unit):
    arr = as_positive(name, value, unit=unit)
    arr = np.broadcast_to(arr, (3,)) if arr.ndim == 0 else arr
    if arr.shape != (3,):
        raise ValueError(f"{name} must be a scalar or three values, got shape {arr.shape}")
    return arr


@_document_system
def three_axis_pair_b(points, currents, radii, separations, turns, axes=np.eye(3)):
    r"""Flux density of three coaxial coil pairs centred on the origin.

    Parameters
    ----------
    points : array_like, shape (..., 3)
        Observation points [m].
    currents : array_like, shape (3,)
        Current in each coil of pair k [A] (both coils of a pair carry it).
    {radii, separations, turns}
    axes : array_like, shape (3, 3), optional
        Row k is the axis of pair k [-] (any non-zero length); default x, y, z.

    Returns
    -------
    ndarray, shape (..., 3)
        B [T].

    Notes
    -----
    Not in the thesis (it built one pair): the three-axis simulator of its ref. [1]
    (Pastena & Grassi 2002) and of Kovalenko (1975) §3.4, p. 60 ("fields along
    three orthogonal axes … to compensate the Earth's field"). Sum of six
    :func:`loop_b_posed` loops at ±d_k/2 along axis k.

    Examples
    --------
    >>> b = three_axis_pair_b([0.0, 0.0, 0.0], [2.3, 0.0, 0.0], 0.5, 0.5, 110)
    >>> from magbench.constants import MU_0
    >>> round(float(b[0] / MU_0), 1)
    362.1
    """
    i = as_finite("currents", currents)
    if i.shape != (3,):
        raise ValueError(f"currents must hold three values, got shape {i.shape}")
    a = _three("radii", radii, "m")
    d = _three("separations", separations, "m")
    n = _three("turns", turns, "")
    ax = _pair_axes(axes)
    p = as_vectors("points", points)
    out = np.zeros(p.shape)
    for k in range(3):
        if i[k] == 0.0:
            continue
        for sign in (-1.0, 1.0):
            out += loop_b_posed(p, a[k], i[k], n[k], sign * d[k] / 2.0 * ax[k], ax[k])
    return out


@_document_system
def three_axis_pair_currents(target_b, background_b, radii, separations, turns, axes=np.eye(3),
                             point=(0.0, 0.0, 0.0)):
    r"""Currents of three coil pairs that make the total field at a point equal a target.

    Parameters
    ----------
    target_b : array_like, shape (3,)
        Wanted total flux density at ``point`` [T] (zero cancels the background).
    background_b : array_like, shape (3,)
        Uniform background flux density, e.g. the Earth's field in the laboratory [T].
    {radii, separations, turns}
    axes : array_like, shape (3, 3), optional
        Row k is the axis of pair k [-]; need not be orthogonal, but must span space.
    point : array_like, shape (3,), optional
        Where the target is imposed [m]; default the common centre.

    Returns
    -------
    ndarray, shape (3,)
        Current per coil of each pair [A].

    Notes
    -----
    Not in the thesis: the design problem of its ref. [1] (Pastena & Grassi 2002). The
    field is linear in the currents, B(point) = B_bg + C i, where column k of C is the
    exact field of pair k at 1 A (:func:`three_axis_pair_b`); C holds the
    cross-coupling of misaligned axes or an off-centre point. Solved with
    ``numpy.linalg.solve``; axes that do not span space raise ``ValueError``.

    Examples
    --------
    >>> from magbench.constants import MU_0
    >>> i = three_axis_pair_currents([MU_0 * 362.0641269167659, 0, 0], [0, 0, 0], 0.5, 0.5, 110)
    >>> np.round(i, 6).tolist()
    [2.3, 0.0, 0.0]
    """
    target = as_vectors("target_b", target_b)
    background = as_vectors("background_b", background_b)
    if target.shape != (3,) or background.shape != (3,):
        raise ValueError("target_b and background_b must be single 3-vectors")
    p = _center(point)
    coupling = np.stack([three_axis_pair_b(p, np.eye(3)[k], radii, separations, turns, axes)
                         for k in range(3)], axis=-1)
    if np.linalg.cond(coupling) > 1e12:
        raise ValueError("axes must span three dimensions (the coupling matrix is singular)")
    return np.linalg.solve(coupling, target - background)


@_document_system
def three_axis_uniform_radius(currents, radii, separations, turns, background_b, target_b, tolerance,
                              axes=np.eye(3)):
    r"""Radius of the largest centred sphere in which three coil pairs and a background
    make the target field to within a tolerance.

    Parameters
    ----------
    currents : array_like, shape (3,)
        Current per coil of each pair [A] (e.g. from :func:`three_axis_pair_currents`).
    {radii, separations, turns}
    background_b : array_like, shape (3,)
        Uniform background flux density [T].
    target_b : array_like, shape (3,)
        The wanted total flux density [T]; zero asks for cancellation of the background.
    tolerance : float
        Allowed vector deviation δ = |B − B_target| / B_ref [-], in (0, 1), where B_ref is
        |B_target|, or |B_background| when the target is zero.
    axes : array_like, shape (3, 3), optional
        Row k is the axis of pair k [-]; default x, y, z.

    Returns
    -------
    float
        Sphere radius [m], at most 0.99 times the smallest coil radius (the search's end).

    Notes
    -----
    Not in the thesis (it built one pair): the uniform volume of the three-axis simulator
    of its ref. [1]. Unlike :func:`coaxial_system_uniform_radius` the deviation is that of
    the vector, B = B_background + :func:`three_axis_pair_b`, sampled on the sphere in the
    1162 directions of :data:`SPHERE_DIRECTIONS`: the first radius at which it reaches δ,
    by a scan of 80 radii up to 0.99 of the smallest coil radius and Brent's method
    (to 1e-7 m).

    Examples
    --------
    >>> from magbench.constants import MU_0
    >>> target = [MU_0 * 250.0, 0.0, 0.0]
    >>> i = three_axis_pair_currents(target, [0.0, 0.0, 0.0], 0.5, 0.5, 110)
    >>> round(three_axis_uniform_radius(i, 0.5, 0.5, 110, [0.0, 0.0, 0.0], target, 0.01), 3)
    0.157
    """
    i = as_finite("currents", currents)
    if i.shape != (3,):
        raise ValueError(f"currents must hold three values, got shape {i.shape}")
    a = _three("radii", radii, "m")
    target = as_vectors("target_b", target_b)
    background = as_vectors("background_b", background_b)
    if target.shape != (3,) or background.shape != (3,):
        raise ValueError("target_b and background_b must be single 3-vectors")
    tol = _tolerance(tolerance)
    reference = float(np.linalg.norm(target)) or float(np.linalg.norm(background))
    if reference == 0.0:
        raise ValueError("target_b and background_b must not both be zero (no field to compare with)")
    s_max = 0.99 * float(a.min())

    def dev(s):
        b = background + three_axis_pair_b(s * SPHERE_DIRECTIONS, i, radii, separations, turns, axes)
        return float(np.max(np.linalg.norm(b - target, axis=-1))) / reference

    grid = np.linspace(0.0, s_max, 81)[1:]
    values = np.array([dev(s) for s in grid])
    return float(_crossing_after_scan(dev, tol, grid, values, s_max, xtol=1e-7))


_SHAPES = ("round", "square")


def _system(shapes, sizes, positions, ampere_turns):
    shapes = list(shapes)
    bad = [s for s in shapes if s not in _SHAPES]
    if bad:
        raise ValueError(f"shapes must be 'round' or 'square', got {shown(bad[0])}")
    sz = as_positive("sizes", sizes, unit="m")
    pos = as_finite("positions", positions)
    ni = as_finite("ampere_turns", ampere_turns)
    n = len(shapes)
    for name, arr in (("sizes", sz), ("positions", pos), ("ampere_turns", ni)):
        if arr.shape != (n,):
            raise ValueError(f"{name} must hold one value per coil ({n}), got shape {arr.shape}")
    return shapes, sz, pos, ni


@_document_system
def coaxial_system_b(points, shapes, sizes, positions, ampere_turns):
    r"""Flux density of a system of coaxial circular and square coils on the z axis.

    Parameters
    ----------
    points : array_like, shape (..., 3)
        Observation points [m].
    {shapes, sizes, positions, ampere_turns}

    Returns
    -------
    ndarray, shape (..., 3)
        B [T].

    Notes
    -----
    Not in the thesis: its Fig. 3 names the candidate systems (pairs of circles or
    squares, multiples of two rings); Kovalenko (1975) §3.4, pp. 60–61, gives
    the Maxwell, three-coil, four-coil and Rubens systems. Sum of :func:`loop_b_posed`
    and :func:`square_loop_b` (sides along x and y).

    Examples
    --------
    >>> b = coaxial_system_b([0.0, 0.0, 0.0], ["round", "round"], [0.5, 0.5], [-0.25, 0.25], [253.0, 253.0])
    >>> from magbench.constants import MU_0
    >>> round(float(b[2] / MU_0), 1)
    362.1
    """
    shapes, sz, pos, ni = _system(shapes, sizes, positions, ampere_turns)
    p = as_vectors("points", points)
    out = np.zeros(p.shape)
    z = np.array([0.0, 0.0, 1.0])
    for shape, size, z0, w in zip(shapes, sz, pos, ni):
        if w == 0.0:
            continue
        if shape == "round":
            out += loop_b_posed(p, size, w, 1, z0 * z, z)
        else:
            out += square_loop_b(p, size, w, 1, z0 * z, z)
    return out


def _fibonacci_directions(count):
    k = np.arange(count) + 0.5
    polar = np.arccos(1.0 - 2.0 * k / count)
    azimuth = np.pi * (1.0 + 5.0**0.5) * k
    return np.stack([np.sin(polar) * np.cos(azimuth), np.sin(polar) * np.sin(azimuth), np.cos(polar)], -1)


def _meridians(count, azimuths):
    t = np.linspace(0.0, np.pi, count)
    return np.concatenate([np.stack([np.sin(t) * np.cos(f), np.sin(t) * np.sin(f), np.cos(t)], -1)
                           for f in azimuths])


#: Directions sampling a sphere's surface: the golden-angle spiral (near-uniform) plus
#: two meridians (azimuth 0 and 45°) through the poles, where coaxial systems usually
#: deviate most, and across the equator.
SPHERE_DIRECTIONS = np.concatenate([_fibonacci_directions(800), _meridians(181, (0.0, np.pi / 4))])


def _system_deviation(points, system):
    b0 = np.linalg.norm(coaxial_system_b(np.zeros(3), *system))
    b = np.linalg.norm(coaxial_system_b(points, *system), axis=-1)
    return np.abs(b / b0 - 1.0)


@_document_system
def coaxial_system_sphere_nonuniformity(shapes, sizes, positions, ampere_turns, sphere_radius):
    r"""Largest deviation of |B| from its centre value inside a centred sphere.

    Parameters
    ----------
    {shapes, sizes, positions, ampere_turns}
    sphere_radius : float
        Radius of the sphere [m], >= 0, inside the coils.

    Returns
    -------
    float
        max | |B| − B0 | / B0 over the ball [-].

    Notes
    -----
    Not in the thesis: Kovalenko (1975) §3.4, p. 61, quotes the four-coil system
    as uniform to 0.5 % in a sphere of radius 2r/3. Sampled on 40 concentric spheres of
    1162 directions each (:data:`SPHERE_DIRECTIONS`).

    Examples
    --------
    >>> dev = coaxial_system_sphere_nonuniformity(["round"] * 2, [1.0, 1.0], [-0.5, 0.5], [1.0, 1.0], 1 / 3)
    >>> round(100 * dev, 2)     # the Helmholtz pair: 1.26 % in a sphere of radius r/3
    1.26
    """
    system = _system(shapes, sizes, positions, ampere_turns)
    s = _nonnegative_scalar("sphere_radius", sphere_radius, unit="m")
    shells = np.linspace(s / 40.0, s, 40)
    pts = shells[:, None, None] * SPHERE_DIRECTIONS[None, :, :]
    return float(_system_deviation(pts.reshape(-1, 3), system).max())


@_document_system
def coaxial_system_cylinder_nonuniformity(shapes, sizes, positions, ampere_turns, cylinder_radius,
                                          cylinder_length):
    r"""Largest deviation of |B| from its centre value inside a centred coaxial cylinder.

    Parameters
    ----------
    {shapes, sizes, positions, ampere_turns}
    cylinder_radius : float
        Radius of the cylinder [m], >= 0.
    cylinder_length : float
        Its length along z [m], >= 0.

    Returns
    -------
    float
        max | |B| − B0 | / B0 over the solid cylinder [-].

    Notes
    -----
    Not in the thesis: Kovalenko (1975) §3.4, p. 61 — Rubens' five square
    sections are uniform to 1 % in a cylinder of length a/2 and radius a/4. Sampled on
    a 41 (ρ) × 25 (azimuth over a quarter turn: circles and squares centred on the axis
    have four-fold symmetry) × 81 (z) grid.

    Examples
    --------
    >>> dev = coaxial_system_cylinder_nonuniformity(["round"] * 2, [1.0, 1.0], [-0.5, 0.5], [1.0, 1.0], 0.1, 0.2)
    >>> round(100 * dev, 4)
    0.0186
    """
    system = _system(shapes, sizes, positions, ampere_turns)
    c = _nonnegative_scalar("cylinder_radius", cylinder_radius, unit="m")
    h = _nonnegative_scalar("cylinder_length", cylinder_length, unit="m") / 2.0
    rho, phi, z = np.meshgrid(np.linspace(0.0, c, 41), np.linspace(0.0, np.pi / 2, 25),
                              np.linspace(-h, h, 81), indexing="ij")
    pts = np.stack([rho * np.cos(phi), rho * np.sin(phi), z], axis=-1).reshape(-1, 3)
    return float(_system_deviation(pts, system).max())


@_document_system
def coaxial_system_uniform_radius(shapes, sizes, positions, ampere_turns, tolerance):
    r"""Radius of the largest centred sphere in which |B| stays within a tolerance.

    Parameters
    ----------
    {shapes, sizes, positions, ampere_turns, tolerance}

    Returns
    -------
    float
        Sphere radius [m].

    Notes
    -----
    Not in the thesis (its requirement, thesis §2.1, is δ < 5 % in a 10 cm sphere):
    the first radius at which the deviation on the sphere (1162 directions) reaches δ,
    by a scan of 120 radii up to the nearest wire and Brent's method. For a circular
    pair it agrees with :func:`uniform_sphere_radius` to 1e-6 radii.

    Examples
    --------
    >>> r = coaxial_system_uniform_radius(["round"] * 2, [1.0, 1.0], [-0.5, 0.5], [1.0, 1.0], 0.01)
    >>> round(r, 3)
    0.314
    """
    system = _system(shapes, sizes, positions, ampere_turns)
    tol = _tolerance(tolerance)
    shapes_, sz, pos, _ = system
    # The nearest wire: a round coil's wire is at distance hypot(r, z); a square's sides at
    # hypot(side/2, z). Stop short of it.
    half = np.array([size if sh == "round" else size / 2.0 for sh, size in zip(shapes_, sz)])
    s_max = 0.999 * float(np.min(np.hypot(half, pos)))

    def dev(s):
        s = np.asarray(s, dtype=float)
        pts = s.reshape(-1, 1, 1) * SPHERE_DIRECTIONS[None, :, :]
        return _system_deviation(pts.reshape(-1, 3), system).reshape(s.size, -1).max(axis=-1).reshape(s.shape)

    grid = np.linspace(0.0, s_max, 121)[1:]
    return float(_crossing_after_scan(dev, tol, grid, dev(grid), s_max, xtol=1e-10))


def horizontal_field(simulator_h, background_h=0.0, background_azimuth=0.0):
    r"""Magnitude of the horizontal flux density the mock-up sees.

    Parameters
    ----------
    simulator_h : array_like
        Field strength of the simulator at the centre [A/m] (the thesis measured 262 A/m,
        designed for 250 A/m).
    background_h : array_like, optional
        Horizontal background field strength, e.g. the Earth's [A/m]; default 0.
    background_azimuth : array_like, optional
        Angle from the simulator's axis to the background's horizontal direction [rad].

    Returns
    -------
    ndarray
        :math:`B_0 = \mu_0\,|H_s\hat x + H_b(\cos\beta, \sin\beta)|` [T].

    Notes
    -----
    Not in the thesis: it states neither how the simulator was oriented relative to the
    Earth's field nor whether the measured 262 A/m includes it. The
    angle ψ is then counted from this total horizontal field, which is also what the
    magnetometer measures, so the background only changes the loop gain.

    Examples
    --------
    >>> round(float(horizontal_field(262.0)) * 1e6, 2)
    329.24
    """
    hs = as_positive("simulator_h", simulator_h, unit="A/m")
    hb = as_nonnegative("background_h", background_h, unit="A/m")
    beta = as_finite("background_azimuth", background_azimuth)
    return MU_0 * np.hypot(hs + hb * np.cos(beta), hb * np.sin(beta))
