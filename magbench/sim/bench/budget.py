r"""An error budget of the bench: its final error band for per-member values of scalar
hardware error sources (:func:`nominal_source_values` names them), mapped onto the
:class:`~magbench.sim.bench.BenchErrors` of :func:`~magbench.sim.bench.simulate_bench`:

- :func:`source_error_bands` the final error band for any set of per-member values;
- :func:`one_at_a_time` each source across its range, the others nominal;
- :func:`from_unit_cube`, :func:`sobol_design`, :func:`sobol_analysis` and
  :func:`sobol_budget`: first-order and total Sobol indices (SALib, Saltelli's sample)
  and the distribution of the error band over the whole allowed space.

A source's range is any object with ``low``, ``high`` [SI] and ``scale`` ("linear" or
"log"); chapter 4 reads its ranges, and where each comes from, from its data
(:mod:`magbench.chapters.ch04_mockup.budget`).

Not in the thesis: the thesis names "disturbing torques, the thread's torsion or the
sensors' inaccuracy" (thesis §4.4) without sizing any of them.
"""

from dataclasses import replace

import numpy as np

from ..._validate import as_count, as_finite, as_positive, shown
from ...fields.systems import horizontal_field
from .config import BenchErrors, BenchSetup
from .loop import simulate_bench

__all__ = ["SAMPLE_INTERVALS", "nominal_source_values", "source_error_bands", "one_at_a_time", "from_unit_cube",
           "sobol_design", "sobol_analysis", "sobol_budget"]

#: Controller periods the budget runs [s]: draws of ``sample_interval`` are rounded to the
#: nearest (in log) so that members share a time grid and stay vectorised.
SAMPLE_INTERVALS = (0.01, 0.02)


def nominal_source_values(setup):
    """Each error source's value in the bench as designed: no error, the setup's choices.

    Parameters
    ----------
    setup : BenchSetup
        The bench as designed [-].

    Returns
    -------
    dict of str to float
        Every source :func:`source_error_bands` takes, at its no-error value [SI]. The
        release is at the target at rest; ``background_azimuth`` is π/2 (across the
        simulator's axis, where a background turns the field most), so that a
        one-at-a-time sweep of ``background_h`` shows its worst case.

    Notes
    -----
    Not in the thesis (thesis §4.4 names the sources without values).
    """
    if not isinstance(setup, BenchSetup):
        raise ValueError(f"setup must be a BenchSetup, got {type(setup).__name__}")
    return {"gyro_offset": 0.0, "gyro_drift": 0.0, "magnetometer_offset_x": 0.0, "magnetometer_offset_y": 0.0,
            "magnetometer_scale_difference": 0.0, "magnetometer_cross_axis": 0.0,
            "magnetometer_misalignment": 0.0, "background_h": 0.0, "background_azimuth": np.pi / 2,
            "heading_ripple": 0.0, "coil_misalignment_1": 0.0, "coil_misalignment_2": 0.0,
            "coil_field_coupling": 0.0, "thread_stiffness": setup.thread_stiffness,
            "thread_neutral_angle": 0.0, "filter_coefficient": setup.filter_coefficient,
            "sample_interval": setup.sample_interval, "pwm_levels": float(setup.pwm_levels),
            "moment_scale_1": 0.0, "moment_scale_2": 0.0, "release_angle": 0.0, "release_rate": 0.0}


def _member_values(setup, psi_des, values):
    """The targets and every source's values broadcast to one size: (target, values, size)."""
    vals = nominal_source_values(setup)
    unknown = sorted(set(values) - set(vals))
    if unknown:
        raise ValueError(f"values names unknown sources {unknown}; the sources are {', '.join(vals)}")
    vals.update(values)
    size = max([np.size(v) for v in vals.values()] + [np.size(psi_des)])
    for name, x in [("psi_des", psi_des)] + list(vals.items()):
        if np.size(x) not in (1, size):
            raise ValueError(f"{name} must hold one value or one per member ({size}), got {np.size(x)}")
        as_finite(name, x)
    target = np.broadcast_to(np.asarray(psi_des, float), (size,))
    return target, {k: np.broadcast_to(np.asarray(x, float), (size,)) for k, x in vals.items()}, size


