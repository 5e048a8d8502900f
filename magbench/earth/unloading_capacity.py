r"""How much wheel momentum magnetorquers can unload along each direction, over an orbit.

Magnetorquers unload reaction-wheel momentum K with the torque L × B, always across the field
B: over an orbit the momentum along a direction ê can be removed only as far as the field has
a component across ê. This module gives that capacity in closed form for a circular orbit of
inclination i around a centred, axial (untilted), non-rotating dipole Earth (Kovalenko (1975)
eq. (2.36); :class:`magbench.earth.CircularOrbit` with its defaults), for the two forms of
Kovalenko's linear law (1975, §5.2):

* without division by B² (the per-axis form (5.6), L = k K × B): torque −k(B² I − B Bᵀ)K,
  capacity u(ê) = ⟨|B × ê|²⟩/⟨B²⟩ = 1 − êᵀ⟨B Bᵀ⟩ê/⟨B²⟩ (:func:`field_second_moment`);
* with division by B² ((5.1), L = k (K × B)/B²): torque −k K⊥ = −k(I − B̂ B̂ᵀ)K ((5.3)),
  capacity u₁(ê) = 1 − ⟨(B̂·ê)²⟩ (:func:`field_direction_second_moment`).

Interpretation. When the unloading is slow against the orbit (k⟨B²⟩ ≪ n for (5.6), k ≪ n for
(5.1)), averaging over an orbit gives K̇ = −k(⟨B²⟩ I − ⟨B Bᵀ⟩)K, resp. K̇ = −k(I − ⟨B̂ B̂ᵀ⟩)K:
the momentum along each eigen-direction ê of the averaged matrix decays at the rate
k⟨B²⟩ u(ê), resp. k u₁(ê) [1/s]. The smallest of them (:func:`unloadable_fraction` with no
direction, along :func:`worst_unloading_direction`) sets how long the last of the momentum
takes; (5.4)–(5.5) guarantee only that |K| never grows. The momentum is taken in inertial axes
(the total momentum, or a body held inertially as in §5.5); the dipole does not turn, so the
averages are over one orbit.

Axes ("orbit axes"): x̂ toward the ascending node, ŷ in the orbit plane 90° ahead of it, n̂ the
orbit normal (inertial, fixed). With u the argument of latitude, r̂ = cos u x̂ + sin u ŷ, the
dipole axis ẑ = sin i ŷ + cos i n̂ and B = ±B0 [3(ẑ·r̂) r̂ − ẑ], ẑ·r̂ = sin i sin u,
B0 = μ0 M/(4π r³) [T] the equatorial field at the orbit's radius (the sign drops out of every
second moment). SI throughout; the results are dimensionless.

Not in the sources: derived here (the averages over u, their eigenvalues and the
normalised-field averages through ⟨1/(1 + a sin²u)⟩ = 1/√(1 + a)); the tests check them with
sympy and against :class:`~magbench.earth.CircularOrbit`'s field sampled over one period.
"""

import numpy as np

from .._validate import as_finite, as_in_range, shown

__all__ = ["field_second_moment", "field_direction_second_moment", "unloadable_fraction",
           "worst_unloading_direction"]


def _inclination(value):
    return as_in_range("inclination", value, 0.0, np.pi, unit="rad")


def _matrix(xx, yy, nn, yn):
    """Symmetric (..., 3, 3) from the four non-zero entries (xy = xn = 0)."""
    xx, yy, nn, yn = np.broadcast_arrays(xx, yy, nn, yn)
    out = np.zeros(xx.shape + (3, 3))
    out[..., 0, 0] = xx
    out[..., 1, 1] = yy
    out[..., 2, 2] = nn
    out[..., 1, 2] = out[..., 2, 1] = yn
    return out


def _raw_entries(i):
    """⟨B Bᵀ⟩/B0² entries (xx, yy, nn, yn) and the trace ⟨B²⟩/B0²; no checks."""
    s, c = np.sin(i), np.cos(i)
    s2 = s * s
    return 9.0 / 8.0 * s2, 11.0 / 8.0 * s2, c * c, -0.5 * s * c, 1.0 + 1.5 * s2


