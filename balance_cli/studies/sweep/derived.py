"""Parameters a designer thinks in, swept through the configuration's own keys.

The configuration gives ``crank_radius``, ``rod_length`` and each throw's ``z``; a designer
often thinks in the rod/crank ratio, the stroke and the bore pitch instead. Each of these is
computed from the file's keys, and a value of it is written back into those keys, so that
every point is built and checked exactly as a file is:

- ``rod_ratio`` = rod_length / crank_radius (l/r, the inverse of λ = r/l): sets
  ``rod_length`` = ratio × crank_radius and holds ``crank_radius``. Not defined for an
  engine with link rods, whose rods have lengths of their own.
- ``stroke`` = 2 × crank_radius: sets ``crank_radius`` = stroke / 2 and holds ``rod_length``
  (the rod ratio changes with it).
- ``bore_pitch``: the spacing of the throws' ``z`` along each crankshaft. Sets every throw's
  ``z`` to its crankshaft's first throw's ``z`` plus a whole number of pitches, and moves a
  listed cylinder's or counterweight's own ``z`` with its throw (its offset from the throw is
  held); balancer shafts' masses stay where they are. Defined when the throws of every
  crankshaft are evenly spaced, by one pitch, and some crankshaft has two throws.

When a grid or an override sets a key one of them reads (``crank_radius`` or ``stroke``
crossed with ``rod_ratio``), that key is set first: the ratio is then of the point's own
crank radius. Two parameters that set the same key are refused.
"""

import math
import re
from collections.abc import Callable
from dataclasses import dataclass

from ...errors import BalanceError, SweepError
from ...units import parse_quantity

__all__ = ["Derived", "DERIVED"]

_WRITTEN = re.compile(r"^\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*(\S.*?)\s*$", re.ASCII)
#: throws closer to even spacing than this, relative to the pitch, are evenly spaced: a file
#: writes z to a few digits, and "150 mm" three times is exact in any unit
_EVEN = 1e-9
#: a throw this close to its new place, relative to the pitch, has not moved (rounding of
#: z₁ + k·p)
_KEEP = 1e-12


@dataclass(frozen=True)
class Derived:
    """A parameter computed from the configuration's keys.

    Attributes
    ----------
    name : str
        as the sweep names it (``rod_ratio``)
    kind : str
        "number" (a plain ratio) or "length" (written with a unit)
    changes : tuple of str
        the keys a value sets, ``[]`` standing for any table's number (``throws[].z``)
    reads : tuple of str
        the keys it is computed from and holds; set first when a grid varies them
    meaning : str
        what it is, which keys it changes and what it holds, for help texts and JSON
    """

    name: str
    kind: str
    changes: tuple
    reads: tuple
    meaning: str
    file_value: Callable
    apply: Callable

    @property
    def rank(self) -> int:
        """Order of setting at a point: after every plain key, and after another derived
        parameter that sets a key this one reads."""
        return 2 if self.reads else 1


def _length(data, key, path):
    """A length key of the parsed file in metres (the file was built: it is valid)."""
    return parse_quantity(data[key], "length")


def _number_unit(text):
    match = _WRITTEN.match(text)
    assert match is not None  # a length the builder or parse_quantity has read
    return float(match.group(1)), match.group(2)


def _in_unit_of(value_m, like):
    """``value_m`` written in the unit ``like`` is written in ("90 mm"), to 12 digits."""
    unit = _number_unit(like)[1] if isinstance(like, str) else "m"
    return f"{value_m / parse_quantity(f'1 {unit}', 'length') + 0.0:.12g} {unit}"


def _positive_length(value, name):
    metres = parse_quantity(value, "length")
    if not metres > 0:
        raise SweepError(f"must be greater than zero, got {value!r}", name)
    return metres


# --- rod_ratio -----------------------------------------------------------------------------


def _link_rods(data):
    """Where the file puts link rods, in its own words, or None."""
    if isinstance(data.get("links"), dict):
        return "[links]"
    rows = data.get("cylinders")
    if isinstance(rows, list):
        for i, row in enumerate(rows, 1):
            if isinstance(row, dict) and "master" in row:
                return f"cylinders[{i}].master"
    return None


def _rod_ratio_defined(data, path):
    where = _link_rods(data)
    if where is not None:
        raise SweepError(
            f"'rod_ratio' is not defined for {path}: its link rods ({where}) have lengths of "
            "their own (links.length, cylinders[k].link_length), so the engine has no one rod "
            "ratio; vary rod_length (the plain and master rods) or links.length instead",
            "parameter",
        )


def _rod_ratio_value(data, path):
    _rod_ratio_defined(data, path)
    return _length(data, "rod_length", path) / _length(data, "crank_radius", path)


def _rod_ratio_apply(data, value, path):
    _rod_ratio_defined(data, path)
    if not (math.isfinite(value) and value > 0):
        raise SweepError(f"must be a ratio greater than zero, got {value!r}", "rod_ratio")
    # l = ratio × r, in metres at full precision: the point's crank radius, set already (a
    # rod already of that length, to rounding, is left as written: the file's own ratio gives
    # the file itself)
    rod = value * _length(data, "crank_radius", path)
    if abs(rod - _length(data, "rod_length", path)) > _KEEP * rod:
        data["rod_length"] = f"{rod!r} m"


# --- stroke --------------------------------------------------------------------------------


def _stroke_value(data, path):
    number, unit = _number_unit(data["crank_radius"])
    return f"{2 * number:.12g} {unit}"


