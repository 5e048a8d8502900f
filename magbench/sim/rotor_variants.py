r"""Variants of the rotor spacecraft beyond the slides, and the pointing error per orbit of its runs.

The slides' model (:mod:`magbench.sim.spinning`, :mod:`magbench.sim.rotor_normalised`) changed
one assumption at a time (``shared/reference/rotor_spin.md`` §9, "robustness"): a transverse
asymmetry I22 ≠ I33, products of inertia (the rotor axis not principal), and a real field that is
a tilted dipole while the law's program field stays the direct one. For a symmetric body
(I22 = I33) the SI model reduces exactly to the five-state normalised model (``rotor_spin.md``
§4: the spin drops out of the transverse dynamics), which runs these variants without resolving
the fast spin.
"""

import math

import numpy as np

from .._validate import as_count, as_finite, as_in_range, as_positive, shown
from ..dynamics.gyrostat import airplane_231_matrix
from .rotor_normalised import simulate_rotor_normalised
from .spinning import RotorSatellite, rotor_dimensionless

__all__ = ["transverse_asymmetry", "transverse_inertia_with_asymmetry", "rotor_satellite_with_products",
           "reference_momentum_rate_offset", "normalised_pointing_error", "maxima_per_orbit",
           "pointing_error_orbit_maxima", "tilted_dipole_pointing_error", "symmetric_rotor_orbit_maxima"]


def transverse_asymmetry(transverse_inertia_2, transverse_inertia_3):
    r"""The transverse asymmetry of a rotor spacecraft.

    Parameters
    ----------
    transverse_inertia_2, transverse_inertia_3 : float
        I22 and I33, the principal moments across the rotor axis [kg·m²], > 0.

    Returns
    -------
    float
        ε = (I33 − I22)/(I33 + I22) [-], in (−1, 1).

    Notes
    -----
    Rotor slides, slide "Simulation (asymmetric spacecraft)" (lost; seed lines 94–96): the
    slides simulate "an asymmetric spacecraft" without saying how asymmetric; ε is the measure
    ``rotor_spin.md`` §14 sweeps.
    """
    i2 = float(as_positive("transverse_inertia_2", transverse_inertia_2, unit="kg·m²"))
    i3 = float(as_positive("transverse_inertia_3", transverse_inertia_3, unit="kg·m²"))
    return (i3 - i2) / (i3 + i2)


def transverse_inertia_with_asymmetry(transverse_inertia_2, transverse_inertia_3, asymmetry):
    r"""The transverse moments with a given asymmetry and the same mean B = (I22 + I33)/2.

    Parameters
    ----------
    transverse_inertia_2, transverse_inertia_3 : float
        I22 and I33 of the body [kg·m²], > 0; only their mean B is kept.
    asymmetry : float
        ε wanted [-], in (−1, 1) (both moments stay > 0).

    Returns
    -------
    tuple of float
        (B(1 − ε), B(1 + ε)) [kg·m²]: the new I22 and I33.

    Notes
    -----
    Rotor slides, slide "Simulation (asymmetric spacecraft)" (lost; seed lines 94–96), with
    ``rotor_spin.md`` §4: the dimensionless numbers use B only, so the gains and the momentum
    c1 ω0 B stay those of the original body.
    """
    i2 = float(as_positive("transverse_inertia_2", transverse_inertia_2, unit="kg·m²"))
    i3 = float(as_positive("transverse_inertia_3", transverse_inertia_3, unit="kg·m²"))
    eps = float(as_finite("asymmetry", asymmetry))
    if not -1.0 < eps < 1.0:
        raise ValueError(f"asymmetry must lie in (-1, 1) (I22, I33 > 0), got {shown(asymmetry)}")
    b = 0.5 * (i2 + i3)
    return b * (1.0 - eps), b * (1.0 + eps)


def rotor_satellite_with_products(satellite, product):
    r"""The satellite with the products of inertia I12 = I13 = ``product``: axis 1 no longer principal.

    Parameters
    ----------
    satellite : RotorSatellite
        The spacecraft, principal axes; its gains and momentum are kept [SI].
    product : float
        I12 = I13 [kg·m²]; the tensor must stay positive definite.

    Returns
    -------
    RotorSatellite
        The same spacecraft with the (3, 3) inertia tensor [SI].

    Notes
    -----
    Kovalenko (1975) eq. (7.5), p. 154: the required momentum of a spinning body with its
    spin axis off a principal axis, the case where the slides' rate-error damping and
    Kovalenko's momentum-error damping ((4.30)–(4.32)) differ (``rotor_spin.md`` §9).
    """
    from dataclasses import replace

    if not isinstance(satellite, RotorSatellite):
        raise ValueError(f"satellite must be a RotorSatellite, got {type(satellite).__name__}")
    j = satellite.inertia_matrix.copy()
    j[0, 1] = j[1, 0] = j[0, 2] = j[2, 0] = float(as_finite("product", product))
    return replace(satellite, inertia=j)