def _unit_entries(i):
    """⟨B̂ B̂ᵀ⟩ entries (xx, yy, nn, yn) and q = √(1 + 3 sin²i); no checks."""
    s, c = np.sin(i), np.cos(i)
    q = np.sqrt(1.0 + 3.0 * s * s)
    xx = 1.5 * (q - 1.0) / (q + 1.0)
    nn = c * c / q
    yn = -s * c * (2.0 - q) / (q * (q + 1.0))
    return xx, 1.0 - xx - nn, nn, yn, q


def field_second_moment(inclination):
    r"""Orbit mean of B Bᵀ over B0², in orbit axes.

    Parameters
    ----------
    inclination : float or array_like
        Orbit inclination i to the dipole's equator, in [0, π] [rad]; an array gives one
        matrix per element.

    Returns
    -------
    ndarray, shape (..., 3, 3)
        ⟨B Bᵀ⟩/B0² [-] in orbit axes (x̂ ascending node, ŷ 90° ahead, n̂ orbit normal):

        xx = (9/8) sin²i, yy = (11/8) sin²i, nn = cos²i, yn = ny = −(1/2) sin i cos i,
        xy = xn = 0; its trace is ⟨B²⟩/B0² = 1 + (3/2) sin²i.

    Notes
    -----
    Not in the sources: derived here from the dipole field (Kovalenko (1975) eq. (2.36)).
    With ẑ·r̂ = sin i sin u, B/B0 = ±(3 sin i sin u cos u, sin i (3 sin²u − 1), −cos i) in
    orbit axes; the mean over u uses ⟨sin²u cos²u⟩ = 1/8, ⟨(3 sin²u − 1)²⟩ = 11/8 and
    ⟨3 sin²u − 1⟩ = 1/2. The trace agrees with :func:`magbench.earth.mean_square_field`.

    Examples
    --------
    >>> field_second_moment(np.pi / 2).round(12).tolist()
    [[1.125, 0.0, 0.0], [0.0, 1.375, -0.0], [0.0, -0.0, 0.0]]
    """
    xx, yy, nn, yn, _ = _raw_entries(_inclination(inclination))
    return _matrix(xx, yy, nn, yn)


def field_direction_second_moment(inclination):
    r"""Orbit mean of B̂ B̂ᵀ (B̂ = B/|B|), in orbit axes.

    Parameters
    ----------
    inclination : float or array_like
        Orbit inclination i, in [0, π] [rad]; an array gives one matrix per element.

    Returns
    -------
    ndarray, shape (..., 3, 3)
        ⟨B̂ B̂ᵀ⟩ [-], trace 1. With q = √(1 + 3 sin²i):

        xx = (3/2)(q − 1)/(q + 1), nn = cos²i/q, yy = 1 − xx − nn,
        yn = ny = −sin i cos i (2 − q)/(q(q + 1)), xy = xn = 0.

        Polar orbit (q = 2): diag(1/2, 1/2, 0), the field direction stays in the orbit plane.

    Notes
    -----
    Not in the sources: derived here. |B|²/B0² = 1 + a sin²u, a = 3 sin²i = q² − 1, so the
    entries of :func:`field_second_moment`'s integrand are divided by it. With
    J0 = ⟨1/(1 + a sin²u)⟩ = 1/q, J1 = ⟨sin²u/(…)⟩ = (1 − J0)/a = 1/(q(q + 1)) and
    J2 = ⟨sin⁴u/(…)⟩ = (1/2 − J1)/a = (q + 2)/(2q(q + 1)²): xx = 9 sin²i (J1 − J2),
    nn = cos²i J0, yn = −sin i cos i (3 J1 − J0), and the trace a J1 + J0 = 1.

    Examples
    --------
    >>> field_direction_second_moment(np.pi / 2).round(12).tolist()
    [[0.5, 0.0, 0.0], [0.0, 0.5, -0.0], [0.0, -0.0, 0.0]]
    """
    xx, yy, nn, yn, _ = _unit_entries(_inclination(inclination))
    return _matrix(xx, yy, nn, yn)


