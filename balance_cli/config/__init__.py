"""Configuration format version 1: TOML -> :class:`~balance_cli.model.Engine`.

Every error names the file, the key (``banks[3].angle``) and what to do about it. Unknown keys
are errors: a typo must not be silently ignored. This module reads values (types, units,
ranges, signs); the rules that relate values to each other (a rod longer than the crank, link
rods on master rods of their own throw, one cylinder per bore, a firing order that lists every
cylinder) are the model's, whose messages are translated here into the file's key names;
only the uniqueness of cylinder numbers is checked here too, because the key of a listed
cylinder is found by its number.
"""

import dataclasses
import math
import os
import re
import tomllib
from collections.abc import Iterable
from pathlib import Path

from .. import checks
from ..errors import ConfigError, ModelError, UnitError
from ..kinematics.linkage import check_assembly
from ..model import (FRAMES, MAX_SHAFT_RATIO, BalancerMass, BalancerShaftSpec, CounterweightMass,
                     Crankshaft, Cylinder, Engine, GasCycle, Parts, ShaftDisk, Throw,
                     TorsionModel)
from ..tolerances import SAME_POSITION_M
from ..units import parse_quantity

__all__ = ["load", "loads", "build", "find_configs", "load_many", "load_template", "load_data",
           "arrangement_toml", "as_built_toml"]

_TOP_KEYS = {
    "name", "source", "cycle", "speed", "crank_radius", "rod_length", "pin_offset", "frame",
    "firing_order", "vertical", "power", "masses", "parts", "gas", "banks", "throws", "links", "cylinders",
    "crankshafts", "counterweights", "shafts", "torsion",
}
_MASS_KEYS = {"reciprocating", "rotating", "knuckle", "crank"}
_PART_KEYS = {"piston", "rod_mass", "rod_cg", "rod_inertia", "link_mass", "link_cg", "link_inertia",
              "crank", "crankshaft_inertia", "flywheel_inertia"}
_GAS_KEYS = {"bore", "compression_ratio", "imep", "intake_pressure", "crankcase_pressure",
             "polytropic_exponent", "combustion_start", "combustion_duration", "wiebe_a", "wiebe_m"}
_TORSION_KEYS = {"throw_inertia", "web_inertia", "stiffness", "throw_damping", "loss_factor",
                 "shaft_diameter", "shaft_bore", "front", "flywheel", "load"}
_DISK_KEYS = {"name", "inertia", "stiffness", "damping"}
_BANK_KEYS = {"angle", "pin_offset"}
_THROW_KEYS = {"phase", "z", "crankshaft"}
_CRANKSHAFT_KEYS = {"x", "y", "direction", "phase"}
_LINK_KEYS = {"master_bank", "length", "knuckle_radius"}
_COUNTERWEIGHT_KEYS = {"throw", "mass", "radius", "mass_radius", "angle", "z"}
_SHAFT_KEYS = {"ratio", "lateral", "vertical", "masses"}
_SHAFT_MASS_KEYS = {"mass", "eccentricity", "mass_radius", "angle", "z"}
_CYLINDER_KEYS = {
    "number", "bank", "throw", "z", "reciprocating", "master", "link_length", "knuckle_radius",
    "knuckle_angle", "pin_offset", "opposed_throw", "opposed_reciprocating",
}
#: model field -> configuration key, for the model's messages
_KEYS = {
    "speed_rad_s": "speed", "crank_radius_m": "crank_radius", "rod_length_m": "rod_length",
    "pin_offset_m": "pin_offset", "rotating_kg": "masses.rotating", "crank_kg": "masses.crank",
    "reciprocating_kg": "reciprocating", "knuckle_kg": "masses.knuckle",
    "link_length_m": "link_length", "knuckle_radius_m": "knuckle_radius",
    "knuckle_angle_rad": "knuckle_angle", "bank_angles_rad": "banks", "z_m": "z",
    "vertical_rad": "vertical", "power_w": "power", "crankshafts": "crankshafts",
    "opposed_throw": "opposed_throw", "opposed_reciprocating_kg": "opposed_reciprocating",
    "balancer_shafts": "shafts",
}
_FIELD = re.compile(r"\b(" + "|".join(map(re.escape, _KEYS)) + r")\b")
#: angles are plain numbers of degrees within one turn either way
_ANGLE_LIMIT_DEG = 360.0


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

    def error(self, key, problem):
        return ConfigError(self.path, self.prefix + key, problem)

    def has(self, key):
        return key in self.table

    def _get(self, key, required):
        if key not in self.table:
            if required:
                raise self.error(key, "missing; this key is required")
            return None
        return self.table[key]

    def quantity(self, key, dimension, required=True, default=None, sign="positive"):
        """A value with a unit, in SI; ``sign`` "positive", "non-negative" or "any"."""
        raw = self._get(key, required)
        if raw is None:
            return default
        try:
            value = parse_quantity(raw, dimension)
        except UnitError as exc:
            raise self.error(key, str(exc)) from None
        if sign == "positive" and value <= 0.0:
            raise self.error(key, f"must be greater than zero, got {raw!r}")
        if sign == "non-negative" and value < 0.0:
            raise self.error(key, f"must not be negative, got {raw!r}")
        return value + 0.0  # -0 reads as 0

    def degrees(self, key, required=True):
        raw = self._get(key, required)
        if raw is None:
            return None
        if isinstance(raw, bool) or not isinstance(raw, (int, float)) or not math.isfinite(raw):
            raise self.error(key, f"expected a number of degrees such as 40 or -22.5, got {raw!r}")
        if abs(raw) > _ANGLE_LIMIT_DEG:
            raise self.error(key, f"must be between -{_ANGLE_LIMIT_DEG:g} and "
                                  f"{_ANGLE_LIMIT_DEG:g} degrees, got {raw!r}")
        return float(raw) + 0.0  # -0 reads as 0

    def real(self, key, required=True, default=None, low=None, high=None, what="a number"):
        """A plain number (no unit) from ``low`` to ``high``."""
        raw = self._get(key, required)
        if raw is None:
            return default
        if isinstance(raw, bool) or not isinstance(raw, (int, float)) or not math.isfinite(raw):
            raise self.error(key, f"expected {what} such as {low if low else 1}, got {raw!r}")
        if low is not None and raw < low or high is not None and raw > high:
            raise self.error(key, f"must be from {low:g} to {high:g}, got {raw!r}")
        return float(raw) + 0.0

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
        if not raw.isprintable():
            raise self.error(key, f"must be one line of printable text, got {raw!r}")
        if choices and raw not in choices:
            options = " or ".join(f'"{c}"' for c in choices)
            raise self.error(key, f"must be {options}, got {raw!r}")
        return raw

    def tables(self, key, required=True):
        raw = self._get(key, required)
        if raw is None:
            return []
        if not isinstance(raw, list) or not raw or not all(isinstance(t, dict) for t in raw):
            table = re.sub(r"\[\d+\]", "", self.prefix + key)   # shafts[2].masses: [[shafts.masses]]
            raise self.error(key, f"expected one or more [[{table}]] tables")
        return raw


