"""The command line: every bad input gets one clear message, a non-zero exit and no traceback."""

import json
import subprocess
import sys
import textwrap

import pytest
from click.testing import CliRunner

from balance_cli.cli import main
from tests.support import CONFIGS, PART3, TWIN as GOOD

LINKED = textwrap.dedent("""\
    name = "test V"
    cycle = 4
    speed = "3000 rpm"
    crank_radius = "40 mm"
    rod_length = "140 mm"

    [masses]
    reciprocating = "500 g"

    [[banks]]
    angle = -30
    [[banks]]
    angle = 30

    [[throws]]
    phase = 0

    [links]
    master_bank = 1
    length = "110 mm"
    knuckle_radius = "30 mm"
""")


def run(*args):
    return CliRunner().invoke(main, list(map(str, args)))


def write(tmp_path, text, name="engine.toml"):
    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    return path


def test_validate_accepts_the_whole_library():
    result = run("validate", CONFIGS)
    assert result.exit_code == 0, result.output
    assert result.output.count("ok: ") == len(list(CONFIGS.rglob("*.toml")))


BAD_INPUTS = [
    # (change to GOOD, key named in the message, words of the fix)
    (lambda t: t.replace('name = "test twin"', 'name = "test twin'), "", "not valid TOML"),
    (lambda t: t.replace('cycle = 4\n', ''), "cycle", "missing; this key is required"),
    (lambda t: t.replace('cycle = 4', 'cycle = 3'), "cycle", "must be 2 or 4"),
    (lambda t: 'colour = "red"\n' + t, "colour", "unknown key; check the spelling"),
    (lambda t: t.replace('phase = 180', 'phase = 180\nzz = "1 mm"'), "throws[2].zz", "unknown key"),
    (lambda t: t.replace('"40 mm"', '"40 kg"'), "crank_radius", "is a mass, but a length is needed"),
    (lambda t: t.replace('"3000 rpm"', '"3000"'), "speed", "write a number and a unit"),
    (lambda t: t.replace('"500 g"', '"-500 g"'), "masses.reciprocating", "greater than zero"),
    (lambda t: t.replace('"140 mm"', '"35 mm"'), "rod_length", "not longer than the crank radius"),
    (lambda t: t.replace('angle = 0', 'angle = "zero"'), "banks[1].angle", "expected a number"),
    (lambda t: t.replace('[1, 2]', '[1, 1]'), "firing_order", "not a permutation"),
    (lambda t: t.replace('[1, 2]', '[1, 2, 3]'), "firing_order", "not a permutation"),
    (lambda t: t.replace('[[banks]]\nangle = 0\n', ''), "banks", "missing"),
    (lambda t: 'frame = "upside-down"\n' + t, "frame", 'must be "fixed" or "rotary"'),
]


@pytest.mark.parametrize("change, key, words", BAD_INPUTS)
@pytest.mark.parametrize("command", ["validate", "compare", "show"])
def test_bad_configuration_gets_one_clear_message(tmp_path, change, key, words, command):
    path = write(tmp_path, change(GOOD))
    out = tmp_path / "out.json"
    args = [command, path] + (["--output", out] if command == "compare" else [])
    result = run(*args)
    assert result.exit_code != 0
    assert str(path) in result.output and words in result.output
    if key:
        assert f": {key}: " in result.output
    assert isinstance(result.exception, SystemExit) and result.exit_code == 1
    assert not out.exists()


def test_linkage_that_cannot_be_assembled_names_the_cylinder(tmp_path):
    path = write(tmp_path, LINKED.replace('length = "110 mm"', 'length = "20 mm"'))
    result = run("compare", path)
    assert result.exit_code != 0
    assert "cylinder 2: its link rod cannot reach the cylinder axis" in result.output
    assert isinstance(result.exception, SystemExit), result.exception


def test_firing_order_that_does_not_fit_the_crank(tmp_path):
    """In-line 4 on a flat crank with 1-4-2-3: see test_firing."""
    text = GOOD.replace('[1, 2]', '[1, 4, 2, 3]').replace(
        'phase = 180\n    z = "90 mm"', 'phase = 180\nz = "90 mm"')
    text = text.replace('[[throws]]\nphase = 180\nz = "90 mm"\n',
                        '[[throws]]\nphase = 180\nz = "90 mm"\n[[throws]]\nphase = 180\nz = "180 mm"\n'
                        '[[throws]]\nphase = 0\nz = "270 mm"\n')
    path = write(tmp_path, text)
    for command in ("validate", "compare", "show"):
        result = run(command, path)
        assert result.exit_code != 0, command
        assert f"{path}: firing_order: cylinder 3 cannot fire after cylinder 2" in result.output
        assert isinstance(result.exception, SystemExit), result.exception


def test_listed_cylinders_errors(tmp_path):
    base = LINKED.replace("[links]", "[[cylinders]]\nnumber = 1\nbank = 1\nthrow = 1\n\n"
                          "[[cylinders]]\nnumber = 2\nbank = 2\nthrow = 1\nmaster = 7\n\n[links]")
    result = run("validate", write(tmp_path, base))
    assert result.exit_code == 1
    assert "cylinders[2].master: names cylinder 7" in result.output
    twice = base.replace("number = 2", "number = 1")
    result = run("validate", write(tmp_path, twice, "twice.toml"))
    assert "cylinders[2].number: cylinder 1 is listed twice" in result.output


