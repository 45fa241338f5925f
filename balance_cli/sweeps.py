"""Parameter sweeps: one configuration analysed again and again with one of its values changed.

The parameter is a key of the configuration as written in the file (``rod_length``,
``banks[2].angle``, ``gas.imep``). Each point sets that key in the parsed TOML and builds the
engine with :func:`balance_cli.config.build`, so every value is read and checked exactly as in
a file, and a value that makes no engine is reported with the file, the key and the value.
The pseudo-parameter ``balance_factor`` instead balances the unchanged engine with classic
per-throw counterweights of that factor and reports what they leave.

What is reported comes from the same records as ``compare``, ``counterweight`` and
``torque``: the quantities are read out of each point's ``to_dict()``-style records, so a
sweep agrees with those commands to the last digit.
"""

import copy
import dataclasses
import math
import os
import re
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from .analysis import DOCUMENT_VERSION, analyse
from .config import _parse, _read_text, build
from .counterweight import check_options, counterweights
from .errors import BalanceError, ConfigError, FiringError, SweepError
from .shaking import DEFAULT_MAX_ORDER, DEFAULT_SAMPLES, check_settings
from .units import DIMENSIONS, parse_quantity, rad_s_to_rpm

__all__ = ["SweepResult", "Parameter", "Quantity", "sweep", "span", "parameter_of",
           "quantities_of", "QUANTITY_NAMES", "DEFAULT_QUANTITIES", "BALANCE_FACTOR"]

#: kinds of value that are not a dimension of :data:`balance_cli.units.DIMENSIONS`
ANGLE, NUMBER, WHOLE, FRACTION = "angle", "number", "whole number", "fraction"

#: every numeric scalar of configuration format version 1, table by table ("" the top level,
#: "banks[]" an array of tables), with the kind of its value. Strings (name, source, frame)
#: and lists (firing_order) are not swept: they have no axis to plot against.
SCHEMA = {
    "": {"cycle": WHOLE, "speed": "angular speed", "crank_radius": "length",
         "rod_length": "length", "pin_offset": "length", "vertical": ANGLE},
    "masses": {"reciprocating": "mass", "rotating": "mass", "knuckle": "mass", "crank": "mass"},
    "parts": {"piston": "mass", "rod_mass": "mass", "rod_cg": "length",
              "rod_inertia": "moment of inertia", "link_mass": "mass", "link_cg": "length",
              "link_inertia": "moment of inertia", "crank": "mass",
              "crankshaft_inertia": "moment of inertia", "flywheel_inertia": "moment of inertia"},
    "gas": {"bore": "length", "compression_ratio": NUMBER, "imep": "pressure",
            "intake_pressure": "pressure", "crankcase_pressure": "pressure",
            "polytropic_exponent": NUMBER, "combustion_start": ANGLE,
            "combustion_duration": ANGLE, "wiebe_a": NUMBER, "wiebe_m": NUMBER},
    "links": {"master_bank": WHOLE, "length": "length", "knuckle_radius": "length"},
    "banks[]": {"angle": ANGLE},
    "throws[]": {"phase": ANGLE, "z": "length"},
    "cylinders[]": {"number": WHOLE, "bank": WHOLE, "throw": WHOLE, "z": "length",
                    "reciprocating": "mass", "master": WHOLE, "link_length": "length",
                    "knuckle_radius": "length", "knuckle_angle": ANGLE},
}
#: configuration keys that hold text or lists: named in messages, never swept
_NOT_SCALARS = {"name": "text", "source": "text", "frame": "text (fixed or rotary)",
                "firing_order": "a list"}

#: the pseudo-parameter: the balance factor of classic per-throw counterweights
BALANCE_FACTOR = "balance_factor"

#: SI unit of each kind of value, as JSON and CSV name it
_SI_UNITS = {"length": "m", "mass": "kg", "angular speed": "rad/s", "moment of inertia": "kg*m^2",
             "pressure": "Pa", "torque": "N*m", ANGLE: "rad", NUMBER: "", WHOLE: "",
             FRACTION: ""}

