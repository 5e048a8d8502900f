"""Chapter inputs: defaults from ``data/params``, overridable for a whole-book build.

Each chapter's ``parameters`` cell calls :func:`chapter_parameters` and assigns every
input to a variable, so papermill (or a reader editing the cell) can override single
values. For a whole-book build with other values, point the environment variable
``MAGBENCH_PARAMS`` at a TOML file (``make book PARAMS=file.toml`` does this)::

    [all]                       # applies to every chapter
    earth_dipole_moment = 8.0e22

    [ch01]                      # applies to chapter 1 only
    orbit_altitude = 500e3

Override values are SI numbers. An unknown chapter or parameter name is an error
that lists the valid names.
"""

import os
import tomllib
from pathlib import Path

from .data import DataError, load_parameter_set

__all__ = ["CHAPTER_INPUTS", "OVERRIDES_ENV", "chapter_parameters", "read_overrides"]

#: Environment variable naming a TOML file of overrides for a whole-book build.
OVERRIDES_ENV = "MAGBENCH_PARAMS"

#: The inputs of each chapter: names of entries in ``data/params/thesis.toml``.
CHAPTER_INPUTS = {
    "ch01": [
        "earth_dipole_moment", "earth_dipole_tilt", "geomagnetic_pole_latitude",
        "geomagnetic_pole_longitude", "earth_radius", "laboratory_latitude",
        "laboratory_longitude", "thesis_epoch", "orbit_altitude", "orbit_inclination",
        "mockup_inertia", "mockup_initial_rate",
    ],
    "ch02": [
        "mockup_inertia", "mockup_magnet_moment", "oscillation_period", "oscillation_amplitude",
        "sim_design_h", "sim_coil_radius", "sim_spacing_ratio", "sim_turns", "sim_current",
        "sim_wire_diameter", "copper_resistivity", "copper_density", "sim_comsol_spacing",
        "sim_built_spacing", "sim_built_radius", "laboratory_latitude", "laboratory_longitude",
        "thesis_epoch",
    ],
    "ch03": [
        "copper_resistivity", "copper_density", "mtq_moment", "mtq_voltage", "mtq_side",
        "mtq_turns", "mtq_max_power", "mtq_max_mass", "aluminium_gamma_rho", "magnet_remanence",
        "magnet_density", "alnico_max_magnetization", "alnico_elongation", "permalloy_a",
        "permalloy_b", "permalloy_design_magnetization", "permalloy_design_field", "core_density",
        "core_averaging_factor", "em_fill_factor", "em_current_density", "em_elongation",
    ],
    "ch04": [
        # equations of motion and the PID (book/ch04-mockup.md)
        "mockup_mass", "mockup_cm_offset", "mtq_moment", "mockup_initial_angle",
        "mockup_initial_angle_alt", "oscillation_period", "oscillation_amplitude", "pid_kp",
        "pid_ki", "pid_kd", "pid_bandwidth", "pid_sample_interval",
        # sensors and estimation (book/ch04-estimation.md)
        "filter_coefficient_low", "filter_coefficient_high", "filter_sample_interval",
        "gyro_residual_bias",
        # the bench experiments (book/ch04-bench.md, magbench.bench)
        "mockup_inertia", "mtq_voltage", "mtq_turns", "mtq_side", "sim_design_h",
        "bench_field_h", "bench_background_h", "bench_background_azimuth",
        "bench_coil_resistance", "bench_moment_tolerance", "bench_pwm_levels",
        "bench_sample_interval", "bench_duration", "bench_error_window",
        "bench_filter_coefficient", "bench_bandwidth", "bench_thread_stiffness",
        "bench_thread_stiffness_factor", "bench_release_angle_spread", "bench_release_rate_std",
        "bench_gyro_bias", "bench_members", "bench_seed",
    ],
}


def read_overrides(path):
    """Read an overrides file into ``{section: {name: value}}`` (sections ``all``, ``chNN``)."""
    path = Path(path)
    try:
        tables = tomllib.loads(path.read_text(encoding="utf-8"))
    except FileNotFoundError:
        raise DataError(f"parameter file {path} (from ${OVERRIDES_ENV}) does not exist") from None
    except tomllib.TOMLDecodeError as exc:
        raise DataError(f"{path}: {exc}") from None
    valid_sections = {"all", *CHAPTER_INPUTS}
    for section, values in tables.items():
        if section not in valid_sections or not isinstance(values, dict):
            raise DataError(f"{path}: unknown section [{section}]; valid: {', '.join(sorted(valid_sections))}")
        for name, value in values.items():
            if isinstance(value, bool) or not isinstance(value, int | float):
                raise DataError(f"{path}: [{section}] {name} must be a number (SI), got {value!r}")
            known = (set().union(*CHAPTER_INPUTS.values()) if section == "all"
                     else set(CHAPTER_INPUTS[section]))
            if name not in known:
                raise DataError(f"{path}: [{section}] has no parameter {name!r}; "
                                f"valid: {', '.join(sorted(known))}")
    return tables


def chapter_parameters(chapter, *, overrides=None):
    """SI values of a chapter's inputs.

    Parameters
    ----------
    chapter : str
        Chapter key, e.g. ``"ch01"``.
    overrides : str or Path, optional
        TOML overrides file; defaults to the file named by ``$MAGBENCH_PARAMS``, if set.

    Returns
    -------
    dict of str to float
        Parameter name to SI value, defaults from ``data/params/thesis.toml``.

    Examples
    --------
    >>> p = chapter_parameters("ch01", overrides=None)
    >>> round(p["earth_radius"])
    6371000
    """
    if chapter not in CHAPTER_INPUTS:
        raise KeyError(f"unknown chapter {chapter!r}; known: {', '.join(CHAPTER_INPUTS)}")
    params = load_parameter_set("thesis")
    names = CHAPTER_INPUTS[chapter]
    values = {name: params[name].value_si for name in names}
    path = overrides if overrides is not None else os.environ.get(OVERRIDES_ENV)
    if path:
        tables = read_overrides(path)
        for section in ("all", chapter):
            for name, value in tables.get(section, {}).items():
                if name in values:      # [all] may also name other chapters' inputs
                    values[name] = float(value)
    return values
