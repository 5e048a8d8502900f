"""The linearised PID loop's transfer functions and state space against its characteristic
polynomial (the peer checks against python-control are in tests/peers/test_python_control.py)."""

import numpy as np
import pytest
from numpy.testing import assert_allclose

from magbench import control

J, B0 = 0.005, 3.14e-4
GAINS = [(0.1, 0.5, 0.5), (0.1, 0.5, 3.0), (1.5, 0.05, 15.0)]   # two printed sets (unstable in SI), a stable one


@pytest.mark.parametrize("kp, ki, kd", GAINS)
def test_loop_forms_share_the_characteristic_polynomial(kp, ki, kd):
    poly = control.closed_loop_polynomial(J, B0, kp, ki, kd)
    num, den = control.open_loop_transfer(J, B0, kp, ki, kd)
    # 1 + L(s) = 0 ⇔ den + num = 0 (num padded to the denominator's degree); exact sums.
    assert_allclose(den + np.concatenate([[0.0], num]), poly, rtol=1e-15)
    a, c = control.closed_loop_state_space(J, B0, kp, ki, kd)
    # rtol 1e-12: np.poly goes through the eigenvalues of A.
    assert_allclose(np.poly(a), poly / J, rtol=1e-12, atol=1e-15)
    assert_allclose(c, [[-kp, -kd, ki]], rtol=0)
    cnum, cden = control.closed_loop_transfer(J, B0, kp, ki, kd)
    assert_allclose(cden, poly, rtol=0)
    assert cnum[-1] / cden[-1] == 1.0          # unit DC gain: the integral removes a steady error


@pytest.mark.parametrize("call, match", [
    (lambda: control.open_loop_transfer(-1.0, B0, 0.1, 0.5, 0.5), "inertia"),
    (lambda: control.closed_loop_transfer(J, 0.0, 0.1, 0.5, 0.5), "field"),
    (lambda: control.closed_loop_state_space(J, B0, np.nan, 0.5, 0.5), "kp"),
])
def test_bad_input_is_named(call, match):
    with pytest.raises(ValueError, match=match):
        call()
