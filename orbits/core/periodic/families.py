"""The families of periodic orbits of the restricted problem: where each starts, how it is followed, what its members
measure, the search for the member with a given amplitude, period, Jacobi constant or closest approach, and the
family's bifurcations.

Units of orbits.core.periodic.cr3bp (r = 1, n = 1). Each family is a curve of symmetric orbits
(orbits.core.periodic.shooting):

    lyapunov   planar, about L1, L2 or L3, crossing the x axis perpendicularly; first member from the linearised
               oscillation of x amplitude START_SIZE gamma (gamma: the point's distance to the nearer primary)
    halo       spatial, about L1 or L2, crossing the x-z plane perpendicularly; first member from Richardson's
               third-order orbit of z amplitude START_SIZE gamma, northern or southern (orbits.core.periodic.libration)
    vertical   spatial figure-of-eight, about L1 or L2, crossing the x axis perpendicularly; first member from the
               linearised vertical oscillation of z amplitude START_SIZE gamma
    dro        planar, retrograde about the secondary, crossing the x axis perpendicularly between the primaries; first
               member from the retrograde circle of radius d = DRO_START_SIZE times the secondary's Hill radius
               (mu/3)**(1/3), in the rotating frame vy = sqrt(mu / d) + d

The first member is corrected with its defining component held (x for the planar ones, z for the halo, vz for the
vertical), then the family is followed by pseudo-arclength continuation (orbits.core.periodic.continuation) in the
direction
of growing amplitude, in a flow written about the family's origin (its point, or the secondary for the DRO). A
member's extent comes from its trajectory sampled at SAMPLES points, each extreme (of x, y, z and of the distance to
either primary) polished by Newton's method on its time derivative along the exact flow.
"""

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from orbits.core.errors import ConvergenceError, OrbitDomainError
from orbits.core.periodic import continuation, cr3bp, libration, shooting

FAMILIES = ("lyapunov", "halo", "vertical", "dro")
#: where each family may start
POINTS = {"lyapunov": ("L1", "L2", "L3"), "halo": ("L1", "L2"), "vertical": ("L1", "L2"), "dro": (None,)}
SYMMETRIES = {"lyapunov": shooting.PLANAR, "halo": shooting.XZ_PLANE, "vertical": shooting.X_AXIS,
              "dro": shooting.PLANAR}
#: the component of u held while correcting the first member: x, z, vz, x
_DEFINING = {"lyapunov": 0, "halo": 1, "vertical": 2, "dro": 0}
#: first members: amplitude in units of gamma (about a point) or of the Hill radius (the DRO)
START_SIZE = 0.02
DRO_START_SIZE = 0.1
SAMPLES = 128
#: Newton steps polishing an extreme, and the time step (units of the period) below which it has converged
POLISH_ITERATIONS = 8
POLISH_TOLERANCE = 1e-14
#: pseudo-arclength continuation: first and largest steps (in the scaled metric of HalfPeriodMap.scaled: units of
#: the origin's length scale), and the most members followed
STEP = 0.1
MAX_STEP = 1.5
MAX_MEMBERS = 2000
#: the metrics a member can be asked for (units of r, 1 / n and (n r)**2)
METRICS = ("ax", "ay", "az", "period", "jacobi", "closest_primary", "closest_secondary")


def check_family(family: str, point: str | None) -> None:
    """OrbitDomainError unless `family` is known and starts at `point` (None for the DRO)."""
    if family not in FAMILIES:
        raise OrbitDomainError(f"unknown family {family!r}; choose from {', '.join(FAMILIES)}")
    allowed = POINTS[family]
    if point not in allowed:
        where = "about the secondary (no point)" if allowed == (None,) else f"about {', '.join(allowed)}"
        raise OrbitDomainError(f"the {family} family lies {where}, not {point if point else 'nowhere'}")


def origin(family: str, point: str | None) -> str:
    """The origin a family's flow is written about (orbits.core.periodic.cr3bp.ORIGINS): its point, or the secondary."""
    return "secondary" if family == "dro" else point


def start_size(mu: float, family: str, point: str | None) -> float:
    """The amplitude (units of r) of a family's first member: START_SIZE gamma about a point, DRO_START_SIZE Hill
    radii about the secondary."""
    if family == "dro":
        return DRO_START_SIZE * (mu / 3.0) ** (1.0 / 3.0)
    return START_SIZE * libration.distance_to_nearer_primary(mu, point)


