"""Execute the book's pages on every core, into the execution cache the build reads.

Jupyter Book executes the pages one after the other while Sphinx reads them. This step
runs before it, in a pool of worker processes (one per core), in three phases:

1. *results*: when the result cache is on (``$MAGBENCH_RESULT_CACHE``), every figure's
   numbers and every chapter's rows and checks are computed into it, each as its own
   task. These are the expensive results; the figure is a finer unit of work than the
   page (a chapter of nine long figures would otherwise hold one core alone).
2. *pages*: each page whose code is not already in the execution cache is executed
   (reading those results) and stored in that cache (jupyter-cache, keyed on the page's
   code cells, as myst-nb keys it), so that ``jupyter-book build`` finds it executed.
3. *summary pages*: the landing page and the Findings part, which gather every
   chapter's rows and checks, after all the others.

Within a phase the longest task goes first (the last run's times, kept in
``_build/page-seconds.json``; in a fresh clone, the times committed in
``tools/task-seconds.json``, measured on the project's 2-core machine: a hint for the
order only, never a result). A page that fails is reported here and left out of the
cache: the build then executes it once more and fails with its traceback, as it would
have without this step.

Prints one line per executed page with its time, the time of the results phase, and
the total.
"""

import argparse
import concurrent.futures
import json
import multiprocessing
import os
import sys
import time
from pathlib import Path

import yaml

ROOT = Path(__file__).resolve().parent.parent


def toc_pages(toc_path):
    """The pages of ``_toc.yml`` as (path, part caption), the root first."""
    toc = yaml.safe_load(Path(toc_path).read_text(encoding="utf-8"))
    pages = [(toc["root"], None)]

    def walk(entries, caption):
        for entry in entries or []:
            if "file" in entry:
                pages.append((entry["file"], caption))
            walk(entry.get("sections"), caption)

    for part in toc.get("parts", []):
        walk(part.get("chapters"), part.get("caption"))
    return [(ROOT / f"{name}.md", caption) for name, caption in pages]


#: Task times [s] to order the first run in a fresh clone by (a later run uses its own).
HINTS = ROOT / "tools" / "task-seconds.json"

#: Pages that gather what the chapters computed: executed after every other page.
SUMMARY_PARTS = (None, "Findings")


def _read(path):
    from myst_nb.core.read import read_myst_markdown_notebook

    return read_myst_markdown_notebook(path.read_text(encoding="utf-8"), add_source_map=True, path=str(path))


#: What every kernel prints to its stderr on start and shutdown (ipykernel 7), not news.
KERNEL_NOISE = ("Kernel is running over TCP without encryption", "KeyboardInterrupt caught in kernel")


def _execute(path, timeout):
    """Run in a worker: execute the page in its folder; returns (notebook, seconds, error
    text, what the kernel wrote to its stderr other than :data:`KERNEL_NOISE`)."""
    import tempfile

    from jupyter_cache.executors.utils import single_nb_execution

    # The kernel inherits this process's stderr: catch it, pass on what is not noise.
    with tempfile.TemporaryFile() as caught:
        saved = os.dup(2)
        os.dup2(caught.fileno(), 2)
        try:
            result = single_nb_execution(_read(path), cwd=str(path.parent), timeout=timeout, allow_errors=False)
        finally:
            os.dup2(saved, 2)
            os.close(saved)
        caught.seek(0)
        lines = caught.read().decode("utf-8", "replace").splitlines()
    stderr = "\n".join(line for line in lines if line.strip() and not any(n in line for n in KERNEL_NOISE))
    return result.nb, result.time, result.exc_string, stderr


def page_parameters(figure_id):
    """The parameters a chapter's page gives a figure: its chapter's (with the overrides of
    ``$MAGBENCH_PARAMS``) that the figure takes, over the figure's source defaults. The
    results phase computes each figure so, and the page then finds exactly that result;
    a page that passes other values computes its own (nothing is wrong, only done twice)."""
    from magbench import chapters, figures

    spec = figures.get_spec(figure_id)
    owner = next(c.key for c in chapters.CHAPTERS if spec.compute.__module__ in c.figure_modules)
    return {name: value for name, value in chapters.chapter_parameters(owner).items() if name in spec.parameters}


