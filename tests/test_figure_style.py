"""Every figure legible in the book's content column.

The book shows a figure at its width in inches × 100 CSS px (report.figure_png). A
figure wider than the column is squeezed by the browser, and its text with it: the
first version drew 13 in wide figures whose 7 pt labels reached the screen at 5 px.
These tests fail for exactly that: a figure wider than MAX_FIGURE_WIDTH, or any text
smaller than 7 pt (9.7 px at 100 px/in).
"""

import matplotlib
import pytest

from magbench import figures

matplotlib.use("Agg")

#: Figures whose defaults take several seconds, or need the BROAD recordings: each declares
#: it when it registers (FigureSpec.slow).
SLOW = {i for i in figures.figure_ids() if figures.get_spec(i).slow}
MIN_FONT_PT = 7.0


def _check(figure_id):
    import matplotlib.pyplot as plt

    fig, _ = figures.render(figure_id)
    try:
        width, _ = fig.get_size_inches()
        assert width <= figures.MAX_FIGURE_WIDTH, (
            f"{figure_id} is {width:.2f} in wide; the column shows at most {figures.MAX_FIGURE_WIDTH} in")
        small = [(t.get_text()[:30], t.get_fontsize()) for t in fig.findobj(matplotlib.text.Text)
                 if t.get_visible() and t.get_text().strip() and t.get_fontsize() < MIN_FONT_PT]
        assert not small, f"{figure_id} has text below {MIN_FONT_PT} pt: {small[:5]}"
        assert not [t for t in fig.texts if "made by" in t.get_text()], \
            f"{figure_id} draws its provenance into the image (the caption carries it)"
    finally:
        plt.close(fig)


@pytest.mark.parametrize("figure_id", [i for i in figures.figure_ids() if i not in SLOW])
def test_figure_fits_the_column_with_legible_text(figure_id):
    _check(figure_id)


@pytest.mark.slow
@pytest.mark.parametrize("figure_id", sorted(SLOW))
def test_slow_figure_fits_the_column_with_legible_text(figure_id):
    _check(figure_id)


def test_the_check_fails_on_a_wide_figure(monkeypatch):
    """The check can fail: a 13 in figure (the first version's size) is rejected."""
    import matplotlib.pyplot as plt

    spec = figures.get_spec("thesis-fig06")

    def wide_plot(data):
        fig, ax = plt.subplots(figsize=(13.0, 4.6))
        ax.plot([0, 1])
        return fig

    monkeypatch.setitem(figures.REGISTRY, "thesis-fig06",
                        figures.FigureSpec(spec.id, spec.title, spec.source, spec.compute, wide_plot,
                                           spec.parameters))
    with pytest.raises(AssertionError, match="13.00 in wide"):
        _check("thesis-fig06")