def load(path: "str | os.PathLike[str]") -> Engine:
    """Read, check and build the engine described by the TOML file at ``path``.

    Raises
    ------
    ConfigError
        naming the file, the key and the fix
    """
    return loads(_read_text(Path(checks.path(path))), name=str(path))


def load_data(path: "str | os.PathLike[str]") -> dict:
    """The parsed TOML of the file at ``path``, checked as a configuration (its throws'
    phases may be given or not): what :func:`balance_cli.studies.family.family` repeats.

    Raises
    ------
    ConfigError
        naming the file, the key and the fix
    """
    data = _read_data(path)
    build(as_template(data), str(path), template=True)
    return data


def as_template(data: dict) -> dict:
    """A configuration's parsed TOML without its throws' phases and firing order: a search
    template of the same engine."""
    template = {k: v for k, v in data.items() if k != "firing_order"}
    if isinstance(template.get("throws"), list):
        template["throws"] = [{k: v for k, v in t.items() if k != "phase"} if isinstance(t, dict)
                              else t for t in template["throws"]]
    return template


def load_template(path: "str | os.PathLike[str]") -> tuple[Engine, dict]:
    """Read a search template: a configuration whose ``[[throws]]`` give only ``z`` and which
    has no ``firing_order`` (``balance search`` chooses both). Returns the engine, every throw
    at phase 0, and the parsed TOML (for :func:`arrangement_toml`).

    Raises
    ------
    ConfigError
        naming the file, the key and the fix
    """
    data = _read_data(path)
    return build(data, str(path), template=True), data


def _read_data(path):
    return _parse(_read_text(Path(checks.path(path))), str(path))


def _read_text(path: Path) -> str:
    try:
        # a FIFO or a device would block or never end: only regular files are configurations
        if path.exists() and not path.is_file() and not path.is_dir():
            raise ConfigError(path, "", "is not a regular file; give a .toml file")
        data = path.read_bytes()
    except FileNotFoundError:
        raise ConfigError(path, "", "no such file; check the path") from None
    except IsADirectoryError:
        raise ConfigError(path, "", "is a folder; give a .toml file (or the folder where a "
                                    "command takes folders)") from None
    except PermissionError as exc:
        raise ConfigError(path, "", f"cannot read the file ({exc.strerror}); check its "
                                    "permissions") from None
    except OSError as exc:
        raise ConfigError(path, "", f"cannot read the file ({exc.strerror or exc})") from None
    try:
        # a byte-order mark (some Windows editors write one) was refused as "Invalid
        # statement (line 1, column 1)"; CSV files already accepted it
        text = data.decode("utf-8-sig")
    except UnicodeDecodeError as exc:
        raise ConfigError(path, "", f"not UTF-8 text ({exc.reason} at byte {exc.start}); save it "
                                    "as UTF-8") from None
    return text


