"""What `orbits ... --help` shows, in one place: each command's one-line summary (the command lists), its
description (the command's docstring, its paragraphs reflowed so that the terminal wraps them between words) and
two to four examples that run (tests/cli/test_help_pages.py runs every one and holds each page to 80 columns).

`document(app)` writes these onto every command registered on the Typer app and its sub-apps, before typer
builds them. It imports nothing of the library: `orbits --help` stays fast.
"""

import shlex

import typer
from typer.core import TyperCommand

#: command path -> the line the command lists show
SUMMARY = {
    "validate": "Check the analytic answers against rebound and heyoka.",
    "orbit": "Every quantity of an orbit, from elements, state or body.",
    "kepler": "Every anomaly from the mean or the true one, any conic.",
    "cosmology": "Age, distances, H(z) and a(t) of a Friedmann universe.",
    "binary": "A binary: orbits about the barycentre, K, mass function.",
    "flyby": "Closest approach and deflection of a hyperbolic flyby.",
    "lagrange": "Lagrange points, Jacobi constants and their stability.",
    "periodic": "Halo, Lyapunov, DRO and NRHO orbits, and their families.",
    "ring": "A ring of equal masses: period, stability, break-up.",
    "rocket": "Delta-v and burn times of a rocket, one stage or several.",
    "where": "Where a planet is at a date: distance, elongation, RA, Dec.",
    "lambert": "Lambert's problem: r1 to r2, or body to body on dates.",
    "porkchop": "C3 and arrival v_inf over launch and arrival dates.",
    "collide": "A collision with restitution: velocities and energies.",
    "projectile": "A projectile, without drag or with linear or quadratic drag.",
    "pendulum": "The exact large-amplitude pendulum, or a vertical circle.",
    "info": "Versions, caches and the catalogue of bodies.",
    "escape": "Escape speed, cosmic velocities, synchronous orbits.",
    "escape speed": "Escape speed sqrt(2 G M / r) from a body.",
    "escape cosmic": "The first, second and third cosmic velocities.",
    "escape geo": "The synchronous orbit of a rotating body.",
    "escape elongation": "The greatest elongation of an inner planet.",
    "transfer": "Impulsive transfers: Hohmann, bi-elliptic, phasing, ...",
    "transfer hohmann": "Hohmann transfer between two circular orbits.",
    "transfer bi-elliptic": "Bi-elliptic transfer, compared with Hohmann.",
    "transfer plane-change": "A plane change on a circular orbit.",
    "transfer phasing": "A phasing manoeuvre to meet a target on the same orbit.",
    "transfer departure": "Departure onto a hyperbola from a parking orbit.",
    "transfer assist": "A gravity assist by patched conics.",
    "perturb": "Secular perturbations: J2, drag, Kozai-Lidov, relativity.",
    "perturb rates": "J2's secular rates of node, periapsis and mean anomaly.",
    "perturb sun-synchronous": "The sun-synchronous inclination or size.",
    "perturb frozen": "The frozen orbit of J2 with J3.",
    "perturb repeat": "The repeat-ground-track orbit: k revolutions in d days.",
    "perturb decay": "Drag decay and lifetime of a circular orbit.",
    "perturb kozai": "The Kozai-Lidov cycle of a hierarchical triple.",
    "perturb relativity": "General relativity's periapsis advance.",
    "bench": "Benchmarks: speed and worst error against the peers.",
    "bench kepler": "Kepler solvers against heyoka, rebound and Newton.",
    "bench propagate": "Two-body propagation against heyoka's lagrange_prop.",
    "bench periodic": "Periodic orbits: one halo and a family, corrections counted.",
    "bench api": "The unit-aware API's cost over the float64 core.",
    "bench call": "One call and small batches against heyoka's cfuncs.",
    "bench cli": "Command-line cold start in fresh processes.",
    "bench validate": "Where the time of orbits validate goes.",
    "bench lambert": "Lambert solvers against lamberthub (and pykep, hapsira).",
    "bench ephemeris": "DE421 states against jplephem and astropy.",
    "bench stm": "The state-transition matrix: cost per state and error.",
    "bench all": "Every benchmark in one run.",
    "bench precision": "Each integrator's accuracy knob: error against time.",
}

