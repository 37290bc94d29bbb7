"""The course's mechanics on float64 arrays (SI, radians): collisions, projectiles, oscillations and rotations.
"""
