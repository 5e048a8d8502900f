"""Registry of every figure the project regenerates.

A figure is a pair of functions: ``compute(**params) -> FigureData`` (numbers only,
tested) and ``plot(data) -> matplotlib Figure`` (drawing only). Both the book and the
``magbench figure`` command go through :func:`render`, so they cannot disagree. Each
figure's parameters have SI defaults taken from ``magbench/data/<source>/params.toml``; :func:`caption_provenance`
names the figure id, the function that made it and the parameters that differ from
those defaults: the book puts it in the caption, the command line into the file's
metadata (the image itself carries no footer).
"""

import importlib

__all__ = [
    "FigureParameter", "Series", "FigureData", "FigureSpec", "REGISTRY", "register",
    "figure_ids", "get_spec", "resolve_parameters", "compute", "render",
    "caption_provenance", "parse_assignment", "BOOK_STYLE", "MAX_FIGURE_WIDTH",
]


from ..chapters.registry import REGISTRY, FigureData, FigureParameter, FigureSpec, Series, register
from .._validate import shown
from ..result_cache import disk_cached

_loaded = False


def _load():
    global _loaded
    if not _loaded:
        from ..chapters import figure_modules

        for name in figure_modules():
            importlib.import_module(name)
        _loaded = True


def figure_ids():
    """All registered figure ids, sorted."""
    _load()
    return sorted(REGISTRY)


def get_spec(figure_id):
    """The spec of a figure; an unknown id raises ``KeyError`` listing the valid ids."""
    _load()
    if figure_id not in REGISTRY:
        raise KeyError(f"unknown figure id {figure_id!r}; valid ids: {', '.join(sorted(REGISTRY))}")
    return REGISTRY[figure_id]


def resolve_parameters(figure_id, overrides=None):
    """Defaults of a figure's parameters updated with ``overrides`` (SI numbers).

    An unknown name raises ``KeyError`` listing the figure's parameters; a value that is
    not a finite number, a count with a fraction or a work input beyond its bound (each
    declared on its :class:`FigureParameter`) raises ``ValueError`` naming it.
    """
    import math

    spec = get_spec(figure_id)
    values = {name: p.default for name, p in spec.parameters.items()}
    for name, value in (overrides or {}).items():
        if name not in values:
            raise KeyError(f"figure {figure_id} has no parameter {name!r}; "
                           f"valid: {', '.join(sorted(values)) or '(none)'}")
        try:
            number = float(value)
        except (TypeError, ValueError):
            raise ValueError(f"parameter {name} of {figure_id} must be a number, got {shown(value)}") from None
        if not math.isfinite(number):
            raise ValueError(f"parameter {name} of {figure_id} must be finite, got {shown(value)}")
        values[name] = number
    # Defaults too: they may come from a whole-book parameter file ($MAGBENCH_PARAMS).
    for name, number in values.items():
        spec.parameters[name].check(figure_id, name, number)
    return values


def compute(figure_id, **overrides):
    """The numbers behind a figure, with the given parameter overrides."""
    spec = get_spec(figure_id)
    params = resolve_parameters(figure_id, overrides)
    data = disk_cached(_numbers, figure_id, tuple(sorted(params.items())))
    data.id, data.title, data.source, data.parameters = spec.id, spec.title, spec.source, params
    return data


def _numbers(figure_id, items):
    # A module-level function of hashable arguments: the result cache's key.
    return get_spec(figure_id).compute(**dict(items))


def caption_provenance(figure_id, parameters=None):
    """Caption footer: the id, the function and the parameters that differ from defaults."""
    spec = get_spec(figure_id)
    changed = []
    for name, value in (parameters or {}).items():
        p = spec.parameters[name]
        if value != p.default:
            # "1" marks a pure number in the parameter tables; a caption shows it bare
            unit = "" if p.unit in ("", "1", "-") else f" {p.unit}"
            changed.append(f"{name} = {value:.6g}{unit}")
    diff = "; ".join(changed) if changed else "all parameters at their defaults"
    return f"[{figure_id}] made by {spec.function_name}; {diff}."


#: Drawing style of every figure: sized for the book's content column (at most 7 in,
#: shown 700 CSS px wide), text of at least 7 pt (≥ 9.7 px on screen), constrained layout
#: so titles and labels are never clipped or overlapped.
BOOK_STYLE = {
    "figure.constrained_layout.use": True, "font.size": 8.0, "axes.titlesize": 8.5,
    "axes.labelsize": 8.0, "xtick.labelsize": 7.5, "ytick.labelsize": 7.5, "legend.fontsize": 7.5,
    "figure.titlesize": 9.0, "savefig.bbox": None,
}
#: Widest figure the book shows without shrinking it [in].
MAX_FIGURE_WIDTH = 7.0


def render(figure_id, **overrides):
    """Compute and draw a figure; returns ``(matplotlib Figure, FigureData)``."""
    import matplotlib

    spec = get_spec(figure_id)
    data = compute(figure_id, **overrides)
    with matplotlib.rc_context(BOOK_STYLE):
        fig = spec.plot(data)
    return fig, data


def parse_assignment(text):
    """Split ``NAME=VALUE`` (as given to ``--set``) into a name and a float."""
    if "=" not in text:
        raise ValueError(f"--set expects NAME=VALUE, got {text!r}")
    name, value = text.split("=", 1)
    try:
        return name.strip(), float(value)
    except ValueError:
        raise ValueError(f"--set {name.strip()}: cannot parse {shown(value)} as a number") from None
