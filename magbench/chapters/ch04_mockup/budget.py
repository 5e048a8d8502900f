r"""Chapter 4: an error budget for the bench's 10° (thesis §4.4, seed line 616).

The thesis measured an absolute orientation error of 10° on its bench; the closed-loop
model of :mod:`magbench.sim.bench` with the bench *as designed* settles within a few
hundredths of a degree. This module asks what the bench *could have been*: every
hardware error source the parts allow, each with a range and where the range comes from
(``magbench/data/bench/error_sources.toml``), run through the same simulation as the
per-member :class:`magbench.sim.bench.BenchErrors` of
:func:`magbench.sim.bench.simulate_bench`, vectorised over members:

- :func:`load_error_sources` the ranges (three computed by the library: the uncancelled
  laboratory field from IGRF and the field's non-uniformity over the mock-up, both as
  chapter 2 computes them, and the coils' field at the magnetometer, a square coil's
  centre field per unit moment);
- :func:`simulate_sources` the final error band for any set of per-member values;
- :func:`one_at_a_time` each source across its range, the others nominal;
- :func:`sobol_budget` first-order and total Sobol indices (SALib, Saltelli's sample)
  and the distribution of the error band over the whole allowed space.

Not in the thesis: the thesis names "disturbing torques, the thread's torsion or the
sensors' inaccuracy" (seed line 616) without sizing any of them.
"""

import tomllib
from dataclasses import dataclass

import numpy as np

from ...constants import MU_0
from ...io.data import DATA_DIR, DataError, to_si, verify_checksum
from ..._validate import shown

__all__ = ["ErrorSource", "load_error_sources", "nominal_values", "simulate_sources", "one_at_a_time",
           "sobol_design", "sobol_analysis", "sobol_budget", "from_unit_cube",
           "SAMPLE_INTERVALS"]

#: Controller periods the budget runs [s]: draws of ``sample_interval`` are rounded to the
#: nearest (in log) so that members share a time grid and stay vectorised.
SAMPLE_INTERVALS = (0.01, 0.02)

_PATH = DATA_DIR / "bench" / "error_sources.toml"
_EXTRA_UNITS = {"uT/(A m^2)": 1e-6}     # T per A·m²
_KEYS = {"low", "high", "unit", "scale", "source", "reference", "note", "computed", "seed_line"}


@dataclass(frozen=True)
class ErrorSource:
    """One hardware error source: its range in SI and where the range comes from.

    ``low``/``high`` [SI unit of ``si_unit``], ``scale`` "linear" or "log", ``unit`` the
    file's unit (for display: ``to_display`` converts), ``source`` datasheet / thesis /
    ours / computed, ``reference`` and ``note`` as in the file.
    """

    name: str
    low: float
    high: float
    unit: str
    scale: str
    source: str
    reference: str
    note: str

    @property
    def factor(self):
        """SI value of one unit of ``unit``."""
        return _EXTRA_UNITS[self.unit] if self.unit in _EXTRA_UNITS else to_si(1.0, self.unit)[0]

    def to_display(self, value):
        """A value in SI expressed in the file's unit."""
        return np.asarray(value, float) / self.factor


def _computed_ranges(params):
    """The ranges computed by the library: {name: (low, high)} in SI.

    ``background_h`` (chapter 2's IGRF at the laboratory), ``heading_ripple`` (the pair's
    non-uniformity over the mock-up) and ``coil_field_coupling`` (a square coil's field
    at its centre per unit moment).
    """
    from ...earth import igrf
    from ... import fields

    lab = igrf.igrf_field(params["laboratory_latitude"], params["laboratory_longitude"],
                          params["thesis_epoch"])
    # The mock-up's radius from the thesis's own J = M R²/2 (thesis §2.1, seed line 240).
    radius = float(np.sqrt(2.0 * params["mockup_inertia"] / params["mockup_mass"]))
    ripple = float(fields.sphere_nonuniformity(params["sim_built_radius"], params["sim_built_spacing"], radius))
    return {"background_h": (0.0, float(lab.horizontal / MU_0)), "heading_ripple": (-ripple, ripple),
            "coil_field_coupling": (0.0, fields.square_loop_center_b_per_moment(params["mtq_side"]))}


