r"""Magnetic control of a spinning spacecraft with a coaxial rotor: the equilibrium dipole,
the projected damping and its momentum-error variant.

Rotor slides, slides "Creating the equilibrium", "Choice of control", "Ensuring
stability" and "Control implementation" (seed lines 41–88), with Kovalenko (1975)
eqs. (4.30)–(4.32) and (7.3)–(7.5) for the projection law. Frames as in
:mod:`magbench.dynamics.gyrostat` (``shared/reference/rotor_spin.md`` §2): the
program field is the direct dipole in orbital axes (velocity, orbit normal, radial out),
B_o(u) = B0 (sin i cos u, cos i, −2 sin i sin u): the Earth family's tilted dipole
(:func:`magbench.earth.orbital_dipole_b`, kernel :func:`magbench.earth.kernels.orbital_dipole_b`)
with tilt 0. The law works for the slides'
normalised quantities as well as SI (see each function). Kovalenko's relay spin law (7.12)
closes the module. Pure functions; their unchecked kernels are in :mod:`magbench.control.kernels`.
"""

import numpy as np

from .._validate import as_finite, as_in_range, as_positive, as_vectors, shown
from ..earth.kernels import orbital_dipole_b
from .kernels import projected_dipole, relay_dipole

__all__ = ["rotor_program_field", "rotor_equilibrium_dipole", "rotor_equilibrium_axial_momentum",
           "rotor_reference_torque", "rotor_spin_reference", "projected_damping_dipole",
           "slides_printed_damping_torque", "rotor_reference_momentum", "momentum_damping_dipole", "relay_spin_dipole"]


def rotor_program_field(argument_of_latitude, inclination, equatorial_b):
    r"""The controller's program field: the direct dipole along a circular orbit, orbital axes.

    Parameters
    ----------
    argument_of_latitude : float or array_like
        u, from the ascending node [rad].
    inclination : float or array_like
        i, in [0, π] [rad].
    equatorial_b : float or array_like
        B0 = μ0 M/(4π r³) [T] (1 gives the field in units of B0 [-]).

    Returns
    -------
    ndarray, shape (..., 3)
        B0 (sin i cos u, cos i, −2 sin i sin u) [T].

    Notes
    -----
    Rotor slides, slide "Problem statement" (seed line 21: direct dipole) and slide
    "Choice of control" (seed line 63: f = −2 sin i B0 is the amplitude of B3);
    Kovalenko (1975) eq. (2.40). Only these axes (velocity, normal, radial out) satisfy
    the slides' equilibrium conditions (``rotor_spin.md`` §5).
    """
    u = as_finite("argument_of_latitude", argument_of_latitude)
    i = as_in_range("inclination", inclination, 0.0, np.pi, unit="rad")
    b0 = as_positive("equatorial_b", equatorial_b, unit="T")
    return orbital_dipole_b(u, i, 0.0, 0.0, b0)


