r"""A gyrostat on a circular orbit: a rigid body with a constant-speed coaxial rotor, gravity
gradient and a magnetic torque; its 2-3-1 (airplane) angles, the semi-body frame and the
normalised equations of the rotor slides.

Rotor slides, slides "Problem statement" and "Equations of motion in the semi-body frame"
(seed lines 18–38). Frames (``shared/reference/rotor_spin.md`` §2): the orbital frame has
axis 1 along the velocity, 2 along the orbit normal r × v, 3 radially out (the axes of
:func:`magbench.earth.orbital_dipole_b` and :meth:`magbench.earth.CircularOrbit.orbital_axes`);
it turns at the orbital rate ω0 about axis 2. Attitude quaternions are scalar first and map
body components to orbital ones, v_O = R(q) v_B. The rotor's axis is body axis 1; its rate
ν relative to the body is held constant by its motor, so its momentum J_f ν e1 is a constant
body-fixed vector. SI, except the normalised functions (time τ = ω0 t, rates in ω0, torques
divided by ω0²), which say so.
"""

import numpy as np

from .._validate import as_finite, as_inertia, as_positive, as_quaternions, as_vectors, shown
from . import kernels

__all__ = ["airplane_231_matrix", "airplane_231_angles", "semi_body_axes", "semi_body_field",
           "gyrostat_rates", "gyrostat_rhs", "gyrostat_turning_field_rhs", "gyrostat_kinetic_energy", "gyrostat_momentum",
           "semi_body_rhs", "rotor_reduced_rhs", "rotor_dimensionless_numbers"]


def _r1(c, s, one, zero):
    return np.stack([np.stack([one, zero, zero], -1), np.stack([zero, c, s], -1),
                     np.stack([zero, -s, c], -1)], -2)


def _r2(c, s, one, zero):
    return np.stack([np.stack([c, zero, -s], -1), np.stack([zero, one, zero], -1),
                     np.stack([s, zero, c], -1)], -2)


def _r3(c, s, one, zero):
    return np.stack([np.stack([c, s, zero], -1), np.stack([-s, c, zero], -1),
                     np.stack([zero, zero, one], -1)], -2)


def airplane_231_matrix(alpha, beta, gamma):
    r"""Orbital-to-body matrix of the 2-3-1 airplane angles.

    Parameters
    ----------
    alpha : float or array_like
        First turn α, about orbital axis 2 (the orbit normal) [rad].
    beta : float or array_like
        Second turn β, about the new axis 3 [rad].
    gamma : float or array_like
        Third turn γ, about the new axis 1 (the rotor axis) [rad].

    Returns
    -------
    ndarray, shape (..., 3, 3)
        C = R1(γ) R3(β) R2(α), passive: v_body = C v_orbital [-].

    Notes
    -----
    Rotor slides, slide "Problem statement" (seed line 23: airplane angles, turn sequence
    2-3-1); the passive elementary matrices are those of ``rotor_spin.md`` §2, the only
    signs that make the slides' equations (seed lines 29–38) follow from the rigid body.

    Examples
    --------
    >>> c = airplane_231_matrix(0.3, -0.2, 1.0)
    >>> bool(np.allclose(c @ c.T, np.eye(3)))
    True
    """
    a, b, g = np.broadcast_arrays(as_finite("alpha", alpha), as_finite("beta", beta), as_finite("gamma", gamma))
    one, zero = np.ones_like(a), np.zeros_like(a)
    return _r1(np.cos(g), np.sin(g), one, zero) @ _r3(np.cos(b), np.sin(b), one, zero) @ _r2(
        np.cos(a), np.sin(a), one, zero)


