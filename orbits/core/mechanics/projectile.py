"""Section XX of the notes: motion under uniform effective gravity, on float64 arrays.

SI units throughout: g in m/s**2, speeds in m/s, lengths in m, times in s, angles in rad, the linear-drag rate b in
1/s (drag force -m b v), the quadratic-drag terminal speed v_t in m/s (drag force -m g |v| v / v_t**2, that is
-(1/2) C rho A |v| v with v_t = sqrt(2 m g / (C rho A)); the notes' v_t leaves out the mass). The frame has x along
the ground and y up, launch from (0, h) at velocity (v_x, v_y).

- Effective gravity on a rotating Earth (XX.i; the horizontal part points toward the equator, the opposite of the
  notes' sign) and the conical pendulum (XX.ii).
- No drag (XX.iii): closed forms; the flight time 2 h / (s - v_y) when thrown downward avoids cancellation.
- Linear drag (XX.v; the notes' y(t) and y'(t) have wrong signs, corrected at each function): closed forms written
  with (1 - e^-z) / z and (z - 1 + e^-z) / z**2, z = b t, so that b -> 0 reproduces the drag-free motion digit for
  digit; the apex by log1p; the landing time by safeguarded Newton on the closed form.
- Quadratic drag (XX.iv): no closed form for x(t), but along the trajectory the horizontal velocity u is a closed
  function of p = tan(velocity angle): 1 / u**2 = 1 / u0**2 + (G(p0) - G(p)) / v_t**2 with
  G(p) = p sqrt(1 + p**2) + asinh(p), and t, x, y are integrals of u, u**2, u**2 p over p (times v_t / g ...),
  evaluated here by graded Gauss-Legendre quadrature. Straight up and down (v_x = 0) has closed forms.
Accuracy against heyoka integrations of the same equations (tests/validation/test_mechanics_integration.py):
linear-drag positions, velocities, apex and flight time to 5e-16 relative; quadratic-drag flight time, range, apex
and landing speed to 6e-14 (the vertical closed forms to 2e-16). Against mpmath: the linear-drag flight time within
2 ulp (tests/core/test_projectile.py).
"""

import math

import numpy as np
from numpy.typing import ArrayLike

from orbits.core.errors import ConvergenceError, OrbitDomainError

# ---- effective gravity and the conical pendulum (XX.i, XX.ii) -----------------------------------------------


def effective_gravity(a_g: ArrayLike, omega: ArrayLike, radius: ArrayLike, latitude: ArrayLike):
    """(toward the equator, down) (m/s**2): gravity a_g toward the centre plus the centrifugal omega**2 R cos(phi)
    away from the axis, at latitude phi on a sphere of radius R spinning at omega (rad/s) (XX.i).

    Components (omega**2 R sin(2 phi) / 2, a_g - omega**2 R cos**2 phi): the horizontal part points toward the
    equator (the notes take x toward the pole with this sign, which points the wrong way); the vertical part is
    least at the equator, a_g - omega**2 R, and a_g at the poles.
    """
    phi = np.asarray(latitude, dtype=float)
    spin = np.asarray(omega, dtype=float) ** 2 * np.asarray(radius, dtype=float)
    cos_phi = np.cos(phi)
    return spin * cos_phi * np.sin(phi), np.asarray(a_g, dtype=float) - spin * cos_phi * cos_phi


def conical_pendulum_rate(g: ArrayLike, length: ArrayLike, angle: ArrayLike) -> np.ndarray:
    """omega = sqrt(g sec(theta) / L) (rad/s): the angular speed of a conical pendulum of string length L (m) at
    angle theta (rad) from the vertical (XX.ii: g tan(theta) = omega**2 L sin(theta))."""
    return np.sqrt(np.asarray(g, dtype=float) / (np.asarray(length, dtype=float) * np.cos(angle)))


def conical_pendulum_speed(g: ArrayLike, length: ArrayLike, angle: ArrayLike) -> np.ndarray:
    """v = sqrt(g L sin(theta) tan(theta)) (m/s) on the circle of radius L sin(theta) (XX.ii)."""
    return np.sqrt(np.asarray(g, dtype=float) * np.asarray(length, dtype=float) * np.sin(angle) * np.tan(angle))


