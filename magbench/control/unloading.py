r"""Magnetic unloading of reaction wheels: Kovalenko's laws of §5.2.

The wheels of a three-axis stabilised spacecraft store the momentum K that external torques
feed into the body; magnetorquers unload them, since their torque L × B (dipole L, field B)
changes the total momentum. Three laws, each a kernel in :mod:`magbench.control.kernels` and a
checked function here:

* the linear law (5.1), L = k (K × B)/B², whose torque −k K⊥ removes the part of K across B
  only (the stability argument (5.3)–(5.5): d|K|²/dt = −2k|K⊥|² ≤ 0);
* the relay law (5.7), L = k F_K(K) × B, F_K a relay with a dead zone K° (Fig. 5.1a);
* the pulsed law (5.8)–(5.9): one axis at a time, while B has no component along it.
"""

import numpy as np

from .._docstrings import fill_docstring
from .._validate import as_count, as_finite, as_nonnegative, as_vectors, shown
from .field_stabilisation import _nonzero_field as _field
from .kernels import pulsed_unloading_dipole as _pulsed
from .kernels import relay_coil_unloading_dipole as _relay_coil
from .kernels import relay_unloading_dipole as _relay
from .kernels import unloading_dipole as _linear

__all__ = ["unloading_dipole", "unloading_torque", "relay_unloading_dipole", "relay_coil_unloading_dipole",
           "pulsed_unloading_dipole"]


#: Parameters described once for the laws that share them (:func:`magbench._docstrings.fill_docstring`).
_document_unloading = fill_docstring({
    "field": """field : array_like, shape (..., 3)
    B in body axes [T]; must not vanish.""",
    "momentum": """momentum : array_like, shape (..., 3)
    K, body axes [N·m·s].""",
})


@_document_unloading
def unloading_dipole(field, momentum, gain):
    r"""Kovalenko's linear unloading law: L = k (K × B)/B².

    Parameters
    ----------
    {field}
    momentum : array_like, shape (..., 3)
        K, the momentum to remove (the wheels' excess momentum), body axes [N·m·s].
    gain : float or array_like
        k ≥ 0 [1/s]; broadcasts over the leading axes.

    Returns
    -------
    ndarray, shape (..., 3)
        L [A·m²]. Its torque L × B = −k K⊥, K⊥ = K − B(K·B)/B² the part of K across B;
        the part along B cannot be touched.

    Notes
    -----
    Kovalenko (1975) §5.2, eq. (5.1) (seed line 98); with the wheels absorbing nothing else,
    K̇ = L × B gives (5.3) and d|K|²/dt = −2k|K⊥|² ≤ 0 ((5.4)–(5.5)), zero only where K ∥ B.
    Written without B² (k' = k/B²) it is the per-axis form (5.6)/(5.11), Lx = k'(K_y B_z −
    K_z B_y).

    Examples
    --------
    >>> unloading_dipole([0.0, 0.0, 2e-5], [1.0, 0.0, 0.0], 0.01).round(6).tolist()
    [0.0, -500.0, 0.0]
    """
    b = _field(field)
    k = as_nonnegative("gain", gain, unit="1/s")
    return _linear(b, as_vectors("momentum", momentum), k)


@_document_unloading
def unloading_torque(field, momentum, gain):
    r"""The torque L × B of the linear unloading law (5.1): −k K⊥.

    Parameters
    ----------
    {field}
    {momentum}
    gain : float or array_like
        k ≥ 0 [1/s].

    Returns
    -------
    ndarray, shape (..., 3)
        L × B [N·m], perpendicular to B.

    Notes
    -----
    Kovalenko (1975) §5.2, eq. (5.3) (seed line 99): the right-hand side
    −(k/B²)[K B² − B(K·B)].

    Examples
    --------
    >>> unloading_torque([0.0, 0.0, 2e-5], [1.0, 0.0, 3.0], 0.01).round(12).tolist()
    [-0.01, 0.0, 0.0]
    """
    b = _field(field)
    return np.cross(unloading_dipole(b, momentum, gain), b)


@_document_unloading
def relay_unloading_dipole(field, momentum, gain, dead_zone):
    r"""Kovalenko's relay unloading law with a dead zone: L = k F_K(K) × B.

    Parameters
    ----------
    field : array_like, shape (..., 3)
        B in body axes [T].
    {momentum}
    gain : float or array_like
        k ≥ 0 [A·m²/T]; the dipole per unit field of the relay's output.
    dead_zone : float or array_like, shape (3,) or (..., 3)
        K°_i ≥ 0, the relay's threshold per axis [N·m·s].

    Returns
    -------
    ndarray, shape (..., 3)
        L [A·m²]: (k[F(K_y)B_z − F(K_z)B_y], k[F(K_z)B_x − F(K_x)B_z], k[F(K_x)B_y − F(K_y)B_x])
        with F(K_i) = sign K_i where |K_i| > K°_i and 0 inside the dead zone; zero when every
        component lies inside it. Its torque is −k[F B² − B(F·B)], perpendicular to B: the
        linear law acting on the relay's output F rather than on K.

    Notes
    -----
    Kovalenko (1975) §5.2, eq. (5.7) and Fig. 5.1a (seed line 100): the relay function
    without hysteresis; the source warns it can slide near K° (§5.5, seed line 121). The
    source's F_L relay on the coil signal (Fig. 5.2) is not included.

    Examples
    --------
    >>> relay_unloading_dipole([0.0, 0.0, 2e-5], [0.5, 0.05, 0.0], 1e6, 0.1).round(6).tolist()
    [0.0, -20.0, 0.0]
    """
    b = as_vectors("field", field)
    k = as_nonnegative("gain", gain, unit="A·m²/T")
    zone = as_nonnegative("dead_zone", dead_zone, unit="N·m·s")
    if zone.ndim and zone.shape[-1] not in (1, 3):
        raise ValueError(f"dead_zone must be a scalar or have 3 components on its last axis, got shape {zone.shape}")
    return _relay(b, as_vectors("momentum", momentum), k, zone)


