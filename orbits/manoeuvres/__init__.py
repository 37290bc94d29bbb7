"""Getting from one orbit to another, with astropy units: the rocket equation and staging (`rocket`), impulsive
transfers about one primary (`impulsive`: Hohmann, bi-elliptic, plane changes, phasing, a hyperbolic departure),
gravity assists (`assist`), Lambert's problem (`lambert`) and grids of Lambert transfers between two bodies of the
solar system (`porkchop`).

Nothing is imported here: each public name is reached through the `orbits` package or its own module, so using
one of them loads only what it needs.
"""
