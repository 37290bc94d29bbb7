"""The Lagrange points of the circular restricted three-body problem and rings of n equal masses, on float64
arrays (SI, radians).
"""
