"""magbench.control.rotor_stability: the rotor's linearisation, Floquet multipliers and
stability map, moved from magbench.sim.spinning; the same numbers and the same names there.
The physics checks (Jacobian of the nonlinear loop, the finite-difference monodromy) stay
in tests/sim/test_spinning.py, which imports them from magbench.sim."""

import numpy as np
import pytest
from numpy.testing import assert_allclose

from magbench import control, sim
from magbench.control import (rotor_floquet_multipliers, rotor_linearised_matrices, rotor_model_numbers,
                              rotor_stability_map)

A, C1, INC = 1.5, 2.0, np.radians(51.6)


def test_the_simulation_package_serves_the_same_functions():
    for name in ("rotor_linearised_matrices", "rotor_floquet_multipliers", "rotor_stability_map"):
        assert getattr(sim, name) is getattr(control, name)
        assert getattr(sim.spinning, name) is getattr(control, name)


def test_multipliers_and_map_are_the_numbers_before_the_move():
    # Recorded from magbench.sim.spinning at commit 40949ce (before the move). The same
    # operations in the same order; 1e-12 leaves room only for a different BLAS/LAPACK
    # ordering of the eigenvalue solve, not for a changed computation.
    rho = np.abs(rotor_floquet_multipliers(A, C1, [4.0, 10.0], [2.0, 0.5], INC, steps=200))
    assert_allclose(rho, [[3.6910744096525594e-01, 2.4299841004680973e-02, 2.4299841004680973e-02,
                           1.1882919715855724e-03, 1.1882919715855724e-03],
                          [2.7621839719283217e+00, 4.1820205478335709e-01, 4.1820205478335709e-01,
                           1.8741345130243181e-01, 4.6263323308541389e-02]], rtol=1e-12)
    grid = rotor_stability_map([1.0, 5.0], [0.5, 2.0], axial_ratio=A, momentum=C1, inclination=INC, steps=200)
    assert_allclose(grid, [[3.4470408538372546, 1.885612702200469], [0.3101806370283198, 0.4882541534418764]],
                    rtol=1e-12)
    sums = [m.sum() for m in rotor_linearised_matrices(0.7, A, C1, INC)]
    # closed-form entries summed: rounding of 75 terms of order 1
    assert_allclose(sums, [-1.5133452125883013, -3.6112766323365486, -1.7369567826297987], rtol=1e-14)


@pytest.mark.parametrize("args, name", [
    ((0.0, C1, INC), "axial_ratio"), ((A, np.nan, INC), "momentum"), ((A, C1, 4.0), "inclination"),
    ((A, C1, 0.0), "inclination"), ((A, C1, np.pi), "inclination"),
])
def test_model_numbers_reject_bad_input_naming_the_parameter(args, name):
    with pytest.raises(ValueError, match=name):
        rotor_model_numbers(*args)


def test_model_numbers_are_floats():
    assert rotor_model_numbers(np.float64(A), 2, INC) == (A, 2.0, INC)
