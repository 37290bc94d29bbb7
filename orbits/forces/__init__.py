"""A user's own perturbed orbit, with units: force models (zonal harmonics, drag, third bodies, radiation
pressure, the 1PN correction, low thrust), their propagation and the events on it (apsides, nodes, eclipses,
altitudes). The float64 accelerations and the integrator's events are in orbits.core.forces. The package is the
subject's home in the house; its modules land with the subject.
"""