def rotor_equilibrium_dipole(argument_of_latitude, inclination, equatorial_b, gain, axial_momentum, orbital_rate):
    r"""The slides' equilibrium dipole: M = k B_o(u) + (0, H0 ω0 cos u/(B0 sin i), 0).

    Parameters
    ----------
    argument_of_latitude : float or array_like
        u, from the ascending node [rad].
    inclination : float or array_like
        i, in (0, π) [rad]; sin i = 0 is rejected (the law does not exist there).
    equatorial_b : float or array_like
        B0 [T] (1 for the normalised law [-]).
    gain : float or array_like
        Restoring gain k [A·m²/T] (κ for the normalised law [-]).
    axial_momentum : float or array_like
        H0, total axial momentum at u = 0 [N·m·s] (c1 for the normalised law [-]).
    orbital_rate : float or array_like
        ω0 [rad/s] (1 for the normalised law [-]).

    Returns
    -------
    ndarray, shape (..., 3)
        Dipole (M1, M2, M3) in the semi-body frame [A·m²]. On the reference motion
        (α = β = 0) its torque is independent of k: (−H0 ω0 sin 2u, 0, −H0 ω0 cos²u)
        [N·m], exactly what the reference needs.

    Notes
    -----
    Rotor slides, slide "Choice of control" (seed lines 61–69): M3 = k f sin u,
    f = −2 sin i B0, M2 = (−½ k f B0 cos i + C1 cos u)/(B0 sin i), M1 = −½ k f cos u.
    Deviation from source: the slides' M1 = (B1/B3) M3 (seed line 57) divides by B3,
    which vanishes at u = 0, π; the closed form M1 = k B1 has no such pole, and the
    k-part is recognised as k B_o (parallel to the field, no torque on the reference).
    In the slides' units M_slides = m/ω0² and C1 = H0/ω0, so the SI m2 is
    H0 ω0 cos u/(B0 sin i).
    """
    u = as_finite("argument_of_latitude", argument_of_latitude)
    i = as_in_range("inclination", inclination, 0.0, np.pi, unit="rad")
    si = np.sin(i)
    if np.any(np.abs(si) < 1e-12):
        raise ValueError(f"inclination must have sin i != 0 (the law divides by B0 sin i), got {shown(float(np.ravel(i)[0]))}")
    b0 = as_positive("equatorial_b", equatorial_b, unit="T")
    k = as_finite("gain", gain)
    h0 = as_finite("axial_momentum", axial_momentum)
    w0 = as_positive("orbital_rate", orbital_rate, unit="rad/s")
    m = k[..., None] * orbital_dipole_b(u, i, 0.0, 0.0, b0)
    m2 = h0 * w0 * np.cos(u) / (b0 * si)
    return m + np.stack(np.broadcast_arrays(0.0 * m2, m2, 0.0 * m2), axis=-1)


def rotor_equilibrium_axial_momentum(argument_of_latitude, axial_momentum):
    r"""Total axial momentum on the reference motion, forced by the equilibrium law.

    Parameters
    ----------
    argument_of_latitude : float or array_like
        u [rad].
    axial_momentum : float or array_like
        H0 at u = 0 [N·m·s].

    Returns
    -------
    ndarray
        H = H0 cos²u [N·m·s].

    Notes
    -----
    Rotor slides, slide "Creating the equilibrium" (seed lines 45–53): on the reference
    the torque is ⊥ B and has no normal component, so H'/H = B3/B1 = −2 tan u
    (``rotor_spin.md`` §5); this swing limits the spin accuracy to about ω0.
    """
    u = as_finite("argument_of_latitude", argument_of_latitude)
    return as_finite("axial_momentum", axial_momentum) * np.cos(u) ** 2


def rotor_reference_torque(argument_of_latitude, axial_momentum, orbital_rate):
    r"""The torque the reference motion needs, semi-body axes on the reference.

    Parameters
    ----------
    argument_of_latitude : float or array_like
        u [rad].
    axial_momentum : float
        H0, total axial momentum at u = 0 [N·m·s].
    orbital_rate : float
        ω0 [rad/s], > 0.

    Returns
    -------
    ndarray, shape (..., 3)
        L_ref = (−H0 ω0 sin 2u, 0, −H0 ω0 cos²u) [N·m]: the change of K_ref = H0 cos²u e1 + B ω0 e2
        (:func:`rotor_equilibrium_axial_momentum`) in the orbital frame turning at ω0 about e2.

    Notes
    -----
    Rotor slides, slide "Creating the equilibrium" (seed lines 45–53), with ``rotor_spin.md`` §5:
    the torque of :func:`rotor_equilibrium_dipole` on the reference equals it for every gain k.
    """
    u = as_finite("argument_of_latitude", argument_of_latitude)
    h0 = float(as_finite("axial_momentum", axial_momentum))
    w0 = float(as_positive("orbital_rate", orbital_rate, unit="rad/s"))
    first, third = -h0 * w0 * np.sin(2 * u), -h0 * w0 * np.cos(u) ** 2
    return np.stack([first, np.zeros_like(first), third], axis=-1)


