"""Figures of chapter 4, estimation: the eq. (39) filter, heading from the magnetometer,
and the 3-D tilt filter on real recordings (BROAD)."""

from functools import lru_cache

import numpy as np

from ... import estimation
from ...hardware import sensors
from ...io import broad
from ...constants import MU_0
from . import CHAPTER
from .._base import chapter_parameters
from ..registry import FigureData, FigureParameter, FigureSpec, Series, register

SOURCE = "Bui (2016), thesis §4, eq. (39)"
GRAVITY = 9.80665


def _defaults():
    return chapter_parameters(CHAPTER.key, overrides="")


# --- eq. (39): what the coefficient A does -------------------------------------------------

VIBRATION_FREQUENCY = 7.0   # [Hz] of the simulated vibration (a fan or motor; assumed)


def single_axis_readings(sample_interval, gyro_bias, duration, amplitude, frequency,
                         vibration_amplitude, seed):
    """A tilting mock-up (roll θ = amplitude·sin 2πft) read by a simulated MPU-6050
    (:func:`magbench.hardware.sensors.roll_readings`, the vibration on its y axis).

    Returns time [s], true angle [rad], gyro rate [rad/s] and the accelerometer angle
    atan2(a_y, a_z) [rad]: the inputs of eq. (39).
    """
    n = int(round(duration / sample_interval))
    t = np.arange(n) * sample_interval
    angle = amplitude * np.sin(2 * np.pi * frequency * t)
    gyro, accel = sensors.roll_readings(angle, sample_interval, rng=np.random.default_rng(int(seed)),
                                        gyro_bias=gyro_bias, vibration_amplitude=[0.0, vibration_amplitude, 0.0],
                                        vibration_frequency=[0.0, VIBRATION_FREQUENCY, 0.0])
    return t, angle, gyro, np.arctan2(accel[:, 1], accel[:, 2])


def filter_error_terms(sample_interval, alpha, gyro_bias, vibration_amplitude, motion_amplitude):
    """Closed-form steady-state error terms of eq. (39) with the simulated MPU-6050
    (:func:`magbench.estimation.complementary_error_terms` with its datasheet noise):
    (bias offset, accelerometer white noise, vibration, gyro noise), each [rad]."""
    return estimation.complementary_error_terms(
        sample_interval, alpha, gyro_bias,
        sensors.noise_std_from_density(sensors.MPU6050_GYRO_NOISE_DENSITY, sample_interval),
        sensors.noise_std_from_density(sensors.MPU6050_ACCEL_NOISE_DENSITY, sample_interval),
        vibration_amplitude, VIBRATION_FREQUENCY, motion_amplitude)


def compute_filter_alpha(sample_interval, gyro_bias, alpha_low, alpha_high, duration, amplitude,
                         frequency, vibration_amplitude, seed):
    """RMS error of eq. (39) against A, simulated and in closed form, and example traces."""
    t, angle, gyro, acc_angle = single_axis_readings(sample_interval, gyro_bias, duration, amplitude,
                                                     frequency, vibration_amplitude, seed)
    alphas = np.linspace(0.80, 0.998, 67)
    settle = t > 10.0          # skip the start-up transient (a few τ at most)
    rms, mean_err = [], []
    for a in alphas:
        err = estimation.complementary_filter(gyro, acc_angle, sample_interval, a) - angle
        rms.append(np.sqrt(np.mean(err[settle] ** 2)))
        mean_err.append(np.mean(err[settle]))
    bias_term, acc_term, vib_term, gyro_term = filter_error_terms(
        sample_interval, alphas, gyro_bias, vibration_amplitude, amplitude)
    closed = np.sqrt(bias_term**2 + acc_term**2 + vib_term**2 + gyro_term**2)
    series = [Series("error against A", {
        "alpha": ("1", alphas), "tau": ("s", estimation.complementary_time_constant(sample_interval, alphas)),
        "rms_error": ("rad", np.array(rms)), "mean_error": ("rad", np.array(mean_err)),
        "closed_form_rms": ("rad", closed), "bias_term": ("rad", bias_term),
        "accel_noise_term": ("rad", np.hypot(acc_term, vib_term)), "gyro_noise_term": ("rad", gyro_term)})]
    window = (t >= 20.0) & (t < 30.0)
    for a in (alpha_low, alpha_high):
        est = estimation.complementary_filter(gyro, acc_angle, sample_interval, a)
        series.append(Series(f"A_f = {a:g}", {"time": ("s", t[window]), "estimate": ("rad", est[window])}))
    series.append(Series("truth and accelerometer", {
        "time": ("s", t[window]), "angle": ("rad", angle[window]), "accel_angle": ("rad", acc_angle[window])}))
    return FigureData("ch04-filter-alpha", "", "", {}, series,
                      extra={"alpha_range": (alpha_low, alpha_high)})


