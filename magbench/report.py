"""Helpers for the book's chapters: figures as images with provenance captions, glued
numbers and quantities, and captioned tables of model-vs-measurement rows and source
checks.

This module sits on top of the library (it imports figures, compare and errata) and
is the only place that knows about myst-nb's ``glue``.
"""

import math
import re
from pathlib import Path

from ._format import format_number

__all__ = ["provenance", "figure", "figure_png", "glue_number", "glue_text", "glue_quantity",
           "format_number", "format_quantity", "format_percent", "display_unit", "printed_text", "printed_quantity",
           "format_with_uncertainty", "format_range", "linked", "written_quantity", "compared_value", "row_verdict", "source_value",
           "table", "compare_table", "checks_table", "benchmark_result", "concordance_entries", "reader_title",
           "FIGURE_DPI", "CSS_PIXELS_PER_INCH"]

#: Resolution of the PNG files in the book: twice the CSS pixel density, so figures
#: stay sharp on high-density screens; they are shown at their CSS size.
FIGURE_DPI = 200
#: CSS pixels per inch of figure size (a 7 in wide figure is shown 700 px wide).
CSS_PIXELS_PER_INCH = 100


def provenance():
    """One line naming what produced the page: library version and content hashes.

    Hashes of content, not a commit id: a cached page stays correct when only
    unrelated files change, and changes whenever the library or the data do.
    """
    from . import __version__
    from .result_cache import library_digests

    library, manifest = library_digests()
    return (f"magbench {__version__} (library sha256 {library[:12]}, "
            f"data manifest sha256 {manifest[:12]})")


def figure_png(fig):
    """PNG bytes of a matplotlib figure and its CSS display width [px].

    Rendering goes straight through the Agg canvas, whatever backend is active, so no
    environment variable (``MPLBACKEND``) can turn a figure into its text repr.
    Metadata are fixed (no software version or date), so the bytes depend only on the
    drawing.
    """
    import io

    from matplotlib.backends.backend_agg import FigureCanvasAgg

    buffer = io.BytesIO()
    FigureCanvasAgg(fig)        # attaches an Agg canvas to the figure, replacing the backend's
    fig.savefig(buffer, format="png", dpi=FIGURE_DPI, metadata={"Software": None})
    width_px = round(fig.get_figwidth() * CSS_PIXELS_PER_INCH)
    return buffer.getvalue(), width_px


def figure(figure_id, **params):
    """Render a registered figure, glue it as a PNG image and its caption provenance.

    The chapter shows it with a ``{glue:figure}`` directive named after the id, whose
    caption includes ``{glue:text}`<id>-provenance``` so the rendered caption names the
    figure id, the function and the parameters that differ from the defaults.
    Returns the figure's data.
    """
    import matplotlib.pyplot as plt
    from IPython.display import Image
    from myst_nb import glue

    from . import figures

    fig, data = figures.render(figure_id, **params)
    png, width = figure_png(fig)
    plt.close(fig)
    glue(figure_id, Image(data=png, format="png", width=width), display=False)
    glue(f"{figure_id}-provenance", figures.caption_provenance(figure_id, data.parameters),
         display=False)
    return data


def glue_number(key, value):
    """Glue a number for ``{glue:text}`key:format``` in prose.

    numpy scalars are glued as Python numbers: their repr (``np.float64(…)``) would
    otherwise reach the text and defeat the format spec. Returns nothing, so a cell
    that ends with it prints nothing.
    """
    import numpy as np
    from myst_nb import glue

    if isinstance(value, np.generic) or (isinstance(value, np.ndarray) and value.ndim == 0):
        value = value.item()
    glue(key, value, display=False)


def glue_text(key, text):
    """Glue a string for ``{glue:text}`key``` (a formatted quantity, a name)."""
    from myst_nb import glue

    glue(key, str(text), display=False)


_UNITS = {"uT": "µT", "ohm": "Ω", "Ohm": "Ω", "A m^2": "A·m²", "m^2": "m²", "kg m^2": "kg·m²",
          "N m/kg": "N·m/kg", "N m": "N·m", "deg": "°", "1": "",
          "kg/m^3": "kg/m³", "A/m^2": "A/m²", "m/s^2": "m/s²"}


_SUPERSCRIPTS = str.maketrans("0123456789-", "⁰¹²³⁴⁵⁶⁷⁸⁹⁻")


