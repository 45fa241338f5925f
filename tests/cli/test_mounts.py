"""balance mounts: the tables, CSV, JSON and pictures of both shipped examples, engines without
[mounts] passed over in a folder, and bad options refused in one line with nothing written."""

import csv
import io
import json

import pytest
from numpy.testing import assert_allclose

import balance_cli as balance
from balance_cli.report.mounts import CSV_COLUMNS
from tests.mounting.helpers import COUPLED, MOUNTS, SYMMETRIC
from tests.support import CONFIGS, invoke


@pytest.mark.parametrize("config", [COUPLED, SYMMETRIC], ids=lambda p: p.stem)
def test_both_examples_print_their_tables(config):
    result = invoke("mounts", config, "--speeds", "200:2000:20")
    assert result.exit_code == 0, result.output
    out = result.output
    for words in (
        "Natural modes and their kinetic-energy distribution",
        "Torque roll axis",
        "Elastic axis",
        "Static deflection under the weight",
        "Resonances crossed",
        "Largest force each mount passes on to the frame",
    ):
        assert words in out, words
    for mode in balance.mounts(balance.load(config), speeds_rpm=[1000.0]).modes:
        assert f"{mode.frequency_hz:.4g}" in out


def test_markdown_and_the_symmetric_examples_pure_modes():
    result = invoke("mounts", SYMMETRIC, "--format", "markdown", "--orders", "2")
    assert result.exit_code == 0, result.output
    assert result.output.startswith("#### Four-mount symmetric example")
    # each mode all in one motion
    assert result.output.count("| 100.0 ") >= 12


def test_csv_has_a_row_per_speed_order_and_place():
    """3 speeds × (the summed "all" + 2 orders) × (the centre of gravity + 4 mounts) = 45
    rows; forces on mount rows only, rotations on the centre of gravity's only."""
    result = invoke(
        "mounts", COUPLED, "--speeds", "500,1000,1500", "--orders", "1,2", "--format", "csv"
    )
    assert result.exit_code == 0, result.output
    rows = list(csv.DictReader(io.StringIO(result.output)))
    assert tuple(rows[0]) == CSV_COLUMNS
    assert len(rows) == 45
    assert {r["order"] for r in rows} == {"all", "1.0", "2.0"}
    centre = [r for r in rows if r["where"] == "centre of gravity"]
    mounts = [r for r in rows if r["where"] != "centre of gravity"]
    assert len(centre) == 9 and all(r["Fx_N"] == "" and r["rx_rad"] != "" for r in centre)
    assert all(r["Fz_N"] != "" and r["rx_rad"] == "" for r in mounts)
    assert {r["where"] for r in mounts} == {"A", "B", "C", "D"}


def test_json_is_the_results_to_dict():
    result = invoke("mounts", COUPLED, "--speeds", "800,1600", "--format", "json")
    assert result.exit_code == 0, result.output
    document = json.loads(result.output)
    engine = document["engines"][0]
    library = balance.mounts(balance.load(COUPLED), speeds_rpm=[800.0, 1600.0])
    assert_allclose(
        [m["frequency_Hz"] for m in engine["modes"]],
        [m.frequency_hz for m in library.modes],
        rtol=1e-15,  # the same computation, written as JSON
    )
    assert [s["speed_rpm"] for s in engine["speeds"]] == [800.0, 1600.0]
    assert len(engine["speeds"][0]["orders"]) == 24  # ½ to 12 in steps of ½
    assert engine["static"]["torque"] is None  # no [gas] and no power


def test_power_gives_the_static_torque():
    result = invoke("mounts", SYMMETRIC, "--speeds", "1000", "--power", "60 kW")
    assert result.exit_code == 0, result.output
    assert "mean torque of 95.49 N·m" in result.output


def test_pictures_of_both_examples(tmp_path):
    folder = tmp_path / "pictures"
    result = invoke(
        "mounts",
        MOUNTS / "four-mount-coupled.toml",
        SYMMETRIC,
        "--speeds",
        "200:1500:50",
        "--plot",
        folder,
        "-o",
        tmp_path / "tables.txt",
    )
    assert result.exit_code == 0, result.output
    names = sorted(p.name for p in folder.iterdir())
    assert names == sorted(
        f"{stem}-mount-{kind}.png"
        for stem in ("four-mount-coupled", "four-mount-symmetric")
        for kind in ("modes", "energy", "forces")
    )
    assert all(p.read_bytes()[:4] == b"\x89PNG" for p in folder.iterdir())


