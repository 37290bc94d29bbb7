"""The house's layering, checked at run time in fresh interpreters: what `sys.modules` holds after an import, and
which import statements the code actually executes (every `import` goes through builtins.__import__, which a
probe wraps to record importer -> imported), never by reading source text.

Layers, bottom up; a module may import its own layer and the layers below it:
    0 core         orbits.core.*: float64 NumPy; numpy, the standard library and (in the _fast kernels) numba
    1 base         units, constants, catalogue_orbits, inputs (the input rules), nbody, io, tables, display, system
    2 domain       orbit, kepler, binary, flyby, escape, lagrange, rings, cosmology, scene, predict, and the
                   pictures orbits.plot.* (one module per subject over the shared orbits._common.frame)
    3 validation   orbits.validate.*
    4 tools        orbits.tools.* (benchmarks, precision sweeps, the mpmath reference, Dask)
    5 interfaces   orbits_cli.*, which calls the public library only: never orbits.core nor a private module
The package `orbits` itself is a lazy facade (PEP 562) for users, the tools and the command line.
"""

import json
import os
import subprocess
import sys
import textwrap

import pytest

FACADES = {"orbits", "orbits.plot"}
HEAVY = ("astropy", "rebound", "heyoka", "numba", "matplotlib", "dask", "distributed", "mpmath", "scipy")


def layer(module):
    """Rank of one of our modules in the layering (the facade ranks with the tools)."""
    if module.startswith("orbits.core"):
        return 0
    if module.startswith("orbits._common"):
        return 1
    if module.startswith("orbits.validate"):
        return 3
    if module.startswith("orbits.tools") or module in FACADES:
        return 4
    if module.startswith("orbits_cli"):
        return 5
    return 2


def fresh(code, **env):
    """Run `code` in a fresh interpreter and return what it printed (stdout), failing on a non-zero exit."""
    result = subprocess.run([sys.executable, "-c", textwrap.dedent(code)], capture_output=True, text=True,
                            env={**os.environ, "MPLBACKEND": "Agg", **env}, timeout=600)
    assert result.returncode == 0, result.stderr
    return result.stdout


def loaded_after(statement):
    """The top-level names of the heavy packages and our own modules in sys.modules after `statement`."""
    out = fresh(f"""
        import json, sys
        {statement}
        print(json.dumps(sorted(sys.modules)))
    """)
    return set(json.loads(out))


def heavy(modules):
    return {m for m in modules if m.split(".")[0] in HEAVY}


def ours(modules):
    return {m for m in modules if m in FACADES or m.startswith(("orbits.", "orbits_cli"))}


# ---- what an import loads -------------------------------------------------------------------------------


def test_import_orbits_loads_nothing_heavy():
    modules = loaded_after("import orbits")
    assert heavy(modules) == set() and ours(modules) == {"orbits"}


CORE_MODULES = [
    "twobody.anomalies", "encounters.binary", "checks", "twobody.elements", "errors", "encounters.escape",
    "encounters.flyby", "cosmology.friedmann", "twobody.kepler", "threebody.lagrange", "twobody.propagate",
    "cosmology.quadrature", "threebody.rings", "series", "cosmology.sphere", "twobody.twobody", "_dd", "_roots",
    "frames", "manoeuvres.rocket", "manoeuvres.impulsive", "manoeuvres.assist", "mechanics.collisions",
    "mechanics.rotation", "mechanics.projectile", "mechanics.oscillations", "manoeuvres.lambert",
    "twobody.transition", "periodic.cr3bp", "dop853", "periodic.libration", "periodic.shooting",
    "periodic.continuation", "periodic.families", "perturb.oblateness", "perturb.drag", "perturb.third_body",
    "perturb.relativity",
]


@pytest.mark.parametrize("name", CORE_MODULES)
def test_every_core_module_stands_alone(name):
    """The core loads numpy and itself only: no astropy, no JIT, and nothing of the layers above."""
    modules = loaded_after(f"import orbits.core.{name}")
    assert heavy(modules) == set()
    assert {m for m in ours(modules) if m not in FACADES and not m.startswith("orbits.core")} == set()


