r"""The field direction on a circular magnetopolar orbit: the angle η between the local
horizontal and B, its derivatives, the gravity-gradient factor sin 2λ and their Fourier
series, and the first-order eccentricity terms of the orbit rate.

Kovalenko (1975) §6.4, eqs. (6.30)–(6.36) (seed lines 136–137) and §6.5, eqs. (6.59)–(6.61)
(seed line 144): a circular orbit through the poles of the centred, untilted dipole, the
argument of latitude u = ω0 t counted from the magnetic equator. In the orbit plane B makes
the angle η with the along-track axis x0, turned toward the nadir: tan η = 2 tan u. Pure
numpy, SI, rad; every function broadcasts over arrays.
"""

import numpy as np

from .._docstrings import fill_docstring
from .._validate import as_count, as_finite, as_positive

__all__ = ["polar_field_direction_angle", "polar_field_direction_rate", "polar_field_direction_acceleration",
           "polar_field_b", "polar_gravity_factor", "polar_fourier_coefficients", "polar_orbit_rate",
           "polar_orbit_acceleration", "polar_eccentric_coefficients"]

#: Parameters described once for the functions that share them (:func:`magbench._docstrings.fill_docstring`).
_ORBIT_PARAMETERS = {
    "argument_of_latitude": """argument_of_latitude : array_like
    u [rad].""",
    "eccentricity": """eccentricity : array_like
    e, in [0, 1) and small [-].""",
    "mean_motion": """mean_motion : array_like
    ω0 [rad/s].""",
    "time": """time : array_like
    t from perigee [s].""",
}
_document_orbit = fill_docstring(_ORBIT_PARAMETERS)

#: The ratio of the three geometric series: every coefficient below is a power of 1/3.
_Q = 1.0 / 3.0


def polar_field_direction_angle(argument_of_latitude):
    r"""Angle η between the along-track axis x0 and B on a magnetopolar orbit, unwrapped.

    Parameters
    ----------
    argument_of_latitude : array_like
        u = ω0 t from the magnetic equator [rad].

    Returns
    -------
    ndarray
        η [rad] with tan η = 2 tan u, continuous in u: η = u + arctan(sin 2u/(3 − cos 2u)),
        so η = u at every multiple of π/2 and η − u is π-periodic.

    Notes
    -----
    Kovalenko (1975) eq. (6.32) (seed line 136): η = arccos(cos u/√(1 + 3 sin²u)), from
    the dipole's components (6.36) B_x0 ∝ cos u, B_z0 ∝ −2 sin u. The arccos form is
    folded into [0, π]; the form here is the same angle unwrapped (Not in the sources:
    tan(η − u) = (2t − t)/(1 + 2t²), t = tan u, whose denominator never vanishes).

    Examples
    --------
    >>> u = np.radians([0.0, 30.0, 90.0, 180.0])
    >>> np.round(np.degrees(polar_field_direction_angle(u)), 4).tolist()
    [0.0, 49.1066, 90.0, 180.0]
    """
    u = as_finite("argument_of_latitude", argument_of_latitude)
    return u + np.arctan2(np.sin(2.0 * u), 3.0 - np.cos(2.0 * u))


@_document_orbit
def polar_field_direction_rate(argument_of_latitude):
    r"""Derivative dη/du of the field-direction angle on a circular magnetopolar orbit.

    Parameters
    ----------
    {argument_of_latitude}

    Returns
    -------
    ndarray
        dη/du = 2/(1 + 3 sin²u) [-]: 2 at the equator, 1/2 over the poles; η̇ = ω0 dη/du
        on a circular orbit.

    Notes
    -----
    Not in the sources: the derivative of Kovalenko (1975) eq. (6.32) (seed line 136),
    sec²η dη = 2 sec²u du with cos²η = cos²u/(1 + 3 sin²u).
    """
    u = as_finite("argument_of_latitude", argument_of_latitude)
    return 2.0 / (1.0 + 3.0 * np.sin(u) ** 2)


