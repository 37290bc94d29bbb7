"""Three bodies and more in the frame that turns with them, with units: the Lagrange points of a circular binary
(lagrange), rings of n equal masses (rings), and their pictures (plot). The float64 numbers are in
orbits.core.threebody.
"""
