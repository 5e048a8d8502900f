"""Time the build loop of one commit: three cold `make book`, three warm, three `make test`.

    .venv/bin/python benchmarks/build_times.py [--runs 3] [--out benchmarks/results/build.json]

Run it in a clean clone with ``.venv`` already created (``make env``) and nothing else
running: a *cold* build starts with no execution cache, no result cache and no Sphinx
environment (``_build`` emptied but for the venv-independent lock); a *warm* build is a
second ``make book`` with nothing changed; ``make test`` always starts from scratch. Each
run records its wall time, the stage times ``make`` printed (``tools/stages.py``), the
1-minute load average before and after, and, for cold builds, each page's execution
time. The record names the commit, the machine and the date.
"""

import argparse
import datetime
import json
import os
import platform
import shutil
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent


def _stages(log):
    path = ROOT / log
    if not path.is_file():
        return {}
    return {name: float(seconds) for name, seconds, _ in
            (line.split("\t") for line in path.read_text(encoding="utf-8").splitlines() if line)}


def _run(kind, command, stage_log):
    before = os.getloadavg()[0]
    start = time.perf_counter()
    subprocess.run(command, cwd=ROOT, check=True, stdout=subprocess.DEVNULL)
    seconds = time.perf_counter() - start
    record = {"kind": kind, "seconds": round(seconds, 1), "stages": _stages(stage_log),
              "load_average_1min_before": round(before, 2), "load_average_1min_after": round(os.getloadavg()[0], 2)}
    print(f"{kind:6s} {seconds:7.1f} s  {record['stages']}", flush=True)
    return record


def _cold():
    for name in ("results", ".jupyter_cache", ".doctrees", "html", ".fingerprint", "stages.log"):
        path = ROOT / "_build" / name
        if path.is_dir():
            shutil.rmtree(path)
        elif path.exists():
            path.unlink()


def _machine():
    model = next((line.split(":", 1)[1].strip() for line in Path("/proc/cpuinfo").read_text().splitlines()
                  if line.startswith("model name")), platform.processor())
    memory = next((int(line.split()[1]) / 2**20 for line in Path("/proc/meminfo").read_text().splitlines()
                   if line.startswith("MemTotal")), None)
    return {"platform": platform.platform(), "cpu": model, "cpu_count": os.cpu_count(),
            "memory_gib": round(memory, 1) if memory else None, "python": platform.python_version()}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--out", default=str(ROOT / "benchmarks" / "results" / "build.json"))
    args = parser.parse_args()
    commit = subprocess.run(["git", "rev-parse", "HEAD"], cwd=ROOT, capture_output=True, text=True).stdout.strip()
    dirty = bool(subprocess.run(["git", "status", "--porcelain", "--untracked-files=no"], cwd=ROOT,
                                capture_output=True, text=True).stdout.strip())
    runs = []
    for _ in range(args.runs):
        _cold()
        runs.append(_run("cold", ["make", "book"], "_build/stages.log"))
        runs[-1]["page_seconds"] = json.loads((ROOT / "_build" / "page-seconds.json").read_text())
        runs.append(_run("warm", ["make", "book"], "_build/stages.log"))
    for _ in range(args.runs):
        runs.append(_run("test", ["make", "test"], "_build/test/stages.log"))
    record = {"benchmark": "build", "commit": commit, "worktree_modified": dirty,
              "date": datetime.datetime.now(datetime.timezone.utc).isoformat(timespec="seconds"),
              "machine": _machine(), "runs": runs,
              "summary": {kind: {"min": min(r["seconds"] for r in runs if r["kind"] == kind),
                                 "max": max(r["seconds"] for r in runs if r["kind"] == kind)}
                          for kind in ("cold", "warm", "test")}}
    Path(args.out).write_text(json.dumps(record, indent=2) + "\n", encoding="utf-8")
    print(f"recorded in {args.out}: {record['summary']}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