def polar_field_direction_acceleration(argument_of_latitude, mean_motion=1.0):
    r"""Angular acceleration η̈ of the field direction on a circular magnetopolar orbit.

    Parameters
    ----------
    argument_of_latitude : array_like
        u = ω0 t [rad].
    mean_motion : array_like, optional
        ω0 [rad/s]; the default 1 returns d²η/du² [-].

    Returns
    -------
    ndarray
        η̈ = −6 ω0² sin 2u/(1 + 3 sin²u)² [rad/s²].

    Notes
    -----
    Kovalenko (1975) eq. (6.34a) (seed line 136, "Точное выражение для η̈ при e = 0"): the
    OCR keeps only "sin 2ω0t … (1 + 3 sin²ω0t)²"; the form here is the derivative of
    :func:`polar_field_direction_rate` (−12 sin u cos u/(1 + 3 sin²u)²), which fits it.
    Its largest magnitude is 2.131 ω0², at u = 18.04° (found numerically).

    Examples
    --------
    >>> round(float(polar_field_direction_acceleration(np.pi / 4)), 6)
    -0.96
    """
    u = as_finite("argument_of_latitude", argument_of_latitude)
    n = as_positive("mean_motion", mean_motion, unit="rad/s")
    return -6.0 * n**2 * np.sin(2.0 * u) / (1.0 + 3.0 * np.sin(u) ** 2) ** 2


@_document_orbit
def polar_field_b(argument_of_latitude, equatorial_b):
    r"""Magnitude of the dipole field along a circular magnetopolar orbit.

    Parameters
    ----------
    {argument_of_latitude}
    equatorial_b : array_like
        B0 = μ0 M/(4π r³), the field over the magnetic equator at the orbit's radius [T].

    Returns
    -------
    ndarray
        B = B0 √(1 + 3 sin²u) [T].

    Notes
    -----
    Kovalenko (1975) eq. (2.40) with i = 90° (|H| = (M/r³)√(1 + 3 sin²u sin²i)) and
    eq. (6.36) (seed line 136).
    """
    u = as_finite("argument_of_latitude", argument_of_latitude)
    b0 = as_positive("equatorial_b", equatorial_b, unit="T")
    return b0 * np.sqrt(1.0 + 3.0 * np.sin(u) ** 2)


@_document_orbit
def polar_gravity_factor(argument_of_latitude):
    r"""The gravity-gradient factor sin 2λ of a body held along B on a magnetopolar orbit.

    Parameters
    ----------
    {argument_of_latitude}

    Returns
    -------
    ndarray
        sin 2λ = 4 sin u cos u/(1 + 3 sin²u) [-], λ = η the angle of B from the local
        horizontal; the gravity torque on a body along B is (3/2) ω0² ΔJ sin 2λ.

    Notes
    -----
    Kovalenko (1975) eqs. (6.59)–(6.60) (seed line 144): sin λ = 2 sin u/√(1 + 3 sin²u),
    cos λ = cos u/√(1 + 3 sin²u); "the second relation is (6.32) written otherwise", so
    λ = η.
    """
    u = as_finite("argument_of_latitude", argument_of_latitude)
    return 2.0 * np.sin(2.0 * u) / (1.0 + 3.0 * np.sin(u) ** 2)


def polar_fourier_coefficients(count=3):
    r"""Exact Fourier sine coefficients of η − u, of η̈/ω0² and of sin 2λ in the harmonics sin 2nu.

    Parameters
    ----------
    count : int, optional
        How many harmonics n = 1 … count [-].

    Returns
    -------
    angle, acceleration, gravity : ndarray, shape (count,)
        b_n of η − u = Σ b_n sin 2nu: (1/3)ⁿ/n [rad]; of η̈/ω0²: −4n (1/3)ⁿ [-]; of sin 2λ:
        (8/3)(1/3)ⁿ [-]. The first three: (0.3333, 0.0556, 0.0123), (−1.333, −0.889,
        −0.444), (0.889, 0.296, 0.099).

    Notes
    -----
    Kovalenko (1975) eqs. (6.33), (6.34), (6.40) and (6.61) (seed lines 136–137, 144) print
    η = ω0t + 0.34 sin 2ω0t + 0.075 sin 4ω0t, η̈ ≈ −ω0²(1.36 sin 2ω0t + 1.20 sin 4ω0t) and
    sin 2λ ≈ 0.88 sin 2ω0t + 0.27 sin 4ω0t + 0.08 sin 6ω0t; the series here are exact.

    Not in the sources: with x = 2u, η − u = arctan(sin x/(3 − cos x)) =
    Im ln(1 − e^{ix}/3)⁻¹ = Σ (1/3)ⁿ sin nx/n; η̈/ω0² is its second derivative in u; and
    sin 2λ = 2 sin x/(5/2 − (3/2) cos x) = (8/3) Σ (1/3)ⁿ sin nx, from
    Σ rⁿ sin nx = r sin x/(1 − 2r cos x + r²) at r = 1/3 (Gradshteyn & Ryzhik 1.447.1).

    Examples
    --------
    >>> a, b, c = polar_fourier_coefficients(2)
    >>> np.round(a, 4).tolist(), np.round(b, 4).tolist(), np.round(c, 4).tolist()
    ([0.3333, 0.0556], [-1.3333, -0.8889], [0.8889, 0.2963])
    """
    n = np.arange(1, as_count("count", count) + 1, dtype=float)
    q = _Q**n
    return q / n, -4.0 * n * q, 8.0 / 3.0 * q


