"""Counterweights, balancer shafts, the antivibrateur and balancing-machine test masses.

Everything works on the phasors of the shaking analysis: a mass m at radius ρ turning with
the crank at angle φ (measured like a throw phase) adds m·ρ·ω²·e^{iφ} to the forward
first-order force and (z − z̄) times that to the free moment. A balancer shaft of order k adds
m·e·(kω)²·e^{iφ} to the forward (or, counter-rotating, the backward) part of order k.

A shaft whose axis sits off the crank axis, at x in the transverse plane, leaves the free
force and the pitching and yawing moments as they are (those depend on z only), but its force
F(θ) acting at x turns the engine about the crank axis: the rolling moment x × F = Im(x̄·F).
"""

import cmath
import math
import numbers
from collections.abc import Mapping, Sequence
from dataclasses import dataclass

import numpy as np

from .. import checks
from ..errors import CounterweightError, UnitError
from ..kinematics import BALANCER, BIG_ENDS, COUNTERWEIGHT, check_assembly
from ..model import Engine, offset_position
from ..tolerances import SAME_POSITION_M
from ..units import check_finite_range, phasor_deg
from .balancing import (Antivibrateur, Balance, BalancerShaft, Counterweight, Plane,
                        RollingMoment, Shaft, ShaftMass, positive_length)
from .firing import firing_sequence
from .shaking import DEFAULT_MAX_ORDER, DEFAULT_SAMPLES, Shaking, shaking_forces

__all__ = ["counterweights", "check_options", "plane_at_throw", "plane_at",
           "rolling_moment_phasor", "built_shafts"]

#: the balance factor is a fraction of the reciprocating masses
_BALANCE_FACTOR_RANGE = (0.0, 1.0)


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
            phasor = mass.mass_radius_kgm * shaft.ratio**2 * spin * cmath.exp(1j * sign * mass.angle_rad)
            masses.append(ShaftMass(mass.mass_radius_kgm, phasor_deg(phasor),
                                    engine.balancer_z_m(mass)))
            force += phasor
        position = offset_position(shaft.lateral_m, shaft.vertical_m, engine.vertical_axis_rad)
        moment = RollingMoment.from_phasor(abs(shaft.ratio),
                                           rolling_moment_phasor(position, force, shaft.ratio),
                                           engine.noise_floor_nm)
        out.append(BalancerShaft(shaft.ratio, tuple(masses), shaft.lateral_m, shaft.vertical_m,
                                 abs(force), moment))
    return tuple(out)


def plane_at_throw(engine, number) -> Plane:
    """The plane of throw ``number`` (1-based)."""
    if isinstance(number, bool) or not isinstance(number, numbers.Integral) \
            or not 1 <= int(number) <= len(engine.throws):
        raise CounterweightError(f"names throw {number!r}, but the engine has throws 1 to "
                                 f"{len(engine.throws)}; give throw numbers or axial positions",
                                 "planes")
    return Plane(engine.throws[number - 1].z_m, int(number))


def plane_at(engine, z_m) -> Plane:
    """A plane at an axial position, m; on a throw if one sits there."""
    try:
        check_finite_range(float(z_m), "length", smallest=False)
    except UnitError as exc:
        raise CounterweightError(f"has an axial position that is invalid: {exc}", "planes") from None
    for i, throw in enumerate(engine.throws, 1):
        if math.isclose(throw.z_m, z_m, abs_tol=SAME_POSITION_M):
            return Plane(throw.z_m, i)
    return Plane(float(z_m), None)


def _plane(engine, spec):
    """A plane from a throw number, or a :class:`Plane` (one at an axial position is on the
    throw that sits there, if any)."""
    if isinstance(spec, Plane):
        return spec if spec.throw is not None else plane_at(engine, spec.z_m)
    if isinstance(spec, numbers.Integral) and not isinstance(spec, bool):
        return plane_at_throw(engine, spec)
    raise CounterweightError(f"takes throw numbers (int, from 1) or Plane objects (Plane(z_m) for "
                             f"an axial position in metres), got {spec!r}", "planes")


def default_planes(engine):
    """The first and last throws, or one plane where every throw sits at one position."""
    first, last = plane_at_throw(engine, 1), plane_at_throw(engine, len(engine.throws))
    return (first,) if math.isclose(first.z_m, last.z_m, abs_tol=SAME_POSITION_M) else (first, last)


