"""`orbits info`: versions, cache locations and where the constants come from."""

import os
import platform
from importlib import metadata
from pathlib import Path
from typing import Any

from orbits_cli.options import Format, FormatOption

_PACKAGES = ["orbits", "numpy", "astropy", "rebound", "heyoka", "typer", "rich", "mpmath"]


def command(fmt: FormatOption = Format.table) -> None:
    """Versions of orbits and its dependencies, cache locations, and the constants' sources."""
    show(fmt.value)


def _version(name):
    try:
        return metadata.version(name)
    except metadata.PackageNotFoundError:
        return "not installed"


def collect() -> dict[str, Any]:
    """Facts about this installation, without importing the heavy backends."""
    from orbits.constants import BODIES

    heyoka_cache = os.environ.get("HEYOKA_CACHE_DIR") or str(Path.home() / ".cache" / "heyoka")
    return {
        "python": platform.python_version(),
        "platform": platform.platform(),
        "versions": {name: _version(name) for name in _PACKAGES},
        "caches": {"heyoka compiled integrators (HEYOKA_CACHE_DIR)": heyoka_cache},
        "constants": {"G": "CODATA 2018 (astropy.constants)", **{b.name: b.source for b in BODIES.values()}},
    }


def show(fmt: str) -> None:
    """Print the facts as a table or JSON."""
    from rich import box
    from rich.table import Table

    from orbits_cli import render

    facts = collect()
    if fmt == "json":
        print(render.dumps(facts))
        return
    grid = Table(show_header=False, box=box.SIMPLE, pad_edge=False)
    grid.add_column("item", overflow="fold")
    grid.add_column("value", overflow="fold")
    grid.add_row("python", f"{facts['python']} on {facts['platform']}")
    for section in ("versions", "caches", "constants"):
        for key, value in facts[section].items():
            grid.add_row(key, value)
    render.print_tables([grid], "orbits info")
