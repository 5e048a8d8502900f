"""magbench.sim.spinning: the closed-loop normalised model, its linearisation and Floquet
map (against a finite-difference monodromy and solve_ivp variational solves), the scalar SI
right-hand side (against the numpy composition of the library's pieces) and the SI run
(against the normalised model)."""

import dataclasses

import numpy as np
import pytest
from numpy.testing import assert_allclose
from scipy.integrate import solve_ivp
from scipy.spatial.transform import Rotation

from magbench.chapters.ch06_rotor.defaults import default_rotor_orbit, default_rotor_satellite
from magbench.control import floquet_multipliers, projected_damping_dipole, rotor_equilibrium_dipole
from magbench.dynamics import gyrostat_momentum, gyrostat_rhs, semi_body_axes
from magbench.earth import CircularOrbit, dipole_equatorial_b
from magbench.sim import rotor_normalised, spinning
from magbench.sim.spinning import (RotorSatellite, rotor_body_rhs, rotor_dimensionless,
                                   rotor_finite_difference_monodromy, rotor_floquet_multipliers,
                                   rotor_linearised_matrices, rotor_normalised_rhs, rotor_satellite_from_dimensionless,
                                   rotor_stability_map, simulate_rotor, simulate_rotor_normalised)

INC = np.radians(51.6)
A, C1 = 0.8, 1.0


@pytest.mark.parametrize("gains", [(4.0, 2.0), (0.0, 0.0), (10.0, 7.0)])
def test_the_reference_is_an_exact_solution(gains):
    tau = np.linspace(0, 2 * np.pi, 25)
    for t in tau:
        ref = np.array([0.0, 0.0, C1 * np.cos(t) ** 2, 1.0, 0.0])
        # rounding of O(1) terms
        assert_allclose(rotor_normalised_rhs(t, ref, A, C1, *gains, INC), [0, 0, -C1 * np.sin(2 * t), 0, 0],
                        atol=1e-14)


def test_linearised_matrices_are_the_jacobian_of_the_nonlinear_model():
    kappa, kappa_w, d = 3.0, 1.7, 1e-6
    for t in np.linspace(0.1, 6.2, 9):
        ref = np.array([0.0, 0.0, C1 * np.cos(t) ** 2, 1.0, 0.0])
        steps = d * np.eye(5)
        jac = (rotor_normalised_rhs(t, ref[:, None] + steps, A, C1, kappa, kappa_w, INC)
               - rotor_normalised_rhs(t, ref[:, None] - steps, A, C1, kappa, kappa_w, INC)) / (2 * d)
        a0, a1, a2 = rotor_linearised_matrices(t, A, C1, INC)
        # central differences: error d²|f'''| ~ 1e-12 plus rounding 1e-16/d ~ 1e-10
        assert_allclose(a0 + kappa * a1 + kappa_w * a2, jac, atol=1e-8)


def test_floquet_multipliers_agree_with_the_finite_difference_monodromy_of_the_nonlinear_model():
    for gains in ((4.0, 2.0), (1.0, 0.5), (10.0, 10.0)):
        rho = rotor_floquet_multipliers(A, C1, *gains, INC, steps=2000)
        rho_fd = floquet_multipliers(rotor_finite_difference_monodromy(A, C1, *gains, INC, steps=2000))
        # the largest multiplier: RK4 at 2000 steps (1e-9) and differences with δ = 1e-6 (δ² |Φ''| ~ 1e-10
        # plus rounding/δ ~ 1e-10), relative 1e-6 leaves a margin of 100
        assert_allclose(abs(rho[0]), abs(rho_fd[0]), rtol=1e-6)
        assert_allclose(np.sort(np.abs(rho)), np.sort(np.abs(rho_fd)), rtol=1e-4, atol=1e-7)


