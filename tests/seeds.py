"""Fresh seeds for the accuracy sweeps: a new one each run (ORBITS_TEST_SEED=N replays a run's), so that no fixed
sample can hide a new worst case of a bound the README states. Every seed drawn is printed in the run's summary
(tests/conftest.py), and the tests name theirs in a failing message."""

import os
import secrets

#: the seeds drawn in this run: who drew it -> seed
DRAWN = {}


def draw(who: str) -> int:
    """A fresh 63-bit seed for `who` (a test id or a module), or ORBITS_TEST_SEED when set."""
    seed = int(os.environ.get("ORBITS_TEST_SEED") or secrets.randbits(63))
    DRAWN[who] = seed
    return seed
