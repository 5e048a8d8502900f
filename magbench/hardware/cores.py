"""Cored magnetorquers: rods, their demagnetising factors, and the electromagnet design.

Kovalenko (1975) ch. 9 (eqs. 9.21–9.25, Table 5; the simplified design, eqs.
9.63–9.73). SI throughout.
"""

import math

import numpy as np

from .._validate import as_finite, as_in_range, as_nonnegative, as_positive, shown

__all__ = ["rod_demagnetizing_factor", "effective_permeability", "magnetization_curve",
           "field_for_magnetization", "core_central_magnetization", "electromagnet_design", "electromagnet_moment"]


def rod_demagnetizing_factor(elongation, formula="power"):
    r"""Central demagnetising factor of a long cylindrical rod (χ → ∞), in SI.

    Parameters
    ----------
    elongation : array_like
        Length over diameter p = l/d [-], at least 10.
    formula : {"power", "rosenblat"}, optional
        Which fit [-]: ``"power"``, Kovalenko's N ≈ 0.93 p^-1.7 (9.25); ``"rosenblat"``,
        N = (ln 1.2p − 1)/p² (9.24).

    Returns
    -------
    ndarray
        N_ц [-] in SI (N_x + N_y + N_z = 1 for an ellipsoid); Kovalenko's Table 5 lists
        4πN, the CGS value.

    Notes
    -----
    Not in the thesis: Kovalenko (1975) eq. (9.25), p. 184 (and eq. (9.24), Rosenblat,
    valid for p = 10–250).

    Deviation from source: the OCR of (9.24) lost the prefactor; it is reconstructed as
    1/p² in SI, which matches Table 5's measured column within 3 %. Table 5's "расч"
    column differs from 4π·0.93 p^-1.7 by up to 1.4 % (e.g. p = 75.63: printed 0.00738,
    formula 0.00748).

    Examples
    --------
    >>> import numpy as np
    >>> [round(float(4 * np.pi * rod_demagnetizing_factor(p)), 4) for p in (20, 30)]
    [0.0718, 0.036]
    >>> round(float(4 * np.pi * rod_demagnetizing_factor(20, "rosenblat")), 4)
    0.0684
    """
    p = as_finite("elongation", elongation)
    if np.any(p < 10):
        raise ValueError(f"elongation must be >= 10 [-] (long rods), got {shown(p[p < 10].ravel()[0])}")
    if formula == "power":
        return 0.93 * p**-1.7
    if formula == "rosenblat":
        return (np.log(1.2 * p) - 1.0) / p**2
    raise ValueError(f"formula must be one of ('power', 'rosenblat'), got {formula!r}")


def effective_permeability(permeability, demagnetizing_factor):
    r"""Apparent (rod) permeability of a core of finite length.

    Parameters
    ----------
    permeability : array_like
        Relative permeability of the material μ [-], at least 1.
    demagnetizing_factor : array_like
        Demagnetising factor N in SI [-], in [0, 1].

    Returns
    -------
    ndarray
        μ_eff = μ/(1 + N(μ − 1)) [-]: B = μ0 μ_eff H_к in the core for an applied field H_к.

    Notes
    -----
    Not in the thesis: Kovalenko (1975) eq. (9.5), p. 179, H = H_к − N J with
    J = (μ − 1)H for a linear, unsaturated material, solved for B = μ0 μ H. For μ → ∞,
    μ_eff → 1/N: the shape, not the material, limits a long core. Saturation is ignored;
    Kovalenko's (9.21)–(9.23) model it.

    Examples
    --------
    >>> n = rod_demagnetizing_factor(50.0)
    >>> round(float(effective_permeability(1e5, n)))
    824
    """
    mu = as_finite("permeability", permeability)
    if np.any(mu < 1):
        raise ValueError(f"permeability must be >= 1 [-], got {shown(mu[mu < 1].ravel()[0])}")
    n = as_in_range("demagnetizing_factor", demagnetizing_factor, 0.0, 1.0)
    return mu / (1.0 + n * (mu - 1.0))


def magnetization_curve(field, a, b):
    r"""Magnetisation of a soft core material, with saturation.

    Parameters
    ----------
    field : array_like
        Field strength inside the material H [A/m], at least 0.
    a : array_like
        Saturation magnetisation of the fit, J(H → ∞) [A/m].
    b : array_like
        Field of half saturation [A/m].

    Returns
    -------
    ndarray
        J = aH/(H + b) [A/m].

    Notes
    -----
    Not in the thesis: Kovalenko (1975) eq. (9.21), p. 183, with a = 1.25·10⁶ A/m,
    b = 40 A/m for permalloy 50Н and a = 1.92·10⁶, b = 170 A/m for permendur.

    Examples
    --------
    >>> round(float(magnetization_curve(500.0, 1.25e6, 40.0)) / 1e6, 3)
    1.157
    """
    h = as_nonnegative("field", field, unit="A/m")
    a_ = as_positive("a", a, unit="A/m")
    b_ = as_positive("b", b, unit="A/m")
    return a_ * h / (h + b_)


