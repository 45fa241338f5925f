"""A sweep's values as the file writes them: checked against the key they set, and evenly
spaced ones (:func:`span`) in the file's units."""

import math
import re
from collections.abc import Sequence

import numpy as np

from ...errors import BalanceError, SweepError
from ...units import DIMENSIONS, parse_quantity
from .keys import ANGLE, MAX_POINTS, NUMBER_TEXT, WHOLE

__all__ = ["normalised", "span"]


_QUANTITY_TEXT = re.compile(
    r"^\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*(\S.*?)\s*$", re.ASCII
)


def _shown(value):
    return f"{value:g}" if isinstance(value, float) else str(value)


def normalised(parameter, values):
    """The values as the file would hold them: text with a unit for a quantity, numbers for an
    angle, a ratio or a whole number (text that holds one is read as that number)."""
    if (
        isinstance(values, (str, bytes))
        or not isinstance(values, Sequence)
        and not isinstance(values, np.ndarray)
    ):
        raise SweepError(
            f"must be a list of values as written in the file, got {values!r}", "values"
        )
    values = list(values)
    if not values:
        raise SweepError("holds none; give at least one", "values")
    if len(values) > MAX_POINTS:
        raise SweepError(
            f"holds {len(values)}; a sweep takes at most {MAX_POINTS} points", "values"
        )
    out = []
    for value in values:
        if isinstance(value, np.generic):
            value = value.item()
        if parameter.takes_units:
            if not isinstance(value, str):
                raise SweepError(
                    f"holds {value!r}: {parameter.key} is written with a unit, "
                    f"as in the file (such as {_example(parameter)!r})",
                    "values",
                )
            out.append(value.strip())
            continue
        if isinstance(value, str):
            if not NUMBER_TEXT.match(value):
                unit = "degrees" if parameter.kind == ANGLE else parameter.kind + "s"
                raise SweepError(
                    f"holds {value!r}: {parameter.key} is a plain number of {unit}, "
                    "written without a unit",
                    "values",
                )
            number = float(value)
            value = int(number) if parameter.kind == WHOLE and number.is_integer() else number
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            raise SweepError(f"holds {value!r}: {parameter.key} takes a number", "values")
        if parameter.kind == WHOLE:
            if isinstance(value, float) and value.is_integer():
                value = int(value)
            if not isinstance(value, int):
                raise SweepError(f"holds {value!r}: {parameter.key} takes whole numbers", "values")
        out.append(value)
    return out


def _example(parameter):
    examples = {
        "length": "140 mm",
        "mass": "500 g",
        "angular speed": "3000 rpm",
        "moment of inertia": "0.12 kg*m^2",
        "pressure": "12 bar",
        "stiffness": "250 N/mm",
        "viscous damping": "0.5 N*s/mm",
    }
    return examples.get(parameter.kind, "1")


def _number_and_unit(text, what):
    """(number, unit text, dimension) of ``"140 mm"``; (number, "", None) of a plain number."""
    if isinstance(text, (int, float)) and not isinstance(text, bool):
        if not math.isfinite(text):
            raise SweepError(f"must be a finite number, got {text!r}", what)
        return float(text), "", None
    if not isinstance(text, str):
        raise SweepError(
            f"must be a number or a value with a unit such as '140 mm', got {text!r}", what
        )
    if NUMBER_TEXT.match(text):
        number = float(text)
        if not math.isfinite(number):
            raise SweepError(f"must be a finite number, got {text!r}", what)
        return number, "", None
    match = _QUANTITY_TEXT.match(text)
    if not match:
        raise SweepError(
            f"cannot read {text!r}: write a number, with its unit where the key "
            "has one (such as '140 mm' or 60)",
            what,
        )
    unit = match.group(2)
    for dimension in DIMENSIONS:
        try:
            # one of the unit is inside every dimension's limits: this finds the unit's dimension
            parse_quantity(f"1 {unit}", dimension)
        except BalanceError:
            continue
        try:
            parse_quantity(text, dimension)
        except BalanceError as exc:
            raise SweepError(str(exc), what) from None
        return float(match.group(1)), unit, dimension
    raise SweepError(f"cannot read {text!r}: unknown unit {unit!r}", what)


def span(start, stop, steps: int) -> list:
    """``steps`` evenly spaced values from ``start`` to ``stop`` inclusive, written as the file
    writes them: ``span("140 mm", "0.2 m", 4)`` is ["140 mm", "160 mm", "180 mm", "200 mm"] (in
    the unit of ``start``), ``span(0, 90, 4)`` is [0.0, 30.0, 60.0, 90.0].

    Raises
    ------
    SweepError
        a value that cannot be read, units of two dimensions, equal ends, fewer than two steps
        (``start``, ``stop`` or ``steps``)
    """
    if isinstance(steps, bool) or not isinstance(steps, (int, np.integer)):
        raise SweepError(f"must be a whole number, got {steps!r}", "steps")
    if not 2 <= steps <= MAX_POINTS:
        raise SweepError(f"must be from 2 to {MAX_POINTS} (both ends count), got {steps}", "steps")
    a, unit, dimension = _number_and_unit(start, "start")
    b, other_unit, other_dimension = _number_and_unit(stop, "stop")
    if dimension != other_dimension:

        def kind(d):
            return f"a{'n' if d and d[0] in 'aeiou' else ''} {d}" if d else "a plain number"

        raise SweepError(
            f"{stop!r} is {kind(other_dimension)}, but the first value ({start!r}) "
            f"is {kind(dimension)}: give both ends alike",
            "stop",
        )
    if unit and other_unit != unit:
        # the far end in the unit of the near one, so every value is written in one unit
        b = parse_quantity(stop, dimension) / parse_quantity(f"1 {unit}", dimension)
    if a == b:
        raise SweepError(
            f"equals the first value ({start!r}): a sweep needs two different ends", "stop"
        )
    numbers = np.linspace(a, b, int(steps))
    # twelve digits hide linspace's rounding (0.30000000000000004) and keep every real step
    written = [float(f"{x:.12g}") + 0.0 for x in numbers]
    written[0], written[-1] = a, b
    if not unit:
        return written
    texts = [f"{x:.12g} {unit}" for x in written]
    texts[0] = start.strip()
    if other_unit == unit:
        texts[-1] = stop.strip()
    return texts
