"""The tests' short name for the mpmath oracle, orbits.tools.reference (see that module)."""

from orbits.tools.reference import (
    barker_D,
    kepler_E,
    kepler_H,
    propagate,
    rel_error,
    transition_matrix,
    true_from_E,
    true_from_H,
    ulp_error,
)

__all__ = ["barker_D", "kepler_E", "kepler_H", "propagate", "rel_error", "transition_matrix", "true_from_E",
           "true_from_H", "ulp_error"]
