"""Writing configurations: the rows ``counterweight --write`` adds, their numbers to twelve
significant digits (the shortest decimal that reads back as the rounded value), a name of
the writer's choosing, and the arguments checked."""

import math
import tomllib

import pytest
from numpy.testing import assert_allclose

from balance_cli.config import WRITE_DIGITS, as_built_toml
from balance_cli.errors import BalanceError, ConfigError

DATA = {
    "name": "Twin",
    "cycle": 4,
    "speed": "3000 rpm",
    # the user's own numbers are written as they were read, whatever their digits
    "vertical": 0.1234567890123456,
}


def test_computed_numbers_are_written_to_twelve_significant_digits():
    """0.45 kg / 2 computed as 0.22500000000000003 is written 0.225; 1/3 kg as the twelve
    digits 0.333333333333 (3.3e-13 kg off, 1e-12 of it: within half a unit of the twelfth
    digit, 5e-12); an angle of 180° less 3e-14 as 180.0; the user's own numbers untouched."""
    assert WRITE_DIGITS == 12
    rows = [
        {"throw": 1, "mass": "0.22500000000000003 kg", "radius": "0.03 m", "angle": 180.0},
        {
            "throw": 2,
            "mass": f"{1 / 3!r} kg",
            "radius": "0.030000000000000002 m",
            "angle": 179.99999999999997,
            "z": "-0.0 m",
        },
    ]
    text = as_built_toml(DATA, {"counterweights": rows}, "made here")
    assert text.startswith("# made here\n")
    assert 'mass = "0.225 kg"' in text and 'mass = "0.333333333333 kg"' in text
    assert 'radius = "0.03 m"' in text and "angle = 180.0" in text and 'z = "0.0 m"' in text
    assert "vertical = 0.1234567890123456" in text and 'name = "Twin"' in text
    read = tomllib.loads(text)
    written = [float(w["mass"].split()[0]) for w in read["counterweights"]]
    # the rule: each number within half a unit of its twelfth significant digit
    assert_allclose(written, [0.225, 1 / 3], rtol=5 * 10.0**-WRITE_DIGITS, atol=0)
    assert read["counterweights"][1]["angle"] == 180.0


def test_a_new_name_and_the_rows_added_after_those_built():
    """The shafts' masses (a table in a table) are rounded too; the built rows come first."""
    built = {**DATA, "counterweights": [{"throw": 1, "mass_radius": "0.01 kg*m", "angle": 90}]}
    shaft = {
        "ratio": 2,
        "lateral": "0.1 m",
        "vertical": "-0.05000000000000001 m",
        "masses": [{"mass_radius": "0.0020000000000000005 kg*m", "angle": -90.00000000000001}],
    }
    added = {"throw": 2, "mass": "1e-05 kg", "radius": "0.05 m", "angle": 0.0}
    read = tomllib.loads(
        as_built_toml(built, {"counterweights": [added], "shafts": [shaft]}, name="Twin, balanced")
    )
    assert read["name"] == "Twin, balanced"
    assert [w["throw"] for w in read["counterweights"]] == [1, 2]
    assert read["counterweights"][1]["mass"] == "1e-05 kg"
    (written,) = read["shafts"]
    assert written["vertical"] == "-0.05 m"
    assert written["masses"] == [{"mass_radius": "0.002 kg*m", "angle": -90.0}]
    assert built["name"] == "Twin" and len(built["counterweights"]) == 1  # not changed


@pytest.mark.parametrize(
    "call, parameter",
    [
        (lambda: as_built_toml(DATA, None), "tables"),
        (lambda: as_built_toml(None, {}), "data"),
        (lambda: as_built_toml("name = 'x'", {}), "data"),
        (lambda: as_built_toml(DATA, [{"throw": 1}]), "tables"),
        (lambda: as_built_toml(DATA, {"cylinders": [{"number": 1}]}), "tables"),
        (lambda: as_built_toml(DATA, {"counterweights": {"throw": 1}}), "tables"),
        (lambda: as_built_toml(DATA, {"counterweights": [3]}), "tables"),
        (lambda: as_built_toml(DATA, {"counterweights": [{"mass": None}]}), "tables"),
        (lambda: as_built_toml({**DATA, "source": object()}, {}), "data"),
        (lambda: as_built_toml(DATA, {}, header=None), "header"),
        (lambda: as_built_toml(DATA, {}, name=""), "name"),
        (lambda: as_built_toml(DATA, {}, name="two\nlines"), "name"),
        (lambda: as_built_toml(DATA, {}, name=3), "name"),
    ],
)
def test_arguments_are_checked(call, parameter):
    """One ConfigError (a BalanceError) naming the argument, not a TypeError, nor a file
    written with the argument silently dropped."""
    with pytest.raises(ConfigError) as caught:
        call()
    assert isinstance(caught.value, BalanceError) and caught.value.parameter == parameter
    assert str(caught.value).startswith(f"<config>: {parameter} ")
    assert "\n" not in str(caught.value)


def test_non_finite_numbers_are_kept_as_toml_writes_them():
    """inf is a TOML float: rounding leaves it (a computed inf would be the analysis' fault,
    not the writer's to hide)."""
    text = as_built_toml(DATA, {"counterweights": [{"angle": math.inf}]})
    assert tomllib.loads(text)["counterweights"][0]["angle"] == math.inf