def _result(kind, key):
    """Run in a worker: compute one expensive result into the result cache (a figure's
    numbers, or a chapter's rows and checks with the studies behind them); returns
    (seconds, error text or None)."""
    start = time.perf_counter()
    try:
        if kind == "figure":
            from magbench import figures

            figures.compute(key, **page_parameters(key))
        else:
            from magbench import chapters

            chapters.comparisons(key)
            chapters.source_checks(key)
    except Exception as exc:             # the page that needs it fails with the traceback
        return time.perf_counter() - start, f"{type(exc).__name__}: {exc}"
    return time.perf_counter() - start, None


def _result_tasks():
    from magbench import chapters, figures

    return ([(_result, ("figure", fid), f"figure {fid}") for fid in figures.figure_ids()]
            + [(_result, ("chapter", spec.key), f"rows and checks {spec.key}") for spec in chapters.CHAPTERS])


def _read_times(path):
    try:
        return json.loads(Path(path).read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return {}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cache", required=True, help="the build's execution cache (jupyter-cache folder)")
    parser.add_argument("--toc", default=str(ROOT / "_toc.yml"))
    parser.add_argument("--jobs", type=int, default=os.cpu_count() or 1, help="worker processes (default: cores)")
    parser.add_argument("--timeout", type=int, default=600, help="seconds per cell (as _config.yml)")
    parser.add_argument("--times", default=str(ROOT / "_build" / "page-seconds.json"),
                        help="each page's last execution time [s], read to schedule and updated (JSON)")
    args = parser.parse_args()

    from jupyter_cache import get_cache
    from jupyter_cache.base import CacheBundleIn

    cache = get_cache(args.cache)
    last = _read_times(args.times) or _read_times(HINTS)
    todo = []
    for path, caption in toc_pages(args.toc):
        try:
            cache.match_cache_notebook(_read(path))
        except KeyError:
            todo.append((path, caption in SUMMARY_PARTS))
    if not todo:
        print("execute: every page is in the execution cache")
        return 0
    name = {path: path.relative_to(ROOT).as_posix() for path, _ in todo}
    phases = [("pages", [(_execute, (path, args.timeout), name[path]) for path, late in todo if not late]),
              ("summary pages", [(_execute, (path, args.timeout), name[path]) for path, late in todo if late])]
    if os.environ.get("MAGBENCH_RESULT_CACHE") and phases[0][1]:
        phases.insert(0, ("results", _result_tasks()))
    print(f"execute: {len(todo)} page(s) on {args.jobs} worker(s)", flush=True)
    start, failed = time.perf_counter(), []
    context = multiprocessing.get_context("spawn")
    with concurrent.futures.ProcessPoolExecutor(args.jobs, mp_context=context) as pool:
        for phase, tasks in phases:
            # Longest first (the last run's times); a task never timed counts as long.
            tasks.sort(key=lambda task: -last.get(task[2], float("inf")))
            phase_start = time.perf_counter()
            futures = {pool.submit(function, *arguments): label for function, arguments, label in tasks}
            for future in concurrent.futures.as_completed(futures):
                label = futures[future]
                if phase == "results":
                    seconds, error = future.result()
                    last[label] = round(seconds, 1)
                    if error:
                        print(f"  {label}: {error} (its page re-runs it and shows why)", flush=True)
                    continue
                notebook, seconds, error, stderr = future.result()
                last[label] = round(seconds, 1)
                if stderr:
                    print(stderr, file=sys.stderr, flush=True)
                if error:
                    failed.append(label)
                    print(f"  FAILED   {label} after {seconds:.1f} s (the build re-runs it and shows why)", flush=True)
                    continue
                path = ROOT / label
                cache.cache_notebook_bundle(CacheBundleIn(notebook, str(path), data={"execution_seconds": seconds}),
                                            check_validity=False, overwrite=True)
                print(f"  executed {label:38s} {seconds:6.1f} s", flush=True)
            if phase == "results":
                slowest = sorted(tasks, key=lambda task: -last[task[2]])[:3]
                print(f"  results: {len(tasks)} computed into the result cache in "
                      f"{time.perf_counter() - phase_start:.1f} s wall time (longest: "
                      + ", ".join(f"{t[2]} {last[t[2]]:.1f} s" for t in slowest) + ")", flush=True)
    Path(args.times).parent.mkdir(parents=True, exist_ok=True)
    Path(args.times).write_text(json.dumps(last, indent=1, sort_keys=True) + "\n", encoding="utf-8")
    print(f"execute: {len(todo) - len(failed)} page(s) in {time.perf_counter() - start:.1f} s wall time"
          + (f"; {len(failed)} failed: {', '.join(failed)}" if failed else ""), flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
