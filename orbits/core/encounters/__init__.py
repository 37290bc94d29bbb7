"""Two bodies meeting or bound, on float64 arrays (SI, radians): binaries, flybys and escape.
"""
