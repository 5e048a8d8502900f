"""The Euler-case sun-sensor model and its session fits (TNS-0 §2), against what no one chose:
the 3-1-3 rotation of :func:`magbench.dynamics.euler_case_matrix` with the cosine law of
:func:`magbench.hardware.sun_sensor_signals`, the closed form of a pure spin, the mirror and
t0 symmetries, and a round trip (synthesise with a known truth, fit, recover it)."""

import numpy as np
import pytest
from numpy.testing import assert_allclose

from magbench.dynamics import euler_case_matrix
from magbench.estimation import (euler_case_sun_signals, fit_frequency_first, fit_multistart, fit_nested_grid,
                                 fold_start_time, mirror_solution, momentum_bound, session_identifiability,
                                 session_recovered, session_rms, synthetic_session)
from magbench.hardware import sun_sensor_signals

A, C = 0.0406, 0.00625                      # a prolate body (TNS-0-like, but any A > C/2 would do)
XZ = np.array([[1.0, 0.0, 0.0], [0.0, 0.0, 1.0], [-1.0, 0.0, 0.0]])     # sensors +x, +z, −x


def test_model_is_the_cosine_law_on_the_euler_case_rotation():
    # Arbitrary unit normals (with y components) and a nonzero t0: the written-out model against
    # R = euler_case_matrix applied to the normals. Same model: equal to float rounding (1e-12).
    rng = np.random.default_rng(3)
    normals = rng.normal(size=(4, 3))
    normals /= np.linalg.norm(normals, axis=-1, keepdims=True)
    t = np.linspace(0.0, 40.0, 401)
    big_l, theta, psi0, phi0, sigma, t0 = 0.07, 1.1, 0.4, 2.5, 0.9, 3.0
    r = euler_case_matrix(t, big_l, theta, A, C, start_time=t0, initial_precession=psi0,
                          initial_proper_rotation=phi0)
    expected = sun_sensor_signals(r, normals, [np.sin(sigma), 0.0, np.cos(sigma)])
    ours = euler_case_sun_signals(t, [big_l, theta, psi0, phi0, sigma], normals, A, C, start_time=t0)
    assert_allclose(ours, expected.T, rtol=0, atol=1e-12)


def test_pure_spin_has_a_closed_form():
    # θ = 0: the symmetry axis along L, the body turns at ψ̇ + φ̇ = L/A + L(1/C − 1/A) = L/C.
    # +z reads cos σ for ever; +x reads max(0, sin σ cos(Lt/C + ψ0 + φ0)). Rounding only.
    t = np.linspace(0.0, 20.0, 201)
    big_l, psi0, phi0, sigma = 0.05, 0.3, 1.2, 0.7
    s = euler_case_sun_signals(t, [big_l, 0.0, psi0, phi0, sigma], XZ, A, C)
    assert_allclose(s[1], np.cos(sigma), rtol=0, atol=1e-12)
    assert_allclose(s[0], np.maximum(np.sin(sigma) * np.cos(big_l / C * t + psi0 + phi0), 0.0), rtol=0, atol=1e-12)


def test_candidates_evaluate_at_once():
    t = np.linspace(0.0, 10.0, 51)
    p = np.array([[0.05, 0.9, 2.0, 4.0, 1.2], [0.08, 0.3, 1.0, 0.5, 2.0]])
    both = euler_case_sun_signals(t, p, XZ, A, C)
    assert both.shape == (2, 3, 51)
    for k in range(2):
        assert_allclose(both[k], euler_case_sun_signals(t, p[k], XZ, A, C), rtol=0, atol=0)  # the same arithmetic


def test_the_mirror_fits_sensors_in_the_xz_plane_only():
    t = np.linspace(0.0, 30.0, 301)
    p = np.array([0.0936, 1.086, 5.952, 1.0, 0.8])
    # Same signals for sensors along ±x and +z (rounding only) ...
    assert_allclose(euler_case_sun_signals(t, mirror_solution(p), XZ, A, C), euler_case_sun_signals(t, p, XZ, A, C),
                    rtol=0, atol=1e-12)
    # ... but not for a sensor along +y, whose s·R e_y changes sign.
    y = [[0.0, 1.0, 0.0]]
    assert np.max(np.abs(euler_case_sun_signals(t, mirror_solution(p), y, A, C)
                         - euler_case_sun_signals(t, p, y, A, C))) > 0.1


def test_t0_folds_into_the_phases():
    t = np.linspace(0.0, 30.0, 301)
    p, t0 = np.array([0.0936, 1.086, 5.952, 1.0, 0.8]), 1234.5
    folded = fold_start_time(p, t0, A, C)
    # Phases of ~3000 rad reduced modulo 2π: ~1e-12 rad of rounding, so 1e-9 on the signals.
    assert_allclose(euler_case_sun_signals(t, folded, XZ, A, C),
                    euler_case_sun_signals(t, p, XZ, A, C, start_time=t0), rtol=0, atol=1e-9)
    # t0 trades against the phases: one singular value of the 6-column Jacobian vanishes (1e-9
    # of the largest: central differences of step 1e-6), the other five do not.
    sv = session_identifiability(p, t, XZ, A, C)
    assert sv[-1] / sv[0] < 1e-9 and sv[-2] / sv[0] > 1e-5


