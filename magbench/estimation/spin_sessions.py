r"""The attitude of a torque-free spinning body from sun-sensor sessions: the Euler-case signal
model of three cosine sensors and three ways to fit its constants (a nested grid, multi-start
least squares, frequency first).

TNS-0 preprint §2 (L141–L173: the Euler case, the sensors' cosine law, the constants of its
Table 1, the fit by a nested grid search bounded by L_max = 2π I_max/Δt). The sensors' normals
are +x, +z and −x in body axes (:data:`SENSOR_NORMALS`; TNS-0's ДС1–ДС3 as the book takes them:
only n1 = −n3 is in the text). Five constants are fitted — L, θ, ψ0, φ0 and the Sun angle σ —
with t0 = 0: t0 is not identifiable, it trades against the phases (:func:`identifiability`).
Chapter 7 runs the fits on synthetic sessions (:func:`synthetic_session`): the measured traces
were never published.
"""

import time as _time

import numpy as np

from .._validate import as_count, as_positive_scalar, shown

__all__ = ["SENSOR_NORMALS", "NAMES", "sensor_signals", "synthetic_session", "rms", "momentum_bound",
           "fit_nested_grid", "fit_multistart", "fit_frequency_first", "mirror", "recovered", "identifiability"]

#: Sensor normals in body axes: +x, +z, −x (TNS-0's ДС1–ДС3; ours: only n1 = −n3 is in the text).
SENSOR_NORMALS = np.array([[1.0, 0.0, 0.0], [0.0, 0.0, 1.0], [-1.0, 0.0, 0.0]])

#: The five fitted constants, in order.
NAMES = ("angular_momentum", "nutation", "precession0", "proper_rotation0", "sun_angle")


def _check_inertias(transverse_inertia, axial_inertia):
    as_positive_scalar("transverse_inertia", transverse_inertia, unit="kg·m²")
    as_positive_scalar("axial_inertia", axial_inertia, unit="kg·m²")


def sensor_signals(time, params, transverse_inertia, axial_inertia, *, start_time=0.0):
    r"""Euler-case signals of ДС1 (+x), ДС2 (+z), ДС3 (−x) for the Sun alone (no albedo).

    Parameters
    ----------
    time : array_like, shape (n,)
        Times of the session [s].
    params : array_like, shape (..., 5)
        L [kg·m²/s], θ [rad], ψ0 [rad], φ0 [rad], σ (Sun angle from L) [rad]; leading axes are
        candidates evaluated at once.
    transverse_inertia, axial_inertia : float
        A, C, > 0 [kg·m²].
    start_time : float, optional
        t0 [s].

    Returns
    -------
    ndarray, shape (..., 3, n)
        max(0, n_k·s), n_k = R n_k^body, R = R_z(ψ) R_x(θ) R_z(φ) [-].

    Notes
    -----
    TNS-0 preprint §2 (L141–L173; its eqs. (4)–(5) lost, reconstructed as in the shared
    reference): ψ = (L/A)(t − t0) + ψ0, φ = L cos θ (1/C − 1/A)(t − t0) + φ0, Sun
    s = (sin σ, 0, cos σ) in the L-frame. Written out for the three normals (R e_x and R e_z)
    so that thousands of candidates evaluate at once.
    """
    _check_inertias(transverse_inertia, axial_inertia)
    p = np.asarray(params, dtype=float)
    if p.ndim == 0 or p.shape[-1] != 5:
        raise ValueError(f"params must have shape (..., 5) (L, θ, ψ0, φ0, σ), got shape {p.shape}")
    big_l, theta, psi0, phi0, sigma = (p[..., k, None] for k in range(5))
    t = np.asarray(time, dtype=float) - start_time
    psi = big_l / transverse_inertia * t + psi0
    phi = big_l * np.cos(theta) * (1.0 / axial_inertia - 1.0 / transverse_inertia) * t + phi0
    cs, ss, ct, st = np.cos(psi), np.sin(psi), np.cos(theta), np.sin(theta)
    cf, sf = np.cos(phi), np.sin(phi)
    s_sin, s_cos = np.sin(sigma), np.cos(sigma)
    x = s_sin * (cs * cf - ss * sf * ct) + s_cos * sf * st
    z = s_sin * ss * st + s_cos * ct
    return np.maximum(np.stack([x, z, -x], axis=-2), 0.0)


