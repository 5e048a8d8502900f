r"""Design of hysteresis rods: how many rods a damping torque needs, the loop a rod of finite
elongation describes, and the demagnetising effect of a parallel neighbour.

Kovalenko (1975) §12.2, "Вопросы расчета МИЭ", seed lines 229–240 (pp. 229–240): the body's loop
from the material's (Figs. 12.3–12.4, the demagnetising shear H_p = N_ц B/μ0 and the equal areas,
p. 230), the number of rods n ≥ 2π M_Г.р/(k_φ V (∮H dB)_ц) (p. 235, from (12.1)), and the mutual
demagnetisation of two parallel rods (p. 238–239, Fig. 12.9, E47b in the project's notes). SI: H
in A/m, B in T, loop energies in J/m³, torques in N·m, lengths in m.
"""

import numpy as np

from .._validate import as_finite, as_nonnegative, as_positive, as_positive_scalar, shown
from ..constants import MU_0
from .hysteresis import limb_constants, settled_hysteresis_loop, hysteresis_loop_energy

__all__ = ["rod_volume_required", "rod_count_required", "despin_torque_required", "rod_central_loop_energy",
           "rod_torque_per_length_cubed", "rod_optimal_elongation", "rayleigh_central_loop_energy",
           "rayleigh_optimal_demagnetizing_factor", "prolate_demagnetizing_factor",
           "parallel_rod_mutual_factor", "parallel_rod_demagnetizing_ratio"]


def rod_volume_required(torque, loop_energy, averaging_factor=1.0):
    r"""Total rod volume that yields a required hysteresis damping torque (Kovalenko (12.1) inverted).

    Parameters
    ----------
    torque : float or array_like
        Required mean damping torque M_Г.р ≥ 0 [N·m].
    loop_energy : float or array_like
        (∮H dB)_ц > 0, the loop area at the rods' centre for the field amplitude they see [J/m³]
        (:func:`rod_central_loop_energy` from a material's loop, or a measured body loop).
    averaging_factor : float or array_like, optional
        k_φ > 0, volume-mean over central loop area (≈ 0.72–0.73 for long rods, Kovalenko p. 221;
        1 when ``loop_energy`` is already the whole body's) [-].

    Returns
    -------
    ndarray
        V = 2π M_Г.р/(k_φ (∮H dB)_ц) [m³], the volume of all rods together, each assumed to
        see the full field amplitude (rods uncoupled: :func:`parallel_rod_demagnetizing_ratio`).

    Notes
    -----
    Kovalenko (1975) eq. (12.1), p. 221, M_Г = k_φ V (∮H dB)_ц/2π, solved for V; §12.2, p. 235
    divides it into rods (:func:`rod_count_required`).

    Examples
    --------
    >>> float(rod_volume_required(1e-6, 2.0 * np.pi))
    1e-06
    """
    m = as_nonnegative("torque", torque, unit="N·m")
    w = as_positive("loop_energy", loop_energy, unit="J/m³")
    kf = as_positive("averaging_factor", averaging_factor, unit="[-]")
    return 2.0 * np.pi * m / (kf * w)


def rod_count_required(torque, rod_volume, loop_energy, averaging_factor=1.0):
    r"""Number of equal rods that yields a required hysteresis damping torque (Kovalenko p. 235).

    Parameters
    ----------
    torque : float or array_like
        Required mean damping torque M_Г.р ≥ 0 [N·m].
    rod_volume : float or array_like
        Volume of one rod V > 0 [m³] (for Kovalenko: πd²l/4 at the optimal elongation p0).
    loop_energy : float or array_like
        (∮H dB)_ц > 0 of one rod at the field amplitude it sees [J/m³].
    averaging_factor : float or array_like, optional
        k_φ > 0 [-] (see :func:`rod_volume_required`).

    Returns
    -------
    ndarray of int
        The least whole n ≥ 2π M_Г.р/(k_φ V (∮H dB)_ц) [-] (0 for no torque).

    Notes
    -----
    Kovalenko (1975) §12.2, p. 235 (seed line 235): n ≥ 2π M_Г.р/(k_φ V (∮H dB)_ц max), with
    (∮H dB)_ц max the largest loss over the elongations at the given field and length. The OCR
    shows only "2π M_Г.р" over a garbled denominator; the denominator is (12.1)'s. The rods are
    counted as uncoupled; parallel rods closer than about 0.3–0.4 of their length demagnetise one
    another (p. 240; :func:`parallel_rod_demagnetizing_ratio`).

    Examples
    --------
    >>> int(rod_count_required(3e-6, 1e-6, 2.0 * np.pi))
    3
    >>> int(rod_count_required(3.1e-6, 1e-6, 2.0 * np.pi))
    4
    """
    v = as_positive("rod_volume", rod_volume, unit="m³")
    ratio = rod_volume_required(torque, loop_energy, averaging_factor) / v
    # n = 3 exactly must not become 4 through a rounding of the last bit (3.0000000000000004)
    return np.ceil(ratio * (1.0 - 1e-12)).astype(int)