_SEGMENT = re.compile(r"^([a-z_]+)(?:\[(\d+)\])?$")
_NUMBER_TEXT = re.compile(r"^\s*[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?\s*$", re.ASCII)
_QUANTITY_TEXT = re.compile(r"^\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*(\S.*?)\s*$",
                            re.ASCII)
#: most points a sweep takes: enough for any curve, few enough that a typo (1e9) is refused
MAX_POINTS = 10_000


@dataclass(frozen=True)
class Parameter:
    """The configuration key a sweep varies.

    Attributes
    ----------
    key : str
        as written in the file: ``rod_length``, ``banks[2].angle`` (1-based), ``gas.imep``, or
        ``balance_factor``
    kind : str
        a dimension of :data:`balance_cli.units.DIMENSIONS` ("length", "mass", ...), or
        "angle" (plain degrees), "number", "whole number" or "fraction" (balance_factor)
    path : tuple
        where the key sits in the parsed TOML: names, and 0-based indices into arrays
    file_value : object
        the value the file gives (None when the key is added, or for balance_factor)
    """

    key: str
    kind: str
    path: tuple
    file_value: object = None

    @property
    def in_file(self) -> bool:
        return self.file_value is not None

    @property
    def unit_si(self) -> str:
        """The SI unit of :meth:`SweepResult.values_si`: "m", "kg", "rad/s", "rad", "" ..."""
        return _SI_UNITS[self.kind]

    @property
    def takes_units(self) -> bool:
        return self.kind in DIMENSIONS


@dataclass(frozen=True)
class Quantity:
    """One quantity a sweep reports at every point.

    ``name`` as asked for (``F2V``, ``largest_moment``), ``column`` its key in the records
    (the name and the SI unit: ``F2V_N``), ``unit`` "N", "Nm" or "" and ``kind`` "force",
    "moment", "torque" or "steadiness".
    """

    name: str
    column: str
    unit: str
    kind: str
    meaning: str
    order: int | None = None
    part: str | None = None

    def to_dict(self) -> dict:
        return {"name": self.name, "column": self.column, "unit": self.unit, "kind": self.kind,
                "meaning": self.meaning}


_PARTS = {"": ("max", "largest over a revolution (the ellipse's semi-major axis)"),
          "V": ("vertical", "vertical component's amplitude"),
          "H": ("horizontal", "horizontal component's amplitude"),
          "+": ("forward", "forward part (turns with the crank)"),
          "-": ("backward", "backward part (turns against the crank)")}
_MOMENT_WORDS = {"V": "pitching (moment of the vertical forces), amplitude",
                 "H": "yawing (moment of the horizontal forces), amplitude"}
_NAMED = {
    "largest_force": ("N", "force", "largest resultant force over a revolution, all orders, "
                                    "after an ideal counterweight"),
    "largest_moment": ("Nm", "moment", "largest free moment over a revolution, all orders, "
                                       "after an ideal two-plane counterweight"),
    "torque_mean": ("Nm", "torque", "mean of the total torque (gas and inertia) at constant speed"),
    "torque_max": ("Nm", "torque", "largest total torque over the cycle"),
    "torque_min": ("Nm", "torque", "smallest total torque over the cycle"),
    "torque_range": ("Nm", "torque", "range ΔC of the total torque over the cycle"),
    "steadiness": ("", "steadiness", "steadiness ω_m/(ω_max − ω_min) with the inertia given"),
}
#: what ``quantities`` may name, for messages and help texts
QUANTITY_NAMES = ("F<k>", "F<k>V", "F<k>H", "F<k>+", "F<k>-", "M<k>", "M<k>V", "M<k>H", "M<k>+",
                  "M<k>-") + tuple(_NAMED)
DEFAULT_QUANTITIES = ("largest_force", "largest_moment")
_ORDER_QUANTITY = re.compile(r"^([FM])(\d+)(V|H|\+|-)?$", re.IGNORECASE)


