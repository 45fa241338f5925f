"""The options several commands share (--samples, --max-order, --units, --speed, ...): bad
values get one error line, and good ones do what they say."""

import json
import re

import pytest
from numpy.testing import assert_allclose

from tests.support import (
    CONFIGS,
    MRW2,
    PART3,
    TEMPLATES,
    TWIN,
    check_refused,
    inline_toml,
    invoke,
    snapshot,
    twin_file,
    write,
)

#: (id, command arguments after the command name and the input, words); input TWIN, or ROTARY
OPTION_CASES = [
    ("samples-below", ["compare", "--samples", "17"], 1, "--samples must be from 33 to 65536"),
    ("samples-zero", ["compare", "--samples", "0"], 1, "--samples must be from 33"),
    ("samples-huge", ["compare", "--samples", "10000000"], 1, "--samples must be from 33 to 65536"),
    ("samples-text", ["compare", "--samples", "many"], 2, "'many' is not a valid integer"),
    ("max-order-zero", ["compare", "--max-order", "0"], 1, "--max-order must be at least 1"),
    ("max-order-negative", ["compare", "--max-order", "-3"], 1, "--max-order must be at least 1"),
    (
        "reference-none",
        ["compare", "--reference", "Zeppelin"],
        1,
        "--reference 'Zeppelin' matches no engine",
    ),
    ("units-unknown", ["compare", "--units", "dyn"], 2, "must be one of N, kN, MN, kgf, lbf"),
    ("format-unknown", ["compare", "--format", "xml"], 2, "'xml' is not one of"),
    (
        "balance-factor-nan",
        ["counterweight", "--balance-factor", "nan"],
        1,
        "--balance-factor must be a fraction of the reciprocating masses from 0 to 1, got nan",
    ),
    ("balance-factor-inf", ["counterweight", "--balance-factor", "inf"], 1, "got inf"),
    ("balance-factor-negative", ["counterweight", "--balance-factor", "-0.5"], 1, "got -0.5"),
    (
        "radius-overflow",
        ["counterweight", "--radius", "1e400 mm"],
        1,
        "--radius: '1e400 mm' is not a finite number",
    ),
    ("radius-zero", ["counterweight", "--radius", "0 mm"], 1, "--radius must be greater than zero"),
    ("radius-mass", ["counterweight", "--radius", "5 kg"], 1, "--radius: '5 kg' is a mass"),
    ("planes-missing-throw", ["counterweight", "--planes", "1,9"], 1, "--planes names throw 9"),
    ("planes-coincide", ["counterweight", "--planes", "1,1"], 1, "--planes coincide"),
    ("planes-three", ["counterweight", "--planes", "1,2,1"], 1, "--planes takes one plane"),
    ("planes-text", ["counterweight", "--planes", "1,two"], 1, "--planes: cannot read 'two'"),
    (
        "planes-overflow",
        ["counterweight", "--planes", "1,1e400 mm"],
        1,
        "--planes: '1e400 mm' is not a finite",
    ),
    ("shafts-outside", ["counterweight", "--shafts", "99"], 1, "--shafts names order 99"),
    ("shafts-text", ["counterweight", "--shafts", "second"], 2, "give orders as whole numbers"),
    (
        "antivibrateur-two-throws",
        ["counterweight", "--antivibrateur"],
        1,
        "--antivibrateur-radius needs a single-throw",
    ),
    (
        "antivibrateur-radius-negative",
        ["counterweight", "--antivibrateur", "--antivibrateur-radius", "-4 mm"],
        1,
        "--antivibrateur-radius must be greater than zero",
    ),
    (
        "star-order-above",
        ["report", "--star-order", "9"],
        1,
        "--star-order 9 is above --max-order 8",
    ),
]


def test_max_order_needs_enough_samples():
    result = invoke("compare", PART3, "--samples", "32", "--max-order", "8")
    assert result.exit_code == 1
    assert "--samples must be from 33 to 65536 for orders up to 8" in result.output
    assert invoke("compare", PART3, "--samples", "33", "--max-order", "8").exit_code == 0


def test_coarse_sampling_is_reported():
    result = invoke(
        "compare", CONFIGS / "inline-4-marine.toml", "--samples", "16", "--max-order", "3"
    )
    assert result.exit_code == 0
    assert "16 samples a revolution are too few for orders up to 3" in result.output


@pytest.mark.parametrize(
    "args, code, words", [case[1:] for case in OPTION_CASES], ids=[case[0] for case in OPTION_CASES]
)
def test_bad_option(tmp_path, args, code, words):
    config = tmp_path / "engine.toml"
    config.write_text(TWIN, encoding="utf-8")
    before = snapshot(tmp_path)
    out = tmp_path / ("report" if args[0] == "report" else "out.txt")
    result = invoke(args[0], config, *args[1:], "--output", out)
    check_refused(result, code, words, before, tmp_path)


@pytest.mark.parametrize(
    "args, code, words",
    [
        (["--max-order", "100000"], 1, "--max-order must be at most 16383"),
        (["--max-order", "16384", "--samples", "65536"], 1, "--max-order must be at most 16383"),
    ],
)
def test_a_max_order_no_sampling_can_resolve(tmp_path, args, code, words):
    config = twin_file(tmp_path)
    before = snapshot(tmp_path)
    check_refused(invoke("compare", config, *args), code, words, before, tmp_path)


