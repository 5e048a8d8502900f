"""Check that a built book is complete and shows what it claims to show.

Fails (exit 1, listing every problem) unless:

* every page of the toc exists and no notebook of this build failed;
* every registered figure is an image (``<img>`` or inline ``<svg>``) inside the same
  figure element as its provenance caption (``[<id>] made by``), and the image file
  exists and is not blank (a single colour);
* no page shows the text ``<Figure size`` (a figure glued as its text repr: the first
  version of the book showed 38 of them and passed a caption-only check);
* no cell whose input is hidden or removed shows a plain-text or stream output (a stray
  printed return value between paragraphs);
* no page shows raw Markdown table text (``|---|``), i.e. a table that did not render.

Prints one line per page: figures shown, equations, tables.
"""

import json
import re
import sys
from pathlib import Path

import yaml

from magbench import figures

ROOT = Path(__file__).resolve().parent.parent
HIDDEN_INPUT_TAGS = ("tag_remove-input", "tag_hide-input")
RAW_TABLE = re.compile(r"\|\s*:?-{3,}:?\s*\|")


def chapter_files():
    """Every page of the toc: the root, each part's chapters and their nested sections."""
    toc = yaml.safe_load((ROOT / "_toc.yml").read_text())

    def walk(entries):
        for entry in entries:
            if "file" in entry:
                yield entry["file"]
            yield from walk(entry.get("sections", []))

    return [toc["root"]] + [f for part in toc.get("parts", []) for f in walk(part.get("chapters", []))]


def image_is_blank(path):
    """True when the image has a single colour (or cannot be read as an image)."""
    from PIL import Image

    try:
        with Image.open(path) as image:
            extrema = image.convert("RGB").getextrema()
    except OSError:
        return True
    return all(low == high for low, high in extrema)


#: A number like 6.2e-41 in the reader's text (code is exempt): prose writes a·10ⁿ.
E_NOTATION = re.compile(r"(?<![\w.])\d+(?:\.\d+)?e[-+]?\d+(?![\w.])")
#: A commit id or content hash as the provenance lines write them.
HEX_ID = re.compile(r"\b(?:commit|sha256) [0-9a-f]{7,64}\b")
#: Working labels of the transcription that mean nothing to a reader.
INTERNAL_LABEL = re.compile(r"seed line|seed text|inventory gap|\bTH-[A-Za-z0-9]+|\bgap G\d+|[(,] ?L\d{2,4}\b")


#: The developer's voice: a dotted path into the library, words of the project's own
#: working documents. Code, and text marked as provenance, are exempt.
DEVELOPER_WORDS = re.compile(r"\bmagbench\.[A-Za-z_][\w.]*|\bholdout\b|\bshared reference\b")


def developer_names():
    """A pattern of the names only a developer knows: the chapters' parameter keys, the
    figures' parameter names and the error budget's source names (snake_case), and the
    ids of rows and checks."""
    import functools

    @functools.cache
    def pattern():
        import tomllib

        from magbench import chapters, figures
        from magbench.io import DATA_DIR

        names = {name for spec in chapters.CHAPTERS for name in spec.inputs}
        names |= set(tomllib.loads((DATA_DIR / "bench" / "error_sources.toml").read_text(encoding="utf-8")))
        names |= {name for fid in figures.figure_ids() for name in figures.get_spec(fid).parameters}
        names = {n for n in names if "_" in n}        # one-word names ("duration") are English
        ids = {entry[0].rstrip("-") for spec in chapters.CHAPTERS
               for entry in (*spec.row_kinds, *spec.check_classes) if "-" in entry[0].rstrip("-")}
        words = sorted(names | ids, key=len, reverse=True)
        return re.compile(r"(?<![\w-])(?:" + "|".join(map(re.escape, words)) + r")(?![\w])")

    return pattern()


#: A LaTeX command left in the text: math that did not render (a "$" lost, or a line of a
#: formula that Markdown read as a list item).
RAW_LATEX = re.compile(r"\\(?:[a-zA-Z]{2,})\b|\$\\")


