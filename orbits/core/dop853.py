"""An explicit Runge-Kutta integrator of order 8: Dormand and Prince's DOP853, with its 5th- and 3rd-order error
estimates (Hairer, Norsett and Wanner, Solving Ordinary Differential Equations I, 2nd ed., 1993, section II.10).

It integrates y' = f(y) (autonomous) from t = 0 to t_end, landing exactly on requested output times and on t_end
(a step that would pass one is shortened to end on it). The local error of each step is estimated on the first
`controlled` components only, in the scaled RMS norm of the method (err5**2 / sqrt(err5**2 + 0.01 err3**2)) with
scale atol + rtol max(|y|, |y_new|); a step is accepted when that norm is at most 1 and the next step is
h * min(10, max(0.2, 0.9 norm**(-1/8))). Error control on the state alone makes a trajectory the same whether or
not its state transition matrix rides along, so a corrector's residual does not depend on whether it asks for
derivatives. The default tolerance, rtol = atol = 100 eps (2.2e-14), is the tightest this method honours in float64
(tests/core/test_periodic_core.py measures the global error of an orbit and of a Kepler ellipse against mpmath).

The coefficients are those of the published method (A, B and the error weights E5 and E3), to 30 digits; the
system being autonomous, the nodes c_i are not needed. The compiled port (orbits/core/_fast_cr3bp.py) reads them here.
"""

import math
from dataclasses import dataclass

import numpy as np

from orbits.core.errors import ConvergenceError, OrbitDomainError

#: the tightest relative and absolute tolerance of the method in float64: 100 machine epsilons
RTOL = 100.0 * np.finfo(float).eps
ATOL = RTOL
#: a trajectory needing more steps than this is stopped (a collision, or a request far beyond the orbit's scale)
MAX_STEPS = 200_000
#: a step shorter than this fraction of the elapsed time cannot be taken in float64 arithmetic
SMALLEST_STEP = 1e-13

#: the stage coefficients a_ij (row i: stage i from stages 0 .. i - 1)
A = np.zeros((12, 12))
A[1, 0] = 5.26001519587677318785587544488e-2
A[2, :2] = [1.97250569845378994544595329183e-2, 5.91751709536136983633785987549e-2]
A[3, [0, 2]] = [2.95875854768068491816892993775e-2, 8.87627564304205475450678981324e-2]
A[4, [0, 2, 3]] = [2.41365134159266685502369798665e-1, -8.84549479328286085344864962717e-1,
                   9.24834003261792003115737966543e-1]
A[5, [0, 3, 4]] = [3.7037037037037037037037037037e-2, 1.70828608729473871279604482173e-1,
                   1.25467687566822425016691814123e-1]
A[6, [0, 3, 4, 5]] = [3.7109375e-2, 1.70252211019544039314978060272e-1, 6.02165389804559606850219397283e-2,
                      -1.7578125e-2]
A[7, [0, 3, 4, 5, 6]] = [3.70920001185047927108779319836e-2, 1.70383925712239993810214054705e-1,
                         1.07262030446373284651809199168e-1, -1.53194377486244017527936158236e-2,
                         8.27378916381402288758473766002e-3]
A[8, [0, 3, 4, 5, 6, 7]] = [6.24110958716075717114429577812e-1, -3.36089262944694129406857109825,
                            -8.68219346841726006818189891453e-1, 2.75920996994467083049415600797e1,
                            2.01540675504778934086186788979e1, -4.34898841810699588477366255144e1]
A[9, [0, 3, 4, 5, 6, 7, 8]] = [4.77662536438264365890433908527e-1, -2.48811461997166764192642586468,
                               -5.90290826836842996371446475743e-1, 2.12300514481811942347288949897e1,
                               1.52792336328824235832596922938e1, -3.32882109689848629194453265587e1,
                               -2.03312017085086261358222928593e-2]
A[10, [0, 3, 4, 5, 6, 7, 8, 9]] = [-9.3714243008598732571704021658e-1, 5.18637242884406370830023853209,
                                   1.09143734899672957818500254654, -8.14978701074692612513997267357,
                                   -1.85200656599969598641566180701e1, 2.27394870993505042818970056734e1,
                                   2.49360555267965238987089396762, -3.0467644718982195003823669022]
