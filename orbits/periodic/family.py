"""Periodic orbits of the circular restricted three-body problem, with units: planar and vertical Lyapunov orbits,
halo orbits and their near-rectilinear continuation, distant retrograde orbits.

    >>> from orbits import PeriodicOrbit, RestrictedThreeBody
    >>> em = RestrictedThreeBody.from_primaries("Earth", "Moon")
    >>> nrho = PeriodicOrbit.near_rectilinear(em, resonance="9:2")      # doctest: +SKIP
    >>> nrho.period.to("d")                                             # doctest: +SKIP
    <Quantity 6.55270481 d>

Units of the numeric core (orbits.core.periodic.cr3bp): the separation r, the binary's angular velocity n, and so
speeds in
n r and the Jacobi constant in (n r)**2; the rotating frame of orbits.threebody.lagrange (origin at the barycentre, x
from the
primary M to the secondary m, z along the binary's spin). Every member is found the same way: the family's first
member from a first guess near its start (orbits.core.periodic.families), continued by pseudo-arclength continuation
to the
requested amplitude, period, Jacobi constant or closest approach, which regula falsi then hits to 1e-13 of itself.
The states are integrated about the family's own point (orbits.core.periodic.cr3bp.Origin), and the correction leaves a
half-period residual below 1e-11 of that point's distance to the nearer primary (measured 1e-18 to 4e-16); over a
full period an orbit closes to 1e-11 of its size (tests/api/test_periodic_api.py, tests/core/test_periodic_core.py;
rebound and heyoka, orbits.validate.periodic: 1e-9).

Families and where they live: "lyapunov" (L1, L2, L3), "halo" (L1, L2; northern or southern: which side of the
binary's plane the orbit reaches farther to), "vertical" (L1, L2), "dro" (about the secondary), and "nrho", the halo
family about L2 (or L1) continued towards the secondary, where a synodic resonance p:q names the member of period
q / p synodic periods (the 9:2 near-rectilinear halo orbit of the lunar Gateway: 2/9 of the synodic month).
"""

import math
from collections.abc import Iterable
from dataclasses import dataclass, field
from functools import cached_property

import astropy.units as u
import numpy as np

from orbits._common import display, inputs, units
from orbits._common.constants import BODIES, body_with_gm
from orbits._common.tables import quantity_table
from orbits.core.errors import ConvergenceError, OrbitDomainError
from orbits.core.periodic import continuation, cr3bp, families, libration, shooting
from orbits.core.threebody import lagrange
from orbits.threebody.lagrange import RestrictedThreeBody

FAMILIES = ("lyapunov", "halo", "vertical", "dro", "nrho")
BRANCHES = ("northern", "southern")
#: what selects a member: amplitudes and the closest approach to the secondary (length), the period (time), the
#: Jacobi constant (m2/s2, or dimensionless in units of (n r)**2), a synodic resonance "p:q" (a string)
TARGETS = ("ax", "ay", "az", "period", "jacobi", "closest_approach", "resonance")
#: the targets that pick a member of each family: the one home of that rule (the constructors, PeriodicOrbit.of,
#: PeriodicFamily.of and the command line all check a request here)
FAMILY_TARGETS = {"lyapunov": ("ax", "ay", "period", "jacobi", "closest_approach"),
                  "halo": ("az", "ax", "period", "jacobi", "closest_approach"),
                  "vertical": ("az", "ay", "period", "jacobi"),
                  "dro": ("ax", "ay", "period", "jacobi", "closest_approach"),
                  "nrho": ("resonance", "period", "closest_approach")}
_METRIC = {"ax": "ax", "ay": "ay", "az": "az", "period": "period", "jacobi": "jacobi",
           "closest_approach": "closest_secondary", "resonance": "period"}
_LABEL = {"ax": "Ax", "ay": "Ay", "az": "Az", "period": "T", "jacobi": "C", "closest_approach": "closest approach",
          "resonance": "resonance"}
DEFAULT_POINT = {"lyapunov": "L1", "halo": "L2", "vertical": "L1", "dro": None, "nrho": "L2"}
#: how many times a family's first member is taken ten times smaller when a target lies nearer the family's start
SHRINKS = 3
#: a family table's largest number of members, and the steps of the walk that finds its extent
MAX_MEMBERS = 1000
MAX_WALK = 300


@dataclass(frozen=True)
class _Binary:
    """The scalars of one binary: mu, r (m), n (rad/s), the primaries' radii in units of r (0 if not catalogued)."""

    mu: float
    r: float
    n: float
    radii: tuple[float, float]

    @property
    def speed(self) -> float:
        return self.n * self.r


