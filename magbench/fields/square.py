"""The field of square loops (straight segments, Biot–Savart) and the square pair.

Thesis §2.2 (Fig. 3, square rings) and Kovalenko (1975) §3.4 (the square Helmholtz
pair). SI throughout.
"""

import numpy as np
from scipy import optimize

from .._validate import as_finite, as_positive_scalar, as_vectors
from ..constants import MU_0
from ._inputs import _center, _finite_scalar, _frame, _positive_scalar

__all__ = ["square_loop_b", "square_loop_axial_b", "square_loop_center_b_per_moment", "square_pair_spacing"]


def _segments_b(p, starts, ends):
    """Σ over straight segments of the Biot–Savart field per unit μ0·I/(4π) [1/m]."""
    out = np.zeros_like(p)
    for a_, b_ in zip(starts, ends):
        r1 = a_ - p
        r2 = b_ - p
        n1 = np.linalg.norm(r1, axis=-1)
        n2 = np.linalg.norm(r2, axis=-1)
        cross = np.cross(r1, r2)
        dot = np.sum(r1 * r2, axis=-1)
        c2 = np.sum(cross * cross, axis=-1)
        nn = n1 * n2
        on_wire = (c2 == 0.0) & (dot <= 0.0)
        if np.any(on_wire):
            raise ValueError("points must not lie on the square loop's wire, where the field is infinite")
        # nn + dot cancels near the segment itself; use (nn² − dot²)/(nn − dot) there.
        denom = np.where(dot < 0.0, c2 / np.where(dot < 0.0, nn - dot, 1.0), nn + dot)
        with np.errstate(invalid="ignore", divide="ignore"):
            f = np.where(c2 > 0.0, (n1 + n2) / (nn * denom), 0.0)
        out += cross * f[..., None]
    return out


def square_loop_b(points, side, current, turns=1, center=(0.0, 0.0, 0.0), normal=(0.0, 0.0, 1.0)):
    r"""Flux density of a thin square loop, by Biot–Savart over its four straight sides.

    Parameters
    ----------
    points : array_like, shape (..., 3)
        Observation points [m]; must not lie on the wire.
    side : float
        Side length l [m], > 0.
    current : float
        Current I [A]; positive circulates right-handedly about ``normal``.
    turns : float, optional
        Number of turns N [-], > 0.
    center : array_like, shape (3,), optional
        Centre of the square [m].
    normal : array_like, shape (3,), optional
        Axis of the square [-], non-zero.

    Returns
    -------
    ndarray, shape (..., 3)
        B [T].

    Notes
    -----
    Not in the thesis (its square-coil formulas (28)–(31) are for magnetorquers); square
    Helmholtz pairs are in Kovalenko (1975) §3.4, p. 60. Each side contributes
    (Griffiths, *Introduction to Electrodynamics*, eq. 5.37, in vector form)

    .. math:: \mathbf B = \frac{\mu_0 NI}{4\pi}\,
              \frac{(\mathbf r_1\times\mathbf r_2)(r_1+r_2)}{r_1r_2(r_1r_2+\mathbf r_1\cdot\mathbf r_2)},

    r_1, r_2 from the point to the side's ends; near a side the denominator is taken as
    |r_1×r_2|²/(r_1r_2 − r_1·r_2) to avoid cancellation. The sides run along e1 and e2 of
    the loop frame: for normal ±z they are parallel to x and y; for normal x to z and
    y; in general e1 = ŷ × n normalised (ẑ × n when n is within ~8° of ±ŷ).

    Examples
    --------
    >>> from magbench.constants import MU_0
    >>> b = square_loop_b([0.0, 0.0, 0.0], 1.0, 1.0)
    >>> bool(np.isclose(b[2], 2 * np.sqrt(2) * MU_0 / np.pi, rtol=1e-14, atol=0))
    True
    """
    s = _positive_scalar("side", side, unit="m")
    i = _finite_scalar("current", current)
    n = _positive_scalar("turns", turns)
    c = _center(center)
    rot = _frame(normal)
    p = as_vectors("points", points)
    local = ((p - c) @ rot).reshape(-1, 3) / s
    h = 0.5
    corners = np.array([[h, -h, 0.0], [h, h, 0.0], [-h, h, 0.0], [-h, -h, 0.0]])
    unit = _segments_b(local, corners, np.roll(corners, -1, axis=0))
    return ((MU_0 * n * i / (4.0 * np.pi * s)) * unit).reshape(p.shape) @ rot.T