def display_unit(unit):
    """A unit as a reader writes it: ``uT`` → µT, ``A m^2`` → A·m², ``ohm`` → Ω.

    Compound units are written factor by factor: a space between factors becomes a
    middle dot and integer powers become superscripts.

    >>> display_unit("ohm kg/m^2")
    'Ω·kg/m²'
    >>> display_unit("kg/(N m)")
    'kg/(N·m)'
    >>> display_unit("uT per A m^2")
    'µT per A·m²'
    """
    if unit in _UNITS:
        return _UNITS[unit]
    if " per " in unit:
        return " per ".join(display_unit(part) for part in unit.split(" per "))
    text = re.sub(r"\^(-?\d+)", lambda m: m.group(1).translate(_SUPERSCRIPTS), unit)
    text = re.sub(r"\bohm\b", "Ω", text).replace("uT", "µT")
    return re.sub(r"(?<=\S) (?=\S)", "·", text)


def format_quantity(value, unit="", digits=3, *, uncertainty=None):
    """``format_number(value) unit`` with the unit as a reader writes it (no space before °).

    A unit with a power-of-ten factor (``1e22 A m^2``) is folded into the number
    (8.03·10²² A·m²); an uncertainty is written before the unit (12.5 ± 1.0 Ω).

    >>> format_quantity(8.028, "1e22 A m^2", 4)
    '8.028·10²² A·m²'
    >>> format_quantity(12.5, "ohm", 3, uncertainty=1.0)
    '12.5 ± 1.0 Ω'
    """
    factor = re.match(r"^1e([+-]?\d+)\s+(.*)$", unit)
    if factor:
        scale = 10.0 ** int(factor.group(1))
        value, unit = value * scale, factor.group(2)
        uncertainty = None if uncertainty is None else uncertainty * scale
    unit = display_unit(unit)
    number = format_number(value, digits)
    if uncertainty is not None:
        number = f"{number} ± {format_number(uncertainty, 2)}"
    if not unit:
        return number
    return f"{number}{unit}" if unit in ("°", "%") else f"{number} {unit}"


def format_percent(fraction, digits=2):
    """A relative difference as a percentage with a sign: 0.0123 → ``+1.2 %``."""
    fraction = float(fraction)
    sign = "+" if fraction > 0 else ("−" if fraction < 0 else "")
    return f"{sign}{format_number(abs(fraction) * 100.0, digits)} %"


def glue_quantity(key, value, unit="", digits=3):
    """Glue ``format_quantity(value, unit, digits)`` as text for ``{glue:text}`key```."""
    glue_text(key, format_quantity(value, unit, digits))


def printed_text(value, tolerance):
    """A printed value with the digits the source printed.

    Printed-value tolerances are half a unit of the last printed digit, so the number
    of printed decimals follows from the tolerance: 0.130 with tolerance 0.0005 is
    shown as ``0.130``, not ``0.13``. Other tolerances fall back to 4 significant digits.

    >>> printed_text(0.13, 0.0005)
    '0.130'
    >>> printed_text(258.0, 0.5)
    '258'
    """
    value, tolerance = float(value), float(tolerance)
    if tolerance > 0:
        unit = math.log10(2.0 * tolerance)
        if abs(unit - round(unit)) < 1e-9 and -12 <= round(unit) <= 12:
            decimals = max(-round(unit), 0)
            if abs(value) < 1e5 and (abs(value) >= 1e-3 or value == 0):
                text = f"{abs(value):.{decimals}f}"
                return ("−" if value < 0 else "") + text
            mantissa_digits = max(math.floor(math.log10(abs(value))) - round(unit) + 1, 1)
            return format_number(value, mantissa_digits)
    return format_number(value, 4)


def _cell(value):
    """One list-table cell: single-line MyST text that cannot start a list by accident."""
    text = " ".join(str(value).split()) or "–"
    text = re.sub(r"^%", r"\\%", text)             # a leading % starts a MyST comment
    return re.sub(r"^(\d+)([.)]) ", r"\1\\\2 ", re.sub(r"^([-+*]) ", r"\\\1 ", text))


def printed_quantity(value, tolerance, unit=""):
    """:func:`printed_text` with its unit as a reader writes it (``−71.6°``, ``0.130 Oe``)."""
    unit = display_unit(unit)
    text = printed_text(value, tolerance)
    if not unit:
        return text
    return f"{text}{unit}" if unit in ("°", "%") else f"{text} {unit}"


