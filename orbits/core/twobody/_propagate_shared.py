"""Constants of the two-body propagator shared by its NumPy specification (orbits.core.twobody.propagate) and its
compiled
port (orbits.core.twobody._fast_propagate): both import them from here, neither from the other."""

from orbits.core.series import factorial_series

#: c_k(z) = sum_j (-z)**j / (2j + k)! for k = 2, 3, to 12 terms (|z| <= 1)
C2_SERIES, C3_SERIES = factorial_series(2, -1.0, 12), factorial_series(3, -1.0, 12)

#: Below this s = sqrt(|z|), s - sin s and sinh s - s come from their series s**3 P(z) (they cancel above 1/2).
SERIES_LIMIT = 2.0

#: Halley steps of pass 1 (then certified): the starter needs 2.5-3 on average and at most 5 on the benchmark's
#: mixed states.
FIXED_STEPS = 5

#: Sixth-order steps of the hyperbolic pass (the first from the starter's own evaluation), then a Newton step and the
#: certificate.
HYPERBOLIC_STEPS = 2

#: The elliptic pass starts from the local starter where its estimated Newton step is below this, else from
#: Markley's.
LOCAL_STARTER_STEP = 1e-5

#: Doublings of hi = tau / r0 that pass 2 may take to bracket the root (F grows at least linearly in chi).
BRACKET_DOUBLINGS = 2100

#: The elliptic pass certifies x when the Newton step d is below 2**-26 x and its own error, |F''| d**2 / (2 F'),
#: below 2**-56 x.
ELLIPTIC_STEP, ELLIPTIC_ERROR = 2.0**-26, 2.0**-55

#: The bracket [m - 2 e, m + 2 e] of x, widened for the rounding of e.
BRACKET_WIDTH = 2.0 * (1.0 + 2.0**-20)

#: Smallest n**2 (1/s**2) the elliptic pass takes: below it (a ~ 1e96 m about the Sun) n**2 nears the subnormal
#: range, and such states go to the universal passes.
SMALLEST_MEAN_MOTION_SQUARED = 1e-280

#: c_k(z) for k = 4, 5 from their series (12 terms, below 1e-20 relative) for |z| <= C45_SERIES_LIMIT, from
#: c_k = (1 / k! - c_(k-2)) / z beyond, which there cancels by less than 2 bits (the state-transition matrix).
C4_SERIES, C5_SERIES = factorial_series(4, -1.0, 12), factorial_series(5, -1.0, 12)
C45_SERIES_LIMIT = 4.0
