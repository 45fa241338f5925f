"""Balancer shafts: the shafts that cancel an order's force and couple, the moment an offset
shaft makes about the crank axis, and the shafts an engine has as built."""

import cmath
import numbers
from collections.abc import Mapping, Sequence

from ..errors import CounterweightError, UnitError
from ..model import offset_position
from ..units import check_finite_range, phasor_deg
from .balancing import BalancerShaft, Plane, RollingMoment, ShaftMass
from .planes import share

__all__ = [
    "built_shafts",
    "shafts_for",
    "rolling_moment_phasor",
    "offset_for",
    "checked_offsets",
    "build_shaft",
    "rolling_totals",
]


def built_shafts(engine) -> tuple:
    """The engine's balancer shafts as built, each as a :class:`BalancerShaft` with the force
    its masses make and its rolling moment about the crank axis (the same quantities a
    proposed shaft reports)."""
    out = []
    spin = engine.speed_rad_s**2
    for shaft in engine.balancer_shafts:
        sign = 1 if shaft.ratio > 0 else -1
        masses, force = [], 0j
        for mass in shaft.masses:
            # the mass is at e·exp(i·s·angle) when θ = 0: its force phasor points there
            phasor = (
                mass.mass_radius_kgm * shaft.ratio**2 * spin * cmath.exp(1j * sign * mass.angle_rad)
            )
            masses.append(
                ShaftMass(mass.mass_radius_kgm, phasor_deg(phasor), engine.balancer_z_m(mass))
            )
            force += phasor
        position = offset_position(shaft.lateral_m, shaft.vertical_m, engine.vertical_axis_rad)
        moment = RollingMoment.from_phasor(
            abs(shaft.ratio),
            rolling_moment_phasor(position, force, shaft.ratio),
            engine.noise_floor_nm,
        )
        out.append(
            BalancerShaft(
                shaft.ratio, tuple(masses), shaft.lateral_m, shaft.vertical_m, abs(force), moment
            )
        )
    return tuple(out)


def shafts_for(order, shaking, planes, engine):
    """Shafts cancelling order ``order``: per turning sense, one shaft carrying one mass at z̄
    when the part has no moment (with its counterpart: Lanchester's pair for a line force),
    else two masses apart, in the planes. Returns [(speed ratio, [(z, force phasor)])]."""
    o = shaking.order(order)
    floor = engine.noise_floor_n
    out = []
    for sign, force, moment in (
        (1, o.force_forward, o.moment_forward),
        (-1, o.force_backward, o.moment_backward),
    ):
        if abs(force) < floor and abs(moment) < engine.noise_floor_nm:
            continue
        if abs(moment) < engine.noise_floor_nm or len(planes) == 1:
            where = (Plane(engine.mean_z_m),)
            phasors = (-force,)
        else:
            where = planes
            phasors = share(-force, -moment, planes, engine.mean_z_m)
        masses = [
            (plane.z_m, phasor)
            for plane, phasor in zip(where, phasors, strict=True)
            if abs(phasor) >= floor
        ]
        if masses:
            out.append((sign * order, masses))
    return out


def rolling_moment_phasor(position, force, speed_ratio):
    """C with Re(C·e^{ikθ}) the moment about the crank axis of a force F(θ) = force·e^{±ikθ}
    (the sign of ``speed_ratio``) acting at ``position``: M = Im(x̄·F), the plane's x × F.

    Turning with the crank, Im(x̄·P·e^{ikθ}) = Re(−i·x̄·P·e^{ikθ}); against it,
    Im(x̄·P·e^{−ikθ}) = −Im(x·P̄·e^{ikθ}) = Re(i·x·P̄·e^{ikθ}).
    """
    if speed_ratio > 0:
        return -1j * position.conjugate() * force
    return 1j * position * force.conjugate()


def offset_for(speed_ratio, offsets):
    return offsets.get(speed_ratio, offsets.get(None, (0.0, 0.0)))


def checked_offsets(shaft_offsets_m, orders):
    """{speed ratio or None (every other shaft): (lateral, vertical) m} from a pair or a
    mapping; ratios must belong to the orders asked for."""
    if shaft_offsets_m is None:
        return {}
    if not orders:
        raise CounterweightError(
            "places balancer shafts, but no shaft order was asked for", "shaft_offsets_m"
        )
    items = (
        shaft_offsets_m.items()
        if isinstance(shaft_offsets_m, Mapping)
        else [(None, shaft_offsets_m)]
    )
    checked = {}
    for ratio, pair in items:
        if ratio is not None:
            if (
                isinstance(ratio, bool)
                or not isinstance(ratio, numbers.Integral)
                or abs(int(ratio)) not in orders
            ):
                raise CounterweightError(
                    f"names speed ratio {ratio!r}, but shafts are made for orders "
                    f"{', '.join(map(str, orders))} only (ratios ±k, + with the crank)",
                    "shaft_offsets_m",
                )
            ratio = int(ratio)
        if isinstance(pair, (str, bytes)) or not isinstance(pair, Sequence) or len(pair) != 2:
            raise CounterweightError(
                f"takes (lateral, vertical) pairs in metres, got {pair!r}", "shaft_offsets_m"
            )
        values = []
        for value in pair:
            if isinstance(value, bool) or not isinstance(value, numbers.Real):
                raise CounterweightError(
                    f"takes lengths in metres, got {value!r}", "shaft_offsets_m"
                )
            try:
                check_finite_range(float(value), "length", smallest=False)
            except UnitError as exc:
                raise CounterweightError(
                    f"has an offset that is invalid: {exc}", "shaft_offsets_m"
                ) from None
            values.append(float(value) + 0.0)  # not -0
        checked[ratio] = tuple(values)
    return checked


def build_shaft(engine, speed_ratio, masses, offset):
    """A BalancerShaft of force phasors at axial positions, with its rolling moment; and that
    moment's phasor before the noise is cut, for the totals."""
    order = abs(speed_ratio)
    spin = (order * engine.speed_rad_s) ** 2
    parts = tuple(ShaftMass(abs(p) / spin, phasor_deg(p), z) for z, p in masses)
    force = sum((p for _, p in masses), 0j)
    position = offset_position(offset[0], offset[1], engine.vertical_axis_rad)
    phasor = rolling_moment_phasor(position, force, speed_ratio)
    moment = RollingMoment.from_phasor(order, phasor, engine.noise_floor_nm)
    return BalancerShaft(speed_ratio, parts, offset[0], offset[1], abs(force), moment), phasor


def rolling_totals(engine, shafts, phasors):
    """Per order, the rolling moment of all its shafts together (a pair's couple)."""
    totals = []
    for order in sorted({s.order for s in shafts}):
        mine = [(s, p) for s, p in zip(shafts, phasors, strict=True) if s.order == order]
        totals.append(
            RollingMoment.from_phasor(
                order,
                sum((p for _, p in mine), 0j),
                engine.noise_floor_nm,
                tuple(s.speed_ratio for s, _ in mine),
            )
        )
    return tuple(totals)
