r"""Sun-sensor sessions of a spinning axisymmetric body: the Euler-case signal model and its fit.

TNS-0 preprint §2 (L141–L173): between the sessions' few minutes the body turns torque-free
(the Euler case: L fixed in inertial space, the symmetry axis on a cone about it), and each sun
sensor reads the cosine of the angle between its normal and the Sun, clipped at zero. A session
is fitted by five constants — L, θ, ψ0, φ0 and the Sun angle σ from L — with t0 = 0: t0 is not
identifiable, it trades against the phases (:func:`session_identifiability`). The preprint fits
by a nested grid bounded by L_max = 2π I_max/Δt (:func:`fit_nested_grid`); two alternatives
are here beside it (:func:`fit_multistart`, :func:`fit_frequency_first`). The sensor normals
are an input: which sensors a spacecraft carries is its own business.

Conventions: the constants are ordered as :data:`SESSION_CONSTANTS` (SI: kg·m²/s and rad);
signals are (sensors, samples), in units of the full signal (a sensor facing the Sun reads 1).
A fit is a dict with ``method``, ``params`` (5,), ``rms`` [-], ``evaluations`` (model
evaluations) and ``seconds`` (wall time).
"""

import time as _time

import numpy as np

from .._docstrings import fill_docstring
from .._validate import (as_axisymmetric_inertias, as_count, as_finite, as_nonnegative, as_positive_scalar,
                         as_vectors, shown)

__all__ = ["SESSION_CONSTANTS", "euler_case_sun_signals", "fold_start_time", "synthetic_session", "session_rms",
           "momentum_bound", "fit_nested_grid", "fit_multistart", "fit_frequency_first", "mirror_solution",
           "session_recovered", "session_identifiability"]

#: The five fitted constants, in order: L [kg·m²/s], θ, ψ0, φ0, σ [rad].
SESSION_CONSTANTS = ("angular_momentum", "nutation", "precession0", "proper_rotation0", "sun_angle")

#: Candidates per model evaluation in a grid search: bounds the memory of one (chunk, sensors,
#: samples) array to a few tens of MB at a session's few thousand samples.
_CHUNK = 2048

#: A session's inputs and a fit's result, described once for every function that takes or
#: returns them.
_SESSION_DOCS = {
    "time": """time : array_like, shape (n,)
    Times of the session [s].""",
    "signals": """signals : array_like, shape (k, n)
    Measured signals [-].""",
    "normals": """normals : array_like, shape (k, 3)
    Unit sensor normals in body axes (z the symmetry axis) [-].""",
    "inertias": """transverse_inertia, axial_inertia : float
    A, C (> 0, C ≤ 2A) [kg·m²].""",
    "constants": """constants : array_like, shape (5,)
    L [kg·m²/s], θ, ψ0, φ0, σ [rad].""",
    "fit": """dict
    ``method``, ``params`` (5,) [SI], ``rms`` [-], ``evaluations``, ``seconds`` [s].""",
}
_document_session = fill_docstring(_SESSION_DOCS)


# --- the signal model ------------------------------------------------------------------------

def _signals(time, params, normals, a, c, start_time=0.0):
    """Unchecked :func:`euler_case_sun_signals` (the fits call it thousands of times)."""
    p = np.asarray(params, dtype=float)
    big_l, theta, psi0, phi0, sigma = (p[..., k, None] for k in range(5))
    t = np.asarray(time, dtype=float) - start_time
    psi = big_l / a * t + psi0
    phi = big_l * np.cos(theta) * (1.0 / c - 1.0 / a) * t + phi0
    cs, ss, ct, st = np.cos(psi), np.sin(psi), np.cos(theta), np.sin(theta)
    cf, sf = np.cos(phi), np.sin(phi)
    s_sin, s_cos = np.sin(sigma), np.cos(sigma)
    # s·(R e_x) and s·(R e_z), written out so that thousands of candidates evaluate at once
    x = s_sin * (cs * cf - ss * sf * ct) + s_cos * sf * st
    z = s_sin * ss * st + s_cos * ct
    out = normals[:, 0, None] * x[..., None, :] + normals[:, 2, None] * z[..., None, :]
    if np.any(normals[:, 1]):
        # s·(R e_y) only when a normal has a y component: sensors in the x–z plane skip it
        y = s_sin * (-cs * sf - ss * cf * ct) + s_cos * cf * st
        out = out + normals[:, 1, None] * y[..., None, :]
    return np.maximum(out, 0.0)


