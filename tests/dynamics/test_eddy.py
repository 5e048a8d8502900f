"""Eddy-current torques (Kovalenko 1975 §4.2, eqs. (4.23)–(4.26)): the general form's power and
components, the coefficients of a thin spherical shell, a solid sphere and an open cylindrical
shell against independent numerical solutions in the inertial frame, the finite-frequency shell,
the book's CGS units, and the despin time constant."""

import numpy as np
import pytest
from numpy.testing import assert_allclose

from magbench import dynamics
from magbench.constants import MU_0
from magbench.integrate import rk4_step

RNG = np.random.default_rng(20261128)
SIGMA_AL = 3.5e7  # S/m, aluminium (ours, a round value for a hull alloy)


def _random_pairs(n=50):
    return RNG.normal(size=(n, 3)), RNG.normal(size=(n, 3)) * 3e-5


def test_the_power_taken_from_the_spin_is_k_b2_w2_sin2_and_never_negative():
    w, b = _random_pairs()
    k = 7.0
    m = dynamics.eddy_torque(w, b, k)
    speed, field = np.linalg.norm(w, axis=-1), np.linalg.norm(b, axis=-1)
    cos_a = np.sum(w * b, axis=-1) / (speed * field)
    # identical algebra by two routes: only rounding (a few ulp of |M||ω|) separates them
    assert_allclose(-np.sum(w * m, axis=-1), k * field ** 2 * speed ** 2 * (1 - cos_a ** 2), rtol=1e-12)
    assert np.all(-np.sum(w * m, axis=-1) >= 0)


def test_the_components_are_4_23a_along_the_rate_and_4_23b_across_it():
    w, b = _random_pairs()
    k = 3.0
    m = dynamics.eddy_torque(w, b, k)
    braking, precession = dynamics.eddy_torque_components(w, b, k)
    what = w / np.linalg.norm(w, axis=-1, keepdims=True)
    along = np.sum(m * what, axis=-1)
    across = np.linalg.norm(m - along[:, None] * what, axis=-1)
    # rounding only (the components come from the angle, the torque from cross products);
    # atol 1e-25 N·m is far below the smallest torque here (~1e-10 N·m)
    assert_allclose(along, braking, rtol=1e-9, atol=1e-25)
    assert_allclose(across, precession, rtol=1e-9, atol=1e-25)
    assert np.all(braking <= 0)


def test_rate_along_the_field_gives_no_torque_and_small_angles_go_as_alpha_squared():
    b = np.array([0.0, 0.0, 4e-5])
    assert np.all(dynamics.eddy_torque([0.0, 0.0, 1.0], b, 5.0) == 0.0)
    alphas = np.array([1e-2, 1e-3, 1e-4])
    w = np.stack([np.sin(alphas), 0 * alphas, np.cos(alphas)], axis=-1)
    braking, precession = dynamics.eddy_torque_components(w, b, 5.0)
    # sin²α = α² (1 − α²/3 + …): relative error ≤ α²/3 ≤ 3.4e-5
    assert_allclose(-braking / (5.0 * 16e-10 * alphas ** 2), 1.0, rtol=4e-5)
    assert_allclose(precession / (5.0 * 16e-10 * alphas), 1.0, rtol=1e-4)  # sinα cosα = α(1 − 2α²/3 …)


def test_the_shell_coefficient_is_linear_in_conductivity_and_thickness_and_goes_as_radius_to_the_fourth():
    k = dynamics.spherical_shell_eddy_coefficient(0.3, 1e-3, SIGMA_AL)
    assert_allclose(dynamics.spherical_shell_eddy_coefficient(0.3, 1e-3, 2 * SIGMA_AL), 2 * k, rtol=1e-15)
    assert_allclose(dynamics.spherical_shell_eddy_coefficient(0.3, 3e-3, SIGMA_AL), 3 * k, rtol=1e-15)
    assert_allclose(dynamics.spherical_shell_eddy_coefficient(0.6, 1e-3, SIGMA_AL), 16 * k, rtol=1e-15)
    # the thin shell is the radius derivative of the solid sphere's (2π/15)σa⁵: central difference, O(h²)
    a, h = 0.3, 1e-5
    dk = (dynamics.solid_sphere_eddy_coefficient(a + h, SIGMA_AL) - dynamics.solid_sphere_eddy_coefficient(a - h, SIGMA_AL)) / (2 * h)
    assert_allclose(dk * 1e-3, k, rtol=1e-8)


