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

Only the keys above are accepted, in every table: a misspelt or misplaced key is an error naming the key, the
table and the nearest allowed key, never a silent default.
"""

import contextlib
import difflib
import json
import tomllib
from collections.abc import Iterator
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, NoReturn

import astropy.units as u
import numpy as np

from orbits._common import display, inputs
from orbits._common.constants import BODIES
from orbits.core.errors import OrbitsError, SceneError
from orbits.core.twobody import elements, twobody
from orbits.validate import nbody

ASKS = ("positions", "conserved", "period", "closest_approach")
DEFAULT_TOLERANCE = {"positions": 1e-10, "energy": 1e-11, "angular_momentum": 1e-11, "lrl": 1e-10,
                     "period": 1e-10, "closest_approach": 1e-10}
BUILTIN_DIR = Path(__file__).parent / "scene_files"
#: the keys each table of a data scene may hold (anything else is refused, with the nearest allowed key)
KEYS = ("name", "description", "asks", "time", "tolerance", "bodies")
BODY_KEYS = ("name", "body", "gm", "mass", "position", "velocity", "test_particle", "orbit")
ORBIT_KEYS = ("primary", "a", "p", "q", "e", "inc", "raan", "argp", "nu")
TIME_KEYS = ("periods", "span", "outputs", "times")
#: the keys of a model scene file (orbits.validate.models), named here so a typo in either kind finds its key
MODEL_KEYS = ("name", "description", "model", "parameters")
MAX_OUTPUTS = 1_000_000
#: the longest scene file read (a list of a million output times fits)
MAX_FILE_BYTES = 32 * 2**20


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
    """(parsed dictionary, source path) of a built-in scene name or a .toml / .json file, read once.

    Every failure is a one-line SceneError naming the file: missing, a folder, unreadable, not UTF-8 text,
    not valid TOML / JSON, or a JSON document that is not an object.
    """
    if not str(name_or_path).strip():
        raise SceneError(f"{str(name_or_path)!r}: empty scene name; give a built-in scene "
                         f"({', '.join(builtin_names())}) or a .toml / .json file")
    path = Path(name_or_path)
    if not path.suffix and (BUILTIN_DIR / f"{name_or_path}.toml").exists():
        path = BUILTIN_DIR / f"{name_or_path}.toml"
    if path.is_dir():
        raise SceneError(f"{path}: is a folder, not a scene file (.toml or .json)")
    if not path.exists():
        raise SceneError(f"{name_or_path}: no such scene file, and not a built-in scene ({', '.join(builtin_names())})")
    kind = "JSON" if path.suffix == ".json" else "TOML"
    try:
        with open(path, "rb") as handle:  # at most one byte past the limit, so that /dev/zero ends too
            raw = handle.read(MAX_FILE_BYTES + 1)
    except OSError as err:
        raise SceneError(f"{path}: cannot read the file: {err.strerror or err}") from None
    if len(raw) > MAX_FILE_BYTES:
        raise SceneError(f"{path}: longer than {MAX_FILE_BYTES // 2**20} MiB, the most a scene file may hold")
    try:
        text = raw.decode("utf-8-sig")  # a leading byte-order mark is harmless
    except UnicodeDecodeError as err:
        raise SceneError(f"{path}: not UTF-8 text (byte 0x{raw[err.start]:02x} at position {err.start}); "
                         f"save the scene as UTF-8 {kind}") from None
    try:
        data = json.loads(text, object_pairs_hook=_unique_keys) if kind == "JSON" else tomllib.loads(text)
    except ValueError as err:  # JSONDecodeError, TOMLDecodeError, or an integer of more than 4300 digits
        raise SceneError(f"{path}: not valid {kind}: {str(err).split(';')[0]}") from None
    except RecursionError:
        raise SceneError(f"{path}: not valid {kind}: nested too deeply") from None
    if not isinstance(data, dict):
        raise SceneError(f"{path}: a scene must be a table (JSON object), not {_json_kind(data)}")
    return data, str(path)


def _unique_keys(pairs: list[tuple[str, Any]]) -> dict:
    """A JSON object as a dict, ValueError for a key given twice (json keeps the last silently; TOML refuses it)."""
    data = {}
    for key, value in pairs:
        if key in data:
            raise ValueError(f"the key {key!r} is given twice in one object")
        data[key] = value
    return data


def _json_kind(value: object) -> str:
    """How a JSON value reads in a message: null, true, a list, a number, a string ..."""
    if value is None or isinstance(value, bool):
        return json.dumps(value)
    if isinstance(value, list):
        return "a list"
    if isinstance(value, (int, float)):
        return f"a number ({value!r})"
    if isinstance(value, str):
        return "a string"
    return f"a {type(value).__name__}"


def unknown_keys(data: dict, allowed: tuple[str, ...], where: str, source: str,
                 elsewhere: dict[str, str] | None = None, synonyms: dict[str, str] | None = None) -> None:
    """SceneError for the first key of `data` not in `allowed`, naming the nearest allowed key (a typo's fix).

    `where` names the table ("bodies[1]", "time"; "" for the top level). `elsewhere` maps keys that belong in
    another table to where they belong, suggested when no allowed key is near: 'outputs' (a key of [time]).
    `synonyms` maps other names of an allowed key to it (ecc -> e), which spelling alone would not find.
    """
    for key in data:
        if key in allowed:
            continue
        lower = str(key).lower()
        close = [k for k in allowed if k.lower() == lower] or [v for k, v in (synonyms or {}).items() if k == lower]
        close = close or difflib.get_close_matches(str(key), allowed, n=1)
        other = difflib.get_close_matches(str(key), list(elsewhere or {}), n=1)
        if close:
            hint = f"; did you mean {close[0]!r}?"
        elif key in (elsewhere or {}):
            hint = f" ({elsewhere[key]});"
        elif other:
            hint = f"; did you mean {other[0]!r} ({elsewhere[other[0]]})?"
        else:
            hint = ";"
        place = f"{where}: unknown key" if where else "unknown top-level key"
        raise SceneError(f"{source}: {place} {key!r}{hint} allowed: {', '.join(allowed)}")


#: other names of the orbit elements, suggested for an unknown key of an orbit table
_ORBIT_SYNONYMS = {"ecc": "e", "eccentricity": "e", "i": "inc", "incl": "inc", "inclination": "inc",
                   "sma": "a", "semi_major_axis": "a", "semimajor_axis": "a", "semi_latus_rectum": "p",
                   "periapsis": "q", "pericenter": "q", "periapsis_distance": "q", "node": "raan", "omega": "argp",
                   "arg_periapsis": "argp", "w": "argp", "anomaly": "nu", "true_anomaly": "nu", "f": "nu",
                   "center": "primary", "centre": "primary", "central_body": "primary"}

_BODY_SYNONYMS = {"mu": "gm", "massless": "test_particle", "test": "test_particle", "testparticle": "test_particle",
                  "pos": "position", "r": "position", "vel": "velocity", "v": "velocity", "elements": "orbit"}

#: keys that belong in another table than the top level of a data scene, for unknown_keys' suggestions
_ELSEWHERE = {
    **{key: "a key of [[bodies]]" for key in BODY_KEYS},
    **{key: "a key of a body's orbit table" for key in ORBIT_KEYS},
    **{key: "a key of [time]" for key in TIME_KEYS},
    **{key: "a key of [tolerance]" for key in DEFAULT_TOLERANCE},
    "model": 'a model scene names its model = "<name>"',
    "parameters": 'a model scene\'s table, with model = "<name>"',
}


def load(name_or_path: str | Path) -> "Scene":
    """Data scene from a built-in name, or from a .toml / .json file (model scenes: orbits.validate.scenes.load)."""
    return from_dict(*read(name_or_path))


def from_dict(data: dict, source: str = "<scene>") -> Scene:
    """Validate a scene dictionary (the parsed TOML/JSON) and convert it to SI."""
    ctx = _Context(source)
    if not isinstance(data, dict):
        raise SceneError(f"{source}: a scene must be a table (JSON object), not {_json_kind(data)}")
    if "model" in data:
        raise SceneError(f"{source}: model: a model scene; load it with orbits.validate.scenes.load "
                         f"(`orbits validate` does)")
    unknown_keys(data, KEYS, "", source, {key: where for key, where in _ELSEWHERE.items() if key not in KEYS})
    name = ctx.name(data, "name", "name")
    description = data.get("description", "")
    if not isinstance(description, str):
        ctx.fail("description", f"{show(description)} must be a string")
    asks = tuple(ctx.get(data, "asks", list))
    for ask in asks:
        if ask not in ASKS:
            ctx.fail("asks", f"unknown ask {show(ask)}{_did_you_mean(ask, ASKS)}; allowed: {', '.join(ASKS)}")
    if not asks:
        ctx.fail("asks", f"ask for at least one of: {', '.join(ASKS)}")
    bodies = _bodies(ctx, ctx.get(data, "bodies", list))
    times = _times(ctx, ctx.get(data, "time", dict), bodies)
    given = next(key for key in ("times", "span", "periods") if key in data["time"])
    with ctx.field(f"time.{given}"):  # elements or vectors alike: the fastest pair sets how long a run may be
        gm = np.array([b.gm for b in bodies])
        nbody.check_span(float(times[-1]), gm, np.array([b.position for b in bodies]),
                         np.array([b.velocity for b in bodies]), int(np.count_nonzero(gm)), [b.name for b in bodies],
                         "s")
    tolerance = dict(DEFAULT_TOLERANCE)
    for key, value in (ctx.get(data, "tolerance", dict) if "tolerance" in data else {}).items():
        if key not in DEFAULT_TOLERANCE:
            ctx.fail(f"tolerance.{key}",
                     f"unknown check{_did_you_mean(key, DEFAULT_TOLERANCE)}; allowed: {', '.join(DEFAULT_TOLERANCE)}")
        if not isinstance(value, (int, float)) or isinstance(value, bool) or not value > 0:
            ctx.fail(f"tolerance.{key}", f"{show(value)} must be a positive number (relative error)")
        tolerance[key] = float(value) if _finite(value) else np.inf  # an int too large for a float: no bound
    if ("period" in asks or "closest_approach" in asks) and not any(b.orbit for b in bodies):
        ctx.fail("asks", "period and closest_approach need at least one body with an `orbit` table")
    return Scene(name, description, bodies, times, asks, tolerance)


def show(value: object) -> str:
    """A value as a message shows it: NumPy scalars as the plain Python number (-1.3e+20, not np.float64(...))."""
    if isinstance(value, np.generic):
        value = value.item()
    if isinstance(value, int) and not isinstance(value, bool) and value.bit_length() > 64:
        return f"an integer of about {int(value.bit_length() * 0.30103) + 1} digits"
    text = repr(value)
    return text if len(text) <= 80 else f"{text[:60]}... ({type(value).__name__} of {len(text)} characters)"


def _finite(value: object) -> bool:
    """True for a finite int or float (bool excluded; an int too large for a float is not finite)."""
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        return False
    try:
        return bool(np.isfinite(float(value)))
    except OverflowError:
        return False


def _did_you_mean(value: object, allowed) -> str:
    """" (did you mean 'x'?)" naming the allowed word nearest a misspelt one, or ""."""
    close = difflib.get_close_matches(str(value), list(allowed), n=1)
    return f" (did you mean {close[0]!r}?)" if close else ""


class _Context:
    """Error reporting that names the source and the field."""

    def __init__(self, source):
        self.source = source

    def fail(self, where: str, message: str) -> NoReturn:
        raise SceneError(f"{self.source}: {where}: {message}")

    def get(self, data: dict, key: str, kind: type, where: str | None = None) -> Any:
        where = where or key
        what = {dict: "table", list: "list", str: "string"}.get(kind, kind.__name__)
        if key not in data:
            self.fail(where, f"missing (a {what} is required)")
        if not isinstance(data[key], kind):
            self.fail(where, f"{show(data[key])} must be a {what}")
        return data[key]

    def string(self, data: dict, key: str, where: str | None = None) -> str:
        return self.get(data, key, str, where)

    def name(self, data: dict, key: str, where: str) -> str:
        """A name: a string with a character that shows (an empty or blank name reads as nothing in a report)."""
        text = self.string(data, key, where)
        if not display.visible(text):
            self.fail(where, f"{show(text)} is empty or blank; give a name that shows")
        return text

    def quantity(self, text: str, kind: str, where: str, bare_unit: u.UnitBase | None = None) -> float:
        """The SI value (float) of a quantity string of the given kind (orbits._common.inputs.KINDS)."""
        with self.field(where), np.errstate(over="ignore"):
            value = float(inputs.parse_quantity(text, kind, where, bare_unit).to_value(inputs.KINDS[kind][0]))
        if not np.isfinite(value):
            self.fail(where, f"{show(text)} overflows float64 in SI units ({inputs.KINDS[kind][0]})")
        return value

    def vector(self, text: str, kind: str, where: str) -> np.ndarray:
        """The SI value (3,) of a vector string 'X,Y,Z UNIT' of the given kind."""
        with self.field(where), np.errstate(over="ignore"):
            value = inputs.parse_vector(text, kind, where).to_value(inputs.KINDS[kind][0])
        if not np.all(np.isfinite(value)):
            self.fail(where, f"{show(text)} overflows float64 in SI units ({inputs.KINDS[kind][0]})")
        return value

    @contextlib.contextmanager
    def field(self, where: str) -> Iterator[None]:
        """Turn the input rules' errors inside the block into a SceneError naming the source and the field."""
        try:
            yield
        except (OrbitsError, TypeError, u.UnitsError) as err:
            message = str(err).removeprefix(f"{where}: ").removeprefix(f"{where} = ")  # the field is named once
            self.fail(where, message)

    def number(self, data: dict, key: str, where: str, default: float | None = None, low: float = -np.inf) -> float:
        value = data.get(key, default)
        if not _finite(value) or value < low:
            self.fail(where, f"{show(value)} must be a finite number >= {low:g}")
        return float(value)


def _gm(ctx, spec, where):
    given = [k for k in ("body", "gm", "mass") if k in spec]
    if len(given) != 1:
        ctx.fail(where, f"give exactly one of body, gm, mass; got {given or 'none'}")
    key = given[0]
    if key == "body":
        named = inputs.find_body(spec["body"]) if isinstance(spec["body"], str) else None
        if named is None:
            ctx.fail(f"{where}.body", f"unknown body {show(spec['body'])}{_did_you_mean(spec['body'], BODIES)}; "
                     f"known: {', '.join(BODIES)}")
        return named.gm
    kind = "gravitational parameter" if key == "gm" else "mass"
    with ctx.field(f"{where}.{key}"):
        value = inputs.parse_quantity(spec[key], kind, f"{where}.{key}")
        return inputs.single(inputs.gravitational_parameter, value, f"{where}.{key}")


def _bodies(ctx, entries):
    if not entries:
        ctx.fail("bodies", "at least one body is required")
    with ctx.field("bodies"):
        nbody.check_bodies(len(entries))  # before any body is read
    built, names = [], []
    for k, spec in enumerate(entries):
        where = f"bodies[{k}]"
        if not isinstance(spec, dict):
            ctx.fail(where, f"{show(spec)} must be a table")
        unknown_keys(spec, BODY_KEYS, where, ctx.source, synonyms=_BODY_SYNONYMS)
        name = ctx.name(spec, "name", f"{where}.name")
        if name in names:
            ctx.fail(f"{where}.name", f"{name!r} is used twice")
        test_particle = spec.get("test_particle", False)
        if not isinstance(test_particle, bool):
            ctx.fail(f"{where}.test_particle", f"{show(test_particle)} must be true or false")
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
    if len(built) < 2:
        ctx.fail("bodies", "a scene needs at least two bodies (a body alone has nothing to validate)")
    _distinct_positions(ctx, built)
    return tuple(built)


def _distinct_positions(ctx, built):
    """SceneError for the first body that starts where an earlier one does (sorted, not compared pair by pair)."""
    positions = np.array([b.position for b in built]) + 0.0  # -0.0 and 0.0 are one point
    _, first, inverse = np.unique(positions, axis=0, return_index=True, return_inverse=True)
    earlier = first[inverse.ravel()]
    repeated = np.flatnonzero(earlier != np.arange(len(built)))
    if repeated.size:
        k = int(repeated[0])
        j = int(earlier[k])
        ctx.fail(f"bodies[{k}]", f"{built[k].name!r} starts at the position of bodies[{j}] ({built[j].name!r}); two "
                 f"bodies cannot start at the same point")


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
        ctx.fail(ow, f"{show(orbit)} must be a table")
    unknown_keys(orbit, ORBIT_KEYS, ow, ctx.source, synonyms=_ORBIT_SYNONYMS)
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
    with ctx.field(f"{ow}.nu"):
        elements.require_inside_asymptotes(e, angles[3])
    mu = primary.gm + gm
    r_rel, v_rel = elements.elements_to_state_unchecked(p, e, *angles, mu)
    spec_orbit = OrbitSpec(names.index(primary_name), p, e, *angles)
    return BodySpec(name, gm, primary.position + r_rel, primary.velocity + v_rel, test_particle, spec_orbit)


def _semi_latus_rectum(ctx, orbit, e, where):
    sizes = {k: orbit[k] for k in ("a", "p", "q") if k in orbit}
    if len(sizes) != 1:
        ctx.fail(where, f"give exactly one size element of a, p, q; got {list(sizes) or 'none'}")
    key = next(iter(sizes))
    with ctx.field(f"{where}.{key}"):
        value = inputs.parse_quantity(sizes[key], "length", f"{where}.{key}")
        with np.errstate(over="ignore"):
            p = float(inputs.semi_latus_rectum(np.float64(e), **{key: value}))
    if not np.isfinite(p):
        ctx.fail(where, f"the semi-latus rectum p of {key} = {show(sizes[key])} and e = {show(e)} overflows float64")
    return p


def _times(ctx, spec, bodies):
    unknown_keys(spec, TIME_KEYS, "time", ctx.source)
    if "times" in spec:
        others = [key for key in ("periods", "span", "outputs") if key in spec]
        if others:
            ctx.fail("time", f"give either a list of times or periods/span with outputs, not both; "
                     f"remove {', '.join(others)}")
        if not isinstance(spec["times"], list) or not spec["times"]:
            ctx.fail("time.times", "must be a non-empty list of times like '1 d'")
        if len(spec["times"]) > MAX_OUTPUTS:
            ctx.fail("time.times", f"{len(spec['times'])} times; at most {MAX_OUTPUTS} are allowed")
        with ctx.field("time.times"):
            nbody.check_states(len(spec["times"]), len(bodies))
        times = np.array([ctx.quantity(t, "time", f"time.times[{i}]") for i, t in enumerate(spec["times"])])
    else:
        span = _span(ctx, spec, bodies)
        outputs = spec.get("outputs", 100)
        if isinstance(outputs, bool) or not isinstance(outputs, int) or not 1 <= outputs <= MAX_OUTPUTS:
            ctx.fail("time.outputs", f"{show(outputs)} must be an integer in [1, {MAX_OUTPUTS}]")
        with ctx.field("time.outputs"):
            nbody.check_states(outputs, len(bodies))
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
            ctx.fail("time.span", f"{show(spec['span'])} must be positive")
        return span
    periods = ctx.number(spec, "periods", "time.periods", low=0.0)
    orbiting = [b for b in bodies if b.orbit is not None]
    if periods <= 0 or not orbiting or orbiting[0].orbit.e >= 1:
        ctx.fail("time.periods", "needs a positive number and a first orbit that is an ellipse (e < 1)")
    if periods > nbody.MAX_PERIODS:  # a first bound (the period is not yet known): the run's own check follows
        ctx.fail("time.periods", f"{show(spec['periods'])} is more than {nbody.MAX_PERIODS:.0e} periods: too long a "
                 f"run")
    return periods * _period(orbiting[0], bodies)


def _period(body, bodies):
    """T (s) of a body's relative orbit about its primary (an ellipse), mu = G (M_primary + m)."""
    mu = bodies[body.orbit.primary].gm + body.gm
    return float(twobody.period(body.orbit.p, body.orbit.e, mu))