def _normals(normals):
    n = as_vectors("normals", normals)
    if n.ndim != 2 or n.shape[0] < 1:
        raise ValueError(f"normals must have shape (sensors, 3) with at least one sensor, got shape {n.shape}")
    size = np.linalg.norm(n, axis=-1)
    if np.any(np.abs(size - 1.0) > 1e-9):
        worst = float(size[np.argmax(np.abs(size - 1.0))])
        raise ValueError(f"normals must be unit vectors, got a normal of length {shown(worst)}")
    return n


def _inertias(transverse_inertia, axial_inertia):
    a = as_positive_scalar("transverse_inertia", transverse_inertia, unit="kg·m²")
    c = as_positive_scalar("axial_inertia", axial_inertia, unit="kg·m²")
    as_axisymmetric_inertias(a, c)
    return a, c


def _five_constants(constants):
    p = as_finite("constants", constants)
    if p.shape != (5,):
        raise ValueError(f"constants must have shape (5,) (L, θ, ψ0, φ0, σ), got shape {p.shape}")
    return p


def _session(time, signals, normals):
    t = as_finite("time", time)
    s = as_finite("signals", signals)
    if t.ndim != 1 or t.size < 8 or np.any(np.diff(t) <= 0):
        raise ValueError(f"time must be 1-D, increasing, with at least 8 samples, got shape {t.shape}")
    if s.shape != (normals.shape[0], t.size):
        raise ValueError(f"signals must have shape (sensors, samples) = {(normals.shape[0], t.size)}, "
                         f"got shape {s.shape}")
    return t, s


@_document_session
def euler_case_sun_signals(time, constants, normals, transverse_inertia, axial_inertia, *, start_time=0.0):
    r"""Sun-sensor signals of an axisymmetric body in Euler-case motion, the Sun alone (no albedo).

    Parameters
    ----------
    {time}
    constants : array_like, shape (..., 5)
        L [kg·m²/s], θ [rad], ψ0 [rad], φ0 [rad], σ (Sun angle from L) [rad]
        (:data:`SESSION_CONSTANTS`); leading axes are candidates evaluated at once.
    {normals, inertias}
    start_time : float, optional
        t0 [s].

    Returns
    -------
    ndarray, shape (..., k, n)
        max(0, s·R n_k), R = R_z(ψ) R_x(θ) R_z(φ) [-].

    Notes
    -----
    TNS-0 preprint §2 (L141–L173; its eqs. (4)–(5) lost, reconstructed as in the shared
    reference): ψ = (L/A)(t − t0) + ψ0, φ = L cos θ (1/C − 1/A)(t − t0) + φ0, the Sun
    s = (sin σ, 0, cos σ) in the L-frame. The same model as
    :func:`magbench.hardware.sun_sensor_signals` of :func:`magbench.dynamics.euler_case_matrix`,
    with R e_x, R e_y and R e_z written out.
    """
    n = _normals(normals)
    a, c = _inertias(transverse_inertia, axial_inertia)
    p = as_finite("constants", constants)
    if p.ndim == 0 or p.shape[-1] != 5:
        raise ValueError(f"constants must have shape (..., 5) (L, θ, ψ0, φ0, σ), got shape {p.shape}")
    t = as_finite("time", time)
    if t.ndim != 1:
        raise ValueError(f"time must be 1-D, got shape {t.shape}")
    return _signals(t, p, n, a, c, float(as_finite("start_time", start_time)))


@_document_session
def fold_start_time(constants, start_time, transverse_inertia, axial_inertia):
    r"""The same motion with t0 = 0: t0 folded into the phases ψ0 and φ0 (taken modulo 2π).

    Parameters
    ----------
    constants : array_like, shape (5,)
        L [kg·m²/s], θ, ψ0, φ0, σ [rad] at the start time t0.
    start_time : float
        t0 [s].
    {inertias}

    Returns
    -------
    ndarray, shape (5,)
        L, θ, ψ0 − ψ̇ t0, φ0 − φ̇ t0 (mod 2π), σ [SI].

    Notes
    -----
    TNS-0 preprint §2 (L141–L157): ψ̇ = L/A and φ̇ = L cos θ (1/C − 1/A) are constant, so
    ψ(t) = ψ̇ (t − t0) + ψ0 = ψ̇ t + (ψ0 − ψ̇ t0), and likewise φ.
    """
    p = _five_constants(constants)
    a, c = _inertias(transverse_inertia, axial_inertia)
    t0 = float(as_finite("start_time", start_time))
    out = p.copy()
    out[2] = np.mod(p[2] - p[0] / a * t0, 2 * np.pi)
    out[3] = np.mod(p[3] - p[0] * np.cos(p[1]) * (1.0 / c - 1.0 / a) * t0, 2 * np.pi)
    return out