def _parse(text, name):
    if not isinstance(text, str):
        error = ConfigError(name, "", f"text must be a str of TOML, got {type(text).__name__}")
        error.parameter = "text"
        raise error
    try:
        return tomllib.loads(text.removeprefix("\ufeff"))
    except tomllib.TOMLDecodeError as exc:
        raise ConfigError(name, "", f"not valid TOML: {exc}; fix the syntax there") from None


def loads(text: str, name: str = "<string>") -> Engine:
    """The engine described by TOML ``text``; ``name`` stands for the file in messages and
    becomes the engine's ``config_path``."""
    if not isinstance(name, str):
        error = ConfigError("<string>", "", f"name must be a str, got {type(name).__name__}")
        error.parameter = "name"
        raise error
    return build(_parse(text, name), name)


def build(data: dict, path: str = "<config>", template: bool = False) -> Engine:
    """Build an engine from parsed TOML ``data`` (a dict), naming ``path`` in errors.

    A ``template`` (for ``balance search``) gives no throw phases and no firing order: its
    throws are built at phase 0."""
    top = _Reader(path, data, "", _TOP_KEYS)
    name = top.string("name")
    source = top.string("source", required=False, default="")
    cycle = top.integer("cycle")
    speed = top.quantity("speed", "angular speed")
    crank_radius = top.quantity("crank_radius", "length")
    rod_length = top.quantity("rod_length", "length")
    pin_offset = top.quantity("pin_offset", "length", required=False, default=0.0, sign="any")
    frame = top.string("frame", required=False, default="fixed", choices=FRAMES)
    vertical = math.radians(top.degrees("vertical")) if top.has("vertical") else None
    power = top.quantity("power", "power", required=False, default=None)

    parts = None
    if top.has("masses") and top.has("parts"):
        raise top.error("parts", "give [masses] (lumped point masses) or [parts] (part data), "
                                 "not both")
    if top.has("parts"):
        parts_reader = _Reader(path, data["parts"], "parts.", _PART_KEYS)
        parts = _read_parts(parts_reader, rod_length)
        missing_link_keys = [k for k in ("link_mass", "link_cg", "link_inertia")
                             if not parts_reader.has(k)]
        reciprocating, rotating, knuckle, crank = parts.piston_kg, 0.0, 0.0, parts.crank_kg
    else:
        if not top.has("masses"):
            raise top.error("masses", "missing; give [masses] (lumped point masses) or [parts] "
                                      "(part data)")
        masses = _Reader(path, data["masses"], "masses.", _MASS_KEYS)
        reciprocating = masses.quantity("reciprocating", "mass")
        rotating, knuckle, crank = (
            masses.quantity(key, "mass", required=False, default=0.0, sign="non-negative")
            for key in ("rotating", "knuckle", "crank"))
    gas = _read_gas(_Reader(path, data["gas"], "gas.", _GAS_KEYS)) if top.has("gas") else None

    banks, bank_offsets = [], []
    for i, table in enumerate(top.tables("banks"), 1):
        bank = _Reader(path, table, f"banks[{i}].", _BANK_KEYS)
        banks.append(math.radians(bank.degrees("angle")))
        bank_offsets.append(bank.quantity("pin_offset", "length", required=False, sign="any"))
    crankshafts = _read_crankshafts(path, data, top)
    throws = []
    for i, table in enumerate(top.tables("throws"), 1):
        throw = _Reader(path, table, f"throws[{i}].", _THROW_KEYS)
        if template and throw.has("phase"):
            raise throw.error("phase", "a search template gives only z for each throw (the "
                                       "search chooses the phases); remove phase")
        throws.append(Throw(0.0 if template else math.radians(throw.degrees("phase")),
                            throw.quantity("z", "length", required=False, default=0.0, sign="any"),
                            throw.integer("crankshaft", required=False, default=1, low=1,
                                          high=max(len(crankshafts), 1)) - 1))
    _check_crankshafts_used(path, crankshafts, throws)
    for i, offset in enumerate(bank_offsets, 1):
        # the model would name the cylinder; the file's key is the bank's
        if offset is not None and rod_length <= crank_radius + abs(offset):
            raise ConfigError(path, f"banks[{i}].pin_offset", f"({offset * 1000:g} mm) leaves the "
                              f"rod ({rod_length * 1000:g} mm) no longer than the crank radius plus "
                              "|pin offset|, so it cannot reach the cylinder axis; make the offset "
                              "smaller")

    links = None
    if top.has("links"):
        reader = _Reader(path, data["links"], "links.", _LINK_KEYS)
        links = {
            "master_bank": reader.integer("master_bank", low=1, high=len(banks)) - 1,
            "length": reader.quantity("length", "length"),
            "knuckle_radius": reader.quantity("knuckle_radius", "length"),
        }

    listed = top.has("cylinders")
    if listed:
        cylinders, keys = _listed_cylinders(path, top.tables("cylinders"), banks, throws,
                                            reciprocating, knuckle, links, bank_offsets)
    else:
        cylinders, keys = _grid_cylinders(banks, throws, reciprocating, knuckle, links), {}
        cylinders = [dataclasses.replace(c, pin_offset_m=bank_offsets[c.bank]) for c in cylinders]

    if parts is not None:
        cylinders, rotating = _lumped(path, parts, cylinders, rod_length, len(throws),
                                      missing_link_keys)

    firing_order = None
    if template and top.has("firing_order"):
        raise top.error("firing_order", "a search template has no firing order (the search "
                                        "chooses it); remove firing_order")
    if top.has("firing_order"):
        raw = data["firing_order"]
        if not isinstance(raw, list) or not all(
            isinstance(n, int) and not isinstance(n, bool) for n in raw
        ):
            raise top.error("firing_order", "expected a list of cylinder numbers such as [1, 3, 4, 2]")
        firing_order = tuple(raw)

    weights = _read_counterweights(top, path, throws, frame)
    shafts = _read_shafts(top, path, frame)

    try:
        engine = Engine(
            name=name, cycle=cycle, speed_rad_s=speed, crank_radius_m=crank_radius,
            rod_length_m=rod_length, bank_angles_rad=tuple(banks), throws=tuple(throws),
            cylinders=tuple(cylinders), rotating_kg=rotating, crank_kg=crank,
            pin_offset_m=pin_offset, frame=frame, firing_order=firing_order, source=source,
            config_path=str(path), parts=parts, gas=gas, vertical_rad=vertical, power_w=power,
            shaft_inertia_kgm2=(0.0 if parts is None else
                                parts.crankshaft_inertia_kgm2 + parts.flywheel_inertia_kgm2),
            crankshafts=tuple(crankshafts),
            counterweights=weights, balancer_shafts=shafts,
            torsion=(_read_torsion(_Reader(path, data["torsion"], "torsion.", _TORSION_KEYS),
                                   len(throws)) if top.has("torsion") else None),
        )
        check_assembly(engine)
    except ModelError as exc:
        raise _translated(path, exc, keys) from None
    return engine


