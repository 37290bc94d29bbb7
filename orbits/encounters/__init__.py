"""Two bodies meeting or bound, with units: binaries (binary), hyperbolic flybys (flyby), escape speeds, cosmic
velocities and synchronous orbits (escape), and their pictures (plot). The float64 numbers are in
orbits.core.encounters.
"""
