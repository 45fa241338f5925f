import math

import pytest
from numpy.testing import assert_allclose

from balance_cli.units import UnitError, parse_quantity


@pytest.mark.parametrize(
    "text, dimension, si",
    [
        ("82.5 mm", "length", 0.0825),
        ("5.5 in", "length", 0.1397),          # 5.5 × 25.4 mm, exact by definition of the inch
        ("-1.5 m", "length", -1.5),
        ("1770.4 g", "mass", 1.7704),
        ("500 kg", "mass", 500.0),
        ("1 lb", "mass", 0.45359237),          # exact by definition of the pound
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
