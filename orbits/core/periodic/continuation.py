"""Continuation along a family of symmetric periodic orbits, and the stability indices that mark its bifurcations.

A family is a curve of solutions u = (kept components, tau) of the half-period map F(u) = 0
(orbits.core.periodic.shooting),
measured in the scaled metric v = weights u (the state components in units of the flow's length scale), so that
steps mean the same for a Sun-Earth halo (1e-3 r) as for an Earth-Moon one (0.1 r).

Pseudo-arclength continuation follows the curve itself: from a member u_k with unit tangent t_k (the null vector
of dF/du, oriented as the previous one), the prediction u_k + ds t_k is corrected with the condition
t_k . (u - u_k - ds t_k) = 0. A step whose correction fails, moves the prediction by more than JUMP ds (a jump to
another family) or turns the tangent by more than 60 degrees is halved, down to MIN_STEP; easy steps (settled
within EASY_ITERATIONS Newton iterations: orbits.core.periodic.shooting.Crossing) grow by half, up to the largest step
given. Every one of these decisions reads a quantity far from rounding noise, so a family follows the same steps
on every CPU. The continuation also stops where the family closes on itself (a step passes its first member, or
that member's mirror image in the binary's plane z = 0, which is a symmetry of the problem: a vertical family
returns to its start that way).

Stability. The monodromy matrix M has the eigenvalues 1, 1 (the orbit itself and the family) and two reciprocal
pairs (lambda_i, 1 / lambda_i). The stability indices nu_i = lambda_i + 1 / lambda_i follow from traces, free of
the defective eigenvalue 1: with s = tr M - 2 = nu_1 + nu_2 and p = nu_1 nu_2 = (s**2 - tr M**2 - 2) / 2, they are the
roots of nu**2 - s nu + p = 0 (complex in a complex quadruplet). The orbit is linearly stable when both are real
with |nu| <= 2. A new family branches off where an index crosses 2 (a pair of eigenvalues meets at 1: the halo and
vertical families leave the planar Lyapunov family there) and period-doubles where one crosses -2; between two
members the sign of (nu_1 - 2)(nu_2 - 2) = p - 2 s + 4, or (nu_1 + 2)(nu_2 + 2) = p + 2 s + 4, changes.
"""

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from orbits.core.errors import ConvergenceError, OrbitDomainError
from orbits.core.periodic import shooting

MIN_STEP = 1e-5
EASY_ITERATIONS = 4
#: a correction that moves the prediction by more than this many steps has left the family: the step is retried
JUMP = 0.5
#: iterations of the root search for a member with a given monitored value, and its relative tolerance
SEARCH_ITERATIONS = 60
SEARCH_TOLERANCE = 1e-13


def stability_indices(monodromy) -> np.ndarray:
    """(nu_1, nu_2) of a monodromy matrix (complex; real pairs and unit-circle pairs give real nu), the larger |nu|
    first, from the traces of M and M**2 (module docstring)."""
    m = np.asarray(monodromy, dtype=float)
    s = np.trace(m) - 2.0
    p = 0.5 * (s * s - np.trace(m @ m) - 2.0)
    root = np.sqrt(complex(s * s - 4.0 * p))
    first = 0.5 * (s + root) if s.real >= 0.0 else 0.5 * (s - root)
    second = p / first if first != 0.0 else 0.5 * (s - root)
    pair = np.array([first, second])
    return pair[np.argsort(-np.abs(pair))]


def tangent_bifurcation_function(monodromy) -> float:
    """(nu_1 - 2)(nu_2 - 2) = p - 2 s + 4 (real): it changes sign where a family branches off."""
    m = np.asarray(monodromy, dtype=float)
    s = np.trace(m) - 2.0
    return float(0.5 * (s * s - np.trace(m @ m) - 2.0) - 2.0 * s + 4.0)


def period_doubling_function(monodromy) -> float:
    """(nu_1 + 2)(nu_2 + 2) = p + 2 s + 4 (real): it changes sign where a period-doubling family branches off."""
    m = np.asarray(monodromy, dtype=float)
    s = np.trace(m) - 2.0
    return float(0.5 * (s * s - np.trace(m @ m) - 2.0) + 2.0 * s + 4.0)


def tangent(jacobian, previous=None) -> np.ndarray:
    """Unit null vector of dF/du (m, m + 1), oriented along `previous` (a vector of m + 1 components) when given."""
    _, _, vt = np.linalg.svd(jacobian)
    t = vt[-1]
    if previous is not None and float(t @ previous) < 0.0:
        t = -t
    return t


@dataclass(frozen=True, eq=False)
class Branch:
    """Members of a family in order, their tangents, and why the continuation stopped (None: it was told to)."""

    members: list
    tangents: list
    stop: str | None


def step_along(hmap: shooting.HalfPeriodMap, member: shooting.Crossing, direction, ds: float) -> shooting.Crossing:
    """The member at arclength ds along unit `direction` (in the scaled metric of hmap.scaled) from `member`: the
    prediction corrected on the plane through it normal to `direction` (ConvergenceError if the corrector fails)."""
    predicted = hmap.scaled(member.u) + ds * direction

    def condition(u):
        return float(direction @ (hmap.scaled(u) - predicted)), direction * hmap.weights

    return hmap.correct(predicted / hmap.weights, condition)


