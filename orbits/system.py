"""Facts about this installation: versions, cache folders, whether the compiled kernels run, and where the
constants come from (`orbits info`). Nothing heavy is imported to tell them: not numba, rebound or heyoka."""

import importlib.util
import os
import platform
from importlib import metadata
from pathlib import Path
from typing import Any

from orbits.constants import BODIES
from orbits.core import _fast

PACKAGES = ["orbits", "numpy", "astropy", "numba", "rebound", "heyoka", "typer", "rich", "mpmath"]


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
        "constants": {"G": "CODATA 2018 (astropy.constants)", **{b.name: b.source for b in BODIES.values()}},
    }


def _kernels_in_use() -> str:
    """Whether the compiled kernels would run, told without importing numba (orbits.core._fast.enabled)."""
    if os.environ.get("ORBITS_JIT", "1").strip().lower() in ("0", "false", "no", "off"):
        return "no: ORBITS_JIT is off, the NumPy implementations run"
    if importlib.util.find_spec("numba") is None:
        return "no: numba is not installed, the NumPy implementations run"
    return "yes"
