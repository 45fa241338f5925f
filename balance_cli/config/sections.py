"""Readers of a configuration's sections beside its banks, throws and cylinders: the
crankshafts, the counterweights and balancer shafts as built, the part data (and the lumped
masses derived from it), the gas cycle, the shaft line's torsion model and the production
scatter of [tolerances]."""

import dataclasses
import math

from ..errors import ConfigError, ModelError
from ..model import (
    MAX_SHAFT_RATIO,
    BalancerMass,
    BalancerShaftSpec,
    CounterweightMass,
    Crankshaft,
    GasCycle,
    Parts,
    ShaftDisk,
    ToleranceBand,
    TorsionModel,
)
from ..tolerances import SAME_POSITION_M
from .reader import (
    COUNTERWEIGHT_KEYS,
    CRANKSHAFT_KEYS,
    DISK_KEYS,
    SHAFT_KEYS,
    SHAFT_MASS_KEYS,
    Reader,
)

__all__ = [
    "read_crankshafts",
    "check_crankshafts_used",
    "read_counterweights",
    "read_shafts",
    "read_parts",
    "lumped",
    "read_gas",
    "read_torsion",
    "read_tolerances",
]


def read_crankshafts(path, data, top):
    """The [[crankshafts]]: the first is the reference, at the origin, turning forward at
    phase 0 (its keys may be left out); the others are placed, turned and phased against it."""
    if not top.has("crankshafts"):
        return []
    shafts = []
    for i, table in enumerate(top.tables("crankshafts"), 1):
        r = Reader(path, table, f"crankshafts[{i}].", CRANKSHAFT_KEYS)
        x = r.quantity("x", "length", required=False, default=0.0, sign="any")
        y = r.quantity("y", "length", required=False, default=0.0, sign="any")
        direction = r.integer("direction", required=False, default=1, low=-1, high=1)
        if direction == 0:
            raise r.error(
                "direction",
                "must be 1 (turning with the first crankshaft) or -1 (against it), got 0",
            )
        phase = r.degrees("phase", required=False) or 0.0
        shaft = Crankshaft(x, y, direction, math.radians(phase))
        if i == 1 and shaft != Crankshaft():
            changed = next(k for k in ("x", "y", "direction", "phase") if r.has(k))
            raise r.error(
                changed,
                "the first crankshaft is the reference (at x = y = 0, direction "
                "1, phase 0); place, turn and phase the others against it",
            )
        shafts.append(shaft)
    return shafts


def _not_on_rotary(top, key, frame, what):
    if top.has(key) and frame == "rotary":
        raise top.error(
            key,
            f"cannot be given for a rotary engine: {what}, and a rotary's crank "
            'stands still; remove the tables, or use frame = "fixed"',
        )


def _unbalance(reader, radius_key):
    """m·ρ (kg·m) and ρ (m, or None) from ``mass`` with ``radius_key``, or ``mass_radius``."""
    if reader.has("mass_radius"):
        for key in ("mass", radius_key):
            if reader.has(key):
                raise reader.error(
                    key, f"give mass with {radius_key}, or mass_radius, not both; remove one"
                )
        return reader.quantity("mass_radius", "unbalance"), None
    if not reader.has("mass"):
        raise reader.error(
            "mass",
            f'missing; give mass with {radius_key} ("1.2 kg", "60 mm"), '
            'or mass_radius ("0.072 kg*m")',
        )
    mass = reader.quantity("mass", "mass")
    if not reader.has(radius_key):
        raise reader.error(
            radius_key,
            f"missing; a mass needs its {radius_key} (or give mass_radius instead of both)",
        )
    radius = reader.quantity(radius_key, "length")
    return mass * radius, radius


def _built(reader, kind, **values):
    """A model object built from values read at ``reader``, its errors put in the file's keys."""
    try:
        return kind(**values)
    except ModelError as exc:
        key = {
            "mass_radius_kgm": "mass_radius",
            "angle_rad": "angle",
            "z_m": "z",
            "radius_m": "radius",
            "eccentricity_m": "eccentricity",
            "ratio": "ratio",
            "lateral_m": "lateral",
            "vertical_m": "vertical",
        }.get(exc.parameter, "")
        raise reader.error(key, exc.problem) from None


