"""The book's presentation helpers: figures as images whatever the backend, numbers as a
reader writes them, tables as MyST list-tables, printed values with their printed digits."""

import io

import matplotlib
import pytest
from PIL import Image

from magbench import chapters, report


@pytest.mark.parametrize("backend", ["agg", "pdf", "svg", "template"])
def test_figure_png_is_an_image_whatever_the_backend(backend):
    """Issue 9's regression: with MPLBACKEND=Agg in the kernel, glue recorded only the text
    '<Figure size …>'. figure_png renders through the Agg canvas itself, so any backend,
    even the do-nothing 'template' one, yields a PNG of the figure's size."""
    import matplotlib.pyplot as plt

    previous = matplotlib.get_backend()
    try:
        plt.switch_backend(backend)
        fig, ax = plt.subplots(figsize=(4.0, 2.0))
        ax.plot([0, 1], [0, 1])
        png, width_px = report.figure_png(fig)
        plt.close(fig)
    finally:
        plt.switch_backend(previous)
    image = Image.open(io.BytesIO(png))
    assert image.format == "PNG"
    # 4 in x 2 in at the book's dpi; shown at 100 CSS px per inch.
    assert image.size == (4 * report.FIGURE_DPI, 2 * report.FIGURE_DPI)
    assert width_px == 400
    low, high = image.convert("L").getextrema()
    assert low < high                                       # something was drawn


@pytest.mark.parametrize("value, unit, digits, expected", [
    (6.2213e-41, "J", 3, "6.22·10⁻⁴¹ J"),
    (8.028, "1e22 A m^2", 4, "8.028·10²² A·m²"),
    (12.5, "ohm", 3, "12.5 Ω"),
    (-71.63, "deg", 3, "−71.6°"),
    (48.3, "uT", 3, "48.3 µT"),
])
def test_format_quantity_writes_numbers_as_a_reader_does(value, unit, digits, expected):
    assert report.format_quantity(value, unit, digits) == expected


def test_format_quantity_has_no_e_notation_at_any_scale():
    for exponent in range(-45, 30, 3):
        text = report.format_quantity(1.234 * 10.0**exponent, "m", 3)
        assert "e" not in text.replace(" m", ""), text


@pytest.mark.parametrize("value, tolerance, expected", [
    (0.13, 0.0005, "0.130"),      # Kovalenko's "0.130": the trailing zero is a printed digit
    (258.0, 0.5, "258"),
    (10.0, 0.5, "10"),
    (2.0, 0.05, "2.0"),
    (0.42, 0.005, "0.42"),
])
def test_printed_text_keeps_the_printed_digits(value, tolerance, expected):
    assert report.printed_text(value, tolerance) == expected


def test_printed_quantity_units():
    assert report.printed_quantity(-71.6, 0.05, "deg") == "−71.6°"
    assert report.printed_quantity(0.13, 0.0005, "Oe") == "0.130 Oe"


def test_table_is_a_captioned_labelled_list_table():
    import pandas as pd

    frame = pd.DataFrame({"quantity": ["- a leading dash", "1. not a list"], "value": ["1 Ω", "2 Ω"]})
    text = report.table(frame, "A caption", label="tab-x", wide_columns=("quantity",)).data
    lines = text.splitlines()
    assert lines[0] == ":::{list-table} A caption"
    assert ":name: tab-x" in lines and ":widths: 3 2" in lines
    assert "* - quantity" in lines and "  - value" in lines
    # Cells that would start a Markdown list are escaped, so each stays one cell.
    assert "* - \\- a leading dash" in lines and "* - 1\\. not a list" in lines
    assert lines[-1] == ":::"
    assert "|---" not in text


def test_compare_table_shows_written_digits_for_values_written_without_uncertainty():
    rows = {r.id: r for r in chapters.comparisons()}
    bench = [r for r in rows.values() if chapters.row_kind(r) == "measurement" and r.unit == "deg"]
    assert bench, "the bench's orientation-error rows"
    text = report.compare_table(bench, "bench", kind="measurement").data
    assert "  - 10°" in text and "10.00°" not in text


def test_compare_table_refuses_a_row_of_another_kind():
    """A row is shown only under its own kind's column: the IGRF-14 column of the old
    ledger held Basilisk's and Cp557's rows, which now raises."""
    import pytest

    from magbench import compare

    row = compare.make_row("ch05-cp557-median", "q", "s", 1.0, 1.0, 0.1, unit="s")
    assert chapters.row_kind(row) == "claim"
    assert "claimed" in report.compare_table([row], "c", kind="claim").data
    with pytest.raises(ValueError, match="not of kind 'reference'"):
        report.compare_table([row], "c", kind="reference")


def test_values_show_the_digits_their_source_supports():
    """A verbal claim as the range read from words; an uncertainty with the digits it
    supports (the review's '12.50 ± 1.0 Ω' and '12.50 ± 2.5°')."""
    from magbench import compare

    verbal = compare.make_row("rotor-pointing-accuracy", "q", "s", 12.5, 5.7, 2.5, unit="deg")
    assert report.compared_value(verbal) == "10–15°"
    measured = compare.make_row("sim-coil-resistance", "q", "s", 12.5, 13.7, 1.5, unit="ohm", uncertainty=1.5)
    assert report.compared_value(measured) == "12.5 ± 1.5 Ω"
