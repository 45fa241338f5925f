"""The configuration keys a sweep can vary, and their values as the file writes them.

A parameter is a key path as written in a configuration (``rod_length``, ``masses.rotating``,
``banks[2].angle``, numbered from 1 as the configuration's messages number tables); its kind
(a dimension of :data:`balance_cli.units.DIMENSIONS`, or plain degrees, a ratio, a whole
number) says how its values are written and what their SI unit is.
"""

import re
from dataclasses import dataclass

from ...errors import SweepError
from ...units import DIMENSIONS
from .derived import DERIVED, Derived
from .mountkeys import mount_keys_hint, mount_parameter

__all__ = [
    "SCHEMA",
    "BALANCE_FACTOR",
    "MAX_POINTS",
    "ANGLE",
    "NUMBER",
    "WHOLE",
    "FRACTION",
    "Parameter",
    "parameter_of",
    "NUMBER_TEXT",
    "DERIVED",
]

#: kinds of value that are not a dimension of :data:`balance_cli.units.DIMENSIONS`
ANGLE, NUMBER, WHOLE, FRACTION = "angle", "number", "whole number", "fraction"

#: every numeric scalar of configuration format version 1, table by table ("" the top level,
#: "banks[]" an array of tables), with the kind of its value. Strings (name, source, frame)
#: and lists (firing_order) are not swept: they have no axis to plot against.
SCHEMA = {
    "": {
        "cycle": WHOLE,
        "speed": "angular speed",
        "crank_radius": "length",
        "rod_length": "length",
        "pin_offset": "length",
        "vertical": ANGLE,
        "power": "power",
    },
    "masses": {"reciprocating": "mass", "rotating": "mass", "knuckle": "mass", "crank": "mass"},
    "parts": {
        "piston": "mass",
        "rod_mass": "mass",
        "rod_cg": "length",
        "rod_inertia": "moment of inertia",
        "link_mass": "mass",
        "link_cg": "length",
        "link_inertia": "moment of inertia",
        "crank": "mass",
        "crankshaft_inertia": "moment of inertia",
        "flywheel_inertia": "moment of inertia",
    },
    "gas": {
        "bore": "length",
        "compression_ratio": NUMBER,
        "imep": "pressure",
        "intake_pressure": "pressure",
        "crankcase_pressure": "pressure",
        "polytropic_exponent": NUMBER,
        "combustion_start": ANGLE,
        "combustion_duration": ANGLE,
        "wiebe_a": NUMBER,
        "wiebe_m": NUMBER,
    },
    "links": {"master_bank": WHOLE, "length": "length", "knuckle_radius": "length"},
    "banks[]": {"angle": ANGLE, "pin_offset": "length"},
    "throws[]": {"phase": ANGLE, "z": "length", "crankshaft": WHOLE, "rotating": "mass"},
    "cylinders[]": {
        "number": WHOLE,
        "bank": WHOLE,
        "throw": WHOLE,
        "z": "length",
        "reciprocating": "mass",
        "master": WHOLE,
        "link_length": "length",
        "knuckle_radius": "length",
        "knuckle_angle": ANGLE,
        "pin_offset": "length",
        "opposed_throw": WHOLE,
        "opposed_reciprocating": "mass",
    },
    "crankshafts[]": {"x": "length", "y": "length", "direction": WHOLE, "phase": ANGLE},
    "counterweights[]": {
        "throw": WHOLE,
        "mass": "mass",
        "radius": "length",
        "mass_radius": "unbalance",
        "angle": ANGLE,
        "z": "length",
    },
    "shafts[]": {"ratio": WHOLE, "lateral": "length", "vertical": "length"},
}
#: configuration keys that hold text or lists: named in messages, never swept
_NOT_SCALARS = {
    "name": "text",
    "source": "text",
    "frame": "text (fixed or rotary)",
    "firing_order": "a list",
}

#: the pseudo-parameter: the balance factor of classic per-throw counterweights
BALANCE_FACTOR = "balance_factor"

#: SI unit of each kind of value, as JSON and CSV name it
_SI_UNITS = {
    "length": "m",
    "mass": "kg",
    "angular speed": "rad/s",
    "moment of inertia": "kg*m^2",
    "pressure": "Pa",
    "torque": "N*m",
    "power": "W",
    "unbalance": "kg*m",
    "stiffness": "N/m",
    "viscous damping": "N*s/m",
    ANGLE: "rad",
    NUMBER: "",
    WHOLE: "",
    FRACTION: "",
}