def quantities_of(names, max_order: int = DEFAULT_MAX_ORDER) -> tuple:
    """The :class:`Quantity` list for ``names`` (a sequence, or one string "F2,M1V"); None or
    empty gives :data:`DEFAULT_QUANTITIES`.

    Raises
    ------
    SweepError
        an unknown name, an order above ``max_order``, or a name given twice (``quantities``)
    """
    if names is None:
        names = DEFAULT_QUANTITIES
    if isinstance(names, str):
        names = [n.strip() for n in names.split(",")]
    names = list(names)
    if not names:
        names = list(DEFAULT_QUANTITIES)
    out = []
    for raw in names:
        if not isinstance(raw, str) or not raw.strip():
            raise SweepError(f"holds {raw!r}: give quantity names such as F2, M1V or "
                             "largest_force", "quantities")
        name = raw.strip()
        match = _ORDER_QUANTITY.match(name)
        if match:
            letter, order, part = match.group(1).upper(), int(match.group(2)), (match.group(3) or "").upper()
            if not 1 <= order <= max_order:
                raise SweepError(f"names {name!r}, order {order}, outside the orders analysed "
                                 f"(1 to {max_order}); analyse more orders or ask for a lower "
                                 "one", "quantities")
            key, words = _PARTS[part]
            what = "force" if letter == "F" else "moment"
            if letter == "M" and part in _MOMENT_WORDS:
                words = _MOMENT_WORDS[part]
            unit = "N" if letter == "F" else "Nm"
            canonical = f"{letter}{order}{part}"
            out.append(Quantity(canonical, f"{canonical}_{unit}", unit, what,
                                f"order-{order} free {what}, {words}", order, key))
            continue
        lowered = name.lower()
        if lowered in _NAMED:
            unit, kind, meaning = _NAMED[lowered]
            out.append(Quantity(lowered, f"{lowered}_{unit}" if unit else lowered, unit, kind,
                                meaning))
            continue
        raise SweepError(f"names {name!r}, which is not a quantity; give F<k> or M<k> (order k: "
                         "the largest force or moment of that order) with V, H, + or - for the "
                         "vertical, horizontal, forward or backward part (F2V, M1H, F1+), or "
                         f"one of {', '.join(_NAMED)}", "quantities")
    columns = [q.column for q in out]
    twice = next((c for c in columns if columns.count(c) > 1), None)
    if twice is not None:
        raise SweepError(f"names {twice.rsplit('_', 1)[0]!r} twice; give each quantity once",
                         "quantities")
    return tuple(out)


def _segments(key):
    """``banks[2].angle`` -> [("banks", 2), ("angle", None)]; None when it is not a key path."""
    out = []
    for part in key.split("."):
        match = _SEGMENT.match(part)
        if not match:
            return None
        out.append((match.group(1), int(match.group(2)) if match.group(2) else None))
    return out


def _compressed(keys):
    """Key paths with runs of indices folded: throws[1].z, throws[2].z -> throws[1-2].z."""
    folded: dict = {}
    order = []
    for key in keys:
        match = re.match(r"^([a-z_]+)\[(\d+)\]\.(.+)$", key)
        if match is None:
            folded[key] = None
            order.append(key)
            continue
        stem = (match.group(1), match.group(3))
        if stem not in folded:
            folded[stem] = []
            order.append(stem)
        folded[stem].append(int(match.group(2)))
    out = []
    for item in order:
        if isinstance(item, str):
            out.append(item)
            continue
        indices = folded[item]
        span_text = f"{indices[0]}" if len(indices) == 1 else f"{indices[0]}-{indices[-1]}"
        out.append(f"{item[0]}[{span_text}].{item[1]}")
    return out


