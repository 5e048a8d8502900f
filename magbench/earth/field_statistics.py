r"""What the dipole field does along a circular orbit, summarised: its largest magnitude, the
time mean of |B|², the range of |B|² over an orbit and how fast its direction turns.

The numbers the detumbling laws are sized by: SamSat-218D's gain rule divides by the largest
field (§"Control law", seed line 247), Kovalenko's detumbling time (1975, eq. (6.50)) by the
mean of |B|², and a B-dot law damps the body's rate to the rate of the field's direction.
Each takes a :class:`~magbench.earth.CircularOrbit` (its field, turning with the Earth when the
orbit says so). SI throughout.
"""

import numpy as np

from .._validate import as_count, as_finite, as_positive_scalar
from ..constants import MU_0

__all__ = ["dipole_max_field", "mean_square_field", "mean_square_perpendicular_field", "field_square_ratio",
           "field_direction_rate_range",
           "field_magnitude_range"]


def dipole_max_field(orbit):
    r"""The largest field magnitude a centred dipole gives at the orbit's radius.

    Parameters
    ----------
    orbit : CircularOrbit
        The orbit; its radius r [m] and the Earth's dipole moment M [A·m²] are read.

    Returns
    -------
    float
        B_max = 2 μ0 M/(4π r³) [T], over the magnetic poles; an orbit that passes near them
        (SamSat-218D's, at 97.3°, within a few degrees) sees nearly all of it.

    Notes
    -----
    Kovalenko (1975) eq. (2.36) at the pole (|B| = (μ0 M/4π r³)√(1 + 3 sin²φ), φ = 90°);
    SamSat-218D's gain rule (seed line 247) divides by it.

    Examples
    --------
    >>> from magbench.earth import CircularOrbit
    >>> round(dipole_max_field(CircularOrbit(6.871e6, 1.0, 8.0e22)) * 1e6, 2)
    49.32
    """
    return 2.0 * MU_0 * orbit.earth_moment / (4.0 * np.pi * orbit.radius**3)


def mean_square_field(orbit, duration=86400.0, samples=20000):
    r"""Time mean of |B|² along the orbit.

    Parameters
    ----------
    orbit : CircularOrbit
        The orbit and its field (turning with the Earth if the orbit's Earth rotation rate
        is not zero) [-].
    duration : float, optional
        Span averaged over from t = 0, > 0 [s]; a day by default, so that the Earth's
        turning under the orbit is averaged too.
    samples : int, optional
        Equally spaced instants, the end excluded, ≥ 2 [-].

    Returns
    -------
    float
        ⟨|B|²⟩ [T²].

    Notes
    -----
    Kovalenko (1975) eq. (6.50) divides by it (his damping coefficient is (2/3) k ⟨B²⟩). For a
    direct dipole on a circular orbit of inclination i it is B0²(1 + (3/2) sin² i), B0 the
    equatorial field at the orbit's radius (the tests hold it to that).
    """
    span = as_positive_scalar("duration", duration, unit="s")
    n = as_count("samples", samples, minimum=2)
    t = np.linspace(0.0, span, n, endpoint=False)
    b = orbit.field(t)
    return float(np.mean(np.sum(b * b, axis=-1)))


def mean_square_perpendicular_field(orbit, axis, duration=86400.0, samples=20000):
    r"""Time mean of the square of the field across a direction fixed in inertial space.

    Parameters
    ----------
    orbit : CircularOrbit
        The orbit and its field [-].
    axis : array_like, shape (3,)
        The direction ŝ in inertial axes (a spin axis that holds its direction), non-zero;
        normalised here [-].
    duration : float, optional
        Span averaged over from t = 0, > 0 [s]; a day by default.
    samples : int, optional
        Equally spaced instants, the end excluded, ≥ 2 [-].

    Returns
    -------
    float
        ⟨|ŝ × B|²⟩ = ⟨B² sin²α⟩ [T²], α the angle between B and ŝ.

    Notes
    -----
    Kovalenko (1975) eq. (4.23a), seed line 87 (p. 86): the eddy braking of a spin goes as
    B² sin²α. Averaged over all directions ŝ it is (2/3)⟨B²⟩ (:func:`mean_square_field`; the
    tests hold it to that).
    """
    s = as_finite("axis", axis)
    if s.shape != (3,) or not np.any(s):
        raise ValueError(f"axis must be a non-zero vector of shape (3,), got {s.tolist()}")
    span = as_positive_scalar("duration", duration, unit="s")
    n = as_count("samples", samples, minimum=2)
    b = orbit.field(np.linspace(0.0, span, n, endpoint=False))
    s = s / np.linalg.norm(s)
    along = b @ s
    return float(np.mean(np.sum(b * b, axis=-1) - along ** 2))


