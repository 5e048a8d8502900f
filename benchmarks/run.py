"""Run every benchmark script in this folder and record what each measured.

Each ``bench_<name>.py`` prints its own times and ratios against a peer measured in the
same run, and its ``main()`` returns a dict of those numbers. This runner writes that
dict, with the machine, the date and the library versions, to
``benchmarks/results/<name>.json``; the book quotes speed-ups from these files (through
``magbench.report.benchmark_result``), so every ratio in the prose comes from a run
that anyone can repeat with ``make bench``.

``python benchmarks/run.py [name ...]`` runs only the named benchmarks. The peer
benchmarks ``bench_peers_*.py`` need a peer simulator the project does not install
(Basilisk); they run only when named, as ``make bench-peers`` does.
"""

import datetime
import json
import os
import platform
import runpy
import sys
from pathlib import Path

here = Path(__file__).resolve().parent
wanted = set(sys.argv[1:])
scripts = sorted(p for p in here.glob("bench_*.py")
                 if p.stem.removeprefix("bench_") in wanted
                 or not wanted and not p.stem.startswith("bench_peers_"))
if not scripts:
    print("no benchmarks matched" if wanted else "no benchmarks yet")
for script in scripts:
    print(f"== {script.name}")
    namespace = runpy.run_path(str(script), run_name="benchmark")
    result = namespace["main"]()
    import numpy
    import scipy

    record = {
        "benchmark": script.stem.removeprefix("bench_"),
        "date": datetime.datetime.now(datetime.timezone.utc).isoformat(timespec="seconds"),
        "machine": {"platform": platform.platform(), "processor": platform.machine(),
                    "cpu_count": os.cpu_count(), "python": platform.python_version(),
                    "numpy": numpy.__version__, "scipy": scipy.__version__},
        "result": result,
    }
    out = here / "results" / f"{record['benchmark']}.json"
    out.parent.mkdir(exist_ok=True)
    out.write_text(json.dumps(record, indent=2) + "\n", encoding="utf-8")
    print(f"   recorded in {out.relative_to(here.parent)}")
sys.exit(0)
