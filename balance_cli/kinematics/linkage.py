"""Closing an engine's linkage: exact positions of every lumped mass, at any crank angles.

No series: every position comes from closing the linkage triangle directly, so any
rod ratio, piston-pin offset and link-rod geometry is exact. An analysis reads the closed
linkage over a revolution from :mod:`balance_cli.kinematics.state`, which closes it once per
engine and sampling grid; this module closes it at whatever angles it is asked.

Masses (point masses, as in Tanaka 1925 and Fraeys de Veubeke 1949 §8):
- per cylinder, ``reciprocating_kg`` at its piston pin;
- per link rod, ``knuckle_kg`` at its knuckle pin on the master rod;
- per throw, ``rotating_kg`` (big ends: the throw's own, else the engine's) and ``crank_kg``
  (the crankshaft's own) at the crank pin;
- per counterweight as built, its unbalance turning with its throw;
- per balancer-shaft mass as built, its unbalance turning about the shaft's axis.
"""

from dataclasses import dataclass
from functools import lru_cache
from typing import NamedTuple

import numpy as np

from ..errors import ModelError
from ..units import round_degrees

__all__ = [
    "MassSet",
    "RodSet",
    "Linkage",
    "LinkageState",
    "close_linkage",
    "linkage_state",
    "pin_angle",
    "BIG_ENDS",
    "CRANK",
    "COUNTERWEIGHT",
    "BALANCER",
    "CRANKSHAFT_OWNERS",
    "UNKNOWN_RADIUS_M",
    "counterweight_angle",
    "balancer_positions",
    "crank_angles_of",
    "piston_travel",
    "check_assembly",
    "engine_angles",
]

#: owner codes of MassSet.cylinder for masses of no cylinder: big ends at a pin, the
#: crankshaft's own unbalance, counterweights as built, balancer-shaft masses
BIG_ENDS, CRANK, COUNTERWEIGHT, BALANCER = 0, -1, -2, -3
#: the owners whose masses are the crankshaft's (they load the main bearings, not the pins)
CRANKSHAFT_OWNERS = (CRANK, COUNTERWEIGHT)

#: where an unbalance given without its radius (``mass_radius`` alone) is placed, m: its forces
#: and moments depend on m·ρ only, and at a vanishing radius its moment of inertia m·ρ², which
#: cannot be known without ρ, stays out of the reduced mass (what is left, 1e-6·m·ρ·ratio²
#: kg·m², is far below any engine's)
UNKNOWN_RADIUS_M = 1e-6

#: crank angles at which a linkage is checked for assembly (0.1° apart)
_CHECK_SAMPLES = 3600


@dataclass(frozen=True)
class MassSet:
    """Point masses and their positions over the engine angles.

    Attributes
    ----------
    positions : ndarray, complex, shape (n_masses, n_angles)
        position in the fixed transverse plane, m (real: along the reference axis,
        imaginary: across it)
    masses_kg : ndarray, shape (n_masses,)
    z_m : ndarray, shape (n_masses,)
        axial position, m
    cylinder : ndarray of int, shape (n_masses,)
        number of the cylinder the mass belongs to; 0 for the big ends at a crank pin
        (``rotating_kg``), −1 for the crankshaft's own (``crank_kg``), −2 for a counterweight
        as built (:data:`COUNTERWEIGHT`), −3 for a balancer-shaft mass (:data:`BALANCER`)
    throw_index : ndarray of int, shape (n_masses,)
        where the throw the mass rides on stands in ``Engine.throws`` (0-based, for indexing;
        a counterweight: the throw it is measured from; −1 for a balancer-shaft mass)
    """

    positions: np.ndarray
    masses_kg: np.ndarray
    z_m: np.ndarray
    cylinder: np.ndarray
    throw_index: np.ndarray