def conical_pendulum_angle(g: ArrayLike, length: ArrayLike, omega: ArrayLike) -> np.ndarray:
    """theta = arccos(g / (omega**2 L)) (rad): the cone angle at angular speed omega (rad/s); needs omega**2 L > g
    (slower, the bob hangs straight down)."""
    ratio = np.asarray(g, dtype=float) / (np.asarray(omega, dtype=float) ** 2 * np.asarray(length, dtype=float))
    if np.any(ratio >= 1):
        value = float(np.asarray(ratio)[np.asarray(ratio) >= 1].flat[0]) if np.ndim(ratio) else float(ratio)
        raise OrbitDomainError(
            f"g / (omega**2 L) = {value!r} is outside the allowed range (0, 1) (dimensionless): a conical pendulum "
            "needs omega > sqrt(g / L)"
        )
    return np.arccos(ratio)


# ---- no drag (XX.iii) ----------------------------------------------------------------------------------------


def free_position(v_x, v_y, h, g, t):
    """(x, y) = (v_x t, h + v_y t - g t**2 / 2) (m) (XX.iii)."""
    t = np.asarray(t, dtype=float)
    return np.asarray(v_x) * t, h + (np.asarray(v_y) - 0.5 * np.asarray(g) * t) * t


def free_velocity(v_x, v_y, g, t):
    """(v_x, v_y - g t) (m/s) (XX.iii)."""
    t = np.asarray(t, dtype=float)
    return np.asarray(v_x, dtype=float) + 0.0 * t, np.asarray(v_y) - np.asarray(g) * t


def free_apex_time(v_y, g):
    """t = v_y / g (s) for v_y > 0, else 0 (the launch point is the highest) (XX.iii)."""
    return np.maximum(np.asarray(v_y, dtype=float), 0.0) / np.asarray(g, dtype=float)


def free_apex_height(v_y, h, g):
    """y = h + v_y**2 / (2 g) (m) for v_y > 0, else h (XX.iii)."""
    up = np.maximum(np.asarray(v_y, dtype=float), 0.0)
    return np.asarray(h, dtype=float) + up * up / (2.0 * np.asarray(g, dtype=float))


def free_landing_vertical_speed(v_y, h, g):
    """s = sqrt(v_y**2 + 2 g h) (m/s): the downward speed at y = 0 (XX.iii)."""
    return np.sqrt(np.asarray(v_y, dtype=float) ** 2 + 2.0 * np.asarray(g) * np.asarray(h))


def free_flight_time(v_y, h, g):
    """t = (v_y + s) / g = 2 h / (s - v_y) (s), s = sqrt(v_y**2 + 2 g h): the time to reach y = 0 (XX.iii). The
    second form is used when v_y < 0, where the first would cancel; h = 0 gives 2 v_y / g."""
    v_y = np.asarray(v_y, dtype=float)
    s = free_landing_vertical_speed(v_y, h, g)
    with np.errstate(divide="ignore", invalid="ignore"):
        down = 2.0 * np.asarray(h, dtype=float) / (s - v_y)
    return np.where(v_y >= 0, (v_y + s) / g, np.where(s - v_y > 0, down, 0.0))


# ---- linear (Stokes) drag (XX.v) ------------------------------------------------------------------------------

_SERIES_TERMS = 24


def _relaxation(z):
    """(1 - e^-z) / z = -expm1(-z) / z, 1 at z = 0 (dimensionless)."""
    z = np.asarray(z, dtype=float)
    safe = np.where(z == 0, 1.0, z)
    return np.where(z == 0, 1.0, -np.expm1(-safe) / safe)


def _settling(z):
    """(z - 1 + e^-z) / z**2 = sum_n (-z)**n / (n + 2)!, 1/2 at z = 0 (dimensionless); the series below |z| = 1,
    where the difference would lose digits, the closed form (within 2 ulp) above."""
    z = np.asarray(z, dtype=float)
    series = np.zeros_like(z)
    for n in range(_SERIES_TERMS, -1, -1):
        series = series * (-z) + 1.0 / math.factorial(n + 2)
    safe = np.where(np.abs(z) < 1, 1.0, z)
    return np.where(np.abs(z) < 1, series, (safe + np.expm1(-safe)) / (safe * safe))


def _log_ratio(z):
    """log1p(z) / z, 1 at z = 0 (dimensionless)."""
    z = np.asarray(z, dtype=float)
    safe = np.where(z == 0, 1.0, z)
    return np.where(z == 0, 1.0, np.log1p(safe) / safe)


