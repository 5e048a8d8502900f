r"""The exchange of angular momentum and energy between a spacecraft and the Earth.

Thesis §1.3, eqs. (9)–(12): momentum is exchanged one for one; the energy the Earth
takes is ω_E ΔK_E, not ½ J_E Δω_E². SI.
"""

import numpy as np

from .._validate import as_finite, as_positive

__all__ = ["momentum_exchange_energy_ratio", "thesis_energy_ratio"]


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
    Thesis eqs. (11)–(12).

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
    Thesis eq. (12a), kept to show the size of its error beside
    :func:`momentum_exchange_energy_ratio`.
    """
    return (as_positive("spacecraft_inertia", spacecraft_inertia, unit="kg·m²")
            / as_positive("earth_inertia", earth_inertia, unit="kg·m²"))
