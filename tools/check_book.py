"""Check that a built book is complete: every chapter page exists, no notebook failed,
and every registered figure appears with its provenance caption."""

import sys
from pathlib import Path

import yaml

from magbench import figures

ROOT = Path(__file__).resolve().parent.parent


def chapter_files():
    """Every page of the toc: the root, each part's chapters and their nested sections."""
    toc = yaml.safe_load((ROOT / "_toc.yml").read_text())

    def walk(entries):
        for entry in entries:
            if "file" in entry:
                yield entry["file"]
            yield from walk(entry.get("sections", []))

    return [toc["root"]] + [f for part in toc.get("parts", []) for f in walk(part.get("chapters", []))]


def main(html_dir):
    html = Path(html_dir)
    problems = []
    pages = {}
    for name in chapter_files():
        page = html / f"{name}.html"
        if not page.is_file():
            problems.append(f"missing page {page}")
        else:
            pages[name] = page.read_text(encoding="utf-8")
    reports = list((html / "reports").glob("**/*.err.log")) if (html / "reports").exists() else []
    problems += [f"execution failure logged in {r}" for r in reports]
    text = "\n".join(pages.values())
    for figure_id in figures.figure_ids():
        if f"[{figure_id}] made by" not in text:
            problems.append(f"figure {figure_id} is registered but not shown with its caption in the book")
    if problems:
        print("book check failed:\n  " + "\n  ".join(problems))
        return 1
    print(f"book check: {len(pages)} pages, {len(figures.figure_ids())} figures, no execution failures")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1] if len(sys.argv) > 1 else "_build/html"))
