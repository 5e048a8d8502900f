"""What a chapter is, and the chapter inputs every page, figure and comparison reads.

A chapter module (``magbench/chapters/chNN_*.py``) describes itself with one
:class:`Chapter`: its key, title, book pages, the source whose parameter set holds its
inputs, the names of those inputs, the modules that register its figures, its
model-vs-measurement rows and its source checks. :data:`magbench.chapters.CHAPTERS`
lists the chapters in book order; everything that walks chapters walks that list.
"""

import math
import os
import tomllib
from dataclasses import dataclass, field
from pathlib import Path

from ..io import DataError, load_parameter_set
from .._validate import shown

__all__ = ["Chapter", "FigureInputs", "OVERRIDES_ENV", "chapter_parameters", "read_overrides", "study_parameters"]

#: Environment variable naming a TOML file of overrides for a whole-book build.
OVERRIDES_ENV = "MAGBENCH_PARAMS"


@dataclass(frozen=True)
class Chapter:
    """One chapter of the book and everything the library knows of it.

    Attributes
    ----------
    key : str
        Short id, ``"ch01"``; the section name in parameter overrides files.
    title : str
        The chapter's title, as the book names it.
    short_title : str
        A few words for table captions ("the Earth's field").
    pages : tuple of str
        The book pages of the chapter (paths without ``.md``).
    source : str
        The source whose parameter set (``magbench/data/<source>/params.toml``) holds the inputs.
    inputs : tuple of str
        Names of the chapter's inputs in that parameter set.
    figure_modules : tuple of str
        Modules that register the chapter's figures when imported.
    comparisons : callable or None
        ``(params=None) -> list[Comparison]``: the chapter's model-vs-measurement rows.
    row_kinds : tuple of (str, str)
        Row id (or id prefix ending in ``-``) and the kind of value it compares with, a key
        of :data:`magbench.compare.ROW_KINDS`.
    source_checks : tuple of callables
        Each ``() -> list[Comparison]``: printed numbers beside their computation, always
        on the source's own inputs (never on overridden parameters).
    cites : str
        What of its sources the chapter reproduces, as a reader looks it up ("thesis §1,
        eqs. (1)–(12), Figs. 1–2"); the landing page's table of chapters shows it.
    finds : str
        What the chapter finds out, in one sentence for that table.
    source_names : tuple of (str, str)
        The data key of each source the chapter checks and how the book cites it
        (``("kovalenko", "Kovalenko (1975)")``).
    check_classes : tuple of (str, str, str or None)
        Source-check id (or id prefix ending in ``-``), its basis (a key of
        :data:`magbench.errata.CHECK_BASES`) and, for a check that disagrees, its severity
        (a key of :data:`magbench.errata.SEVERITIES`).
    discussed_in : tuple of (str, str)
        Row or check id (or id prefix ending in ``-``) and the label of the book section
        that discusses it; the ledger pages link each row there.
    concordance : tuple of (str, str, str, str)
        Places of the sources the chapter reproduces: the source's data key, the place as
        the source numbers it ("§2.2, eq. (16)"), what it is, and where the book has it
        (MyST markup: ``{ref}``, ``{eq}`` or ``{numref}`` links). The concordance page is
        generated from these and from the figures' own citations.
    dispersions : tuple of DispersionStudy
        The chapter's dispersion studies (:mod:`magbench.sim.dispersion`), run by name with
        ``magbench montecarlo``.

    The chapter's first page carries the label ``(key)=``, so ``{ref}`key``` links it.
    """

    key: str
    title: str
    short_title: str
    pages: tuple
    source: str
    inputs: tuple
    figure_modules: tuple = ()
    comparisons: object = None
    row_kinds: tuple = ()
    source_checks: tuple = field(default_factory=tuple)
    cites: str = ""
    finds: str = ""
    source_names: tuple = ()
    check_classes: tuple = ()
    discussed_in: tuple = ()
    concordance: tuple = ()
    dispersions: tuple = ()


def _chapters():
    from . import CHAPTERS

    return CHAPTERS


def _chapter(key):
    for chapter in _chapters():
        if chapter.key == key:
            return chapter
    raise KeyError(f"unknown chapter {key!r}; known: {', '.join(c.key for c in _chapters())}")