@_document_session
def synthetic_session(constants, normals, transverse_inertia, axial_inertia, *, duration=60.0, rate=10.0, noise=0.01,
                      seed=0):
    """Sensor signals of known constants plus white noise: a session with a known answer.

    Parameters
    ----------
    constants : array_like, shape (5,)
        The truth (:data:`SESSION_CONSTANTS`) [SI].
    {normals, inertias}
    duration : float, optional
        Length, > 0 [s].
    rate : float, optional
        Samples per second, > 0 [1/s].
    noise : float, optional
        Standard deviation of the additive Gaussian noise, >= 0, in units of the full signal [-].
    seed : int, optional
        Seed of the noise [-].

    Returns
    -------
    time : ndarray, shape (n,)
        0, 1/rate, … < duration [s].
    signals : ndarray, shape (k, n)
        [-].

    Notes
    -----
    Not in the sources: the preprint's measured traces were never published; this makes a
    stand-in with the model of TNS-0 preprint §2 (:func:`euler_case_sun_signals`).
    """
    duration = as_positive_scalar("duration", duration, unit="s")
    rate = as_positive_scalar("rate", rate, unit="1/s")
    noise = float(as_nonnegative("noise", noise))
    t = np.arange(0.0, duration, 1.0 / rate)
    clean = euler_case_sun_signals(t, constants, normals, transverse_inertia, axial_inertia)
    return t, clean + noise * np.random.default_rng(seed).normal(size=clean.shape)


@_document_session
def session_rms(constants, time, signals, normals, transverse_inertia, axial_inertia):
    """Root-mean-square residual of candidate constants against a session's signals.

    Parameters
    ----------
    constants : array_like, shape (..., 5)
        Candidates (:data:`SESSION_CONSTANTS`) [SI].
    {time, signals, normals, inertias}

    Returns
    -------
    ndarray, shape (...)
        RMS over sensors and samples of model − signals [-].

    Notes
    -----
    TNS-0 preprint §2 (L165–L173): the fit's objective.
    """
    n = _normals(normals)
    t, s = _session(time, signals, n)
    a, c = _inertias(transverse_inertia, axial_inertia)
    return _rms(as_finite("constants", constants), t, s, n, a, c)


def _rms(params, time, signals, normals, a, c):
    model = _signals(time, params, normals, a, c)
    return np.sqrt(np.mean((model - signals) ** 2, axis=(-2, -1)))


def _rms_chunked(candidates, time, signals, normals, a, c):
    out = np.empty(candidates.shape[0])
    for i in range(0, candidates.shape[0], _CHUNK):
        out[i:i + _CHUNK] = _rms(candidates[i:i + _CHUNK], time, signals, normals, a, c)
    return out


@_document_session
def momentum_bound(time, signals, transverse_inertia, axial_inertia):
    r"""L_max = 2π I_max/Δt, Δt the shortest interval between neighbouring signal peaks.

    Parameters
    ----------
    {time, signals, inertias}

    Returns
    -------
    float
        L_max [kg·m²/s]; Δt is the session's length when no sensor shows two peaks.

    Notes
    -----
    TNS-0 preprint §2 (L171–L173, the formula lost, described in words). Peaks are local maxima
    above half the session's largest signal.
    """
    s = as_finite("signals", signals)
    t = as_finite("time", time)
    if s.ndim != 2 or t.ndim != 1 or s.shape[1] != t.size or t.size < 3:
        raise ValueError(f"signals must be (sensors, samples) on time (samples,) with >= 3 samples, "
                         f"got shapes {s.shape} and {t.shape}")
    a, c = _inertias(transverse_inertia, axial_inertia)
    return _momentum_bound(t, s, a, c)


