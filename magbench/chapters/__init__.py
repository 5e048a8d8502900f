"""The chapters of the book, in order, and everything that walks them.

Each chapter is one module here that owns its inputs, the modules of its figures, its
model-vs-measurement rows and its source checks (see :class:`Chapter`). Adding a chapter
is a new module and one line in :data:`CHAPTERS`; the figure registry,
``magbench compare``, the errata page, the parameter overrides and the tests walk this
list and need no other change.
"""

from . import (ch01_earth_field, ch02_field_simulator, ch03_magnetorquers, ch04_mockup, ch05_detumbling, ch06_rotor,
               ch07_tns0, ch08_field_stabilisation, ch09_unloading)
from ._base import OVERRIDES_ENV, Chapter, chapter_parameters, read_overrides

__all__ = ["CHAPTERS", "Chapter", "OVERRIDES_ENV", "chapter", "chapter_parameters", "read_overrides",
           "comparisons", "source_checks", "errata", "row_kind", "figure_modules", "caption_name", "source_name",
           "dispersion_studies", "dispersion_study"]

#: The chapters in book order.
CHAPTERS = [
    ch01_earth_field.CHAPTER,
    ch02_field_simulator.CHAPTER,
    ch03_magnetorquers.CHAPTER,
    ch04_mockup.CHAPTER,
    ch05_detumbling.CHAPTER,
    ch06_rotor.CHAPTER,
    ch07_tns0.CHAPTER,
    ch08_field_stabilisation.CHAPTER,
    ch09_unloading.CHAPTER,
]


def chapter(key):
    """The :class:`Chapter` with ``key``; an unknown key raises ``KeyError`` listing the keys."""
    for spec in CHAPTERS:
        if spec.key == key:
            return spec
    raise KeyError(f"unknown chapter {key!r}; known: {', '.join(c.key for c in CHAPTERS)}")


def dispersion_studies():
    """Every chapter's dispersion studies (:mod:`magbench.sim.dispersion`), by name, in book order."""
    return {study.name: study for spec in CHAPTERS for study in spec.dispersions}


def dispersion_study(name):
    """The dispersion study called ``name``; an unknown name raises ``KeyError`` listing the studies."""
    studies = dispersion_studies()
    if name not in studies:
        raise KeyError(f"unknown study {name!r}; known: {', '.join(studies)}")
    return studies[name]


def caption_name(key):
    """"Chapter 2, the field simulator": the chapter's number in book order and short title."""
    for number, spec in enumerate(CHAPTERS, 1):
        if spec.key == key:
            return f"Chapter {number}, {spec.short_title}"
    return chapter(key).key      # raises KeyError listing the keys


def source_name(source):
    """How the book cites a source by its data key ("thesis", "Kovalenko (1975)"), as the
    chapters that check it declare it; an undeclared key is returned unchanged."""
    for spec in CHAPTERS:
        for key, name in spec.source_names:
            if key == source:
                return name
    return source


def _selected(key):
    return CHAPTERS if key is None else [chapter(key)]


def _match(entries, item_id):
    """The first entry of ``(id or "prefix-", *values)`` that names ``item_id``, or None."""
    for entry in entries:
        prefix = entry[0]
        if item_id == prefix or (prefix.endswith("-") and item_id.startswith(prefix)):
            return entry
    return None


def _section(spec, item_id):
    entry = _match(spec.discussed_in, item_id)
    return entry[1] if entry else ""


def comparisons(key=None):
    """Every model-vs-measurement row (of one chapter, or of all), in book order, each
    with its kind (:data:`magbench.compare.ROW_KINDS`) and the section discussing it."""
    import dataclasses

    from ..result_cache import disk_cached

    return [dataclasses.replace(row, kind=_row_kind(spec, row), chapter=row.chapter or spec.key,
                                section=_section(spec, row.id))
            for spec in _selected(key) if spec.comparisons for row in disk_cached(_rows, spec.key)]


def _rows(key):
    # A module-level function of the chapter's key: the result cache's key. The rows'
    # inputs (the chapter's parameters, $MAGBENCH_PARAMS) are in the cache's fingerprint.
    return chapter(key).comparisons()


def source_checks(key=None):
    """Every printed-vs-computed check (of one chapter, or of all), in book order, each
    classified as its chapter declares (:func:`magbench.errata.classified`): printed or
    evaluated, and, when it disagrees, how much it matters.

    A check its chapter does not classify raises ``KeyError``.
    """
    from ..errata import HAND_TABLE_PRECISION, classified

    checks = []
    for spec in _selected(key):
        for provider in spec.source_checks:
            for check in provider():
                entry = _match(spec.check_classes, check.id)
                if entry is None:
                    raise KeyError(f"source check {check.id!r} has no class; add it to the check_classes "
                                   f"of chapter {spec.key}: (id, 'printed' or 'evaluated', severity or None)")
                _, basis, severity, *method = entry
                precision = HAND_TABLE_PRECISION if method == ["hand table"] else None
                checks.append(classified(check, basis, severity, precision=precision,
                                         section=_section(spec, check.id)))
    return checks


def errata(key=None):
    """The checks whose printed value disagrees with the computation: the errata."""
    return [c for c in source_checks(key) if not c.agrees]


def _row_kind(spec, row):
    from ..compare import ROW_KINDS

    entry = _match(spec.row_kinds, row.id)
    if entry is None or entry[1] not in ROW_KINDS:
        raise KeyError(f"compare row {row.id!r} has no kind; add it to its chapter's row_kinds "
                       f"as one of {', '.join(ROW_KINDS)}")
    return entry[1]


def row_kind(row):
    """The kind of value a row's ``measured`` column holds: a key of
    :data:`magbench.compare.ROW_KINDS`, as the row's chapter declares it.

    A row that no chapter classifies raises ``KeyError``: every new row must say what
    it compares with.
    """
    if row.kind:
        return row.kind
    spec = next((spec for spec in CHAPTERS if _match(spec.row_kinds, row.id)), CHAPTERS[0])
    return _row_kind(spec, row)            # an unclassified row raises, naming the kinds


def figure_modules():
    """The modules that register every chapter's figures, in book order."""
    return [name for spec in CHAPTERS for name in spec.figure_modules]
