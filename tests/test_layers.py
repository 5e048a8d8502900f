"""The import-layer contract of pyproject.toml ([tool.importlinter]): physics imports no
plotting, tables, data files or chapters, and nothing imports upward."""

import os
import shutil
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
LINT = Path(sys.executable).with_name("lint-imports")


def _lint(pythonpath):
    env = dict(os.environ, PYTHONPATH=str(pythonpath))
    return subprocess.run([str(LINT), "--config", str(ROOT / "pyproject.toml"), "--no-cache"],
                          capture_output=True, text=True, env=env, cwd=pythonpath)


def test_the_layers_hold():
    result = _lint(ROOT)
    assert result.returncode == 0, result.stdout + result.stderr
    assert "3 kept, 0 broken" in result.stdout


def test_the_contract_fails_on_plotting_in_physics(tmp_path):
    """A check must be able to fail: the same contract on a copy whose loop field imports
    matplotlib, and whose earth family imports a chapter, breaks both contracts."""
    shutil.copytree(ROOT / "magbench", tmp_path / "magbench", ignore=shutil.ignore_patterns("__pycache__"))
    loop = tmp_path / "magbench" / "fields" / "loop.py"
    loop.write_text("import matplotlib.pyplot\n" + loop.read_text())
    dipole = tmp_path / "magbench" / "earth" / "dipole.py"
    dipole.write_text("from ..chapters import CHAPTERS\n" + dipole.read_text())
    result = _lint(tmp_path)
    assert result.returncode != 0
    assert "1 kept, 2 broken" in result.stdout, result.stdout
    assert "magbench.fields.loop -> matplotlib" in result.stdout


def test_the_kernel_contract_fails_on_a_kernel_that_imports_scipy(tmp_path):
    shutil.copytree(ROOT / "magbench", tmp_path / "magbench", ignore=shutil.ignore_patterns("__pycache__"))
    kernel = tmp_path / "magbench" / "earth" / "kernels.py"
    kernel.write_text("import scipy.special\nfrom ..earth import circular_orbit\n" + kernel.read_text())
    result = _lint(tmp_path)
    assert "2 kept, 1 broken" in result.stdout, result.stdout
    assert "magbench.earth.kernels -> scipy" in result.stdout
    assert "magbench.earth.kernels -> magbench.earth.circular_orbit" in result.stdout
