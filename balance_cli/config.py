"""Configuration format version 1: TOML file -> :class:`~balance_cli.model.Engine`.

Every error names the file, the key (``banks[3].angle``) and what to do about it.
Unknown keys are errors: a typo must not be silently ignored.
"""

import math
import tomllib
from pathlib import Path

from .kinematics import check_assembly
from .model import Cylinder, Engine, ModelError, Throw
from .units import UnitError, parse_quantity

__all__ = ["ConfigError", "load", "load_many", "find_configs"]

_TOP_KEYS = {
    "name", "source", "cycle", "speed", "crank_radius", "rod_length", "pin_offset", "frame",
    "firing_order", "masses", "banks", "throws", "links", "cylinders",
}
_MASS_KEYS = {"reciprocating", "rotating", "knuckle", "crank"}
_BANK_KEYS = {"angle"}
_THROW_KEYS = {"phase", "z"}
_LINK_KEYS = {"master_bank", "length", "knuckle_radius"}
_CYLINDER_KEYS = {
    "number", "bank", "throw", "z", "reciprocating", "master", "link_length", "knuckle_radius",
    "knuckle_angle",
}


class ConfigError(ValueError):
    """A configuration that cannot be read; the message names file, key and fix."""

    def __init__(self, path, key, problem):
        self.path, self.key, self.problem = str(path), key, problem
        where = f"{self.path}: {key}: " if key else f"{self.path}: "
        super().__init__(where + problem)


class _Reader:
    """Typed access to one TOML table, raising ConfigError with the key's full name."""

    def __init__(self, path, table, prefix, allowed):
        self.path, self.table, self.prefix = path, table, prefix
        if not isinstance(table, dict):
            raise ConfigError(path, prefix.rstrip("."), "expected a table")
        for key in table:
            if key not in allowed:
                known = ", ".join(sorted(allowed))
                raise ConfigError(
                    path, prefix + key, f"unknown key; check the spelling (known keys: {known})"
                )

    def name(self, key):
        return self.prefix + key

    def error(self, key, problem):
        return ConfigError(self.path, self.name(key), problem)

    def has(self, key):
        return key in self.table

    def _get(self, key, required):
        if key not in self.table:
            if required:
                raise self.error(key, "missing; this key is required")
            return None
        return self.table[key]

    def quantity(self, key, dimension, required=True, default=None, positive=True, minimum=None):
        raw = self._get(key, required)
        if raw is None:
            return default
        try:
            value = parse_quantity(raw, dimension)
        except UnitError as exc:
            raise self.error(key, str(exc)) from None
        if positive and value <= 0.0:
            raise self.error(key, f"must be greater than zero, got {raw!r}")
        if minimum is not None and value < minimum:
            raise self.error(key, f"must not be negative, got {raw!r}")
        return value

    def number(self, key, required=True, default=None):
        raw = self._get(key, required)
        if raw is None:
            return default
        if isinstance(raw, bool) or not isinstance(raw, (int, float)) or not math.isfinite(raw):
            raise self.error(key, f"expected a number of degrees such as 40 or -22.5, got {raw!r}")
        return float(raw)

    def integer(self, key, required=True, default=None, low=None, high=None):
        raw = self._get(key, required)
        if raw is None:
            return default
        if isinstance(raw, bool) or not isinstance(raw, int):
            raise self.error(key, f"expected a whole number, got {raw!r}")
        if low is not None and raw < low or high is not None and raw > high:
            raise self.error(key, f"must be between {low} and {high}, got {raw}")
        return raw

    def string(self, key, required=True, default=None, choices=None):
        raw = self._get(key, required)
        if raw is None:
            return default
        if not isinstance(raw, str) or not raw.strip():
            raise self.error(key, f"expected a non-empty string, got {raw!r}")
        if choices and raw not in choices:
            options = " or ".join(f'"{c}"' for c in choices)
            raise self.error(key, f"must be {options}, got {raw!r}")
        return raw

    def tables(self, key, required=True):
        raw = self._get(key, required)
        if raw is None:
            return []
        if not isinstance(raw, list) or not raw or not all(isinstance(t, dict) for t in raw):
            raise self.error(key, f"expected one or more [[{key}]] tables")
        return raw


def load(path):
    """Read, validate and build the engine described by the TOML file at ``path``."""
    path = Path(path)
    try:
        text = path.read_bytes().decode("utf-8")
    except FileNotFoundError:
        raise ConfigError(path, "", "no such file; check the path") from None
    except (OSError, UnicodeDecodeError) as exc:
        raise ConfigError(path, "", f"cannot read the file ({exc})") from None
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise ConfigError(path, "", f"not valid TOML: {exc}; fix the syntax there") from None
    return build(data, path)


