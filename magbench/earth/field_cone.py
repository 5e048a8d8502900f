r"""The cone swept by the direct-dipole field direction along a circular orbit.

TNS-0 preprint §1 (seed lines L78–L84, Fig. 3; its formulas were lost in extraction): in the
averaged model the field direction sweeps a cone of half-angle Δ(i) twice per orbit; the
cone touches the Earth's axis (the field is along it at the ascending node) and opens most at
u = π/2. The closed form here is a reconstruction from the standard sources the preprint
cites (Sarychev & Ovchinnikov 1985; Beletsky & Khentov 1985), checked against a direct sweep of
the dipole field (:class:`magbench.earth.CircularOrbit`).

Inertial frame N: X toward the ascending node, Z along the Earth's axis (north); the dipole
is direct (axial, non-rotating), as :class:`~magbench.earth.CircularOrbit` has it by default.
"""

import numpy as np

from .._validate import as_finite, as_in_range

__all__ = ["field_cone_half_angle", "field_cone_axis", "orbit_field_direction", "cone_field_direction",
           "field_cone_deviation", "field_cone_rate"]


def _inclination(value):
    return as_in_range("inclination", value, 0.0, np.pi, unit="rad")


def field_cone_half_angle(inclination):
    r"""Half-angle Δ of the cone the dipole field direction sweeps along a circular orbit.

    Parameters
    ----------
    inclination : float or array_like
        Orbit inclination i to the dipole's equator, in [0, π] [rad]; broadcasts.

    Returns
    -------
    ndarray
        Δ [rad], with cos 2Δ = (1 − 3 sin² i)/√(1 + 3 sin² i): Δ(0) = 0, Δ(π/2) = π/2.

    Notes
    -----
    TNS-0 preprint §1 (L78–L84, Fig. 3): the cone through the field directions at u = 0
    (along the Earth's axis) and u = π/2 (its widest opening). The preprint's formula was
    lost in extraction; this is the reconstruction of the standard averaged model (Not in
    the sources: Beletsky & Khentov (1985); Sarychev & Ovchinnikov (1985)). Equivalently
    tan Δ = 3 sin 2i / [2(1 − 3 sin² i + √(1 + 3 sin² i))].

    Examples
    --------
    >>> round(float(np.degrees(field_cone_half_angle(np.radians(51.6)))), 3)
    59.991
    """
    i = _inclination(inclination)
    s2 = np.sin(i) ** 2
    root = np.sqrt(1.0 + 3.0 * s2)
    return 0.5 * np.arccos(np.clip((1.0 - 3.0 * s2) / root, -1.0, 1.0))


def field_cone_axis(inclination):
    r"""Axis of the field cone, a unit vector in the inertial frame N.

    Parameters
    ----------
    inclination : float or array_like
        Orbit inclination i, in [0, π] [rad]; broadcasts.

    Returns
    -------
    ndarray, shape (..., 3)
        (0, −sin Δ, cos Δ) [-]: the Earth's axis turned by Δ about the node line, toward the
        field direction at u = π/2 (X → ascending node, Z → Earth's axis).

    Notes
    -----
    TNS-0 preprint §1 (L84): the cone frame has one axis toward the ascending node and the
    cone touches the Earth's axis. Reconstruction (Not in the sources: Sarychev &
    Ovchinnikov 1985).

    Examples
    --------
    >>> (np.round(field_cone_axis(0.0), 12) + 0.0).tolist()
    [0.0, 0.0, 1.0]
    """
    return _cone_frame(_inclination(inclination))[2]


def _cone_frame(i):
    """(node, side, axis) with the field ẑ = sin Δ side + cos Δ axis at u = 0; no checks."""
    delta = field_cone_half_angle(i)
    # A retrograde orbit's u = π/2 field leans toward +Y instead of −Y.
    sign = np.where(i > 0.5 * np.pi, -1.0, 1.0)
    sd, cd, zero = np.sin(delta), np.cos(delta), 0.0 * delta
    axis = np.stack(np.broadcast_arrays(zero, -sign * sd, cd), axis=-1)
    side = np.stack(np.broadcast_arrays(zero, sign * cd, sd), axis=-1)
    node = np.stack(np.broadcast_arrays(zero + 1.0, zero, zero), axis=-1)
    return node, side, axis


def orbit_field_direction(inclination, argument_of_latitude):
    r"""Exact direction of the direct-dipole field along a circular orbit, in the frame N.

    Parameters
    ----------
    inclination : float or array_like
        Orbit inclination i, in [0, π] [rad].
    argument_of_latitude : float or array_like
        Argument of latitude u (angle from the ascending node) [rad]; broadcasts with
        ``inclination``.

    Returns
    -------
    ndarray, shape (..., 3)
        B̂ [-], B ∝ ẑ − 3 sin u sin i r̂(u), r̂ = (cos u, sin u cos i, sin u sin i).

    Notes
    -----
    Not in the sources: Jackson (1999) eq. (5.56) for a dipole −M ẑ at the Earth's centre
    (the field :class:`magbench.earth.CircularOrbit` computes); independent of the radius and
    of M. Equivalently B ∝ c + (3/2) sin i [−sin 2u x̂ + cos 2u (0, cos i, sin i)]: its tip
    runs on a round path at 2u (TNS-0 preprint §1, L80: "twice the orbital rate").
    """
    i = _inclination(inclination)
    u = as_finite("argument_of_latitude", argument_of_latitude)
    i, u = np.broadcast_arrays(i, u)
    si = np.sin(i)
    r = np.stack([np.cos(u), np.sin(u) * np.cos(i), np.sin(u) * si], axis=-1)
    b = np.zeros(r.shape)
    b[..., 2] = 1.0
    b = b - 3.0 * (np.sin(u) * si)[..., None] * r
    return b / np.linalg.norm(b, axis=-1, keepdims=True)


