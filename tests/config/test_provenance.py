"""A configuration's ``sources`` and ``estimates``: their form checked on reading (one line
naming the file, the entry and the fix), the keys they name, the numbers they cover, and the
Estimates column of ``balance list``."""

import tomllib

import pytest
from click.testing import CliRunner

import balance_cli as balance
from balance_cli.cli import main
from balance_cli.config import Note, build, number_paths, read_provenance
from balance_cli.errors import ConfigError
from tests.support import TWIN, check_refused, invoke, snapshot, write

NOTES = (
    "sources = [\n"
    '    "crank_radius, rod_length, throws.phase: maker\'s data sheet (2020)",\n'
    '    "cycle, banks: a four-stroke in-line twin",\n'
    "]\n"
    "estimates = [\n"
    '    "speed: chosen",\n'
    '    "masses, throws[2].z: scaled from the bore",\n'
    "]\n"
)


def twin_with(notes):
    """TWIN with ``notes`` among its top-level keys."""
    return TWIN.replace("cycle = 4\n", notes + "cycle = 4\n", 1)


def test_notes_are_read_and_the_engine_is_unchanged():
    data = tomllib.loads(twin_with(NOTES))
    provenance = read_provenance(data, "twin.toml")
    assert provenance.sources[0] == Note(
        ("crank_radius", "rod_length", "throws.phase"), "maker's data sheet (2020)"
    )
    assert provenance.estimates[1].keys == ("masses", "throws[2].z")
    assert build(data, "twin.toml") == build(tomllib.loads(TWIN), "twin.toml")
    assert balance.loads(twin_with(NOTES)).name == "test twin"
    # and back to the file's own strings
    assert provenance.to_dict()["estimates"] == [
        "speed: chosen",
        "masses, throws[2].z: scaled from the bore",
    ]


def test_which_numbers_the_notes_cover():
    """TWIN's numbers: cycle, speed, crank_radius, rod_length, firing_order, the mass, one bank
    angle, two throws' phase and z. The sources name crank_radius, rod_length, both phases,
    cycle and the bank; the estimates speed, the mass and the second throw's z: the first
    throw's z and the firing order are spoken for by neither."""
    data = tomllib.loads(twin_with(NOTES))
    provenance = read_provenance(data)
    assert number_paths(data) == [
        "cycle",
        "speed",
        "crank_radius",
        "rod_length",
        "firing_order",
        "masses.reciprocating",
        "banks[1].angle",
        "throws[1].phase",
        "throws[1].z",
        "throws[2].phase",
        "throws[2].z",
    ]
    assert provenance.estimated(data) == ["speed", "masses.reciprocating", "throws[2].z"]
    assert provenance.unsourced(data) == ["firing_order", "throws[1].z"]
    assert provenance.unknown_selectors(data) == []


@pytest.mark.parametrize(
    "selector, path, covered",
    [
        ("*", "cylinders[3].z", True),
        ("throws", "throws[3].z", True),
        ("throws.z", "throws[3].z", True),
        ("throws[3].z", "throws[3].z", True),
        ("throws[3]", "throws[3].phase", True),
        ("throws[2].z", "throws[3].z", False),
        ("throws.z", "throws[3].phase", False),
        ("masses", "masses.rotating", True),
        ("masses.rotating", "masses", False),
        ("gas", "gasket", False),
        ("torsion.front.inertia", "torsion.front[2].inertia", True),
    ],
)
def test_a_selector_names_a_key_and_everything_under_it(selector, path, covered):
    assert Note((selector,), "why").covers(path) is covered


def test_names_indices_and_notes_are_not_numbers():
    data = tomllib.loads(
        twin_with('source = "x"\nframe = "fixed"\n')
        + '[[cylinders]]\nnumber = 1\nbank = 1\nthrow = 1\nz = "0 mm"\n'
        + "[[cylinders]]\nnumber = 2\nbank = 1\nthrow = 2\n"
    )
    paths = number_paths(data)
    assert "cylinders[1].z" in paths
    for word in ("name", "source", "frame", "number", "bank", "throw"):
        assert not any(p == word or p.endswith("." + word) for p in paths), word


