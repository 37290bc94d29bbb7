"""Flights built to be hard for the two-body solvers: grazing the focus, or starting nearly radial (mu = 1)."""

import numpy as np

from orbits.core.twobody.elements import elements_to_state


def grazing_flight(rng):
    """A flight from |r0| = 1 (mu = 1) inbound on a near-parabolic ellipse or a hyperbola whose periapsis lies 1e-7
    to 0.1 from the focus, to 0.9-1.5 times the time to periapsis, or (half of them) a short way along the nearly
    radial inbound leg."""
    e = rng.choice([1 + 10 ** rng.uniform(-3, 1), 1 - 10 ** rng.uniform(-4, -0.3)])
    p = 10 ** rng.uniform(-7, -1) * (1 + e)
    nu = -np.arccos(np.clip((p - 1) / e, -1.0, 1.0))
    r0, v0 = elements_to_state(p, e, rng.uniform(0, np.pi), rng.uniform(0, 2 * np.pi), rng.uniform(0, 2 * np.pi),
                               nu, 1.0)
    if e < 1:
        anomaly = 2 * np.arctan(np.sqrt((1 - e) / (1 + e)) * np.tan(nu / 2))
        mean, a = anomaly - e * np.sin(anomaly), p / (1 - e * e)
    else:
        anomaly = 2 * np.arctanh(np.sqrt((e - 1) / (e + 1)) * np.tan(nu / 2))
        mean, a = e * np.sinh(anomaly) - anomaly, p / (e * e - 1)
    dt = -mean * a**1.5 * rng.uniform(0.9, 1.5)
    return r0, v0, dt * (rng.uniform(0.001, 0.5) if rng.random() < 0.5 else 1.0)
