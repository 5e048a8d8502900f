"""Error messages show a bad value as the number the user typed, not numpy's ``repr``.

numpy 2 writes a scalar as ``np.float64(-0.5)``; values reach the checks as numpy scalars
when they come from arrays, parameter files or other library results, so each case here
passes one. The message must name the argument and show the plain value.
"""

import numpy as np
import pytest

from magbench import dynamics, earth, fields, hardware
from magbench._validate import shown

CASES = [
    ("radius", -0.5, lambda v: fields.helmholtz_center_h(1.0, 10, v, 0.5)),
    ("latitude", 2.0, lambda v: earth.igrf_field(v, 0.0, 2015.0)),
    ("period", 0.001, lambda v: dynamics.amplitude_for_period(v, 1e-3, 0.1, 5e-5)),
    ("elongation", 2.0, lambda v: hardware.rod_demagnetizing_factor(v)),
]


@pytest.mark.parametrize("name, value, call", CASES, ids=[c[0] for c in CASES])
def test_a_numpy_scalar_is_shown_as_a_plain_number(name, value, call):
    with pytest.raises(ValueError) as info:
        call(np.float64(value))
    message = str(info.value)
    assert name in message
    assert "np." not in message, message
    assert repr(value) in message, message


def test_shown_keeps_python_values_and_unwraps_numpy_ones():
    assert shown(np.float64(-0.5)) == "-0.5"
    assert shown(np.int64(3)) == "3"
    assert shown(np.array(2.5)) == "2.5"
    assert shown((np.float64(0.1), 0.2)) == "(0.1, 0.2)"
    assert shown("coil") == "'coil'"
    assert shown(1.5) == "1.5"
