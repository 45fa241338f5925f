"""Reading a configuration: every malformed, extreme or non-finite value gets one error line
naming the file and the key (the command's exit status, no traceback, no output file left),
and a valid file is read whatever its byte-order mark."""

import json
import tomllib

import pytest
from click.testing import CliRunner
from hypothesis import given, settings
from hypothesis import strategies as st

from balance_cli.cli import main
from balance_cli.config import build
from balance_cli.errors import ConfigError
from tests.support import (
    BOXER,
    LINKED,
    TEMPLATES,
    TWIN,
    check_refused,
    invoke,
    replaced,
    snapshot,
    twin_file,
    write,
)

BAD_INPUTS = [
    # (change to TWIN, key named in the message, words of the fix)
    (lambda t: t.replace('name = "test twin"', 'name = "test twin'), "", "not valid TOML"),
    (lambda t: t.replace("cycle = 4\n", ""), "cycle", "missing; this key is required"),
    (lambda t: t.replace("cycle = 4", "cycle = 3"), "cycle", "must be 2 or 4"),
    (lambda t: 'colour = "red"\n' + t, "colour", "unknown key; check the spelling"),
    (lambda t: t.replace("phase = 180", 'phase = 180\nzz = "1 mm"'), "throws[2].zz", "unknown key"),
    (
        lambda t: t.replace('"40 mm"', '"40 kg"'),
        "crank_radius",
        "is a mass, but a length is needed",
    ),
    (lambda t: t.replace('"3000 rpm"', '"3000"'), "speed", "write a number and a unit"),
    (lambda t: t.replace('"500 g"', '"-500 g"'), "masses.reciprocating", "greater than zero"),
    (lambda t: t.replace('"140 mm"', '"35 mm"'), "rod_length", "not longer than the crank radius"),
    (lambda t: t.replace("angle = 0", 'angle = "zero"'), "banks[1].angle", "expected a number"),
    (lambda t: t.replace("[1, 2]", "[1, 1]"), "firing_order", "not a permutation"),
    (lambda t: t.replace("[1, 2]", "[1, 2, 3]"), "firing_order", "not a permutation"),
    (lambda t: t.replace("[[banks]]\nangle = 0\n", ""), "banks", "missing"),
    (lambda t: 'frame = "upside-down"\n' + t, "frame", 'must be "fixed" or "rotary"'),
]
LISTED = """\
name = "listed V"
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

[[cylinders]]
number = 1
bank = 1
throw = 1
[[cylinders]]
number = 2
bank = 2
throw = 1
"""
#: (id, configuration text, words the one error line must hold); run as `compare FILE -o OUT`
CONFIG_CASES = [
    ("not-toml", "name = \n", "not valid TOML"),
    ("empty", "", "name: missing"),
    ("unclosed-string", replaced('"test twin"', '"hostile twin'), "not valid TOML"),
    ("missing-name", replaced('name = "test twin"\n', ""), "name: missing"),
    ("name-newline", replaced('"test twin"', '"hostile\\ntwin"'), "name: must be one line"),
    ("name-empty", replaced('"test twin"', '"  "'), "name: expected a non-empty string"),
    ("name-number", replaced('"test twin"', "12"), "name: expected a non-empty string"),
    ("cycle-3", replaced("cycle = 4", "cycle = 3"), "cycle: must be 2 or 4"),
    ("cycle-string", replaced("cycle = 4", 'cycle = "4"'), "cycle: expected a whole number"),
    ("cycle-bool", replaced("cycle = 4", "cycle = true"), "cycle: expected a whole number"),
    ("speed-no-unit", replaced('"3000 rpm"', '"3000"'), "speed: cannot read '3000'"),
    ("speed-huge", replaced('"3000 rpm"', '"1e200 rpm"'), "speed: '1e200 rpm' is outside"),
    ("speed-tiny", replaced('"3000 rpm"', '"1e-300 rpm"'), "speed: '1e-300 rpm' is outside"),
    ("speed-zero", replaced('"3000 rpm"', '"0 rpm"'), "speed: must be greater than zero"),
    ("speed-negative", replaced('"3000 rpm"', '"-3000 rpm"'), "speed: must be greater than zero"),
    ("speed-nan", replaced('"3000 rpm"', '"nan rpm"'), "speed: cannot read 'nan rpm'"),
    ("speed-inf", replaced('"3000 rpm"', '"inf rpm"'), "speed: cannot read 'inf rpm'"),
    ("speed-overflow", replaced('"3000 rpm"', '"1e400 rpm"'), "is not a finite number"),
    ("speed-length", replaced('"3000 rpm"', '"3000 mm"'), "is a length, but an angular speed"),
    ("speed-number", replaced('"3000 rpm"', "3000"), "speed: expected a string with a unit"),
    (
        "crank-overflow",
        replaced('"40 mm"', '"1e400 mm"'),
        "crank_radius: '1e400 mm' is not a finite",
    ),
    ("crank-mass", replaced('"40 mm"', '"40 kg"'), "crank_radius: '40 kg' is a mass"),
    ("crank-unknown-unit", replaced('"40 mm"', '"40 furlong"'), "unknown unit 'furlong'"),
    ("crank-huge", replaced('"40 mm"', '"40 km"'), "unknown unit 'km'"),
    ("crank-too-big", replaced('"40 mm"', '"4e6 mm"'), "crank_radius: '4e6 mm' is outside"),
    ("rod-shorter", replaced('"140 mm"', '"35 mm"'), "rod_length: of 0.035 m is not longer"),
    ("rod-equal", replaced('"140 mm"', '"40 mm"'), "rod_length: of 0.04 m is not longer"),
    (
        "rod-with-offset",
        replaced('rod_length = "140 mm"', 'rod_length = "60 mm"\npin_offset = "25 mm"'),
        "is not longer than the crank radius plus |pin offset|",
    ),
    (
        "offset-overflow",
        replaced('rod_length = "140 mm"', 'rod_length = "140 mm"\npin_offset = "1e400 mm"'),
        "pin_offset: '1e400 mm' is not a finite",
    ),
    (
        "mass-overflow",
        replaced('"500 g"', '"1e400 g"'),
        "masses.reciprocating: '1e400 g' is not a finite",
    ),
    ("mass-zero", replaced('"500 g"', '"0 g"'), "masses.reciprocating: must be greater than zero"),
    ("mass-huge", replaced('"500 g"', '"1e12 g"'), "masses.reciprocating: '1e12 g' is outside"),
    (
        "rotating-negative",
        replaced('reciprocating = "500 g"', 'reciprocating = "500 g"\nrotating = "-1 g"'),
        "masses.rotating: must not be negative",
    ),
    (
        "masses-unknown-key",
        replaced('reciprocating = "500 g"', 'reciprocating = "500 g"\npiston = "1 g"'),
        "masses.piston: unknown key",
    ),
    ("masses-missing", replaced('[masses]\nreciprocating = "500 g"\n', ""), "masses: missing"),
    (
        "masses-not-table",
        replaced('[masses]\nreciprocating = "500 g"\n', "").replace(
            "firing_order = [1, 2]", "firing_order = [1, 2]\nmasses = 3"
        ),
        "masses: expected a table",
    ),
    ("banks-missing", replaced("[[banks]]\nangle = 0\n", ""), "banks: missing"),
    (
        "bank-angle-text",
        replaced("angle = 0", 'angle = "zero"'),
        "banks[1].angle: expected a number",
    ),
    ("bank-angle-inf", replaced("angle = 0", "angle = inf"), "banks[1].angle: expected a number"),
    ("bank-angle-nan", replaced("angle = 0", "angle = nan"), "banks[1].angle: expected a number"),
    (
        "bank-angle-huge",
        replaced("angle = 0", "angle = 1e9"),
        "banks[1].angle: must be between -360",
    ),
    (
        "throws-empty",
        "throws = []\n" + TWIN[: TWIN.index("[[throws]]")],
        "throws: expected one or more [[throws]] tables",
    ),
    ("throw-phase-missing", replaced("phase = 180\n", ""), "throws[2].phase: missing"),
    ("throw-z-mass", replaced('z = "90 mm"', 'z = "90 kg"'), "throws[2].z: '90 kg' is a mass"),
    ("unknown-top-key", 'colour = "red"\n' + TWIN, "colour: unknown key"),
    ("firing-repeated", replaced("[1, 2]", "[1, 1]"), "firing_order: [1, 1] is not a permutation"),
    (
        "firing-too-long",
        replaced("[1, 2]", "[1, 2, 3]"),
        "firing_order: [1, 2, 3] is not a permutation",
    ),
    (
        "firing-strings",
        replaced("[1, 2]", '["1", "2"]'),
        "firing_order: expected a list of cylinder numbers",
    ),
    ("frame-unknown", 'frame = "upside-down"\n' + TWIN, 'frame: must be "fixed" or "rotary"'),
    (
        "links-bank-out-of-range",
        LISTED.replace(
            "[[cylinders]]",
            '[links]\nmaster_bank = 5\nlength = "110 mm"\n'
            'knuckle_radius = "30 mm"\n\n[[cylinders]]',
            1,
        ),
        "links.master_bank: must be between 1 and 2",
    ),
    (
        "link-cannot-reach",
        LISTED + 'master = 1\nlink_length = "20 mm"\nknuckle_radius = "30 mm"\n',
        "cylinders[2]: cylinder 2: its link rod cannot reach the cylinder axis",
    ),
    (
        "two-in-one-bore",
        LISTED.replace("number = 2\nbank = 2", "number = 2\nbank = 1"),
        "cylinders[2]: cylinder 2 sits in the bore of cylinder 1",
    ),
    (
        "cylinder-twice",
        LISTED.replace("number = 2", "number = 1"),
        "cylinders[2].number: cylinder 1 is listed twice",
    ),
    (
        "master-missing",
        LISTED + "master = 7\n",
        "cylinders[2].master: names cylinder 7, which is not listed",
    ),
    (
        "master-itself",
        LISTED + 'master = 2\nlink_length = "110 mm"\nknuckle_radius = "30 mm"\n',
        "cylinders[2]: cylinder 2: its master 2 is not another cylinder",
    ),
    (
        "cylinder-bank-zero",
        LISTED.replace("number = 2\nbank = 2", "number = 2\nbank = 0"),
        "cylinders[2].bank: must be between 1 and 2",
    ),
    (
        "cylinder-throw-nine",
        LISTED.replace("bank = 2\nthrow = 1", "bank = 2\nthrow = 9"),
        "cylinders[2].throw: must be between 1 and 1",
    ),
    (
        "cylinder-number-bool",
        LISTED.replace("number = 2", "number = true"),
        "cylinders[2].number: expected a whole number",
    ),
    (
        "knuckle-angle-huge",
        LISTED + 'master = 1\nlink_length = "110 mm"\nknuckle_radius = "30 mm"\n'
        "knuckle_angle = 1000\n",
        "cylinders[2].knuckle_angle: must be between",
    ),
    (
        "plain-rod-with-link-key",
        LISTED + 'link_length = "110 mm"\n',
        "cylinders[2].link_length: only a link rod",
    ),
    (
        "firing-does-not-fit",
        replaced("firing_order = [1, 2]", "firing_order = [1, 4, 2, 3]").replace(
            '[[throws]]\nphase = 180\nz = "90 mm"\n',
            '[[throws]]\nphase = 180\nz = "90 mm"\n[[throws]]\nphase = 180\nz = "180 mm"\n'
            '[[throws]]\nphase = 0\nz = "270 mm"\n',
        ),
        "firing_order: cylinder 3 cannot fire after cylinder 2",
    ),
]
NASTY = [
    '"abc"',
    "-1",
    "0",
    "1e400",
    "[]",
    "{}",
    "true",
    '"0 mm"',
    '"-5 kg"',
    '"1 rpm"',
    '"nan mm"',
    '"12 parsecs"',
    "[1, 2, 2]",
    "99999999999999999999",
    '"1e308 m"',
    '"1e-300 mm"',
    "[[1]]",
    '""',
    "3.5",
    "-0.0",
]


