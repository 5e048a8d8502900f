"""Model beside measurement: one row per measured (or independently known) quantity.

A row holds the measured value with its source and uncertainty, the model's value,
their difference and the tolerance within which they count as agreeing. The verdict
is computed, never typed, and a disagreement is a finding, not an error.

Tolerances are never chosen to make a row agree: they come from the measurement's
stated uncertainty, or, where the model rests on rounded printed inputs, from the
spread of the model over those inputs' last printed digit.

Each chapter contributes a provider: a function ``(params) -> list[CompareRow]``
registered in :data:`PROVIDERS`.
"""

import datetime as _dt
import itertools
from dataclasses import asdict, dataclass

import numpy as np

from . import geomag, igrf
from .constants import EARTH_RADIUS
from .params import chapter_parameters

__all__ = ["CompareRow", "PROVIDERS", "CH04_PROVIDERS", "make_row", "all_rows", "geomagnetic_rows",
           "chapter4_rows", "today_decimal_year"]


@dataclass(frozen=True)
class CompareRow:
    """One model-vs-measurement comparison (SI values; ``unit`` names the display unit)."""

    id: str
    quantity: str
    source: str
    measured: float
    uncertainty: float | None
    unit: str
    model: float
    difference: float
    tolerance: float
    verdict: str
    note: str = ""

    def as_dict(self):
        """The row as a JSON-ready dict with the public keys."""
        d = asdict(self)
        d.pop("note")
        return d


def make_row(id, quantity, source, measured, model, tolerance, *, unit, uncertainty=None,
             scale=1.0, note=""):
    """Build a row; values are given in SI and divided by ``scale`` for display in ``unit``.

    The verdict is ``"agrees"`` when |model − measured| ≤ tolerance, else ``"disagrees"``.
    """
    diff = float(model) - float(measured)
    verdict = "agrees" if abs(diff) <= float(tolerance) else "disagrees"
    return CompareRow(
        id=id, quantity=quantity, source=source, measured=float(measured) / scale,
        uncertainty=None if uncertainty is None else float(uncertainty) / scale, unit=unit,
        model=float(model) / scale, difference=diff / scale, tolerance=float(tolerance) / scale,
        verdict=verdict, note=note,
    )


def today_decimal_year(today=None):
    """Decimal year of ``today`` (default: the current UTC date)."""
    today = today or _dt.datetime.now(_dt.timezone.utc).date()
    start = _dt.date(today.year, 1, 1)
    return today.year + (today - start).days / (_dt.date(today.year + 1, 1, 1) - start).days


def _printed_digit_spread(func, values, half_units):
    """Largest |func(perturbed) − func(values)| over the corners of the printed-digit box."""
    base = func(*values)
    spread = 0.0
    for signs in itertools.product((-1.0, 1.0), repeat=len(values)):
        moved = [v + s * d for v, s, d in zip(values, signs, half_units)]
        spread = max(spread, float(np.max(np.abs(func(*moved) - base))))
    return spread


