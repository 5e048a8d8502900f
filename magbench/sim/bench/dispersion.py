r"""Seeded Monte Carlo of the bench over its uncertain inputs (:func:`monte_carlo`, with the
spreads of :class:`BenchDispersion`) and the error band it is scored by
(:func:`steady_error_band`).
"""

from dataclasses import dataclass

import numpy as np

from ..._validate import as_count, as_finite, as_in_range, as_nonnegative, as_positive, check_member_steps
from ..dispersion import member_generators
from .config import BenchErrors, BenchSetup  # noqa: F401 - BenchSetup: doctests
from .loop import simulate_bench

__all__ = ["BenchDispersion", "draw_bench_member", "monte_carlo", "steady_error_band"]


@dataclass(frozen=True)
class BenchDispersion:
    r"""Spreads of the bench's uncertain inputs over Monte Carlo members (:func:`monte_carlo`).

    Parameters
    ----------
    moment_tolerance : float
        Each coil's moment is uniform in nominal·(1 ± tolerance) [-], in [0, 0.5]
        (thesis: σ = 5 %).
    release_angle_spread : float
        Release angle uniform in centre ± spread [rad], in [0, π] (ours: the mock-up is
        turned by hand).
    release_rate_std : float
        Release rate normal about the mean release rate with this standard deviation
        [rad/s], ≥ 0 (ours).
    thread_stiffness_factor : float
        Thread stiffness log-uniform in nominal ×/÷ factor [-], in [1, 1e6] (ours).

    Notes
    -----
    Not in the thesis: the thesis reports single runs with unstated initial conditions.
    Chapter 4's values are :func:`magbench.chapters.ch04_mockup.bench_dispersion` of its inputs.
    """

    moment_tolerance: float
    release_angle_spread: float
    release_rate_std: float
    thread_stiffness_factor: float

    def __post_init__(self):
        as_in_range("moment_tolerance", self.moment_tolerance, 0.0, 0.5)
        as_in_range("release_angle_spread", self.release_angle_spread, 0.0, np.pi, unit="rad")
        as_nonnegative("release_rate_std", self.release_rate_std, unit="rad/s")
        as_in_range("thread_stiffness_factor", self.thread_stiffness_factor, 1.0, 1e6)


def monte_carlo(setup, psi_des, *, members, seed, duration, dispersion, record_interval=None, window=20.0,
                release_angle=None, release_rate=0.0, first_member=0):
    r"""Seeded Monte Carlo of the bench over its uncertain inputs.

    Parameters
    ----------
    setup : BenchSetup
        The nominal bench [-].
    psi_des : float
        Target angle [rad].
    members : int
        Number of members [-].
    seed : int
        The study's seed ≥ 0 [-]: member k draws its inputs, then its sensor noise, from
        ``numpy.random.default_rng([seed, k])``, so that a member's run does not depend on
        how many members run beside it.
    duration : float
        Simulated time [s].
    dispersion : BenchDispersion
        Spreads of the coils' moments [-], the release angle [rad] and rate [rad/s] and
        the thread's stiffness [-] over the members.
    record_interval : float, optional
        Spacing of the recorded traces [s].
    window : float, optional
        Final window of the error band [s].
    release_angle : float, optional
        Centre of the release angles [rad]; default ψ_des. A nominal run released at
        ``release_angle`` with ``release_rate`` is then the centre of the members' inputs.
    release_rate : float, optional
        Mean of the release rates [rad/s]; default 0.
    first_member : int, optional
        Index k of the first member [-] (a chunk of a larger study).

    Returns
    -------
    SimulationResult
        All members, as :func:`simulate_bench` returns them; ``params`` holds the drawn
        values.

    Notes
    -----
    Not in the thesis: the thesis reports single runs with unstated initial conditions.
    Each member's inputs are :func:`draw_bench_member`; its sensor noise follows from the
    same generator.

    Examples
    --------
    >>> from magbench.chapters.ch04_mockup import bench_setup
    >>> from magbench.params import chapter_parameters
    >>> s = bench_setup(chapter_parameters("ch04"))
    >>> d = BenchDispersion(moment_tolerance=0.05, release_angle_spread=0.5, release_rate_std=0.01,
    ...                     thread_stiffness_factor=3.0)
    >>> a = monte_carlo(s, 1.0, members=3, seed=1, duration=1.0, dispersion=d, window=0.5)
    >>> b = monte_carlo(s, 1.0, members=3, seed=1, duration=1.0, dispersion=d, window=0.5)
    >>> bool(np.array_equal(a.psi, b.psi))
    True
    """
    members = as_count("members", members)
    # Before the draws: a billion members would spend minutes drawing inputs first.
    check_member_steps(members, float(as_positive("duration", duration, unit="s")) / setup.sample_interval)
    centre = psi_des if release_angle is None else float(as_finite("release_angle", release_angle))
    mean_rate = float(as_finite("release_rate", release_rate))
    rngs = member_generators(seed, first_member, first_member + members)
    draws = [draw_bench_member(rng, dispersion, centre, mean_rate, setup.thread_stiffness) for rng in rngs]
    scale, angle, rate, stiffness = (np.array(d) for d in zip(*draws))
    return simulate_bench(setup, psi_des, duration=duration, release_angle=angle, release_rate=rate,
                          members=members, errors=BenchErrors(moment_scale=scale, thread_stiffness=stiffness),
                          rng=rngs, record_interval=record_interval, window=window)


