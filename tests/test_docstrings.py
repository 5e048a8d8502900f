"""House rules for public functions of the physics modules (python-control style):
every parameter documented with its unit in brackets, and a source line."""

import importlib
import importlib.util
import inspect
import re
import subprocess
import sys

import pytest

#: The physics families and the layers below them, and the simulations that compose them
#: (not the chapters, the book helpers or the data layer).
_LIBRARY = ("magbench.fields", "magbench.earth", "magbench.hardware", "magbench.dynamics", "magbench.control",
            "magbench.estimation", "magbench.sim")
_BASE = ("magbench.rotations", "magbench.units", "magbench.integrate")


def _walk():
    """Every public module of the library's packages, found by walking them (a new module
    cannot escape these rules by being left off a list): the checked modules, and the
    families' ``kernels`` modules (unchecked array kernels and compiled twins, each documented
    by the checked function it names). Private modules (``_..._kernel``) are neither."""
    import pkgutil

    names, kernels = list(_BASE), []
    for package in _LIBRARY:
        names.append(package)
        module = importlib.import_module(package)
        for m in pkgutil.iter_modules(module.__path__, package + "."):
            short = m.name.rsplit(".", 1)[1]
            if short == "kernels":
                kernels.append(m.name)
            elif not short.startswith("_"):
                names.append(m.name)
    return names, kernels


PHYSICS, KERNELS = _walk()
#: A line a reader can look up, in any of the five sources (the thesis, Kovalenko, the
#: SamSat-218D paper, the rotor slides, the TNS-0 preprint), or an explicit "not in".
SOURCE_LINE = re.compile(r"Thesis (eqs?\.|§)|Not in the (thesis|sources)|Kovalenko \(1975\)"
                         r"|SamSat-218D (eqs?\.|§|Fig)|[Rr]otor slides?,? (slide|eq)|TNS-0 (preprint )?(§|eqs?\.|Table|Fig)")


def _public_functions():
    for name in PHYSICS:
        module = importlib.import_module(name)
        for fname in getattr(module, "__all__", []):
            func = getattr(module, fname)
            if inspect.isfunction(func):
                yield pytest.param(func, id=f"{name}.{fname}")


@pytest.mark.parametrize("func", list(_public_functions()))
def test_parameters_documented_with_units(func):
    doc = inspect.getdoc(func) or ""
    if func.__module__ == "magbench.units":
        assert doc, "converters need a one-line docstring"
        return
    assert SOURCE_LINE.search(doc), "needs a 'Thesis eq.', 'Kovalenko (1975)' or 'Not in the thesis:' line"
    section = doc.split("Parameters\n----------\n", 1)
    assert len(section) == 2, "needs a numpydoc Parameters section"
    body = re.split(r"\n\n[A-Z][a-z]+\n-+\n", section[1])[0]
    for name in inspect.signature(func).parameters:
        entry = re.search(rf"^(?:\S+, )*{name}(?:, \S+)* :.*\n((?:    .*\n?)+)", body, re.M)
        assert entry, f"parameter {name} is not documented"
        assert re.search(r"\[[^\]]+\]", entry.group(1)), f"parameter {name} lacks a [unit]"


def test_physics_modules_do_not_import_plotting_or_io():
    code = ("import sys, magbench.fields, magbench.hardware, magbench.dynamics, magbench.earth, "
            "magbench.control, magbench.estimation; "
            "bad = [m for m in ('matplotlib', 'pandas', 'magbench.figures', 'magbench.io') if m in sys.modules]; "
            "print(bad); sys.exit(bool(bad))")
    result = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert result.returncode == 0, result.stdout + result.stderr


@pytest.mark.parametrize("line, cites", [
    ("Thesis §2.2, eq. (16).", True), ("Kovalenko (1975) eq. (9.21), p. 160.", True),
    ("SamSat-218D eq. (3): the B-dot law.", True), ("Rotor slides, slide 12: the spin law.", True),
    ("TNS-0 preprint §3: the hysteresis rods.", True), ("Not in the sources: Wertz (1978).", True),
    ("Some formula.", False), ("seed line 278", False),
])
def test_the_source_rule_takes_the_five_sources(line, cites):
    assert bool(SOURCE_LINE.search(line)) is cites


#: The book's vocabulary (DESIGN.md, Conventions): one word per concept in public names.
#: ``t`` stays allowed as the first argument of a ``solve_ivp`` right-hand side.
GLOSSARY_BANNED = {"centre": "center", "circle": "round", "psi0": "initial_angle", "omega0": "initial_rate",
                   "t_end": "duration", "omega": "rate"}