# --- an independent solution: the rotating conductor in the inertial frame ---------------------
# There the body moves through a static field: the motional field v × B, v = ω × r, drives the
# current, and the charges it piles up add −∇ψ so that no current leaves the conductor. ψ is the
# potential that minimises the dissipation ∫ σ|v × B − ∇ψ|² (its Euler–Lagrange equation is
# ∇·J = 0 with J·n = 0 on the boundary); we find it by least squares over all polynomials in
# x, y, z of degree ≤ 4, with no knowledge of the answer, then integrate r × (J × B).

def _monomial_gradients(points, degree=4):
    x, y, z = points[..., 0], points[..., 1], points[..., 2]
    grads = []
    for i in range(degree + 1):
        for j in range(degree + 1 - i):
            for k in range(degree + 1 - i - j):
                if i + j + k == 0:
                    continue
                gx = i * x ** max(i - 1, 0) * y ** j * z ** k if i else 0 * x
                gy = j * x ** i * y ** max(j - 1, 0) * z ** k if j else 0 * x
                gz = k * x ** i * y ** j * z ** max(k - 1, 0) if k else 0 * x
                grads.append(np.stack([gx, gy, gz], axis=-1))
    return np.stack(grads)  # (basis, points, 3)


def _least_dissipation_current(points, weights, emf, grads, conductance):
    """σ(emf − ∇ψ) with ψ minimising Σ w |emf − ∇ψ|² over the basis whose gradients are ``grads``."""
    sw = np.sqrt(weights)[:, None]
    a = (grads * sw).transpose(1, 2, 0).reshape(-1, grads.shape[0])
    coef = np.linalg.lstsq(a, (emf * sw).reshape(-1), rcond=None)[0]
    return conductance * (emf - np.tensordot(coef, grads, axes=1))


def _sphere_nodes(radius, n=24):
    u, wu = np.polynomial.legendre.leggauss(n)             # cos θ
    phi = np.linspace(0, 2 * np.pi, 2 * n, endpoint=False)  # trapezoid: exact for trigonometric polynomials
    uu, pp = np.meshgrid(u, phi, indexing="ij")
    s = np.sqrt(1 - uu ** 2)
    normal = np.stack([s * np.cos(pp), s * np.sin(pp), uu], axis=-1).reshape(-1, 3)
    weights = (wu[:, None] * np.full(pp.shape[1], 2 * np.pi / pp.shape[1])).reshape(-1) * radius ** 2
    return normal, weights


@pytest.mark.parametrize("seed", [1, 2, 3])
def test_the_thin_shell_torque_matches_the_inertial_frame_surface_current_solution(seed):
    rng = np.random.default_rng(seed)
    w, b = rng.normal(size=3), rng.normal(size=3) * 3e-5
    a, d = 0.4, 2e-3
    normal, weights = _sphere_nodes(a)
    r = a * normal
    emf = np.cross(np.cross(w, r), b)
    tangential = lambda v: v - np.sum(v * normal, axis=-1, keepdims=True) * normal  # noqa: E731
    grads = np.stack([tangential(g) for g in _monomial_gradients(r)])
    current = _least_dissipation_current(r, weights, tangential(emf), grads, SIGMA_AL * d)
    torque = np.sum(weights[:, None] * np.cross(r, np.cross(current, b)), axis=0)
    power = np.sum(weights * np.sum(current ** 2, axis=-1)) / (SIGMA_AL * d)
    k = dynamics.spherical_shell_eddy_coefficient(a, d, SIGMA_AL)
    # Gauss–Legendre × trapezoid of 24 × 48 nodes integrates these degree ≤ 8 polynomials exactly,
    # and the basis holds the exact ψ: only rounding in the least squares remains (~1e-13 relative)
    assert_allclose(torque, dynamics.eddy_torque(w, b, k), rtol=1e-9, atol=1e-9 * np.abs(torque).max())
    assert_allclose(power, -w @ torque, rtol=1e-9)


