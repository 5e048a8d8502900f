r"""Hysteresis rods: the Flatley–Henretty loop model, its energy identities, Kovalenko's damping torque.

Kovalenko (1975) ch. 12 (§12.1, eq. (12.1), p. 221: the mean damping torque of a rod turning in
the Earth's field; p. 229: the Transit rods) and the TNS-0 preprint §3 (L392: two rods along
orthogonal directions in the equatorial plane). The rod model itself is not in the sources:
Flatley & Henretty, NASA CP-3299 (1995), as used by Gerhardt & Palo (SSC10, 2010). SI: H in
A/m, B in T, energies in J/m³.

The limbs of the limiting loop are B±(H) = (2Bs/π) arctan[k(H ∓ Hc)], k = tan(πBr/2Bs)/Hc;
a state between them moves toward the limb ahead with the slope

.. math::
   \frac{dB}{dH} = \frac{2B_s}{\pi}\,k\cos^2\!\frac{\pi B}{2B_s}
   \left(\frac{H - H_{from}(B)}{2H_c}\right)^2,\qquad
   H_{from} = \frac{\tan(\pi B/2B_s)}{k} - \operatorname{sgn}(\dot H)\,H_c,

H_from being the field on the limb the state comes from; on a limb the slope is the limb's.
"""

import numpy as np

from ..integrate import rk4_step
from . import kernels
from .._docstrings import fill_docstring
from .._validate import as_count, as_finite, as_nonnegative, as_positive, as_positive_scalar, shown

__all__ = ["limb_constants", "limb_induction", "hysteresis_slope", "hysteresis_response", "hysteresis_loop_energy",
           "rod_cycle_energy", "settled_hysteresis_loop", "limiting_loop_energy", "hysteresis_damping_torque"]

#: The rod's loop and the sinusoidal field, described once for every function that takes them
#: (each checks the loop through :func:`limb_constants`).
_ROD_PARAMETERS = {
    "coercivity": """coercivity : float
    Coercive field Hc, > 0 [A/m].""",
    "remanence": """remanence : float
    Remanent induction Br, 0 < Br < Bs [T].""",
    "saturation": """saturation : float
    Saturation induction Bs, > 0 [T].""",
    "field_amplitude": """field_amplitude : float or array_like
    Amplitude Ha of H = bias + Ha sin φ, > 0 [A/m].""",
    "bias": """bias : float or array_like, optional
    Constant part of the field [A/m]; broadcasts with ``field_amplitude``.""",
}
_document_rod = fill_docstring(_ROD_PARAMETERS)


@_document_rod
def limb_constants(coercivity, remanence, saturation):
    r"""The checked constants of a rod's limiting loop.

    Parameters
    ----------
    {coercivity, remanence, saturation}

    Returns
    -------
    tuple of float
        (Hc [A/m], Br [T], Bs [T], k [m/A]), k = tan(πBr/2Bs)/Hc the limbs' shape factor.

    Notes
    -----
    Not in the sources: Flatley & Henretty, NASA CP-3299 (1995); the limbs are
    B±(H) = (2Bs/π) arctan[k(H ∓ Hc)] (:func:`limb_induction`).

    Examples
    --------
    >>> hc, br, bs, k = limb_constants(12.0, 0.35, 0.7)
    >>> float(round(k * hc, 12))
    1.0
    """
    hc = as_positive_scalar("coercivity", coercivity, unit="A/m")
    bs = as_positive_scalar("saturation", saturation, unit="T")
    br = as_positive_scalar("remanence", remanence, unit="T")
    if br >= bs:
        raise ValueError(f"remanence must be below saturation ({shown(bs)} T), got {shown(br)} T")
    return hc, br, bs, np.tan(0.5 * np.pi * br / bs) / hc


