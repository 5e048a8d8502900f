"""Model beside measurement, and printed values beside their computation: one type.

A :class:`Comparison` holds the value compared with (a measurement, an independent
reference, the source's own simulation, or a number the source printed) with its
provenance and uncertainty, the value the model or the source's own formula gives,
their difference and the tolerance within which they count as agreeing. The verdict is
computed, never typed, and a disagreement is a finding, not an error.

Every row says what it compares with (:data:`ROW_KINDS`: a measurement, an
independent reference, a peer simulation, a published or verbal claim, a design value,
or a consistency check with calibrated parameters, which is not counted), and every
printed-value check whether its value was printed or evaluated from a printed formula
and, when it disagrees, how much that matters (:mod:`magbench.errata`).

Tolerances are never chosen to make a row agree: they come from the measurement's
stated uncertainty, or, where the model rests on rounded printed inputs, from the
spread of the model over those inputs' last printed digit, or, for a printed value,
from its own last printed digit.

Two constructors: :func:`make_row` (model vs measurement, from SI values) and
:func:`magbench.errata.source_check` / :func:`magbench.errata.printed_check` (a printed
number beside the source's own formula). Each chapter contributes its rows and checks
(``magbench.chapters``); :func:`magbench.chapters.comparisons` and
:func:`magbench.chapters.source_checks` walk them in book order.
"""

from dataclasses import dataclass

__all__ = ["Comparison", "CompareRow", "ROW_KINDS", "COUNTED_ROW_KINDS", "make_row"]


@dataclass(frozen=True)
class Comparison:
    """One value beside the model's (or the source's formula's) value.

    Values are in the display unit ``unit``; ``scale`` is the SI value of one display
    unit (``1e-6`` for µT, ``π/180`` for degrees), so ``measured * scale`` is SI.

    Attributes
    ----------
    id, quantity : str
        Stable id and what is compared.
    source : str
        Where the compared value comes from (a citation for rows, the source's key for
        printed-value checks).
    measured : float
        The value compared with: measured, reference, simulated or printed [unit].
    uncertainty : float or None
        Its stated uncertainty [unit].
    model : float
        What the model (or the source's own formula and inputs) gives [unit].
    difference : float
        ``model − measured`` [unit], computed in SI.
    tolerance : float
        Largest ``|difference|`` that counts as agreement [unit].
    verdict : str
        ``"agrees"`` or ``"disagrees"``, computed.
    chapter, location, note, computation : str
        The chapter's key; the place in the source; the explanation; the library function
        that computes ``model``.
    kind : str
        For a model-vs-measurement row, what the compared value is: a key of
        :data:`ROW_KINDS`. Set by :func:`magbench.chapters.comparisons` from the
        chapter's declaration.
    basis, severity : str
        For a source check, whether the compared value was printed by the source or
        evaluated by us from a printed formula (a key of
        :data:`magbench.errata.CHECK_BASES`), and, when it disagrees, how much it matters
        (a key of :data:`magbench.errata.SEVERITIES`). Set by
        :func:`magbench.chapters.source_checks`.
    section : str
        Label of the book section that discusses the row or check ("" if none).
    """

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
    chapter: str = ""
    location: str = ""
    computation: str = ""
    scale: float = 1.0
    kind: str = ""
    basis: str = ""
    severity: str = ""
    section: str = ""

    @property
    def agrees(self):
        """Whether the two values agree within ``tolerance``."""
        return self.verdict == "agrees"

    @property
    def counted(self):
        """Whether the row counts towards agree/disagree totals (a consistency check with
        calibrated parameters does not: it states consistency, it cannot test the model)."""
        return self.kind in COUNTED_ROW_KINDS

    @property
    def printed(self):
        """The printed value of a printed-value check (the same as :attr:`measured`)."""
        return self.measured

    @property
    def computed(self):
        """What the source's formula gives (the same as :attr:`model`)."""
        return self.model

    @property
    def explanation(self):
        """The reader-facing explanation (the same as :attr:`note`)."""
        return self.note

    @property
    def relative_difference(self):
        """(measured − model) / |model| [-]: how far a printed value is off."""
        return (self.measured - self.model) / abs(self.model)

    @property
    def measured_si(self):
        """:attr:`measured` in SI."""
        return self.measured * self.scale

    @property
    def model_si(self):
        """:attr:`model` in SI."""
        return self.model * self.scale

    def as_dict(self):
        """The row as a JSON-ready dict with the public keys of ``magbench compare --json``."""
        return {key: getattr(self, key) for key in ("id", "kind", "quantity", "source", "measured", "uncertainty",
                                                     "unit", "model", "difference", "tolerance", "verdict")}


#: The former name of :class:`Comparison` for model-vs-measurement rows.
CompareRow = Comparison


def verdict(difference, tolerance):
    """``"agrees"`` when |difference| ≤ tolerance, else ``"disagrees"``."""
    return "agrees" if abs(float(difference)) <= float(tolerance) else "disagrees"


def make_row(id, quantity, source, measured, model, tolerance, *, unit, uncertainty=None,
             scale=1.0, note=""):
    """Build a row; values are given in SI and divided by ``scale`` for display in ``unit``.

    The verdict is ``"agrees"`` when |model − measured| ≤ tolerance, else ``"disagrees"``.
    """
    diff = float(model) - float(measured)
    return Comparison(
        id=id, quantity=quantity, source=source, measured=float(measured) / scale,
        uncertainty=None if uncertainty is None else float(uncertainty) / scale, unit=unit,
        model=float(model) / scale, difference=diff / scale, tolerance=float(tolerance) / scale,
        verdict=verdict(diff, tolerance), note=note, scale=float(scale),
    )


#: What the value a row compares with is (its ``measured`` column): the kind of a
#: model-vs-measurement row, its column heading on the ledger pages, and what it means.
ROW_KINDS = {
    "measurement": ("measured", "a value a person measured (on the bench, the coils or in flight)"),
    "reference": ("reference", "an independent reference: the IGRF-14 field model (fitted to observatory and "
                               "satellite data) or a closed-form result"),
    "simulation": ("simulated", "a peer simulation: another tool's run of the same case (Basilisk; the "
                                "thesis's COMSOL model)"),
    "claim": ("claimed", "a published claim: a number a paper, book or software repository states for its "
                         "own case, not re-run here"),
    "verbal": ("stated in words", "a verbal claim: a range read from the source's words, shown as that range"),
    "design": ("design value", "a design value: a limit or value the source chose, which the built hardware "
                               "should meet"),
    "consistency": ("reported", "a consistency check with calibrated parameters: the model was fitted to part "
                                "of the same data, so agreement shows consistency, not a prediction (not "
                                "counted as agree or disagree)"),
}

#: The kinds whose rows are counted as agreeing or disagreeing.
COUNTED_ROW_KINDS = tuple(k for k in ROW_KINDS if k != "consistency")