def plot_filter_alpha(data):
    """Left: traces for the thesis's two A; right: RMS error against A with the closed form."""
    import matplotlib.pyplot as plt

    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(7.0, 4.7))
    truth = data.series[-1].columns
    ax1.plot(truth["time"][1], np.degrees(truth["accel_angle"][1]), color="0.75", lw=0.6,
             label="accelerometer angle")
    ax1.plot(truth["time"][1], np.degrees(truth["angle"][1]), "k", lw=1.2, label="true angle")
    for s, color in zip(data.series[1:3], ("C0", "C3")):
        ax1.plot(s.columns["time"][1], np.degrees(s.columns["estimate"][1]), color=color, lw=1,
                 label="eq. (39), " + s.label.replace("A_f", "$A_f$"))
    ax1.set_xlabel("time [s]")
    ax1.set_ylabel("roll angle [°]")
    ax1.legend(fontsize=7, loc="upper right")
    c = data.series[0].columns
    alpha = c["alpha"][1]
    ax2.semilogy(alpha, np.degrees(c["rms_error"][1]), "k", lw=1.5, label="simulated RMS error")
    ax2.semilogy(alpha, np.degrees(c["closed_form_rms"][1]), "C1--", lw=1.2, label="closed form")
    ax2.semilogy(alpha, np.degrees(c["bias_term"][1]), "C3:", label=r"gyro offset × $\tau_f$")
    ax2.semilogy(alpha, np.degrees(c["accel_noise_term"][1]), "C0:", label="accelerometer noise")
    ax2.semilogy(alpha, np.degrees(c["gyro_noise_term"][1]), "C2:", label="gyro noise")
    lo, hi = data.extra["alpha_range"]
    ax2.axvspan(lo, hi, color="0.9", label="thesis's range")
    ax2.set_xlabel("filter coefficient $A_f$ [-]")
    ax2.set_ylabel("error [°]")
    ax2.legend(fontsize=7, loc="lower left")
    top = ax2.secondary_xaxis("top", functions=(
        lambda a: a * data.parameters["sample_interval"] / np.clip(1 - a, 1e-9, None),
        lambda tau: tau / (tau + data.parameters["sample_interval"])))
    top.set_xlabel(r"time constant $\tau_f = A_f\,\Delta t/(1 - A_f)$ [s]")
    # τ_f grows as 1/(1 − A_f): ticks a factor of 2–2.5 apart stay apart on the A_f axis.
    top.set_xticks([0.05, 0.1, 0.2, 0.5], ["0.05", "0.1", "0.2", "0.5"])
    return fig