def _log_excess(z):
    """(z - log1p(z)) / z**2 = sum_n (-z)**n / (n + 2), 1/2 at z = 0 (dimensionless): the series below |z| = 1/2,
    the closed form (within 6 ulp) above."""
    z = np.asarray(z, dtype=float)
    series = np.zeros_like(z)
    for n in range(60, -1, -1):
        series = series * (-z) + 1.0 / (n + 2)
    safe = np.where(np.abs(z) < 0.5, 1.0, z)
    return np.where(np.abs(z) < 0.5, series, (safe - np.log1p(safe)) / (safe * safe))


def linear_drag_position(v_x, v_y, h, g, b, t):
    """(x, y) (m) under drag -m b v (XX.v): x = (v_x / b)(1 - e^-bt),
    y = h - g t / b + (v_y / b + g / b**2)(1 - e^-bt) (the notes flip both signs of y, which gives y'(0) = -v_y),
    evaluated as x = v_x t F1, y = h + v_y t F1 - g t**2 F2 with F1 = (1 - e^-z) / z, F2 = (z - 1 + e^-z) / z**2,
    z = b t (b = 0 is the drag-free motion)."""
    t = np.asarray(t, dtype=float)
    z = np.asarray(b, dtype=float) * t
    f1 = _relaxation(z)
    return np.asarray(v_x) * t * f1, h + np.asarray(v_y) * t * f1 - np.asarray(g) * t * t * _settling(z)


def linear_drag_velocity(v_x, v_y, g, b, t):
    """(v_x e^-bt, -g / b + (v_y + g / b) e^-bt) (m/s) (XX.v; the notes' +g / b breaks v(0) = v_y), evaluated as
    v_y e^-bt - g t (1 - e^-bt) / (b t)."""
    t = np.asarray(t, dtype=float)
    z = np.asarray(b, dtype=float) * t
    decay = np.exp(-z)
    return np.asarray(v_x) * decay, np.asarray(v_y) * decay - np.asarray(g) * t * _relaxation(z)


def linear_drag_terminal_speed(g, b):
    """g / b (m/s): the terminal velocity is (0, -g / b) (XX.v)."""
    return np.asarray(g, dtype=float) / np.asarray(b, dtype=float)


def linear_drag_apex_time(v_y, g, b):
    """t = ln(1 + b v_y / g) / b (s) for v_y > 0 (where the vertical velocity vanishes), else 0."""
    up = np.maximum(np.asarray(v_y, dtype=float), 0.0)
    return up / g * _log_ratio(np.asarray(b) * up / g)


def linear_drag_apex_height(v_y, h, g, b):
    """y = h + v_y / b - (g / b**2) ln(1 + b v_y / g) (m) for v_y > 0, else h, evaluated as
    h + (v_y**2 / g) (z - ln(1 + z)) / z**2 with z = b v_y / g."""
    up = np.maximum(np.asarray(v_y, dtype=float), 0.0)
    return np.asarray(h, dtype=float) + up * up / g * _log_excess(np.asarray(b) * up / g)


def linear_drag_flight_time(v_y, h, g, b):
    """t (s) with y(t) = 0 after the apex under linear drag: safeguarded Newton on the closed-form y (XX.v).

    y decreases monotonically after the apex, so the root is unique; the bracket [apex time, T] uses
    T = max(drag-free flight time, h b / g + (b v_y + g) / (b g)) (above both bounds of y), bisecting when a
    Newton step leaves it. Converges to a few ulp (tests/core/test_projectile.py).
    """
    v_y, h, g, b = np.broadcast_arrays(*(np.asarray(x, dtype=float) for x in (v_y, h, g, b)))
    lo = linear_drag_apex_time(v_y, g, b)
    start = free_flight_time(v_y, h, g)
    with np.errstate(divide="ignore", invalid="ignore"):  # b = 0: the drag-free time is the root itself
        bound = np.where(b > 0, h * b / g + np.maximum(b * v_y + g, 0.0) / (b * g), start)
    hi = np.maximum(bound, lo)
    t = np.clip(start, lo, hi)

    def height_and_rate(times):
        return linear_drag_position(0.0, v_y, h, g, b, times)[1], linear_drag_velocity(0.0, v_y, g, b, times)[1]

    return _newton_descending(t, lo, hi, height_and_rate, "linear-drag flight time")


