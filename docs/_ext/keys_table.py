"""The configuration keys' tables of "Describe an engine", and their check against the reader.

Pure Python (no Sphinx), so that the test suite uses it without the documentation tools:
``tables()`` reads docs/howto/engine-keys.toml, ``mismatches()`` compares it with the key sets
of :mod:`balance_cli.config.reader`, ``rows()`` gives each table's rows as the page shows them.
"""

import tomllib
from dataclasses import dataclass, field
from pathlib import Path

from balance_cli.config import reader
from balance_cli.units import DIMENSIONS, parse_quantity

DATA = Path(__file__).resolve().parent.parent / "howto" / "engine-keys.toml"

#: kinds that are not a dimension: how a value of each is written
PLAIN_KINDS = {
    "degrees": "degrees (a plain number)",
    "number": "a plain number",
    "integer": "a whole number",
    "text": "text",
    "list": "a list of whole numbers",
    "notes": 'a list of "KEYS: text" strings',
    "table": "a table",
    "tables": "one or more tables",
}


@dataclass(frozen=True)
class Key:
    name: str
    kind: str
    required: bool = False
    default: str | None = None
    default_note: str | None = None
    example: str = ""
    meaning: str = ""
    per_throw: bool = False
    #: a key that takes a list of values of its kind: how many, and what each stands for
    values: str | None = None

    @property
    def default_value(self):
        """The default as the reader holds it (SI for a quantity), or None when none is given."""
        if self.default is None:
            return None
        value = tomllib.loads(f"v = {self.default}")["v"]
        if self.kind in DIMENSIONS:
            return parse_quantity(value, self.kind)
        return value


@dataclass(frozen=True)
class Table:
    path: str
    reader: str
    title: str
    keys: dict = field(default_factory=dict)
    also: tuple = ()

    @property
    def paths(self):
        """Every place of a configuration where this table's keys are read."""
        return (self.path, *self.also)


def tables(path=DATA):
    """The tables of the page, in its order."""
    with open(path, "rb") as file:
        data = tomllib.load(file)
    out = []
    for entry in data["table"]:
        keys = {name: Key(name, **spec) for name, spec in entry.get("keys", {}).items()}
        out.append(
            Table(
                entry["path"], entry["reader"], entry["title"], keys, tuple(entry.get("also", ()))
            )
        )
    return out


def reader_key_sets():
    """The reader's key sets by name: every ``*_KEYS`` of balance_cli.config.reader."""
    return {name: getattr(reader, name) for name in reader.__all__ if name.endswith("_KEYS")}


def mismatches(documented=None):
    """What differs between the page's keys and the reader's, one line each (empty: none)."""
    documented = tables() if documented is None else documented
    sets = reader_key_sets()
    problems = []
    used = [t.reader for t in documented]
    for name in sorted(set(sets) - set(used)):
        problems.append(f"the reader's {name} has no table on the page: {sorted(sets[name])}")
    for table in documented:
        if table.reader not in sets:
            problems.append(f"{table.title}: the reader has no {table.reader}")
            continue
        keys, accepted = set(table.keys), set(sets[table.reader])
        for key in sorted(accepted - keys):
            problems.append(f"{table.title}: the reader accepts {key}, the page does not list it")
        for key in sorted(keys - accepted):
            problems.append(f"{table.title}: the page lists {key}, the reader does not accept it")
        for key in table.keys.values():
            if key.kind not in DIMENSIONS and key.kind not in PLAIN_KINDS:
                problems.append(f"{table.title}: {key.name} has an unknown kind {key.kind!r}")
    return problems


def unit_text(key):
    """The Unit column: the dimension (its units are in the units table) or the plain kind."""
    if key.kind in DIMENSIONS:
        text = key.kind
    else:
        text = PLAIN_KINDS[key.kind]
    if key.values:
        return f"{text}: {key.values}"
    return f"{text}, one or one per throw" if key.per_throw else text


def default_text(key):
    """The Default column: required, the default as written, or words."""
    if key.required:
        return "required"
    if key.default is not None:
        return key.default
    return key.default_note or "none"


def rows(table):
    """(key, unit, default, example, meaning) for every key of ``table``, in the page's order."""
    return [
        (key.name, unit_text(key), default_text(key), key.example, key.meaning)
        for key in table.keys.values()
    ]


def units_rows():
    """(dimension, SI unit, units accepted) for every dimension a configuration may use."""
    return [
        (dimension, next(u for u, f in units.items() if f == 1.0), ", ".join(units))
        for dimension, units in DIMENSIONS.items()
    ]
