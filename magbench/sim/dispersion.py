r"""Dispersion studies: Monte Carlo over a study's uncertain inputs, one random stream per
member, run in chunks on any :class:`concurrent.futures.Executor`.

A study (:class:`DispersionStudy`, registered by its chapter) names its dispersed inputs and
their distributions, draws one member's inputs from that member's own generator
(:func:`member_generators`: ``numpy.random.default_rng([seed, k])`` for member k), and runs a
chunk of members through the library's vectorised simulators. Because no member draws from
another's stream and the simulators compute each member on its own, a study gives the same
rows, bit for bit, serial or parallel, for any chunk size and any number of workers:
:func:`run_dispersion` only decides where the chunks run. :func:`dispersion_statistics`
puts bootstrap confidence intervals (:func:`scipy.stats.bootstrap`) on the statistics of the
outcomes.

Not in the sources: the sources report single runs or small seeded sets; an engineer's
dispersion analysis is 10⁴–10⁶ members with intervals on its statistics.
"""

import os
from concurrent.futures import FIRST_COMPLETED, Executor, wait
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from .._validate import as_count, shown

__all__ = ["DispersedInput", "Outcome", "DispersionStudy", "DispersionTable", "DispersionError",
           "member_generators", "run_dispersion", "dispersion_statistics", "STATISTICS", "DEFAULT_CHUNK"]

#: Members per chunk by default: a call of the vectorised simulators costs a fixed ~0.3–0.9 s
#: (set-up, tabulating the field), and the cost per member levels off near 1,000 members.
DEFAULT_CHUNK = 1000

#: The statistics :func:`dispersion_statistics` reports: name → quantile over members.
STATISTICS = {"median": 0.5, "p95": 0.95}


@dataclass(frozen=True)
class DispersedInput:
    """One dispersed input of a study.

    Attributes
    ----------
    name : str
        The input's name [-].
    unit : str
        SI unit of its columns [-].
    columns : tuple of str
        Its columns in the table (one per component) [-].
    distribution : str
        How it is drawn, naming the parameters that set the distribution [-].
    parameters : tuple of str
        Those parameters (names in the chapter's parameter set) [-].
    """

    name: str
    unit: str
    columns: tuple
    distribution: str
    parameters: tuple = ()


@dataclass(frozen=True)
class Outcome:
    """One outcome of a study: a number per member, with its unit and meaning [-]."""

    name: str
    unit: str
    description: str


@dataclass(frozen=True)
class DispersionStudy:
    """A dispersion study: what is dispersed, what is measured, and how one chunk runs.

    Attributes
    ----------
    name : str
        The study's name (``magbench montecarlo NAME``) [-].
    description : str
        One sentence: the scenario [-].
    chapter : str
        The chapter whose parameter set holds the study's parameters [-].
    inputs : tuple of DispersedInput
        The dispersed inputs [-].
    outcomes : tuple of Outcome
        The outcomes [-].
    parameters : callable
        ``parameters(overrides) -> dict``: the chapter's parameters [SI] with ``overrides``
        (a mapping of names to SI values) applied; an unknown name raises ValueError.
    draw : callable
        ``draw(params, rng) -> dict``: one member's inputs, column → float [SI], drawn from
        that member's generator.
    simulate : callable
        ``simulate(params, columns, rngs) -> dict``: the outcomes [SI], outcome name → array
        (members,), of the members whose input columns (arrays (members,)) are given;
        ``rngs`` are the members' generators after their draws (for sensor noise).

    Notes
    -----
    The three callables must be module-level functions, so that a study pickles by
    reference to a process pool or a Dask worker.
    """

    name: str
    description: str
    chapter: str
    inputs: tuple
    outcomes: tuple
    parameters: object = field(repr=False)
    draw: object = field(repr=False)
    simulate: object = field(repr=False)

    @property
    def input_columns(self):
        """The table's input columns, in order [-]."""
        return tuple(c for item in self.inputs for c in item.columns)

    @property
    def columns(self):
        """All columns of the table: ``member``, the inputs', the outcomes [-]."""
        return ("member",) + self.input_columns + tuple(o.name for o in self.outcomes)


class DispersionError(RuntimeError):
    """A chunk of a dispersion study failed twice; the message names the chunk."""


