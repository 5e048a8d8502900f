"""Labels from what was computed: a legend, title or text that shows a parameter's value
must show the value the figure was computed with, not the default typed into it.

For every registered figure, the texts of its default render are searched for each
parameter's default value (in the parameter's unit or a display unit: degrees, rpm,
minutes, centimetres …, to the printed digits; :func:`shown_values`). Only a parameter
whose default is shown can be shown wrongly, so only those are re-rendered: with the
value ×1.5 (or, where that is refused as out of range or not a whole number, ×0.5), and
every text of the default render that still shows the default unchanged is a failure.
A parameter whose default equals another's of the same unit is not checked (a text showing
the value cannot say whose it is), nor are the texts in :data:`FIXED_VALUES`.
About thirty figures show a default; their re-renders compute new results (about a minute
and a half on one core in ``make test``). The detector itself is tested first, on the label
samsat-fig2 once typed.
"""

import math
import re

import matplotlib.pyplot as plt
import pytest

from magbench import figures


#: How a label may show an SI value: (factor, the unit symbols that may follow the number).
_SHOWN_AS = {
    "rad": ((180.0 / math.pi, ("°", "deg")), (1.0, ("rad",))),
    "rad/s": ((180.0 / math.pi, ("°/s", "deg/s")), (30.0 / math.pi, ("rpm",)), (1.0, ("rad/s",))),
    "s": ((1.0, ("s",)), (1 / 60.0, ("min",)), (1 / 3600.0, ("h",)), (1 / 86400.0, ("d",)), (1e3, ("ms",))),
    "m": ((1.0, ("m",)), (1e2, ("cm",)), (1e3, ("mm",)), (1e-3, ("km",))),
}
_DIMENSIONLESS = ((1.0, ("",)), (1e2, ("%",)))
#: What follows a number that is not dimensionless (an angle, a length, a time …).
_UNIT_START = re.compile(r"[°%]|(?:s|ms|min|h|d|m|cm|mm|km|rad|rpm|A|T|nT|µT|W|V|Hz|kg)\b")
_NUMBER = re.compile(r"(?<![\w.^{])[-−]?\d+(?:\.\d+)?(?:[eE][-+−]?\d+)?(?!\w)")
# References, not values: figure, table, equation, section and row numbers.
_REFERENCE = re.compile(r"(?:Figs?\.|Table|[Ee]qs?\.|§|row|slide|ch\.|member)\s*\(?\d+(?:\.\d+)?\)?|\(\d+(?:\.\d+)?\)")


def figure_texts(fig, data):
    """Every text a reader sees in a figure: the spec's title, the series labels, the axes'
    titles, axis labels, texts and legends, the figure's texts, suptitle and legends."""
    texts = [data.title] + [s.label for s in data.series]
    for ax in fig.axes:
        texts += [ax.get_title(loc) for loc in ("left", "center", "right")]
        texts += [ax.get_xlabel(), ax.get_ylabel()] + [t.get_text() for t in ax.texts]
        if ax.get_legend() is not None:
            texts += [t.get_text() for t in ax.get_legend().get_texts()]
    texts += [t.get_text() for t in fig.texts]
    for legend in fig.legends:
        texts += [t.get_text() for t in legend.get_texts()]
    if getattr(fig, "_suptitle", None) is not None:
        texts.append(fig._suptitle.get_text())
    return {t for t in texts if t}


def shown_values(text, value, unit):
    """The number tokens of ``text`` that show ``value`` (SI, in ``unit``) to the token's
    printed digits, followed by the symbol of a display unit of ``unit`` (:data:`_SHOWN_AS`;
    a dimensionless value may stand alone); single-digit whole numbers are left out (axis
    indices and counts coincide with them too often to mean the value)."""
    dimensionless = unit in ("", "1", "-")
    ways = _DIMENSIONLESS if dimensionless else _SHOWN_AS.get(unit, ((1.0, (unit,)),))
    text = _REFERENCE.sub(" ", text)
    found = []
    for match in _NUMBER.finditer(text):
        token = match.group()
        after = text[match.end():].lstrip(" \u202f\u00a0$")
        plain = token.replace("−", "-")
        number = float(plain)
        mantissa = plain.lower().split("e")[0]
        if number == 0.0 or ("." not in mantissa and "e" not in plain.lower() and abs(number) < 10):
            continue
        digits = len(mantissa.split(".")[1]) if "." in mantissa else 0
        exponent = int(plain.lower().split("e")[1]) if "e" in plain.lower() else 0
        half = 0.5 * 10.0 ** (exponent - digits)
        if dimensionless and _unit_follows(after):
            continue
        if any(value * c != 0 and abs(number - value * c) <= half * (1 + 1e-9)
               and any(after.startswith(symbol) for symbol in symbols) for c, symbols in ways):
            found.append(token)
    return found