FAMILIES = PHYSICS + KERNELS
#: Exceptions to the glossary, each a name fixed by a contract other tools use: chapter 5's
#: contract (shared/reference/bdot_triad.md §9) calls the angular-velocity *vector* ``omega``
#: (``rate`` is its magnitude there, as elsewhere in the book). Only these exact places.
GLOSSARY_CONTRACT = {"magbench.dynamics.rigid_body.quaternion_rate(omega)",
                     "magbench.dynamics.rigid_body.euler_rates(omega)",
                     "magbench.dynamics.quaternion_rate(omega)", "magbench.dynamics.euler_rates(omega)",
                     "magbench.sim.detumble.DetumbleRun.omega", "magbench.sim.DetumbleRun.omega",
                     "magbench.sim.result.DetumbleRun.omega", "magbench.sim.result.RotorRun.omega",
                     # chapter 6's contract (shared/reference/rotor_spin.md §15): the run's body rate vectors
                     "magbench.sim.spinning.RotorRun.omega", "magbench.sim.RotorRun.omega"}


def _public_words():
    import dataclasses

    for name in FAMILIES:
        module = importlib.import_module(name)
        for public in module.__all__:
            obj = getattr(module, public)
            yield f"{name}.{public}", public
            if dataclasses.is_dataclass(obj):
                for f in dataclasses.fields(obj):
                    yield f"{name}.{public}.{f.name}", f.name
            elif callable(obj):
                try:
                    params = inspect.signature(obj).parameters
                except (TypeError, ValueError):
                    continue
                for p in params:
                    yield f"{name}.{public}({p})", p


def test_public_names_use_the_glossary():
    """Public names and parameters say center (not centre), round (not circle), time,
    rate, initial_angle, initial_rate, duration: a test no rename can slip past."""
    wrong = [f"{where}: use {GLOSSARY_BANNED[w]!r} for {w!r}" for where, word in _public_words()
             if where not in GLOSSARY_CONTRACT
             for w in GLOSSARY_BANNED if w in word.split("_") or word == w]
    assert not wrong, "\n".join(wrong)


def test_the_glossary_exceptions_are_still_needed():
    """An exception outlives its reason only if the name it excuses is gone: each must match."""
    found = {where for where, _ in _public_words()}
    assert GLOSSARY_CONTRACT <= found, sorted(GLOSSARY_CONTRACT - found)


def _is_module(name):
    try:
        return importlib.util.find_spec(name) is not None
    except ModuleNotFoundError:  # a parent that is not a package (a class, a function)
        return False


def _kernel_functions():
    for name in KERNELS:
        module = importlib.import_module(name)
        for fname in module.__all__:
            yield pytest.param(name, fname, id=f"{name}.{fname}")


def test_the_kernels_are_found():
    assert {"magbench.dynamics.kernels", "magbench.earth.kernels", "magbench.hardware.kernels"} <= set(KERNELS)


@pytest.mark.parametrize("module_name, fname", list(_kernel_functions()))
def test_each_kernel_names_the_checked_function_that_documents_it(module_name, fname):
    """A kernel skips the checks, not the documentation: its docstring names the checked
    function (or the twin) whose numpydoc gives the physics, units and source, and that name
    resolves."""
    doc = inspect.getdoc(getattr(importlib.import_module(module_name), fname)) or ""
    refs = re.findall(r":(?:func|meth):`~?([\w.]+)`", doc)
    assert refs, f"{module_name}.{fname}: the docstring names no checked function (:func:`...`)"
    for ref in refs:
        parts = ref.split(".")
        cut = max(i for i in range(1, len(parts) + 1) if _is_module(".".join(parts[:i])))
        obj = importlib.import_module(".".join(parts[:cut]))
        for attr in parts[cut:]:
            assert hasattr(obj, attr), f"{module_name}.{fname}: {ref} does not exist"
            obj = getattr(obj, attr)


def test_no_docstring_keeps_a_shared_entry_unfilled():
    """A ``{name}`` line is filled at import by :func:`magbench._docstrings.fill_docstring`; one
    left over means a function lost its decorator."""
    from magbench._docstrings import _SLOT

    left = [p.id for p in _public_functions() if _SLOT.search(p.values[0].__doc__ or "")]
    assert not left, left


def test_fill_docstring_fills_indents_and_retypes():
    from magbench._docstrings import fill_docstring

    entries = {"side": "side : array_like\n    Turn side l [m].", "shape": "shape : str\n    Shape [-]."}

    @fill_docstring(entries)
    def f(side, shape):
        """Doc.

        Parameters
        ----------
        {side, shape}
        """

    @fill_docstring(entries)
    def g(side):
        """Doc.

        Parameters
        ----------
        {side : float}
        """

    assert inspect.getdoc(f).endswith("side : array_like\n    Turn side l [m].\nshape : str\n    Shape [-].")
    assert inspect.getdoc(g).endswith("side : float\n    Turn side l [m].")


def test_fill_docstring_refuses_unknown_names_and_docstrings_without_slots():
    from magbench._docstrings import fill_docstring

    def unknown():
        """{size}"""

    def plain():
        """No slot."""

    with pytest.raises(KeyError, match="size"):
        fill_docstring({"side": "side : float\n    l [m]."})(unknown)
    with pytest.raises(ValueError, match="no {name} line"):
        fill_docstring({"side": "side : float\n    l [m]."})(plain)