def _newton_descending(t, lo, hi, function, what):
    """Root of a function decreasing in [lo, hi] (a bracket), Newton steps with bisection when one leaves it."""
    t, lo, hi = t.copy(), lo.copy(), hi.copy()
    for _ in range(200):
        y, rate = function(t)
        lo = np.where(y > 0, t, lo)
        hi = np.where(y < 0, t, hi)
        with np.errstate(divide="ignore", invalid="ignore"):
            step = np.where(rate != 0, -y / rate, 0.0)
        new = t + step
        inside = np.isfinite(new) & (new >= lo) & (new <= hi) & (rate < 0)
        new = np.where(inside, new, 0.5 * (lo + hi))
        done = (np.abs(new - t) <= 2.0**-51 * np.abs(new)) | (y == 0) | (hi - lo <= 2.0**-52 * np.abs(t))
        t = np.where(y == 0, t, new)
        if np.all(done):
            return t
    raise ConvergenceError(f"{what}: Newton's method did not converge in 200 iterations; last t = {t!r}")


# ---- quadratic drag (XX.iv) -----------------------------------------------------------------------------------


def quadratic_drag_terminal_speed(mass, g, drag_coefficient, density, area):
    """v_t = sqrt(2 m g / (C rho A)) (m/s): where drag (1/2) C rho A v**2 balances m g (XX.iv; the
    notes drop the mass, which leaves a formula of the wrong dimension)."""
    return np.sqrt(2.0 * np.asarray(mass) * np.asarray(g) / (np.asarray(drag_coefficient) * np.asarray(density)
                                                               * np.asarray(area)))


def _hodograph_g(p):
    """G(p) = p sqrt(1 + p**2) + asinh(p) = 2 int_0^p sqrt(1 + s**2) ds (dimensionless), odd and increasing."""
    return p * np.hypot(1.0, p) + np.arcsinh(p)


def _hodograph_step(anchor, width):
    """G(anchor + width) - G(anchor) (anchor a float, width an array of either sign), from the width itself: when both
    ends have one sign each term's difference is rewritten as a quotient, a s_a - b s_b = (a**2 - b**2)(1 + a**2 +
    b**2) / (a s_a + b s_b) and asinh(a) - asinh(b) = asinh((a**2 - b**2) / (a s_b + b s_a)), s_x = sqrt(1 + x**2),
    with a**2 - b**2 = |width| (a + b): no cancellation, and a width below the anchor's last bit still counts."""
    width = np.asarray(width, dtype=float)
    other = anchor + width
    upper, lower = np.maximum(anchor, other), np.minimum(anchor, other)
    direct = _hodograph_g(upper) - _hodograph_g(lower)
    same = upper * lower > 0
    a = np.where(same, np.where(upper > 0, upper, -lower), 1.0)  # a >= b > 0 on the same-sign side
    b = np.where(same, np.where(upper > 0, lower, -upper), 0.5)
    sa, sb = np.hypot(1.0, a), np.hypot(1.0, b)
    squares = np.where(same, np.abs(width) * (a + b), 0.75)
    quotient = squares * (1.0 + a * a + b * b) / (a * sa + b * sb) + np.arcsinh(squares / (a * sb + b * sa))
    return np.copysign(np.where(same, quotient, direct), width)


#: Gauss-Legendre nodes and weights on [-1, 1] for each panel of the quadratic-drag quadrature
_GL_NODES, _GL_WEIGHTS = np.polynomial.legendre.leggauss(24)


