"""Measured parts: pistons and connecting rods weighed one by one, read from ``PARTS.csv``.

The file has the columns ``kind,id,mass``. ``kind`` is ``piston`` (a piston with its pin,
rings and clips: all of it reciprocates), ``rod_small`` or ``rod_big`` (a connecting rod's
small-end and big-end masses, weighed on the usual two-scale fixture: the small end
reciprocates, the big end turns with the crank pin); one rod is one ``id`` with both rows.
Masses carry their units (``"512.4 g"``). Any other column or kind is an error naming the
line.
"""

import csv
import math
import os
from dataclasses import dataclass
from pathlib import Path

from .. import checks
from ..errors import AnalysisError, ConfigError, UnitError
from ..tabular import Tabular
from ..units import parse_quantity

__all__ = ["Piston", "Rod", "PartSet", "read_parts_csv", "as_parts", "KINDS", "COLUMNS"]

#: the kinds of row a parts file may hold
KINDS = ("piston", "rod_small", "rod_big")
#: its columns, in this order
COLUMNS = ("kind", "id", "mass")


@dataclass(frozen=True)
class Piston:
    """One piston as weighed: ``mass_kg`` with its pin, rings and clips (all reciprocating)."""

    id: str
    mass_kg: float


@dataclass(frozen=True)
class Rod:
    """One connecting rod as weighed on a two-scale fixture: its small end (reciprocating)
    and its big end (rotating with the crank pin), kg."""

    id: str
    small_end_kg: float
    big_end_kg: float

    @property
    def mass_kg(self) -> float:
        return self.small_end_kg + self.big_end_kg


@dataclass(frozen=True)
class PartSet(Tabular):
    """The pistons and rods to fit, in the order given (the file's).

    Attributes
    ----------
    pistons : tuple of Piston
    rods : tuple of Rod
    source : str
        the file they were read from (empty when built in code)
    """

    pistons: tuple = ()
    rods: tuple = ()
    source: str = ""

    def __post_init__(self):
        for name, kind in (("pistons", Piston), ("rods", Rod)):
            value = getattr(self, name)
            if isinstance(value, (str, bytes)) or not hasattr(value, "__iter__"):
                raise AnalysisError(f"must be a list of {kind.__name__}s, got {value!r}", name)
            value = tuple(value)
            if not all(isinstance(v, kind) for v in value):
                raise AnalysisError(f"must hold {kind.__name__}s only", name)
            for part in value:
                masses = (part.mass_kg,) if kind is Piston else (part.small_end_kg, part.big_end_kg)
                if not all(checks.is_real(m) and math.isfinite(m) and m > 0 for m in masses):
                    raise AnalysisError(
                        f"{part.id!r}: its masses must be finite numbers above zero, kg", name
                    )
            object.__setattr__(self, name, value)
            ids = [p.id for p in value]
            twice = next((i for i in ids if ids.count(i) > 1), None)
            if twice is not None:
                raise AnalysisError(f"has the id {twice!r} twice; give each part its own", name)
        if not self.pistons and not self.rods:
            raise AnalysisError("has neither pistons nor rods; give one kind at least", "parts")

    @property
    def kinds(self) -> tuple:
        """The kinds given: "pistons", "rods" or both."""
        return tuple(k for k in ("pistons", "rods") if getattr(self, k))

    def mean_piston_kg(self) -> float:
        return sum(p.mass_kg for p in self.pistons) / len(self.pistons)

    def mean_small_end_kg(self) -> float:
        return sum(r.small_end_kg for r in self.rods) / len(self.rods)

    def mean_big_end_kg(self) -> float:
        return sum(r.big_end_kg for r in self.rods) / len(self.rods)

    def records(self) -> list:
        """One row per weighed mass, as the file gives them: ``kind`` (piston, rod_small,
        rod_big), ``id``, ``mass_kg``."""
        rows = [{"kind": "piston", "id": p.id, "mass_kg": p.mass_kg} for p in self.pistons]
        for r in self.rods:
            rows.append({"kind": "rod_small", "id": r.id, "mass_kg": r.small_end_kg})
            rows.append({"kind": "rod_big", "id": r.id, "mass_kg": r.big_end_kg})
        return rows


