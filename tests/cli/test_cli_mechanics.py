"""The verbs `orbits collide`, `orbits projectile` and `orbits pendulum` (notes IX, XX, XXV): JSON equal to the
library, tables, plots, and one-line errors with exit status 2."""

import json
import math

import astropy.units as u
import numpy as np
import pytest
from typer.testing import CliRunner

from orbits import Collision, Pendulum, Projectile
from orbits_cli.main import app

runner = CliRunner()


def run_json(*args):
    result = runner.invoke(app, [*args, "--format", "json"])
    assert result.exit_code == 0, result.output
    return json.loads(result.stdout)


def test_collide_head_on_json_is_the_library_bit_for_bit():
    data = run_json("collide", "--m1", "2 kg", "--v1", "3 m/s", "--m2", "1 kg", "--v2", "-1 m/s", "--restitution",
                    "0.8")
    hit = Collision.head_on(2 * u.kg, 3 * u.m / u.s, 1 * u.kg, -1 * u.m / u.s, 0.8)
    assert data["velocity1_after"] == {"value": hit.velocity1_after.value, "unit": "m / s"}
    assert data["velocity2_after"]["value"] == hit.velocity2_after.value
    assert data["internal_kinetic_energy_after"]["value"] == pytest.approx(
        0.64 * data["internal_kinetic_energy_before"]["value"], rel=1e-15)


def test_collide_with_vectors_and_a_contact_normal():
    data = run_json("collide", "--m1", "1 kg", "--v1", "2,0 m/s", "--m2", "1 kg", "--v2", "0,0 m/s", "--line-of-impact",
                    "1,1", "--only", "velocity1_after,velocity2_after")
    v1, v2 = data["velocity1_after"]["value"], data["velocity2_after"]["value"]
    assert v1 == pytest.approx([1.0, -1.0]) and v2 == pytest.approx([1.0, 1.0])
    three = run_json("collide", "--m1", "1 kg", "--v1", "1,2,3 km/s", "--m2", "3 kg", "--v2", "0,0,0 km/s")
    assert len(three["velocity1_after"]["value"]) == 3


def test_projectile_table_and_json():
    result = runner.invoke(app, ["projectile", "--speed", "20 m/s", "--angle", "45"])
    assert result.exit_code == 0 and "no drag" in result.stdout and "40.78865" in result.stdout  # v**2 / g0
    assert "terminal_speed" not in result.stdout
    data = run_json("projectile", "--speed", "20 m/s", "--angle", "45", "--drag", "quadratic", "--terminal-speed",
                    "30 m/s", "--height", "2 m")
    shot = Projectile.launch(20 * u.m / u.s, 45 * u.deg, 2 * u.m).with_quadratic_drag(30 * u.m / u.s)
    assert data["range"]["value"] == shot.range.value and data["landing_angle"]["unit"] == "rad"
    ball = run_json("projectile", "--speed", "40 m/s", "--angle", "45", "--drag", "quadratic", "--mass", "0.145 kg",
                    "--drag-coefficient", "0.35", "--density", "1.2 kg/m3", "--area", "4.2e-3 m2")
    assert ball["terminal_speed"]["value"] == pytest.approx(math.sqrt(2 * 0.145 * 9.80665 / (0.35 * 1.2 * 4.2e-3)),
                                                            rel=1e-15)  # ERRATA #32's corrected form
    linear = run_json("projectile", "--speed", "20 m/s", "--angle", "30 deg", "--drag", "linear", "--rate", "0.5 1/s")
    assert linear["terminal_speed"]["value"] == pytest.approx(9.80665 / 0.5)


def test_pendulum_and_vertical_circle():
    data = run_json("pendulum", "--length", "1 m", "--amplitude", "170 deg")
    assert data["period"]["value"] == Pendulum.simple(1 * u.m, 170 * u.deg).period.value
    assert data["period_ratio"]["value"] == pytest.approx(2.4393627196738, rel=1e-13)
    circle = run_json("pendulum", "--length", "1 m", "--bottom-speed", "6 m/s", "--mass", "1 kg")
    assert "leaving_angle" in circle and "period" not in circle and "normal_force_at_top" not in circle
    assert math.pi / 2 < circle["leaving_angle"]["value"] < math.pi
    looping = run_json("pendulum", "--length", "1 m", "--bottom-speed", "8 m/s", "--rod")
    assert "period" in looping and "normal_force_at_top" not in looping  # no mass: no forces


