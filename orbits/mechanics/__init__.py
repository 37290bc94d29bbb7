"""The course's mechanics, with units: collisions (collisions), motion under uniform gravity (projectile),
pendulums and oscillators (oscillations), rotations and rolling (rotation), and their pictures (plot). The
float64 numbers are in orbits.core.mechanics.
"""
