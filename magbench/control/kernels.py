r"""The control family's array kernels: the rotor spacecraft's program field, the projected
damping dipole and Kovalenko's relay spin law, unchecked.

The checked public functions of :mod:`magbench.control.spin` call these after checking
their arguments; the simulations (:mod:`magbench.sim`) call them directly inside their
right-hand sides, where the checks would run once per stage. Vectors on a trailing axis
of 3, members on leading axes; SI or the slides' normalised units, as the caller's
arguments are. Like every kernel module, this one imports only numpy (import contract in
``pyproject.toml``).
"""

import numpy as np

__all__ = ["program_field", "projected_dipole", "relay_dipole"]


def program_field(u, i, b0):
    r"""The direct dipole along a circular orbit in orbital axes, B0 (sin i cos u, cos i,
    −2 sin i sin u) [T], for u [rad], i [rad] and b0 [T] (..., broadcasting); no checks. The
    checked form, which documents it (rotor slides, seed lines 21 and 63; Kovalenko (1975)
    eq. (2.40)), is :func:`magbench.control.rotor_program_field`.
    """
    su, cu, si, ci = np.sin(u), np.cos(u), np.sin(i), np.cos(i)
    # ci + 0·u: the normal component takes the shape of u like the other two
    return b0[..., None] * np.stack(np.broadcast_arrays(si * cu, ci + 0.0 * u, -2.0 * si * su), axis=-1)


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
