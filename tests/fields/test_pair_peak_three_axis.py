"""The midpoint field's peak over coil radii, and the uniform sphere of a three-axis simulator.

Checked against a closed-form maximum, the Helmholtz pair's fourth-order field error, an
exact linear symmetry and magpylib (an independent Biot–Savart code).
"""

import numpy as np
import pytest
from numpy.testing import assert_allclose
from scipy import optimize

from magbench import fields
from magbench.constants import MU_0


# --- pair_peak_center_h ------------------------------------------------------------------

@pytest.mark.parametrize("ni, d", [(253.0, 0.51), (1.0, 1.0), (40.0, 0.02)])
def test_peak_is_the_maximum_of_eq16_over_the_radius(ni, d):
    best = optimize.minimize_scalar(lambda a: -float(fields.helmholtz_center_h(1.0, ni, a, d)),
                                    bounds=(0.1 * d, 10 * d), method="bounded", options={"xatol": 1e-10 * d})
    # At a maximum the value is flat: a radius error of 1e-10 d changes H by ~1e-20 relative;
    # 1e-12 leaves room for the optimiser's own stopping rule.
    assert_allclose(-best.fun, fields.pair_peak_center_h(ni, d), rtol=1e-12)
    assert_allclose(best.x, d / np.sqrt(2.0), rtol=1e-5)     # flat maximum: the argmax is known to √xatol


def test_peak_bounds_the_radius_solver():
    ni, d = 253.0, 0.51
    peak = float(fields.pair_peak_center_h(ni, d))
    # Just below the peak a radius exists (near d/√2); just above, none does.
    a = fields.pair_radius_for_center_h(peak * (1 - 1e-9), ni, d)
    assert_allclose(fields.helmholtz_center_h(1.0, ni, a, d), peak * (1 - 1e-9), rtol=1e-12)  # solver's xtol
    with pytest.raises(ValueError, match="center_h must be <="):
        fields.pair_radius_for_center_h(peak * (1 + 1e-9), ni, d)


def test_peak_scales_as_ampere_turns_over_separation():
    # Exact scalings of the closed form (only rounding differs).
    assert_allclose(fields.pair_peak_center_h(3.0, 2.0), 1.5 * fields.pair_peak_center_h(1.0, 1.0), rtol=1e-15)
    assert_allclose(fields.pair_peak_center_h(-2.0, 1.0), -2 * fields.pair_peak_center_h(1.0, 1.0), rtol=1e-15)


@pytest.mark.parametrize("kw, name", [({"separation": 0.0}, "separation"), ({"separation": -1.0}, "separation"),
                                      ({"ampere_turns": np.nan}, "ampere_turns")])
def test_peak_bad_input(kw, name):
    args = {"ampere_turns": 1.0, "separation": 1.0} | kw
    with pytest.raises(ValueError, match=name):
        fields.pair_peak_center_h(**args)


# --- three_axis_uniform_radius ------------------------------------------------------------

A, N = 0.5, 110.0


def _x_pair(h=250.0, background=(0.0, 0.0, 0.0), radius=A):
    target = np.array([MU_0 * h, 0.0, 0.0])
    i = fields.three_axis_pair_currents(target, background, radius, radius, N)
    return i, target


def test_helmholtz_error_is_fourth_order():
    # A Helmholtz pair's field deviates as (r/a)^4 near the centre, so the radius of the
    # δ-sphere grows as δ^(1/4): a factor 100 in δ is a factor √10 in radius. The next
    # term is (r/a)^6, a relative correction of order (r/a)^2 ≈ 1e-2 at δ = 1e-4; 2 % covers it.
    i, target = _x_pair()
    r_small = fields.three_axis_uniform_radius(i, A, A, N, np.zeros(3), target, 1e-6)
    r_large = fields.three_axis_uniform_radius(i, A, A, N, np.zeros(3), target, 1e-4)
    assert_allclose(r_large / r_small, 100 ** 0.25, rtol=2e-2)


def test_against_magpylib():
    magpy = pytest.importorskip("magpylib")
    radii = np.array([0.50, 0.55, 0.60])
    background = np.array([15e-6, 2e-6, 48e-6])
    target = np.array([MU_0 * 250.0, 0.0, 0.0])
    i = fields.three_axis_pair_currents(target, background, radii, radii, N)
    r_u = fields.three_axis_uniform_radius(i, radii, radii, N, background, target, 0.01)
    loops = []
    for k, (a, current) in enumerate(zip(radii, i)):
        rot = {0: ("y", 90), 1: ("x", -90), 2: ("z", 0)}[k]
        for sign in (-1, 1):
            pos = np.zeros(3)
            pos[k] = sign * a / 2
            loop = magpy.current.Circle(diameter=2 * a, current=current * N, position=pos)
            loop.rotate_from_angax(rot[1], rot[0], anchor=pos)
            loops.append(loop)
    coll = magpy.Collection(*loops)

    def deviation(s):
        b = background + coll.getB(s * fields.SPHERE_DIRECTIONS)
        return np.max(np.linalg.norm(b - target, axis=-1)) / np.linalg.norm(target)

    # At the returned radius the independent field deviates by δ: the radius is found to
    # 1e-7 m and the two Biot–Savart codes agree to ~1e-8 relative, so 1e-4 of δ is ample.
    assert_allclose(deviation(r_u), 0.01, rtol=1e-4)
    assert deviation(0.9 * r_u) < 0.01


def test_cancelling_a_background_is_the_mirror_of_making_it():
    # B = bg + C i is linear: cancelling bg = −B_t with i is the same field error as making
    # B_t from nothing with the same i, and the reference |bg| equals |B_t|. Exact.
    i, target = _x_pair()
    made = fields.three_axis_uniform_radius(i, A, A, N, np.zeros(3), target, 0.01)
    cancelled = fields.three_axis_uniform_radius(i, A, A, N, -target, np.zeros(3), 0.01)
    assert made == cancelled


def test_scales_with_the_coils():
    # Every length times k: the radius times k, to the root finder's 1e-7 m (2e-6 relative here).
    i1, t1 = _x_pair(radius=0.5)
    i2, t2 = _x_pair(radius=1.0)
    r1 = fields.three_axis_uniform_radius(i1, 0.5, 0.5, N, np.zeros(3), t1, 0.01)
    r2 = fields.three_axis_uniform_radius(i2, 1.0, 1.0, N, np.zeros(3), t2, 0.01)
    assert_allclose(r2, 2 * r1, rtol=2e-6)


@pytest.mark.parametrize("kw, match", [
    ({"tolerance": 1.5}, "tolerance"), ({"tolerance": 0.0}, "tolerance"),
    ({"currents": [1.0, 2.0]}, "currents"), ({"radii": -0.5}, "radii"),
    ({"target_b": [0.0, 0.0, 0.0], "background_b": [0.0, 0.0, 0.0]}, "both be zero"),
])
def test_three_axis_uniform_radius_bad_input(kw, match):
    args = {"currents": [1.0, 0.0, 0.0], "radii": A, "separations": A, "turns": N,
            "background_b": [0.0, 0.0, 0.0], "target_b": [1e-4, 0.0, 0.0], "tolerance": 0.01} | kw
    with pytest.raises(ValueError, match=match):
        fields.three_axis_uniform_radius(**args)