def _member_errors(setup, v, idx, target, total, gamma, matrix, duration):
    """The :class:`BenchErrors` of members ``idx`` from their source values ``v`` [SI]."""
    return BenchErrors(
        moment_scale=np.stack([1 + v["moment_scale_1"][idx], 1 + v["moment_scale_2"][idx]], -1),
        thread_stiffness=v["thread_stiffness"][idx],
        gyro_offset=v["gyro_offset"][idx], gyro_drift=v["gyro_drift"][idx] / duration,
        magnetometer_offset=np.stack([v["magnetometer_offset_x"][idx], v["magnetometer_offset_y"][idx]], -1),
        magnetometer_matrix=matrix[idx], magnetometer_misalignment=v["magnetometer_misalignment"][idx],
        heading_ripple=v["heading_ripple"][idx],
        coil_misalignment=np.stack([v["coil_misalignment_1"][idx], v["coil_misalignment_2"][idx]], -1),
        coil_field_coupling=v["coil_field_coupling"][idx],
        field_scale=total[idx] / setup.field, field_azimuth=gamma[idx],
        thread_neutral_angle=target[idx] + v["thread_neutral_angle"][idx],
        filter_coefficient=v["filter_coefficient"][idx], pwm_levels=np.rint(v["pwm_levels"][idx]))


def source_error_bands(setup, psi_des, values, *, duration, window, field_h, seed=None):
    r"""Final error band of the bench for per-member values of the error sources.

    Parameters
    ----------
    setup : BenchSetup
        The bench as designed [-]; its field is ``field_h`` with no background.
    psi_des : float or array_like
        Target [rad], one for all or one per member.
    values : dict of str to array_like
        Per-member values [SI] of sources of :func:`nominal_source_values` (missing names
        take the nominal value); ``gyro_drift`` is the change of the offset over the run
        [rad/s]; ``sample_interval`` is rounded to the nearest of :data:`SAMPLE_INTERVALS`.
    duration, window : float
        Run length and final window of the band [s].
    field_h : float
        The simulator's field at the center [A/m], > 0 (the background adds to it).
    seed : int, optional
        Seed of the sensor noise (datasheet levels) [-]; None for ideal sensors.

    Returns
    -------
    band, indicated : ndarray (M,)
        max |ψ + γ − ψ_des| over the window, scored from the simulator's axis (γ the
        turn of the field by the background) [rad], and the same for the filtered angle.

    Notes
    -----
    Not in the thesis. Members sharing a controller period run in one vectorised call
    of :func:`magbench.sim.bench.simulate_bench`.
    """
    as_positive("field_h", field_h, unit="A/m")
    as_positive("duration", duration, unit="s")
    target, v, size = _member_values(setup, psi_des, values)
    levels = np.asarray(SAMPLE_INTERVALS)
    # Nearest period in log (a draw between two levels goes to the nearer by ratio).
    pick = np.argmin(np.abs(np.log(as_positive("sample_interval", v["sample_interval"], unit="s"))[:, None]
                            - np.log(levels)[None, :]), axis=1)
    hb, beta = v["background_h"], v["background_azimuth"]
    total = horizontal_field(field_h, hb, beta)
    gamma = np.arctan2(hb * np.sin(beta), field_h + hb * np.cos(beta))
    s, c = v["magnetometer_scale_difference"], v["magnetometer_cross_axis"]
    matrix = np.stack([np.stack([1 + s, c], -1), np.stack([c, 1 - s], -1)], -2)
    band = np.empty(size)
    indicated = np.empty(size)
    for k, dt in enumerate(levels):
        idx = np.flatnonzero(pick == k)
        if idx.size == 0:
            continue
        sub = replace(setup, sample_interval=float(dt))
        rng = None if seed is None else np.random.default_rng([int(seed), k])
        run = simulate_bench(
            sub, target[idx], duration=duration, window=window, members=idx.size, rng=rng,
            record_interval=duration,
            release_angle=target[idx] + v["release_angle"][idx], release_rate=v["release_rate"][idx],
            errors=_member_errors(setup, v, idx, target, total, gamma, matrix, duration))
        band[idx], indicated[idx] = run.error_band, run.indicated_error_band
    return band, indicated


