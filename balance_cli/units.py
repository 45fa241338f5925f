"""Quantities with units at the edges of the program; SI inside.

A configuration value such as ``"82.5 mm"`` or ``"1650 rpm"`` is parsed once, here,
into SI (metres, kilograms, radians per second). Nothing else in the package knows
about millimetres, grams or revolutions per minute.
"""

import math
import re

__all__ = ["UnitError", "parse_quantity", "DIMENSIONS", "STANDARD_GRAVITY", "rad_s_to_rpm"]

#: m/s², the conventional value used to turn kilogram-force into newtons
STANDARD_GRAVITY = 9.80665

_RPM = 2.0 * math.pi / 60.0

#: unit symbol -> factor to SI, per dimension
DIMENSIONS = {
    "length": {"m": 1.0, "cm": 1e-2, "mm": 1e-3, "in": 0.0254, "ft": 0.3048},
    "mass": {"kg": 1.0, "g": 1e-3, "lb": 0.45359237},
    "angular speed": {"rpm": _RPM, "rev/min": _RPM, "rad/s": 1.0, "rps": 2.0 * math.pi},
}

_QUANTITY = re.compile(r"^\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*([A-Za-z/]+)\s*$")


class UnitError(ValueError):
    """A value whose unit is missing, unknown or of the wrong dimension."""


def _units_of(dimension):
    return ", ".join(f'"{u}"' for u in DIMENSIONS[dimension])


def parse_quantity(text, dimension):
    """Parse ``"<number> <unit>"`` into SI.

    Parameters
    ----------
    text : str
        the value as written, e.g. ``"82.5 mm"``
    dimension : str
        one of the keys of :data:`DIMENSIONS`

    Returns
    -------
    float
        the value in SI (m, kg or rad/s)
    """
    if isinstance(text, bool) or not isinstance(text, str):
        raise UnitError(
            f'expected a string with a unit such as "{_example(dimension)}", got {text!r}'
        )
    match = _QUANTITY.match(text)
    if not match:
        raise UnitError(
            f'cannot read {text!r}: write a number and a unit, such as "{_example(dimension)}"'
        )
    number, unit = float(match.group(1)), match.group(2)
    factors = DIMENSIONS[dimension]
    if unit in factors:
        return number * factors[unit]
    for other, table in DIMENSIONS.items():
        if unit in table:
            raise UnitError(
                f"{text!r} is a {other}, but a {dimension} is needed (units: {_units_of(dimension)})"
            )
    raise UnitError(f"unknown unit {unit!r} in {text!r} (units: {_units_of(dimension)})")


def _example(dimension):
    return {"length": "82.5 mm", "mass": "1770.4 g", "angular speed": "1650 rpm"}[dimension]


def rad_s_to_rpm(speed_rad_s):
    """Angular speed, rad/s -> rev/min."""
    return speed_rad_s / _RPM