def _binary(system: RestrictedThreeBody) -> _Binary:
    if np.ndim(system.mu) != 0:
        raise OrbitDomainError("periodic orbits need a single binary; this RestrictedThreeBody holds an array of them")
    r = float(system.r)
    radii = tuple(_radius(gm) / r for gm in (system.gm_primary, system.gm_secondary))
    return _Binary(float(system.mu), r, float(system._n), radii)


def _radius(gm) -> float:
    """The catalogue body's radius (m) for this GM, 0 for a mass the catalogue does not hold (a point mass)."""
    known = body_with_gm(gm)
    return 0.0 if known is None else known.radius


def synodic_period(system: RestrictedThreeBody) -> u.Quantity:
    """The binary's synodic period (s): 1 / (1 / T - 1 / T_p), T the binary's period and T_p that of the binary's
    barycentre about the primary's own primary (the Earth-Moon pair about the Sun: the synodic month, 29.49 d for
    the catalogue's mean distances). OrbitDomainError when the catalogue gives the primary no orbit."""
    known = body_with_gm(system.gm_primary)
    if known is None or known.orbit is None or known.parent not in BODIES:
        name = known.name if known is not None else "the primary"
        raise OrbitDomainError(f"a synodic period needs the primary's own orbit: {name} orbits nothing in the "
                               f"catalogue (give the period instead)")
    parent = BODIES[known.parent]
    gm = parent.gm + float(system.gm_primary) + float(system.gm_secondary)
    orbit_period = 2.0 * math.pi * math.sqrt(known.orbit.a**3 / gm)
    binary_period = float(system.period.to_value(u.s))
    return 1.0 / (1.0 / binary_period - 1.0 / orbit_period) * u.s


def resonance_period(system: RestrictedThreeBody, resonance: str) -> u.Quantity:
    """The period (s) of the p:q synodic resonance: p revolutions in q synodic periods, T = (q / p) T_syn."""
    p, q = _resonance(resonance)
    return synodic_period(system) * (q / p)


def _resonance(text) -> tuple[int, int]:
    parts = str(text).split(":")
    try:
        p, q = (int(part) for part in parts)
    except ValueError:
        raise OrbitDomainError(f"resonance = {text!r} must read 'p:q' with whole numbers, e.g. '9:2' (p "
                               f"revolutions in q synodic periods)") from None
    if not (0 < p <= 1000 and 0 < q <= 1000):
        raise OrbitDomainError(f"resonance = {text!r}: p and q must lie in [1, 1000]")
    return p, q


def _target(binary: _Binary, system: RestrictedThreeBody, name: str, value) -> float:
    """A target in the core's units (r, 1 / n, (n r)**2), checked where it enters."""
    if name not in TARGETS:
        raise OrbitDomainError(f"unknown target {name!r}; choose from {', '.join(TARGETS)}")
    if name == "resonance":
        return float(resonance_period(system, value).to_value(u.s)) * binary.n
    if name == "period":
        return inputs.single(inputs.positive, value, units.S, "period T") * binary.n
    if name == "jacobi":
        label = "Jacobi constant C"
        if isinstance(value, u.Quantity) and value.unit.is_equivalent(units.M_PER_S**2):
            return inputs.single(units.to_si, value, units.M_PER_S**2, label) / binary.speed**2
        number = inputs.single(units.to_number, value, label)
        if not math.isfinite(number):
            raise OrbitDomainError(f"Jacobi constant C = {number!r} is not finite")
        return number
    label = "closest approach" if name == "closest_approach" else _LABEL[name]
    return inputs.single(inputs.positive, value, units.M, label) / binary.r


def _family_parts(family: str, point: str | None, branch: str | None):
    """(the core family, the point, northern?) of a request, each checked."""
    if family not in FAMILIES:
        raise OrbitDomainError(f"unknown family {family!r}; choose from {', '.join(FAMILIES)}")
    core = "halo" if family == "nrho" else family
    if point is not None:
        lagrange.point_index(point)
    families.check_family(core, point)
    if core != "halo":
        if branch is not None:
            raise OrbitDomainError(f"branch = {branch!r}: only halo families have a northern and a southern branch")
        return core, point, True
    if branch not in BRANCHES:
        raise OrbitDomainError(f"branch = {branch!r}; choose from {', '.join(BRANCHES)}")
    return core, point, branch == "northern"


