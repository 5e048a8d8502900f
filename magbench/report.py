"""Helpers for the book's chapters: figures with provenance captions, glued numbers,
and tables of model-vs-measurement rows and source checks.

This module sits on top of the library (it imports figures, compare and errata) and
is the only place that knows about myst-nb's ``glue``.
"""

from pathlib import Path

__all__ = ["provenance", "figure", "glue_number", "compare_table", "checks_table", "benchmark_result"]


def provenance():
    """One line naming what produced the page: library version and content hashes.

    Hashes of content, not a commit id: a cached page stays correct when only
    unrelated files change, and changes whenever the library or the data do.
    """
    import hashlib

    from . import __version__
    from .data import DATA_DIR

    library = hashlib.sha256()
    for path in sorted(Path(__file__).resolve().parent.rglob("*.py")):
        library.update(path.read_bytes())
    manifest = hashlib.sha256((DATA_DIR / "SHA256SUMS").read_bytes()).hexdigest()[:12]
    return (f"magbench {__version__} (library sha256 {library.hexdigest()[:12]}, "
            f"data manifest sha256 {manifest})")


def figure(figure_id, **params):
    """Render a registered figure, glue it and its provenance caption; return the data.

    The chapter shows it with a ``{glue:figure}`` directive named after the id, whose
    caption includes ``{glue:text}`<id>-provenance``` so the rendered caption names the
    figure id, the function and the parameters that differ from the defaults.
    """
    import matplotlib.pyplot as plt
    from myst_nb import glue

    from . import figures

    fig, data = figures.render(figure_id, **params)
    glue(figure_id, fig, display=False)
    glue(f"{figure_id}-provenance", figures.caption_provenance(figure_id, data.parameters),
         display=False)
    plt.close(fig)
    return data


def glue_number(key, value):
    """Glue a number for ``{glue:text}`key:format``` in prose; returns the value.

    numpy scalars are glued as Python numbers: their repr (``np.float64(…)``) would
    otherwise reach the text and defeat the format spec.
    """
    import numpy as np
    from myst_nb import glue

    if isinstance(value, np.generic) or (isinstance(value, np.ndarray) and value.ndim == 0):
        value = value.item()
    glue(key, value, display=False)
    return value


def compare_table(rows):
    """A pandas DataFrame of :class:`magbench.compare.CompareRow` objects for display."""
    import pandas as pd

    return pd.DataFrame([{
        "quantity": r.quantity, "source": r.source, "measured": f"{r.measured:.5g}",
        "model": f"{r.model:.5g}", "difference": f"{r.difference:+.3g}",
        "tolerance": f"{r.tolerance:.2g}", "unit": r.unit, "verdict": r.verdict} for r in rows],
        index=[r.id for r in rows])


def checks_table(checks):
    """A pandas DataFrame of :class:`magbench.errata.SourceCheck` objects for display."""
    import pandas as pd

    return pd.DataFrame([{
        "quantity": c.quantity, "where": c.location, "printed": f"{c.printed:.5g}",
        "computed": f"{c.computed:.5g}", "tolerance": f"{c.tolerance:.2g}", "unit": c.unit,
        "verdict": "reproduces" if c.agrees else "does not reproduce"} for c in checks],
        index=[c.id for c in checks])


def benchmark_result(name):
    """The record of the last ``make bench`` run of ``benchmarks/bench_<name>.py``.

    Returns the dict written by ``benchmarks/run.py``: ``date``, ``machine`` and the
    script's own ``result``. The book quotes speed-ups from these committed records
    rather than timing code during the build, where other load would distort them.
    """
    import json

    path = Path(__file__).resolve().parents[1] / "benchmarks" / "results" / f"{name}.json"
    if not path.exists():
        raise FileNotFoundError(f"no benchmark record {path}; run `make bench` first")
    return json.loads(path.read_text(encoding="utf-8"))
