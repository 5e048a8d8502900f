r"""Linear and exponential fits of a decaying series, with a model-selection number (AICc).

TNS-0 preprint Fig. 14 (L175, L380–L381): the angular momentum of Table 1 against the hours since
the first session. A linear decay is the signature of rate-independent hysteresis (a constant
energy per revolution, Kovalenko (1975) eq. (12.1)); a loss proportional to the rate gives an
exponential one. Pure numpy/scipy.
"""

from dataclasses import dataclass

import numpy as np
from scipy.optimize import curve_fit

from .._validate import as_finite, shown

__all__ = ["DecayFit", "fit_linear_decay", "fit_exponential_decay", "corrected_aic"]


@dataclass(frozen=True)
class DecayFit:
    r"""A fitted decay law.

    Attributes
    ----------
    model : str
        ``"linear"`` (y = y0 + s t) or ``"exponential"`` (y = y0 exp(−t/τ)) [-].
    parameters : dict
        ``initial`` y0 and ``slope`` s or ``time_constant`` τ [units of the data].
    uncertainty : dict
        One-sigma uncertainty of each parameter, from the residual variance [same units].
    rms : float
        RMS of the residuals [units of y].
    aicc : float
        Corrected Akaike information criterion (lower is better) [-].
    """

    model: str
    parameters: dict
    uncertainty: dict
    rms: float
    aicc: float

    def predict(self, time):
        """The fitted law at ``time`` [units of the fitted time]."""
        t = np.asarray(time, dtype=float)
        if self.model == "linear":
            return self.parameters["initial"] + self.parameters["slope"] * t
        return self.parameters["initial"] * np.exp(-t / self.parameters["time_constant"])


def _series(time, values):
    t = as_finite("time", time)
    y = as_finite("values", values)
    if t.ndim != 1 or t.shape != y.shape or t.size < 5:
        raise ValueError(f"time and values must be 1-D of one length >= 5 (AICc of a 2-parameter fit), got {t.shape} and {y.shape}")
    return t, y


def corrected_aic(residual_sum_squares, samples, parameters):
    r"""Corrected Akaike information criterion of a least-squares fit with Gaussian errors.

    Parameters
    ----------
    residual_sum_squares : float
        Σ r² > 0 [units of y squared].
    samples : int
        n, number of data points, > parameters + 2 [-].
    parameters : int
        k, number of fitted parameters (the noise variance not counted) [-].

    Returns
    -------
    float
        n ln(RSS/n) + 2(k + 1) + 2(k + 1)(k + 2)/(n − k − 2) [-]; differences between models
        on the same data are what count.

    Notes
    -----
    Not in the sources: Burnham & Anderson, *Model Selection and Multimodel Inference*, 2nd ed.
    (2002), eqs. (2.13)–(2.14), with the variance as a (k + 1)-th parameter.
    """
    rss = float(as_finite("residual_sum_squares", residual_sum_squares))
    if rss <= 0:
        raise ValueError(f"residual_sum_squares must be > 0, got {shown(rss)}")
    n, k = int(samples), int(parameters) + 1
    if n - k - 1 <= 0:
        raise ValueError(f"samples must exceed parameters + 2, got samples={shown(n)}, parameters={shown(k - 1)}")
    return n * np.log(rss / n) + 2 * k + 2 * k * (k + 1) / (n - k - 1)


def fit_linear_decay(time, values):
    r"""Least-squares straight line y = y0 + s t.

    Parameters
    ----------
    time : array_like, shape (n,)
        Abscissae (TNS-0 Fig. 14: hours since the first session) [any unit].
    values : array_like, shape (n,)
        Ordinates (Table 1's L) [any unit].

    Returns
    -------
    DecayFit
        ``parameters`` ``initial``, ``slope``, with standard errors, RMS and AICc.

    Notes
    -----
    TNS-0 preprint Fig. 14 (L380–L381) regenerated from Table 1; Not in the sources: ordinary
    least squares with the residual variance RSS/(n − 2).

    Examples
    --------
    >>> fit = fit_linear_decay([0.0, 1.0, 2.0, 3.0, 4.0], [1.0, 0.9, 0.81, 0.7, 0.6])
    >>> round(fit.parameters["slope"], 3)
    -0.1
    """
    t, y = _series(time, values)
    design = np.stack([np.ones_like(t), t], axis=-1)
    coef, *_ = np.linalg.lstsq(design, y, rcond=None)
    residual = y - design @ coef
    rss = float(residual @ residual)
    cov = rss / (t.size - 2) * np.linalg.inv(design.T @ design)
    return DecayFit("linear", {"initial": float(coef[0]), "slope": float(coef[1])},
                    {"initial": float(np.sqrt(cov[0, 0])), "slope": float(np.sqrt(cov[1, 1]))},
                    float(np.sqrt(rss / t.size)), corrected_aic(rss, t.size, 2))


def fit_exponential_decay(time, values):
    r"""Least-squares exponential y = y0 exp(−t/τ) (unweighted, in y, not in ln y).

    Parameters
    ----------
    time : array_like, shape (n,)
        Abscissae [any unit].
    values : array_like, shape (n,)
        Ordinates, > 0 for the starting guess [any unit].

    Returns
    -------
    DecayFit
        ``parameters`` ``initial``, ``time_constant`` (same unit as ``time``), standard errors,
        RMS and AICc.

    Notes
    -----
    TNS-0 preprint Fig. 14 (L380–L381): the exponential a rate-proportional loss (the preprint's
    delayed-projection rod model, §3, L449–L455) would give. Not in the sources: nonlinear least
    squares (scipy ``curve_fit``, started from the log-linear fit).
    """
    t, y = _series(time, values)
    if np.any(y <= 0):
        raise ValueError("values must be > 0 for an exponential fit")
    slope, intercept = np.polyfit(t, np.log(y), 1)
    guess = (float(np.exp(intercept)), float(-1.0 / slope) if slope < 0 else float(np.ptp(t)))

    def law(x, y0, tau):
        return y0 * np.exp(-x / tau)

    popt, pcov = curve_fit(law, t, y, p0=guess, maxfev=10000)
    residual = y - law(t, *popt)
    rss = float(residual @ residual)
    err = np.sqrt(np.diag(pcov))
    return DecayFit("exponential", {"initial": float(popt[0]), "time_constant": float(popt[1])},
                    {"initial": float(err[0]), "time_constant": float(err[1])},
                    float(np.sqrt(rss / t.size)), corrected_aic(rss, t.size, 2))