@_document_rod
def limb_induction(field, coercivity, remanence, saturation, *, ascending=True):
    r"""Induction on a limb of the limiting (major) loop.

    Parameters
    ----------
    field : float or array_like
        Field strength H along the rod [A/m].
    {coercivity, remanence, saturation}
    ascending : bool, optional
        The ascending limb B+ (H increasing) or the descending limb B− [-].

    Returns
    -------
    ndarray
        B±(H) = (2Bs/π) arctan[k(H ∓ Hc)] [T], k = tan(πBr/2Bs)/Hc.

    Notes
    -----
    Not in the sources: Flatley & Henretty (1995), eq. for the limiting loop; B+(0) = −Br,
    B+(Hc) = 0.
    """
    h = as_finite("field", field)
    hc, _, bs, k = limb_constants(coercivity, remanence, saturation)
    shift = hc if ascending else -hc
    return 2.0 * bs / np.pi * np.arctan(k * (h - shift))


def _slope_along_h(h, b, direction, hc, bs, k):
    """dB/dH with H first, as an integrator takes a right-hand side."""
    return kernels.hysteresis_slope(b, h, direction, hc, bs, k)


@_document_rod
def hysteresis_slope(induction, field, field_rate, coercivity, remanence, saturation):
    r"""Slope dB/dH of the Flatley–Henretty state equation, and the induction rate.

    Parameters
    ----------
    induction : array_like
        Rod induction B, |B| < Bs [T].
    field : array_like
        Field strength H along the rod [A/m]; broadcasts with ``induction``.
    field_rate : array_like
        dH/dt along the rod [A/(m·s)]; its sign chooses the limb the state comes from.
    {coercivity, remanence, saturation}

    Returns
    -------
    slope : ndarray
        dB/dH [T·m/A].
    induction_rate : ndarray
        dB/dt = (dB/dH)·dH/dt [T/s].

    Notes
    -----
    Not in the sources: Flatley & Henretty (1995); Gerhardt & Palo (2010) eq. (3). The
    limbs (:func:`limb_induction`) are invariant: a state on the limb ahead follows it.
    """
    b = as_finite("induction", induction)
    h = as_finite("field", field)
    rate = as_finite("field_rate", field_rate)
    hc, _, bs, k = limb_constants(coercivity, remanence, saturation)
    if np.any(np.abs(b) >= bs):
        raise ValueError(f"induction must lie in (-{shown(bs)}, {shown(bs)}) T (below saturation), got "
                         f"{shown(b[np.abs(b) >= bs].ravel()[0])}")
    slope = kernels.hysteresis_slope(b, h, np.sign(rate), hc, bs, k)
    return slope, slope * rate


@_document_rod
def hysteresis_response(field, coercivity, remanence, saturation, *, initial_induction=0.0):
    r"""Induction along a sampled field path, by the Flatley–Henretty state equation.

    Parameters
    ----------
    field : array_like, shape (..., n)
        Field strength H along the rod at n ≥ 2 samples, the path trailing; leading axes are
        independent paths [A/m].
    {coercivity, remanence, saturation}
    initial_induction : float or array_like, optional
        B at the first sample, |B| < Bs; broadcasts with the leading axes [T].

    Returns
    -------
    ndarray, shape (..., n)
        B [T] at every sample; H varies linearly between samples (RK4 in H, sub-steps of at
        most Hc/50).

    Notes
    -----
    Not in the sources: Flatley & Henretty (1995). The loop a rod describes in a rotating
    uniform field is the Warburg loop of Kovalenko (1975) §12.1, p. 220.

    Examples
    --------
    >>> h = 100.0 * np.sin(np.linspace(0.0, 4.0 * np.pi, 801))
    >>> b = hysteresis_response(h, 12.0, 0.004, 0.025)
    >>> bool(abs(b[-1]) < 0.025)
    True
    """
    h = as_finite("field", field)
    if h.ndim == 0 or h.shape[-1] < 2:
        raise ValueError(f"field must have n >= 2 samples on its trailing axis [A/m], got shape {h.shape}")
    hc, _, bs, k = limb_constants(coercivity, remanence, saturation)
    b0 = as_finite("initial_induction", initial_induction)
    if np.any(np.abs(b0) >= bs):
        raise ValueError(f"initial_induction must lie in (-{shown(bs)}, {shown(bs)}) T, got {shown(b0.ravel()[0])}")
    b = np.empty(h.shape)
    b[..., 0] = np.broadcast_to(b0, h.shape[:-1])
    for j in range(h.shape[-1] - 1):
        start, stop = h[..., j], h[..., j + 1]
        delta = stop - start
        direction = np.sign(delta)
        n = max(1, int(np.ceil(np.max(np.abs(delta)) / (hc / 50.0))))
        dh = delta / n
        state = b[..., j]
        for s in range(n):
            # the library's RK4 step with H as the independent variable
            state = rk4_step(_slope_along_h, start + s * dh, state, dh, args=(direction, hc, bs, k))
        b[..., j + 1] = state
    return b