def _rows(path):
    """The file's non-empty rows with their line numbers."""
    if os.path.exists(path) and not os.path.isdir(path) and not os.path.isfile(path):
        raise ConfigError(path, "", "is not a regular file; give a CSV file")
    try:
        with open(path, encoding="utf-8-sig", newline="") as handle:
            records = list(csv.reader(handle))
    except FileNotFoundError:
        raise ConfigError(path, "", "no such file; check the path") from None
    except IsADirectoryError:
        raise ConfigError(path, "", "is a folder; give a CSV file") from None
    except UnicodeDecodeError:
        raise ConfigError(path, "", "is not UTF-8 text; give a CSV file") from None
    except (OSError, csv.Error) as exc:
        raise ConfigError(
            path, "", f"cannot read the file ({getattr(exc, 'strerror', None) or exc})"
        ) from None
    return [(i, row) for i, row in enumerate(records, 1) if any(cell.strip() for cell in row)]


def read_parts_csv(path) -> PartSet:
    """The pistons and rods of a parts file (``kind,id,mass``), in the file's order.

    Raises
    ------
    ConfigError
        naming the file, the line and the fix: another column or kind, a mass without its
        unit, an id given twice, a rod without both its ends
    """
    checks.path(path)
    rows = _rows(path)
    header = ",".join(COLUMNS)
    if not rows:
        raise ConfigError(path, "", f"is empty; give a header {header} and one row per mass")
    line, first = rows[0]
    if [c.strip().lower() for c in first] != list(COLUMNS):
        raise ConfigError(
            path,
            f"line {line}",
            f"the header is {','.join(c.strip() for c in first)!r}; it must be {header} "
            "(no other column)",
        )
    pistons: dict = {}
    ends: dict = {}  # rod id -> {"rod_small": (kg, line), "rod_big": (kg, line)}
    for line, row in rows[1:]:
        if len(row) != len(COLUMNS):
            raise ConfigError(
                path,
                f"line {line}",
                f"has {len(row)} column{'' if len(row) == 1 else 's'}; give three: {header}",
            )
        kind, ident, text = (cell.strip() for cell in row)
        if kind not in KINDS:
            raise ConfigError(
                path,
                f"line {line}",
                f"kind {kind!r} is not one of {', '.join(KINDS)} (a piston with its pin, rings "
                "and clips; a rod's small end; its big end)",
            )
        if not ident:
            raise ConfigError(path, f"line {line}", "has no id; give each part one")
        try:
            mass = parse_quantity(text, "mass")
        except UnitError as exc:
            raise ConfigError(path, f"line {line}", f"mass: {exc}") from None
        if mass <= 0.0:
            raise ConfigError(path, f"line {line}", f"mass {text!r} must be greater than zero")
        if kind == "piston":
            if ident in pistons:
                raise ConfigError(
                    path,
                    f"line {line}",
                    f"piston {ident!r} is given twice (first on line "
                    f"{pistons[ident][1]}); give each piston once",
                )
            pistons[ident] = (mass, line)
            continue
        own = ends.setdefault(ident, {})
        if kind in own:
            raise ConfigError(
                path,
                f"line {line}",
                f"the {kind} of rod {ident!r} is given twice (first on line {own[kind][1]})",
            )
        own[kind] = (mass, line)
    rods = []
    for ident, own in ends.items():
        missing = [k for k in ("rod_small", "rod_big") if k not in own]
        if missing:
            line = next(iter(own.values()))[1]
            raise ConfigError(
                path,
                f"line {line}",
                f"rod {ident!r} has no {missing[0]} row; a rod is one id with both its "
                "rod_small and its rod_big mass",
            )
        rods.append(Rod(ident, own["rod_small"][0], own["rod_big"][0]))
    if not pistons and not rods:
        raise ConfigError(path, "", "lists no part; give one row per mass after the header")
    return PartSet(
        tuple(Piston(i, m) for i, (m, _) in pistons.items()), tuple(rods), str(Path(path))
    )


def as_parts(parts) -> PartSet:
    """``parts`` as a PartSet: itself, or the parts file at that path."""
    if isinstance(parts, PartSet):
        return parts
    if isinstance(parts, (str, os.PathLike)):
        return read_parts_csv(parts)
    raise AnalysisError(
        f"must be a PartSet or the path of a parts file (kind,id,mass), got {type(parts).__name__}",
        "parts",
    )