def drawn(monkeypatch, tmp_path, *args):
    """Run a verb with --plot; return the figure's axes as drawn (captured as it is saved) after checking the file."""
    import orbits.plot

    figures = []
    real_save = orbits.plot.save

    def keep(fig, path):
        figures.append(fig)
        real_save(fig, path)

    monkeypatch.setattr(orbits.plot, "save", keep)
    target = tmp_path / "picture.png"
    result = runner.invoke(app, [*args, "--plot", str(target)])
    assert result.exit_code == 0, result.output
    assert target.stat().st_size > 10000 and len(figures) == 1
    return figures[0].axes[0]


def lines(ax):
    return {line.get_label(): line for line in ax.get_lines()}


def test_collide_plot_shows_the_velocities_after(monkeypatch, tmp_path):
    ax = drawn(monkeypatch, tmp_path, "collide", "--m1", "2 kg", "--v1", "3,1 m/s", "--m2", "1 kg", "--v2", "0,0 m/s")
    hit = Collision.oblique(2 * u.kg, [3, 1] * u.m / u.s, 1 * u.kg, [0, 0] * u.m / u.s)
    drawn_lines = lines(ax)
    for label, velocity in (("body 1 after", hit.velocity1_after), ("body 2 after", hit.velocity2_after)):
        tip = [drawn_lines[label].get_xdata()[1], drawn_lines[label].get_ydata()[1]]
        assert tip == pytest.approx(velocity.to_value(u.m / u.s), rel=1e-15)
    assert "body 2 before (at rest)" in drawn_lines  # a zero vector is named, not lost
    assert ax.get_legend() is not None and ax.get_xlabel() == "$v_x$ [m/s]"


def test_projectile_plot_lands_where_the_table_says(monkeypatch, tmp_path):
    args = ["projectile", "--speed", "30 m/s", "--angle", "60", "--drag", "quadratic", "--terminal-speed", "25 m/s"]
    ax = drawn(monkeypatch, tmp_path, *args)
    shot = Projectile.launch(30 * u.m / u.s, 60 * u.deg).with_quadratic_drag(25 * u.m / u.s)
    path = lines(ax)["quadratic drag"]
    assert path.get_xdata()[-1] == pytest.approx(shot.range.to_value(u.m), rel=1e-12)
    assert max(path.get_ydata()) == pytest.approx(shot.apex_height.to_value(u.m), rel=1e-3)  # 200 samples


def test_pendulum_plot_marks_this_amplitude(monkeypatch, tmp_path):
    ax = drawn(monkeypatch, tmp_path, "pendulum", "--length", "1 m", "--amplitude", "120")
    mark = lines(ax)["this pendulum"]
    assert mark.get_xdata()[0] == pytest.approx(120.0, rel=1e-15)
    assert mark.get_ydata()[0] == pytest.approx(Pendulum.simple(1 * u.m, 120 * u.deg).period_ratio.value, rel=1e-15)


@pytest.mark.parametrize("extra, arc, end", [([], 123.848, "leaves the circle (N = 0)"), (["--rod"], 180.0, None),
                                             (["--bottom-speed", "4 m/s"], 79.384, "turns back (v = 0)")])
def test_vertical_circle_plot_follows_the_arc_on_the_circle(monkeypatch, tmp_path, extra, arc, end):
    """A string's curve stops where it slackens (beyond, the body flies free); a looping rod's covers the circle;
    a swing's stops where it turns back; the ends are marked."""
    speed = ["--bottom-speed", "6.5 m/s"] if "--rod" in extra else ["--bottom-speed", "6 m/s"]
    if "--bottom-speed" in extra:
        speed = []
    ax = drawn(monkeypatch, tmp_path, "pendulum", "--length", "1 m", *speed, "--mass", "1 kg", *extra)
    curve = next(line for line in ax.get_lines() if line.get_linestyle() == "-" and line.get_label()[0] != "_")
    assert max(np.abs(curve.get_xdata())) == pytest.approx(arc, abs=1e-3)
    assert (end is None) == all(end_label not in line.get_label() for line in ax.get_lines()
                                for end_label in ("leaves", "turns back"))
    assert ax.get_xlim() == (-180.0, 180.0)


