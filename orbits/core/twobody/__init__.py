"""Two-body motion on float64 arrays (SI, radians): Kepler's equation for every conic (kepler), anomalies,
elements and vectors (elements), the course's two-body quantities (twobody), propagation (propagate) and the
state-transition matrix (transition), each with its compiled port (_fast_*) and shared constants (_*_shared).
"""