def _prose_text(main, *, without_math=False):
    """The page's text without code: source cells, code blocks and inline code."""
    import copy

    main = copy.copy(main)
    for node in main.select("div.cell_input, pre, code, .provenance"
                            + (", div.math, span.math, .MathJax, mjx-container, script" if without_math else "")):
        node.decompose()
    # Commit ids and content hashes are hex: "5861051e3259" is not a number in e-notation.
    return HEX_ID.sub("", main.get_text(" "))


def check_page(name, page_path, html_dir):
    """Problems of one built page, and its counts (figures shown, equations, tables)."""
    from bs4 import BeautifulSoup

    soup = BeautifulSoup(page_path.read_text(encoding="utf-8"), "html.parser")
    main = soup.find("main") or soup
    text = main.get_text(" ")
    problems = []
    prose = _prose_text(main)
    for pattern, what in ((E_NOTATION, "a number in e-notation"), (INTERNAL_LABEL, "an internal label")):
        for match in pattern.finditer(prose):
            snippet = " ".join(prose[max(0, match.start() - 30):match.end() + 20].split())
            problems.append(f"{name}: {what} in the text: …{snippet}…")
    bare = _prose_text(main, without_math=True)
    for pattern, what in ((DEVELOPER_WORDS, "the developer's voice (a library path or a working word)"),
                          (developer_names(), "the developer's voice (a parameter key or an entry id)")):
        for match in pattern.finditer(bare):
            snippet = " ".join(bare[max(0, match.start() - 30):match.end() + 20].split())
            problems.append(f"{name}: {what} in the text: …{snippet}…")
    for match in RAW_LATEX.finditer(bare):
        snippet = " ".join(bare[max(0, match.start() - 30):match.end() + 30].split())
        problems.append(f"{name}: unrendered LaTeX in the text: …{snippet}…")
    if "<Figure size" in text:
        problems.append(f"{name}: a figure is shown as its text repr ('<Figure size …')")
    if RAW_TABLE.search(text):
        problems.append(f"{name}: raw Markdown table text ('|---|'): a table did not render")
    for cell in main.select("div.cell"):
        tags = cell.get("class", [])
        if not any(tag in tags for tag in HIDDEN_INPUT_TAGS):
            continue
        for output in cell.select("div.cell_output div.output"):
            classes = output.get("class", [])
            if "text_plain" in classes or "stream" in classes:
                snippet = " ".join(output.get_text().split())[:60]
                problems.append(f"{name}: a hidden-input cell prints {snippet!r}")
    shown = {}
    for figure in main.select("figure"):
        caption = figure.find("figcaption")
        match = re.search(r"\[([a-z0-9-]+)\] made by", caption.get_text(" ") if caption else "")
        if not match:
            continue
        figure_id = match.group(1)
        images = figure.select("img") + figure.select("svg")
        if not images:
            problems.append(f"{name}: figure {figure_id} has a caption but no image")
            continue
        for image in figure.select("img"):
            source = (page_path.parent / image.get("src", "")).resolve()
            if not source.is_file() or html_dir.resolve() not in source.parents:
                problems.append(f"{name}: figure {figure_id}: image {image.get('src')!r} is missing")
            elif image_is_blank(source):
                problems.append(f"{name}: figure {figure_id}: image {image.get('src')!r} is blank")
        shown[figure_id] = name
    for table in main.select("table"):
        if table.find("caption") is None:
            first = " ".join(table.get_text(" ").split())[:50]
            problems.append(f"{name}: a table without a caption ({first!r})")
    footer = soup.select_one("p.magbench-provenance")
    if footer is None or "requirements.lock sha256" not in footer.get_text():
        problems.append(f"{name}: no build provenance line (commit, date, lock-file hash) in the footer")
    if main.select("div.cell"):
        problems += _download_problems(name, soup, page_path, html_dir, expect_images=bool(shown))
    counts = {"figures": len(shown),
              "equations": len(main.select("div.math")) + len(main.select("span.math")),
              "tables": len(main.select("table"))}
    return problems, shown, counts


