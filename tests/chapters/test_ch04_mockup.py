"""Chapter 4: the mock-up's equations of motion, the PID loop and its linear analysis.

References nobody here chose: closed forms (eq. 14, the elliptic period, the energy
integral, Routh–Hurwitz), numerical integration with scipy's solve_ivp, python-control
(poles, margins, step responses) and a symbolic derivation with sympy.
"""

import numpy as np
import pytest
from numpy.testing import assert_allclose

from magbench.chapters import errata
from scipy.integrate import solve_ivp

from magbench import control
from magbench import dynamics
from magbench import sim
from magbench.constants import MU_0

J, M1 = 0.005, 0.4                  # thesis seed line 516
B0 = MU_0 * 250.0                   # design field (inventory G18)
PRINTED_SETS = [(0.1, 0.5, 0.5), (0.2, 0.5, 0.5), (0.3, 0.5, 0.5),
                (0.1, 0.5, 1.0), (0.1, 0.5, 2.0), (0.1, 0.5, 3.0)]   # (kp, ki, kd), L565-579


# --- the magnetic pendulum ----------------------------------------------------------------

def test_small_angle_period_is_eq14():
    # Eq. (14): ω = 2π/T = √(mB/J).
    assert_allclose(dynamics.small_angle_period(J, M1, B0), 2 * np.pi * np.sqrt(J / (M1 * B0)), rtol=1e-15)


@pytest.mark.parametrize("amplitude", [0.05, 0.5, 1.0, np.pi / 2, 2.5, 3.0, 3.1])
def test_elliptic_period_against_solve_ivp(amplitude):
    # Released at rest at ψ = A, the pendulum next stops at ψ = −A after half a period.
    plant = dynamics.Mockup(J, B0, M1)

    def turn(t, y, p):
        return y[1]
    turn.direction = 1.0          # ω crosses zero upwards at ψ = −A
    t0 = float(dynamics.small_angle_period(J, M1, B0))
    sol = solve_ivp(dynamics.pendulum_rhs, (0, 20 * t0), [amplitude, 0.0], args=(plant,),
                    events=turn, rtol=1e-12, atol=1e-14)
    half = sol.t_events[0][0]
    # Tolerance: solve_ivp at rtol 1e-12; near the separatrix (A = 3.1) the slow crawl
    # at the turning point amplifies the event-time error.
    assert_allclose(2 * half, dynamics.pendulum_period(amplitude, J, M1, B0), rtol=1e-8)
    assert_allclose(sol.y_events[0][0][0], -amplitude, atol=1e-8)


def test_period_limits_and_series():
    t0 = dynamics.small_angle_period(J, M1, B0)
    # Small-amplitude series T = T0 (1 + A²/16 + 11A⁴/3072 + …): error O(A⁶).
    a = 0.1
    assert_allclose(dynamics.pendulum_period(a, J, M1, B0), t0 * (1 + a**2 / 16 + 11 * a**4 / 3072), rtol=1e-9)
    assert dynamics.pendulum_period(0.0, J, M1, B0) == pytest.approx(float(t0), rel=1e-15)
    assert np.isinf(dynamics.pendulum_period(np.pi, J, M1, B0))          # the separatrix
    # Monotone in the amplitude.
    assert np.all(np.diff(dynamics.pendulum_period(np.linspace(0, 3.1, 50), J, M1, B0)) > 0)


def test_energy_is_conserved_and_peak_rate():
    plant = dynamics.Mockup(J, B0, M1)
    t0 = float(dynamics.small_angle_period(J, M1, B0))
    sol = solve_ivp(dynamics.pendulum_rhs, (0, 5 * t0), [np.pi / 2, 0.0], args=(plant,),
                    t_eval=np.linspace(0, 5 * t0, 4001), rtol=1e-11, atol=1e-13)
    e = dynamics.pendulum_energy(sol.y[0], sol.y[1], J, M1, B0)
    scale = M1 * B0                      # energy scale mB0 [J]
    assert np.max(np.abs(e - e[0])) / scale < 1e-8     # integrator tolerance 1e-11 over 5 periods
    assert_allclose(np.max(np.abs(sol.y[1])), dynamics.pendulum_peak_rate(np.pi / 2, J, M1, B0), rtol=1e-5)
    # rtol 1e-5: the sampled maximum misses the true peak by O((Δt ω0)²).


