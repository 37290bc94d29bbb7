"""Earth satellites, with units: TLE and OMM, SGP4 and SDP4, observers and passes, and a TLE fitted to a
trajectory. The float64 propagator is in orbits.core.satellites. The package is the subject's home in the house;
its modules land with the subject.
"""
