r"""Eddy-current losses of a magnetically soft rod turning in the Earth's field: the currents in
the rod itself and in a conducting shell (a short-circuited winding) round it.

Kovalenko (1975) §12.1, eqs. (12.2)–(12.9), seed lines 221–223 (pp. 221–223), and (12.33)–(12.35),
seed line 228 (p. 228); the comparison E44 on seed lines 228–229. SI: B in T, H in A/m,
resistivities in Ω·m, torques in N·m. Inductances are neglected throughout (the book's
footnote to (12.5): low frequency, no skin effect).

Along a rod of length l the central induction B_ц falls off as the parabola (12.4)
B_x = B_ц[1 − c(2x/l)²], c = 3(1 − k) ≈ 0.85, k the ratio of the mean to the central induction.
"""

import numpy as np

from .._docstrings import fill_docstring
from .._validate import as_finite, as_in_range, as_nonnegative, as_positive
from ..constants import MU_0

__all__ = ["rod_eddy_profile_coefficient", "rod_eddy_power", "rod_eddy_torque", "rod_eddy_torque_from_field",
           "shell_eddy_torque", "rod_to_shell_eddy_ratio", "winding_parameter", "winding_damping_torque"]

#: Parameters described once for the functions that share them (:func:`magbench._docstrings.fill_docstring`).
_LOSS_PARAMETERS = {
    "diameter": """diameter : float or array_like
    Rod diameter d > 0 [m].""",
    "parabola_coefficient": """parabola_coefficient : float or array_like, optional
    c of the axial profile (12.4), in [0, 1] [-].""",
    "rate": """rate : float or array_like
    Rate ω ≥ 0 of the rod relative to the field [rad/s].""",
    "resistivity": """resistivity : float or array_like
    Resistivity ρ_c > 0 [Ω·m].""",
    "volume": """volume : float or array_like
    Rod volume V > 0 [m³].""",
}
_document_losses = fill_docstring(_LOSS_PARAMETERS)


def rod_eddy_profile_coefficient(parabola_coefficient=0.85):
    r"""The factor α of the rod's eddy loss: the mean of (B_x/B_ц)² along the rod, halved.

    Parameters
    ----------
    parabola_coefficient : float or array_like, optional
        c of the axial profile (12.4), 0 ≤ c ≤ 1 [-]; the book's 0.85 by default
        (c = 3(1 − k), k ≈ 0.72–0.73 for long rods).

    Returns
    -------
    ndarray
        α = ½ − c/3 + c²/10 [-] (0.2889 at c = 0.85; ½ for a uniform rod).

    Notes
    -----
    Kovalenko (1975) eq. (12.5), seed line 222 (p. 222): "α = ½ − c/3 + c²/10 ≈ 0,288". The
    printed 0.288 is 0.2889 truncated, not rounded (the tests keep both). Check:
    ½∫₋₁¹(1 − cu²)² du/2 = ½(1 − 2c/3 + c²/5).

    Examples
    --------
    >>> round(float(rod_eddy_profile_coefficient()), 5)
    0.28892
    """
    c = as_in_range("parabola_coefficient", parabola_coefficient, 0.0, 1.0)
    return 0.5 - c / 3.0 + c ** 2 / 10.0


