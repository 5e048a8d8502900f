"""Every printed number the project checks, across chapters.

Each chapter's test module (``tests/chapters/test_<chapter module>.py``) lists the
errata it expects, independently of the library, and runs its printed-value checks;
here what holds across chapters.
"""

import importlib
from pathlib import Path

from magbench.chapters import CHAPTERS, source_checks

HERE = Path(__file__).resolve().parent


def test_check_ids_are_unique():
    ids = [c.id for c in source_checks()]
    assert len(set(ids)) == len(ids)


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