def _checked_planes(engine, planes):
    if planes is None:
        return default_planes(engine)
    planes = tuple(_plane(engine, p) for p in planes)
    if not 1 <= len(planes) <= 2:
        raise CounterweightError(f"takes one plane (force only) or two (force and moment), got "
                                 f"{len(planes)}", "planes")
    if len(planes) == 2 and math.isclose(planes[0].z_m, planes[1].z_m, abs_tol=SAME_POSITION_M):
        raise CounterweightError("coincide; choose two planes apart, or give one", "planes")
    return planes


def _share(force, moment, planes, z_mean):
    """Phasors in each plane that add up to ``force`` and, with two planes, ``moment``.

    Two planes at a = z_A − z̄, b = z_B − z̄: c_A + c_B = F and a·c_A + b·c_B = M.
    """
    if len(planes) == 1:
        return (force,)
    a, b = planes[0].z_m - z_mean, planes[1].z_m - z_mean
    first = (moment - b * force) / (a - b)
    return (first, force - first)


def _rotating_target(engine, factor, pin_kg=0.0):
    """Forward first-order force and moment (N, N·m) of the classic per-throw counterweights:
    rotating, crank and knuckle masses (and ``pin_kg`` more on every pin: an antivibrateur's)
    plus ``factor`` times the reciprocating ones, opposite each throw at crank radius."""
    force = moment = 0j
    for index, throw in enumerate(engine.throws):
        on_throw = [c for c in engine.cylinders if c.throw_index == index]
        mass = (engine.rotating_kg + engine.crank_kg + pin_kg + sum(c.knuckle_kg for c in on_throw)
                + factor * sum(c.reciprocating_kg for c in on_throw))
        phasor = -mass * engine.crank_radius_m * engine.speed_rad_s**2 * cmath.exp(1j * throw.phase_rad)
        force += phasor
        moment += (throw.z_m - engine.mean_z_m) * phasor
    return force, moment


def _built_first_order(engine, shaking):
    """Forward first-order force and moment (N, N·m) of the counterweights and balancer shafts
    as built (a shaft turning with the crank at its speed, ratio +1, makes a forward first
    order as a counterweight does), read off the engine's own analysis (their rows of the
    point masses)."""
    if not engine.counterweights and not any(s.ratio == 1 for s in engine.balancer_shafts):
        return 0j, 0j
    mine = np.isin(shaking.masses.cylinder, (COUNTERWEIGHT, BALANCER))
    forces = shaking.mass_coefficients[mine, 1]
    levers = shaking.masses.z_m[mine] - engine.mean_z_m
    return complex(forces.sum()), complex((levers * forces).sum())


def _antivibrateur(engine, shaking, eccentricity):
    """Size the rotor to cancel the forward second order exactly; return it and its phasors."""
    second = shaking.order(2).force_forward
    omega = engine.speed_rad_s
    me = abs(second) / (4 * omega**2)
    rotor = Antivibrateur(me, eccentricity, phasor_deg(-second))
    # its mass also rides on the crank pin: a forward first order like a rotating mass
    pin = rotor.mass_kg * engine.crank_radius_m * omega**2 * cmath.exp(1j * engine.throws[0].phase_rad)
    return rotor, -second, pin


def _shafts_for(order, shaking, planes, engine):
    """Shafts cancelling order ``order``: per turning sense, one shaft carrying one mass at z̄
    when the part has no moment (with its counterpart: Lanchester's pair for a line force),
    else two masses apart, in the planes. Returns [(speed ratio, [(z, force phasor)])]."""
    o = shaking.order(order)
    floor = engine.noise_floor_n
    out = []
    for sign, force, moment in ((1, o.force_forward, o.moment_forward),
                                (-1, o.force_backward, o.moment_backward)):
        if abs(force) < floor and abs(moment) < engine.noise_floor_nm:
            continue
        if abs(moment) < engine.noise_floor_nm or len(planes) == 1:
            where = (Plane(engine.mean_z_m),)
            phasors = (-force,)
        else:
            where = planes
            phasors = _share(-force, -moment, planes, engine.mean_z_m)
        masses = [(plane.z_m, phasor) for plane, phasor in zip(where, phasors) if abs(phasor) >= floor]
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


def _offset_for(speed_ratio, offsets):
    return offsets.get(speed_ratio, offsets.get(None, (0.0, 0.0)))