def airplane_231_angles(matrix):
    r"""The 2-3-1 airplane angles of an orbital-to-body matrix.

    Parameters
    ----------
    matrix : array_like, shape (..., 3, 3)
        C, v_body = C v_orbital [-].

    Returns
    -------
    alpha, beta, gamma : ndarray
        α = atan2(−C13, C11), β = asin C12 in [−π/2, π/2], γ = atan2(−C32, C22) [rad];
        singular at β = ±π/2 (rotor axis along the orbit normal).

    Notes
    -----
    Rotor slides, slide "Problem statement" (seed line 23); the inverse of
    :func:`airplane_231_matrix` (``rotor_spin.md`` §2, 1-based indices above).
    """
    c = as_finite("matrix", matrix)
    if c.shape[-2:] != (3, 3):
        raise ValueError(f"matrix must have shape (..., 3, 3), got shape {c.shape}")
    beta = np.arcsin(np.clip(c[..., 0, 1], -1.0, 1.0))
    alpha = np.arctan2(-c[..., 0, 2], c[..., 0, 0])
    gamma = np.arctan2(-c[..., 2, 1], c[..., 1, 1])
    return alpha, beta, gamma


def semi_body_axes(matrix):
    r"""The semi-body frame S in body components (the frame after α and β, without γ).

    Parameters
    ----------
    matrix : array_like, shape (..., 3, 3)
        Orbital-to-body matrix C [-].

    Returns
    -------
    ndarray, shape (..., 3, 3)
        Rows s1 = e1, s3 = (e1 × o2)/|e1 × o2|, s2 = s3 × s1, with o2 = C e2 the orbit
        normal in body axes; ``axes @ v_body`` gives S components, ``axes.T @ v_S`` body
        ones [-]. Singular when the rotor axis is along the orbit normal (β = ±π/2).

    Notes
    -----
    Rotor slides, slide "Control implementation" (seed line 84: "sine and cosine of γ are
    replaced by elements of the orientation matrix"); this is the exact triad of
    ``rotor_spin.md`` §2 (equal to R1(γ)ᵀ rows), no small-γ approximation.
    """
    c = as_finite("matrix", matrix)
    if c.shape[-2:] != (3, 3):
        raise ValueError(f"matrix must have shape (..., 3, 3), got shape {c.shape}")
    o2 = c[..., :, 1]
    s1 = np.broadcast_to(np.array([1.0, 0.0, 0.0]), o2.shape)
    s3 = kernels.cross(s1, o2)
    norm = np.linalg.norm(s3, axis=-1, keepdims=True)
    if np.any(norm < 1e-12):
        raise ValueError("matrix puts the rotor axis along the orbit normal (β = ±90°): the semi-body frame is singular")
    s3 = s3 / norm
    return np.stack([s1, kernels.cross(s3, s1), s3], axis=-2)


def semi_body_field(field_orbital, alpha, beta):
    r"""Field components in the semi-body frame.

    Parameters
    ----------
    field_orbital : array_like, shape (..., 3)
        B in orbital axes [T] (or normalised by B0 [-]).
    alpha, beta : float or array_like
        Airplane angles α, β [rad].

    Returns
    -------
    ndarray, shape (..., 3)
        R3(β) R2(α) B_o [same unit as ``field_orbital``]: (B1 sα + B3 cα,
        B1 cα sβ − B2 cβ − B3 sα sβ, ...) up to the slides' signs, see Notes.

    Notes
    -----
    Rotor slides, slide "Equations of motion in the semi-body frame" (seed lines 31–37):
    the brackets multiplying M_i are these components, B_s = (B1 cα cβ + B2 sβ − B3 sα cβ,
    −B1 cα sβ + B2 cβ + B3 sα sβ, B1 sα + B3 cα) (``rotor_spin.md`` §3).
    """
    b = as_vectors("field_orbital", field_orbital)
    a, be = np.broadcast_arrays(as_finite("alpha", alpha), as_finite("beta", beta))
    one, zero = np.ones_like(a), np.zeros_like(a)
    m = _r3(np.cos(be), np.sin(be), one, zero) @ _r2(np.cos(a), np.sin(a), one, zero)
    return np.einsum("...ij,...j->...i", m, b)