def hysteresis_loop_energy(field, induction):
    r"""Work ∮H dB per unit volume around a sampled loop.

    Parameters
    ----------
    field : array_like, shape (..., n)
        Field strength H along the loop [A/m].
    induction : array_like, shape (..., n)
        Induction B along the loop, same samples [T].

    Returns
    -------
    ndarray
        ∮H dB [J/m³] by the trapezoid rule, closing the path from the last sample to the
        first; positive for a dissipative loop (traversed anticlockwise in the H–B plane).

    Notes
    -----
    Kovalenko (1975) §12.1, p. 220 (Warburg's law: the energy lost per cycle in a volume dV
    is dV ∮H dB).

    Examples
    --------
    >>> t = np.linspace(0.0, 2.0 * np.pi, 2001)[:-1]
    >>> round(float(hysteresis_loop_energy(np.cos(t), np.sin(t))), 6)   # area π of a unit round loop
    3.141587
    """
    h = as_finite("field", field)
    b = as_finite("induction", induction)
    if h.shape != b.shape or h.ndim == 0 or h.shape[-1] < 3:
        raise ValueError(f"field and induction must have one shape (..., n >= 3), got {h.shape} and {b.shape}")
    h_next, b_next = np.roll(h, -1, axis=-1), np.roll(b, -1, axis=-1)
    return np.sum(0.5 * (h + h_next) * (b_next - b), axis=-1)


@_document_rod
def rod_cycle_energy(field_amplitude, coercivity, remanence, saturation, *, bias=0.0):
    r"""Energy dissipated per unit volume per cycle of a sinusoidal field, settled loop.

    Parameters
    ----------
    {field_amplitude, coercivity, remanence, saturation, bias}

    Returns
    -------
    ndarray
        ∮H dB [J/m³] over the third cycle, started demagnetised (see
        :func:`settled_hysteresis_loop` for how closed that cycle is).

    Notes
    -----
    Not in the sources: Flatley & Henretty (1995) for the loop; the energy is Warburg's
    ∮H dB (Kovalenko (1975) §12.1, p. 220). Limits: → :func:`limiting_loop_energy` for
    Ha ≫ Hc (→ 4 Bs Hc), ∝ Ha³ for Ha ≪ Hc (the Rayleigh law, Kovalenko (1975) eq. (12.40)).

    Examples
    --------
    >>> round(float(rod_cycle_energy(30.0, 12.0, 0.004, 0.025)), 3)
    0.217
    """
    h, b = settled_hysteresis_loop(field_amplitude, coercivity, remanence, saturation, bias=bias)
    return hysteresis_loop_energy(h[..., :-1], b[..., :-1])


