"""Where a configuration's numbers come from: its ``sources`` and its ``estimates``.

Both are optional top-level lists of one-line strings, each ``"KEYS: text"``: the keys it
speaks for, then a colon and a space, then the citation (``sources``) or why the value was
estimated and how (``estimates``)::

    sources = [
        "crank_radius, gas.bore: Junkers Jumo 205 C type data (bore 105 mm, stroke 2 × 160 mm)",
        "throws.phase: the usual two-stroke six, 1-5-3-6-2-4",
    ]
    estimates = [
        "rod_length: not published; four crank radii, as opposed-piston diesels of the time",
        "masses: piston with rings and pin, scaled from the bore",
    ]

KEYS is a comma-separated list of selectors, each a dotted path of the file's keys in which a
table of an array may be picked by its 1-based index: ``rod_length``, ``masses`` (every key in
``[masses]``), ``throws.z`` (the ``z`` of every throw), ``throws[3].z`` (the third's),
``crankshafts[2]`` (all of the second crankshaft's keys), or ``*`` (every number of the file).
A number named by an estimate is an estimate, whatever a source says of it.

Reading a configuration checks the form of both lists (:func:`read_provenance`); whether every
selector names a key of the file and every number is spoken for is a policy the shipped library
keeps (:meth:`Provenance.unknown_selectors`, :meth:`Provenance.unsourced`), not a rule of the
format: a search template or an engine family derived from a file drops or repeats keys its
notes name.
"""

import re
from dataclasses import dataclass

from ..errors import ConfigError

__all__ = ["Note", "Provenance", "read_provenance", "number_paths", "PROVENANCE_KEYS"]

#: the top-level keys this module reads
PROVENANCE_KEYS = ("sources", "estimates")
#: keys whose values are names, choices, notes or cross-references, not figures of the engine
_NOT_NUMBERS = {
    "name",
    "source",
    "sources",
    "estimates",
    "frame",
    "number",
    "bank",
    "throw",
    "master",
    "opposed_throw",
    "crankshaft",
    "master_bank",
    "rotation",
    "products_convention",
}
#: one segment of a selector: a key, optionally with a 1-based index of an array of tables
_SEGMENT = r"[A-Za-z_][A-Za-z0-9_]*(?:\[[1-9][0-9]*\])?"
_SELECTOR = re.compile(rf"\*|{_SEGMENT}(?:\.{_SEGMENT})*")
#: "KEYS: text": the selectors, a colon and one space, then the text
_NOTE = re.compile(r"(?P<keys>[^:]*?): (?P<text>\S.*)")


@dataclass(frozen=True)
class Note:
    """One entry of ``sources`` or ``estimates``: the selectors it speaks for and its text."""

    keys: tuple[str, ...]
    text: str

    def covers(self, path: str) -> bool:
        """Whether one of the selectors names ``path`` (a number's path, see
        :func:`number_paths`) or a table above it."""
        return any(_covers(selector, path) for selector in self.keys)

    def __str__(self):
        return f"{', '.join(self.keys)}: {self.text}"


@dataclass(frozen=True)
class Provenance:
    """A configuration's ``sources`` and ``estimates`` (empty tuples where it gives none)."""

    sources: tuple[Note, ...] = ()
    estimates: tuple[Note, ...] = ()

    @property
    def declared(self) -> bool:
        """Whether the file gives ``sources`` or ``estimates`` at all."""
        return bool(self.sources or self.estimates)

    def estimated(self, data: dict) -> list[str]:
        """The paths of the numbers of ``data`` (the file's parsed TOML) an estimate names."""
        return [p for p in number_paths(data) if any(n.covers(p) for n in self.estimates)]

    def unsourced(self, data: dict) -> list[str]:
        """The paths of the numbers of ``data`` that neither a source nor an estimate names."""
        notes = self.sources + self.estimates
        return [p for p in number_paths(data) if not any(n.covers(p) for n in notes)]

    def unknown_selectors(self, data: dict) -> list[str]:
        """The selectors that name no key of ``data`` (``*`` names every number)."""
        paths = _all_paths(data)
        return [
            selector
            for note in self.sources + self.estimates
            for selector in note.keys
            if selector != "*" and not any(_covers(selector, p) for p in paths)
        ]

    def to_dict(self) -> dict:
        return {
            "sources": [str(n) for n in self.sources],
            "estimates": [str(n) for n in self.estimates],
        }