#: command path -> examples, each "orbits ..." optionally followed by "  # a comment"
EXAMPLES = {
    "validate": [
        "orbits validate",
        "orbits validate circular eccentric --format json",
        "orbits validate lagrange_L4_L5 --backend heyoka --plot check.png",
    ],
    "orbit": [
        "orbits orbit Earth",
        'orbits orbit --primary Earth --a "42164 km" --only period,speed',
        "orbits orbit Ceres --epoch 2026-01-01 --format json",
        'orbits orbit --primary Earth --a "8000 km" --e 0.1 --mass "1000 kg" --at-r "7500 km" --area-between "0 h,1 h"',
    ],
    "kepler": [
        'orbits kepler --e 0.9 --M "0.1 rad"',
        'orbits kepler --e 1.5 --nu "60 deg"',
        "orbits kepler --e 1 --M 2  # a parabola: M is Barker's W",
    ],
    "cosmology": [
        "orbits cosmology",
        'orbits cosmology --H0 "67.66 km/s/Mpc" --Om 0.30966 --z 0.5,1,1100',
        "orbits cosmology --model planck18 --z 1 --plot cosmology.png",
    ],
    "binary": [
        'orbits binary --m1 Sun --m2 Jupiter --a "5.2 AU" --e 0.048',
        'orbits binary --m1 Earth --m2 Moon --a "384399 km" --format json',
        'orbits binary --m1 "1 solMass" --m2 "1 jupiterMass" --period "4.23 d" --inc 90',
        'orbits binary --K "59 m/s" --period "4.2293 d" --m1 "1 solMass"',
    ],
    "flyby": [
        'orbits flyby --primary Jupiter --v-inf "5.6 km/s" --periapsis "200000 km"',
        'orbits flyby --primary Earth --v-inf "3 km/s" --b "30000 km" --plot flyby.png',
    ],
    "lagrange": [
        "orbits lagrange --primary Earth --secondary Moon",
        "orbits lagrange --primary Sun --secondary Earth --points L1,L2 --format json",
        'orbits lagrange --primary "1 solMass" --secondary "0.1 solMass" --separation "1 AU" --plot lagrange.png',
    ],
    "periodic": [
        'orbits periodic --primary Earth --secondary Moon --family halo --point L2 --az "20000 km"',
        "orbits periodic --primary Earth --secondary Moon --family nrho --resonance 9:2",
        'orbits periodic --primary Sun --secondary Earth --family lyapunov --point L1 --ax "200000 km"',
        "orbits periodic --primary Earth --secondary Moon --family nrho --resonance 9:2 --members 12",
    ],
    "ring": [
        'orbits ring 7 --mass "1e20 kg" --radius "1e5 km" --primary Earth',
        'orbits ring 3 --mass "1 kg" --radius "1 m" --format json',
    ],
    "rocket": [
        'orbits rocket --m0 "100 t" --mf "40 t" --isp "300 s" --thrust "2 MN"',
        'orbits rocket --propellant "80 t" --propellant "15 t" --structure "8 t" --structure "2 t" --payload '
        '"1 t" --isp "280 s" --isp "340 s"',
    ],
    "where": [
        "orbits where Mars --epoch 2026-11-25",
        "orbits where Venus --observer Mars --epoch 2027-01-01 --format json",
        "orbits where Jupiter --epoch 2026-11-25 --plot sky.png",
        "orbits where Ceres --epoch 2026-01-01",
    ],
    "lambert": [
        'orbits lambert --r1 "1,0,0 AU" --r2 "0,1.5,0 AU" --tof "200 d"',
        'orbits lambert --r1 "1,0,0 AU" --r2 "0,1.5,0 AU" --tof "900 d" --revolutions 1 --branch left',
        "orbits lambert --from Earth --to Mars --depart 2026-11-26 --arrive 2027-08-15",
    ],
    "porkchop": [
        "orbits porkchop --from EMB --to Mars --step \"5 d\"",
        'orbits porkchop --from Earth --to Mars --depart 2028-09-01:2029-01-31 --arrive '
        '2029-06-01:2030-03-01 --step "10 d" --plot porkchop.png',
    ],
    "collide": [
        'orbits collide --m1 "2 kg" --v1 "3 m/s" --m2 "1 kg" --v2 "0 m/s" --restitution 0.8',
        'orbits collide --m1 "2 kg" --v1 "3 m/s" --m2 "1 kg" --v2 "-1 m/s" --plot collide.png',
    ],
    "projectile": [
        'orbits projectile --speed "20 m/s" --angle 45',
        'orbits projectile --speed "20 m/s" --angle 45 --drag quadratic --terminal-speed "30 m/s"',
    ],
    "pendulum": [
        'orbits pendulum --length "1 m" --amplitude "170 deg"',
        'orbits pendulum --length "1 m" --amplitude "30 deg" --plot pendulum.png',
    ],
    "info": [
        "orbits info",
        "orbits info --format json",
    ],
    "escape speed": [
        "orbits escape speed --primary Moon",
        'orbits escape speed --primary Earth --at-r "384399 km"',
    ],
    "escape cosmic": [
        "orbits escape cosmic",
        "orbits escape cosmic --format json",
    ],
    "escape geo": [
        "orbits escape geo",
        "orbits escape geo --primary Jupiter",
    ],
    "escape elongation": [
        'orbits escape elongation --inner "0.723 AU" --outer Earth',
        "orbits escape elongation --inner Mercury --outer Earth",
    ],
    "transfer hohmann": [
        'orbits transfer hohmann --radius1 "6678 km" --radius2 "42164 km"',
        'orbits transfer hohmann --radius1 "6678 km" --radius2 "42164 km" --inc "28.5 deg"',
        "orbits transfer hohmann --from Earth --to Mars",
    ],
    "transfer bi-elliptic": [
        'orbits transfer bi-elliptic --radius1 "7000 km" --radius2 "105000 km" --apoapsis "210000 km"',
        'orbits transfer bi-elliptic --primary Sun --radius1 "1 AU" --radius2 "30 AU" --apoapsis "60 AU"',
    ],
    "transfer plane-change": [
        'orbits transfer plane-change --radius "7000 km" --inc "30 deg"',
        'orbits transfer plane-change --radius "42164 km" --inc "28.5 deg" --format json',
    ],
    "transfer phasing": [
        'orbits transfer phasing --radius "7000 km" --phase "20 deg" --revolutions 2',
        'orbits transfer phasing --radius "42164 km" --phase "-60 deg"',
    ],
    "transfer departure": [
        'orbits transfer departure --radius "6678 km" --v-inf "3 km/s"',
        'orbits transfer departure --primary Mars --radius "3700 km" --v-inf "2.6 km/s"',
    ],
    "transfer assist": [
        'orbits transfer assist --primary Jupiter --v-in "0,7.4,0 km/s" --v-planet "0,13.06,0 km/s" '
        '--periapsis "200000 km"',
        'orbits transfer assist --primary Venus --v-in "0,30,3 km/s" --v-planet "0,35,0 km/s" --periapsis "7000 km"',
    ],
    "perturb rates": [
        'orbits perturb rates --altitude "400 km" --inc 51.64',
        'orbits perturb rates --primary Mars --a "9378 km" --inc 1.1 --format json',
        "orbits perturb rates --a \"26554 km\" --e 0.74 --inc 63.43 --argp 270 --plot-revolutions 10 --plot "
        "molniya.png  # a Molniya orbit's node and periapsis",
    ],
    "perturb sun-synchronous": [
        'orbits perturb sun-synchronous --altitude "700 km"  # 98.19 deg',
        "orbits perturb sun-synchronous --inc 99",
        'orbits perturb sun-synchronous --altitude "700 km" --plot-revolutions 15 --plot sun-synchronous.png',
    ],
    "perturb frozen": [
        'orbits perturb frozen --altitude "700 km" --inc 98.19',
        'orbits perturb frozen --altitude "1336 km" --inc 66',
        'orbits perturb frozen --altitude "700 km" --inc 98.19 --plot frozen.png  # one apsidal period',
    ],
    "perturb repeat": [
        "orbits perturb repeat --revolutions 127 --days 10 --inc 66.04  # TOPEX/Jason",
        "orbits perturb repeat --revolutions 15 --days 1 --inc 98",
        "orbits perturb repeat --revolutions 29 --days 2 --inc 98 --plot track.png",
    ],
    "perturb decay": [
        'orbits perturb decay --altitude "280 km" --ballistic "0.022 m2/kg"',
        'orbits perturb decay --altitude "400 km" --ballistic "0.005 m2/kg" --plot decay.png',
        'orbits perturb decay --primary Mars --altitude "200 km" --ballistic "0.01 m2/kg" --density "0.020 '
        'kg/m3" --scale-height "11.1 km" --base-altitude "0 km" --plot mars.png  # ends where it sinks H a '
        'revolution',
    ],
    "perturb kozai": [
        'orbits perturb kozai --primary Sun --perturber Jupiter --a "1 AU" --a-out "5.2 AU" --inc 65',
        'orbits perturb kozai --primary Earth --perturber Sun --a "50000 km" --a-out "1 AU" --inc 80',
        'orbits perturb kozai --primary "1 solMass" --perturber "1 solMass" --a "1 AU" --a-out "12 AU" --inc '
        '65 --e 0.01 --plot kozai.png',
    ],
    "perturb relativity": [
        "orbits perturb relativity Mercury  # 42.98 arcsec per century",
        "orbits perturb relativity Earth --format json",
    ],
    "bench kepler": [
        "orbits bench kepler --easy 10000 --hard 1000 --hyperbolic 1000 --reference 100",
        "orbits bench kepler --easy 100000 --repeats 5 --output kepler.json",
    ],
    "bench periodic": [
        "orbits bench periodic --members 10 --repeats 1 --no-numpy",
        "orbits bench periodic --members 20 --repeats 1 --format json",
    ],
    "bench propagate": [
        "orbits bench propagate --states 10000 --reference 50",
        "orbits bench propagate --states 100000 --reference 20 --format json",
    ],
    "bench stm": [
        "orbits bench stm --states 10000 --reference 5",
        "orbits bench stm --states 30000 --reference 5 --output stm.json",
    ],
    "bench api": [
        "orbits bench api --sizes 1,1000",
        "orbits bench api --sizes 1,100000 --repeats 3",
    ],
    "bench call": [
        "orbits bench call --sizes 1,1000 --repeats 3 --no-compile  # the cache as it is",
        "orbits bench call --sizes 1 --repeats 1 --no-compile --format json",
    ],
    "bench cli": [
        "orbits bench cli --runs 1 --no-first-run",
        "orbits bench cli --runs 2 --no-first-run --format json",
    ],
    "bench validate": [
        "orbits bench validate circular eccentric --no-sweep",
        "orbits bench validate binary flyby --no-sweep --format json",
    ],
    "bench lambert": [
        "orbits bench lambert --transfers 10000 --reference 50",
        "orbits bench lambert --transfers 30000 --reference 20 --output lambert.json",
    ],
    "bench ephemeris": [
        "orbits bench ephemeris --epochs 10000",
        "orbits bench ephemeris --epochs 1000 --repeats 5",
    ],
    "bench all": [
        "orbits bench all --quick --only ephemeris,api",
        "orbits bench all --quick --only lambert --output bench.json",
    ],
    "bench precision": [
        "orbits bench precision --quick --problem L4",
        'orbits bench precision --quick --problem "e=0.9" --plot precision.png',
    ],
}