def gyrostat_rates(rate, torque, inertia, rotor_momentum):
    r"""Angular acceleration of a body carrying a constant-speed rotor along body axis 1.

    Parameters
    ----------
    rate : array_like, shape (..., 3)
        Absolute angular velocity ω of the body, body axes [rad/s].
    torque : array_like, shape (..., 3)
        External torque T, body axes [N·m].
    inertia : array_like, shape (..., 3) or (3, 3)
        Principal moments or tensor of body + rotor (rotor counted as rigid) [kg·m²].
    rotor_momentum : float or array_like
        J_f ν, the rotor's momentum relative to the body along axis 1 [N·m·s].

    Returns
    -------
    ndarray, shape (..., 3)
        ω̇ = I⁻¹(T − ω × (Iω + J_f ν e1)) [rad/s²].

    Notes
    -----
    Rotor slides, slide "Problem statement" (seed line 24: rotor at constant speed);
    ``rotor_spin.md`` §3. The rigid body of :func:`magbench.dynamics.euler_rates` with the
    gyroscopic torque −ω × J_f ν e1 added (Kovalenko (1975) eq. (5.1) with a flywheel).
    """
    w = as_vectors("rate", rate)
    tau = as_vectors("torque", torque)
    return kernels.gyrostat_rates(w, tau, as_inertia("inertia", inertia), as_finite("rotor_momentum", rotor_momentum))


def gyrostat_rhs(time, state, dipole, field_orbital, inertia, rotor_momentum, mean_motion):
    r"""Right-hand side of the SI gyrostat on a circular orbit (attitude to the orbital frame).

    Parameters
    ----------
    time : float
        Time [s] (the model is autonomous given its inputs; kept for solvers).
    state : array_like, shape (..., 7)
        Quaternion q (scalar first, v_orbital = R(q) v_body) [-] and the body's absolute
        angular velocity ω in body axes [rad/s].
    dipole : array_like, shape (..., 3)
        Commanded magnetic moment m, body axes [A·m²].
    field_orbital : array_like, shape (..., 3)
        Field B at the spacecraft, orbital axes [T].
    inertia : array_like, shape (..., 3) or (3, 3)
        Body + rotor inertia [kg·m²].
    rotor_momentum : float or array_like
        J_f ν along body axis 1 [N·m·s].
    mean_motion : float
        Orbital rate ω0 [rad/s].

    Returns
    -------
    ndarray, shape (..., 7)
        (q̇, ω̇) [1/s, rad/s²]: q̇ = ½ q ⊗ (0, ω − ω0 C e2),
        ω̇ from :func:`gyrostat_rates` with T = m × C B_o + 3ω0² r × I r, r = C e3.

    Notes
    -----
    Rotor slides, slide "Problem statement" (seed lines 20–25: circular orbit, central
    gravity, coils); the body-axes model of ``rotor_spin.md`` §3 that the slides' semi-body
    equations (seed lines 29–38) reduce to term by term. Gravity gradient Kovalenko (1975)
    eq. (4.18); quaternion kinematics :func:`magbench.dynamics.quaternion_rate`.
    """
    x = as_finite("state", state)
    if x.ndim == 0 or x.shape[-1] != 7:
        raise ValueError(f"state must have shape (..., 7) (quaternion, rate), got shape {x.shape}")
    as_quaternions("state[..., :4]", x[..., :4])
    n = as_positive("mean_motion", mean_motion, unit="rad/s")
    return kernels.gyrostat_rhs(x, as_vectors("dipole", dipole), as_vectors("field_orbital", field_orbital),
                                as_inertia("inertia", inertia), as_finite("rotor_momentum", rotor_momentum), n)


