"""The ``magbench`` command: list and regenerate figures, print model-vs-measurement rows.

Usage::

    magbench figures
    magbench figure ID [--set NAME=VALUE ...] [--out FILE.png|svg|pdf] [--data FILE.json]
    magbench compare [--json]
"""

import argparse
import json
import sys
from pathlib import Path

__all__ = ["main"]

_FORMATS = (".png", ".svg", ".pdf")


def _cmd_figures(args):
    from . import figures

    ids = figures.figure_ids()
    width = max(len(i) for i in ids)
    for figure_id in ids:
        spec = figures.get_spec(figure_id)
        print(f"{figure_id:<{width}}  {spec.title}  [{spec.source}]")
    return 0


def _cmd_figure(args):
    from . import figures

    try:
        figures.get_spec(args.id)
    except KeyError as exc:
        print(f"magbench figure: {exc.args[0]}", file=sys.stderr)
        return 2
    overrides = {}
    for item in args.set or []:
        try:
            name, value = figures.parse_assignment(item)
        except ValueError as exc:
            print(f"magbench figure: {exc}", file=sys.stderr)
            return 2
        overrides[name] = value
    if args.out and Path(args.out).suffix.lower() not in _FORMATS:
        print(f"magbench figure: --out must end in one of {', '.join(_FORMATS)}, got {args.out!r}",
              file=sys.stderr)
        return 2
    try:
        if args.out:
            import matplotlib

            matplotlib.use("Agg")
            fig, data = figures.render(args.id, **overrides)
            fig.savefig(args.out, dpi=150, metadata={"CreationDate": None} if args.out.endswith(".pdf") else None)
        else:
            data = figures.compute(args.id, **overrides)
    except (KeyError, ValueError) as exc:      # unknown parameter name, or a value out of range
        print(f"magbench figure: {exc.args[0]}", file=sys.stderr)
        return 2
    if args.data:
        Path(args.data).write_text(json.dumps(data.to_json_dict(), indent=1), encoding="utf-8")
    print(figures.caption_provenance(args.id, data.parameters))
    return 0


def _cmd_compare(args):
    from .compare import all_rows

    rows = all_rows()
    if args.json:
        print(json.dumps([r.as_dict() for r in rows], indent=1))
        return 0
    header = ("id", "measured", "model", "difference", "tolerance", "unit", "verdict")
    table = [header] + [(r.id, f"{r.measured:.6g}", f"{r.model:.6g}", f"{r.difference:+.3g}",
                         f"{r.tolerance:.3g}", r.unit, r.verdict) for r in rows]
    widths = [max(len(row[k]) for row in table) for k in range(len(header))]
    for row in table:
        print("  ".join(cell.ljust(w) for cell, w in zip(row, widths)).rstrip())
    agree = sum(r.verdict == "agrees" for r in rows)
    print(f"\n{len(rows)} rows: {agree} agree, {len(rows) - agree} disagree")
    return 0


def main(argv=None):
    """Entry point of the ``magbench`` command; returns the exit status."""
    parser = argparse.ArgumentParser(prog="magbench", description=__doc__.splitlines()[0])
    sub = parser.add_subparsers(dest="command", required=True)
    sub.add_parser("figures", help="list every registered figure id")
    fig = sub.add_parser("figure", help="regenerate one figure")
    fig.add_argument("id", help="figure id (see `magbench figures`)")
    fig.add_argument("--set", action="append", metavar="NAME=VALUE",
                     help="override a parameter (SI value); repeatable")
    fig.add_argument("--out", metavar="FILE", help="write the figure (.png, .svg or .pdf)")
    fig.add_argument("--data", metavar="FILE", help="write the numbers behind the figure as JSON")
    cmp_ = sub.add_parser("compare", help="print every model-vs-measurement row")
    cmp_.add_argument("--json", action="store_true", help="print the rows as a JSON list")
    args = parser.parse_args(argv)
    handler = {"figures": _cmd_figures, "figure": _cmd_figure, "compare": _cmd_compare}[args.command]
    return handler(args)


if __name__ == "__main__":
    sys.exit(main())