def _download_problems(name, soup, page_path, html_dir, expect_images):
    """An executed page offers its executed notebook, with its outputs, for download."""
    link = soup.find("a", href=re.compile(r"_sources/.*\.ipynb$"))
    if link is None:
        return [f"{name}: no .ipynb download"]
    notebook = (page_path.parent / link["href"]).resolve()
    if not notebook.is_file() or html_dir.resolve() not in notebook.parents:
        return [f"{name}: the .ipynb download {link['href']!r} is missing"]
    cells = json.loads(notebook.read_text(encoding="utf-8"))["cells"]
    outputs = [o for c in cells for o in c.get("outputs", [])]
    if not outputs:
        return [f"{name}: the .ipynb download has no outputs (not the executed notebook)"]
    if expect_images and not any("image/png" in o.get("data", {}) for o in outputs):
        return [f"{name}: the .ipynb download has none of the page's figures"]
    return []


#: The landing page's headline states its counts by class: each of these must appear
#: with its number.
HEADLINE_CLASSES = (r"\d+ are errors that change a conclusion or a design",
                    r"\d+ are\s+slips the source goes on to use",
                    r"\d+ are slips nothing\s+depends on",
                    r"\d+ differ only in the last printed digit",
                    r"Against measurements\s+\d+ of \d+ rows agree",
                    r"\d+ further rows are consistency checks")


def check_chapter_parts(errata_html, intro_html, errata_keys, chapter_keys):
    """Problems of the pages that walk CHAPTERS: the errata page's summary table must link
    each chapter with source checks, the landing page's chapter table must link every
    chapter, and the landing page's headline must state its counts by class."""
    problems = []
    summary = re.search(r'<table[^>]*id="errata-summary".*?</table>', errata_html, re.S)
    if summary is None:
        problems.append("errata page has no errata-summary table")
    else:
        problems += [f"errata page's summary does not list {key}" for key in errata_keys
                     if f'href="{key}' not in summary.group(0) and f'#{key}"' not in summary.group(0)]
    table = re.search(r'<table[^>]*id="chapters-table".*?</table>', intro_html, re.S)
    if table is None:
        return problems + ["landing page has no chapters-table"]
    problems += [f"landing page's chapter table does not link {key}" for key in chapter_keys
                 if f'href="book/{key}' not in table.group(0) and f'#{key}"' not in table.group(0)]
    text = " ".join(re.sub(r"<[^>]+>", " ", intro_html).split())
    problems += [f"landing page's headline lacks a count by class: /{pattern}/" for pattern in HEADLINE_CLASSES
                 if not re.search(pattern, text)]
    return problems


def main(html_dir):
    html = Path(html_dir)
    problems = []
    shown = {}
    lines = []
    for name in chapter_files():
        page = html / f"{name}.html"
        if not page.is_file():
            problems.append(f"missing page {page}")
            continue
        page_problems, page_shown, counts = check_page(name, page, html)
        problems += page_problems
        shown.update(page_shown)
        lines.append(f"  {name:32s} {counts['figures']:3d} figures  {counts['equations']:4d} equations  "
                     f"{counts['tables']:3d} tables")
    from magbench import chapters

    errata_page, intro_page = html / "book" / "errata.html", html / "book" / "intro.html"
    if errata_page.is_file() and intro_page.is_file():
        problems += check_chapter_parts(errata_page.read_text(encoding="utf-8"), intro_page.read_text(encoding="utf-8"),
                                        [c.key for c in chapters.CHAPTERS if c.source_checks],
                                        [c.key for c in chapters.CHAPTERS])
    reports = list((html / "reports").glob("**/*.err.log")) if (html / "reports").exists() else []
    problems += [f"execution failure logged in {r}" for r in reports]
    for figure_id in figures.figure_ids():
        if figure_id not in shown:
            problems.append(f"figure {figure_id} is registered but not shown as an image with its caption")
    print("\n".join(lines))
    if problems:
        print("book check failed:\n  " + "\n  ".join(problems))
        return 1
    print(f"book check: {len(lines)} pages, {len(shown)} of {len(figures.figure_ids())} figures shown "
          "as images, no execution failures")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1] if len(sys.argv) > 1 else "_build/html"))