def test_speed_option_scales_forces_by_the_square(twin):
    """--speed doubles ω: every force and moment × 4 (ω² law), exactly."""
    path = twin
    slow = json.loads(invoke("compare", path, "--format", "json").output)["engines"][0]
    fast = json.loads(invoke("compare", path, "--format", "json", "--speed", "6000 rpm").output)
    fast = fast["engines"][0]
    assert fast["speed_rpm"] == pytest.approx(6000.0)
    assert_allclose(
        fast["orders"][1]["force"]["max_N"], 4 * slow["orders"][1]["force"]["max_N"], rtol=1e-12
    )
    assert_allclose(
        fast["orders"][0]["moment"]["max_Nm"], 4 * slow["orders"][0]["moment"]["max_Nm"], rtol=1e-12
    )
    for command in ("counterweight", "torque"):
        out = invoke(command, path, "--speed", "0 rpm")
        assert out.exit_code == 1 and "--speed" in out.output and "Traceback" not in out.output


def test_every_command_that_prints_forces_takes_units(twin, tmp_path):
    """--units kN on counterweight, torque, regress and report: headings in kN and kN·m, and
    the figures a thousandth of the newtons (hand factor 1e3)."""
    out = invoke("counterweight", twin, "--units", "kn")
    assert out.exit_code == 0 and "(kN)" in out.output and "(kN·m)" in out.output
    torque = invoke("torque", twin, "--units", "kN")
    assert torque.exit_code == 0 and "Range ΔC (kN·m)" in torque.output
    newtons = json.loads(invoke("torque", twin, "--format", "json").output)["engines"][0]
    row = next(line for line in torque.output.splitlines() if line.startswith("inertia"))
    shown = float(re.split(r"\s{2,}", row)[2].replace(" ", ""))
    assert_allclose(shown * 1e3, newtons["inertia"]["max_Nm"], rtol=5e-4)
    baseline = tmp_path / "base.json"
    baseline.write_text(invoke("compare", twin, "--format", "json").output, encoding="utf-8")
    heavier = tmp_path / "heavier.toml"
    heavier.write_text(TWIN.replace('"500 g"', '"600 g"'), encoding="utf-8")
    moved = invoke("regress", baseline, heavier, "--units", "kN")
    assert moved.exit_code == 1 and "kN for *_N and kN·m for *_Nm" in moved.output
    report = invoke("report", twin, "--output", tmp_path / "r", "--units", "kN")
    assert report.exit_code == 0, report.output
    assert "Mean (kN·m)" in (tmp_path / "r" / "report.md").read_text(encoding="utf-8")


def _cells(output, first):
    """The cells of the first table row of ``output`` that starts with ``first``."""
    row = next(line for line in output.splitlines() if line.startswith(first))
    return re.split(r"\s{2,}", row)


def test_any_units_means_absolute_forces_on_every_command(tmp_path):
    """--units N is newtons, not per cylinder: compare, counterweight, search and report show
    the forces of an in-line 4 (m = 1 kg, r = 50 mm, l = 200 mm, 3000 rpm) in N with --units
    N as with --absolute. By hand: the order-2 force's max is n·m·r·ω²·A₂, A₂ = λ + λ³/4 +
    15λ⁵/128 + 35λ⁷/512 + … with λ = 0.25: 0.2540249 (the next term, ~1e-6 of it, is below
    the table's four figures), so 4 × 4934.80 N × 0.2540249 = 5014.3 N, or 0.2540 per
    cylinder."""
    engine = write(tmp_path, inline_toml("In-line 4", [0, 180, 180, 0], 100, cycle=4))
    lam = 0.25
    a2 = lam + lam**3 / 4 + 15 * lam**5 / 128 + 35 * lam**7 / 512
    per_cylinder = invoke("compare", engine)
    assert per_cylinder.exit_code == 0 and "F max (per cyl)" in per_cylinder.output
    # four significant figures printed: rtol half a unit of the fourth
    assert_allclose(float(_cells(per_cylinder.output, "In-line 4  ")[4]), a2, rtol=2e-4)
    newtons = invoke("compare", engine, "--units", "N")
    assert newtons.exit_code == 0 and "F max (N)" in newtons.output
    assert "per cyl" not in newtons.output
    shown = float(_cells(newtons.output, "In-line 4  ")[4].replace(" ", ""))
    assert_allclose(shown, 4 * MRW2 * a2, rtol=2e-4)
    assert newtons.output == invoke("compare", engine, "--absolute").output
    for args in (["counterweight", engine], ["search", TEMPLATES / "inline-3-2stroke.toml"]):
        given, default = invoke(*args, "--units", "N"), invoke(*args)
        assert given.exit_code == 0 == default.exit_code, given.output
        assert "F max (N)" in given.output and "F max (N)" not in default.output
        assert "per cyl" in default.output
    assert invoke("counterweight", engine, "--units", "n").output == (
        invoke("counterweight", engine, "--absolute").output
    )
    report = invoke("report", engine, "--output", tmp_path / "r", "--units", "N")
    assert report.exit_code == 0, report.output
    assert "F max (N)" in (tmp_path / "r" / "report.md").read_text(encoding="utf-8")


def test_negative_zero_reads_as_zero(tmp_path):
    result = invoke(
        "counterweight", CONFIGS / "inline-4-car.toml", "--balance-factor", "-0", "--format", "json"
    )
    assert '"balance_factor": 0.0' in result.stdout
    config = tmp_path / "e.toml"
    config.write_text(
        (CONFIGS / "inline-4-car.toml")
        .read_text()
        .replace("[[banks]]\nangle = 0", "[[banks]]\nangle = -0.0"),
        encoding="utf-8",
    )
    assert "(-0°)" not in invoke("show", config).stdout
