"""balance sweep: its tables, CSV, JSON, picture and errors."""

import csv
import io
import json
import xml.etree.ElementTree as ET

import numpy as np
import pytest
from numpy.testing import assert_allclose

from tests.support import CONFIGS, LINKED, SINGLE, TWIN, TWIN_PITCH, invoke, rad_s, write
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
        (["--vary", "power", "--values", "1 MW"], "--vary power changes only the power related"),
        (["--vary", "rod_ratio", "--values", "3,0.9"], "rod_ratio = 0.9: rod_length of 0.036 m"),
        (["--vary", "stroke", "--values", "80 kg"], "stroke = '80 kg': '80 kg' is a mass"),
        (["--vary", "bore_pitch", "--values", "0 mm"], "bore_pitch = '0 mm': must be greater"),
        (
            [
                "--vary",
                "speed",
                "--values",
                "1 rpm,2 rpm",
                "--vary",
                "speed",
                "--values",
                "3 rpm,4 rpm",
            ],
            "--vary names 'speed' twice",
        ),
        (
            [
                "--vary",
                "rod_ratio",
                "--values",
                "3,4",
                "--vary",
                "rod_length",
                "--values",
                "1 m,2 m",
            ],
            "--vary 'rod_ratio' and 'rod_length' both change rod_length",
        ),
        (
            ["--vary", "speed", "--values", "1 rpm", "--vary", "rod_length", "--values", "1 m,2 m"],
            "--values holds one value of speed: a grid needs two or more",
        ),
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


def test_a_derived_parameter_the_engine_lacks_is_one_line(tmp_path):
    path = write(tmp_path, LINKED)
    result = invoke("sweep", path, "--vary", "rod_ratio", "--values", "3,4")
    assert result.exit_code == 1 and result.output.count("\n") == 1, result.output
    assert result.output.startswith(f"Error: --vary 'rod_ratio' is not defined for {path}: ")
    assert "link rods" in result.output and "vary rod_length" in result.output


GRID = ["--vary", "rod_ratio", "--from", "3", "--to", "5", "--steps", "3"]
GRID += ["--vary", "balance_factor", "--values", "0,0.5,1", "--quantity", "F1V,F1H,F2"]


def test_two_vary_make_a_grid_in_every_format(tmp_path):
    # a single with counterweights of factor f: F1V = (1 − f)·m·r·ω², F1H = f·m·r·ω²
    path = write(tmp_path, SINGLE)
    unit = M_REC * R * rad_s(3000) ** 2
    document = json.loads(invoke("sweep", path, *GRID, "--format", "json").output)
    assert [p["key"] for p in document["parameters"]] == ["rod_ratio", "balance_factor"]
    assert document["shape"] == [3, 3] and len(document["points"]) == 9
    assert [p["value_1"] for p in document["points"][:4]] == [3.0, 3.0, 3.0, 4.0]
    assert_allclose(
        [p["F1H_N"] for p in document["points"]], [0, unit / 2, unit] * 3, rtol=1e-12, atol=1e-6
    )
    out = tmp_path / "grid.csv"
    assert invoke("sweep", path, *GRID, "--format", "csv", "-o", out).exit_code == 0
    rows = list(csv.reader(io.StringIO(out.read_text(encoding="utf-8"))))
    assert rows[0] == [
        "parameter_1",
        "value_1",
        "value_1_SI",
        "unit_1_SI",
        "parameter_2",
        "value_2",
        "value_2_SI",
        "unit_2_SI",
        "F1V_N",
        "F1H_N",
        "F2_N",
    ]
    assert len(rows) == 10 and rows[5][:2] == ["rod_ratio", "4.0"] and rows[5][5] == "0.5"
    assert_allclose(float(rows[5][8]), unit / 2, rtol=1e-12)
    table = invoke("sweep", path, *GRID, "--units", "kN")
    assert table.exit_code == 0, table.output
    assert "against rod_ratio and balance_factor" in table.output
    assert "3×3 = 9 points" in table.output and "rod_ratio: rod length over crank" in table.output


@pytest.mark.parametrize("suffix", ["png", "svg"])
def test_a_grid_draws_heat_maps(tmp_path, suffix):
    path = write(tmp_path, SINGLE)
    picture = tmp_path / f"grid.{suffix}"
    result = invoke("sweep", path, *GRID, "--plot", picture, "--units", "kN")
    assert result.exit_code == 0, result.output
    data = picture.read_bytes()
    if suffix == "png":
        assert data.startswith(b"\x89PNG\r\n\x1a\n")
    else:
        text = data.decode("utf-8")
        assert ET.fromstring(data).tag.endswith("svg")
        # both axes and the colour bars carry what they show
        for label in ("rod_ratio", "balance_factor", "F1V (kN)", "F2 (kN)"):
            assert label in text, label