def field_for_magnetization(magnetization, a, b):
    r"""Field that magnetises a soft core material to a given magnetisation.

    Parameters
    ----------
    magnetization : array_like
        Magnetisation J [A/m], in [0, a).
    a : array_like
        Saturation magnetisation of the fit [A/m].
    b : array_like
        Field of half saturation [A/m].

    Returns
    -------
    ndarray
        H = bJ/(a − J) [A/m].

    Notes
    -----
    Not in the thesis: Kovalenko (1975) eq. (9.22), p. 183, the inverse of (9.21).

    Examples
    --------
    >>> round(float(field_for_magnetization(1.1e6, 1.25e6, 40.0)), 1)
    293.3
    """
    j = as_nonnegative("magnetization", magnetization, unit="A/m")
    a_ = as_positive("a", a, unit="A/m")
    b_ = as_positive("b", b, unit="A/m")
    if np.any(j >= a_):
        raise ValueError(f"magnetization must be below the saturation a = {shown(np.max(a_))} A/m, "
                         f"got {shown(np.max(j))}")
    return b_ * j / (a_ - j)


def core_central_magnetization(coil_field, demagnetizing_factor, a, b):
    r"""Magnetisation of a rod core's central section in a coil's field, with saturation.

    Parameters
    ----------
    coil_field : array_like
        Field of the magnetising winding H_к [A/m], at least 0.
    demagnetizing_factor : array_like
        Central demagnetising factor N_ц in SI [-], in (0, 1].
    a : array_like
        Saturation magnetisation of the material's curve (9.21) [A/m].
    b : array_like
        Field of half saturation of the curve [A/m].

    Returns
    -------
    ndarray
        J_ц = [(H_к + N_ц a + b) − √((H_к + N_ц a + b)² − 4 N_ц a H_к)]/(2N_ц) [A/m]: the
        smaller root of J = aH/(H + b) with H = H_к − N_ц J (the physical one, J < a).

    Notes
    -----
    Not in the thesis: Kovalenko (1975) eq. (9.23), p. 183 (the minus root; OCR
    reconstructed). For a weak field it is the linear result H_к/(N_ц + b/a); for
    H_к → ∞ it tends to a (saturation).

    Examples
    --------
    >>> n = rod_demagnetizing_factor(40.0)
    >>> round(float(core_central_magnetization(2434.0, n, 1.25e6, 40.0)) / 1e6, 3)
    1.143
    """
    hk = as_nonnegative("coil_field", coil_field, unit="A/m")
    n = as_in_range("demagnetizing_factor", demagnetizing_factor, 0.0, 1.0)
    if np.any(n == 0):
        raise ValueError("demagnetizing_factor must lie in (0, 1] [-], got 0.0")
    a_ = as_positive("a", a, unit="A/m")
    b_ = as_positive("b", b, unit="A/m")
    c = hk + n * a_ + b_
    # c − √(c² − 4nah) loses digits for a weak field: use the equal form 4nah/(c + √…)
    return 2.0 * a_ * hk / (c + np.sqrt(c**2 - 4.0 * n * a_ * hk))