def synthetic_session(truth, transverse_inertia, axial_inertia, *, duration=60.0, rate=10.0, noise=0.01, seed=0):
    """Sensor signals of a truth (5 constants) plus white noise: a session with a known answer.

    Parameters
    ----------
    truth : array_like, shape (5,)
        The constants (:data:`NAMES`) [SI].
    transverse_inertia, axial_inertia : float
        A, C [kg·m²].
    duration : float, optional
        Length [s].
    rate : float, optional
        Samples per second [1/s].
    noise : float, optional
        Standard deviation of the additive noise, in units of the full signal [-].
    seed : int, optional
        Seed of the noise [-].

    Returns
    -------
    time : ndarray, shape (n,)
        [s].
    signals : ndarray, shape (3, n)
        [-].

    Notes
    -----
    Not in the sources: a test bench for the TNS-0 preprint §2 fits, whose measured traces were
    never published.
    """
    if duration <= 0 or rate <= 0 or noise < 0:
        raise ValueError(f"duration ({shown(duration)} s) and rate ({rate!r} /s) must be > 0 and noise ({noise!r}) >= 0")
    t = np.arange(0.0, duration, 1.0 / rate)
    clean = sensor_signals(t, truth, transverse_inertia, axial_inertia)
    return t, clean + noise * np.random.default_rng(seed).normal(size=clean.shape)


def rms(params, time, signals, transverse_inertia, axial_inertia):
    """Root-mean-square residual of candidate constants against a session's signals.

    Parameters
    ----------
    params : array_like, shape (..., 5)
        Candidates (:data:`NAMES`) [SI].
    time : ndarray, shape (n,)
        Sample times [s].
    signals : ndarray, shape (3, n)
        The three sensors' signals [-].
    transverse_inertia, axial_inertia : float
        A, C [kg·m²].

    Returns
    -------
    ndarray, shape (...)
        √mean((model − signals)²) over sensors and samples [-].

    Notes
    -----
    TNS-0 preprint §2 (L171: the fit minimises the mismatch of model and signals).
    """
    model = sensor_signals(time, params, transverse_inertia, axial_inertia)
    return np.sqrt(np.mean((model - signals) ** 2, axis=(-2, -1)))


def _rms_chunked(candidates, time, signals, a, c, chunk=2048):
    out = np.empty(candidates.shape[0])
    for i in range(0, candidates.shape[0], chunk):
        out[i:i + chunk] = rms(candidates[i:i + chunk], time, signals, a, c)
    return out


def momentum_bound(time, signals, transverse_inertia, axial_inertia):
    r"""The largest angular momentum a session's sampling can show.

    Parameters
    ----------
    time : ndarray, shape (n,)
        Sample times [s].
    signals : ndarray, shape (3, n)
        The three sensors' signals [-].
    transverse_inertia, axial_inertia : float
        A, C [kg·m²].

    Returns
    -------
    float
        L_max = 2π I_max/Δt [kg·m²/s], Δt the shortest interval between neighbouring signal
        peaks (the whole session when no sensor shows two).

    Notes
    -----
    TNS-0 preprint §2 (L171–L173, the formula lost, described in words). Peaks are local maxima
    above half the session's largest signal.
    """
    gaps = []
    for s in signals:
        k = np.flatnonzero((s[1:-1] > s[:-2]) & (s[1:-1] >= s[2:]) & (s[1:-1] > 0.5 * signals.max())) + 1
        if k.size > 1:
            gaps.append(np.min(np.diff(time[k])))
    dt = min(gaps) if gaps else time[-1] - time[0]
    return 2.0 * np.pi * max(transverse_inertia, axial_inertia) / dt


def _polish(start, time, signals, a, c):
    from scipy.optimize import least_squares

    fun = lambda x: (sensor_signals(time, x, a, c) - signals).ravel()  # noqa: E731
    # Phases are left unbounded (a bound at 0 or 2π stalls the polish, shared reference §7).
    res = least_squares(fun, start, method="lm", x_scale=np.array([0.01, 0.1, 0.5, 0.5, 0.1]))
    return res.x, res.nfev


def _result(method, x, time, signals, a, c, evaluations, seconds):
    x = np.array(x, dtype=float)
    x[2:4] = np.mod(x[2:4], 2.0 * np.pi)
    return {"method": method, "params": x, "rms": float(rms(x, time, signals, a, c)),
            "evaluations": int(evaluations), "seconds": seconds}


