"""The rotor chapter's default spacecraft and orbit, built from ``data/rotor/params.toml``.

The home the chapter-6 contract gives the defaults (``shared/reference/rotor_spin.md`` §15:
"the chapter module for defaults"): physics and ``sim`` read no data files, so the
parameter set is read here, and the chapter module re-exports these names.
"""

import math

import numpy as np

from ...earth import CircularOrbit
from ...io import load_parameter_set
from ...sim.spinning import rotor_satellite_from_dimensionless

__all__ = ["rotor_parameters", "default_rotor_orbit", "default_rotor_satellite"]


def rotor_parameters():
    """The rotor parameter set in SI: name -> value (``data/rotor/params.toml``)."""
    return {name: par.value_si for name, par in load_parameter_set("rotor").items()}


def default_rotor_orbit(params=None):
    """The default orbit: circular, direct non-rotating dipole, u = 0 at t = 0 (rotor slides, seed line 21).

    ``params`` (name -> SI value, as :func:`rotor_parameters` returns) overrides the file.
    """
    p = {**rotor_parameters(), **(params or {})}
    return CircularOrbit(p["orbit_radius"], p["inclination"], p["earth_dipole_moment"], 0.0,
                         dipole_tilt=p["dipole_tilt"], earth_rotation_rate=0.0)


def default_rotor_satellite(params=None):
    """The default (asymmetric) spacecraft with the chosen gains (``rotor_spin.md`` §10)."""
    p = {**rotor_parameters(), **(params or {})}
    inertia = np.array([p["axial_inertia"], p["transverse_inertia_2"], p["transverse_inertia_3"]])
    return rotor_satellite_from_dimensionless(inertia, p["rotor_inertia"], p["spin_rate"], default_rotor_orbit(p),
                                              momentum=p["momentum_number"], restoring=p["restoring_number"],
                                              damping=p["damping_number"],
                                              moment_limit=p.get("moment_limit", math.inf))
