r"""Rotational dynamics: the exchange of angular momentum and energy with the Earth.

Thesis §1.3 (eqs. 9–12). The mock-up's equations of motion (§4) will join this module.
"""

import numpy as np

from ._validate import as_finite, as_positive

__all__ = ["momentum_exchange_energy_ratio", "thesis_energy_ratio", "two_coil_torque"]


def momentum_exchange_energy_ratio(spacecraft_inertia, spacecraft_rate, rate_change,
                                   earth_inertia, earth_rate):
    r"""Kinetic energy the Earth gains per unit the spacecraft loses, when magnetic
    torques trade angular momentum between them.

    Parameters
    ----------
    spacecraft_inertia : array_like
        Spacecraft moment of inertia J_c [kg·m²].
    spacecraft_rate : array_like
        Spacecraft rate ω_c before the exchange [rad/s].
    rate_change : array_like
        Change Δω_c of the spacecraft rate [rad/s] (non-zero).
    earth_inertia : array_like
        Earth's moment of inertia J_E about the exchange axis [kg·m²].
    earth_rate : array_like
        Earth's rate ω_E about that axis [rad/s].

    Returns
    -------
    ndarray
        ΔT_E / ΔT_c [-], exact for the momentum balance of eq. (12),
        J_c Δω_c + J_E Δω_E = 0. Negative when the spacecraft's loss is the
        Earth's gain (spins in the same sense); the thesis compares magnitudes.

    Notes
    -----
    Thesis eqs. (11)–(12), seed lines 186–196.

    Deviation from source: the thesis concludes ΔT_E/ΔT_c ≈ |Δω_E/Δω_c| = J_c/J_E by
    treating Δ(ω²) as (Δω)². With ΔK_E = −ΔK_c the exact ratio is
    −(2ω_E + Δω_E)/(2ω_c + Δω_c), i.e. ≈ −ω_E/ω̄_c for a rotating Earth: far larger
    than J_c/J_E, yet still ≪ 1 whenever the spacecraft turns much faster than the
    Earth, so the thesis's conclusion stands.

    Examples
    --------
    >>> r = momentum_exchange_energy_ratio(0.005, 0.1, -0.1, 8.0e37, 7.292115e-5)
    >>> round(abs(float(r)), 6)   # ≈ ω_E / (ω_c / 2): despinning from 0.1 rad/s
    0.001458
    """
    jc = as_positive("spacecraft_inertia", spacecraft_inertia, unit="kg·m²")
    wc = as_finite("spacecraft_rate", spacecraft_rate)
    dwc = as_finite("rate_change", rate_change)
    if np.any(dwc == 0):
        raise ValueError("rate_change must be non-zero: no exchange, no energy ratio")
    je = as_positive("earth_inertia", earth_inertia, unit="kg·m²")
    we = as_finite("earth_rate", earth_rate)
    dwe = -jc * dwc / je
    d_te = 0.5 * je * dwe * (2.0 * we + dwe)
    d_tc = 0.5 * jc * dwc * (2.0 * wc + dwc)
    if np.any(d_tc == 0):
        raise ValueError("spacecraft_rate and rate_change leave the spacecraft's energy unchanged "
                         "(ω_c → −ω_c); the ratio is undefined")
    return d_te / d_tc


def thesis_energy_ratio(spacecraft_inertia, earth_inertia):
    r"""The thesis's estimate ΔT_E/ΔT_c = J_c/J_E.

    Parameters
    ----------
    spacecraft_inertia : array_like
        Spacecraft moment of inertia J_c [kg·m²].
    earth_inertia : array_like
        Earth's moment of inertia J_E [kg·m²].

    Returns
    -------
    ndarray
        J_c / J_E [-].

    Notes
    -----
    Thesis eq. (12a), seed line 196, kept to show the size of its error beside
    :func:`momentum_exchange_energy_ratio`.
    """
    return (as_positive("spacecraft_inertia", spacecraft_inertia, unit="kg·m²")
            / as_positive("earth_inertia", earth_inertia, unit="kg·m²"))


def two_coil_torque(psi, moment_1, moment_2, field):
    r"""Torque about the vertical on the mock-up's two horizontal, orthogonal coils.

    Parameters
    ----------
    psi : array_like
        Angle ψ from the horizontal field to coil 1's dipole axis [rad].
    moment_1, moment_2 : array_like
        Dipole moments of coil 1 (along x') and coil 2 (along y') [A·m²].
    field : array_like
        Horizontal field magnitude B0 [T].

    Returns
    -------
    ndarray
        :math:`\tau_z = -B_0\,(m_1 \sin\psi + m_2 \cos\psi)` [N·m].

    Notes
    -----
    Thesis eq. (36), seed lines 508–512 (the right-hand side of J ω̇ = τ_z); with
    m₂ = 0 it is the restoring torque of eqs. (34)–(35). No argument checks: this is the
    inner kernel of simulations that check their inputs once.

    Examples
    --------
    >>> float(two_coil_torque(0.5 * np.pi, 0.4, 0.0, 1e-4))
    -4e-05
    """
    return -field * (moment_1 * np.sin(psi) + moment_2 * np.cos(psi))
