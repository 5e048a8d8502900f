r"""Stabilisation along the geomagnetic field: Kovalenko's orienting law and his §6.5 design
estimates (detumbling and transient times, the forced pitch response on a magnetopolar orbit,
the elastic damper's transfer function, the steady-state error).

Kovalenko (1975) §6.2, eqs. (6.8)–(6.14) (seed lines 127–129) and §6.5, eqs. (6.45)–(6.79)
(seed lines 139–150). SI, rad; the orbit quantities come from :mod:`magbench.earth.polar_orbit`.
"""

import numpy as np
from scipy.optimize import minimize_scalar

from .._docstrings import fill_docstring
from .._validate import as_count, as_finite, as_nonnegative, as_positive, as_vectors
from ..earth.polar_orbit import (polar_field_b, polar_field_direction_acceleration, polar_fourier_coefficients,
                                 polar_gravity_factor)
from . import kernels

__all__ = ["orienting_dipole", "orienting_torque", "orienting_dipole_per_axis", "pointing_dipole", "pointing_torque",
           "viscous_detumble_time", "dry_detumble_time", "dry_friction_torque", "capture_momentum", "dry_transient_time",
           "polar_forcing_coefficients", "polar_forced_response", "polar_disturbance_ratio", "elastic_damper_response",
           "polar_error_factor", "polar_disturbance_peak", "steady_state_error_estimate", "steady_state_error_closed_form"]

#: Parameters described once for the functions that share them (:func:`magbench._docstrings.fill_docstring`).
_STABILISATION_PARAMETERS = {
    "field": """field : array_like, shape (..., 3)
    B in body axes, not zero [T].""",
    "field_b": """field_b : array_like
    B > 0 [T].""",
    "inertia": """inertia : array_like
    J > 0 [kg·m²].""",
    "initial_rate": """initial_rate : array_like
    ω_н > 0 [rad/s].""",
    "mean_motion": """mean_motion : array_like
    ω0 > 0 [rad/s].""",
    "moment": """moment : array_like
    L ≥ 0 [A·m²].""",
    "equatorial_b": """equatorial_b : float
    B0 > 0, the field over the magnetic equator [T].""",
    "inertia_difference": """inertia_difference : float, optional
    ΔJ [kg·m²]; 0 leaves out the gravity torque.""",
    "friction": """friction : float, optional
    M_T ≥ 0, the dry friction of a damper whose magnet rests against the field [N·m].""",
}
_document_stabilisation = fill_docstring(_STABILISATION_PARAMETERS)

#: Kovalenko's printed forcing coefficients of (6.62): A_k = ω0² (a_k + g_k ΔJ/J).
PRINTED_FORCING = ((1.36, 1.32), (1.2, 0.4), (0.0, 0.13))


def _unit_axis(axis):
    return _unit_vector("axis", axis)


def _unit_vector(name, value):
    v = as_vectors(name, value)
    norm = np.linalg.norm(v, axis=-1, keepdims=True)
    if np.any(norm == 0):
        raise ValueError(f"{name} must not contain a zero vector")
    return v / norm


def _nonzero_field(field):
    b = as_vectors("field", field)
    if np.any(np.sum(b * b, axis=-1) == 0):
        raise ValueError("field must not contain a zero vector (the law divides by B²)")
    return b


@_document_stabilisation
def orienting_dipole(field, axis, gain):
    r"""Kovalenko's orienting dipole: turn the body axis i0 toward B with a torque k0 θ.

    Parameters
    ----------
    {field}
    axis : array_like, shape (..., 3)
        i0, the body's orientation axis; normalised here [-].
    gain : array_like
        k0 > 0 [N·m/rad]; broadcasts over the leading axes.

    Returns
    -------
    ndarray, shape (..., 3)
        L0 = k̃0 [i0 B² − B(B·i0)]/B² [A·m²], k̃0 = k0 θ/|B × i0| [A·m²/T], θ the angle
        between i0 and B; |L0| = k0 θ/B, perpendicular to B.

    Notes
    -----
    Kovalenko (1975) eqs. (6.8)–(6.9) (seed line 127), from the error (6.1)
    Δ = k0 θ ϑ, ϑ = B × i0/|B × i0| (6.5). At θ → 0, k̃0 → k0/B (the limit the book
    states); at θ = π the direction is undefined and the bracket, hence L0, is zero.

    Examples
    --------
    >>> np.round(orienting_dipole([0.0, 2e-5, 0.0], [1.0, 0.0, 0.0], 1e-3), 6).tolist()
    [78.539816, 0.0, 0.0]
    """
    k = as_positive("gain", gain, unit="N·m/rad")
    return kernels.orienting_dipole(_nonzero_field(field), _unit_axis(axis), k)


