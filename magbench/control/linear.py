r"""Linear analysis of the mock-up's PID loop: characteristic polynomial, poles, transfer
functions and state space, the Routh–Hurwitz limit on the integral gain, ultimate gains.

Thesis §4.1, eqs. (36)–(38) linearised; python-control is the peer in the tests. SI.
"""

import numpy as np

from .._docstrings import fill_docstring
from .._validate import as_finite, as_positive

__all__ = ["closed_loop_polynomial", "closed_loop_poles", "open_loop_transfer", "closed_loop_transfer",
           "closed_loop_state_space", "integral_gain_limit", "critical_gain_scale", "double_integrator_ultimate_gain"]


#: The linearised loop's inputs, described once (thesis eqs. (36)-(38)).
_LOOP_PARAMETERS = {
    "inertia": """
        inertia : float
            J [kg·m²], > 0.""",
    "field": """
        field : float
            B0 [T], > 0.""",
    "gains": """
        kp, ki, kd : float
            Gains [A·m²/rad], [A·m²/(rad·s)], [A·m²·s/rad].""",
}
_document_loop = fill_docstring(_LOOP_PARAMETERS)


def _checked_loop(inertia, field, kp, ki, kd):
    """(J, B0, K_p, K_i, K_d) as floats, checked: J, B0 > 0, the gains finite."""
    j = float(as_positive("inertia", inertia, unit="kg·m²"))
    b = float(as_positive("field", field, unit="T"))
    kp, ki, kd = (float(as_finite(n, v)) for n, v in (("kp", kp), ("ki", ki), ("kd", kd)))
    return j, b, kp, ki, kd


@_document_loop
def closed_loop_polynomial(inertia, field, kp, ki, kd):
    r"""Characteristic polynomial of the linearised closed loop.

    Parameters
    ----------
    {inertia, field, gains}

    Returns
    -------
    ndarray, shape (4,)
        Coefficients of :math:`J s^3 + B_0 K_d s^2 + B_0 K_p s + B_0 K_i` (highest first).

    Notes
    -----
    Thesis eqs. (36)–(38) linearised about ψ = ψ_des with exact allocation and no
    saturation: the plant is a pure double integrator :math:`B_0/(J s^2)`; the thesis
    does not linearise its loop.

    Examples
    --------
    >>> closed_loop_polynomial(0.005, 1e-4, 0.1, 0.5, 0.5)
    array([5.e-03, 5.e-05, 1.e-05, 5.e-05])
    """
    j, b, kp, ki, kd = _checked_loop(inertia, field, kp, ki, kd)
    return np.array([j, b * kd, b * kp, b * ki])


@_document_loop
def closed_loop_poles(inertia, field, kp, ki, kd):
    r"""Poles of the linearised closed loop.

    Parameters
    ----------
    {inertia, field, gains}

    Returns
    -------
    ndarray, shape (3,)
        Roots of :func:`closed_loop_polynomial` [1/s], sorted by real part (most
        unstable first).

    Notes
    -----
    Thesis eqs. (36)–(38) linearised as in :func:`closed_loop_polynomial`; the thesis
    does not analyse its loop's poles.

    Examples
    --------
    >>> p = closed_loop_poles(0.005, 3.14e-4, 0.1, 0.5, 0.5)   # a printed gain set, in SI
    >>> round(float(p[0].real), 3), round(float(p[2].real), 3)     # unstable pair, stable real pole
    (0.144, -0.319)
    """
    roots = np.roots(closed_loop_polynomial(inertia, field, kp, ki, kd))
    return roots[np.argsort(-roots.real, kind="stable")]


@_document_loop
def open_loop_transfer(inertia, field, kp, ki, kd):
    r"""Numerator and denominator of the loop transfer function, the PID times the plant.

    Parameters
    ----------
    {inertia, field, gains}

    Returns
    -------
    numerator, denominator : ndarray
        Coefficients, highest power first, of
        :math:`L(s) = B_0(K_d s^2 + K_p s + K_i)/(J s^3)` [-]: the PID
        :math:`C(s) = K_p + K_i/s + K_d s` on the double integrator :math:`B_0/(J s^2)`.
        A common factor k on the gains is the root locus's gain.

    Notes
    -----
    Thesis eqs. (36)–(38) linearised as in :func:`closed_loop_polynomial` (not in the
    thesis, which does not linearise its loop).

    Examples
    --------
    >>> open_loop_transfer(0.005, 1e-4, 0.1, 0.5, 0.5)
    (array([5.e-05, 1.e-05, 5.e-05]), array([0.005, 0.   , 0.   , 0.   ]))
    """
    j, b, kp, ki, kd = _checked_loop(inertia, field, kp, ki, kd)
    return b * np.array([kd, kp, ki]), np.array([j, 0.0, 0.0, 0.0])


@_document_loop
def closed_loop_transfer(inertia, field, kp, ki, kd):
    r"""Numerator and denominator of the closed loop from the target ψ_des to ψ.

    Parameters
    ----------
    {inertia, field, gains}

    Returns
    -------
    numerator, denominator : ndarray
        Coefficients, highest power first, of :math:`B_0(K_p s + K_i)` and of
        :func:`closed_loop_polynomial` [-]: the derivative acts on the measured rate
        (u = K_p e + K_i ∫e − K_d ω, as the loop runs), so it adds no zero.

    Notes
    -----
    Thesis eqs. (36)–(38) linearised as in :func:`closed_loop_polynomial` (not in the thesis).

    Examples
    --------
    >>> closed_loop_transfer(0.005, 1e-4, 0.1, 0.5, 0.5)[0]
    array([1.e-05, 5.e-05])
    """
    j, b, kp, ki, kd = _checked_loop(inertia, field, kp, ki, kd)
    return b * np.array([kp, ki]), closed_loop_polynomial(j, b, kp, ki, kd)


