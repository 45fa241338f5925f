"""balance torque and balance steadiness: their tables, JSON and CSV, their input files and
options."""

import csv
import io
import json
import math
import os

import numpy as np
import pytest
from numpy.testing import assert_allclose

import balance_cli as balance
from tests.support import CONFIGS, JUMO, invoke, sinusoid, strict_json


def write_torque(path, values, cycle=720.0, unit="Nm"):
    angles = np.arange(len(values)) * cycle / len(values)
    lines = [f"angle_deg,torque_{unit}"] + [
        f"{float(a)!r},{float(v)!r}" for a, v in zip(angles, values, strict=True)
    ]
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return path


def flat_torque_file(path, variation=1e-6, mean=1000.0):
    """A torque varying by ``variation`` of its mean, order 2 over a 720° cycle, every 2°."""
    angles = np.arange(0.0, 720.0, 2.0)
    values = mean * (1 + variation * np.sin(2 * np.radians(angles)))
    path.write_text(
        "angle_deg,torque_Nm\n"
        + "".join(f"{float(a)!r},{float(v)!r}\n" for a, v in zip(angles, values, strict=True)),
        encoding="utf-8",
    )
    return path


def test_steadiness_command(tmp_path):
    path = write_torque(tmp_path / "t.csv", sinusoid(samples=720))
    result = invoke(
        "steadiness",
        "--torque",
        path,
        "--inertia",
        "0.3 kg*m^2",
        "--speed",
        "1200 rpm",
        "--format",
        "json",
        "--target",
        "50",
    )
    assert result.exit_code == 0, result.output
    document = json.loads(result.stdout)
    assert_allclose(document["steadiness"], document["r_h"], rtol=0.01)
    assert document["order"] == 2.0 and document["load"] == "propeller"
    assert document["inertia_for_target_kgm2"] > 0
    text = invoke("steadiness", "--torque", path, "--inertia", "0.3 kg m2", "--speed", "1200 rpm")
    assert "steadiness ω_m/(ω_max − ω_min)" in text.stdout


@pytest.mark.parametrize(
    "content, words",
    [
        (
            "angle_deg,torque_Nm\n0,1\n10,2\n5,3\n20,1\n30,1\n40,1\n50,1\n60,1\n",
            "line 4: goes back",
        ),
        (
            "angle_deg,torque_Nm\n0,1\n0,2\n10,3\n20,1\n30,1\n40,1\n50,1\n60,1\n",
            "line 3: repeats the angle",
        ),
        (
            "angle_deg,torque\n" + "".join(f"{a},1\n" for a in range(0, 360, 10)),
            "name it torque_<unit>",
        ),
        (
            "angle_deg,torque_furlong\n" + "".join(f"{a},1\n" for a in range(0, 360, 10)),
            "unknown unit 'furlong'",
        ),
        (
            "angle_deg,torque_Nm\n" + "".join(f"{a},1\n" for a in range(0, 200, 10)),
            "cover 190°, not one 360° cycle",
        ),
        ("angle_deg,torque_Nm,x\n0,1,2\n", "the header must name two columns"),
        ("angle_deg,torque_Nm\n0,1\n10\n", "line 3: has 1 column; give two"),
        (
            "angle_deg,torque_Nm\n"
            + "".join(f"{a},{1e300 if a == 30 else 1}\n" for a in range(0, 360, 10)),
            "line 5: 1e+300 Nm is outside the torques balance accepts",
        ),
        (
            "time_ms,torque_Nm\n" + "".join(f"{a},1\n" for a in range(0, 360, 10)),
            "the first column is 'time_ms'; name it angle_deg",
        ),
        ('angle_deg,torque_Nm\n0,"32,5"\n', "with a decimal point (12.5, not 12,5)"),
        (
            "angle_deg,torque_Nm\n" + "".join(f"{a},100\n" for a in range(0, 360, 10)),
            "does not vary over the cycle",
        ),
        (
            "angle_deg,torque_Nm\n"
            + "".join(f"{a},{100 if a < 180 else -100}\n" for a in range(0, 360, 10)),
            "has a mean of 0 N·m: a propeller absorbs only a positive mean torque",
        ),
        ("angle_deg,torque_Nm\n0,one\n", "line 2: cannot read"),
        ("", "is empty"),
    ],
)
def test_bad_torque_files(tmp_path, content, words):
    path = tmp_path / "t.csv"
    path.write_text(content, encoding="utf-8")
    result = invoke("steadiness", "--torque", path, "--inertia", "1 kg*m^2", "--speed", "1000 rpm")
    assert result.exit_code == 1 and isinstance(result.exception, SystemExit)
    assert result.stderr.count("\n") == 1 and words in result.stderr and str(path) in result.stderr


