"""Re-run a chapter with one of its inputs scaled: its comparison rows, and the
computation and drawing of each of its figures (not the PNG encoding).

A new user who doubles a coil current or halves a sample interval must get a chapter
that says what the model concludes ("no design fits", "this hypothesis is excluded"),
not a traceback. The override goes where a whole-book parameter file would put it: the
chapter's source parameter set, read by :func:`magbench.chapters.chapter_parameters`
(rows) and by each figure's parameter table (figure defaults).

Only what can change is re-run: a figure whose resolved parameters are unchanged by the
override (and whose computation reads no chapter parameters itself) is skipped, and the
rows are skipped when their provider never reads the scaled input (tracked on a default
run). Both prunings are conservative (a copied parameter dict counts as reading every
input), so nothing that depends on the input escapes the sweep.
"""

import dataclasses
import inspect

import matplotlib.pyplot as plt

import magbench.io as _io
from magbench import chapters, figures, result_cache
from magbench.chapters import _base, registry

__all__ = ["chapter_figures", "figure_dependencies", "row_dependencies", "run_scaled"]


class _Tracking(dict):
    """A parameter dict that records which names are read (a copy reads them all)."""

    def __init__(self, values, seen):
        super().__init__(values)
        self.seen = seen

    def __getitem__(self, name):
        self.seen.add(name)
        return super().__getitem__(name)

    def get(self, name, default=None):
        self.seen.add(name)
        return super().get(name, default)

    def __iter__(self):         # dict(p), {**p}, p.items() … go through here: reads all
        self.seen.update(super().keys())
        return super().__iter__()

    def keys(self):
        self.seen.update(super().keys())
        return super().keys()

    def items(self):
        self.seen.update(super().keys())
        return super().items()

    def values(self):
        self.seen.update(super().keys())
        return super().values()

    def copy(self):
        self.seen.update(super().keys())
        return dict(super().items())


class _Scaled:
    """Context: the chapter's source parameter set with one value multiplied, and the disk
    result cache off for a figure's numbers and a chapter's rows (keyed on their arguments
    only, which the scaling does not change when they read the parameter set themselves).
    The studies keep it: each is keyed on every input it reads, so a study the scaled
    input does not touch is loaded (from the book's run or another case), not computed."""

    def __init__(self, key, name=None, factor=1.0):
        self.source = chapters.chapter(key).source
        self.name, self.factor = name, factor

    def __enter__(self):
        original = self.original = _base.load_parameter_set

        def scaled(source="thesis", data_dir=None):
            params = _io.load_parameter_set(source, data_dir)
            if self.name is not None and source == self.source:
                params = dict(params)
                par = params[self.name]
                params[self.name] = dataclasses.replace(par, value=par.value * self.factor)
            return params

        _base.load_parameter_set = scaled
        registry._PARAMETERS.clear()    # figure defaults are read from the parameter set once
        self.no_disk = result_cache.disabled(studies=False)
        self.no_disk.__enter__()
        return self

    def __exit__(self, *exc):
        self.no_disk.__exit__(*exc)
        _base.load_parameter_set = self.original
        registry._PARAMETERS.clear()


def chapter_figures(key):
    """Ids of the figures registered by the chapter's figure modules, sorted."""
    modules = set(chapters.chapter(key).figure_modules)
    return [fid for fid in figures.figure_ids() if figures.get_spec(fid).compute.__module__ in modules]


def _reads_parameters_itself(spec):
    source = inspect.getsource(spec.compute)
    return any(call in source for call in ("chapter_parameters(", "_defaults(", "load_parameter_set(", "_numbers("))


def figure_dependencies(key, name, factor):
    """Figures of the chapter whose computation can change when ``name`` is scaled."""
    with _Scaled(key):
        defaults = {fid: figures.resolve_parameters(fid) for fid in chapter_figures(key)}
    with _Scaled(key, name, factor):
        changed = {fid: figures.resolve_parameters(fid) for fid in chapter_figures(key)}
    return [fid for fid in defaults
            if changed[fid] != defaults[fid] or _reads_parameters_itself(figures.get_spec(fid))]


_ROW_READS = {}


def row_dependencies(key):
    """The inputs the chapter's rows read (a default run, tracked; cached)."""
    if key not in _ROW_READS:
        spec, seen = chapters.chapter(key), set()
        if spec.comparisons is not None:
            with _Scaled(key):
                spec.comparisons(_Tracking(chapters.chapter_parameters(key, overrides=""), seen))
        _ROW_READS[key] = seen
    return _ROW_READS[key]


def run_scaled(key, name, factor):
    """Run the parts of chapter ``key`` that depend on input ``name`` scaled by ``factor``.

    Returns the ids of what ran (``"rows"`` and figure ids); raises whatever they raise.
    """
    spec = chapters.chapter(key)
    ran = []
    todo = figure_dependencies(key, name, factor)
    rows = spec.comparisons is not None and name in row_dependencies(key)
    with _Scaled(key, name, factor):
        if rows:
            spec.comparisons(chapters.chapter_parameters(key, overrides=""))
            ran.append("rows")
        for fid in todo:
            fig, _ = figures.render(fid)
            plt.close(fig)
            ran.append(fid)
    return ran