def one_at_a_time(setup, targets, sources, *, points, duration, window, field_h, seed=None):
    """Error band against each source across its range, every other source nominal.

    Parameters
    ----------
    setup : BenchSetup
        The bench as designed [-] (:func:`source_error_bands`).
    targets : sequence of float
        Targets ψ_des [rad]; all run in one batch of members.
    sources : dict of str to range
        The sources swept, by name, each with ``low``, ``high`` [SI] and ``scale`` [-]
        (:func:`from_unit_cube`).
    points : int
        Values per source, evenly spaced (in log for a log scale) from low to high [-], ≥ 2.
    duration, window : float
        Run length and final window of the band [s].
    field_h : float
        The simulator's field at the center [A/m].
    seed : int, optional
        Seed of the sensor noise [-]; None for ideal sensors.

    Returns
    -------
    dict of str to (values (points,), band (T, points), indicated (T, points))
        SI values and, per target, the bands [rad].

    Notes
    -----
    Not in the thesis: a one-at-a-time sweep through :func:`source_error_bands`.
    """
    points = as_count("points", points, minimum=2)
    targets = np.atleast_1d(as_finite("targets", targets))
    names = list(sources)
    grid = np.linspace(0.0, 1.0, points)
    xs = from_unit_cube(np.tile(grid[:, None], (1, len(names))), sources)
    nominal = nominal_source_values(setup)
    block = len(names) * points
    values = {n: np.full(block * targets.size, float(nominal[n])) for n in nominal}
    for t in range(targets.size):
        for i, n in enumerate(names):
            start = t * block + i * points
            values[n][start:start + points] = xs[n]
    band, ind = source_error_bands(setup, np.repeat(targets, block), values, duration=duration, window=window,
                                   field_h=field_h, seed=seed)
    band, ind = band.reshape(targets.size, len(names), points), ind.reshape(targets.size, len(names), points)
    return {n: (xs[n], band[:, i], ind[:, i]) for i, n in enumerate(names)}


def _checked_range(name, source):
    """(low, high, scale) of one source's range, checked."""
    low, high, scale = float(source.low), float(source.high), source.scale
    if scale not in ("linear", "log"):
        raise ValueError(f"source {name!r}: scale must be 'linear' or 'log', got {shown(scale)}")
    if not (np.isfinite(low) and np.isfinite(high) and low < high):
        raise ValueError(f"source {name!r}: needs finite low < high, got {shown(low)}, {shown(high)}")
    if scale == "log" and low <= 0:
        raise ValueError(f"source {name!r}: a log scale needs low > 0, got {shown(low)}")
    return low, high, scale


def from_unit_cube(u, sources):
    """Map points of the unit hypercube to source values (SI): uniform or log-uniform.

    Parameters
    ----------
    u : array_like, shape (M, D)
        Points in [0, 1]^D, D = len(sources) in their order [-].
    sources : dict of str to range
        Each with ``low`` < ``high`` [SI] and ``scale`` "linear" or "log" (low > 0) [-].

    Returns
    -------
    dict of str to ndarray (M,)
        Values [SI] by source name.

    Notes
    -----
    Not in the thesis: the sampling space of :func:`sobol_design`.

    Examples
    --------
    >>> from types import SimpleNamespace as Range
    >>> x = from_unit_cube([[0.5, 0.5]], {"a": Range(low=0.0, high=2.0, scale="linear"),
    ...                                   "b": Range(low=1.0, high=100.0, scale="log")})
    >>> float(x["a"][0]), float(x["b"][0])
    (1.0, 10.0)
    """
    u = np.asarray(u, float)
    if u.ndim != 2 or u.shape[1] != len(sources):
        raise ValueError(f"u must have shape (M, {len(sources)}), got {u.shape}")
    if np.any((u < 0) | (u > 1)):
        raise ValueError("u must lie in [0, 1]")
    out = {}
    for j, (name, source) in enumerate(sources.items()):
        low, high, scale = _checked_range(name, source)
        if scale == "log":
            out[name] = low * (high / low) ** u[:, j]
        else:
            out[name] = low + u[:, j] * (high - low)
    return out


def sobol_design(sources, *, base_samples, seed, fixed=None):
    """Saltelli's sample over the sources' ranges (SALib), first and total order.

    Parameters
    ----------
    sources : dict of str to range
        Each with ``low``, ``high`` [SI] and ``scale`` [-] (:func:`from_unit_cube`).
    base_samples : int
        N, a power of 2 [-]; N·(D + 2) points for D sampled sources.
    seed : int
        Seed of the scrambled Sobol sequence [-].
    fixed : dict of str to float, optional
        Sources held at these values [SI] instead of sampled (not in the indices).

    Returns
    -------
    problem : dict
        SALib's problem (names, unit bounds).
    values : dict of str to ndarray
        Per-point source values [SI], ready for :func:`source_error_bands`.

    Notes
    -----
    Not in the thesis: Saltelli's scheme (``SALib.sample.sobol``, scrambled Sobol
    sequence), without second-order terms.
    """
    from SALib.sample import sobol as sobol_sample

    n = int(base_samples)
    if n < 2 or n & (n - 1):
        raise ValueError(f"base_samples must be a power of 2 >= 2, got {shown(base_samples)}")
    fixed = fixed or {}
    unknown = set(fixed) - set(sources)
    if unknown:
        raise ValueError(f"fixed names unknown sources: {sorted(unknown)}")
    free = {k: s for k, s in sources.items() if k not in fixed}
    if not free:
        raise ValueError("every source is fixed: nothing to analyse")
    names = list(free)
    problem = {"num_vars": len(names), "names": names, "bounds": [[0.0, 1.0]] * len(names)}
    u = sobol_sample.sample(problem, n, calc_second_order=False, seed=seed)
    values = from_unit_cube(u, free)
    values.update({k: np.full(len(u), float(x)) for k, x in fixed.items()})
    return problem, values