def test_the_public_api_loads_no_integrator_jit_or_plotting_library():
    """Every public name (astropy is the API's unit system) without rebound, heyoka, numba or matplotlib."""
    modules = loaded_after("import orbits; [getattr(orbits, name) for name in orbits.__all__]")
    assert heavy(modules) <= {m for m in modules if m.split(".")[0] == "astropy"}
    assert not any(m.startswith(("orbits.validate", "orbits.tools", "orbits_cli")) for m in modules)


def test_the_validation_layer_loads_its_backends_only_to_integrate():
    modules = loaded_after("import orbits.validate")
    assert not {m.split(".")[0] for m in modules} & {"rebound", "heyoka", "numba", "matplotlib"}
    assert not any(m.startswith(("orbits.tools", "orbits_cli")) for m in modules)


def test_the_command_line_starts_without_the_library():
    """`orbits --help` imports typer and the command modules only."""
    modules = loaded_after("import orbits_cli.main")
    assert heavy(modules) == set()
    assert {m for m in ours(modules) if not m.startswith("orbits_cli")} == set()


# ---- who imports whom, at run time ---------------------------------------------------------------------

PROBE = """
import builtins, importlib.util, json, os, pkgutil, sys, tempfile

edges = set()
real_import = builtins.__import__


def ours(name):
    return name == "orbits" or name.startswith(("orbits.", "orbits_cli"))


def record(name, globals=None, locals=None, fromlist=(), level=0):
    module = real_import(name, globals, locals, fromlist, level)
    importer = (globals or {}).get("__name__", "")
    if ours(importer):
        base = importlib.util.resolve_name("." * level + name, globals.get("__package__")) if level else name
        targets = [f"{base}.{item}" if f"{base}.{item}" in sys.modules else base for item in fromlist or ()]
        for target in targets or [base]:
            edges.add((importer, target))
    return module


builtins.__import__ = record

import orbits, orbits_cli
for package in (orbits, orbits_cli):
    for info in pkgutil.walk_packages(package.__path__, package.__name__ + "."):
        importlib.import_module(info.name)

from typer.testing import CliRunner
from orbits_cli.main import app

out = tempfile.mkdtemp()
runs = [
    ["kepler", "--e", "0.5", "--M", "1"],
    ["kepler", "--e", "2", "--nu", "30 deg"],
    ["orbit", "Earth", "--format", "json"],
    ["orbit", "--primary", "Earth", "--a", "7000 km", "--e", "0.1", "--plot", os.path.join(out, "o.png")],
    ["orbit", "--primary", "Earth", "--r", "7000,0,0 km", "--v", "0,7.5,0 km/s"],
    ["binary", "--m1", "Earth", "--m2", "Moon", "--a", "384399 km", "--plot", os.path.join(out, "b.png")],
    ["flyby", "--primary", "Earth", "--v-inf", "1 km/s", "--b", "10000 km", "--plot", os.path.join(out, "f.png")],
    ["lagrange", "--primary", "Earth", "--secondary", "Moon"],
    ["periodic", "--primary", "Earth", "--secondary", "Moon", "--family", "halo", "--point", "L2", "--az", "5000 km"],
    ["ring", "3", "--mass", "1 kg", "--radius", "1 m"],
    ["escape", "cosmic"],
    ["where", "Mars", "--epoch", "2026-11-25", "--plot", os.path.join(out, "w.png")],
    ["orbit", "Mars", "--epoch", "2026-11-25 TDB"],
    ["escape", "geo", "--primary", "Earth"],
    ["rocket", "--m0", "100 t", "--mf", "40 t", "--isp", "300 s", "--thrust", "2 MN"],
    ["transfer", "hohmann", "--radius1", "6678 km", "--radius2", "42164 km", "--format", "json"],
    ["lambert", "--r1", "1,0,0 AU", "--r2", "0,1.5,0 AU", "--tof", "200 d", "--format", "json"],
    ["porkchop", "--depart", "2026-10-01:2026-12-01", "--arrive", "2027-07-01:2027-10-01", "--step", "15 d",
     "--plot", os.path.join(out, "pc.png")],
    ["cosmology", "--z", "1", "--plot", os.path.join(out, "c.png")],
    ["validate", "circular", "expanding_universe", "--output", os.path.join(out, "v.json"),
     "--plot", os.path.join(out, "v.png")],
    ["info"],
    ["collide", "--m1", "2 kg", "--v1", "3 m/s", "--m2", "1 kg", "--v2", "0 m/s", "--plot", os.path.join(out, "k.png")],
    ["projectile", "--speed", "20 m/s", "--angle", "45", "--drag", "quadratic", "--terminal-speed", "30 m/s"],
    ["pendulum", "--length", "1 m", "--amplitude", "170 deg", "--plot", os.path.join(out, "p.png")],
    ["perturb", "rates", "--altitude", "400 km", "--inc", "51.64", "--plot-revolutions", "1", "--plot",
     os.path.join(out, "j2.png")],
    ["perturb", "decay", "--altitude", "280 km", "--ballistic", "0.022 m2/kg", "--plot", os.path.join(out, "d.png")],
]
for args in runs:
    result = CliRunner().invoke(app, args)
    assert result.exit_code == 0, (args, result.output)

import astropy.units as u

orbits.Orbit.circular("Earth", 7000 * u.km).plot()  # the picture a domain object draws of itself
print(json.dumps(sorted(edges)))
"""


