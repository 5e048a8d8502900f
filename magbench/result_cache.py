"""The result cache: each expensive result (a chapter's study, a figure's numbers)
computed once per build and shared by the pages, the command line and the tests.

Within one process a result is kept in memory (:func:`functools.lru_cache`). When
``$MAGBENCH_RESULT_CACHE`` names a folder, results also go to disk there, through
:class:`joblib.Memory`, so that the next process (the next page of the book, the tests
after the book, ``magbench compare``) loads them instead of computing them again. The
key of a result on disk is content, never a time stamp:

* the *inputs fingerprint* (:func:`inputs_fingerprint`): every module of the library,
  the data checksums, the parameter overrides (``$MAGBENCH_PARAMS``) and the listing of the
  BROAD recordings, hashed; it names the subfolder, so a changed line of the library or
  of a data file starts a new, empty one;
* the function's own source and its arguments (joblib's key).

Two processes that ask for the same result at once (two pages on two cores) do not both
compute it: the second waits on a lock file of that result and then loads it.

Without the variable nothing is written anywhere: a script that imports the library
computes what it asks for, as it always did. ``make book`` sets it to
``_build/results``; ``make test`` to ``_build/test/results``, emptied first, so that
a test run still computes everything from scratch, once.
"""

import contextlib
import fcntl
import functools
import hashlib
import os
from collections.abc import Mapping
from pathlib import Path

__all__ = ["RESULT_CACHE_ENV", "ChapterInputs", "cached_result", "disabled", "disk_cached", "external_inputs", "inputs_fingerprint",
           "library_digests", "result_cache_folder"]

#: The environment variable naming the folder of the on-disk result cache.
RESULT_CACHE_ENV = "MAGBENCH_RESULT_CACHE"

_PACKAGE = Path(__file__).resolve().parent
_disabled = 0              # depth of disabled() blocks: no disk at all
_unkeyed_disabled = 0      # depth of disabled(studies=False) blocks: the studies keep the disk


@functools.lru_cache(maxsize=1)
def library_digests():
    """SHA-256 (hex) of the library's modules and of its data checksums: the manifests
    (``data/<source>/SHA256SUMS``) every data file is checked against when it is read,
    so that a data file that changes without its manifest is an error, not a new key.
    :func:`magbench.report.provenance` prints them on every page."""
    from .io import DATA_DIR

    library = hashlib.sha256()
    for path in sorted(_PACKAGE.rglob("*.py")):
        library.update(path.read_bytes())
    manifest = hashlib.sha256()
    for path in sorted(DATA_DIR.glob("*/SHA256SUMS")):
        manifest.update(path.parent.name.encode() + b"\n" + path.read_bytes())
    return library.hexdigest(), manifest.hexdigest()


def _library_digest():
    return "".join(library_digests())


def external_inputs():
    """The inputs a result may depend on that live outside the package, as bytes to hash:
    the overrides file named by ``$MAGBENCH_PARAMS`` and the folder of the BROAD recordings
    with each recording's name, size and modification time."""
    from .io.broad import broad_directory

    parts = []
    overrides = os.environ.get("MAGBENCH_PARAMS")
    if overrides:
        path = Path(overrides)
        parts.append(b"MAGBENCH_PARAMS" + (path.read_bytes() if path.is_file() else overrides.encode()))
    folder = broad_directory()
    parts.append(b"BROAD " + str(folder).encode())
    if folder.is_dir():
        for path in sorted(folder.iterdir()):
            if path.is_file():
                stat = path.stat()
                parts.append(f"{path.name} {stat.st_size} {stat.st_mtime_ns}\n".encode())
    return b"".join(parts)


def inputs_fingerprint():
    """SHA-256 (hex) of everything a result may depend on besides its arguments: the
    library's modules and data checksums (:func:`library_digests`) and
    :func:`external_inputs`."""
    return hashlib.sha256(_library_digest().encode() + external_inputs()).hexdigest()


def result_cache_folder(study=False):
    """The folder results go to in this process (``$MAGBENCH_RESULT_CACHE`` / the first 16
    digits of :func:`inputs_fingerprint`), or None when the disk cache is off (for a
    :func:`cached_result` function if ``study``, else for :func:`disk_cached`)."""
    base = os.environ.get(RESULT_CACHE_ENV)
    if not base or _disabled or (_unkeyed_disabled and not study):
        return None
    return Path(base).resolve() / inputs_fingerprint()[:16]


@functools.lru_cache(maxsize=4)
def _memory(folder):
    import joblib

    return joblib.Memory(location=folder, verbose=0)


@functools.lru_cache(maxsize=256)
def _memorized(folder, func):
    """joblib's wrapper of ``func`` in ``folder``, one per process and function: its check
    of the function's stored source then happens once, at the first call."""
    return _memory(folder).cache(func)


_checked = set()


