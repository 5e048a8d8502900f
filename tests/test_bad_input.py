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


def _bench():
    from magbench.chapters.ch04_mockup import bench_setup
    from magbench.io import load_parameter_set

    return bench_setup({k: p.value_si for k, p in load_parameter_set("thesis").items()})


MC = dict(seed=1, duration=1.0, window=0.5)
SPREAD = dict(moment_tolerance=0.05, release_angle_spread=0.5, release_rate_std=0.01, thread_stiffness_factor=3.0)


def test_monte_carlo_refuses_a_fractional_count_and_an_unbounded_run():
    from magbench.sim.bench import BenchDispersion, monte_carlo

    spread = BenchDispersion(**SPREAD)

    # (was) 1.5 members computed one member
    with pytest.raises(ValueError, match=r"members must be a whole number >= 1, got 1.5"):
        monte_carlo(_bench(), 1.0, members=1.5, dispersion=spread, **MC)
    # (was) members=1e9 ran for minutes before running out of memory; now refused before any work
    with pytest.raises(ValueError, match=r"members × steps = 1000000000 × \d+ = .* exceeds 1e\+09 member-steps"):
        monte_carlo(_bench(), 1.0, members=1e9, dispersion=spread, **MC)
    assert monte_carlo(_bench(), 1.0, members=2, dispersion=spread, **MC).psi.shape[-1] == 2      # (time, members)


def test_detumble_refuses_an_unbounded_run():
    from magbench.earth.circular_orbit import CircularOrbit
    from magbench.sim.detumble import detumble_monte_carlo

    orbit = CircularOrbit(6871e3, 1.7, 7.7e22)
    with pytest.raises(ValueError, match="member-steps"):
        detumble_monte_carlo([0.03, 0.03, 0.01], orbit, members=10_000, seed=1, duration=1e6,
                             rate_range=(0.0, 0.1), gain=5e4, max_dipole=0.2, step=1.0)


def test_an_electromagnet_core_beyond_its_saturation_is_refused():
    # (was) permalloy_design_magnetization = 2e6 A/m, above the curve's saturation a, drew a design
    from magbench import figures

    a = figures.resolve_parameters("ch03-actuators")["permalloy_a"]
    with pytest.raises(ValueError, match=r"permalloy_design_magnetization must lie in \(0, permalloy_a"):
        figures.compute("ch03-actuators", permalloy_design_magnetization=1.6 * a)
    figures.compute("ch03-actuators", permalloy_design_magnetization=0.95 * a)