def _unit_follows(after):
    """Whether a unit symbol follows a number (``after`` is the text after it)."""
    return _UNIT_START.match(after) is not None


def stale_texts(default_texts, scaled_texts, changed):
    """Texts unchanged by the scaling that still show a changed parameter's default value.

    ``changed`` maps a parameter's name to (default, scaled, unit) [SI]; returns (name, text)
    pairs.
    """
    stale = []
    for text in sorted(default_texts & scaled_texts):
        for name, (default, scaled, unit) in changed.items():
            if shown_values(text, default, unit) and not shown_values(text, scaled, unit):
                stale.append((name, text))
    return stale


#: (figure, parameter, text): why the text shows a fixed value that equals the parameter's default.
FIXED_VALUES = {
    ("tns0-rod-loops", "rod_coercivity", "Ha = 12 A/m"):
        "a loop at the fixed amplitude 12 A/m (figures.AMPLITUDES), equal to Hc by coincidence",
    ("ch05-gain-sweep", "detumble_threshold", r"decay rate of $|\boldsymbol{\omega}|$, 2 → 0.5 °/s [10$^{-3}$/s]"):
        "the decay rate's fixed band (study.decay_rate_sweep, 2 → 0.5 °/s), not the detumbling threshold",
}


def test_the_fixed_values_are_shown_by_their_figures():
    for (figure_id, name, text), reason in FIXED_VALUES.items():
        fig, data = figures.render(figure_id)
        plt.close(fig)
        assert text in figure_texts(fig, data) and name in figures.get_spec(figure_id).parameters, reason


def test_a_typed_default_is_found_and_a_computed_label_is_not():
    # samsat-fig2 labelled its curve "discrete (16 s on / 1 s off)" whatever on_time it ran with
    typed = {"discrete (16 s on / 1 s off)", "time to 0.5 °/s [h]"}
    changed = {"on_time": (16.0, 24.0, "s")}
    assert stale_texts(typed, typed, changed) == [("on_time", "discrete (16 s on / 1 s off)")]
    computed = {"discrete (24 s on / 1 s off)", "time to 0.5 °/s [h]"}
    assert stale_texts(typed, computed, changed) == []


@pytest.mark.parametrize("text, value, unit, shown", [
    ("The bench as designed, $\\psi_\\mathrm{des}$ = 60° (thesis Fig. 19)", 1.0471975511965976, "rad", ["60"]),
    ("as built, d = 51.0 cm", 0.51, "m", ["51.0"]),
    ("spin −30 rpm", -3.141592653589793, "rad/s", ["−30"]),
    ("Damping time (SamSat-218D Fig. 2, reconstruction)", 218.0, "1", []),     # a name, not a seed
    ("thesis: 10°", 10.0, "1", []),                                         # an angle, not a factor of 10
    ("target ± 10° (thesis's error)", 0.1, "m", []),                        # 10 cm would say cm
    ("eq. (39), $A_f$ = 0.95", 0.95, "1", ["0.95"]),
    ("Monte Carlo, 1000 members", 1000.0, "1", ["1000"]),
    ("(thesis Fig. 12)", 12.0, "1", []),
    ("from 3 attitudes", 3.0, "1", []),                                     # single digits are too common
])
def test_shown_values(text, value, unit, shown):
    assert shown_values(text, value, unit) == shown


def _changed_render(figure_id, name, default):
    """The figure rendered with ``name`` ×1.5, or ×0.5 where ×1.5 is refused (a bound, a
    whole number, the quantity's domain): (value, figure, data)."""
    for factor in (1.5, 0.5):
        value = default * factor
        if figures.get_spec(figure_id).parameters[name].whole:
            value = float(round(value))
        if value == default:
            continue
        try:
            return (value, *figures.render(figure_id, **{name: value}))
        except ValueError:
            continue
    raise AssertionError(f"{figure_id}: no valid value near {name} = {default:g} ×1.5 or ×0.5")


@pytest.mark.slow
@pytest.mark.parametrize("figure_id", figures.figure_ids())
def test_labels_show_the_values_computed_with(figure_id):
    spec = figures.get_spec(figure_id)
    fig, data = figures.render(figure_id)
    default_texts = figure_texts(fig, data)
    plt.close(fig)
    stale = []
    for name, par in spec.parameters.items():
        if not any(shown_values(text, par.default, par.unit) for text in default_texts):
            continue
        if any(other != name and o.unit == par.unit and o.default == par.default
               for other, o in spec.parameters.items()):
            continue
        value, fig, data = _changed_render(figure_id, name, par.default)
        changed = {name: (par.default, value, par.unit)}
        stale += [f"{name} = {value:g} {par.unit}: {text!r}"
                  for _, text in stale_texts(default_texts, figure_texts(fig, data), changed)
                  if (figure_id, name, text) not in FIXED_VALUES]
        plt.close(fig)
    assert not stale, f"{figure_id} still shows a default after the parameter changed:\n" + "\n".join(stale)
