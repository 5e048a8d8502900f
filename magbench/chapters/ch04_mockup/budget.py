r"""Chapter 4: the error sources of the bench's 10° (thesis §4.4, seed line 616).

The thesis measured an absolute orientation error of 10° on its bench; the closed-loop
model of :mod:`magbench.sim.bench` with the bench *as designed* settles within a few
hundredths of a degree. The chapter asks what the bench *could have been*: every
hardware error source the parts allow, each with a range and where the range comes from
(``magbench/data/bench/error_sources.toml``). :func:`load_error_sources` reads the
ranges (three computed by the library: the uncancelled laboratory field from IGRF and
the field's non-uniformity over the mock-up, both as chapter 2 computes them, and the
coils' field at the magnetometer, a square coil's center field per unit moment); the
budget itself, one source at a time and Sobol indices over all of them, is
:mod:`magbench.sim.bench.budget`.

Not in the thesis: the thesis names "disturbing torques, the thread's torsion or the
sensors' inaccuracy" (seed line 616) without sizing any of them.
"""

import tomllib
from dataclasses import dataclass

import numpy as np

from ...constants import MU_0
from ...io.data import DATA_DIR, DataError, to_si, verify_checksum

__all__ = ["ErrorSource", "load_error_sources"]

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