def _alpha_parameters():
    p = _defaults()
    return {
        "sample_interval": FigureParameter(p["filter_sample_interval"], "s", "filter loop period (assumed)"),
        "gyro_bias": FigureParameter(p["gyro_residual_bias"], "rad/s", "residual gyro bias (assumed)"),
        "alpha_low": FigureParameter(p["filter_coefficient_low"], "1", "thesis's lower A"),
        "alpha_high": FigureParameter(p["filter_coefficient_high"], "1", "thesis's upper A"),
        "duration": FigureParameter(120.0, "s", "simulated time", high=1e4),
        "amplitude": FigureParameter(np.radians(20.0), "rad", "roll amplitude of the motion"),
        "frequency": FigureParameter(0.2, "Hz", "roll frequency"),
        "vibration_amplitude": FigureParameter(0.5, "m/s^2", "7 Hz vibration on the accelerometer"),
        "seed": FigureParameter(4.0, "1", "random seed of the sensor noise", whole=True),
    }


register(FigureSpec("ch04-filter-alpha", "Eq. (39): error and time constant against the coefficient A_f",
                    SOURCE, compute_filter_alpha, plot_filter_alpha, _alpha_parameters))


# --- heading: gravity cannot see it, the magnetometer can -----------------------------------

def heading_readings(sample_interval, gyro_bias, field, duration, seed):
    """The mock-up turning about the vertical, read by simulated MPU-6050 and HMC5883L
    (:func:`magbench.hardware.sensors.heading_readings`).

    The motion is a decaying swing ψ(t) = (π/2) e^{−t/100 s} cos(2πt/30 s) (the thesis's
    ψ0 = π/2), the field is horizontal with magnitude ``field`` plus no vertical part.
    Returns t, ψ, gyro z [rad/s], accelerometer readings (N, 3) [m/s²], magnetometer (N, 3) [T].
    """
    n = int(round(duration / sample_interval))
    t = np.arange(n) * sample_interval
    psi = 0.5 * np.pi * np.exp(-t / 100.0) * np.cos(2 * np.pi * t / 30.0)
    gyro, accel, mag = sensors.heading_readings(psi, field, sample_interval, rng=np.random.default_rng(int(seed)),
                                                gyro_bias=gyro_bias)
    return t, psi, gyro, accel, mag


def compute_heading_fusion(sample_interval, gyro_bias, field_h, alpha, duration, seed):
    """Heading by gyro alone, eq. (39) with an accelerometer 'angle', and eq. (39) with the magnetometer."""
    field = MU_0 * field_h
    t, psi, gyro, accel, mag = heading_readings(sample_interval, gyro_bias, field, duration, seed)
    gyro_only = estimation.complementary_filter(gyro, psi[0] * np.ones_like(psi), sample_interval, 1.0,
                                                initial_angle=psi[0])
    # What the thesis's recipe gives about the vertical: an accelerometer "angle" in the
    # horizontal plane, atan2(a_y, a_x), which is the direction of noise only.
    accel_angle = np.arctan2(accel[:, 1], accel[:, 0])
    # (Not unwrapped: unwrapping a noise direction makes it a random walk of many turns.)
    with_accel = estimation.complementary_filter(gyro, accel_angle, sample_interval, alpha)
    mag_heading = np.unwrap(estimation.magnetometer_heading(mag))
    with_mag = estimation.complementary_filter(gyro, mag_heading, sample_interval, alpha)
    # The accelerometer's true input is identical for every heading: spread of the specific
    # force R_z(ψ)ᵀ(0, 0, g) over the whole motion, exactly zero.
    from scipy.spatial.transform import Rotation
    force = Rotation.from_rotvec(np.outer(psi, [0.0, 0.0, 1.0])).inv().apply([0.0, 0.0, GRAVITY])
    series = [Series("heading", {
        "time": ("s", t), "true": ("rad", psi), "gyro_only": ("rad", gyro_only),
        "accel_reference": ("rad", with_accel), "magnetometer_reference": ("rad", with_mag),
        "magnetometer_heading": ("rad", mag_heading)})]
    return FigureData("ch04-heading-fusion", "", "", {}, series,
                      extra={"accel_spread": float(np.ptp(force, axis=0).max())})


