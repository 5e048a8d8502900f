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
    "ch04": [
        "mockup_inertia", "mockup_mass", "mockup_cm_offset", "mtq_moment", "sim_design_h",
        "mockup_initial_angle", "mockup_initial_angle_alt", "oscillation_period",
        "oscillation_amplitude", "pid_kp", "pid_ki", "pid_kd", "pid_bandwidth",
        "pid_sample_interval",
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
