r"""Eddy-current torques on a conducting body spinning in a uniform field: Kovalenko's general
form (4.23), its coefficient for a thin spherical shell, a solid sphere and a thin open
cylindrical shell, the finite-frequency spherical shell (4.24), and the despin time constant.

Kovalenko (1975) §4.2, eqs. (4.23)–(4.26), seed lines 87–88 (pp. 86–87). SI throughout: a
coefficient k is in N·m·s/T² (= S·m⁴), so that k ω B² is a torque.

In the body frame a field that is fixed in inertial space changes as Ḃ = −ω × B. At low
frequency (the induced currents' own field negligible: ωτ ≪ 1, τ the body's L/R time) the
currents are driven by the electric field −∂A/∂t of that change and the body's eddy moment is
m = −Γ Ḃ = Γ(ω × B), Γ a symmetric positive "eddy polarisability" [S·m⁴] that depends only on
shape, size and conductivity; the torque is m × B and the power it takes from the spin is
Ḃ·Γ·Ḃ ≥ 0. For an isotropic body Γ = k 1 and this is Kovalenko's (4.23).
"""

import numpy as np

from .._docstrings import fill_docstring
from .._validate import as_finite, as_nonnegative, as_positive, as_vectors, shown
from ..constants import MU_0
from . import kernels

__all__ = ["eddy_torque", "eddy_torque_components", "anisotropic_eddy_torque", "spherical_shell_eddy_coefficient",
           "spherical_shell_time_constant", "spherical_shell_eddy_torque", "solid_sphere_eddy_coefficient",
           "cylinder_eddy_coefficients", "eddy_despin_time_constant", "shell_despin_time_constant"]

#: Parameters described once for the functions that share them (:func:`magbench._docstrings.fill_docstring`).
_EDDY_PARAMETERS = {
    "b": """b : array_like, shape (..., 3)
    Flux density **B**₀ in the same axes [T].""",
    "conductivity": """conductivity : float or array_like
    Conductivity σ > 0 [S/m].""",
    "inertia": """inertia : float or array_like
    Moment of inertia about the spin axis J > 0 [kg·m²].""",
    "radius": """radius : float or array_like
    Shell radius a > 0 [m].""",
    "rate": """rate : array_like, shape (..., 3)
    Body angular velocity **ω**, body axes [rad/s].""",
    "thickness": """thickness : float or array_like
    Wall thickness d > 0, d < a [m].""",
}
_document_eddy = fill_docstring(_EDDY_PARAMETERS)


@_document_eddy
def eddy_torque(rate, b, coefficient):
    r"""Eddy-current torque on an isotropic conducting body spinning in a uniform field.

    Parameters
    ----------
    {rate, b}
    coefficient : float or array_like
        Eddy coefficient k_в ≥ 0 [N·m·s/T²] (:func:`spherical_shell_eddy_coefficient`,
        :func:`solid_sphere_eddy_coefficient`).

    Returns
    -------
    ndarray, shape (..., 3)
        **M** = k_в (**ω** × **B**₀) × **B**₀ [N·m]. Its part along **ω** is
        −k_в B₀² ω sin²α (braking), its part across **ω** has magnitude k_в B₀² ω sin α cos α
        (precession), α the angle between **B**₀ and **ω** (:func:`eddy_torque_components`).

    Notes
    -----
    Kovalenko (1975) eq. (4.23), seed line 87 (p. 86); components (4.23a), (4.23b). The
    power taken from the spin is −**ω**·**M** = k_в |**ω** × **B**₀|² ≥ 0. Valid at low
    frequency (ωτ ≪ 1, τ the body's L/R time; :func:`spherical_shell_eddy_torque` gives the
    spherical shell at any ωτ).

    Examples
    --------
    >>> eddy_torque([0.0, 0.0, 2.0], [1.0, 0.0, 0.0], 0.5).tolist()   # α = 90°: braking only
    [0.0, 0.0, -1.0]
    """
    w = as_vectors("rate", rate)
    bb = as_vectors("b", b)
    k = as_nonnegative("coefficient", coefficient, unit="N·m·s/T²")
    return kernels.eddy_torque(w, bb, k)