def test_two_coil_equilibrium():
    # Eq. (36) with constant m1, m2: at rest where the net dipole lies along the field.
    plant = dynamics.Mockup(J, B0, 0.3, 0.4)
    psi_eq = -np.arctan2(0.4, 0.3)
    assert_allclose(dynamics.two_coil_rhs(0.0, [psi_eq, 0.0], plant)[1], 0.0, atol=1e-18)
    assert_allclose(dynamics.pendulum_rhs(0.0, [0.3, 0.0], plant),
                    dynamics.two_coil_rhs(0.0, [0.3, 0.0], dynamics.Mockup(J, B0, 0.3, 0.0)))


def test_field_and_amplitude_for_period_invert_the_period():
    for a in (0.2, 1.0, 2.0, 3.0):
        t = dynamics.pendulum_period(a, J, M1, B0)
        assert_allclose(dynamics.field_for_period(t, a, J, M1), B0, rtol=1e-13)
        assert_allclose(dynamics.amplitude_for_period(float(t), J, M1, B0), a, rtol=1e-10)
    # At A → 0 the exact field is eq. (15) without its amplitude factor.
    assert_allclose(dynamics.field_for_period(60.0, 0.0, J, M1), 4 * np.pi**2 * J / (M1 * 60.0**2), rtol=1e-14)


# --- geometry of the mock-up on a thread (thesis §4.1) -----------------------------------

def test_euler_matrix_is_a_rotation_with_the_printed_body_axis():
    rng = np.random.default_rng(1)
    psi, theta, phi = rng.uniform(-3, 3, (3, 20))
    r = dynamics.euler_313_matrix(psi, theta, phi)
    assert_allclose(r @ np.swapaxes(r, -1, -2), np.broadcast_to(np.eye(3), r.shape), atol=1e-14)
    assert_allclose(np.linalg.det(r), 1.0, rtol=1e-14)
    # Inventory audit A36: z' = (sinθ sinψ, −sinθ cosψ, cosθ).
    assert_allclose(r[..., :, 2], np.stack([np.sin(theta) * np.sin(psi), -np.sin(theta) * np.cos(psi),
                                            np.cos(theta)], -1), atol=1e-15)


def test_printed_cm_velocity_and_body_rates_by_finite_differences():
    # The thesis's v_C (seed line 464) and p, q, r (seed line 472) against central
    # differences of the position and of the rotation matrix; step 1e-5 s: error O(h²).
    def angles(t):
        return 0.3 + 0.2 * t, 0.4 - 0.1 * t, -0.2 + 0.7 * t, 0.01 * t, -0.02 * t
    rates = (0.2, -0.1, 0.7, 0.01, -0.02)
    d, h, t = 0.1, 1e-5, 0.8
    psi, theta, phi, x, y = angles(t)
    dpsi, dth, dphi, dx, dy = rates
    fd = (dynamics.thread_center_of_mass(*angles(t + h)[3:], *angles(t + h)[:2], d)
          - dynamics.thread_center_of_mass(*angles(t - h)[3:], *angles(t - h)[:2], d)) / (2 * h)
    printed = [dx - d * np.cos(theta) * np.sin(psi) * dth - d * np.sin(theta) * np.cos(psi) * dpsi,
               dy + d * np.cos(theta) * np.cos(psi) * dth - d * np.sin(theta) * np.sin(psi) * dpsi,
               d * np.sin(theta) * dth]
    assert_allclose(fd, printed, atol=1e-10)
    r = dynamics.euler_313_matrix(psi, theta, phi)
    rdot = (dynamics.euler_313_matrix(*angles(t + h)[:3]) - dynamics.euler_313_matrix(*angles(t - h)[:3])) / (2 * h)
    w = r.T @ rdot                       # skew matrix of the body-axis rate
    assert_allclose([w[2, 1], w[0, 2], w[1, 0]], dynamics.body_rates_313(psi, theta, phi, dpsi, dth, dphi),
                    atol=1e-9)