@dataclass
class DispersionTable:
    """The rows of a dispersion study, one per member, ordered by member index.

    Attributes
    ----------
    study : DispersionStudy
        The study [-].
    seed : int
        The study's seed [-].
    parameters : dict
        The parameters the members were drawn and run with [SI].
    columns : dict of str to ndarray
        ``member`` (int), each input column and each outcome [SI]. A run that wrote its
        rows to a file keeps only ``member`` and the outcomes here.
    path : Path or None
        The CSV file the rows were written to [-].
    """

    study: DispersionStudy
    seed: int
    parameters: dict
    columns: dict
    path: Path | None = None

    @property
    def members(self):
        """Number of members [-]."""
        return int(self.columns["member"].size)

    def __getitem__(self, name):
        return self.columns[name]


def member_generators(seed, start, stop):
    r"""The random generators of members ``start`` … ``stop − 1`` of a seeded study.

    Parameters
    ----------
    seed : int
        The study's seed, ≥ 0 [-].
    start, stop : int
        First member and one past the last, 0 ≤ start ≤ stop [-].

    Returns
    -------
    list of numpy.random.Generator
        ``numpy.random.default_rng([seed, k])`` for each member k: a stream of its own
        (:class:`numpy.random.SeedSequence` of the pair), whatever else is drawn around it.

    Notes
    -----
    Not in the sources: numpy's recommended way to give parallel work independent
    streams (a ``SeedSequence`` of an entropy tuple).

    Examples
    --------
    >>> a = member_generators(7, 0, 3)[2].normal()
    >>> b = member_generators(7, 2, 3)[0].normal()
    >>> a == b
    True
    """
    s = as_count("seed", seed, minimum=0)
    first, last = as_count("start", start, minimum=0), as_count("stop", stop, minimum=0)
    if last < first:
        raise ValueError(f"stop must be >= start ({first}), got {last}")
    return [np.random.default_rng([s, k]) for k in range(first, last)]


def _chunk_rows(study, params, seed, start, stop):
    """The rows of members ``start`` … ``stop − 1``: member index, input columns, outcomes."""
    rngs = member_generators(seed, start, stop)
    draws = [study.draw(params, rng) for rng in rngs]
    columns = {name: np.array([float(d[name]) for d in draws]) for name in study.input_columns}
    outcomes = study.simulate(params, columns, rngs)
    rows = {"member": np.arange(start, stop)}
    rows.update(columns)
    for o in study.outcomes:
        value = np.asarray(outcomes[o.name], dtype=float)
        if value.shape != (stop - start,):
            raise ValueError(f"study {study.name}: outcome {o.name} has shape {value.shape}, "
                             f"expected ({stop - start},)")
        rows[o.name] = value
    return rows


def _csv_lines(rows, names):
    """CSV lines of a chunk's rows: the member index as an integer, floats by ``repr``
    (the shortest string that reads back to the same float)."""
    cols = [rows[n].tolist() for n in names]
    return "".join(",".join([str(int(r[0]))] + [repr(float(x)) for x in r[1:]]) + "\n" for r in zip(*cols))


def _checked_overrides(overrides):
    out = {}
    for name, value in dict(overrides or {}).items():
        try:
            number = float(value)
        except (TypeError, ValueError):
            raise ValueError(f"override {name} must be a number (SI), got {shown(value)}") from None
        if not np.isfinite(number):
            raise ValueError(f"override {name} must be finite, got {shown(value)}")
        out[str(name)] = number
    return out


