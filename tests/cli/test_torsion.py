"""balance torsion: its tables, JSON, CSV and pictures, and its options."""

import json

import pytest
from numpy.testing import assert_allclose

from tests.support import INLINE6, TORSION6, TORSION_ORDERS, invoke


def test_tables_json_csv_and_pictures(tmp_path):
    path = tmp_path / "six.toml"
    path.write_text(
        INLINE6 + '\n[gas]\nbore = "105 mm"\ncompression_ratio = 17\nimep = "15 bar"\n' + TORSION6
    )
    result = invoke("torsion", path, "--speeds", "1000:2500:50")
    assert result.exit_code == 0, result.output
    for heading in (
        "Natural modes",
        "Phase-vector sums",
        "Criticals in the speed range",
        "Largest vibratory torque per section",
    ):
        assert heading in result.output
    result = invoke("torsion", path, "--speeds", "1000:2500:50", "--format", "json")
    document = json.loads(result.output)
    (entry,) = document["engines"]
    assert len(entry["response"]) == 31
    first = entry["response"][0]["sections"][0]
    assert set(first) == {"section", "torque_Nm", "stress_Pa", "orders"}
    assert [o["order"] for o in first["orders"]] == list(TORSION_ORDERS)
    assert {
        "mode",
        "frequency_Hz",
        "frequency_cpm",
        "shape",
        "throw_amplitudes",
        "phase_vector_sums",
    } <= set(entry["modes"][0])
    result = invoke(
        "torsion", path, "--speeds", "1000,2000", "--format", "csv", "--plot", tmp_path / "pics"
    )
    lines = result.stdout.splitlines()
    assert lines[0] == (
        "engine,config,speed_rpm,section,order,torque_Nm,stress_Pa,free_end_deg,"
        "free_end_elastic_deg"
    )
    # 2 speeds × 7 sections (pulley, 6 throws, flywheel) × (24 orders + all)
    assert len(lines) == 1 + 2 * 7 * 25
    assert sorted(p.name for p in (tmp_path / "pics").iterdir()) == [
        "six-campbell.png",
        "six-modes.png",
        "six-torque.png",
    ]


def test_bad_speeds(tmp_path):
    path = tmp_path / "six.toml"
    path.write_text(INLINE6 + TORSION6)
    result = invoke("torsion", path, "--speeds", "2400:600:25")
    assert result.exit_code == 2 and "--speeds" in result.output


def test_folder_passes_over_engines_without_torsion(tmp_path):
    (tmp_path / "six.toml").write_text(INLINE6 + TORSION6)
    (tmp_path / "plain.toml").write_text(
        INLINE6.replace('name = "test in-line 6"', 'name = "plain six"')
    )
    result = invoke("torsion", tmp_path, "--speeds", "2000", "--format", "json")
    assert result.exit_code == 0, result.output
    assert [e["name"] for e in json.loads(result.stdout)["engines"]] == ["test in-line 6"]
    assert "plain.toml: no [torsion] table; passed over" in result.stderr
    (tmp_path / "six.toml").unlink()
    # one engine alone is analysed or refused by name
    result = invoke("torsion", tmp_path)
    assert (
        result.exit_code == 1
        and "plain.toml: engine 'plain six' has no [torsion] table" in result.output
    )
    (tmp_path / "other.toml").write_text(INLINE6)
    result = invoke("torsion", tmp_path)
    assert result.exit_code == 1 and "none of these engines has a [torsion] table" in result.output


@pytest.mark.parametrize(
    "speeds", ["600:inf:25", "600:2400:inf", "1e300", "0:100:1", "1:2:0.00001", "nan", "600:2400"]
)
def test_bad_speeds_are_one_line(tmp_path, speeds):
    path = tmp_path / "six.toml"
    path.write_text(INLINE6 + TORSION6)
    result = invoke("torsion", path, "--speeds", speeds)
    assert result.exit_code == 2
    assert "--speeds" in result.output and "Traceback" not in result.output


def test_plot_refuses_pictures_that_would_overwrite_each_other(tmp_path):
    for folder in ("a", "b"):
        (tmp_path / folder).mkdir()
        (tmp_path / folder / "x.toml").write_text(INLINE6 + TORSION6)
    result = invoke(
        "torsion", tmp_path / "a/x.toml", tmp_path / "b/x.toml", "--plot", tmp_path / "pd"
    )
    assert result.exit_code == 2 and "x.toml is given twice" in result.output
    result = invoke(
        "torsion",
        tmp_path / "a/x.toml",
        "--plot",
        tmp_path / "pd",
        "-o",
        tmp_path / "pd/x-torque.png",
    )
    assert result.exit_code == 2 and "one of the pictures" in result.output
    assert not (tmp_path / "pd").exists()