@_document_stabilisation
def orienting_torque(field, axis, gain):
    r"""Torque of Kovalenko's orienting dipole.

    Parameters
    ----------
    {field}
    axis : array_like, shape (..., 3)
        i0; normalised here [-].
    gain : array_like
        k0 > 0 [N·m/rad].

    Returns
    -------
    ndarray, shape (..., 3)
        M0 = L0 × B = k̃0 (i0 × B) [N·m], of magnitude k0 θ, turning i0 toward B.

    Notes
    -----
    Kovalenko (1975) eq. (6.11) (seed line 128).
    """
    b = _nonzero_field(field)
    k = as_positive("gain", gain, unit="N·m/rad")
    return np.cross(kernels.orienting_dipole(b, _unit_axis(axis), k), b)


@_document_stabilisation
def pointing_dipole(field, axis, direction, gain):
    r"""Kovalenko's orienting dipole toward an arbitrary direction p measured by another sensor.

    Parameters
    ----------
    {field}
    axis : array_like, shape (..., 3)
        i0, the body's orientation axis; normalised here [-].
    direction : array_like, shape (..., 3)
        p, the direction the axis should point along (a Sun sensor's, a star tracker's, the
        local vertical's), body axes; normalised here [-].
    gain : array_like
        k_p > 0 [N·m/rad].

    Returns
    -------
    ndarray, shape (..., 3)
        L_p = k̃_p [i0 (B·p) − p (B·i0)]/B² [A·m²], k̃_p = k_p ψ/|p × i0|, ψ the angle
        between i0 and p: the dipole (Δ_p × B)/B² of the wanted torque
        Δ_p = k_p ψ (p × i0)/|p × i0|, whose part across B is all a magnetic torque can make.

    Notes
    -----
    Kovalenko (1975) eqs. (6.15)–(6.17) (seed lines 129–130), "p here replaces B in (6.8)":
    with p = B/B it is :func:`orienting_dipole`. Deviation from source: (6.16)'s bracket is
    garbled in the OCR; it is reconstructed from the error (6.15) put into (4.30) as the text
    says, and it has the property the book states: the torque never increases the error
    (M_p · (i0 × p) ≥ 0, tested). At ψ = π the direction is undefined and L_p is zero.

    Examples
    --------
    >>> np.round(pointing_dipole([0.0, 0.0, 2e-5], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], 1e-3), 6).tolist()
    [0.0, 0.0, 0.0]
    """
    k = as_positive("gain", gain, unit="N·m/rad")
    return kernels.pointing_dipole(_nonzero_field(field), _unit_axis(axis), _unit_vector("direction", direction), k)


@_document_stabilisation
def pointing_torque(field, axis, direction, gain):
    r"""Torque of :func:`pointing_dipole`.

    Parameters
    ----------
    {field}
    axis, direction : array_like, shape (..., 3)
        i0 and p; normalised here [-].
    gain : array_like
        k_p > 0 [N·m/rad].

    Returns
    -------
    ndarray, shape (..., 3)
        M_p = L_p × B = k̃_p [(i0 × B)(B·p) − (p × B)(B·i0)]/B² [N·m].

    Notes
    -----
    Kovalenko (1975) eq. (6.17) (seed line 130), reconstructed as :func:`pointing_dipole`.
    """
    b = _nonzero_field(field)
    k = as_positive("gain", gain, unit="N·m/rad")
    return np.cross(kernels.pointing_dipole(b, _unit_axis(axis), _unit_vector("direction", direction), k), b)


