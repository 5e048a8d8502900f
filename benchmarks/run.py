"""Run every benchmark script in this folder (each prints its own ratios against a peer)."""

import runpy
import sys
from pathlib import Path

here = Path(__file__).resolve().parent
scripts = sorted(p for p in here.glob("bench_*.py"))
if not scripts:
    print("no benchmarks yet")
for script in scripts:
    print(f"== {script.name}")
    runpy.run_path(str(script), run_name="__main__")
sys.exit(0)
