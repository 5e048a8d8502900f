"""Numpydoc text shared between docstrings: a parameter described once, filled into every
function that takes it.

A module keeps its shared entries in a dict (name → numpydoc text, unindented, its first line
``name : type``) and decorates each function with :func:`fill_docstring`. In the docstring a
line holding only ``{name, other}`` becomes those entries, indented as the line is;
``{name, other : float}`` gives them another type (a scalar-only function among array ones).
The text is filled in at import, so ``help()``, doctests and the book see whole docstrings.
"""

import re
import textwrap

__all__ = ["fill_docstring"]

#: A docstring line that is only ``{name, ...}`` or ``{name, ... : type}``.
_SLOT = re.compile(r"^(?P<indent>[ ]*)\{(?P<names>\w+(?:, \w+)*)(?: : (?P<type>[^{}\n]+))?\}$", re.M)


def _entry(text, type_):
    text = textwrap.dedent(text).strip("\n")
    if type_ is None:
        return text
    first, newline, rest = text.partition("\n")
    return first.split(" : ", 1)[0] + " : " + type_ + newline + rest


def fill_docstring(entries):
    """Decorator filling the ``{name, ...}`` lines of a function's docstring from ``entries``.

    A name missing from ``entries``, or a docstring with nothing to fill, raises at import:
    a typo must not leave a placeholder in the rendered text.
    """
    def fill(func):
        doc = func.__doc__
        if doc is None:  # python -OO strips docstrings
            return func

        def replace(match):
            names = match["names"].split(", ")
            unknown = [n for n in names if n not in entries]
            if unknown:
                raise KeyError(f"{func.__qualname__}: no shared docstring entry {unknown}")
            text = "\n".join(_entry(entries[n], match["type"]) for n in names)
            return textwrap.indent(text, match["indent"])

        filled, count = _SLOT.subn(replace, doc)
        if count == 0:
            raise ValueError(f"{func.__qualname__}: the docstring has no {{name}} line to fill")
        func.__doc__ = filled
        return func

    return fill
