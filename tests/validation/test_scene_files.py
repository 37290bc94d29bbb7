"""Scene files that are wrong: every mistake is one SceneError line naming the file, the field and what is allowed.

Typos are refused rather than defaulted, unreadable files say why, and model parameters are checked by type and
range before anything is built or run.
"""

import inspect
import json

import numpy as np
import pytest
from typer.testing import CliRunner

from orbits.core.errors import SceneError
from orbits.validate import models, scene, scenes
from orbits_cli.main import app

DATA = """\
name = "test"
description = "a test"
asks = ["positions", "period"]

[time]
periods = 2
outputs = 8

[[bodies]]
name = "Earth"
body = "Earth"

[[bodies]]
name = "sat"
test_particle = true
orbit = { primary = "Earth", a = "8000 km", e = 0.3 }
"""


def write(tmp_path, text, name="bad.toml"):
    path = tmp_path / name
    path.write_bytes(text) if isinstance(text, bytes) else path.write_text(text)
    return path


def refusal(path):
    """The message of the SceneError that loading `path` raises (through the one loader of `orbits validate`)."""
    with pytest.raises(SceneError) as err:
        scenes.load(path)
    message = str(err.value)
    assert "\n" not in message
    return message


def test_the_template_loads(tmp_path):
    loaded = scenes.load(write(tmp_path, DATA))
    assert loaded.name == "test" and loaded.description == "a test" and not loaded.bodies[0].test_particle


# ---- typos: unknown keys at every level --------------------------------------------------------------------------
@pytest.mark.parametrize(
    "old, new, expected",
    [
        ('description = "a test"', 'descripton = "a test"',
         "unknown top-level key 'descripton'; did you mean 'description'? allowed: name, description, asks"),
        ("[time]", "output = 3\n[time]", "unknown top-level key 'output'; did you mean 'outputs' (a key of [time])?"),
        ("[time]", "[paramters]\nn = 1\n[time]", "unknown top-level key 'paramters'; did you mean 'parameters'"),
        ("test_particle = true", 'test_particle = true\nveloctiy = "0,1,0 km/s"',
         "bodies[1]: unknown key 'veloctiy'; did you mean 'velocity'? allowed: name, body, gm, mass, position"),
        ("test_particle = true", "test_partcle = true",
         "bodies[1]: unknown key 'test_partcle'; did you mean 'test_particle'?"),
        ("e = 0.3", "ecc = 0.5", "bodies[1].orbit: unknown key 'ecc'; did you mean 'e'? allowed: primary, a, p, q, e"),
        ("e = 0.3", 'e = 0.3, incl = "10 deg"', "bodies[1].orbit: unknown key 'incl'; did you mean 'inc'?"),
        ("outputs = 8", "outputs = 8\nouputs = 9", "time: unknown key 'ouputs'; did you mean 'outputs'? allowed: "
         "periods, span, outputs, times"),
        ("[time]", "[tolerance]\npostions = 1e-9\n[time]", "tolerance.postions: unknown check (did you mean "
         "'positions'?)"),
    ],
)
def test_a_misspelt_key_is_refused_with_the_nearest_allowed_key(tmp_path, old, new, expected):
    assert old in DATA
    message = refusal(write(tmp_path, DATA.replace(old, new, 1)))
    assert message.startswith(f"{tmp_path / 'bad.toml'}: ") and expected in message


def test_a_misspelt_test_particle_no_longer_turns_the_body_massive():
    data = {"name": "s", "asks": ["positions"], "time": {"span": "1 d"},
            "bodies": [{"name": "Earth", "body": "Earth"},
                       {"name": "sat", "test_partcle": True, "mass": "1 kg", "position": "7000,0,0 km"}]}
    with pytest.raises(SceneError, match=r"^bad.toml: bodies\[1\]: unknown key 'test_partcle'"):
        scene.from_dict(data, "bad.toml")


def test_a_list_of_times_with_periods_is_refused_not_ignored():
    data = json.loads(json.dumps({"name": "s", "asks": ["positions"], "time": {"times": ["1 d"], "periods": 3},
                                  "bodies": [{"name": "Earth", "body": "Earth"},
                                             {"name": "m", "gm": "1 m3/s2", "position": "7000,0,0 km"}]}))
    with pytest.raises(SceneError, match="time: give either a list of times or periods/span"):
        scene.from_dict(data, "bad.toml")


