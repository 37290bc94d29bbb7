"""Secular perturbation theory on float64 arrays (SI, radians): oblateness, drag, a distant third body and
general relativity.
"""