def reflow(text: str) -> str:
    """A docstring's paragraphs each on one line (separated by blank lines), so the terminal wraps between words."""
    paragraphs = [" ".join(p.split()) for p in (text or "").strip().split("\n\n")]
    return "\n\n".join(p for p in paragraphs if p)


#: the longest line of an example on a help page (the page is 80 columns, with a margin each side)
EXAMPLE_WIDTH = 76


def example_lines(example: str) -> list[str]:
    """An example broken into lines of at most EXAMPLE_WIDTH characters that a shell reads as one command: each
    line but the last ends with " \\", a break falls only between an option and the next one (never inside a
    quoted value), and a "  # comment" stays on the last line when it fits, else on a line of its own."""
    command, _, comment = example.partition("  # ")
    lexer = shlex.shlex(command, posix=False)
    lexer.whitespace_split = True
    words = list(lexer)
    groups = []
    for word in words:
        if groups and not word.startswith("--") and groups[-1][0].startswith("--") and len(groups[-1]) == 1:
            groups[-1].append(word)
        else:
            groups.append([word])
    lines, line = [], ""
    for group in (" ".join(g) for g in groups):
        if line and len(line) + 1 + len(group) + 2 > EXAMPLE_WIDTH:
            lines.append(line + " \\")
            line = "    " + group
        else:
            line = f"{line} {group}" if line else group
    if comment and len(line) + 4 + len(comment) > EXAMPLE_WIDTH:
        return [*lines, line, f"# {comment}"]
    return [*lines, line + (f"  # {comment}" if comment else "")]