def _checked_offsets(shaft_offsets_m, orders):
    """{speed ratio or None (every other shaft): (lateral, vertical) m} from a pair or a
    mapping; ratios must belong to the orders asked for."""
    if shaft_offsets_m is None:
        return {}
    if not orders:
        raise CounterweightError("places balancer shafts, but no shaft order was asked for",
                                 "shaft_offsets_m")
    items = shaft_offsets_m.items() if isinstance(shaft_offsets_m, Mapping) else [(None, shaft_offsets_m)]
    checked = {}
    for ratio, pair in items:
        if ratio is not None:
            if isinstance(ratio, bool) or not isinstance(ratio, numbers.Integral) \
                    or abs(int(ratio)) not in orders:
                raise CounterweightError(
                    f"names speed ratio {ratio!r}, but shafts are made for orders "
                    f"{', '.join(map(str, orders))} only (ratios ±k, + with the crank)",
                    "shaft_offsets_m")
            ratio = int(ratio)
        if isinstance(pair, (str, bytes)) or not isinstance(pair, Sequence) or len(pair) != 2:
            raise CounterweightError(f"takes (lateral, vertical) pairs in metres, got {pair!r}",
                                     "shaft_offsets_m")
        values = []
        for value in pair:
            if isinstance(value, bool) or not isinstance(value, numbers.Real):
                raise CounterweightError(f"takes lengths in metres, got {value!r}", "shaft_offsets_m")
            try:
                check_finite_range(float(value), "length", smallest=False)
            except UnitError as exc:
                raise CounterweightError(f"has an offset that is invalid: {exc}",
                                         "shaft_offsets_m") from None
            values.append(float(value) + 0.0)   # not -0
        checked[ratio] = tuple(values)
    return checked


def _build_shaft(engine, speed_ratio, masses, offset):
    """A BalancerShaft of force phasors at axial positions, with its rolling moment; and that
    moment's phasor before the noise is cut, for the totals."""
    order = abs(speed_ratio)
    spin = (order * engine.speed_rad_s) ** 2
    parts = tuple(ShaftMass(abs(p) / spin, phasor_deg(p), z) for z, p in masses)
    force = sum((p for _, p in masses), 0j)
    position = offset_position(*offset, engine.vertical_axis_rad)
    phasor = rolling_moment_phasor(position, force, speed_ratio)
    moment = RollingMoment.from_phasor(order, phasor, engine.noise_floor_nm)
    return BalancerShaft(speed_ratio, parts, offset[0], offset[1], abs(force), moment), phasor


def _rolling_totals(engine, shafts, phasors):
    """Per order, the rolling moment of all its shafts together (a pair's couple)."""
    totals = []
    for order in sorted({s.order for s in shafts}):
        mine = [(s, p) for s, p in zip(shafts, phasors) if s.order == order]
        totals.append(RollingMoment.from_phasor(order, sum((p for _, p in mine), 0j),
                                                engine.noise_floor_nm,
                                                tuple(s.speed_ratio for s, _ in mine)))
    return tuple(totals)


def _test_masses(engine, shaking):
    """Mass to hang on each crank pin so that the counterweighted shaft balances on a machine:
    the forward first order of everything on the throw but the crankshaft itself, as a mass
    at crank radius (Nakanishi § 4)."""
    coefficients, masses = shaking.mass_coefficients, shaking.masses
    unit = engine.crank_radius_m * engine.speed_rad_s**2
    out = []
    for index, throw in enumerate(engine.throws):
        # the crankshaft's own unbalance and its counterweights stay on the machine
        mine = (masses.throw_index == index) & (masses.cylinder >= BIG_ENDS)
        forward = coefficients[mine, 1].sum()
        # the equivalent mass sits on the pin; its share along the pin's direction
        out.append(float((forward * cmath.exp(-1j * throw.phase_rad)).real / unit))
    return tuple(out)


def _checked_orders(shaft_orders, max_order):
    orders = []
    for k in shaft_orders:
        if isinstance(k, bool) or not isinstance(k, numbers.Integral) or not 1 <= k <= max_order:
            raise CounterweightError(f"names order {k!r}, outside the orders analysed (1 to "
                                     f"{max_order})", "shaft_orders")
        orders.append(int(k))
    return sorted(set(orders))


