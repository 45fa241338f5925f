"""balance sweep: its tables, CSV, JSON, picture and errors."""

import csv
import io
import json
import xml.etree.ElementTree as ET

import pytest
from numpy.testing import assert_allclose

from tests.support import CONFIGS, TWIN, TWIN_PITCH, invoke, rad_s, write
from tests.support import TWIN_CRANK_RADIUS_M as R
from tests.support import TWIN_RECIPROCATING_KG as M_REC


def test_table_csv_and_json(tmp_path):
    path = write(tmp_path, TWIN)
    common = [
        "sweep",
        path,
        "--vary",
        "speed",
        "--from",
        "1000 rpm",
        "--to",
        "3000 rpm",
        "--steps",
        "3",
        "--quantity",
        "F1,M1V",
    ]
    table = invoke(*common, "--units", "kN")
    assert table.exit_code == 0, table.output
    assert "M1V (kN·m)" in table.output and "1000 rpm" in table.output
    out = tmp_path / "sweep.csv"
    assert invoke(*common, "--format", "csv", "-o", out).exit_code == 0
    rows = list(csv.reader(io.StringIO(out.read_text(encoding="utf-8"))))
    assert rows[0] == ["parameter", "value", "value_SI", "unit_SI", "F1_N", "M1V_Nm"]
    assert [r[1] for r in rows[1:]] == ["1000 rpm", "2000 rpm", "3000 rpm"]
    assert {r[3] for r in rows[1:]} == {"rad/s"}
    # SI at full precision, whatever --units says
    couple = M_REC * R * rad_s(3000) ** 2 * TWIN_PITCH
    assert_allclose(float(rows[3][5]), couple, rtol=1e-12)
    document = json.loads(invoke(*common, "--format", "json", "--units", "lbf").output)
    assert document["parameter"]["values"] == ["1000 rpm", "2000 rpm", "3000 rpm"]
    assert_allclose(document["points"][2]["M1V_Nm"], couple, rtol=1e-12)


def test_table_units_convert_by_hand(tmp_path):
    # 1 lbf = 0.45359237 kg × 9.80665 m/s² = 4.4482216152605 N; 1 lbf·ft = that × 0.3048 m
    path = write(tmp_path, TWIN)
    text = invoke(
        "sweep",
        path,
        "--vary",
        "speed",
        "--values",
        "3000 rpm",
        "--quantity",
        "F1,M1",
        "--units",
        "lbf",
    ).output
    row = [line for line in text.splitlines() if line.startswith("3000 rpm")][0].split()
    force = M_REC * R * rad_s(3000) ** 2 / 4.4482216152605  # the free primary force is 0
    couple = M_REC * R * rad_s(3000) ** 2 * TWIN_PITCH / (4.4482216152605 * 0.3048)
    assert row[2] == "0" and force > 0
    assert_allclose(float(row[3]), couple, rtol=5e-4)  # four significant figures


@pytest.mark.parametrize(
    "args, words",
    [
        (["--vary", "rod_lenght", "--values", "140 mm"], "--vary 'rod_lenght': no such key"),
        (["--vary", "rod_length", "--values", "140 mm,20 mm"], "rod_length = '20 mm'"),
        (["--vary", "rod_length", "--values", "140"], "rod_length = '140'"),
        (["--vary", "speed", "--from", "1000 rpm", "--to", "2 kg", "--steps", "3"], "--to '2 kg'"),
        (["--vary", "speed", "--from", "1000 rpm", "--to", "2000 rpm", "--steps", "1"], "--steps"),
        (["--vary", "speed", "--values", "3000 rpm", "--quantity", "F2,F2Q"], "--quantity"),
        (["--vary", "speed", "--values", "3000 rpm", "--quantity", "steadiness"], "--inertia"),
        (["--vary", "speed", "--values", "3000 rpm", "--plot", "x.gif"], "--plot"),
    ],
)
def test_errors_are_one_line_and_write_nothing(tmp_path, args, words):
    path = write(tmp_path, TWIN)
    out, picture = tmp_path / "out.json", tmp_path / "picture.png"
    if "--plot" not in args:
        args = args + ["--plot", picture]
    result = invoke("sweep", path, *args, "--format", "json", "-o", out)
    assert result.exit_code == 1, result.output
    assert result.output.startswith("Error: ") and result.output.count("\n") == 1, result.output
    assert words in result.output
    assert "Traceback" not in result.output
    assert not out.exists() and not picture.exists()


def test_values_and_span_together_is_a_usage_error(tmp_path):
    path = write(tmp_path, TWIN)
    result = invoke("sweep", path, "--vary", "speed", "--values", "1 rpm", "--from", "1 rpm")
    assert result.exit_code == 2 and "not both" in result.output


@pytest.mark.parametrize("suffix", ["png", "svg"])
def test_plot_writes_a_real_picture(tmp_path, suffix):
    path = write(tmp_path, TWIN)
    picture = tmp_path / f"sweep.{suffix}"
    result = invoke(
        "sweep",
        path,
        "--vary",
        "rod_length",
        "--from",
        "120 mm",
        "--to",
        "200 mm",
        "--steps",
        "5",
        "--quantity",
        "F2,F2V,M1,torque_range",
        "--plot",
        picture,
        "--units",
        "kN",
    )
    assert result.exit_code == 0, result.output
    data = picture.read_bytes()
    if suffix == "png":
        assert data.startswith(b"\x89PNG\r\n\x1a\n")
    else:
        root = ET.fromstring(data)
        assert root.tag.endswith("svg")
        text = data.decode("utf-8")
        # the axis labels carry the units (svg.fonttype none keeps text as text)
        assert "rod_length (mm)" in text and "Force (kN)" in text and "Torque (kN·m)" in text


def test_speed_fixes_the_speed(tmp_path):
    path = write(tmp_path, TWIN)
    result = invoke(
        "sweep",
        path,
        "--vary",
        "rod_length",
        "--values",
        "140 mm",
        "--speed",
        "1500 rpm",
        "--format",
        "json",
    )
    assert json.loads(result.output)["overrides"] == {"speed": "1500 rpm"}
    bad = invoke("sweep", path, "--vary", "rod_length", "--values", "140 mm", "--speed", "3 kg")
    assert bad.exit_code == 1 and bad.output.startswith("Error: --speed: '3 kg' is a mass")
    both = invoke("sweep", path, "--vary", "speed", "--values", "140 rpm", "--speed", "1500 rpm")
    assert both.exit_code == 2


def test_markdown_and_one_sampling_warning_for_the_whole_sweep():
    # 37 samples leave the Dragonfly's orders above 8 aliasing at every speed: one line says so
    result = invoke(
        "sweep",
        CONFIGS / "abc-dragonfly.toml",
        "--vary",
        "speed",
        "--from",
        "1500 rpm",
        "--to",
        "1800 rpm",
        "--steps",
        "4",
        "--samples",
        "37",
        "--quantity",
        "F1,F2",
        "--format",
        "markdown",
    )
    assert result.exit_code == 0, result.output
    assert result.output.count("warning: ") == 1 and "(--samples)" in result.output
    assert "| speed" in result.output and "#### ABC Dragonfly" in result.output