def despin_torque_required(initial_momentum, despin_time, final_momentum=0.0):
    r"""Constant damping torque that brings an angular momentum down in a given time.

    Parameters
    ----------
    initial_momentum : float or array_like
        |L| at the start, > 0 [kg·m²/s].
    despin_time : float or array_like
        Time allowed, > 0 [s].
    final_momentum : float or array_like, optional
        |L| to reach, in [0, initial_momentum) [kg·m²/s].

    Returns
    -------
    ndarray
        M = (L0 − L1)/T [N·m]: a constant torque against the spin takes L down linearly (the
        straight line of a hysteresis despin, TNS-0 preprint Fig. 14).

    Notes
    -----
    Not in the sources: dL/dt = −M for a torque M opposing L. A spin-decay slope dL/dt read off
    a flight record gives the same torque as M = −dL/dt, the required M_Г.р of Kovalenko §12.2.

    Examples
    --------
    >>> round(float(despin_torque_required(0.09, 9000.0, 0.0)), 12)
    1e-05
    """
    l0 = as_positive("initial_momentum", initial_momentum, unit="kg·m²/s")
    t = as_positive("despin_time", despin_time, unit="s")
    l1 = as_nonnegative("final_momentum", final_momentum, unit="kg·m²/s")
    if np.any(l1 >= l0):
        raise ValueError(f"final_momentum must be below initial_momentum ({shown(np.max(l0))} kg·m²/s), "
                         f"got {shown(np.max(l1))}")
    return (l0 - l1) / t