def orienting_dipole_per_axis(field, gains):
    r"""Kovalenko's per-axis orienting law for the orientation axis x.

    Parameters
    ----------
    field : array_like, shape (..., 3)
        B in body axes [T].
    gains : array_like, shape (3,) or (..., 3)
        k0x, k0y, k0z, ≥ 0 [A·m²/T²].

    Returns
    -------
    ndarray, shape (..., 3)
        L0 = (k0x (B_y² + B_z²), −k0y B_x B_y, −k0z B_x B_z) [A·m²]: with equal gains, B²
        times :func:`orienting_dipole`'s bracket for i0 = x.

    Notes
    -----
    Kovalenko (1975) eq. (6.14) (seed line 129), of which the OCR keeps only "k_0y B_x B_y".
    Deviation from source: reconstructed as the components of (6.8) for i0 = x with k̃0/B²
    folded into the per-axis gains (the reference's reconstruction).
    """
    return kernels.orienting_dipole_per_axis(as_vectors("field", field),
                                             as_nonnegative("gains", gains, unit="A·m²/T²"))


@_document_stabilisation
def viscous_detumble_time(inertia, viscous, initial_rate, final_rate):
    r"""Time for a viscous damper to slow the body from ω_н to ω_к.

    Parameters
    ----------
    {inertia}
    viscous : array_like
        k_д > 0, the damping coefficient [N·m·s].
    {initial_rate}
    final_rate : array_like
        ω_к > 0 [rad/s].

    Returns
    -------
    ndarray
        t_1в = (J/k_д) ln(ω_н/ω_к) [s].

    Notes
    -----
    Kovalenko (1975) eqs. (6.48), (6.50) (seed lines 140–141): J ω̇ + k_д ω = 0.
    :func:`magbench.control.kovalenko_detumble_time` is this with the B-dot law's
    k_д = (2/3) k ⟨B²⟩.
    """
    j = as_positive("inertia", inertia, unit="kg·m²")
    k = as_positive("viscous", viscous, unit="N·m·s")
    w0 = as_positive("initial_rate", initial_rate, unit="rad/s")
    w1 = as_positive("final_rate", final_rate, unit="rad/s")
    return j / k * np.log(w0 / w1)


@_document_stabilisation
def dry_detumble_time(inertia, friction, initial_rate, final_rate=0.0):
    r"""Time for a dry-friction damper to slow the body from ω_н to ω_к.

    Parameters
    ----------
    {inertia}
    friction : array_like
        M_T > 0, the friction torque [N·m].
    {initial_rate}
    final_rate : array_like, optional
        ω_к, in [0, ω_н] [rad/s].

    Returns
    -------
    ndarray
        t_1с = J (ω_н − ω_к)/M_T [s].

    Notes
    -----
    Kovalenko (1975) eq. (6.45) (seed line 140), with ω_к = 0; the book's comparison with
    (6.50) (seed line 141) takes ω_к = 0.001 ω_н.
    """
    j = as_positive("inertia", inertia, unit="kg·m²")
    m = as_positive("friction", friction, unit="N·m")
    w0 = as_positive("initial_rate", initial_rate, unit="rad/s")
    w1 = as_nonnegative("final_rate", final_rate, unit="rad/s")
    if np.any(w1 > w0):
        raise ValueError(f"final_rate must be <= initial_rate, got {np.max(w1)!r} > {np.min(w0)!r} rad/s")
    return j * (w0 - w1) / m


def dry_friction_torque(damper_moment, mean_b, angle):
    r"""Friction torque a dry damper's magnet can hold against the field.

    Parameters
    ----------
    damper_moment : array_like
        L_y ≥ 0 [A·m²].
    mean_b : array_like
        B_ср, the mean field on the orbit, > 0 [T].
    angle : array_like
        α, the angle between L_y and B_ср [rad].

    Returns
    -------
    ndarray
        M_T = L_y B_ср sin α [N·m].

    Notes
    -----
    Kovalenko (1975) eqs. (6.46)–(6.47) (seed line 140): the magnet holds to the field only
    while L_y ≥ M_T/B_ср (better M_T/B_min).
    """
    ly = as_nonnegative("damper_moment", damper_moment, unit="A·m²")
    b = as_positive("mean_b", mean_b, unit="T")
    a = as_finite("angle", angle)
    return ly * b * np.sin(a)