@pytest.mark.parametrize(
    "text, expected",
    [
        ('model = "expanding_universe"\nnam = "x"\n', "unknown top-level key 'nam'; did you mean 'name'? allowed: "
         "name, description, model, parameters"),
        ('model = "ring_5"\noutputs = 20\n', "unknown top-level key 'outputs' (a parameter of ring_5: put it under "
         "[parameters])"),
        ('model = "expanding_universe"\n[parameters]\nshells = 3\n',
         "parameters: unknown parameter 'shells' of model 'expanding_universe'; did you mean 'n_shells'? "
         "allowed: n_shells, duration, outputs"),
        ('model = "lagrange_unstable"\n[parameters]\npoint = ["L1"]\n',
         "allowed: mass_ratio, points, offset, outputs"),
        ('model = "ring_4"\n[parameters]\nn = 5\n', "unknown parameter 'n' of model 'ring_4'; allowed: outputs"),
        ('model = ["ring_4"]\n', "model: ['ring_4'] must be a string naming a model"),
        ('model = "ring_44"\n', "model: unknown model 'ring_44' (did you mean 'ring_4'?)"),
        ('model = "ring_4"\nparameters = 3\n', "parameters: 3 must be a table"),
        ('model = "ring_4"\nname = 3\n', "name: 3 must be a string"),
    ],
)
def test_model_scene_files_refuse_unknown_keys_and_parameters(tmp_path, text, expected):
    message = refusal(write(tmp_path, text))
    assert message.startswith(f"{tmp_path / 'bad.toml'}: ") and expected in message


def test_a_model_file_may_carry_a_name_and_a_description(tmp_path):
    path = write(tmp_path, 'name = "mine"\ndescription = "d"\nmodel = "ring_3"\n[parameters]\noutputs = 40\n')
    assert scenes.load(path).problem.times.size == 40


# ---- messages that name the file and the point -------------------------------------------------------------------
def test_a_latin1_file_is_named_with_the_offending_byte(tmp_path):
    path = write(tmp_path, DATA.replace('"a test"', '"caf\xe9"').encode("latin-1"))
    position = DATA.encode().index(b"a test") + 3
    assert refusal(path) == (f"{path}: not UTF-8 text (byte 0xe9 at position {position}); save the scene as "
                             f"UTF-8 TOML")


def test_a_binary_file_is_not_utf8_text(tmp_path):
    path = write(tmp_path, b"\x89PNG\r\n\x1a\n\x00\x00", "picture.json")
    assert refusal(path).startswith(f"{path}: not UTF-8 text (byte 0x89 at position 0)")


@pytest.mark.parametrize("content, kind", [("null", "null"), ("[1, 2]", "a list"), ("3.5", "a number (3.5)"),
                                           ('"circular"', "a string"), ("true", "true")])
def test_a_json_document_that_is_not_an_object_is_refused(tmp_path, content, kind):
    path = write(tmp_path, content, "bad.json")
    assert refusal(path) == f"{path}: a scene must be a table (JSON object), not {kind}"
    with pytest.raises(SceneError, match="must be a table"):
        scene.from_dict(None, "api")


def test_a_folder_and_an_empty_name_are_one_line_errors(tmp_path):
    folder = tmp_path / "scenes.toml"
    folder.mkdir()
    assert refusal(folder) == f"{folder}: is a folder, not a scene file (.toml or .json)"
    assert refusal(tmp_path).endswith("is a folder, not a scene file (.toml or .json)")
    assert refusal("").startswith("'': empty scene name; give a built-in scene (")
    with pytest.raises(SceneError, match="empty scene name"):
        scene.read("")


def test_an_unknown_builtin_name_suggests_one_and_lists_every_builtin():
    message = refusal("circulr")
    assert "no such scene file" in message and "(did you mean 'circular'?)" in message
    assert "lagrange_L4_L5" in message and "ring_8" in message


def test_overlong_and_too_deep_files_are_invalid_not_crashes(tmp_path):
    assert "not valid JSON: nested too deeply" in refusal(write(tmp_path, "[" * 100_000, "deep.json"))
    assert "not valid TOML: Exceeds the limit" in refusal(write(tmp_path, "x = " + "1" * 5000))


def test_a_negative_gm_reads_as_a_plain_number_naming_the_field_once(tmp_path):
    path = write(tmp_path, DATA.replace('body = "Earth"', 'gm = "-1.3e20 m3 / s2"'))
    message = refusal(path)
    assert message.startswith(f"{path}: bodies[0].gm: -1.3e+20 m3 / s2 ") and "must be positive" in message
    assert "np.float64" not in message and message.count("bodies[0].gm") == 1


