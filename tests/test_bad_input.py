"""Bad input the library used to accept or answer with someone else's error (the audit of
issue 14). Each case names what happened before; each now raises ValueError naming the
argument and the value, and a nearby valid input still computes."""

import numpy as np
import pytest

from magbench import control, earth, estimation, fields
from magbench.sim.bench import quantise_duty

CASES = [
    # (was) returned -8e6 T from inside the core
    ("altitude", lambda: earth.igrf_field(0.5, 0.1, 2015.0, altitude=-7e6),
     lambda: earth.igrf_field(0.5, 0.1, 2015.0, altitude=-1e6)),
    # (was) TypeError: only 0-dimensional arrays can be converted
    ("latitude must be a scalar", lambda: earth.igrf_field(np.array([0.1, 0.2]), 0.1, 2015.0),
     lambda: earth.igrf_field(0.1, 0.1, 2015.0)),
    # (was) computed with degree 1
    ("max_degree", lambda: earth.igrf_field(0.1, 0.1, 2015.0, max_degree=1.5),
     lambda: earth.igrf_field(0.1, 0.1, 2015.0, max_degree=1)),
    # (was) numpy's "deg must be a positive integer"
    ("nodes", lambda: earth.igrf_mean_surface_b(2015.0, nodes=0),
     lambda: earth.igrf_mean_surface_b(2015.0, nodes=4)),
    # (was) 1.30 for a sphere through the wires (528 for another)
    ("sphere_radius", lambda: fields.sphere_nonuniformity(0.5, 0.5, 0.6),
     lambda: fields.sphere_nonuniformity(0.5, 0.5, 0.55)),
    # (was) IndexError
    ("at least one sample", lambda: estimation.complementary_filter(np.array([]), np.array([]), 0.01, 0.98),
     lambda: estimation.complementary_filter(np.zeros(1), np.ones(1), 0.01, 0.98)),
    # (was) 0.667: rint(-1.5)/-3
    ("levels", lambda: quantise_duty(0.5, -3), lambda: quantise_duty(0.5, 3)),
    # (was) an inverted output: clip(u, 1, -1)
    ("output_limit", lambda: control.pid_step(1.0, 0.0, 0.0, 0.01, 1.0, 0.0, 0.0, output_limit=-1.0),
     lambda: control.pid_step(1.0, 0.0, 0.0, 0.01, 1.0, 0.0, 0.0, output_limit=1.0)),
]


@pytest.mark.parametrize("name, bad, good", CASES, ids=[c[0].split()[0] for c in CASES])
def test_bad_input_is_refused_by_name_and_good_input_still_computes(name, bad, good):
    with pytest.raises(ValueError, match=name):
        bad()
    result = good()
    assert np.all(np.isfinite(np.asarray(getattr(result, "total", result), float)))


def test_a_sphere_just_inside_the_wires_is_accepted_and_the_bound_is_the_wire_distance():
    a, d = 0.5, 0.5
    wire = np.hypot(a, d / 2)        # every point of both wires is this far from the centre
    fields.sphere_nonuniformity(a, d, wire * (1 - 1e-9))
    with pytest.raises(ValueError, match="0.559017"):
        fields.sphere_nonuniformity(a, d, wire)


def test_quantise_duty_keeps_its_documented_results():
    # The docstring's example and levels=0 (no quantisation) are unchanged by the check.
    np.testing.assert_allclose(quantise_duty([0.5, -0.001, 0.003], 255), [128 / 255, 0.0, 1 / 255], rtol=1e-15)
    assert quantise_duty(0.3, 0) == 0.3
