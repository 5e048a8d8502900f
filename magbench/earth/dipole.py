r"""The Earth's field as a centred dipole: field elements, the vector field, surface means.

Thesis §1.1 (eqs. 1–3) and Kovalenko (1975) ch. 2 (eqs. 2.1–2.3; the mean and RMS field,
Lowes' spectrum). SI: tesla, A·m², metres, radians; convert oersted and CGS moments at
the edge with :mod:`magbench.units`.

Sign convention (the thesis's own, §1.1): the local frame has x north, y east and z
**down**, and the inclination is positive when the field dips downwards, i.e. in the
northern geomagnetic hemisphere. The thesis's eqs. (1) and (3) print the opposite sign
(inherited from Kovalenko's eq. 2.3, whose footnote counts θ_M from the other pole);
this module implements the physically correct sign and the errata record the
difference.
"""

import numpy as np

from .._docstrings import fill_docstring
from .._validate import as_finite, as_in_range, as_positive, as_vectors, shown
from ..constants import MU_0
from .coordinates import _unit_vector, geomagnetic_latitude

__all__ = ["dipole_equatorial_b", "dipole_vertical_b", "dipole_horizontal_b", "dipole_total_b",
           "dipole_inclination", "dipole_b", "earth_dipole_moment_vector", "dipole_elements", "dipole_ned_b", "field_elements",
           "dipole_shell", "dipole_field_line", "dipole_from_gauss_coefficients", "dipole_mean_surface_b",
           "dipole_rms_surface_b", "lowes_spectrum"]

#: The dipole and the place, described once for every function that takes them (each checks
#: the ranges these texts give).
_DIPOLE_PARAMETERS = {
    "geomagnetic_latitude": """geomagnetic_latitude : array_like
    Geomagnetic latitude Φ [rad], in [−π/2, π/2].""",
    "moment": """moment : array_like
    Dipole moment magnitude M [A·m²], > 0.""",
    "radius": """radius : array_like
    Distance from the Earth's centre R [m], > 0.""",
    "latitude": """latitude : array_like
    Geographic latitude of the place [rad], in [−π/2, π/2].""",
    "longitude": """longitude : array_like
    Geographic longitude of the place, east positive [rad].""",
    "pole_latitude": """pole_latitude : array_like
    Geographic latitude of the northern geomagnetic pole [rad].""",
    "pole_longitude": """pole_longitude : array_like
    Geographic longitude of the northern geomagnetic pole, east positive [rad].""",
}
_document_dipole = fill_docstring(_DIPOLE_PARAMETERS)


def dipole_equatorial_b(moment, radius):
    r"""Flux density of a centred dipole on its magnetic equator.

    Parameters
    ----------
    moment : array_like
        Magnitude of the dipole moment, thesis symbol M_З [A·m²].
    radius : array_like
        Distance from the dipole centre, thesis symbol R [m].

    Returns
    -------
    ndarray
        B0 = μ0 M / (4π R³) [T], the smallest |B| on the sphere of that radius.

    Notes
    -----
    Thesis eq. (2) at Φ = 0 ("from M/R³ at the equator"); in CGS the
    thesis writes M/R³ [Oe]. The value at the poles is twice this.

    Examples
    --------
    >>> round(float(dipole_equatorial_b(8.1e22, 6371e3) * 1e9))   # thesis dipole [nT]
    31323
    """
    m = as_positive("moment", moment, unit="A·m²")
    r = as_positive("radius", radius, unit="m")
    return MU_0 * m / (4.0 * np.pi * r**3)


@_document_dipole
def dipole_vertical_b(geomagnetic_latitude, moment, radius):
    r"""Downward (vertical) component Z of a centred dipole's field.

    Parameters
    ----------
    {geomagnetic_latitude, moment, radius}

    Returns
    -------
    ndarray
        Z = 2 B0 sin Φ [T], positive downwards (northern geomagnetic hemisphere).

    Notes
    -----
    Thesis eq. (1), with θ_M = π/2 − Φ.

    Deviation from source: the thesis prints Z = −2(M/R³) cos θ_M, which is negative
    in the north although its own z axis points down and J > 0 there. The magnitude
    is right; the sign here is the physical one (see the errata chapter).
    """
    lat = as_in_range("geomagnetic_latitude", geomagnetic_latitude, -np.pi / 2, np.pi / 2, unit="rad")
    return 2.0 * dipole_equatorial_b(moment, radius) * np.sin(lat)


