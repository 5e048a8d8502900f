"""The figure types and the registry a chapter's figure module registers into.

They live in the chapter layer so that a chapter (package) can keep its figures beside
its inputs and rows; :mod:`magbench.figures` renders them, lists them and serves the
command line.
"""

from dataclasses import dataclass, field

__all__ = ["FigureParameter", "WORK_LIMITS", "WHOLE_NUMBER_INPUTS", "Series", "FigureData", "FigureSpec", "REGISTRY",
           "register"]


@dataclass(frozen=True)
class FigureParameter:
    """One input of a figure: SI default, unit and meaning."""

    default: float
    unit: str
    description: str


#: Inputs that set a figure's amount of work, and the values a figure accepts (SI,
#: inclusive; None: no bound on that side). Each keeps one figure to minutes on one core
#: (the defaults take seconds to about a minute), so that ``--set duration=1e7`` or a
#: parameter file with a million members is refused at once, naming the range, instead of
#: running for hours. One name means one concept across the chapters, so the table is
#: keyed by name, or by (figure id, name) where one figure's cost differs; the library
#: functions behind the figures take any size.
WORK_LIMITS = {
    "orbits": (None, 50.0),
    "samples": (None, 1e5),
    "duration": (None, 1e4),
    "steps": (None, 1e5),
    "grid_points": (None, 200.0),
    "span": (None, 1e5),
    "integration_step": (0.01, None),
    "bench_duration": (None, 3600.0),
    "bench_members": (None, 2e4),
    "budget_points": (None, 20.0),
    "budget_base_samples": (None, 1024.0),
    "envelope_members": (None, 1e4),
    "envelope_duration": (None, 1e5),
    "fig2_members": (None, 100.0),
    "capture_duration": (None, 1e7),
    "capture_members": (None, 1e4),
    "full_run_duration": (None, 3e7),
    # A figure whose cost is not linear in the name's input: its own entry wins. The
    # wrong-sign damping run diverges, and the solver's steps shrink with it: 3000 s take
    # 11 s, 5000 s over 5 min (measured).
    ("rotor-damping-sign", "duration"): (None, 3000.0),
}

#: Inputs that count something (members, points, steps, turns, a seed, a code): a figure
#: refuses 1.5 instead of computing with 1 while its caption shows 1.5. Orbits are a
#: length of time (2.5 orbits is meaningful) and are not here.
WHOLE_NUMBER_INPUTS = frozenset({
    "amplitude_checks", "bench_members", "bench_pwm_levels", "bench_seed", "budget_base_samples",
    "budget_points", "budget_seed", "capture_members", "capture_seed", "coils", "envelope_members",
    "envelope_seed", "estimator", "fig2_members", "fig2_seed", "grid_points", "mtq_turns", "order",
    "row", "samples", "seed", "steps", "turns",
})


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
    listing) figures reads none; :attr:`parameters` reads them on first use.
    """

    id: str
    title: str
    source: str
    compute: object
    plot: object
    parameter_table: object     # dict name -> FigureParameter, or a function returning it

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