def reference_momentum_rate_offset(satellite, orbit, initial_angles):
    r"""The rate error that gives a start turned by (α0, β0, γ0) the reference's angular momentum.

    Parameters
    ----------
    satellite : RotorSatellite
        Spacecraft (any inertia tensor) and its momentum H0 [SI].
    orbit : CircularOrbit
        Gives ω0 and the start's u0 [SI].
    initial_angles : array_like, shape (3,)
        (α0, β0, γ0) of the start [rad].

    Returns
    -------
    ndarray, shape (3,)
        Δω to add to :func:`magbench.sim.simulate_rotor`'s start ω0 C0 e2 + s_ref(u0) e1 so that
        I ω + J_f ν e1 = H0 cos²u0 e1 + B ω0 C0 e2, body axes [rad/s]; zero from the reference
        itself (no turn) for a body with I22 = I33 on principal axes.

    Notes
    -----
    Kovalenko (1975) eqs. (7.3)–(7.5), p. 154: the required momentum (as
    :func:`magbench.control.rotor_reference_momentum`). With products of inertia the rate
    ω0 o2 + s e1 would carry a transverse momentum s I12, several times H0, and the body would
    cone at once (``rotor_spin.md`` §9).
    """
    if not isinstance(satellite, RotorSatellite):
        raise ValueError(f"satellite must be a RotorSatellite, got {type(satellite).__name__}")
    angles = as_finite("initial_angles", initial_angles)
    if angles.shape != (3,):
        raise ValueError(f"initial_angles must have shape (3,) (α, β, γ) [rad], got shape {angles.shape}")
    w0 = orbit.mean_motion
    j = satellite.inertia_matrix
    c0 = airplane_231_matrix(*angles)
    e1 = np.array([1.0, 0.0, 0.0])
    h = satellite.axial_momentum * math.cos(float(orbit.argument_of_latitude0)) ** 2
    hr = satellite.rotor_inertia * satellite.rotor_rate
    needed = np.linalg.solve(j, h * e1 + satellite.transverse_inertia * w0 * c0[:, 1] - hr * e1)
    return needed - (w0 * c0[:, 1] + (h - hr) / j[0, 0] * e1)


def normalised_pointing_error(alpha, beta):
    r"""Angle between the rotor axis and the velocity from the normalised model's angles.

    Parameters
    ----------
    alpha, beta : array_like
        α and β of the semi-body axes from the orbital frame [rad].

    Returns
    -------
    ndarray
        arccos C11 = arccos(cos α cos β) [rad].

    Notes
    -----
    Rotor slides, slide "Equations of motion" (seed lines 29–38): the 2-3-1 airplane angles,
    whose C11 = cos α cos β; the spin angle γ does not enter (``rotor_spin.md`` §4).
    """
    a, b = as_finite("alpha", alpha), as_finite("beta", beta)
    return np.arccos(np.clip(np.cos(a) * np.cos(b), -1.0, 1.0))


def maxima_per_orbit(time_orbits, values, orbits=None):
    r"""Largest value in each whole orbit k ≤ t < k + 1.

    Parameters
    ----------
    time_orbits : array_like, shape (n,)
        Sample times in orbits, increasing from 0 [-].
    values : array_like, shape (n,)
        The samples [any unit].
    orbits : int, optional
        Number of orbits; by default the run's length rounded (one partial orbit for a run
        shorter than an orbit) [-].

    Returns
    -------
    ndarray, shape (orbits,)
        The maxima [unit of ``values``].

    Notes
    -----
    Not in the sources: how chapter 6 reads a transient against the rotor slides' "accuracy
    10–15°" (slide "Conclusion"); a sample a rounding below a whole orbit counts to the next.
    """
    t, v = as_finite("time_orbits", time_orbits), np.asarray(values)
    if t.ndim != 1 or v.shape != t.shape:
        raise ValueError(f"time_orbits and values must be 1-D of one length, got shapes {t.shape} and {v.shape}")
    index = np.floor(t * (1.0 + 1e-12)).astype(int)
    n = max(1, int(round(t[-1]))) if orbits is None else as_count("orbits", orbits)
    return np.array([v[index == k].max() for k in range(n)])


def pointing_error_orbit_maxima(run, orbital_rate):
    r"""Largest pointing error of a rotor run in each whole orbit (orbit k: k T ≤ t < (k + 1) T).

    Parameters
    ----------
    run : RotorRun
        A run of :func:`magbench.sim.simulate_rotor` [SI].
    orbital_rate : float
        ω0 [rad/s], > 0.

    Returns
    -------
    ndarray
        The maxima [rad]; one per orbit of the run's length rounded (at least one).

    Notes
    -----
    Rotor slides, slide "Conclusion" (seed lines 98–102): the pointing accuracy is read per
    orbit; :func:`maxima_per_orbit` of the run's pointing error.
    """
    period = 2.0 * math.pi / float(as_positive("orbital_rate", orbital_rate, unit="rad/s"))
    return maxima_per_orbit(run.time / period, run.pointing_error)


