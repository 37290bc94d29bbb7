"""The size of the `slow` tests, in one place: ORBITS_SLOW_SCALE multiplies their spans and sample counts.

Unset, it is 0.05, the bounded form that the README's test command and CI (`.ci/run` sets it explicitly) run in
a few seconds each; ORBITS_SLOW_SCALE=1 runs the full size (about 3.5 more minutes on 2 cores).
"""

import os

import pytest

#: the scale when ORBITS_SLOW_SCALE is unset
DEFAULT = 0.05


def slow_scale() -> float:
    """ORBITS_SLOW_SCALE as a positive float (DEFAULT when unset)."""
    value = os.environ.get("ORBITS_SLOW_SCALE")
    if value is None:
        return DEFAULT
    try:
        scale = float(value)
    except ValueError:
        scale = float("nan")
    if not scale > 0:
        raise pytest.UsageError(f"ORBITS_SLOW_SCALE = {value!r} must be a positive number (1 = full size)")
    return scale