def _sweepable(data):
    """The numeric scalars the parsed configuration ``data`` has, and those it may add."""
    present, addable = [], []
    for table, keys in SCHEMA.items():
        if table == "":
            for key in keys:
                (present if key in data else addable).append(key)
        elif table.endswith("[]"):
            name = table[:-2]
            rows = data.get(name)
            if isinstance(rows, list):
                for i, row in enumerate(rows, 1):
                    if isinstance(row, dict):
                        present += [f"{name}[{i}].{k}" for k in keys if k in row]
        elif isinstance(data.get(table), dict):
            for key in keys:
                (present if key in data[table] else addable).append(f"{table}.{key}")
    return present, addable


def _refused(text, problem, data, path, listing=True):
    """The error for a key that cannot be swept; ``listing`` adds the keys that can."""
    if not listing:
        return SweepError(f"{text!r}: {problem}", "parameter")
    present, addable = _sweepable(data)
    has = ", ".join(_compressed(present))
    more = f"; it may add {', '.join(addable)}" if addable else ""
    return SweepError(f"{text!r}: {problem}; {path} has {has}{more}, and there is "
                      "balance_factor (of the counterweights)", "parameter")


def parameter_of(data: dict, key: str, path: str = "<config>") -> Parameter:
    """The :class:`Parameter` for configuration ``key`` in the parsed configuration ``data``.

    A key the format allows but the file leaves out (``pin_offset``, ``masses.rotating``) is
    added at each point; a key of a table the file does not have is refused.

    Raises
    ------
    SweepError
        an unknown key, a key of text or a list, an index outside the file's array
        (``parameter``); the message lists the keys there are
    """
    if not isinstance(key, str) or not key.strip():
        raise SweepError(f"must be a configuration key such as rod_length or banks[2].angle, "
                         f"got {key!r}", "parameter")
    text = key.strip()
    if text == BALANCE_FACTOR:
        return Parameter(text, FRACTION, ())
    segments = _segments(text)
    if segments is None or len(segments) > 2:
        raise _refused(text, "not a configuration key (write it as in the file: rod_length, "
                             "masses.rotating, banks[2].angle)", data, path)
    head, index = segments[0]
    if len(segments) == 1:
        if index is not None:
            raise _refused(text, "not a configuration key", data, path)
        if head in _NOT_SCALARS:
            raise _refused(text, f"holds {_NOT_SCALARS[head]}, not a number to vary", data, path,
                           listing=False)
        if head not in SCHEMA[""]:
            problem = (f"{head} is a table; name one of its keys, such as {head}.{next(iter(SCHEMA[head]))}"
                       if head in SCHEMA else
                       f"[{head}] is an array of tables; name one of its keys with the table's number, "
                       f"such as {head}[1].{next(iter(SCHEMA[head + '[]']))}"
                       if head + "[]" in SCHEMA else "no such key")
            raise _refused(text, problem, data, path, listing=problem == "no such key")
        return Parameter(text, SCHEMA[""][head], (head,), data.get(head))
    (name, subkey) = segments[1]
    if subkey is not None:
        raise _refused(text, "not a configuration key", data, path)
    if index is None:
        if head not in SCHEMA:
            hint = (f"[[{head}]] is an array of tables: give the table's number, such as "
                    f"{head}[1].{name}" if head + "[]" in SCHEMA else "no such key")
            raise _refused(text, hint, data, path, listing=hint == "no such key")
        if name not in SCHEMA[head]:
            raise _refused(text, f"[{head}] has no key {name} in the configuration format", data, path)
        table = data.get(head)
        if not isinstance(table, dict):
            raise _refused(text, f"{path} has no [{head}] table; add one to vary its keys",
                           data, path, listing=False)
        return Parameter(text, SCHEMA[head][name], (head, name), table.get(name))
    array = head + "[]"
    if array not in SCHEMA:
        raise _refused(text, f"{head} is not an array of tables" if head in SCHEMA else "no such key",
                       data, path)
    if name not in SCHEMA[array]:
        raise _refused(text, f"[[{head}]] tables have no key {name}", data, path)
    rows = data.get(head)
    count = len(rows) if isinstance(rows, list) else 0
    if not 1 <= index <= count:
        where = (f"only {head}[1]" if count == 1 else f"{head}[1] to {head}[{count}]" if count
                 else f"no [[{head}]] tables")
        raise _refused(text, f"{path} has {where}" + (" (numbered from 1)" if count else ""),
                       data, path, listing=False)
    row = rows[index - 1]
    return Parameter(text, SCHEMA[array][name], (head, index - 1, name),
                     row.get(name) if isinstance(row, dict) else None)


