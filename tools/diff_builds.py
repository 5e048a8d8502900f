"""Compare the numbers of two builds of the book: every glued value and every figure.

    python tools/diff_builds.py OLD_BUILD NEW_BUILD [--figure-data OLD_DIR NEW_DIR]

``OLD_BUILD`` and ``NEW_BUILD`` are Jupyter Book output folders (``_build`` or
``_build/test/_build``). Compared: each page's glued values (``jupyter_execute/**/
*.glue.json``: every number the prose shows) and each figure image (``html/_images``,
byte for byte). With ``--figure-data``, two folders of ``magbench figure ID --data``
files are compared too (every number behind every figure, exactly). The provenance
glue (library and data hashes, which change with any commit) is listed apart.

Exits 1 when anything else differs, listing it.
"""

import argparse
import hashlib
import json
import sys
from pathlib import Path

#: Glued values that name the build, not a result.
BUILD_STAMPS = ("provenance",)


def glued(build):
    """{(page, key): value} of every glued value of a build (text/plain, else first mime)."""
    values = {}
    for path in sorted(Path(build, "jupyter_execute").rglob("*.glue.json")):
        page = path.relative_to(Path(build, "jupyter_execute")).as_posix().removesuffix(".glue.json")
        for key, output in json.loads(path.read_text(encoding="utf-8")).items():
            data = output.get("data", {})
            values[(page, key)] = data.get("text/plain", json.dumps(data, sort_keys=True))
    return values


def images(build):
    """{name: sha256} of the images the HTML shows."""
    folder = Path(build, "html", "_images")
    return {p.name: hashlib.sha256(p.read_bytes()).hexdigest() for p in sorted(folder.glob("*")) if p.is_file()}


def figure_data(folder):
    return {p.stem: json.loads(p.read_text(encoding="utf-8")) for p in sorted(Path(folder).glob("*.json"))}


def _differences(kind, old, new, ignore=()):
    lines = []
    for key in sorted(set(old) | set(new), key=str):
        if any(stamp in str(key) for stamp in ignore):
            continue
        if key not in old:
            lines.append(f"{kind} only in the new build: {key}")
        elif key not in new:
            lines.append(f"{kind} only in the old build: {key}")
        elif old[key] != new[key]:
            lines.append(f"{kind} differs: {key}: {str(old[key])[:160]} -> {str(new[key])[:160]}")
    return lines


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("old")
    parser.add_argument("new")
    parser.add_argument("--figure-data", nargs=2, metavar=("OLD_DIR", "NEW_DIR"))
    args = parser.parse_args(argv)
    old_glue, new_glue = glued(args.old), glued(args.new)
    old_images, new_images = images(args.old), images(args.new)
    lines = _differences("glued value", old_glue, new_glue, BUILD_STAMPS)
    lines += _differences("image", old_images, new_images)
    counts = [f"{len(new_glue)} glued values on {len({p for p, _ in new_glue})} pages", f"{len(new_images)} images"]
    if args.figure_data:
        old_data, new_data = (figure_data(d) for d in args.figure_data)
        lines += _differences("figure data", old_data, new_data)
        counts.append(f"{len(new_data)} figures' data")
    stamps = sorted({key for page, key in new_glue if key in BUILD_STAMPS})
    print(f"compared {', '.join(counts)} (build stamps not compared: {', '.join(stamps) or 'none'})")
    for line in lines:
        print("  " + line)
    print("identical" if not lines else f"{len(lines)} difference(s)")
    return 1 if lines else 0


if __name__ == "__main__":
    sys.exit(main())