def plot_heading_fusion(data):
    """Top: headings; bottom: their errors."""
    import matplotlib.pyplot as plt

    c = data.series[0].columns
    t = c["time"][1]
    fig, (ax1, ax2) = plt.subplots(2, 1, figsize=(7.0, 6.2), sharex=True)
    ax1.plot(t, np.degrees(c["magnetometer_heading"][1]), color="0.8", lw=0.5, label="magnetometer heading")
    ax1.plot(t, np.degrees(c["true"][1]), "k", lw=1.2, label="true ψ")
    labels = {"gyro_only": ("gyro integral (A_f = 1)", "C3"),
              "accel_reference": ("eq. (39) with an accelerometer angle", "C1"),
              "magnetometer_reference": ("eq. (39) with the magnetometer heading", "C0")}
    for key, (label, color) in labels.items():
        ax1.plot(t, np.degrees(c[key][1]), color=color, lw=1, label=label)
        ax2.plot(t, np.degrees(c[key][1] - c["true"][1]), color=color, lw=1, label=label)
    ax1.set_ylabel("heading ψ [°]")
    ax1.legend(fontsize=7, loc="upper right")
    ax2.set_xlabel("time [s]")
    ax2.set_ylabel("error [°]")
    ax2.set_yscale("symlog", linthresh=1.0)
    return fig


def _heading_parameters():
    p = _defaults()
    return {
        "sample_interval": FigureParameter(p["filter_sample_interval"], "s", "filter loop period (assumed)"),
        "gyro_bias": FigureParameter(p["gyro_residual_bias"], "rad/s", "residual gyro bias (assumed)"),
        "field_h": FigureParameter(p["sim_design_h"], "A/m", "simulator's field (design value)"),
        "alpha": FigureParameter(p["filter_coefficient_high"], "1", "eq. (39) coefficient A"),
        "duration": FigureParameter(300.0, "s", "simulated time", high=1e4),
        "seed": FigureParameter(5.0, "1", "random seed of the sensor noise", whole=True),
    }


register(FigureSpec("ch04-heading-fusion", "Heading about the vertical: gyro, accelerometer, magnetometer",
                    SOURCE, compute_heading_fusion, plot_heading_fusion, _heading_parameters))


# --- BROAD: the 3-D tilt filter on real recordings ------------------------------------------

BROAD_SOURCE = "Laidig et al. (2021), BROAD dataset (CC BY 4.0); not in the thesis"


@lru_cache(maxsize=8)
def _trial(name):
    return broad.load_trial(name)


def _missing(figure_id):
    return FigureData(figure_id, "", "", {}, [Series("no BROAD trials found", {"trials": ("1", [0.0])})],
                      extra={"missing": broad.MISSING_MESSAGE})


def _plot_missing(data):
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(7.0, 2.1))
    ax.axis("off")
    ax.text(0.5, 0.5, data.extra["missing"], ha="center", va="center", wrap=True, fontsize=9)
    return fig


def compute_broad_tilt(tau, order):
    """Inclination error over time for one trial, and the RMSE of each method on every trial."""
    names = broad.available_trials()
    if not names:
        return _missing("ch04-broad-tilt")
    trial = _trial(names[0])
    methods = {
        "accelerometer only": estimation.accelerometer_tilt(trial.accel),
        "complementary_tilt": estimation.complementary_tilt(trial.gyro, trial.accel, trial.dt,
                                                            tau=tau, order=int(order)),
    }
    methods["gyro only"] = estimation.strapdown_orientation(trial.gyro, trial.dt,
                                                            methods["accelerometer only"][0])
    t = np.arange(len(trial.gyro)) * trial.dt
    step = max(1, int(round(0.05 / trial.dt)))      # plot at 20 Hz
    errors = {label: broad.inclination_error(q, trial.reference)[::step] for label, q in methods.items()}
    # Samples where the optical reference is missing (NaN) have no error; leave them out.
    known = np.all(np.isfinite(trial.reference[::step]), axis=1)
    columns = {"time": ("s", t[::step][known]),
               "movement": ("1", trial.movement[::step][known].astype(float))}
    for label, err in errors.items():
        columns[label] = ("rad", err[known])
    series = [Series(trial.name, columns)]
    table = {}
    for name in names:
        table[name] = broad.evaluate_trial(_trial(name), tau=tau, order=int(order))
    series.append(Series("rmse", {
        "complementary": ("rad", [table[n]["complementary"] for n in names]),
        "accelerometer": ("rad", [table[n]["accelerometer"] for n in names]),
        "gyro": ("rad", [table[n]["gyro"] for n in names])}))
    return FigureData("ch04-broad-tilt", "", "", {}, series, extra={"trials": names, "table": table})