def build(data, path="<config>"):
    """Build an engine from parsed TOML ``data`` (a dict), naming ``path`` in errors."""
    top = _Reader(path, data, "", _TOP_KEYS)
    name = top.string("name")
    source = top.string("source", required=False, default="")
    cycle = top.integer("cycle")
    if cycle not in (2, 4):
        raise top.error("cycle", f"must be 2 or 4 (strokes per cycle), got {cycle}")
    speed = top.quantity("speed", "angular speed")
    crank_radius = top.quantity("crank_radius", "length")
    rod_length = top.quantity("rod_length", "length")
    pin_offset = top.quantity("pin_offset", "length", required=False, default=0.0, positive=False)
    frame = top.string("frame", required=False, default="fixed", choices=("fixed", "rotary"))
    if rod_length <= crank_radius + abs(pin_offset):
        raise top.error(
            "rod_length",
            f"{data['rod_length']!r} is not longer than the crank radius plus |pin_offset|, so "
            "the rod cannot reach the cylinder axis; make it longer or the crank shorter",
        )

    masses = _Reader(path, top._get("masses", True), "masses.", _MASS_KEYS)
    reciprocating = masses.quantity("reciprocating", "mass")
    rotating = masses.quantity("rotating", "mass", required=False, default=0.0, positive=False,
                               minimum=0.0)
    knuckle = masses.quantity("knuckle", "mass", required=False, default=0.0, positive=False,
                              minimum=0.0)
    crank = masses.quantity("crank", "mass", required=False, default=0.0, positive=False,
                            minimum=0.0)

    banks = []
    for i, table in enumerate(top.tables("banks"), 1):
        bank = _Reader(path, table, f"banks[{i}].", _BANK_KEYS)
        banks.append(math.radians(bank.number("angle")))
    throws = []
    for i, table in enumerate(top.tables("throws"), 1):
        throw = _Reader(path, table, f"throws[{i}].", _THROW_KEYS)
        throws.append(Throw(math.radians(throw.number("phase")),
                            throw.quantity("z", "length", required=False, default=0.0,
                                           positive=False)))

    links = None
    if top.has("links"):
        reader = _Reader(path, data["links"], "links.", _LINK_KEYS)
        links = {
            "master_bank": reader.integer("master_bank", low=1, high=len(banks)) - 1,
            "length": reader.quantity("length", "length"),
            "knuckle_radius": reader.quantity("knuckle_radius", "length"),
        }

    if top.has("cylinders"):
        cylinders = _listed_cylinders(path, top.tables("cylinders"), banks, throws, reciprocating,
                                      knuckle, links)
    else:
        cylinders = _grid_cylinders(banks, throws, reciprocating, knuckle, links)

    firing_order = None
    if top.has("firing_order"):
        raw = data["firing_order"]
        if not isinstance(raw, list) or not all(
            isinstance(n, int) and not isinstance(n, bool) for n in raw
        ):
            raise top.error("firing_order", "expected a list of cylinder numbers such as [1, 3, 4, 2]")
        numbers = sorted(c.number for c in cylinders)
        if sorted(raw) != numbers:
            raise top.error(
                "firing_order",
                f"{raw} is not a permutation of the cylinder numbers {numbers}; "
                "list every cylinder exactly once",
            )
        firing_order = tuple(raw)

    engine = Engine(
        name=name, cycle=cycle, speed_rad_s=speed, crank_radius_m=crank_radius,
        rod_length_m=rod_length, bank_angles_rad=tuple(banks), throws=tuple(throws),
        cylinders=tuple(cylinders), rotating_kg=rotating, crank_kg=crank, pin_offset_m=pin_offset,
        frame=frame,
        firing_order=firing_order, source=source, config_path=str(path),
    )
    try:
        check_assembly(engine)
    except ModelError as exc:
        raise ConfigError(path, "", f"{exc}") from None
    return engine


def _link_fields(cylinder_bank, master_bank, banks, links, knuckle_mass):
    return dict(
        link_length_m=links["length"],
        knuckle_radius_m=links["knuckle_radius"],
        knuckle_angle_rad=banks[cylinder_bank] - banks[master_bank],
        knuckle_kg=knuckle_mass,
    )


