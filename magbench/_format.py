"""Numbers as a reader writes them (shared by the figures and the book's glue)."""

import math

__all__ = ["format_number"]


_SUPERSCRIPT = str.maketrans("-0123456789", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹")


def format_number(value, digits=3, *, small=1e-3, large=1e5):
    """A number for prose: ``digits`` significant digits, ``a·10ⁿ`` outside [small, large).

    >>> format_number(6.2213e-41)
    '6.22·10⁻⁴¹'
    >>> format_number(228.46)
    '228'
    >>> format_number(0.046672, 2)
    '0.047'
    """
    value = float(value)
    if not math.isfinite(value):
        return {math.inf: "∞", -math.inf: "−∞"}.get(value, "NaN")
    if value == 0.0:
        return "0"
    magnitude = abs(value)
    if small <= magnitude < large:
        decimals = max(digits - 1 - math.floor(math.log10(magnitude)), 0)
        text = f"{magnitude:.{decimals}f}"
        if float(text) >= large:     # rounding carried it over the threshold
            return format_number(value, digits, small=small, large=large)
    else:
        mantissa, exponent = f"{magnitude:.{digits - 1}e}".split("e")
        text = f"{mantissa}·10{str(int(exponent)).translate(_SUPERSCRIPT)}"
    return ("−" if value < 0 else "") + text