def field_square_ratio(orbit, samples=3601):
    r"""Largest over smallest |B|² over one orbital period.

    Parameters
    ----------
    orbit : CircularOrbit
        The orbit and its field [-].
    samples : int, optional
        Equally spaced instants over [0, T], both ends included, ≥ 2 [-].

    Returns
    -------
    float
        max |B|² / min |B|² [-]: 4 on a polar orbit of a direct dipole (the field doubles from
        equator to pole).

    Notes
    -----
    Kovalenko (1975) p. 99: on a polar orbit |B|² varies fourfold, which is why the
    detumbling time of eq. (6.50) takes the mean of |B|².
    """
    n = as_count("samples", samples, minimum=2)
    t = np.linspace(0.0, orbit.period, n)
    b2 = np.sum(orbit.field(t) ** 2, axis=-1)
    return float(np.max(b2) / np.min(b2))


def field_direction_rate_range(orbit, duration=86400.0, step=5.0):
    r"""Smallest, mean and largest angular rate of the field's direction in inertial space.

    Parameters
    ----------
    orbit : CircularOrbit
        The orbit and its field [-].
    duration : float, optional
        Span from t = 0, > 0 [s] (a day by default).
    step : float, optional
        Sampling interval, > 0 and below ``duration`` [s]; the derivative of the direction is
        taken by central differences on it (:func:`numpy.gradient`).

    Returns
    -------
    tuple of float
        (min, mean, max) of |b̂ × db̂/dt| [rad/s], b̂ = B/|B|: the rotation a B-dot law damps
        the body's rate to.

    Notes
    -----
    Not in the sources: the rate the shared reference's B-dot analysis names (a B-dot law
    drives the body's rate toward the field direction's). On a polar orbit of a direct
    dipole it lies between 1.5 and 3 times the orbital rate (mean 2): b̂ turns once per orbit
    in the orbital frame, non-uniformly, and the frame turns once more.
    """
    span = as_positive_scalar("duration", duration, unit="s")
    h = as_positive_scalar("step", step, unit="s")
    if h >= span:
        raise ValueError(f"step must be below duration ({span!r} s), got {h!r} s")
    t = np.arange(0.0, span, h)
    b = orbit.field(t)
    b_hat = b / np.linalg.norm(b, axis=-1, keepdims=True)
    rate = np.linalg.norm(np.cross(b_hat, np.gradient(b_hat, t, axis=0)), axis=-1)
    return float(np.min(rate)), float(np.mean(rate)), float(np.max(rate))


def field_magnitude_range(orbit, samples=721):
    r"""Smallest and largest field magnitude over one orbit.

    Parameters
    ----------
    orbit : CircularOrbit
        The orbit and its field [-].
    samples : int, optional
        Equally spaced instants from t = 0 to one period, both ends included, >= 2 [-].

    Returns
    -------
    tuple of float
        (min |B|, max |B|) [T]; over a direct dipole, B0 near the magnetic equator up to
        B0 √(1 + 3 sin²i) at the orbit's highest latitude.

    Notes
    -----
    Kovalenko (1975) eq. (2.36) along the orbit (:meth:`magbench.earth.CircularOrbit.field`): the
    span of field amplitudes a hysteresis rod along the field is cycled through (TNS-0 preprint §3,
    Kovalenko (1975) §12.1).
    """
    n = as_count("samples", samples, minimum=2)
    b = np.linalg.norm(orbit.field(np.linspace(0.0, orbit.period, n)), axis=-1)
    return float(b.min()), float(b.max())