def eddy_torque_components(rate, b, coefficient):
    r"""Braking and precession parts of the eddy torque (4.23a), (4.23b).

    Parameters
    ----------
    rate : array_like, shape (..., 3)
        Body angular velocity **ω**, non-zero [rad/s].
    b : array_like, shape (..., 3)
        Flux density **B**₀ [T].
    coefficient : float or array_like
        Eddy coefficient k_в ≥ 0 [N·m·s/T²].

    Returns
    -------
    braking : ndarray
        Component along **ω**, −k_в B₀² ω sin²α [N·m] (≤ 0).
    precession : ndarray
        Magnitude of the component across **ω**, k_в B₀² ω sin α |cos α| [N·m].

    Notes
    -----
    Kovalenko (1975) eqs. (4.23a), (4.23b), seed line 87 (p. 86). The book writes the
    precession part as k_в B₀² sin α cos α ω; its sign follows the sign of cos α, so the
    magnitude carries |cos α|.
    """
    w = as_vectors("rate", rate)
    bb = as_vectors("b", b)
    k = as_nonnegative("coefficient", coefficient, unit="N·m·s/T²")
    speed = np.linalg.norm(w, axis=-1)
    if np.any(speed == 0):
        raise ValueError("rate must be non-zero: the angle α between B and ω is undefined at rest")
    b2 = np.sum(bb * bb, axis=-1)
    cos_a = np.sum(w * bb, axis=-1) / (speed * np.sqrt(np.where(b2 > 0, b2, 1.0)))
    sin2 = np.clip(1.0 - cos_a ** 2, 0.0, 1.0)  # rounding only: |cos α| ≤ 1 up to one ulp
    return -k * b2 * speed * sin2, k * b2 * speed * np.sqrt(sin2) * np.abs(cos_a)


@_document_eddy
def anisotropic_eddy_torque(rate, b, coefficients):
    r"""Eddy-current torque on a body whose eddy polarisability differs between its axes.

    Parameters
    ----------
    {rate}
    b : array_like, shape (..., 3)
        Flux density **B**₀ in body axes [T].
    coefficients : array_like, shape (..., 3)
        Principal eddy coefficients Γ_x, Γ_y, Γ_z ≥ 0 along the body axes [N·m·s/T²]
        (for a cylinder along z: :func:`cylinder_eddy_coefficients`).

    Returns
    -------
    ndarray, shape (..., 3)
        **M** = (Γ(**ω** × **B**₀)) × **B**₀ [N·m]; with Γ_x = Γ_y = Γ_z = k it is
        :func:`eddy_torque`.

    Notes
    -----
    Kovalenko (1975) eqs. (4.25), (4.26), seed lines 87–88 (pp. 86–87): a cylindrical shell
    spinning about its own axis, where only Γ⊥ acts and (4.25) is (4.23) with k_в = Γ⊥, and
    about a transverse axis, where the torque pulsates at twice the spin rate and its mean is
    braking only, −½(Γ⊥ + Γ∥) B₀² ω sin²α along **ω** (the book's "½ Q sin α").

    Not in the sources: the tensor form m = Γ(**ω** × **B**₀), the low-frequency induced
    moment of a resistive body (the power −**ω**·**M** = Ḃ·Γ·Ḃ ≥ 0; Landau & Lifshitz,
    *Electrodynamics of Continuous Media*, 2nd ed., §59). The book's (4.26) is garbled in
    the seed; its mean follows from this form.
    """
    w = as_vectors("rate", rate)
    bb = as_vectors("b", b)
    g = as_vectors("coefficients", coefficients)
    as_nonnegative("coefficients", g, unit="N·m·s/T²")
    return kernels.anisotropic_eddy_torque(w, bb, g)


def _thin_shell(radius, thickness, conductivity):
    """The checked radius, thickness and conductivity of a thin spherical shell (d < a)."""
    a = as_positive("radius", radius, unit="m")
    d = as_positive("thickness", thickness, unit="m")
    s = as_positive("conductivity", conductivity, unit="S/m")
    if np.any(d >= a):
        raise ValueError(f"thickness must be < radius for a thin shell [m], got thickness {shown(np.max(d))} "
                         f"and radius {shown(np.min(a))}")
    return a, d, s