def rotor_spin_reference(argument_of_latitude, axial_momentum, rotor_momentum, axial_inertia):
    r"""Body spin on the reference motion.

    Parameters
    ----------
    argument_of_latitude : float or array_like
        u [rad].
    axial_momentum : float or array_like
        H0 at u = 0 [N·m·s].
    rotor_momentum : float or array_like
        J_f ν, the rotor's momentum relative to the body [N·m·s].
    axial_inertia : float or array_like
        A = I11 of body + rotor [kg·m²].

    Returns
    -------
    ndarray
        s_ref(u) = (H0 cos²u − J_f ν)/A [rad/s]; it swings by H0/A twice per orbit.

    Notes
    -----
    Rotor slides, slide "Ensuring stability" (seed line 77: Ω_1ref) with the axial
    momentum of :func:`rotor_equilibrium_axial_momentum` (``rotor_spin.md`` §13, pitfall 6:
    Ω_1ref is not constant unless H0 = 0).
    """
    h = rotor_equilibrium_axial_momentum(argument_of_latitude, axial_momentum)
    a = as_positive("axial_inertia", axial_inertia, unit="kg·m²")
    return (h - as_finite("rotor_momentum", rotor_momentum)) / a


def projected_damping_dipole(field, rate_error, gain):
    r"""The damping dipole that damps: m = k_w (w × B)/|B|².

    Parameters
    ----------
    field : array_like, shape (..., 3)
        B in the axes of ``rate_error`` [T] (or normalised [-]); must not vanish.
    rate_error : array_like, shape (..., 3)
        w, angular-velocity error from the reference motion [rad/s] (units of ω0 [-]).
    gain : float or array_like
        k_w ≥ 0 [N·m·s] (κ_w [-] in the normalised model).

    Returns
    -------
    ndarray, shape (..., 3)
        m [A·m²]; its torque m × B = −k_w w⊥ (w⊥ the part of w across B), so the power
        w·T = −k_w |w⊥|² ≤ 0.

    Notes
    -----
    Rotor slides, slide "Control implementation" (seed lines 85–87): the model damping
    u = −k_w w (seed line 79) realised as a projection. Kovalenko (1975) eqs.
    (4.30)–(4.32), L = k (Δ × B)/B², with Δ = w. Deviation from source: the slides print
    M = −k_w (w × B) × B/|B|², whose torque (read as a torque) is +k_w w⊥ and pumps
    energy; see :func:`slides_printed_damping_torque`.
    """
    b = as_vectors("field", field)
    if np.any(np.sum(b * b, axis=-1) == 0):
        raise ValueError("field must not contain a zero vector (the projection divides by |B|²)")
    k = as_finite("gain", gain)
    if np.any(k < 0):
        raise ValueError(f"gain must be >= 0 N·m·s, got {shown(float(k[k < 0].ravel()[0]))}")
    return projected_dipole(b, as_vectors("rate_error", rate_error), k)


def slides_printed_damping_torque(field, rate_error, gain):
    r"""The damping as printed on the slides, read as a torque: −k_w (w × B) × B/|B|².

    Parameters
    ----------
    field : array_like, shape (..., 3)
        B [T]; must not vanish.
    rate_error : array_like, shape (..., 3)
        w [rad/s].
    gain : float or array_like
        k_w ≥ 0 [N·m·s].

    Returns
    -------
    ndarray, shape (..., 3)
        +k_w w⊥ [N·m]: the opposite of the damping torque, it raises the kinetic energy.

    Notes
    -----
    Rotor slides, slide "Control implementation" (seed line 86), as printed: this function
    reproduces the slides' slip on purpose, for the errata (the entry
    ``rotor-damping-sign``); no controller uses it (the printed sign anti-damps; read as a dipole it is k_w w⊥, whose torque is
    perpendicular to w and does no work). Since (w × B) × B = −|B|² w⊥, this equals −(m × B) of
    :func:`projected_damping_dipole`.
    """
    b = as_vectors("field", field)
    if np.any(np.sum(b * b, axis=-1) == 0):
        raise ValueError("field must not contain a zero vector (the projection divides by |B|²)")
    k = as_finite("gain", gain)
    if np.any(k < 0):
        raise ValueError(f"gain must be >= 0 N·m·s, got {shown(float(k[k < 0].ravel()[0]))}")
    w = as_vectors("rate_error", rate_error)
    return -np.cross(projected_dipole(b, w, k), b)