def electromagnet_design(moment, elongation, design_magnetization, design_field,
                         averaging_factor, current_density, fill_factor, resistivity,
                         core_density, conductor_density, voltage):
    r"""A rod electromagnet sized for a moment at a near-saturation core state.

    Parameters
    ----------
    moment : float
        Required moment L_p [A·m²].
    elongation : float
        Core elongation p = l/D₁ [-], at least 10.
    design_magnetization : float
        Central magnetisation chosen near saturation J° [A/m].
    design_field : float
        Field inside the core at that state H° [A/m].
    averaging_factor : float
        k = J_c/J_ц, mean over central magnetisation [-], in (0, 1].
    current_density : float
        Current density in the winding j [A/m²].
    fill_factor : float
        Winding fill factor k_з [-], in (0, 1].
    resistivity : float
        Conductor resistivity ρ [Ω·m].
    core_density : float
        Core density γ_c [kg/m³].
    conductor_density : float
        Conductor density γ_м [kg/m³].
    voltage : float
        Supply voltage U [V] (sets the wire diameter only).

    Returns
    -------
    dict
        ``core_diameter`` D₁ (9.64) [m], ``length`` l (9.65) [m], ``demagnetizing_factor``
        N_ц (9.25) [-], ``coil_field`` H_к = H° + N_ц J° (9.63) [A/m],
        ``winding_outer_diameter`` D₂ (9.72) [m], ``power`` P = (π/4) l ρ j² k_з (D₂² − D₁²)
        (9.56) [W], ``current`` P/U [A], ``wire_diameter`` √(4P/(πjU)) (9.73) [m],
        ``core_mass`` γ_c π D₁² l/4 [kg], ``conductor_mass`` P γ_м/(j²ρ) (9.38) [kg],
        ``mass`` (core + conductor; insulation, casing and supply excluded, as for the
        air-core coil) [kg].

    Notes
    -----
    Not in the thesis: Kovalenko (1975) §9.3, eqs. (9.63)–(9.65), (9.72), (9.56), (9.38),
    (9.73), pp. 193–198, the "simplified design" in which the core is taken to a chosen
    state near saturation. The winding's own moment (two orders smaller, (9.33)) is
    neglected, as Kovalenko does. :func:`core_central_magnetization` checks the state
    against the material's curve.

    Examples
    --------
    >>> em = electromagnet_design(0.4, 40.0, 1.1e6, 500.0, 0.79, 2e6, 0.5, 0.0175e-6,
    ...                           8.0e3, 8.9e3, 12.0)
    >>> round(em["length"], 4), round(em["power"], 3), round(em["mass"] * 1e3, 1)
    (0.0979, 0.128, 19.9)
    """
    lp = float(as_positive("moment", moment, unit="A·m²"))
    p = float(as_finite("elongation", elongation))
    if p < 10:
        raise ValueError(f"elongation must be >= 10 [-] (long rods), got {shown(p)}")
    j0 = float(as_positive("design_magnetization", design_magnetization, unit="A/m"))
    h0 = float(as_nonnegative("design_field", design_field, unit="A/m"))
    k = float(as_in_range("averaging_factor", averaging_factor, 0.0, 1.0))
    kz = float(as_in_range("fill_factor", fill_factor, 0.0, 1.0))
    for name, value in (("averaging_factor", k), ("fill_factor", kz)):
        if value == 0:
            raise ValueError(f"{name} must lie in (0, 1] [-], got 0.0")
    j = float(as_positive("current_density", current_density, unit="A/m²"))
    rho = float(as_positive("resistivity", resistivity, unit="Ω·m"))
    g_c = float(as_positive("core_density", core_density, unit="kg/m³"))
    g_m = float(as_positive("conductor_density", conductor_density, unit="kg/m³"))
    u = float(as_positive("voltage", voltage, unit="V"))
    d1 = (4.0 * lp / (math.pi * k * j0 * p)) ** (1.0 / 3.0)              # (9.64)
    length = p * d1                                                        # (9.65)
    n_c = float(rod_demagnetizing_factor(p))                               # (9.25)
    h_k = h0 + n_c * j0                                                    # (9.63)
    d2 = d1 + h_k / (0.5 * j * kz)                                         # (9.72)
    power = math.pi / 4.0 * length * rho * j**2 * kz * (d2**2 - d1**2)     # (9.56)
    core_mass = g_c * math.pi * d1**2 * length / 4.0
    conductor_mass = power * g_m / (j**2 * rho)                            # (9.38)
    return {
        "core_diameter": d1, "length": length, "demagnetizing_factor": n_c, "coil_field": h_k,
        "winding_outer_diameter": d2, "power": power, "current": power / u,
        "wire_diameter": math.sqrt(4.0 * power / (math.pi * j * u)),       # (9.73)
        "core_mass": core_mass, "conductor_mass": conductor_mass,
        "mass": core_mass + conductor_mass,
    }


def electromagnet_moment(central_magnetization, core_diameter, length, averaging_factor):
    r"""Moment of a rod electromagnet's core from the magnetisation of its central section.

    Parameters
    ----------
    central_magnetization : array_like
        Magnetisation of the core's central section J_ц [A/m], e.g. from
        :func:`core_central_magnetization` (the state the winding actually produces).
    core_diameter : array_like
        Core diameter D₁ [m], > 0.
    length : array_like
        Core length l [m], > 0.
    averaging_factor : array_like
        k = J_c/J_ц, mean over central magnetisation [-], in (0, 1].

    Returns
    -------
    ndarray
        L = k J_ц π D₁² l / 4 [A·m²].

    Notes
    -----
    Not in the thesis: Kovalenko (1975) §9.3, eq. (9.64) read the other way (the moment
    of a core of volume πD₁²l/4 magnetised to k J_ц on average). At the design state J°
    of :func:`electromagnet_design` it gives back the required moment; with the
    magnetisation from the material's curve it shows whether the core saturates first.

    Examples
    --------
    >>> em = electromagnet_design(0.4, 40.0, 1.1e6, 500.0, 0.79, 2e6, 0.5, 0.0175e-6,
    ...                           8.0e3, 8.9e3, 12.0)
    >>> round(float(electromagnet_moment(1.1e6, em["core_diameter"], em["length"], 0.79)), 12)
    0.4
    """
    j = as_finite("central_magnetization", central_magnetization)
    d = as_positive("core_diameter", core_diameter, unit="m")
    length_ = as_positive("length", length, unit="m")
    k = as_in_range("averaging_factor", averaging_factor, 0.0, 1.0)
    if np.any(k == 0):
        raise ValueError("averaging_factor must lie in (0, 1] [-], got 0.0")
    return k * j * math.pi * d ** 2 * length_ / 4
