"""Execute the book's pages on every core, into the execution cache the build reads.

Jupyter Book executes the pages one after the other while Sphinx reads them. This step
runs before it: each page whose code is not already in the execution cache is executed
in a pool of worker processes (one per core) and stored in that cache (jupyter-cache,
keyed on the page's code cells, as myst-nb keys it), so that ``jupyter-book build``
then finds every page executed. Pages are scheduled longest first (the times of the
last run, kept in _build/page-seconds.json), and the summary pages (the landing page and the
Findings part) after every chapter: they gather the chapters' rows and checks, which
the chapters have by then left in the result cache (``$MAGBENCH_RESULT_CACHE``).

A page that fails is reported here and left out of the cache: the build then executes
it once more and fails with its traceback, as it would have without this step.

Prints one line per executed page with its time, and the total.
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
    last = _read_times(args.times)
    todo = []
    for path, caption in toc_pages(args.toc):
        try:
            cache.match_cache_notebook(_read(path))
        except KeyError:
            todo.append((path, caption in SUMMARY_PARTS))
    if not todo:
        print("execute: every page is in the execution cache")
        return 0
    # Longest first within each phase; a page never executed here counts as long.
    name = {path: path.relative_to(ROOT).as_posix() for path, _ in todo}
    todo.sort(key=lambda item: (item[1], -last.get(name[item[0]], float("inf"))))
    print(f"execute: {len(todo)} page(s) on {args.jobs} worker(s)", flush=True)
    start, failed = time.perf_counter(), []
    context = multiprocessing.get_context("spawn")
    with concurrent.futures.ProcessPoolExecutor(args.jobs, mp_context=context) as pool:
        for summaries in (False, True):
            futures = {pool.submit(_execute, path, args.timeout): path for path, late in todo if late == summaries}
            for future in concurrent.futures.as_completed(futures):
                path = futures[future]
                notebook, seconds, error, stderr = future.result()
                last[name[path]] = round(seconds, 1)
                if stderr:
                    print(stderr, file=sys.stderr, flush=True)
                if error:
                    failed.append(name[path])
                    print(f"  FAILED   {name[path]} after {seconds:.1f} s (the build re-runs it and shows why)",
                          flush=True)
                    continue
                cache.cache_notebook_bundle(CacheBundleIn(notebook, str(path), data={"execution_seconds": seconds}),
                                            check_validity=False, overwrite=True)
                print(f"  executed {name[path]:38s} {seconds:6.1f} s", flush=True)
    Path(args.times).parent.mkdir(parents=True, exist_ok=True)
    Path(args.times).write_text(json.dumps(last, indent=1, sort_keys=True) + "\n", encoding="utf-8")
    print(f"execute: {len(todo) - len(failed)} page(s) in {time.perf_counter() - start:.1f} s wall time"
          + (f"; {len(failed)} failed: {', '.join(failed)}" if failed else ""), flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