def _request(family: str, kwargs: dict, required: bool = True) -> tuple[str, object] | None:
    """The one target given among the keyword arguments (name, value), checked against the family's
    FAMILY_TARGETS; None when none is given and none is `required`."""
    if family not in FAMILY_TARGETS:
        raise OrbitDomainError(f"unknown family {family!r}; choose from {', '.join(FAMILIES)}")
    allowed = FAMILY_TARGETS[family]
    given = [(name, value) for name, value in kwargs.items() if value is not None]
    for name, _ in given:
        if name not in allowed:
            raise OrbitDomainError(f"{name} does not pick a {family} orbit; give one of {', '.join(allowed)}")
    if len(given) > 1 or (required and not given):
        raise OrbitDomainError(f"give {'exactly' if required else 'at most'} one of {', '.join(allowed)} to pick "
                               f"the family's member ({', '.join(n for n, _ in given) or 'none'} given)")
    return given[0] if given else None


class _Finder:
    """A family of one binary being followed: its flow, half-period map, first member, direction and measures."""

    def __init__(self, system, family, point, branch, compiled=None):
        self.system, self.binary = system, _binary(system)
        self.family, self.point = family, point
        core, point, northern = _family_parts(family, point, branch)  # a branch given to a planar family is refused
        self.branch = None if family not in ("halo", "nrho") else branch
        place = cr3bp.origin(self.binary.mu, families.origin(core, point))
        self.flow = shooting.Flow(self.binary.mu, place, shooting.use_compiled(True) if compiled is None else compiled)
        self.measures = families.Measures(self.flow)
        self.core, self.northern = core, northern
        self.size = families.start_size(self.binary.mu, core, point)
        try:
            self.hmap, self.first, self.direction = families.first_member(self.flow, core, point, northern,
                                                                          self.size)
        except ConvergenceError as err:
            raise OrbitDomainError(f"the {self.describe()} family's first member (amplitude "
                                   f"{display.quantity_text(self.size * self.binary.r * u.m)}) could not be "
                                   f"corrected from its first guess at mu = {self.binary.mu:.6g}: {err}") from None

    def stop(self, member: shooting.Crossing) -> str | None:
        """Why the family ends at `member`: it passes within a primary's radius (None otherwise)."""
        reach = self.measures.extent(member)
        for which, distance in enumerate(reach.closest):
            if distance <= self.binary.radii[which]:
                gm = (self.system.gm_primary, self.system.gm_secondary)[which]
                km = display.quantity_text(distance * self.binary.r * u.m, "length")
                radius = display.quantity_text(self.binary.radii[which] * self.binary.r * u.m, "length")
                name = display.body_name(gm)
                name = f"the {name}" if name in ("Sun", "Moon") else name
                return (f"the family reaches the surface of {name}: the next member passes {km} from its centre, "
                        f"inside its radius {radius}")
        return None

    def trace(self, name: str | None, value, count: int = families.MAX_MEMBERS):
        """(the followed members, the last one): the member with target `name` = value (its Quantity, checked
        here), or the last before the family ends."""
        if name is None:
            return families.trace(self.hmap, self.measures, self.first, self.direction, stop=self.stop, count=count)
        target = _target(self.binary, self.system, name, value)
        for _ in range(SHRINKS + 1):
            try:
                return families.trace(self.hmap, self.measures, self.first, self.direction, _METRIC[name], target,
                                      self.stop, count)
            except families.BeyondFamily as err:
                if not err.behind:
                    raise OrbitDomainError(self._beyond(name, value, err)) from None
                last = err
                self.size *= 0.1  # the target lies nearer the family's start: begin nearer it
                self.hmap, self.first, self.direction = families.first_member(self.flow, self.core, self.point,
                                                                              self.northern, self.size)
        raise OrbitDomainError(self._beyond(name, value, last)) from None

    def _beyond(self, name, value, err):
        """The one-line message of a target the family does not reach, in the target's natural unit."""
        metric = _METRIC[name]
        if metric == "jacobi":
            shown = [display.number(x) for x in (err.target, err.low, err.high)]
            what = f"C = {shown[0]} (units of (n r)**2)"
        else:
            scale = 1.0 / self.binary.n * u.s if metric == "period" else self.binary.r * u.m
            shown = [display.quantity_text(x * scale, metric) for x in (err.target, err.low, err.high)]
            what = f"the {value} resonance (T = {shown[0]})" if name == "resonance" else f"{_LABEL[name]} = {shown[0]}"
        return (f"{what} is beyond the {self.describe()} family: its members reach {shown[1]} to {shown[2]} "
                f"({err.reason})")

    def describe(self) -> str:
        pair = f"{display.body_name(self.system.gm_primary)}-{display.body_name(self.system.gm_secondary)}"
        words = [pair, self.point or "", self.branch or "", {"dro": "distant retrograde", "nrho": "halo"}.get(
            self.family, self.family)]
        return " ".join(w for w in words if w)

    def orbit(self, member: shooting.Crossing, request=None) -> "PeriodicOrbit":
        return PeriodicOrbit(self.system, self.family, self.point, self.branch, self.flow.origin.name,
                             member.state.copy(), member.period, self.hmap.symmetry.signs, member.transition, None,
                             member.residual, request, self.flow.compiled, _work(self.flow))