def first_member(flow: shooting.Flow, family: str, point: str | None, northern: bool = True,
                 size: float | None = None) -> tuple[shooting.HalfPeriodMap, shooting.Crossing, np.ndarray]:
    """(the family's half-period map, its corrected first member, the direction of growing amplitude in u), along a
    flow written about the family's origin.

    `size` (units of r) overrides the starting amplitude: the x amplitude of a Lyapunov orbit, the z amplitude of a
    halo or vertical orbit, the distance of a DRO's crossing from the secondary."""
    check_family(family, point)
    mu = flow.mu
    hmap = shooting.HalfPeriodMap(flow, SYMMETRIES[family])
    direction = np.zeros(len(hmap.symmetry.kept) + 1)
    size = start_size(mu, family, point) if size is None else size
    if family == "dro":
        d = size
        state = np.array([1.0 - mu - d, 0.0, 0.0, 0.0, math.sqrt(mu / d) + d, 0.0])
        half_period = math.pi / (math.sqrt(mu / d**3) + 1.0)
        direction[0] = -1.0
    else:
        amplitude = size
        if family == "lyapunov":
            state, half_period = libration.planar_guess(mu, point, amplitude)
            direction[0] = -1.0
        elif family == "vertical":
            state, half_period = libration.vertical_guess(mu, point, amplitude)
            direction[2] = 1.0
        else:
            halo = libration.richardson_halo(mu, point, amplitude, northern)
            state, half_period = halo.states(0.0), 0.5 * halo.period
            direction[1] = math.copysign(1.0, state[2])
    u = hmap.unknowns(flow.local(state), half_period)
    index = _DEFINING[family]
    member = hmap.correct(u, shooting.fixed_component(index, u[index]))
    return hmap, member, direction


@dataclass(frozen=True)
class Extent:
    """The reach of a periodic orbit: smallest and largest x, y, z (`low`, `high`, units of r), and the least and
    greatest distances from the centres of the primary and the secondary (`closest`, `farthest`, shape (2,))."""

    low: np.ndarray
    high: np.ndarray
    closest: np.ndarray
    farthest: np.ndarray

    @property
    def amplitudes(self) -> np.ndarray:
        """(Ax, Ay, Az): half the extent in x and y; the largest distance from the x-y plane in z."""
        half = 0.5 * (self.high - self.low)
        return np.array([half[0], half[1], max(self.high[2], -self.low[2])])


def extent(flow: shooting.Flow, state, period: float, samples: int = SAMPLES) -> Extent:
    """The Extent of the orbit from `state` (about the flow's origin) over one `period`, each extreme polished along
    the flow; positions in it are about the barycentre."""
    times = np.linspace(0.0, period, samples + 1)
    states = flow.arc(state, period, outputs=times).states
    low, high = np.zeros(3), np.zeros(3)
    for k in range(3):
        def coordinate(s, k=k):
            return s[k]

        def derivatives(s, a, k=k):
            return s[3 + k], a[k]

        low[k] = _polish(flow, times, states, coordinate, derivatives, np.argmin)
        high[k] = _polish(flow, times, states, coordinate, derivatives, np.argmax)
    low[0] += flow.origin.x
    high[0] += flow.origin.x
    closest, farthest = np.zeros(2), np.zeros(2)
    for j, offset in enumerate((flow.origin.from_primary, flow.origin.from_secondary)):
        centre = np.array([-offset, 0.0, 0.0])

        def distance(s, c=centre):
            return float(np.linalg.norm(s[:3] - c))

        def slopes(s, a, c=centre):  # d/dt and d2/dt2 of |r - c|**2 / 2
            d = s[:3] - c
            return float(d @ s[3:]), float(s[3:] @ s[3:] + d @ a)

        closest[j] = _polish(flow, times, states, distance, slopes, np.argmin)
        farthest[j] = _polish(flow, times, states, distance, slopes, np.argmax)
    return Extent(low, high, closest, farthest)


def _polish(flow, times, states, value, derivatives, pick):
    """The extreme of value(state) nearest the sampled one that `pick` (np.argmin or np.argmax) chooses: Newton's
    method on g(t) = 0 with (g, g') = derivatives(state, acceleration), each step integrated from the last state,
    while it stays within two samples of the start; the better of the sample and the polished value."""
    samples = np.array([value(s) for s in states])
    k = int(pick(samples))
    s = states[k]
    period = float(times[-1])
    polished = samples[k]
    for _ in range(POLISH_ITERATIONS):
        g, slope = derivatives(s, flow.field(s)[3:])
        if slope == 0.0:
            break
        dt = -g / slope
        if not abs(dt) <= 2.0 * period / len(times) or abs(dt) <= POLISH_TOLERANCE * period:
            break
        s = flow.arc(s, dt).end
        polished = value(s)
    return float((samples[k], polished)[int(pick([samples[k], polished]))])


