"""The command line's words: one option per idea across every verb, and the spellings it no longer takes.

VOCABULARY is the one list of option words with the idea each names; a verb's option is one of them
(tests/cli/test_vocabulary.py walks the click tree and holds every verb to it). The ideas that recur:

- the central body (the one orbited, or flown past) is ``--primary``; a second body of a pair is
  ``--secondary``; the distant body of a hierarchical triple is ``--perturber``; two bodies of equal standing
  are ``--m1`` and ``--m2``; a single body's own mass is ``--mass``;
- a date is ``--epoch``; a transfer leaves ``--from`` a body on ``--depart`` and reaches ``--to`` a body on
  ``--arrive`` (one date, or START:END for a grid);
- ``--r``, ``--r1``, ``--r2`` are position vectors ('X,Y,Z UNIT'); a circle's radius (a circular orbit, a ring)
  is ``--radius`` (``--radius1``, ``--radius2`` for the two orbits of a transfer); the distance between two bodies
  is ``--separation``; a body's own radius is ``--body-radius``; a distance from the centre where a speed is
  asked is ``--at-r``;
- ``--revolutions`` counts the complete revolutions of the orbit asked for; the revolutions a picture integrates
  are ``--plot-revolutions``.

RETIRED maps a verb's former spelling to its word now; RETIRED_ARGUMENTS names the verbs whose bodies were
positional and are options now. Both are refused with a one-line hint before anything is parsed (no work is done).
"""

#: option -> the idea it names, the same on every verb that takes it
VOCABULARY = {
    # bodies and masses
    "--primary": "the central body: a name, a mass or a GM",
    "--secondary": "the second body of a pair",
    "--perturber": "the distant third body of a hierarchical triple",
    "--m1": "the first of two bodies of equal standing",
    "--m2": "the second of two bodies of equal standing",
    "--mass": "a body's own mass",
    "--m0": "a rocket's initial (wet) mass",
    "--mf": "a rocket's final (dry) mass",
    "--propellant": "a stage's propellant mass",
    "--structure": "a stage's structural mass",
    "--payload": "a rocket's payload mass",
    # dates and places in the solar system
    "--epoch": "the date of a state",
    "--from": "the body a transfer leaves",
    "--to": "the body a transfer reaches",
    "--depart": "the departure date (or START:END)",
    "--arrive": "the arrival date (or START:END)",
    "--step": "the spacing of a date grid",
    "--ephemeris": "where the planets' positions come from",
    "--observer": "the body a position is seen from",
    # distances and vectors
    "--r": "a position vector",
    "--r1": "the departure position vector",
    "--r2": "the arrival position vector",
    "--v": "a velocity vector",
    "--v1": "the velocity of body 1",
    "--v2": "the velocity of body 2",
    "--radius": "the radius of a circle: a circular orbit or a ring",
    "--radius1": "the radius of a transfer's first circular orbit",
    "--radius2": "the radius of a transfer's second circular orbit",
    "--apoapsis": "the common apoapsis of a bi-elliptic transfer",
    "--separation": "the distance between two bodies",
    "--body-radius": "a body's own radius",
    "--at-r": "a distance from the centre where a speed is asked",
    "--inner": "the inner orbit of two, by its radius or its body",
    "--outer": "the outer (observer's) orbit of two, by its radius or its body",
    "--distance": "the distance of a binary from the observer",
    "--altitude": "a height above the body's equator",
    "--height": "a launch height above the ground",
    "--length": "a pendulum's length",
    # conic elements
    "--a": "semi-major axis",
    "--p": "semi-latus rectum",
    "--q": "periapsis distance",
    "--e": "eccentricity",
    "--inc": "inclination, or a turn of the orbit plane",
    "--raan": "longitude of the ascending node",
    "--argp": "argument of periapsis",
    "--nu": "true anomaly",
    "--M": "mean anomaly",
    "--a-out": "the perturber's semi-major axis",
    "--e-out": "the perturber's eccentricity",
    "--period": "an orbital period",
    "--rotation-period": "a body's sidereal rotation period",
    # encounters and manoeuvres
    "--v-inf": "the speed at infinity",
    "--b": "the impact parameter",
    "--periapsis": "the closest approach of a flyby",
    "--v-in": "a probe's velocity before an assist",
    "--v-planet": "the planet's velocity at an assist",
    "--normal": "the normal of the orbit plane",
    "--line-of-impact": "the line along which two bodies collide",
    "--restitution": "the coefficient of restitution",
    "--tof": "a time of flight",
    "--revolutions": "complete revolutions of the orbit asked for",
    "--plot-revolutions": "the revolutions a picture integrates",
    "--branch": "which of two solutions",
    "--retrograde": "clockwise motion",
    "--phase": "how far a target leads",
    "--isp": "specific impulse",
    "--exhaust-speed": "exhaust speed",
    "--thrust": "thrust",
    "--g": "the local acceleration of gravity",
    "--orbital-speed": "a body's circular speed about the Sun",
    "--K": "a measured radial-velocity semi-amplitude",
    "--gamma": "the systemic radial velocity",
    "--sky": "the picture of the apparent orbit",
    "--rv": "the picture of the radial-velocity curves",
    "--area-between": "two times bounding a swept area",
    # three bodies
    "--points": "which Lagrange points",
    "--family": "a family of periodic orbits",
    "--point": "the Lagrange point a family is about",
    "--ax": "an x amplitude",
    "--ay": "a y amplitude",
    "--az": "a z amplitude",
    "--jacobi": "a Jacobi constant",
    "--closest-approach": "a periodic orbit's least distance from the secondary",
    "--resonance": "a synodic resonance p:q",
    "--members": "how many members of a family",
    "--spacing": "how a family's members are spread",
    # perturbations
    "--days": "days in a repeat cycle",
    "--ballistic": "the ballistic coefficient C_D A / m",
    "--density": "an air density",
    "--scale-height": "an atmosphere band's scale height",
    "--base-altitude": "an atmosphere band's base altitude",
    "--cycles": "how many Kozai-Lidov cycles",
    # the course's mechanics
    "--speed": "a launch speed",
    "--angle": "a launch angle above the horizontal",
    "--drag": "a drag law",
    "--rate": "a linear drag rate",
    "--terminal-speed": "a terminal speed",
    "--drag-coefficient": "a drag coefficient",
    "--area": "a cross-section",
    "--amplitude": "a release angle",
    "--bottom-speed": "the speed at the lowest point",
    "--rod": "a rigid rod instead of a string",
    # cosmology
    "--model": "a named universe",
    "--H0": "the Hubble constant",
    "--Om": "the matter density parameter",
    "--Ol": "the cosmological-constant density parameter",
    "--Or": "the radiation density parameter",
    "--Ok": "the curvature parameter",
    "--z": "a redshift",
    "--t": "a time since the big bang",
    # what is shown, and where it goes
    "--only": "which quantities to show",
    "--format": "table or JSON",
    "--units": "natural or SI display units",
    "--unit": "one quantity's display unit",
    "--digits": "significant digits shown",
    "--plot": "a picture file",
    "--output": "a JSON file",
    "--quiet": "the summary alone",
    "--sources": "the source of every constant",
    # validation and benchmarks
    "--backend": "which integrators check a scene",
    "--sweep": "scenes run as dask tasks",
    "--scheduler": "a dask scheduler",
    "--easy": "elements of the easy Kepler set",
    "--hard": "elements of the hard Kepler set",
    "--hyperbolic": "elements of the hyperbolic Kepler set",
    "--reference": "elements checked against mpmath",
    "--repeats": "timing repeats",
    "--states": "states per benchmark",
    "--numpy": "the NumPy path as well",
    "--sizes": "batch sizes",
    "--runs": "command runs",
    "--first-run": "a first run on an empty cache",
    "--compile": "the compiled kernels the cache lacks, compiled first",
    "--transfers": "Lambert transfers per benchmark",
    "--epochs": "epochs per benchmark",
    "--quick": "a shorter run",
    "--problem": "which problems",
    "--target": "a target accuracy",
    "--version": "the version",
}

