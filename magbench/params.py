"""Chapter inputs: defaults from each chapter's source's parameter set, overridable.

Each chapter's ``parameters`` cell calls :func:`chapter_parameters` and assigns every
input to a variable, so papermill (or a reader editing the cell) can override single
values. For a whole-book build with other values, point the environment variable
``MAGBENCH_PARAMS`` at a TOML file (``make book PARAMS=file.toml`` does this)::

    [all]                       # applies to every chapter
    earth_dipole_moment = 8.0e22

    [ch01]                      # applies to chapter 1 only
    orbit_altitude = 500e3

Override values are SI numbers. An unknown chapter or parameter name is an error
that lists the valid names. Which inputs a chapter has is said by the chapter itself
(:mod:`magbench.chapters`); this module is the name the book's parameter cells use.
"""

from .chapters import CHAPTERS, OVERRIDES_ENV, chapter_parameters, read_overrides

__all__ = ["CHAPTER_INPUTS", "OVERRIDES_ENV", "chapter_parameters", "read_overrides"]

#: The inputs of each chapter, by chapter key (read from :data:`magbench.chapters.CHAPTERS`).
CHAPTER_INPUTS = {spec.key: list(spec.inputs) for spec in CHAPTERS}