def rotor_reference_momentum(spin_axis_momentum, orbit_normal, transverse_inertia, orbital_rate):
    r"""The angular momentum of the reference motion, body axes.

    Parameters
    ----------
    spin_axis_momentum : float or array_like
        H0 cos²u, the reference axial momentum [N·m·s].
    orbit_normal : array_like, shape (..., 3)
        Unit orbit normal o2 = C e2 in body axes [-].
    transverse_inertia : float
        B = (I22 + I33)/2 [kg·m²].
    orbital_rate : float
        ω0 [rad/s].

    Returns
    -------
    ndarray, shape (..., 3)
        K_ref = H0 cos²u e1 + B ω0 o2 [N·m·s].

    Notes
    -----
    Kovalenko (1975) eqs. (7.3)–(7.5), p. 154: the required momentum K_з of a spinning
    spacecraft; here the reference of the rotor slides (seed lines 75–77) turning once per
    orbit (``rotor_spin.md`` §9).
    """
    o2 = as_vectors("orbit_normal", orbit_normal)
    h = as_finite("spin_axis_momentum", spin_axis_momentum)
    b = float(as_positive("transverse_inertia", transverse_inertia, unit="kg·m²"))
    w0 = float(as_positive("orbital_rate", orbital_rate, unit="rad/s"))
    return h[..., None] * np.array([1.0, 0.0, 0.0]) + b * w0 * o2


def momentum_damping_dipole(field, momentum_error, gain, transverse_inertia):
    r"""Damping of the momentum error: m = k_w ((K − K_ref)/B × B_field)/|B_field|².

    Parameters
    ----------
    field : array_like, shape (..., 3)
        Field in body axes [T]; must not vanish.
    momentum_error : array_like, shape (..., 3)
        K − K_ref, body axes [N·m·s] (K = Iω + J_f ν e1, K_ref from
        :func:`rotor_reference_momentum`).
    gain : float or array_like
        k_w ≥ 0 [N·m·s], the same gain as the rate form.
    transverse_inertia : float
        B, which turns the momentum error into a rate [kg·m²].

    Returns
    -------
    ndarray, shape (..., 3)
        m [A·m²], torque −k_w (ΔK/B)⊥.

    Notes
    -----
    Kovalenko (1975) eqs. (4.30)–(4.32), p. 83, and (7.3)–(7.5), p. 154: L = k (Δ_K × B)/B².
    Not in the rotor slides, which damp the rate error (seed lines 85–87); with products of
    inertia the momentum form keeps the axis where the rate form loses it
    (``rotor_spin.md`` §9).
    """
    b = float(as_positive("transverse_inertia", transverse_inertia, unit="kg·m²"))
    return projected_damping_dipole(field, as_vectors("momentum_error", momentum_error) / b, gain)


def relay_spin_dipole(field, moment, spin_error):
    r"""Kovalenko's relay spin law: the full dipole across the spin axis, switched by the field's signs.

    Parameters
    ----------
    field : array_like, shape (..., 3)
        B in body axes, axis 3 the spin axis [T].
    moment : float or array_like
        L0 > 0, the coils' dipole [A·m²].
    spin_error : float or array_like
        Δω = ω3 − ω3,required, the spin error; only its sign is used [rad/s].

    Returns
    -------
    ndarray, shape (..., 3)
        L = (−L0 sign Δω sign B_y, L0 sign Δω sign B_x, 0) [A·m²]; its spin-axis torque
        (L × B)_z = −L0 sign Δω (|B_x| + |B_y|) drives Δω toward zero (spin about +z),
        (4/π) L0 B⊥ on average over a turn of the transverse field (his (7.26)). Δω = 0
        gives L = 0 (nothing to correct).

    Notes
    -----
    Kovalenko (1975) §7.3, eq. (7.12), the spin correction of spin-stabilised satellites
    (Tiros, ESSA); its mean moment (7.26) and the spin-axis turn (7.27)–(7.30) are the
    chapter's checks. Unchecked kernel :func:`magbench.control.kernels.relay_dipole`.

    Examples
    --------
    >>> (relay_spin_dipole([1.0, 1.0, 0.5], 2.0, 0.1) + 0.0).tolist()   # + 0.0: no −0.0
    [-2.0, 2.0, 0.0]
    """
    b = as_vectors("field", field)
    m0 = as_positive("moment", moment, unit="A·m²")
    direction = np.sign(as_finite("spin_error", spin_error))
    return relay_dipole(b, m0, direction)
