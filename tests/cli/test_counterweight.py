"""balance counterweight: its options, errors, JSON contract and tables."""

import json
import math
import shutil

import pytest
from numpy.testing import assert_allclose

from balance_cli import load
from tests.support import (
    CONFIGS,
    JUMO,
    TWIN,
    V12,
    check_refused,
    exact_b,
    invoke,
    snapshot,
    twin_file,
)

ROTARY = CONFIGS / "clerget-rotary.toml"
ROTARY_CASES = [
    ("antivibrateur-rotary", ["counterweight", "--antivibrateur"], "with a turning crank"),
    (
        "test-masses-rotary",
        ["counterweight", "--test-masses"],
        "--test-masses does not apply to a rotary",
    ),
    (
        "balance-factor-rotary",
        ["counterweight", "--balance-factor", "0.5"],
        "--balance-factor does not apply to a rotary",
    ),
]
TWIN_270 = """name = "270° twin"
cycle = 4
speed = "6000 rpm"
crank_radius = "35 mm"
rod_length = "120 mm"
[masses]
reciprocating = "400 g"
[[banks]]
angle = 0
[[throws]]
phase = 0
z = "0 mm"
[[throws]]
phase = 90
z = "80 mm"
"""


@pytest.mark.parametrize(
    "args, words",
    [
        (["--planes", "1,9"], "--planes names throw 9, but the engine has throws 1 to 6"),
        (["--planes", "1,1"], "--planes coincide"),
        (["--planes", "1,two"], "--planes: cannot read 'two'"),
        (["--radius", "0 mm"], "--radius must be greater than zero"),
        (["--radius", "-5 mm"], "--radius must be greater than zero"),
        (["--radius", "5 kg"], "is a mass, but a length is needed"),
        (["--shafts", "x"], "give orders as whole numbers"),
        (["--antivibrateur"], "single-throw engine"),
        (
            ["--shaft-offset", "1 mm,2 mm"],
            "--shaft-offset places balancer shafts, but no shaft order was asked for",
        ),
        (["--shafts", "6", "--shaft-offset", "3:1 mm,2 mm"], "--shaft-offset names speed ratio 3"),
        (["--shafts", "6", "--shaft-offset", "1 mm"], "give LATERAL,VERTICAL"),
        (["--shafts", "6", "--shaft-offset", "x:1 mm,1 mm"], "must be a whole number"),
        (["--shafts", "6", "--shaft-offset", "6:1 kg,1 mm"], "is a mass, but a length is needed"),
        (
            ["--shafts", "6", "--shaft-offset", "1 mm,1 mm", "--shaft-offset", "2 mm,2 mm"],
            "every shaft is placed twice",
        ),
    ],
)
def test_errors(tmp_path, args, words):
    out = tmp_path / "cw.json"
    result = invoke("counterweight", V12, *args, "--format", "json", "--output", out)
    assert result.exit_code != 0
    assert words in result.output and isinstance(result.exception, SystemExit)
    assert not out.exists()


def test_json_contract(tmp_path):
    out = tmp_path / "cw.json"
    result = invoke(
        "counterweight",
        V12,
        "--planes",
        "1,6",
        "--shafts",
        "6",
        "--test-masses",
        "--max-order",
        "8",
        "--format",
        "json",
        "--output",
        out,
    )
    assert result.exit_code == 0, result.output
    (engine,) = json.loads(out.read_text(encoding="utf-8"))["engines"]
    assert [c["throw"] for c in engine["counterweights"]] == [1, 6]
    assert set(engine["counterweights"][0]) == {"z_m", "throw", "mass_kg", "radius_m", "angle_deg"}
    assert [o["order"] for o in engine["residual"]["orders"]] == list(range(1, 9))
    assert engine["residual"]["orders"][0]["force"]["max_N"] == 0.0
    assert {s["speed_ratio"] for s in engine["shafts"]} == {6, -6}
    assert engine["after_shafts"]["orders"][5]["force"]["max_N"] == 0.0
    assert engine["test_masses_kg"] == pytest.approx([5.96] * 6, rel=1e-9)


def test_table_and_csv():
    table = invoke("counterweight", CONFIGS / "bramo-323.toml", "--antivibrateur", "--units", "kgf")
    assert table.exit_code == 0, table.output
    assert "M·e = 0.04408 kg·m" in table.output
    csv_text = invoke("counterweight", V12, "--format", "csv").output
    assert csv_text.startswith("engine,config,item,quantity,value,unit")
    assert "counterweight 2,mass," in csv_text