@_document_dipole
def dipole_horizontal_b(geomagnetic_latitude, moment, radius):
    r"""Horizontal component H of a centred dipole's field (towards geomagnetic north).

    Parameters
    ----------
    {geomagnetic_latitude, moment, radius}

    Returns
    -------
    ndarray
        H = B0 cos Φ [T], never negative.

    Notes
    -----
    Thesis eq. (1): H = (M/R³) sin θ_M.
    """
    lat = as_in_range("geomagnetic_latitude", geomagnetic_latitude, -np.pi / 2, np.pi / 2, unit="rad")
    return dipole_equatorial_b(moment, radius) * np.cos(lat)


@_document_dipole
def dipole_total_b(geomagnetic_latitude, moment, radius):
    r"""Magnitude T of a centred dipole's field.

    Parameters
    ----------
    {geomagnetic_latitude, moment, radius}

    Returns
    -------
    ndarray
        T = B0 √(1 + 3 sin²Φ) [T].

    Notes
    -----
    Thesis eq. (2): T = (M/R³) √(1 + 3 cos²θ_M).

    Examples
    --------
    >>> import numpy as np
    >>> from magbench.units import tesla_to_oersted
    >>> [round(float(tesla_to_oersted(dipole_total_b(p, 8.1e22, 6371e3))), 4)
    ...  for p in (0.0, np.pi / 2)]
    [0.3132, 0.6265]
    """
    lat = as_in_range("geomagnetic_latitude", geomagnetic_latitude, -np.pi / 2, np.pi / 2, unit="rad")
    return dipole_equatorial_b(moment, radius) * np.sqrt(1.0 + 3.0 * np.sin(lat) ** 2)


@_document_dipole
def dipole_inclination(geomagnetic_latitude):
    r"""Magnetic inclination (dip) J of a centred dipole's field.

    Parameters
    ----------
    {geomagnetic_latitude}

    Returns
    -------
    ndarray
        J = arctan(2 tan Φ) [rad], positive when the field points below the horizon.

    Notes
    -----
    Thesis eq. (3).

    Deviation from source: the thesis (and Kovalenko's eq. 2.3) prints
    tan J = −2 tan Φ, which gives J < 0 in the north; with the thesis's own
    convention (z down, J = atan(Z/H)) the correct relation is tan J = +2 tan Φ.

    Examples
    --------
    >>> import numpy as np
    >>> round(float(np.degrees(dipole_inclination(np.radians(45.0)))), 3)
    63.435
    """
    lat = as_in_range("geomagnetic_latitude", geomagnetic_latitude, -np.pi / 2, np.pi / 2, unit="rad")
    return np.arctan2(2.0 * np.sin(lat), np.cos(lat))


def dipole_b(points, moment):
    r"""Flux density of a point dipole at the origin.

    Parameters
    ----------
    points : array_like, shape (..., 3)
        Observation points [m]; the origin itself is rejected.
    moment : array_like, shape (..., 3)
        Dipole moment vector [A·m²]; broadcasts against ``points``.

    Returns
    -------
    ndarray, shape (..., 3)
        B [T].

    Notes
    -----
    Not in the sources as a vector formula: Jackson, *Classical Electrodynamics*,
    3rd ed., eq. (5.56),

    .. math:: \mathbf B = \frac{\mu_0}{4\pi}\,\frac{3(\mathbf m\cdot\hat{\mathbf r})\hat{\mathbf r} - \mathbf m}{r^3}.

    It reduces to thesis eqs. (1)–(2) on the Earth's surface.

    Examples
    --------
    >>> b = dipole_b([0.0, 0.0, 1.0], [0.0, 0.0, 1.0])   # on the axis: μ0 m / (2π r³)
    >>> round(float(b[2]) * 1e7, 6)
    2.0
    """
    p = as_vectors("points", points)
    m = as_vectors("moment", moment)
    r = np.linalg.norm(p, axis=-1, keepdims=True)
    if np.any(r == 0):
        raise ValueError("points must not include the origin, where the dipole field is singular")
    rhat = p / r
    mdotr = np.sum(m * rhat, axis=-1, keepdims=True)
    return MU_0 / (4.0 * np.pi) * (3.0 * mdotr * rhat - m) / r**3


