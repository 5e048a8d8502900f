"""Turns per layer and the winding band, each wire's feasible turns, and a rod electromagnet's moment.

Checked against the thesis's resistance, power and mass formulas (independent functions),
the design chain's N/U bounds (eq. 32), Kovalenko's eq. (9.64) and exact integer limits.
"""

import numpy as np
import pytest
from numpy.testing import assert_allclose

from magbench import hardware

RHO, GAMMA = 0.0175e-6, 8.9e3      # the thesis's copper
U, SIDE, W_MAX, M_MAX, M_REQ = 12.0, 0.1, 2.0, 0.1, 0.4


def test_turns_per_layer_is_the_floor():
    assert hardware.turns_per_layer(0.1, 0.226e-3) == 442           # 442.47…: floor, exact
    assert hardware.turns_per_layer(0.1, 0.2e-3) in (499, 500)      # 0.1/0.2e-3 rounds either side of 500
    assert hardware.turns_per_layer(0.1, 0.3) == 0                   # wider than the side
    assert_allclose(hardware.turns_per_layer(0.1, [0.01, 0.025, 0.04]), [10, 4, 2], rtol=0)


@pytest.mark.parametrize("turns", [1, 240, 442, 443, 1000, 5000])
def test_winding_band_holds_the_turns_in_the_fewest_layers(turns):
    pitch = 0.226e-3
    per_layer = int(hardware.turns_per_layer(SIDE, pitch))
    layers, width = hardware.winding_band(turns, SIDE, pitch)
    per = round(width / pitch)
    assert layers * per >= turns > (layers - 1) * per_layer     # enough layers, and no fewer would do
    assert per <= per_layer and width <= SIDE
    if turns <= per_layer:
        assert layers == 1
        assert_allclose(width, turns * pitch, rtol=1e-15)        # a single dense layer: rounding only


@pytest.mark.parametrize("kw, match", [({"wire_pitch": 0.2}, "not one turn fits"), ({"turns": 0}, "turns"),
                                       ({"side": -0.1}, "side"), ({"wire_pitch": 0.0}, "wire_pitch")])
def test_winding_band_bad_input(kw, match):
    args = {"turns": 240, "side": SIDE, "wire_pitch": 0.226e-3} | kw
    with pytest.raises(ValueError, match=match):
        hardware.winding_band(**args)


@pytest.mark.parametrize("d", [0.1e-3, 0.2e-3, 0.315e-3, 0.5e-3])
def test_wire_turn_limits_are_the_integer_edges_of_power_and_mass(d):
    s = hardware.wire_area(d)
    lo, hi = hardware.wire_turn_limits(U, SIDE, s, W_MAX, M_MAX, RHO, GAMMA, "square")

    def power(n):
        return float(hardware.joule_power(U, hardware.coil_resistance(n, SIDE, s, RHO, "square")))

    def mass(n):
        return float(hardware.coil_mass(n, SIDE, s, GAMMA, "square"))

    # Integer edges: lo turns meet the power limit and one fewer do not; hi meet the mass
    # limit and one more do not (exact comparisons of the thesis's own formulas).
    assert power(lo) <= W_MAX < power(lo - 1)
    assert mass(hi) <= M_MAX < mass(hi + 1)


def test_wire_turn_limits_agree_with_eq32_for_its_wire():
    # For the wire of eq. (21) the limits are U times the N/U bounds of eq. (32), up to
    # the rounding to whole turns (at most one turn).
    s = hardware.wire_area_for_moment(M_REQ, U, SIDE, RHO)
    lo, hi = hardware.wire_turn_limits(U, SIDE, s, W_MAX, M_MAX, RHO, GAMMA, "square")
    lo_u, hi_u = hardware.turns_per_volt_bounds(M_REQ, SIDE, W_MAX, M_MAX, RHO, GAMMA, "square")
    assert 0 <= lo - lo_u * U < 1 + 1e-9 and 0 <= hi_u * U - hi < 1 + 1e-9


@pytest.mark.parametrize("kw, name", [({"wire_area": 0.0}, "wire_area"), ({"max_power": -1.0}, "max_power"),
                                      ({"max_mass": 0.0}, "max_mass"), ({"shape": "hex"}, "shape"),
                                      ({"voltage": np.nan}, "voltage")])
def test_wire_turn_limits_bad_input(kw, name):
    args = {"voltage": U, "side": SIDE, "wire_area": 3e-8, "max_power": W_MAX, "max_mass": M_MAX,
            "resistivity": RHO, "density": GAMMA, "shape": "square"} | kw
    with pytest.raises(ValueError, match=name):
        hardware.wire_turn_limits(**args)


EM = (M_REQ, 40.0, 1.1e6, 500.0, 0.79, 2e6, 0.5, RHO, 8.0e3, GAMMA, U)


def test_electromagnet_moment_at_the_design_state_is_the_required_moment():
    # Eq. (9.64) sizes D₁ so that k J° π D₁² l/4 = L_p: reading it back gives L_p (rounding only).
    em = hardware.electromagnet_design(*EM)
    assert_allclose(hardware.electromagnet_moment(1.1e6, em["core_diameter"], em["length"], 0.79), M_REQ,
                    rtol=1e-13)


def test_electromagnet_moment_is_bounded_by_saturation():
    # However strong the winding's field, the curve's J stays below a, and so does the moment.
    em = hardware.electromagnet_design(*EM)
    a, b = 1.25e6, 40.0
    j = hardware.core_central_magnetization([1e2, 1e4, 1e7], em["demagnetizing_factor"], a, b)
    m = hardware.electromagnet_moment(j, em["core_diameter"], em["length"], 0.79)
    bound = hardware.electromagnet_moment(a, em["core_diameter"], em["length"], 0.79)
    assert np.all(np.diff(m) > 0) and np.all(m < bound)
    assert_allclose(m[-1], bound, rtol=1e-3)    # H_к = 1e7 A/m: J within (b + N a)/H_к ≈ 1e-4 of a


@pytest.mark.parametrize("kw, name", [({"averaging_factor": 0.0}, "averaging_factor"),
                                      ({"averaging_factor": 1.5}, "averaging_factor"),
                                      ({"core_diameter": 0.0}, "core_diameter"), ({"length": -1.0}, "length"),
                                      ({"central_magnetization": np.inf}, "central_magnetization")])
def test_electromagnet_moment_bad_input(kw, name):
    args = {"central_magnetization": 1e6, "core_diameter": 4e-3, "length": 0.1, "averaging_factor": 0.79} | kw
    with pytest.raises(ValueError, match=name):
        hardware.electromagnet_moment(**args)