@dataclass(frozen=True)
class RodSet:
    """Every rod's direction over the engine angles, with the rotational inertia its two point
    masses leave out.

    Attributes
    ----------
    directions : ndarray, complex, shape (n_rods, n_angles)
        unit vector from the rod's big end to its small end, in the fixed frame
    corrections_kgm2 : ndarray, shape (n_rods,)
        each rod's correcting moment of inertia (``Cylinder.rod_inertia_kgm2``), kg·m²
    cylinder : ndarray of int, shape (n_rods,)
        the cylinder whose rod it is (an opposed-piston cylinder has two)
    throw_index : ndarray of int, shape (n_rods,)
        where the throw the rod's big end rides on (its master's, for a link rod) stands in
        ``Engine.throws`` (0-based, for indexing)
    """

    directions: np.ndarray
    corrections_kgm2: np.ndarray
    cylinder: np.ndarray
    throw_index: np.ndarray


def engine_angles(samples):
    """``samples`` engine angles evenly spaced over one revolution, rad."""
    return 2.0 * np.pi * np.arange(samples) / samples


def _slider(point, axis_angle, length, offset, cylinder, crank_angles, centre=0j):
    """Piston pin on a cylinder axis through ``centre`` (its crank axis), joined by a rod of
    ``length`` to ``point``.

    Returns the pin position and the travel along the axis from ``centre`` (both exact). The squared
    half-chord ``length² − (offset − y)²`` must stay positive for the rod to reach the axis:
    where it does not, the linkage cannot be assembled and ModelError names the cylinder and
    the crank angle.
    """
    turn = np.exp(-1j * axis_angle)
    local = (point - centre if centre else point) * turn
    reach = length**2 - (offset - local.imag) ** 2
    if reach.size and reach.min() <= 0.0:
        _cannot_reach(cylinder, np.asarray(crank_angles).flat[int(np.argmin(reach))])
    travel = local.real + np.sqrt(reach)
    position = (travel + 1j * offset) / turn
    return (position + centre if centre else position), travel


def _cannot_reach(cylinder, crank_angle):
    where = f"{round_degrees(np.degrees(crank_angle), 1):.1f}°"
    if cylinder.is_link:
        raise ModelError(
            f"cylinder {cylinder.number}: its link rod cannot reach the cylinder axis "
            f"at crank angle {where}; make link_length_m longer or knuckle_radius_m "
            "smaller",
            cylinder=cylinder.number,
        )
    raise ModelError(
        f"cylinder {cylinder.number}: the rod cannot reach the cylinder axis at crank "
        f"angle {where}; rod_length_m must exceed crank_radius_m plus |pin_offset_m|",
        cylinder=cylinder.number,
    )


class Linkage(NamedTuple):
    """Points of the linkage in the crankcase frame, m (complex), keyed by cylinder number.

    ``travel`` is the piston pin's distance from its crank axis along its cylinder axis; for
    an opposed-piston cylinder, the two pistons' distances from their crank axes added (the
    bore closes as it grows: inner dead centre at its largest). ``knuckle`` exists for link
    rods only; ``opposed`` holds an opposed-piston cylinder's second piston as (position, its
    own travel); ``crank_pins`` is per throw (None for a throw no cylinder asked for rides on).
    """

    piston: dict
    travel: dict
    knuckle: dict
    crank_pins: list
    opposed: dict


def pin_angle(engine, index, crank_angles):
    """The direction of throw ``index``'s crank pin from its crankshaft's axis, rad from the
    reference axis, at crank angles ``crank_angles`` of the first crankshaft."""
    throw = engine.throws[index]
    shaft = engine.crankshafts[throw.crankshaft_index]
    return shaft.direction * (crank_angles + shaft.phase_rad + throw.phase_rad)


def counterweight_angle(engine, weight, crank_angles):
    """The direction of counterweight ``weight`` from its crankshaft's axis, rad from the
    reference axis: its throw's pin direction turned by its own angle, in the sense its
    crankshaft turns."""
    shaft = engine.crankshaft_of(weight.throw_index)
    return pin_angle(engine, weight.throw_index, crank_angles) + shaft.direction * weight.angle_rad