def fit_nested_grid(time, signals, transverse_inertia, axial_inertia, *, points=5, levels=4):
    """The preprint's method: a grid over the five constants, refined around the best point.

    TNS-0 preprint §2 (L171–L173). L in (0, L_max] (:func:`momentum_bound`), θ and σ in [0, π], the phases in [0, 2π);
    each level halves the ranges about the best point so far.

    Parameters
    ----------
    time : ndarray, shape (n,)
        [s].
    signals : ndarray, shape (3, n)
        [-].
    transverse_inertia, axial_inertia : float
        A, C [kg·m²].
    points : int, optional
        Grid points per constant and level [-].
    levels : int, optional
        Refinements [-].

    Returns
    -------
    dict
        ``method``, ``params`` (5,), ``rms`` [-], ``evaluations`` (model evaluations), ``seconds``.
    """
    as_count("points", points, minimum=2)
    as_count("levels", levels)
    start = _time.perf_counter()
    a, c = transverse_inertia, axial_inertia
    lo = np.array([0.0, 0.0, 0.0, 0.0, 0.0])
    hi = np.array([momentum_bound(time, signals, a, c), np.pi, 2 * np.pi, 2 * np.pi, np.pi])
    centre, width = 0.5 * (lo + hi), hi - lo
    best, best_rms, evaluations = centre, np.inf, 0
    sub = slice(None, None, 2)
    for _ in range(levels):
        # the refined box kept inside the bounds
        low = np.clip(centre - 0.5 * width, lo, hi - width)
        axes = [low[k] + width[k] * (np.arange(points) + 0.5) / points for k in range(5)]
        grid = np.stack(np.meshgrid(*axes, indexing="ij"), axis=-1).reshape(-1, 5)
        values = _rms_chunked(grid, time[sub], signals[:, sub], a, c)
        evaluations += grid.shape[0]
        k = int(np.argmin(values))
        if values[k] < best_rms:
            best, best_rms = grid[k], values[k]
        centre, width = best, 0.5 * width
    return _result("nested grid (preprint)", best, time, signals, a, c, evaluations, _time.perf_counter() - start)


def fit_multistart(time, signals, transverse_inertia, axial_inertia, *, starts=20, seed=0):
    """Local least squares (Levenberg–Marquardt) from random starts within the grid's bounds.

    Parameters
    ----------
    time : ndarray, shape (n,)
        Sample times, equally spaced [s].
    signals : ndarray, shape (3, n)
        The three sensors' signals [-].
    transverse_inertia, axial_inertia : float
        A, C [kg·m²].
    starts : int, optional
        Random starts [-].
    seed : int, optional
        Seed of the starts [-].

    Returns
    -------
    dict
        ``method``, ``params`` (5,) [SI], ``rms`` [-], ``evaluations`` (model evaluations), ``seconds``.

    Notes
    -----
    Not in the sources: scipy's least_squares from random starts, the book's alternative (TNS-0 preprint §2 fits by a nested grid).
    """
    start = _time.perf_counter()
    a, c = transverse_inertia, axial_inertia
    rng = np.random.default_rng(seed)
    hi = np.array([momentum_bound(time, signals, a, c), np.pi, 2 * np.pi, 2 * np.pi, np.pi])
    best, best_rms, evaluations = None, np.inf, 0
    for _ in range(starts):
        x, n = _polish(rng.uniform(0.0, 1.0, 5) * hi, time, signals, a, c)
        evaluations += n
        value = float(rms(x, time, signals, a, c))
        if value < best_rms:
            best, best_rms = x, value
    return _result("multi-start least squares", best, time, signals, a, c, evaluations, _time.perf_counter() - start)


def _peaks(signal, time, count):
    n = 8 * time.size
    spectrum = np.abs(np.fft.rfft((signal - signal.mean()) * np.hanning(time.size), n))
    freq = 2 * np.pi * np.fft.rfftfreq(n, time[1] - time[0])
    k = np.flatnonzero((spectrum[1:-1] > spectrum[:-2]) & (spectrum[1:-1] >= spectrum[2:])) + 1
    k = k[np.argsort(spectrum[k])[::-1][:count]]
    return freq[k]