class BeyondFamily(OrbitDomainError):
    """A searched value the family does not reach: `low` to `high` is what its members reached before `reason`."""

    def __init__(self, name: str, target: float, low: float, high: float, reason: str, behind: bool = False):
        super().__init__(f"{name} = {target:.9g} is beyond the family: its members reach {low:.9g} to {high:.9g} "
                         f"({reason})")
        self.name, self.target, self.low, self.high, self.reason = name, target, low, high, reason
        #: the target lies on the far side of the first member: a smaller first member may reach it
        self.behind = behind


class Measures:
    """Metrics of the members of one family along a Flow, each member's Extent computed once."""

    def __init__(self, flow: shooting.Flow):
        self.flow = flow
        self._extents = {}

    def extent(self, member: shooting.Crossing) -> Extent:
        key = id(member)
        if key not in self._extents:
            self._extents[key] = (member, extent(self.flow, member.state, member.period))
        return self._extents[key][1]

    def metric(self, member: shooting.Crossing, name: str) -> float:
        """One of METRICS of a member (units of r, 1 / n, (n r)**2)."""
        if name == "period":
            return member.period
        if name == "jacobi":
            return float(cr3bp.jacobi_constant(self.flow.barycentric(member.state), self.flow.mu))
        if name in ("ax", "ay", "az"):
            return float(self.extent(member).amplitudes[("ax", "ay", "az").index(name)])
        if name in ("closest_primary", "closest_secondary"):
            return float(self.extent(member).closest[0 if name == "closest_primary" else 1])
        raise OrbitDomainError(f"unknown metric {name!r}; choose from {', '.join(METRICS)}")


def trace(hmap: shooting.HalfPeriodMap, measures: Measures, first: shooting.Crossing, direction,
          name: str | None = None, target: float | None = None,
          stop: Callable[[shooting.Crossing], str | None] | None = None, count: int = MAX_MEMBERS,
          step: float = STEP) -> tuple[continuation.Branch, shooting.Crossing]:
    """(the members followed from `first` along `direction`, the last member): the one with metric `name` = target
    when a target is given, else the last before `stop` gave a reason or `count` members. BeyondFamily names the
    range reached when the family ends or turns back before the target, or (`behind`) when its first step leads
    away from the target."""
    if name is None:
        branch = continuation.pseudo_arclength(hmap, first, direction, step, count, stop=stop, max_step=MAX_STEP)
        return branch, branch.members[-1]

    def value(member):
        return measures.metric(member, name)

    seen = [value(first)]
    if seen[0] == target:
        return continuation.Branch([first], [continuation.family_tangent(hmap, first, direction)], None), first
    side = math.copysign(1.0, target - seen[0])

    def passed(previous, member):
        seen.append(value(member))
        return (seen[-1] - target) * side >= 0.0 or (len(seen) == 2 and abs(seen[1] - target) > abs(seen[0] - target))

    branch = continuation.pseudo_arclength(hmap, first, direction, step, count, stop=stop, until=passed,
                                           max_step=MAX_STEP)
    if len(seen) == 2 and len(branch.members) == 2 and (seen[1] - target) * side < 0.0:
        raise BeyondFamily(name, target, min(seen), max(seen), "the family's first member already lies beyond it",
                           behind=True)
    reached = seen[: len(branch.members)]
    if len(branch.members) < 2 or (reached[-1] - target) * side < 0.0:
        why = branch.stop or f"no crossing within {count} members"
        raise BeyondFamily(name, target, min(reached), max(reached), why)
    before, after = branch.members[-2], branch.members[-1]
    t = branch.tangents[-2]
    member = continuation.locate(hmap, before, t, float(t @ hmap.scaled(after.u - before.u)), value, target,
                                 (reached[-2], reached[-1]))
    return continuation.Branch(branch.members[:-1], branch.tangents[:-1], None), member


def resample(hmap: shooting.HalfPeriodMap, branch: continuation.Branch, last: shooting.Crossing,
             count: int) -> list:
    """`count` >= 2 members evenly spaced in arclength from the branch's first member to `last`, each corrected from
    the followed member before it along its tangent (the arclength between two followed members is the step the
    first one's tangent took to the second); where that correction fails, the nearer followed member stands in."""
    members = list(branch.members)
    if members[-1] is not last:
        members.append(last)
    steps = [float(t @ hmap.scaled(b.u - a.u)) for a, b, t in zip(members, members[1:], branch.tangents)]
    lengths = np.concatenate([[0.0], np.cumsum(steps)])
    chosen = []
    for s in np.linspace(0.0, lengths[-1], count):
        j = min(int(np.searchsorted(lengths, s, side="right")) - 1, len(members) - 1)
        ds = s - lengths[j]
        if ds <= 1e-12 * max(lengths[-1], 1e-300) or j == len(members) - 1:
            chosen.append(members[j])
            continue
        try:
            chosen.append(continuation.step_along(hmap, members[j], branch.tangents[j], ds))
        except ConvergenceError:  # where the corrector cannot reach the float64 floor: the nearer followed member
            chosen.append(members[j] if ds <= 0.5 * (lengths[j + 1] - lengths[j]) else members[j + 1])
    return chosen


