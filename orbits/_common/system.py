"""Facts about this installation: versions, cache folders, whether the compiled kernels run, and where the
constants come from (`orbits info`). Nothing heavy is imported to tell them: not numba, rebound or heyoka."""

import importlib.util
import os
import platform
from importlib import metadata
from pathlib import Path
from typing import Any

from orbits._common.constants import BODIES
from orbits.core import _fast

PACKAGES = ["orbits", "numpy", "astropy", "numba", "rebound", "heyoka", "typer", "rich", "mpmath", "skyfield-data",
            "jplephem", "reboundx"]


def _version(name):
    try:
        return metadata.version(name)
    except metadata.PackageNotFoundError:
        return "not installed"


def info() -> dict[str, Any]:
    """Facts about this installation, without importing the heavy backends."""
    heyoka_cache = os.environ.get("HEYOKA_CACHE_DIR") or str(Path.home() / ".cache" / "heyoka")
    return {
        "python": platform.python_version(),
        "platform": platform.platform(),
        "versions": {name: _version(name) for name in PACKAGES},
        "caches": {"heyoka compiled integrators (HEYOKA_CACHE_DIR)": heyoka_cache,
                   "orbits compiled kernels (numba; NUMBA_CACHE_DIR)": _fast.cache_dir() or "in memory (no folder)",
                   "compiled kernels in use (ORBITS_JIT)": _kernels_in_use()},
        "kernels_ready": {kernel: _fast.ready(kernel) for kernel in _fast.entry_kernels()},
        "ephemeris": _ephemeris(),
        "constants": {"G": "CODATA 2018 (astropy.constants)", **{b.name: b.source for b in BODIES.values()}},
        "bodies": [{"name": b.name, "kind": b.kind, "parent": b.parent, "gm_m3_s2": b.gm,
                    "system_gm_m3_s2": b.system_gm, "radius_m": b.radius,
                    "rotation_period_s": b.rotation_period, "retrograde": b.retrograde, "j2": b.j2,
                    "j2_radius_m": b.j2_radius} for b in BODIES.values()],
    }


def _ephemeris() -> str:
    """Which ephemeris answers `source="auto"`, told without importing jplephem."""
    if all(importlib.util.find_spec(m) is not None for m in ("skyfield_data", "jplephem")):
        return "JPL DE421 (skyfield-data, read by jplephem), 1899-07-29 to 2053-10-09"
    return "astropy built-in (approximate; pip install 'orbits[ephemeris]' for JPL DE421)"


def _kernels_in_use() -> str:
    """When the compiled kernels run, told without importing numba (orbits.core._fast.use)."""
    setting = os.environ.get("ORBITS_JIT", "auto").strip().lower()
    if setting in ("0", "false", "no", "off"):
        return "no: ORBITS_JIT is off, the NumPy implementations run"
    if importlib.util.find_spec("numba") is None:
        return "no: numba is not installed, the NumPy implementations run"
    if setting in ("1", "true", "yes", "on"):
        return "always (ORBITS_JIT=1): an absent kernel compiles at its first call"
    return (f"a cached kernel for any batch, an absent one compiles for batches of {_fast.AUTO_MIN_BATCH:,} or more "
            f"(ORBITS_JIT=auto)")