def test_selectors_that_name_nothing_are_found():
    data = tomllib.loads(twin_with('estimates = ["rod_lenght, throws[3].z, gas: why"]\n'))
    assert read_provenance(data).unknown_selectors(data) == ["rod_lenght", "throws[3].z", "gas"]


@pytest.mark.parametrize(
    "notes, key, words",
    [
        ('sources = "maker"\n', "sources", 'expected a list of "KEYS: text" strings'),
        ("estimates = []\n", "estimates", 'expected a list of "KEYS: text" strings'),
        ("sources = [3]\n", "sources[1]", 'expected a "KEYS: text" string'),
        ('sources = ["  "]\n', "sources[1]", 'expected a "KEYS: text" string'),
        ('sources = ["Tanaka (1925)"]\n', "sources[1]", "the keys it speaks for, a colon"),
        ('sources = ["rod_length:maker"]\n', "sources[1]", "the keys it speaks for, a colon"),
        ('sources = ["rod_length: "]\n', "sources[1]", "the keys it speaks for, a colon"),
        (
            'estimates = ["speed: ok", "Tanaka (1925): Appendix I"]\n',
            "estimates[2]",
            "'Tanaka (1925)' is not a key",
        ),
        ('estimates = ["throws[0].z: why"]\n', "estimates[1]", "'throws[0].z' is not a key"),
        ('estimates = ["speed,: why"]\n', "estimates[1]", "'' is not a key"),
        ('estimates = ["speed: a\\tb"]\n', "estimates[1]", "one line of printable text"),
    ],
)
def test_bad_notes_are_named_with_the_fix(notes, key, words):
    with pytest.raises(ConfigError) as info:
        balance.loads(twin_with(notes), name="twin.toml")
    assert info.value.key == key, str(info.value)
    assert words in str(info.value)
    assert str(info.value).startswith("twin.toml: ")


def test_bad_notes_are_one_line_from_the_command(tmp_path):
    path = write(tmp_path, twin_with('sources = ["Tanaka (1925)"]\n'))
    before = snapshot(tmp_path)
    check_refused(invoke("compare", path), 1, "sources[1]", before, tmp_path)


def test_a_configuration_gives_its_notes():
    configuration = balance.Configuration(tomllib.loads(twin_with(NOTES)), "twin.toml")
    assert len(configuration.provenance.estimates) == 2
    assert not balance.Configuration(tomllib.loads(TWIN)).provenance.declared


def test_a_template_or_family_of_a_file_may_drop_keys_its_notes_name():
    """The notes' form is the format's; that each names a key of the file is the library's
    policy: a search template has no phases, yet the file's sources name them."""
    configuration = balance.Configuration(tomllib.loads(twin_with(NOTES)), "twin.toml")
    template = configuration.as_template()
    assert template.template().n_cylinders == 2
    data = template.data
    assert read_provenance(data).unknown_selectors(data) == ["throws.phase"]


def test_list_shows_how_many_numbers_are_estimates(tmp_path):
    """Three numbers estimated (speed, the mass, throw 2's z); "none" where a file declares
    sources only; blank where it declares neither."""
    write(tmp_path, twin_with(NOTES).replace("test twin", "noted"), "a.toml")
    write(
        tmp_path,
        twin_with('sources = ["*: a maker\'s data sheet"]\n').replace("test twin", "sourced"),
        "b.toml",
    )
    write(tmp_path, TWIN.replace("test twin", "plain"), "c.toml")
    result = CliRunner().invoke(main, ["list", str(tmp_path)])
    assert result.exit_code == 0, result.output
    lines = result.output.splitlines()
    header = next(line for line in lines if line.startswith("Config"))
    start, end = header.index("Estimates"), header.index("Source")
    cells = {
        line.split()[0].rsplit("/", 1)[-1]: line[start:end].strip()
        for line in lines
        if line.split() and line.split()[0].endswith(".toml")
    }
    assert cells == {"a.toml": "3", "b.toml": "none", "c.toml": ""}