def read_overrides(path):
    """Read an overrides file into ``{section: {name: value}}`` (sections ``all``, ``chNN``)."""
    path = Path(path)
    try:
        tables = tomllib.loads(path.read_text(encoding="utf-8"))
    except FileNotFoundError:
        raise DataError(f"parameter file {path} (from ${OVERRIDES_ENV}) does not exist") from None
    except tomllib.TOMLDecodeError as exc:
        raise DataError(f"{path}: {exc}") from None
    inputs = {c.key: set(c.inputs) for c in _chapters()}
    valid_sections = {"all", *inputs}
    for section, values in tables.items():
        if section not in valid_sections or not isinstance(values, dict):
            raise DataError(f"{path}: unknown section [{section}]; valid: {', '.join(sorted(valid_sections))}")
        for name, value in values.items():
            if isinstance(value, bool) or not isinstance(value, int | float):
                raise DataError(f"{path}: [{section}] {name} must be a number (SI), got {shown(value)}")
            if not math.isfinite(value):     # TOML spells them nan and inf
                raise DataError(f"{path}: [{section}] {name} must be finite, got {value!r}")
            known = set().union(*inputs.values()) if section == "all" else inputs[section]
            if name not in known:
                raise DataError(f"{path}: [{section}] has no parameter {name!r}; "
                                f"valid: {', '.join(sorted(known))}")
    return tables


def chapter_parameters(chapter, *, overrides=None):
    """SI values of a chapter's inputs.

    Parameters
    ----------
    chapter : str
        Chapter key, e.g. ``"ch01"``.
    overrides : str or Path, optional
        TOML overrides file; defaults to the file named by ``$MAGBENCH_PARAMS``, if set.

    Returns
    -------
    dict of str to float
        Parameter name to SI value, defaults from the chapter's source's parameter set.

    Examples
    --------
    >>> p = chapter_parameters("ch01", overrides=None)
    >>> round(p["earth_radius"])
    6371000
    """
    spec = _chapter(chapter)
    params = load_parameter_set(spec.source)
    values = {name: params[name].value_si for name in spec.inputs}
    path = overrides if overrides is not None else os.environ.get(OVERRIDES_ENV)
    if path:
        tables = read_overrides(path)
        for section in ("all", chapter):
            for name, value in tables.get(section, {}).items():
                if name in values:      # [all] may also name other chapters' inputs
                    values[name] = float(value)
    return values


def study_parameters(chapter, overrides=None):
    """A chapter's parameters [SI] with ``overrides`` (name → SI value) applied on top: the
    ``parameters`` of a :class:`magbench.sim.dispersion.DispersionStudy`. A name that is not
    one of the chapter's inputs raises ValueError listing them."""
    values = chapter_parameters(chapter)
    for name, value in dict(overrides or {}).items():
        if name not in values:
            raise ValueError(f"unknown parameter {name!r} of {chapter}; valid: {', '.join(sorted(values))}")
        values[name] = float(value)
    return values


class FigureInputs:
    """A chapter's inputs as its figures take them: the defaults, each input's description
    and bounds, and a figure's parameters over the defaults.

    ``inputs`` maps a parameter name to ``(description, bounds)``, ``bounds`` the keyword
    arguments of :class:`~magbench.chapters.registry.FigureParameter` (``low``, ``high``,
    ``whole``); the unit comes from the chapter's parameter set.
    """

    def __init__(self, chapter, source, inputs):
        self.chapter, self.source, self.inputs = chapter, source, dict(inputs)

    def defaults(self):
        """The chapter's parameters from its data alone (no overrides file) [SI]."""
        return chapter_parameters(self.chapter, overrides="")

    def table(self, names):
        """A function returning ``{name: FigureParameter}`` of ``names`` (a figure's
        ``parameter_table``; called on first use, so that registering reads no data)."""
        def parameters():
            from .registry import FigureParameter

            p, units = self.defaults(), load_parameter_set(self.source)
            return {name: FigureParameter(p[name], units[name].unit_si, self.inputs[name][0], **self.inputs[name][1])
                    for name in names}
        return parameters

    def merged(self, params):
        """The defaults with a figure's ``params`` over them [SI]."""
        p = self.defaults()
        p.update(params)
        return p
