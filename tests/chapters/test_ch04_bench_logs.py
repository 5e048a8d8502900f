"""Chapter 4's bench figures and the logs in magbench/data/bench: a log is drawn on the
figure of its target (π/3, Fig. 19; 2π/3, Fig. 20), and a log whose target is neither
is named on the figures instead of vanishing. Synthetic logs in tmp_path only."""

import numpy as np

from magbench.chapters.ch04_mockup import figures_bench
from magbench.io import benchlog
from magbench.io.benchlog import COLUMNS

HEADER = ",".join(f"{name} [{unit or 'duty'}]" for name, unit in COLUMNS)


def _write(path, psi_des, n=50, dt=0.01):
    t = np.arange(n) * dt
    rows = np.column_stack([t] + [np.zeros(n)] * 5 + [np.full(n, 9.81), np.full(n, 3e-4)]
                           + [np.zeros(n)] * 2 + [np.full(n, 0.25), np.full(n, -0.5)])
    lines = ["# synthetic log written by the test", f"# psi_des: {psi_des!r}", HEADER]
    lines += [",".join(repr(float(v)) for v in r) for r in rows]
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")


def test_logs_with_other_targets_are_named_not_dropped(tmp_path, monkeypatch):
    _write(tmp_path / "a-fig19.csv", np.pi / 3)
    _write(tmp_path / "b-near.csv", np.pi / 3 + 5e-7)        # within the 1e-6 rad match
    _write(tmp_path / "c-off.csv", np.pi / 3 + 2e-6)         # beyond it: on neither figure
    _write(tmp_path / "d-fig20.csv", 2 * np.pi / 3)
    _write(tmp_path / "e-other.csv", 1.0)
    real = benchlog.load_bench_logs
    monkeypatch.setattr(benchlog, "load_bench_logs", lambda directory=None: real(tmp_path))
    drawn, unplotted = figures_bench._logs_for(np.pi / 3, 0.98)
    assert [s.label for s in drawn] == ["bench log a-fig19.csv", "bench log b-near.csv"]
    assert [name for name, _ in unplotted] == ["c-off.csv", "e-other.csv"]
    drawn, unplotted = figures_bench._logs_for(2 * np.pi / 3, 0.98)
    assert [s.label for s in drawn] == ["bench log d-fig20.csv"]
    assert [name for name, _ in unplotted] == ["c-off.csv", "e-other.csv"]
    # every log is either drawn on one of the book's two figures or named on both
    on_figures = {s.label.removeprefix("bench log ") for t in figures_bench.BENCH_TARGETS
                  for s in figures_bench._logs_for(t, 0.98)[0]}
    assert on_figures | {name for name, _ in unplotted} == {p.name for p in tmp_path.glob("*.csv")}