def gyrostat_turning_field_rhs(time, state, principal_inertia, rotor_momentum, damping_gain, field_rate):
    r"""Right-hand side of a damped gyrostat in a field that turns about a fixed inertial axis,
    carried in body axes (no attitude needed). Array kernel: unchecked, SI.

    Parameters
    ----------
    time : float
        Time [s] (unused: the model is autonomous; solvers pass it).
    state : ndarray, shape (..., 9)
        ω, the body's absolute angular velocity [rad/s]; B, the field [T]; n, the unit axis
        the field turns about [-]; all in body axes.
    principal_inertia : ndarray, shape (3,)
        A, B, C of body + rotor (rotor counted as rigid), principal axes [kg·m²].
    rotor_momentum : float
        J_f ν along body axis 1 [N·m·s].
    damping_gain : float
        k in the torque −k w⊥, w⊥ = ω − (ω·B̂)B̂ [N·m·s]; k > 0 damps, k < 0 is the slides'
        printed sign read as a torque.
    field_rate : float
        Ω_f, the field's turning rate in inertial space [rad/s].

    Returns
    -------
    ndarray, shape (..., 9)
        (ω̇, Ḃ, ṅ): ω̇ of :func:`gyrostat_rates` under T = −k w⊥, Ḃ = −ω × B + Ω_f n × B,
        ṅ = −ω × n [SI per s].

    Notes
    -----
    Rotor slides, slide "Control implementation" (seed lines 85–87; the damping torque of
    :func:`magbench.control.spin.projected_damping_dipole`, and of
    :func:`magbench.control.spin.slides_printed_damping_torque` with k < 0); the field turns
    as a circular orbit's does at Ω_f = ω0 (``rotor_spin.md`` §9). The power is
    ω·T = −k |w⊥|²; |B|, |n| and n·B are invariants. Its compiled twin (equal to the last
    bit) is :func:`magbench.dynamics.kernels.gyrostat_turning_field_rhs`.
    """
    w1, w2, w3, b1, b2, b3, n1, n2, n3 = np.moveaxis(np.asarray(state, dtype=float), -1, 0)
    a, b, c = principal_inertia[0], principal_inertia[1], principal_inertia[2]
    h, k = rotor_momentum, damping_gain
    bb = b1 * b1 + b2 * b2 + b3 * b3
    wb = (w1 * b1 + w2 * b2 + w3 * b3) / bb
    t1, t2, t3 = -k * (w1 - wb * b1), -k * (w2 - wb * b2), -k * (w3 - wb * b3)
    w_dot = kernels.gyrostat_rates(np.stack([w1, w2, w3], axis=-1), np.stack([t1, t2, t3], axis=-1),
                                   np.array([a, b, c]), h)
    return np.stack([w_dot[..., 0], w_dot[..., 1], w_dot[..., 2],
                     -(w2 * b3 - w3 * b2) + field_rate * (n2 * b3 - n3 * b2),
                     -(w3 * b1 - w1 * b3) + field_rate * (n3 * b1 - n1 * b3),
                     -(w1 * b2 - w2 * b1) + field_rate * (n1 * b2 - n2 * b1),
                     -(w2 * n3 - w3 * n2), -(w3 * n1 - w1 * n3), -(w1 * n2 - w2 * n1)], axis=-1)


def gyrostat_momentum(rate, inertia, rotor_momentum):
    r"""Angular momentum of body + rotor, body axes.

    Parameters
    ----------
    rate : array_like, shape (..., 3)
        Absolute angular velocity ω of the body [rad/s].
    inertia : array_like, shape (..., 3) or (3, 3)
        Body + rotor inertia [kg·m²].
    rotor_momentum : float or array_like
        J_f ν along body axis 1 [N·m·s].

    Returns
    -------
    ndarray, shape (..., 3)
        K = I ω + J_f ν e1 [N·m·s].

    Notes
    -----
    Rotor slides, slide "Equations of motion" (seed line 30: Ā Ω1 + J_f Ω_f is its axial
    component); Kovalenko (1975) eq. (7.5) uses K as the controlled quantity.
    """
    w = as_vectors("rate", rate)
    j = as_inertia("inertia", inertia)
    k = w @ j.T if j.shape == (3, 3) else j * w
    return k + np.asarray(as_finite("rotor_momentum", rotor_momentum))[..., None] * np.array([1.0, 0.0, 0.0])


def gyrostat_kinetic_energy(rate, inertia, rotor_momentum, rotor_inertia):
    r"""Kinetic energy of body + rotor with the rotor's relative rate ν.

    Parameters
    ----------
    rate : array_like, shape (..., 3)
        Absolute angular velocity ω of the body [rad/s].
    inertia : array_like, shape (..., 3) or (3, 3)
        Body + rotor inertia (rotor counted as rigid) [kg·m²].
    rotor_momentum : float or array_like
        J_f ν [N·m·s].
    rotor_inertia : float
        J_f, rotor axial inertia [kg·m²].

    Returns
    -------
    ndarray
        E = ½ ωᵀIω + J_f ν ω1 + ½ J_f ν² [J].

    Notes
    -----
    Not in the sources: the kinetic energy of a gyrostat (Wittenburg, *Dynamics of
    Multibody Systems*, 2nd ed., 2008, §3.4); with constant ν and no torque it is
    conserved only up to the motor's work, ν J_f ω̇1, so the conserved quantity of a
    torque-free gyrostat is E − J_f ν ω1 − ½ J_f ν² = ½ ωᵀIω (see the tests).
    """
    w = as_vectors("rate", rate)
    j = as_inertia("inertia", inertia)
    iw = w @ j.T if j.shape == (3, 3) else j * w
    h = np.asarray(as_finite("rotor_momentum", rotor_momentum))
    jf = float(as_positive("rotor_inertia", rotor_inertia, unit="kg·m²"))
    return 0.5 * np.sum(w * iw, axis=-1) + h * w[..., 0] + 0.5 * h**2 / jf


