r"""Kovalenko's spin correction simulated: a rigid spinning body under the relay spin law.

Kovalenko (1975) §7.3: the relay law (7.12) changes the spin of a spin-stabilised
satellite (Tiros, ESSA) by δω and, through the field's component along the spin axis,
turns the spin axis by γ = δω B∥/B⊥ (his (7.27)–(7.30), from the averaged equations).
This model runs the unaveraged motion: the rigid body of
:func:`magbench.dynamics.euler_rates` and :func:`magbench.dynamics.quaternion_rate`, the
law of :func:`magbench.control.kernels.relay_dipole`, the torque of
:func:`magbench.dynamics.magnetic_torque`, integrated by
:func:`magbench.integrate.solve_adaptive`. Chapter 6 sets its turn beside his "much less
than 1°".
"""

import math

import numpy as np

from .._validate import as_count, as_positive_scalar, shown
from ..control.kernels import relay_dipole
from ..control.spin import relay_spin_dipole
from ..dynamics import kernels
from ..dynamics.rigid_body import rotate_to_inertial
from ..integrate import solve_adaptive

__all__ = ["relay_spin_correction", "relay_spin_torque_over_turn"]


def _relay_body_rhs(time, state, moment, field_inertial, inertia):
    """(q̇, ω̇) of the rigid body under the relay law in a constant inertial field.

    The family's kernels (the numbers of the checked functions, without their checks, which
    cost four times the arithmetic at ~40 000 calls; the inputs are checked once below)."""
    q, w = state[:4], state[4:]
    b = kernels.rotate(q, field_inertial, -1.0)
    # sign Δω = +1: the spin about +z is to be slowed (Kovalenko's Δω is the spin's excess)
    torque = kernels.cross(relay_dipole(b, moment, 1.0), b)
    return np.concatenate([kernels.quaternion_rate(q, w), kernels.euler_rates(w, torque, inertia)])


def relay_spin_correction(relative_change, field_ratio, *, torque_number=2e-4, axial_ratio=1.5):
    r"""Turn of the spin axis while Kovalenko's relay law (7.12) corrects the spin (his (7.27)–(7.30)).

    Parameters
    ----------
    relative_change : float
        δω = Δω3/ω3 the correction makes, in (0, 0.5) [-].
    field_ratio : float
        B∥/B⊥ during the correction, in [0, 10] [-].
    torque_number : float, optional
        L0 B⊥/(J3 ω3²) > 0 [-]; small (the default 2e-4) so that the correction lasts many
        spin turns, as on the satellites he describes.
    axial_ratio : float, optional
        J3 over the transverse inertia, > 0 [-].

    Returns
    -------
    turn : float
        Angle between the angular momentum's initial and final directions [rad].
    achieved : float
        The spin's relative change at the end, |1 − ω3(t0)/ω3(0)| [-].

    Notes
    -----
    Kovalenko (1975) §7.3, eqs. (7.12), (7.26)–(7.30). A rigid axisymmetric body
    (transverse inertia 1, axial ``axial_ratio``, spin ω3 = 1 about body z, body axes
    inertial at the start) in a constant field with transverse part B⊥ = 1 along inertial
    x and axial part ``field_ratio`` along z; the relay dipole
    L = (−L0 sign B_y, L0 sign B_x, 0) in body axes (sign Δω = +1, the spin slowed)
    acts for t0 = δω J3 ω3/((4/π) L0 B⊥), the duration his mean moment (7.26) gives. The
    attitude is a quaternion (:func:`magbench.dynamics.quaternion_rate`); DOP853 with
    rtol 1e-10, atol 1e-12 and steps of at most 0.05 (a fiftieth of a spin turn's 2π/ω3:
    the relay switches four times a turn and the error control must see each switch).
    Normalised units: time in 1/ω3, inertia in the transverse moment.

    Raises
    ------
    ValueError
        When an argument is outside its range, naming it, its value and the range.
    """
    if not 0.0 < relative_change < 0.5:
        raise ValueError(f"relative_change must be in (0, 0.5), got {shown(relative_change)}")
    if not 0.0 <= field_ratio <= 10.0:
        raise ValueError(f"field_ratio must be in [0, 10], got {shown(field_ratio)}")
    ratio = float(field_ratio)
    torque_number = as_positive_scalar("torque_number", torque_number)
    axial = as_positive_scalar("axial_ratio", axial_ratio)
    inertia = np.array([1.0, 1.0, axial])
    moment = torque_number * axial                      # L0 B⊥ = torque_number J3 ω3² with B⊥ = ω3 = 1
    field_inertial = np.array([1.0, 0.0, ratio])
    # Kovalenko (7.26)-(7.29): mean moment (4/π) L0, so t0 = δω J3 ω3 / ((4/π) L0 B⊥)
    duration = relative_change * axial / (4.0 / math.pi * moment)
    y0 = np.array([1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0])
    sol = solve_adaptive(_relay_body_rhs, (0.0, duration), y0, args=(moment, field_inertial, inertia),
                         method="DOP853", rtol=1e-10, atol=1e-12, max_step=0.05)
    q_end, w_end = sol.y[:4, -1], sol.y[4:, -1]
    k0 = inertia * y0[4:]
    k1 = rotate_to_inertial(q_end, inertia * w_end)
    cos = float(k0 @ k1 / (np.linalg.norm(k0) * np.linalg.norm(k1)))
    # min: rounding can put cos a few ulps above 1 when the axis has not turned
    return math.acos(min(1.0, cos)), abs(1.0 - float(w_end[2]))


def relay_spin_torque_over_turn(samples):
    r"""Spin-axis torque of Kovalenko's relay law (7.12) over one turn of the transverse field.

    Parameters
    ----------
    samples : int
        Points over the turn, at the midpoints of equal arcs, >= 8 [-].

    Returns
    -------
    angle : ndarray, shape (samples,)
        α, the transverse field's angle in the spin plane [rad].
    torque : ndarray, shape (samples,)
        (L × B)_z/(L0 B⊥) with sign Δω = +1 [-]; the mean of its modulus is the law's effective
        moment per L0 (4/π, Kovalenko (7.26)).

    Notes
    -----
    Kovalenko (1975) §7.3, eqs. (7.12), (7.26): the law of
    :func:`magbench.control.relay_spin_dipole`, L_x = −L0 sign Δω sign B_y,
    L_y = L0 sign Δω sign B_x, in the transverse field of magnitude B⊥ at angle α.
    """
    n = as_count("samples", samples, minimum=8)
    angle = (np.arange(n) + 0.5) * (2.0 * math.pi / n)
    # the transverse field over one turn, in units of B⊥; the law with L0 = 1, sign Δω = +1
    field = np.stack([np.cos(angle), np.sin(angle), np.zeros_like(angle)], axis=-1)
    return angle, np.cross(relay_spin_dipole(field, 1.0, 1.0), field)[:, 2]