def read_counterweights(top, path, throws, frame):
    """The [[counterweights]] as built: each on a throw, measured from its pin."""
    _not_on_rotary(top, "counterweights", frame, "a counterweight turns with the crank")
    weights = []
    for i, table in enumerate(top.tables("counterweights", required=False), 1):
        r = Reader(path, table, f"counterweights[{i}].", COUNTERWEIGHT_KEYS)
        throw = r.integer("throw", low=1, high=len(throws))
        mass_radius, radius = _unbalance(r, "radius")
        weights.append(
            _built(
                r,
                CounterweightMass,
                throw=throw,
                mass_radius_kgm=mass_radius,
                angle_rad=math.radians(r.degrees("angle")),
                z_m=r.quantity("z", "length", required=False, sign="any"),
                radius_m=radius,
            )
        )
    return tuple(weights)


def read_shafts(top, path, frame):
    """The [[shafts]] as built, each with its [[shafts.masses]]."""
    _not_on_rotary(top, "shafts", frame, "a balancer shaft is geared to a turning crank")
    shafts = []
    for i, table in enumerate(top.tables("shafts", required=False), 1):
        r = Reader(path, table, f"shafts[{i}].", SHAFT_KEYS)
        ratio = r.integer("ratio", low=-MAX_SHAFT_RATIO, high=MAX_SHAFT_RATIO)
        if ratio == 0:
            raise r.error(
                "ratio",
                "must not be 0: give the shaft's turns per crank turn, such as "
                "2 (with the crank at twice its speed) or -2 (against it)",
            )
        masses = []
        for j, entry in enumerate(r.tables("masses"), 1):
            m = Reader(path, entry, f"shafts[{i}].masses[{j}].", SHAFT_MASS_KEYS)
            mass_radius, eccentricity = _unbalance(m, "eccentricity")
            masses.append(
                _built(
                    m,
                    BalancerMass,
                    mass_radius_kgm=mass_radius,
                    angle_rad=math.radians(m.degrees("angle")),
                    z_m=m.quantity("z", "length", required=False, sign="any"),
                    eccentricity_m=eccentricity,
                )
            )
        shafts.append(
            _built(
                r,
                BalancerShaftSpec,
                ratio=ratio,
                masses=tuple(masses),
                lateral_m=r.quantity("lateral", "length", required=False, default=0.0, sign="any"),
                vertical_m=r.quantity(
                    "vertical", "length", required=False, default=0.0, sign="any"
                ),
            )
        )
    return tuple(shafts)


def check_crankshafts_used(path, crankshafts, throws):
    """Every crankshaft named carries a throw, and no two share an axis: said with the file's
    keys."""
    used = {t.crankshaft_index for t in throws}
    for k, shaft in enumerate(crankshafts):
        if k not in used:
            raise ConfigError(
                path,
                f"crankshafts[{k + 1}]",
                f"carries no throw; give it throws "
                f"(crankshaft = {k + 1} in [[throws]]) or remove it",
            )
        for j in range(k):
            if abs(shaft.centre - crankshafts[j].centre) < SAME_POSITION_M:
                raise ConfigError(
                    path,
                    f"crankshafts[{k + 1}]",
                    f"shares its axis with crankshafts[{j + 1}]; give it its own x and y",
                )


def read_parts(reader, rod_length):
    """The [parts] table; centres of gravity between the rod's ends."""
    inertia = "moment of inertia"
    parts = Parts(
        piston_kg=reader.quantity("piston", "mass"),
        rod_kg=reader.quantity("rod_mass", "mass"),
        rod_cg_m=reader.quantity("rod_cg", "length", sign="non-negative"),
        rod_inertia_kgm2=reader.quantity("rod_inertia", inertia, sign="non-negative"),
        link_kg=reader.quantity("link_mass", "mass", required=False, default=0.0),
        link_cg_m=reader.quantity(
            "link_cg", "length", required=False, default=0.0, sign="non-negative"
        ),
        link_inertia_kgm2=reader.quantity(
            "link_inertia", inertia, required=False, default=0.0, sign="non-negative"
        ),
        crank_kg=reader.quantity("crank", "mass", required=False, default=0.0, sign="non-negative"),
        crankshaft_inertia_kgm2=reader.quantity(
            "crankshaft_inertia", inertia, required=False, default=0.0, sign="non-negative"
        ),
        flywheel_inertia_kgm2=reader.quantity(
            "flywheel_inertia", inertia, required=False, default=0.0, sign="non-negative"
        ),
    )
    if parts.rod_cg_m > rod_length:
        raise reader.error(
            "rod_cg",
            "lies beyond the small end: the centre of gravity is measured "
            "from the big end, between 0 and rod_length",
        )
    return parts