@_document_stabilisation
def capture_momentum(inertia, moment, field_b, capture_angle):
    r"""Angular momentum of a magnet-held body passing B after a capture at rest.

    Parameters
    ----------
    {inertia, moment, field_b}
    capture_angle : array_like
        γ0, the angle from B at capture (γ̇ = 0) [rad].

    Returns
    -------
    ndarray
        K_К = J γ̇ = √(2 L B J (1 − cos γ0)) [kg·m²/s].

    Notes
    -----
    Kovalenko (1975) eq. (6.53) (seed line 142): the pendulum's energy integral.
    """
    j = as_positive("inertia", inertia, unit="kg·m²")
    m = as_nonnegative("moment", moment, unit="A·m²")
    b = as_positive("field_b", field_b, unit="T")
    g0 = as_finite("capture_angle", capture_angle)
    return np.sqrt(2.0 * m * b * j * (1.0 - np.cos(g0)))


@_document_stabilisation
def dry_transient_time(inertia, moment, field_b, capture_angle, friction):
    r"""Duration of the transient with a dry-friction damper after capture by the field.

    Parameters
    ----------
    {inertia, moment, field_b}
    capture_angle : array_like
        γ0 [rad].
    friction : array_like
        M_T > 0 [N·m].

    Returns
    -------
    ndarray
        t_2с = √(2 L B J (1 − cos γ0))/M_T [s].

    Notes
    -----
    Kovalenko (1975) eq. (6.54) (seed line 143): the friction removes the momentum (6.53)
    at the rate M_T.
    """
    m_t = as_positive("friction", friction, unit="N·m")
    return capture_momentum(inertia, moment, field_b, capture_angle) / m_t


@_document_stabilisation
def polar_forcing_coefficients(inertia, inertia_difference, mean_motion, count=3, printed=False):
    r"""Amplitudes A_k of the harmonic forcing sin 2kω0t of the linearised pitch equation.

    Parameters
    ----------
    {inertia}
    inertia_difference : array_like
        ΔJ = J_transverse − J_axial [kg·m²].
    {mean_motion}
    count : int, optional
        Harmonics k = 1 … count (at most 3 when ``printed``) [-].
    printed : bool, optional
        Kovalenko's printed coefficients instead of the exact ones [-].

    Returns
    -------
    ndarray, shape (count,) + broadcast shape
        A_k [rad/s²]: exact, ω0² (1/3)^k (4k + 4 ΔJ/J) (from −η̈ and (3/2)(ΔJ/J) ω0² sin 2λ);
        printed, ω0² (1.36 + 1.32 ΔJ/J), ω0² (1.2 + 0.4 ΔJ/J), 0.13 ω0² ΔJ/J.

    Notes
    -----
    Kovalenko (1975) eq. (6.62) (seed line 144), from (6.39), (6.42) and (6.61) with the
    gravity term's dependence on γ dropped, as the book does. The exact series are
    :func:`magbench.earth.polar_fourier_coefficients`; the book's third harmonic has no
    kinematic term (exactly (4/9) ω0², as large as its gravity term 0.148 ω0² ΔJ/J).
    """
    j = as_positive("inertia", inertia, unit="kg·m²")
    dj = as_finite("inertia_difference", inertia_difference)
    n = as_positive("mean_motion", mean_motion, unit="rad/s")
    k = as_count("count", count)
    ratio = dj / j
    if printed:
        if k > 3:
            raise ValueError(f"count must be <= 3 with printed=True (the book prints three), got {k}")
        rows = [a + g * ratio for a, g in PRINTED_FORCING[:k]]
    else:
        _, acceleration, gravity = polar_fourier_coefficients(k)
        rows = [-a + 1.5 * g * ratio for a, g in zip(acceleration, gravity)]
    return n**2 * np.stack(np.broadcast_arrays(*rows))


