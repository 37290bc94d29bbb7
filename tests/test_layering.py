"""Imports flow one way (interfaces -> domain -> core), and the heavy backends stay in their adapters."""

import ast
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
STDLIB_OK = {"math", "functools", "dataclasses", "typing", "enum"}


def imports_of(path):
    tree = ast.parse(path.read_text())
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            yield from (alias.name for alias in node.names)
        elif isinstance(node, ast.ImportFrom) and node.level == 0:
            yield node.module


# The compiled kernels (orbits/core/_fast*.py) also use numba and what locating its disk cache takes;
# they are imported lazily, so `import orbits` never loads numba (tests/core/test_fast_kepler.py).
FAST_KERNELS_OK = {"numba", "llvmlite", "os", "tempfile", "hashlib", "pathlib", "concurrent"}


def test_core_imports_numpy_and_itself_only():
    for path in (ROOT / "orbits" / "core").glob("*.py"):
        allowed = STDLIB_OK | {"numpy"} | (FAST_KERNELS_OK if path.name.startswith("_fast") else set())
        for name in imports_of(path):
            top = name.split(".")[0]
            assert top in allowed or name.startswith(("orbits.core", "orbits.core.errors")), (path, name)


def test_library_never_imports_the_cli():
    for path in (ROOT / "orbits").rglob("*.py"):
        assert not any(n.startswith("orbits_cli") for n in imports_of(path)), path


def test_backends_are_imported_only_by_their_adapters():
    for path in (ROOT / "orbits").rglob("*.py"):
        for name in imports_of(path):
            top = name.split(".")[0]
            if top in ("rebound", "heyoka"):
                assert path.name in ("_rebound.py", "_heyoka.py", "bench.py"), (path, name)
