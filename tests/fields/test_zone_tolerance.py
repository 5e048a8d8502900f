"""The tolerance band a uniform-zone length implies: the inverse of uniform_zone_length."""

import numpy as np
import pytest
from numpy.testing import assert_allclose

from magbench import fields

GRID = np.geomspace(1e-4, 0.1, 61)


@pytest.mark.parametrize("ratio, direction", [(1.0, "axial"), (1.0, "transverse"), (1.116, "transverse"),
                                              (0.8, "axial")])
@pytest.mark.parametrize("delta", [0.003, 0.02])
def test_round_trip_where_the_zone_grows_smoothly(ratio, direction, delta):
    a = 0.5
    length = fields.uniform_zone_length(a, ratio * a, delta, direction)
    # Brent stops at 1e-9 in δ: 1e-6 relative at δ ≥ 3e-3.
    assert_allclose(fields.zone_tolerance_for_length(a, ratio * a, length, direction, GRID), delta, rtol=1e-6)


def test_with_a_jump_the_smallest_band_is_returned():
    # Above d = a the axial field dips at the centre and rises off it: the zone jumps as δ
    # passes the bump. The answer must be the smallest δ whose zone reaches the length.
    a, d, length = 0.5, 0.558, 0.30
    t = fields.zone_tolerance_for_length(a, d, length, "axial", GRID)
    assert all(fields.uniform_zone_length(a, d, s, "axial") < length for s in GRID[GRID < t * (1 - 1e-6)])
    assert fields.uniform_zone_length(a, d, t * (1 + 1e-6), "axial") >= length


def test_outside_the_scan_is_nan():
    a = 0.5
    too_long = fields.uniform_zone_length(a, a, 0.2, "axial")       # needs δ = 0.2 > 0.1, the scan's end
    too_short = 0.5 * fields.uniform_zone_length(a, a, 1e-4, "axial")
    assert np.isnan(fields.zone_tolerance_for_length(a, a, too_long, "axial", GRID))
    assert np.isnan(fields.zone_tolerance_for_length(a, a, too_short, "axial", GRID))


@pytest.mark.parametrize("kw, match", [({"tolerances": [0.1, 0.01]}, "increasing"),
                                       ({"tolerances": [0.01]}, "at least two"),
                                       ({"tolerances": [0.0, 0.1]}, r"\(0, 1\)"),
                                       ({"tolerances": [0.1, 1.5]}, r"\(0, 1\)"),
                                       ({"length": 0.0}, "length"), ({"radius": -1.0}, "radius"),
                                       ({"direction": "radial"}, "direction")])
def test_bad_input(kw, match):
    args = {"radius": 0.5, "separation": 0.5, "length": 0.3, "direction": "axial", "tolerances": GRID} | kw
    with pytest.raises(ValueError, match=match):
        fields.zone_tolerance_for_length(**args)