@_document_stabilisation
def polar_forced_response(inertia, moment, field_b, viscous, mean_motion, inertia_difference=0.0, count=3,
                          printed=False):
    r"""Steady forced pitch oscillation of a magnet-held body with a viscous damper.

    Parameters
    ----------
    {inertia}
    moment : array_like
        L > 0 [A·m²].
    field_b : array_like
        B > 0, the field in ω_c² = LB/J (the book takes B0) [T].
    viscous : array_like
        k_д ≥ 0 [N·m·s].
    {mean_motion}
    inertia_difference : array_like, optional
        ΔJ [kg·m²].
    count : int, optional
        Harmonics k = 1 … count [-].
    printed : bool, optional
        Force with Kovalenko's printed coefficients [-].

    Returns
    -------
    amplitude, phase : ndarray, shape (count,) + broadcast shape
        γ_k [rad] and α_k in [0, π] [rad] of γ = Σ γ_k sin(2kω0t − α_k):
        γ_k = A_k/√((ω_c² − 4k²ω0²)² + 16k²b²ω0²), α_k = arg(ω_c² − 4k²ω0² + i 4kbω0).

    Notes
    -----
    Kovalenko (1975) eqs. (6.62)–(6.64) (seed lines 144–145, the third harmonic on 145):
    γ̈ + 2bγ̇ + ω_c²γ = Σ A_k sin 2kω0t,
    2b = k_д/J, ω_c² = LB/J. The book's arctg is taken as the two-argument arctangent, so
    that the phase passes π/2 at resonance instead of jumping.

    Examples
    --------
    >>> amp, _ = polar_forced_response(650.0, 500.0, 2.02e-5, 0.2, 1e-3, 400.0)
    >>> np.round(np.degrees(amp), 2).tolist()
    [10.68, 50.67, 1.49]
    """
    j = as_positive("inertia", inertia, unit="kg·m²")
    m = as_positive("moment", moment, unit="A·m²")
    b = as_positive("field_b", field_b, unit="T")
    kd = as_nonnegative("viscous", viscous, unit="N·m·s")
    n = as_positive("mean_motion", mean_motion, unit="rad/s")
    forcing = polar_forcing_coefficients(j, inertia_difference, n, count, printed)
    # every argument may carry the members' axes: the harmonics go first, the members after
    shape = np.broadcast_shapes(np.shape(m), np.shape(b), np.shape(kd), forcing.shape[1:])
    forcing = forcing.reshape(forcing.shape[:1] + (1,) * (len(shape) - forcing.ndim + 1) + forcing.shape[1:])
    k = np.arange(1, forcing.shape[0] + 1).reshape((-1,) + (1,) * len(shape))
    half_damping = kd / (2.0 * j)
    real = m * b / j - 4.0 * k**2 * n**2
    imag = 4.0 * k * half_damping * n
    return forcing / np.hypot(real, imag), np.arctan2(imag, real)


@_document_stabilisation
def elastic_damper_response(forcing, frequency, inertia, stiffness, viscous, damper_moment, field_b):
    r"""Forced response of a body whose orienting magnet is an elastically coupled viscous damper.

    Parameters
    ----------
    forcing : array_like
        A, the amplitude of the forcing (torque/J) [rad/s²].
    frequency : array_like
        ω of the forcing, 2kω0 for the k-th harmonic [rad/s].
    {inertia}
    stiffness : array_like
        c ≥ 0 [N·m/rad].
    viscous : array_like
        k_д > 0 [N·m·s].
    damper_moment : array_like
        L_y > 0, the damper's magnet [A·m²].
    {field_b}

    Returns
    -------
    amplitude, phase : ndarray
        γ^mod = A |W(iω)| [rad] and φ = arg W(iω) [rad], with

        .. math::
           W(p) = \frac{2\delta p + \omega_{yc}^2 + \omega_c^2}
           {(p^2 + 2\delta p + \omega_{yc}^2)(2\delta p + \omega_{yc}^2 + \omega_c^2) - (2\delta p + \omega_{yc}^2)^2},

        2δ = k_д/J, ω_yc² = c/J, ω_c² = L_y B/J.

    Notes
    -----
    Kovalenko (1975) eqs. (6.65)–(6.68) (seed lines 145–146), the linearised (6.43)–(6.44)
    with the body carrying no magnet of its own. The book's phase (6.68), numerator's arg
    minus denominator's, is arg W; it is taken here from the complex value (no branch of
    arctg to choose).
    """
    a = as_finite("forcing", forcing)
    w = as_nonnegative("frequency", frequency, unit="rad/s")
    j = as_positive("inertia", inertia, unit="kg·m²")
    c = as_nonnegative("stiffness", stiffness, unit="N·m/rad")
    kd = as_positive("viscous", viscous, unit="N·m·s")
    ly = as_positive("damper_moment", damper_moment, unit="A·m²")
    b = as_positive("field_b", field_b, unit="T")
    p = 1j * w
    coupling = kd / j * p + c / j
    numerator = coupling + ly * b / j
    transfer = numerator / ((p * p + coupling) * numerator - coupling**2)
    return a * np.abs(transfer), np.angle(transfer)