def _momentum_bound(time, signals, a, c):
    gaps = []
    for s in signals:
        k = np.flatnonzero((s[1:-1] > s[:-2]) & (s[1:-1] >= s[2:]) & (s[1:-1] > 0.5 * signals.max())) + 1
        if k.size > 1:
            gaps.append(np.min(np.diff(time[k])))
    dt = min(gaps) if gaps else time[-1] - time[0]
    return 2.0 * np.pi * max(a, c) / dt


# --- the fits --------------------------------------------------------------------------------

def _polish(start, time, signals, normals, a, c):
    from scipy.optimize import least_squares

    fun = lambda x: (_signals(time, x, normals, a, c) - signals).ravel()  # noqa: E731
    # Phases are left unbounded (a bound at 0 or 2π stalls the polish, shared reference §7).
    res = least_squares(fun, start, method="lm", x_scale=np.array([0.01, 0.1, 0.5, 0.5, 0.1]))
    return res.x, res.nfev


def _result(method, x, session, evaluations, seconds):
    x = np.array(x, dtype=float)
    x[2:4] = np.mod(x[2:4], 2.0 * np.pi)
    return {"method": method, "params": x, "rms": float(_rms(x, *session)),
            "evaluations": int(evaluations), "seconds": seconds}


def _checked(time, signals, normals, transverse_inertia, axial_inertia):
    """(time, signals, normals, A, C), checked: the session every fit works on."""
    n = _normals(normals)
    t, s = _session(time, signals, n)
    return (t, s, n) + _inertias(transverse_inertia, axial_inertia)


@_document_session
def fit_nested_grid(time, signals, normals, transverse_inertia, axial_inertia, *, points=5, levels=4):
    """The preprint's method: a grid over the five constants, refined around the best point.

    L in (0, L_max] (:func:`momentum_bound`), θ and σ in [0, π], the phases in [0, 2π);
    each level halves the ranges about the best point so far. The grid is evaluated on every
    second sample (half the cost; the best point is then scored on all of them).

    Parameters
    ----------
    {time, signals, normals, inertias}
    points : int, optional
        Grid points per constant and level, >= 1 [-].
    levels : int, optional
        Refinements, >= 1 [-].

    Returns
    -------
    {fit}

    Notes
    -----
    TNS-0 preprint §2 (L165–L173): the nested grid and its bound on L.
    """
    session = _checked(time, signals, normals, transverse_inertia, axial_inertia)
    points, levels = as_count("points", points), as_count("levels", levels)
    start = _time.perf_counter()
    t, s, n, a, c = session
    lo = np.array([0.0, 0.0, 0.0, 0.0, 0.0])
    hi = np.array([_momentum_bound(t, s, a, c), np.pi, 2 * np.pi, 2 * np.pi, np.pi])
    middle, width = 0.5 * (lo + hi), hi - lo
    best, best_rms, evaluations = middle, np.inf, 0
    sub = slice(None, None, 2)
    for _ in range(levels):
        # the refined box kept inside the bounds
        low = np.clip(middle - 0.5 * width, lo, hi - width)
        axes = [low[k] + width[k] * (np.arange(points) + 0.5) / points for k in range(5)]
        grid = np.stack(np.meshgrid(*axes, indexing="ij"), axis=-1).reshape(-1, 5)
        values = _rms_chunked(grid, t[sub], s[:, sub], n, a, c)
        evaluations += grid.shape[0]
        k = int(np.argmin(values))
        if values[k] < best_rms:
            best, best_rms = grid[k], values[k]
        middle, width = best, 0.5 * width
    return _result("nested grid (preprint)", best, session, evaluations, _time.perf_counter() - start)


@_document_session
def fit_multistart(time, signals, normals, transverse_inertia, axial_inertia, *, starts=20, seed=0):
    """Local least squares (Levenberg–Marquardt) from random starts within the grid's bounds.

    Parameters
    ----------
    {time, signals, normals, inertias}
    starts : int, optional
        Random starts, >= 1 [-].
    seed : int, optional
        Seed of the starts [-].

    Returns
    -------
    {fit}

    Notes
    -----
    Not in the sources: an alternative to the nested grid of TNS-0 preprint §2 (L165–L173),
    within its bounds.
    """
    session = _checked(time, signals, normals, transverse_inertia, axial_inertia)
    starts = as_count("starts", starts)
    start = _time.perf_counter()
    t, s, n, a, c = session
    rng = np.random.default_rng(seed)
    hi = np.array([_momentum_bound(t, s, a, c), np.pi, 2 * np.pi, 2 * np.pi, np.pi])
    best, best_rms, evaluations = None, np.inf, 0
    for _ in range(starts):
        x, nfev = _polish(rng.uniform(0.0, 1.0, 5) * hi, t, s, n, a, c)
        evaluations += nfev
        value = float(_rms(x, t, s, n, a, c))
        if value < best_rms:
            best, best_rms = x, value
    return _result("multi-start least squares", best, session, evaluations, _time.perf_counter() - start)