def test_units_convert_the_vibratory_torque(tmp_path):
    """--units kN: the table's torques are the N·m figures / 1000 (kN·m), the CSV's column
    torque_kNm; JSON stays SI."""
    path = tmp_path / "six.toml"
    path.write_text(INLINE6 + TORSION6)
    si = invoke("torsion", path, "--speeds", "2000", "--format", "csv").output.splitlines()
    kn = invoke(
        "torsion", path, "--speeds", "2000", "--format", "csv", "--units", "kN"
    ).output.splitlines()
    assert si[0].split(",")[5] == "torque_Nm" and kn[0].split(",")[5] == "torque_kNm"
    for a, b in zip(si[1:], kn[1:], strict=True):
        assert_allclose(float(b.split(",")[5]), float(a.split(",")[5]) / 1000, rtol=1e-12)
    assert "Torque (kN·m)" in invoke("torsion", path, "--speeds", "2000", "--units", "kn").output


def test_help_names_only_the_options_it_has():
    """``torsion --help`` once told of an --absolute it does not have (the --units help of the
    force commands)."""
    result = invoke("torsion", "--help")
    assert result.exit_code == 0
    assert "--absolute" not in result.output
    for option in ("--criticals", "--orders", "--modes", "--units"):
        assert option in result.output


def criticals_rows(output):
    """(speed, mode, order, kind) of the criticals table of one engine's text output."""
    lines = output.split("Criticals in the speed range")[1].split("\n\n")[1].splitlines()[2:]
    return [tuple(line.split(maxsplit=3)[:3]) + (line.split()[3],) for line in lines]


def test_criticals_orders_and_modes_choose_the_criticals(tmp_path):
    path = tmp_path / "six.toml"
    path.write_text(INLINE6 + TORSION6)
    every = criticals_rows(invoke("torsion", path).output)
    major = criticals_rows(invoke("torsion", path, "--criticals", "major").output)
    assert major and all(kind == "major" for *_, kind in major)
    # an even six's major orders are the multiples of 3 (k·120° a multiple of 360°)
    assert [r for r in every if float(r[2]) % 3 == 0] == major
    chosen = criticals_rows(invoke("torsion", path, "--orders", "4.5,6", "--modes", "1").output)
    assert chosen == [r for r in every if r[2] in ("4.5", "6") and r[1] == "1"]
    document = json.loads(invoke("torsion", path, "--orders", "6", "--format", "json").output)[
        "engines"
    ][0]
    assert {c["order"] for c in document["criticals"]} == {6.0}
    assert document["criticals_chosen"] == {"kind": "excited", "orders": [6.0], "modes": None}


@pytest.mark.parametrize(
    "args, status, words",
    [
        (["--orders", "4.25"], 1, "--orders has 4.25"),
        (["--orders", "x"], 2, "--orders"),
        (["--modes", "0"], 2, "--modes"),
        (["--modes", "1,x"], 2, "--modes"),
        (["--modes", "12"], 1, "--modes has 12"),
        (["--criticals", "minor"], 2, "--criticals"),
    ],
)
def test_bad_filters_are_one_line_and_write_nothing(tmp_path, args, status, words):
    path = tmp_path / "six.toml"
    path.write_text(INLINE6 + TORSION6)
    out = tmp_path / "out.json"
    result = invoke("torsion", path, *args, "--format", "json", "-o", out, "--plot", tmp_path / "p")
    assert result.exit_code == status
    assert words in result.output and "Traceback" not in result.output
    assert len([line for line in result.output.splitlines() if line.startswith("Error")]) == 1
    assert not out.exists() and not (tmp_path / "p").exists()


def test_the_tables_name_the_largest_peak_and_the_elastic_twist(tmp_path):
    path = tmp_path / "six.toml"
    path.write_text(INLINE6 + TORSION6)
    text = invoke("torsion", path).output
    assert "Largest of all: " in text and "elastic twist" in text
    document = json.loads(invoke("torsion", path, "--format", "json").output)["engines"][0]
    assert set(document["peak"]) == {
        "section",
        "torque_Nm",
        "speed_rpm",
        "order",
        "mode",
        "critical_rpm",
        "major",
    }
    first = document["response"][0]
    assert "free_end_elastic_deg" in first and "elastic_deg" in first["free_end_orders"][0]
