r"""B-dot detumbling: the coil dipole from the rate of change of the field in body axes.

SamSat-218D §"Rate damping" (seed lines 225–251: M = −kḢ and the choice of k) and
Kovalenko (1975) eqs. (6.7) and (6.13) (the projected and the per-axis law). Laws are pure
functions of the measured (or modelled) field; per-axis saturation is part of the law.
SI: T, T/s, A·m².
"""

import numpy as np

from .._validate import as_finite, as_in_range, as_positive, as_positive_or_infinite, as_vectors
from . import kernels
from .field_stabilisation import viscous_detumble_time

__all__ = ["bdot_dipole", "bdot_dipole_projected", "avanzini_giulietti_gain", "samsat_gain", "kovalenko_detumble_time",
           "held_bdot_rate_limit"]


def bdot_dipole(field_rate, gain, max_dipole=np.inf):
    r"""The B-dot law: a coil dipole opposing the rate of change of the body-axis field.

    Parameters
    ----------
    field_rate : array_like, shape (..., 3)
        Time derivative Ḃ of the field in body axes [T/s].
    gain : array_like
        Gain k > 0 [A·m²·s/T]; SamSat-218D's k_H (on Ḣ) is μ0·k [m³·s].
    max_dipole : array_like, optional
        Largest dipole of each coil, > 0 (``inf``: no limit); broadcasts per axis [A·m²].

    Returns
    -------
    ndarray, shape (..., 3)
        m_j = −sat(k Ḃ_j), each component clipped to ±``max_dipole`` [A·m²].

    Notes
    -----
    SamSat-218D §"Rate damping" (seed lines 225–229): M = −kḢ; Kovalenko (1975) eq. (6.13):
    the same law per axis for three orthogonal coils. Per-axis saturation keeps the law
    dissipative (m·Ḃ ≤ 0); it is the saturation of Basilisk's ``MtbEffector`` and of most
    flight codes, not a scaling of the whole vector.

    Examples
    --------
    >>> bdot_dipole([1e-6, -1e-7, 0.0], 1e4, 0.2).tolist()
    [-0.01, 0.001, -0.0]
    >>> bdot_dipole([1e-3, 0.0, 0.0], 1e4, 0.2).tolist()
    [-0.2, -0.0, -0.0]
    """
    rate = as_vectors("field_rate", field_rate)
    k = as_positive("gain", gain, unit="A·m²·s/T")
    limit = as_positive_or_infinite("max_dipole", max_dipole, unit="A·m²")
    return kernels.bdot_dipole(rate, np.asarray(k)[..., None] if k.ndim else k, limit)


def bdot_dipole_projected(field, field_rate, gain, max_dipole=np.inf):
    r"""The projected B-dot law: only the part of Ḃ due to the body's rotation, normalised by B².

    Parameters
    ----------
    field : array_like, shape (..., 3)
        Field B in body axes; must not be zero [T].
    field_rate : array_like, shape (..., 3)
        Time derivative Ḃ in body axes [T/s].
    gain : array_like
        Gain k > 0 [N·m·s].
    max_dipole : array_like, optional
        Largest dipole of each coil, > 0 (``inf``: no limit) [A·m²].

    Returns
    -------
    ndarray, shape (..., 3)
        m = −sat(k [Ḃ − b̂(b̂·Ḃ)] / |B|²) per axis [A·m²], i.e. −(k/|B|) db̂/dt.

    Notes
    -----
    Kovalenko (1975) eq. (6.7): L = −(k/B²)[Ḃ − B(B·Ḃ)/B²], preferred because a
    magnetometer cannot tell the body's rotation from a change of |B|; its torque is
    eq. (6.10), −(k/B²)(Ḃ × B). The same law as Avanzini & Giulietti (2012) (Not in the
    sources: JGCD 35(4), 1326) and Markley & Crassidis (2014) eq. (7.48).

    Examples
    --------
    >>> m = bdot_dipole_projected([0.0, 0.0, 2e-5], [1e-7, 0.0, 5e-7], 1e-5)
    >>> np.round(m, 12).tolist()   # the component along B is ignored
    [-0.0025, -0.0, -0.0]
    """
    b = as_vectors("field", field)
    rate = as_vectors("field_rate", field_rate)
    if np.any(np.linalg.norm(b, axis=-1) == 0):
        raise ValueError("field must not contain a zero vector (the law divides by |B|²)")
    k = as_positive("gain", gain, unit="N·m·s")
    limit = as_positive_or_infinite("max_dipole", max_dipole, unit="A·m²")
    return kernels.bdot_dipole_projected(b, rate, np.asarray(k)[..., None] if k.ndim else k, limit)