def test_lagrangian_reduces_to_eq35_with_sympy():
    sp = pytest.importorskip("sympy")
    t = sp.symbols("t")
    mass, g, d, a_, b_, c_, m, b0 = sp.symbols("M g d A B C m B_0", positive=True)
    x, y, psi, theta, phi = (sp.Function(n)(t) for n in ("x", "y", "psi", "theta", "phi"))
    rz = lambda q: sp.Matrix([[sp.cos(q), -sp.sin(q), 0], [sp.sin(q), sp.cos(q), 0], [0, 0, 1]])  # noqa: E731
    rx = sp.Matrix([[1, 0, 0], [0, sp.cos(theta), -sp.sin(theta)], [0, sp.sin(theta), sp.cos(theta)]])
    rot = rz(psi) * rx * rz(phi)
    r_c = sp.Matrix([x, y, 0]) - d * rot[:, 2]
    v_c = r_c.diff(t)
    w = rot.T * rot.diff(t)
    p, q, r = w[2, 1], w[0, 2], w[1, 0]
    # The printed p, q, r (seed line 472) are the body rates of this matrix.
    printed = [psi.diff(t) * sp.sin(theta) * sp.sin(phi) + theta.diff(t) * sp.cos(phi),
               psi.diff(t) * sp.sin(theta) * sp.cos(phi) - theta.diff(t) * sp.sin(phi),
               psi.diff(t) * sp.cos(theta) + phi.diff(t)]
    assert all(sp.simplify(u - v) == 0 for u, v in zip((p, q, r), printed))
    kinetic = mass * v_c.dot(v_c) / 2 + (a_ * p**2 + b_ * q**2 + c_ * r**2) / 2     # König
    # Coil 1 along x', field B0 along x: Π = −Mgd cosθ − m·B0 (seed line 480, with the dot product).
    potential = -mass * g * d * sp.cos(theta) - m * b0 * rot[0, 0]
    lagr = kinetic - potential
    eq_psi = sp.diff(lagr.diff(psi.diff(t)), t) - lagr.diff(psi)
    rotation_only = {theta: 0, phi: 0, x: 0, y: 0}
    reduced = sp.simplify(eq_psi.subs({f.diff(t, 2): 0 for f in (theta, phi, x, y)})
                          .subs({f.diff(t): 0 for f in (theta, phi, x, y)}).subs(rotation_only).doit())
    assert sp.simplify(reduced - (c_ * psi.diff(t, 2) + m * b0 * sp.sin(psi))) == 0      # eq. (35)
    # θ = 0 is consistent: the θ equation holds identically there.
    eq_theta = sp.diff(lagr.diff(theta.diff(t)), t) - lagr.diff(theta)
    th0 = (eq_theta.subs({f.diff(t, 2): 0 for f in (theta, phi, x, y)})
           .subs({f.diff(t): 0 for f in (theta, phi, x, y)}).subs(rotation_only).doit())
    assert sp.simplify(th0) == 0


# --- allocation ---------------------------------------------------------------------------

def test_exact_allocation_gives_the_commanded_torque():
    rng = np.random.default_rng(7)
    psi = rng.uniform(-np.pi, np.pi, 100)
    u = rng.uniform(-0.4, 0.4, 100)
    b_body = control.body_field_exact(psi, [B0, 0.0, 0.0])
    mz = np.stack([0 * u, 0 * u, -u], -1)
    coils = control.dipole_allocation(mz, b_body / B0)
    tau = np.cross(coils, b_body)[:, 2]                          # M × B, independent of eq. (36)
    assert_allclose(tau, B0 * u, rtol=1e-12, atol=1e-20)
    loop = sim.PidLoop(J, B0, 0.1, 0.0, 0.5)
    assert_allclose(sim.loop_torque(psi, u, loop), tau, rtol=1e-12, atol=1e-20)
    assert_allclose(coils[:, 2], 0.0, atol=1e-20)                # only the two horizontal coils


def test_small_angle_allocation_error_closed_form():
    psi = np.linspace(-np.pi, np.pi, 201)
    loop = sim.PidLoop(J, B0, 0.1, 0.0, 0.5, allocation="small-angle")
    ratio = sim.loop_torque(psi, 1.0, loop) / B0
    assert_allclose(ratio, psi * np.sin(psi) + np.cos(psi), rtol=1e-12, atol=1e-15)
    small = np.array([1e-3, 1e-2])
    assert_allclose(sim.loop_torque(small, 1.0, loop) / B0 - 1, small**2 / 2, rtol=1e-4)   # O(ψ⁴) term
    # The thesis's small-angle vector is the exact one to first order in ψ.
    assert_allclose(control.body_field_small_angle(1e-4, [1.0, 2.0, 0.5]),
                    control.body_field_exact(1e-4, [1.0, 2.0, 0.5]), atol=1e-8)