def test_nothing_left_in_words():
    """Orders 2, 4, 6, 8 are all an in-line 4 has: after their shafts nothing is left, said
    in words, not as an empty table; centred shafts are said to make no rolling moment."""
    result = invoke("counterweight", CONFIGS / "inline-4-car.toml", "--shafts", "2,4,6,8")
    assert result.exit_code == 0, result.output
    assert "After the shafts, nothing is left up to order 8" in result.output
    assert "Left after the shafts" not in result.output
    assert "Rolling moment about the crank axis of the shafts: none" in result.output
    assert "kg·mm" not in result.output
    primary = invoke("counterweight", CONFIGS / "inline-4-car.toml", "--shafts", "1,2")
    assert "Order 1: no shaft needed, already zero." in primary.output
    six = invoke("counterweight", CONFIGS / "tanaka-part3" / "3-inline-6.toml", "--max-order", "5")
    assert six.exit_code == 0, six.output
    assert "After the counterweights, nothing is left up to order 5" in six.output


def test_shaft_table_and_rolling_moment():
    """The Lanchester pair at ±100 mm lateral and +50/−50 mm: each shaft's m·e in kg·m
    (m_rec·r·B2/2 = 0.003640 kg·m), and the pair's couple |P|·0.1 m, P = 2·B2·m·r·ω²."""
    engine = load(CONFIGS / "inline-4-car.toml")
    lam = exact_b(engine.crank_radius_m / engine.rod_length_m, 2)
    p = 2 * lam * engine.mean_reciprocating_kg * engine.crank_radius_m * engine.speed_rad_s**2
    result = invoke(
        "counterweight",
        CONFIGS / "inline-4-car.toml",
        "--shafts",
        "2",
        "--shaft-offset",
        "+2:100 mm,50 mm",
        "--shaft-offset",
        "-2:-100 mm,-50 mm",
    )
    assert result.exit_code == 0, result.output
    text = result.output
    assert "m·e (kg·m)" in text and "0.003640" in text and "100, 50" in text
    together = next(line for line in text.splitlines() if "together" in line)
    assert float(together.split()[-2]) == pytest.approx(p * 0.1, rel=1e-3)


def test_json_balancer_shafts(tmp_path):
    out = tmp_path / "cw.json"
    result = invoke(
        "counterweight",
        CONFIGS / "inline-4-car.toml",
        "--shafts",
        "2",
        "--shaft-offset",
        "120 mm,-80 mm",
        "--shaft-offset",
        "-2:0 mm,0 mm",
        "--format",
        "json",
        "--output",
        out,
    )
    assert result.exit_code == 0, result.output
    (engine,) = json.loads(out.read_text(encoding="utf-8"))["engines"]
    assert engine["shaft_orders"] == [2]
    # the old per-mass list, unchanged
    assert [set(s) for s in engine["shafts"]] == [
        {"order", "speed_ratio", "mass_eccentricity_kgm", "phase_deg", "z_m"}
    ] * 2
    plus, minus = engine["balancer_shafts"]
    assert set(plus) == {
        "speed_ratio",
        "order",
        "turning",
        "offset_m",
        "masses",
        "force_N",
        "rolling_moment",
    }
    assert (plus["speed_ratio"], plus["turning"], minus["speed_ratio"], minus["turning"]) == (
        2,
        "with",
        -2,
        "against",
    )
    assert plus["offset_m"] == pytest.approx({"lateral": 0.12, "vertical": -0.08})
    assert minus["offset_m"] == {"lateral": 0.0, "vertical": 0.0}
    assert set(plus["masses"][0]) == {"mass_eccentricity_kgm", "phase_deg", "z_m"}
    assert set(plus["rolling_moment"]) == {"order", "cos_Nm", "sin_Nm", "amplitude_Nm", "phase_deg"}
    assert minus["rolling_moment"]["amplitude_Nm"] == 0.0
    (pair,) = engine["shaft_rolling_moments"]
    assert pair["speed_ratios"] == [2, -2]
    # only the +2 shaft is off the axis: the pair's moment is its own
    assert pair["amplitude_Nm"] == pytest.approx(plus["rolling_moment"]["amplitude_Nm"], rel=1e-12)
    assert pair["amplitude_Nm"] == pytest.approx(plus["force_N"] * math.hypot(0.12, 0.08), rel=1e-9)
    csv_text = invoke(
        "counterweight", CONFIGS / "inline-4-car.toml", "--shafts", "2", "--format", "csv"
    ).output
    assert "balancer shaft 1 mass 1,mass_eccentricity," in csv_text
    assert "shafts +2 -2 rolling moment order 2,amplitude,0.0,N·m" in csv_text