@_document_dipole
def earth_dipole_moment_vector(moment, pole_latitude, pole_longitude):
    r"""Earth's dipole moment as an Earth-fixed vector.

    Parameters
    ----------
    {moment, pole_latitude, pole_longitude}

    Returns
    -------
    ndarray, shape (..., 3)
        Moment vector in Earth-centred, Earth-fixed axes (x towards 0° E on the
        equator, z towards the geographic north pole) [A·m²]. It points *away* from the
        northern geomagnetic pole: field lines enter the Earth there.

    Notes
    -----
    Thesis §1.1 (pole 78.5° N, 69° W; tilt 11.5°).
    """
    m = as_positive("moment", moment, unit="A·m²")
    plat = as_in_range("pole_latitude", pole_latitude, -np.pi / 2, np.pi / 2, unit="rad")
    plon = as_finite("pole_longitude", pole_longitude)
    return -m[..., None] * _unit_vector(plat, plon)


@_document_dipole
def dipole_elements(latitude, longitude, moment, pole_latitude, pole_longitude, radius):
    r"""Total, horizontal and vertical field and inclination of a tilted centred dipole at a place.

    Parameters
    ----------
    {latitude, longitude, moment, pole_latitude, pole_longitude, radius}

    Returns
    -------
    total, horizontal, vertical, inclination : ndarray
        T, H, Z (down) [T] and I [rad] (positive downwards).

    Notes
    -----
    Thesis §1.1, eqs. (1)–(3) at the place's geomagnetic latitude Φ
    (:func:`magbench.earth.geomagnetic_latitude`), with the corrected sign of eq. (3)
    (:func:`dipole_inclination`). The same numbers as :func:`field_elements` of
    :func:`dipole_ned_b`, by the closed forms.

    Examples
    --------
    >>> t, h, z, i = dipole_elements(np.radians(59.94), np.radians(30.31), 8.1e22, np.radians(78.5),
    ...                              np.radians(-69.0), 6371.2e3)
    >>> round(float(t) * 1e6, 1), round(float(np.degrees(i)), 1)
    (54.9, 71.6)
    """
    phi = geomagnetic_latitude(latitude, longitude, pole_latitude, pole_longitude)
    return (dipole_total_b(phi, moment, radius), dipole_horizontal_b(phi, moment, radius),
            dipole_vertical_b(phi, moment, radius), dipole_inclination(phi))


def _ned_basis(latitude, longitude):
    """Rows: north, east, down unit vectors in Earth-fixed axes at a place."""
    sl, cl, so, co = np.sin(latitude), np.cos(latitude), np.sin(longitude), np.cos(longitude)
    return np.array([[-sl * co, -sl * so, cl], [-so, co, 0.0], [-cl * co, -cl * so, -sl]])