@_document_eddy
def spherical_shell_eddy_coefficient(radius, thickness, conductivity):
    r"""Low-frequency eddy coefficient of a thin conducting spherical shell.

    Parameters
    ----------
    {radius}
    thickness : float or array_like
        Wall thickness d > 0, d ≪ a [m].
    conductivity : float or array_like
        Electrical conductivity σ > 0 [S/m].

    Returns
    -------
    ndarray
        k_в = (2π/3) σ d a⁴ = 2π a⁴/(3ξ), ξ = 1/(σd) the surface resistivity [N·m·s/T²].

    Notes
    -----
    Kovalenko (1975) eq. (4.24), seed line 87 (p. 86), after Halverson & Cohen (1964), at
    ωτ ≪ 1. Deviation from source: (4.24) is garbled in the seed (only the denominator
    9ξ² + μ0²a²ω² survives); the coefficient is derived here. A changing uniform field Ḃ drives
    the azimuthal surface current K = −½σd Ḃ × **r** (the circulation of E round a parallel
    is −Ḃ·area), whose moment is m = −(2π/3)σ d a⁴ Ḃ; with Ḃ = −**ω** × **B** in the body
    this is k_в(**ω** × **B**): the low-frequency limit of the thin-shell solution (the
    shell's internal field B/(1 + iωτ), :func:`spherical_shell_time_constant`). The tests
    hold it to an independent numerical solution of the rotating shell in the inertial frame
    (motional EMF plus the surface charges' potential, by least dissipation).

    Examples
    --------
    >>> round(float(spherical_shell_eddy_coefficient(0.5, 1e-3, 3.5e7)), 1)   # aluminium, 1 mm
    4581.5
    """
    a, d, s = _thin_shell(radius, thickness, conductivity)
    return 2.0 * np.pi / 3.0 * s * d * a ** 4


@_document_eddy
def spherical_shell_time_constant(radius, thickness, conductivity):
    r"""L/R time constant of a thin conducting spherical shell.

    Parameters
    ----------
    {radius}
    thickness : float or array_like
        Wall thickness d > 0 [m].
    conductivity : float or array_like
        Electrical conductivity σ > 0 [S/m].

    Returns
    -------
    ndarray
        τ = μ0 σ d a/3 = μ0 a/(3ξ) [s]: the internal field follows a step of the applied
        field as 1 − e^(−t/τ).

    Notes
    -----
    Kovalenko (1975) eq. (4.24), seed line 87 (p. 86): its denominator 9ξ² + μ0²a²ω² is
    9ξ²(1 + ω²τ²). Not in the sources: τ itself, from the shell's current K = −½σd Ḃ_in × **r**
    and its internal field (2/3)μ0 K.
    """
    a, d, s = _thin_shell(radius, thickness, conductivity)
    return MU_0 * s * d * a / 3.0


@_document_eddy
def spherical_shell_eddy_torque(rate, b, radius, thickness, conductivity):
    r"""Eddy torque on a thin spherical shell spinning in a uniform field, at any frequency.

    Parameters
    ----------
    rate : array_like, shape (..., 3)
        Shell angular velocity **ω**, body axes [rad/s].
    {b, radius, thickness, conductivity}

    Returns
    -------
    ndarray, shape (..., 3)
        **M** = k_в [(**ω** × **B**₀) × **B**₀ − τω² **B**⊥ × **B**₀]/(1 + ω²τ²) [N·m], with
        k_в from :func:`spherical_shell_eddy_coefficient`, τ from
        :func:`spherical_shell_time_constant` and **B**⊥ the part of **B**₀ across **ω**. The
        first term is (4.23) reduced by the shell's self-inductance; the second, a torque
        across both **ω** and **B**₀, comes from the diamagnetic part of the induced moment.

    Notes
    -----
    Kovalenko (1975) eq. (4.24), seed line 87 (p. 86), after Halverson & Cohen (1964).
    Deviation from source: the seed's (4.24) is garbled; this is derived (the shell's internal
    field is B/(1 + iωτ) for a field turning at ω relative to it, and its moment is
    (2πa³/μ0)(B_in − B)), and it has the structure the seed shows: the denominator
    9ξ² + μ0²a²ω² and terms in sin 2α and sin²α. At ωτ → 0 it is :func:`eddy_torque`.
    """
    w = as_vectors("rate", rate)
    bb = as_vectors("b", b)
    k = spherical_shell_eddy_coefficient(radius, thickness, conductivity)
    tau = spherical_shell_time_constant(radius, thickness, conductivity)
    return kernels.spherical_shell_eddy_torque(w, bb, k, tau)


