"""The calculator: outputs, JSON schema, exit codes and one-line errors."""

import json
import subprocess
import sys

import pytest
from typer.testing import CliRunner

from orbits_cli.main import app

runner = CliRunner()


def run(*args):
    return runner.invoke(app, list(args))


def test_orbit_of_a_named_body_in_json():
    result = run("orbit", "Earth", "--format", "json")
    assert result.exit_code == 0, result.output
    data = json.loads(result.stdout)
    assert data["period"]["unit"] == "s"
    assert abs(data["period"]["value"] / 86400 - 365.2583) < 1e-3
    assert abs(data["eccentricity"]["value"] - 0.01671123) < 1e-15


def test_orbit_from_elements_only_some_quantities():
    result = run(
        "orbit", "--primary", "Earth", "--a", "42164.17 km", "--e", "0", "--only", "period,speed", "--format", "json"
    )
    assert result.exit_code == 0, result.output
    data = json.loads(result.stdout)
    assert list(data) == ["period", "speed"]
    assert abs(data["period"]["value"] - 86164.09) < 0.2


def test_orbit_from_a_state_vector_table():
    result = run("orbit", "--primary", "Earth", "--r", "7000,0,0 km", "--v", "0,7.5,1 km/s")
    assert result.exit_code == 0, result.output
    assert "semi_major_axis" in result.stdout and "periapsis_speed" in result.stdout


def test_kepler_conversions_both_ways():
    forward = json.loads(run("kepler", "--e", "0.5", "--M", "1.0 rad", "--format", "json").stdout)
    nu = forward["true_anomaly"]["value"]
    back = json.loads(run("kepler", "--e", "0.5", "--nu", f"{nu} rad", "--format", "json").stdout)
    assert abs(back["mean_anomaly"]["value"] - 1.0) < 1e-15
    hyper = json.loads(run("kepler", "--e", "2", "--M", "3", "--format", "json").stdout)
    assert "hyperbolic_anomaly" in hyper
    parab = json.loads(run("kepler", "--e", "1", "--M", "2", "--format", "json").stdout)
    assert "parabolic_anomaly" in parab


@pytest.mark.parametrize(
    "args, fragment",
    [
        (["orbit", "--primary", "Earth", "--a", "7000", "--e", "0.1"], "has no unit"),
        (["orbit", "--primary", "Earth", "--a", "-7000 km", "--e", "0.1"], "a > 0 for a bound orbit"),
        (["orbit", "--primary", "Earth", "--a", "7000 s"], "not a length"),
        (["orbit", "--primary", "Vulcan", "--a", "7000 km"], "neither a known body"),
        (["orbit", "--primary", "Earth"], "give a size"),
        (["orbit", "--primary", "Earth", "--a", "7000 km", "--only", "perod"], "unknown quantities"),
        (["kepler", "--e", "0.5"], "exactly one of --M"),
        (["kepler", "--e", "1", "--nu", "180 deg"], "infinite distance"),
    ],
)
def test_errors_exit_2_with_one_line_on_stderr(args, fragment):
    result = run(*args)
    assert result.exit_code == 2
    assert fragment in result.stderr
    assert len(result.stderr.strip().splitlines()) == 1
    assert result.stdout == ""


def test_info_lists_versions_without_importing_backends():
    data = json.loads(run("info", "--format", "json").stdout)
    assert data["versions"]["numpy"] and "heyoka compiled integrators (HEYOKA_CACHE_DIR)" in data["caches"]


def test_info_says_which_kernels_the_cache_holds_and_compile_fills_the_gaps(monkeypatch):
    """`orbits info` reports each entry kernel as orbits.core._fast.ready finds it; --compile starts, through
    orbits.tools.kernels, exactly the kernels not ready (two pretended absent here, their starters replaced by
    recorders), one line each on stderr, and leaves ORBITS_JIT's mode as it was."""
    from orbits.core import _fast
    from orbits.tools import kernels

    names = _fast.entry_kernels()
    assert len(names) == 7 and set(names) == set(kernels.STARTERS)
    absent = ["twobody._fast_propagate.propagate", "manoeuvres._fast_lambert.solve"]
    monkeypatch.setitem(_fast._state, "ready", {name: name not in absent for name in names})
    monkeypatch.setattr(_fast, "enabled", lambda: True)
    started = []
    for name in absent:
        monkeypatch.setitem(kernels.STARTERS, name, lambda name=name: started.append((name, _fast._mode())))
    mode = _fast._mode()
    data = json.loads(run("info", "--format", "json").stdout)
    assert [name for name, ready in data["kernels_ready"].items() if not ready] == absent
    result = run("info", "--compile")
    assert started == [(name, True) for name in absent] and _fast._mode() == mode
    assert "kernels in the cache: 5 of 7; absent: propagate.propagate, lambert.solve" in result.stdout
    assert [line.split(" in ")[0] for line in result.stderr.splitlines()] == [
        "orbits: compiled twobody._fast_propagate.propagate", "orbits: compiled manoeuvres._fast_lambert.solve",
        "orbits: 2 kernels compiled"]