# --- linear analysis against python-control ----------------------------------------------


def test_printed_gains_are_all_unstable_in_si():
    # Inventory audit A40: Re λ between +0.098 and +0.144 1/s.
    worst = [control.closed_loop_poles(J, B0, *g)[0].real for g in PRINTED_SETS]
    assert min(worst) > 0.09 and max(worst) < 0.15


def test_sampled_pid_converges_to_the_continuous_loop():
    kp, ki, kd = control.pid_gains_for_triple_pole(J, B0, 0.05)
    loop = sim.PidLoop(J, B0, kp, ki, kd, moment_limit=0.4)
    ref = sim.simulate_pid(loop, 0.3, 0.0, 100.0, output_interval=1.0)
    errors = []
    for dt in (0.5, 0.25, 0.125):
        run = sim.simulate_pid(loop, 0.3, 0.0, 100.0, sample_interval=dt, output_interval=1.0)
        errors.append(np.max(np.abs(run.psi - ref.psi)))
    errors = np.array(errors)
    # First order in Δt (zero-order hold, rectangle-rule integral): halving Δt halves the error.
    assert_allclose(errors[:-1] / errors[1:], 2.0, rtol=0.1)
    assert errors[-1] < 1e-2


def test_back_calculation_bleeds_the_integral_in_saturation():
    loop = sim.PidLoop(J, B0, 1.0, 1.0, 1.0, moment_limit=0.4)
    assert loop.tracking == 1.0                                      # √(Kd/Ki)
    # Saturated (raw 1.0 > 0.4): İ = e + (u − raw)/(Ki Tt) = 1 − 0.6.
    assert sim.pid_continuous_rhs(0.0, [-1.0, 0.0, 0.0], loop)[2] == pytest.approx(0.4)
    assert sim.pid_continuous_rhs(0.0, [-0.1, 0.0, 0.0], loop)[2] == pytest.approx(0.1)   # linear
    free = sim.PidLoop(J, B0, 1.0, 1.0, 0.0, moment_limit=0.4, anti_windup=False)
    assert sim.pid_continuous_rhs(0.0, [-1.0, 0.0, 0.0], free)[2] == 1.0


def test_saturated_continuous_and_sampled_loops_agree():
    # The two anti-windup schemes differ only while saturated; from a large error both
    # settle on the target, and the sampled loop stays within the coil limit.
    kp, ki, kd = control.pid_gains_for_triple_pole(J, B0, 0.1)      # Kp·2π/3 ≈ 1 A·m² > 0.4
    loop = sim.PidLoop(J, B0, kp, ki, kd, target=2 * np.pi / 3, moment_limit=0.4)
    cont = sim.simulate_pid(loop, 0.0, 0.0, 600.0, output_interval=1.0)
    samp = sim.simulate_pid(loop, 0.0, 0.0, 600.0, sample_interval=0.05, output_interval=1.0)
    assert np.max(np.abs(cont.command)) == pytest.approx(0.4)          # it does saturate
    assert_allclose([cont.psi[-1], samp.psi[-1]], 2 * np.pi / 3, atol=2e-3)


def test_saturated_run_respects_the_coil_limit():
    loop = sim.PidLoop(J, B0, 0.3, 0.01, 3.0, moment_limit=0.4)
    run = sim.simulate_pid(loop, np.pi / 2, 0.0, 200.0)
    assert np.max(np.abs(run.command)) <= 0.4 + 1e-15
    assert np.max(np.abs(run.torque)) <= 0.4 * B0 * (1 + 1e-12)


def test_gain_reading_scales():
    assert control.gain_reading_scale("si", B0, 0.4) == 1.0
    assert_allclose(control.gain_reading_scale("field-in-A/m", B0, 0.4), 1 / MU_0)
    assert_allclose(control.gain_reading_scale("torque-output", B0, 0.4) * B0, 1.0)
    assert set(control.GAIN_READINGS) == {"si", "per-degree", "normalised", "per-degree-normalised",
                                          "field-in-gauss", "field-in-A/m", "torque-output"}