def _shown(value):
    return f"{value:g}" if isinstance(value, float) else str(value)


def _normalised(parameter, values):
    """The values as the file would hold them: text with a unit for a quantity, numbers for an
    angle, a ratio or a whole number (text that holds one is read as that number)."""
    if isinstance(values, (str, bytes)) or not isinstance(values, Sequence) and not isinstance(
            values, np.ndarray):
        raise SweepError(f"must be a list of values as written in the file, got {values!r}",
                         "values")
    values = list(values)
    if not values:
        raise SweepError("holds none; give at least one", "values")
    if len(values) > MAX_POINTS:
        raise SweepError(f"holds {len(values)}; a sweep takes at most {MAX_POINTS} points",
                         "values")
    out = []
    for value in values:
        if isinstance(value, np.generic):
            value = value.item()
        if parameter.takes_units:
            if not isinstance(value, str):
                raise SweepError(f"holds {value!r}: {parameter.key} is written with a unit, "
                                 f"as in the file (such as {_example(parameter)!r})", "values")
            out.append(value.strip())
            continue
        if isinstance(value, str):
            if not _NUMBER_TEXT.match(value):
                unit = "degrees" if parameter.kind == ANGLE else parameter.kind + "s"
                raise SweepError(f"holds {value!r}: {parameter.key} is a plain number of {unit}, "
                                 "written without a unit", "values")
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
    examples = {"length": "140 mm", "mass": "500 g", "angular speed": "3000 rpm",
                "moment of inertia": "0.12 kg*m^2", "pressure": "12 bar"}
    return examples.get(parameter.kind, "1")


def _number_and_unit(text, what):
    """(number, unit text, dimension) of ``"140 mm"``; (number, "", None) of a plain number."""
    if isinstance(text, (int, float)) and not isinstance(text, bool):
        if not math.isfinite(text):
            raise SweepError(f"must be a finite number, got {text!r}", what)
        return float(text), "", None
    if not isinstance(text, str):
        raise SweepError(f"must be a number or a value with a unit such as '140 mm', got "
                         f"{text!r}", what)
    if _NUMBER_TEXT.match(text):
        number = float(text)
        if not math.isfinite(number):
            raise SweepError(f"must be a finite number, got {text!r}", what)
        return number, "", None
    match = _QUANTITY_TEXT.match(text)
    if not match:
        raise SweepError(f"cannot read {text!r}: write a number, with its unit where the key "
                         "has one (such as '140 mm' or 60)", what)
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
        raise SweepError(f"{stop!r} is {kind(other_dimension)}, but the first value ({start!r}) "
                         f"is {kind(dimension)}: give both ends alike", "stop")
    if unit and other_unit != unit:
        # the far end in the unit of the near one, so every value is written in one unit
        b = parse_quantity(stop, dimension) / parse_quantity(f"1 {unit}", dimension)
    if a == b:
        raise SweepError(f"equals the first value ({start!r}): a sweep needs two different ends",
                         "stop")
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