def semi_body_rhs(tau, state, torque, axial_inertia, transverse_inertia, rotor_inertia, rotor_rate):
    r"""The slides' normalised equations of the symmetric gyrostat in the semi-body frame.

    Parameters
    ----------
    tau : float
        Normalised time τ = ω0 t [-] (the equations are autonomous given ``torque``).
    state : array_like, shape (6, ...)
        α, β, γ [rad] and Ω1, Ω2, Ω3, the body's absolute angular velocity in the
        semi-body frame in units of ω0 [-].
    torque : array_like, shape (..., 3)
        External torque other than gravity in the semi-body frame divided by ω0²
        (the slides' M × B_s) [kg·m²].
    axial_inertia : float
        A = I11 of body + rotor [kg·m²].
    transverse_inertia : float
        B = I22 = I33 [kg·m²].
    rotor_inertia : float
        J_f [kg·m²].
    rotor_rate : float
        ν/ω0, the rotor's rate relative to the body in units of ω0 [-]; the rotor's
        absolute rate is Ω_f = Ω1 + ν/ω0.

    Returns
    -------
    ndarray, shape (6, ...)
        d/dτ of the state [-]: with Ā = A − J_f, H = ĀΩ1 + J_fΩ_f,

        Ā Ω1' + J_f Ω_f' = T1,
        B Ω2' + (Ā − B)Ω1Ω3 + J_fΩ_fΩ3 = −3(A − B) sα cα cβ + T2 − BΩ3(Ω1 − Ω2 tan β),
        B Ω3' + (B − Ā)Ω1Ω2 − J_fΩ_fΩ2 = −3(B − A) s²α sβ cβ + T3 + BΩ2(Ω1 − Ω2 tan β),
        α' = Ω2/cos β − 1, β' = Ω3, γ' = Ω1 − Ω2 tan β.

    Notes
    -----
    Rotor slides, slide "Equations of motion in the semi-body frame" (seed lines 29–38),
    as printed; the brackets there are the components of ``torque`` = M × B_s with
    B_s from :func:`semi_body_field`. Constant ν makes Ω_f' = Ω1'.
    """
    x = as_finite("state", state)
    if x.shape[:1] != (6,):
        raise ValueError(f"state must have shape (6, ...) (α, β, γ, Ω1, Ω2, Ω3), got shape {x.shape}")
    t = as_vectors("torque", torque)
    a = float(as_positive("axial_inertia", axial_inertia, unit="kg·m²"))
    b = float(as_positive("transverse_inertia", transverse_inertia, unit="kg·m²"))
    jf = float(as_positive("rotor_inertia", rotor_inertia, unit="kg·m²"))
    nu = float(as_finite("rotor_rate", rotor_rate))
    if jf >= a:
        raise ValueError(f"rotor_inertia must be < axial_inertia ({shown(a)} kg·m²), got {shown(jf)}")
    alpha, beta, _, w1, w2, w3 = x
    abar, wf = a - jf, w1 + nu
    sa, ca, sb, cb, tb = np.sin(alpha), np.cos(alpha), np.sin(beta), np.cos(beta), np.tan(beta)
    t1, t2, t3 = t[..., 0], t[..., 1], t[..., 2]
    dw1 = t1 / (abar + jf)
    dw2 = (-(abar - b) * w1 * w3 - jf * wf * w3 - 3.0 * (a - b) * sa * ca * cb + t2 - b * w3 * (w1 - w2 * tb)) / b
    dw3 = (-(b - abar) * w1 * w2 + jf * wf * w2 - 3.0 * (b - a) * sa**2 * sb * cb + t3 + b * w2 * (w1 - w2 * tb)) / b
    return np.stack(np.broadcast_arrays(w2 / cb - 1.0, w3, w1 - w2 * tb, dw1, dw2, dw3))