#: (verb, former spelling) -> the word now
RETIRED = {
    ("lagrange", "--r"): "--separation",
    ("periodic", "--r"): "--separation",
    ("ring", "--m"): "--mass",
    ("ring", "--r"): "--radius",
    ("ring", "--central-mass"): "--primary",
    ("escape speed", "--distance"): "--at-r",
    ("escape cosmic", "--radius"): "--body-radius",
    ("escape geo", "--radius"): "--body-radius",
    ("escape geo", "--period"): "--rotation-period",
    ("porkchop", "--launch"): "--depart",
    ("porkchop", "--arrival"): "--arrive",
    ("transfer hohmann", "--r1"): "--radius1",
    ("transfer hohmann", "--r2"): "--radius2",
    ("transfer bi-elliptic", "--r1"): "--radius1",
    ("transfer bi-elliptic", "--r2"): "--radius2",
    ("transfer bi-elliptic", "--rb"): "--apoapsis",
    ("transfer plane-change", "--r"): "--radius",
    ("transfer plane-change", "--angle"): "--inc",
    ("transfer phasing", "--r"): "--radius",
    ("transfer departure", "--r"): "--radius",
    ("transfer assist", "--planet"): "--primary",
    ("perturb rates", "--revolutions"): "--plot-revolutions",
    ("perturb sun-synchronous", "--revolutions"): "--plot-revolutions",
    ("perturb frozen", "--revolutions"): "--plot-revolutions",
    ("perturb kozai", "--m0"): "--primary",
    ("perturb kozai", "--m3"): "--perturber",
    ("collide", "--normal"): "--line-of-impact",
}

#: verb -> the options its former positional bodies became, in their order
RETIRED_ARGUMENTS = {
    "lagrange": ("--primary", "--secondary"),
    "periodic": ("--primary", "--secondary"),
    "escape speed": ("--primary",),
    "escape cosmic": ("--primary",),
    "escape geo": ("--primary",),
    "perturb rates": ("--primary",),
    "perturb sun-synchronous": ("--primary",),
    "perturb frozen": ("--primary",),
    "perturb repeat": ("--primary",),
    "perturb decay": ("--primary",),
}


def retired_word(verb: str, words: list[str]) -> str | None:
    """The one-line hint for the first former spelling among `words` (what follows the verb), or None.

    >>> retired_word("lagrange", ["Earth", "Moon"])
    'orbits lagrange takes its bodies as options now: --primary Earth --secondary Moon'
    >>> retired_word("porkchop", ["--launch", "2026-09-01:2026-12-01"])
    'orbits porkchop: --launch is now --depart'
    """
    options = RETIRED_ARGUMENTS.get(verb, ())
    bare = []
    for word in words:
        if word.startswith("-") or len(bare) == len(options):
            break
        bare.append(word)
    if bare:
        given = " ".join(f"{option} {_quoted(word)}" for option, word in zip(options, bare))
        return f"orbits {verb} takes its bodies as options now: {given}"
    for word in words:
        if word == "--":
            break
        spelling = word.partition("=")[0]
        if (verb, spelling) in RETIRED:
            return f"orbits {verb}: {spelling} is now {RETIRED[verb, spelling]}"
    return None


def _quoted(word: str) -> str:
    return f"'{word}'" if " " in word else word