def test_floquet_multipliers_agree_with_a_variational_solve_ivp():
    """scipy as peer: Φ' = A(τ)Φ by DOP853 at rtol 1e-11."""
    kappa, kappa_w = 4.0, 2.0

    def rhs(t, y):
        a0, a1, a2 = rotor_linearised_matrices(t, A, C1, INC)
        return ((a0 + kappa * a1 + kappa_w * a2) @ y.reshape(5, 5)).ravel()

    phi = solve_ivp(rhs, (0, 2 * np.pi), np.eye(5).ravel(), method="DOP853", rtol=1e-11, atol=1e-13).y[:, -1]
    expected = floquet_multipliers(phi.reshape(5, 5))
    # RK4 with 1000 steps: global error ~1e-8 relative on the largest multiplier
    assert_allclose(np.abs(rotor_floquet_multipliers(A, C1, kappa, kappa_w, INC)), np.abs(expected),
                    rtol=1e-6, atol=1e-9)


def test_known_points_of_the_map():
    """Regression anchors of rotor_spin.md §7 (computed there three ways): the default gains are
    stable with max|ρ| = 0.1424, no control is unstable (gravity gradient with A < B), too much
    damping is unstable."""
    rho = np.abs(rotor_floquet_multipliers(A, C1, [4.0, 1.0, 10.0, 0.0], [2.0, 0.5, 10.0, 0.0], INC))[:, 0]
    assert_allclose(rho, [0.1424, 0.5838, 8.171, 20.66], rtol=5e-4)      # the digits printed there


def test_stability_map_shape_and_consistency():
    k, kw = np.array([1.0, 4.0, 10.0]), np.array([0.5, 2.0])
    m = rotor_stability_map(k, kw, axial_ratio=A, momentum=C1, inclination=INC, steps=500)
    assert m.shape == (2, 3)
    point = np.abs(rotor_floquet_multipliers(A, C1, 10.0, 0.5, INC, steps=500))[0]
    assert_allclose(m[0, 2], point, rtol=1e-12)          # the same computation, batched
    assert m[1, 1] < 1


def test_normalised_simulation_matches_solve_ivp_and_decays_at_the_floquet_rate():
    x0 = np.array([0.02, -0.01, C1 + 0.01, 1.0, 0.0])
    run = simulate_rotor_normalised(A, C1, 4.0, 2.0, INC, x0, 3, steps_per_orbit=1000)
    peer = solve_ivp(rotor_normalised_rhs, (0, 6 * np.pi), x0, args=(A, C1, 4.0, 2.0, INC), method="DOP853",
                     rtol=1e-11, atol=1e-13, t_eval=run.time[::500]).y
    states = np.stack([run.alpha, run.beta, run.h, run.rate_2, run.rate_3])[:, ::500]
    assert_allclose(states, peer, atol=1e-8)            # RK4 at 1000 steps/orbit: ~1e-10
    # small errors shrink by about max|ρ| = 0.142 per orbit (linear regime; transient factors allowed)
    err = np.abs(run.alpha[::1000])
    assert err[3] < 0.05 * err[0]


def test_members_are_independent():
    x0 = np.array([[0.1, 0.0], [0.0, -0.05], [C1, C1], [1.0, 1.0], [0.0, 0.0]])
    both = simulate_rotor_normalised(A, C1, [4.0, 2.0], [2.0, 0.75], INC, x0, 1, steps_per_orbit=300)
    one = simulate_rotor_normalised(A, C1, 2.0, 0.75, INC, x0[:, 1], 1, steps_per_orbit=300)
    assert both.alpha.shape == (301, 2)
    assert_allclose(both.alpha[:, 1], one.alpha, rtol=1e-13, atol=1e-16)