def table(frame, caption, *, label=None, wide_columns=(), widths=None):
    """A captioned, numbered table for a remove-input cell, as a MyST ``list-table``.

    ``frame`` is a pandas DataFrame whose cells are already formatted text (MyST
    markup such as ``{ref}`` links and ``$math$`` is allowed); its index is not shown
    (make the key a column). ``label`` makes the table a target for ``{numref}``;
    ``wide_columns`` are given more room than the others unless ``widths`` (relative
    column widths) is given. The book renders Markdown outputs as MyST
    (``nb_render_markdown_format: myst``), so this becomes a real table.
    """
    from IPython.display import Markdown

    columns = list(frame.columns)
    if widths is None:
        widths = [3 if c in wide_columns else 2 for c in columns]
    lines = [f":::{{list-table}} {_cell(caption)}", ":header-rows: 1", ":class: magbench-table",
             f":widths: {' '.join(str(int(w)) for w in widths)}"]
    if label:
        lines.append(f":name: {label}")
    lines.append("")
    for record in [columns] + [list(r) for r in frame.itertuples(index=False)]:
        lines.append("* - " + "\n  - ".join(_cell(v) for v in record))
    return Markdown("\n".join(lines) + "\n:::\n")


def format_with_uncertainty(value, uncertainty, unit=""):
    """A value and its uncertainty with the digits the uncertainty supports.

    The uncertainty keeps one significant digit (two when its first is 1) and the value
    is rounded to the same decimal place: 12.5 ± 1.5 Ω, not 12.50 ± 1.5 Ω.

    >>> format_with_uncertainty(12.5, 1.5, "ohm")
    '12.5 ± 1.5 Ω'
    >>> format_with_uncertainty(4259.5, 192.4, "s")
    '4260 ± 190 s'
    """
    uncertainty = abs(float(uncertainty))
    if not math.isfinite(uncertainty) or uncertainty == 0:
        return format_quantity(value, unit, 4)
    exponent = math.floor(math.log10(uncertainty))
    if int(uncertainty / 10.0 ** exponent) < 2:      # a leading 1 keeps a second digit
        exponent -= 1
    decimals = max(-exponent, 0)

    def rounded(x):
        x = round(float(x), -exponent)
        return (f"{abs(x):.{decimals}f}", "−" if x < 0 else "")

    number, sign = rounded(value)
    text = f"{sign}{number} ± {rounded(uncertainty)[0]}"
    unit = display_unit(unit)
    if not unit:
        return text
    return f"{text}{unit}" if unit in ("°", "%") else f"{text} {unit}"


def format_range(low, high, unit=""):
    """A range read from words, low–high, with the digits such a reading has.

    >>> format_range(10, 15, "deg")
    '10–15°'
    >>> format_range(20.0, 90.0, "rpm")
    '20–90 rpm'
    """
    def short(x):
        return f"{float(x):.3g}".replace("-", "−")

    unit = display_unit(unit)
    text = f"{short(low)}–{short(high)}"
    if not unit:
        return text
    return f"{text}{unit}" if unit in ("°", "%") else f"{text} {unit}"


def compared_value(row):
    """The value a row compares with, as a reader should see it.

    A verbal claim is shown as the range read from the words; a value with a stated
    uncertainty with the digits that uncertainty supports; a value a person or a source
    wrote down (a measurement, a claim, a design value, a read-off) with the digits it
    was written with; a reference with four significant digits.
    """
    from .chapters import row_kind

    kind = row_kind(row)
    if kind == "verbal":
        half = row.uncertainty or row.tolerance
        return format_range(row.measured - half, row.measured + half, row.unit)
    if row.uncertainty:
        return format_with_uncertainty(row.measured, row.uncertainty, row.unit)
    if kind in ("reference", "consistency"):
        return format_quantity(row.measured, row.unit, 4)
    return written_quantity(row.measured, row.tolerance, row.unit)


def written_quantity(value, tolerance, unit=""):
    """A value a person or a source wrote down: with its written digits when the tolerance
    is half a unit of them (:func:`printed_quantity`), else with at most four significant
    digits and no trailing zeros (262 A/m, not 262.0 A/m).

    >>> written_quantity(262.0, 12.2, "A/m")
    '262 A/m'
    >>> written_quantity(0.13, 0.0005, "Oe")
    '0.130 Oe'
    """
    text = printed_text(value, tolerance)
    if printed_text(value, 0.0) == text:        # no digit information in the tolerance
        text = f"{float(value):.4g}".replace("-", "−")
        if "e" in text:
            text = format_number(value, 4)
    unit = display_unit(unit)
    if not unit:
        return text
    return f"{text}{unit}" if unit in ("°", "%") else f"{text} {unit}"


def row_verdict(row):
    """"agrees"/"disagrees", or for a consistency check "consistent"/"not consistent"."""
    from .chapters import row_kind

    if row_kind(row) == "consistency":
        return "consistent" if row.agrees else "not consistent"
    return row.verdict