def lumped(path, parts, cylinders, rod_length, n_throws, missing_link_keys=()):
    """Lumped masses and rod corrections from part data, Fraeys de Veubeke § 8 (first
    reduction): the piston and the small-end share K·M of a plain or master rod reciprocate,
    its big-end share (1 − K)·M rotates with the pin; a link rod's shares k·m and (1 − k)·m go
    to its piston and its knuckle pin; what the two point masses leave out of each rod's
    rotational inertia stays with the rod as a correction C = J − M·H·(L − H)."""
    links = [c for c in cylinders if c.is_link]
    if links and missing_link_keys:
        raise ConfigError(
            path,
            f"parts.{missing_link_keys[0]}",
            "missing for the link rods; give their link_mass, link_cg and link_inertia",
        )
    lumped = []
    for c in cylinders:
        if c.is_link:
            if parts.link_cg_m > c.link_length_m:
                raise ConfigError(
                    path,
                    "parts.link_cg",
                    f"lies beyond the link rod of cylinder "
                    f"{c.number} ({c.link_length_m:g} m): it is measured from the knuckle pin",
                )
            share = parts.link_cg_m / c.link_length_m
            lumped.append(
                dataclasses.replace(
                    c,
                    reciprocating_kg=parts.piston_kg + share * parts.link_kg,
                    knuckle_kg=(1 - share) * parts.link_kg,
                    rod_inertia_kgm2=parts.link_correction_kgm2(c.link_length_m),
                )
            )
        else:
            piston = parts.piston_kg + parts.small_end_share(rod_length) * parts.rod_kg
            lumped.append(
                dataclasses.replace(
                    c,
                    reciprocating_kg=piston,
                    opposed_reciprocating_kg=piston if c.is_opposed else None,
                    rod_inertia_kgm2=parts.rod_correction_kgm2(rod_length),
                )
            )
    rods = [
        sum((not c.is_link and c.throw == t) + (c.opposed_throw == t) for c in cylinders)
        for t in range(1, n_throws + 1)
    ]
    if len(set(rods)) > 1:
        raise ConfigError(
            path,
            "parts",
            f"the throws carry different numbers of plain or master "
            f"rods ({rods}); give [masses] for such an engine",
        )
    big_ends = rods[0] * (1 - parts.small_end_share(rod_length)) * parts.rod_kg
    return lumped, big_ends


def read_tolerances(reader):
    """The [tolerances] table: one standard deviation of each part's and dimension's normal
    scatter, masses and lengths with their units, angles in degrees (each key 0 by default)."""

    def sigma(key, dimension):
        return reader.quantity(key, dimension, required=False, default=0.0, sign="non-negative")

    def degrees(key):
        return math.radians(
            reader.real(key, required=False, default=0.0, low=0.0, high=90.0, what="degrees")
        )

    return ToleranceBand(
        reciprocating_kg=sigma("reciprocating", "mass"),
        rotating_kg=sigma("rotating", "mass"),
        crank_radius_m=sigma("crank_radius", "length"),
        rod_length_m=sigma("rod_length", "length"),
        phase_rad=degrees("phase"),
        bank_angle_rad=degrees("bank_angle"),
        pin_offset_m=sigma("pin_offset", "length"),
    )


