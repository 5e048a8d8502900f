"""The build helpers: the cache fingerprint must move with library, data and overrides."""

import importlib.util
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent


def _load(name):
    spec = importlib.util.spec_from_file_location(name, ROOT / "tools" / f"{name}.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_fingerprint_tracks_library_data_and_overrides(tmp_path, monkeypatch):
    fp = _load("fingerprint")
    (tmp_path / "magbench").mkdir()
    (tmp_path / "data").mkdir()
    (tmp_path / "magbench" / "a.py").write_text("x = 1\n")
    (tmp_path / "data" / "d.csv").write_text("1\n")
    monkeypatch.setattr(fp, "ROOT", tmp_path)
    monkeypatch.delenv("MAGBENCH_PARAMS", raising=False)
    base = fp.fingerprint()
    (tmp_path / "data" / "d.csv").write_text("2\n")
    after_data = fp.fingerprint()
    (tmp_path / "magbench" / "a.py").write_text("x = 2\n")
    after_code = fp.fingerprint()
    overrides = tmp_path / "o.toml"
    overrides.write_text("[ch01]\norbit_altitude = 5e5\n")
    monkeypatch.setenv("MAGBENCH_PARAMS", str(overrides))
    after_params = fp.fingerprint()
    assert len({base, after_data, after_code, after_params}) == 4
    monkeypatch.delenv("MAGBENCH_PARAMS")
    assert fp.fingerprint() == after_code      # deterministic


def test_book_check_sees_every_page_including_sections():
    """tools/check_book.py must check nested toc sections too: every page in book/ is listed."""
    listed = set(_load("check_book").chapter_files())
    on_disk = {f"book/{p.stem}" for p in (ROOT / "book").glob("*.md")}
    assert on_disk == listed