def _work(flow: shooting.Flow) -> dict:
    return {"integrations": flow.integrations, "steps": flow.steps, "evaluations": flow.evaluations,
            "iterations": flow.iterations}


@dataclass(frozen=True, eq=False, repr=False)
class PeriodicOrbit(display.Displayed):
    """A periodic orbit of a RestrictedThreeBody: its initial state in the rotating frame (dimensionless, units of r
    and n r) written about an `origin` (orbits.core.periodic.cr3bp.ORIGINS: its collinear point, or the secondary for a
    DRO, where the integrations run to the orbit's own relative accuracy), its period (units of 1 / n), and how it
    was found. Build it with the family constructors (lyapunov, halo, vertical, distant_retrograde,
    near_rectilinear) or from_state; every quantity is computed when first asked for (the extent from one
    integration, the monodromy from the stored transition matrices)."""

    system: RestrictedThreeBody
    family: str
    point: str | None
    branch: str | None
    origin: str
    local_state: np.ndarray
    dimensionless_period: float
    symmetry_signs: np.ndarray | None = field(default=None, repr=False)
    half_period_transition: np.ndarray | None = field(default=None, repr=False)
    arc_transitions: tuple | None = field(default=None, repr=False)
    residual: float = 0.0
    request: tuple | None = None
    compiled: bool = False
    work: dict = field(default_factory=dict, repr=False)

    # ---- constructors ---------------------------------------------------------------------------------------
    @classmethod
    def lyapunov(cls, system: RestrictedThreeBody, point: str = "L1", *, ax: u.Quantity | None = None,
                 ay: u.Quantity | None = None, period: u.Quantity | None = None, jacobi=None,
                 closest_approach: u.Quantity | None = None) -> "PeriodicOrbit":
        """The planar Lyapunov orbit about L1, L2 or L3 with the given x or y amplitude (half its extent), period,
        Jacobi constant or closest approach to the secondary (exactly one)."""
        return cls._member(system, "lyapunov", point, None, ax=ax, ay=ay, period=period, jacobi=jacobi,
                           closest_approach=closest_approach)

    @classmethod
    def halo(cls, system: RestrictedThreeBody, point: str = "L2", *, az: u.Quantity | None = None,
             ax: u.Quantity | None = None, period: u.Quantity | None = None, jacobi=None,
             closest_approach: u.Quantity | None = None, branch: str = "northern") -> "PeriodicOrbit":
        """The halo orbit about L1 or L2 with the given z amplitude (the largest distance from the binary's plane),
        x amplitude, period, Jacobi constant or closest approach to the secondary (exactly one), on the "northern"
        or "southern" branch."""
        return cls._member(system, "halo", point, branch, az=az, ax=ax, period=period, jacobi=jacobi,
                           closest_approach=closest_approach)

    @classmethod
    def vertical(cls, system: RestrictedThreeBody, point: str = "L1", *, az: u.Quantity | None = None,
                 ay: u.Quantity | None = None, period: u.Quantity | None = None, jacobi=None) -> "PeriodicOrbit":
        """The vertical Lyapunov orbit (a figure of eight across the binary's plane) about L1 or L2 with the given z
        or y amplitude, period or Jacobi constant (exactly one)."""
        return cls._member(system, "vertical", point, None, az=az, ay=ay, period=period, jacobi=jacobi)

    @classmethod
    def distant_retrograde(cls, system: RestrictedThreeBody, *, ax: u.Quantity | None = None,
                           ay: u.Quantity | None = None, period: u.Quantity | None = None, jacobi=None,
                           closest_approach: u.Quantity | None = None) -> "PeriodicOrbit":
        """The distant retrograde orbit about the secondary with the given x or y amplitude, period, Jacobi constant
        or closest approach to the secondary (exactly one)."""
        return cls._member(system, "dro", None, None, ax=ax, ay=ay, period=period, jacobi=jacobi,
                           closest_approach=closest_approach)

    @classmethod
    def near_rectilinear(cls, system: RestrictedThreeBody, point: str = "L2", *, resonance: str | None = None,
                         period: u.Quantity | None = None, closest_approach: u.Quantity | None = None,
                         branch: str = "southern") -> "PeriodicOrbit":
        """The near-rectilinear halo orbit about L2 (or L1) with the given synodic resonance "p:q" (period q / p
        synodic periods; "9:2" is the lunar Gateway's), period or closest approach to the secondary (exactly one);
        southern by default, as the Gateway's."""
        return cls._member(system, "nrho", point, branch, resonance=resonance, period=period,
                           closest_approach=closest_approach)

    @classmethod
    def of(cls, system: RestrictedThreeBody, family: str, point: str | None = None, *, branch: str | None = None,
           **target) -> "PeriodicOrbit":
        """The member of `family` ("lyapunov", "halo", "vertical", "dro" or "nrho") about `point` (the family's
        usual one, DEFAULT_POINT, when None; none for the DRO) picked by exactly one target of FAMILY_TARGETS[family],
        on `branch` for the halo families (northern halo, southern NRHO by default)."""
        if family in DEFAULT_POINT and point is None:
            point = DEFAULT_POINT[family]
        if branch is None and family in ("halo", "nrho"):
            branch = "southern" if family == "nrho" else "northern"
        return cls._member(system, family, point, branch, **target)

    @classmethod
    def _member(cls, system, family, point, branch, **targets) -> "PeriodicOrbit":
        name, value = _request(family, targets)
        finder = _Finder(system, family, point, branch)
        return finder.orbit(finder.trace(name, value)[1], (name, value))

    @classmethod
    def from_state(cls, system: RestrictedThreeBody, r: u.Quantity, v: u.Quantity, period: u.Quantity,
                   nodes: int = 8) -> "PeriodicOrbit":
        """The periodic orbit of the given period through (nearly) the rotating-frame state r (length), v (speed),
        corrected by multiple shooting from `nodes` points along the guess: no symmetry is assumed. The period is
        held; the first node keeps its y coordinate."""
        binary = _binary(system)
        if not (isinstance(nodes, int) and not isinstance(nodes, bool) and 2 <= nodes <= 64):
            raise OrbitDomainError(f"nodes = {nodes!r} must be an integer in [2, 64]")
        state = np.concatenate([inputs.vector(r, units.M, "position r") / binary.r,
                                inputs.vector(v, units.M_PER_S, "velocity v") / binary.speed])
        t = inputs.single(inputs.positive, period, units.S, "period T") * binary.n
        places = [cr3bp.origin(binary.mu, name) for name in cr3bp.ORIGINS]
        place = min(places, key=lambda p: np.linalg.norm(state[:3] - [p.x, 0.0, 0.0]) / p.scale)
        flow = shooting.Flow(binary.mu, place, shooting.use_compiled(False))
        guess = flow.arc(flow.local(state), t, outputs=np.linspace(0.0, t, nodes + 1)[:-1]).states
        shot = shooting.multiple_shooting(flow, guess, t)
        return cls(system, "", None, None, place.name, shot.nodes[0].copy(), shot.period, None, None,
                   tuple(shot.transitions), shot.residual, None, flow.compiled, _work(flow))

    # ---- the state and the period --------------------------------------------------------------------------
    @cached_property
    def _binary(self) -> _Binary:
        return _binary(self.system)

    @cached_property
    def _origin(self) -> cr3bp.Origin:
        return cr3bp.origin(self._binary.mu, self.origin)

    @cached_property
    def dimensionless_state(self) -> np.ndarray:
        """The initial state (x, y, z, vx, vy, vz) about the barycentre, in units of r and n r."""
        return cr3bp.to_barycentric(self.local_state, self._origin)

    @cached_property
    def position(self) -> u.Quantity:
        """Initial rotating-frame position (m), shape (3,)."""
        return self.dimensionless_state[:3] * self._binary.r << units.M

    @cached_property
    def velocity(self) -> u.Quantity:
        """Initial rotating-frame velocity (m/s), shape (3,)."""
        return self.dimensionless_state[3:] * self._binary.speed << units.M_PER_S

    @cached_property
    def period(self) -> u.Quantity:
        """T (s)."""
        return self.dimensionless_period / self._binary.n << units.S

    @cached_property
    def dimensionless_jacobi_constant(self) -> float:
        """C = 2 Omega - |v|**2 in units of (n r)**2 (the value tables of the restricted problem quote)."""
        return float(cr3bp.jacobi_constant(self.dimensionless_state, self._binary.mu))

    @cached_property
    def jacobi_constant(self) -> u.Quantity:
        """C (m2/s2)."""
        return self.dimensionless_jacobi_constant * self._binary.speed**2 << units.M_PER_S**2

    # ---- the extent -----------------------------------------------------------------------------------------
    def _flow(self) -> shooting.Flow:
        return shooting.Flow(self._binary.mu, self._origin, self.compiled)

    @cached_property
    def _extent(self) -> families.Extent:
        return families.extent(self._flow(), self.local_state, self.dimensionless_period)

    @cached_property
    def amplitudes(self) -> u.Quantity:
        """(Ax, Ay, Az) (m): half the orbit's extent along x and y, and its largest distance from the x-y plane."""
        return self._extent.amplitudes * self._binary.r << units.M

    @property
    def ax(self) -> u.Quantity:
        return self.amplitudes[0]

    @property
    def ay(self) -> u.Quantity:
        return self.amplitudes[1]

    @property
    def az(self) -> u.Quantity:
        return self.amplitudes[2]

    @cached_property
    def closest_approaches(self) -> u.Quantity:
        """The orbit's least distance (m) from the centre of the primary and of the secondary, shape (2,)."""
        return self._extent.closest * self._binary.r << units.M

    @cached_property
    def farthest_from_secondary(self) -> u.Quantity:
        """The orbit's greatest distance (m) from the secondary's centre (an NRHO's apolune)."""
        return self._extent.farthest[1] * self._binary.r << units.M

    # ---- stability ------------------------------------------------------------------------------------------
    @cached_property
    def monodromy(self) -> np.ndarray:
        """M = Phi(T), the state transition matrix over one period in the dimensionless coordinates (6, 6); its
        eigenvalues and the stability indices do not depend on the units."""
        if self.half_period_transition is not None:
            return shooting.symmetric_monodromy(self.half_period_transition, self.symmetry_signs)
        m = np.eye(6)
        for phi in self.arc_transitions:
            m = phi @ m
        return m

    @cached_property
    def eigenvalues(self) -> np.ndarray:
        """The monodromy's six eigenvalues (complex), largest modulus first: 1, 1 and two reciprocal pairs."""
        values = np.linalg.eigvals(self.monodromy)
        return values[np.argsort(-np.abs(values))]

    @cached_property
    def stability_indices(self) -> np.ndarray:
        """(nu_1, nu_2) = lambda + 1 / lambda of the two nontrivial eigenvalue pairs (complex; real unless the pairs
        form a complex quadruplet), larger |nu| first: linearly stable when both are real with |nu| <= 2."""
        return continuation.stability_indices(self.monodromy)

    @property
    def stable(self) -> bool:
        """True when both stability indices are real and at most 2 in size."""
        nu = self.stability_indices
        return bool(np.all(np.abs(nu.imag) <= 1e-9 * np.abs(nu)) and np.all(np.abs(nu.real) <= 2.0))

    @cached_property
    def e_folding_time(self) -> u.Quantity:
        """T / ln |lambda_max| (s): the time a small deviation along the unstable direction takes to grow e-fold
        (inf when stable)."""
        growth = float(np.max(np.abs(self.eigenvalues)))
        if self.stable or not growth > 1.0:
            return np.inf * u.s
        return float(self.period.to_value(u.s)) / math.log(growth) * u.s

    # ---- Richardson's prediction (halo orbits) --------------------------------------------------------------
    @cached_property
    def richardson(self) -> libration.Richardson:
        """Richardson's third-order halo orbit of this orbit's z amplitude on its branch (halo orbits only: near the
        secondary, the near-rectilinear ones lie far beyond its reach)."""
        if self.family != "halo":
            raise OrbitDomainError(f"Richardson's approximation is a halo orbit's; this is a "
                                   f"{self.family or 'free'} orbit")
        return libration.richardson_halo(self._binary.mu, self.point, float(self.az.to_value(u.m)) / self._binary.r,
                                         self.branch == "northern")

    @cached_property
    def richardson_period(self) -> u.Quantity:
        """The period (s) of Richardson's third-order halo of this z amplitude."""
        return self.richardson.period / self._binary.n << units.S

    # ---- states at any time ---------------------------------------------------------------------------------
    def _dimensionless_states(self, t) -> np.ndarray:
        """Rotating-frame states (..., 6) at times t (s): integrated once over the sorted times modulo the period."""
        t_nd = np.asarray(units.to_si(t, units.S, "time t"), dtype=float) * self._binary.n
        if not np.all(np.isfinite(t_nd)):
            raise OrbitDomainError("times t must be finite")
        if t_nd.size > 10_000_000:
            raise OrbitDomainError(f"{t_nd.size} times: at most 10000000 states at once")
        phase = np.mod(t_nd, self.dimensionless_period).ravel()
        order = np.argsort(phase)
        flow = self._flow()
        arc = flow.arc(self.local_state, self.dimensionless_period, outputs=phase[order])
        states = np.empty((phase.size, 6))
        states[order] = flow.barycentric(arc.states)
        return states.reshape(t_nd.shape + (6,))

    def states(self, t: u.Quantity) -> tuple[u.Quantity, u.Quantity]:
        """Rotating-frame positions (m) and velocities (m/s) at times t (time, any shape) from the initial state,
        shape t.shape + (3,); a periodic orbit repeats, so t is taken modulo the period."""
        s = self._dimensionless_states(t)
        return s[..., :3] * self._binary.r << units.M, s[..., 3:] * self._binary.speed << units.M_PER_S

    def inertial_states(self, t: u.Quantity) -> tuple[u.Quantity, u.Quantity]:
        """Barycentric inertial positions (m) and velocities (m/s) at times t, the frame having turned by the
        binary's phase + n t (its plane and node as the RestrictedThreeBody gives them)."""
        s = self._dimensionless_states(t)
        angle = float(self.system.phase) + np.asarray(units.to_si(t, units.S, "time t")) * self._binary.n
        r, v = lagrange.rotating_to_inertial(s[..., :3], s[..., 3:], angle, float(self.system.inc),
                                             float(self.system.raan))
        return r * self._binary.r << units.M, v * self._binary.speed << units.M_PER_S

    # ---- tables ---------------------------------------------------------------------------------------------
    def describe(self) -> str:
        """E.g. "Earth-Moon L2 southern halo"."""
        pair = f"{display.body_name(self.system.gm_primary)}-{display.body_name(self.system.gm_secondary)}"
        name = {"dro": "distant retrograde", "nrho": "near-rectilinear halo", "": "periodic"}.get(self.family,
                                                                                                    self.family)
        return " ".join(w for w in (pair, self.point or "", self.branch or "", name) if w)

    def _facts(self) -> list[str]:
        """What names this member: the target it was asked for (unless its period or Jacobi constant), T and C."""
        parts = []
        if self.request is not None and self.request[0] not in ("period", "jacobi"):
            parts.append(f"{_LABEL[self.request[0]]} = {_shown(self.request)}")
        parts.append("T = " + display.summary(self.period))
        parts.append(f"C = {display.number(self.dimensionless_jacobi_constant)}")
        return parts

    @property
    def title(self) -> str:
        """The orbit in words, for a table or a picture: "Earth-Moon L2 southern halo orbit: Az = 20000 km,
        T = 14.73 d, C = 3.0566"."""
        return f"{self.describe()} orbit: {', '.join(self._facts())}"

    def __repr__(self) -> str:
        """E.g. "PeriodicOrbit(Earth-Moon L2 southern halo, Az = 20000 km, T = 14.73 d, C = 3.0566)"."""
        return display.one_line("PeriodicOrbit", self.describe(), *self._facts())

    def quantities(self, only: Iterable[str] | None = None) -> dict[str, u.Quantity]:
        """{name: Quantity} of QUANTITY_NAMES (or `only` those). Stability quantities come as (re, im) pairs;
        e_folding_time is left out for a stable orbit and richardson_period for other than halo orbits."""
        return quantity_table(self._lookup, QUANTITY_NAMES, only)

    def _lookup(self, name):
        if name in ("eigenvalues", "stability_indices"):
            values = getattr(self, name)
            return np.stack([values.real, values.imag], axis=-1) << u.one
        if name == "e_folding_time" and self.stable:
            raise OrbitDomainError("a stable orbit has no e-folding time")
        if name in ("dimensionless_position", "dimensionless_velocity"):
            part = self.dimensionless_state[:3] if name.endswith("position") else self.dimensionless_state[3:]
            return part << u.one
        if name in ("dimensionless_period", "dimensionless_jacobi_constant"):
            return getattr(self, name) << u.one
        if name in ("closest_approach_primary", "closest_approach_secondary"):
            return self.closest_approaches[0 if name.endswith("primary") else 1]
        return getattr(self, name)


