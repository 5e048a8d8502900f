"""Helpers shared by test modules (not a test module): sample points near a loop's axis
and wire, and the error measure the loop-field tests use. Importable as ``tests.support``
(``pythonpath = ["."]`` in the pytest options)."""

import numpy as np

#: The thesis's simulator coil radius [m] (thesis §2.2), the scale of the sample points.
A = 0.5


def relative_to_norm(b, ref):
    """Largest component error of each point divided by |B| at that point."""
    return np.max(np.abs(b - ref), axis=-1) / np.linalg.norm(ref, axis=-1)


def near_axis_points(rng, rho_over_a, n=50):
    """n points at distance rho_over_a·A from the axis, |z| ≤ 3A."""
    phi = rng.uniform(0, 2 * np.pi, n)
    z = rng.uniform(-3 * A, 3 * A, n)
    rho = rho_over_a * A
    return np.stack([rho * np.cos(phi), rho * np.sin(phi), z], axis=-1)


def near_wire_points(rng, delta_over_a, n=50):
    """n points on a torus of minor radius delta_over_a·A around the loop's wire."""
    phi = rng.uniform(0, 2 * np.pi, n)
    th = rng.uniform(0, 2 * np.pi, n)
    rho = A * (1 + delta_over_a * np.cos(th))
    return np.stack([rho * np.cos(phi), rho * np.sin(phi), A * delta_over_a * np.sin(th)], axis=-1)
