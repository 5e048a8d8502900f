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

from .compare import Comparison, verdict
from .units import SI_FACTORS

__all__ = ["source_check", "printed_check", "kovalenko_page"]

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
