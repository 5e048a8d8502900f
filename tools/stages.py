"""Time the stages of ``make book`` and ``make test`` and print them at the end.

    python tools/stages.py run LOG NAME -- COMMAND [ARG ...]   run COMMAND, log its time
    python tools/stages.py report LOG                          print the logged stages

``run`` exits with the command's status (and still logs the stage, marked failed), so
that make stops where it would have stopped without it.
"""

import subprocess
import sys
import time
from pathlib import Path


def run(log, name, command):
    start = time.perf_counter()
    status = subprocess.call(command)
    seconds = time.perf_counter() - start
    Path(log).parent.mkdir(parents=True, exist_ok=True)
    with open(log, "a", encoding="utf-8") as out:
        out.write(f"{name}\t{seconds:.1f}\t{'ok' if status == 0 else f'failed ({status})'}\n")
    if status != 0:
        print(f"stage {name} failed after {seconds:.1f} s", file=sys.stderr)
    return status


def report(log):
    rows = [line.split("\t") for line in Path(log).read_text(encoding="utf-8").splitlines() if line]
    total = sum(float(seconds) for _, seconds, _ in rows)
    width = max(len(name) for name, _, _ in rows)
    print("stage times:")
    for name, seconds, status in rows:
        s = float(seconds)
        print(f"  {name:{width}s} {int(s // 60):3d} min {s % 60:4.1f} s" + ("" if status == "ok" else f"  {status}"))
    print(f"  {'total':{width}s} {int(total // 60):3d} min {total % 60:4.1f} s")
    return 0


def main(argv):
    if len(argv) >= 4 and argv[0] == "run" and "--" in argv:
        split = argv.index("--")
        return run(argv[1], argv[2], argv[split + 1:])
    if len(argv) == 2 and argv[0] == "report":
        return report(argv[1])
    print(__doc__, file=sys.stderr)
    return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