def square_loop_axial_b(z, side, current, turns=1):
    r"""Axial flux density of a square loop on its own axis.

    Parameters
    ----------
    z : array_like
        Distance from the loop's plane along its axis [m].
    side : float
        Side length l [m], > 0.
    current : float
        Current I [A].
    turns : float, optional
        Number of turns N [-], > 0.

    Returns
    -------
    ndarray
        B_z [T].

    Notes
    -----
    Not in the thesis: with h = l/2, B_z = 2μ0NIh² / (π(h² + z²)√(2h² + z²)), the sum
    of the four sides' fields projected on the axis.

    Examples
    --------
    >>> from magbench.constants import MU_0
    >>> bool(np.isclose(square_loop_axial_b(0.0, 1.0, 1.0), 2 * np.sqrt(2) * MU_0 / np.pi))
    True
    """
    zz = as_finite("z", z)
    s = _positive_scalar("side", side, unit="m")
    i = _finite_scalar("current", current)
    n = _positive_scalar("turns", turns)
    h2 = (s / 2.0) ** 2
    return 2.0 * MU_0 * n * i * h2 / (np.pi * (h2 + zz**2) * np.sqrt(2.0 * h2 + zz**2))


def square_loop_center_b_per_moment(side):
    r"""Flux density at the center of a square loop per unit of its dipole moment [T/(A·m²)].

    Parameters
    ----------
    side : float
        Side l of the square turn [m], > 0.

    Returns
    -------
    float
        :math:`|B(0)|/m = 2\sqrt2\,\mu_0/(\pi l^3)` for any N and I (m = N I l²), by
        Biot–Savart over the four sides (:func:`square_loop_b`).

    Notes
    -----
    Not in the thesis. A sensor inside a square coil (a magnetometer within a mock-up's
    coils) sees this near field; the far-field dipole :math:`\mu_0/(2\pi r^3)` does not
    apply there.

    Examples
    --------
    >>> from magbench.constants import MU_0
    >>> bool(np.isclose(square_loop_center_b_per_moment(0.1), 2 * np.sqrt(2) * MU_0 / (np.pi * 0.1 ** 3)))
    True
    """
    side = as_positive_scalar("side", side, unit="m")
    b = square_loop_b([0.0, 0.0, 0.0], side, 1.0, turns=1)
    return float(np.linalg.norm(b) / side ** 2)


def square_pair_spacing(side):
    r"""Spacing of a square coil pair whose axial field has zero curvature at the centre.

    Parameters
    ----------
    side : float
        Side length l [m], > 0.

    Returns
    -------
    float
        Distance between the two coil planes [m].

    Notes
    -----
    Not in the thesis: Kovalenko (1975) §3.4, p. 60, gives 0.5445 l. With
    f(z) = 1/((h² + z²)√(2h² + z²)) (:func:`square_loop_axial_b`), the pair's
    ∂²B_z/∂z² at the centre vanishes where (ln f)'' + ((ln f)')² = 0 at z = d/2; solved
    by Brent's method: d = 0.544505 l.

    Examples
    --------
    >>> round(float(square_pair_spacing(1.0)), 4)
    0.5445
    """
    s = _positive_scalar("side", side, unit="m")

    def curvature(z, h2=0.25):
        a_, b_ = h2 + z * z, 2.0 * h2 + z * z
        g1 = -2.0 * z / a_ - z / b_
        g2 = -2.0 * (h2 - z * z) / a_**2 - (2.0 * h2 - z * z) / b_**2
        return g2 + g1 * g1

    return s * 2.0 * optimize.brentq(curvature, 0.05, 0.5, xtol=1e-15)