def rotor_reduced_rhs(tau, state, torque, axial_ratio):
    r"""The symmetric gyrostat's 5-state dimensionless model (γ and Ω1 eliminated).

    Parameters
    ----------
    tau : float
        Normalised time τ = ω0 t [-].
    state : array_like, shape (5, ...)
        α, β [rad], h = H/(ω0 B) (total axial momentum), Ω2, Ω3 (semi-body rates in
        units of ω0) [-].
    torque : array_like, shape (..., 3)
        Non-gravity torque in the semi-body frame divided by ω0² B [-].
    axial_ratio : float or array_like
        a = A/B [-].

    Returns
    -------
    ndarray, shape (5, ...)
        (α', β', h', Ω2', Ω3') [-]: α' = Ω2/cos β − 1, β' = Ω3, h' = t1,
        Ω2' = −hΩ3 + Ω2Ω3 tan β + t2 − 3(a − 1) sα cα cβ,
        Ω3' = hΩ2 − Ω2² tan β + t3 + 3(a − 1) s²α sβ cβ.

    Notes
    -----
    Rotor slides, slide "Equations of motion in the semi-body frame" (seed lines 29–38)
    divided by B with H = ĀΩ1 + J_fΩ_f: the body spin enters only through H
    (``rotor_spin.md`` §4), which is why the rotor lets the body spin fast. Unchecked kernel
    :func:`magbench.dynamics.kernels.rotor_reduced_rates`.
    """
    x = as_finite("state", state)
    if x.shape[:1] != (5,):
        raise ValueError(f"state must have shape (5, ...) (α, β, h, Ω2, Ω3), got shape {x.shape}")
    t = as_vectors("torque", torque)
    a = as_positive("axial_ratio", axial_ratio)
    return kernels.rotor_reduced_rates(x, t[..., 0], t[..., 1], t[..., 2], a)


def rotor_dimensionless_numbers(axial_inertia, transverse_inertia, axial_momentum, restoring_gain, damping_gain,
                                orbital_rate, equatorial_b):
    r"""The normalisation's dimensionless numbers of a symmetric rotor spacecraft.

    Parameters
    ----------
    axial_inertia : float
        A = I11 of body + rotor [kg·m²].
    transverse_inertia : float
        B, the transverse moment of inertia [kg·m²].
    axial_momentum : float
        H0, total axial momentum at u = 0 [N·m·s].
    restoring_gain : float
        k of the equilibrium law [A·m²/T].
    damping_gain : float
        k_w of the projected damping [N·m·s].
    orbital_rate : float
        ω0 [rad/s].
    equatorial_b : float
        B0 = μ0 M/(4π r³), the dipole's equatorial field at the orbit radius [T].

    Returns
    -------
    dict
        ``axial_ratio`` a = A/B, ``momentum`` c1 = H0/(ω0 B), ``restoring``
        κ = k B0²/(ω0² B), ``damping`` κ_w = k_w/(ω0 B) [-]; with the inclination these
        are the five numbers of the normalised model.

    Notes
    -----
    Rotor slides, slide "Equations of motion" (seed lines 29–38: τ = ω0 t, rates in ω0,
    torques / ω0²), divided further by B and B0 as in ``rotor_spin.md`` §4.
    """
    a = float(as_positive("axial_inertia", axial_inertia, unit="kg·m²"))
    b = float(as_positive("transverse_inertia", transverse_inertia, unit="kg·m²"))
    h0 = float(as_finite("axial_momentum", axial_momentum))
    k = float(as_finite("restoring_gain", restoring_gain))
    kw = float(as_finite("damping_gain", damping_gain))
    w0 = float(as_positive("orbital_rate", orbital_rate, unit="rad/s"))
    b0 = float(as_positive("equatorial_b", equatorial_b, unit="T"))
    return {"axial_ratio": a / b, "momentum": h0 / (w0 * b), "restoring": k * b0**2 / (w0**2 * b),
            "damping": kw / (w0 * b)}