def read_provenance(data: dict, path: str = "<config>") -> Provenance:
    """The ``sources`` and ``estimates`` of a configuration's parsed TOML ``data``.

    Raises
    ------
    ConfigError
        naming the file and the entry (``estimates[2]``) whose form is wrong, and the fix
    """
    notes = {}
    for key in PROVENANCE_KEYS:
        raw = data.get(key, [])
        if not isinstance(raw, list) or not raw and key in data:
            raise ConfigError(
                path,
                key,
                f'expected a list of "KEYS: text" strings such as ["rod_length: {_EXAMPLE[key]}"]',
            )
        notes[key] = tuple(_note(path, f"{key}[{i}]", entry) for i, entry in enumerate(raw, 1))
    return Provenance(notes["sources"], notes["estimates"])


_EXAMPLE = {"sources": "maker's data sheet", "estimates": "not published; 3.3 crank radii"}


def _note(path, key, entry):
    example = f'such as "rod_length, masses.reciprocating: {_EXAMPLE[key.split("[")[0]]}"'
    if not isinstance(entry, str) or not entry.strip():
        raise ConfigError(path, key, f'expected a "KEYS: text" string {example}, got {entry!r}')
    if not entry.isprintable():
        raise ConfigError(path, key, f"must be one line of printable text, got {entry!r}")
    match = _NOTE.fullmatch(entry)
    if match is None:
        raise ConfigError(
            path,
            key,
            f"expected the keys it speaks for, a colon and a space, then its text, {example}; "
            f"got {entry!r}",
        )
    selectors = tuple(s.strip() for s in match["keys"].split(","))
    for selector in selectors:
        if not _SELECTOR.fullmatch(selector):
            raise ConfigError(
                path,
                key,
                f"{selector!r} is not a key: give dotted keys of the file, an array's table by "
                f"its 1-based index (throws[3].z), or * for every number",
            )
    return Note(selectors, match["text"].strip())


def number_paths(data: dict) -> list[str]:
    """The paths (``throws[3].z``, ``masses.reciprocating``, ``firing_order``) of every number
    in a configuration's parsed TOML ``data``: values with units, plain numbers and lists of
    them; names, choices, notes and indices that refer to another table are not numbers."""
    return [p for p, key, _ in _leaves(data, "") if key not in _NOT_NUMBERS]


def _all_paths(data):
    """Every key's path, tables and arrays of tables included."""
    out = []
    for key, value in data.items():
        if isinstance(value, dict):
            out.append(key)
            out += [f"{key}.{p}" for p in _all_paths(value)]
        elif _is_tables(value):
            for i, table in enumerate(value, 1):
                out.append(f"{key}[{i}]")
                out += [f"{key}[{i}].{p}" for p in _all_paths(table)]
        else:
            out.append(key)
    return out


def _leaves(table, prefix):
    for key, value in table.items():
        if isinstance(value, dict):
            yield from _leaves(value, f"{prefix}{key}.")
        elif _is_tables(value):
            for i, row in enumerate(value, 1):
                yield from _leaves(row, f"{prefix}{key}[{i}].")
        else:
            yield f"{prefix}{key}", key, value


def _is_tables(value):
    return isinstance(value, list) and bool(value) and all(isinstance(v, dict) for v in value)


def _segments(path):
    """``throws[3].z`` -> [("throws", 3), ("z", None)]."""
    out = []
    for part in path.split("."):
        name, _, index = part.partition("[")
        out.append((name, int(index[:-1]) if index else None))
    return out


def _covers(selector, path):
    """A selector names a path if its segments lead the path's, an unindexed one standing for
    every table of its array."""
    if selector == "*":
        return True
    wanted, have = _segments(selector), _segments(path)
    if len(wanted) > len(have):
        return False
    return all(
        name == own and (index is None or index == own_index)
        for (name, index), (own, own_index) in zip(wanted, have, strict=False)
    )
