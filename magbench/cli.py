"""The ``magbench`` command: list and regenerate figures, print model-vs-measurement rows.

Usage::

    magbench figures
    magbench figure ID [--set NAME=VALUE ...] [--out FILE.png|svg|pdf] [--data FILE.json]
    magbench compare [--json]
    magbench design-coil --moment M --voltage U --side L --max-power W --max-mass KG
                         [--shape round|square] [--wire-table iec60317|iec60228|awg] [--json]
    magbench montecarlo --list
    magbench montecarlo STUDY --members N --seed S [--workers K | --scheduler tcp://HOST:PORT]
                        [--chunk C] [--set NAME=VALUE ...] [--until-ci WIDTH] --out FILE.csv
"""

import argparse
import json
import os
import sys
from concurrent.futures import Executor
from pathlib import Path

import numpy as np

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
    # Before computing: a figure can take minutes, and its result must not be lost to a typo.
    for flag, path in (("--out", args.out), ("--data", args.data)):
        problem = path and _unwritable(path)
        if problem:
            print(f"magbench figure: {flag} {path}: {problem}", file=sys.stderr)
            return 2
    try:
        figures.resolve_parameters(args.id, overrides)
    except (KeyError, ValueError) as exc:      # unknown parameter name, or not a finite number
        print(f"magbench figure: {exc.args[0]}", file=sys.stderr)
        return 2
    try:
        if args.out:
            import matplotlib

            matplotlib.use("Agg")
            fig, data = figures.render(args.id, **overrides)
            # A fixed salt: SVG clip-path ids are hashes salted with a random UUID otherwise,
            # so the same figure would give a different file at every run.
            with matplotlib.rc_context({"svg.hashsalt": "magbench"}):
                try:
                    fig.savefig(args.out, dpi=150, metadata=_file_metadata(args.out, figures.caption_provenance(
                        args.id, data.parameters)))
                except OSError as exc:
                    print(f"magbench figure: --out {args.out}: {exc.strerror or exc}", file=sys.stderr)
                    return 2
        else:
            data = figures.compute(args.id, **overrides)
    except (KeyError, ValueError) as exc:      # a value out of the range of the function it reaches
        # The check that failed names the library's argument (``radius``); say which of the
        # figure's parameters were set, since one of them (``coil_radius``) is the cause.
        given = ", ".join(f"{name}={value:g}" for name, value in overrides.items())
        context = f"{args.id} with {given}: " if given else f"{args.id}: "
        print(f"magbench figure: {context}{exc.args[0]}", file=sys.stderr)
        return 2
    if args.data:
        try:
            Path(args.data).write_text(json.dumps(data.to_json_dict(), indent=1), encoding="utf-8")
        except OSError as exc:
            print(f"magbench figure: --data {args.data}: {exc.strerror or exc}", file=sys.stderr)
            return 2
    print(figures.caption_provenance(args.id, data.parameters))
    return 0


def _unwritable(path):
    """Why ``path`` cannot be written as a file, or None if it can."""
    target = Path(path)
    folder = target.parent
    if target.is_dir():
        return "is a folder, not a file"
    if not folder.is_dir():
        return f"folder {folder} does not exist"
    if not os.access(folder, os.W_OK) or (target.exists() and not os.access(target, os.W_OK)):
        return "not writable"
    return None


def _file_metadata(path, description):
    """Figure-file metadata: the provenance as its description, no date or version.

    Each format names the fields differently; dates are dropped so that the same
    figure and parameters give the same file.
    """
    suffix = Path(path).suffix.lower()
    if suffix == ".png":
        return {"Description": description, "Software": None}
    if suffix == ".pdf":
        return {"Subject": description, "CreationDate": None, "Creator": None, "Producer": None}
    if suffix == ".svg":
        return {"Description": description, "Date": None, "Creator": None}
    return None