@_document_losses
def rod_eddy_power(volume, diameter, resistivity, induction_rate, parabola_coefficient=0.85):
    r"""Instantaneous eddy-current loss in a long rod whose induction changes.

    Parameters
    ----------
    volume : float or array_like
        Rod volume V = πd²l/4 > 0 [m³].
    {diameter}
    resistivity : float or array_like
        Resistivity of the rod's material ρ_c > 0 [Ω·m].
    induction_rate : float or array_like
        dB_ц/dt at the rod's centre [T/s].
    {parabola_coefficient}

    Returns
    -------
    ndarray
        P_в.с = α V d² (dB_ц/dt)²/(16ρ_c) [W].

    Notes
    -----
    Kovalenko (1975) eqs. (12.2)–(12.5), seed lines 221–222 (pp. 221–222): a ring of radius y
    links the flux πy²B_x, has resistance ρ_c 2πy/(dx dy) and loses
    dP = π y³ Ḃ_x² dx dy/(2ρ_c) (12.3); integrated over the section and the length with (12.4).
    """
    v = as_positive("volume", volume, unit="m³")
    d = as_positive("diameter", diameter, unit="m")
    rho = as_positive("resistivity", resistivity, unit="Ω·m")
    rate = as_finite("induction_rate", induction_rate)
    alpha = rod_eddy_profile_coefficient(parabola_coefficient)
    return alpha * v * d ** 2 * rate ** 2 / (16.0 * rho)


@_document_losses
def rod_eddy_torque(volume, diameter, resistivity, rate, induction_amplitude, parabola_coefficient=0.85):
    r"""Mean damping torque of the eddy currents in a rod turning uniformly in a field.

    Parameters
    ----------
    {volume, diameter, resistivity}
    rate : float or array_like
        Rate ω ≥ 0 at which the rod turns relative to the field [rad/s].
    induction_amplitude : float or array_like
        Amplitude B_0ц of the central induction, B_ц = B_0ц sin ωt (12.6) [T].
    {parabola_coefficient}

    Returns
    -------
    ndarray
        M_в.с = α V d² ω B_0ц²/(32ρ_c) [N·m]: the mean loss αVd²ω²B_0ц²/(32ρ_c) over ω.

    Notes
    -----
    Kovalenko (1975) eqs. (12.6), (12.7), seed line 223 (p. 223): ⟨Ḃ²⟩ = ω²B_0ц²/2.
    """
    v = as_positive("volume", volume, unit="m³")
    d = as_positive("diameter", diameter, unit="m")
    rho = as_positive("resistivity", resistivity, unit="Ω·m")
    w = as_nonnegative("rate", rate, unit="rad/s")
    b0 = as_finite("induction_amplitude", induction_amplitude)
    alpha = rod_eddy_profile_coefficient(parabola_coefficient)
    return alpha * v * d ** 2 * w * b0 ** 2 / (32.0 * rho)


@_document_losses
def rod_eddy_torque_from_field(volume, diameter, resistivity, rate, field_amplitude, elongation,
                               parabola_coefficient=0.85):
    r"""Rod eddy torque for an ideally soft rod (μ → ∞) in a field of amplitude H₀.

    Parameters
    ----------
    {volume, diameter, resistivity, rate}
    field_amplitude : float or array_like
        Amplitude H₀ of the field along the rod [A/m].
    elongation : float or array_like
        p = l/d ≥ 10 [-].
    {parabola_coefficient}

    Returns
    -------
    ndarray
        (12.7) with B_0ц = μ0H₀/N_ц, N_ц = 0.93 p^-1.7 (9.25) [N·m]; at c = 0.85 this is
        α/(32·0.93²) V d² ω μ0² H₀² p^3.4/ρ_c = 1.04·10⁻² V d² ω μ0² H₀² p^3.4/ρ_c.

    Notes
    -----
    Kovalenko (1975) eqs. (12.8), (12.9) and the unnumbered formula after them, seed line 223
    (p. 223); the printed coefficient is "1,04" (α/(32·0.93²) = 0.01044).
    """
    from .cores import rod_demagnetizing_factor

    n = rod_demagnetizing_factor(elongation)
    h0 = as_finite("field_amplitude", field_amplitude)
    return rod_eddy_torque(volume, diameter, resistivity, rate, MU_0 * h0 / n, parabola_coefficient)