def test_the_solid_sphere_torque_matches_the_inertial_frame_volume_current_solution():
    rng = np.random.default_rng(7)
    w, b = rng.normal(size=3), rng.normal(size=3) * 3e-5
    a = 0.2
    normal, wa = _sphere_nodes(1.0, n=16)
    x, wr = np.polynomial.legendre.leggauss(12)
    radii, wr = a * (x + 1) / 2, wr * a / 2
    r = (radii[:, None, None] * normal[None]).reshape(-1, 3)
    weights = (wr[:, None] * radii[:, None] ** 2 * wa[None]).reshape(-1)
    emf = np.cross(np.cross(w, r), b)
    current = _least_dissipation_current(r, weights, emf, _monomial_gradients(r), SIGMA_AL)
    torque = np.sum(weights[:, None] * np.cross(r, np.cross(current, b)), axis=0)
    k = dynamics.solid_sphere_eddy_coefficient(a, SIGMA_AL)
    # exact quadrature for these polynomials (degree ≤ 10 in r, ≤ 8 in angle): rounding only
    assert_allclose(torque, dynamics.eddy_torque(w, b, k), rtol=1e-9, atol=1e-9 * np.abs(torque).max())


@pytest.mark.parametrize("length", [0.3, 1.0])
def test_the_open_cylinder_transverse_coefficient_matches_a_numerical_surface_current_solution(length):
    """The cylinder spins about its axis z in a transverse field: the power, found by least
    dissipation over ψ = Σ P_n(2z/l)(a_n sin φ + b_n cos φ + …) on the wall, against Γ⊥ω²B⊥²."""
    r, tau, w, bx = 0.05, 1e-3, 2.0, 3e-5
    nz, nphi = 40, 16
    u, wu = np.polynomial.legendre.leggauss(nz)
    phi = np.linspace(0, 2 * np.pi, nphi, endpoint=False)
    uu, pp = np.meshgrid(u, phi, indexing="ij")
    z = uu * length / 2
    weights = (wu[:, None] * length / 2 * r * 2 * np.pi / nphi) * np.ones_like(pp)
    # tangential motional field (v × B)·e_z = −ω r B_x cos φ... computed, not typed: v = ω ẑ × r
    pos = np.stack([r * np.cos(pp), r * np.sin(pp), z], axis=-1)
    emf = np.cross(np.cross([0.0, 0.0, w], pos), [bx, 0.0, 0.0])
    e_phi = np.stack([-np.sin(pp), np.cos(pp), 0 * pp], axis=-1)
    emf_t = np.stack([np.sum(emf * e_phi, axis=-1), emf[..., 2]], axis=-1)  # (φ, z) components
    grads = []
    legendre = np.polynomial.legendre
    for n in range(24):
        pn = legendre.legval(uu, np.eye(24)[n])
        dpn = legendre.legval(uu, legendre.legder(np.eye(24)[n])) * 2 / length
        for m in (1, 2):
            for f, df in ((np.sin(m * pp), m * np.cos(m * pp)), (np.cos(m * pp), -m * np.sin(m * pp))):
                grads.append(np.stack([pn * df / r, dpn * f], axis=-1))
    grads = np.stack(grads).reshape(len(grads), -1, 2)
    current = _least_dissipation_current(None, weights.reshape(-1), emf_t.reshape(-1, 2), grads, SIGMA_AL * tau)
    power = np.sum(weights.reshape(-1) * np.sum(current ** 2, axis=-1)) / (SIGMA_AL * tau)
    transverse, _ = dynamics.cylinder_eddy_coefficients(r, length, tau, SIGMA_AL)
    # the exact ψ ∝ sinh(z/r) is entire; Legendre degree 23 on |z/r| ≤ 10 leaves < 1e-6 relative
    assert_allclose(power, transverse * w ** 2 * bx ** 2, rtol=1e-6)


def test_the_axial_coefficient_is_a_loop_of_uniform_azimuthal_current():
    r, l, tau = 0.05, 0.3, 1e-3
    _, axial = dynamics.cylinder_eddy_coefficients(r, l, tau, SIGMA_AL)
    # E_φ = −½ r Ḃ round the wall; P = σ τ (½ r Ḃ)² · 2π r l: exact arithmetic
    assert_allclose(axial, SIGMA_AL * tau * 0.25 * r ** 2 * 2 * np.pi * r * l, rtol=1e-15)