A[11, [0, 3, 4, 5, 6, 7, 8, 9, 10]] = [2.27331014751653820792359768449, -1.05344954667372501984066689879e1,
                                       -2.00087205822486249909675718444, -1.79589318631187989172765950534e1,
                                       2.79488845294199600508499808837e1, -2.85899827713502369474065508674,
                                       -8.87285693353062954433549289258, 1.23605671757943030647266201528e1,
                                       6.43392746015763530355970484046e-1]
#: the weights b_j of the 8th-order solution
B = np.zeros(12)
B[[0, 5, 6, 7, 8, 9, 10, 11]] = [5.42937341165687622380535766363e-2, 4.45031289275240888144113950566,
                                 1.89151789931450038304281599044, -5.8012039600105847814672114227,
                                 3.1116436695781989440891606237e-1, -1.52160949662516078556178806805e-1,
                                 2.01365400804030348374776537501e-1, 4.47106157277725905176885569043e-2]
#: the weights of the 3rd- and 5th-order error estimates
E3 = B.copy()
E3[[0, 8, 11]] -= [0.244094488188976377952755905512, 0.733846688281611857341361741547,
                   0.220588235294117647058823529412e-1]
E5 = np.zeros(12)
E5[[0, 5, 6, 7, 8, 9, 10, 11]] = [0.1312004499419488073250102996e-1, -0.1225156446376204440720569753e+1,
                                  -0.4957589496572501915214079952, 0.1664377182454986536961530415e+1,
                                  -0.3503288487499736816886487290, 0.3341791187130174790297318841,
                                  0.8192320648511571246570742613e-1, -0.2235530786388629525884427845e-1]
ORDER = 8
SAFETY, SHRINK, GROW = 0.9, 0.2, 10.0


@dataclass(frozen=True, eq=False)
class Arc:
    """An integrated trajectory: `end` = y(t_end), `states` (K, n) at the requested output times (None if none were
    asked), and what it cost: accepted `steps`, `rejected` steps and right-hand-side `evaluations`."""

    end: np.ndarray
    states: np.ndarray | None
    steps: int
    rejected: int
    evaluations: int


def integrate(f, y0, t_end: float, outputs=None, rtol: float = RTOL, atol: float = ATOL,
              controlled: int | None = None) -> Arc:
    """Integrate y' = f(y) from y(0) = y0 to t_end (either sign), landing on each of `outputs` (times between 0 and
    t_end, in the direction of integration, non-decreasing) and on t_end; the first `controlled` components of y
    (all by default) set the step sizes.

    Raises ConvergenceError when the steps shrink below 1e-13 of the elapsed time or exceed MAX_STEPS (the
    trajectory runs into a singularity, such as a primary)."""
    y = np.array(y0, dtype=float)
    t_end = float(t_end)
    direction = 1.0 if t_end >= 0.0 else -1.0
    marks = output_marks(outputs, t_end)
    n = y.size if controlled is None else int(controlled)
    states = np.empty((len(marks), y.size)) if outputs is not None else None
    stages = np.empty((12, y.size))
    stages[0] = f(y)
    evaluations = 1
    h = direction * _first_step(f, y, stages[0], n, abs(t_end), rtol, atol)
    evaluations += 1
    t, steps, rejected, k = 0.0, 0, 0, 0
    while k < len(marks) and marks[k] * direction <= 0.0:  # outputs at t = 0
        states[k] = y
        k += 1
    targets = np.concatenate([marks[k:], [t_end]]) if outputs is not None else np.array([t_end])
    for target in targets:
        while (target - t) * direction > 0.0:
            if steps + rejected >= MAX_STEPS:
                raise ConvergenceError(stop_message(True, t_end))
            landing = (t + h - target) * direction >= 0.0
            step = target - t if landing else h
            y_new, norm = _step(f, y, step, stages, n, rtol, atol)
            evaluations += 11
            factor = SAFETY * norm ** (-1.0 / ORDER) if norm > 0.0 else GROW
            if norm <= 1.0:
                t = target if landing else t + step
                y = y_new
                stages[0] = f(y)
                evaluations += 1
                steps += 1
                if not landing or abs(step) >= abs(h):
                    h = step * min(GROW, max(SHRINK, factor))
            else:
                rejected += 1
                h = step * max(SHRINK, factor)
                if abs(h) < SMALLEST_STEP * max(abs(t), 1.0):
                    raise ConvergenceError(stop_message(False, t_end))
        if outputs is not None and k < len(marks):
            states[k] = y
            k += 1
    return Arc(y, states, steps, rejected, evaluations)