def _peaks(signal, time, count):
    """The ``count`` strongest spectral lines of a signal [rad/s] (Hann window, 8× zero padding)."""
    n = 8 * time.size
    spectrum = np.abs(np.fft.rfft((signal - signal.mean()) * np.hanning(time.size), n))
    freq = 2 * np.pi * np.fft.rfftfreq(n, time[1] - time[0])
    k = np.flatnonzero((spectrum[1:-1] > spectrum[:-2]) & (spectrum[1:-1] >= spectrum[2:])) + 1
    k = k[np.argsort(spectrum[k])[::-1][:count]]
    return freq[k]


def _sensor_roles(normals):
    """Indices of the first sensor along +z and the first sensor across z (z component 0)."""
    axial = np.flatnonzero(np.all(normals == [0.0, 0.0, 1.0], axis=-1))
    transverse = np.flatnonzero(normals[:, 2] == 0.0)
    if axial.size == 0 or transverse.size == 0:
        raise ValueError(f"normals must include one along +z and one across z (z component 0) for the "
                         f"frequency-first fit, got {normals.tolist()}")
    return int(axial[0]), int(transverse[0])


@_document_session
def fit_frequency_first(time, signals, normals, transverse_inertia, axial_inertia, *, phase_points=24,
                        sun_points=12):
    r"""Rates from the spectra, then the phases and σ on a grid, then a polish of all five.

    A sensor along the symmetry axis (+z) turns about L at ψ̇ = L/A alone: its strongest
    spectral line gives L. A sensor across the axis carries φ̇ and ψ̇ ± φ̇: each of its
    strongest lines gives candidates for φ̇ and so cos θ = φ̇ / (L(1/C − 1/A)); for each, a grid
    over ψ0, φ0 and σ picks the phases, and the best candidate is polished. φ̇ > 0 is taken:
    for sensors in the x–z plane the mirror (:func:`mirror_solution`) fits equally.

    Parameters
    ----------
    time : array_like, shape (n,)
        Times of the session, uniformly sampled [s].
    {signals}
    normals : array_like, shape (k, 3)
        Unit sensor normals in body axes: one along +z and one with z component 0 [-].
    {inertias}
    phase_points : int, optional
        Grid points of each phase in [0, 2π), >= 1 [-].
    sun_points : int, optional
        Grid points of σ in (0, π), >= 1 [-].

    Returns
    -------
    {fit}

    Notes
    -----
    Not in the sources: an alternative to the nested grid of TNS-0 preprint §2 (L165–L173),
    on the rates of its Euler case (L141–L157).
    """
    session = _checked(time, signals, normals, transverse_inertia, axial_inertia)
    phase_points, sun_points = as_count("phase_points", phase_points), as_count("sun_points", sun_points)
    axial, transverse = _sensor_roles(session[2])
    start = _time.perf_counter()
    t, s, n, a, c = session
    psi_rate = _peaks(s[axial], t, 1)[0]
    big_l = a * psi_rate
    candidates = set()
    for f in _peaks(s[transverse], t, 4):
        for phi_rate in (f, f - psi_rate, psi_rate - f, f + psi_rate):
            cos_theta = phi_rate / (big_l * (1.0 / c - 1.0 / a))
            if 0.0 < cos_theta < 1.0:
                candidates.add(round(float(np.arccos(cos_theta)), 6))
    phases = 2 * np.pi * np.arange(phase_points) / phase_points
    sun = np.pi * (np.arange(sun_points) + 0.5) / sun_points
    g_psi, g_phi, g_sun = (x.ravel() for x in np.meshgrid(phases, phases, sun, indexing="ij"))
    sub = slice(None, None, 2)
    best, best_rms, evaluations = None, np.inf, 0
    for theta in sorted(candidates):
        grid = np.stack([np.full(g_psi.size, big_l), np.full(g_psi.size, theta), g_psi, g_phi, g_sun], axis=-1)
        values = _rms_chunked(grid, t[sub], s[:, sub], n, a, c)
        evaluations += grid.shape[0]
        x, nfev = _polish(grid[int(np.argmin(values))], t, s, n, a, c)
        evaluations += nfev
        value = float(_rms(x, t, s, n, a, c))
        if value < best_rms:
            best, best_rms = x, value
    if best is None:
        best = np.array([big_l, 0.5 * np.pi, 0.0, 0.0, 0.5 * np.pi])
    return _result("frequency first", best, session, evaluations, _time.perf_counter() - start)


