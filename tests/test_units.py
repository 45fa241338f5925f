"""Quantities with units (balance_cli.units): parsing into SI, unit systems for display,
significant figures and angles normalised once."""

import math

import pytest
from numpy.testing import assert_allclose

import balance_cli as balance
from balance_cli.units import (
    UNIT_SYSTEMS,
    Scale,
    UnitError,
    parse_quantity,
    round_degrees,
    significant,
    wrap_degrees,
)
from tests.support import invoke


@pytest.mark.parametrize(
    "text, dimension, si",
    [
        ("82.5 mm", "length", 0.0825),
        ("5.5 in", "length", 0.1397),  # 5.5 × 25.4 mm, exact by definition of the inch
        ("-1.5 m", "length", -1.5),
        ("1770.4 g", "mass", 1.7704),
        ("500 kg", "mass", 500.0),
        ("1 lb", "mass", 0.45359237),  # exact by definition of the pound
        ("1650 rpm", "angular speed", 1650 * 2 * math.pi / 60),
        ("60 rev/min", "angular speed", 2 * math.pi),
        ("1e3 mm", "length", 1.0),
    ],
)
def test_quantities_convert_to_si(text, dimension, si):
    assert_allclose(parse_quantity(text, dimension), si, rtol=1e-15)


@pytest.mark.parametrize(
    "value, dimension, words",
    [
        ("82.5 g", "length", "is a mass, but a length is needed"),
        ("10 furlongs", "length", "unknown unit 'furlongs'"),
        ("82.5", "length", "write a number and a unit"),
        (82.5, "length", "expected a string with a unit"),
        (True, "mass", "expected a string with a unit"),
        ("mm 82.5", "length", "write a number and a unit"),
    ],
)
def test_bad_quantities_say_what_to_write(value, dimension, words):
    with pytest.raises(UnitError, match=words):
        parse_quantity(value, dimension)


@pytest.mark.parametrize(
    "units, force, moment",
    [
        ("N", 1.0, 1.0),
        ("kN", 1e3, 1e3),
        ("MN", 1e6, 1e6),
        ("kgf", 9.80665, 9.80665),
        # 1 lbf = 0.45359237 kg × 9.80665 m/s² = 4.4482216152605 N; 1 lbf·ft = that × 0.3048 m
        ("lbf", 4.4482216152605, 1.3558179483314004),
    ],
)
def test_unit_systems_against_hand_conversion(units, force, moment):
    scale = Scale.of(False, units.upper() if units != "MN" else "Mn")
    assert scale.units == units
    assert_allclose(
        scale.force(force * 123.0, 1.0), 123.0 if units != "N" else 123.0 * force, rtol=1e-15
    )
    assert_allclose(scale.moment(moment * 7.0), 7.0, rtol=1e-15)
    assert (
        UNIT_SYSTEMS[units][1]
        == {"N": "N·m", "kN": "kN·m", "MN": "MN·m", "kgf": "kgf·m", "lbf": "lbf·ft"}[units]
    )


def test_significant_figures():
    assert significant(4980395.12) == "4 980 000"
    assert significant(4980395.12 / 1e3) == "4 980"
    assert significant(0.214712) == "0.2147"
    assert significant(3.4e-5) == "3.400e-05"
    assert significant(0.0) == "0"
    assert significant(-12.5) == "-12.50"


def test_unit_names_in_any_case_unless_ambiguous():
    assert parse_quantity("1650 RPM", "angular speed") == pytest.approx(1650 * math.pi / 30)
    assert parse_quantity("2 KG", "mass") == 2.0
    # 1 psi = 6894.757293168 Pa; P here is no prefix
    assert parse_quantity("1 PSI", "pressure") == pytest.approx(6894.757293168, rel=1e-15)
    for text, dimension, meant in (
        ("5 Mm", "length", "'mm'"),
        ("5 mpa", "pressure", "'MPa'"),
        ("0.05 M", "length", "'m'"),
        ("5 MBAR", "pressure", "'mbar'"),
        ("1 kg*Mm^2", "moment of inertia", "'kg*mm^2'"),
    ):
        with pytest.raises(balance.UnitError) as caught:
            parse_quantity(text, dimension)
        assert "milli" in str(caught.value) and "mega" in str(caught.value)
        assert f"write {meant}" in str(caught.value)
    for name in ("mn", "mN"):
        with pytest.raises(balance.UnitError, match="milli"):
            Scale.of(False, name)
    out = invoke("compare", "configs/inline-4-car.toml", "--units", "mn")
    assert out.exit_code == 2 and "milli" in out.output and "Traceback" not in out.output


def test_wrap_and_round_degrees():
    assert wrap_degrees(-1e-12) == 0.0 and wrap_degrees(360.0) == 0.0
    assert wrap_degrees(179.9999999, 180.0) == 0.0 and wrap_degrees(179.99, 180.0) == 179.99
    assert wrap_degrees(-90.0) == 270.0 and wrap_degrees(725.0) == 5.0
    assert round_degrees(359.996, 2) == 0.0 and round_degrees(359.994, 2) == 359.99


@pytest.mark.parametrize(
    "text, dimension, si",
    [
        ("14 280 kW", "power", 14_280e3),
        # 19 000 mechanical horsepower, 550 ft·lbf/s each: 19 000 × 550 × 0.3048 m ×
        # 0.45359237 kg × 9.80665 m/s² = 14 168 297.56 W
        ("19 000 hp", "power", 19_000 * 550 * 0.3048 * 0.45359237 * 9.80665),
        ("19 000 PS", "power", 19_000 * 75 * 9.80665),  # metric: 75 kgf·m/s each
        ("1 000 000 W", "power", 1e6),
        ("14\u202f280\u202fkW", "power", 14_280e3),  # narrow no-break spaces (SI's)
        ("14\u2009280 kW", "power", 14_280e3),  # a thin space
        ("21\u00a0MW", "power", 21e6),  # a no-break space before the unit
        ("-1 000.5 mm", "length", -1.0005),
        ("2 500 rpm", "angular speed", 2500 * math.pi / 30),
    ],
)
def test_thousands_set_apart_by_spaces(text, dimension, si):
    assert_allclose(parse_quantity(text, dimension), si, rtol=1e-15)  # exact but for rounding


@pytest.mark.parametrize(
    "text", ["12 34 mm", "1 2345 mm", "14  280 mm", "1 000 00 mm", "1 0000 mm"]
)
def test_groups_that_are_not_threes_are_refused(text):
    """A space inside a number only sets apart groups of three digits, one space each: "12 34"
    is two numbers, not twelve hundred and thirty-four."""
    with pytest.raises(balance.UnitError, match="in groups of three"):
        parse_quantity(text, "length")


def test_a_comma_is_no_thousands_separator():
    """1,000 is a thousand in English and one in French: refused, as a unit it cannot read."""
    with pytest.raises(balance.UnitError, match="unknown unit ',000 kW'"):
        parse_quantity("1,000 kW", "power")
