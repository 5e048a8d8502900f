"""Every printed number the project checks, across chapters.

Each chapter's test module (``tests/chapters/test_<chapter module>.py``) lists the
errata it expects, independently of the library, and runs its printed-value checks;
here what holds across chapters.
"""

import dataclasses
import importlib
import math
from pathlib import Path

import pytest

from magbench import errata
from magbench.chapters import CHAPTERS, source_checks
from magbench.errata import CHECK_BASES, SEVERITIES, classified, is_last_digit_rounding, source_check

HERE = Path(__file__).resolve().parent


@pytest.fixture(scope="module")
def checks():
    """Every check of the book, computed once for this module (they take a minute)."""
    return source_checks()


def test_check_ids_are_unique(checks):
    ids = [c.id for c in checks]
    assert len(set(ids)) == len(ids)


def test_every_check_is_classified(checks):
    """Each check says whether its value was printed or evaluated by us, and each that
    disagrees how much it matters; one that agrees has no severity."""
    for c in checks:
        assert c.basis in CHECK_BASES, c.id
        if c.agrees:
            assert c.severity == "", c.id
        else:
            assert c.severity in SEVERITIES, c.id
        if c.severity == "rounding":
            assert is_last_digit_rounding(c), c.id


def _data_values(source):
    """Every value the source's data files hold as printed or measured: as printed and in SI."""
    from magbench.io import DATA_DIR
    from magbench.io.data import load_measurements, load_parameter_set, load_printed

    values = []
    for loader, name in ((load_printed, "printed.csv"), (load_measurements, "measurements.csv")):
        if (DATA_DIR / source / name).is_file():
            values += [v for r in loader(source).values() for v in (r.value_as_printed, r.value_low,
                                                                     r.value_high, r.value)]
    if (DATA_DIR / source / "params.toml").is_file():
        values += [p.value_si for p in load_parameter_set(source).values()]
    return values


def test_a_printed_check_has_its_digits_in_the_data(checks):
    """A check marked *printed* compares with a number that stands in the source's data
    files (printed.csv, measurements.csv, params.toml), as printed or in SI. A number we
    evaluated from a printed formula (100.0 N·m from eq. (5), a cosine of 1) is not
    there, so marking it printed fails here. Tolerance 1e-9: the same number, read back."""
    missing = []
    for c in checks:
        if c.basis != "printed":
            continue
        values = _data_values(c.source)
        if not any(math.isclose(c.printed, v, rel_tol=1e-9) or math.isclose(c.measured_si, v, rel_tol=1e-9)
                   for v in values):
            missing.append(f"{c.id} ({c.printed:g} {c.unit})")
    assert not missing, "checks marked printed with no printed value in the data: " + ", ".join(missing)


def test_an_evaluated_number_marked_printed_is_caught(checks):
    """The test above can fail: eq. (5)'s 100.0 N·m, which the book evaluates, is not a
    data value of the thesis."""
    c = next(c for c in checks if c.id == "thesis-eq5-cgs-torque")
    values = _data_values(c.source)
    assert not any(math.isclose(c.printed, v, rel_tol=1e-9) or math.isclose(c.measured_si, v, rel_tol=1e-9)
                   for v in values)


def _check(printed, computed, tolerance):
    return source_check(id="x", chapter="ch01", source="thesis", location="§1", quantity="q", printed=printed,
                        computed=computed, tolerance=tolerance, unit="1", explanation="e", computation="c")


def test_last_digit_rule():
    """Rounding is |printed − computed| within one unit of the last printed digit (twice
    the half-unit tolerance); beyond it the severity must be declared."""
    assert classified(_check(0.62, 0.6265, 0.005), "printed").severity == "rounding"
    with pytest.raises(ValueError, match="declare its severity"):
        classified(_check(0.62, 0.64, 0.005), "printed")
    with pytest.raises(ValueError, match="'rounding' is for"):
        classified(_check(0.62, 0.64, 0.005), "printed", "rounding")
    assert classified(_check(0.62, 0.64, 0.005), "printed", "downstream").severity == "downstream"
    assert classified(_check(100.0, 1.3e-4, 0.0), "evaluated", "conclusion").severity == "conclusion"
    with pytest.raises(ValueError, match="basis must be one of"):
        classified(_check(1.0, 1.0, 0.5), "typed")


def test_hand_table_precision():
    """A hand-computed table is judged at HAND_TABLE_PRECISION of the computed value:
    Kovalenko's 0.286 Oe against 0.2875 Oe (0.5 %) agrees; 0.22 against 2.24 does not."""
    assert not _check(0.286, 0.28745, 0.0005).agrees
    assert classified(_check(0.286, 0.28745, 0.0005), "printed", precision=errata.HAND_TABLE_PRECISION).agrees
    assert not classified(_check(-0.22, -2.24, 0.005), "printed", "contained",
                          precision=errata.HAND_TABLE_PRECISION).agrees


def test_an_unclassified_check_is_refused(monkeypatch):
    """A new check without a class is refused by name, not shown unclassified."""
    from magbench import chapters

    spec = dataclasses.replace(CHAPTERS[0], check_classes=(), source_checks=(lambda: [_check(1.0, 1.0, 0.5)],))
    monkeypatch.setattr(chapters, "CHAPTERS", [spec, *CHAPTERS[1:]])
    with pytest.raises(KeyError, match="has no class"):
        chapters.source_checks("ch01")


def test_every_chapter_has_its_test_module_with_expected_errata():
    """A chapter added to CHAPTERS must come with its test module, which states the
    errata it expects (an empty dict when none)."""
    import pkgutil

    import magbench.chapters as package

    modules = {importlib.import_module(f"magbench.chapters.{info.name}").CHAPTER.key: info.name
               for info in pkgutil.iter_modules(package.__path__) if info.name.startswith("ch")}
    for spec in CHAPTERS:
        name = modules[spec.key]
        path = HERE / "chapters" / f"test_{name}.py"
        assert path.is_file(), f"{spec.key}: no {path.relative_to(HERE.parent)}"
        text = path.read_text(encoding="utf-8")
        if spec.source_checks:
            assert "EXPECTED_ERRATA = {" in text and f'CHAPTER_KEY = "{spec.key}"' in text, spec.key
