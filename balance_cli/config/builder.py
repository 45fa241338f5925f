"""Building the :class:`~balance_cli.model.Engine` from a configuration's parsed TOML: its top
keys, banks, throws and links, its cylinders (a grid of banks by throws, or listed), the
optional sections, and the model's errors put in the file's key names."""

import dataclasses
import math
import re

from ..errors import ConfigError, ModelError
from ..kinematics.linkage import check_assembly
from ..model import FRAMES, Cylinder, Engine, Throw
from .mounts import read_mounts
from .provenance import read_provenance
from .reader import (
    BANK_KEYS,
    CYLINDER_KEYS,
    GAS_KEYS,
    LINK_KEYS,
    MASS_KEYS,
    PART_KEYS,
    THROW_KEYS,
    TOLERANCE_KEYS,
    TOP_KEYS,
    TORSION_KEYS,
    Reader,
)
from .sections import (
    check_crankshafts_used,
    lumped,
    read_counterweights,
    read_crankshafts,
    read_gas,
    read_parts,
    read_shafts,
    read_tolerances,
    read_torsion,
)

__all__ = ["build"]

#: model field -> configuration key, for the model's messages
_KEYS = {
    "speed_rad_s": "speed",
    "crank_radius_m": "crank_radius",
    "rod_length_m": "rod_length",
    "pin_offset_m": "pin_offset",
    "rotating_kg": "masses.rotating",
    "crank_kg": "masses.crank",
    "reciprocating_kg": "reciprocating",
    "knuckle_kg": "masses.knuckle",
    "link_length_m": "link_length",
    "knuckle_radius_m": "knuckle_radius",
    "knuckle_angle_rad": "knuckle_angle",
    "bank_angles_rad": "banks",
    "z_m": "z",
    "vertical_rad": "vertical",
    "power_w": "power",
    "crankshafts": "crankshafts",
    "opposed_throw": "opposed_throw",
    "opposed_reciprocating_kg": "opposed_reciprocating",
    "balancer_shafts": "shafts",
}
_FIELD = re.compile(r"\b(" + "|".join(map(re.escape, _KEYS)) + r")\b")


