"""Friedmann models (friedmann), the Newtonian expanding sphere (sphere) and the tanh-sinh quadrature their
integrals need (quadrature), on float64 arrays.
"""