class QuadraticDragPath:
    """One trajectory under quadratic drag, in the units of the terminal speed: speeds / v_t, times / (v_t / g),
    lengths / (v_t**2 / g); p = tan(angle of the velocity above the horizontal), decreasing from p0 along the path.

    u(p) = U v_t is the horizontal velocity, 1 / U**2 = 1 / U0**2 + G(p0) - G(p); then
    t = int_p^p0 U dp', x = int_p^p0 U**2 dp', y - h = int_p^p0 U**2 p' dp' (XX.iv, derived from dpsi/dt =
    -g cos(psi) / v and du/dt = -g v u / v_t**2). The quadrature runs in the drop d = p0 - p, so that the
    distance to the integrand's branch point p* = p0 + gap (1 / U(p*)**2 = 0) is gap + d, exact however small the gap
    (a launch 1e9 times faster than v_t has gap ~ 1e-18, below p0's last bit); the panels are graded toward it.
    """

    def __init__(self, speed: float, angle: float, height: float):
        self.speed, self.angle, self.height = speed, angle, height
        self.p0 = math.tan(angle)
        cos0 = math.cos(angle)
        self.inverse_u0_squared = 1.0 / (speed * cos0) ** 2
        self.branch_gap = self._branch_gap()

    def _branch_gap(self):
        """p* - p0 (> 0), where G(p*) - G(p0) = 1 / U0**2, by Newton from below (G is increasing and convex
        for p > 0; a bracket keeps the iteration safe for p < 0)."""
        target, lo = self.inverse_u0_squared, 0.0
        hi = target / 2.0  # G' = 2 sqrt(1 + p**2) >= 2
        gap = hi
        for _ in range(200):
            value = float(_hodograph_step(self.p0, gap)) - target
            if value > 0:
                hi = gap
            else:
                lo = gap
            step = value / (2.0 * math.hypot(1.0, self.p0 + gap))
            new = gap - step
            if not lo <= new <= hi:
                new = 0.5 * (lo + hi)
            if abs(new - gap) <= 2.0**-52 * new:
                return new
            gap = new
        return gap

    def horizontal_speed_squared(self, p):
        """U(p)**2 (dimensionless), p <= p0 an array."""
        return self._speed_squared_after(self.p0 - np.asarray(p, dtype=float))

    def _speed_squared_after(self, drop):
        """U**2 at p = p0 - drop (drop >= 0 an array): 1 / (1 / U0**2 - (G(p0 - drop) - G(p0)))."""
        return 1.0 / (self.inverse_u0_squared - _hodograph_step(self.p0, -drop))

    def _panels(self, end):
        """Panel edges in the drop d = p0 - p, from 0 to `end`: each width at most the distance gap + d to the
        branch point and at most max(1/2, |p| / 2) (the other singularities of the integrand, at p = +-i), so every
        panel lies at least its own width from them; widths grow geometrically away from p*, and each edge moves
        on by at least its last bit."""
        edges = [0.0]
        while edges[-1] < end:
            drop = edges[-1]
            width = min(self.branch_gap + drop, max(0.5, 0.5 * abs(self.p0 - drop)))
            edges.append(min(max(drop + width, math.nextafter(drop, math.inf)), end))
        return np.array(edges)

    def integrals(self, lower):
        """(t, x, y - h) from p0 down to p = lower (dimensionless)."""
        return self.integrals_to(self.p0 - lower)

    def integrals_to(self, end):
        """(t, x, y - h) from p0 down to p = p0 - end (dimensionless), by Gauss-Legendre panels in the drop."""
        edges = self._panels(end)
        left, right = edges[:-1], edges[1:]
        half, middle = 0.5 * (right - left), 0.5 * (right + left)
        drop = middle[:, None] + half[:, None] * _GL_NODES
        weights = half[:, None] * _GL_WEIGHTS
        u2 = self._speed_squared_after(drop)
        p = self.p0 - drop
        return (float(np.sum(weights * np.sqrt(u2))), float(np.sum(weights * u2)), float(np.sum(weights * u2 * p)))

    def landing_drop(self):
        """The drop d = p0 - p at y = 0: y = h + int U**2 p' dp' decreases with d past the apex (p < 0);
        safeguarded Newton in d with dy/dd = U**2 p, bracketed above by doubling. Solved in the drop, not in p,
        so that a nearly straight path (a fast launch downwards) lands within its own tiny bend. It stops on a step
        below 2**-50 of d, or on a height within 2**-46 of the apex height, the rounding of y = rise - fall: a steep
        landing (a launch far faster than v_t) has dy/dp ~ 1 / |p|, and y's rounding moves d by more than 2**-50 of
        itself."""
        top = max(self.p0, 0.0)  # the apex, p = 0, or the start when launched downwards
        peak = self.height + (self.integrals_to(top)[2] if top > 0 else 0.0)
        if peak <= 0:
            return top
        lo, hi = top, top + 1.0
        while self.height + self.integrals_to(hi)[2] > 0:
            lo, hi = hi, 2.0 * hi + 1.0
        d = 0.5 * (lo + hi)
        for _ in range(200):
            y = self.height + self.integrals_to(d)[2]
            if y > 0:
                lo = d
            else:
                hi = d
            slope = float(self._speed_squared_after(np.array(d))) * (self.p0 - d)
            new = d - y / slope if slope < 0 else 0.5 * (lo + hi)
            if not lo <= new <= hi:
                new = 0.5 * (lo + hi)
            if abs(new - d) <= 2.0**-50 * new or abs(y) <= 2.0**-46 * max(peak, 1.0):
                return new
            d = new
        raise ConvergenceError(f"quadratic-drag landing: no convergence from speed {self.speed!r} v_t, "
                               f"angle {self.angle!r} rad, height {self.height!r} v_t**2 / g")