def test_momentum_bound_of_a_pure_spin():
    # θ = 0: +x peaks every 2πC/L, so L_max = 2π A/Δt = L A/C; Δt is found to one sample
    # (0.01 s of a ~0.8 s period): 2 % covers it.
    big_l = 0.05
    t = np.arange(0.0, 10.0, 0.01)
    s = euler_case_sun_signals(t, [big_l, 0.0, 0.0, 0.0, 1.0], XZ, A, C)
    assert_allclose(momentum_bound(t, s, A, C), big_l * A / C, rtol=0.02)


def test_frequency_first_recovers_a_synthetic_session():
    truth = np.array([0.05, 0.9, 2.0, 4.0, 1.2])     # not a Table 1 row: the method is not tuned to it
    noise = 0.01
    t, s = synthetic_session(truth, XZ, A, C, noise=noise, seed=5)
    fit = fit_frequency_first(t, s, XZ, A, C)
    x = fit["params"]
    if abs(x[1] - truth[1]) > abs(x[1] - mirror_solution(truth)[1]):
        truth = mirror_solution(truth)
    # L from the spectral line and a polish: 0.1 %; angles to 5e-3 rad (noise 0.01 over 1800 samples).
    assert_allclose(x[0], truth[0], rtol=1e-3)
    assert_allclose(x[[1, 4]], truth[[1, 4]], atol=5e-3)
    # At the global minimum the rms residual is the noise level: 1800 samples, ±5 % is ~3 sd.
    assert_allclose(fit["rms"], noise, rtol=0.05)
    assert session_recovered(fit, truth)
    assert_allclose(session_rms(x, t, s, XZ, A, C), fit["rms"], rtol=1e-12)   # the same residual


def test_noise_free_round_trip_is_exact():
    # Without noise the global minimum has zero residual: the LM polish stops at its default
    # tolerances (~1e-8 relative), far below the 1e-3 a local minimum leaves; the truth (or its
    # mirror) is then found to 1e-5.
    truth = np.array([0.03, 1.3, 0.5, 3.0, 2.0])
    t, s = synthetic_session(truth, XZ, A, C, duration=30.0, noise=0.0)
    fit = fit_frequency_first(t, s, XZ, A, C)
    assert fit["rms"] < 1e-6
    assert session_recovered(fit, truth, momentum_rtol=1e-5, angle_atol=1e-5)


def test_multistart_is_no_worse_than_its_best_start():
    # Random starts of a multimodal problem: no promise of the global minimum, only that the
    # reported fit is the best polished start and its residual is what the model says.
    truth = np.array([0.05, 0.9, 2.0, 4.0, 1.2])
    t, s = synthetic_session(truth, XZ, A, C, duration=20.0, noise=0.01, seed=2)
    fit = fit_multistart(t, s, XZ, A, C, starts=3, seed=0)
    assert_allclose(fit["rms"], session_rms(fit["params"], t, s, XZ, A, C), rtol=1e-12)   # rounding
    assert fit["rms"] >= 0.01 * (1 - 0.1)     # never below the noise (10 %: ~2400 samples' spread)


def test_nested_grid_reports_its_evaluations():
    t, s = synthetic_session([0.05, 0.9, 2.0, 4.0, 1.2], XZ, A, C, duration=20.0)
    fit = fit_nested_grid(t, s, XZ, A, C, points=3, levels=2)
    assert fit["evaluations"] == 2 * 3 ** 5 and fit["method"] == "nested grid (preprint)"
    assert 0.0 <= fit["params"][2] < 2 * np.pi and 0.0 <= fit["params"][3] < 2 * np.pi


T = np.linspace(0.0, 10.0, 101)
P = [0.05, 0.9, 2.0, 4.0, 1.2]


@pytest.mark.parametrize("name, call", [
    ("normals", lambda: euler_case_sun_signals(T, P, [[2.0, 0.0, 0.0]], A, C)),
    ("normals", lambda: euler_case_sun_signals(T, P, [1.0, 0.0], A, C)),
    ("transverse_inertia", lambda: euler_case_sun_signals(T, P, XZ, -A, C)),
    ("axial_inertia", lambda: euler_case_sun_signals(T, P, XZ, A, 3 * A)),
    ("constants", lambda: euler_case_sun_signals(T, P[:4], XZ, A, C)),
    ("duration", lambda: synthetic_session(P, XZ, A, C, duration=0.0)),
    ("noise", lambda: synthetic_session(P, XZ, A, C, noise=-0.1)),
    ("signals", lambda: session_rms(P, T, np.zeros((2, T.size)), XZ, A, C)),
    ("points", lambda: fit_nested_grid(T, np.zeros((3, T.size)), XZ, A, C, points=0)),
    ("normals", lambda: fit_frequency_first(T, np.zeros((1, T.size)), [[1.0, 0.0, 0.0]], A, C)),
    ("step", lambda: session_identifiability(P, T, XZ, A, C, step=0.0)),
])
def test_bad_input_is_refused_by_name(name, call):
    with pytest.raises(ValueError, match=name):
        call()