def output_marks(outputs, t_end: float) -> np.ndarray:
    """The requested output times as a float array, checked to run monotonically from 0 towards t_end."""
    direction = 1.0 if t_end >= 0.0 else -1.0
    if outputs is None:
        return np.zeros(0)
    marks = np.asarray(outputs, dtype=float).ravel()
    if marks.size and (np.any(np.diff(marks) * direction < 0.0) or marks[0] * direction < 0.0
                       or (marks[-1] - t_end) * direction > 0.0):
        raise OrbitDomainError(f"output times must run monotonically from 0 to t_end = {t_end:.6g}; got "
                               f"{marks[0]:.6g} ... {marks[-1]:.6g}")
    return marks


def stop_message(too_many_steps: bool, t_end: float) -> str:
    """Why an integration towards t_end stopped early (a ConvergenceError's message)."""
    if too_many_steps:
        return (f"the integration to t = {t_end:.6g} took more than {MAX_STEPS} steps: the trajectory runs into a "
                f"singularity (a primary)")
    return f"the step size of the integration to t = {t_end:.6g} fell below float64's reach: the trajectory runs " \
           f"into a singularity (a primary)"


def _step(f, y, h, stages, n, rtol, atol):
    """One DOP853 step of size h from y (stages[0] = f(y)): (y_new, scaled error norm); the norm is inf when a stage
    lands on or next to a singularity (a non-finite value, or one beyond float64), so that the step is retried
    shorter."""
    try:
        with np.errstate(over="raise", invalid="raise", divide="raise"):
            for s in range(1, 12):
                stages[s] = f(y + h * (A[s, :s] @ stages[:s]))
            y_new = y + h * (B @ stages)
            scale = atol + rtol * np.maximum(np.abs(y[:n]), np.abs(y_new[:n]))
            err5 = (E5 @ stages[:, :n]) / scale
            err3 = (E3 @ stages[:, :n]) / scale
            e5, e3 = float(err5 @ err5), float(err3 @ err3)
    except (ArithmeticError, FloatingPointError):
        return y, math.inf
    if not (math.isfinite(e5) and math.isfinite(e3)):
        return y, math.inf
    if e5 == 0.0 and e3 == 0.0:
        return y_new, 0.0
    return y_new, abs(h) * e5 / math.sqrt((e5 + 0.01 * e3) * n)


def _first_step(f, y, f0, n, span, rtol, atol):
    """Starting step from the scaled sizes of y, y' and y'' (Hairer, Norsett and Wanner, II.4), at most the span."""
    scale = atol + rtol * np.abs(y[:n])
    d0 = np.sqrt(np.mean((y[:n] / scale) ** 2))
    d1 = np.sqrt(np.mean((f0[:n] / scale) ** 2))
    h0 = 1e-6 if d0 < 1e-5 or d1 < 1e-5 else 0.01 * d0 / d1
    h0 = min(h0, span) if span > 0.0 else h0
    f1 = f(y + h0 * f0)
    d2 = np.sqrt(np.mean(((f1[:n] - f0[:n]) / scale) ** 2)) / h0
    h1 = max(1e-6, h0 * 1e-3) if max(d1, d2) <= 1e-15 else (0.01 / max(d1, d2)) ** (1.0 / (ORDER + 1))
    return min(100.0 * h0, h1, span) if span > 0.0 else min(100.0 * h0, h1)