@pytest.mark.parametrize("case", ["one", "members", "tilted-members", "monodromy"])
def test_compiled_normalised_loop_equals_the_numpy_loop(monkeypatch, case):
    # Every operation of the compiled loop is the numpy loop's, in the same order, without
    # fast-math, and its sines and cosines equal numpy's: equal to the last bit.
    x1 = np.array([0.3, -0.2, C1 + 0.1, 0.9, 0.05])
    xm = np.array([[0.1, 0.0, -0.4], [0.0, -0.05, 0.2], [C1, C1 - 0.1, C1], [1.0, 1.1, 1.0], [0.0, 0.02, -0.1]])
    runs = []
    for engine in ("numpy", "compiled"):
        monkeypatch.setattr(rotor_normalised, "_NORMALISED_ENGINE", engine)
        if case == "monodromy":
            runs.append(rotor_finite_difference_monodromy(A, C1, 4.0, 2.0, INC, steps=200))
            continue
        x0, gains, tilt = {"one": (x1, (4.0, 2.0), 0.0), "members": (xm, ([4.0, 2.0, 10.0], [2.0, 0.75, 0.3]), 0.0),
                           "tilted-members": (xm, (4.0, [2.0, 0.75, 0.3]), np.radians(11.5))}[case]
        run = simulate_rotor_normalised(A, C1, *gains, INC, x0, 1, steps_per_orbit=200, real_dipole_tilt=tilt,
                                        real_node_phase=0.7)
        runs.append(np.stack([run.alpha, run.beta, run.h, run.rate_2, run.rate_3]))
    np.testing.assert_array_equal(runs[1], runs[0])


def _tilted_orbit():
    return CircularOrbit(6871e3, INC, 8.1e22, 0.4, ascending_node=0.3, dipole_tilt=np.radians(11.5),
                         dipole_longitude=1.0, earth_rotation_rate=7.29e-5)


def _satellite(inertia, **changes):
    sat = rotor_satellite_from_dimensionless(inertia, 1e-3, -np.pi, default_rotor_orbit(), momentum=1.0,
                                             restoring=4.0, damping=2.0, moment_limit=0.02)
    return dataclasses.replace(sat, **changes)


@pytest.mark.parametrize("damping", ["rate", "momentum"])
def test_scalar_body_rhs_is_the_composition_of_the_library_pieces(damping):
    inertia = np.array([[0.2, 0.002, -0.001], [0.002, 0.1875, 0.0005], [-0.001, 0.0005, 0.3125]])
    sat, orbit = _satellite(inertia), _tilted_orbit()
    rng = np.random.default_rng(3)
    n = orbit.mean_motion
    b0 = dipole_equatorial_b(orbit.earth_moment, orbit.radius)
    hr = sat.rotor_inertia * sat.rotor_rate
    for _ in range(5):
        t = rng.uniform(0, 6000)
        q = rng.normal(size=4)
        q /= np.linalg.norm(q)
        w = rng.normal(size=3) * 1e-2 + [-np.pi, 0, 0]
        c = Rotation.from_quat(q, scalar_first=True).as_matrix().T
        u = orbit.argument_of_latitude(t)
        field_body = c @ orbit.field_orbital(t)
        m = semi_body_axes(c).T @ rotor_equilibrium_dipole(u, orbit.inclination, b0, sat.restoring_gain,
                                                           sat.axial_momentum, n)
        if damping == "rate":
            error = w - n * c[:, 1] - (sat.axial_momentum * np.cos(u) ** 2 - hr) / inertia[0, 0] * np.eye(3)[0]
        else:
            k_ref = sat.axial_momentum * np.cos(u) ** 2 * np.eye(3)[0] + sat.transverse_inertia * n * c[:, 1]
            error = (gyrostat_momentum(w, inertia, hr) - k_ref) / sat.transverse_inertia
        m = np.clip(m + projected_damping_dipole(field_body, error, sat.damping_gain), -0.02, 0.02)
        expected = gyrostat_rhs(t, np.concatenate([q, w]), m, orbit.field_orbital(t), inertia, hr, n)
        got = rotor_body_rhs(t, np.concatenate([q, w]), sat, orbit, damping=damping)
        # same equations, different arithmetic order: rounding relative to the largest terms
        assert_allclose(got, expected, rtol=1e-9, atol=1e-15)