def plot_broad_tilt(data):
    """Left: inclination error against time on one trial; right: RMSE of each method per trial."""
    import matplotlib.pyplot as plt

    if "missing" in data.extra:
        return _plot_missing(data)
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(7.0, 4.8), gridspec_kw={"width_ratios": [1.6, 1]})
    c = data.series[0].columns
    t = c["time"][1]
    colors = {"accelerometer only": "C1", "gyro only": "C3", "complementary_tilt": "C0"}
    shown = {"complementary_tilt": "3-D complementary filter"}
    for label, color in colors.items():
        ax1.plot(t, np.degrees(c[label][1]), color=color, lw=0.8, label=shown.get(label, label))
    moving = c["movement"][1] > 0.5
    ax1.fill_between(t, 0, 1, where=moving, color="0.92", transform=ax1.get_xaxis_transform(),
                     label="movement phase (scored)")
    ax1.set_yscale("log")
    ax1.set_ylim(1e-2, 180)
    ax1.set_xlabel("time [s]")
    ax1.set_ylabel("inclination error [°]")
    ax1.set_title(data.series[0].label, fontsize=9)
    ax1.legend(fontsize=7, loc="lower right")
    r = data.series[1].columns
    names = data.extra["trials"]
    x = np.arange(len(names))
    for k, (key, label) in enumerate((("accelerometer", "accelerometer only"), ("gyro", "gyro only"),
                                      ("complementary", "complementary_tilt"))):
        ax2.bar(x + (k - 1) * 0.27, np.degrees(r[key][1]), 0.27, color=colors[label], label=shown.get(label, label))
    ax2.set_yscale("log")
    ax2.set_xticks(x, [n[:2] for n in names])
    ax2.set_xlabel("BROAD trial")
    ax2.set_ylabel("inclination RMSE, movement phases [°]")
    ax2.legend(fontsize=7)
    return fig


def compute_tau_sensitivity(tau_min, tau_max, default_tau):
    """Inclination RMSE of complementary_tilt against tau, first and second order, every trial."""
    names = broad.available_trials()
    if not names:
        return _missing("ch04-tau-sensitivity")
    taus = np.geomspace(tau_min, tau_max, 11)
    series = []
    for name in names:
        trial = _trial(name)
        columns = {"tau": ("s", taus)}
        for order in (1, 2):
            rmse = []
            for tau in taus:
                q = estimation.complementary_tilt(trial.gyro, trial.accel, trial.dt, tau=tau, order=order)
                rmse.append(broad.inclination_rmse(q, trial.reference, trial.movement))
            columns[f"order_{order}"] = ("rad", np.array(rmse))
        series.append(Series(name, columns))
    return FigureData("ch04-tau-sensitivity", "", "", {}, series, extra={"default_tau": default_tau})