def geomagnetic_rows(params=None, *, epochs=None):
    """Chapter 1: the thesis's dipole beside the IGRF-14 field.

    The "measured" side is IGRF-14, the field model fitted to observatory and
    satellite measurements; the "model" side is the thesis's dipole (moment 8.1·10²²
    A·m², pole 78.5° N 69° W). Tolerances are the thesis's printed-digit rounding.

    Parameters
    ----------
    params : dict, optional
        Chapter-1 parameters (SI); defaults from :func:`magbench.params.chapter_parameters`.
    epochs : sequence of float, optional
        Decimal years for the dipole rows; default 1960, the thesis's epoch and today.
    """
    p = params or chapter_parameters("ch01")
    if epochs is None:
        epochs = (1960.0, p["thesis_epoch"], today_decimal_year())
    m, tilt = p["earth_dipole_moment"], p["earth_dipole_tilt"]
    plat, plon = p["geomagnetic_pole_latitude"], p["geomagnetic_pole_longitude"]
    deg = np.pi / 180
    # Half a unit in the last printed digit: 8.1e25 CGS, 11.5°, 78.5° N, 69° W.
    half_m, half_tilt, half_plat, half_plon = 0.05e22, 0.05 * deg, 0.05 * deg, 0.5 * deg
    src = "IGRF-14 (ppigrf), degree 1"
    rows = []
    for year in epochs:
        d = igrf.igrf_dipole(year)
        tag = f"{year:.0f}" if float(year).is_integer() else f"{year:.2f}"
        rows += [
            make_row(f"dipole-moment-{tag}", f"Earth dipole moment, {tag}", src, d.moment, m, half_m,
                     unit="1e22 A m^2", scale=1e22),
            make_row(f"dipole-tilt-{tag}", f"Dipole tilt to the rotation axis, {tag}", src,
                     d.tilt, tilt, half_tilt, unit="deg", scale=deg),
            make_row(f"pole-latitude-{tag}", f"Northern geomagnetic pole latitude, {tag}", src,
                     d.pole_latitude, plat, half_plat, unit="deg", scale=deg),
            make_row(f"pole-longitude-{tag}", f"Northern geomagnetic pole longitude, {tag}", src,
                     d.pole_longitude, plon, half_plon, unit="deg", scale=deg),
        ]
    # The full field at the laboratory when the bench was built.
    lat, lon, year = p["laboratory_latitude"], p["laboratory_longitude"], p["thesis_epoch"]
    f = igrf.igrf_field(lat, lon, year)

    def lab_elements(moment, pole_lat, pole_lon):
        phi = geomag.geomagnetic_latitude(lat, lon, pole_lat, pole_lon)
        return np.array([geomag.dipole_total_b(phi, moment, p["earth_radius"]),
                         geomag.dipole_horizontal_b(phi, moment, p["earth_radius"]),
                         geomag.dipole_vertical_b(phi, moment, p["earth_radius"]),
                         geomag.dipole_inclination(phi)])

    model = lab_elements(m, plat, plon)
    spread = [_printed_digit_spread(lambda *v, k=k: lab_elements(*v)[k], (m, plat, plon),
                                    (half_m, half_plat, half_plon)) for k in range(4)]
    src_full = f"IGRF-14 (ppigrf), full field, {year:.0f}"
    rows += [
        make_row("lab-total-field", "Total field at the laboratory (St Petersburg)", src_full,
                 f.total, model[0], spread[0], unit="uT", scale=1e-6),
        make_row("lab-horizontal-field", "Horizontal field at the laboratory", src_full,
                 f.horizontal, model[1], spread[1], unit="uT", scale=1e-6),
        make_row("lab-vertical-field", "Vertical (downward) field at the laboratory", src_full,
                 f.down, model[2], spread[2], unit="uT", scale=1e-6),
        make_row("lab-inclination", "Inclination at the laboratory", src_full,
                 f.inclination, model[3], spread[3], unit="deg", scale=deg),
    ]
    # The equatorial dipole field the thesis prints (0.31 Oe) against the real dipole.
    d = igrf.igrf_dipole(year)
    b0_igrf = geomag.dipole_equatorial_b(d.moment, EARTH_RADIUS)
    b0_model = geomag.dipole_equatorial_b(m, p["earth_radius"])
    rows.append(make_row("equatorial-dipole-field", f"Dipole field on the equator, {year:.0f}",
                         src, b0_igrf, b0_model, b0_model * half_m / m, unit="uT", scale=1e-6))
    return rows


#: Chapter 4 has three pages (dynamics, estimation, bench); each appends its own
#: ``(params) -> list[CompareRow]`` provider here and :func:`chapter4_rows` joins them.
CH04_PROVIDERS = []


def chapter4_rows(params=None):
    """Chapter 4: the rows of every provider in :data:`CH04_PROVIDERS`, in order."""
    rows = []
    for provider in CH04_PROVIDERS:
        rows.extend(provider(params))
    return rows


#: Row providers by chapter, in book order.
PROVIDERS = {"ch01": geomagnetic_rows, "ch04": chapter4_rows}


def all_rows():
    """Every model-vs-measurement row of the project, in chapter order."""
    rows = []
    for provider in PROVIDERS.values():
        rows.extend(provider())
    return rows
