"""The figure types and the registry a chapter's figure module registers into.

They live in the chapter layer so that a chapter (package) can keep its figures beside
its inputs and rows; :mod:`magbench.figures` renders them, lists them and serves the
command line.
"""

from dataclasses import dataclass, field

__all__ = ["FigureParameter", "count", "Series", "FigureData", "FigureSpec", "REGISTRY", "register"]


@dataclass(frozen=True)
class FigureParameter:
    """One input of a figure: SI default, unit, meaning, and the values the figure accepts.

    ``low`` and ``high`` (SI, inclusive; None: no bound on that side) bound the inputs that
    set a figure's amount of work (members, orbits, durations, grid sizes), each keeping one
    figure to minutes on one core (the defaults take seconds to about a minute), so that
    ``--set duration=1e7`` or a parameter file with a million members is refused at once,
    naming the range, instead of running for hours; the library functions behind the figures
    take any size. ``whole`` marks an input that counts something (members, points, steps,
    turns, a seed, a code): 1.5 is refused instead of computed with 1 while the caption shows
    1.5. Orbits are a length of time (2.5 orbits is meaningful) and are not whole.
    """

    default: float
    unit: str
    description: str
    low: float | None = None
    high: float | None = None
    whole: bool = False

    def check(self, figure_id, name, number):
        """``number`` if this parameter accepts it, else ``ValueError`` naming the figure, the
        parameter, the bound and the value."""
        if self.whole and number != round(number):
            raise ValueError(f"parameter {name} of {figure_id} must be a whole number, got {number:g}")
        unit = f" {self.unit}" if self.unit not in ("", "1", "-") else ""
        why = "(a figure's work is bounded to minutes; call the library for more)"
        if self.low is not None and number < self.low:
            raise ValueError(f"parameter {name} of {figure_id} must be >= {self.low:g}{unit} {why}, got {number:g}")
        if self.high is not None and number > self.high:
            raise ValueError(f"parameter {name} of {figure_id} must be <= {self.high:g}{unit} {why}, got {number:g}")
        return number


def count(default, description, *, high=None, low=None):
    """A whole-number input (members, points, steps, a seed) [-]."""
    return FigureParameter(default, "1", description, low=low, high=high, whole=True)


@dataclass
class Series:
    """One labelled set of columns: ``{name: (unit, values)}``."""

    label: str
    columns: dict


@dataclass
class FigureData:
    """The numbers behind a figure, and the parameters actually used (SI)."""

    id: str
    title: str
    source: str
    parameters: dict
    series: list = field(default_factory=list)
    extra: dict = field(default_factory=dict)   # drawing hints that are not data

    def to_json_dict(self):
        """The ``--data`` JSON shape: id, title, source, parameters, series."""
        import numpy as np

        def values(v):
            return [float(x) for x in np.ravel(np.asarray(v, dtype=float))]

        return {
            "id": self.id, "title": self.title, "source": self.source,
            "parameters": {k: float(v) for k, v in self.parameters.items()},
            "series": [{"label": s.label,
                        "columns": {name: {"unit": unit, "values": values(vals)}
                                    for name, (unit, vals) in s.columns.items()}}
                       for s in self.series],
        }


@dataclass(frozen=True)
class FigureSpec:
    """A registered figure.

    ``parameter_table`` is the figure's inputs, ``{name: FigureParameter}``, or a
    function returning it: the defaults come from data files, so registering (and
    listing) figures reads none; :attr:`parameters` reads them on first use. ``slow``
    marks a figure whose defaults take several seconds (a simulation study) or need the
    BROAD recordings: the quick test stages leave it to the slow ones.
    """

    id: str
    title: str
    source: str
    compute: object
    plot: object
    parameter_table: object     # dict name -> FigureParameter, or a function returning it
    slow: bool = False

    @property
    def parameters(self):
        """The figure's inputs, ``{name: FigureParameter}`` (SI defaults)."""
        table = self.parameter_table
        if callable(table):
            if self.id not in _PARAMETERS:
                _PARAMETERS[self.id] = table()
            return _PARAMETERS[self.id]
        return table

    @property
    def function_name(self):
        """Dotted name of the compute function (provenance)."""
        return f"{self.compute.__module__}.{self.compute.__qualname__}"


#: Figure id -> FigureSpec, filled on first use by the figure modules each chapter names
#: (:func:`magbench.chapters.figure_modules`).
REGISTRY = {}
_PARAMETERS = {}


def register(spec):
    """Add a :class:`FigureSpec` to the registry (ids must be unique)."""
    if spec.id in REGISTRY:
        raise ValueError(f"figure id {spec.id!r} is registered twice")
    REGISTRY[spec.id] = spec
    return spec