def test_the_book_s_cgs_form_of_4_25_gives_the_si_torque():
    """(4.25) in the book's units: σ [S/m] × 9·10⁹, c = 3·10¹⁰ cm/s, cm, Oe → dyn·cm = 10⁷ N·m."""
    r, l, tau, sigma, w, b, alpha = 0.05, 0.3, 1e-3, SIGMA_AL, 2.0, 3e-5, 0.7
    transverse, _ = dynamics.cylinder_eddy_coefficients(r, l, tau, sigma)
    si = transverse * b ** 2 * w * np.sin(alpha) ** 2
    from magbench.io import load_printed

    factor = load_printed("kovalenko")["kovalenko-eddy-cgs-conductivity-factor"].value   # 9·10⁹, seed line 89
    rc, lc, tc, h0 = 100 * r, 100 * l, 100 * tau, 1e4 * b
    q = np.pi * sigma * factor * (3e10) ** -2 * h0 ** 2 * w * np.sin(alpha) * rc ** 3 * tc * lc * (
        1 - 2 * rc / lc * np.tanh(lc / (2 * rc)))
    # the book's 9e9 and 3e10 stand for 1/(4πε0) and c: (9e9)/(3e10)² = 1e-11 exactly, as
    # 8.988e9/(2.998e10)² = 1e-11 to 4 digits; the identity is exact with the book's constants
    assert_allclose(q * np.sin(alpha) * 1e-7, si, rtol=1e-12)


def test_a_cylinder_spinning_about_a_transverse_axis_brakes_on_average_by_half_the_sum():
    gt, ga = dynamics.cylinder_eddy_coefficients(0.05, 0.3, 1e-3, SIGMA_AL)
    w, b0, alpha = 2.0, 3e-5, 0.6
    t = np.linspace(0, 2 * np.pi / w, 4000, endpoint=False)
    # body axes: cylinder along z, spin about y; the inertial field seen from the body turns about y
    b = b0 * np.stack([np.sin(alpha) * np.cos(w * t), np.full_like(t, np.cos(alpha)),
                       np.sin(alpha) * np.sin(w * t)], axis=-1)
    m = dynamics.anisotropic_eddy_torque([0.0, w, 0.0], b, [gt, gt, ga])
    mean = m.mean(axis=0)
    # the samples cover whole periods of a trigonometric polynomial of degree 2: exact mean
    assert_allclose(mean, [0.0, -0.5 * (gt + ga) * b0 ** 2 * w * np.sin(alpha) ** 2, 0.0],
                    rtol=1e-12, atol=1e-12 * abs(mean[1]))
    assert np.ptp(m[:, 1]) > 0.1 * abs(mean[1])  # and it pulsates (Γ⊥ ≠ Γ∥)


def test_the_finite_frequency_shell_tends_to_4_23_at_low_and_to_a_diamagnet_at_high_frequency():
    a, d = 0.5, 1e-3
    b = np.array([1e-5, 0.0, 2e-5])
    k = dynamics.spherical_shell_eddy_coefficient(a, d, SIGMA_AL)
    tau = dynamics.spherical_shell_time_constant(a, d, SIGMA_AL)
    slow = np.array([0.0, 0.0, 1e-4 / tau])                      # ωτ = 1e-4
    # relative correction ωτ (across) and (ωτ)² (along): 1e-4
    assert_allclose(dynamics.spherical_shell_eddy_torque(slow, b, a, d, SIGMA_AL),
                    dynamics.eddy_torque(slow, b, k), rtol=2e-4, atol=2e-4 * np.linalg.norm(dynamics.eddy_torque(slow, b, k)))
    fast = np.array([0.0, 0.0, 1e6 / tau])
    b_perp = b * [1, 1, 0]
    # the shell excludes the turning field: moment −(2πa³/μ0) B⊥; corrections O(1/ωτ) = 1e-6
    assert_allclose(dynamics.spherical_shell_eddy_torque(fast, b, a, d, SIGMA_AL),
                    np.cross(-2 * np.pi * a ** 3 / MU_0 * b_perp, b), rtol=1e-5, atol=1e-5 * 2 * np.pi * a ** 3 / MU_0 * 2e-10)
    for wz in (0.1 / tau, 1 / tau, 10 / tau):
        rate = np.array([0.0, 0.0, wz])
        m = dynamics.spherical_shell_eddy_torque(rate, b, a, d, SIGMA_AL)
        # the diamagnetic term is across ω: the power is (4.23)'s over 1 + ω²τ² (rounding only)
        assert_allclose(-rate @ m, k * wz ** 2 * 1e-10 / (1 + (wz * tau) ** 2), rtol=1e-12)


