"""Chapter parameters and whole-book overrides."""

import os

import numpy as np
import pytest
from numpy.testing import assert_allclose

from magbench.io import DataError
from magbench.params import chapter_parameters


def test_defaults_are_si():
    p = chapter_parameters("ch01", overrides="")
    assert_allclose(p["earth_dipole_moment"], 8.1e22, rtol=1e-15)     # 8.1e25 emu
    assert_allclose(p["geomagnetic_pole_longitude"], np.radians(-69.0), rtol=1e-15)
    assert_allclose(p["orbit_altitude"], 1.0e6, rtol=0)


def test_overrides_file(tmp_path, monkeypatch):
    path = tmp_path / "o.toml"
    path.write_text("[all]\nearth_dipole_moment = 8.0e22\n[ch01]\norbit_altitude = 5e5\n")
    monkeypatch.setenv("MAGBENCH_PARAMS", str(path))
    p = chapter_parameters("ch01")
    assert p["earth_dipole_moment"] == 8.0e22 and p["orbit_altitude"] == 5e5


@pytest.mark.parametrize("text, match", [
    ("[ch01]\nno_such = 1\n", "no parameter 'no_such'"),
    ("[ch99]\nx = 1\n", r"unknown section \[ch99\]"),
    ("[ch01]\norbit_altitude = 'high'\n", "must be a number"),
    ("[ch01]\norbit_altitude = nan\n", r"o.toml: \[ch01\] orbit_altitude must be finite, got nan"),
    ("[all]\norbit_altitude = -inf\n", r"o.toml: \[all\] orbit_altitude must be finite, got -inf"),
])
def test_bad_overrides(tmp_path, text, match):
    path = tmp_path / "o.toml"
    path.write_text(text)
    with pytest.raises(DataError, match=match):
        chapter_parameters("ch01", overrides=path)


def test_unknown_chapter():
    with pytest.raises(KeyError, match="ch01"):
        chapter_parameters("ch42")


def _parameter_cell_names(page):
    """Names assigned in a page's cell tagged ``parameters`` (``_``-prefixed helpers aside)."""
    import ast
    import re
    from pathlib import Path

    text = (Path(__file__).resolve().parent.parent / f"{page}.md").read_text(encoding="utf-8")
    cell = re.search(r"```\{code-cell\}[^\n]*\n:tags: \[[^\]]*parameters[^\]]*\]\n(.*?)```", text, re.S)
    if cell is None:
        return None
    tree = ast.parse(cell.group(1))
    return {t.id for node in tree.body if isinstance(node, ast.Assign) for t in node.targets
            if isinstance(t, ast.Name) and not t.id.startswith("_")}


def test_parameters_cells_name_exactly_the_chapters_inputs():
    """A reader (or papermill) overrides a chapter through its parameters cells: together
    they must name every input of the chapter, and nothing else."""
    from magbench.chapters import CHAPTERS

    for spec in CHAPTERS:
        cells = {page: _parameter_cell_names(page) for page in spec.pages}
        assert cells[spec.pages[0]] is not None, f"{spec.pages[0]} has no parameters cell"
        named = set().union(*(names for names in cells.values() if names))
        for page, names in cells.items():
            assert names is None or names <= set(spec.inputs), (page, sorted(names - set(spec.inputs)))
        assert named == set(spec.inputs), (spec.key, sorted(set(spec.inputs) - named))


def test_suite_ignores_the_callers_parameter_file(tmp_path):
    # `make test PARAMS=…` (or a shell with $MAGBENCH_PARAMS set) must not change what the
    # tests see: the doctest of chapter_parameters reads the defaults even then.
    import subprocess
    import sys
    from pathlib import Path

    root = Path(__file__).resolve().parent.parent
    bad = tmp_path / "bad.toml"
    bad.write_text("[ch01]\nearth_radius = 1.0\n", encoding="utf-8")
    env = dict(os.environ, MAGBENCH_PARAMS=str(bad))
    run = subprocess.run([sys.executable, "-m", "pytest", "-q", "-p", "no:cacheprovider",
                          "magbench/chapters/_base.py"], cwd=root, env=env, capture_output=True, text=True)
    assert run.returncode == 0, run.stdout[-2000:]
