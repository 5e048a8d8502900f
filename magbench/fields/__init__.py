"""What produces a magnetic field: thin circular and square loops, coil pairs and
systems of coils, how uniform their field is, and the horizontal field at the bench.
Pure functions of numpy arrays, SI.

Re-exports the public functions of its modules: ``from magbench.fields import loop_b``.
"""

from .loop import loop_b, loop_b_posed
from .pair import (helmholtz_ampere_turns, helmholtz_b, helmholtz_center_h, helmholtz_center_h_spread,
                   helmholtz_h_magnitude, pair_peak_center_h, pair_radius_for_center_h, planar_pair_center_h)
from .square import square_loop_axial_b, square_loop_b, square_loop_center_b_per_moment, square_pair_spacing
from .systems import (SPHERE_DIRECTIONS, coaxial_system_b, coaxial_system_cylinder_nonuniformity, coaxial_system_sphere_nonuniformity,
                      coaxial_system_uniform_radius, horizontal_field, three_axis_pair_b,
                      three_axis_pair_currents, three_axis_uniform_radius)
from .uniformity import (cylinder_nonuniformity, optimal_separation, pair_distance_to_h, sphere_nonuniformity,
                         uniform_cylinder, uniform_sphere_radius, uniform_zone_length,
                         zone_tolerance_for_length)

__all__ = ["SPHERE_DIRECTIONS", "loop_b", "loop_b_posed", "helmholtz_b", "helmholtz_h_magnitude", "helmholtz_center_h",
           "helmholtz_center_h_spread", "helmholtz_ampere_turns",
           "pair_radius_for_center_h", "pair_peak_center_h", "planar_pair_center_h", "square_loop_b", "square_loop_axial_b",
           "square_loop_center_b_per_moment",
           "square_pair_spacing", "three_axis_pair_b", "three_axis_pair_currents", "three_axis_uniform_radius",
           "coaxial_system_b",
           "coaxial_system_sphere_nonuniformity", "coaxial_system_cylinder_nonuniformity",
           "coaxial_system_uniform_radius", "sphere_nonuniformity", "cylinder_nonuniformity",
           "uniform_sphere_radius", "uniform_cylinder", "optimal_separation", "pair_distance_to_h",
           "uniform_zone_length", "zone_tolerance_for_length", "horizontal_field"]
