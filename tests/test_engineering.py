"""Issue 17: results in an engineer's terms — directions (vertical/horizontal, pitch/yaw), the
summary of the largest free force and moment, units, significant figures, the moment noise
floor and --speed.

Every expected value is a closed form derived by hand in the test's docstring, or the
slider-crank harmonic B_k of ``conftest.exact_b`` (the closed-form acceleration projected by
the trapezoidal rule, apart from the library).
"""

import json
import math
import re

import numpy as np
import pytest
from click.testing import CliRunner
from numpy.testing import assert_allclose

import balance_cli as balance
from balance_cli.cli import main
from balance_cli.units import Scale
from balance_cli.units import UNIT_SYSTEMS, parse_quantity, significant

from tests.support import ROOT, TWIN, exact_b, make_engine

M, R, L, RPM, D = 0.6, 0.045, 0.15, 3000.0, 0.1
W = RPM * math.pi / 30.0
UNIT = M * R * W**2     # m·r·ω² of one reciprocating mass, N
# rounding of the FFT is about 1e-13 of the largest force; 1e-9 leaves a wide margin
RTOL = 1e-9


def run(*args):
    return CliRunner().invoke(main, [str(a) for a in args])


def record(engine, order, max_order=8):
    return balance.analyse(engine, max_order=max_order).to_dict()["orders"][order - 1]


def test_cross_plane_v8_primary_couple_is_all_forward_with_equal_pitch_and_yaw():
    """90° V8, cross-plane crank (throws 0°, 90°, 270°, 180° at z = 0, d, 2d, 3d), reciprocating
    masses only. A throw's two pistons at ±45° make a first-order force m·r·ω² turning with the
    crank (exactly: the rod adds only even orders), so the couple is forward only, of size
    m·r·ω²·|Σ(z_j − z̄)·e^{iβ_j}| = m·r·ω²·d·|−1.5 − 0.5i + 0.5·(−i) + 1.5·(−1)|
    = m·r·ω²·d·|−3 − i| = √10·m·r·ω²·d.
    A turning vector has equal vertical and horizontal amplitudes."""
    engine = make_engine([-45, 45], [(0, 0), (90, D), (270, 2 * D), (180, 3 * D)], r=R, l=L, m=M,
                         rpm=RPM)
    moment = record(engine, 1)["moment"]
    couple = math.sqrt(10) * UNIT * D
    assert_allclose(moment["forward_Nm"], couple, rtol=RTOL)
    assert moment["backward_Nm"] == 0.0 and moment["axis_deg"] is None
    assert_allclose([moment["vertical_Nm"], moment["horizontal_Nm"]], [couple, couple], rtol=RTOL)
    # a turning couple's components are 90° apart: yaw peaks a quarter turn after pitch
    assert_allclose((moment["horizontal_deg"] - moment["vertical_deg"]) % 360.0, 90.0, atol=1e-6)


def test_flat_plane_v8_secondary_force_is_horizontal_only():
    """90° V8, flat crank (0°, 180°, 180°, 0°): each bank is an in-line 4 whose four secondary
    forces add, 4·m·r·ω²·B₂·cos 2(θ − γ) along its axis γ = ±45°. Summed over the banks:
    4·m·r·ω²·B₂·(cos(2θ − 90°)·e^{i45°} + cos(2θ + 90°)·e^{−i45°}) = i·4√2·m·r·ω²·B₂·sin 2θ,
    across the bisector only: horizontal 4√2·m·r·ω²·|B₂|, vertical 0."""
    engine = make_engine([-45, 45], [(0, 0), (180, D), (180, 2 * D), (0, 3 * D)], r=R, l=L, m=M,
                         rpm=RPM)
    force = record(engine, 2)["force"]
    expected = 4 * math.sqrt(2) * UNIT * abs(exact_b(R / L, 2))
    assert_allclose(force["horizontal_N"], expected, rtol=1e-9)
    assert force["vertical_N"] == 0.0
    assert_allclose(force["axis_deg"], 90.0, atol=1e-6)