def sobol_analysis(problem, values, band, indicated, *, threshold, seed):
    r"""Sobol indices of the error band and its distribution over the independent points.

    Parameters
    ----------
    problem : dict
        SALib's problem, from :func:`sobol_design` [-].
    values : dict of str to ndarray
        Per-point source values, from :func:`sobol_design` [SI].
    band, indicated : ndarray
        Error bands of every point [rad] (:func:`source_error_bands`).
    threshold : float
        Error band whose exceedance fraction is returned [rad] (the thesis's 10°).
    seed : int
        Seed of the bootstrap [-].

    Returns
    -------
    dict
        ``names``; ``S1``, ``S1_conf``, ``ST``, ``ST_conf`` (95 % bootstrap half-widths)
        per name; ``band``, ``indicated`` and ``values`` of the 2N independent points (the
        A and B matrices of Saltelli's scheme) [rad, SI]; ``fraction`` of them with
        band ≥ threshold and its 95 % Clopper–Pearson interval ``fraction_ci``; ``runs``.

    Notes
    -----
    Not in the thesis. Jansen's estimators with bootstrap intervals
    (``SALib.analyze.sobol``), on the band in degrees.
    """
    from SALib.analyze import sobol as sobol_analyze
    from scipy.stats import binomtest

    names = problem["names"]
    step = len(names) + 2
    if np.size(band) % step or np.size(band) != np.size(indicated):
        raise ValueError(f"band and indicated must hold N·(D + 2) = N·{step} points each (Saltelli's sample), "
                         f"got {np.size(band)} and {np.size(indicated)}")
    as_finite("threshold", threshold)
    res = sobol_analyze.analyze(problem, np.degrees(band), calc_second_order=False, conf_level=0.95,
                                seed=seed, print_to_console=False)
    independent = np.sort(np.concatenate([np.arange(0, len(band), step), np.arange(step - 1, len(band), step)]))
    reach = int(np.sum(band[independent] >= threshold))
    ci = binomtest(reach, independent.size).proportion_ci(0.95, method="exact")
    return {"names": names, "S1": dict(zip(names, res["S1"])), "S1_conf": dict(zip(names, res["S1_conf"])),
            "ST": dict(zip(names, res["ST"])), "ST_conf": dict(zip(names, res["ST_conf"])),
            "band": band[independent], "indicated": indicated[independent],
            "values": {k: np.asarray(x)[independent] for k, x in values.items()},
            "fraction": reach / independent.size, "fraction_ci": (float(ci.low), float(ci.high)),
            "runs": len(band)}


def sobol_budget(setup, psi_des, sources, *, base_samples, duration, window, field_h, seed,
                 threshold, fixed=None):
    """:func:`sobol_design`, :func:`source_error_bands` and :func:`sobol_analysis` in one call.

    Parameters
    ----------
    setup : BenchSetup
        The bench as designed [-].
    psi_des : float
        Target [rad].
    sources : dict of str to range
        Each with ``low``, ``high`` [SI] and ``scale`` [-] (:func:`from_unit_cube`).
    base_samples : int
        N of Saltelli's sample, a power of 2 [-].
    duration, window : float
        Run length and final window of the band [s].
    field_h : float
        The simulator's field at the center [A/m].
    seed : int
        Seed of the Sobol sequence, the sensor noise and the bootstrap [-].
    threshold : float
        Error band whose exceedance fraction is returned [rad].
    fixed : dict of str to float, optional
        Sources held at these values [SI] instead of sampled.

    Returns
    -------
    dict
        As :func:`sobol_analysis`.

    Notes
    -----
    Not in the thesis: the three steps of the budget's Sobol analysis.
    """
    problem, values = sobol_design(sources, base_samples=base_samples, seed=seed, fixed=fixed)
    band, ind = source_error_bands(setup, psi_des, values, duration=duration, window=window,
                                   field_h=field_h, seed=seed)
    return sobol_analysis(problem, values, band, ind, threshold=threshold, seed=seed)
