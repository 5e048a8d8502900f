"""Printed numbers of the sources beside what their own formulas and inputs give.

A printed-value check is a :class:`magbench.compare.Comparison` whose ``measured``
column is the value as printed (read from the source's ``printed.csv`` where the
source prints it as a number) and whose ``model`` column is what the source's own
formula and inputs (or correct physics) give; its tolerance is implied by the printed
digits. Each chapter contributes its checks (``magbench.chapters``); those that
disagree are the errata, which the book's errata page renders through
:func:`magbench.chapters.errata`. The chapter tests list, independently of this module,
which checks are expected to disagree: those become strict xfail tests asserting the
printed value, the rest ordinary reference-value tests.
"""

import dataclasses

from .compare import Comparison, verdict
from .units import SI_FACTORS

__all__ = ["source_check", "printed_check", "kovalenko_page", "classified", "is_last_digit_rounding",
           "CHECK_BASES", "SEVERITIES", "HAND_TABLE_PRECISION"]

#: Where the compared ("printed") value of a check comes from.
CHECK_BASES = {
    "printed": "printed value: a number the source prints, with the digits it prints",
    "evaluated": "evaluated from a printed formula: the source prints the formula (or a count of figures), "
                 "the number is ours, from its formula and its own inputs",
}

#: How much a disagreeing check matters, most serious first.
SEVERITIES = {
    "conclusion": "changes a conclusion or a design: a wrong sign, a missing factor or a wrong formula whose "
                  "result the source uses",
    "downstream": "slip with downstream effect: a wrong number the source goes on to use",
    "contained": "slip without downstream effect: a wrong number or formula nothing else in the source "
                 "depends on",
    "rounding": "last-digit rounding: the printed value is off by at most one unit of its last printed digit",
    "lost": "lost or garbled in the source: the transcription cannot decide what was printed",
}

#: Relative precision at which a table the source computed by hand is judged: the spread
#: of such tables about their own formulas, 0.6 % in Kovalenko's Table 2 (its n = 1 entry
#: at R + 1000 km against the (R/r)^6 scaling of its own entry at R) and 0.2–1.4 % in the
#: computed column of his Table 5 against (9.25). Half a unit of the last printed digit
#: would ask a 1975 slide-rule table for more than its method gave.
HAND_TABLE_PRECISION = 0.015

def source_check(*, id, chapter, source, location, quantity, printed, computed, tolerance, unit,
                 explanation, computation):
    """A printed value beside the value computed from the source's own inputs.

    ``printed``, ``computed`` and ``tolerance`` are in the display unit ``unit``; the
    check agrees when |printed − computed| ≤ tolerance.
    """
    printed, computed = float(printed), float(computed)
    return Comparison(id=id, quantity=quantity, source=source, measured=printed, uncertainty=None,
                      unit=unit, model=computed, difference=computed - printed, tolerance=float(tolerance),
                      verdict=verdict(printed - computed, tolerance), note=explanation, chapter=chapter,
                      location=location, computation=computation, scale=SI_FACTORS.get(unit, 1.0))


def printed_check(row, *, id, chapter, location, computed, explanation, computation, quantity=None,
                  unit=None, scale=1.0):
    """A check of a printed value read from the source's data (``printed.csv``).

    The printed value, its tolerance (half a unit of its last printed digit) and its
    source come from ``row`` (a :class:`magbench.io.Measurement`), never from code.

    Parameters
    ----------
    row : magbench.io.Measurement
        The printed value with its provenance and ``resolution``.
    computed : float
        What the source's own formula and inputs give, in the display unit.
    unit : str, optional
        Display unit. The row's printed unit (the default) shows the value as printed;
        any other unit shows its SI value times ``scale`` (``100`` for a fraction in %).
    """
    if unit is None or unit == row.unit:
        printed, tolerance = row.value_as_printed, row.resolution
    else:
        printed, tolerance = row.value * scale, row.resolution_si * abs(scale)
    return source_check(id=id, chapter=chapter, source=row.source, location=location,
                        quantity=quantity or row.quantity, printed=printed, computed=computed,
                        tolerance=tolerance, unit=unit or row.unit, explanation=explanation,
                        computation=computation)


def kovalenko_page(seed_line):
    """The printed page of a line of the Kovalenko transcription (one line per page).

    The page number is the line's last token: line N is page N − 1 up to line 115 and
    page N from line 116 on (an unnumbered page before it), per the seed's README.
    """
    return seed_line - 1 if seed_line <= 115 else seed_line


def is_last_digit_rounding(check):
    """Whether a printed value is off by at most one unit of its last printed digit.

    A printed check's tolerance is half a unit of its last digit, so this is
    |printed − computed| ≤ 2·tolerance; a check about a formula (tolerance 0) never is.
    """
    return check.tolerance > 0 and abs(check.measured - check.model) <= 2.0 * check.tolerance * (1 + 1e-12)


def classified(check, basis, severity=None, *, precision=None, section=""):
    """The check with its basis, severity and discussing section set.

    Parameters
    ----------
    basis : str
        A key of :data:`CHECK_BASES`.
    severity : str or None
        For a check that disagrees, a key of :data:`SEVERITIES`; ``None`` lets the
        last-digit rule decide (:func:`is_last_digit_rounding`) and is refused for any
        other disagreement. An agreeing check has no severity.
    precision : float, optional
        Relative precision of the source's method (``HAND_TABLE_PRECISION`` for a table
        computed by hand): the tolerance becomes at least ``precision · |computed|``.
    """
    if basis not in CHECK_BASES:
        raise ValueError(f"check {check.id}: basis must be one of {', '.join(CHECK_BASES)}, got {basis!r}")
    if severity is not None and severity not in SEVERITIES:
        raise ValueError(f"check {check.id}: severity must be one of {', '.join(SEVERITIES)}, got {severity!r}")
    if precision is not None:
        if not 0 < precision < 0.1:
            raise ValueError(f"check {check.id}: precision must lie in (0, 0.1), got {precision!r}")
        tolerance = max(check.tolerance, precision * abs(check.model))
        check = dataclasses.replace(check, tolerance=tolerance,
                                    verdict=verdict(check.measured - check.model, tolerance))
    if check.agrees:
        severity = ""
    elif severity is None:
        if not is_last_digit_rounding(check):
            raise ValueError(f"check {check.id} disagrees beyond its last printed digit "
                             f"({check.measured:g} vs {check.model:g} {check.unit}): declare its severity, "
                             f"one of {', '.join(SEVERITIES)}")
        severity = "rounding"
    elif severity == "rounding" and not is_last_digit_rounding(check):
        raise ValueError(f"check {check.id}: 'rounding' is for a value within one unit of its last printed "
                         f"digit, but {check.measured:g} vs {check.model:g} {check.unit} is not")
    return dataclasses.replace(check, basis=basis, severity=severity, section=section)