def test_a_sphere_in_a_field_across_its_spin_spins_down_with_the_time_constant():
    j, k, b0 = 0.04, 5.0, 3e-5
    tau = dynamics.eddy_despin_time_constant(j, k, b0 ** 2)
    b = np.array([b0, 0.0, 0.0])
    rhs = lambda t, w: dynamics.eddy_torque(w, b, k) / j  # noqa: E731
    w, h = np.array([0.0, 0.0, 2.0]), tau / 200
    for i in range(400):
        w = rk4_step(rhs, i * h, w, h)
    # RK4 on a linear decay, 200 steps per τ: relative error ~ 400·(h/τ)⁵/120 ~ 1e-12
    assert_allclose(w[2], 2.0 * np.exp(-2.0), rtol=1e-10)


def test_tns0_hull_shell_that_would_give_fig_14_decay_is_centimetres_thick():
    """Chapter 7's Fig. 14: Table 1's L falls by 1.47e-4 kg·m²/s per hour. A hull of aluminium
    (σ = 3.5e7 S/m, ours) braking a flat spin by eddy currents alone gives an exponential with
    τ = J/(k⟨B²sin²α⟩); matched to the line's slope at its session-1 value (τ = L0/|slope|)
    the thickness it needs is ours to solve for: a 5 cm sphere needs a wall of ≈ 4.6 cm (not a
    thin shell: eddy currents cannot be the decay), the 0.1 m × 0.3 m cylinder spinning about
    a transverse axis ≈ 9 mm."""
    from magbench.chapters.ch07_tns0 import decay_fits, tns0_orbit
    from magbench.earth import mean_square_field
    from magbench.params import chapter_parameters

    p = chapter_parameters("ch07")
    _, _, linear, exponential = decay_fits()
    tau = linear.parameters["initial"] / -linear.parameters["slope"] * 3600.0   # s
    b2_perp = 2.0 / 3.0 * mean_square_field(tns0_orbit(p))  # over a day; an axis with no preferred direction (ours)
    radius, length, j = p["diameter"] / 2, p["length"], p["transverse_inertia"]
    per_metre = dynamics.spherical_shell_eddy_coefficient(radius, 1e-6, SIGMA_AL) / 1e-6
    sphere = j / (tau * per_metre * b2_perp)
    # k ∝ d: the wall found by one division gives back the time constant through the orbit
    assert_allclose(dynamics.shell_despin_time_constant(j, radius, sphere, SIGMA_AL, tns0_orbit(p)), tau, rtol=1e-12)
    gt, ga = dynamics.cylinder_eddy_coefficients(radius, length, 1e-6, SIGMA_AL)
    cylinder = j / (tau * 0.5 * (gt + ga) / 1e-6 * b2_perp)
    assert_allclose(dynamics.eddy_despin_time_constant(j, per_metre * sphere, b2_perp), tau, rtol=1e-12)
    # the numbers the docstring and report quote, to 2 digits
    assert sphere == pytest.approx(0.046, abs=0.001) and sphere > 0.9 * radius
    assert cylinder == pytest.approx(0.0087, abs=0.0002)
    # matched to the exponential fit's τ instead (430 h), both walls are 1.5 times thicker
    ratio = exponential.parameters["time_constant"] * 3600.0 / tau
    assert 0.6 < ratio < 0.7