@_document_orbit
def polar_orbit_rate(time, mean_motion, eccentricity):
    r"""Rate of the true anomaly on a slightly elliptic orbit, to first order in e.

    Parameters
    ----------
    {time, mean_motion, eccentricity}

    Returns
    -------
    ndarray
        ν̇ ≈ ω0 (1 + 2e cos ω0t) [rad/s].

    Notes
    -----
    Kovalenko (1975) eq. (6.30) (seed line 136), the expansion of (5.18)
    ν̇ = (1 + e cos ν)² √μ/[a(1 − e²)]^{3/2} for e ≪ 1.
    """
    t = as_finite("time", time)
    n = as_positive("mean_motion", mean_motion, unit="rad/s")
    e = _eccentricity(eccentricity)
    return n * (1.0 + 2.0 * e * np.cos(n * t))


@_document_orbit
def polar_orbit_acceleration(time, mean_motion, eccentricity):
    r"""Angular acceleration of the true anomaly on a slightly elliptic orbit, to first order in e.

    Parameters
    ----------
    {time, mean_motion, eccentricity}

    Returns
    -------
    ndarray
        ν̈ ≈ −2e ω0² sin ω0t [rad/s²], the derivative of :func:`polar_orbit_rate`.

    Notes
    -----
    Kovalenko (1975) eq. (6.31) (seed line 136). It accounts for the difference between the
    first e-term of (6.34), 4.0 sin ω0t (η̈ alone), and that of (6.39), 6.0 sin ω0t, which
    is the coefficient of η̈ + ν̈ (Not in the sources: our reading; the reference calls the
    two "inconsistent").
    """
    t = as_finite("time", time)
    n = as_positive("mean_motion", mean_motion, unit="rad/s")
    e = _eccentricity(eccentricity)
    return -2.0 * e * n**2 * np.sin(n * t)


def polar_eccentric_coefficients(count=3):
    r"""First-order eccentricity terms of −η̈/ω0² on a magnetopolar orbit whose perigee is at the node.

    Parameters
    ----------
    count : int, optional
        How many terms, in sin ω0t, sin 3ω0t, … sin (2·count − 1)ω0t [-].

    Returns
    -------
    ndarray, shape (count,)
        c_k with −η̈/ω0² = Σ b_n sin 2nω0t + e Σ_k c_k sin (2k + 1)ω0t + O(e²):
        c_k = (4/3)(2k + 1)² (1/3)^k, k = 0, 1, …: 1.333, 4.0, 3.704, 2.420 [-].

    Notes
    -----
    Kovalenko (1975) eq. (6.34) (seed line 136) prints e(4.0 sin ω0t + 5.8 sin 3ω0t +
    2.4 sin 5ω0t), from (6.33) differentiated with (6.30)–(6.31).

    Not in the sources: the exact first-order terms. With the perigee at the ascending node
    (u and the mean anomaly both ω0t, as the book writes), u = M + 2e sin M + O(e²), so
    η(u) = η(M) + 2e sin M η'(M), η'(M) = 1 + 2 Σ (1/3)ⁿ cos 2nM; then
    sin M η'(M) = sin M + Σ (1/3)ⁿ [sin (2n+1)M − sin (2n−1)M], and twice differentiated
    the coefficient of sin (2k+1)M in η̈/ω0² is −2e (2k+1)² (1/3)^k (1 − 1/3). ν̈ of (6.31)
    adds 2e sin ω0t more to −(η̈ + ν̈)/ω0² (the book's (6.39) has 6.0 = 4.0 + 2.0 there).
    """
    k = np.arange(as_count("count", count), dtype=float)
    return 4.0 / 3.0 * (2.0 * k + 1.0) ** 2 * _Q**k


def _eccentricity(eccentricity):
    e = as_finite("eccentricity", eccentricity)
    if np.any((e < 0) | (e >= 1)):
        raise ValueError(f"eccentricity must lie in [0, 1), got {e[(e < 0) | (e >= 1)].ravel()[0]!r}")
    return e
