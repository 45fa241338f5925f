"""The rules an :class:`~balance_cli.model.engine.Engine` must satisfy, whether built in code or
read from a file: the values, and how they relate to each other."""

import math
from typing import TYPE_CHECKING

from ..errors import ModelError
from ..tolerances import SAME_DIRECTION_RAD, SAME_POSITION_M
from .as_built import BalancerShaftSpec, CounterweightMass
from .crankshaft import REFERENCE_CRANKSHAFT, Crankshaft, Throw
from .cylinder import Cylinder
from .scatter import ToleranceBand
from .values import check_angle, check_quantity

if TYPE_CHECKING:
    from .engine import Engine

__all__ = ["check_engine", "FRAMES", "MAX_NAME_LENGTH", "OPPOSED_AXIS_TOLERANCE"]

#: "fixed": the crank turns in a fixed crankcase; "rotary": the crankcase and its cylinders
#: turn about a fixed crank
FRAMES = ("fixed", "rotary")
#: how far off the bore's axis (a fraction of the crankshafts' distance) an opposed piston's
#: crankshaft may lie
OPPOSED_AXIS_TOLERANCE = 1e-6
#: a name is shown in table cells and picture titles
MAX_NAME_LENGTH = 120


def check_engine(engine: "Engine") -> None:
    """Every rule an engine must satisfy, whether built in code or read from a file."""
    if (
        not isinstance(engine.name, str)
        or not engine.name.strip()
        or not engine.name.isprintable()
        or len(engine.name) > MAX_NAME_LENGTH
    ):
        raise ModelError(
            f"must be a non-empty line of printable text of at most {MAX_NAME_LENGTH} "
            f"characters, got {engine.name[:80]!r}"
            if isinstance(engine.name, str)
            else f"must be text, got {engine.name!r}",
            "name",
        )
    if (
        isinstance(engine.cycle, bool)
        or not isinstance(engine.cycle, int)
        or engine.cycle not in (2, 4)
    ):
        raise ModelError(f"must be 2 or 4 (strokes per cycle), got {engine.cycle!r}", "cycle")
    if engine.frame not in FRAMES:
        raise ModelError(f'must be "fixed" or "rotary", got {engine.frame!r}', "frame")
    check_quantity(engine.speed_rad_s, "angular speed", "speed_rad_s")
    check_quantity(engine.crank_radius_m, "length", "crank_radius_m")
    check_quantity(engine.rod_length_m, "length", "rod_length_m")
    check_quantity(engine.pin_offset_m, "length", "pin_offset_m", sign="any")
    check_quantity(engine.rotating_kg, "mass", "rotating_kg", sign="non-negative")
    check_quantity(engine.crank_kg, "mass", "crank_kg", sign="non-negative")
    check_quantity(
        engine.shaft_inertia_kgm2, "moment of inertia", "shaft_inertia_kgm2", sign="non-negative"
    )
    if engine.vertical_rad is not None:
        check_angle(engine.vertical_rad, "vertical_rad")
    if engine.power_w is not None:
        check_quantity(engine.power_w, "power", "power_w")
        check_quantity(engine.power_speed_rad_s, "angular speed", "power_speed_rad_s")
    if engine.rod_length_m <= engine.crank_radius_m + abs(engine.pin_offset_m):
        raise ModelError(
            f"of {engine.rod_length_m:g} m is not longer than the crank radius plus |pin offset| "
            f"({engine.crank_radius_m:g} m + {abs(engine.pin_offset_m):g} m), so the rod cannot "
            "reach the cylinder axis; make it longer or the crank shorter",
            "rod_length_m",
        )
    _check_crankshafts(engine)
    if not engine.bank_angles_rad:
        raise ModelError("needs at least one cylinder-axis direction", "bank_angles_rad")
    directions: list[float] = []
    for i, angle in enumerate(engine.bank_angles_rad):
        check_angle(angle, "bank_angles_rad")
        # two banks pointing the same way put two cylinders in every bore of a throw
        direction = math.remainder(angle, 2 * math.pi)
        for j, earlier in enumerate(directions):
            if abs(math.remainder(direction - earlier, 2 * math.pi)) < SAME_DIRECTION_RAD:
                raise ModelError(
                    f"{j + 1} and {i + 1} point the same way ({math.degrees(earlier):g}° "
                    f"and {math.degrees(angle):g}°); give each bank its own direction",
                    "bank_angles_rad",
                )
        directions.append(direction)
    if not engine.throws or not all(isinstance(t, Throw) for t in engine.throws):
        raise ModelError("needs one or more Throw objects", "throws")
    for i, throw in enumerate(engine.throws, 1):
        check_angle(throw.phase_rad, "throws")
        check_quantity(throw.z_m, "length", "throws", sign="any")
        if not throw.crankshaft <= len(engine.crankshafts):
            raise ModelError(
                f"throw {i} names crankshaft {throw.crankshaft}, but the engine "
                f"has crankshafts 1 to {len(engine.crankshafts)}; add the "
                "crankshaft or name another",
                "throws",
            )
    idle = sorted(
        set(range(1, len(engine.crankshafts) + 1)) - {t.crankshaft for t in engine.throws}
    )
    if idle:
        raise ModelError(
            f"crankshaft {idle[0]} carries no throw; give it throws or remove it", "crankshafts"
        )
    if not engine.cylinders or not all(isinstance(c, Cylinder) for c in engine.cylinders):
        raise ModelError("needs one or more Cylinder objects", "cylinders")
    numbers = [c.number for c in engine.cylinders]
    if len(set(numbers)) != len(numbers):
        twice = next(n for n in numbers if numbers.count(n) > 1)
        raise ModelError(
            f"cylinder {twice} is listed twice; give each a unique number", cylinder=twice
        )
    bores: dict[tuple[int, int, int], int] = {}  # (bank, throw, z step): cylinder number
    for c in engine.cylinders:
        _check_cylinder(engine, c)
        bore = (c.bank, c.throw, round(c.z_m / SAME_POSITION_M))
        if bore in bores:
            raise ModelError(
                f"cylinder {c.number} sits in the bore of cylinder {bores[bore]} (bank {c.bank}, "
                f"throw {c.throw}, same z); give it another bank, throw or axial position",
                cylinder=c.number,
            )
        bores[bore] = c.number
    for c in engine.cylinders:
        # an opposed bore seen from its far end: a cylinder of a bank pointing back along it,
        # on the opposed throw, would be a third piston in it
        if not c.is_opposed:
            continue
        back = engine.bank_angles_rad[c.bank_index] + math.pi
        for j, angle in enumerate(engine.bank_angles_rad, 1):
            if abs(math.remainder(angle - back, 2 * math.pi)) < SAME_DIRECTION_RAD:
                other = bores.get((j, c.opposed_throw, round(c.z_m / SAME_POSITION_M)))
                if other is not None:
                    raise ModelError(
                        f"cylinder {other} sits in the bore of cylinder {c.number}, whose opposed "
                        "piston comes from that end; give it another bank, throw or axial "
                        "position",
                        cylinder=other,
                    )
    _check_balancers(engine)
    if engine.tolerances is not None and not isinstance(engine.tolerances, ToleranceBand):
        raise ModelError(
            f"must be a ToleranceBand or None, got {type(engine.tolerances).__name__}",
            "tolerances",
        )
    if engine.torsion is not None and (engine.is_rotary or engine.has_several_crankshafts):
        raise ModelError(
            "is a shaft line of one turning crankshaft; this engine "
            + (
                "is a rotary (its crank stands still)"
                if engine.is_rotary
                else f"has {len(engine.crankshafts)} crankshafts"
            )
            + ": remove the [torsion] table",
            "torsion",
        )
    if engine.firing_order is not None:
        order = list(engine.firing_order)
        if not all(isinstance(n, int) and not isinstance(n, bool) for n in order) or sorted(
            order
        ) != sorted(numbers):
            raise ModelError(
                f"{order} is not a permutation of the cylinder numbers "
                f"{sorted(numbers)}; list every cylinder exactly once",
                "firing_order",
            )