def _vertical_flight(speed, height):
    """(flight time, apex height, apex time, landing speed) in terminal-speed units for v_x = 0, speed >= 0 up
    or < 0 down: up, t = atan(v0) and rise ln(1 + v0**2) / 2; down from rest through H, t = acosh(e**H) and
    v = sqrt(1 - e**(-2H)); thrown down at v0 < 1 (or > 1), the same with the rest point shifted."""
    if speed >= 0:
        rise_time, rise = math.atan(speed), 0.5 * math.log1p(speed * speed)
        fall = height + rise
        fall_time = math.acosh(math.exp(fall)) if fall < 700 else fall + math.log(2.0)
        return rise_time + fall_time, fall, rise_time, math.sqrt(-math.expm1(-2.0 * fall))
    v0 = -speed
    if v0 < 1:  # as if it had fallen from rest through ln(1 / sqrt(1 - v0**2)) = -ln(1 - v0**2) / 2
        before = -0.5 * math.log1p(-v0 * v0)
        start_time = math.atanh(v0)
        total = before + height
        end_time = math.acosh(math.exp(total)) if total < 700 else total + math.log(2.0)
        # max: from height 0 the two times agree but for rounding (-8.5e-16 measured), a flight of 0
        return max(end_time - start_time, 0.0), height, 0.0, math.sqrt(-math.expm1(-2.0 * total))
    if v0 == 1:
        return height, height, 0.0, 1.0
    # faster than terminal: v = coth(t + c) with coth(c) = v0; y falls by ln(sinh(t + c) / sinh(c))
    c = math.atanh(1.0 / v0)
    target = height + math.log(math.sinh(c))  # ln sinh(t + c) at landing
    s = math.asinh(math.exp(target)) if target < 700 else target + math.log(2.0)
    return s - c, height, 0.0, 1.0 / math.tanh(s)


def quadratic_drag_flight(speed, angle, height, terminal_speed, g):
    """(flight time s, range m, apex height m, apex time s, apex distance m, landing speed m/s, landing angle rad)
    under drag -m g |v| v / v_t**2, launched from height h (m) at `speed` (m/s) and `angle` (rad, in
    (-pi/2, pi/2], measured above the horizontal) (XX.iv). Broadcasts by looping over the launches."""
    arrays = np.broadcast_arrays(*(np.asarray(x, dtype=float) for x in (speed, angle, height, terminal_speed, g)))
    out = np.empty((7,) + arrays[0].shape)
    for index in np.ndindex(arrays[0].shape):
        out[(slice(None),) + index] = _one_quadratic_flight(*(float(a[index]) for a in arrays))
    return tuple(out)


def _one_quadratic_flight(speed, angle, height, terminal_speed, g):
    time_unit, length_unit = terminal_speed / g, terminal_speed**2 / g
    v, h = speed / terminal_speed, height / length_unit
    if math.cos(angle) * v <= 0 or abs(angle) >= 0.5 * math.pi:  # straight up or down
        vertical = v if angle > 0 else -v
        total, apex, apex_time, landing = _vertical_flight(vertical, h)
        return (total * time_unit, 0.0, apex * length_unit, apex_time * time_unit, 0.0, landing * terminal_speed,
                -0.5 * math.pi)
    path = QuadraticDragPath(v, angle, h)
    drop = path.landing_drop()
    p_land = path.p0 - drop
    t, x, _ = path.integrals_to(drop)
    if path.p0 > 0:
        apex_t, apex_x, rise = path.integrals(0.0)
    else:
        apex_t, apex_x, rise = 0.0, 0.0, 0.0
    landing_u = math.sqrt(float(path._speed_squared_after(np.array(drop))))
    return (t * time_unit, x * length_unit, (h + rise) * length_unit, apex_t * time_unit, apex_x * length_unit,
            landing_u * math.hypot(1.0, p_land) * terminal_speed, math.atan(p_land))


def quadratic_drag_state(speed, angle, height, terminal_speed, g, slope):
    """(t s, x m, y m, v_x m/s, v_y m/s) at the point of one quadratic-drag trajectory where the velocity has slope
    p = tan(angle) <= tan(launch angle) (XX.iv); for sampling the path (plots, tests). Scalars only."""
    time_unit, length_unit = terminal_speed / g, terminal_speed**2 / g
    path = QuadraticDragPath(speed / terminal_speed, angle, height / length_unit)
    t, x, rise = path.integrals(slope)
    u = math.sqrt(float(path.horizontal_speed_squared(np.array(slope))))
    return (t * time_unit, x * length_unit, height + rise * length_unit, u * terminal_speed,
            u * slope * terminal_speed)