def respace(hmap: shooting.HalfPeriodMap, branch: continuation.Branch, last: shooting.Crossing, count: int,
            measure: Callable[[shooting.Crossing], float]) -> list:
    """`count` >= 2 members from the branch's first member to `last` evenly spaced in measure(member) (the period or
    the Jacobi constant), each located on the family by regula falsi between the two followed members whose measures
    bracket its value (continuation.locate), so that a member's value decides nothing but its own bracket: the same
    members on every CPU, to the corrector's tolerance. TurningPoint if the measure turns back between the first
    member and `last` (a step against the first one's sense by more than FLAT of the measure)."""
    members = list(branch.members)
    if members[-1] is not last:
        members.append(last)
    tangents = list(branch.tangents) + [None]
    along = np.array([measure(m) for m in members])
    turn = turning_point(along)
    if turn is not None:
        raise TurningPoint(float(along[turn]))
    values = np.linspace(along[0], along[-1], count)
    chosen = [members[0]]
    for value in values[1:-1]:
        k = int(np.flatnonzero((along[:-1] - value) * (along[1:] - value) <= 0.0)[0])
        if along[k] == value or along[k + 1] == value:
            chosen.append(members[k] if along[k] == value else members[k + 1])
            continue
        t = tangents[k]
        span = float(t @ hmap.scaled(members[k + 1].u - members[k].u))
        chosen.append(continuation.locate(hmap, members[k], t, span, measure, float(value),
                                          (along[k], along[k + 1])))
    return chosen + [members[-1]]


#: a step of a followed family's measure against the sense of its first step counts as turning back only beyond
#: this fraction of the measure: rounding moves a corrected member's measure far less (the same member's period
#: differs by 9e-15 of itself between CPU classes, tests/stability/test_cpu_profiles.py), and pseudo-arclength
#: steps of at least continuation.MIN_STEP move a monotone measure by far more
FLAT = 1e-9


class TurningPoint(OrbitDomainError):
    """The measure of a followed family turns back (at `value`) before the last member asked for."""

    def __init__(self, value: float):
        super().__init__(f"the family turns back in it near {value:.9g}")
        self.value = value


def turning_point(along) -> int | None:
    """The index of the first member where the sequence `along` turns back against the sense of its first step by
    more than FLAT of its size (None if it does not)."""
    steps = np.diff(np.asarray(along, dtype=float))
    noise = FLAT * np.maximum(np.abs(along[:-1]), np.abs(along[1:]))
    real = np.flatnonzero(np.abs(steps) > noise)
    if real.size == 0:
        return None
    sense = np.sign(steps[real[0]])
    against = real[np.sign(steps[real]) != sense]
    return int(against[0]) if against.size else None


def monodromy(hmap: shooting.HalfPeriodMap, member: shooting.Crossing) -> np.ndarray:
    """The member's monodromy matrix from its half-period transition matrix."""
    return shooting.symmetric_monodromy(member.transition, hmap.symmetry.signs)


def bifurcations(hmap: shooting.HalfPeriodMap, branch: continuation.Branch) -> list:
    """[(kind, member)] where a stability index crosses 2 ("tangent": a family branches off) or -2 ("period
    doubling") between consecutive members, each located on the family by regula falsi on the crossing function."""
    functions = {"tangent": continuation.tangent_bifurcation_function,
                 "period doubling": continuation.period_doubling_function}
    found = []
    members, tangents = branch.members, branch.tangents
    for kind, function in functions.items():
        values = [function(monodromy(hmap, m)) for m in members]
        for k in range(len(members) - 1):
            if values[k] == 0.0 or values[k] * values[k + 1] < 0.0:
                t = tangents[k]
                span = float(t @ hmap.scaled(members[k + 1].u - members[k].u))
                try:
                    member = continuation.locate(hmap, members[k], t, span,
                                                 lambda m, f=function: f(monodromy(hmap, m)), 0.0,
                                                 (values[k], values[k + 1]))
                except (ConvergenceError, OrbitDomainError):
                    member = members[k]
                found.append((kind, member))
    found.sort(key=lambda item: _position(hmap, members, item[1]))
    return found


def _position(hmap, members, member):
    """Where a located member falls along the branch: the index of the nearest computed member."""
    return int(np.argmin([np.linalg.norm(hmap.scaled(m.u - member.u)) for m in members]))