@pytest.mark.parametrize(
    "content, words",
    [
        (
            "angle_deg,pressure_bar\n"
            + "".join(f"{a},{-1 if a == 40 else 5}\n" for a in range(0, 720, 10)),
            "line 6: pressure -1 bar is negative",
        ),
        (
            "angle_deg,pressure_bar\n" + "".join(f"{a},5\n" for a in range(0, 360, 10)),
            "--pressure covers 360°, but 'In-line 4, car proportions' is a 4-stroke (720°)",
        ),
        (
            "angle_deg,pressure_bar\n"
            + "".join(f"{a},{1e200 if a == 30 else 5}\n" for a in range(0, 720, 10)),
            "line 5: 1e+200 bar is outside the pressures balance accepts",
        ),
        ("angle_deg,pressure_psx\n0,1\n", "unknown unit 'psx'"),
    ],
)
def test_bad_pressure_files(tmp_path, content, words):
    path = tmp_path / "p.csv"
    path.write_text(content, encoding="utf-8")
    result = invoke("torque", CONFIGS / "inline-4-car.toml", "--pressure", path, "--bore", "86 mm")
    assert result.exit_code == 1 and result.stderr.count("\n") == 1 and words in result.stderr


def test_torque_command_table_json_csv(tmp_path):
    table = invoke("torque", CONFIGS / "bramo-323.toml")
    assert table.exit_code == 0, table.output
    assert "Reduced mass μ" in table.stdout and "tilting" in table.stdout
    result = invoke(
        "torque",
        CONFIGS / "bramo-323.toml",
        CONFIGS / "inline-4-car.toml",
        "--format",
        "json",
        "--max-order",
        "4",
    )
    document = json.loads(result.stdout)
    (bramo, car) = document["engines"]
    assert set(bramo) >= {
        "name",
        "config",
        "cycle",
        "speed_rpm",
        "period_deg",
        "reduced_mass",
        "inertia",
        "frame",
        "tilting",
        "gas",
        "total",
        "bearing",
    }
    assert bramo["period_deg"] == 720.0 and bramo["gas"] is None
    assert [o["order"] for o in bramo["inertia"]["orders"]] == [0.5 * k for k in range(1, 9)]
    assert set(bramo["inertia"]["orders"][1]) == {
        "order",
        "cos_Nm",
        "sin_Nm",
        "amplitude_Nm",
        "phase_deg",
    }
    pin = bramo["bearing"]["crank_pins"][0]
    assert set(pin["orders"][2]["force"]) >= {
        "forward_N",
        "backward_N",
        "max_N",
        "min_N",
        "axis_deg",
    }
    engine = balance.load(CONFIGS / "bramo-323.toml")
    from balance_cli.analysis.torque import torque

    assert bramo == torque(engine, max_order=4).to_dict()  # the JSON is the result's to_dict
    csv_text = invoke(
        "torque", CONFIGS / "inline-4-car.toml", "--format", "csv", "--units", "kgf"
    ).stdout
    assert csv_text.startswith("engine,config,torque,order,cos_kgfm")
    rows = list(csv.reader(io.StringIO(csv_text)))
    numbers = [cell for row in rows[1:] for cell in row[3:] if cell]
    assert numbers and all(float(cell) == float(cell) for cell in numbers)  # plain numbers only
    # the order rows read back as the JSON's values, in kgf·m
    car = balance.load(CONFIGS / "inline-4-car.toml")
    from balance_cli.analysis.torque import torque as torque_of

    inertia = torque_of(car).inertia
    second = next(row for row in rows if row[2] == "inertia" and float(row[3]) == 2.0)
    assert_allclose(float(second[5]), inertia.order(2)[1] / 9.80665, rtol=1e-12)


def test_torque_with_gas_and_a_flywheel(tmp_path):
    path = tmp_path / "p.csv"
    angles = np.arange(0, 720, 2.0)
    pressure = 1.0 + 40.0 * np.exp(
        -(((angles + 360) % 720 - 380.0) ** 2) / 400.0
    )  # a burst after TDC
    path.write_text(
        "angle_deg,pressure_bar\n"
        + "".join(f"{a},{p}\n" for a, p in zip(angles, pressure, strict=True))
    )
    result = invoke(
        "torque",
        CONFIGS / "inline-4-car.toml",
        "--pressure",
        path,
        "--bore",
        "86 mm",
        "--inertia",
        "0.15 kg*m^2",
        "--target",
        "100",
        "--format",
        "json",
    )
    assert result.exit_code == 0, result.output
    (car,) = json.loads(result.stdout)["engines"]
    assert car["gas"]["mean_Nm"] > 0 and car["steadiness"]["steadiness"] > 1
    assert car["steadiness"]["flywheel_for_target_kgm2"] > 0
    # no gas: a steadiness cannot be asked for
    result = invoke("torque", CONFIGS / "inline-4-car.toml", "--inertia", "0.15 kg*m^2")
    assert (
        result.exit_code == 1
        and "--inertia needs a gas torque to drive the engine" in result.stderr
    )


