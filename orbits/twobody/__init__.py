"""Two-body orbits with units: Orbit (elements, vectors, propagation, the state-transition matrix), every
anomaly of a conic (kepler), and their pictures (plot). The float64 numbers are in orbits.core.twobody.
"""
