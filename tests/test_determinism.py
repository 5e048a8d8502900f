"""Nothing the project writes depends on when or how often it is run: figure files are
byte-identical from run to run, and no code (library or book page) reads the clock.

A book built in 2031 must show the same numbers as one built today (IGRF-14 has no
main field after 2030, and a row dated "today" would change every year): the library
and the pages take every date from their inputs, never from the clock.
"""

import ast
from pathlib import Path

import jupytext
import pytest

from magbench.cli import main

ROOT = Path(__file__).resolve().parent.parent

#: Calls that read the wall clock (a date or a time of day).
CLOCK_CALLS = {("datetime", "now"), ("datetime", "today"), ("datetime", "utcnow"), ("date", "today"),
               ("time", "time"), ("time", "time_ns"), ("time", "localtime"), ("time", "gmtime"),
               ("time", "ctime"), ("time", "asctime"), ("time", "strftime")}
#: Durations measured on the clock: fine in benchmarks/ (which record them with the
#: machine and date), never in a page's prose, which would change from build to build.
TIMER_CALLS = {("time", "perf_counter"), ("time", "perf_counter_ns"), ("time", "monotonic"),
               ("time", "process_time")}


def _calls(tree):
    """(module or class, function, line) of every call of a ``time``/``datetime`` function,
    however imported (``import time as t``, ``from time import time``, ``dt.datetime.now``)."""
    modules, imported = {}, {}
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            for alias in node.names:
                if alias.name in ("time", "datetime"):
                    modules[alias.asname or alias.name] = alias.name
        elif isinstance(node, ast.ImportFrom) and node.module in ("time", "datetime"):
            for alias in node.names:
                imported[alias.asname or alias.name] = (node.module, alias.name)
    for node in ast.walk(tree):
        if not isinstance(node, ast.Call):
            continue
        f = node.func
        if isinstance(f, ast.Name) and f.id in imported:
            yield imported[f.id] + (node.lineno,)
        elif isinstance(f, ast.Attribute):
            owner = f.value
            if isinstance(owner, ast.Name) and owner.id in modules:          # time.time(), t.perf_counter()
                yield modules[owner.id], f.attr, node.lineno
            elif isinstance(owner, ast.Name) and owner.id in imported:       # datetime.now() after from-import
                yield imported[owner.id][1], f.attr, node.lineno
            elif isinstance(owner, ast.Attribute) and isinstance(owner.value, ast.Name) \
                    and owner.value.id in modules:                          # dt.datetime.now()
                yield owner.attr, f.attr, node.lineno


def _library_files():
    return sorted((ROOT / "magbench").rglob("*.py"))


def _page_code(path):
    notebook = jupytext.read(path, fmt="md:myst")
    source = "\n".join(c.source for c in notebook.cells if c.cell_type == "code")
    # IPython magics and shell escapes are not Python
    return "\n".join(line for line in source.splitlines() if not line.lstrip().startswith(("%", "!")))


def test_the_scan_finds_a_clock_call():
    # The detector itself: each way of reading the clock is found.
    code = ("import datetime as dt\nfrom time import time\nimport time as t\n"
            "a = dt.datetime.now()\nb = time()\nc = dt.date.today()\nd = t.perf_counter()\n")
    found = {(o, a) for o, a, _ in _calls(ast.parse(code))}
    assert found == {("datetime", "now"), ("time", "time"), ("date", "today"), ("time", "perf_counter")}


def test_library_never_reads_the_date():
    hits = [f"{p.relative_to(ROOT)}:{line} {o}.{a}()" for p in _library_files()
            for o, a, line in _calls(ast.parse(p.read_text(encoding="utf-8")))
            if (o, a) in CLOCK_CALLS]
    assert not hits, "the library reads the clock: " + "; ".join(hits)


@pytest.mark.parametrize("page", sorted(p.name for p in (ROOT / "book").glob("*.md")))
def test_pages_read_neither_date_nor_timer(page):
    tree = ast.parse(_page_code(ROOT / "book" / page))
    hits = [f"line {line} of the code: {o}.{a}()" for o, a, line in _calls(tree)
            if (o, a) in CLOCK_CALLS | TIMER_CALLS]
    assert not hits, f"{page} reads the clock: " + "; ".join(hits)


def test_compare_rows_are_the_same_after_2030(monkeypatch):
    # Every way the library could read the date, moved to mid-2031 (IGRF-14's main field
    # ends with 2030): the rows must not change.
    import datetime as dt
    import time

    from magbench import chapters, result_cache

    before = [(r.id, r.model, r.measured) for r in chapters.comparisons("ch01")]
    later = dt.datetime(2031, 6, 1, tzinfo=dt.timezone.utc)

    class Later(dt.datetime):
        @classmethod
        def now(cls, tz=None):
            return later if tz else later.replace(tzinfo=None)

        @classmethod
        def today(cls):
            return later.replace(tzinfo=None)

        @classmethod
        def utcnow(cls):
            return later.replace(tzinfo=None)

    class LaterDate(dt.date):
        @classmethod
        def today(cls):
            return later.date()

    monkeypatch.setattr(dt, "datetime", Later)
    monkeypatch.setattr(dt, "date", LaterDate)
    monkeypatch.setattr(time, "time", lambda: later.timestamp())
    with result_cache.disabled():      # computed again under the later clock, not loaded
        after = [(r.id, r.model, r.measured) for r in chapters.comparisons("ch01")]
    assert after == before


@pytest.mark.parametrize("suffix", ["svg", "pdf", "PDF", "png"])
def test_figure_file_is_the_same_at_every_run(tmp_path, suffix, capsys):
    # SVG ids are salted hashes (a random salt unless svg.hashsalt is set); PDF and SVG
    # carry a creation date unless it is removed, whatever the case of the suffix.
    files = [tmp_path / f"{k}.{suffix}" for k in (1, 2)]
    for f in files:
        assert main(["figure", "thesis-fig01", "--out", str(f)]) == 0
    first, second = (f.read_bytes() for f in files)
    assert first == second
    if suffix.lower() in ("svg", "pdf"):
        assert b"CreationDate" not in first and b"<dc:date>" not in first
