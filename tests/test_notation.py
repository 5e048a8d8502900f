"""One notation for the whole book: the notation page's table against the chapters' math.

The notation page (``book/notation.md``) holds one table: symbol, meaning, unit, the
source's symbol, and the chapters that use it. Read against the math of every chapter
page, it must hold:

* a symbol is defined once (two rows with the same symbol are two meanings);
* a chapter whose math uses a symbol of the table is listed in that symbol's row, so a
  chapter cannot use a defined letter without a reader being told it means the same;
* the letters the sources overloaded (L for torque, dipole and angular momentum; B for
  field and inertia; A; H and H₀; M; K; m; n), in every subscripted form the chapters'
  math uses, are in the table;
* no Cyrillic letter in the math: the sources' subscripts are translated.
"""

import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
BOOK = ROOT / "book"

GREEK = set("alpha beta gamma delta epsilon varepsilon zeta eta theta vartheta iota kappa lambda mu nu xi pi rho "
            "varrho sigma tau upsilon phi varphi chi psi omega Gamma Delta Theta Lambda Xi Pi Sigma Phi Psi "
            "Omega".split())
#: Letters the sources give several meanings, watched in every subscripted form.
OVERLOADED = {"L", "B", "A", "H", "M", "K", "m", "n"}
#: Component subscripts: B_x is a component of B, not a symbol of its own.
COMPONENTS = {"x", "y", "z"}

_CODE = re.compile(r"```\{code-cell\}.*?```", re.S)
_MATH = re.compile(r"\$\$(.+?)\$\$|\$(.+?)\$|```\{math\}(.*?)```", re.S)
_STRIP = re.compile(r"\\(?:mathrm|text|operatorname|mathit|mathsf|label|tag|begin|end)(?:\{[^{}]*\}|\s*[A-Za-z])"
                    r"|\{\\rm[^{}]*\}")
_WRAP = re.compile(r"\\(?:mathbf|boldsymbol|vec|bm|hat|dot|ddot|tilde|bar|overline)\s*"
                   r"(?:\{([^{}]*)\}|(\\[a-zA-Z]+|[A-Za-z]))")
_TOKEN = re.compile(r"(\\[a-zA-Z]+|[A-Za-z])(?:_(\{[^{}]*\}|\\[a-zA-Z]+|[A-Za-z0-9]))?")
_CYRILLIC = re.compile(r"[А-Яа-яЁё]")


def math_of(text):
    """The math of a MyST page: inline, display and ``{math}`` blocks; code cells left out."""
    text = _CODE.sub("", text)
    return [next(g for g in m.groups() if g is not None) for m in _MATH.finditer(text)]


def symbols(math):
    """The symbols of a formula: a Latin or Greek letter with its subscript, typeface
    commands dropped (\\mathbf L is L), text and operator names left out."""
    # A subscript in upright type is a name (ψ_des, k_d): keep it; other upright text goes.
    math = re.sub(r"_\{?\\(?:mathrm|text|rm)\s*\{([^{}]*)\}\}?", r"_{\1}", math)
    math = re.sub(r"_\{\\(?:mathrm|text|rm)\s+([A-Za-z]+)\}", r"_{\1}", math)
    math = _STRIP.sub(" ", math)
    # A calligraphic letter (the Lagrangian) is a symbol of its own, not the letter.
    math = re.sub(r"\\mathcal\s*\{?([A-Za-z])\}?", r"\\mathcal\1", math)
    math = _WRAP.sub(lambda m: m.group(1) or m.group(2), math)
    found = []
    for token in _TOKEN.finditer(math):
        base, sub = token.group(1), token.group(2)
        if base.startswith("\\") and base[1:] not in GREEK:
            continue
        sub = (sub or "").strip("{} ")
        found.append(base if not sub or sub in COMPONENTS else f"{base}_{sub}")
    return found


def notation_table():
    """Rows of the notation table: (symbols of the row, chapters column, the row's text)."""
    text = (BOOK / "notation.md").read_text(encoding="utf-8")
    rows = []
    for line in text.splitlines():
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if not line.startswith("|") or len(cells) < 5 or set(cells[0]) <= set("-: ") or cells[0] == "symbol":
            continue
        row_symbols = {s for m in math_of(cells[0]) for s in symbols(m)}
        chapters = set(re.findall(r"\d+", cells[-1]))
        for a, b in re.findall(r"(\d)–(\d)", cells[-1]):
            chapters |= {str(k) for k in range(int(a), int(b) + 1)}
        rows.append((row_symbols, chapters, line))
    return rows


def chapter_pages():
    """Chapter pages by chapter number ("4" for ch04-mockup, ch04-bench, …)."""
    pages = {}
    for path in sorted(BOOK.glob("ch[0-9][0-9]-*.md")):
        pages.setdefault(str(int(path.name[2:4])), []).append(path)
    return pages


def used_symbols():
    return {chapter: {s for p in paths for m in math_of(p.read_text(encoding="utf-8")) for s in symbols(m)}
            for chapter, paths in chapter_pages().items()}


def test_the_tokeniser_reads_the_book_s_math():
    assert symbols(r"\mathbf L = \mathbf m \times \mathbf B_0") == ["L", "m", "B_0"]
    assert symbols(r"k_{\mathrm d}\,\omega_\perp + B_x + \psi_{\mathrm{des}}") == ["k_d", "\\omega_\\perp", "B",
                                                                                  "\\psi_des"]
    assert symbols(r"\frac{\mathrm d}{\mathrm dt} \sin\theta") == ["t", "\\theta"]


def test_a_symbol_is_defined_once():
    seen = {}
    for row_symbols, _, line in notation_table():
        for symbol in row_symbols:
            assert symbol not in seen, f"{symbol} is defined twice:\n  {seen[symbol]}\n  {line}"
            seen[symbol] = line


def test_a_chapter_using_a_symbol_is_listed_with_it():
    used = used_symbols()
    missing = []
    for row_symbols, chapters, line in notation_table():
        for symbol in row_symbols:
            for chapter, found in used.items():
                if symbol in found and chapter not in chapters:
                    missing.append(f"chapter {chapter} uses {symbol} (row: {line[:60]}…)")
    assert not missing, "\n".join(missing)


def test_overloaded_letters_are_in_the_table():
    defined = {s for row_symbols, _, _ in notation_table() for s in row_symbols}
    missing = sorted({f"{s} (chapter {chapter})" for chapter, found in used_symbols().items() for s in found
                      if s.split("_")[0] in OVERLOADED and s not in defined})
    assert not missing, "symbols of overloaded letters used but not in the notation table: " + ", ".join(missing)


@pytest.mark.parametrize("path", sorted(BOOK.glob("ch[0-9][0-9]-*.md")), ids=lambda p: p.stem)
def test_no_cyrillic_in_the_math(path):
    bad = [m for m in math_of(path.read_text(encoding="utf-8")) if _CYRILLIC.search(m)]
    assert not bad, f"Cyrillic in the math of {path.name}: {bad[:3]}"