@dataclass(frozen=True)
class SweepResult:
    """A sweep: one parameter's values and what each gives.

    Attributes
    ----------
    name, config : str
        the engine's name and the configuration's path (or the name given for a dict)
    parameter : Parameter
    values : tuple
        as written in the file ("140 mm", 60.0)
    values_si : tuple of float
        the same in SI (m, kg, rad/s, kg·m², Pa; radians for angles), see ``parameter.unit_si``
    quantities : tuple of Quantity
    points : tuple of dict
        one record per value: ``value``, ``value_SI`` and one key per quantity's ``column``
        (SI: N, N·m)
    engines : tuple of Engine
        each point's engine, built and checked (analyse one again for more than the
        quantities; the analyses are not kept, so that a long sweep stays small)
    samples, max_order : int
    inertia_kgm2 : float or None
        the flywheel inertia of the steadiness, kg·m²
    load : str
    overrides : tuple of (key, value)
        the keys set at every point besides the parameter
    """

    name: str
    config: str
    parameter: Parameter
    values: tuple
    values_si: tuple
    quantities: tuple
    points: tuple
    engines: tuple
    samples: int
    max_order: int
    inertia_kgm2: float | None = None
    load: str = "propeller"
    overrides: tuple = ()

    @property
    def speed_rpm(self) -> float | None:
        """The speed of every point, rpm; None when the speed is what varies."""
        if self.parameter.key == "speed":
            return None
        return rad_s_to_rpm(self.engines[0].speed_rad_s)

    def series(self, quantity: str) -> np.ndarray:
        """One quantity at every point, SI, by name (``"F2"``) or column (``"F2_N"``)."""
        for q in self.quantities:
            if quantity in (q.name, q.column):
                return np.array([p[q.column] for p in self.points], dtype=float)
        raise KeyError(f"{quantity!r} is not among this sweep's quantities "
                       f"({', '.join(q.name for q in self.quantities)})")

    def records(self) -> list:
        """One flat dict per point (``value``, ``value_SI``, the quantities' columns), ready
        for ``pandas.DataFrame(result.records())``."""
        return [dict(p) for p in self.points]

    def to_dict(self) -> dict:
        """What ``sweep --format json`` writes (SI; see the README)."""
        p = self.parameter
        return {
            "balance_version": DOCUMENT_VERSION,
            "name": self.name,
            "config": self.config,
            "samples": self.samples,
            "max_order": self.max_order,
            "speed_rpm": self.speed_rpm,
            "overrides": dict(self.overrides),
            "parameter": {"key": p.key, "kind": p.kind, "unit_SI": p.unit_si,
                          "file_value": p.file_value, "values": list(self.values),
                          "values_SI": list(self.values_si)},
            "quantities": [q.to_dict() for q in self.quantities],
            "inertia_kgm2": self.inertia_kgm2,
            "load": self.load if self.inertia_kgm2 is not None else None,
            "points": self.records(),
        }


def _with_value(data, parameter, value):
    changed = copy.deepcopy(data)
    place = changed
    for step in parameter.path[:-1]:
        place = place[step]
    place[parameter.path[-1]] = value
    return changed


def _si(parameter, value):
    if parameter.takes_units:
        return parse_quantity(value, parameter.kind)
    if parameter.kind == ANGLE:
        return math.radians(value)
    return float(value)


def _point_error(exc, parameter, value, path):
    """A failure at one point as one line: the file, the key, the value."""
    shown = repr(value) if isinstance(value, str) else _shown(value)
    at = f"{parameter.key} = {shown}"
    if isinstance(exc, ConfigError):
        # the model's sentences about a field start "of 0.01 m is ...": give them their subject
        if exc.problem.startswith("of "):
            problem = f"{exc.key} {exc.problem}"
        elif exc.key and exc.key != parameter.key:
            problem = f"{exc.key}: {exc.problem}"
        else:
            problem = exc.problem
        text = f"{exc.path}: {at}: {problem}"
    elif isinstance(exc, FiringError):
        text = f"{path}: {at}: firing_order: {exc}"
    elif isinstance(exc, BalanceError) and exc.parameter == parameter.key:
        text = f"{path}: {at}: {exc.problem}"
    else:
        text = f"{path}: {at}: {exc}"
    error = SweepError(text, key=parameter.key, value=value)
    error.cause = exc
    return error