def plot_tau_sensitivity(data):
    """RMSE against tau on log axes, one colour per trial, solid second order, dashed first."""
    import matplotlib.pyplot as plt

    if "missing" in data.extra:
        return _plot_missing(data)
    from matplotlib.lines import Line2D

    fig, ax = plt.subplots(figsize=(7.0, 4.0))
    colors = plt.get_cmap("tab20")
    for k, s in enumerate(data.series):
        c = s.columns
        color = colors(k % 20)
        ax.loglog(c["tau"][1], np.degrees(c["order_2"][1]), "o-", color=color, ms=2.5, lw=1)
        ax.loglog(c["tau"][1], np.degrees(c["order_1"][1]), "--", color=color, lw=0.8)
    ax.axvline(data.extra["default_tau"], color="0.3", lw=1, ls=":")
    ax.set_xlabel(r"accelerometer time constant $\tau_f$ [s]")
    ax.set_ylabel("inclination RMSE [°]")
    ax.set_title(f"one colour per BROAD trial ({len(data.series)} trials)", fontsize=8)
    # One legend entry per line style: thirty per-trial entries covered the plot.
    ax.legend([Line2D([], [], color="k", marker="o", ms=2.5, lw=1), Line2D([], [], color="k", ls="--", lw=0.8),
               Line2D([], [], color="0.3", ls=":", lw=1)],
              ["second-order low-pass", "first-order low-pass", r"default $\tau_f$"], fontsize=7, loc="upper right")
    return fig


register(FigureSpec("ch04-broad-tilt", "The 3-D complementary filter on BROAD: inclination error and RMSE",
                    BROAD_SOURCE, compute_broad_tilt, plot_broad_tilt,
                    {"tau": FigureParameter(3.0, "s", "accelerometer time constant (default)"),
                     "order": FigureParameter(2.0, "1", "low-pass order (1 or 2)", whole=True)}, slow=True))
register(FigureSpec("ch04-tau-sensitivity", "Sensitivity of the BROAD RMSE to the time constant",
                    BROAD_SOURCE, compute_tau_sensitivity, plot_tau_sensitivity,
                    {"tau_min": FigureParameter(0.3, "s", "smallest τ"),
                     "tau_max": FigureParameter(30.0, "s", "largest τ"),
                     "default_tau": FigureParameter(3.0, "s", "the filter's default τ")}, slow=True))


# --- BROAD: the offline (post-processing) estimator -----------------------------------------

#: The time constants the offline sweep evaluates [s]: the default 3 s, ±50 %, and a
#: factor of three either way (a log-spaced grid around VQF's published default).
OFFLINE_TAUS = (1.0, 1.5, 2.0, 3.0, 4.5, 6.0, 9.0)


def _vqf_estimates(trial):
    """vqf's causal and offline 6-D quaternions for one trial, or None without the package."""
    try:
        import vqf
    except ImportError:
        return None
    gyro, accel = np.ascontiguousarray(trial.gyro), np.ascontiguousarray(trial.accel)
    return {"vqf": vqf.VQF(trial.dt).updateBatch(gyro, accel)["quat6D"],
            "vqf_offline": vqf.offlineVQF(gyro, accel, None, trial.dt)["quat6D"]}


def compute_offline_tilt(tau):
    """Inclination RMSE of six estimators on every trial, and of offline_tilt against its τ.

    The six: accelerometer alone, gyro alone (from the first accelerometer tilt),
    complementary_tilt (causal, defaults), VQF causal and VQF offline (the peer package
    ``vqf``, its defaults; NaN when it is not installed), offline_tilt with ``tau``.
    """
    names = broad.available_trials()
    if not names:
        return _missing("ch04-offline-tilt")
    keys = ("accelerometer", "gyro", "complementary", "vqf", "vqf_offline", "offline")
    rmse = {k: [] for k in keys}
    sweep = {t: [] for t in OFFLINE_TAUS}
    for name in names:
        trial = _trial(name)
        score = lambda q: broad.inclination_rmse(q, trial.reference, trial.movement)  # noqa: E731
        accel_only = estimation.accelerometer_tilt(trial.accel)
        rmse["accelerometer"].append(score(accel_only))
        rmse["gyro"].append(score(estimation.strapdown_orientation(trial.gyro, trial.dt, accel_only[0])))
        rmse["complementary"].append(score(estimation.complementary_tilt(trial.gyro, trial.accel, trial.dt)))
        peer = _vqf_estimates(trial)
        rmse["vqf"].append(score(peer["vqf"]) if peer else np.nan)
        rmse["vqf_offline"].append(score(peer["vqf_offline"]) if peer else np.nan)
        rmse["offline"].append(score(estimation.offline_tilt(trial.gyro, trial.accel, trial.dt, tau=tau)))
        for t in OFFLINE_TAUS:
            sweep[t].append(rmse["offline"][-1] if t == tau else
                            score(estimation.offline_tilt(trial.gyro, trial.accel, trial.dt, tau=t)))
    series = [Series("rmse", {k: ("rad", np.array(v)) for k, v in rmse.items()}),
              Series("tau sweep", {"tau": ("s", np.array(OFFLINE_TAUS)),
                                   **{f"trial_{i}": ("rad", np.array([sweep[t][i] for t in OFFLINE_TAUS]))
                                      for i in range(len(names))}})]
    return FigureData("ch04-offline-tilt", "", "", {}, series, extra={"trials": names})