@_document_loop
def closed_loop_state_space(inertia, field, kp, ki, kd):
    r"""State and output matrices of the linearised closed loop about ψ_des = 0.

    Parameters
    ----------
    {inertia, field, gains}

    Returns
    -------
    a : ndarray, shape (3, 3)
        :math:`\dot x = A x` for the states x = (ψ [rad], ω [rad/s], ∫e dt [rad·s]) with
        e = −ψ: rows (0, 1, 0), (−B0K_p/J, −B0K_d/J, B0K_i/J), (−1, 0, 0) [SI].
    c : ndarray, shape (1, 3)
        The PID output u = C x = −K_p ψ − K_d ω + K_i ∫e [A·m²]: (−K_p, −K_d, K_i).

    Notes
    -----
    Thesis eqs. (36)–(38) linearised as in :func:`closed_loop_polynomial` (not in the
    thesis); the eigenvalues of A are :func:`closed_loop_poles`.

    Examples
    --------
    >>> a, c = closed_loop_state_space(0.005, 1e-4, 0.1, 0.5, 0.5)
    >>> bool(np.allclose(np.sort_complex(np.linalg.eigvals(a)),
    ...                  np.sort_complex(closed_loop_poles(0.005, 1e-4, 0.1, 0.5, 0.5))))
    True
    """
    j, b, kp, ki, kd = _checked_loop(inertia, field, kp, ki, kd)
    a = np.array([[0.0, 1.0, 0.0], [-b * kp / j, -b * kd / j, b * ki / j], [-1.0, 0.0, 0.0]])
    return a, np.array([[-kp, -kd, ki]])


def integral_gain_limit(inertia, field, kp, kd):
    r"""Largest integral gain for which the linearised loop is stable (Routh–Hurwitz).

    Parameters
    ----------
    inertia : array_like
        J [kg·m²], > 0.
    field : array_like
        B0 [T], > 0.
    kp, kd : array_like
        Proportional [A·m²/rad] and derivative [A·m²·s/rad] gains, > 0.

    Returns
    -------
    ndarray
        :math:`K_{i,max} = B_0 K_p K_d / J` [A·m²/(rad·s)]: the cubic
        :math:`J s^3 + B_0K_d s^2 + B_0K_p s + B_0K_i` is Hurwitz iff all coefficients are
        positive and :math:`K_i < K_{i,max}`.

    Notes
    -----
    Not in the thesis: the stability condition its gains (thesis §4.1) violate in
    SI by a factor of 25–160 (the thesis states no units for its gains).

    Examples
    --------
    >>> round(float(integral_gain_limit(0.005, 1e-4, 0.1, 0.5)), 12)
    0.001
    """
    return (as_positive("field", field, unit="T") * as_positive("kp", kp, unit="A·m²/rad")
            * as_positive("kd", kd, unit="A·m²·s/rad") / as_positive("inertia", inertia, unit="kg·m²"))


def critical_gain_scale(inertia, field, kp, ki, kd):
    r"""Common factor on all three gains at which the linearised loop becomes stable.

    Parameters
    ----------
    inertia : array_like
        J [kg·m²], > 0.
    field : array_like
        B0 [T], > 0.
    kp, ki, kd : array_like
        Gains [A·m²/rad], [A·m²/(rad·s)], [A·m²·s/rad], > 0.

    Returns
    -------
    ndarray
        :math:`s_c = J K_i / (B_0 K_p K_d)` [-]: the loop with gains s·K is stable iff
        s > s_c. Any reading of the thesis's gain units that multiplies them by a
        constant factor s (degrees, normalised outputs, other field units) is stable
        iff s > s_c; for a stable design, s_c < 1 is its lower gain margin.

    Notes
    -----
    Not in the thesis: Routh–Hurwitz (:func:`integral_gain_limit`) with every gain
    scaled by s, since K_i < B0 s K_p K_d / J ⇔ s > s_c.

    Examples
    --------
    >>> round(float(critical_gain_scale(0.005, 1e-4, 1.5, 0.05, 15.0)), 12)   # triple pole: 1/9
    0.111111111111
    """
    ki = as_positive("ki", ki, unit="A·m²/(rad·s)")
    return ki / integral_gain_limit(inertia, field, kp, kd)


def double_integrator_ultimate_gain(inertia, field, period):
    r"""P gain at which the P-only loop on the mock-up oscillates with a chosen period.

    Parameters
    ----------
    inertia : array_like
        J [kg·m²], > 0.
    field : array_like
        B0 [T], > 0.
    period : array_like
        Oscillation period [s], > 0.

    Returns
    -------
    ndarray
        :math:`K_u = J(2\pi/T)^2/B_0` [A·m²/rad]. The P-only loop
        :math:`J s^2 + B_0 K_p = 0` oscillates undamped for *every* K_p > 0, so the
        Ziegler–Nichols experiment has no unique ultimate point: the period is a free
        choice and fixes K_u.

    Notes
    -----
    Not in the thesis: follows from eqs. (36)–(38) with K_i = K_d = 0.

    Examples
    --------
    >>> round(float(double_integrator_ultimate_gain(0.005, 1e-4, 2 * np.pi)), 12)
    50.0
    """
    j = as_positive("inertia", inertia, unit="kg·m²")
    w = 2.0 * np.pi / as_positive("period", period, unit="s")
    return j * w**2 / as_positive("field", field, unit="T")
