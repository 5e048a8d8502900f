"""Clear the book's execution cache when anything the notebooks depend on has changed.

jupyter-cache keys a notebook on its code cells only; a change in the library, the
data, the lock file, the book configuration or the parameter overrides would otherwise
be served from stale cached outputs. This script hashes all of those and, when the hash
differs from the one recorded at the last build, deletes the execution cache and the
Sphinx environment (doctrees): Sphinx re-reads only changed sources, so without the
second step an unchanged chapter would keep its old outputs.
"""

import argparse
import hashlib
import shutil
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
INPUTS = ["magbench/**/*.py", "magbench/data/**/*", "benchmarks/results/*.json", "requirements.lock", "pyproject.toml", "_config.yml"]


def fingerprint():
    digest = hashlib.sha256()
    files = sorted({p for pattern in INPUTS for p in ROOT.glob(pattern) if p.is_file()
                    and "__pycache__" not in p.parts})
    for path in files:
        digest.update(path.relative_to(ROOT).as_posix().encode())
        digest.update(path.read_bytes())
    # The parameter overrides and the BROAD recordings (outside the repository: adding or
    # replacing one re-executes the pages that show them instead of serving "not found").
    from magbench.result_cache import external_inputs

    digest.update(external_inputs())
    return digest.hexdigest()


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cache", required=True, help="execution cache directory")
    parser.add_argument("--stamp", required=True, help="file recording the last fingerprint")
    parser.add_argument("--doctrees", required=True, help="Sphinx environment directory")
    parser.add_argument("--results", help="result cache folder ($MAGBENCH_RESULT_CACHE): its results "
                        "are keyed on the library already; cleared so that stale ones do not pile up")
    args = parser.parse_args()
    stamp, cache = Path(args.stamp), Path(args.cache)
    new = fingerprint()
    old = stamp.read_text().strip() if stamp.is_file() else None
    if new != old:
        for stale in (cache, Path(args.doctrees), *([Path(args.results)] if args.results else [])):
            if stale.exists():
                shutil.rmtree(stale)
        print(f"fingerprint {new[:12]} (was {old[:12] if old else 'none'}): execution cache "
              "and Sphinx environment cleared")
    else:
        print(f"fingerprint {new[:12]} unchanged: execution cache kept")
    stamp.parent.mkdir(parents=True, exist_ok=True)
    stamp.write_text(new + "\n")


if __name__ == "__main__":
    main()