def tilted_dipole_pointing_error(satellite, orbit, real_dipole_tilt, orbits, *, steps_per_orbit=1000):
    r"""Pointing error from the reference when the real dipole is tilted and the program one is not.

    Parameters
    ----------
    satellite : RotorSatellite
        Spacecraft and gains; the normalised model takes B = (I22 + I33)/2, exact for
        I22 = I33 (for an asymmetric body the reference is no exact solution) [SI].
    orbit : CircularOrbit
        Orbit and the direct dipole of the program field; its node and dipole longitude
        set the tilted dipole's Λ (a non-rotating Earth) [SI].
    real_dipole_tilt : float
        δ of the real dipole, in [0, π] [rad].
    orbits : int
        Orbits simulated [-].
    steps_per_orbit : int, optional
        RK4 steps per orbit, also the samples [-].

    Returns
    -------
    time_orbits : ndarray
        τ/2π [-].
    pointing_error : ndarray
        arccos(cos α cos β) [rad] (:func:`normalised_pointing_error`).

    Notes
    -----
    Kovalenko (1975) eq. (2.36): the tilted dipole's field along the orbit, with Λ that of the SI
    model's real field (Λ = Ω − λ − π/2), in the five-state model of :func:`simulate_rotor_normalised`
    from the reference (α = β = 0, h = c1, Ω = (1, 0)): every error is the mismatch's
    (``rotor_spin.md`` §9).
    """
    n = rotor_dimensionless(satellite, orbit)
    phase = orbit.ascending_node - orbit.dipole_longitude - 0.5 * math.pi
    run = simulate_rotor_normalised(n["axial_ratio"], n["momentum"], n["restoring"], n["damping"], n["inclination"],
                                    [0.0, 0.0, n["momentum"], 1.0, 0.0], orbits, steps_per_orbit=steps_per_orbit,
                                    real_dipole_tilt=real_dipole_tilt, real_node_phase=phase)
    return run.time / (2.0 * math.pi), normalised_pointing_error(run.states[0], run.states[1])


def symmetric_rotor_orbit_maxima(satellite, orbit, initial_alpha, initial_beta, orbits, *, steps_per_orbit=1000):
    r"""Largest pointing error per orbit of a symmetric rotor spacecraft from an SI start, by the normalised model.

    Parameters
    ----------
    satellite : RotorSatellite
        Spacecraft with I22 = I33 and its gains [SI].
    orbit : CircularOrbit
        Orbit and field, direct dipole [SI].
    initial_alpha, initial_beta : float
        α0 and β0 of the start (γ0 drops out), |β0| < π/2 [rad].
    orbits : int
        Orbits simulated [-].
    steps_per_orbit : int, optional
        RK4 steps per orbit [-]; orbit k holds samples k·steps … (k + 1)·steps − 1.

    Returns
    -------
    ndarray, shape (orbits,)
        The maxima [rad].

    Notes
    -----
    Rotor slides, slide "Simulation (asymmetric spacecraft)" (lost; seed lines 94–96), its
    symmetric member in the normalised form of ``rotor_spin.md`` §4: the SI start
    ω = ω0 C0 e2 + s_ref(0) e1 of :func:`magbench.sim.simulate_rotor` is h = c1 + a sin β0
    (H = A ω1 + J_f ν), Ω2 = cos β0, Ω3 = 0. No fast spin in it: 500 and 4000 steps per orbit
    give maxima equal to 1e-5°.
    """
    alpha0, beta0 = float(as_finite("initial_alpha", initial_alpha)), float(as_finite("initial_beta", initial_beta))
    if abs(beta0) >= 0.5 * math.pi:
        raise ValueError(f"initial_beta must lie in (−π/2, π/2) rad, got {shown(initial_beta)}")
    n_orbits, steps = as_count("orbits", orbits), as_count("steps_per_orbit", steps_per_orbit)
    n = rotor_dimensionless(satellite, orbit)
    x0 = [alpha0, beta0, n["momentum"] + n["axial_ratio"] * math.sin(beta0), math.cos(beta0), 0.0]
    run = simulate_rotor_normalised(n["axial_ratio"], n["momentum"], n["restoring"], n["damping"], n["inclination"],
                                    x0, n_orbits, steps_per_orbit=steps)
    error = normalised_pointing_error(run.states[0], run.states[1])
    return np.array([error[k * steps:(k + 1) * steps].max() for k in range(n_orbits)])