def _cmd_compare(args):
    from .chapters import comparisons

    rows = comparisons()
    if args.json:
        print(json.dumps([r.as_dict() for r in rows], indent=1))
        return 0
    header = ("id", "kind", "measured", "model", "difference", "tolerance", "unit", "verdict")
    table = [header] + [(r.id, r.kind, f"{r.measured:.6g}", f"{r.model:.6g}", f"{r.difference:+.3g}",
                         f"{r.tolerance:.3g}", r.unit, r.verdict if r.counted else "(consistency)")
                        for r in rows]
    widths = [max(len(row[k]) for row in table) for k in range(len(header))]
    for row in table:
        print("  ".join(cell.ljust(w) for cell, w in zip(row, widths)).rstrip())
    counted = [r for r in rows if r.counted]
    agree = sum(r.agrees for r in counted)
    by_kind = ", ".join(f"{k}: {sum(r.agrees for r in counted if r.kind == k)}/{sum(r.kind == k for r in counted)}"
                        for k in dict.fromkeys(r.kind for r in counted))
    print(f"\n{len(rows)} rows, {len(counted)} counted: {agree} agree, {len(counted) - agree} disagree "
          f"(agree/rows by kind: {by_kind}); {len(rows) - len(counted)} consistency checks, not counted")
    return 0


# design-coil: CLI flag of each solver parameter, so an error names what the user typed.
_COIL_FLAGS = {"moment": "--moment", "voltage": "--voltage", "side": "--side",
               "max_power": "--max-power", "max_mass": "--max-mass", "resistivity": "--resistivity",
               "density": "--density", "winding_length": "--winding-length",
               "max_layers": "--max-layers", "enamel_thickness": "--enamel"}
_AWG_GAUGES = range(20, 45)          # 0.81 mm down to 0.051 mm: the magnetorquer range
_DESIGN_KEYS = ("turns", "wire_diameter", "pitch", "resistance", "current", "power", "mass",
                "moment", "layers", "fill_factor")


def _coil_wires(name, enamel):
    """(bare diameters, overall diameters or None, label) of a wire table [m]."""
    if name == "awg":
        from .hardware import awg_diameter

        d = [float(awg_diameter(g)) for g in _AWG_GAUGES]
        return d, None, (f"AWG {_AWG_GAUGES[0]}-{_AWG_GAUGES[-1]} (ASTM B258, by definition); "
                         f"enamel not tabulated: pitch = d + 2 x {enamel * 1e6:g} um")
    from .io import load_wire_table

    t = load_wire_table(name)
    label = "IEC 60317-0-1 grade 1 enamelled copper (R20 sizes); pitch = maximum overall diameter"
    if name == "iec60228":
        label += " [iec60228 is an alias: IEC 60228 itself lists cable conductors, not winding wire]"
    return list(t.nominal_diameter), list(t.max_overall_diameter), label


def _limit_explanation(kind, numbers, max_power, max_mass, moment, voltage):
    """A sentence saying why no design exists, from the numbers of
    :func:`magbench.hardware.binding_limit` (thesis §3.2, eqs. (20), (26)/(30)).

    Parameters
    ----------
    kind : str
        The binding limit, as :func:`binding_limit` returns it [-].
    numbers : dict
        Its numbers, as :func:`binding_limit` returns them (SI) [-].
    max_power, max_mass, moment, voltage : float
        The limits [W], [kg], the required moment [A·m²] and the supply [V].

    Returns
    -------
    str
        The explanation.
    """
    w_max, m_max, m_req, u = max_power, max_mass, moment, voltage
    if kind == "moment":
        return (
            f"moment: no wire reaches {m_req:.4g} A·m² at {u:.4g} V. By eq. (20) the thickest "
            f"wire, d = {numbers['thickest_wire'] * 1e3:.4g} mm, gives {numbers['thickest_wire_moment']:.4g} A·m² "
            f"whatever the turns; eq. (21) needs S_r >= {numbers['wire_area_needed']:.4g} m² (d >= "
            f"{numbers['wire_diameter_needed'] * 1e3:.4g} mm) or a higher voltage"
        )
    if kind == "power and mass":
        return (
            f"power and mass together: with the thinnest adequate wire, d = {numbers['wire'] * 1e3:.4g} mm "
            f"(moment {numbers['wire_moment']:.4g} A·m²), W <= {w_max:.4g} W needs N >= {numbers['turns_for_power']} "
            f"but M <= {m_max:.4g} kg allows N <= {numbers['turns_for_mass']}. Their product, eq. (26)/(30), "
            f"M·W = 16ρρ̃m²/l² = {numbers['mass_power_product']:.4g} kg·W whatever N and U, exceeds "
            f"max_mass·max_power = {numbers['budget_product']:.4g} kg·W; raise a limit, enlarge the "
            f"coil or use a thinner wire closer to the required moment"
        )
    if kind == "integer turns":
        return (
            f"integer turns: for d = {numbers['wire'] * 1e3:.4g} mm the limits allow "
            f"{numbers['exact_turns_for_power']:.6g} <= N <= {numbers['exact_turns_for_mass']:.6g}, "
            f"which holds no integer"
        )
    return (
        f"winding fit: designs meet the moment, power and mass limits, but none fits in "
        f"{numbers['max_layers']} layer(s) over {numbers['winding_length']:.4g} m at the wires' pitch "
        f"(enamel included)"
    )