def rod_central_loop_energy(field_amplitude, demagnetizing_factor, coercivity, remanence, saturation, *,
                            grid_points=160):
    r"""Loop energy at a rod's centre and the field there, from the material's loops (Kovalenko Figs. 12.3–12.4).

    Parameters
    ----------
    field_amplitude : float or array_like
        Amplitude H0 > 0 of the external field along the rod [A/m].
    demagnetizing_factor : float or array_like
        Central demagnetising factor N_ц in [0, 1] of the rod in SI [-] (0: the material's own
        loop; :func:`magbench.hardware.rod_demagnetizing_factor` for a long cylinder); broadcasts
        with ``field_amplitude``.
    coercivity, remanence, saturation : float
        Flatley–Henretty constants of the *material* (not a rod's apparent ones) [A/m, T, T]
        (:func:`magbench.hardware.limb_constants`).
    grid_points : int, optional
        Central amplitudes on which the shear is solved, ≥ 20 [-].

    Returns
    -------
    loop_energy : ndarray
        (∮H dB)_ц [J/m³], the area of the material's settled loop at the central amplitude.
    central_field_amplitude : ndarray
        H_ц [A/m], the amplitude of the field inside the rod's centre: H_ц + N_ц B_ц(H_ц)/μ0 = H0,
        B_ц the tip of the material's loop (its normal magnetisation curve).

    Notes
    -----
    Kovalenko (1975) §12.2, pp. 230–232: the body's loop at the centre is the material's loop
    with every abscissa shifted by H_p = N_ц B/μ0 (the line of shear OA, Fig. 12.3); the areas
    are equal because ∮N_ц (B/μ0) dB = 0, so the body loses at H0 what the material loses at the
    central amplitude H_ц, found where the shear line meets the normal curve (the arrows of
    Fig. 12.4). The book reads the curves of 50Н tape (ЦНИИЧМ, not printed as numbers); here
    the material is a Flatley–Henretty loop (:func:`magbench.hardware.settled_hysteresis_loop`).
    The tips and areas are computed on ``grid_points`` log-spaced central amplitudes down to
    10⁻⁶ of the smallest H0, H_ц is interpolated in log–log there and corrected by one Newton
    step on the exact tip, and the area is then computed at that H_ц itself; the residual of
    H_ц + N_ц B_ц/μ0 − H0 is below 10⁻⁵ H0 with the default grid (tested).

    Examples
    --------
    >>> w, hc = rod_central_loop_energy(30.0, 0.0, 12.0, 0.004, 0.025)
    >>> round(float(w), 3), float(hc)
    (0.217, 30.0)
    """
    h0 = as_positive("field_amplitude", field_amplitude, unit="A/m")
    n = as_nonnegative("demagnetizing_factor", demagnetizing_factor, unit="[-]")
    if np.any(n > 1.0):
        raise ValueError(f"demagnetizing_factor must lie in [0, 1] [-], got {shown(n[n > 1.0].ravel()[0])}")
    h0, n = np.broadcast_arrays(h0, n)
    limb_constants(coercivity, remanence, saturation)
    points = int(as_positive_scalar("grid_points", grid_points))
    if points != grid_points or points < 20:
        raise ValueError(f"grid_points must be a whole number >= 20 [-], got {shown(grid_points)}")
    # The material's loops do not depend on N_ц: one grid of central amplitudes serves every rod.
    grid = np.geomspace(1e-6 * float(np.min(h0)), float(np.max(h0)), points)
    _, b = settled_hysteresis_loop(grid, coercivity, remanence, saturation)
    tip = np.max(b, axis=-1)                           # the normal curve: the loops' vertices
    if np.any(np.diff(tip) <= 0):
        raise ValueError("the material's normal curve is not increasing on the grid; change grid_points")
    central, slope = np.empty(h0.shape), np.empty(h0.shape)
    log_grid = np.log(grid)
    for index in np.ndindex(h0.shape):
        log_external = np.log(grid + n[index] * tip / MU_0)   # H0 at which each central amplitude is reached
        if np.log(h0[index]) < log_external[0]:
            raise ValueError(f"field_amplitude {shown(h0[index])} A/m is below the grid's reach "
                             f"{shown(np.exp(log_external[0]))} A/m (N_ц μ above 10⁶)")
        # log–log: the normal curve is close to a power law over each grid step
        central[index] = np.exp(np.interp(np.log(h0[index]), log_external, log_grid))
        slope[index] = np.interp(np.log(central[index]), log_grid, np.gradient(log_external, log_grid))
    if np.any(n > 0):
        # one Newton step in log–log on the exact tip at the interpolated amplitude
        _, b = settled_hysteresis_loop(central, coercivity, remanence, saturation)
        miss = np.log((central + n * np.max(b, axis=-1) / MU_0) / h0)
        central = central * np.exp(-miss / slope)
    central = np.minimum(central, h0)                  # N_ц = 0: exactly H0 (no rounding above it)
    h, b = settled_hysteresis_loop(central, coercivity, remanence, saturation)
    return hysteresis_loop_energy(h[..., :-1], b[..., :-1]), central


def rod_torque_per_length_cubed(elongation, field_amplitude, coercivity, remanence, saturation,
                                averaging_factor=1.0):
    r"""Hysteresis damping torque of one cylindrical rod over its length cubed (Kovalenko Fig. 12.6).

    Parameters
    ----------
    elongation : float or array_like
        p = l/d ≥ 10 of the rod [-]; broadcasts with ``field_amplitude``.
    field_amplitude : float or array_like
        Amplitude H0 > 0 of the external field along the rod [A/m].
    coercivity, remanence, saturation : float
        Flatley–Henretty constants of the material [A/m, T, T].
    averaging_factor : float, optional
        k_φ > 0 [-] (:func:`rod_volume_required`).

    Returns
    -------
    ndarray
        M_Г/l³ = k_φ (∮H dB)_ц/(8p²) [N·m/m³]: (12.1) with V = πl³/(4p²) and the central loop of
        :func:`rod_central_loop_energy` at N_ц = 0.93 p^−1.7 (9.25).

    Notes
    -----
    Kovalenko (1975) §12.2, pp. 232–233, Figs. 12.5–12.6: at a fixed length a thin rod loses
    little for want of volume, a thick one for its demagnetisation; the torque peaks at an
    optimal elongation p0 that depends on H0 (:func:`rod_optimal_elongation`).
    """
    from .cores import rod_demagnetizing_factor

    p = as_finite("elongation", elongation)
    p, h0 = np.broadcast_arrays(p, as_positive("field_amplitude", field_amplitude, unit="A/m"))
    kf = as_positive_scalar("averaging_factor", averaging_factor)
    w, _ = rod_central_loop_energy(h0, rod_demagnetizing_factor(p), coercivity, remanence, saturation)
    return kf * w / (8.0 * p * p)