def _read_crankshafts(path, data, top):
    """The [[crankshafts]]: the first is the reference, at the origin, turning forward at
    phase 0 (its keys may be left out); the others are placed, turned and phased against it."""
    if not top.has("crankshafts"):
        return []
    shafts = []
    for i, table in enumerate(top.tables("crankshafts"), 1):
        r = _Reader(path, table, f"crankshafts[{i}].", _CRANKSHAFT_KEYS)
        x = r.quantity("x", "length", required=False, default=0.0, sign="any")
        y = r.quantity("y", "length", required=False, default=0.0, sign="any")
        direction = r.integer("direction", required=False, default=1, low=-1, high=1)
        if direction == 0:
            raise r.error("direction", "must be 1 (turning with the first crankshaft) or -1 "
                                       "(against it), got 0")
        phase = r.degrees("phase", required=False) or 0.0
        shaft = Crankshaft(x, y, direction, math.radians(phase))
        if i == 1 and shaft != Crankshaft():
            changed = next(k for k in ("x", "y", "direction", "phase") if r.has(k))
            raise r.error(changed, "the first crankshaft is the reference (at x = y = 0, direction "
                                   "1, phase 0); place, turn and phase the others against it")
        shafts.append(shaft)
    return shafts


def _not_on_rotary(top, key, frame, what):
    if top.has(key) and frame == "rotary":
        raise top.error(key, f"cannot be given for a rotary engine: {what}, and a rotary's crank "
                             'stands still; remove the tables, or use frame = "fixed"')


def _unbalance(reader, radius_key):
    """m·ρ (kg·m) and ρ (m, or None) from ``mass`` with ``radius_key``, or ``mass_radius``."""
    if reader.has("mass_radius"):
        for key in ("mass", radius_key):
            if reader.has(key):
                raise reader.error(key, f"give mass with {radius_key}, or mass_radius, not both; "
                                        "remove one")
        return reader.quantity("mass_radius", "unbalance"), None
    if not reader.has("mass"):
        raise reader.error("mass", f'missing; give mass with {radius_key} ("1.2 kg", "60 mm"), '
                                   'or mass_radius ("0.072 kg*m")')
    mass = reader.quantity("mass", "mass")
    if not reader.has(radius_key):
        raise reader.error(radius_key, f"missing; a mass needs its {radius_key} (or give "
                                       "mass_radius instead of both)")
    radius = reader.quantity(radius_key, "length")
    return mass * radius, radius


def _built(reader, kind, **values):
    """A model object built from values read at ``reader``, its errors put in the file's keys."""
    try:
        return kind(**values)
    except ModelError as exc:
        key = {"mass_radius_kgm": "mass_radius", "angle_rad": "angle", "z_m": "z",
               "radius_m": "radius", "eccentricity_m": "eccentricity", "ratio": "ratio",
               "lateral_m": "lateral", "vertical_m": "vertical"}.get(exc.parameter, "")
        raise reader.error(key, exc.problem) from None