@_document_rod
def settled_hysteresis_loop(field_amplitude, coercivity, remanence, saturation, *, bias=0.0, samples=720):
    r"""The settled Flatley–Henretty loop of a sinusoidal field: the third cycle, started demagnetised.

    Parameters
    ----------
    {field_amplitude, coercivity, remanence, saturation, bias}
    samples : int, optional
        Samples per cycle, >= 4 [-].

    Returns
    -------
    field, induction : ndarray, shape (..., samples + 1)
        H [A/m] and B [T] over the third cycle, φ from 4π to 6π, the closing point included.

    Notes
    -----
    Not in the sources: Flatley & Henretty (1995) for the loop (Kovalenko (1975) §12.1, p. 220,
    for the loop as the rods' loss per cycle). Well above Hc the first cycle settles it; near and
    below Hc the loop still creeps. For TNS-0's rods (Hc 12 A/m, Br 4 mT, Bs 25 mT) the third
    cycle's ends differ by 2e-17 T at 200 A/m, 1.5e-9 T at 30 A/m and 1.6e-5 T at 6 A/m.
    """
    ha = as_positive("field_amplitude", field_amplitude, unit="A/m")
    bias = as_finite("bias", bias)
    samples = as_count("samples", samples, minimum=4)
    ha, bias = np.broadcast_arrays(ha, bias)
    phase = np.linspace(0.0, 3.0 * 2.0 * np.pi, 3 * samples + 1)
    h = bias[..., None] + ha[..., None] * np.sin(phase)
    b = hysteresis_response(h, coercivity, remanence, saturation)
    last = slice(2 * samples, 3 * samples + 1)
    return h[..., last], b[..., last]


def _primitive(x):
    return x * np.arctan(x) - 0.5 * np.log1p(x * x)


@_document_rod
def limiting_loop_energy(field_amplitude, coercivity, remanence, saturation):
    r"""Area between the limbs of the limiting loop over |H| ≤ Ha, in closed form.

    Parameters
    ----------
    field_amplitude : float or array_like
        Ha, > 0 [A/m].
    {coercivity, remanence, saturation}

    Returns
    -------
    ndarray
        ∫ (B− − B+) dH over [−Ha, Ha] = (4Bs/πk)[F(k(Ha + Hc)) − F(k(Ha − Hc))] [J/m³],
        F(x) = x arctan x − ½ ln(1 + x²); → 4 Bs Hc as Ha → ∞.

    Notes
    -----
    Not in the sources: the integral of the Flatley & Henretty (1995) limbs; the large-amplitude
    limit of :func:`rod_cycle_energy`.

    Examples
    --------
    >>> round(float(limiting_loop_energy(1e7, 12.0, 0.004, 0.025) / (4 * 0.025 * 12.0)), 4)
    1.0
    """
    ha = as_positive("field_amplitude", field_amplitude, unit="A/m")
    hc, _, bs, k = limb_constants(coercivity, remanence, saturation)
    return 4.0 * bs / (np.pi * k) * (_primitive(k * (ha + hc)) - _primitive(k * (ha - hc)))


def hysteresis_damping_torque(volume, loop_energy, averaging_factor=1.0):
    r"""Mean damping torque of a hysteresis rod turning uniformly in a field (Kovalenko 12.1).

    Parameters
    ----------
    volume : float or array_like
        Rod volume V, ≥ 0 [m³].
    loop_energy : float or array_like
        (∮H dB)_ц, the loop area at the rod's centre for the field amplitude it sees [J/m³].
    averaging_factor : float or array_like, optional
        k_φ, the ratio of the volume-mean loop area to the central one (≈ 0.72–0.73 for long
        rods, Kovalenko p. 221; 1 for a rod model that is already the whole body's) [-].

    Returns
    -------
    ndarray
        M_Г = k_φ V (∮H dB)_ц / (2π) [N·m]: the energy lost per revolution over 2π.

    Notes
    -----
    Kovalenko (1975) eq. (12.1), p. 221. The Transit rods (p. 229): 450 G·Oe ≈ 3.6 J/m³ at
    H0 = 0.3 Oe ≈ 24 A/m.

    Examples
    --------
    >>> round(float(hysteresis_damping_torque(1e-6, 2.0 * np.pi)), 12)
    1e-06
    """
    v = as_nonnegative("volume", volume, unit="m³")
    w = as_nonnegative("loop_energy", loop_energy, unit="J/m³")
    kf = as_positive("averaging_factor", averaging_factor, unit="[-]")
    return kf * v * w / (2.0 * np.pi)