def _disturbance_ratio(u, inertia, inertia_difference, friction, mean_motion, equatorial_b):
    """[J|η̈| + (3/2)ω0²ΔJ sin 2λ − M_T]/B at u, from the Earth family's η̈, sin 2λ and |B|."""
    kinematic = -inertia * polar_field_direction_acceleration(u, mean_motion)
    gravity = 1.5 * mean_motion**2 * inertia_difference * polar_gravity_factor(u)
    return (kinematic + gravity - friction) / polar_field_b(u, equatorial_b)


@_document_stabilisation
def polar_disturbance_ratio(argument_of_latitude, inertia, mean_motion, equatorial_b, inertia_difference=0.0,
                            friction=0.0):
    r"""The disturbance a magnet must hold on a magnetopolar orbit, per unit field, along the orbit.

    Parameters
    ----------
    argument_of_latitude : array_like
        u from the magnetic equator [rad].
    {inertia : float}
    {mean_motion : float}
    {equatorial_b, inertia_difference, friction}

    Returns
    -------
    ndarray
        [J|η̈| + (3/2)ω0²ΔJ sin 2λ − M_T]/B(u) [A·m²] (= N·m/T); its largest value over the
        orbit is :func:`polar_disturbance_peak`.

    Notes
    -----
    Kovalenko (1975) eqs. (6.72)–(6.79) (seed lines 146–149).
    """
    u = as_finite("argument_of_latitude", argument_of_latitude)
    return _disturbance_ratio(u, as_positive("inertia", inertia, unit="kg·m²"),
                              as_finite("inertia_difference", inertia_difference),
                              as_nonnegative("friction", friction, unit="N·m"),
                              as_positive("mean_motion", mean_motion, unit="rad/s"),
                              as_positive("equatorial_b", equatorial_b, unit="T"))


def polar_error_factor(tolerance=1e-12):
    r"""Largest value of 6 sin 2u/(1 + 3 sin²u)^{5/2} and where it is reached.

    Parameters
    ----------
    tolerance : float, optional
        Absolute tolerance on u of the search, > 0 [rad].

    Returns
    -------
    factor : float
        1.9030 [-], the number Kovalenko prints as 1.92.
    argument_of_latitude : float
        u = 0.2775 rad = 15.90° [rad] (the book: ω0t ≈ 16°).

    Notes
    -----
    Kovalenko (1975) eqs. (6.73)–(6.74) (seed lines 146–147): J|η̈|/(LB) on a magnetopolar
    orbit is (ω0² J/(L B0)) 6 sin 2u/(1 + 3 sin²u)^{5/2}. Maximised with scipy's bounded
    Brent search on (0, π/2) (the function has one maximum there).
    """
    xatol = float(as_positive("tolerance", tolerance, unit="rad"))

    def minus(u):
        # |η̈|/(ω0² B/B0): the disturbance ratio of a unit body, orbit and field
        return -_disturbance_ratio(u, 1.0, 0.0, 0.0, 1.0, 1.0)

    best = minimize_scalar(minus, bounds=(0.0, np.pi / 2), method="bounded", options={"xatol": xatol})
    return float(-best.fun), float(best.x)