def rod_optimal_elongation(field_amplitude, coercivity, remanence, saturation, *, elongations=None):
    r"""Elongation of the largest hysteresis torque of a rod of given length (Kovalenko p. 233).

    Parameters
    ----------
    field_amplitude : float
        Amplitude H0 > 0 of the external field along the rod [A/m].
    coercivity, remanence, saturation : float
        Flatley–Henretty constants of the material [A/m, T, T].
    elongations : array_like, optional
        Candidate p, each ≥ 10, increasing [-]; default 121 log-spaced from 10 to 2000.

    Returns
    -------
    elongation : float
        p0, the candidate of the largest :func:`rod_torque_per_length_cubed` [-].
    torque_per_length_cubed : float
        M_Г/l³ at p0 with k_φ = 1 [N·m/m³].

    Notes
    -----
    Kovalenko (1975) §12.2, p. 233–234: find p0 for the given H0 and length from Figs. 12.5–12.6,
    then the volume of one rod and the count n (:func:`rod_count_required`). A candidate at
    either end of ``elongations`` means the optimum lies outside them: it raises.
    """
    h0 = as_positive_scalar("field_amplitude", field_amplitude, unit="A/m")
    p = np.geomspace(10.0, 2000.0, 121) if elongations is None else as_finite("elongations", elongations)
    if p.ndim != 1 or p.size < 3 or np.any(np.diff(p) <= 0):
        raise ValueError(f"elongations must be an increasing 1-D array of >= 3 values [-], got shape {p.shape}")
    torque = rod_torque_per_length_cubed(p, h0, coercivity, remanence, saturation)
    best = int(np.argmax(torque))
    if best in (0, p.size - 1):
        raise ValueError(f"the optimal elongation lies outside elongations [{shown(p[0])}, {shown(p[-1])}] "
                         f"at H0 = {shown(h0)} A/m (the largest torque is at {shown(p[best])})")
    return float(p[best]), float(torque[best])


def rayleigh_central_loop_energy(field_amplitude, demagnetizing_factor, rayleigh_constant, initial_permeability):
    r"""Loop energy at a rod's centre in the Rayleigh region (Kovalenko (12.40)).

    Parameters
    ----------
    field_amplitude : float or array_like
        Amplitude H0 > 0 of the external field along the rod [A/m].
    demagnetizing_factor : float or array_like
        Central demagnetising factor N_ц ≥ 0 in SI [-].
    rayleigh_constant : float or array_like
        a > 0 of μ = μ_нач + aH, the relative permeability's growth with the field [m/A].
    initial_permeability : float or array_like
        μ_нач > 0, relative [-].

    Returns
    -------
    ndarray
        (∮H dB)_ц = (4/3) μ0 a H_ц³, H_ц = H0/(1 + N_ц μ_нач) [J/m³]: Rayleigh's loop at the
        central amplitude, the permeability taken as μ_нач in the demagnetisation (H_ц ≪ Hc).

    Notes
    -----
    Kovalenko (1975) eq. (12.40), p. 234 [OCR garbled; the project's reconstruction, with μ0 for
    SI]: "(12.40) справедлива для области Рэлея". The loop of B = μ0(μ_нач H + aH²) between ±H_ц
    has the area (4/3) μ0 a H_ц³ (Rayleigh 1887).
    """
    h0 = as_positive("field_amplitude", field_amplitude, unit="A/m")
    n = as_nonnegative("demagnetizing_factor", demagnetizing_factor, unit="[-]")
    a = as_positive("rayleigh_constant", rayleigh_constant, unit="m/A")
    mu = as_positive("initial_permeability", initial_permeability, unit="[-]")
    return 4.0 / 3.0 * MU_0 * a * (h0 / (1.0 + n * mu)) ** 3