# --- bad input ----------------------------------------------------------------------------

@pytest.mark.parametrize("call, message", [
    (lambda: dynamics.pendulum_period(3.2, J, M1, B0), "amplitude"),
    (lambda: dynamics.pendulum_period(1.0, -J, M1, B0), "inertia"),
    (lambda: dynamics.small_angle_period(J, 0.0, B0), "moment"),
    (lambda: dynamics.field_for_period(0.0, 1.0, J, M1), "period"),
    (lambda: dynamics.amplitude_for_period(1.0, J, M1, B0), "small-angle period"),
    (lambda: dynamics.Mockup(0.0, B0), "inertia"),
    (lambda: dynamics.Mockup(J, np.nan), "field"),
    (lambda: dynamics.thread_center_of_mass(0, 0, 0, 0, -0.1), "cm_offset"),
    (lambda: sim.PidLoop(J, B0, 0.1, 0.5, 0.5, allocation="approx"), "allocation"),
    (lambda: sim.PidLoop(J, B0, 0.1, 0.5, 0.5, moment_limit=0.0), "moment_limit"),
    (lambda: sim.PidLoop(J, -B0, 0.1, 0.5, 0.5), "field"),
    (lambda: sim.simulate_pid(sim.PidLoop(J, B0, 0.1, 0.5, 0.5), 0.0, 0.0, -1.0), "duration"),
    (lambda: control.body_field_exact(0.1, [1.0, 0.0]), "world_field"),
    (lambda: control.gain_reading_scale("furlongs", B0, 0.4), "reading"),
    (lambda: control.integral_gain_limit(J, B0, 0.0, 0.5), "kp"),
    (lambda: control.ziegler_nichols_pid(1.0, 0.0), "ultimate_period"),
])
def test_bad_input(call, message):
    with pytest.raises(ValueError, match=message):
        call()


# --- the figure layer: python-control interconnection and the reading table ---------------


def test_reading_evidence_decides_stability():
    pytest.importorskip("control")
    from magbench.chapters.ch04_mockup import figures as thesis_ch4

    rows = {r["reading"]: r for r in thesis_ch4.reading_evidence(J, B0, M1, np.pi / 2)}
    # Independent of the pole computation: Routh–Hurwitz for J s³ + B0 Kd s² + B0 Kp s + B0 Ki
    # with every gain multiplied by the reading's factor s: stable iff s Ki < B0 s² Kp Kd / J.
    expected = {}
    for reading in rows:
        s = control.gain_reading_scale(reading, B0, M1)
        expected[reading] = sum(s * ki < B0 * s**2 * kp * kd / J for kp, ki, kd in thesis_ch4.PRINTED_SETS)
    assert {k: r["stable_sets"] for k, r in rows.items()} == expected
    assert 0 < expected["per-degree"] < 6 and expected["si"] == 0    # both outcomes occur
    # Large factors: the slow poles tend to the roots of Kd s² + Kp s + Ki (scale-free).
    zeta_limit = [kp / (2 * np.sqrt(kd * ki)) for kp, ki, kd in thesis_ch4.PRINTED_SETS]
    assert_allclose(rows["field-in-A/m"]["zeta_max"], max(zeta_limit), rtol=1e-3)
    assert_allclose(rows["field-in-A/m"]["zeta_min"], min(zeta_limit), rtol=1e-3)


# ------------------------------------------------------------ printed values (errata)

CHAPTER_KEY = "ch04"

#: The printed values of this chapter's sources that do not reproduce, written here
#: independently of the library: a change that makes one suddenly reproduce (or another
#: stop reproducing) fails. Each is a strict xfail asserting the printed value.
EXPECTED_ERRATA = {
    "thesis-eq14-design-amplitude": "60 s at m = 0.4, H = 250 only up to ~134°; infinite period at π",
    "thesis-pid-gains-stable-si": "all six printed gain sets are unstable in SI (Routh–Hurwitz)",
}


def test_printed_value(printed_check):
    # Tolerance: half a unit of the source's last printed digit (printed_check.tolerance).
    assert_allclose(printed_check.printed, printed_check.computed, rtol=0, atol=printed_check.tolerance)


def test_errata_match_expectation():
    assert {e.id for e in errata(CHAPTER_KEY)} == set(EXPECTED_ERRATA)
