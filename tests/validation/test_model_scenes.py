"""Model scenes: problems built by the domain models, validated beside the data scenes."""

import pytest

from orbits.core.errors import SceneError
from orbits.validate import models, run, scenes


def test_expanding_universe_agrees_with_both_backends():
    report = run.validate([models.build("expanding_universe")])
    scene = report.scenes[0]
    assert report.passed, [(c.quantity, c.errors) for c in scene.checks]
    assert {c.quantity.split(":")[0] for c in scene.checks} >= {"positions |dr|/r_max", "Hubble parameter"}
    assert max(scene.checks[0].errors.values()) < 1e-13


@pytest.mark.parametrize("name", [n for n in models.builtin_names() if n != "expanding_universe"])
def test_lagrange_and_ring_scenes_agree_with_both_backends(name):
    """L4/L5 stay put; unstable points depart at the eigenvalue rate (3 %); rings break up within a factor 3
    of the predicted time (measured 1.04-1.07); Jacobi constants hold to 1e-12."""
    report = run.validate([models.build(name)])
    scene = report.scenes[0]
    assert report.passed, [(c.quantity, c.errors) for c in scene.checks if not c.passed]
    assert scene.name == name


def test_a_file_can_ask_for_a_model_with_parameters(tmp_path):
    path = tmp_path / "universe.toml"
    path.write_text('model = "expanding_universe"\n[parameters]\nn_shells = 3\nduration = 5.0\noutputs = 10\n')
    scene = scenes.load(path)
    assert scene.problem.n_bodies == 4 and scene.problem.times.size == 10


@pytest.mark.parametrize(
    "text, fragment",
    [('model = "big_crunch"\n', "unknown model 'big_crunch'"),
     ('model = "expanding_universe"\n[parameters]\nshells = 3\n', "parameters:")],
)
def test_bad_model_files_name_the_problem(tmp_path, text, fragment):
    path = tmp_path / "bad.toml"
    path.write_text(text)
    with pytest.raises(SceneError, match=fragment):
        scenes.load(path)


def test_data_scenes_still_load_through_the_same_door():
    assert scenes.load("flyby").name == "flyby"
    assert "expanding_universe" in models.builtin_names()