def plot_offline_tilt(data):
    """Left: RMSE per trial of the four gyro+accelerometer estimators; right: mean RMSE against τ."""
    import matplotlib.pyplot as plt

    if "missing" in data.extra:
        return _plot_missing(data)
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(7.0, 4.3), gridspec_kw={"width_ratios": [1.7, 1]},
                                   layout="constrained")
    r = data.series[0].columns
    names = data.extra["trials"]
    x = np.arange(len(names))
    styles = (("complementary", "3-D complementary filter (causal)", "C0", "o", "none"),
              ("vqf", "VQF (causal)", "C2", "s", "none"),
              ("vqf_offline", "VQF offline", "C1", "D", "none"),
              ("offline", "whole-record smoother", "C3", "o", "C3"))
    for k, (key, label, color, marker, face) in enumerate(styles):
        values = np.degrees(r[key][1])
        if np.all(np.isnan(values)):
            continue
        ax1.plot(x + (k - 1.5) * 0.12, values, marker, color=color, mfc=face, ms=4.5, label=label)
    ax1.set_xticks(x, [n[:2] for n in names])
    ax1.set_xlabel("BROAD trial")
    ax1.set_ylabel("inclination RMSE, movement phases [°]")
    ax1.set_ylim(0, None)
    ax1.legend(fontsize=7, loc="upper left")
    sweep = data.series[1].columns
    taus = sweep["tau"][1]
    per_trial = np.degrees(np.array([sweep[f"trial_{i}"][1] for i in range(len(names))]))
    ax2.plot(taus, per_trial.T, color="0.8", lw=0.7)
    ax2.plot(taus, per_trial.mean(axis=0), "o-", color="C3", lw=1.5, ms=4, label="mean over trials")
    default = data.parameters.get("tau", 3.0)
    ax2.axvspan(0.5 * default, 1.5 * default, color="0.93", label=r"default $\tau_f$ ±50 %")
    ax2.set_xscale("log")
    ax2.set_xticks(taus, [f"{t:g}" for t in taus])
    ax2.minorticks_off()
    ax2.set_xlabel(r"smoother time constant $\tau_f$ [s]")
    ax2.set_ylabel("inclination RMSE [°]")
    ax2.set_ylim(0, None)
    ax2.legend(fontsize=7, loc="upper right")
    return fig


register(FigureSpec("ch04-offline-tilt", "The whole-record smoother on BROAD beside the causal filters and VQF",
                    BROAD_SOURCE, compute_offline_tilt, plot_offline_tilt,
                    {"tau": FigureParameter(3.0, "s", "offline_tilt's time constant (default)")}, slow=True))


# --- BROAD: what limits the offline estimator (a diagnostic of the comparison's timing) -----