@st.composite
def malformed(draw):
    text = draw(st.sampled_from([TWIN, LINKED]))
    lines = text.splitlines()
    for _ in range(draw(st.integers(1, 3))):
        i = draw(st.integers(0, len(lines) - 1))
        action = draw(st.sampled_from(["value", "delete", "key", "garble"]))
        if action == "value" and "=" in lines[i]:
            key = lines[i].split("=")[0]
            lines[i] = f"{key}= {draw(st.sampled_from(NASTY))}"
        elif action == "delete":
            del lines[i]
            if not lines:
                lines = ["x = 1"]
        elif action == "key":
            lines.insert(
                i,
                f"{draw(st.sampled_from(['zz', 'angle', 'phase', 'master', 'links']))} = "
                f"{draw(st.sampled_from(NASTY))}",
            )
        else:
            j = draw(st.integers(0, len(lines[i])))
            lines[i] = (
                lines[i][:j] + draw(st.sampled_from(["[", "]", '"', "=", "#", "\\"])) + lines[i][j:]
            )
    return "\n".join(lines) + "\n"


@pytest.mark.parametrize("change, key, words", BAD_INPUTS)
@pytest.mark.parametrize("command", ["validate", "compare", "show"])
def test_bad_configuration_gets_one_clear_message(tmp_path, change, key, words, command):
    path = write(tmp_path, change(TWIN))
    out = tmp_path / "out.json"
    args = [command, path] + (["--output", out] if command == "compare" else [])
    result = invoke(*args)
    assert result.exit_code != 0
    assert str(path) in result.output and words in result.output
    if key:
        assert f": {key}: " in result.output
    assert isinstance(result.exception, SystemExit) and result.exit_code == 1
    assert not out.exists()