def test_numpy_values_in_a_dictionary_read_as_plain_numbers():
    data = {"name": "s", "asks": ["positions"], "time": {"span": "1 d", "outputs": np.int64(0)},
            "bodies": [{"name": "Earth", "body": "Earth"}, {"name": "m", "gm": "1 m3/s2", "position": "7000,0,0 km"}]}
    with pytest.raises(SceneError) as err:
        scene.from_dict(data, "api")
    assert str(err.value) == "api: time.outputs: 0 must be an integer in [1, 1000000]"


@pytest.mark.parametrize(
    "bodies, expected",
    [
        ([{"name": "Sun", "body": "Sun"}], "bodies: a scene needs at least two bodies"),
        ([{"name": "Sun", "body": "Sun"}, {"name": "Earth", "body": "Earth"}],
         "bodies[1]: 'Earth' starts at the position of bodies[0] ('Sun')"),
        ([{"name": "Sun", "body": "Sun"}, {"name": "Earth", "body": "Earth", "position": "1e308,0,0 km"}],
         "bodies[1].position: '1e308,0,0 km' overflows float64 in SI units (m)"),
    ],
)
def test_scenes_the_integrators_cannot_start_are_refused(bodies, expected):
    data = {"name": "s", "asks": ["positions"], "time": {"span": "1 d"}, "bodies": bodies}
    with pytest.raises(SceneError) as err:
        scene.from_dict(data, "bad.toml")
    assert str(err.value).startswith(f"bad.toml: {expected}")


# ---- model parameters: type and range -------------------------------------------------------------------------
@pytest.mark.parametrize(
    "model, parameters, expected",
    [
        ("lagrange_unstable", 'points = ["L9"]',
         "parameters.points: 'L9' is not a Lagrange point; allowed: L1, L2, L3, L4, L5"),
        ("lagrange_unstable", 'points = ["l1"]', "'l1' is not a Lagrange point (did you mean 'L1'?)"),
        ("lagrange_unstable", 'points = "L1"', "parameters.points: 'L1' must be a non-empty list of Lagrange points"),
        ("lagrange_unstable", 'points = ["L1", "L1"]', "names a point twice"),
        ("lagrange_unstable", 'points = ["L4"]', "parameters.points: 'L4' is linearly stable at mu = 0.0121506"),
        ("lagrange_unstable", "mass_ratio = 0.6", "parameters.mass_ratio: 0.6 must be a number in [1e-07, 0.5]"),
        ("lagrange_unstable", "offset = 1e-3", "parameters.offset: 0.001 is outside [1e-14, 0.0001)"),
        ("lagrange_unstable", "offset = 0.0", "parameters.offset: 0.0 is outside [1e-14, 0.0001)"),
        ("lagrange_unstable", 'mass_ratio = 0.0385209\npoints = ["L4"]',
         "parameters: L4 departs at 0.0001043 / time unit at mu = 0.0385209"),
        ("expanding_universe", "duration = 1e30", "parameters.duration: 1e+30 is outside (0, 1e+06] time units"),
        ("expanding_universe", "duration = -1.0", "parameters.duration: -1.0 is outside (0, 1e+06] time units"),
        ("expanding_universe", "duration = nan", "parameters.duration: nan is outside (0, 1e+06] time units"),
        ("expanding_universe", 'duration = "20"', "parameters.duration: '20' must be a number in (0, 1e+06]"),
        ("expanding_universe", "n_shells = 0", "parameters.n_shells: 0 is outside [1, 1000]"),
        ("expanding_universe", "outputs = 10.0", "parameters.outputs: 10.0 must be an integer in [1, 1000000]"),
        ("expanding_universe", "outputs = true", "parameters.outputs: True must be an integer in [1, 1000000]"),
        ("expanding_universe", "outputs = 2_000_000", "parameters.outputs: 2000000 is outside [1, 1000000]"),
        ("expanding_universe", "n_shells = 1000\noutputs = 1_000_000", "parameters: outputs x bodies = 1000000 x "
         "1001 = 1e+09 stored states; at most 1e+07 are allowed: ask for fewer outputs, or lower n_shells"),
        ("lagrange_L4_L5", "periods = inf", "parameters.periods: inf is outside (0, 10000] binary periods"),
        ("lagrange_L4_L5", "periods = 0", "parameters.periods: 0 is outside (0, 10000] binary periods"),
        ("ring_5", "outputs = 3", "parameters.outputs: 3 is outside [10, 1000000]: the shape check needs outputs"),
    ],
)
def test_model_parameters_are_checked_by_type_and_range_at_load_time(tmp_path, model, parameters, expected):
    path = write(tmp_path, f'model = "{model}"\n[parameters]\n{parameters}\n')
    message = refusal(path)
    assert message.startswith(f"{path}: ") and expected in message


