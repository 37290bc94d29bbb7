"""Every exception orbits raises on purpose, in one module at the bottom of the house.

The numeric core raises them, so they live in the core and import nothing; the unit-aware library, the
scene loader, the validation layer and the command line all raise these same types. Every message names
the quantity, its value, the allowed range and the unit.
"""


class OrbitsError(Exception):
    """Base class of every error orbits raises on purpose."""


class OrbitDomainError(OrbitsError, ValueError):
    """A value lies outside the range where the requested quantity is defined (the input rules' error)."""


class DegenerateOrbitError(OrbitDomainError):
    """The orbit has no well-defined plane or orientation (radial orbit, h = 0)."""


class ConvergenceError(OrbitsError, RuntimeError):
    """An iterative solver hit its iteration cap; the message carries the inputs and last iterate."""


class SceneError(OrbitsError, ValueError):
    """A scene file or dictionary is invalid; the message names the source, the field and what is allowed."""


class OutputError(OrbitsError, OSError):
    """A file could not be written (a full disk, a folder where no file can be made); the message names the file and
    the system's reason, in one line."""


class ParameterError(OrbitsError, ValueError):
    """A model scene's parameter, or a combination of them (`name` None), that the model cannot run."""

    def __init__(self, name: str | None, message: str):
        super().__init__(message)
        self.name = name


class UnknownNameError(OrbitDomainError, KeyError):
    """A name (a body, a quantity, a Lagrange point) that is not one of those known; the message lists them.

    It is a KeyError too, so that code looking names up the dictionary way catches it."""

    def __str__(self) -> str:
        return str(self.args[0]) if self.args else ""

    @classmethod
    def among(cls, what: str, name: object, known: "list[str]", note: str = "") -> "UnknownNameError":
        """The error for `name`, which is not among `known`: "unknown body 'Marz'; did you mean Mars?" when some
        names are close (the line stays short), else every known name."""
        import difflib

        close = difflib.get_close_matches(str(name).strip().lower(), [k.lower() for k in known], n=3, cutoff=0.6)
        if close:
            return cls(f"{what} {name!r}{note}; did you mean {' or '.join(k for k in known if k.lower() in close)}?")
        return cls(f"{what} {name!r}{note}; known: {', '.join(known)}")


class OrbitsWarning(UserWarning):
    """Base class of the warnings orbits gives on purpose: the answer stands, but something about it needs saying
    (a picture whose closest approach lies inside a body). The command line prints each as one line."""


class InsideBodyWarning(OrbitsWarning):
    """A closest approach lies inside a catalogue body (or inside both bodies' radii, for two bodies meeting): the
    orbit passes through the body, or the two collide. The two-body answer is still computed."""


class IllConditionedWarning(OrbitsWarning):
    """The answer is computed, but rounding moves it so far that few of its digits mean anything: the message says
    by how much (past ILL_CONDITIONED, a relative 1e-8: fewer than eight digits)."""


#: the relative error, or shift under rounding, past which an answer carries an IllConditionedWarning
ILL_CONDITIONED = 1e-8
