"""Model-vs-measurement rows: shape, verdict logic and the chapter-1 findings."""

import numpy as np
import pytest

from magbench import chapters, compare, result_cache
from magbench.chapters import ch01_earth_field


def test_make_row_verdict_and_scaling():
    row = compare.make_row("x", "q", "s", 2.0e-6, 2.3e-6, 0.25e-6, unit="uT", scale=1e-6)
    assert row.verdict == "disagrees"
    assert row.measured == pytest.approx(2.0) and row.difference == pytest.approx(0.3)
    assert compare.make_row("x", "q", "s", 1.0, 1.1, 0.1 + 1e-12, unit="1").verdict == "agrees"


def test_geomagnetic_rows_have_the_public_keys():
    rows = ch01_earth_field.geomagnetic_rows(epochs=(1960.0, 2016.0))
    keys = {"id", "kind", "quantity", "source", "measured", "uncertainty", "unit", "model",
            "difference", "tolerance", "verdict"}
    for row in rows:
        assert set(row.as_dict()) == keys
        assert np.isfinite([row.measured, row.model, row.tolerance]).all()
    by_id = {r.id: r for r in rows}
    # The thesis's pole is the 1960 pole to its printed digits, not the 2016 one.
    assert by_id["pole-latitude-1960"].verdict == "agrees"
    assert by_id["pole-latitude-2016"].verdict == "disagrees"


def test_no_row_depends_on_the_build_date(monkeypatch):
    """Rows are dated 1960 and the thesis's year, never by the clock (nor by IGRF's
    newest epoch, no test of a 2016 thesis): a build a year later gives the same rows."""
    import datetime as dt

    ids = [r.id for r in chapters.comparisons()]
    assert "dipole-moment-2016" in ids and "dipole-moment-1960" in ids
    assert not any(i.endswith("-2025") for i in ids)

    class Later(dt.datetime):
        @classmethod
        def now(cls, tz=None):
            return dt.datetime(2031, 6, 1, tzinfo=tz)

    monkeypatch.setattr(dt, "datetime", Later)
    with result_cache.disabled():      # the rows formed again, not loaded from the first call's
        assert [r.id for r in chapters.comparisons()] == ids


def test_rows_and_checks_are_one_type():
    """A model-vs-measurement row and a printed-value check are both Comparisons, with
    the same verdict rule and their SI values one multiplication away."""
    from magbench.errata import source_check

    row = compare.make_row("x", "q", "s", 2.0e-6, 2.3e-6, 0.25e-6, unit="uT", scale=1e-6)
    check = source_check(id="y", chapter="ch01", source="thesis", location="§1", quantity="q", printed=10.0,
                         computed=10.4, tolerance=0.5, unit="deg", explanation="e", computation="c")
    assert type(row) is type(check) is compare.Comparison
    assert check.agrees and check.printed == check.measured == 10.0 and check.computed == check.model == 10.4
    assert row.measured_si == pytest.approx(2.0e-6, rel=1e-15)         # µT back to T
    assert check.model_si == pytest.approx(np.radians(10.4), rel=1e-15)  # degrees to rad
    assert check.relative_difference == pytest.approx(-0.4 / 10.4)
    assert set(check.as_dict()) == set(row.as_dict())