def _check_balancers(engine):
    """Counterweights on existing throws, balancer shafts of the right types; neither on a
    rotary, whose crank stands still while its crankcase turns."""
    for name, kind in (
        ("counterweights", CounterweightMass),
        ("balancer_shafts", BalancerShaftSpec),
    ):
        items = getattr(engine, name)
        if not items:
            continue
        if not all(isinstance(item, kind) for item in items):
            raise ModelError(f"needs {kind.__name__} objects", name)
        if engine.is_rotary:
            what = (
                "a counterweight turns with the crank, and a rotary's crank stands still"
                if name == "counterweights"
                else "a balancer shaft is geared to a turning crank, and a rotary's crank stands "
                "still"
            )
            raise ModelError(
                f'cannot be given for a rotary engine: {what}; remove them, or use frame = "fixed"',
                name,
            )
    for i, weight in enumerate(engine.counterweights, 1):
        if not weight.throw <= len(engine.throws):
            raise ModelError(
                f"counterweight {i} is on throw {weight.throw}, but the engine has "
                f"throws 1 to {len(engine.throws)}; give one of them",
                "counterweights",
            )


def _check_crankshafts(engine):
    shafts = engine.crankshafts
    if not all(isinstance(s, Crankshaft) for s in shafts):
        raise ModelError("needs Crankshaft objects", "crankshafts")
    if shafts[0] != REFERENCE_CRANKSHAFT:
        raise ModelError(
            "must begin with the reference crankshaft (at the origin, turning "
            "forward, at phase 0); place and phase the others relative to it",
            "crankshafts",
        )
    if len(shafts) > 1 and engine.is_rotary:
        raise ModelError(
            "a rotary engine turns its crankcase about one fixed crank; give one "
            'crankshaft or frame = "fixed"',
            "crankshafts",
        )
    for i, shaft in enumerate(shafts):
        for j in range(i):
            if abs(shaft.centre - shafts[j].centre) < SAME_POSITION_M:
                raise ModelError(
                    f"crankshafts {j + 1} and {i + 1} share an axis; give each "
                    "crankshaft its own position",
                    "crankshafts",
                )


