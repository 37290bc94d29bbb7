"""The expanding universe, with units: Friedmann models and the Newtonian expanding sphere (models), and their
pictures (plot). The float64 numbers are in orbits.core.cosmology.
"""
