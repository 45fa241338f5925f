"""balance compare: its JSON contract, tables, references and percentages."""

import json
import re

import pytest
from numpy.testing import assert_allclose

from tests.support import (
    BOXER,
    CONFIGS,
    PART3,
    check_refused,
    invoke,
    replaced,
    snapshot,
    twin_file,
)


def test_unknown_reference_lists_the_engines():
    result = invoke("compare", PART3, "--reference", "Zeppelin")
    assert (
        result.exit_code != 0
        and "matches no engine" in result.output
        and "60° W12" in result.output
    )


def test_compare_json_contract(tmp_path):
    out = tmp_path / "deep" / "compare.json"
    result = invoke("compare", PART3, "--format", "json", "--output", out, "--max-order", "6")
    assert result.exit_code == 0, result.output
    assert [p.name for p in out.parent.iterdir()] == ["compare.json"]  # no temporary left behind
    document = json.loads(out.read_text(encoding="utf-8"))
    engines = document["engines"]
    assert len(engines) == 9
    v8 = engines[0]
    for key in (
        "name",
        "config",
        "cylinders",
        "cycle",
        "frame",
        "speed_rpm",
        "unit_force_N",
        "firing",
        "orders",
        "percent_of_reference",
    ):
        assert key in v8
    assert set(v8["firing"]) >= {"order", "angles_deg", "intervals_deg", "uniform"}
    assert [o["order"] for o in v8["orders"]] == [1, 2, 3, 4, 5, 6]
    assert set(v8["orders"][0]["force"]) >= {
        "forward_N",
        "forward_deg",
        "backward_N",
        "backward_deg",
        "max_N",
        "min_N",
    }
    assert set(v8["orders"][0]["moment"]) >= {
        "forward_Nm",
        "forward_deg",
        "backward_Nm",
        "backward_deg",
        "max_Nm",
        "min_Nm",
    }
    assert v8["orders"][0]["force"]["max_N"] == 0.0  # zero orders are listed, as exact zeros
    second = v8["orders"][1]["force"]["max_N"] / v8["unit_force_N"] / v8["cylinders"]
    assert abs(second - 0.215) < 0.0005
    assert v8["speed_rpm"] == pytest.approx(1250.0, rel=1e-12)
    assert v8["firing"]["intervals_deg"] == pytest.approx([90.0] * 8, abs=1e-6)
    assert [
        round(e["percent_of_reference"])
        for e in engines
        if e["name"] in ("60° W12", "9-cylinder rotary")
    ] == [71, 16]


def test_compare_table_markdown_csv():
    table = invoke("compare", PART3)
    assert table.exit_code == 0
    assert "90° V8, flat crank" in table.output and "0.2147" in table.output
    assert "% of 90° V8, flat crank" in table.output
    markdown = invoke("compare", PART3, "--format", "markdown")
    assert "| Engine" in markdown.output
    csv_text = invoke("compare", PART3 / "2a-w12-60.toml", "--format", "csv").output
    header, *rows = csv_text.strip().splitlines()
    assert header.startswith("engine,config,order,force_forward_per_cyl")
    assert len(rows) == 8
    absolute = invoke("compare", PART3 / "2a-w12-60.toml", "--units", "kgf")
    assert "F max (kgf)" in absolute.output


def test_reference_by_prefix_changes_the_percentages():
    result = invoke("compare", PART3, "--reference", "60° W12,")
    assert result.exit_code == 0, result.output
    assert "% of 60° W12, link rods on…" in result.output  # at a word


def test_ambiguous_reference_lists_only_the_matches(tmp_path):
    for name in ("Alpha one", "Alpha two", "Beta"):
        (tmp_path / f"{name.replace(' ', '_')}.toml").write_text(
            replaced('"test twin"', f'"{name}"'), encoding="utf-8"
        )
    before = snapshot(tmp_path)
    result = invoke("compare", tmp_path, "--reference", "alpha", "-o", tmp_path / "o.txt")
    check_refused(
        result,
        1,
        "--reference 'alpha' matches several engines: Alpha one; Alpha two;",
        before,
        tmp_path,
    )
    assert "Beta" not in result.stderr


def test_two_engines_of_one_name_are_refused_by_compare(tmp_path):
    config = twin_file(tmp_path)
    before = snapshot(tmp_path)
    check_refused(
        invoke("compare", config, config, "-o", tmp_path / "o.json"),
        1,
        "name 'test twin' more than once",
        before,
        tmp_path,
    )


