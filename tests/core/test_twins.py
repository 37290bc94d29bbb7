"""Each NumPy specification and its compiled port depend one way: the constants they share come from one module
both import, the port imports nothing from the specification, and the specification takes only the port's module
(to call its kernels), never a name from it. Checked at run time in a fresh interpreter, by recording every import
statement the six modules execute (as tests/test_layering.py does)."""

import json
import subprocess
import sys
import textwrap

import pytest

pytest.importorskip("numba")

TWINS = [("twobody.kepler", "twobody._fast_kepler", "twobody._kepler_shared"),
         ("twobody.propagate", "twobody._fast_propagate", "twobody._propagate_shared"),
         ("manoeuvres.lambert", "manoeuvres._fast_lambert", "manoeuvres._lambert_shared")]

PROBE = """
import builtins, importlib, json

edges = set()
real_import = builtins.__import__


def record(name, globals=None, locals=None, fromlist=(), level=0):
    module = real_import(name, globals, locals, fromlist, level)
    importer = (globals or {}).get("__name__", "")
    if importer.startswith("orbits.core"):
        for item in fromlist or ("",):
            edges.add((importer, name, item))
    return module


builtins.__import__ = record
for spec, port in (("twobody.kepler", "twobody._fast_kepler"), ("twobody.propagate", "twobody._fast_propagate"),
                   ("manoeuvres.lambert", "manoeuvres._fast_lambert")):
    importlib.import_module("orbits.core." + spec)
    importlib.import_module("orbits.core." + port)
print(json.dumps(sorted(edges)))
"""


@pytest.fixture(scope="module")
def edges():
    result = subprocess.run([sys.executable, "-c", textwrap.dedent(PROBE)], capture_output=True, text=True,
                            check=True, timeout=600)
    return [tuple(edge) for edge in json.loads(result.stdout.splitlines()[-1])]


def names_taken(edges, importer, source):
    """What `importer` takes from module `source`: names of `from source import ...`, or the module itself."""
    importer, source = f"orbits.core.{importer}", f"orbits.core.{source}"
    package, _, module = source.rpartition(".")
    taken = {item for src, name, item in edges if src == importer and name == source}
    return taken | {source for src, name, item in edges if src == importer and name == package and item == module}


@pytest.mark.parametrize("spec, port, shared", TWINS)
def test_twins_share_constants_through_one_module_and_depend_one_way(edges, spec, port, shared):
    assert names_taken(edges, spec, shared) and names_taken(edges, port, shared)  # not vacuous
    assert names_taken(edges, port, spec) == set()
    assert names_taken(edges, spec, port) <= {f"orbits.core.{port}"}
