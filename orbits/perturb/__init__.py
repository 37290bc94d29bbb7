"""Perturbed orbits, with units: an oblate body's secular rates and the orbit designs built on them, drag decay,
the Kozai-Lidov cycle and general relativity's periapsis advance (secular), and their pictures (plot). The
float64 numbers are in orbits.core.perturb.
"""