@_document_stabilisation
def polar_disturbance_peak(inertia, mean_motion, equatorial_b, inertia_difference=0.0, friction=0.0):
    r"""Largest (J|η̈| + M_в − M_T)/B over a magnetopolar orbit, and where it is reached.

    Parameters
    ----------
    {inertia : float}
    {mean_motion : float}
    {equatorial_b, inertia_difference, friction}

    Returns
    -------
    peak : float
        max over u of [J|η̈| + (3/2)ω0²ΔJ sin 2λ − M_T]/B(u) [A·m²] (= N·m/T).
    argument_of_latitude : float
        u at the maximum, in (0, π/2) [rad].

    Notes
    -----
    Kovalenko (1975) eqs. (6.72)–(6.79) (seed lines 146–149): on (0, π/2) −η̈ and the
    gravity torque with ΔJ > 0 have the same sign, so they add (the book writes
    (Jη̈ + M_в)/B). Maximised on a 20 001-point grid of u, refined by scipy's bounded
    Brent search around the best point (the function has one maximum there).
    """
    args = (as_positive("inertia", inertia, unit="kg·m²"), as_finite("inertia_difference", inertia_difference),
            as_nonnegative("friction", friction, unit="N·m"), as_positive("mean_motion", mean_motion, unit="rad/s"),
            as_positive("equatorial_b", equatorial_b, unit="T"))
    if any(np.ndim(a) for a in args):
        raise ValueError("polar_disturbance_peak takes scalars (one orbit and one body)")
    u = np.linspace(0.0, np.pi / 2, 20001)
    i = int(np.argmax(_disturbance_ratio(u, *args)))
    lo, hi = u[max(i - 1, 0)], u[min(i + 1, u.size - 1)]
    best = minimize_scalar(lambda x: -_disturbance_ratio(x, *args), bounds=(lo, hi), method="bounded",
                           options={"xatol": 1e-12})
    return float(-best.fun), float(best.x)


def steady_state_error_estimate(inertia, moment, mean_motion, equatorial_b, inertia_difference=0.0, friction=0.0):
    r"""Kovalenko's estimate of the largest steady-state angle from B on a magnetopolar orbit.

    Parameters
    ----------
    inertia : float
        J > 0 [kg·m²].
    moment : float
        L > 0, the magnet (L + L_y for (6.76)–(6.77), a damper magnet that turns with the
        body) [A·m²].
    mean_motion : float
        ω0 > 0 [rad/s].
    equatorial_b : float
        B0 > 0 [T].
    inertia_difference : float, optional
        ΔJ [kg·m²]: (6.75), (6.77), (6.79) when not 0.
    friction : float, optional
        M_T ≥ 0: (6.78)–(6.79) when not 0 [N·m].

    Returns
    -------
    float
        γ_max = arcsin(peak/L) [rad], peak from :func:`polar_disturbance_peak`.

    Raises
    ------
    ValueError
        When peak > L: the magnet cannot hold the body along B (no steady state).

    Notes
    -----
    Kovalenko (1975) eqs. (6.70)–(6.79) (seed lines 146–149): L B sin γ_max balances the
    largest disturbance. The book finds it good for ω_c > 4ω0 (seed line 149).
    """
    m = as_positive("moment", moment, unit="A·m²")
    peak, _ = polar_disturbance_peak(inertia, mean_motion, equatorial_b, inertia_difference, friction)
    if peak > m:
        raise ValueError(f"moment {float(m)!r} A·m² is below the largest disturbance {peak:.6g} A·m²: "
                         "the magnet cannot hold the body along B")
    return float(np.arcsin(max(peak, 0.0) / m))


@_document_stabilisation
def steady_state_error_closed_form(inertia, moment, mean_motion, equatorial_b):
    r"""Kovalenko's closed-form error bound arcsin(1.903 ω0² J/(L B0)).

    Parameters
    ----------
    {inertia}
    moment : array_like
        L > 0 [A·m²].
    {mean_motion}
    equatorial_b : array_like
        B0 > 0 [T].

    Returns
    -------
    ndarray
        γ_max [rad], with the factor of :func:`polar_error_factor` (the book prints 1.92).

    Notes
    -----
    Kovalenko (1975) eq. (6.74) (seed line 147). On a circular orbit ω0²/B0 =
    4π GM/(μ0 M_E) does not depend on the altitude, so neither does this bound.
    """
    j = as_positive("inertia", inertia, unit="kg·m²")
    m = as_positive("moment", moment, unit="A·m²")
    n = as_positive("mean_motion", mean_motion, unit="rad/s")
    b0 = as_positive("equatorial_b", equatorial_b, unit="T")
    ratio = polar_error_factor()[0] * n**2 * j / (m * b0)
    if np.any(ratio > 1):
        raise ValueError(f"moment is too small: 1.903 ω0² J/(L B0) = {np.max(ratio):.4g} > 1 (no steady state)")
    return np.arcsin(ratio)
