"""The result cache: a result computed in one process is loaded, not recomputed, by the
next; a changed argument, library or overrides file is a different result; without the
variable nothing is written."""

import pickle
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from magbench import figures, result_cache

ROOT = Path(__file__).resolve().parent.parent

CALLS = []


@result_cache.cached_result
def _square(x):
    CALLS.append(x)
    return np.arange(3) * x


@pytest.fixture
def cache_dir(tmp_path, monkeypatch):
    monkeypatch.setenv(result_cache.RESULT_CACHE_ENV, str(tmp_path / "results"))
    CALLS.clear()
    _square.cache_clear()
    yield tmp_path / "results"
    _square.cache_clear()


def test_a_result_is_computed_once_and_then_read_from_disk(cache_dir):
    first = _square(2.0)
    _square.cache_clear()                     # a new process: nothing in memory
    second = _square(2.0)
    assert CALLS == [2.0]
    np.testing.assert_array_equal(second, first)    # exact: the same pickled array
    assert any(cache_dir.rglob("output.pkl"))


STUDY_CALLS = []


@result_cache.cached_result(reads=("b", "a"))
def _study(params, scale=1.0):
    STUDY_CALLS.append(params)
    p = dict(params)
    return scale * (p["a"] + p["b"])


@result_cache.cached_result(reads=("a",))
def _undeclared(params):
    return dict(params)["b"]


def test_a_study_is_keyed_on_the_inputs_it_reads(monkeypatch):
    monkeypatch.delenv(result_cache.RESULT_CACHE_ENV, raising=False)
    STUDY_CALLS.clear()
    _study.cache_clear()
    assert _study({"a": 1.0, "b": 2.0, "c": 3.0}) == 3.0
    # Another value of an input it does not read, as a mapping or as pairs: the same result.
    assert _study([("c", 9.0), ("b", 2.0), ("a", 1.0)]) == 3.0
    # called with its own inputs alone, as one frozen mapping
    assert STUDY_CALLS == [result_cache.ChapterInputs({"a": 1.0, "b": 2.0})]
    assert list(STUDY_CALLS[0].items()) == [("a", 1.0), ("b", 2.0)]
    assert _study({"a": 1.0, "b": 5.0}) == 6.0 and _study({"a": 1.0, "b": 2.0}, scale=2.0) == 6.0
    assert len(STUDY_CALLS) == 3 and _study.reads == ("a", "b")


def test_chapter_inputs_are_one_frozen_key():
    a = result_cache.ChapterInputs({"b": 2, "a": 1.0})
    # order and number type do not make another key; another value does
    same = result_cache.ChapterInputs([("a", 1), ("b", 2.0)])
    assert a == same and hash(a) == hash(same)
    assert a != result_cache.ChapterInputs({"a": 1.0, "b": 3.0}) and a != {"a": 1.0, "b": 2.0}
    with pytest.raises(AttributeError, match="frozen"):
        a.gain = 1.0
    with pytest.raises(KeyError, match="c not among the inputs"):
        a.replace(c=1.0)
    assert a.replace(b=4.0)["b"] == 4.0 and a["b"] == 2.0
    assert pickle.loads(pickle.dumps(a)) == a


def test_a_study_missing_an_input_or_reading_an_undeclared_one_fails():
    with pytest.raises(KeyError, match="_study reads b, not among the parameters"):
        _study({"a": 1.0})
    with pytest.raises(KeyError, match="'b'"):
        _undeclared({"a": 1.0, "b": 2.0})


def test_another_argument_is_another_result(cache_dir):
    _square(2.0)
    _square(3.0)
    assert CALLS == [2.0, 3.0]


def test_without_the_variable_nothing_is_written(tmp_path, monkeypatch):
    monkeypatch.delenv(result_cache.RESULT_CACHE_ENV, raising=False)
    monkeypatch.chdir(tmp_path)
    assert result_cache.result_cache_folder() is None
    CALLS.clear()
    _square.cache_clear()
    _square(5.0)
    _square.cache_clear()
    _square(5.0)
    assert CALLS == [5.0, 5.0] and not any(tmp_path.iterdir())


def test_disabled_reads_and_writes_nothing(cache_dir):
    with result_cache.disabled():
        assert result_cache.result_cache_folder() is None
        _square(7.0)
    assert not cache_dir.exists()


def test_overrides_file_and_library_change_the_folder(cache_dir, tmp_path, monkeypatch):
    monkeypatch.delenv("MAGBENCH_PARAMS", raising=False)
    base = result_cache.result_cache_folder()
    overrides = tmp_path / "o.toml"
    overrides.write_text("[ch01]\norbit_altitude = 5e5\n")
    monkeypatch.setenv("MAGBENCH_PARAMS", str(overrides))
    with_file = result_cache.result_cache_folder()
    overrides.write_text("[ch01]\norbit_altitude = 6e5\n")
    with_other_value = result_cache.result_cache_folder()
    assert len({base, with_file, with_other_value}) == 3
    assert base.parent == cache_dir.resolve()
    # The library's own files: a change to any module or data file is another folder.
    monkeypatch.setattr(result_cache, "_library_digest", lambda: "edited")
    assert result_cache.result_cache_folder() != with_other_value


def test_a_figures_numbers_come_from_disk_in_a_new_process(cache_dir):
    # Two processes (as two pages of the book, or a page and the tests): the second loads
    # what the first stored (it writes nothing) and gets the same numbers.
    script = ("import json, numpy as np; from magbench import figures; d = figures.compute('thesis-fig01'); "
              "print(json.dumps([np.ravel(v).tolist() for s in d.series for _, v in s.columns.values()]))")
    env = {"MAGBENCH_RESULT_CACHE": str(cache_dir), "PATH": "", "OMP_NUM_THREADS": "1"}

    def run():
        return subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, check=True, cwd=ROOT,
                              env=env).stdout

    def stored():
        return {p: p.stat().st_mtime_ns for p in cache_dir.rglob("*") if p.is_file()}

    first = run()
    after_first = stored()
    second = run()
    assert any(p.name == "output.pkl" for p in after_first)
    assert stored() == after_first and second == first


def test_figure_data_is_fresh_each_call(cache_dir):
    # compute() stamps id and parameters on the data: a cached object must not be shared.
    a = figures.compute("thesis-fig01")
    b = figures.compute("thesis-fig01")
    assert a is not b and a.id == b.id == "thesis-fig01"


def test_disabled_but_for_studies_keeps_the_studies_on_disk(cache_dir):
    # The input sweep's mode: a study is keyed on every input it reads, so its disk entry is
    # safe to share; a plain disk_cached call is not (it may read parameters behind its key).
    STUDY_CALLS.clear()
    _study.cache_clear()
    with result_cache.disabled(studies=False):
        assert result_cache.result_cache_folder() is None
        assert result_cache.result_cache_folder(study=True) is not None
        _study({"a": 1.0, "b": 2.0})
        _study.cache_clear()                   # another process
        _study({"a": 1.0, "b": 2.0})
    assert len(STUDY_CALLS) == 1 and any(cache_dir.rglob("output.pkl"))
    with result_cache.disabled():
        assert result_cache.result_cache_folder(study=True) is None