@pytest.mark.parametrize("damping", ["rate", "momentum"])
def test_compiled_body_rhs_equals_its_uncompiled_source(damping):
    # The kernel and its own source run by Python: no fast-math, so every operation and its
    # order are Python's and the results are equal to the last bit (also the controller's).
    from magbench.sim._rotor_kernel import rotor_controller, rotor_rhs
    from magbench.sim.spinning import _body_constants

    inertia = np.array([[0.2, 0.002, -0.001], [0.002, 0.1875, 0.0005], [-0.001, 0.0005, 0.3125]])
    constants = _body_constants(_satellite(inertia), _tilted_orbit(), damping)
    rng = np.random.default_rng(5)
    for _ in range(20):
        t, q, w = rng.uniform(0, 6000), rng.normal(size=4), rng.normal(size=3) * 1e-2 + [-np.pi, 0, 0]
        y = np.concatenate([q / np.linalg.norm(q), w])
        np.testing.assert_array_equal(rotor_rhs(t, y, constants), rotor_rhs.py_func(t, y, constants))
        assert rotor_controller(t, *y, constants) == rotor_controller.py_func(t, *y, constants)


def test_si_run_matches_the_normalised_model_for_the_symmetric_body():
    """Same start in both models (rotor_spin.md §4 mapping); a slow spin keeps the test quick:
    the spin does not enter the symmetric model."""
    orbit = default_rotor_orbit()
    sat = _satellite(np.array([0.2, 0.25, 0.25]), spin_rate=-0.05, moment_limit=np.inf)
    sat = rotor_satellite_from_dimensionless(sat.inertia, sat.rotor_inertia, -0.05, orbit, momentum=1.0,
                                             restoring=4.0, damping=2.0)
    d = rotor_dimensionless(sat, orbit)
    alpha0, beta0 = np.radians(20.0), np.radians(-15.0)
    run = simulate_rotor(sat, orbit, 2 * orbit.period, initial_angles=(alpha0, beta0, 0.3),
                         sample_interval=orbit.period / 20, rtol=1e-10, atol=1e-12)
    x0 = [alpha0, beta0, d["momentum"] + d["axial_ratio"] * np.sin(beta0), np.cos(beta0), 0.0]
    tau = orbit.mean_motion * run.time
    x = solve_ivp(rotor_normalised_rhs, (0, tau[-1]), x0, args=(d["axial_ratio"], d["momentum"], d["restoring"],
                                                                  d["damping"], d["inclination"]),
                  method="DOP853", rtol=1e-11, atol=1e-13, t_eval=tau).y
    # both solved to rtol ≤ 1e-10: 2e-6 rad (1e-4°) is the agreement rotor_spin.md §3 quotes
    assert_allclose(run.angles[:, :2].T, x[:2], atol=2e-6)
    assert np.degrees(run.pointing_error.max()) > 20          # a large-angle transient, not the linear regime


def test_a_start_on_the_reference_stays_on_it():
    orbit = default_rotor_orbit()
    sat = _satellite(np.array([0.2, 0.25, 0.25]), moment_limit=np.inf)
    sat = dataclasses.replace(sat, spin_rate=-0.2,
                              axial_momentum=sat.axial_momentum)       # rotor rate follows from H0 and s
    run = simulate_rotor(sat, orbit, 0.5 * orbit.period, sample_interval=60.0)
    assert np.degrees(run.pointing_error.max()) < 1e-4                   # integrator error only
    # spin follows the forced reference s_ref(u) = (H0 cos²u − J_f ν)/A (rtol 1e-8 of the spin)
    assert_allclose(run.spin_rate, run.spin_reference, atol=1e-8 * 0.2 + 1e-10)
    # the dipole makes the torque the reference needs: T = (−H0 ω0 sin 2u, 0, −H0 ω0 cos²u) (body = orbital here
    # up to the spin γ about axis 1, so check the axial component)
    n, u = orbit.mean_motion, run.argument_of_latitude
    assert_allclose(run.torque[:, 0], -sat.axial_momentum * n * np.sin(2 * u), atol=1e-3 * sat.axial_momentum * n)