def _read_counterweights(top, path, throws, frame):
    """The [[counterweights]] as built: each on a throw, measured from its pin."""
    _not_on_rotary(top, "counterweights", frame, "a counterweight turns with the crank")
    weights = []
    for i, table in enumerate(top.tables("counterweights", required=False), 1):
        r = _Reader(path, table, f"counterweights[{i}].", _COUNTERWEIGHT_KEYS)
        throw = r.integer("throw", low=1, high=len(throws)) - 1
        mass_radius, radius = _unbalance(r, "radius")
        weights.append(_built(r, CounterweightMass, throw=throw, mass_radius_kgm=mass_radius,
                              angle_rad=math.radians(r.degrees("angle")),
                              z_m=r.quantity("z", "length", required=False, sign="any"),
                              radius_m=radius))
    return tuple(weights)


def _read_shafts(top, path, frame):
    """The [[shafts]] as built, each with its [[shafts.masses]]."""
    _not_on_rotary(top, "shafts", frame, "a balancer shaft is geared to a turning crank")
    shafts = []
    for i, table in enumerate(top.tables("shafts", required=False), 1):
        r = _Reader(path, table, f"shafts[{i}].", _SHAFT_KEYS)
        ratio = r.integer("ratio", low=-MAX_SHAFT_RATIO, high=MAX_SHAFT_RATIO)
        if ratio == 0:
            raise r.error("ratio", "must not be 0: give the shaft's turns per crank turn, such as "
                                   "2 (with the crank at twice its speed) or -2 (against it)")
        masses = []
        for j, entry in enumerate(r.tables("masses"), 1):
            m = _Reader(path, entry, f"shafts[{i}].masses[{j}].", _SHAFT_MASS_KEYS)
            mass_radius, eccentricity = _unbalance(m, "eccentricity")
            masses.append(_built(m, BalancerMass, mass_radius_kgm=mass_radius,
                                 angle_rad=math.radians(m.degrees("angle")),
                                 z_m=m.quantity("z", "length", required=False, sign="any"),
                                 eccentricity_m=eccentricity))
        shafts.append(_built(r, BalancerShaftSpec, ratio=ratio, masses=tuple(masses),
                             lateral_m=r.quantity("lateral", "length", required=False,
                                                  default=0.0, sign="any"),
                             vertical_m=r.quantity("vertical", "length", required=False,
                                                   default=0.0, sign="any")))
    return tuple(shafts)


def _check_crankshafts_used(path, crankshafts, throws):
    """Every crankshaft named carries a throw, and no two share an axis: said with the file's
    1-based keys (the model counts from 0)."""
    used = {t.crankshaft for t in throws}
    for k, shaft in enumerate(crankshafts):
        if k not in used:
            raise ConfigError(path, f"crankshafts[{k + 1}]", f"carries no throw; give it throws "
                              f"(crankshaft = {k + 1} in [[throws]]) or remove it")
        for j in range(k):
            if abs(shaft.centre - crankshafts[j].centre) < SAME_POSITION_M:
                raise ConfigError(path, f"crankshafts[{k + 1}]", f"shares its axis with "
                                  f"crankshafts[{j + 1}]; give it its own x and y")


def _read_parts(reader, rod_length):
    """The [parts] table; centres of gravity between the rod's ends."""
    inertia = "moment of inertia"
    parts = Parts(
        piston_kg=reader.quantity("piston", "mass"),
        rod_kg=reader.quantity("rod_mass", "mass"),
        rod_cg_m=reader.quantity("rod_cg", "length", sign="non-negative"),
        rod_inertia_kgm2=reader.quantity("rod_inertia", inertia, sign="non-negative"),
        link_kg=reader.quantity("link_mass", "mass", required=False, default=0.0),
        link_cg_m=reader.quantity("link_cg", "length", required=False, default=0.0,
                                  sign="non-negative"),
        link_inertia_kgm2=reader.quantity("link_inertia", inertia, required=False, default=0.0,
                                          sign="non-negative"),
        crank_kg=reader.quantity("crank", "mass", required=False, default=0.0, sign="non-negative"),
        crankshaft_inertia_kgm2=reader.quantity("crankshaft_inertia", inertia, required=False,
                                                default=0.0, sign="non-negative"),
        flywheel_inertia_kgm2=reader.quantity("flywheel_inertia", inertia, required=False,
                                              default=0.0, sign="non-negative"),
    )
    if parts.rod_cg_m > rod_length:
        raise reader.error("rod_cg", "lies beyond the small end: the centre of gravity is measured "
                                     "from the big end, between 0 and rod_length")
    return parts