@pytest.fixture(scope="module")
def edges():
    """(importer, imported) for every import statement executed while importing every module of orbits and
    orbits_cli and running each command-line verb once."""
    return [tuple(edge) for edge in json.loads(fresh(PROBE).splitlines()[-1])]


def test_the_probe_sees_the_imports_inside_functions(edges):
    """The record is not vacuous: the lazy imports inside commands and adapters are there."""
    assert ("orbits_cli.commands.validate", "orbits.validate") in edges
    assert ("orbits.twobody.orbit", "orbits.twobody.plot") in edges  # Orbit.plot draws its own subject's picture
    assert ("orbits.validate._rebound", "rebound") in edges and ("orbits.validate._heyoka", "heyoka") in edges
    assert any(src.startswith("orbits.core") and dst.startswith("orbits.core") for src, dst in edges)


def import_cycles(edges):
    """The strongly connected components of more than one module in the graph importer -> imported among our own
    modules (orbits.* and orbits_cli.*, the facade `orbits` aside), each sorted: every one holds an import cycle."""
    graph = {}
    for src, dst in edges:
        if src != dst and all(name.startswith(("orbits.", "orbits_cli")) for name in (src, dst)):
            graph.setdefault(src, set()).add(dst)
    index, low, stack, on_stack, components = {}, {}, [], set(), []

    def visit(node):  # Tarjan's algorithm
        index[node] = low[node] = len(index)
        stack.append(node)
        on_stack.add(node)
        for nxt in graph.get(node, ()):
            if nxt not in index:
                visit(nxt)
                low[node] = min(low[node], low[nxt])
            elif nxt in on_stack:
                low[node] = min(low[node], index[nxt])
        if low[node] == index[node]:
            component = []
            while not component or component[-1] != node:
                component.append(stack.pop())
                on_stack.discard(component[-1])
            if len(component) > 1:
                components.append(sorted(component))

    for node in sorted(graph):
        if node not in index:
            visit(node)
    return sorted(components)


def test_import_cycles_are_found():
    """The cycle finder is not vacuous: a -> b -> c -> a is one cycle, d -> a outside it; the facade is no node."""
    edges = [("orbits.a", "orbits.b"), ("orbits.b", "orbits.c"), ("orbits.c", "orbits.a"), ("orbits.d", "orbits.a"),
             ("orbits.e", "orbits"), ("orbits", "orbits.e")]
    assert import_cycles(edges) == [["orbits.a", "orbits.b", "orbits.c"]]


def test_no_module_imports_itself_back(edges):
    """No import cycle between our modules at run time, function-local imports included: a module never needs,
    directly or through others, a module that needs it (e.g. a picture importing the object that draws itself)."""
    assert import_cycles(edges) == []


