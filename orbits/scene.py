"""Scenes: plain data describing bodies, their initial state, output times and what the user asks for.

A scene is loaded from TOML or JSON (same schema) and validated completely before anything runs; a bad
file raises SceneError naming the file, the field and what is allowed. Everything is converted to SI
float64 here, once. Schema (TOML):

    name = "eccentric"
    description = "a comet-like test particle on an e = 0.9 orbit about the Sun"
    asks = ["positions", "conserved", "period"]          # any of ASKS

    [time]
    periods = 100        # span in periods of the first body with an orbit; or span = "10 yr"
    outputs = 200        # evenly spaced output times in (0, span]; or times = ["1 d", "2.5 d"]

    [tolerance]          # optional relative tolerances per check (defaults in DEFAULT_TOLERANCE)
    positions = 1e-10

    [[bodies]]
    name = "Sun"
    body = "Sun"         # catalogue GM; or gm = "1.327e20 m3 / s2"; or mass = "1 solMass"
    position = "0,0,0 km"          # optional Cartesian state (default: at rest at the origin)
    velocity = "0,0,0 km/s"

    [[bodies]]
    name = "comet"
    test_particle = true           # massless: rebound N_active, heyoka's restricted n-body model
    orbit = { primary = "Sun", a = "1 AU", e = 0.9, inc = "10 deg", raan = "0 deg", argp = "0 deg", nu = "0 deg" }

An `orbit` gives the body's state relative to an earlier-listed primary, as the relative Kepler orbit
with mu = G (M_primary + m_body) (exact for an isolated pair); use exactly one of a, p, q.
"""

import contextlib
import json
import tomllib
from collections.abc import Iterator
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, NoReturn

import astropy.units as u
import numpy as np

from orbits import inputs
from orbits.constants import BODIES
from orbits.core import elements, twobody
from orbits.core.errors import OrbitsError, SceneError

ASKS = ("positions", "conserved", "period", "closest_approach")
DEFAULT_TOLERANCE = {"positions": 1e-10, "energy": 1e-11, "angular_momentum": 1e-11, "lrl": 1e-10,
                     "period": 1e-10, "closest_approach": 1e-10}
BUILTIN_DIR = Path(__file__).parent / "scenes"


@dataclass(frozen=True)
class OrbitSpec:
    """Initial relative orbit of a body about an earlier-listed primary (SI, radians)."""

    primary: int
    p: float
    e: float
    inc: float
    raan: float
    argp: float
    nu: float


@dataclass(frozen=True, eq=False)
class BodySpec:
    """One body: name, GM (m3/s2, 0 for test particles), initial state (m, m/s) and its orbit if given."""

    name: str
    gm: float
    position: np.ndarray
    velocity: np.ndarray
    test_particle: bool = False
    orbit: OrbitSpec | None = None


@dataclass(frozen=True, eq=False)
class Scene:
    """A validated scene in SI units: bodies (massive first), output times (s), asks and tolerances."""

    name: str
    description: str
    bodies: tuple[BodySpec, ...]
    times: np.ndarray
    asks: tuple[str, ...]
    tolerance: dict = field(default_factory=dict)

    @property
    def n_active(self) -> int:
        """Number of massive bodies (they come first)."""
        return sum(not b.test_particle for b in self.bodies)

    @property
    def gm(self) -> np.ndarray:
        """(N,) GM of every body (m3/s2)."""
        return np.array([b.gm for b in self.bodies])

    @property
    def positions(self) -> np.ndarray:
        """(N, 3) initial positions (m)."""
        return np.array([b.position for b in self.bodies])

    @property
    def velocities(self) -> np.ndarray:
        """(N, 3) initial velocities (m/s)."""
        return np.array([b.velocity for b in self.bodies])

    @property
    def orbiting(self) -> list[int]:
        """Indices of the bodies that were given an orbit (the subjects of period and closest approach)."""
        return [i for i, b in enumerate(self.bodies) if b.orbit is not None]


def builtin_names() -> list[str]:
    """Names of the built-in scenes, in the order `orbits validate` runs them."""
    return sorted(path.stem for path in BUILTIN_DIR.glob("*.toml"))


def read(name_or_path: str | Path) -> tuple[dict, str]:
    """(parsed dictionary, source path) of a built-in scene name or a .toml / .json file, read once."""
    path = Path(name_or_path)
    if not path.suffix and (BUILTIN_DIR / f"{name_or_path}.toml").exists():
        path = BUILTIN_DIR / f"{name_or_path}.toml"
    if not path.exists():
        raise SceneError(f"{name_or_path}: no such scene file, and not a built-in scene ({', '.join(builtin_names())})")
    text = path.read_text()
    try:
        data = json.loads(text) if path.suffix == ".json" else tomllib.loads(text)
    except (json.JSONDecodeError, tomllib.TOMLDecodeError) as err:
        raise SceneError(f"{path}: not valid {'JSON' if path.suffix == '.json' else 'TOML'}: {err}") from None
    return data, str(path)