def test_every_builder_parameter_has_a_rule():
    for name, builder in models.MODELS.items():
        assert set(inspect.signature(builder).parameters) == set(models.PARAMETER_RULES[name]), name
        assert models.parameters_of(name) == tuple(inspect.signature(builder).parameters)


def test_the_defaults_and_the_bounds_themselves_are_accepted():
    for name in models.MODELS:
        defaults = {k: p.default for k, p in inspect.signature(models.MODELS[name]).parameters.items()}
        assert models.build(name, defaults).name.startswith(name.split("_")[0])
    universe = models.build("expanding_universe", {"duration": 1e6, "outputs": 10})
    assert universe.problem.times[-1] == 1e6
    assert models.build("lagrange_unstable", {"points": ["L1"], "offset": 1e-14}).problem.n_bodies == 3


# ---- the command line: one line on stderr, exit status 2 ----------------------------------------------------------
@pytest.mark.parametrize(
    "name, content",
    [
        ("typo.toml", DATA.replace("description", "descripton")),
        ("latin.toml", DATA.replace('"a test"', '"caf\xe9"').encode("latin-1")),
        ("null.json", "null"),
        ("points.toml", 'model = "lagrange_unstable"\n[parameters]\npoints = ["L9"]\n'),
        ("long.toml", 'model = "expanding_universe"\n[parameters]\nduration = 1e30\n'),
        ("alone.toml", 'name = "a"\nasks = ["positions"]\n[time]\nspan = "1 d"\n[[bodies]]\nname = "S"\nbody = "Sun"'),
        ("folder.toml", None),
    ],
    ids=["typo", "latin-1", "null", "point", "duration", "one body", "folder"],
)
def test_the_command_line_prints_one_line_and_exits_2(tmp_path, name, content):
    path = tmp_path / name
    path.mkdir() if content is None else write(tmp_path, content, name)
    result = CliRunner().invoke(app, ["validate", str(path)])
    assert result.exit_code == 2, result.output
    assert result.stdout == ""
    lines = result.stderr.splitlines()
    assert len(lines) == 1 and lines[0].startswith(f"orbits: error: {path}: "), result.stderr
    assert "Traceback" not in result.stderr


@pytest.mark.parametrize("old, new", [('name = "test"', 'name = ""'), ('name = "test"', 'name = "   "'),
                                      ('name = "sat"', 'name = "\\u200b"'), ('name = "Earth"', 'name = "\\t"')])
def test_empty_and_blank_names_are_refused(tmp_path, old, new):
    """An empty or blank scene or body name was accepted and read ': passed' in the report."""
    field = "name" if old == 'name = "test"' else ("bodies[1].name" if "sat" in old else "bodies[0].name")
    message = refusal(write(tmp_path, DATA.replace(old, new)))
    assert f"{field}: " in message and "is empty or blank; give a name that shows" in message


EVIL = (DATA.replace('name = "test"', 'name = "red\\u001b[31mtext\\u202e"')
        .replace('description = "a test"', 'description = "clear\\u001b[2J\\nscreen"')
        .replace('name = "sat"', 'name = "s\\u001b[5mat"'))


def test_control_characters_from_a_scene_file_reach_the_terminal_escaped(tmp_path):
    """A scene's name and description went to the terminal raw: ESC [2J cleared the screen."""
    pytest.importorskip("rebound")
    result = CliRunner().invoke(app, ["validate", str(write(tmp_path, EVIL)), "--backend", "rebound"])
    assert result.exit_code == 0, result.output
    assert "\x1b" not in result.stdout and "\u202e" not in result.stdout
    assert "red\\x1b[31mtext\\u202e: passed" in result.stdout and "clear\\x1b[2J\\nscreen" in result.stdout
    assert "period[s\\x1b[5mat]" in result.stdout
    data = json.loads(CliRunner().invoke(app, ["validate", str(tmp_path / "bad.toml"), "--backend", "rebound",
                                               "--format", "json"]).stdout)
    assert data["scenes"][0]["name"] == "red\x1b[31mtext\u202e"  # JSON keeps the text, escaped by JSON itself


def test_an_error_about_a_file_is_one_line_without_raw_controls(tmp_path):
    result = CliRunner().invoke(app, ["validate", str(tmp_path / "no\x1b[2Jfile")])
    assert result.exit_code == 2 and len(result.stderr.splitlines()) == 1
    assert "\x1b" not in result.stderr and "no\\x1b[2Jfile" in result.stderr