@pytest.mark.parametrize("call, name", [
    (lambda: dynamics.eddy_torque([0, 0, 1.0], [1e-5, 0, 0], -1.0), "coefficient"),
    (lambda: dynamics.spherical_shell_eddy_coefficient(0.1, 0.2, SIGMA_AL), "thickness"),
    (lambda: dynamics.spherical_shell_eddy_coefficient(-0.1, 1e-3, SIGMA_AL), "radius"),
    (lambda: dynamics.cylinder_eddy_coefficients(0.1, 0.3, 1e-3, 0.0), "conductivity"),
    (lambda: dynamics.eddy_torque_components([0, 0, 0.0], [1e-5, 0, 0], 1.0), "rate"),
    (lambda: dynamics.anisotropic_eddy_torque([0, 0, 1.0], [1e-5, 0, 0], [1.0, -1.0, 1.0]), "coefficients"),
    (lambda: dynamics.eddy_despin_time_constant(0.04, 1.0, np.nan), "mean_square_perpendicular_b"),
])
def test_bad_input_names_the_parameter(call, name):
    with pytest.raises(ValueError, match=name):
        call()


def test_the_field_across_three_orthogonal_axes_averages_to_two_thirds_of_the_mean_square():
    from magbench.earth import CircularOrbit, mean_square_field, mean_square_perpendicular_field

    orbit = CircularOrbit(6.721e6, np.radians(51.6), 7.766e22)
    rng = np.random.default_rng(5)
    axes, _ = np.linalg.qr(rng.normal(size=(3, 3)))
    across = [mean_square_perpendicular_field(orbit, a, samples=2000) for a in axes.T]
    # Σ_i (B² − (e_i·B)²) = 2B² at every instant, for any orthonormal e_i: rounding only
    assert_allclose(np.mean(across), 2 / 3 * mean_square_field(orbit, samples=2000), rtol=1e-12)
    # the orbit normal sees the in-plane field, more than the average (|B|² sin²α varies by axis)
    assert np.ptp(across) > 0
    with pytest.raises(ValueError, match="axis"):
        mean_square_perpendicular_field(orbit, [0.0, 0.0, 0.0])


def test_the_shell_despin_time_constant_composes_the_coefficient_and_the_orbit_field():
    from magbench.earth import CircularOrbit, mean_square_field, mean_square_perpendicular_field

    orbit = CircularOrbit(6.721e6, np.radians(51.6), 7.766e22)
    k = dynamics.spherical_shell_eddy_coefficient(0.05, 1e-3, SIGMA_AL)
    tau = dynamics.shell_despin_time_constant(0.0406, 0.05, 1e-3, SIGMA_AL, orbit)
    assert_allclose(tau, 0.0406 / (k * 2 / 3 * mean_square_field(orbit)), rtol=1e-14)
    tau_z = dynamics.shell_despin_time_constant(0.0406, 0.05, 1e-3, SIGMA_AL, orbit, axis=[0.0, 0.0, 1.0])
    assert_allclose(tau_z, 0.0406 / (k * mean_square_perpendicular_field(orbit, [0.0, 0.0, 1.0])), rtol=1e-14)


@pytest.mark.parametrize("w_tau", [0.3, 1.0, 3.0])
def test_the_finite_frequency_shell_matches_its_circuit_integrated_in_time(w_tau):
    """The shell's one current mode in the time domain: τ dB_in/dt = B − B_in in inertial axes
    (the field is fixed, the shell turns: in inertial axes the mode's field relaxes toward B while
    being carried round by the spin, dB_in/dt|inertial = (B − B_in)/τ + ω × B_in), integrated by
    rk4_step to the steady state; the moment (2πa³/μ0)(B_in − B) and its torque against the
    closed form. No complex algebra is shared with the function."""
    a, d = 0.5, 1e-3
    tau = dynamics.spherical_shell_time_constant(a, d, SIGMA_AL)
    w = np.array([0.0, 0.0, w_tau / tau])
    b = np.array([2e-5, 0.0, 1.5e-5])
    rhs = lambda t, x: (b - x) / tau + np.cross(w, x)  # noqa: E731
    x, h = b.copy(), tau / 200
    for i in range(4000):                 # 20 τ: the transient has decayed to e⁻²⁰ ~ 2e-9
        x = rk4_step(rhs, i * h, x, h)
    torque = np.cross(2 * np.pi * a ** 3 / MU_0 * (x - b), b)
    expected = dynamics.spherical_shell_eddy_torque(w, b, a, d, SIGMA_AL)
    # RK4 with h = τ/200 (|ω|h ≤ 0.015): ~1e-10; the transient e⁻²⁰ ≈ 2e-9 relative dominates
    assert_allclose(torque, expected, rtol=1e-7, atol=1e-7 * np.linalg.norm(expected))