def _counterweight_rows(engine, crank_angles):
    """(position, mass, z, owner, throw) of every counterweight as built, in the crankcase's
    frame; an unbalance given without its radius at :data:`UNKNOWN_RADIUS_M`."""
    rows = []
    for weight in engine.counterweights:
        radius = UNKNOWN_RADIUS_M if weight.radius_m is None else weight.radius_m
        position = radius * np.exp(1j * counterweight_angle(engine, weight, crank_angles))
        centre = engine.crankshaft_of(weight.throw_index).centre
        rows.append(
            (
                position + centre if centre else position,
                weight.mass_radius_kgm / radius,
                engine.counterweight_z_m(weight),
                COUNTERWEIGHT,
                weight.throw_index,
            )
        )
    return rows


def balancer_positions(engine, shaft, angles):
    """Each mass of balancer ``shaft`` at engine angles ``angles``, in the fixed frame, m:
    centre + e·exp(i·s·(|ratio|·θ + angle)), s the sign of the ratio (its own sense of turning)."""
    centre = engine.balancer_centre(shaft)
    sign = 1 if shaft.ratio > 0 else -1
    out = []
    for mass in shaft.masses:
        e = UNKNOWN_RADIUS_M if mass.eccentricity_m is None else mass.eccentricity_m
        out.append(centre + e * np.exp(1j * sign * (abs(shaft.ratio) * angles + mass.angle_rad)))
    return out


def _balancer_rows(engine, angles):
    """(position, mass, z, owner, throw) of every balancer-shaft mass as built, fixed frame."""
    rows = []
    for shaft in engine.balancer_shafts:
        for mass, position in zip(
            shaft.masses, balancer_positions(engine, shaft, angles), strict=True
        ):
            e = UNKNOWN_RADIUS_M if mass.eccentricity_m is None else mass.eccentricity_m
            rows.append(
                (position, mass.mass_radius_kgm / e, engine.balancer_z_m(mass), BALANCER, -1)
            )
    return rows


def close_linkage(engine, crank_angles, numbers=None, pin_shift=None):
    """The exact linkage at crank angles ``crank_angles`` seen from the crankcase (any shape),
    of every cylinder or of those ``numbers`` (with the master rods they ride on).

    ``pin_shift`` ({throw index: complex offset in the crankcase frame, m}) moves crank pins
    off their circle: a virtual displacement, for the forces on the pins.
    """
    r = engine.crank_radius_m
    crank_angles = np.asarray(crank_angles, dtype=float)
    wanted = engine.cylinders if numbers is None else [engine.cylinder(n) for n in numbers]
    masters = {c.master for c in wanted if c.is_link}
    # only the pins the wanted cylinders ride on (None for the others): the TDC search asks
    # for one cylinder at a time
    throws = (
        {c.throw_index for c in wanted}
        | {c.opposed_throw_index for c in wanted if c.is_opposed}
        | set(pin_shift or {})
    )
    pins = [None] * len(engine.throws)
    for i in range(len(engine.throws)):
        if i in throws or numbers is None:
            pins[i] = r * np.exp(1j * pin_angle(engine, i, crank_angles))
            centre = engine.crankshaft_of(i).centre
            if centre:
                pins[i] = pins[i] + centre
    for index, shift in (pin_shift or {}).items():
        pins[index] = pins[index] + shift
    piston, travel, knuckle, opposed = {}, {}, {}, {}
    for cyl in engine.cylinders:
        if cyl.is_link or not (cyl in wanted or cyl.number in masters):
            continue
        axis = engine.bank_angles_rad[cyl.bank_index]
        shaft = engine.crankshaft_of(cyl.throw_index)
        # the offset is towards the crankshaft's own direction of rotation
        offset = shaft.direction * engine.pin_offset_of(cyl)
        piston[cyl.number], travel[cyl.number] = _slider(
            pins[cyl.throw_index],
            axis,
            engine.rod_length_m,
            offset,
            cyl,
            crank_angles,
            shaft.centre,
        )
        if cyl.is_opposed:
            # the same bore line seen from the other end: the axis turned half a turn; the
            # offset from that end is the far crankshaft's (tiny) distance off the axis less
            # this end's offset
            far = engine.crankshaft_of(cyl.opposed_throw_index).centre
            span = (far - shaft.centre) * np.exp(-1j * axis)
            position, own = _slider(
                pins[cyl.opposed_throw_index],
                axis + np.pi,
                engine.rod_length_m,
                span.imag - offset,
                cyl,
                crank_angles,
                far,
            )
            opposed[cyl.number] = (position, own)
            travel[cyl.number] = travel[cyl.number] + own
    for cyl in wanted:
        if not cyl.is_link:
            continue
        master = engine.cylinder(cyl.master)
        crank_pin = pins[master.throw_index]
        # the knuckle pin is fixed in the master rod: turn the rod's unit vector by the knuckle
        # angle
        rod_direction = (piston[master.number] - crank_pin) / engine.rod_length_m
        knuckle[cyl.number] = crank_pin + cyl.knuckle_radius_m * rod_direction * np.exp(
            1j * cyl.knuckle_angle_rad
        )
        axis = engine.bank_angles_rad[cyl.bank_index]
        shaft = engine.crankshaft_of(cyl.throw_index)
        piston[cyl.number], travel[cyl.number] = _slider(
            knuckle[cyl.number],
            axis,
            cyl.link_length_m,
            shaft.direction * engine.pin_offset_of(cyl),
            cyl,
            crank_angles,
            shaft.centre,
        )
    return Linkage(piston, travel, knuckle, pins, opposed)