@_document_losses
def shell_eddy_torque(volume, diameter, outer_diameter, resistivity, rate, induction_amplitude,
                      parabola_coefficient=0.85):
    r"""Mean damping torque of the currents in a conducting shell (or a short-circuited winding)
    round a rod turning in a field, its inductance neglected.

    Parameters
    ----------
    volume : float or array_like
        Volume of the rod V_c = πd²l/4 > 0 [m³].
    diameter : float or array_like
        Rod diameter d = the shell's inner diameter > 0 [m].
    outer_diameter : float or array_like
        Shell's outer diameter D > d [m].
    resistivity : float or array_like
        Resistivity of the shell ρ_м > 0 [Ω·m].
    {rate}
    induction_amplitude : float or array_like
        Amplitude B_0ц of the rod's central induction [T].
    {parabola_coefficient}

    Returns
    -------
    ndarray
        M_в.к = α V_c d² ω B_0ц² ln(D/d)/(8ρ_м) [N·m].

    Notes
    -----
    Kovalenko (1975) eq. (12.35), seed line 228 (p. 228): (12.5) integrated from y = d/2 to
    D/2. Every ring of the shell links the whole flux of the rod, π(d/2)²B_x (the shell
    itself carries ≈ μ0H, negligible), so dP = (πd²Ḃ_x/4)² dx dy/(2πρ_м y) and ∫dy/y = ln(D/d).

    Deviation from source: the seed's OCR loses the volume's symbol and calls it "the volume
    of the shell"; the derivation gives the volume of the rod. The two agree in the book's
    example D = √2 d (V_c = V_к), where the ratio E44 is computed.
    """
    d = as_positive("diameter", diameter, unit="m")
    big = as_positive("outer_diameter", outer_diameter, unit="m")
    if np.any(big <= d):
        raise ValueError(f"outer_diameter must be > diameter [m], got {np.min(big)!r} and {np.max(d)!r}")
    return 4.0 * rod_eddy_torque(volume, d, resistivity, rate, induction_amplitude,
                                 parabola_coefficient) * np.log(big / d)


def rod_to_shell_eddy_ratio(rod_resistivity, shell_resistivity, diameter_ratio):
    r"""Ratio of the eddy torque in the rod to that in a shell round it, at equal B and ω.

    Parameters
    ----------
    rod_resistivity : float or array_like
        ρ_c of the rod > 0 [Ω·m].
    shell_resistivity : float or array_like
        ρ_м of the shell > 0 [Ω·m].
    diameter_ratio : float or array_like
        D/d > 1 [-].

    Returns
    -------
    ndarray
        M_в.с/M_в.к = ρ_м/(4ρ_c ln(D/d)) [-].

    Notes
    -----
    Kovalenko (1975) (12.7)/(12.35), seed lines 228–229 (pp. 228–229): with D = √2 d, copper
    (ρ_м = 0.0175·10⁻⁶ Ω·m) and permalloy rods (ρ_c = 0.45–0.9·10⁻⁶ Ω·m) the book prints
    (1.4–2.8)·10⁻², "so M_в.с can be neglected".

    Examples
    --------
    >>> [round(float(rod_to_shell_eddy_ratio(r, 0.0175e-6, 2 ** 0.5)), 4) for r in (0.9e-6, 0.45e-6)]
    [0.014, 0.0281]
    """
    rc = as_positive("rod_resistivity", rod_resistivity, unit="Ω·m")
    rm = as_positive("shell_resistivity", shell_resistivity, unit="Ω·m")
    q = as_positive("diameter_ratio", diameter_ratio)
    if np.any(q <= 1):
        raise ValueError(f"diameter_ratio must be > 1 [-] (D > d), got {np.min(q)!r}")
    return rm / (4.0 * rc * np.log(q))


