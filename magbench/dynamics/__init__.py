"""Equations of motion and what follows from them (for now: the swing of thesis §2.1).

Re-exports the public functions of its modules. The mock-up's equations of motion still
live in :mod:`magbench.attitude`.
"""

from .swing import oscillation_field_h

__all__ = ["oscillation_field_h"]