def test_the_picture_frame_imports_no_picture(edges):
    """orbits._common.frame is what every picture builds on: it imports no other module of orbits.plot."""
    assert [(src, dst) for src, dst in edges if src == "orbits._common.frame" and dst.startswith("orbits.plot")] == []
    assert ("orbits.twobody.plot", "orbits._common.frame") in edges


def test_imports_flow_one_way(edges):
    """No module imports a layer above its own (e.g. domain -> validation, validation -> tools, core -> units)."""
    upward = [(src, dst) for src, dst in edges
              if src not in FACADES and dst.split(".")[0] in ("orbits", "orbits_cli") and layer(dst) > layer(src)]
    assert upward == []


def test_no_verb_imports_another(edges):
    """What two verbs share lives in orbits_cli.options; a verb's module imports no other verb's."""
    across = [(src, dst) for src, dst in edges if src.startswith("orbits_cli.commands.")
              and dst.startswith("orbits_cli.commands.") and src != dst]
    assert across == []


def test_the_command_line_calls_only_the_public_library(edges):
    """orbits_cli never reaches into the numeric core or a private module: it calls unit-aware functions, and
    reads text with the library's own input rules and display (orbits._common, the house's infrastructure)."""
    behind = [(src, dst) for src, dst in edges if src.startswith("orbits_cli") and dst.startswith("orbits.")
              and not dst.startswith("orbits._common")
              and (dst.startswith("orbits.core") or any(part.startswith("_") for part in dst.split(".")))]
    assert behind == []


def test_the_core_imports_numpy_and_the_standard_library_only(edges):
    allowed = set(sys.stdlib_module_names) | {"numpy"}
    kernels = allowed | {"numba", "llvmlite"}
    outside = [(src, dst) for src, dst in edges if src.startswith("orbits.core") and not dst.startswith("orbits")
               and dst.split(".")[0] not in (kernels if src.split(".")[-1].startswith("_fast") else allowed)]
    assert outside == []


ADAPTERS = {"orbits.validate._rebound", "orbits.validate._heyoka"}


def test_rebound_and_heyoka_are_imported_by_their_adapters_only(edges):
    importers = {src for src, dst in edges if dst.split(".")[0] in ("rebound", "reboundx", "heyoka")}
    assert importers <= ADAPTERS


def test_no_other_module_holds_an_import_of_rebound_or_heyoka():
    """Every import statement of the library's source, executed or not (an import inside a benchmark the probe does
    not run included), names rebound, REBOUNDx or heyoka only in the two adapters."""
    import ast
    import pathlib

    import orbits

    root = pathlib.Path(orbits.__file__).parent
    found = set()
    for path in root.rglob("*.py"):
        for node in ast.walk(ast.parse(path.read_text())):
            names = ([a.name for a in node.names] if isinstance(node, ast.Import)
                     else [node.module or ""] if isinstance(node, ast.ImportFrom) and not node.level else [])
            if any(n.split(".")[0] in ("rebound", "reboundx", "heyoka") for n in names):
                found.add("orbits." + ".".join(path.relative_to(root).with_suffix("").parts))
    assert found == ADAPTERS


def test_the_library_never_imports_the_command_line(edges):
    assert [(src, dst) for src, dst in edges if src.startswith("orbits") and not src.startswith("orbits_cli")
            and dst.startswith("orbits_cli")] == []


BENCH = "orbits.tools.bench."
BENCH_SHARED = {BENCH + "table", BENCH + "harness"}


def test_benchmarks_import_the_shared_bench_modules_only(edges):
    """A benchmark module of orbits.tools.bench imports no other benchmark, only the shared table and harness
    modules (which import no module of the package); suite, which runs every benchmark, imports them all."""
    within = [(src, dst) for src, dst in edges if src.startswith(BENCH) and dst.startswith(BENCH)]
    assert (BENCH + "kepler", BENCH + "table") in within and (BENCH + "suite", BENCH + "kepler") in within
    assert [(src, dst) for src, dst in within if src != BENCH + "suite" and dst not in BENCH_SHARED] == []
    assert [(src, dst) for src, dst in within if src in BENCH_SHARED] == []