def run_dispersion(study, members, seed, executor=None, chunk=None, overrides=None, *, out=None, progress=None,
                   until_ci=None, in_flight=None):
    r"""Run a dispersion study: ``members`` members in chunks, on ``executor`` or here.

    Parameters
    ----------
    study : DispersionStudy
        The study [-].
    members : int
        Number of members, ≥ 1 (with ``until_ci``: the most) [-].
    seed : int
        The study's seed, ≥ 0; member k draws from ``default_rng([seed, k])`` [-].
    executor : concurrent.futures.Executor, optional
        Where the chunks run: a process pool, ``dask.distributed.Client(...).get_executor()``,
        …; default this process, one chunk after another [-].
    chunk : int, optional
        Members per chunk, ≥ 1 [-]; default :data:`DEFAULT_CHUNK`. The rows do not depend on it.
    overrides : mapping, optional
        Parameter name → SI value, applied to the study's chapter parameters [SI].
    out : str or Path, optional
        CSV file to write: a header line, then one row per member ordered by member index,
        floats by ``repr``. Rows are written chunk by chunk (memory stays flat) to
        ``out + ".part"``, which replaces ``out`` only when the study is complete [-].
    progress : callable, optional
        Called as ``progress(done)`` with the number of members finished (in order) [-].
    until_ci : float, optional
        Stop at the first chunk boundary where every statistic's 95 % interval
        (:func:`dispersion_statistics`) is narrower than ``until_ci`` times its value [-].
    in_flight : int, optional
        Most chunks submitted and not yet written [-]; default 16.

    Returns
    -------
    DispersionTable
        The rows (with ``out``: the member index and the outcomes; the inputs are in the file).

    Raises
    ------
    DispersionError
        A chunk failed, was submitted again, and failed again (or could not be submitted).

    Notes
    -----
    Not in the sources: a dispersion analysis as an engineer runs it. A chunk that fails is
    submitted once more; a process pool whose worker died is
    broken, so the second submission fails too unless the executor replaces its workers
    (as a Dask cluster does; :class:`magbench.cli` gives its local pool that property).

    Examples
    --------
    >>> from magbench.chapters import dispersion_study
    >>> study = dispersion_study("detumble")
    >>> t = run_dispersion(study, 3, seed=1, overrides={"envelope_duration": 600.0})
    >>> t.members, t.columns["member"].tolist(), t.study.columns[-3:]
    (3, [0, 1, 2], ('detumble_time', 'held_time', 'final_rate'))
    >>> u = run_dispersion(study, 3, seed=1, chunk=2, overrides={"envelope_duration": 600.0})
    >>> bool(np.array_equal(t["final_rate"], u["final_rate"]))
    True
    """
    if not isinstance(study, DispersionStudy):
        raise ValueError(f"study must be a DispersionStudy, got {type(study).__name__}")
    total = as_count("members", members)
    seed = as_count("seed", seed, minimum=0)
    size = DEFAULT_CHUNK if chunk is None else as_count("chunk", chunk)
    window = 16 if in_flight is None else as_count("in_flight", in_flight)
    if executor is not None and not isinstance(executor, Executor):
        raise ValueError(f"executor must be a concurrent.futures.Executor or None, got {type(executor).__name__}")
    if until_ci is not None and not float(until_ci) > 0:
        raise ValueError(f"until_ci must be a relative width > 0, got {shown(until_ci)}")
    params = study.parameters(_checked_overrides(overrides))
    bounds = [(a, min(a + size, total)) for a in range(0, total, size)]
    names = study.columns
    kept = ("member",) + tuple(o.name for o in study.outcomes) if out is not None else names
    parts = {n: [] for n in kept}
    path = None if out is None else Path(out)
    partial = None if path is None else path.with_name(path.name + ".part")
    handle = None
    if partial is not None:
        handle = open(partial, "w", encoding="utf-8", newline="")
        handle.write(",".join(names) + "\n")
    done, next_check = 0, 0
    try:
        for rows in _ordered_chunks(study, params, seed, bounds, executor, window):
            if handle is not None:
                handle.write(_csv_lines(rows, names))
            for n in kept:
                parts[n].append(rows[n])
            done = int(rows["member"][-1]) + 1
            if progress is not None:
                progress(done)
            if until_ci is not None and done >= next_check and done < total:
                # checked at chunk boundaries only (the rows stay the same for any executor),
                # and again only after the members grew by a quarter (a bootstrap is not free)
                next_check = int(done * 1.25)
                table = DispersionTable(study, seed, params, {n: np.concatenate(v) for n, v in parts.items()})
                if _narrow(dispersion_statistics(table), float(until_ci)):
                    break
        if handle is not None:
            handle.close()
            handle = None
            os.replace(partial, path)
    except BaseException:
        if handle is not None:
            handle.close()
        if partial is not None and partial.exists():
            partial.unlink()
        raise
    return DispersionTable(study, seed, params, {n: np.concatenate(v) for n, v in parts.items()}, path)


def _narrow(statistics, width):
    return all(np.isfinite(s["low"]) and np.isfinite(s["high"]) and s["value"] != 0
               and (s["high"] - s["low"]) < width * abs(s["value"]) for s in statistics)