def counterweights(engine,
                   planes: "Sequence[int | float | Plane] | None" = None,
                   radius_m: float | None = None, balance_factor: float | None = None,
                   shaft_orders: "Sequence[int]" = (), antivibrateur_radius_m: float | None = None,
                   test_masses: bool = False, samples: int = DEFAULT_SAMPLES,
                   max_order: int = DEFAULT_MAX_ORDER,
                   shaft_offsets_m: "tuple[float, float] | Mapping | None" = None) -> Balance:
    """Counterweights (and optionally antivibrateur, shafts, test masses) for ``engine``.

    Parameters
    ----------
    engine : Engine or EngineResult
        an analysed engine (:func:`~balance_cli.analyse`) is not analysed again: its samples
        and max_order are used
    planes : sequence of int, float or Plane, optional
        one plane (cancel the force only) or two (force and moment): a throw number (int,
        1-based), an axial position (float, m) or a :class:`Plane`; default the first and
        last throws
    radius_m : float, optional
        radius of the counterweights' centre of mass, m; default the crank radius
    balance_factor : float, optional
        size for the rotating masses plus this fraction (0 to 1) of the reciprocating ones
        per throw, instead of cancelling the forward first order exactly; counterweights as
        built count towards that size, and the rest is proposed
    shaft_orders : sequence of int
        residual orders to cancel with balancer shafts: per order and turning sense one shaft
        (speed ratio +k with the crank, −k against it) carrying one mass at z̄, or two in the
        planes (default the end throws) where the part has a moment
    antivibrateur_radius_m : float, optional
        add Fraeys de Veubeke's rotor of this eccentricity, m, sized to cancel the forward
        second order (single-throw engines with a turning crank)
    test_masses : bool
        also give the balancing-machine mass for each crank pin (not for a rotary)
    samples, max_order : int
        as for :func:`~balance_cli.analyse`
    shaft_offsets_m : (lateral, vertical) or mapping, optional
        where the shafts' axes sit, m from the crank axis (vertical along the engine's
        vertical, lateral 90° on from it with rotation): one pair for every shaft, or a mapping
        from speed ratio (+k, −k) to a pair, the key None for every shaft not named; default
        on the crank axis. The offset changes no force and no pitching or yawing moment, only
        the rolling moment about the crank axis

    An engine with counterweights or balancer shafts as built (``Engine.counterweights``,
    ``Engine.balancer_shafts``) is balanced as it is: ``Balance.original`` is what they leave,
    and the counterweights and shafts proposed are what to add to them.

    Raises
    ------
    CounterweightError
        naming the parameter that cannot be used
    """
    if not isinstance(engine, Engine) and not _analysed(engine):
        checks.instance(engine, Engine, "engine", CounterweightError)
    for name, value in (("planes", planes), ("shaft_orders", shaft_orders)):
        if (value is not None or name == "shaft_orders") and \
                (isinstance(value, (str, bytes)) or not hasattr(value, "__iter__")):
            raise CounterweightError(f"must be a list, got {value!r}", name)
    if _analysed(engine):
        shaking, samples = engine.shaking, engine.samples
        engine = engine.engine
    else:
        # as an analysis checks: the linkage, then the settings, then the firing order
        check_assembly(engine)
        shaking = shaking_forces(engine, samples, max_order)
        firing_sequence(engine)
    if engine.has_several_crankshafts:
        # the planes, shafts and balance factor are about one crankshaft's throws; a second
        # crankshaft (turning either way) needs its own counterweights, which are not proposed
        raise CounterweightError(f"{engine.name!r} has {len(engine.crankshafts)} crankshafts; "
                                 "counterweights are proposed for an engine with one (its free "
                                 "forces and moments are in balance compare)", "engine")
    max_order = shaking.max_order
    check_options(radius_m, balance_factor, shaft_orders, antivibrateur_radius_m, max_order,
                  shaft_offsets_m)
    planes = _checked_planes(engine, planes)
    radius = engine.crank_radius_m if radius_m is None else float(radius_m)
    balance_factor = None if balance_factor is None else float(balance_factor) + 0.0  # not -0
    orders = _checked_orders(shaft_orders, max_order)
    offsets = _checked_offsets(shaft_offsets_m, orders)
    if antivibrateur_radius_m is not None and (engine.is_rotary or len(engine.throws) != 1):
        raise CounterweightError(
            "needs a single-throw engine with a turning crank: the rotor turns on the crank pin "
            f"(this engine: {len(engine.throws)} throws, frame {engine.frame})",
            "antivibrateur_radius_m")
    if engine.is_rotary and (test_masses or balance_factor is not None):
        parameter = "test_masses" if test_masses else "balance_factor"
        raise CounterweightError("does not apply to a rotary engine: its crank stands still, so "
                                 "nothing rotates with it to balance", parameter)
    omega = engine.speed_rad_s
    z_mean = engine.mean_z_m
    current = shaking

    rotor = None
    if antivibrateur_radius_m is not None:
        rotor, second, pin = _antivibrateur(engine, current, float(antivibrateur_radius_m))
        lever = engine.throws[0].z_m - z_mean
        current = current.plus(2, forward=second, forward_moment=lever * second)
        current = current.plus(1, forward=pin, forward_moment=lever * pin)

    first = current.order(1)
    if balance_factor is None:
        target_force, target_moment = -first.force_forward, -first.moment_forward
    else:
        target_force, target_moment = _rotating_target(
            engine, balance_factor, rotor.mass_kg if rotor is not None else 0.0)
        # the counterweights as built already give part of the target: propose the rest
        built_force, built_moment = _built_first_order(engine, shaking)
        target_force, target_moment = target_force - built_force, target_moment - built_moment
    throw_one = cmath.exp(-1j * engine.throws[0].phase_rad)
    weights = []
    for plane, phasor in zip(planes, _share(target_force, target_moment, planes, z_mean)):
        if abs(phasor) < engine.noise_floor_n:
            phasor = 0j  # rounding noise of a balanced first order: no counterweight
        weights.append(Counterweight(plane, abs(phasor) / (radius * omega**2), radius,
                                     phasor_deg(phasor * throw_one)))
        current = current.plus(1, forward=phasor, forward_moment=(plane.z_m - z_mean) * phasor)
    residual = current

    shafts, built, rolling = [], [], []
    shaft_planes = planes if len(planes) == 2 else default_planes(engine)
    for order in orders:
        for ratio, masses in _shafts_for(order, residual, shaft_planes, engine):
            shaft, turning = _build_shaft(engine, ratio, masses, _offset_for(ratio, offsets))
            built.append(shaft)
            rolling.append(turning)
            for (z, phasor), mass in zip(masses, shaft.masses):
                shafts.append(Shaft(order, ratio, mass.mass_eccentricity_kgm, mass.phase_deg, z))
                lever = (z - z_mean) * phasor
                if ratio > 0:
                    current = current.plus(order, forward=phasor, forward_moment=lever)
                else:
                    current = current.plus(order, backward=phasor, backward_moment=lever)

    masses = _test_masses(engine, shaking) if test_masses else None
    return Balance(engine, shaking, rotor, tuple(weights), balance_factor, residual,
                   tuple(shafts), current if orders else None, masses, samples, tuple(built),
                   _rolling_totals(engine, built, rolling), tuple(orders), built_shafts(engine))


