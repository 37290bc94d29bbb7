"""Constants of Lambert's solver shared by its NumPy specification (orbits.core.manoeuvres.lambert) and its compiled
port
(orbits.core.manoeuvres._fast_lambert): both import them from here, neither from the other."""

from orbits.core.series import factorial_series

#: Householder iterations allowed (Izzo's starts need 2-4; the bracket's bisections a few more)
MAX_ITERATIONS = 40
#: a step below this (relative to max(1, |x|)) ends the iteration: the root is then known to far below an ulp
STEP_TOLERANCE = 2.0**-40
#: for N = 0 a step below this already ends it: the fourth-order step leaves an error ~ step**4 (1e-28), and even
#: the first-order convergence of the derivatives' Taylor zone (relative error < 1e-9) leaves < 1e-16
ZERO_REVOLUTION_TOLERANCE = 1e-7
#: within this distance of the parabola x = 1 the derivatives come from their Taylor series at x = 1
PARABOLA_ZONE = 1e-3
#: below this relative excess over T_min(N) the iteration starts from the quadratic model of T at x_min
NEAR_MINIMUM = 0.1
#: a time of flight this close (relative) below T_min(N) counts as T_min: the rounding of T_min itself
AT_MINIMUM = 16 * 2.0**-52
#: (z - sin z) / z**3 and (sinh z - z) / z**3 in powers of z**2, to z**22 (the first term left out is
#: 2**24 / 27! < 1.5e-21 of the sum for z < 2)
C3_ELLIPSE = factorial_series(3, -1.0, 12)
C3_HYPERBOLA = factorial_series(3, 1.0, 12)
#: below this angle C(z) comes from its series, above it from (z -+ sin z) / z**3 (no cancellation there)
SERIES_LIMIT = 2.0