@_document_eddy
def solid_sphere_eddy_coefficient(radius, conductivity):
    r"""Low-frequency eddy coefficient of a solid conducting sphere.

    Parameters
    ----------
    radius : float or array_like
        Sphere radius a > 0 [m].
    {conductivity}

    Returns
    -------
    ndarray
        k = (2π/15) σ a⁵ [N·m·s/T²], valid for a ≪ skin depth √(2/μ0σω).

    Notes
    -----
    Kovalenko (1975) eq. (4.23), seed line 87 (p. 86), gives the form; the book has no solid
    body. Not in the sources: the volume current J = −½σ Ḃ × **r** has the moment
    m = ½∫ **r** × J dV = −(2π/15)σ a⁵ Ḃ (the low-frequency magnetic polarisability of a
    conducting sphere: Landau & Lifshitz, *Electrodynamics of Continuous Media*, §59, problem). A shell of
    thickness d is its derivative with respect to a: (2π/3)σ a⁴ d.
    """
    a = as_positive("radius", radius, unit="m")
    s = as_positive("conductivity", conductivity, unit="S/m")
    return 2.0 * np.pi / 15.0 * s * a ** 5


@_document_eddy
def cylinder_eddy_coefficients(radius, length, thickness, conductivity):
    r"""Low-frequency eddy coefficients of a thin open cylindrical shell (no end caps).

    Parameters
    ----------
    radius : float or array_like
        Cylinder radius r > 0 [m].
    length : float or array_like
        Cylinder length l > 0 [m].
    thickness : float or array_like
        Wall thickness τ > 0, τ ≪ r [m].
    {conductivity}

    Returns
    -------
    transverse : ndarray
        Γ⊥ = π σ τ r³ l [1 − (2r/l) th(l/2r)] [N·m·s/T²], for a field changing across the axis.
    axial : ndarray
        Γ∥ = (π/2) σ τ r³ l [N·m·s/T²], for a field changing along the axis.

    Notes
    -----
    Kovalenko (1975) eqs. (4.25), (4.26), seed lines 87–88 (pp. 86–87), after his ref. [52].
    The book prints them in Gaussian (CGSE) units (seed line 89, p. 88): lengths in cm, H₀ in Oe, torques in
    dyn·cm, c = 3·10¹⁰ cm/s and σ [S/m] × 9·10⁹ [s⁻¹]; the spin-axis torque (4.25) has the
    magnitude Q = π σ_G c⁻² H₀² ω sin α r³ τ l [1 − (2r/l) th(l/2r)]. In SI, with
    σ_G = σ/(4πε0) [s⁻¹], c² = 1/(μ0ε0) and H₀ [Oe] = 10⁴ B₀ [T], the same expression with σ
    in S/m, lengths in m and B₀ in T gives N·m, i.e. Γ⊥ above (the tests check it). Check with σ = 1 S/m, all lengths
    1 m (= 100 cm), ω = 1 rad/s, B₀ = 1 T (= 10⁴ Oe), bracket = 1: Gaussian
    π·8.988·10⁹·(2.998·10¹⁰)⁻²·10⁸·10¹⁰ = π·10⁷ dyn·cm = π N·m, the SI value.

    Deviation from source: the seed's prefactors are partly lost; both coefficients are derived.
    Transverse: the electric field −Ḃ_x y ẑ drives axial currents that close round the open
    ends through the surface charges' potential ψ = C sinh(z/r) sin φ (K_z = 0 at z = ±l/2),
    and the loss per unit Ḃ² integrates to the bracket above (which the seed keeps). Axial:
    the azimuthal current −½σ τ r Ḃ_z needs no return path.
    """
    r = as_positive("radius", radius, unit="m")
    l = as_positive("length", length, unit="m")
    t = as_positive("thickness", thickness, unit="m")
    s = as_positive("conductivity", conductivity, unit="S/m")
    base = np.pi * s * t * r ** 3 * l
    return base * (1.0 - 2.0 * r / l * np.tanh(l / (2.0 * r))), 0.5 * base