def draw_bench_member(rng, dispersion, release_angle, release_rate, thread_stiffness):
    r"""One member's coil moments, release and thread stiffness, drawn from its own generator.

    Parameters
    ----------
    rng : numpy.random.Generator
        The member's generator [-] (:func:`magbench.sim.dispersion.member_generators`).
    dispersion : BenchDispersion
        The spreads [-].
    release_angle : float
        Centre of the release angles [rad].
    release_rate : float
        Mean of the release rates [rad/s].
    thread_stiffness : float
        Nominal thread stiffness [N·m/rad].

    Returns
    -------
    moment_scale : ndarray, shape (2,)
        Each coil's moment over its nominal, uniform in 1 ± tolerance [-].
    angle : float
        Release angle [rad].
    rate : float
        Release rate [rad/s].
    stiffness : float
        Thread stiffness, log-uniform in nominal ×/÷ factor [N·m/rad].

    Notes
    -----
    Not in the thesis: the thesis reports single runs with unstated initial conditions;
    the spreads are :class:`BenchDispersion`'s.

    Examples
    --------
    >>> d = BenchDispersion(0.05, 0.5, 0.01, 3.0)
    >>> s, a, r, k = draw_bench_member(np.random.default_rng([1, 0]), d, 1.0, 0.0, 1e-6)
    >>> bool(np.all(abs(s - 1) <= 0.05) and abs(a - 1) <= 0.5 and 1e-6 / 3 <= k <= 3e-6)
    True
    """
    if not isinstance(dispersion, BenchDispersion):
        raise ValueError(f"dispersion must be a BenchDispersion, got {type(dispersion).__name__}")
    tol, spread = float(dispersion.moment_tolerance), float(dispersion.release_angle_spread)
    factor = float(dispersion.thread_stiffness_factor)
    scale = rng.uniform(1.0 - tol, 1.0 + tol, 2)
    angle = release_angle + rng.uniform(-spread, spread)
    rate = release_rate + float(dispersion.release_rate_std) * rng.standard_normal()
    stiffness = thread_stiffness * np.exp(rng.uniform(-np.log(factor), np.log(factor)))
    return scale, angle, rate, stiffness


def steady_error_band(run, quantile=None):
    r"""The error band of a run: per member, or a quantile over members.

    Parameters
    ----------
    run : SimulationResult
        A run of :func:`simulate_bench` [-].
    quantile : float, optional
        Quantile over members in [0, 1] [-]; default: the per-member values.

    Returns
    -------
    ndarray or float
        max |ψ − ψ_des| over the final window [rad].

    Notes
    -----
    Not in the thesis: the thesis's "absolute orientation error of 10°" (thesis §4.4)
    has no stated metric; this is the one used here.

    Examples
    --------
    >>> from magbench.sim import SimulationResult
    >>> r = SimulationResult(np.zeros(1), np.zeros((0, 1, 2)), np.zeros((0, 1, 2)), np.zeros((0, 1, 2)),
    ...                      (), (), (), summary={"error_band": np.array([0.1, 0.3])})
    >>> round(float(steady_error_band(r, 0.5)), 6)
    0.2
    """
    if quantile is None:
        return run.error_band
    q = float(as_in_range("quantile", quantile, 0.0, 1.0))
    return float(np.quantile(run.error_band, q))