def _grid_cylinders(banks, throws, reciprocating, knuckle, links):
    """One cylinder per (bank, throw), numbered bank by bank."""
    cylinders = []
    for b in range(len(banks)):
        for t, throw in enumerate(throws):
            number = b * len(throws) + t + 1
            extra = {}
            if links and b != links["master_bank"]:
                extra = _link_fields(b, links["master_bank"], banks, links, knuckle)
                extra["master"] = links["master_bank"] * len(throws) + t + 1
            cylinders.append(Cylinder(number, b, t, throw.z_m, reciprocating, **extra))
    return cylinders


def _listed_cylinders(path, tables, banks, throws, reciprocating, knuckle, links):
    """The complete list of [[cylinders]], with link rods resolved against their masters."""
    rows = []
    seen = set()
    for i, table in enumerate(tables, 1):
        r = _Reader(path, table, f"cylinders[{i}].", _CYLINDER_KEYS)
        number = r.integer("number", low=1, high=10_000)
        if number in seen:
            raise r.error("number", f"cylinder {number} is listed twice; give each a unique number")
        seen.add(number)
        bank = r.integer("bank", low=1, high=len(banks)) - 1
        throw = r.integer("throw", low=1, high=len(throws)) - 1
        rows.append(dict(
            reader=r, number=number, bank=bank, throw=throw,
            z=r.quantity("z", "length", required=False, default=throws[throw].z_m, positive=False),
            reciprocating=r.quantity("reciprocating", "mass", required=False, default=reciprocating),
            master=r.integer("master", required=False),
            link_length=r.quantity("link_length", "length", required=False),
            knuckle_radius=r.quantity("knuckle_radius", "length", required=False),
            knuckle_angle=r.number("knuckle_angle", required=False),
        ))
    by_number = {row["number"]: row for row in rows}
    if links:
        # [links]: every cylinder off the master bank that names no master rides on the
        # master-bank cylinder of its throw
        masters_by_throw = {row["throw"]: row["number"] for row in rows
                            if row["bank"] == links["master_bank"] and row["master"] is None}
        for row in rows:
            if row["master"] is None and row["bank"] != links["master_bank"]:
                if row["throw"] not in masters_by_throw:
                    raise row["reader"].error(
                        "throw", f"no cylinder of links.master_bank sits on throw {row['throw'] + 1} "
                        "to carry this link rod; add one or give this cylinder its own master")
                row["master"] = masters_by_throw[row["throw"]]
    cylinders = []
    for row in rows:
        r = row["reader"]
        fields = {}
        if row["master"] is not None:
            master = by_number.get(row["master"])
            if master is None or master is row:
                raise r.error("master", f"names cylinder {row['master']}, which is not another "
                              "listed cylinder; give the number of the master-rod cylinder")
            if master["master"] is not None:
                raise r.error("master", f"cylinder {row['master']} has a link rod itself; a link "
                              "rod must ride on a master rod")
            if master["throw"] != row["throw"]:
                raise r.error("master", f"cylinder {row['master']} is on throw {master['throw'] + 1} "
                              f"but this one on throw {row['throw'] + 1}; a link rod rides on the "
                              "master rod of its own throw")
            defaults = links or {}
            length = row["link_length"] or defaults.get("length")
            radius = row["knuckle_radius"] or defaults.get("knuckle_radius")
            for key, value in (("link_length", length), ("knuckle_radius", radius)):
                if value is None:
                    raise r.error(key, "missing for a link rod; give it here or in [links]")
            angle = row["knuckle_angle"]
            fields = dict(
                master=row["master"], link_length_m=length, knuckle_radius_m=radius,
                knuckle_angle_rad=(math.radians(angle) if angle is not None
                                   else banks[row["bank"]] - banks[master["bank"]]),
                knuckle_kg=knuckle,
            )
        else:
            for key in ("link_length", "knuckle_radius", "knuckle_angle"):
                if row[key] is not None:
                    raise r.error(key, "only a link rod has this; give the cylinder a master "
                                  "(or [links]) or remove the key")
        cylinders.append(Cylinder(row["number"], row["bank"], row["throw"], row["z"],
                                  row["reciprocating"], **fields))
    return cylinders


def find_configs(paths):
    """Expand files and directories (recursively, sorted) into a list of .toml files."""
    found = []
    for p in map(Path, paths):
        if p.is_dir():
            found.extend(sorted(p.rglob("*.toml")))
        else:
            found.append(p)
    return found


def load_many(paths):
    """Load every configuration under ``paths``; raise ConfigError when there is none."""
    files = find_configs(paths)
    if not files:
        raise ConfigError(", ".join(map(str, paths)), "", "no .toml configuration found there")
    return [load(f) for f in files]