def _load(config, name):
    if isinstance(config, dict):
        return copy.deepcopy(config), name or "<config>"
    if isinstance(config, (str, os.PathLike)):
        path = os.fspath(config)
        return _parse(_read_text(Path(path)), path), name or path
    raise SweepError(f"must be a configuration file's path or its parsed TOML (a dict), got "
                     f"{type(config).__name__}", "config")


def sweep(config, parameter: str, values: Sequence, quantities=None,
          samples: int = DEFAULT_SAMPLES, max_order: int = DEFAULT_MAX_ORDER, *,
          inertia_kgm2: float | None = None, load: str = "propeller", name: str | None = None,
          overrides: "dict | None" = None,
          progress: "Callable[[int, int], None] | None" = None) -> SweepResult:
    """Analyse the configuration ``config`` once per value of ``parameter``.

    Parameters
    ----------
    config : str, PathLike or dict
        a configuration file, or its parsed TOML (not changed)
    parameter : str
        a configuration key as written in the file: ``speed``, ``rod_length``,
        ``masses.rotating``, ``banks[2].angle``, ``throws[3].phase``, ``gas.imep``,
        ``cylinders[4].reciprocating``, ... (any number of the configuration; see
        :data:`SCHEMA`), or ``balance_factor`` (classic per-throw counterweights of that
        factor, 0 to 1, and what they leave)
    values : sequence
        as written in the file: text with a unit for a quantity ("140 mm", "3000 rpm"),
        numbers for angles (degrees), ratios and whole numbers (text holding a number is
        read as that number); :func:`span` makes evenly spaced ones
    quantities : str or sequence of str, optional
        what to report at each point (see :func:`quantities_of`); default the largest free
        force and moment after an ideal counterweight
    samples, max_order : int
        as for :func:`~balance_cli.analyse`
    inertia_kgm2 : float, optional
        flywheel inertia for the ``steadiness`` quantity, kg·m²
    load : str
        "propeller" or "constant", for the steadiness
    name : str, optional
        what a dict ``config`` is called in messages (default "<config>")
    overrides : dict, optional
        other keys to set at every point, as written in the file (``{"speed": "3000 rpm"}``:
        the command line's ``--speed``); checked like the file's own values
    progress : callable, optional
        ``progress(done, total)`` after each point

    Raises
    ------
    ConfigError
        the configuration itself cannot be read or built
    SweepError
        an unknown parameter (``parameter``), unusable values (``values``) or quantities
        (``quantities``), a steadiness without ``inertia_kgm2``, or a point whose configuration
        is invalid (the message names the file, the key and the value; ``key`` and ``value``
        say which)
    AnalysisError
        ``samples`` or ``max_order`` out of range
    """
    check_settings(samples, max_order)
    data, path = _load(config, name)
    build(data, path)   # the file as it is first: its own errors are the file's, not the sweep's
    param = parameter_of(data, parameter, path)
    for key, value in (overrides or {}).items():
        try:
            fixed = parameter_of(data, key, path)
        except SweepError as exc:
            raise SweepError(exc.problem, "overrides") from None
        if fixed.key == param.key or fixed.kind == FRACTION:
            raise SweepError(f"sets {key!r}, which the sweep varies or which is no key of the "
                             "file; leave it out", "overrides")
        data = _with_value(data, fixed, _normalised(fixed, [value])[0])
    try:
        base = build(data, path)
    except ConfigError as exc:
        if exc.key not in (overrides or {}):
            raise
        raise SweepError(f"{exc.key} = {overrides[exc.key]!r}: {exc.problem}", "overrides") from None
    wanted = quantities_of(quantities, max_order)
    if param.kind == FRACTION:
        # what the counterweights of each factor leave, not what an ideal one would
        wanted = tuple(dataclasses.replace(q, meaning=q.meaning.split(", after")[0] + ", after "
                                           "the counterweights of that balance factor")
                       if q.name.startswith("largest_") else q for q in wanted)
    values = _normalised(param, values)
    torque_wanted = any(q.kind in ("torque", "steadiness") for q in wanted)
    steady = any(q.kind == "steadiness" for q in wanted)
    if steady and inertia_kgm2 is None:
        raise SweepError("is needed for the quantity steadiness: give the flywheel inertia, "
                         "kg·m²", "inertia_kgm2")
    if inertia_kgm2 is not None:
        if isinstance(inertia_kgm2, bool) or not isinstance(inertia_kgm2, (int, float)) or \
                not math.isfinite(inertia_kgm2) or inertia_kgm2 <= 0:
            raise SweepError(f"must be a positive number of kg·m², got {inertia_kgm2!r}",
                             "inertia_kgm2")
        if not steady:
            raise SweepError("applies to the quantity steadiness only; ask for it or leave the "
                             "inertia out", "inertia_kgm2")
    if steady and base.gas is None:
        raise SweepError(f"needs a gas torque to drive the engine, but {path} has no [gas] "
                         "table", "quantities")

    # every point is built before any is analysed: a bad value is reported at once
    engines, values_si = [], []
    for value in values:
        try:
            if param.kind == FRACTION:
                check_options(balance_factor=value)
                engine = base
            else:
                engine = build(_with_value(data, param, value), path)
            values_si.append(_si(param, value) + 0.0)
        except BalanceError as exc:
            raise _point_error(exc, param, value, path) from None
        engines.append(engine)

    if param.kind != FRACTION and len(set(values_si)) > 1 and all(e == engines[0] for e in engines):
        raise SweepError(
            f"{param.key!r} changes nothing in the engine {path} describes: another key sets "
            "what it would (a cylinder's own value overrides [links] and [masses], [parts] "
            "derive the lumped masses); vary that key instead", "parameter")

    torque_of = None
    if torque_wanted:
        from .torques import torque as torque_of   # the torques load scipy for the steadiness

    points = []
    for i, (engine, value, value_si) in enumerate(zip(engines, values, values_si)):
        try:
            result = analyse(engine, samples, max_order)
            record = _measure(result, wanted, param, value, samples, max_order, torque_of,
                              inertia_kgm2, load)
        except BalanceError as exc:
            raise _point_error(exc, param, value, path) from None
        points.append({"value": value, "value_SI": value_si, **record})
        if progress is not None:
            progress(i + 1, len(values))
    return SweepResult(base.name, path, param, tuple(values), tuple(values_si), wanted,
                       tuple(points), tuple(engines), samples, max_order, inertia_kgm2, load,
                       tuple((overrides or {}).items()))