def test_linkage_that_cannot_be_assembled_names_the_cylinder(tmp_path):
    path = write(tmp_path, LINKED.replace('length = "110 mm"', 'length = "20 mm"'))
    result = invoke("compare", path)
    assert result.exit_code != 0
    assert "cylinder 2: its link rod cannot reach the cylinder axis" in result.output
    assert isinstance(result.exception, SystemExit), result.exception


def test_firing_order_that_does_not_fit_the_crank(tmp_path):
    """In-line 4 on a flat crank with 1-4-2-3: see tests/analysis/test_firing.py."""
    text = TWIN.replace("[1, 2]", "[1, 4, 2, 3]").replace(
        'phase = 180\n    z = "90 mm"', 'phase = 180\nz = "90 mm"'
    )
    text = text.replace(
        '[[throws]]\nphase = 180\nz = "90 mm"\n',
        '[[throws]]\nphase = 180\nz = "90 mm"\n[[throws]]\nphase = 180\nz = "180 mm"\n'
        '[[throws]]\nphase = 0\nz = "270 mm"\n',
    )
    path = write(tmp_path, text)
    for command in ("validate", "compare", "show"):
        result = invoke(command, path)
        assert result.exit_code != 0, command
        assert f"{path}: firing_order: cylinder 3 cannot fire after cylinder 2" in result.output
        assert isinstance(result.exception, SystemExit), result.exception