def linked(text, section):
    """``text`` as a link to the book section labelled ``section`` (plain text if none)."""
    if not section:
        return text
    if re.search(r"[_<>`*\\]", text):
        # A role's title is not Markdown: an underscore or a bracket would be lost or
        # misread there, so the text stays plain and an arrow links the section.
        return f"{text} ({{ref}}`→ <{section}>`)"
    return f"{{ref}}`{text} <{section}>`"


def compare_table(rows, caption="Model beside measurement", *, label=None, kind=None):
    """A captioned table of model-vs-measurement :class:`magbench.compare.Comparison` rows.

    Columns: quantity (with the row's source, linked to the section that discusses it),
    the value compared with, model, difference, tolerance, verdict. With ``kind`` (a key
    of :data:`magbench.compare.ROW_KINDS`) every row must be of that kind and the second
    column is headed by the kind ("measured", "reference", "claimed", …); a row of
    another kind raises ``ValueError``, so no row is filed under another kind's column.
    Without it, the column is "compared with" and each value names its kind.
    """
    import pandas as pd

    from .chapters import row_kind
    from .compare import ROW_KINDS

    if kind is not None:
        if kind not in ROW_KINDS:
            raise ValueError(f"kind must be one of {', '.join(ROW_KINDS)}, got {kind!r}")
        misfiled = [r.id for r in rows if row_kind(r) != kind]
        if misfiled:
            raise ValueError(f"rows {', '.join(misfiled)} are not of kind {kind!r}: they cannot be shown under "
                             f"the column {ROW_KINDS[kind][0]!r}")
        heading = ROW_KINDS[kind][0]
    else:
        heading = "compared with"

    def against(r):
        text = compared_value(r)
        return text if kind is not None else f"{ROW_KINDS[row_kind(r)][0]}: {text}"

    frame = pd.DataFrame([{
        "quantity": linked(f"{r.quantity} ({r.source})", r.section),
        heading: against(r),
        "model": format_quantity(r.model, r.unit, 4),
        "difference": ("+" if r.difference > 0 else "") + format_quantity(r.difference, r.unit, 3),
        "tolerance": format_quantity(r.tolerance, r.unit, 2),
        "verdict": row_verdict(r)} for r in rows])
    return table(frame, caption, label=label, wide_columns=("quantity",))


def checks_table(checks, caption="Printed values beside the computation", *, label=None):
    """A captioned table of printed-value checks (:class:`magbench.compare.Comparison`).

    Printed values keep the source's printed digits (:func:`printed_text`); a value we
    evaluated from a printed formula says so.
    """
    import pandas as pd

    frame = pd.DataFrame([{
        "quantity": c.quantity, "where": c.location,
        "the source": source_value(c),
        "computed": format_quantity(c.computed, c.unit, 4),
        "verdict": "reproduces" if c.agrees else "does not reproduce"} for c in checks])
    return table(frame, caption, label=label, wide_columns=("quantity", "where"))


def source_value(check):
    """The source's side of a check: the printed value with its printed digits, or, for
    a value evaluated from a printed formula, that value marked as ours."""
    if getattr(check, "basis", "") == "evaluated":
        return f"{written_quantity(check.printed, 0.0, check.unit)} (evaluated from its formula)"
    return printed_quantity(check.printed, check.tolerance, check.unit)


def benchmark_result(name, directory=None):
    """The record of the last ``make bench`` run of ``benchmarks/bench_<name>.py``.

    Returns the dict written by ``benchmarks/run.py``: ``date``, ``machine`` and the
    script's own ``result``. The book quotes speed-ups from these committed records
    rather than timing code during the build, where other load would distort them.

    The records belong to the repository, not to the installed package: ``directory``
    defaults to ``benchmarks/results`` of the checkout the book is built from, found
    from the working directory upwards.
    """
    import json

    if directory is None:
        here = Path.cwd().resolve()
        candidates = [p / "benchmarks" / "results" for p in (here, *here.parents)]
        directory = next((c for c in candidates if c.is_dir()), None)
        if directory is None:
            raise FileNotFoundError(f"no benchmarks/results folder in {here} or above; pass the folder of "
                                    "the benchmark records (a magbench checkout's benchmarks/results)")
    path = Path(directory) / f"{name}.json"
    if not path.exists():
        raise FileNotFoundError(f"no benchmark record {path}; run `make bench` first")
    return json.loads(path.read_text(encoding="utf-8"))