def test_engines_without_mounts_are_passed_over_in_a_list(tmp_path):
    result = invoke("mounts", CONFIGS / "inline-4-car.toml", SYMMETRIC, "--speeds", "1000")
    assert result.exit_code == 0, result.output
    assert "inline-4-car.toml: no [mounts] table; passed over" in result.output
    alone = invoke("mounts", CONFIGS / "inline-4-car.toml")
    assert alone.exit_code == 1
    assert alone.output.strip().splitlines() == [
        f"Error: {CONFIGS / 'inline-4-car.toml'}: engine has no [mounts] table: give the "
        "powertrain's mass, centre of gravity, inertia and mounts (see the how-to page 'The "
        "engine on its mounts')"
    ]


@pytest.mark.parametrize(
    "args, flag",
    [
        (["--orders", "0.3"], "--orders"),
        (["--orders", "two"], "--orders"),
        (["--power", "-3 kW"], "--power"),
        (["--power", "3 kg"], "--power"),
        (["--speeds", "0:100:10"], "--speeds"),
        (["--max-order", "0"], "--max-order"),
        (["--samples", "20"], "--samples"),
    ],
)
def test_bad_options_are_one_line_and_write_nothing(args, flag, tmp_path):
    out = tmp_path / "out.json"
    result = invoke("mounts", SYMMETRIC, *args, "--format", "json", "-o", out)
    assert result.exit_code != 0
    assert flag in result.output and "Traceback" not in result.output
    assert not out.exists()


def test_decouple_prints_the_rates_and_analyses_the_mounts_with_them():
    """The five rates of the coupled example that decouple (tests/mounting/test_decouple.py
    checks them): the decoupling's table first, then the analysis of the mounts with them,
    whose roll mode is pure; the JSON carries the decoupling beside the mounts analysed."""
    args = ["--decouple", "A+B:y", "--decouple", "A:z", "--decouple", "B:x"]
    args += ["--decouple", "C:compression", "--decouple", "C:shear", "--speeds", "1000"]
    result = invoke("mounts", COUPLED, *args)
    assert result.exit_code == 0, result.output
    out = result.output
    assert out.index("torque roll axis decoupling") < out.index("Natural modes")
    assert "decoupled to rounding" in out and "A+B:y" in out
    document = json.loads(invoke("mounts", COUPLED, *args, "--format", "json").output)
    (engine,) = document["engines"]
    found = balance.decouple(
        balance.load(COUPLED),
        [(("A", "B"), "y"), ("A", "z"), ("B", "x"), ("C", "compression"), ("C", "shear")],
    )
    assert engine["decoupling"] == json.loads(json.dumps(found.to_dict()))
    rates = {m["mount"]: m["rates_N_per_m"] for m in engine["system"]["mounts"]}
    assert rates["A"][1] == rates["B"][1] == found.rates[0].after_n_m
    roll = [m for m in engine["modes"] if m["mode"] == found.after.mode][0]
    assert_allclose(roll["purity_pct"], 100.0, rtol=1e-9)  # all its energy about x (M·q* ∥ x̂)


@pytest.mark.parametrize(
    "args, words",
    [
        (["--decouple", "A"], "give MOUNT:RATE"),
        (["--decouple", "+B:z"], "give MOUNT:RATE"),
        (["--decouple", "all", "--decouple", "A:z"], "give it alone"),
        (["--decouple", "E:z"], "--decouple"),
        (["--rate-bounds", "1 N/mm,2 N/mm"], "give --decouple"),
        (["--decouple", "A:z", "--rate-bounds", "1 N/mm"], "LOW,HIGH"),
        (["--decouple", "A:z", "--rate-bounds", "1 N/mm,2 kg"], "--rate-bounds"),
        (["--decouple", "A:z", "--rate-bounds", "5 N/mm,2 N/mm"], "--rate-bounds"),
    ],
)
def test_bad_decouple_options_are_one_line(args, words, tmp_path):
    out = tmp_path / "out.json"
    result = invoke("mounts", COUPLED, *args, "--format", "json", "-o", out)
    assert result.exit_code != 0
    assert words in result.output and "Traceback" not in result.output
    assert not out.exists()