def _check_opposed(engine, c):
    """The second piston of an opposed-piston cylinder: on a throw of another crankshaft that
    lies on the cylinder's axis, far enough out that the two pistons never meet."""
    n = c.number
    if not 1 <= c.opposed_throw <= len(engine.throws):
        raise ModelError(
            f"cylinder {n}: opposed_throw {c.opposed_throw} is not one of the "
            f"engine's throws (1 to {len(engine.throws)})",
            cylinder=n,
        )
    own = engine.throws[c.throw_index].crankshaft_index
    other = engine.throws[c.opposed_throw_index].crankshaft_index
    if own == other:
        raise ModelError(
            f"cylinder {n}: its opposed throw is on the same crankshaft as its own "
            "throw; an opposed piston is driven by another crankshaft, at the other "
            "end of the bore",
            cylinder=n,
        )
    # the far piston runs in this bore, at its axial position: its throw must be there too
    # (as far off it as the near throw is, for rods set side by side)
    far_z, near_z = engine.throws[c.opposed_throw_index].z_m, engine.throws[c.throw_index].z_m
    if abs(far_z - c.z_m) > abs(near_z - c.z_m) + SAME_POSITION_M:
        raise ModelError(
            f"cylinder {n}: its opposed throw is at z = {far_z:g} m but the bore at "
            f"z = {c.z_m:g} m; the far piston runs in the same bore, so give its throw "
            "the bore's axial position",
            cylinder=n,
        )
    span = (engine.crankshafts[other].centre - engine.crankshafts[own].centre) * complex(
        math.cos(engine.bank_angles_rad[c.bank_index]),
        -math.sin(engine.bank_angles_rad[c.bank_index]),
    )
    # decimal inputs put a crankshaft on a slanted axis only to within rounding: a micrometre
    # a metre is accepted (the linkage then uses the exact line through the first crankshaft)
    if abs(span.imag) > max(SAME_POSITION_M, OPPOSED_AXIS_TOLERANCE * abs(span)):
        raise ModelError(
            f"cylinder {n}: crankshaft {other + 1} lies {abs(span.imag):g} m off the "
            f"axis of the cylinder's bank {c.bank}; an opposed piston's crankshaft "
            "must sit on the bore's axis, at the other end",
            cylinder=n,
        )
    reach = 2 * (engine.rod_length_m + engine.crank_radius_m)
    if span.real <= reach:
        where = "behind the first piston's crankshaft" if span.real <= 0 else "too close"
        raise ModelError(
            f"cylinder {n}: crankshaft {other + 1} is {span.real:g} m along the bore "
            f"({where}); the two pistons could meet unless the crankshafts are more "
            f"than 2·(rod_length + crank_radius) = {reach:g} m apart",
            cylinder=n,
        )