def family_tangent(hmap: shooting.HalfPeriodMap, member: shooting.Crossing, previous=None) -> np.ndarray:
    """The family's unit tangent at `member` in the scaled metric (dF/dv = dF/du / weights), oriented along
    `previous`."""
    return tangent(member.jacobian / hmap.weights, previous)


def pseudo_arclength(hmap: shooting.HalfPeriodMap, first: shooting.Crossing, direction, step: float, count: int,
                     stop: Callable[[shooting.Crossing], str | None] | None = None,
                     max_step: float | None = None, until: Callable | None = None) -> Branch:
    """Up to `count` members from `first` (included), leaving it along `direction` (a vector of u's size whose sign
    picks the way along the family), first step `step`.

    Stops early when stop(member) returns a reason (the member is not kept), when until(previous, member) is true
    (the member is kept: a monitored quantity was passed), or when steps shrink below MIN_STEP."""
    max_step = abs(step) * 8.0 if max_step is None else max_step
    members = [first]
    t = family_tangent(hmap, first, np.asarray(direction, dtype=float))
    tangents = [t]
    ds = abs(step)
    while len(members) < count:
        try:
            member = step_along(hmap, members[-1], t, ds)
        except ConvergenceError:
            ds *= 0.5
            if ds < MIN_STEP:
                return Branch(members, tangents, _stuck(members[-1]))
            continue
        new_t = family_tangent(hmap, member, t)
        jumped = np.linalg.norm(hmap.scaled(member.u - members[-1].u) - ds * t) > JUMP * ds
        if jumped or float(new_t @ t) < 0.5:  # the tangent turned by more than 60 degrees, or the corrector moved
            # the prediction more than JUMP steps (onto another family): too long a step for this bend
            ds *= 0.5
            if ds < MIN_STEP:
                return Branch(members, tangents, _stuck(members[-1]))
            continue
        reason = stop(member) if stop is not None else None
        if reason is None and len(members) > 2 and _returns(hmap, members[0], members[-1], member):
            reason = ("the family closes on itself: it returns to its first member or that member's mirror image "
                      "in the binary's plane")
        if reason is not None:
            return Branch(members, tangents, reason)
        members.append(member)
        tangents.append(new_t)
        t = new_t
        if member.settled <= EASY_ITERATIONS:
            ds = min(1.5 * ds, max_step)
        if until is not None and until(members[-2], member):
            return Branch(members, tangents, None)
    return Branch(members, tangents, None)


def _returns(hmap, first, previous, member) -> bool:
    """Whether the step from `previous` to `member` passes within a quarter of its length of `first` or of first's
    image under z -> -z (the binary's plane is a mirror of the problem)."""
    mirror = np.array([-1.0 if k in (2, 5) else 1.0 for k in hmap.symmetry.kept] + [1.0])
    a, b = hmap.scaled(previous.u), hmap.scaled(member.u)
    chord = b - a
    length = float(np.linalg.norm(chord))
    for point in (hmap.scaled(first.u), hmap.scaled(first.u * mirror)):
        along = min(max(float((point - a) @ chord) / length**2, 0.0), 1.0) if length > 0.0 else 0.0
        if np.linalg.norm(a + along * chord - point) <= 0.25 * length:
            return True
    return False


def _stuck(member):
    return (f"the corrector cannot pass the member with half period {member.u[-1]:.6g} (a sharp turn or the end "
            f"of the family)")


def locate(hmap: shooting.HalfPeriodMap, member: shooting.Crossing, direction, span: float,
           monitor: Callable[[shooting.Crossing], float], target: float,
           bracket: tuple[float, float]) -> shooting.Crossing:
    """The member between `member` (s = 0) and arclength `span` along unit `direction` where monitor = target, given
    the monitor's values at both ends (`bracket`, of opposite signs after subtracting target): regula falsi with the
    Illinois modification on s (a bisection where the corrector cannot reach the trial), each trial corrected onto
    the family at its arclength."""
    a, b = 0.0, float(span)
    fa, fb = bracket[0] - target, bracket[1] - target
    if fa * fb > 0.0:
        raise OrbitDomainError("the monitored quantity does not cross the target between these members")
    best = member
    for _ in range(SEARCH_ITERATIONS):
        s = b - fb * (b - a) / (fb - fa)
        try:
            best = step_along(hmap, member, direction, s)
        except ConvergenceError:  # a prediction the corrector cannot bring back: bisect instead
            s = 0.5 * (a + b)
            best = step_along(hmap, member, direction, s)
        value = monitor(best) - target
        if abs(value) <= SEARCH_TOLERANCE * abs(target) or abs(b - a) <= 1e-15 * abs(span):
            return best
        if value * fb < 0.0:
            a, fa = b, fb
        else:
            fa *= 0.5
        b, fb = s, value
    return best
