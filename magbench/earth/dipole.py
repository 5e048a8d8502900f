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

from .._validate import as_finite, as_in_range, as_positive, as_vectors
from ..constants import MU_0
from .coordinates import _unit_vector

__all__ = ["dipole_equatorial_b", "dipole_vertical_b", "dipole_horizontal_b", "dipole_total_b",
           "dipole_inclination", "dipole_b", "earth_dipole_moment_vector",
           "dipole_from_gauss_coefficients", "dipole_mean_surface_b", "dipole_rms_surface_b",
           "lowes_spectrum"]


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


def dipole_vertical_b(geomagnetic_latitude, moment, radius):
    r"""Downward (vertical) component Z of a centred dipole's field.

    Parameters
    ----------
    geomagnetic_latitude : array_like
        Geomagnetic latitude Φ [rad].
    moment : array_like
        Dipole moment magnitude M_З [A·m²].
    radius : array_like
        Distance from the centre R [m].

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


def dipole_horizontal_b(geomagnetic_latitude, moment, radius):
    r"""Horizontal component H of a centred dipole's field (towards geomagnetic north).

    Parameters
    ----------
    geomagnetic_latitude : array_like
        Geomagnetic latitude Φ [rad].
    moment : array_like
        Dipole moment magnitude M_З [A·m²].
    radius : array_like
        Distance from the centre R [m].

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


def dipole_total_b(geomagnetic_latitude, moment, radius):
    r"""Magnitude T of a centred dipole's field.

    Parameters
    ----------
    geomagnetic_latitude : array_like
        Geomagnetic latitude Φ [rad].
    moment : array_like
        Dipole moment magnitude M_З [A·m²].
    radius : array_like
        Distance from the centre R [m].

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


def dipole_inclination(geomagnetic_latitude):
    r"""Magnetic inclination (dip) J of a centred dipole's field.

    Parameters
    ----------
    geomagnetic_latitude : array_like
        Geomagnetic latitude Φ [rad].

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


def earth_dipole_moment_vector(moment, pole_latitude, pole_longitude):
    r"""Earth's dipole moment as an Earth-fixed vector.

    Parameters
    ----------
    moment : array_like
        Dipole moment magnitude M_З [A·m²].
    pole_latitude : array_like
        Geographic latitude of the northern geomagnetic pole [rad].
    pole_longitude : array_like
        Geographic longitude of the northern geomagnetic pole, east positive [rad].

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
