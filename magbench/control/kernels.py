r"""The control family's array kernels: the B-dot laws (and their compiled twin), the
projected damping dipole, Kovalenko's relay spin law and his orienting laws for
stabilisation along B (:mod:`magbench.control.field_stabilisation`), unchecked. The rotor
laws' program field is the Earth family's kernel (:func:`magbench.earth.kernels.orbital_dipole_b`, tilt 0).

The checked public functions of :mod:`magbench.control.spin` call these after checking
their arguments; the simulations (:mod:`magbench.sim`) call them directly inside their
right-hand sides, where the checks would run once per stage. Vectors on a trailing axis
of 3, members on leading axes; SI or the slides' normalised units, as the caller's
arguments are. Like every kernel module, this one imports only numpy and numba (import contract in
``pyproject.toml``).
"""

import numpy as np
from numba import njit

__all__ = ["bdot_dipole", "bdot_dipole_projected", "bdot_dipole_scalar", "projected_dipole",
           "relay_dipole"]


def bdot_dipole(field_rate, gain, limit):
    """m = sat(−k Ḃ) per axis, Ḃ = field_rate (..., 3) [T/s], k = gain [N·m·s] (scalar, or
    (..., 1) per member), limit [A·m²] per axis; no checks. The checked form, which
    documents the law, is :func:`magbench.control.bdot_dipole`."""
    return np.clip(-gain * field_rate, -limit, limit)


def bdot_dipole_projected(field, field_rate, gain, limit):
    """m = sat(−(k/|B|²)[Ḃ − B(B·Ḃ)/|B|²]) per axis, B = field and Ḃ = field_rate (..., 3);
    no checks (B must not vanish). The checked form, which documents the law (Kovalenko
    (1975) eq. (6.7)), is :func:`magbench.control.bdot_dipole_projected`."""
    f0, f1, f2 = field[..., 0], field[..., 1], field[..., 2]
    b2 = (f0 * f0 + f1 * f1 + f2 * f2)[..., None]
    along = (f0 * field_rate[..., 0] + f1 * field_rate[..., 1] + f2 * field_rate[..., 2])[..., None] / b2
    return np.clip(-gain / b2 * (field_rate - field * along), -limit, limit)


@njit(cache=True, error_model="numpy")
def bdot_dipole_scalar(field, field_rate, gain, limit, projected):
    """Compiled twin of :func:`~magbench.control.kernels.bdot_dipole` (``projected`` false) and
    :func:`~magbench.control.kernels.bdot_dipole_projected` (true) for one body: B, Ḃ and the limits as 3-tuples, the
    dipole as a 3-tuple. The same operations in the same order (equal to the last bit);
    both laws are formed and one selected, so that a loop over members stays free of
    branches."""
    b0, b1, b2 = field
    d0, d1, d2 = field_rate
    lim0, lim1, lim2 = limit
    bb = b0 * b0 + b1 * b1 + b2 * b2
    along = (b0 * d0 + b1 * d1 + b2 * d2) / bb
    scale = -gain / bb
    p0, p1, p2 = scale * (d0 - b0 * along), scale * (d1 - b1 * along), scale * (d2 - b2 * along)
    u0, u1, u2 = -gain * d0, -gain * d1, -gain * d2
    v0, v1, v2 = (p0, p1, p2) if projected else (u0, u1, u2)
    return (min(max(v0, -lim0), lim0), min(max(v1, -lim1), lim1), min(max(v2, -lim2), lim2))


def projected_dipole(field, error, gain):
    r"""The projected damping dipole k (e × B)/|B|²; no checks (B must not vanish).

    Parameters
    ----------
    field : ndarray, shape (..., 3)
        B [T] (or normalised [-]).
    error : ndarray, shape (..., 3)
        The error e to damp: a rate error [rad/s] (units of ω0 [-]) or a momentum error
        divided by an inertia [rad/s].
    gain : float or ndarray
        k [N·m·s] (κ_w [-] in the normalised model); broadcasts against the leading axes.

    Returns
    -------
    ndarray, shape (..., 3)
        m [A·m²], whose torque m × B = −k e⊥.

    Notes
    -----
    Rotor slides, slide "Control implementation" (seed lines 85–87) with the sign
    corrected; Kovalenko (1975) eqs. (4.30)–(4.32). The kernel of
    :func:`magbench.control.projected_damping_dipole`.
    """
    b2 = np.sum(field * field, axis=-1, keepdims=True)
    c = np.cross(error, field)
    return np.asarray(gain)[..., None] * c / b2


def relay_dipole(field, moment, direction):
    r"""Kovalenko's relay spin law; no checks.

    Parameters
    ----------
    field : ndarray, shape (..., 3)
        B in body axes, axis 3 the spin axis [T].
    moment : float or ndarray
        L0, the coils' dipole [A·m²].
    direction : float or ndarray
        sign Δω, Δω = ω3 − ω3,required the spin error: +1 when the spin (about +z) is too
        fast, −1 when too slow [-].

    Returns
    -------
    ndarray, shape (..., 3)
        (−L0 sign Δω sign B_y, L0 sign Δω sign B_x, 0) [A·m²]: the spin-axis torque
        (L × B)_z = −L0 sign Δω (|B_x| + |B_y|), which drives Δω toward zero.

    Notes
    -----
    Kovalenko (1975) §7.3, eq. (7.12). A relay without a dead zone: sign 0 is taken as
    +1 (``copysign``), so that the law commands the full dipole at every instant as the
    source's relay does. The checked form is :func:`magbench.control.relay_spin_dipole`.
    """
    level = np.asarray(moment) * np.asarray(direction)
    bx, by = field[..., 0], field[..., 1]
    lx, ly = -level * np.copysign(1.0, by), level * np.copysign(1.0, bx)
    return np.stack(np.broadcast_arrays(lx, ly, 0.0 * lx), axis=-1)


