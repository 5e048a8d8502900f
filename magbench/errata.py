"""Printed numbers of the sources beside what their own formulas and inputs give.

Each :class:`SourceCheck` keeps the value as printed, computes the value that the
source's own formula and inputs (or correct physics) give, and carries the tolerance
implied by the printed digits. Each chapter contributes its checks
(``magbench.chapters``); those that disagree are the errata, which the book's errata
page renders through :func:`magbench.chapters.errata`. ``tests/test_errata.py`` lists, independently of
this module, which checks are expected to disagree: those become strict xfail tests
asserting the printed value, the rest ordinary reference-value tests.
"""

from dataclasses import dataclass

__all__ = ["SourceCheck", "kovalenko_page"]


@dataclass(frozen=True)
class SourceCheck:
    """A printed value beside the value computed from the source's own inputs."""

    id: str
    chapter: str
    source: str
    location: str
    quantity: str
    printed: float
    computed: float
    tolerance: float
    unit: str
    explanation: str
    computation: str

    @property
    def relative_difference(self):
        """(printed − computed) / |computed| [-]."""
        return (self.printed - self.computed) / abs(self.computed)

    @property
    def agrees(self):
        """Whether the printed value lies within ``tolerance`` of the computed one."""
        return abs(self.printed - self.computed) <= self.tolerance

    @classmethod
    def from_printed(cls, row, *, id, chapter, location, computed, explanation, computation, quantity=None,
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
            Display unit. The row's printed unit (the default) shows the value as
            printed; any other unit shows its SI value times ``scale`` (``100`` for a
            fraction in %).
        """
        if unit is None or unit == row.unit:
            printed, tolerance = row.value_as_printed, row.resolution
        else:
            printed, tolerance = row.value * scale, row.resolution_si * abs(scale)
        return cls(id=id, chapter=chapter, source=row.source, location=location,
                   quantity=quantity or row.quantity, printed=printed, computed=float(computed),
                   tolerance=tolerance, unit=unit or row.unit, explanation=explanation, computation=computation)


def kovalenko_page(seed_line):
    """The printed page of a line of the Kovalenko transcription (one line per page).

    The page number is the line's last token: line N is page N − 1 up to line 115 and
    page N from line 116 on (an unnumbered page before it), per the seed's README.
    """
    return seed_line - 1 if seed_line <= 115 else seed_line