def test_default_run_first_orbits():
    """The default asymmetric spacecraft from (20°, −15°): spin held at −30 rpm, the swing of
    the spin within the forced H0/A plus the transient, the error shrinking orbit to orbit."""
    sat, orbit = default_rotor_satellite(), default_rotor_orbit()
    run = simulate_rotor(sat, orbit, 2 * orbit.period, initial_angles=np.radians([20.0, -15.0, 0.0]))
    per = int(round(orbit.period / 10.0))
    first, second = (np.degrees(run.pointing_error[k * per:(k + 1) * per].max()) for k in range(2))
    assert first > second
    assert_allclose(run.spin_rate.mean() * 30 / np.pi, -30.0, rtol=1e-3)
    deviation = (run.spin_rate - run.spin_rate.mean()) / orbit.mean_motion
    assert np.ptp(deviation) < 3 * sat.axial_momentum / sat.inertia_matrix[0, 0] / orbit.mean_motion
    assert np.abs(run.dipole).max() <= sat.moment_limit
    result = run.to_result()
    assert result.pointing_error.shape == run.time.shape


def test_dimensionless_round_trip():
    sat, orbit = default_rotor_satellite(), default_rotor_orbit()
    d = rotor_dimensionless(sat, orbit)
    # the parameter file's numbers come back (rounding only)
    assert_allclose([d["axial_ratio"], d["momentum"], d["restoring"], d["damping"]], [0.8, 1.0, 4.0, 2.0],
                    rtol=1e-12)
    assert_allclose(sat.rotor_rate, (sat.axial_momentum + 0.2 * np.pi) / 1e-3, rtol=1e-14)


@pytest.mark.parametrize("call, name", [
    (lambda: RotorSatellite([0.2, 0.25, 0.25], 0.3, 1.0, 1e-4, 1.0, 1.0), "rotor_inertia"),
    (lambda: RotorSatellite([0.2, -0.25, 0.25], 1e-3, 1.0, 1e-4, 1.0, 1.0), "inertia"),
    (lambda: RotorSatellite([0.2, 0.25, 0.25], 1e-3, 1.0, 1e-4, -1.0, 1.0), "restoring_gain"),
    (lambda: rotor_floquet_multipliers(A, C1, 1.0, -1.0, INC), "damping"),
    (lambda: rotor_floquet_multipliers(A, C1, 1.0, 1.0, 0.0), "inclination"),
    (lambda: rotor_stability_map(np.ones((2, 2)), [1.0], axial_ratio=A, momentum=C1, inclination=INC), "1-D"),
    (lambda: rotor_normalised_rhs(0.0, np.zeros(4), A, C1, 1.0, 1.0, INC), "state"),
    (lambda: simulate_rotor(default_rotor_satellite(), default_rotor_orbit(), -1.0), "duration"),
    (lambda: simulate_rotor(default_rotor_satellite(), default_rotor_orbit(), 10.0, damping="relay"), "damping"),
    (lambda: simulate_rotor(default_rotor_satellite(), default_rotor_orbit(), 10.0, initial_angles=(0, 2, 0)),
     "initial_angles"),
])
def test_bad_input_names_the_parameter(call, name):
    with pytest.raises(ValueError, match=name):
        call()


def test_normalised_run_rejects_a_real_dipole_tilt_out_of_range():
    from magbench.sim import simulate_rotor_normalised

    with pytest.raises(ValueError, match="real_dipole_tilt"):
        simulate_rotor_normalised(1.0, 1.0, 4.0, 2.0, 0.9, [0.0, 0.0, 1.0, 1.0, 0.0], 1, steps_per_orbit=10,
                                  real_dipole_tilt=-0.1)


