"""Numerical cross-checks: every scene predicted analytically and integrated with rebound and heyoka.

    >>> from orbits.validate import load, validate
    >>> report = validate([load("circular")])           # doctest: +SKIP
    >>> report.passed                                   # doctest: +SKIP
    True

The public entry points are `load` (a scene of either kind, by name or file), `builtin_names`, `validate` and
`validate_scene`, `available` (is a backend installed) and the report records. The adapters (_rebound, _heyoka)
are the only modules that import rebound and heyoka, inside the functions that use them: every integration, the
scenes', the impulsive manoeuvres' and the three-body runs', goes through `backends.integrate`, and `peers` hands
the benchmarks the libraries' own closed-form functions.
"""

from orbits.validate.backends import BACKENDS, available
from orbits.validate.plan import Measurement
from orbits.validate.run import Check, SceneReport, ValidationReport, validate, validate_scene
from orbits.validate.scenes import builtin_names, load, summaries, unavailable_builtins

__all__ = ["BACKENDS", "Check", "Measurement", "SceneReport", "ValidationReport", "available", "builtin_names",
           "load", "summaries", "unavailable_builtins", "validate", "validate_scene"]