def test_twin_180_primary_couple_pitches_and_the_summary_names_it():
    """180° twin, pitch d, one bank: the primary forces m·r·ω²·cos θ at z = 0 and
    −m·r·ω²·cos θ at z = d make the couple −m·r·ω²·d·cos θ about z̄, along the cylinder axis:
    pitching amplitude m·r·ω²·d, yaw 0; forward and backward halves m·r·ω²·d/2. After an ideal
    counterweight the backward half is left, turning: the summary's main moment order is 1,
    rotating, m·r·ω²·d/2 — the twin does not look balanced."""
    engine = make_engine([0], [(0, 0), (180, D)], r=R, l=L, m=M, rpm=RPM)
    result = balance.analyse(engine)
    moment = result.to_dict()["orders"][0]["moment"]
    assert_allclose(moment["vertical_Nm"], UNIT * D, rtol=RTOL)
    assert moment["horizontal_Nm"] == 0.0
    assert_allclose([moment["forward_Nm"], moment["backward_Nm"]], [UNIT * D / 2] * 2, rtol=RTOL)
    main_moment = result.to_dict()["main_moment_order"]
    assert main_moment["order"] == 1 and main_moment["direction"] == "rotating backward"
    assert_allclose(main_moment["max_Nm"], UNIT * D / 2, rtol=RTOL)
    assert_allclose(result.counterweighted_moment_nm, UNIT * D / 2, rtol=1e-6)
    # without a counterweight the largest moment is the whole couple (all orders: the twin's
    # second orders are in phase and make no couple, so the first order is all of it)
    assert_allclose(result.largest_moment_nm, UNIT * D, rtol=1e-6)

def test_the_summary_of_a_twin_names_its_couple(twin):
    out = run("compare", twin)
    assert out.exit_code == 0, out.output
    summary = out.output.split("Largest free force and moment")[1]
    assert "1: " in summary and "rotating" in summary


@pytest.fixture
def twin(tmp_path):
    """The shared twin configuration (180°, 90 mm apart) in a file."""
    path = tmp_path / "twin.toml"
    path.write_text(TWIN, encoding="utf-8")
    return path


def test_inline_3_primary_couple_is_all_pitch():
    """In-line 3 (0°, 120°, 240° at 0, d, 2d), reciprocating masses only: the primary couple is
    m·r·ω²·d·Re(−e^{iθ} + e^{i(θ + 240°)}), amplitude |−1 + e^{i240°}|·m·r·ω²·d = √3·m·r·ω²·d,
    along the cylinder axis: all pitching, no yaw."""
    engine = make_engine([0], [(0, 0), (120, D), (240, 2 * D)], r=R, l=L, m=M, rpm=RPM)
    moment = record(engine, 1)["moment"]
    assert_allclose([moment["max_Nm"], moment["vertical_Nm"]], [math.sqrt(3) * UNIT * D] * 2,
                    rtol=RTOL)
    assert moment["horizontal_Nm"] == 0.0
    assert_allclose(moment["axis_deg"], 0.0, atol=1e-6)


def test_vertical_key_turns_the_components():
    """The 180° twin with `vertical = 90` (an engine lying on its side): the cylinder axis is
    now horizontal, so its primary couple is all yaw."""
    text = TWIN.replace('firing_order = [1, 2]\n', 'vertical = 90\n')
    engine = balance.loads(text)
    assert_allclose(engine.vertical_axis_rad, math.pi / 2, rtol=1e-15)
    moment = balance.analyse(engine).to_dict()["orders"][0]["moment"]
    assert moment["vertical_Nm"] == 0.0 and moment["horizontal_Nm"] > 0.0
    with pytest.raises(balance.ConfigError, match="vertical"):
        balance.loads(TWIN + 'vertical = "up"\n')


def test_default_vertical_is_the_banks_bisector():
    """In-line: its axis; V: the bisector; banks that add up to nothing (a radial, a boxer):
    the reference axis."""
    assert make_engine([30], [(0, 0)]).vertical_axis_rad == pytest.approx(math.radians(30))
    assert make_engine([-30, 90], [(0, 0)]).vertical_axis_rad == pytest.approx(math.radians(30))
    radial = balance.load("configs/abc-dragonfly.toml")
    assert radial.vertical_axis_rad == 0.0
    assert make_engine([90, 270], [(0, 0)]).vertical_axis_rad == 0.0