def load_error_sources(params=None):
    """The error sources of ``magbench/data/bench/error_sources.toml``, ranges in SI.

    Parameters
    ----------
    params : dict, optional
        SI values of the thesis's parameters (laboratory position and epoch, the
        simulator as built, the mock-up's inertia and mass); default the thesis's set.

    Returns
    -------
    dict of str to ErrorSource
        In the file's order.

    Notes
    -----
    ``background_h`` runs from 0 to the laboratory's horizontal field (IGRF at the
    thesis's epoch, as chapter 2 computes it); ``heading_ripple`` within ± the
    relative non-uniformity of the pair as built over a sphere of the mock-up's radius;
    ``coil_field_coupling`` from 0 to the field at a square coil's centre per unit
    moment (:func:`magbench.fields.square_loop_center_b_per_moment` of the thesis's side).
    """
    if params is None:
        from ...io import load_parameter_set
        params = {k: p.value_si for k, p in load_parameter_set("thesis").items()}
    content = verify_checksum(_PATH).decode("utf-8")
    tables = tomllib.loads(content)
    computed = _computed_ranges(params)
    out = {}
    for name, t in tables.items():
        where = f"{_PATH}: [{name}]"
        if set(t) - _KEYS or not {"unit", "scale", "source"} <= set(t):
            raise DataError(f"{where} needs unit, scale and source (allowed keys: {', '.join(sorted(_KEYS))})")
        if t["scale"] not in ("linear", "log"):
            raise DataError(f"{where}: scale must be 'linear' or 'log', got {t['scale']!r}")
        unit = t["unit"]
        factor = _EXTRA_UNITS.get(unit) or to_si(1.0, unit)[0]
        if t["source"] == "computed":
            if name not in computed:
                raise DataError(f"{where}: no computed range is defined for this source "
                                f"(computed ones: {', '.join(computed)})")
            low, high = computed[name]
        else:
            low, high = float(t["low"]) * factor, float(t["high"]) * factor
            if not low < high:
                raise DataError(f"{where}: low must be below high, got {t['low']!r}, {t['high']!r}")
        if t["scale"] == "log" and low <= 0:
            raise DataError(f"{where}: a log scale needs low > 0, got {t['low']!r}")
        out[name] = ErrorSource(name, low, high, unit, t["scale"], t["source"],
                                t.get("reference", t.get("computed", "")), t.get("note", ""))
    return out


def nominal_values(setup):
    """Each source's value in the bench as designed (SI): no error, the setup's choices.

    The release is at the target at rest; ``background_azimuth`` is 90° (across the
    simulator's axis, where a background turns the field most), so that the
    one-at-a-time sweep of ``background_h`` shows its worst case.
    """
    return {"gyro_offset": 0.0, "gyro_drift": 0.0, "magnetometer_offset_x": 0.0, "magnetometer_offset_y": 0.0,
            "magnetometer_scale_difference": 0.0, "magnetometer_cross_axis": 0.0,
            "magnetometer_misalignment": 0.0, "background_h": 0.0, "background_azimuth": np.pi / 2,
            "heading_ripple": 0.0, "coil_misalignment_1": 0.0, "coil_misalignment_2": 0.0,
            "coil_field_coupling": 0.0, "thread_stiffness": setup.thread_stiffness,
            "thread_neutral_angle": 0.0, "filter_coefficient": setup.filter_coefficient,
            "sample_interval": setup.sample_interval, "pwm_levels": float(setup.pwm_levels),
            "moment_scale_1": 0.0, "moment_scale_2": 0.0, "release_angle": 0.0, "release_rate": 0.0}


def from_unit_cube(u, sources):
    """Map points of the unit hypercube to source values (SI): uniform or log-uniform.

    Parameters
    ----------
    u : array_like, shape (M, D)
        Points in [0, 1]^D, D = len(sources) in their order [-].
    sources : dict of str to ErrorSource

    Returns
    -------
    dict of str to ndarray (M,)
    """
    u = np.asarray(u, float)
    if u.ndim != 2 or u.shape[1] != len(sources):
        raise ValueError(f"u must have shape (M, {len(sources)}), got {u.shape}")
    if np.any((u < 0) | (u > 1)):
        raise ValueError("u must lie in [0, 1]")
    out = {}
    for j, s in enumerate(sources.values()):
        if s.scale == "log":
            out[s.name] = s.low * (s.high / s.low) ** u[:, j]
        else:
            out[s.name] = s.low + u[:, j] * (s.high - s.low)
    return out