# --- what a fit can and cannot tell --------------------------------------------------------

@_document_session
def mirror_solution(constants):
    r"""The mirror solution (π − θ, −φ0, π − σ): the same signals for sensors in the body x–z plane.

    Parameters
    ----------
    {constants}

    Returns
    -------
    ndarray, shape (5,)
        L, π − θ, ψ0, −φ0 (mod 2π), π − σ [SI].

    Notes
    -----
    TNS-0 preprint §2 (L141–L173): θ → π − θ reverses φ̇, so φ(t) → −φ(t); with σ → π − σ the
    terms of s·R e_x and s·R e_z keep their values (their sign changes come in pairs) while
    s·R e_y changes sign, so no sensor in the body x–z plane can tell the two apart.
    """
    p = _five_constants(constants).astype(float, copy=True)
    p[1], p[3], p[4] = np.pi - p[1], np.mod(-p[3], 2 * np.pi), np.pi - p[4]
    return p


def session_recovered(fit, truth, *, momentum_rtol=0.01, angle_atol=0.02):
    """True when a fit finds L to ``momentum_rtol`` and θ, σ to ``angle_atol`` (or the mirror's).

    Parameters
    ----------
    fit : dict
        A fit (``params`` (5,) [SI]).
    truth : array_like, shape (5,)
        The known constants [SI].
    momentum_rtol : float, optional
        Relative tolerance on L, >= 0 [-].
    angle_atol : float, optional
        Absolute tolerance on θ and σ, >= 0 [rad].

    Returns
    -------
    bool
        [-].

    Notes
    -----
    Not in the sources: the phases are not compared (they trade against t0,
    :func:`session_identifiability`; TNS-0 preprint §2, L141–L173).
    """
    momentum_rtol = float(as_nonnegative("momentum_rtol", momentum_rtol))
    angle_atol = float(as_nonnegative("angle_atol", angle_atol))
    x = fit["params"]
    truth = as_finite("truth", truth)
    return bool(any(abs(x[0] - t[0]) <= momentum_rtol * t[0] and abs(x[1] - t[1]) <= angle_atol
                    and abs(x[4] - t[4]) <= angle_atol for t in (truth, mirror_solution(truth))))


@_document_session
def session_identifiability(constants, time, normals, transverse_inertia, axial_inertia, *, start_time=0.0,
                            step=1e-6):
    r"""Singular values of the signals' Jacobian in (L, θ, ψ0, φ0, σ, t0), largest first.

    Parameters
    ----------
    {constants, time, normals, inertias}
    start_time : float, optional
        t0 [s].
    step : float, optional
        Step of the central differences, > 0 [SI of each constant].

    Returns
    -------
    ndarray, shape (6,)
        [-].

    Notes
    -----
    TNS-0 preprint §2 (L141–L173). The smallest is ~0: ∂/∂t0 = −ψ̇ ∂/∂ψ0 − φ̇ ∂/∂φ0 exactly, so
    t0 trades against the phases and only five of the six constants are identifiable (at
    θ = π/2, φ̇ = 0 and t0 trades against ψ0 alone).
    """
    n = _normals(normals)
    a, c = _inertias(transverse_inertia, axial_inertia)
    p = _five_constants(constants)
    t = as_finite("time", time)
    step = as_positive_scalar("step", step)
    cols = []
    for k in range(6):
        d = np.zeros(6)
        d[k] = step
        plus, minus = np.append(p, start_time) + d, np.append(p, start_time) - d
        cols.append((_signals(t, plus[:5], n, a, c, plus[5])
                     - _signals(t, minus[:5], n, a, c, minus[5])).ravel() / (2 * step))
    return np.linalg.svd(np.stack(cols, axis=-1), compute_uv=False)