def test_270_twin_reports_one_shaft_with_two_masses(tmp_path):
    """As test_270_twin_…: one −1 shaft, masses m·r/2 = 0.4·0.035/2 = 0.007 kg·m at 180° (throw
    1's plane) and 90° (throw 2's)."""
    config = tmp_path / "twin.toml"
    config.write_text(TWIN_270, encoding="utf-8")
    result = invoke("counterweight", config, "--shafts", "1", "--format", "json")
    assert result.exit_code == 0, result.output
    (engine,) = json.loads(result.output)["engines"]
    (shaft,) = engine["balancer_shafts"]
    assert shaft["speed_ratio"] == -1 and shaft["turning"] == "against"
    assert_allclose(
        [m["mass_eccentricity_kgm"] for m in shaft["masses"]], [0.007, 0.007], rtol=1e-9
    )
    assert_allclose([m["phase_deg"] for m in shaft["masses"]], [180.0, 90.0], atol=1e-9)
    assert_allclose([m["z_m"] for m in shaft["masses"]], [0.0, 0.08], atol=1e-12)
    assert engine["after_shafts"]["orders"][0]["force"]["max_N"] == 0.0
    assert engine["after_shafts"]["orders"][0]["moment"]["max_Nm"] == 0.0


@pytest.mark.parametrize(
    "args, words", [case[1:] for case in ROTARY_CASES], ids=[case[0] for case in ROTARY_CASES]
)
def test_rotary_refuses_what_needs_a_turning_crank(tmp_path, args, words):
    config = tmp_path / "rotary.toml"
    shutil.copy(ROTARY, config)
    before = snapshot(tmp_path)
    check_refused(
        invoke(args[0], config, *args[1:], "-o", tmp_path / "o.txt"), 1, words, before, tmp_path
    )


@pytest.mark.parametrize(
    "args, code, words",
    [
        (["--shafts", ""], 2, "give orders as whole numbers"),
        (["--planes", "-1"], 1, "--planes: cannot read '-1': give throw numbers"),
        (["--planes", "40 µm"], 1, "unknown unit 'µm'"),
    ],
)
def test_more_bad_counterweight_options(tmp_path, args, code, words):
    config = twin_file(tmp_path)
    before = snapshot(tmp_path)
    check_refused(invoke("counterweight", config, *args), code, words, before, tmp_path)


def test_the_counterweight_table_says_why_a_rotary_gets_no_test_masses():
    result = invoke("counterweight", CONFIGS / "clerget-rotary.toml", "--test-masses")
    assert result.exit_code == 1
    assert (
        "--test-masses does not apply to a rotary engine: its crank stands still" in result.stderr
    )


def test_a_plane_in_a_foreign_digit_is_one_error_line(tmp_path):
    result = invoke("counterweight", CONFIGS / "inline-4-car.toml", "--planes", "¹")
    assert result.exit_code == 1 and result.stderr.count("\n") == 1
    assert "--planes: cannot read '¹'" in result.stderr


def test_shafts_for_a_zero_order_say_none_are_needed():
    result = invoke("counterweight", CONFIGS / "tanaka-part3" / "3-inline-6.toml", "--shafts", "3")
    assert result.exit_code == 0
    assert "Balancer shafts: none needed; the orders asked for are already zero." in result.stdout


def test_one_plane_shafts_say_the_couple_is_left(tmp_path):
    """A V-twin with its two cylinders 40 mm apart on one throw: one correction plane (the
    throw's) cannot hold the two masses a couple needs; the output says so, and with two
    planes the order-1 moment is gone."""
    config = tmp_path / "vt.toml"
    config.write_text(
        TWIN.replace("firing_order = [1, 2]\n", "")
        .replace("[[banks]]\nangle = 0\n", "[[banks]]\nangle = -22.5\n[[banks]]\nangle = 22.5\n")
        .split("[[throws]]")[0]
        + "[[throws]]\nphase = 0\n\n[[cylinders]]\nnumber = 1\nbank = 1\n"
        'throw = 1\nz = "0 mm"\n[[cylinders]]\nnumber = 2\nbank = 2\nthrow = 1\nz = "40 mm"\n',
        encoding="utf-8",
    )
    one = invoke("counterweight", config, "--max-order", "1", "--shafts", "1")
    assert one.exit_code == 0, one.output
    assert "One correction plane cannot cancel a couple" in one.output
    two = invoke(
        "counterweight",
        config,
        "--max-order",
        "1",
        "--shafts",
        "1",
        "--planes",
        "0 mm,40 mm",
        "--format",
        "json",
    )
    left = json.loads(two.output)["engines"][0]["after_shafts"]["orders"][0]
    assert left["moment"]["max_Nm"] == 0.0 and left["force"]["max_N"] == 0.0


def test_counterweight_on_a_folder_passes_over_engines_with_several_crankshafts():
    from click.testing import CliRunner

    from balance_cli.cli import main

    result = CliRunner().invoke(
        main, ["counterweight", "configs/today/opposed-piston", "configs/today/vr"]
    )
    assert result.exit_code == 0, result.output
    assert "junkers-jumo-205.toml: 2 crankshafts" in result.output
    assert "VW VR6" in result.output
    alone = CliRunner().invoke(main, ["counterweight", JUMO])
    assert alone.exit_code == 1 and "has 2 crankshafts" in alone.output
