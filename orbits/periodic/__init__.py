"""Periodic orbits of the circular restricted three-body problem, with units: PeriodicOrbit and PeriodicFamily
(family) and their pictures (plot). The float64 numbers (equations of motion, shooting, continuation,
families) are in orbits.core.periodic.
"""