def fit_frequency_first(time, signals, transverse_inertia, axial_inertia, *, phase_points=24, sun_points=12):
    r"""Rates from the spectra, then the phases and σ on a grid, then a polish of all five.

    ДС2 (+z) turns about L at ψ̇ = L/A alone: its strongest spectral line gives L. ДС1 (+x)
    carries φ̇ and ψ̇ ± φ̇: each of its strongest lines gives candidates for φ̇ and so
    cos θ = φ̇ / (L(1/C − 1/A)); for each, a grid over ψ0, φ0 and σ picks the phases, and the
    best candidate is polished. φ̇ > 0 is taken: the mirror (π − θ, −φ0, π − σ) fits equally.
    Parameters
    ----------
    time : ndarray, shape (n,)
        Sample times, equally spaced [s].
    signals : ndarray, shape (3, n)
        The three sensors' signals [-].
    transverse_inertia, axial_inertia : float
        A, C [kg·m²].
    phase_points : int, optional
        Grid points for ψ0 and for φ0 [-].
    sun_points : int, optional
        Grid points for σ [-].

    Returns
    -------
    dict
        ``method``, ``params`` (5,) [SI], ``rms`` [-], ``evaluations`` (model evaluations), ``seconds``.

    Notes
    -----
    Not in the sources: the rates read from the spectra, the book's alternative (TNS-0 preprint §2 fits by a nested grid).
    """
    start = _time.perf_counter()
    a, c = transverse_inertia, axial_inertia
    psi_rate = _peaks(signals[1], time, 1)[0]
    big_l = a * psi_rate
    candidates = set()
    for f in _peaks(signals[0], time, 4):
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
        values = _rms_chunked(grid, time[sub], signals[:, sub], a, c)
        evaluations += grid.shape[0]
        x, n = _polish(grid[int(np.argmin(values))], time, signals, a, c)
        evaluations += n
        value = float(rms(x, time, signals, a, c))
        if value < best_rms:
            best, best_rms = x, value
    if best is None:
        best = np.array([big_l, 0.5 * np.pi, 0.0, 0.0, 0.5 * np.pi])
    return _result("frequency first", best, time, signals, a, c, evaluations, _time.perf_counter() - start)


def mirror(params):
    """The mirror solution, which gives the same signals for sensors along ±x and +z.

    Parameters
    ----------
    params : array_like, shape (5,)
        Constants (:data:`NAMES`) [SI].

    Returns
    -------
    ndarray, shape (5,)
        (L, π − θ, ψ0, −φ0 mod 2π, π − σ) [SI].

    Notes
    -----
    Not in the sources: the symmetry of the TNS-0 preprint §2 sensor model (x → −x exchanges
    ДС1 and ДС3, which the fit cannot tell apart).
    """
    p = np.array(params, dtype=float)
    p[1], p[3], p[4] = np.pi - p[1], np.mod(-p[3], 2 * np.pi), np.pi - p[4]
    return p


def recovered(fit, truth, *, momentum_rtol=0.01, angle_atol=0.02):
    """Whether a fit found the truth (or its mirror).

    Parameters
    ----------
    fit : dict
        A fit's result (``params``) [SI].
    truth : array_like, shape (5,)
        The constants the session was made with [SI].
    momentum_rtol : float, optional
        Relative tolerance on L [-].
    angle_atol : float, optional
        Absolute tolerance on θ and σ [rad].

    Returns
    -------
    bool
        L within ``momentum_rtol`` and θ, σ within ``angle_atol`` of the truth's or its mirror's.

    Notes
    -----
    Not in the sources: the book's criterion for the TNS-0 preprint §2 fits on synthetic
    sessions (the phases are not compared: they trade against t0).
    """
    x = fit["params"]
    return bool(any(abs(x[0] - t[0]) <= momentum_rtol * t[0] and abs(x[1] - t[1]) <= angle_atol
                    and abs(x[4] - t[4]) <= angle_atol for t in (np.asarray(truth, float), mirror(truth))))


def identifiability(params, time, transverse_inertia, axial_inertia, *, start_time=0.0, step=1e-6):
    r"""Singular values of the signals' Jacobian in (L, θ, ψ0, φ0, σ, t0), largest first.

    The smallest is ~0: ∂/∂t0 = −ψ̇ ∂/∂ψ0 − φ̇ ∂/∂φ0 exactly, so t0 trades against the phases and
    only five of the six constants are identifiable (at θ = π/2, φ̇ = 0 and t0 trades against ψ0
    alone). Central differences of step ``step``.

    Parameters
    ----------
    params : array_like, shape (5,)
        Constants (:data:`NAMES`) [SI].
    time : ndarray, shape (n,)
        Sample times [s].
    transverse_inertia, axial_inertia : float
        A, C [kg·m²].
    start_time : float, optional
        t0 [s].
    step : float, optional
        Difference step in every constant [SI].

    Returns
    -------
    ndarray, shape (6,)
        Singular values [-].

    Notes
    -----
    TNS-0 preprint §2 (L141–L173) lists t0 among the constants; this is why it is not fitted.
    """
    p = np.asarray(params, dtype=float)
    a, c = transverse_inertia, axial_inertia
    cols = []
    for k in range(6):
        d = np.zeros(6)
        d[k] = step
        plus, minus = np.append(p, start_time) + d, np.append(p, start_time) - d
        cols.append((sensor_signals(time, plus[:5], a, c, start_time=plus[5])
                     - sensor_signals(time, minus[:5], a, c, start_time=minus[5])).ravel() / (2 * step))
    return np.linalg.svd(np.stack(cols, axis=-1), compute_uv=False)