def _lumped(path, parts, cylinders, rod_length, n_throws, missing_link_keys=()):
    """Lumped masses and rod corrections from part data, Fraeys de Veubeke § 8 (first
    reduction): the piston and the small-end share K·M of a plain or master rod reciprocate,
    its big-end share (1 − K)·M rotates with the pin; a link rod's shares k·m and (1 − k)·m go
    to its piston and its knuckle pin; what the two point masses leave out of each rod's
    rotational inertia stays with the rod as a correction C = J − M·H·(L − H)."""
    links = [c for c in cylinders if c.is_link]
    if links and missing_link_keys:
        raise ConfigError(path, f"parts.{missing_link_keys[0]}", "missing for the link rods; give "
                                                                "their link_mass, link_cg and link_inertia")
    lumped = []
    for c in cylinders:
        if c.is_link:
            if parts.link_cg_m > c.link_length_m:
                raise ConfigError(path, "parts.link_cg", f"lies beyond the link rod of cylinder "
                                  f"{c.number} ({c.link_length_m:g} m): it is measured from the knuckle pin")
            share = parts.link_cg_m / c.link_length_m
            lumped.append(dataclasses.replace(
                c, reciprocating_kg=parts.piston_kg + share * parts.link_kg,
                knuckle_kg=(1 - share) * parts.link_kg,
                rod_inertia_kgm2=parts.link_correction_kgm2(c.link_length_m)))
        else:
            piston = parts.piston_kg + parts.small_end_share(rod_length) * parts.rod_kg
            lumped.append(dataclasses.replace(
                c, reciprocating_kg=piston,
                opposed_reciprocating_kg=piston if c.is_opposed else None,
                rod_inertia_kgm2=parts.rod_correction_kgm2(rod_length)))
    rods = [sum((not c.is_link and c.throw == t) + (c.opposed_throw == t) for c in cylinders)
            for t in range(n_throws)]
    if len(set(rods)) > 1:
        raise ConfigError(path, "parts", f"the throws carry different numbers of plain or master "
                                         f"rods ({rods}); give [masses] for such an engine")
    big_ends = rods[0] * (1 - parts.small_end_share(rod_length)) * parts.rod_kg
    return lumped, big_ends


def _read_gas(reader):
    """The [gas] table: the bore and, for a parametric cycle, its compression ratio."""
    return GasCycle(
        bore_m=reader.quantity("bore", "length"),
        compression_ratio=reader.real("compression_ratio", low=1.01, high=100.0),
        imep_pa=reader.quantity("imep", "pressure", required=False, default=None),
        intake_pa=reader.quantity("intake_pressure", "pressure", required=False, default=1.0e5),
        crankcase_pa=reader.quantity("crankcase_pressure", "pressure", required=False,
                                     default=101325.0, sign="non-negative"),
        # n = 1 would make p·Vⁿ⁻¹ constant and the cycle's heat term vanish
        polytropic_exponent=reader.real("polytropic_exponent", required=False, default=1.32,
                                        low=1.01, high=1.67),
        combustion_start_deg=reader.real("combustion_start", required=False, default=-10.0,
                                         low=-90.0, high=90.0, what="a number of degrees"),
        combustion_duration_deg=reader.real("combustion_duration", required=False, default=50.0,
                                            low=1.0, high=180.0, what="a number of degrees"),
        wiebe_a=reader.real("wiebe_a", required=False, default=5.0, low=0.1, high=20.0),
        wiebe_m=reader.real("wiebe_m", required=False, default=2.0, low=0.0, high=10.0),
    )


def _per_throw(reader, key, dimension, count, sign="positive", required=True):
    """One value for every one of ``count`` items, or a list of exactly ``count`` values."""
    raw = reader.table.get(key)
    if raw is None:
        if required:
            raise reader.error(key, "missing; this key is required")
        return None
    if not isinstance(raw, list):
        return (reader.quantity(key, dimension, sign=sign),) * count
    if len(raw) != count:
        raise reader.error(key, f"has {len(raw)} values but needs {count} (or one value for all)")
    out = []
    for i, text in enumerate(raw, 1):
        item = _Reader(reader.path, {f"{key}[{i}]": text}, reader.prefix, {f"{key}[{i}]"})
        out.append(item.quantity(f"{key}[{i}]", dimension, sign=sign))
    return tuple(out)


def _read_disk(reader, default_name):
    return ShaftDisk(
        name=reader.string("name", required=False, default=default_name),
        inertia_kgm2=reader.quantity("inertia", "moment of inertia"),
        stiffness_nm_rad=reader.quantity("stiffness", "torsional stiffness"),
        damping_nms_rad=reader.quantity("damping", "torsional damping", required=False,
                                        default=0.0, sign="non-negative"))


