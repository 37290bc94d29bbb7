"""Constants of the Kepler solvers shared by their NumPy specification (orbits.core.twobody.kepler) and its compiled
port
(orbits.core.twobody._fast_kepler), and by the propagator's twins: both sides import them from here, neither from the
other."""

import math

from orbits.core.series import factorial_series

# 2 pi as an unevaluated sum of three doubles (checked against mpmath in the tests).
TWO_PI_1 = 6.283185307179586
TWO_PI_2 = 2.4492935982947064e-16
TWO_PI_3 = -5.989539619436679e-33
INVERSE_TWO_PI = 1.0 / TWO_PI_1

#: pi = PI_1 + PI_2 to 2**-106
PI_1 = 3.141592653589793
PI_2 = 1.2246467991473532e-16

#: The elliptic single pass certifies E when its Newton step is below this, relative (Markley's starter is within
#: 2.8e-4 = 2**-11.8; the sixth-order step then leaves below 132 (2**-11)**6 < 2**-58).
SINGLE_PASS_ACCEPT = 2.0**-11

#: Bracketed sixth-order steps of the hyperbolic solver's fixed first pass (two certify every pair of the
#: benchmark's set; four Halley steps did, at two more evaluations).
HYPERBOLIC_FIXED_STEPS = 2

#: Largest |M| (rad) reduced exactly: 2**50 revolutions.
MAX_MEAN_ANOMALY = 2.0**50 * TWO_PI_1

#: |x| below which x - sin x and sinh x - x come from their series
SERIES_LIMIT = 2.0
#: H above which the hyperbolic equation is solved in logarithmic form
LOG_FORM_LIMIT = 20.0
#: below this, E = M / (1 - e) and H = M / (e - 1) are exact roots
TINY_MEAN_ANOMALY = 1e-280
#: 1 / (pi**2 - 6), the scale of Markley's alpha
MARKLEY_SCALE = 1.0 / (math.pi**2 - 6.0)

#: x**3 times these series in x**2 are x - sin x and sinh x - x, x**2 times them 1 - cos x and cosh x - 1
#: (14 terms: below 2**-53 relative for |x| < 2)
X_MINUS_SIN = factorial_series(3, -1.0, 14)
SINH_MINUS_X = factorial_series(3, 1.0, 14)
ONE_MINUS_COS = factorial_series(2, -1.0, 14)
COSH_MINUS_ONE = factorial_series(2, 1.0, 14)