def test_a_small_couple_above_the_engines_own_floor_is_reported():
    """In-line 3 with r/l = 0.05/0.22 and d = 0.1 m: its order-10 couple √3·d·m·r·ω²·|B₁₀| is
    about 5.6e-10 of m·r·ω²·n times one metre, below the old floor (1e-9 of that), but its
    forward and backward halves are above the floor on the engine's own lever arm
    (1e-9 · m·r·ω²·n · 0.1 m)."""
    r, l = 0.05, 0.22
    engine = make_engine([0], [(0, 0), (120, D), (240, 2 * D)], r=r, l=l, m=M, rpm=RPM)
    unit = M * r * W**2
    expected = math.sqrt(3) * D * unit * abs(exact_b(r / l, 10))
    assert expected < 1e-9 * unit * 3 * 1.0     # the old floor would have zeroed it
    assert expected / 2 > engine.noise_floor_nm
    assert engine.noise_floor_nm == pytest.approx(1e-9 * unit * 3 * D, rel=1e-12)
    moment = record(engine, 10, max_order=12)["moment"]
    # the FFT's rounding is about 1e-16 of the largest moment, 1e-7 of this one
    assert_allclose(moment["max_Nm"], expected, rtol=1e-5)


@pytest.mark.parametrize("units, force, moment", [
    ("N", 1.0, 1.0), ("kN", 1e3, 1e3), ("MN", 1e6, 1e6),
    ("kgf", 9.80665, 9.80665),
    # 1 lbf = 0.45359237 kg × 9.80665 m/s² = 4.4482216152605 N; 1 lbf·ft = that × 0.3048 m
    ("lbf", 4.4482216152605, 1.3558179483314004),
])
def test_unit_systems_against_hand_conversion(units, force, moment):
    scale = Scale.of(False, units.upper() if units != "MN" else "Mn")
    assert scale.units == units
    assert_allclose(scale.force(force * 123.0, 1.0), 123.0 if units != "N" else 123.0 * force,
                    rtol=1e-15)
    assert_allclose(scale.moment(moment * 7.0), 7.0, rtol=1e-15)
    assert UNIT_SYSTEMS[units][1] == {"N": "N·m", "kN": "kN·m", "MN": "MN·m", "kgf": "kgf·m",
                                      "lbf": "lbf·ft"}[units]


def test_compare_in_lbf_round_trips_to_the_json_in_newtons(twin):
    """The table in lbf and lbf·ft, read back and multiplied by the hand factors, gives the
    JSON's newtons to the four significant figures printed."""
    path = twin
    data = json.loads(run("compare", path, "--format", "json").output)["engines"][0]
    text = run("compare", path, "--units", "LBF").output
    forces, moments = text.split("Free moments by order (in lbf·ft)")

    def first_row(table):
        # columns are set apart by two or more spaces; numbers group thousands by one
        line = next(line for line in table.splitlines() if line.startswith("test twin"))
        return [cell.replace(" ", "") for cell in re.split(r"\s{2,}", line)]

    row = first_row(forces.split("Free forces by order (in lbf)")[1])
    assert row[1] == "2"    # the twin's primary forces cancel: its first row is order 2
    # four significant figures: within 5e-4 of the value
    assert_allclose(float(row[4]) * 4.4482216152605, data["orders"][1]["force"]["max_N"],
                    rtol=5e-4)
    row = first_row(moments)
    assert row[1] == "1"
    assert_allclose(float(row[4]) * 1.3558179483314004, data["orders"][0]["moment"]["max_Nm"],
                    rtol=5e-4)


def test_significant_figures():
    assert significant(4980395.12) == "4 980 000"
    assert significant(4980395.12 / 1e3) == "4 980"
    assert significant(0.214712) == "0.2147"
    assert significant(3.4e-5) == "3.400e-05"
    assert significant(0.0) == "0"
    assert significant(-12.5) == "-12.50"


def test_unit_names_in_any_case_unless_ambiguous():
    assert parse_quantity("1650 RPM", "angular speed") == pytest.approx(1650 * math.pi / 30)
    assert parse_quantity("2 KG", "mass") == 2.0
    # 1 psi = 6894.757293168 Pa; P here is no prefix
    assert parse_quantity("1 PSI", "pressure") == pytest.approx(6894.757293168, rel=1e-15)
    for text, dimension, meant in (("5 Mm", "length", "'mm'"), ("5 mpa", "pressure", "'MPa'"),
                                   ("0.05 M", "length", "'m'"), ("5 MBAR", "pressure", "'mbar'"),
                                   ("1 kg*Mm^2", "moment of inertia", "'kg*mm^2'")):
        with pytest.raises(balance.UnitError) as caught:
            parse_quantity(text, dimension)
        assert "milli" in str(caught.value) and "mega" in str(caught.value)
        assert f"write {meant}" in str(caught.value)
    for name in ("mn", "mN"):
        with pytest.raises(balance.UnitError, match="milli"):
            Scale.of(False, name)
    out = run("compare", "configs/inline-4-car.toml", "--units", "mn")
    assert out.exit_code == 2 and "milli" in out.output and "Traceback" not in out.output