def read_gas(reader):
    """The [gas] table: the bore and, for a parametric cycle, its compression ratio."""
    return GasCycle(
        bore_m=reader.quantity("bore", "length"),
        compression_ratio=reader.real("compression_ratio", low=1.01, high=100.0),
        imep_pa=reader.quantity("imep", "pressure", required=False, default=None),
        intake_pa=reader.quantity("intake_pressure", "pressure", required=False, default=1.0e5),
        crankcase_pa=reader.quantity(
            "crankcase_pressure", "pressure", required=False, default=101325.0, sign="non-negative"
        ),
        # n = 1 would make p·Vⁿ⁻¹ constant and the cycle's heat term vanish
        polytropic_exponent=reader.real(
            "polytropic_exponent", required=False, default=1.32, low=1.01, high=1.67
        ),
        combustion_start_deg=reader.real(
            "combustion_start",
            required=False,
            default=-10.0,
            low=-90.0,
            high=90.0,
            what="a number of degrees",
        ),
        combustion_duration_deg=reader.real(
            "combustion_duration",
            required=False,
            default=50.0,
            low=1.0,
            high=180.0,
            what="a number of degrees",
        ),
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
        item = Reader(reader.path, {f"{key}[{i}]": text}, reader.prefix, {f"{key}[{i}]"})
        out.append(item.quantity(f"{key}[{i}]", dimension, sign=sign))
    return tuple(out)


def _read_disk(reader, default_name):
    return ShaftDisk(
        name=reader.string("name", required=False, default=default_name),
        inertia_kgm2=reader.quantity("inertia", "moment of inertia"),
        stiffness_nm_rad=reader.quantity("stiffness", "torsional stiffness"),
        damping_nms_rad=reader.quantity(
            "damping", "torsional damping", required=False, default=0.0, sign="non-negative"
        ),
    )


def read_torsion(reader, n_throws):
    """The [torsion] table: the crankshaft's inertias, stiffnesses and damping, free end
    first (see :class:`balance_cli.model.TorsionModel`)."""
    if reader.has("throw_inertia") and reader.has("web_inertia"):
        raise reader.error(
            "web_inertia",
            "give throw_inertia (each throw's whole inertia) or "
            "web_inertia (added to the reduced mass), not both",
        )
    if not reader.has("throw_inertia") and not reader.has("web_inertia"):
        raise reader.error(
            "throw_inertia",
            'missing; give throw_inertia (e.g. "0.05 kg*m^2", or one per throw) or web_inertia',
        )
    stiffness = ()
    if n_throws > 1:
        stiffness = _per_throw(reader, "stiffness", "torsional stiffness", n_throws - 1)
    elif reader.has("stiffness"):
        raise reader.error(
            "stiffness", "a single throw has no sections between throws; remove stiffness"
        )
    diameter = reader.quantity("shaft_diameter", "length", required=False)
    bore = reader.quantity("shaft_bore", "length", required=False, default=0.0, sign="non-negative")
    if bore and diameter is None:
        raise reader.error("shaft_bore", "needs shaft_diameter too")
    if diameter is not None and bore >= diameter:
        raise reader.error(
            "shaft_bore", f"must be smaller than shaft_diameter, got {reader.table['shaft_bore']!r}"
        )
    front = []
    if reader.has("front"):
        for i, table in enumerate(reader.tables("front"), 1):
            front.append(
                _read_disk(
                    Reader(reader.path, table, f"torsion.front[{i}].", DISK_KEYS), f"front {i}"
                )
            )
    ends = {}
    for key in ("flywheel", "load"):
        if reader.has(key):
            ends[key] = _read_disk(
                Reader(reader.path, reader.table[key], f"torsion.{key}.", DISK_KEYS), key
            )
    if "load" in ends and "flywheel" not in ends:
        raise reader.error(
            "load", "needs a [torsion.flywheel] to hang on (the load is joined to the flywheel)"
        )
    return TorsionModel(
        throw_inertia_kgm2=_per_throw(
            reader, "throw_inertia", "moment of inertia", n_throws, required=False
        ),
        web_inertia_kgm2=reader.quantity(
            "web_inertia", "moment of inertia", required=False, default=0.0, sign="non-negative"
        ),
        stiffness_nm_rad=stiffness,
        throw_damping_nms_rad=_per_throw(
            reader,
            "throw_damping",
            "torsional damping",
            n_throws,
            sign="non-negative",
            required=False,
        )
        or (0.0,) * n_throws,
        loss_factor=reader.real("loss_factor", required=False, default=0.0, low=0.0, high=2.0),
        front=tuple(front),
        flywheel=ends.get("flywheel"),
        load=ends.get("load"),
        shaft_diameter_m=diameter,
        shaft_bore_m=bore,
    )