def _analysed(value):
    """An analysed engine (:class:`~balance_cli.EngineResult`, or anything with its engine,
    shaking and samples): balanced without analysing it again."""
    return isinstance(getattr(value, "engine", None), Engine) and \
        isinstance(getattr(value, "shaking", None), Shaking) and hasattr(value, "samples")


def check_options(radius_m=None, balance_factor=None, shaft_orders=(),
                  antivibrateur_radius_m=None, max_order=DEFAULT_MAX_ORDER, shaft_offsets_m=None):
    """Raise CounterweightError for options that no engine could use (the ones that depend on
    the engine are checked by :func:`counterweights`); a front end calls it before analysing."""
    if radius_m is not None:
        positive_length(radius_m, "radius_m")
    if antivibrateur_radius_m is not None:
        positive_length(antivibrateur_radius_m, "antivibrateur_radius_m")
    if balance_factor is not None:
        low, high = _BALANCE_FACTOR_RANGE
        if isinstance(balance_factor, bool) or not isinstance(balance_factor, numbers.Real) \
                or not low <= balance_factor <= high:
            raise CounterweightError(f"must be a fraction of the reciprocating masses from "
                                     f"{low:g} to {high:g}, got {balance_factor!r}", "balance_factor")
    _checked_offsets(shaft_offsets_m, _checked_orders(shaft_orders, max_order))
    if antivibrateur_radius_m is not None and max_order < 2:
        raise CounterweightError("needs max_order of at least 2: the rotor cancels the second "
                                 "order", "antivibrateur_radius_m")