def test_percentages_beyond_a_thousand_are_ratios(twin):
    """A nearly balanced reference (an in-line 6) against a twin: the twin's share is a
    multiple (×), not "6199.2 %"."""
    out = run("compare", "--reference", "In-line 6", "configs/tanaka-part3", twin)
    assert out.exit_code == 0, out.output
    row = [line for line in out.output.split("Largest free force and moment")[1].splitlines()
           if line.startswith("test twin")][0]
    assert "×" in row and " %" not in row


def test_speed_option_scales_forces_by_the_square(twin):
    """--speed doubles ω: every force and moment × 4 (ω² law), exactly."""
    path = twin
    slow = json.loads(run("compare", path, "--format", "json").output)["engines"][0]
    fast = json.loads(run("compare", path, "--format", "json", "--speed", "6000 rpm").output)
    fast = fast["engines"][0]
    assert fast["speed_rpm"] == pytest.approx(6000.0)
    assert_allclose(fast["orders"][1]["force"]["max_N"], 4 * slow["orders"][1]["force"]["max_N"],
                    rtol=1e-12)
    assert_allclose(fast["orders"][0]["moment"]["max_Nm"],
                    4 * slow["orders"][0]["moment"]["max_Nm"], rtol=1e-12)
    for command in ("counterweight", "torque"):
        out = run(command, path, "--speed", "0 rpm")
        assert out.exit_code == 1 and "--speed" in out.output and "Traceback" not in out.output


def test_engine_replace_is_checked():
    engine = balance.loads(TWIN)
    assert engine.replace(speed_rad_s=100.0).speed_rad_s == 100.0
    with pytest.raises(balance.ModelError, match="not a field"):
        engine.replace(speed=1.0)
    with pytest.raises(balance.ModelError, match="rod_length_m"):
        engine.replace(rod_length_m=0.01)


def test_json_version_2_and_regress_reads_version_1(monkeypatch):
    """New keys only, and a baseline written by version 1 still regresses clean."""
    monkeypatch.chdir(ROOT)   # the baselines name their configurations from the root
    data = json.loads(run("compare", "configs", "--format", "json").output)
    assert data["balance_version"] == 2
    engine = data["engines"][0]
    for key in ("vertical_deg", "largest_moment_Nm", "counterweighted_moment_Nm",
                "main_force_order", "main_moment_order", "noise_floor_N", "noise_floor_Nm"):
        assert key in engine
    # compare-v1.json is the golden baseline as version 1 wrote it, kept unchanged
    old = ROOT / "tests" / "golden" / "compare-v1.json"
    assert json.loads(old.read_text(encoding="utf-8"))["balance_version"] == 1
    out = run("regress", old)
    assert out.exit_code == 0, out.output


def test_every_command_that_prints_forces_takes_units(twin, tmp_path):
    """--units kN on counterweight, torque, regress and report: headings in kN and kN·m, and
    the figures a thousandth of the newtons (hand factor 1e3)."""
    out = run("counterweight", twin, "--units", "kn")
    assert out.exit_code == 0 and "(kN)" in out.output and "(kN·m)" in out.output
    torque = run("torque", twin, "--units", "kN")
    assert torque.exit_code == 0 and "Range ΔC (kN·m)" in torque.output
    newtons = json.loads(run("torque", twin, "--format", "json").output)["engines"][0]
    row = next(line for line in torque.output.splitlines() if line.startswith("inertia"))
    shown = float(re.split(r"\s{2,}", row)[2].replace(" ", ""))
    assert_allclose(shown * 1e3, newtons["inertia"]["max_Nm"], rtol=5e-4)
    baseline = tmp_path / "base.json"
    baseline.write_text(run("compare", twin, "--format", "json").output, encoding="utf-8")
    heavier = tmp_path / "heavier.toml"
    heavier.write_text(TWIN.replace('"500 g"', '"600 g"'), encoding="utf-8")
    moved = run("regress", baseline, heavier, "--units", "kN")
    assert moved.exit_code == 1 and "kN for *_N and kN·m for *_Nm" in moved.output
    report = run("report", twin, "--output", tmp_path / "r", "--units", "kN")
    assert report.exit_code == 0, report.output
    assert "Mean (kN·m)" in (tmp_path / "r" / "report.md").read_text(encoding="utf-8")