QUANTITY_NAMES = ["position", "velocity", "period", "jacobi_constant", "dimensionless_position",
                  "dimensionless_velocity", "dimensionless_period",
                  "dimensionless_jacobi_constant", "ax", "ay", "az", "closest_approach_primary",
                  "closest_approach_secondary", "eigenvalues", "stability_indices", "e_folding_time",
                  "richardson_period"]


SPACINGS = ("arclength", "period", "jacobi")


@dataclass(frozen=True, eq=False, repr=False)
class PeriodicFamily(display.Displayed):
    """Members of a family of periodic orbits of one binary, from its first member (the smallest, near its point or
    close about the secondary) to a requested member or to where the family ends, with why it ends there.

    Build it with PeriodicFamily.of. `bifurcations` lists (kind, PeriodicOrbit) where a stability index crosses 2
    (another family branches off) or -2 (a period-doubling family does), found along the followed family."""

    system: RestrictedThreeBody
    family: str
    point: str | None
    branch: str | None
    members: tuple
    end: str
    _finder: object = field(repr=False)
    _followed: object = field(repr=False)

    @classmethod
    def of(cls, system: RestrictedThreeBody, family: str, point: str | None = None, *, branch: str | None = None,
           members: int = 20, spacing: str = "arclength", **until) -> "PeriodicFamily":
        """`members` (2 .. MAX_MEMBERS) orbits of `family` ("lyapunov", "halo", "vertical", "dro" or "nrho") about
        `point` (the family's usual one by default), spread evenly in `spacing`: "arclength" along the family
        (pseudo-arclength continuation), or "period" or "jacobi" (each member located between the followed members
        that bracket its value; refused where the quantity turns back before the last member). The last member is
        the one with the given target (one of TARGETS, as PeriodicOrbit's constructors take them), or else the last
        before the family reaches a primary's surface or MAX_WALK continuation steps."""
        if not (isinstance(members, int) and not isinstance(members, bool) and 2 <= members <= MAX_MEMBERS):
            raise OrbitDomainError(f"members = {members!r} must be an integer in [2, {MAX_MEMBERS}]")
        if spacing not in SPACINGS:
            raise OrbitDomainError(f"spacing = {spacing!r}; choose from {', '.join(SPACINGS)}")
        point = DEFAULT_POINT.get(family) if point is None else point
        if branch is None and family in ("halo", "nrho"):
            branch = "southern" if family == "nrho" else "northern"
        request = _request(family, until, required=False)
        finder = _Finder(system, family, point, branch)
        followed, last = finder.trace(*(request or (None, None)), count=MAX_WALK)
        crossings = _spaced(finder, followed, last, members, spacing)
        end = f"the member with {_LABEL[request[0]]} = {_shown(request)}" if request else (
            followed.stop or f"{MAX_WALK} continuation steps")
        return cls(system, family, point, finder.branch, tuple(finder.orbit(c) for c in crossings), end, finder,
                   followed)

    @cached_property
    def bifurcations(self) -> list:
        """[(kind, PeriodicOrbit)]: "tangent" where a stability index crosses 2, "period doubling" where one crosses
        -2, located between the followed members by regula falsi on (nu_1 -/+ 2)(nu_2 -/+ 2)."""
        found = families.bifurcations(self._finder.hmap, self._followed)
        return [(kind, self._finder.orbit(member)) for kind, member in found]

    @property
    def work(self) -> dict:
        """What following the family has cost so far: trajectories integrated, their accepted steps and
        right-hand-side evaluations, and Newton iterations."""
        return _work(self._finder.flow)

    def _stack(self, name) -> u.Quantity:
        return u.Quantity([member._lookup(name) for member in self.members])

    def quantities(self, only: Iterable[str] | None = None) -> dict[str, u.Quantity]:
        """{name: Quantity} over the members (a leading axis of len(members)) of FAMILY_NAMES (or `only` those);
        stability indices as (re, im) pairs."""
        return quantity_table(self._stack, FAMILY_NAMES, only)

    def __len__(self) -> int:
        return len(self.members)

    def __repr__(self) -> str:
        """E.g. "PeriodicFamily(Earth-Moon L2 southern halo, 20 members, T = 5.95..14.83 d, to ...)"."""
        periods = u.Quantity([m.period for m in self.members])
        return display.one_line("PeriodicFamily", self.members[0].describe(), f"{len(self.members)} members",
                                "T = " + display.summary(periods), f"to {self.end}")


