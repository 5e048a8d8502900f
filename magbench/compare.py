"""Model beside measurement: one row per measured (or independently known) quantity.

A row holds the measured value with its source and uncertainty, the model's value,
their difference and the tolerance within which they count as agreeing. The verdict
is computed, never typed, and a disagreement is a finding, not an error.

Tolerances are never chosen to make a row agree: they come from the measurement's
stated uncertainty, or, where the model rests on rounded printed inputs, from the
spread of the model over those inputs' last printed digit.

Each chapter contributes its rows (``magbench.chapters``: a chapter's ``comparisons``
and the kind of each row); :func:`magbench.chapters.comparisons` walks them in book order.
"""

from dataclasses import asdict, dataclass

__all__ = ["CompareRow", "ROW_KINDS", "make_row"]


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


#: What the value a row compares with is (its ``measured`` column): a measurement, an
#: independent reference (a model fitted to measurements, such as IGRF), the source's
#: own simulation, or a value the source printed as its design or calculation.
ROW_KINDS = {
    "measurement": "measured by a person (on the bench or the coils)",
    "reference": "independent reference (IGRF-14, fitted to observatory and satellite data)",
    "simulation": "the source's own simulation (COMSOL)",
    "printed": "printed design or calculated value of the source",
}