def test_normalised_run_with_the_dipole_untilted_is_the_program_field_run():
    # tilt 0 must be the direct dipole itself, not a different branch's field (exact: the
    # tilted dipole formula (Kovalenko 2.36) at δ = 0 is the direct dipole to rounding)
    from magbench.sim import simulate_rotor_normalised

    x0 = [0.2, -0.1, 1.0, 1.0, 0.0]
    a = simulate_rotor_normalised(0.8, 1.0, 4.0, 2.0, 0.9, x0, 1, steps_per_orbit=200).states
    b = simulate_rotor_normalised(0.8, 1.0, 4.0, 2.0, 0.9, x0, 1, steps_per_orbit=200, real_dipole_tilt=1e-300,
                                  real_node_phase=0.7).states
    np.testing.assert_allclose(b, a, rtol=0, atol=1e-12)


def test_turning_field_gyrostat_keeps_its_invariants_and_the_damping_drains_energy():
    from magbench.sim import simulate_turning_field_gyrostat

    j = np.array([0.9, 1.2, 1.35])
    w0, b0, n0 = [0.2, -0.1, 0.15], [2.5e-5, 0.0, 1e-5], [0.0, 0.6, 0.8]
    free = simulate_turning_field_gyrostat(j, 0.05, 0.0, 1.1e-3, w0, b0, n0, 600.0, samples=61)
    w = free.states[:3].T
    energy = 0.5 * np.sum(j * w * w, axis=1)
    # no torque: ½ωᵀIω is conserved with the rotor at constant speed (ω·(ω × K) = 0), and the
    # field and its axis only turn: |B|, |n|, n·B constant; DOP853 at rtol 1e-9 over ~100 spin
    # turns keeps them to ~1e-8
    assert_allclose(energy, energy[0], rtol=1e-8)
    b, n = free.states[3:6].T, free.states[6:].T
    assert_allclose(np.linalg.norm(b, axis=1), np.linalg.norm(b0), rtol=1e-8)
    assert_allclose(np.linalg.norm(n, axis=1), 1.0, rtol=1e-8)
    assert_allclose(np.sum(n * b, axis=1), 0.8e-5, rtol=1e-7)
    # the corrected damping (k > 0) never raises the energy, the printed sign (k < 0) never lowers it
    for k, sign in ((0.01, -1.0), (-0.01, 1.0)):
        run = simulate_turning_field_gyrostat(np.diag(j), 0.05, k, 1.1e-3, w0, b0, n0, 600.0, samples=61)
        w = run.states[:3].T
        assert np.all(sign * np.diff(0.5 * np.sum(j * w * w, axis=1)) > 0)


@pytest.mark.parametrize("change, name", [
    ({"inertia": [[1.0, 0.1, 0.0], [0.1, 1.0, 0.0], [0.0, 0.0, 1.0]]}, "inertia"),
    ({"inertia": [1.0, -1.0, 1.0]}, "inertia"),
    ({"initial_field": [0.0, 0.0, 0.0]}, "initial_field"),
    ({"field_axis": [0.0, 2.0, 0.0]}, "field_axis"),
    ({"initial_rate": [0.1, 0.2]}, "initial_rate"),
    ({"duration": 0.0}, "duration"),
    ({"samples": 1}, "samples"),
    ({"damping_gain": np.nan}, "damping_gain"),
])
def test_turning_field_gyrostat_rejects_bad_input(change, name):
    from magbench.sim import simulate_turning_field_gyrostat

    args = {"inertia": [1.0, 1.2, 1.3], "rotor_momentum": 0.05, "damping_gain": 0.01, "field_rate": 1e-3,
            "initial_rate": [0.1, 0.1, 0.1], "initial_field": [2e-5, 0.0, 0.0], "field_axis": [0.0, 1.0, 0.0],
            "duration": 10.0, **change}
    with pytest.raises(ValueError, match=name):
        simulate_turning_field_gyrostat(**args)
