"""A corrupted on-disk cache of the compiled kernels is detected, cleared with one line on stderr, and rebuilt."""

import os
import subprocess
import sys
from pathlib import Path

import pytest

pytest.importorskip("numba")

SOLVE = ("import numpy as np; from orbits.core.twobody import kepler; "
         "print(repr(float(kepler.eccentric_anomaly(np.array([0.3, 1.0]), np.array([0.5, 0.9]))[1])))")


def solve(cache):
    result = subprocess.run([sys.executable, "-c", SOLVE], capture_output=True, text=True, timeout=600,
                            env={**os.environ, "NUMBA_CACHE_DIR": str(cache), "ORBITS_JIT": "1"})  # kernels always
    assert result.returncode == 0, result.stderr
    return result.stdout.strip(), result.stderr


def test_a_truncated_cache_is_cleared_and_rebuilt(tmp_path):
    first, _ = solve(tmp_path)
    files = list(tmp_path.rglob("*.nbi")) + list(tmp_path.rglob("*.nbc"))  # index and code
    assert files, "the first run wrote the kernels' cache"
    for path in files:
        path.write_bytes(path.read_bytes()[:20])  # truncated, as by a full disk or a killed process
    second, warning = solve(tmp_path)
    assert second == first  # the NumPy implementation answered, with the same bits
    lines = [line for line in warning.splitlines() if line.strip()]
    assert len(lines) == 1 and "was unreadable" in lines[0] and "cleared it" in lines[0]
    third, quiet = solve(tmp_path)
    assert third == first and "unreadable" not in quiet
    assert any(Path(tmp_path).rglob("*.nbi"))  # compiled and cached again


def test_a_cache_holding_another_kernels_code_is_cleared_like_a_corrupt_one(tmp_path):
    """Two cache files swapped gave "_halley expected 8 arguments, got 5" on every later run: numba checks an entry's
    signature, not whose code it holds, and the cache was never cleared."""
    first, _ = solve(tmp_path)
    entry = next(tmp_path.rglob("_fast_kepler.elliptic-*.nbc"))
    other = next(tmp_path.rglob("_fast_kepler._halley-*.nbc"))
    entry_bytes, other_bytes = entry.read_bytes(), other.read_bytes()
    entry.write_bytes(other_bytes)
    other.write_bytes(entry_bytes)
    second, warning = solve(tmp_path)
    assert second == first  # the NumPy implementation answered, with the same bits
    lines = [line for line in warning.splitlines() if line.strip()]
    assert len(lines) == 1 and "held the code of _halley under the name elliptic; cleared it" in lines[0], warning
    third, _ = solve(tmp_path)  # compiled again
    fourth, quiet = solve(tmp_path)
    assert third == fourth == first and "held" not in quiet and "compiling" not in quiet