@_document_unloading
def pulsed_unloading_dipole(field, momentum, gain, axis, field_threshold):
    r"""Kovalenko's pulsed unloading of one axis while B has no component along it.

    Parameters
    ----------
    {field}
    {momentum}
    gain : float or array_like
        k ≥ 0 [1/s].
    axis : int
        The axis a unloaded, 0 (x), 1 (y) or 2 (z) [-].
    field_threshold : float
        δ ≥ 0: the coils are on while |B_a| ≤ δ [T].

    Returns
    -------
    ndarray, shape (..., 3)
        L = k K_a (e_a × B)/B² while |B_a| ≤ δ, else 0 [A·m²]. At B_a = 0 its torque is
        exactly −k K_a e_a: the axis is unloaded without touching the others.

    Notes
    -----
    Kovalenko (1975) §5.2, eqs. (5.8)–(5.9) (seed line 101): at B_x = 0, (5.6) leaves
    L_y = −k' K_x B_z, L_z = k' K_x B_y, and with the x coil off the torque is (5.9),
    M_x = −k' K_x (B_y² + B_z²), M_y = M_z = 0: independent control about x. This is that law
    for any axis a, with k' = k/B² (the form of (5.1)) so that the torque is −k K_a e_a; away
    from B_a = 0 it is switched off (|B_a| > δ). Chapter 9's check ``kov-pulsed-torque-59``
    evaluates (5.9) against it.

    Examples
    --------
    >>> pulsed_unloading_dipole([0.0, 0.0, 2e-5], [1.0, 0.0, 0.0], 0.01, 0, 1e-6).round(6).tolist()
    [0.0, -500.0, 0.0]
    """
    b = _field(field)
    k = as_nonnegative("gain", gain, unit="1/s")
    a = as_count("axis", axis, minimum=0)
    if a > 2:
        raise ValueError(f"axis must be 0, 1 or 2, got {shown(axis)}")
    delta = as_nonnegative("field_threshold", field_threshold, unit="T")
    if delta.ndim:
        raise ValueError(f"field_threshold must be a scalar [T], got shape {delta.shape}")
    return _pulsed(b, as_vectors("momentum", momentum), k, a, float(delta))


@_document_unloading
def relay_coil_unloading_dipole(field, momentum, moment, dead_zone, signal_dead_zone):
    r"""Kovalenko's relay law with relay coils: L_i = L0 F_L(δ_i), δ = F_K(K) × B.

    Parameters
    ----------
    field : array_like, shape (..., 3)
        B in body axes [T].
    {momentum}
    moment : float or array_like
        L0 ≥ 0, the dipole of a switched-on coil [A·m²].
    dead_zone : float or array_like, shape (3,) or (..., 3)
        K°_i ≥ 0, the momentum relay's threshold per axis [N·m·s].
    signal_dead_zone : float
        δ0 ≥ 0, the coil relay's threshold on the signal δ_i [T].

    Returns
    -------
    ndarray, shape (..., 3)
        L [A·m²], each component −L0, 0 or +L0: δ_x = F(K_y)B_z − F(K_z)B_y (and cyclic), F
        and F_L sign functions with dead zones.

    Notes
    -----
    Kovalenko (1975) §5.2 eq. (5.7) with the relay output F_L of Fig. 5.2 (seed lines
    100, 106: "the signal ... is passed through a logic circuit with the characteristic of
    Fig. 5.1, after which the dipole takes the characteristic of Fig. 5.2"); the §5.5
    runs (seed lines 122–124) use δ0 = 5·10⁻⁶ and 1.25·10⁻⁶ T. Reconstructed: the figures
    are not in the seed; the relays are taken without hysteresis and without the coil's
    residual dipole k_B L0 of Fig. 5.2 (the simulation adds a residual dipole separately).

    Examples
    --------
    >>> relay_coil_unloading_dipole([0.0, 0.0, 2e-5], [0.5, 0.05, 0.0], 50.0, 0.1, 5e-6).tolist()
    [0.0, -50.0, 0.0]
    """
    b = as_vectors("field", field)
    moment = as_nonnegative("moment", moment, unit="A·m²")
    zone = as_nonnegative("dead_zone", dead_zone, unit="N·m·s")
    if zone.ndim and zone.shape[-1] not in (1, 3):
        raise ValueError(f"dead_zone must be a scalar or have 3 components on its last axis, got shape {zone.shape}")
    delta = as_nonnegative("signal_dead_zone", signal_dead_zone, unit="T")
    if delta.ndim:
        raise ValueError(f"signal_dead_zone must be a scalar [T], got shape {delta.shape}")
    return _relay_coil(b, as_vectors("momentum", momentum), moment, zone, float(delta))