def epilog(path: str) -> str:
    """The examples of a command as its help page's last lines, each broken to fit (example_lines)."""
    return "Examples:\n" + "\n".join(f"  {line}" for example in EXAMPLES[path] for line in example_lines(example))


class ListsScenes(TyperCommand):
    """A command whose help page lists the built-in scenes before its examples, read when the page is shown (so
    that no other command loads the validation layer)."""

    @property
    def epilog(self) -> str:
        from orbits._common.display import filled
        from orbits.validate import summaries

        scenes = "\n".join(filled(f"{name}: {line}", 76, initial_indent="  ", subsequent_indent="      ")
                           for name, line in summaries().items())
        return f"Built-in scenes (give their names, or none for all):\n{scenes}\n\n{self._examples}"

    @epilog.setter
    def epilog(self, value: str) -> None:
        self._examples = value


#: the panels of `orbits --help`: each subject's verbs together, in the order of the house's subjects
SUBJECTS = {
    "Two-body orbits": ("orbit", "kepler"),
    "Binaries, flybys, escape": ("binary", "flyby", "escape"),
    "Three bodies": ("lagrange", "ring", "periodic"),
    "Manoeuvres": ("transfer", "rocket", "lambert", "porkchop"),
    "Perturbed orbits": ("perturb",),
    "The solar system": ("where",),
    "Cosmology": ("cosmology",),
    "The course's mechanics": ("collide", "projectile", "pendulum"),
    "Checks and facts": ("validate", "bench", "info"),
}
_PANEL = {verb: panel for panel, verbs in SUBJECTS.items() for verb in verbs}

#: commands whose help pages need more than their examples
CLASSES = {"validate": ListsScenes}


def document(app: typer.Typer, prefix: str = "") -> None:
    """Give every command of `app` (and of its sub-apps) its summary, reflowed description and examples."""
    for info in app.registered_commands:
        path = f"{prefix}{info.name}"
        info.help = reflow(info.help or info.callback.__doc__)
        info.short_help = SUMMARY.get(path, info.help.split(". ")[0])
        if path in EXAMPLES:
            info.epilog = epilog(path)
        if path in CLASSES:
            info.cls = CLASSES[path]
        if not prefix:
            info.rich_help_panel = _PANEL[path]
    for group in app.registered_groups:
        path = f"{prefix}{group.name}"
        group.short_help = SUMMARY.get(path, group.short_help)
        if not prefix:
            group.rich_help_panel = _PANEL[path]
        document(group.typer_instance, f"{path} ")