def test_listed_cylinders_errors(tmp_path):
    base = LINKED.replace(
        "[links]",
        "[[cylinders]]\nnumber = 1\nbank = 1\nthrow = 1\n\n"
        "[[cylinders]]\nnumber = 2\nbank = 2\nthrow = 1\nmaster = 7\n\n[links]",
    )
    result = invoke("validate", write(tmp_path, base))
    assert result.exit_code == 1
    assert "cylinders[2].master: names cylinder 7" in result.output
    twice = base.replace("number = 2", "number = 1")
    result = invoke("validate", write(tmp_path, twice, "twice.toml"))
    assert "cylinders[2].number: cylinder 1 is listed twice" in result.output


@pytest.mark.parametrize(
    "text, words", [case[1:] for case in CONFIG_CASES], ids=[case[0] for case in CONFIG_CASES]
)
def test_malformed_configuration(tmp_path, text, words):
    config = tmp_path / "engine.toml"
    config.write_text(text, encoding="utf-8")
    before = snapshot(tmp_path)
    result = invoke("compare", config, "--output", tmp_path / "out.json")
    check_refused(result, 1, f"{config}: ", before, tmp_path)
    assert words in result.stderr


def test_not_utf8(tmp_path):
    config = tmp_path / "engine.toml"
    config.write_bytes(b'name = "\xff\xfe"\n')
    before = snapshot(tmp_path)
    result = invoke("compare", config, "-o", tmp_path / "o.txt")
    check_refused(result, 1, "not UTF-8 text", before, tmp_path)