FAMILY_NAMES = ["period", "jacobi_constant", "dimensionless_jacobi_constant", "dimensionless_position",
                "dimensionless_velocity", "ax", "ay",
                "az", "closest_approach_primary", "closest_approach_secondary", "stability_indices"]


def _shown(request) -> str:
    name, value = request
    return str(value) if name == "resonance" else display.summary(value) if isinstance(value, u.Quantity) else \
        display.number(float(value))


def _spaced(finder, followed, last, count, spacing) -> list:
    """`count` crossings from the followed family's first member to `last`, evenly spaced in `spacing`."""
    if spacing == "arclength":
        return families.resample(finder.hmap, followed, last, count)
    mu = finder.binary.mu

    def measure(member):
        if spacing == "period":
            return member.period
        return float(cr3bp.jacobi_constant(finder.flow.barycentric(member.state), mu))

    try:
        return families.respace(finder.hmap, followed, last, count, measure)
    except families.TurningPoint as turn:
        shown = display.number(turn.value) if spacing == "jacobi" else display.summary(
            turn.value / finder.binary.n * u.s)
        raise OrbitDomainError(f"the {finder.describe()} family cannot be spaced evenly in {spacing}: it turns back "
                               f"in {spacing} near {shown} on its way to the last member (space it in arclength)"
                               ) from None
