"""magbench: the reproducible companion to Bui (2016), magnetic attitude control of
small satellites.

Physics modules (pure functions of numpy arrays, SI units): :mod:`geomag`,
:mod:`attitude`. Data with provenance: :mod:`data`, :mod:`params`. Model beside
measurement: :mod:`compare`; source errors: :mod:`errata`. Figures:
:mod:`magbench.figures`. The command line: :mod:`magbench.cli`.
"""

__version__ = "0.1.0"