def design_explanation(result, max_power, max_mass, moment, voltage):
    """What ``design-coil`` says of a :func:`magbench.hardware.design_magnetorquer` result:
    the best designs when there are any, else why none exists.

    Parameters
    ----------
    result : dict
        The solver's result.
    max_power, max_mass, moment, voltage : float
        The limits [W], [kg], the required moment [A·m²] and the supply [V].
    """
    if result["feasible"]:
        low_w, low_m = result["min_power"], result["min_mass"]
        return (f"{result['turns'].size} feasible designs; least power {low_w['power']:.4g} W at "
                f"N = {low_w['turns']}, d = {low_w['wire_diameter'] * 1e3:.4g} mm; least mass "
                f"{low_m['mass'] * 1e3:.4g} g at N = {low_m['turns']}, d = {low_m['wire_diameter'] * 1e3:.4g} mm")
    return _limit_explanation(result["binding_limit"], result["limit_numbers"], max_power, max_mass, moment, voltage)


def _cmd_design_coil(args):
    from .io import load_parameter_set
    from .hardware import Turn, WireSizes, design_magnetorquer

    thesis = load_parameter_set("thesis")       # the thesis's copper, unless given
    rho = thesis["copper_resistivity"].value_si if args.resistivity is None else args.resistivity
    gamma = thesis["copper_density"].value_si if args.density is None else args.density
    try:
        bare, overall, label = _coil_wires(args.wire_table, args.enamel)
        # the turn and the wire are checked as they are built: inside the try, so their
        # errors reach the user with the flag too
        turn = Turn(args.shape, args.side)
        wire = WireSizes(bare, rho, gamma, args.enamel, overall)
        res = design_magnetorquer(
            args.moment, args.voltage, turn, args.max_power, args.max_mass, wire,
            winding_length=args.winding_length, max_layers=args.max_layers, require_fit=True)
    except ValueError as exc:
        message = str(exc)
        flag = _COIL_FLAGS.get(message.split(" ", 1)[0])
        print(f"magbench design-coil: {flag + ': ' if flag else ''}{message}", file=sys.stderr)
        return 2
    best = res["min_mass" if args.minimise == "mass" else "min_power"]
    explanation = design_explanation(res, args.max_power, args.max_mass, args.moment, args.voltage)
    if args.json:
        designs = [{k: res[k][i].item() for k in _DESIGN_KEYS} for i in range(res["turns"].size)]
        print(json.dumps({
            "inputs": {"moment": args.moment, "voltage": args.voltage, "side": args.side,
                       "shape": args.shape, "max_power": args.max_power, "max_mass": args.max_mass,
                       "resistivity": rho, "density": gamma,
                       "winding_length": args.winding_length or args.side,
                       "max_layers": args.max_layers},
            "wire_table": args.wire_table, "wire_table_note": label, "minimise": args.minimise,
            "feasible": res["feasible"], "binding_limit": res["binding_limit"],
            "explanation": explanation, "recommended": best,
            "min_power": res["min_power"], "min_mass": res["min_mass"], "designs": designs,
        }, indent=1))
        return 0 if res["feasible"] else 1
    print(f"Coil for {args.moment:g} A m^2 at {args.voltage:g} V, {args.shape} turn of "
          f"{args.side:g} m; limits {args.max_power:g} W and {args.max_mass:g} kg per coil")
    print(f"Wires: {label}")
    if not res["feasible"]:
        print(f"No feasible design. Binding limit: {res['binding_limit']}.")
        print(explanation)
        return 1
    header = ("d [mm]", "pitch [mm]", "turns", "R [ohm]", "I [mA]", "W [W]", "M [g]", "m [A m^2]")
    table = [header]
    for d in np.unique(res["wire_diameter"]):
        k = res["wire_diameter"] == d

        def span(col, scale=1.0, fmt=".4g", k=k):
            lo, hi = (res[col][k].min(), res[col][k].max()) if scale == 1.0 else (
                res[col][k].min() * scale, res[col][k].max() * scale)
            return f"{lo:{fmt}}" if lo == hi else f"{lo:{fmt}}-{hi:{fmt}}"
        table.append((f"{d * 1e3:.3f}", f"{res['pitch'][k][0] * 1e3:.3f}", span("turns", fmt="d"),
                      span("resistance"), span("current", 1e3), span("power"), span("mass", 1e3),
                      f"{res['moment'][k][0]:.4g}"))
    widths = [max(len(row[i]) for row in table) for i in range(len(header))]
    for row in table:
        print("  ".join(cell.rjust(w) for cell, w in zip(row, widths)))
    print(f"\n{res['turns'].size} feasible (turns, wire) designs.")
    for title, d in ((f"Recommended (least {args.minimise})", best),
                     ("Least power" if args.minimise == "mass" else "Least mass",
                      res["min_power" if args.minimise == "mass" else "min_mass"])):
        print(f"{title}: N = {d['turns']}, d = {d['wire_diameter'] * 1e3:.3f} mm: "
              f"R = {d['resistance']:.4g} ohm, I = {d['current'] * 1e3:.4g} mA, "
              f"W = {d['power']:.4g} W, M = {d['mass'] * 1e3:.4g} g, m = {d['moment']:.4g} A m^2, "
              f"{d['layers']} layer(s)")
    return 0


