"""Power of a winding at given ampere-turns, and the size of a coil system at equal power.

Checked against the thesis's own winding formulas (R = 2πaρN/S₀, P = I²R), eq. (16),
exact scalings and the field of a square loop.
"""

import numpy as np
import pytest
from numpy.testing import assert_allclose

from magbench import fields, hardware
from magbench.constants import MU_0

RHO = 0.0175e-6     # the thesis's copper [Ω·m]
D_WIRE = 0.75e-3    # the simulator's wire [m]


@pytest.mark.parametrize("turns, current", [(110, 2.3), (100, 2.58), (1, 250.0)])
def test_ampere_turns_power_is_i2r_of_the_winding(turns, current):
    # N turns of wire area S₀ fill A = N S₀; the power must be the thesis's I²R of that winding.
    area = turns * np.pi * D_WIRE**2 / 4
    p = hardware.ampere_turns_power(0.5, turns * current, area, RHO)
    assert_allclose(p, hardware.winding_power(0.5, turns, D_WIRE, RHO, current), rtol=1e-13)  # rounding only


def test_ampere_turns_power_square_turn_and_split():
    # A square turn of side l has length 4l; the split of NI into N and I does not matter.
    turn = hardware.Turn.square(0.1)
    p1 = hardware.ampere_turns_power(turn, 240 * 0.1, 240 * 3e-8, RHO)
    r = hardware.coil_resistance(120, 0.1, 3e-8 * 2, RHO, "square")     # half the turns, twice the wire
    assert_allclose(p1, r * (240 * 0.1 / 120) ** 2, rtol=1e-13)              # rounding only
    assert_allclose(p1, RHO * 0.4 * (240 * 0.1) ** 2 / (240 * 3e-8), rtol=1e-15)


@pytest.mark.parametrize("kw, name", [({"winding_area": 0.0}, "winding_area"), ({"resistivity": -1.0}, "resistivity"),
                                      ({"ampere_turns": np.inf}, "ampere_turns"), ({"turn": 0.0}, "radius")])
def test_ampere_turns_power_bad_input(kw, name):
    args = {"turn": 0.5, "ampere_turns": 100.0, "winding_area": 1e-5, "resistivity": RHO} | kw
    with pytest.raises(ValueError, match=name):
        hardware.ampere_turns_power(**args)


HELMHOLTZ = (["round"] * 2, [1.0, 1.0], [-0.5, 0.5], [1.0, 1.0])


def test_helmholtz_pair_round_trip_through_eq16_and_the_power():
    # The returned size and ampere-turns must give back the centre field (eq. 16) and the
    # power (two coils of I²R): independent formulas, so only rounding (1e-12) separates them.
    h0, power, area = 250.0, 80.0, 110 * np.pi * D_WIRE**2 / 4
    scale, ni = hardware.coaxial_system_scale_for_power(*HELMHOLTZ, h0, power, area, RHO)
    assert_allclose(ni[0], ni[1], rtol=0)
    assert_allclose(fields.helmholtz_center_h(1.0, ni[0], scale, scale), h0, rtol=1e-12)
    assert_allclose(2 * hardware.ampere_turns_power(scale, ni[0], area, RHO), power, rtol=1e-12)


def test_square_pair_round_trip():
    # Squares of side 1 at ±0.2722: the centre field from the square-loop formula, turn length 4l.
    half = float(fields.square_pair_spacing(1.0)) / 2
    system = (["square"] * 2, [1.0, 1.0], [-half, half], [1.0, 1.0])
    scale, ni = hardware.coaxial_system_scale_for_power(*system, 100.0, 50.0, 1e-5, RHO)
    b = sum(fields.square_loop_b([0.0, 0.0, 0.0], scale, ni[0], 1, [0.0, 0.0, s * half * scale]) for s in (-1, 1))
    assert_allclose(np.linalg.norm(b) / MU_0, 100.0, rtol=1e-12)                       # rounding only
    assert_allclose(2 * hardware.ampere_turns_power(hardware.Turn.square(scale), ni[0], 1e-5, RHO), 50.0, rtol=1e-12)


def test_only_ratios_of_weights_and_shape_of_geometry_count():
    base = hardware.coaxial_system_scale_for_power(*HELMHOLTZ, 250.0, 80.0, 1e-4, RHO)
    shapes, sizes, pos, w = HELMHOLTZ
    heavier = hardware.coaxial_system_scale_for_power(shapes, sizes, pos, [7.0, 7.0], 250.0, 80.0, 1e-4, RHO)
    bigger = hardware.coaxial_system_scale_for_power(shapes, [3.0, 3.0], [-1.5, 1.5], w, 250.0, 80.0, 1e-4, RHO)
    # Exact invariances of the formula; rounding only.
    assert_allclose(heavier[0], base[0], rtol=1e-13)
    assert_allclose(heavier[1], base[1], rtol=1e-13)
    assert_allclose(3 * bigger[0], base[0], rtol=1e-13)
    assert_allclose(bigger[1], base[1], rtol=1e-13)


def test_size_grows_as_the_cube_root_of_power():
    # L ∝ P^(1/3) at fixed H₀ (closed form); rounding only.
    small = hardware.coaxial_system_scale_for_power(*HELMHOLTZ, 250.0, 10.0, 1e-4, RHO)[0]
    large = hardware.coaxial_system_scale_for_power(*HELMHOLTZ, 250.0, 80.0, 1e-4, RHO)[0]
    assert_allclose(large / small, 2.0, rtol=1e-13)


@pytest.mark.parametrize("kw, name", [({"power": 0.0}, "power"), ({"center_h": -1.0}, "center_h"),
                                      ({"winding_area": 0.0}, "winding_area"), ({"resistivity": 0.0}, "resistivity"),
                                      ({"weights": [1.0, -1.0]}, "centre field zero"),
                                      ({"sizes": [1.0, -1.0]}, "sizes")])
def test_scale_for_power_bad_input(kw, name):
    shapes, sizes, pos, w = HELMHOLTZ
    args = {"shapes": shapes, "sizes": sizes, "positions": pos, "weights": w, "center_h": 250.0,
            "power": 80.0, "winding_area": 1e-4, "resistivity": RHO} | kw
    with pytest.raises(ValueError, match=name):
        hardware.coaxial_system_scale_for_power(**args)


def test_helmholtz_pair_power_is_both_coils_at_the_ampere_turns_of_eq16():
    """Two coils of N turns at I = NI/N: 2 I²R with R = 2πaρN/S₀ (the thesis's winding formulas)."""
    a, d, n, h = 0.5, 0.558, 110.0, 250.0
    current = float(fields.helmholtz_ampere_turns(h, a, d)) / n
    expected = 2 * current**2 * float(hardware.winding_resistance(a, n, D_WIRE, RHO))
    area = n * np.pi * D_WIRE**2 / 4
    assert_allclose(hardware.helmholtz_pair_power(h, a, d, area, RHO), expected, rtol=1e-12)
    with pytest.raises(ValueError, match="winding_area"):
        hardware.helmholtz_pair_power(h, a, d, 0.0, RHO)