def avanzini_giulietti_gain(mean_motion, geomagnetic_inclination, min_inertia):
    r"""Avanzini and Giulietti's gain for the projected B-dot law.

    Parameters
    ----------
    mean_motion : array_like
        Orbital mean motion n [rad/s].
    geomagnetic_inclination : array_like
        Inclination ξm of the orbit to the geomagnetic equator, in [0, π] (the orbit
        inclination is the usual proxy) [rad].
    min_inertia : array_like
        Smallest principal moment of inertia J_min [kg·m²].

    Returns
    -------
    ndarray
        k* = 2 n (1 + sin ξm) J_min [N·m·s], for :func:`bdot_dipole_projected`.

    Notes
    -----
    Not in the sources: Avanzini & Giulietti (2012), "Magnetic detumbling of a rigid
    spacecraft", JGCD 35(4), 1326, DOI 10.2514/1.53074 — a quasi-minimum-time gain with
    saturation. For a prolate body the simulated optimum lies near J_max instead of J_min.

    Examples
    --------
    >>> round(float(avanzini_giulietti_gain(1.1e-3, np.pi / 2, 0.01)), 9)
    4.4e-05
    """
    n = as_positive("mean_motion", mean_motion, unit="rad/s")
    xi = as_in_range("geomagnetic_inclination", geomagnetic_inclination, 0.0, np.pi, unit="rad")
    j = as_positive("min_inertia", min_inertia, unit="kg·m²")
    return 2.0 * n * (1.0 + np.sin(xi)) * j


def kovalenko_detumble_time(inertia, gain, mean_square_field, initial_rate, final_rate):
    r"""Kovalenko's estimate of the B-dot detumbling time.

    Parameters
    ----------
    inertia : array_like
        Moment of inertia J about the axes being damped, > 0 [kg·m²].
    gain : array_like
        B-dot gain k, > 0 [A·m²·s/T].
    mean_square_field : array_like
        Time mean of |B|² along the orbit, > 0 [T²]
        (:func:`magbench.earth.mean_square_field`).
    initial_rate : array_like
        Rate at the start ω_н, > 0 [rad/s].
    final_rate : array_like
        Rate to reach ω_к, > 0 [rad/s].

    Returns
    -------
    ndarray
        t = (J/k_д) ln(ω_н/ω_к) [s], with the damping coefficient k_д = (2/3) k ⟨B²⟩.

    Notes
    -----
    Kovalenko (1975) eq. (6.50), :func:`magbench.control.viscous_detumble_time`. The 2/3 is the mean of sin² of the angle between ω and B
    over their relative directions (his averaging). It is unsaturated: a limited dipole
    lengthens the time (chapter 5 sets it beside the simulated envelope).

    Examples
    --------
    >>> round(float(kovalenko_detumble_time(0.04, 5e4, 1.2e-9, 0.1, 0.01)), 1)
    2302.6
    """
    j = as_positive("inertia", inertia, unit="kg·m²")
    k = as_positive("gain", gain, unit="A·m²·s/T")
    b2 = as_positive("mean_square_field", mean_square_field, unit="T²")
    w0 = as_positive("initial_rate", initial_rate, unit="rad/s")
    w1 = as_positive("final_rate", final_rate, unit="rad/s")
    return viscous_detumble_time(j, 2.0 / 3.0 * k * b2, w0, w1)


def samsat_gain(max_dipole, initial_rate, max_field):
    r"""SamSat-218D's gain: the initial rates command the coil's largest dipole.

    Parameters
    ----------
    max_dipole : array_like
        Largest coil dipole L_max [A·m²].
    initial_rate : array_like, shape (..., 3)
        Initial angular velocity ω₀ in body axes; not zero [rad/s].
    max_field : array_like
        Largest |B| on the orbit B_max [T].

    Returns
    -------
    ndarray
        k = L_max / (|ω₀| B_max) [A·m²·s/T], for :func:`bdot_dipole`.

    Notes
    -----
    SamSat-218D §"Rate damping" (seed lines 245–251, Fig. 1): "k corresponds to the
    largest dipole moment of the coil" and depends on the initial rates; the formula is our
    reading (|Ḃ| ≈ |ω| B at most), which makes Fig. 1 k ∝ 1/|ω₀|.

    Examples
    --------
    >>> w = np.radians([0.1, 10.0, 10.0])
    >>> round(float(samsat_gain(0.2, w, 47.9e-6)))
    16916
    """
    limit = as_positive("max_dipole", max_dipole, unit="A·m²")
    speed = np.linalg.norm(as_vectors("initial_rate", initial_rate), axis=-1)
    if np.any(speed == 0):
        raise ValueError("initial_rate must not be zero (the gain divides by |ω₀|) [rad/s]")
    b = as_positive("max_field", max_field, unit="T")
    return limit / (speed * b)


def held_bdot_rate_limit(on_time, off_time):
    r"""Largest body rate that a B-dot dipole held over a duty cycle still damps.

    Parameters
    ----------
    on_time : array_like
        Time the coils are on in each cycle [s].
    off_time : array_like
        Time the coils are off (the measurement window) in each cycle [s].

    Returns
    -------
    ndarray
        π / (on_time + off_time) [rad/s]: the cycle-averaged damping of a dipole from the
        field difference across the window vanishes at this |ω| and is negative above it.

    Notes
    -----
    SamSat-218D §"Rate damping" (seed line 259: 16 s on, 1 s off). Not in the sources: the
    average of the held dipole's damping, ∝ [sin(ω(T_on + T_off/2)) − sin(ω T_off/2)] /
    (ω(T_on + T_off)), derived in the chapter; compare the PROVES flight software's bound
    360°/Δt_actuation.

    Examples
    --------
    >>> round(float(np.degrees(held_bdot_rate_limit(16.0, 1.0))), 3)
    10.588
    """
    on = as_positive("on_time", on_time, unit="s")
    off = as_positive("off_time", off_time, unit="s")
    return np.pi / (on + off)