#: How each source is named in the figures' citations (``FigureSpec.source``): a pattern
#: of the name, which the concordance removes to leave the place in the source.
SOURCE_CITATIONS = {
    "thesis": r"Bui \(2016\),?\s*(?:thesis\s*)?",
    "kovalenko": r"Kovalenko \(1975\),?\s*",
    "samsat": r"(?:Kramlikh & Melnik \(2016\),?\s*)?SamSat-218D,?\s*",
    "rotor": r"(?:ours, beyond the\s*)?rotor slides(?: \(Ovchinnikov, Pen'kov, Roldugin, Tkachev\))?,?\s*",
    "tns0": r"TNS-0 preprint(?: \(Ilyin et al\. 2006\))?,?\s*",
}


def _top_level_split(text, sep=";"):
    """``text`` split at ``sep`` outside parentheses."""
    parts, depth, current = [], 0, ""
    for char in text:
        depth += (char == "(") - (char == ")")
        if char == sep and depth == 0:
            parts.append(current)
            current = ""
        else:
            current += char
    return parts + [current]


def reader_title(title):
    """A figure title without the developer's notes on how long it takes to compute."""
    title = re.sub(r";\s*(?:slow|about \d+\s*(?:–\s*\d+\s*)?s to compute)[^);]*(?=\))", "", title)
    return re.sub(r"\s*\((?:slow|about \d+\s*(?:–\s*\d+\s*)?s to compute)[^)]*\)", "", title).strip()


def concordance_entries(source):
    """Where the book reproduces each place of a source, in reading order.

    Generated from the chapters' own citations: each chapter's ``concordance`` entries,
    then every figure whose citation names the source (its place in the source as the
    figure cites it). Returns a list of dicts with keys ``source`` (the place in the
    source), ``what`` and ``book`` (MyST markup linking the book's place).
    """
    from . import figures
    from .chapters import CHAPTERS

    name = re.compile(SOURCE_CITATIONS[source])
    entries = []
    for spec in CHAPTERS:
        linked = set()
        for key, place, what, book in spec.concordance:
            if key == source:
                entries.append({"source": place, "what": what, "book": book})
                linked |= set(re.findall(r"`([\w-]+)`", book))
        for module in spec.figure_modules:
            for figure_id in figures.figure_ids():
                figure = figures.get_spec(figure_id)
                if figure_id in linked or not figure.function_name.startswith(module + "."):
                    continue
                parts = [p.strip() for p in _top_level_split(figure.source) if name.search(p)]
                if parts:
                    beyond = parts[0].startswith("ours, beyond")
                    place = name.sub("", parts[0], count=1).strip(" ,") or "the source as a whole"
                    if beyond:
                        place = f"{place} (beyond the source: ours)".strip()
                    title = reader_title(figure.title)
                    entries.append({"source": place, "what": title, "book": f"{{numref}}`{figure_id}`"})
                    linked.add(figure_id)
    return entries


def parameter_table(chapter, namespace, *, label=None):
    """The chapter's inputs as a reader-facing table: name, value used, unit, provenance.

    ``namespace`` holds the values the page actually runs with (the page's globals after
    its ``parameters`` cell, so papermill's ``-p`` and ``$MAGBENCH_PARAMS`` show); the
    chapter's inputs the page does not define are left out. Each
    value is shown in the unit its source prints it in; the provenance column says whose
    value it is: the source's (with its section), external (a datasheet, IGRF, …) or ours
    (a modelling choice; the chapter's text gives the reason). A value as the parameter
    set has it is shown as written there; one that differs is marked "changed".
    """
    import pandas as pd

    from .chapters import chapter as chapter_spec, source_name
    from .io import load_parameter_set
    from .io.data import to_si

    spec = chapter_spec(chapter)
    params = load_parameter_set(spec.source)
    rows = []
    for name in spec.inputs:
        if name not in namespace:       # an input of the chapter that this page does not use
            continue
        p = params[name]
        used = float(namespace[name])
        if math.isclose(used, p.value_si, rel_tol=1e-12, abs_tol=0.0):
            mantissa, _, exponent = f"{p.value:g}".partition("e")
            value = mantissa.replace("-", "−")
            if exponent:
                value += "·10" + str(int(exponent)).translate(_SUPERSCRIPTS)
        else:
            value = format_number(used / to_si(1.0, p.unit)[0], 4) + " (changed)"
        if p.source in ("ours", "external"):
            whose = p.source
        else:
            whose = source_name(p.source) + (f", §{p.section}" if p.section else "")
        rows.append({"parameter": f"`{name}`", "value": value, "unit": display_unit(p.unit) or "–",
                     "whose": whose})
    frame = pd.DataFrame(rows)
    return table(frame, "The chapter's inputs: the value each computation on this page uses, and whose "
                        "value it is. Change one with papermill's -p or a parameter file (see the landing page).",
                 label=label or f"{chapter}-inputs", widths=(5, 3, 2, 4))