def cone_field_direction(inclination, argument_of_latitude):
    r"""Field direction of the averaged (uniform-rate) cone model, in the frame N.

    Parameters
    ----------
    inclination : float or array_like
        Orbit inclination i, in [0, π] [rad].
    argument_of_latitude : float or array_like
        Argument of latitude u [rad]; broadcasts with ``inclination``.

    Returns
    -------
    ndarray, shape (..., 3)
        ê [-]: in the cone frame (x̂ node, ŷ, axis) e = (−sin Δ sin 2u, sin Δ cos 2u, cos Δ),
        the Earth's axis at u = 0, the cone's widest opening at u = π/2, turning at 2u.

    Notes
    -----
    TNS-0 preprint §1 (L78–L84, eq. (1), lost in extraction): the averaged field direction
    moves uniformly on the cone at twice the orbital rate. Reconstruction (Not in the
    sources: Sarychev & Ovchinnikov 1985). It matches :func:`orbit_field_direction` at
    u = 0 and π/2 only.
    """
    i = _inclination(inclination)
    u = as_finite("argument_of_latitude", argument_of_latitude)
    i, u = np.broadcast_arrays(i, u)
    delta = field_cone_half_angle(i)
    node, side, axis = _cone_frame(i)
    sd, cd = np.sin(delta)[..., None], np.cos(delta)[..., None]
    s2u, c2u = np.sin(2.0 * u)[..., None], np.cos(2.0 * u)[..., None]
    return -sd * s2u * node + sd * c2u * side + cd * axis


def field_cone_deviation(inclination, argument_of_latitude):
    r"""How far the exact field direction is from the cone and from the uniform-rate model.

    Parameters
    ----------
    inclination : float or array_like
        Orbit inclination i, in [0, π] [rad].
    argument_of_latitude : float or array_like
        Argument of latitude u [rad]; broadcasts with ``inclination``.

    Returns
    -------
    off_cone : ndarray
        Angle between the exact direction and the cone axis minus Δ [rad] (> 0: outside).
    direction_error : ndarray
        Angle between the exact direction and :func:`cone_field_direction` [rad].
    phase_error : ndarray
        Azimuth of the exact direction about the cone axis minus the model's 2u, wrapped to
        (−π, π] [rad].

    Notes
    -----
    Not in the sources: the comparison of :func:`orbit_field_direction` (Jackson 1999
    eq. (5.56)) with the averaged model of the TNS-0 preprint §1 (L78–L84). At i = 51.6°
    the exact direction lies 0–1.1° outside the cone but its azimuth runs non-uniformly,
    so the model is off by up to ≈ 13° at an instant.
    """
    exact = orbit_field_direction(inclination, argument_of_latitude)
    model = cone_field_direction(inclination, argument_of_latitude)
    i = np.broadcast_to(_inclination(inclination), exact.shape[:-1])
    u = np.broadcast_to(as_finite("argument_of_latitude", argument_of_latitude), exact.shape[:-1])
    node, side, axis = _cone_frame(i)
    delta = field_cone_half_angle(i)
    off_cone = np.arccos(np.clip(np.sum(exact * axis, axis=-1), -1.0, 1.0)) - delta
    direction_error = np.arccos(np.clip(np.sum(exact * model, axis=-1), -1.0, 1.0))
    azimuth = np.arctan2(-np.sum(exact * node, axis=-1), np.sum(exact * side, axis=-1))
    phase_error = np.angle(np.exp(1j * (azimuth - 2.0 * u)))
    return off_cone, direction_error, phase_error


def field_cone_rate(inclination, argument_of_latitude):
    r"""Rate at which the exact field direction goes round the cone, in units of the orbital rate.

    Parameters
    ----------
    inclination : float
        Orbit inclination i, in [0, π] [rad].
    argument_of_latitude : array_like, shape (n,)
        Increasing samples of u, n >= 2, fine enough for a numerical derivative [rad].

    Returns
    -------
    ndarray, shape (n,)
        dφ/du of the exact direction's azimuth φ about the cone axis [-] (the averaged model's
        is 2 at every u), by central differences of 2u plus the unwrapped phase error of
        :func:`field_cone_deviation`.

    Notes
    -----
    TNS-0 preprint §1 (L78–L84): the averaged model's "constant rate, twice the orbital rate";
    the exact direct-dipole direction (:func:`orbit_field_direction`) goes round once per half
    orbit, at 2 on average but not uniformly.
    """
    u = as_finite("argument_of_latitude", argument_of_latitude)
    if u.ndim != 1 or u.size < 2 or np.any(np.diff(u) <= 0):
        raise ValueError(f"argument_of_latitude must be increasing samples of shape (n,), n >= 2, got shape {u.shape}")
    if np.ndim(inclination) != 0:
        raise ValueError(f"inclination must be a scalar [rad], got shape {np.shape(inclination)}")
    phase_error = field_cone_deviation(inclination, u)[2]
    return np.gradient(2.0 * u + np.unwrap(phase_error), u)