def load(name_or_path: str | Path) -> "Scene":
    """Data scene from a built-in name, or from a .toml / .json file (model scenes: orbits.validate.scenes.load)."""
    return from_dict(*read(name_or_path))


def from_dict(data: dict, source: str = "<scene>") -> Scene:
    """Validate a scene dictionary (the parsed TOML/JSON) and convert it to SI."""
    ctx = _Context(source)
    name = ctx.string(data, "name")
    asks = tuple(ctx.get(data, "asks", list))
    for ask in asks:
        if ask not in ASKS:
            ctx.fail("asks", f"unknown ask {ask!r}; allowed: {', '.join(ASKS)}")
    if not asks:
        ctx.fail("asks", f"ask for at least one of: {', '.join(ASKS)}")
    bodies = _bodies(ctx, ctx.get(data, "bodies", list))
    times = _times(ctx, ctx.get(data, "time", dict), bodies)
    tolerance = dict(DEFAULT_TOLERANCE)
    for key, value in data.get("tolerance", {}).items():
        if key not in DEFAULT_TOLERANCE:
            ctx.fail(f"tolerance.{key}", f"unknown check; allowed: {', '.join(DEFAULT_TOLERANCE)}")
        if not isinstance(value, (int, float)) or isinstance(value, bool) or not value > 0:
            ctx.fail(f"tolerance.{key}", f"{value!r} must be a positive number (relative error)")
        tolerance[key] = float(value)
    if ("period" in asks or "closest_approach" in asks) and not any(b.orbit for b in bodies):
        ctx.fail("asks", "period and closest_approach need at least one body with an `orbit` table")
    return Scene(name, str(data.get("description", "")), bodies, times, asks, tolerance)


class _Context:
    """Error reporting that names the source and the field."""

    def __init__(self, source):
        self.source = source

    def fail(self, where: str, message: str) -> NoReturn:
        raise SceneError(f"{self.source}: {where}: {message}")

    def get(self, data: dict, key: str, kind: type, where: str | None = None) -> Any:
        where = where or key
        if key not in data:
            self.fail(where, f"missing (a {kind.__name__} is required)")
        if not isinstance(data[key], kind):
            self.fail(where, f"{data[key]!r} must be a {kind.__name__}")
        return data[key]

    def string(self, data: dict, key: str, where: str | None = None) -> str:
        return self.get(data, key, str, where)

    def quantity(self, text: str, kind: str, where: str, bare_unit: u.UnitBase | None = None) -> float:
        """The SI value (float) of a quantity string of the given kind (orbits.inputs.KINDS)."""
        with self.field(where):
            value = inputs.parse_quantity(text, kind, where, bare_unit)
        return float(value.to_value(inputs.KINDS[kind][0]))

    def vector(self, text: str, kind: str, where: str) -> np.ndarray:
        """The SI value (3,) of a vector string 'X,Y,Z UNIT' of the given kind."""
        with self.field(where):
            value = inputs.parse_vector(text, kind, where)
        return value.to_value(inputs.KINDS[kind][0])

    @contextlib.contextmanager
    def field(self, where: str) -> Iterator[None]:
        """Turn the input rules' errors inside the block into a SceneError naming the source and the field."""
        try:
            yield
        except (OrbitsError, TypeError, u.UnitsError) as err:
            message = str(err).removeprefix(f"{where}: ")
            self.fail(where, message)

    def number(self, data: dict, key: str, where: str, default: float | None = None, low: float = -np.inf) -> float:
        value = data.get(key, default)
        if isinstance(value, bool) or not isinstance(value, (int, float)) or not np.isfinite(value) or value < low:
            self.fail(where, f"{value!r} must be a finite number >= {low}")
        return float(value)


def _gm(ctx, spec, where):
    given = [k for k in ("body", "gm", "mass") if k in spec]
    if len(given) != 1:
        ctx.fail(where, f"give exactly one of body, gm, mass; got {given or 'none'}")
    key = given[0]
    if key == "body":
        named = inputs.find_body(spec["body"])
        if named is None:
            ctx.fail(f"{where}.body", f"unknown body {spec['body']!r}; known: {', '.join(BODIES)}")
        return named.gm
    kind = "gravitational parameter" if key == "gm" else "mass"
    with ctx.field(f"{where}.{key}"):
        value = inputs.parse_quantity(spec[key], kind, f"{where}.{key}")
        return float(inputs.gravitational_parameter(value, f"{where}.{key}"))


def _bodies(ctx, entries):
    if not entries:
        ctx.fail("bodies", "at least one body is required")
    built, names = [], []
    for k, spec in enumerate(entries):
        where = f"bodies[{k}]"
        if not isinstance(spec, dict):
            ctx.fail(where, "must be a table")
        name = ctx.string(spec, "name", f"{where}.name")
        if name in names:
            ctx.fail(f"{where}.name", f"{name!r} is used twice")
        test_particle = spec.get("test_particle", False)
        if not isinstance(test_particle, bool):
            ctx.fail(f"{where}.test_particle", f"{test_particle!r} must be true or false")
        if test_particle and any(key in spec for key in ("body", "gm", "mass")):
            ctx.fail(where, "a test particle is massless: remove body, gm and mass")
        gm = 0.0 if test_particle else _gm(ctx, spec, where)
        built.append(_state(ctx, spec, where, name, gm, test_particle, built, names))
        names.append(name)
    massive = [b for b in built if not b.test_particle]
    if not massive:
        ctx.fail("bodies", "at least one body must be massive (not test_particle)")
    if any(b.test_particle for b in built[: len(massive)]):
        ctx.fail("bodies", "list massive bodies before test particles (test particles come last)")
    return tuple(built)