@pytest.mark.parametrize(
    "change, words",
    [
        (
            lambda t: t.replace(
                "[[banks]]\nangle = 0\n", "[[banks]]\nangle = 0\n[[banks]]\nangle = 360\n"
            ),
            "banks: 1 and 2 point the same way",
        ),
        (
            lambda t: t.replace('"test twin"', '"' + "x" * 200 + '"'),
            "name: must be a non-empty line",
        ),
    ],
)
def test_impossible_geometry_and_overlong_names(tmp_path, change, words):
    config = twin_file(tmp_path, change(TWIN))
    before = snapshot(tmp_path)
    result = invoke("compare", config, "-o", tmp_path / "o.txt")
    check_refused(result, 1, words, before, tmp_path)


def test_a_knuckle_beyond_the_master_rod_is_refused(tmp_path):
    text = LISTED + 'master = 1\nlink_length = "110 mm"\nknuckle_radius = "200 mm"\n'
    config = twin_file(tmp_path, text)
    before = snapshot(tmp_path)
    check_refused(
        invoke("compare", config, "-o", tmp_path / "o.txt"),
        1,
        "knuckle_radius (0.2 m) must be shorter than the master rod",
        before,
        tmp_path,
    )


def test_a_configuration_with_a_byte_order_mark_is_read(tmp_path):
    """Guards against a UTF-8 byte-order mark refused as "Invalid statement (line 1,
    column 1)"; CSV files accepted it. The same engine with and without the mark compares
    alike, from a file and from a string."""
    import balance_cli as balance

    plain = twin_file(tmp_path, name="plain.toml")
    marked = tmp_path / "marked.toml"
    marked.write_bytes(b"\xef\xbb\xbf" + TWIN.encode("utf-8"))
    before = snapshot(tmp_path)
    result = invoke("compare", marked, "--format", "json")
    assert result.exit_code == 0, result.output
    assert (
        json.loads(result.stdout)["engines"][0]["orders"]
        == json.loads(invoke("compare", plain, "--format", "json").stdout)["engines"][0]["orders"]
    )
    assert snapshot(tmp_path) == before
    assert balance.loads("\ufeff" + TWIN).name == "test twin"
    template = tmp_path / "template.toml"
    template.write_bytes(b"\xef\xbb\xbf" + (TEMPLATES / "inline-6-2stroke.toml").read_bytes())
    assert balance.load_template(template).n_cylinders == 6


def test_a_name_with_a_line_break_is_refused(tmp_path):
    config = tmp_path / "e.toml"
    config.write_text(BOXER.replace("Flat twin |", "Flat\\ntwin |"), encoding="utf-8")
    result = invoke("compare", config)
    assert result.exit_code == 1 and "name: must be one line of printable text" in result.stderr


@settings(derandomize=True, max_examples=150, deadline=None)
@given(malformed())
def test_malformed_configurations_end_in_a_clean_error(text):
    """Either a valid engine or a ConfigError naming the file; never anything else."""
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError:
        return  # load() turns this into a ConfigError; see test_bad_configuration_…
    try:
        build(data, "random.toml")
    except ConfigError as exc:
        assert str(exc).startswith("random.toml: ")


@settings(derandomize=True, max_examples=40, deadline=None)
@given(malformed())
def test_malformed_configurations_never_show_a_traceback(tmp_path_factory, text):
    path = tmp_path_factory.mktemp("cfg") / "engine.toml"
    path.write_text(text, encoding="utf-8")
    result = CliRunner().invoke(main, ["compare", str(path), "--format", "json"])
    assert result.exit_code in (0, 1), result.output
    # an uncaught exception would be result.exception itself; a clean error is SystemExit
    assert (
        (result.exception is None)
        if result.exit_code == 0
        else isinstance(result.exception, SystemExit)
    )
    if result.exit_code == 1:
        assert result.output.startswith("Error: ") and str(path) in result.output
    else:
        assert result.exception is None