def _measure(result, wanted, param, value, samples, max_order, torque_of, inertia, load):
    """Every quantity of one point, read from the records ``compare`` writes."""
    engine = result.engine
    if param.kind == FRACTION:
        shaking = counterweights(result, balance_factor=value).residual
        largest_force = _above(shaking.largest_force(), engine.noise_floor_n)
        largest_moment = _above(shaking.largest_moment(), engine.noise_floor_nm)
    else:
        shaking = result.shaking
        largest_force, largest_moment = result.counterweighted_force_n, result.counterweighted_moment_nm
    orders = shaking.records(engine)
    torques = None
    if torque_of is not None:
        steady = any(q.kind == "steadiness" for q in wanted)
        torques = torque_of(engine, samples, max_order, inertia_kgm2=inertia if steady else None,
                            load=load, bearings=False)
    record = {}
    for q in wanted:
        if q.order is not None:
            record[q.column] = orders[q.order - 1][q.kind][f"{q.part}_{q.unit}"]
        elif q.name == "largest_force":
            record[q.column] = largest_force
        elif q.name == "largest_moment":
            record[q.column] = largest_moment
        elif q.name == "steadiness":
            record[q.column] = torques.steadiness.factor
        else:
            total = torques.total
            record[q.column] = {"torque_mean": total.mean, "torque_max": total.max,
                                "torque_min": total.min, "torque_range": total.range}[q.name]
    return record


def _above(value, floor):
    return value if value >= floor else 0.0