def test_a_fifo_is_not_read_as_a_pressure_or_torque_file(tmp_path):
    fifo = tmp_path / "p.csv"
    os.mkfifo(fifo)
    for args in (
        ("torque", CONFIGS / "inline-4-car.toml", "--pressure", fifo, "--bore", "86 mm"),
        ("steadiness", "--torque", fifo, "--inertia", "1 kg*m^2", "--speed", "1000 rpm"),
    ):
        result = invoke(*args)
        assert result.exit_code == 1 and "is not a regular file" in result.stderr


@pytest.mark.parametrize(
    "args, code, words",
    [
        (("--bore", "86 mm"), 2, "--bore applies with --pressure only"),
        (("--inertia", "1 kg*m^2", "--format", "csv"), 2, "not csv"),
        (("--inertia", "0 kg*m^2"), 1, "--inertia: must be greater than zero, got '0 kg*m^2'"),
    ],
)
def test_torque_options_that_cannot_apply(args, code, words):
    result = invoke("torque", CONFIGS / "abc-dragonfly.toml", *args)
    assert result.exit_code == code and words in result.stderr and "Traceback" not in result.output


def test_a_motored_cycle_cannot_drive_a_propeller(tmp_path):
    text = (
        (CONFIGS / "abc-dragonfly.toml").read_text(encoding="utf-8").replace('imep = "9 bar"\n', "")
    )
    config = tmp_path / "motored.toml"
    config.write_text(text, encoding="utf-8")
    result = invoke("torque", config, "--inertia", "3 kg*m^2")
    assert result.exit_code == 1
    assert "--inertia needs an engine that drives its propeller" in result.stderr
    assert "(a motored cycle?)" in result.stderr


def test_a_target_that_needs_no_flywheel_says_so():
    result = invoke("torque", CONFIGS / "abc-dragonfly.toml", "--target", "0.8")
    assert result.exit_code == 0, result.output
    assert "The target steadiness needs no flywheel." in result.stdout
    assert "With no flywheel (the moving parts' own inertia)" in result.stdout


@pytest.mark.parametrize("inertia, speed", [("1e6 kg*m^2", "1e5 rpm"), ("1e9 kg*m^2", "1e6 rpm")])
def test_a_steadiness_beyond_rounding_is_finite_and_ordered(tmp_path, inertia, speed):
    """Guards against a torque varying by 1e-6 of its mean with a huge flywheel writing
    "steadiness": Infinity, and a mean speed outside min..max. Margoulis's r_c =
    ω²·N·I/(2ΔC) is exact to second order in a fluctuation this small (one harmonic,
    constant load), so the integrated steadiness must equal it, ΔC = 2A of the sine; the
    file's 2° steps, read as linear, flatten the sine by (2·2°)²/12 ≈ 4e-4."""
    torque = flat_torque_file(tmp_path / "t.csv")
    result = invoke(
        "steadiness",
        "--torque",
        torque,
        "--inertia",
        inertia,
        "--speed",
        speed,
        "--load",
        "constant",
        "--format",
        "json",
    )
    assert result.exit_code == 0, result.output
    document = strict_json(result.stdout)
    assert document["min_speed_rpm"] <= document["mean_speed_rpm"] <= document["max_speed_rpm"]
    omega = float(speed.split()[0]) * math.pi / 30
    closed = omega**2 * 4 * float(inertia.split()[0]) / (2 * 2e-6 * 1000.0)
    np.testing.assert_allclose(document["steadiness"], closed, rtol=1e-3)
    table = invoke(
        "steadiness",
        "--torque",
        torque,
        "--inertia",
        inertia,
        "--speed",
        speed,
        "--load",
        "constant",
    )
    assert table.exit_code == 0 and "inf" not in table.stdout, table.output


def test_torque_csv_gives_each_crankshafts_torque():
    from click.testing import CliRunner

    from balance_cli.cli import main

    result = CliRunner().invoke(main, ["torque", JUMO, "--format", "csv"])
    assert result.exit_code == 0, result.output
    means = {
        row.split(",")[2]: float(row.split(",")[4])
        for row in result.output.splitlines()[1:]
        if row.split(",")[3] == "0.0"
    }
    assert_allclose(means["crankshaft 1"] + means["crankshaft 2"], means["total"], rtol=1e-9)