def _read_torsion(reader, n_throws):
    """The [torsion] table: the crankshaft's inertias, stiffnesses and damping, free end
    first (see :class:`balance_cli.model.TorsionModel`)."""
    if reader.has("throw_inertia") and reader.has("web_inertia"):
        raise reader.error("web_inertia", "give throw_inertia (each throw's whole inertia) or "
                                          "web_inertia (added to the reduced mass), not both")
    if not reader.has("throw_inertia") and not reader.has("web_inertia"):
        raise reader.error("throw_inertia", "missing; give throw_inertia (e.g. \"0.05 kg*m^2\", "
                                            "or one per throw) or web_inertia")
    stiffness = ()
    if n_throws > 1:
        stiffness = _per_throw(reader, "stiffness", "torsional stiffness", n_throws - 1)
    elif reader.has("stiffness"):
        raise reader.error("stiffness", "a single throw has no sections between throws; "
                                        "remove stiffness")
    diameter = reader.quantity("shaft_diameter", "length", required=False)
    bore = reader.quantity("shaft_bore", "length", required=False, default=0.0,
                           sign="non-negative")
    if bore and diameter is None:
        raise reader.error("shaft_bore", "needs shaft_diameter too")
    if diameter is not None and bore >= diameter:
        raise reader.error("shaft_bore", f"must be smaller than shaft_diameter, got "
                                         f"{reader.table['shaft_bore']!r}")
    front = []
    if reader.has("front"):
        for i, table in enumerate(reader.tables("front"), 1):
            front.append(_read_disk(_Reader(reader.path, table, f"torsion.front[{i}].",
                                            _DISK_KEYS), f"front {i}"))
    ends = {}
    for key in ("flywheel", "load"):
        if reader.has(key):
            ends[key] = _read_disk(_Reader(reader.path, reader.table[key], f"torsion.{key}.",
                                           _DISK_KEYS), key)
    if "load" in ends and "flywheel" not in ends:
        raise reader.error("load", "needs a [torsion.flywheel] to hang on (the load is "
                                   "joined to the flywheel)")
    return TorsionModel(
        throw_inertia_kgm2=_per_throw(reader, "throw_inertia", "moment of inertia", n_throws,
                                      required=False),
        web_inertia_kgm2=reader.quantity("web_inertia", "moment of inertia", required=False,
                                         default=0.0, sign="non-negative"),
        stiffness_nm_rad=stiffness,
        throw_damping_nms_rad=_per_throw(reader, "throw_damping", "torsional damping", n_throws,
                                         sign="non-negative", required=False) or (0.0,) * n_throws,
        loss_factor=reader.real("loss_factor", required=False, default=0.0, low=0.0, high=2.0),
        front=tuple(front), flywheel=ends.get("flywheel"), load=ends.get("load"),
        shaft_diameter_m=diameter, shaft_bore_m=bore)


def _translated(path, exc, cylinder_keys):
    """A model error as a configuration error: the key it concerns, the file's key names."""
    problem = _FIELD.sub(lambda m: _KEYS[m.group(1)], exc.problem)
    if exc.parameter:
        key = _KEYS.get(exc.parameter, exc.parameter)
    else:
        key = cylinder_keys.get(exc.cylinder, "")
    return ConfigError(path, key, problem)


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