def _stroke_apply(data, value, path):
    _positive_length(value, "stroke")
    number, unit = _number_unit(value)
    # halving is exact in binary: r = s/2 in the stroke's own unit
    data["crank_radius"] = f"{number / 2!r} {unit}"


# --- bore_pitch ----------------------------------------------------------------------------


def _throw_rows(data):
    rows = data.get("throws")
    return [row if isinstance(row, dict) else {} for row in rows] if isinstance(rows, list) else []


def _shaft_groups(data):
    """Throw indices (0-based, in the file's order) on each crankshaft, by crankshaft number."""
    groups: dict = {}
    for i, row in enumerate(_throw_rows(data)):
        groups.setdefault(row.get("crankshaft", 1), []).append(i)
    return groups


def _z_of(row):
    return parse_quantity(row["z"], "length") if "z" in row else 0.0


def _shown_m(metres, like):
    try:
        return _in_unit_of(metres, like)
    except BalanceError:  # a z written as an unreadable thing was refused by the builder
        return f"{metres:.6g} m"


def _pitch(data, path):
    """(pitch in metres, {crankshaft: direction ±1}) of the file's throws, or a SweepError
    saying why the throws have no one pitch."""
    rows = _throw_rows(data)
    like = next((row["z"] for row in rows if "z" in row), "0 mm")
    refused = f"'bore_pitch' is not defined for {path}: "  # completed below with the reason
    pitches, directions = [], {}
    for shaft, indices in sorted(_shaft_groups(data).items()):
        if len(indices) < 2:
            continue
        z = [_z_of(rows[i]) for i in indices]
        gaps = [b - a for a, b in zip(z, z[1:], strict=False)]
        size = max(abs(g) for g in gaps)
        on = f" on crankshaft {shaft}" if len(_shaft_groups(data)) > 1 else ""
        if size == 0:
            raise SweepError(
                refused + f"its throws{on} all sit at one z, so they have no spacing; give "
                "each throw its z",
                "parameter",
            )
        if any(abs(g - gaps[0]) > _EVEN * size for g in gaps):
            shown = ", ".join(_shown_m(g, like) for g in gaps)
            raise SweepError(
                refused + f"its throws{on} are not evenly spaced (gaps {shown}); vary "
                "throws[k].z instead",
                "parameter",
            )
        pitches.append((shaft, abs(gaps[0])))
        directions[shaft] = 1.0 if gaps[0] > 0 else -1.0
    if not pitches:
        raise SweepError(
            refused + "it has one throw on each crankshaft, so there is no spacing between "
            "throws; vary throws[k].z or cylinders[k].z instead",
            "parameter",
        )
    first = pitches[0][1]
    for shaft, pitch in pitches[1:]:
        if abs(pitch - first) > _EVEN * first:
            raise SweepError(
                refused + f"the throws of crankshaft {pitches[0][0]} are "
                f"{_shown_m(first, like)} apart and those of crankshaft {shaft} "
                f"{_shown_m(pitch, like)}; vary throws[k].z instead",
                "parameter",
            )
    return first, directions


def _bore_pitch_value(data, path):
    pitch, _ = _pitch(data, path)
    like = next((row["z"] for row in _throw_rows(data) if "z" in row), "0 mm")
    return _in_unit_of(pitch, like)


def _bore_pitch_apply(data, value, path):
    _, directions = _pitch(data, path)
    pitch = _positive_length(value, "bore_pitch")
    rows = _throw_rows(data)
    old = [_z_of(row) for row in rows]
    new = list(old)
    for shaft, indices in _shaft_groups(data).items():
        step = directions.get(shaft, 1.0) * pitch
        for k, i in enumerate(indices):
            # z of the k-th throw of its crankshaft: its first throw's, plus k pitches
            new[i] = old[indices[0]] + k * step
    # a throw already where the pitch puts it keeps its z as written (to rounding: the file's
    # own pitch gives the file itself, to the last digit), and so do its cylinders
    moved = [abs(b - a) > _KEEP * pitch for a, b in zip(old, new, strict=True)]
    for row, z, move in zip(data["throws"], new, moved, strict=True):
        if move:
            row["z"] = f"{z!r} m"
    # a cylinder's or counterweight's own z keeps its offset from its throw's
    for table in ("cylinders", "counterweights"):
        for row in data.get(table) or []:
            if isinstance(row, dict) and "z" in row and isinstance(row.get("throw"), int):
                t = row["throw"] - 1
                if 0 <= t < len(old) and moved[t]:
                    row["z"] = f"{parse_quantity(row['z'], 'length') - old[t] + new[t]!r} m"


#: the derived parameters by name
DERIVED = {
    "rod_ratio": Derived(
        "rod_ratio",
        "number",
        ("rod_length",),
        ("crank_radius",),
        "rod length over crank radius, l/r; sets rod_length = ratio × crank_radius and "
        "holds crank_radius (not for link rods)",
        _rod_ratio_value,
        _rod_ratio_apply,
    ),
    "stroke": Derived(
        "stroke",
        "length",
        ("crank_radius",),
        (),
        "twice the crank radius; sets crank_radius = stroke / 2 and holds rod_length (the rod "
        "ratio changes with it)",
        _stroke_value,
        _stroke_apply,
    ),
    "bore_pitch": Derived(
        "bore_pitch",
        "length",
        ("throws[].z", "cylinders[].z", "counterweights[].z"),
        (),
        "the spacing of the throws' z along each crankshaft; sets each throw's z to its "
        "crankshaft's first throw's z plus whole pitches and moves listed cylinders' and "
        "counterweights' own z with their throws (balancer shafts' masses stay)",
        _bore_pitch_value,
        _bore_pitch_apply,
    ),
}