def crank_angles_of(engine, angles):
    """Crank angle seen from the crankcase for engine angles ``angles``.

    In a rotary the crankcase turns forward about a fixed crank, so the crank turns
    backward relative to the cylinders.
    """
    return -angles if engine.is_rotary else angles


@lru_cache(maxsize=256)
def check_assembly(engine):
    """Raise :class:`ModelError` naming the first cylinder whose rod cannot reach its axis
    somewhere in a revolution. Every analysis calls it first (it is cached).

    A plain rod's crank pin sweeps the whole width ±r across its axis, so it reaches exactly
    when the rod is longer than r + |pin offset|, which the Engine checks when it is built. A
    link rod's knuckle pin follows no such simple path: checked here on a 0.1° grid.
    """
    links = [c.number for c in engine.cylinders if c.is_link]
    if links:
        close_linkage(engine, engine_angles(_CHECK_SAMPLES), links)
    _check_opposed_strokes(engine)


#: an opposed bore's volume must change by at least this fraction of the 4·r of two pistons
#: moved as mirror images: a lead of up to 120° keeps 4r·cos 60° = 2r
_OPPOSED_SWEEP = 0.5


def _check_opposed_strokes(engine):
    """An opposed bore whose two pistons move together (the far throw at 0° where 180° was
    meant) sweeps almost no volume: refused, naming the cylinder and the fix."""
    opposed = [c.number for c in engine.cylinders if c.is_opposed]
    if not opposed:
        return
    travel = close_linkage(engine, engine_angles(720), opposed).travel
    for n in opposed:
        sweep = float(np.ptp(travel[n]))
        if sweep < _OPPOSED_SWEEP * 4 * engine.crank_radius_m:
            raise ModelError(
                f"cylinder {n}: its two pistons move together (the bore's length changes by "
                f"{sweep * 1000:.3g} mm, against {4 * engine.crank_radius_m * 1000:.3g} mm for "
                "mirror images); a far throw at 180° in its crankshaft's own sense moves its "
                "piston as the mirror image of the near one (180° ± the lead)",
                cylinder=n,
            )


def piston_travel(engine, crank_angles, numbers=None, pin_shift=None):
    """Distance of every piston pin (or of those ``numbers``) from the crank axis along its
    cylinder axis, m.

    ``crank_angles`` are crank angles seen from the crankcase (any shape); returns a dict
    keyed by cylinder number. ``pin_shift`` moves crank pins (crankcase frame, see
    :func:`close_linkage`).
    """
    check_assembly(engine)
    return close_linkage(engine, crank_angles, numbers, pin_shift).travel


def _case_shift(engine, angles, pin_shift):
    """Pin offsets given in the fixed frame, seen from the (turning) crankcase of a rotary."""
    if not pin_shift or not engine.is_rotary:
        return pin_shift
    return {i: shift * np.exp(-1j * angles) for i, shift in pin_shift.items()}