class _LocalPool(Executor):
    """A process pool that replaces itself when a worker dies, so that the chunk the worker
    held can be submitted once more (a stdlib pool whose worker died is broken for good)."""

    def __init__(self, workers):
        self._workers = workers
        self._pool = self._new()

    def _new(self):
        from concurrent.futures import ProcessPoolExecutor

        return ProcessPoolExecutor(self._workers)

    def submit(self, fn, *args, **kwargs):
        from concurrent.futures import BrokenExecutor

        try:
            return self._pool.submit(fn, *args, **kwargs)
        except BrokenExecutor:
            self._pool.shutdown(wait=False, cancel_futures=True)
            self._pool = self._new()
            return self._pool.submit(fn, *args, **kwargs)

    def shutdown(self, wait=True, *, cancel_futures=False):
        self._pool.shutdown(wait=wait, cancel_futures=cancel_futures)


def _whole(minimum):
    def parse(text):
        try:
            value = int(text)
        except ValueError:
            raise argparse.ArgumentTypeError(f"must be a whole number >= {minimum}, got {text!r}") from None
        if value < minimum:
            raise argparse.ArgumentTypeError(f"must be a whole number >= {minimum}, got {text!r}")
        return value
    return parse


def _positive_float(text):
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"must be a number > 0, got {text!r}") from None
    if not value > 0 or not np.isfinite(value):
        raise argparse.ArgumentTypeError(f"must be a number > 0, got {text!r}")
    return value


def _list_studies():
    from .chapters import chapter as chapter_spec, dispersion_studies
    from .io import load_parameter_set

    for study in dispersion_studies().values():
        spec = chapter_spec(study.chapter)
        meta = load_parameter_set(spec.source)
        values = study.parameters({})
        print(f"{study.name} (chapter {study.chapter}): {study.description}")
        print("  dispersed inputs:")
        for item in study.inputs:
            print(f"    {item.name} [{item.unit}] -> columns {', '.join(item.columns)}: {item.distribution}")
            for name in item.parameters:
                entry = meta[name]
                print(f"      {name} = {values[name]:.6g} (SI; {entry.source}: {entry.note})")
        print("  outcomes:")
        for o in study.outcomes:
            print(f"    {o.name} [{o.unit}]: {o.description}")
        print()
    return 0