_SEGMENT = re.compile(r"^([a-z_]+)(?:\[(\d+)\])?$")
NUMBER_TEXT = re.compile(r"^\s*[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?\s*$", re.ASCII)
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
        the value the file gives (None when the key is added, or for balance_factor); of a
        derived parameter, the value the file's keys give it
    derived : Derived or None
        for ``rod_ratio``, ``stroke`` and ``bore_pitch``: how it is computed and set
    """

    key: str
    kind: str
    path: tuple
    file_value: object = None
    derived: Derived | None = None

    @property
    def changes(self) -> tuple:
        """The keys a value sets (``[]`` standing for any table's number): the key itself, a
        derived parameter's keys, none for balance_factor."""
        if self.derived is not None:
            return self.derived.changes
        return () if self.kind == FRACTION else (self.key,)

    @property
    def meaning(self) -> str | None:
        """What a derived parameter or balance_factor is and sets; None for a file's key."""
        if self.derived is not None:
            return self.derived.meaning
        if self.kind == FRACTION:
            return (
                "balance factor of classic per-throw counterweights (the rotating masses "
                "plus this fraction of the reciprocating ones); changes no key"
            )
        return None

    @property
    def rank(self) -> int:
        """Order of setting at a point: the file's keys first, then derived parameters
        (after those setting a key they read)."""
        return 0 if self.derived is None else self.derived.rank

    def conflicts(self, other: "Parameter") -> str | None:
        """A key both this and ``other`` set, or None."""
        for mine in self.changes:
            for theirs in other.changes:
                if mine == theirs or _generic(mine) == theirs or mine == _generic(theirs):
                    return mine if "[]" not in mine else theirs
        return None

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


def _generic(key):
    """``throws[2].z`` -> ``throws[].z``: the pattern a derived parameter's keys are named by."""
    return re.sub(r"\[\d+\]", "[]", key)


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
    present: list[str] = []
    addable: list[str] = []
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
    return SweepError(
        f"{text!r}: {problem}; {path} has {has}{more}{mount_keys_hint(data)}, and there are "
        f"{', '.join(DERIVED)} (derived from those keys) and balance_factor (of the "
        "counterweights)",
        "parameter",
    )


def parameter_of(data: dict, key: str, path: str = "<config>") -> Parameter:
    """The :class:`Parameter` for configuration ``key`` in the parsed configuration ``data``.

    A key the format allows but the file leaves out (``pin_offset``, ``masses.rotating``) is
    added at each point; a key of a table the file does not have is refused. ``rod_ratio``,
    ``stroke`` and ``bore_pitch`` are derived from the file's keys (see :mod:`.derived`); the
    [mounts] table's keys are written as :mod:`.mountkeys` says (``mounts.mass``,
    ``mounts.mount[2].stiffness[3]``, ``mounts.mount[*].stiffness[3]``).

    Raises
    ------
    SweepError
        an unknown key, a key of text or a list, an index outside the file's array, a derived
        parameter the engine does not define (``parameter``); the message lists the keys
        there are, or says why
    """
    if not isinstance(key, str) or not key.strip():
        raise SweepError(
            f"must be a configuration key such as rod_length or banks[2].angle, got {key!r}",
            "parameter",
        )
    text = key.strip()
    if text == BALANCE_FACTOR:
        return Parameter(text, FRACTION, ())
    if text == "mounts" or text.startswith("mounts."):
        return Parameter(text, *mount_parameter(data, text, path))
    if text in DERIVED:
        derived = DERIVED[text]
        # the file's own value, or the reason the engine has none (link rods, uneven throws)
        return Parameter(text, derived.kind, (), derived.file_value(data, path), derived)
    segments = _segments(text)
    if segments is None or len(segments) > 2:
        raise _refused(
            text,
            "not a configuration key (write it as in the file: rod_length, "
            "masses.rotating, banks[2].angle)",
            data,
            path,
        )
    head, index = segments[0]
    if len(segments) == 1:
        if index is not None:
            raise _refused(text, "not a configuration key", data, path)
        if head in _NOT_SCALARS:
            raise _refused(
                text, f"holds {_NOT_SCALARS[head]}, not a number to vary", data, path, listing=False
            )
        if head not in SCHEMA[""]:
            problem = (
                f"{head} is a table; name one of its keys, such as "
                f"{head}.{next(iter(SCHEMA[head]))}"
                if head in SCHEMA
                else f"[{head}] is an array of tables; name one of its keys with the table's "
                "number, "
                f"such as {head}[1].{next(iter(SCHEMA[head + '[]']))}"
                if head + "[]" in SCHEMA
                else "no such key"
            )
            raise _refused(text, problem, data, path, listing=problem == "no such key")
        return Parameter(text, SCHEMA[""][head], (head,), data.get(head))
    (name, subkey) = segments[1]
    if subkey is not None:
        raise _refused(text, "not a configuration key", data, path)
    if index is None:
        if head not in SCHEMA:
            hint = (
                f"[[{head}]] is an array of tables: give the table's number, such as "
                f"{head}[1].{name}"
                if head + "[]" in SCHEMA
                else "no such key"
            )
            raise _refused(text, hint, data, path, listing=hint == "no such key")
        if name not in SCHEMA[head]:
            raise _refused(
                text, f"[{head}] has no key {name} in the configuration format", data, path
            )
        table = data.get(head)
        if not isinstance(table, dict):
            raise _refused(
                text,
                f"{path} has no [{head}] table; add one to vary its keys",
                data,
                path,
                listing=False,
            )
        return Parameter(text, SCHEMA[head][name], (head, name), table.get(name))
    array = head + "[]"
    if array not in SCHEMA:
        raise _refused(
            text,
            f"{head} is not an array of tables" if head in SCHEMA else "no such key",
            data,
            path,
        )
    if name not in SCHEMA[array]:
        raise _refused(text, f"[[{head}]] tables have no key {name}", data, path)
    rows = data.get(head)
    count = len(rows) if isinstance(rows, list) else 0
    if not 1 <= index <= count:
        where = (
            f"only {head}[1]"
            if count == 1
            else f"{head}[1] to {head}[{count}]"
            if count
            else f"no [[{head}]] tables"
        )
        raise _refused(
            text,
            f"{path} has {where}" + (" (numbered from 1)" if count else ""),
            data,
            path,
            listing=False,
        )
    row = rows[index - 1] if isinstance(rows, list) else None
    return Parameter(
        text,
        SCHEMA[array][name],
        (head, index - 1, name),
        row.get(name) if isinstance(row, dict) else None,
    )
