"""Compatibility module: the IGRF-14 adapter moved to :mod:`magbench.earth.igrf`."""

from .earth.igrf import (IgrfDipole, IgrfField, decimal_year_to_datetime, igrf_dipole, igrf_field,
                         igrf_gauss_coefficients, igrf_mean_surface_b)

__all__ = ["IgrfDipole", "IgrfField", "decimal_year_to_datetime", "igrf_dipole", "igrf_field",
           "igrf_gauss_coefficients", "igrf_mean_surface_b"]