def rayleigh_optimal_demagnetizing_factor(initial_permeability, exponent=1.7):
    r"""Central demagnetising factor of the largest Rayleigh-region torque at a fixed rod length.

    Parameters
    ----------
    initial_permeability : float or array_like
        μ_нач > 0, relative [-].
    exponent : float or array_like, optional
        n > 2/3 of N_ц ∝ p^−n (1.7 for Kovalenko's (9.25); ≈ 2 − 1/(ln 2p − 1) for spheroids) [-].

    Returns
    -------
    ndarray
        N_ц.0 = 2/((3n − 2) μ_нач) [-]: at a fixed length V ∝ p^−2, and (12.1) with (12.40) gives
        M_Г ∝ p^−2 (1 + N_ц μ_нач)^−3, largest where N_ц μ_нач = 2/(3n − 2) (0.645 for n = 1.7).

    Notes
    -----
    Not in the sources as such: our derivation from Kovalenko (1975) (12.1), (12.40) and (9.25).
    Deviation from source: his (12.36), p. 233, quoted from his refs. [31, 54, 55], reads
    N_ц.0 = (numerator lost in the OCR)/μ_нач, and his (12.37), 0.167 a H0³ = (4/3)(1/2)³ a H0³,
    fits a numerator of 1 (H_ц = H0/2). At N_ц μ_нач = 1 the torque is 7 % below the optimum of
    n = 1.7.

    Examples
    --------
    >>> round(float(rayleigh_optimal_demagnetizing_factor(1.0)), 3)
    0.645
    """
    mu = as_positive("initial_permeability", initial_permeability, unit="[-]")
    n = as_positive("exponent", exponent, unit="[-]")
    if np.any(n <= 2.0 / 3.0):
        bad = n[n <= 2.0 / 3.0].ravel()[0]
        raise ValueError(f"exponent must be > 2/3 [-] (else the thickest rod wins), got {shown(bad)}")
    return 2.0 / ((3.0 * n - 2.0) * mu)


def prolate_demagnetizing_factor(elongation):
    r"""Exact axial demagnetising factor of a prolate spheroid, in SI.

    Parameters
    ----------
    elongation : float or array_like
        Ratio p = a/b > 1 of the polar to the equatorial semi-axis (= l/d) [-].

    Returns
    -------
    ndarray
        N = (1 − e²)/e³ (artanh e − e), e = (1 − 1/p²)^½ [-]; → (ln 2p − 1)/p² for p ≫ 1.

    Notes
    -----
    Not in the sources: Osborn, Phys. Rev. 67, 351 (1945), eq. (2). Kovalenko (1975) p. 239 uses
    spheroids of p = 300 for the theoretical curve of Fig. 12.9; his (9.24) (Rosenblat) and (9.25)
    (0.93 p^−1.7) are for cylinders (:func:`magbench.hardware.rod_demagnetizing_factor`).

    Examples
    --------
    >>> round(float(prolate_demagnetizing_factor(300.0) * 300.0**2), 3)   # ln 600 − 1 = 5.397
    5.397
    """
    p = as_positive("elongation", elongation)
    if np.any(p <= 1.0):
        raise ValueError(f"elongation must be > 1 [-] (prolate), got {shown(p[p <= 1.0].ravel()[0])}")
    e = np.sqrt(1.0 - 1.0 / p**2)
    return (1.0 - e * e) / e**3 * (np.arctanh(e) - e)


def _line_pair_integral(u):
    r"""J(u) = ∫∫ x y /√(u² + (x − y)²) dx dy over [−1, 1]², in closed form.

    With t = x − y the diagonal's weight is g(t) = 2/3 − |t| + |t|³/6, so
    J = 2∫₀² g(t)/√(u² + t²) dt; each term integrates elementarily.
    """
    r = np.sqrt(u * u + 4.0)
    return 2.0 * (2.0 / 3.0 * np.arcsinh(2.0 / u) - (r - u) + ((r**3 - u**3) / 3.0 - u * u * (r - u)) / 6.0)


def _mutual_factor(separation, length, diameter):
    """Unchecked kernel of :func:`parallel_rod_mutual_factor` (any separation > 0)."""
    a, b = 0.5 * length, 0.5 * diameter
    focal = np.sqrt(a * a - b * b)
    return 0.75 * a * b * b * _line_pair_integral(separation / focal) / focal**3


def _rod_pair(separation, length, diameter):
    s = as_positive("separation", separation, unit="m")
    l = as_positive("length", length, unit="m")
    d = as_positive("diameter", diameter, unit="m")
    s, l, d = np.broadcast_arrays(s, l, d)
    if np.any(l <= d):
        raise ValueError(f"length must exceed diameter (a prolate rod), got length {shown(l[l <= d].ravel()[0])} m "
                         f"and diameter {shown(d[l <= d].ravel()[0])} m")
    if np.any(s < d):
        raise ValueError(f"separation must be >= diameter {shown(d[s < d].ravel()[0])} m (axis to axis; the rods "
                         f"may touch, not overlap), got {shown(s[s < d].ravel()[0])} m")
    return s, l, d