def _ordered_chunks(study, params, seed, bounds, executor, window):
    """Yield each chunk's rows in member order; a failed chunk is submitted once more."""
    if executor is None:
        for a, b in bounds:
            yield _chunk_rows(study, params, seed, a, b)
        return
    pending, ready, tries = {}, {}, {}
    queue = list(range(len(bounds)))
    position = 0

    def submit(i):
        a, b = bounds[i]
        tries[i] = tries.get(i, 0) + 1
        try:
            pending[executor.submit(_chunk_rows, study, params, seed, a, b)] = i
        except Exception as exc:
            raise DispersionError(f"chunk {i} (members {a}-{b - 1}) could not be submitted "
                                  f"(try {tries[i]}): {type(exc).__name__}: {exc}") from exc

    try:
        while position < len(bounds):
            while queue and len(pending) + len(ready) < window:
                submit(queue.pop(0))
            finished, _ = wait(list(pending), return_when=FIRST_COMPLETED)
            for future in finished:
                i = pending.pop(future)
                try:
                    ready[i] = future.result()
                except Exception as exc:
                    if tries[i] >= 2:
                        a, b = bounds[i]
                        raise DispersionError(f"chunk {i} (members {a}-{b - 1}) failed twice: "
                                              f"{type(exc).__name__}: {exc}") from exc
                    submit(i)
            while position in ready:
                yield ready.pop(position)
                position += 1
    finally:
        for future in pending:
            future.cancel()


def dispersion_statistics(table, *, outcomes=None, confidence=0.95, resamples=999, seed=0):
    r"""The outcomes' median and 95th percentile, each with a bootstrap confidence interval.

    Parameters
    ----------
    table : DispersionTable
        The rows of a study [-].
    outcomes : sequence of str, optional
        The outcomes to describe [-]; default all of the study's.
    confidence : float, optional
        Confidence level of the intervals, in (0, 1) [-].
    resamples : int, optional
        Bootstrap resamples [-].
    seed : int, optional
        Seed of the bootstrap's generator [-] (the intervals are reproducible).

    Returns
    -------
    list of dict
        One per outcome and statistic: ``outcome``, ``unit``, ``statistic`` (a key of
        :data:`STATISTICS`), ``value``, ``low``, ``high`` [SI], ``members`` and ``missing``
        (members whose outcome is NaN: not reached within the run; they count as larger
        than every number, so a statistic beyond them is +inf).

    Notes
    -----
    Not in the sources. Percentile bootstrap (:func:`scipy.stats.bootstrap`, ``method="percentile"``) of the
    quantile taken without interpolation (``method="inverted_cdf"``), so that members
    counted as +inf give +inf only when the statistic lies among them.

    Examples
    --------
    >>> from magbench.sim.dispersion import DispersionTable
    >>> t = DispersionTable(None, 0, {}, {"member": np.arange(200), "x": np.arange(200.0)})
    >>> t.study = type("S", (), {"outcomes": (Outcome("x", "s", ""),)})()
    >>> s = dispersion_statistics(t)[0]
    >>> s["statistic"], s["value"], bool(s["low"] < 99 < s["high"])
    ('median', 99.0, True)
    """
    from scipy.stats import bootstrap

    rng = np.random.default_rng(seed)
    out = []
    chosen = table.study.outcomes if outcomes is None else [o for o in table.study.outcomes if o.name in outcomes]
    unknown = set(outcomes or ()) - {o.name for o in chosen}
    if unknown:
        raise ValueError(f"outcomes {sorted(unknown)} are not outcomes of {table.study.name}; "
                         f"valid: {', '.join(o.name for o in table.study.outcomes)}")
    for outcome in chosen:
        values = np.asarray(table.columns[outcome.name], dtype=float)
        missing = int(np.count_nonzero(np.isnan(values)))
        data = np.where(np.isnan(values), np.inf, values)
        # at most ~2e6 numbers per bootstrap batch: flat memory at a million members
        batch = max(1, int(2e6 // max(1, data.size)))
        for name, q in STATISTICS.items():
            def statistic(x, axis, q=q):
                return np.quantile(x, q, axis=axis, method="inverted_cdf")
            value = float(statistic(data, -1))
            if data.size < 2:
                low = high = float("nan")
            else:
                with np.errstate(invalid="ignore"):
                    res = bootstrap((data,), statistic, n_resamples=resamples, confidence_level=confidence,
                                    method="percentile", vectorized=True, batch=batch, rng=rng)
                low, high = float(res.confidence_interval.low), float(res.confidence_interval.high)
            out.append({"outcome": outcome.name, "unit": outcome.unit, "statistic": name, "value": value,
                        "low": low, "high": high, "members": int(data.size), "missing": missing})
    return out