def _call(folder, func, args, kwargs):
    memorized = _memorized(folder, func)
    if (folder, func) not in _checked:
        # joblib compares the function's source with the copy it stored, and writes the
        # copy if there is none; two processes starting at once (two pages, two test
        # workers) would read each other's half-written copy, take it for another
        # function and clear its results. One process at a time, here.
        Path(folder).mkdir(parents=True, exist_ok=True)
        with open(Path(folder) / ".lock", "a") as lock:
            fcntl.flock(lock, fcntl.LOCK_EX)
            memorized.check_call_in_cache(*args, **kwargs)
        _checked.add((folder, func))
    import joblib

    # One process computes a result at a time: two pages or figures that need the same
    # study at once (two cores) would otherwise both compute it; the second waits here and
    # then loads it.
    locks = Path(folder) / ".locks"
    locks.mkdir(parents=True, exist_ok=True)
    name = f"{func.__module__}.{func.__qualname__}-{joblib.hash((args, kwargs))}"
    with open(locks / name, "a") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        return memorized(*args, **kwargs)


@contextlib.contextmanager
def disabled(studies=True):
    """Within the block, results are neither read from nor written to disk (for code that
    changes the library's inputs behind its arguments' back, as the input sweep does).
    The in-memory layer stays: it is keyed on the arguments alone, as it always was.

    With ``studies=False`` only :func:`disk_cached`'s callers (a figure's numbers, a
    chapter's rows: keyed on an id and what they were given, not on the chapter
    parameters they may read themselves) lose the disk; the :func:`cached_result`
    functions keep it, keyed on every input they read, so that the input sweep loads a
    study no scaled input touches instead of computing it again."""
    global _disabled, _unkeyed_disabled
    if studies:
        _disabled += 1
    else:
        _unkeyed_disabled += 1
    try:
        yield
    finally:
        if studies:
            _disabled -= 1
        else:
            _unkeyed_disabled -= 1


class ChapterInputs(Mapping):
    """A chapter's inputs, name → SI value [SI], as one frozen, hashable value: the key on
    which the chapters' studies and runs are cached, in memory and on disk.

    Built from a mapping or (name, value) pairs, plus keyword changes; read as a dict.
    Equal inputs are one key whatever their order or number type (7 and 7.0).

    Examples
    --------
    >>> a = ChapterInputs({"gain": 2, "step": 0.5})
    >>> a == ChapterInputs([("step", 0.5), ("gain", 2.0)]), a["gain"], dict(a.replace(step=1))
    (True, 2.0, {'gain': 2.0, 'step': 1.0})
    """

    __slots__ = ("_values",)

    def __init__(self, values=(), **changes):
        merged = {**dict(values), **changes}
        object.__setattr__(self, "_values", {str(k): float(merged[k]) for k in sorted(merged)})

    def __setattr__(self, name, value):
        raise AttributeError(f"ChapterInputs is frozen: use replace({name}=...)")

    def __getitem__(self, name):
        return self._values[name]

    def __iter__(self):
        return iter(self._values)

    def __len__(self):
        return len(self._values)

    def __hash__(self):
        return hash(tuple(self._values.items()))

    def __eq__(self, other):
        return isinstance(other, ChapterInputs) and self._values == other._values

    def __repr__(self):
        return f"ChapterInputs({self._values!r})"

    def __reduce__(self):
        return ChapterInputs, (tuple(self._values.items()),)

    def replace(self, **changes):
        """The same inputs with ``changes``; a name that is not among them raises ``KeyError``."""
        unknown = sorted(set(changes) - set(self._values))
        if unknown:
            raise KeyError(f"{', '.join(unknown)} not among the inputs ({', '.join(self._values)})")
        return ChapterInputs(self._values, **changes)


def cached_result(func=None, *, maxsize=4, reads=None):
    """Decorator: keep ``func``'s results in memory (``maxsize`` per process) and, when the
    disk cache is on, on disk (see the module's description).

    ``func`` must be a pure function of its arguments (hashable: tuples, numbers,
    strings) and of the library's inputs; its result must pickle.

    ``reads``, the names of the parameters ``func`` reads, makes it a *study*: its first
    argument is then a chapter's parameters (a mapping or (name, value) pairs, any
    superset of ``reads``), and ``func`` is called with, and keyed on, the
    :class:`ChapterInputs` of ``reads`` alone. A study reading a name it does not declare
    fails with a ``KeyError``; one whose names are all unchanged is not computed again,
    whatever else of the chapter changed (the input sweep relies on it).
    """
    if func is None:
        return functools.partial(cached_result, maxsize=maxsize, reads=reads)

    def _from_disk_or_computed(*args, **kwargs):
        folder = result_cache_folder(study=True)
        return func(*args, **kwargs) if folder is None else _call(str(folder), func, args, kwargs)

    cached = functools.lru_cache(maxsize=maxsize)(_from_disk_or_computed)
    if reads is None:
        return functools.wraps(func)(cached)
    names = tuple(sorted(set(reads)))

    @functools.wraps(func)
    def study(params, *args, **kwargs):
        given = params if isinstance(params, Mapping) else dict(params)
        missing = [name for name in names if name not in given]
        if missing:
            raise KeyError(f"{func.__qualname__} reads {', '.join(missing)}, not among the parameters it was given")
        return cached(ChapterInputs({name: given[name] for name in names}), *args, **kwargs)

    study.reads = names
    study.cache_clear = cached.cache_clear
    return study


def disk_cached(func, *args, **kwargs):
    """``func(*args, **kwargs)``, from the disk cache when it is on (nothing kept in memory:
    for results the caller mutates, such as a figure's numbers)."""
    folder = result_cache_folder()
    if folder is None:
        return func(*args, **kwargs)
    return _call(str(folder), func, args, kwargs)