# Kovalenko's orienting laws for stabilisation along B (§6.2).
__all__ += ["orienting_dipole", "orienting_dipole_per_axis", "pointing_dipole"]


def orienting_dipole(field, axis, gain):
    """L0 = k̃0 [i0 B² − B(B·i0)]/B², k̃0 = k0 θ/|B × i0| (k0/|B| where B ∥ i0), B = field
    (..., 3), i0 = axis a unit vector (..., 3), k0 = gain [N·m/rad] broadcasting over the
    leading axes; no checks. The checked form, which documents the law, is
    :func:`magbench.control.orienting_dipole`."""
    b2 = np.sum(field * field, axis=-1)
    along = np.sum(field * axis, axis=-1)
    c = np.cross(field, axis)
    sine = np.sqrt(np.sum(c * c, axis=-1))
    theta = np.arctan2(sine, along)
    ratio = np.where(sine > 0.0, theta / np.where(sine > 0.0, sine, 1.0), 1.0 / np.sqrt(b2))
    scale = np.asarray(gain) * ratio
    return scale[..., None] * (axis * b2[..., None] - field * along[..., None]) / b2[..., None]


def pointing_dipole(field, axis, direction, gain):
    """L_p = k̃_p [i0 (B·p) − p (B·i0)]/B², k̃_p = k_p ψ/|p × i0| (k_p where p ∥ i0), ψ the
    angle between the unit vectors i0 = axis and p = direction (..., 3), B = field (..., 3),
    k_p = gain [N·m/rad]; no checks. The checked form is :func:`magbench.control.pointing_dipole`."""
    b2 = np.sum(field * field, axis=-1)
    c = np.cross(direction, axis)
    sine = np.sqrt(np.sum(c * c, axis=-1))
    psi = np.arctan2(sine, np.sum(direction * axis, axis=-1))
    scale = np.asarray(gain) * np.where(sine > 0.0, psi / np.where(sine > 0.0, sine, 1.0), 1.0)
    bracket = (axis * np.sum(field * direction, axis=-1)[..., None]
               - direction * np.sum(field * axis, axis=-1)[..., None])
    return scale[..., None] * bracket / b2[..., None]


def orienting_dipole_per_axis(field, gains):
    """(k0x(B_y² + B_z²), −k0y B_x B_y, −k0z B_x B_z) for i0 = x, B = field (..., 3), gains
    (3,) or (..., 3); no checks. The checked form is
    :func:`magbench.control.orienting_dipole_per_axis`."""
    bx, by, bz = field[..., 0], field[..., 1], field[..., 2]
    return gains * np.stack([by * by + bz * bz, -bx * by, -bx * bz], axis=-1)


# Kovalenko's laws for magnetic unloading of reaction wheels (§5.2).
__all__ += ["unloading_dipole", "relay_unloading_dipole", "pulsed_unloading_dipole"]


def unloading_dipole(field, momentum, gain):
    """L = k (K × B)/B², K = momentum (..., 3) [N·m·s], B = field (..., 3), k = gain [1/s]
    broadcasting over the leading axes; no checks (B must not vanish). The checked form, which
    documents the law (Kovalenko (1975) eq. (5.1)), is :func:`magbench.control.unloading_dipole`."""
    b2 = np.sum(field * field, axis=-1, keepdims=True)
    return np.asarray(gain)[..., None] * np.cross(momentum, field) / b2


def relay_unloading_dipole(field, momentum, gain, dead_zone):
    """L = k F_K(K) × B with F_K(K_i) = sign(K_i) where |K_i| > K°_i, else 0; K = momentum
    (..., 3), K° = dead_zone (3,) or (..., 3) [N·m·s], k = gain [A·m²/T]; no checks. The
    checked form is :func:`magbench.control.relay_unloading_dipole` (Kovalenko eq. (5.7))."""
    relay = np.where(np.abs(momentum) > dead_zone, np.sign(momentum), 0.0)
    return np.asarray(gain)[..., None] * np.cross(relay, field)


def pulsed_unloading_dipole(field, momentum, gain, axis, field_threshold):
    """L = k K_a (e_a × B)/B² while |B_a| ≤ δ (else 0), a = axis (0, 1, 2), δ = field_threshold
    [T], k = gain [1/s]; no checks. The checked form is
    :func:`magbench.control.pulsed_unloading_dipole` (Kovalenko eqs. (5.8)–(5.9), reconstructed)."""
    e = np.zeros(3)
    e[axis] = 1.0
    b2 = np.sum(field * field, axis=-1, keepdims=True)
    on = np.abs(field[..., axis:axis + 1]) <= field_threshold
    dipole = np.asarray(gain)[..., None] * momentum[..., axis:axis + 1] * np.cross(e, field) / b2
    return np.where(on, dipole, 0.0)


__all__ += ["relay_coil_unloading_dipole"]


def relay_coil_unloading_dipole(field, momentum, moment, dead_zone, signal_dead_zone):
    """L_i = L0 F_L(δ_i), δ = F_K(K) × B, both relays with dead zones (K° = dead_zone [N·m·s],
    δ0 = signal_dead_zone [T]), L0 = moment [A·m²]; no checks. The checked form is
    :func:`magbench.control.relay_coil_unloading_dipole` (Kovalenko eq. (5.7), Figs. 5.1–5.2)."""
    relay = np.where(np.abs(momentum) > dead_zone, np.sign(momentum), 0.0)
    signal = np.cross(relay, field)
    return np.asarray(moment)[..., None] * np.where(np.abs(signal) > signal_dead_zone, np.sign(signal), 0.0)