def compute_offline_timing(earliest_shift, latest_shift, shift_step):
    """offline_tilt's inclination RMSE with its estimate read a fraction of a sample later.

    Not a metric: a diagnostic of the comparison. The estimate at time t_k + s·dt
    (spherical interpolation between neighbouring samples) is compared with the optical
    reference at t_k, for shifts s from ``earliest_shift`` to ``latest_shift`` [samples].
    s = 0 is BROAD's metric. A lag of the IMU's clock behind the optical system shows as a
    minimum at s > 0 on every trial; the RMSE at the minimum is what is left when timing is
    removed (measured on these trials; the estimator is not changed by it).
    """
    from scipy.spatial.transform import Rotation, Slerp

    if latest_shift <= earliest_shift or shift_step <= 0 or (latest_shift - earliest_shift) / shift_step > 200:
        raise ValueError("shifts must satisfy earliest_shift < latest_shift and 0 < shift_step, with at most 200 "
                         f"steps, got {earliest_shift:g}, {latest_shift:g}, {shift_step:g}")
    names = broad.available_trials()
    if not names:
        return _missing("ch04-offline-timing")
    shifts = np.arange(earliest_shift, latest_shift + 0.5 * shift_step, shift_step)
    per_trial = []
    for name in names:
        trial = _trial(name)
        q = estimation.offline_tilt(trial.gyro, trial.accel, trial.dt)
        k = np.arange(len(q), dtype=float)
        between = Slerp(k, Rotation.from_quat(q, scalar_first=True))
        per_trial.append([broad.inclination_rmse(between(np.clip(k + s, 0.0, k[-1])).as_quat(scalar_first=True),
                                                 trial.reference, trial.movement) for s in shifts])
    per_trial = np.array(per_trial)
    series = [Series("shift", {"shift": ("1", shifts),
                               **{f"trial_{i}": ("rad", per_trial[i]) for i in range(len(names))}})]
    return FigureData("ch04-offline-timing", "", "", {}, series,
                      extra={"trials": names, "sample_interval": _trial(names[0]).dt})


def plot_offline_timing(data):
    """RMSE against the shift: each trial in grey, the mean in red, the metric's s = 0 marked."""
    import matplotlib.pyplot as plt

    if "missing" in data.extra:
        return _plot_missing(data)
    cols = data.series[0].columns
    shifts = cols["shift"][1]
    per_trial = np.degrees(np.array([cols[f"trial_{i}"][1] for i in range(len(data.extra["trials"]))]))
    mean = per_trial.mean(axis=0)
    best = int(np.argmin(mean))
    fig, ax = plt.subplots(figsize=(6.0, 3.6), layout="constrained")
    ax.plot(shifts, per_trial.T, color="0.8", lw=0.7)
    ax.plot([], [], color="0.8", lw=0.7, label="each trial")
    ax.plot(shifts, mean, "o-", color="C3", ms=3.5, lw=1.5, label="mean over trials")
    ax.axvline(0.0, color="0.3", lw=0.8, ls="--", label="s = 0: BROAD's metric")
    lag_ms = shifts[best] * data.extra["sample_interval"] * 1e3
    ax.plot(shifts[best], mean[best], "v", color="k", ms=7,
            label=f"smallest mean: s = {shifts[best]:+.2f} samples ({lag_ms:+.1f} ms)")
    ax.set_xlabel("estimate read s samples after the reference's time stamp")
    ax.set_ylabel("inclination RMSE, movement phases [°]")
    ax.set_ylim(0, None)
    ax.legend(fontsize=7, loc="upper left")
    return fig


register(FigureSpec("ch04-offline-timing", "What limits the whole-record smoother on BROAD: the timing of the comparison",
                    BROAD_SOURCE, compute_offline_timing, plot_offline_timing,
                    {"earliest_shift": FigureParameter(-1.0, "1", "first shift [samples]"),
                     "latest_shift": FigureParameter(1.5, "1", "last shift [samples]"),
                     "shift_step": FigureParameter(0.125, "1", "spacing of the shifts [samples]")}, slow=True))