def _connect(address):
    """A Dask client's executor on the scheduler at ``address`` (and the client), or a
    one-line reason why not."""
    try:
        from distributed import Client
    except ImportError:
        return None, "--scheduler needs dask.distributed: pip install distributed (or magbench[cluster])"
    import logging

    logging.getLogger("distributed").setLevel(logging.CRITICAL)     # one line of ours instead
    try:
        client = Client(address, timeout="4s", set_as_default=False)
    except (OSError, TimeoutError, ValueError) as exc:
        return None, f"cannot reach the Dask scheduler at {address} within 4 s ({type(exc).__name__}: {exc})"
    return client, None


def _cmd_montecarlo(args):
    from .chapters import dispersion_study, dispersion_studies
    from .figures import parse_assignment
    from .sim.dispersion import DispersionError, dispersion_statistics, run_dispersion

    def fail(message):
        print(f"magbench montecarlo: {message}", file=sys.stderr)
        return 2

    if args.list:
        return _list_studies()
    if args.study is None:
        return fail(f"name a study ({', '.join(dispersion_studies())}) or give --list")
    try:
        study = dispersion_study(args.study)
    except KeyError as exc:
        return fail(exc.args[0])
    if args.members is None or args.seed is None or args.out is None:
        return fail("--members, --seed and --out are required")
    if args.workers is not None and args.scheduler is not None:
        return fail("give --workers or --scheduler, not both")
    overrides = {}
    for item in args.set or []:
        try:
            name, value = parse_assignment(item)
        except ValueError as exc:
            return fail(str(exc))
        overrides[name] = value
    try:
        study.parameters(overrides)
    except ValueError as exc:
        return fail(str(exc))
    problem = _unwritable(args.out)
    if problem:
        return fail(f"--out {args.out}: {problem}")
    client = executor = None
    if args.scheduler is not None:
        client, problem = _connect(args.scheduler)
        if problem:
            return fail(problem)
        executor = client.get_executor()
    elif args.workers is not None and args.workers > 1:
        executor = _LocalPool(args.workers)
    bar = None
    if sys.stderr.isatty():
        from tqdm import tqdm

        bar = tqdm(total=args.members, unit="member", file=sys.stderr, dynamic_ncols=True)
    shown_done = [0]

    def progress(done):
        if bar is not None:
            bar.update(done - shown_done[0])
            shown_done[0] = done

    try:
        table = run_dispersion(study, args.members, args.seed, executor=executor, chunk=args.chunk,
                               overrides=overrides, out=args.out, progress=progress, until_ci=args.until_ci)
    except DispersionError as exc:
        return fail(f"{exc} (nothing written to {args.out})")
    finally:
        if bar is not None:
            bar.close()
        if executor is not None and client is None:
            executor.shutdown(wait=False, cancel_futures=True)
        if client is not None:
            client.close()
    print(f"{study.name}: {table.members} members, seed {args.seed}, rows in {args.out}")
    print(f"{'outcome':<22} {'statistic':<9} {'value':>13} {'95 % bootstrap interval':>29}  unit")
    for row in dispersion_statistics(table):
        note = f"  ({row['missing']} members not reached)" if row["missing"] else ""
        print(f"{row['outcome']:<22} {row['statistic']:<9} {row['value']:>13.6g} "
              f"[{row['low']:>12.6g}, {row['high']:>12.6g}]  {row['unit']}{note}")
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
    coil = sub.add_parser(
        "design-coil", help="every feasible air-core magnetorquer from a wire table",
        description=("Every feasible (turns, wire) design of an air-core magnetorquer (thesis §3, "
                     "eqs. 17-32) and the recommended one. SI units. Exit status 0: feasible; "
                     "1: no feasible design (the binding limit is named); 2: bad input."))
    coil.add_argument("--moment", type=float, required=True, help="required dipole moment [A m^2]")
    coil.add_argument("--voltage", type=float, required=True, help="supply voltage [V]")
    coil.add_argument("--side", type=float, required=True, help="turn side (square) or diameter (round) [m]")
    coil.add_argument("--shape", choices=("square", "round"), default="square", help="turn shape")
    coil.add_argument("--max-power", type=float, required=True, help="Joule power limit per coil [W]")
    coil.add_argument("--max-mass", type=float, required=True, help="conductor mass limit per coil [kg]")
    coil.add_argument("--wire-table", choices=("iec60317", "iec60228", "awg"), default="iec60317",
                      help="wire sizes: IEC 60317-0-1 grade 1 (iec60228 is an alias) or AWG")
    coil.add_argument("--minimise", choices=("mass", "power"), default="mass",
                      help="what the recommended design minimises (default: mass)")
    coil.add_argument("--resistivity", type=float, help="conductor resistivity [ohm m] (default: thesis copper)")
    coil.add_argument("--density", type=float, help="conductor density [kg/m^3] (default: thesis copper)")
    coil.add_argument("--winding-length", type=float,
                      help="axial length of one layer [m] (default: --side, the thesis's single layer)")
    coil.add_argument("--max-layers", type=int, default=1, help="layers the former holds (default 1)")
    coil.add_argument("--enamel", type=float, default=10e-6,
                      help="radial enamel thickness for AWG wires [m] (default 10e-6, an order of magnitude)")
    coil.add_argument("--json", action="store_true", help="print the result as JSON")
    mc = sub.add_parser(
        "montecarlo", help="run a dispersion study over many members, locally or on a Dask cluster",
        description=("Run a chapter's dispersion study: one row per member (index, dispersed inputs, outcomes; "
                     "SI) written to a CSV file, then the outcomes' median and 95th percentile with 95 %% "
                     "bootstrap intervals. Member k draws from numpy.random.default_rng([seed, k]): the file is "
                     "the same, byte for byte, for any --workers, --scheduler and --chunk. Exit status 2: bad "
                     "input, an unreachable scheduler, or a chunk that failed twice."))
    mc.add_argument("study", nargs="?", help="the study (see --list)")
    mc.add_argument("--list", action="store_true", help="list the studies, their inputs and outcomes")
    mc.add_argument("--members", type=_whole(1), help="number of members (with --until-ci: the most)")
    mc.add_argument("--seed", type=_whole(0), help="the study's seed")
    mc.add_argument("--workers", type=_whole(1), help="local worker processes (default: this process)")
    mc.add_argument("--scheduler", metavar="ADDRESS", help="a running Dask scheduler, tcp://HOST:PORT")
    mc.add_argument("--chunk", type=_whole(1), help="members per chunk (default 1000)")
    mc.add_argument("--set", action="append", metavar="NAME=VALUE",
                    help="override a parameter of the study's chapter (SI value); repeatable")
    mc.add_argument("--until-ci", type=_positive_float, metavar="WIDTH",
                    help="stop once every interval is narrower than WIDTH times its statistic")
    mc.add_argument("--out", metavar="FILE.csv", help="the table to write")
    args = parser.parse_args(argv)
    handler = {"figures": _cmd_figures, "figure": _cmd_figure, "compare": _cmd_compare,
               "design-coil": _cmd_design_coil, "montecarlo": _cmd_montecarlo}[args.command]
    from .io import DataError

    try:
        status = handler(args)
        sys.stdout.flush()       # inside the try: a closed pipe fails here, not at exit
        return status
    except DataError as exc:
        # A data file or a $MAGBENCH_PARAMS file that is missing, tampered with or out of
        # range: its message names the file and the value; a traceback adds nothing.
        print(f"magbench {args.command}: {exc}", file=sys.stderr)
        return 2
    except BrokenPipeError:
        # The reader closed the pipe (`magbench compare --json | head`): not an error of
        # ours. Python's recipe: point stdout at devnull so the exit flush does not fail too.
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return 0


if __name__ == "__main__":
    sys.exit(main())