def build(data: dict, path: str = "<config>", template: bool = False) -> Engine:
    """Build an engine from parsed TOML ``data`` (a dict), naming ``path`` in errors.

    A ``template`` (for ``balance search``) gives no throw phases and no firing order: its
    throws are built at phase 0."""
    top = Reader(path, data, "", TOP_KEYS)
    name = top.string("name")
    source = top.string("source", required=False, default="")
    read_provenance(data, path)  # their form only: a template or a family drops keys they name
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
        raise top.error(
            "parts", "give [masses] (lumped point masses) or [parts] (part data), not both"
        )
    if top.has("parts"):
        parts_reader = Reader(path, data["parts"], "parts.", PART_KEYS)
        parts = read_parts(parts_reader, rod_length)
        missing_link_keys = [
            k for k in ("link_mass", "link_cg", "link_inertia") if not parts_reader.has(k)
        ]
        reciprocating, rotating, knuckle, crank = parts.piston_kg, 0.0, 0.0, parts.crank_kg
    else:
        if not top.has("masses"):
            raise top.error(
                "masses", "missing; give [masses] (lumped point masses) or [parts] (part data)"
            )
        masses = Reader(path, data["masses"], "masses.", MASS_KEYS)
        reciprocating = masses.quantity("reciprocating", "mass")
        rotating, knuckle, crank = (
            masses.quantity(key, "mass", required=False, default=0.0, sign="non-negative")
            for key in ("rotating", "knuckle", "crank")
        )
    gas = read_gas(Reader(path, data["gas"], "gas.", GAS_KEYS)) if top.has("gas") else None

    banks, bank_offsets = [], []
    for i, table in enumerate(top.tables("banks"), 1):
        bank = Reader(path, table, f"banks[{i}].", BANK_KEYS)
        banks.append(math.radians(bank.degrees("angle")))
        bank_offsets.append(bank.quantity("pin_offset", "length", required=False, sign="any"))
    crankshafts = read_crankshafts(path, data, top)
    throws = []
    for i, table in enumerate(top.tables("throws"), 1):
        throw = Reader(path, table, f"throws[{i}].", THROW_KEYS)
        if template and throw.has("phase"):
            raise throw.error(
                "phase",
                "a search template gives only z for each throw (the "
                "search chooses the phases); remove phase",
            )
        throws.append(
            Throw(
                0.0 if template else math.radians(throw.degrees("phase")),
                throw.quantity("z", "length", required=False, default=0.0, sign="any"),
                throw.integer(
                    "crankshaft", required=False, default=1, low=1, high=max(len(crankshafts), 1)
                ),
                throw.quantity("rotating", "mass", required=False, sign="non-negative"),
            )
        )
    check_crankshafts_used(path, crankshafts, throws)
    for i, offset in enumerate(bank_offsets, 1):
        # the model would name the cylinder; the file's key is the bank's
        if offset is not None and rod_length <= crank_radius + abs(offset):
            raise ConfigError(
                path,
                f"banks[{i}].pin_offset",
                f"({offset * 1000:g} mm) leaves the "
                f"rod ({rod_length * 1000:g} mm) no longer than the crank radius plus "
                "|pin offset|, so it cannot reach the cylinder axis; make the offset "
                "smaller",
            )

    links = None
    if top.has("links"):
        reader = Reader(path, data["links"], "links.", LINK_KEYS)
        links = {
            "master_bank": reader.integer("master_bank", low=1, high=len(banks)),
            "length": reader.quantity("length", "length"),
            "knuckle_radius": reader.quantity("knuckle_radius", "length"),
        }

    listed = top.has("cylinders")
    if listed:
        cylinders, keys = _listed_cylinders(
            path,
            top.tables("cylinders"),
            banks,
            throws,
            reciprocating,
            knuckle,
            links,
            bank_offsets,
        )
    else:
        cylinders, keys = _grid_cylinders(banks, throws, reciprocating, knuckle, links), {}
        cylinders = [
            dataclasses.replace(c, pin_offset_m=bank_offsets[c.bank_index]) for c in cylinders
        ]

    if parts is not None:
        cylinders, rotating = lumped(
            path, parts, cylinders, rod_length, len(throws), missing_link_keys
        )

    firing_order = None
    if template and top.has("firing_order"):
        raise top.error(
            "firing_order",
            "a search template has no firing order (the search chooses it); remove firing_order",
        )
    if top.has("firing_order"):
        raw = data["firing_order"]
        if not isinstance(raw, list) or not all(
            isinstance(n, int) and not isinstance(n, bool) for n in raw
        ):
            raise top.error(
                "firing_order", "expected a list of cylinder numbers such as [1, 3, 4, 2]"
            )
        firing_order = tuple(raw)

    weights = read_counterweights(top, path, throws, frame)
    shafts = read_shafts(top, path, frame)

    try:
        engine = Engine(
            name=name,
            cycle=cycle,
            speed_rad_s=speed,
            crank_radius_m=crank_radius,
            rod_length_m=rod_length,
            bank_angles_rad=tuple(banks),
            throws=tuple(throws),
            cylinders=tuple(cylinders),
            rotating_kg=rotating,
            crank_kg=crank,
            pin_offset_m=pin_offset,
            frame=frame,
            firing_order=firing_order,
            source=source,
            config_path=str(path),
            parts=parts,
            gas=gas,
            vertical_rad=vertical,
            power_w=power,
            shaft_inertia_kgm2=(
                0.0
                if parts is None
                else parts.crankshaft_inertia_kgm2 + parts.flywheel_inertia_kgm2
            ),
            crankshafts=tuple(crankshafts),
            counterweights=weights,
            balancer_shafts=shafts,
            torsion=(
                read_torsion(Reader(path, data["torsion"], "torsion.", TORSION_KEYS), len(throws))
                if top.has("torsion")
                else None
            ),
            mounts=read_mounts(path, data["mounts"]) if top.has("mounts") else None,
            tolerances=(
                read_tolerances(Reader(path, data["tolerances"], "tolerances.", TOLERANCE_KEYS))
                if top.has("tolerances")
                else None
            ),
        )
        check_assembly(engine)
    except ModelError as exc:
        raise _translated(path, exc, keys) from None
    return engine


def _translated(path, exc, cylinder_keys):
    """A model error as a configuration error: the key it concerns, the file's key names."""
    problem = _FIELD.sub(lambda m: _KEYS[m.group(1)], exc.problem)
    if exc.parameter:
        key = _KEYS.get(exc.parameter, exc.parameter)
    else:
        key = cylinder_keys.get(exc.cylinder, "")
    return ConfigError(path, key, problem)


def _link_fields(cylinder_bank, master_bank, banks, links, knuckle_mass):
    """A link rod's fields from [links], between banks numbered from 1."""
    return dict(
        link_length_m=links["length"],
        knuckle_radius_m=links["knuckle_radius"],
        knuckle_angle_rad=banks[cylinder_bank - 1] - banks[master_bank - 1],
        knuckle_kg=knuckle_mass,
    )


def _grid_cylinders(banks, throws, reciprocating, knuckle, links):
    """One cylinder per (bank, throw), numbered bank by bank."""
    cylinders = []
    for b in range(1, len(banks) + 1):
        for t, throw in enumerate(throws, 1):
            number = (b - 1) * len(throws) + t
            extra = {}
            if links and b != links["master_bank"]:
                extra = _link_fields(b, links["master_bank"], banks, links, knuckle)
                extra["master"] = (links["master_bank"] - 1) * len(throws) + t
            cylinders.append(Cylinder(number, b, t, throw.z_m, reciprocating, **extra))
    return cylinders