def simulate_sources(setup, psi_des, values, *, duration, window, field_h, seed=None):
    r"""Final error band of the bench for per-member values of the error sources.

    Parameters
    ----------
    setup : magbench.sim.bench.BenchSetup
        The bench as designed [-]; its field is ``field_h`` with no background.
    psi_des : float or array_like
        Target [rad], one for all or one per member.
    values : dict of str to array_like
        Per-member values [SI] of every source of :func:`nominal_values` (missing names
        take the nominal value); ``gyro_drift`` is the change of the offset over the run
        [rad/s]; ``sample_interval`` is rounded to the nearest of :data:`SAMPLE_INTERVALS`.
    duration, window : float
        Run length and final window of the band [s].
    field_h : float
        The simulator's field at the centre [A/m] (the background adds to it).
    seed : int, optional
        Seed of the sensor noise (datasheet levels); None for ideal sensors.

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
    from dataclasses import replace
    from ...sim import bench

    vals = dict(nominal_values(setup))
    vals.update(values)
    size = max([np.size(v) for v in vals.values()] + [np.size(psi_des)])
    target = np.broadcast_to(np.asarray(psi_des, float), (size,))
    v = {k: np.broadcast_to(np.asarray(x, float), (size,)) for k, x in vals.items()}
    levels = np.asarray(SAMPLE_INTERVALS)
    # Nearest period in log (a draw between two levels goes to the nearer by ratio).
    pick = np.argmin(np.abs(np.log(v["sample_interval"])[:, None] - np.log(levels)[None, :]), axis=1)
    hb, beta = v["background_h"], v["background_azimuth"]
    total = bench.horizontal_field(field_h, hb, beta)
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
        errors = bench.BenchErrors(
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
        run = bench.simulate_bench(
            sub, target[idx], duration=duration, window=window, members=idx.size, rng=rng,
            record_interval=duration,
            release_angle=target[idx] + v["release_angle"][idx], release_rate=v["release_rate"][idx],
            errors=errors)
        band[idx], indicated[idx] = run.error_band, run.indicated_error_band
    return band, indicated


def one_at_a_time(setup, targets, sources, *, points, duration, window, field_h, seed=None):
    """Error band against each source across its range, every other source nominal.

    Parameters
    ----------
    setup, duration, window, field_h, seed
        As :func:`simulate_sources`.
    targets : sequence of float
        Targets ψ_des [rad]; all run in one batch of members.
    sources : dict of str to ErrorSource
    points : int
        Values per source, evenly spaced (in log for a log scale) from low to high [-], ≥ 2.

    Returns
    -------
    dict of str to (values (points,), band (T, points), indicated (T, points))
        SI values and, per target, the bands [rad].
    """
    points = int(points)
    if points < 2:
        raise ValueError(f"points must be >= 2, got {shown(points)}")
    targets = np.atleast_1d(np.asarray(targets, float))
    names = list(sources)
    grid = np.linspace(0.0, 1.0, points)
    xs = from_unit_cube(np.tile(grid[:, None], (1, len(names))), sources)
    nominal = nominal_values(setup)
    block = len(names) * points
    values = {n: np.full(block * targets.size, float(nominal[n])) for n in nominal}
    for t in range(targets.size):
        for i, n in enumerate(names):
            start = t * block + i * points
            values[n][start:start + points] = xs[n]
    band, ind = simulate_sources(setup, np.repeat(targets, block), values, duration=duration, window=window,
                                 field_h=field_h, seed=seed)
    band, ind = band.reshape(targets.size, len(names), points), ind.reshape(targets.size, len(names), points)
    return {n: (xs[n], band[:, i], ind[:, i]) for i, n in enumerate(names)}


def sobol_design(sources, *, base_samples, seed, fixed=None):
    """Saltelli's sample over the sources' ranges (SALib), first and total order.

    Parameters
    ----------
    sources : dict of str to ErrorSource
    base_samples : int
        N, a power of 2 [-]; N·(D + 2) points for D sampled sources.
    seed : int
        Seed of the scrambled Sobol sequence [-].
    fixed : dict of str to float, optional
        Sources held at these values (SI) instead of sampled (not in the indices).

    Returns
    -------
    problem : dict
        SALib's problem (names, unit bounds).
    values : dict of str to ndarray
        Per-point source values [SI], ready for :func:`simulate_sources`.
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
    problem, values
        From :func:`sobol_design`.
    band, indicated : ndarray
        Error bands of every point [rad] (:func:`simulate_sources`).
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
    res = sobol_analyze.analyze(problem, np.degrees(band), calc_second_order=False, conf_level=0.95,
                                seed=seed, print_to_console=False)
    step = len(names) + 2
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
    """:func:`sobol_design`, :func:`simulate_sources` and :func:`sobol_analysis` in one call.

    Parameters are those of the three; returns :func:`sobol_analysis`'s dict.
    """
    problem, values = sobol_design(sources, base_samples=base_samples, seed=seed, fixed=fixed)
    band, ind = simulate_sources(setup, psi_des, values, duration=duration, window=window,
                                 field_h=field_h, seed=seed)
    return sobol_analysis(problem, values, band, ind, threshold=threshold, seed=seed)