def test_each_vary_takes_the_values_after_it(tmp_path):
    # values given before the first --vary belong to it; the grid is the same
    path = write(tmp_path, SINGLE)
    reordered = ["--from", "3", "--to", "5", "--steps", "3", *GRID[:1], "rod_ratio", *GRID[8:]]
    first = invoke("sweep", path, *GRID, "--format", "json").output
    assert invoke("sweep", path, *reordered, "--format", "json").output == first
    for args, words in [
        (["--vary", "speed", "--values", "1 rpm", "--values", "2 rpm"], "--values given twice"),
        (
            ["--vary", "speed", "--vary", "rod_length", "--values", "1 m,2 m"],
            "--vary speed: give --values, or --from, --to and --steps",
        ),
        (
            ["--vary", "speed", "--values", "1 rpm,2 rpm", "--vary", "rod_length"]
            + ["--values", "1 m,2 m", "--vary", "pin_offset", "--values", "0 mm,1 mm"],
            "--vary is given 3 times",
        ),
        (["--vary", "power", "--values", "1 MW", "--power", "2 MW"], "--power fixes the power"),
    ]:
        result = invoke("sweep", path, *args)
        assert result.exit_code == 2 and words in result.output, result.output


MARINE = CONFIGS / "marine-6-2stroke.toml"


@pytest.mark.parametrize("fmt", ["json", "csv", "table"])
def test_vary_power_in_every_format(fmt):
    # it ended in a traceback, KeyError 'power'
    result = invoke(
        "sweep",
        MARINE,
        "--vary",
        "power",
        "--values",
        "10000 kW,14280 kW",
        "--quantity",
        "PRU2V",
        "--format",
        fmt,
    )
    assert result.exit_code == 0 and "Traceback" not in result.output, result.output
    assert "14280 kW" in result.output


def test_speed_with_the_files_power_is_refused_and_power_fixes_it(tmp_path):
    out = tmp_path / "out.csv"
    common = ["sweep", MARINE, "--vary", "rod_length", "--values", "2900 mm,3000 mm"]
    common += ["--quantity", "PRU2V", "--speed", "80 rpm", "--format", "csv"]
    refused = invoke(*common, "-o", out)
    assert refused.exit_code == 1 and refused.output.count("\n") == 1, refused.output
    assert refused.output.startswith("Error: --speed sets speed = '80 rpm', but the file's power")
    assert "given at 105 rpm" in refused.output and not out.exists()
    at_file = invoke(*common[:8], "--format", "csv")
    given = invoke(*common, "--power", "8000 kW", "-o", out)
    assert given.exit_code == 0, given.output
    pru = [float(r[4]) for r in list(csv.reader(io.StringIO(out.read_text())))[1:]]
    pru_file = [float(r[4]) for r in list(csv.reader(io.StringIO(at_file.output)))[1:]]
    # the moment falls as n², the power is the one given: (80/105)² × 14 280 / 8 000
    assert_allclose(pru, np.array(pru_file) * (80 / 105) ** 2 * 14280 / 8000, rtol=1e-12)


class _Terminal(io.StringIO):
    def isatty(self):
        return True


def test_the_bar_shows_before_the_first_point(tmp_path, monkeypatch):
    # a 10 000-point sweep showed nothing for 19 s: the bar is drawn before any point's engine
    # is built, so what the terminal holds when the first point is built already shows it
    import types

    from balance_cli.cli import sweep as command
    from balance_cli.studies.sweep import run

    terminal = _Terminal()
    monkeypatch.setattr(command, "sys", types.SimpleNamespace(stderr=terminal))
    seen = []
    build = run.build
    monkeypatch.setattr(run, "build", lambda *a: seen.append(terminal.getvalue()) or build(*a))
    path = write(tmp_path, TWIN)
    result = invoke("sweep", path, "--vary", "speed", "--values", "1000 rpm,2000 rpm,3000 rpm")
    assert result.exit_code == 0, result.output
    # the first build is the file's own; the bar is up before the second, the first point's
    assert "Sweeping" not in seen[0] and "Sweeping" in seen[1] and "0%" in seen[1]


def test_a_mount_rate_with_the_mount_quantities(tmp_path):
    """Every mount's vertical rate of the symmetric example: bounce √(4·k_z/m)/2π in the table
    (Hz) and the CSV, the mount's force in the units asked for, a picture of them."""
    config = CONFIGS / "mounts" / "four-mount-symmetric.toml"
    common = ["sweep", config, "--vary", "mounts.mount[*].stiffness[3]"]
    common += ["--values", "150 N/mm,250 N/mm", "--quantity", "bounce_mode,mount_1_force"]
    common += ["--mount-speeds", "500:1500:100"]
    table = invoke(*common, "--units", "kN", "--plot", tmp_path / "mounts.png")
    assert table.exit_code == 0, table.output
    assert "bounce_mode (Hz)" in table.output and "mount_1_force (kN)" in table.output
    assert (tmp_path / "mounts.png").read_bytes()[:4] == b"\x89PNG"
    rows = list(csv.DictReader(io.StringIO(invoke(*common, "--format", "csv").output)))
    bounce = [np.sqrt(4 * k / 150) / (2 * np.pi) for k in (150e3, 250e3)]
    assert_allclose([float(r["bounce_mode_Hz"]) for r in rows], bounce, rtol=1e-12)
    bad = invoke(*common, "--mount-speeds", "5:1")
    assert bad.exit_code != 0 and "--mount-speeds" in bad.output