@_document_dipole
def dipole_ned_b(latitude, longitude, moment, pole_latitude, pole_longitude, radius):
    r"""Field of the Earth's tilted centred dipole at a place, in the local north-east-down frame.

    Parameters
    ----------
    {latitude, longitude, moment, pole_latitude, pole_longitude, radius : float}

    Returns
    -------
    ndarray, shape (3,)
        (X north, Y east, Z down) [T], the components of the thesis's Fig. 1.

    Notes
    -----
    Thesis §1.1, Fig. 1 and eqs. (1)–(2) (the field elements of the centred dipole whose
    pole the thesis gives): :func:`dipole_b` of :func:`earth_dipole_moment_vector` at the
    point on the sphere, resolved on the local north, east and down axes. Unlike eqs.
    (1)–(2) it keeps the declination the tilted pole gives away from the geomagnetic
    meridian.

    Examples
    --------
    >>> b = dipole_ned_b(np.radians(59.94), np.radians(30.31), 8.1e22, np.radians(78.5),
    ...                  np.radians(-69.0), 6371.2e3)
    >>> np.round(b * 1e6, 1).tolist()
    [16.2, -6.2, 52.1]
    """
    lat = as_in_range("latitude", latitude, -np.pi / 2, np.pi / 2, unit="rad")
    lon = as_finite("longitude", longitude)
    if lat.ndim or lon.ndim:
        raise ValueError(f"latitude and longitude must be scalars (one place), got shapes {lat.shape} and {lon.shape}")
    r = as_positive("radius", radius, unit="m")
    m_vec = earth_dipole_moment_vector(moment, pole_latitude, pole_longitude)
    clat = np.cos(lat)
    point = r * np.array([clat * np.cos(lon), clat * np.sin(lon), np.sin(lat)])
    return _ned_basis(lat, lon) @ dipole_b(point, m_vec)


def field_elements(north, east, down):
    r"""The elements of a magnetic field from its north, east and down components.

    Parameters
    ----------
    north : array_like
        X, the northward component [T].
    east : array_like
        Y, the eastward component [T].
    down : array_like
        Z, the downward component [T].

    Returns
    -------
    horizontal : ndarray
        H = √(X² + Y²) [T].
    total : ndarray
        T = √(H² + Z²) [T].
    declination : ndarray
        D = atan2(Y, X), east of north [rad].
    inclination : ndarray
        I = atan2(Z, H), positive downwards [rad].

    Notes
    -----
    Thesis §1.1, Fig. 1 (the elements X, Y, Z, H, T, D, J of the geomagnetic field), with
    the thesis's axes (z down, J > 0 where the field dips, as in the northern hemisphere).

    Examples
    --------
    >>> h, t, d, i = field_elements(3.0, 4.0, 12.0)
    >>> float(h), float(t), round(float(np.degrees(d)), 2), round(float(np.degrees(i)), 2)
    (5.0, 13.0, 53.13, 67.38)
    """
    x = as_finite("north", north)
    y = as_finite("east", east)
    z = as_finite("down", down)
    h = np.hypot(x, y)
    return h, np.sqrt(h**2 + z**2), np.arctan2(y, x), np.arctan2(z, h)


def dipole_shell(footpoint_latitude):
    r"""Shell parameter L of the dipole field line through a magnetic latitude on the surface.

    Parameters
    ----------
    footpoint_latitude : array_like
        Geomagnetic latitude where the line meets the sphere r = R [rad], in (−π/2, π/2).

    Returns
    -------
    ndarray
        L = 1/cos²λ_f [-]: the line's distance from the centre at the magnetic equator, in R.

    Notes
    -----
    Not in the thesis as a formula (its Fig. 2 draws the lines): a field line of a centred
    dipole is r = L R cos²λ (Kovalenko (1975) ch. 2, eqs. (2.1)–(2.2): dr/(r dλ) = B_r/B_λ =
    −2 tan λ), so the line through (R, λ_f) has L = 1/cos²λ_f.

    Examples
    --------
    >>> round(float(dipole_shell(np.radians(60.0))), 12)
    4.0
    """
    lam = as_finite("footpoint_latitude", footpoint_latitude)
    if np.any(np.abs(lam) >= np.pi / 2):
        raise ValueError(f"footpoint_latitude must lie in (-pi/2, pi/2) rad (the pole's line is the axis), "
                         f"got {shown(lam[np.abs(lam) >= np.pi / 2].ravel()[0])}")
    return 1.0 / np.cos(lam) ** 2