def test_help_does_not_load_heavy_modules():
    code = (
        "import sys; from orbits_cli.main import app; from typer.testing import CliRunner; "
        "CliRunner().invoke(app, ['--help']); "
        "print(sorted(m for m in ('rebound', 'heyoka', 'matplotlib', 'astropy') if m in sys.modules))"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    assert out.strip() == "[]"


def test_bench_kepler_small_run_writes_json_atomically(tmp_path):
    target = tmp_path / "bench.json"
    result = run(
        "bench",
        "kepler",
        "--easy",
        "2000",
        "--hard",
        "500",
        "--hyperbolic",
        "500",
        "--reference",
        "20",
        "--repeats",
        "1",
        "--output",
        str(target),
    )
    assert result.exit_code == 0, result.output
    rows = json.loads(target.read_text())
    orbits_rows = [r for r in rows if r["method"] == "orbits" and not r["dataset"].startswith("easy, ")]
    assert {r["dataset"] for r in orbits_rows} == {"easy", "hard", "hyperbolic"}
    assert all(r["max_ulp"] <= 4 for r in orbits_rows)
    layouts = {r["dataset"] for r in rows if r["dataset"].startswith("easy, ")}  # the alignment rows
    assert layouts == {"easy, adjacent", "easy, offset 8 B", "easy, padded 64 B"}
    assert [p.name for p in tmp_path.iterdir()] == ["bench.json"]  # no temporary file left behind


def test_validate_default_runs_every_builtin_scene_and_writes_json(tmp_path):
    target = tmp_path / "report.json"
    result = run("validate", "--output", str(target))
    assert result.exit_code == 0, result.output
    data = json.loads(target.read_text())
    assert data["passed"] is True and len(data["scenes"]) >= 5
    first = data["scenes"][0]
    assert {"rebound", "heyoka"} <= set(first["versions"]) and "analytic" in first["wall_time_s"]
    checks = sum(len(scene["checks"]) for scene in data["scenes"])
    summary = result.stdout[result.stdout.rindex("worst error / tolerance per scene"):].splitlines()
    assert summary[-1] == f"all {checks} checks of {len(data['scenes'])} scenes passed"
    assert len(summary) <= len(data["scenes"]) + 6  # one screen: a row a scene, a header, the verdict
    rows = {line.split()[0]: line.split()[1:] for line in summary[4:-2]}
    assert list(rows) == [scene["name"] for scene in data["scenes"]]
    for scene in data["scenes"]:  # each backend's worst error as a fraction of its tolerance, then the time
        for k, backend in enumerate(("rebound", "heyoka")):
            worst = max(c["errors"][backend] / c["tolerance"] for c in scene["checks"] if backend in c["errors"])
            assert float(rows[scene["name"]][1 + k]) == pytest.approx(worst, rel=0.06)  # 2 digits shown
    quiet = run("validate", "circular", "binary", "--quiet")
    lines = quiet.stdout.strip().splitlines()
    assert quiet.exit_code == 0 and lines[0].startswith("worst error / tolerance per scene") and len(lines) == 8


def test_validate_without_the_ephemeris_extra_skips_solar_system_and_says_so(monkeypatch):
    """A base install (no skyfield-data, jplephem, REBOUNDx) runs the other built-in scenes and names the one it
    leaves out, with what it needs; the scene list is cut to two so the run stays short."""
    import importlib.util

    from orbits import validate
    from orbits.ephemeris import positions as ephemeris
    from orbits.validate import scenes

    monkeypatch.setattr(ephemeris, "available_source", lambda: "builtin")
    real_find_spec = importlib.util.find_spec
    monkeypatch.setattr(importlib.util, "find_spec", lambda name, *a: None if name == "reboundx" else
                        real_find_spec(name, *a))
    monkeypatch.setattr(validate, "builtin_names", lambda: ["circular", "solar_system"])
    from orbits.validate import perturb as perturbed

    assert scenes.unavailable_builtins() == {
        "solar_system": "needs JPL DE421 (skyfield-data, jplephem) and REBOUNDx: pip install 'orbits[ephemeris]'",
        **{name: "needs REBOUNDx: pip install 'orbits[ephemeris]'" for name in perturbed.SCENES
           if name != "kozai_lidov"}}
    result = run("validate")
    assert result.exit_code == 0, result.output
    said = result.stderr.strip().splitlines()
    assert ("orbits: skipped the built-in scene solar_system: it needs JPL DE421 (skyfield-data, jplephem) and "
            "REBOUNDx: pip install 'orbits[ephemeris]'") in said
    assert len(said) == 1 + len(perturbed.SCENES) - 1  # and each perturbed scene that needs REBOUNDx
    assert "circular" in result.stdout and "solar_system" not in result.stdout


def test_validate_exits_1_when_a_check_fails(tmp_path):
    scene_file = tmp_path / "strict.toml"
    scene_file.write_text(
        'name = "strict"\nasks = ["positions"]\n[time]\nperiods = 2\noutputs = 4\n[tolerance]\npositions = 1e-30\n'
        '[[bodies]]\nname = "Earth"\nbody = "Earth"\n[[bodies]]\nname = "sat"\ntest_particle = true\n'
        'orbit = { primary = "Earth", a = "8000 km", e = 0.1 }\n'
    )
    result = run("validate", str(scene_file), "--backend", "rebound", "--format", "json")
    assert result.exit_code == 1
    assert json.loads(result.stdout)["passed"] is False
    summary = run("validate", str(scene_file), "--backend", "rebound", "--quiet")
    assert summary.exit_code == 1 and summary.stdout.strip().endswith("1 of 1 scenes FAILED: strict")


def test_validate_bad_scene_exits_2_before_running(tmp_path):
    result = run("validate", str(tmp_path / "nope.toml"))
    assert result.exit_code == 2 and "no such scene file" in result.stderr


def test_plot_option_writes_the_picture(tmp_path):
    picture = tmp_path / "earth.png"
    result = run("orbit", "Earth", "--only", "period", "--plot", str(picture))
    assert result.exit_code == 0, result.output
    assert picture.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    residuals = tmp_path / "residuals.svg"
    assert run("validate", "flyby", "--plot", str(residuals)).exit_code == 0
    assert residuals.read_text().lstrip().startswith("<?xml")
    bad = run("orbit", "Earth", "--plot", str(tmp_path / "x.gif"))
    assert bad.exit_code == 2 and ".png, .svg or .pdf" in bad.stderr


@pytest.mark.parametrize(
    "args",
    [["flyby", "--primary", "Jupiter", "--v-inf", "5.6 km/s", "--periapsis", "200000 km"],
     ["binary", "--m1", "1 solMass", "--m2", "0.5 solMass", "--a", "1 AU", "--e", "0.5"],
     ["cosmology", "--Om", "0.3"]],
)
def test_plot_option_on_the_other_verbs(args, tmp_path):
    picture = tmp_path / "p.pdf"
    result = run(*args, "--plot", str(picture))
    assert result.exit_code == 0, result.output
    assert picture.read_bytes()[:5] == b"%PDF-"


def test_orbit_speed_energies_and_swept_area_asked_for():
    import astropy.units as u

    from orbits import Orbit

    args = ["orbit", "--primary", "Earth", "--a", "8000 km", "--e", "0.1", "--mass", "1000 kg", "--at-r", "7500 km",
            "--area-between", "0 h,1 h", "--format", "json"]
    result = run(*args)
    assert result.exit_code == 0, result.output
    data = json.loads(result.stdout)
    orbit = Orbit.from_elements("Earth", a=8000 * u.km, e=0.1, mass=1000 * u.kg)
    assert data["speed_at_r"]["value"] == orbit.speed_at(7500 * u.km).value
    assert data["kinetic_energy_at_r"]["value"] == orbit.kinetic_energy_at(7500 * u.km).value
    assert data["potential_energy_at_r"]["unit"] == "J"
    assert data["area_swept"]["value"] == orbit.area_swept(0 * u.s, 1 * u.h).value
    assert data["laplace_runge_lenz_magnitude"]["value"] == orbit.laplace_runge_lenz_magnitude.value
    only = json.loads(run(*args[:-2], "--only", "speed_at_r,period", "--format", "json").stdout)
    assert set(only) == {"speed_at_r", "period"}
    unreachable = run("orbit", "--primary", "Earth", "--a", "8000 km", "--e", "0.1", "--at-r", "9000 km")
    assert unreachable.exit_code == 2 and "the body never gets there" in unreachable.output
    bad = run("orbit", "--primary", "Earth", "--a", "8000 km", "--area-between", "1 h")
    assert bad.exit_code == 2 and "write T1,T2" in bad.output


def test_version_and_the_short_help_option():
    """`orbits --version` prints the version; -h is --help for the root and for every verb."""
    from orbits import __version__

    version = run("--version")
    assert (version.exit_code, version.output) == (0, f"orbits {__version__}\n")
    for words in (["-h"], ["lambert", "-h"], ["perturb", "kozai", "-h"]):
        result = run(*words)
        assert result.exit_code == 0 and "Usage: " in result.output, (words, result.output)