@pytest.mark.parametrize("args, fragment", [
    (["collide", "--m1", "-2 kg", "--v1", "3 m/s", "--m2", "1 kg", "--v2", "0 m/s"], "mass m1 = -2.0 kg is outside"),
    (["collide", "--m1", "2 kg", "--v1", "3 m/s", "--m2", "1 kg", "--v2", "0 m/s", "--restitution", "1.5"],
     "coefficient of restitution e = 1.5"),
    (["collide", "--m1", "2 kg", "--v1", "3,0 m/s", "--m2", "1 kg", "--v2", "0 m/s"], "both be speeds"),
    (["collide", "--m1", "2 kg", "--v1", "3 kg", "--m2", "1 kg", "--v2", "0 m/s"], "not a speed"),
    (["collide", "--m1", "2 kg", "--v1", "1,0 m/s", "--m2", "1 kg", "--v2", "1,0 m/s"], "never collide"),
    (["projectile", "--speed", "20 m/s", "--angle", "95"], "launch angle"),
    (["projectile", "--speed", "20", "--angle", "45"], "has no unit"),
    (["projectile", "--speed", "20 m/s", "--angle", "45", "--drag", "linear"], "--rate"),
    (["projectile", "--speed", "40 m/s", "--angle", "45", "--drag", "quadratic", "--mass", "0.145 kg"],
     "or all of --mass, --drag-coefficient, --density and --area"),
    (["projectile", "--speed", "40 m/s", "--angle", "45", "--drag", "quadratic", "--mass", "0.145 kg",
      "--drag-coefficient", "-0.35", "--density", "1.2 kg/m3", "--area", "4.2e-3 m2"],
     "drag coefficient C = -0.35 is outside the allowed range (0, inf)"),
    (["projectile", "--speed", "40 m/s", "--angle", "45", "--area", "1 m2"], "--area: need --drag"),
    (["pendulum", "--length", "1 m", "--amplitude", "180"], "amplitude theta0"),
    (["pendulum", "--length", "1 m"], "exactly one of --amplitude and --bottom-speed"),
    (["pendulum", "--length", "-1 m", "--amplitude", "10"], "length L = -1.0 m"),
])
def test_bad_input_is_one_line_and_exit_2(args, fragment):
    result = runner.invoke(app, args)
    assert result.exit_code == 2
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("orbits: error:") and fragment in lines[0]


def test_the_course_quantities_are_in_the_tables_and_json():
    """Each body's kinetic energy before and after, the projectile's accelerations at launch and landing, the
    vertical circle's at the bottom and top: in the JSON, equal to the library."""
    hit = run_json("collide", "--m1", "2 kg", "--v1", "3 m/s", "--m2", "1 kg", "--v2", "0 m/s")
    library = Collision.head_on(2 * u.kg, 3 * u.m / u.s, 1 * u.kg, 0 * u.m / u.s)
    for name in ("kinetic_energy1_before", "kinetic_energy2_before", "kinetic_energy1_after", "kinetic_energy2_after"):
        assert hit[name]["value"] == getattr(library, name).value and hit[name]["unit"] == "J"
    thrown = run_json("projectile", "--speed", "30 m/s", "--angle", "40", "--drag", "quadratic",
                      "--terminal-speed", "25 m/s")
    ball = Projectile.launch(30 * u.m / u.s, 40 * u.deg).with_quadratic_drag(25 * u.m / u.s)
    assert thrown["launch_acceleration"]["value"] == ball.launch_acceleration.value
    assert thrown["landing_acceleration"]["unit"] == "m / s2"
    loop = run_json("pendulum", "--length", "1.5 m", "--bottom-speed", "9 m/s")
    assert loop["acceleration_at_bottom"]["value"] == 54.0 and "acceleration_at_top" in loop