def dipole_field_line(shell, magnetic_latitude, tilt=0.0, side=1.0):
    r"""Points of a centred dipole's field line in the meridian plane, above the surface.

    Parameters
    ----------
    shell : float
        L of the line (:func:`dipole_shell`) [-], >= 1.
    magnetic_latitude : array_like
        Geomagnetic latitudes λ to sample, in [−π/2, π/2] [rad].
    tilt : float, optional
        Angle of the dipole axis from the rotation axis [rad]; default 0.
    side : {1.0, -1.0}, optional
        Which half of the meridian plane (+1: the positive x side of the magnetic axis) [-].

    Returns
    -------
    x : ndarray
        Distance from the rotation axis, signed [R] (Earth radii).
    z : ndarray
        Distance along the rotation axis, north positive [R].

    Notes
    -----
    Not in the thesis as a formula: its Fig. 2 (geomagnetic coordinates, after Kovalenko
    (1975) ch. 2). The line r = L cos²λ (in R, eqs. (2.1)–(2.2) integrated), kept where
    r ≥ 1, turned from magnetic to geographic axes by the tilt in the plane of both axes.

    Examples
    --------
    >>> x, z = dipole_field_line(2.0, np.array([0.0]))
    >>> float(x[0]), float(z[0])
    (2.0, 0.0)
    """
    L = float(as_finite("shell", shell))
    if L < 1.0:
        raise ValueError(f"shell must be >= 1 (lines inside the Earth are not drawn), got {shown(L)}")
    lam = as_in_range("magnetic_latitude", magnetic_latitude, -np.pi / 2, np.pi / 2, unit="rad")
    t = float(as_finite("tilt", tilt))
    if side not in (1.0, -1.0):
        raise ValueError(f"side must be 1.0 or -1.0, got {shown(side)}")
    c, s = np.cos(t), np.sin(t)
    r = L * np.cos(lam) ** 2
    keep = r >= 1.0
    xm, zm = side * r[keep] * np.cos(lam[keep]), r[keep] * np.sin(lam[keep])
    return c * xm + s * zm, -s * xm + c * zm


def dipole_from_gauss_coefficients(g10, g11, h11, reference_radius):
    r"""Dipole moment, tilt and pole of the degree-1 part of a Gauss expansion.

    Parameters
    ----------
    g10, g11, h11 : array_like
        Schmidt semi-normalised Gauss coefficients of degree 1 [T].
    reference_radius : array_like
        Reference radius a of the expansion [m] (6371.2 km for IGRF).

    Returns
    -------
    moment : ndarray
        Dipole moment magnitude M = 4π a³ B0 / μ0 [A·m²], B0 = √(g10² + g11² + h11²).
    tilt : ndarray
        Angle between the dipole axis and the rotation axis, arccos(−g10/B0) [rad].
    pole_latitude : ndarray
        Latitude of the northern geomagnetic pole, π/2 − tilt [rad].
    pole_longitude : ndarray
        East longitude of the northern geomagnetic pole, atan2(−h11, −g11) [rad].

    Notes
    -----
    Not in the thesis (which quotes M_З = 8.1·10²⁵ CGS and the pole without a source):
    Kovalenko (1975) eq. (2.4) with n = 1; Campbell, *Introduction to Geomagnetic
    Fields*, 2nd ed., §2.2. Used to set the thesis's dipole beside IGRF.

    Examples
    --------
    >>> m, tilt, lat, lon = dipole_from_gauss_coefficients(-30000e-9, 0.0, 0.0, 6371.2e3)
    >>> float(tilt), float(lat)
    (0.0, 1.5707963267948966)
    """
    g10 = as_finite("g10", g10)
    g11 = as_finite("g11", g11)
    h11 = as_finite("h11", h11)
    a = as_positive("reference_radius", reference_radius, unit="m")
    b0 = np.sqrt(g10**2 + g11**2 + h11**2)
    if np.any(b0 == 0):
        raise ValueError("g10, g11 and h11 must not all be zero (no dipole to describe)")
    moment = 4.0 * np.pi * a**3 * b0 / MU_0
    tilt = np.arccos(-g10 / b0)
    return moment, tilt, np.pi / 2 - tilt, np.arctan2(-h11, -g11)