def parallel_rod_mutual_factor(separation, length, diameter):
    r"""Mutual demagnetising factor of two equal parallel spheroidal rods side by side.

    Parameters
    ----------
    separation : float or array_like
        Distance between the rods' axes, ≥ ``diameter`` (touching) [m]; their centres lie on a
        line perpendicular to both axes.
    length : float or array_like
        Rod length l = 2a > diameter [m].
    diameter : float or array_like
        Rod diameter d = 2b [m].

    Returns
    -------
    ndarray
        N_m [-]: the mean field one rod, magnetised M along its axis, makes inside the other is
        −N_m M. N_m = (3/4) a b² J(s/f)/f³, f = (a² − b²)^½, with
        J(u) = ∫∫ x y/√(u² + (x − y)²) dx dy over [−1, 1]² (closed form in the code);
        → V/(4π s³) (two dipoles) for s ≫ l.

    Notes
    -----
    Not in the sources: our derivation, a reconstruction of the theory behind Kovalenko (1975)
    Fig. 12.9 (p. 239), whose formula the OCR garbled. Outside a uniformly magnetised prolate
    spheroid the field is exactly that of a line charge λ = 3m z/(2f³) on its focal segment
    |z| ≤ f (m the moment). The mutual energy of two such lines is μ0 ∫∫ λ₁λ₂/(4πr); the mean
    field over the partner is taken on its axis, exact for slender rods (the field is locally
    two-dimensional and harmonic across the partner, so its mean over a cross-section is the
    value at the centre). Each rod is kept uniformly magnetised (the first-order, energy
    estimate): the neighbour's field is not uniform along the rod.
    """
    s, l, d = _rod_pair(separation, length, diameter)
    return _mutual_factor(s, l, d)


def parallel_rod_demagnetizing_ratio(separation, length, diameter):
    r"""Ratio N_c∞/N_c0 of the demagnetising factor of a rod beside an equal parallel rod to that of the rod alone.

    Parameters
    ----------
    separation : float or array_like
        Distance between the rods' axes, ≥ ``diameter`` [m] (Kovalenko's Δ; his abscissa is
        a = 2Δ/l).
    length : float or array_like
        Rod length l > diameter [m].
    diameter : float or array_like
        Rod diameter d [m].

    Returns
    -------
    ndarray
        1 + N_m/N0 [-], N_m of :func:`parallel_rod_mutual_factor` and N0 of
        :func:`prolate_demagnetizing_factor` at p = l/d: each rod of a soft pair (χ → ∞) takes
        M = H0/(N0 + N_m). → 1 far apart; 1.755 for touching spheroids of p = 300 (the merged
        rod of twice the section, p/√2, gives N(p/√2)/N(p) = 1.872; the text's estimate with
        N ∝ p^−1.7 is (√2)^1.7 = 1.80).

    Notes
    -----
    Kovalenko (1975) §12.2, pp. 238–239, Fig. 12.9 (E47b): measured for mumetal rods 3 mm × 600 mm
    at Δ = 3, 10, 30, 74.5 mm, 1.815, 1.605, 1.325 and 1.15; his theoretical curve is for
    spheroids of p = 300 (l = 600 mm, d = 2 mm), its formula garbled in the OCR. This function
    is our reconstruction (:func:`parallel_rod_mutual_factor`), not the printed formula; Δ is
    read as the distance between axes (at Δ = 3 mm the 3 mm rods touch, and the measured 1.815
    is near the coincident-rod estimate 1.80). For spheroids of the measured rods' p = 200 it
    gives 1.736, 1.502, 1.301, 1.158: within 7 % of the measured points; the pair's effect
    (ratio − 1) is 5–17 % below the measured one at the three closest points and 5 % above at
    74.5 mm.

    Examples
    --------
    >>> round(float(parallel_rod_demagnetizing_ratio(0.0745, 0.6, 0.003)), 3)
    1.158
    """
    s, l, d = _rod_pair(separation, length, diameter)
    return 1.0 + _mutual_factor(s, l, d) / prolate_demagnetizing_factor(l / d)