def test_search_takes_units_and_speed(tmp_path):
    """--speed on a template: the listed arrangement's forces follow ω² (×4 at twice the
    speed), and --write writes the speed asked for."""
    template = "templates/inline-3-2stroke.toml"
    slow = json.loads(run("search", template, "--top", "1", "--format", "json").output)
    fast = run("search", template, "--top", "1", "--format", "json", "--speed", "2x")
    assert fast.exit_code == 1 and "--speed" in fast.output
    base = balance.load_template(template).speed_rad_s * 30 / math.pi
    fast = json.loads(run("search", template, "--top", "1", "--format", "json",
                          "--speed", f"{2 * base} rpm", "--write", tmp_path).output)
    a, b = slow["results"][0], fast["results"][0]
    assert_allclose(b["orders"][0]["moment"]["max_Nm"], 4 * a["orders"][0]["moment"]["max_Nm"],
                    rtol=1e-12)
    assert balance.load(tmp_path / "arrangement-01.toml").speed_rad_s == pytest.approx(
        2 * base * math.pi / 30, rel=1e-12)
    table = run("search", template, "--top", "1", "--units", "kN")
    assert table.exit_code == 0 and "(kN·m)" in table.output


def test_regress_checks_the_version_2_quantities(twin, tmp_path):
    """Turning the engine's vertical by 60° moves no ellipse but every vertical and horizontal
    component: the twin's couple m·r·ω²·d was all pitch and is now cos 60° = ½ of it pitch."""
    baseline = tmp_path / "base.json"
    baseline.write_text(run("compare", twin, "--format", "json").output, encoding="utf-8")
    turned = tmp_path / "turned.toml"
    turned.write_text("vertical = 60\n" + TWIN, encoding="utf-8")
    out = run("regress", baseline, turned, "--format", "json")
    assert out.exit_code == 1
    rows = {(r["order"], r["quantity"]): r for r in json.loads(out.output)["rows"]}
    assert_allclose(rows[(1, "moment.vertical_Nm")]["now"],
                    0.5 * rows[(1, "moment.vertical_Nm")]["baseline"], rtol=1e-12)
    assert (None, "vertical_deg") in rows and (1, "moment.max_Nm") not in rows


def test_a_baseline_written_at_another_speed_is_checked_at_that_speed(twin, tmp_path):
    baseline = tmp_path / "fast.json"
    baseline.write_text(run("compare", twin, "--speed", "5000 rpm", "--format", "json").output,
                        encoding="utf-8")
    assert json.loads(baseline.read_text(encoding="utf-8"))["speed_override_rpm"] == 5000.0
    out = run("regress", baseline)
    assert out.exit_code == 0 and "nothing moved" in out.output and "1 engine checked" in out.output
    broken = json.loads(baseline.read_text(encoding="utf-8"))
    broken["speed_override_rpm"] = -1
    baseline.write_text(json.dumps(broken), encoding="utf-8")
    out = run("regress", baseline)
    assert out.exit_code == 1 and "speed_override_rpm" in out.output


def test_one_plane_shafts_say_the_couple_is_left(tmp_path):
    """A V-twin with its two cylinders 40 mm apart on one throw: one correction plane (the
    throw's) cannot hold the two masses a couple needs; the output says so, and with two
    planes the order-1 moment is gone."""
    config = tmp_path / "vt.toml"
    config.write_text(TWIN.replace('firing_order = [1, 2]\n', "").replace(
        "[[banks]]\nangle = 0\n", "[[banks]]\nangle = -22.5\n[[banks]]\nangle = 22.5\n").split(
        "[[throws]]")[0] + '[[throws]]\nphase = 0\n\n[[cylinders]]\nnumber = 1\nbank = 1\n'
        'throw = 1\nz = "0 mm"\n[[cylinders]]\nnumber = 2\nbank = 2\nthrow = 1\nz = "40 mm"\n',
        encoding="utf-8")
    one = run("counterweight", config, "--max-order", "1", "--shafts", "1")
    assert one.exit_code == 0, one.output
    assert "One correction plane cannot cancel a couple" in one.output
    two = run("counterweight", config, "--max-order", "1", "--shafts", "1",
              "--planes", "0 mm,40 mm", "--format", "json")
    left = json.loads(two.output)["engines"][0]["after_shafts"]["orders"][0]
    assert left["moment"]["max_Nm"] == 0.0 and left["force"]["max_N"] == 0.0