def test_percent_of_a_balanced_reference_is_not_available(tmp_path):
    boxer = tmp_path / "boxer.toml"
    boxer.write_text(BOXER, encoding="utf-8")
    result = invoke("compare", boxer, PART3 / "1a-v8-90-flat.toml", "--format", "json")
    engines = json.loads(result.stdout)["engines"]
    assert engines[0]["counterweighted_resultant_N"] == 0.0
    assert [e["percent_of_reference"] for e in engines] == [None, None]
    table = invoke("compare", boxer, PART3 / "1a-v8-90-flat.toml").stdout
    assert "n/a" in table and "e+" not in table
    # the other way round the boxer is 0 % of the V8
    engines = json.loads(
        invoke("compare", PART3 / "1a-v8-90-flat.toml", boxer, "--format", "json").stdout
    )["engines"]
    assert [e["percent_of_reference"] for e in engines] == [100.0, 0.0]


def test_every_angle_of_the_library_is_in_its_range():
    document = json.loads(
        invoke("compare", CONFIGS, "--format", "json", "--max-order", "12").stdout
    )
    for engine in document["engines"]:
        for order in engine["orders"]:
            for part, unit in (("force", "N"), ("moment", "Nm")):
                values = order[part]
                floor = engine[f"noise_floor_{unit}"]
                # a circle, or nothing, has no axis
                if values[f"forward_{unit}"] == 0.0 or values[f"backward_{unit}"] == 0.0:
                    assert values["axis_deg"] is None
                else:
                    assert 0.0 <= values["axis_deg"] < 180.0
                assert (
                    0.0 <= values["forward_deg"] < 360.0 and 0.0 <= values["backward_deg"] < 360.0
                )
                assert values[f"min_{unit}"] == 0.0 or values[f"min_{unit}"] >= floor
        assert all(0.0 <= a < 180.0 * engine["cycle"] for a in engine["firing"]["angles_deg"])


def test_the_summary_of_a_twin_names_its_couple(twin):
    out = invoke("compare", twin)
    assert out.exit_code == 0, out.output
    summary = out.output.split("Largest free force and moment")[1]
    assert "1: " in summary and "rotating" in summary


def test_compare_in_lbf_round_trips_to_the_json_in_newtons(twin):
    """The table in lbf and lbf·ft, read back and multiplied by the hand factors, gives the
    JSON's newtons to the four significant figures printed."""
    path = twin
    data = json.loads(invoke("compare", path, "--format", "json").output)["engines"][0]
    text = invoke("compare", path, "--units", "LBF").output
    forces, moments = text.split("Free moments by order (in lbf·ft)")

    def first_row(table):
        # columns are set apart by two or more spaces; numbers group thousands by one
        line = next(line for line in table.splitlines() if line.startswith("test twin"))
        return [cell.replace(" ", "") for cell in re.split(r"\s{2,}", line)]

    row = first_row(forces.split("Free forces by order (in lbf)")[1])
    assert row[1] == "2"  # the twin's primary forces cancel: its first row is order 2
    # four significant figures: within 5e-4 of the value
    assert_allclose(float(row[4]) * 4.4482216152605, data["orders"][1]["force"]["max_N"], rtol=5e-4)
    row = first_row(moments)
    assert row[1] == "1"
    assert_allclose(
        float(row[4]) * 1.3558179483314004, data["orders"][0]["moment"]["max_Nm"], rtol=5e-4
    )


def test_percentages_beyond_a_thousand_are_ratios(twin):
    """A nearly balanced reference (an in-line 6) against a twin: the twin's share is a
    multiple (×), not "6199.2 %"."""
    out = invoke("compare", "--reference", "In-line 6", "configs/tanaka-part3", twin)
    assert out.exit_code == 0, out.output
    row = [
        line
        for line in out.output.split("Largest free force and moment")[1].splitlines()
        if line.startswith("test twin")
    ][0]
    assert "×" in row and " %" not in row


CROSS_PLANE_4 = """\
name = "Cross-plane in-line 4"
cycle = 4
speed = "10000 rpm"
crank_radius = "26 mm"
rod_length = "100 mm"
firing_order = [1, 3, 2, 4]

[masses]
reciprocating = "300 g"

[[banks]]
angle = 0

[[throws]]
phase = 0
z = "0 mm"
[[throws]]
phase = 270
z = "80 mm"
[[throws]]
phase = 90
z = "160 mm"
[[throws]]
phase = 180
z = "240 mm"
"""