def _listed_cylinders(path, tables, banks, throws, reciprocating, knuckle, links, bank_offsets):
    """The complete list of [[cylinders]] with link rods given their defaults, and the key of
    each cylinder's table by number (for the model's messages)."""
    rows = []
    keys = {}
    for i, table in enumerate(tables, 1):
        r = Reader(path, table, f"cylinders[{i}].", CYLINDER_KEYS)
        number = r.integer("number", low=1, high=10_000)
        if number in keys:
            raise r.error("number", f"cylinder {number} is listed twice; give each a unique number")
        keys[number] = f"cylinders[{i}]"
        throw = r.integer("throw", low=1, high=len(throws))
        rows.append(
            dict(
                reader=r,
                number=number,
                bank=r.integer("bank", low=1, high=len(banks)),
                throw=throw,
                z=r.quantity(
                    "z", "length", required=False, default=throws[throw - 1].z_m, sign="any"
                ),
                reciprocating=r.quantity(
                    "reciprocating", "mass", required=False, default=reciprocating
                ),
                master=r.integer("master", required=False),
                link_length=r.quantity("link_length", "length", required=False),
                knuckle_radius=r.quantity("knuckle_radius", "length", required=False),
                knuckle_angle=r.degrees("knuckle_angle", required=False),
                pin_offset=r.quantity("pin_offset", "length", required=False, sign="any"),
                opposed_throw=r.integer("opposed_throw", required=False, low=1, high=len(throws)),
                opposed_reciprocating=r.quantity("opposed_reciprocating", "mass", required=False),
            )
        )
    by_number = {row["number"]: row for row in rows}
    if links:
        # [links]: every cylinder off the master bank that names no master rides on the
        # master-bank cylinder of its throw
        masters_by_throw = {
            row["throw"]: row["number"]
            for row in rows
            if row["bank"] == links["master_bank"] and row["master"] is None
        }
        for row in rows:
            if row["master"] is None and row["bank"] != links["master_bank"]:
                if row["throw"] not in masters_by_throw:
                    raise row["reader"].error(
                        "throw",
                        f"no cylinder of links.master_bank sits on throw {row['throw']} "
                        "to carry this link rod; add one or give this cylinder its own master",
                    )
                row["master"] = masters_by_throw[row["throw"]]
    cylinders = []
    for row in rows:
        r = row["reader"]
        fields = {}
        if row["master"] is not None:
            master = by_number.get(row["master"])
            if master is None:
                raise r.error(
                    "master",
                    f"names cylinder {row['master']}, which is not listed; "
                    "give the number of the master-rod cylinder",
                )
            defaults = links or {}
            length = row["link_length"] or defaults.get("length")
            radius = row["knuckle_radius"] or defaults.get("knuckle_radius")
            for key, value in (("link_length", length), ("knuckle_radius", radius)):
                if value is None:
                    raise r.error(key, "missing for a link rod; give it here or in [links]")
            angle = row["knuckle_angle"]
            fields = dict(
                master=row["master"],
                link_length_m=length,
                knuckle_radius_m=radius,
                knuckle_angle_rad=(
                    math.radians(angle)
                    if angle is not None
                    else banks[row["bank"] - 1] - banks[master["bank"] - 1]
                ),
                knuckle_kg=knuckle,
            )
        else:
            for key in ("link_length", "knuckle_radius", "knuckle_angle"):
                if row[key] is not None:
                    raise r.error(
                        key,
                        "only a link rod has this; give the cylinder a master "
                        "(or [links]) or remove the key",
                    )
        if row["opposed_throw"] is not None:
            if row["master"] is not None:
                raise r.error(
                    "opposed_throw",
                    "an opposed-piston cylinder has two plain rods; it "
                    "cannot carry a link rod too (remove master or this)",
                )
            fields.update(
                opposed_throw=row["opposed_throw"],
                opposed_reciprocating_kg=(row["opposed_reciprocating"] or row["reciprocating"]),
            )
        elif row["opposed_reciprocating"] is not None:
            raise r.error(
                "opposed_reciprocating",
                "belongs to an opposed-piston cylinder; give "
                "its opposed_throw too, or remove the key",
            )
        offset = (
            row["pin_offset"] if row["pin_offset"] is not None else bank_offsets[row["bank"] - 1]
        )
        cylinders.append(
            Cylinder(
                row["number"],
                row["bank"],
                row["throw"],
                row["z"],
                row["reciprocating"],
                pin_offset_m=offset,
                **fields,
            )
        )
    return cylinders, keys