class LinkageState(NamedTuple):
    """What one closing of the linkage gives: the point masses, the rods and the pistons'
    travel (by cylinder number, m; an opposed bore's two pistons added), at the same engine
    angles, and an opposed bore's far piston's own travel (by cylinder number, m)."""

    masses: MassSet
    rods: RodSet
    travel: dict
    opposed_travel: dict


def linkage_state(engine, angles, pin_shift=None, throw_index=None) -> LinkageState:
    """Masses, rods and travel at engine angles ``angles`` (any shape, rad; arrays gain that
    shape as trailing axes), in the fixed frame, with crank pins moved by ``pin_shift``
    (fixed-frame offsets by throw index, each broadcasting against ``angles``), from one
    closing of the linkage: the crank-pin forces shift every pin several times, and closing
    it once per shift for all three is what keeps ``balance torque`` fast.

    With ``throw_index`` (a throw's place in ``Engine.throws``), only what rides on that throw:
    its cylinders' masses and rods and the masses at its pin, in the order they have in the
    whole engine's state (no counterweight or balancer-shaft mass: they ride on no pin).
    """
    check_assembly(engine)
    angles = np.asarray(angles, dtype=float)
    chosen = (
        engine.cylinders
        if throw_index is None
        else [c for c in engine.cylinders if throw_index in (c.throw_index, c.opposed_throw_index)]
    )
    piston, travel, knuckle, pins, opposed = close_linkage(
        engine,
        crank_angles_of(engine, angles),
        None if throw_index is None else [c.number for c in chosen],
        _case_shift(engine, angles, pin_shift),
    )
    rows = []  # (position, mass, z, owner, throw)
    for cyl in chosen:
        rows.append(
            (piston[cyl.number], cyl.reciprocating_kg, cyl.z_m, cyl.number, cyl.throw_index)
        )
        if cyl.is_link and cyl.knuckle_kg:
            rows.append((knuckle[cyl.number], cyl.knuckle_kg, cyl.z_m, cyl.number, cyl.throw_index))
        if cyl.is_opposed:
            rows.append(
                (
                    opposed[cyl.number][0],
                    cyl.opposed_reciprocating_kg,
                    cyl.z_m,
                    cyl.number,
                    cyl.opposed_throw_index,
                )
            )
    for index, (crank, pin) in enumerate(zip(engine.throws, pins, strict=True)):
        if throw_index is not None and index != throw_index:
            continue
        for owner, mass in ((BIG_ENDS, engine.rotating_of(index)), (CRANK, engine.crank_kg)):
            if mass:
                rows.append((pin, mass, crank.z_m, owner, index))
    if throw_index is None:
        # after the pins: they turn with the crankshaft but ride on no pin (a shifted pin
        # leaves them where they are); neither exists on a rotary, so the frames agree
        rows += _counterweight_rows(engine, crank_angles_of(engine, angles))
        rows += _balancer_rows(engine, angles)
    rods, rod_rows = [], []  # unit vectors; (correction, cylinder, throw)
    for cyl in chosen:
        big_end = knuckle[cyl.number] if cyl.is_link else pins[cyl.throw_index]
        rod = piston[cyl.number] - big_end
        rods.append(rod / np.abs(rod))
        rod_rows.append((cyl.rod_inertia_kgm2, cyl.number, cyl.throw_index))
        if cyl.is_opposed:
            rod = opposed[cyl.number][0] - pins[cyl.opposed_throw_index]
            rods.append(rod / np.abs(rod))
            rod_rows.append((cyl.rod_inertia_kgm2, cyl.number, cyl.opposed_throw_index))
    positions = np.array([np.broadcast_to(row[0], angles.shape) for row in rows])
    directions = np.array(rods)
    if engine.is_rotary:
        # the linkage was closed in the crankcase's frame, which itself turns forward by the
        # engine angle: turn every position into the fixed frame the forces are wanted in
        turn = np.exp(1j * angles)
        positions, directions = positions * turn, directions * turn
    masses = MassSet(positions, *(np.array([row[i] for row in rows]) for i in range(1, 5)))
    rod_set = RodSet(directions, *(np.array([row[i] for row in rod_rows]) for i in range(3)))
    return LinkageState(masses, rod_set, travel, {n: own for n, (_, own) in opposed.items()})