def _listed_cylinders(path, tables, banks, throws, reciprocating, knuckle, links, bank_offsets):
    """The complete list of [[cylinders]] with link rods given their defaults, and the key of
    each cylinder's table by number (for the model's messages)."""
    rows = []
    keys = {}
    for i, table in enumerate(tables, 1):
        r = _Reader(path, table, f"cylinders[{i}].", _CYLINDER_KEYS)
        number = r.integer("number", low=1, high=10_000)
        if number in keys:
            raise r.error("number", f"cylinder {number} is listed twice; give each a unique number")
        keys[number] = f"cylinders[{i}]"
        throw = r.integer("throw", low=1, high=len(throws)) - 1
        rows.append(dict(
            reader=r, number=number, bank=r.integer("bank", low=1, high=len(banks)) - 1,
            throw=throw,
            z=r.quantity("z", "length", required=False, default=throws[throw].z_m, sign="any"),
            reciprocating=r.quantity("reciprocating", "mass", required=False, default=reciprocating),
            master=r.integer("master", required=False),
            link_length=r.quantity("link_length", "length", required=False),
            knuckle_radius=r.quantity("knuckle_radius", "length", required=False),
            knuckle_angle=r.degrees("knuckle_angle", required=False),
            pin_offset=r.quantity("pin_offset", "length", required=False, sign="any"),
            opposed_throw=r.integer("opposed_throw", required=False, low=1, high=len(throws)),
            opposed_reciprocating=r.quantity("opposed_reciprocating", "mass", required=False),
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
            if master is None:
                raise r.error("master", f"names cylinder {row['master']}, which is not listed; "
                                        "give the number of the master-rod cylinder")
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
        if row["opposed_throw"] is not None:
            if row["master"] is not None:
                raise r.error("opposed_throw", "an opposed-piston cylinder has two plain rods; it "
                                               "cannot carry a link rod too (remove master or this)")
            fields.update(opposed_throw=row["opposed_throw"] - 1,
                          opposed_reciprocating_kg=(row["opposed_reciprocating"]
                                                    or row["reciprocating"]))
        elif row["opposed_reciprocating"] is not None:
            raise r.error("opposed_reciprocating", "belongs to an opposed-piston cylinder; give "
                                                   "its opposed_throw too, or remove the key")
        offset = row["pin_offset"] if row["pin_offset"] is not None else bank_offsets[row["bank"]]
        cylinders.append(Cylinder(row["number"], row["bank"], row["throw"], row["z"],
                                  row["reciprocating"], pin_offset_m=offset, **fields))
    return cylinders, keys


def find_configs(paths: "Iterable[str | os.PathLike[str]]") -> list[Path]:
    """Expand files and folders (recursively, sorted by path) into a list of .toml files.

    A path that does not exist is kept (reading it says so); a folder that cannot be read, or
    holds no .toml file, is a ConfigError.
    """
    if isinstance(paths, (str, os.PathLike)):
        paths = [paths]   # one path, not the characters of one
    try:
        paths = [checks.path(p, "paths") for p in paths]
    except TypeError:
        error = ConfigError("<paths>", "", f"paths must be a list of file or folder paths, got "
                                           f"{type(paths).__name__}")
        error.parameter = "paths"
        raise error from None
    found = []
    for p in map(Path, paths):
        if not p.is_dir():
            found.append(p)
            continue
        files = []

        def unreadable(exc, folder=p):
            raise ConfigError(exc.filename or folder, "", f"cannot read the folder "
                              f"({exc.strerror or exc}); check its permissions") from None

        if not os.access(p, os.R_OK | os.X_OK):
            unreadable(PermissionError(13, "Permission denied", str(p)))
        for folder, subfolders, names in os.walk(p, onerror=unreadable):
            subfolders.sort()
            files += [Path(folder) / n for n in names
                      if n.endswith(".toml") and (Path(folder) / n).is_file()]
        if not files:
            raise ConfigError(p, "", "no .toml configuration found in this folder")
        found += sorted(files)
    return found


def load_many(paths: "Iterable[str | os.PathLike[str]]") -> list[Engine]:
    """Load every configuration under ``paths`` (see :func:`find_configs`)."""
    return [load(f) for f in find_configs(paths)]


def arrangement_toml(template: dict, phases_deg: "Iterable[float]",
                     firing_order: "Iterable[int] | None",
                     name: str, header: str = "") -> str:
    """A complete configuration: the parsed ``template`` (see :func:`load_template`) with these
    throw phases (degrees, throw by throw), firing order (None: none, the most uniform one the
    crank allows is then found) and name; ``header`` becomes comment
    lines at the top. The template's comments are not kept (TOML readers drop them)."""
    data = dict(template)
    data["name"] = name
    phases = list(phases_deg)
    data["throws"] = [{"phase": p, **{k: v for k, v in t.items() if k != "phase"}}
                      for t, p in zip(template["throws"], phases, strict=True)]
    data.pop("firing_order", None)
    if firing_order is not None:
        data["firing_order"] = list(firing_order)
    return _dump(data, header)


def as_built_toml(data: dict, tables: dict, header: str = "") -> str:
    """A complete configuration: the parsed ``data`` of one (see :func:`load_data`) with the
    rows of ``tables`` (``{"counterweights": [...], "shafts": [...]}``, in the file's keys, as
    :meth:`balance_cli.analysis.counterweight.Balance.configuration_tables` gives them) added after its
    own ``[[counterweights]]`` and ``[[shafts]]``; ``header`` becomes comment lines at the top.
    The file's comments are not kept (TOML readers drop them)."""
    data = dict(data)
    for key, rows in tables.items():
        if rows:
            data[key] = list(data.get(key, [])) + list(rows)
    return _dump(data, header)


def _is_tables(value):
    return isinstance(value, list) and value and all(isinstance(v, dict) for v in value)


def _dump(data, header=""):
    """TOML text of parsed configuration ``data``: plain keys first, then its tables and arrays
    of tables (``[[shafts]]`` with their ``[[shafts.masses]]``)."""
    lines = [f"# {line}".rstrip() for line in header.splitlines()]
    lines += _table_lines(data, "")
    return "\n".join(lines) + "\n"


def _table_lines(table, prefix):
    lines, tables = [], []
    for key, value in table.items():
        if isinstance(value, dict):
            tables.append((key, [value], False))
        elif _is_tables(value):
            tables.append((key, value, True))
        else:
            lines.append(f"{key} = {_toml_value(value)}")
    for key, rows, array in tables:
        name = prefix + key
        for row in rows:
            lines += ["", f"[[{name}]]" if array else f"[{name}]"]
            lines += _table_lines(row, name + ".")
    return lines


def _toml_value(value):
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, (int, float)):
        return repr(value)
    if isinstance(value, str):
        escaped = value.replace("\\", "\\\\").replace('"', '\\"')
        return f'"{escaped}"'
    if isinstance(value, list):
        return "[" + ", ".join(_toml_value(v) for v in value) + "]"
    raise TypeError(f"no TOML form for {value!r}")