def _worst_fraction(i, normalised):
    """Smallest unloadable fraction, closed form; no checks."""
    s2 = np.sin(i) ** 2
    if normalised:
        q = np.sqrt(1.0 + 3.0 * s2)
        root = np.sqrt(np.maximum(8.0 * q**3 + q**2 - 50.0 * q + 25.0 + 32.0 / q, 0.0))
        return (5.0 * q - 1.0 - root) / (4.0 * (q + 1.0))
    root = np.sqrt(64.0 - 240.0 * s2 + 297.0 * s2 * s2)  # > 0: its discriminant in s² is < 0
    return (8.0 + 21.0 * s2 - root) / (16.0 + 24.0 * s2)


def unloadable_fraction(inclination, direction=None, *, normalised=False):
    r"""Share of the field's strength that lies across a direction, averaged over an orbit.

    Parameters
    ----------
    inclination : float or array_like
        Orbit inclination i, in [0, π] [rad].
    direction : array_like, shape (..., 3), optional
        The direction ê in orbit axes (x̂ ascending node, ŷ 90° ahead, n̂ orbit normal),
        non-zero; normalised here [-]; broadcasts with ``inclination``. None (default): the
        worst direction, :func:`worst_unloading_direction`.
    normalised : bool, optional
        False (default): for the law without division by B², Kovalenko (1975) eq. (5.6);
        True: for the law L = k (K × B)/B², eq. (5.1) [-].

    Returns
    -------
    ndarray
        In [0, 1] [-]:

        * ``normalised=False``: u(ê) = ⟨|B × ê|²⟩/⟨B²⟩ = 1 − êᵀ⟨B Bᵀ⟩ê/⟨B²⟩; momentum along an
          eigen-direction decays at k⟨B²⟩ u [1/s]. Worst direction, s = sin i:

          u_min = [8 + 21 s² − √(64 − 240 s² + 297 s⁴)]/(16 + 24 s²),

          0 on the equator, 9/20 on a polar orbit (along the dipole axis ŷ; u(n̂) = 1 there).
        * ``normalised=True``: u₁(ê) = 1 − ⟨(B̂·ê)²⟩; it decays at k u₁ [1/s]. Worst
          direction, q = √(1 + 3 sin²i):

          u₁_min = [5q − 1 − √(8q³ + q² − 50q + 25 + 32/q)]/(4(q + 1)),

          0 on the equator, 1/2 on a polar orbit (every direction in the orbit plane;
          u₁(n̂) = 1 there).

    Notes
    -----
    Not in the sources: derived here. u_min = 1 − λ_max/trace of :func:`field_second_moment`
    (resp. 1 − λ_max of :func:`field_direction_second_moment`). λ_max is always the larger
    eigenvalue of the (ŷ, n̂) block, never the xx entry: without division the block's
    λ₊ ≥ max(yy, nn) ≥ (11/8) sin²i ≥ xx, equal only at i = 0, where xx = 0 < λ₊ = 1; with
    division λ₊ − xx has the sign of 11 − 7q + √(P(q)/q), P(q) = 8q⁴ + q³ − 50q² + 25q + 32,
    and P(q) − q(7q − 11)² = 8(q − 1)²(q − 2)² ≥ 0, so λ₊ ≥ xx, equal only on a polar orbit
    (q = 2), where the worst direction is any in the orbit plane. Neither is monotonic in i:
    u_min peaks at ≈ 0.510 near i ≈ 47.2°, u₁_min at ≈ 0.618 near i ≈ 46.7° (numerical
    maxima of the closed forms), above their polar values. Both depend on sin²i only:
    i and π − i give the same values (a given ê maps to ê with n̂ reversed).

    Kovalenko (1975) §5.2: the torque of (5.1) is −k K⊥ ((5.3)), of (5.6) −k(B² K − B(B·K));
    (5.4)–(5.5) show only that |K| does not grow. Dipole field: eq. (2.36).

    Examples
    --------
    >>> round(float(unloadable_fraction(np.pi / 2)), 12)
    0.45
    >>> round(float(unloadable_fraction(np.pi / 2, normalised=True)), 12)
    0.5
    >>> unloadable_fraction(np.radians([0.0, 51.6]), [0.0, 0.0, 1.0]).round(4).tolist()
    [0.0, 0.7992]
    """
    i = _inclination(inclination)
    if direction is None:
        return _worst_fraction(i, bool(normalised))
    e = as_finite("direction", direction)
    if e.ndim == 0 or e.shape[-1] != 3:
        raise ValueError(f"direction must have shape (..., 3), got shape {e.shape}")
    norm = np.linalg.norm(e, axis=-1, keepdims=True)
    if np.any(norm == 0.0):
        raise ValueError(f"direction must be non-zero, got {shown(e[(norm == 0.0)[..., 0]][0].tolist())}")
    e = e / norm
    if normalised:
        xx, yy, nn, yn, _ = _unit_entries(i)
        total = 1.0
    else:
        xx, yy, nn, yn, total = _raw_entries(i)
    along = xx * e[..., 0] ** 2 + yy * e[..., 1] ** 2 + nn * e[..., 2] ** 2 + 2.0 * yn * e[..., 1] * e[..., 2]
    return np.clip(1.0 - along / total, 0.0, 1.0)