@_document_losses
def winding_parameter(rate, diameter, outer_diameter, resistivity, fill_factor=1.0):
    r"""The parameter a = ωL_к/R_к of a short-circuited winding (or a shell) round a rod.

    Parameters
    ----------
    {rate}
    diameter : float or array_like
        Rod (inner) diameter d > 0 [m].
    outer_diameter : float or array_like
        Outer diameter of the winding D > d [m].
    resistivity : float or array_like
        Resistivity of the conductor ρ_м > 0 [Ω·m].
    fill_factor : float or array_like, optional
        Fill factor of the winding k_з in (0, 1] [-]; 1 for a solid shell.

    Returns
    -------
    ndarray
        a = ω μ0 d² (D − d) k_з/(4ρ_м(D + d)) [-]; independent of the number of turns.

    Notes
    -----
    Kovalenko (1975) eq. (12.33), seed line 228 (p. 228), from L_к = μ0 w² πd²/(4l) (a long
    solenoid on the rod's section, (12.25)) and R_к (12.32). Deviation from source: the seed's
    (12.33) is OCR; reconstructed from (12.25) and (12.32), which give it exactly.
    """
    w = as_nonnegative("rate", rate, unit="rad/s")
    d = as_positive("diameter", diameter, unit="m")
    big = as_positive("outer_diameter", outer_diameter, unit="m")
    if np.any(big <= d):
        raise ValueError(f"outer_diameter must be > diameter [m], got {np.min(big)!r} and {np.max(d)!r}")
    rho = as_positive("resistivity", resistivity, unit="Ω·m")
    k = as_in_range("fill_factor", fill_factor, 0.0, 1.0)
    if np.any(k == 0):
        raise ValueError("fill_factor must lie in (0, 1] [-], got 0.0")
    return w * MU_0 * d ** 2 * (big - d) * k / (4.0 * rho * (big + d))


@_document_losses
def winding_damping_torque(volume, field_amplitude, demagnetizing_factor, winding_parameter, averaging_factor=0.72):
    r"""Mean damping torque of a short-circuited winding on an ideally soft, lossless rod.

    Parameters
    ----------
    {volume}
    field_amplitude : float or array_like
        Amplitude H₀ of the external field along the rod [A/m].
    demagnetizing_factor : float or array_like
        Central demagnetising factor N_ц > 0 (SI) [-]
        (:func:`magbench.hardware.rod_demagnetizing_factor`).
    winding_parameter : float or array_like
        a = ωL_к/R_к ≥ 0 [-] (:func:`winding_parameter`).
    averaging_factor : float or array_like, optional
        k, the mean over the rod of the induction relative to its centre, in (0, 1] [-].

    Returns
    -------
    ndarray
        M*_в.к = ½ V μ0 H₀² a k²/(N_ц² + (ak)²) [N·m]; largest at a₀ = N_ц/k, where it is
        k V μ0 H₀²/(4N_ц) (12.31).

    Notes
    -----
    Kovalenko (1975) eqs. (12.16), (12.22), (12.30), (12.31), seed lines 225–227
    (pp. 225–227). With μ → ∞ and no hysteresis, (12.19) gives the central induction
    B = μ0H₀/(N_ц + jak); the winding links k B S per turn, so its EMF amplitude is
    E = ω w S k |B| and (12.22) M = E²/(2R_кω) = a V k²|B|²/(2μ0).

    Deviation from source: (12.30) and (12.31) are garbled in the seed; they are derived as
    above. The factor k² (one k from the reaction (12.16), one from the EMF) is what makes the
    book's E45 comparison with (12.1) "at k = k_φ" come out as πμ0H₀²/(2N_ц(∮HdB)_ц)
    (the k cancels against (12.1)'s k_φ); a reading with a single k would leave 1/k there.
    """
    v = as_positive("volume", volume, unit="m³")
    h0 = as_finite("field_amplitude", field_amplitude)
    n = as_positive("demagnetizing_factor", demagnetizing_factor)
    a = as_nonnegative("winding_parameter", winding_parameter)
    k = as_in_range("averaging_factor", averaging_factor, 0.0, 1.0)
    if np.any(k == 0):
        raise ValueError("averaging_factor must lie in (0, 1] [-], got 0.0")
    return 0.5 * v * MU_0 * h0 ** 2 * a * k ** 2 / (n ** 2 + (a * k) ** 2)