def _state(ctx, spec, where, name, gm, test_particle, built, names):
    if "orbit" in spec and ("position" in spec or "velocity" in spec):
        ctx.fail(where, "give either an orbit table or position/velocity, not both")
    if "orbit" not in spec:
        r = ctx.vector(spec.get("position", "0,0,0 m"), "length", f"{where}.position")
        v = ctx.vector(spec.get("velocity", "0,0,0 m/s"), "speed", f"{where}.velocity")
        return BodySpec(name, gm, r, v, test_particle)
    orbit = spec["orbit"]
    ow = f"{where}.orbit"
    if not isinstance(orbit, dict):
        ctx.fail(ow, "must be a table")
    primary_name = ctx.string(orbit, "primary", f"{ow}.primary")
    if primary_name not in names:
        ctx.fail(f"{ow}.primary", f"{primary_name!r} must name a body listed earlier ({', '.join(names) or 'none'})")
    primary = built[names.index(primary_name)]
    if primary.test_particle:
        ctx.fail(f"{ow}.primary", f"{primary_name!r} is a test particle; a primary must be massive")
    e = ctx.number(orbit, "e", f"{ow}.e", default=0.0, low=0.0)
    p = _semi_latus_rectum(ctx, orbit, e, ow)
    angles = [ctx.quantity(orbit.get(k, "0 deg"), "angle", f"{ow}.{k}") for k in ("inc", "raan", "argp", "nu")]
    if not 0 <= angles[0] <= np.pi:
        ctx.fail(f"{ow}.inc", f"{orbit.get('inc')!r} must lie in [0, 180] deg")
    if e >= 1 and 1 + e * np.cos(angles[3]) <= 0:
        ctx.fail(f"{ow}.nu", f"{orbit.get('nu')!r} lies on or beyond the asymptote of the e = {e} conic")
    mu = primary.gm + gm
    r_rel, v_rel = elements.elements_to_state(p, e, *angles, mu)
    spec_orbit = OrbitSpec(names.index(primary_name), p, e, *angles)
    return BodySpec(name, gm, primary.position + r_rel, primary.velocity + v_rel, test_particle, spec_orbit)


def _semi_latus_rectum(ctx, orbit, e, where):
    sizes = {k: orbit[k] for k in ("a", "p", "q") if k in orbit}
    if len(sizes) != 1:
        ctx.fail(where, f"give exactly one size element of a, p, q; got {list(sizes) or 'none'}")
    key = next(iter(sizes))
    with ctx.field(f"{where}.{key}"):
        value = inputs.parse_quantity(sizes[key], "length", f"{where}.{key}")
        return float(inputs.semi_latus_rectum(np.float64(e), **{key: value}))


def _times(ctx, spec, bodies):
    if "times" in spec:
        if not isinstance(spec["times"], list) or not spec["times"]:
            ctx.fail("time.times", "must be a non-empty list of times like '1 d'")
        times = np.array([ctx.quantity(t, "time", f"time.times[{i}]") for i, t in enumerate(spec["times"])])
    else:
        span = _span(ctx, spec, bodies)
        outputs = spec.get("outputs", 100)
        if isinstance(outputs, bool) or not isinstance(outputs, int) or not 1 <= outputs <= 1_000_000:
            ctx.fail("time.outputs", f"{outputs!r} must be an integer in [1, 1000000]")
        times = np.linspace(0.0, span, outputs + 1)[1:]
    if np.any(times <= 0) or np.any(np.diff(times) <= 0):
        ctx.fail("time", "output times must be positive and strictly increasing")
    return times


def _span(ctx, spec, bodies):
    if ("periods" in spec) == ("span" in spec):
        ctx.fail("time", "give exactly one of periods, span (or a list of times)")
    if "span" in spec:
        span = ctx.quantity(spec["span"], "time", "time.span")
        if not span > 0:
            ctx.fail("time.span", f"{spec['span']!r} must be positive")
        return span
    periods = ctx.number(spec, "periods", "time.periods", low=0.0)
    orbiting = [b for b in bodies if b.orbit is not None]
    if periods <= 0 or not orbiting or orbiting[0].orbit.e >= 1:
        ctx.fail("time.periods", "needs a positive number and a first orbit that is an ellipse (e < 1)")
    first = orbiting[0]
    mu = bodies[first.orbit.primary].gm + first.gm
    return periods * float(twobody.period(first.orbit.p, first.orbit.e, mu))
