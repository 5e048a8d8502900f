r"""The final regime of a passive run: where the magnet's axis settles about the field.

TNS-0 preprint §4 (L554–L580): captured, the axis turns on a cone about B whose angle
:func:`magbench.dynamics.conical_rotation_angle` gives from the mean field. These read a run of
:func:`magbench.sim.simulate_passive` over its last orbits.
"""

import numpy as np

from .._validate import as_count, as_finite, as_positive
from ..dynamics.axisymmetric import conical_rotation_angle
from ..earth.circular_orbit import CircularOrbit
from .passive import PassiveSatellite
from .result import PassiveRun

__all__ = ["orbit_mean_field", "passive_final_regime", "passive_transition_times"]


def orbit_mean_field(orbit, *, samples=720):
    r"""|B| averaged over one orbit: the field a slow conical rotation about B sees on average.

    Parameters
    ----------
    orbit : CircularOrbit
        Orbit and field [-].
    samples : int, optional
        Equally spaced times over one period (the end point, the start again, left out), >= 1 [-].

    Returns
    -------
    float
        Mean |B| [T].

    Notes
    -----
    Not in the sources: the mean that :func:`magbench.dynamics.conical_rotation_angle` takes for
    the final regime of the TNS-0 preprint §4 (L554–L580).
    """
    if not isinstance(orbit, CircularOrbit):
        raise ValueError(f"orbit must be a magbench.earth.CircularOrbit, got {type(orbit).__name__}")
    samples = as_count("samples", samples)
    sweep = np.linspace(0.0, orbit.period, samples + 1)[:-1]
    return float(np.mean(np.linalg.norm(orbit.field(sweep), axis=-1)))


def passive_final_regime(run, satellite, orbit, *, orbits=3):
    r"""The final regime of a passive run: means over its last orbit, the trend of its last orbits,
    and the conical rotation about B that the final rate implies.

    Parameters
    ----------
    run : PassiveRun
        A run of :func:`simulate_passive` (its ``inputs`` name the sample interval) [-].
    satellite : PassiveSatellite
        The satellite of the run (magnet and inertia) [-].
    orbit : CircularOrbit
        The orbit of the run [-].
    orbits : int, optional
        Last orbits whose means of the angle between B and the axis are returned, >= 2, at most
        the run's whole orbits [-].

    Returns
    -------
    dict
        ``orbit_samples`` (samples per orbit, at least 2) [-]; per member (or scalars for one):
        ``final_angle`` (angle between B and the symmetry axis, mean over the last orbit) [rad],
        ``final_rate`` (|ω|, likewise) [rad/s], ``final_momentum`` (|L|, likewise) [kg·m²/s],
        ``orbit_means`` (the angle's means over each of the last ``orbits`` orbits, on the last
        axis) [rad], ``drift`` (slope of the least-squares line through them) [rad/s],
        ``conical_angle`` (Ω²(A − C) cos θ′ = mB at the final rate and the orbit-mean |B|; NaN
        without a solution) [rad]; and ``mean_field`` (:func:`orbit_mean_field`) [T].

    Notes
    -----
    Not in the sources: what the TNS-0 preprint's Table 2 (one orbit of flight data fitted,
    §4, L554–L580) reports, taken from a simulated run; the drift tells whether the run has
    settled (a regime still changing at the stop gives a value that depends on the stop).
    """
    if not isinstance(run, PassiveRun):
        raise ValueError(f"run must be a magbench.sim.PassiveRun, got {type(run).__name__}")
    if not isinstance(satellite, PassiveSatellite):
        raise ValueError(f"satellite must be a magbench.sim.PassiveSatellite, got {type(satellite).__name__}")
    mean_field = orbit_mean_field(orbit)
    last = max(2, int(np.ceil(orbit.period / run.inputs["sample_interval"])))
    orbits = as_count("orbits", orbits, minimum=2)
    if orbits * last > run.time.size:
        raise ValueError(f"orbits must be at most the run's whole orbits ({run.time.size // last}), got {orbits}")
    angle = run.axis_field_angle
    final_rate = run.rate[..., -last:].mean(axis=-1)
    means = angle[..., -orbits * last:].reshape(angle.shape[:-1] + (orbits, last)).mean(axis=-1)
    # the trend at the stop: a line through the orbit means, one per member
    drift = np.polyfit(np.arange(orbits) * (run.time[-1] - run.time[-1 - last]), np.moveaxis(means, -1, 0), 1)[0]
    return {"orbit_samples": last, "final_angle": angle[..., -last:].mean(axis=-1), "final_rate": final_rate,
            "final_momentum": run.angular_momentum[..., -last:].mean(axis=-1), "orbit_means": means,
            "drift": drift, "mean_field": mean_field,
            "conical_angle": conical_rotation_angle(final_rate, mean_field, satellite.magnet_moment,
                                                    satellite.transverse_inertia, satellite.axial_inertia)}


def passive_transition_times(run, final_momentum, *, flat_tolerance=np.radians(1.0), capture_ratio=2.0):
    r"""When a passive run reaches the flat spin and when it is captured about B.

    Parameters
    ----------
    run : PassiveRun
        A run of :func:`simulate_passive` [-].
    final_momentum : float or array_like
        |L| of the final regime, per member (:func:`passive_final_regime`'s ``final_momentum``)
        [kg·m²/s].
    flat_tolerance : float, optional
        How close to π/2 the nutation counts as the flat spin, > 0 [rad].
    capture_ratio : float, optional
        The run counts as captured once |L| falls to this multiple of ``final_momentum``, > 0 [-].

    Returns
    -------
    relaxed_time : float or ndarray
        First sample time with |θ − π/2| < ``flat_tolerance`` (NaN if never) [s].
    capture_time : float or ndarray
        First sample time with |L| ≤ ``capture_ratio`` × ``final_momentum`` (NaN if never) [s].

    Notes
    -----
    TNS-0 preprint Table 1 (sessions 2–7 at θ = π/2, the flat spin that energy dissipation
    drives a prolate body to) and §4 (L554–L580, the capture into rotation about B), read off
    a simulated run.
    """
    if not isinstance(run, PassiveRun):
        raise ValueError(f"run must be a magbench.sim.PassiveRun, got {type(run).__name__}")
    tolerance = float(as_positive("flat_tolerance", flat_tolerance, unit="rad"))
    ratio = float(as_positive("capture_ratio", capture_ratio))
    final = as_finite("final_momentum", final_momentum)

    def first(mask):
        found = np.take(run.time, np.argmax(mask, axis=-1))
        return np.where(np.any(mask, axis=-1), found, np.nan)[()]

    relaxed = first(np.abs(run.nutation - np.pi / 2) < tolerance)
    return relaxed, first(run.angular_momentum <= ratio * final[..., None])
