"""What an install carries: every package folder of the library and the command line is named in pyproject.toml
(setuptools is given the list, and a folder missing from it would be left out of a wheel while an editable install
still found it), and every data file the code reads from the package sits where package-data says."""

import pathlib
import tomllib

ROOT = pathlib.Path(__file__).resolve().parents[1]
CONFIG = tomllib.loads((ROOT / "pyproject.toml").read_text())["tool"]["setuptools"]


def package_folders() -> set[str]:
    """Dotted names of the folders holding an __init__.py under orbits/ and cli/ (installed as orbits_cli)."""
    names = set()
    for top, installed in (("orbits", "orbits"), ("cli", "orbits_cli")):
        for init in (ROOT / top).rglob("__init__.py"):
            parts = init.parent.relative_to(ROOT / top).parts
            names.add(".".join((installed, *parts)))
    return names


def test_every_package_folder_is_installed():
    assert package_folders() == set(CONFIG["packages"])


def test_every_folder_of_python_modules_is_a_package():
    """A folder of modules without __init__.py would import as a namespace package in the checkout and be left
    out of the install."""
    loose = [str(folder.relative_to(ROOT)) for top in ("orbits", "cli") for folder in (ROOT / top).rglob("*")
             if folder.is_dir() and folder.name != "__pycache__" and any(folder.glob("*.py"))
             and not (folder / "__init__.py").exists()]
    assert loose == []


def test_the_built_in_scenes_are_package_data():
    (package, patterns), = CONFIG["package-data"].items()
    folder = ROOT / package.replace("orbits.", "orbits/", 1).replace(".", "/")
    assert all(list(folder.glob(pattern)) for pattern in patterns)