def _check_cylinder(engine, c):
    n = c.number
    if isinstance(n, bool) or not isinstance(n, int) or n < 1:
        raise ModelError(f"cylinder numbers are whole numbers from 1, got {n!r}", "cylinders")
    for number in (c.bank, c.throw):
        if isinstance(number, bool) or not isinstance(number, int):
            raise ModelError(
                f"cylinder {n}: bank and throw are whole numbers from 1, got {number!r}", cylinder=n
            )
    if not 1 <= c.bank <= len(engine.bank_angles_rad):
        raise ModelError(
            f"cylinder {n}: bank {c.bank} is not one of the engine's "
            f"{len(engine.bank_angles_rad)} banks (1 to "
            f"{len(engine.bank_angles_rad)})",
            cylinder=n,
        )
    if not 1 <= c.throw <= len(engine.throws):
        raise ModelError(
            f"cylinder {n}: throw {c.throw} is not one of the engine's "
            f"{len(engine.throws)} throws (1 to {len(engine.throws)})",
            cylinder=n,
        )
    check_quantity(c.z_m, "length", "z_m", sign="any", cylinder=n)
    check_quantity(c.reciprocating_kg, "mass", "reciprocating_kg", cylinder=n)
    check_quantity(
        c.rod_inertia_kgm2, "moment of inertia", "rod_inertia_kgm2", sign="any", cylinder=n
    )
    offset = engine.pin_offset_of(c)
    if c.pin_offset_m is not None and engine.rod_length_m <= engine.crank_radius_m + abs(offset):
        raise ModelError(
            f"cylinder {n}: its pin_offset_m ({offset:g} m) leaves the rod "
            f"({engine.rod_length_m:g} m) no longer than the crank radius plus "
            f"|pin offset|, so it cannot reach the cylinder axis; make the offset "
            "smaller",
            cylinder=n,
        )
    if c.is_opposed:
        _check_opposed(engine, c)
    if not c.is_link:
        return
    try:
        master = engine.cylinder(c.master)
    except KeyError:
        master = None
    if master is None or master is c:
        raise ModelError(
            f"cylinder {n}: its master {c.master} is not another cylinder; give the "
            "number of the master-rod cylinder",
            cylinder=n,
        )
    if master.is_link:
        raise ModelError(
            f"cylinder {n}: cylinder {c.master} has a link rod itself; a link rod "
            "must ride on a master rod",
            cylinder=n,
        )
    if master.is_opposed:
        raise ModelError(
            f"cylinder {n}: cylinder {c.master} is an opposed-piston cylinder, whose "
            "rods are plain; a link rod needs a master rod of its own",
            cylinder=n,
        )
    if master.throw != c.throw:
        raise ModelError(
            f"cylinder {n}: its master, cylinder {c.master}, is on throw "
            f"{master.throw} but this one on throw {c.throw}; a link rod rides "
            "on the master rod of its own throw",
            cylinder=n,
        )
    check_quantity(c.link_length_m, "length", "link_length_m", cylinder=n)
    check_quantity(c.knuckle_radius_m, "length", "knuckle_radius_m", cylinder=n)
    if c.knuckle_radius_m >= engine.rod_length_m:
        raise ModelError(
            f"cylinder {n}: knuckle_radius_m ({c.knuckle_radius_m:g} m) must be shorter "
            f"than the master rod (rod_length_m, {engine.rod_length_m:g} m): the knuckle "
            "pin sits on it",
            cylinder=n,
        )
    check_angle(c.knuckle_angle_rad, "knuckle_angle_rad", cylinder=n)
    check_quantity(c.knuckle_kg, "mass", "knuckle_kg", sign="non-negative", cylinder=n)