def worst_unloading_direction(inclination, *, normalised=False):
    r"""The direction along which the least momentum can be unloaded, in orbit axes.

    Parameters
    ----------
    inclination : float or array_like
        Orbit inclination i, in [0, π] [rad].
    normalised : bool, optional
        False (default): for Kovalenko's (5.6), eigenvector of ⟨B Bᵀ⟩; True: for (5.1),
        eigenvector of ⟨B̂ B̂ᵀ⟩ [-].

    Returns
    -------
    ndarray, shape (..., 3)
        Unit ê = (0, sin θ, cos θ) [-] in orbit axes, the eigenvector of the largest
        eigenvalue of the (ŷ, n̂) block A of the averaged matrix, θ = (1/2) atan2(2 A_yn,
        A_nn − A_yy) in [−π/2, π/2] (sign: ê·n̂ ≥ 0; +ŷ on a polar orbit). Both versions
        give n̂ on the equator and ŷ (the dipole axis) on a polar orbit; with division x̂, and
        any direction in the orbit plane, is as bad there.

    Notes
    -----
    Not in the sources: derived here (the largest eigenvalue lies in the (ŷ, n̂) block, see
    :func:`unloadable_fraction`). For 0 < i < π/2 it turns from n̂ toward −ŷ (θ from 0 to
    −π/2), away from the dipole axis (0, sin i, cos i), on the same side as the orbit mean of
    the field, ∝ (0, −sin i/2, cos i); π − i gives ê with its ŷ part reversed.

    Examples
    --------
    >>> (worst_unloading_direction([0.0, np.pi / 2]).round(12) + 0.0).tolist()
    [[0.0, 0.0, 1.0], [0.0, 1.0, 0.0]]
    """
    i = _inclination(inclination)
    if normalised:
        _, yy, nn, yn, _ = _unit_entries(i)
    else:
        _, yy, nn, yn, _ = _raw_entries(i)
    theta = 0.5 * np.arctan2(2.0 * yn, nn - yy)  # in [−π/2, π/2]: cos θ ≥ 0
    # A polar orbit gives θ = ±π/2 by the rounding of cos i; take +ŷ there.
    theta = np.where(np.abs(np.cos(theta)) < 1e-12, 0.5 * np.pi, theta)
    return np.stack(np.broadcast_arrays(0.0 * theta, np.sin(theta), np.cos(theta)), axis=-1)