def test_uneven_intervals_are_printed_in_firing_order(tmp_path):
    """A cross-plane in-line 4 (Yamaha's R1 crank) with throws 0, 270, 90, 180° firing
    1-3-2-4. By hand: a cylinder on a throw of phase β reaches top dead centre at θ = −β
    (mod 360°): cylinder 1 at 0° and 360°, 3 at 270° and 630°, 2 at 90° and 450°, 4 at 180°
    and 540°. Each fires at its first TDC after the one before: 1 at 0, 3 at 270, 2 at 450, 4
    at 540, and 1 again at 720: intervals 270, 180, 90, 180, printed as the sequence (the
    table said "90.0 to 270.0")."""
    path = tmp_path / "r1.toml"
    path.write_text(CROSS_PLANE_4, encoding="utf-8")
    for fmt in ("table", "markdown"):
        result = invoke("compare", path, "--format", fmt)
        assert result.exit_code == 0, result.output
        row = next(line for line in result.output.splitlines() if "1-3-2-4" in line)
        assert "270-180-90-180" in row and " to " not in row
    firing = json.loads(invoke("compare", path, "--format", "json").output)["engines"][0]["firing"]
    assert_allclose(firing["intervals_deg"], [270, 180, 90, 180], atol=1e-4)  # TDC search
    # throws 0, 180, 0, 180 firing 1-2-3-4 (TDCs 0, 180, 360, 540): every 180° (a flat crank)
    flat = CROSS_PLANE_4.replace("270", "180", 1).replace("phase = 90", "phase = 0")
    path.write_text(flat.replace("[1, 3, 2, 4]", "[1, 2, 3, 4]"), encoding="utf-8")
    row = next(line for line in invoke("compare", path).output.splitlines() if "1-2-3-4" in line)
    assert row.rstrip().endswith("every 180")


@pytest.mark.parametrize(
    "power, kilowatts",
    [
        ("14 280 kW", 14_280.0),
        # 19 000 mechanical horsepower of 550 ft·lbf/s: 19 000 × 745.69987158227 W
        ("19 000 hp", 19_000 * 550 * 0.3048 * 0.45359237 * 9.80665 / 1e3),
        ("14\u202f280 kW", 14_280.0),
    ],
)
def test_power_option_as_its_help_writes_it(power, kilowatts):
    """The help's own examples, thousands set apart by a space: read, and the power related
    unbalance refers to them as given with the analysis ("option", shown "(--power)"), the
    PRU being each moment over that power."""
    marine = CONFIGS / "marine-6-2stroke.toml"
    result = invoke("compare", marine, "--power", power, "--format", "json")
    assert result.exit_code == 0, result.output
    record = json.loads(result.output)["engines"][0]
    assert_allclose(record["power_kW"], kilowatts, rtol=1e-15)
    pru = record["pru"]
    assert pru["power_source"] == "option"
    second = next(e for e in pru["orders"] if e["order"] == 2)
    assert_allclose(second["vertical_Nm_per_kW"], second["vertical_Nm"] / kilowatts, rtol=1e-14)
    table = invoke("compare", marine, "--power", power).output
    assert "(--power)" in table


def test_power_of_the_library_comparison():
    """balance.compare(power_w=...) is what --power passes; the engines keep their own power."""
    import balance_cli as balance

    result = balance.analyse(balance.load(CONFIGS / "marine-6-2stroke.toml"))
    own = balance.compare([result]).to_dict()["engines"][0]["pru"]
    assert own["power_source"] == "given"
    given = balance.compare([result], power_w=1.2e7).to_dict()["engines"][0]
    assert given["pru"]["power_source"] == "option" and given["power_kW"] == 12_000.0
    assert result.engine.power_w is not None and result.engine.power_w != 1.2e7
    for bad in (0.0, -1.0, float("nan"), "12 MW", 1e300):
        with pytest.raises(balance.AnalysisError, match="power_w"):
            balance.compare([result], power_w=bad)


def test_power_in_groups_that_are_not_threes_is_refused(tmp_path):
    """'14 28 kW' is not fourteen hundred and twenty-eight: one line naming --power and the
    rule, status 1, no traceback, no output file."""
    before = snapshot(tmp_path)
    result = invoke(
        "compare", CONFIGS / "marine-6-2stroke.toml", "--power", "14 28 kW", "-o", tmp_path / "x"
    )
    check_refused(result, 1, "--power: cannot read '14 28 kW'", before, tmp_path)
    assert "in groups of three" in result.stderr
