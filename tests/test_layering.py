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


def test_core_imports_numpy_and_itself_only():
    for path in (ROOT / "orbits" / "core").glob("*.py"):
        for name in imports_of(path):
            top = name.split(".")[0]
            assert top in STDLIB_OK | {"numpy"} or name.startswith(("orbits.core", "orbits.errors")), (path, name)


def test_library_never_imports_the_cli():
    for path in (ROOT / "orbits").rglob("*.py"):
        assert not any(n.startswith("orbits_cli") for n in imports_of(path)), path


def test_backends_are_imported_only_by_their_adapters():
    for path in (ROOT / "orbits").rglob("*.py"):
        for name in imports_of(path):
            top = name.split(".")[0]
            if top in ("rebound", "heyoka"):
                assert path.name in ("_rebound.py", "_heyoka.py", "bench.py"), (path, name)