@_document_eddy
def eddy_despin_time_constant(inertia, coefficient, mean_square_perpendicular_b):
    r"""Time constant of the exponential spin decay that eddy currents alone cause.

    Parameters
    ----------
    {inertia}
    coefficient : float or array_like
        Eddy coefficient about that axis, k_в > 0 [N·m·s/T²] (for an anisotropic body the
        Γ of the plane across the spin axis averaged over a turn, e.g. ½(Γ⊥ + Γ∥) for a
        cylinder spinning about a transverse axis).
    mean_square_perpendicular_b : float or array_like
        ⟨B₀² sin²α⟩ along the orbit, the mean square of the field across the spin axis, > 0
        [T²] (⅔⟨B²⟩ for a spin axis with no preferred direction; ⟨B²⟩ from
        :func:`magbench.earth.mean_square_field`).

    Returns
    -------
    ndarray
        τ = J/(k_в ⟨B₀² sin²α⟩) [s]; ω(t) = ω(0) e^(−t/τ) while the axis holds its direction.

    Notes
    -----
    Kovalenko (1975) eq. (4.23a), seed line 87 (p. 86): J ω̇ = −k_в B₀² ω sin²α, averaged
    along the orbit; seed line 163 uses the same braking on spin-stabilised craft,
    M = −k* B⊥² ω. Not in the sources: the orbit average (valid when τ is many orbits).
    """
    j = as_positive("inertia", inertia, unit="kg·m²")
    k = as_positive("coefficient", coefficient, unit="N·m·s/T²")
    b2 = as_positive("mean_square_perpendicular_b", mean_square_perpendicular_b, unit="T²")
    return j / (k * b2)


@_document_eddy
def shell_despin_time_constant(inertia, radius, thickness, conductivity, orbit, axis=None):
    r"""Spin-decay time constant of a body wrapped in a thin conducting spherical shell, on orbit.

    Parameters
    ----------
    {inertia, radius, thickness, conductivity}
    orbit : CircularOrbit
        The orbit and its field (:class:`magbench.earth.CircularOrbit`) [-].
    axis : array_like, shape (3,), optional
        Spin axis in inertial axes, held fixed [-]; ``None`` (default) for an axis with no
        preferred direction, ⟨B² sin²α⟩ = (2/3)⟨B²⟩.

    Returns
    -------
    float or ndarray
        τ = J/(k_в⟨B² sin²α⟩) [s], k_в = (2π/3)σ d a⁴; the mean is taken over a day.

    Notes
    -----
    Kovalenko (1975) eqs. (4.23a), (4.24), seed line 87 (p. 86), with
    :func:`spherical_shell_eddy_coefficient` and :func:`eddy_despin_time_constant`; the field
    from :func:`magbench.earth.mean_square_field` or
    :func:`magbench.earth.mean_square_perpendicular_field`. Not in the sources: the orbit
    average. Valid at low frequency (ω τ_shell ≪ 1, :func:`spherical_shell_time_constant`).

    Examples
    --------
    TNS-0's hull radius (0.05 m), aluminium (σ = 3.5·10⁷ S/m, ours) 1 mm thick (ours), its
    transverse inertia 0.0406 kg·m² and orbit (350 km, 51.6°): τ ≈ 1220 days (3.3 years); the Fig. 14
    decay (τ ≈ 640 h matched at session 1) would need a 4.6 cm wall.

    >>> from magbench.earth import CircularOrbit
    >>> orbit = CircularOrbit(6371.0e3 + 350e3, np.radians(51.6), 7.766e22)
    >>> round(float(shell_despin_time_constant(0.0406, 0.05, 1e-3, 3.5e7, orbit)) / 86400, -1)   # days
    1220.0
    """
    from ..earth import mean_square_field, mean_square_perpendicular_field

    k = spherical_shell_eddy_coefficient(radius, thickness, conductivity)
    if axis is None:
        b2 = 2.0 / 3.0 * mean_square_field(orbit)
    else:
        b2 = mean_square_perpendicular_field(orbit, axis)
    return eddy_despin_time_constant(inertia, k, b2)
