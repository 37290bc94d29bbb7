"""The integrator libraries' own closed-form functions, which the benchmarks time beside orbits' (heyoka's kepE and
lagrange_prop, rebound's M_to_E). They live in the adapters, the only modules that import those libraries."""

from orbits.validate._heyoka import kepler_solver as heyoka_kepler_solver
from orbits.validate._heyoka import lagrange_propagator as heyoka_lagrange_propagator
from orbits.validate._heyoka import pinned_threads as heyoka_threads
from orbits.validate._rebound import kepler_solver as rebound_kepler_solver

__all__ = ["heyoka_kepler_solver", "heyoka_lagrange_propagator", "heyoka_threads", "rebound_kepler_solver"]