def dipole_mean_surface_b(equatorial_b):
    r"""Mean of |B| of a centred dipole over a sphere.

    Parameters
    ----------
    equatorial_b : array_like
        Dipole field on the equator of that sphere, B0 [T].

    Returns
    -------
    ndarray
        Area average of |B| = B0 √(1 + 3 cos²θ) [T], i.e. B0 · ½∫₋₁¹ √(1 + 3x²) dx
        = 1.3802 B0.

    Notes
    -----
    Kovalenko (1975), p. 40 (mean of the first harmonic, T₁c ≈ 0.4283 Oe for the
    1965 field). The closed form of the integral is
    ½[x√(1+3x²) + asinh(√3 x)/√3] over [−1, 1].
    """
    b0 = as_positive("equatorial_b", equatorial_b, unit="T")
    s3 = np.sqrt(3.0)
    integral = 2.0 + np.arcsinh(s3) / s3   # ∫₋₁¹ √(1+3x²) dx
    return b0 * integral / 2.0


def dipole_rms_surface_b(equatorial_b):
    r"""Root-mean-square |B| of a centred dipole over a sphere.

    Parameters
    ----------
    equatorial_b : array_like
        Dipole field on the equator of that sphere, B0 [T].

    Returns
    -------
    ndarray
        √⟨B²⟩ = √2 · B0 [T].

    Notes
    -----
    Kovalenko (1975) eq. (2.6)–(2.7), Table 2 column "T₁ с.к." (rms dipole field);
    the degree-1 term of the Lowes–Mauersberger spectrum (n+1)(a/r)^(2n+4) Σ(g² + h²)
    with n = 1.
    """
    b0 = as_positive("equatorial_b", equatorial_b, unit="T")
    return np.sqrt(2.0) * b0


def lowes_spectrum(g, h, radius_ratio):
    r"""Mean-square field of each spherical-harmonic degree over a sphere.

    Parameters
    ----------
    g, h : array_like, shape (n_max + 1, n_max + 1)
        Schmidt semi-normalised Gauss coefficients, ``g[n, m]`` and ``h[n, m]``
        (row 0 and the entries with m > n are ignored) [T].
    radius_ratio : array_like
        Ratio a / r of the reference radius to the radius of the sphere [-].

    Returns
    -------
    ndarray, shape (..., n_max)
        ⟨B_n²⟩ for n = 1 … n_max on the sphere [T²]; their sum is the mean square of
        |B| and its square root the rms field.

    Notes
    -----
    Kovalenko (1975) eqs. (2.6)–(2.7) (garbled in the seed text); the standard form
    is Lowes (1966), J. Geophys. Res. 71, 2179:

    .. math:: \langle B_n^2\rangle = (n+1)\left(\frac{a}{r}\right)^{2n+4}\sum_{m=0}^{n}\left[(g_n^m)^2+(h_n^m)^2\right].

    Examples
    --------
    >>> import numpy as np
    >>> g = np.zeros((2, 2)); g[1, 0] = 3e-5
    >>> float(lowes_spectrum(g, np.zeros((2, 2)), 1.0)[0]) == 2 * 3e-5**2
    True
    """
    g = as_finite("g", g)
    h = as_finite("h", h)
    if g.ndim != 2 or g.shape[0] != g.shape[1] or g.shape != h.shape or g.shape[0] < 2:
        raise ValueError(f"g and h must be square arrays of equal shape (n_max+1, n_max+1) with "
                         f"n_max >= 1, got {g.shape} and {h.shape}")
    ratio = as_positive("radius_ratio", radius_ratio)
    n = np.arange(1, g.shape[0])
    lower = np.tril(np.ones_like(g, dtype=bool))
    power = np.sum(np.where(lower, g**2 + h**2, 0.0), axis=1)[1:]
    return (n + 1) * np.asarray(ratio)[..., None] ** (2 * n + 4) * power