def test_missing_file_and_empty_folder(tmp_path):
    result = run("compare", tmp_path / "nothing.toml")
    assert result.exit_code != 0 and "no such file" in result.output
    result = run("compare", tmp_path)
    assert result.exit_code != 0 and "no .toml configuration found" in result.output


def test_unwritable_output_leaves_nothing(tmp_path):
    blocker = tmp_path / "file"
    blocker.write_text("x")
    result = run("compare", PART3 / "1a-v8-90-flat.toml", "--output", blocker / "sub" / "out.json")
    assert result.exit_code != 0 and "cannot create the folder" in result.output
    assert isinstance(result.exception, SystemExit), result.exception


def test_unknown_reference_lists_the_engines():
    result = run("compare", PART3, "--reference", "Zeppelin")
    assert result.exit_code != 0 and "matches no engine" in result.output and "60° W12" in result.output


def test_compare_json_contract(tmp_path):
    out = tmp_path / "deep" / "compare.json"
    result = run("compare", PART3, "--format", "json", "--output", out, "--max-order", "6")
    assert result.exit_code == 0, result.output
    assert [p.name for p in out.parent.iterdir()] == ["compare.json"]  # no temporary left behind
    document = json.loads(out.read_text(encoding="utf-8"))
    engines = document["engines"]
    assert len(engines) == 9
    v8 = engines[0]
    for key in ("name", "config", "cylinders", "cycle", "frame", "speed_rpm", "unit_force_N",
                "firing", "orders", "percent_of_reference"):
        assert key in v8
    assert set(v8["firing"]) >= {"order", "angles_deg", "intervals_deg", "uniform"}
    assert [o["order"] for o in v8["orders"]] == [1, 2, 3, 4, 5, 6]
    assert set(v8["orders"][0]["force"]) >= {"forward_N", "forward_deg", "backward_N",
                                            "backward_deg", "max_N", "min_N"}
    assert set(v8["orders"][0]["moment"]) >= {"forward_Nm", "forward_deg", "backward_Nm",
                                             "backward_deg", "max_Nm", "min_Nm"}
    assert v8["orders"][0]["force"]["max_N"] == 0.0  # zero orders are listed, as exact zeros
    second = v8["orders"][1]["force"]["max_N"] / v8["unit_force_N"] / v8["cylinders"]
    assert abs(second - 0.215) < 0.0005
    assert v8["speed_rpm"] == pytest.approx(1250.0, rel=1e-12)
    assert v8["firing"]["intervals_deg"] == pytest.approx([90.0] * 8, abs=1e-6)
    assert [round(e["percent_of_reference"]) for e in engines if e["name"] in
            ("60° W12", "9-cylinder rotary")] == [71, 16]


def test_compare_table_markdown_csv():
    table = run("compare", PART3)
    assert table.exit_code == 0
    assert "90° V8, flat crank" in table.output and "0.2147" in table.output
    assert "% of 90° V8, flat crank" in table.output
    markdown = run("compare", PART3, "--format", "markdown")
    assert "| Engine" in markdown.output
    csv_text = run("compare", PART3 / "2a-w12-60.toml", "--format", "csv").output
    header, *rows = csv_text.strip().splitlines()
    assert header.startswith("engine,config,order,force_forward_per_cyl")
    assert len(rows) == 8
    absolute = run("compare", PART3 / "2a-w12-60.toml", "--units", "kgf")
    assert "F max (kgf)" in absolute.output


def test_reference_by_prefix_changes_the_percentages():
    result = run("compare", PART3, "--reference", "60° W12,")
    assert result.exit_code == 0, result.output
    assert "% of 60° W12, link rods on t…" in result.output


def test_max_order_needs_enough_samples():
    result = run("compare", PART3, "--samples", "32", "--max-order", "8")
    assert result.exit_code == 1
    assert "--samples must be from 33 to 65536 for orders up to 8" in result.output
    assert run("compare", PART3, "--samples", "33", "--max-order", "8").exit_code == 0


def test_coarse_sampling_is_reported():
    result = run("compare", CONFIGS / "inline-4-marine.toml", "--samples", "16", "--max-order", "3")
    assert result.exit_code == 0
    assert "16 samples a revolution are too few for orders up to 3" in result.output


def test_list_and_show():
    listing = run("list", CONFIGS)
    assert listing.exit_code == 0 and "ABC Dragonfly" in listing.output and "Source" in listing.output
    shown = run("show", CONFIGS / "bramo-323.toml")
    assert shown.exit_code == 0
    assert "link on 1 (261.5 mm, knuckle 71.26 mm at 80°)" in shown.output
    assert "TDC (°)" in shown.output


def test_compare_does_not_import_matplotlib():
    code = ("import sys; from balance_cli.cli import main\n"
            "try:\n    main(['compare', sys.argv[1], '--format', 'json', '-o', sys.argv[2]])\n"
            "except SystemExit:\n    pass\n"
            "assert 'matplotlib' not in sys.modules, 'matplotlib imported'\n")
    import tempfile
    with tempfile.TemporaryDirectory() as folder:
        done = subprocess.run([sys.executable, "-c", code, str(PART3), f"{folder}/o.json"],
                              capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
