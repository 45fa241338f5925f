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
import numbers
from collections.abc import Mapping, Sequence

import numpy as np

from .. import checks
from ..errors import CounterweightError
from ..kinematics import BALANCER, BIG_ENDS, COUNTERWEIGHT, check_assembly
from ..model import Engine
from ..units import phasor_deg
from .balancer import (
    build_shaft,
    built_shafts,
    checked_offsets,
    offset_for,
    rolling_totals,
    shafts_for,
)
from .balancing import Antivibrateur, Balance, Counterweight, Plane, Shaft, positive_length
from .firing import firing_sequence
from .planes import checked_planes, default_planes, share
from .shaking import DEFAULT_MAX_ORDER, DEFAULT_SAMPLES, Shaking, shaking_forces

__all__ = ["counterweights", "check_options"]

#: the balance factor is a fraction of the reciprocating masses
_BALANCE_FACTOR_RANGE = (0.0, 1.0)


def _rotating_target(engine, factor, pin_kg=0.0):
    """Forward first-order force and moment (N, N·m) of the classic per-throw counterweights:
    rotating, crank and knuckle masses (and ``pin_kg`` more on every pin: an antivibrateur's)
    plus ``factor`` times the reciprocating ones, opposite each throw at crank radius."""
    force = moment = 0j
    for index, throw in enumerate(engine.throws):
        on_throw = [c for c in engine.cylinders if c.throw_index == index]
        mass = (
            engine.rotating_of(index)
            + engine.crank_kg
            + pin_kg
            + sum(c.knuckle_kg for c in on_throw)
            + factor * sum(c.reciprocating_kg for c in on_throw)
        )
        phasor = (
            -mass * engine.crank_radius_m * engine.speed_rad_s**2 * cmath.exp(1j * throw.phase_rad)
        )
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
    pin = (
        rotor.mass_kg
        * engine.crank_radius_m
        * omega**2
        * cmath.exp(1j * engine.throws[0].phase_rad)
    )
    return rotor, -second, pin


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
        if (
            isinstance(k, bool)
            or not isinstance(k, numbers.Integral)
            or not 1 <= int(k) <= max_order
        ):
            raise CounterweightError(
                f"names order {k!r}, outside the orders analysed (1 to {max_order})", "shaft_orders"
            )
        orders.append(int(k))
    return sorted(set(orders))


def counterweights(
    engine,
    planes: "Sequence[int | Plane] | None" = None,
    radius_m: float | None = None,
    balance_factor: float | None = None,
    shaft_orders: "Sequence[int]" = (),
    antivibrateur_radius_m: float | None = None,
    test_masses: bool = False,
    samples: int = DEFAULT_SAMPLES,
    max_order: int = DEFAULT_MAX_ORDER,
    shaft_offsets_m: "tuple[float, float] | Mapping | None" = None,
) -> Balance:
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
        if (value is not None or name == "shaft_orders") and (
            isinstance(value, (str, bytes)) or not hasattr(value, "__iter__")
        ):
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
        raise CounterweightError(
            f"{engine.name!r} has {len(engine.crankshafts)} crankshafts; "
            "counterweights are proposed for an engine with one (its free "
            "forces and moments are in balance compare)",
            "engine",
        )
    max_order = shaking.max_order
    check_options(
        radius_m, balance_factor, shaft_orders, antivibrateur_radius_m, max_order, shaft_offsets_m
    )
    planes = checked_planes(engine, planes)
    radius = engine.crank_radius_m if radius_m is None else float(radius_m)
    balance_factor = None if balance_factor is None else float(balance_factor) + 0.0  # not -0
    orders = _checked_orders(shaft_orders, max_order)
    offsets = checked_offsets(shaft_offsets_m, orders)
    if antivibrateur_radius_m is not None and (engine.is_rotary or len(engine.throws) != 1):
        raise CounterweightError(
            "needs a single-throw engine with a turning crank: the rotor turns on the crank pin "
            f"(this engine: {len(engine.throws)} throws, frame {engine.frame})",
            "antivibrateur_radius_m",
        )
    if engine.is_rotary and (test_masses or balance_factor is not None):
        parameter = "test_masses" if test_masses else "balance_factor"
        raise CounterweightError(
            "does not apply to a rotary engine: its crank stands still, so "
            "nothing rotates with it to balance",
            parameter,
        )
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
            engine, balance_factor, rotor.mass_kg if rotor is not None else 0.0
        )
        # the counterweights as built already give part of the target: propose the rest
        built_force, built_moment = _built_first_order(engine, shaking)
        target_force, target_moment = target_force - built_force, target_moment - built_moment
    throw_one = cmath.exp(-1j * engine.throws[0].phase_rad)
    weights = []
    for plane, phasor in zip(
        planes, share(target_force, target_moment, planes, z_mean), strict=True
    ):
        if abs(phasor) < engine.noise_floor_n:
            phasor = 0j  # rounding noise of a balanced first order: no counterweight
        weights.append(
            Counterweight(
                plane, abs(phasor) / (radius * omega**2), radius, phasor_deg(phasor * throw_one)
            )
        )
        current = current.plus(1, forward=phasor, forward_moment=(plane.z_m - z_mean) * phasor)
    residual = current

    shafts, built, rolling = [], [], []
    shaft_planes = planes if len(planes) == 2 else default_planes(engine)
    for order in orders:
        for ratio, masses in shafts_for(order, residual, shaft_planes, engine):
            shaft, turning = build_shaft(engine, ratio, masses, offset_for(ratio, offsets))
            built.append(shaft)
            rolling.append(turning)
            for (z, phasor), mass in zip(masses, shaft.masses, strict=True):
                shafts.append(Shaft(order, ratio, mass.mass_eccentricity_kgm, mass.phase_deg, z))
                lever = (z - z_mean) * phasor
                if ratio > 0:
                    current = current.plus(order, forward=phasor, forward_moment=lever)
                else:
                    current = current.plus(order, backward=phasor, backward_moment=lever)

    masses = _test_masses(engine, shaking) if test_masses else None
    return Balance(
        engine,
        shaking,
        rotor,
        tuple(weights),
        balance_factor,
        residual,
        tuple(shafts),
        current if orders else None,
        masses,
        samples,
        tuple(built),
        rolling_totals(engine, built, rolling),
        tuple(orders),
        built_shafts(engine),
    )


def _analysed(value):
    """An analysed engine (:class:`~balance_cli.EngineResult`, or anything with its engine,
    shaking and samples): balanced without analysing it again."""
    return (
        isinstance(getattr(value, "engine", None), Engine)
        and isinstance(getattr(value, "shaking", None), Shaking)
        and hasattr(value, "samples")
    )


def check_options(
    radius_m=None,
    balance_factor=None,
    shaft_orders=(),
    antivibrateur_radius_m=None,
    max_order=DEFAULT_MAX_ORDER,
    shaft_offsets_m=None,
):
    """Raise CounterweightError for options that no engine could use (the ones that depend on
    the engine are checked by :func:`counterweights`); a front end calls it before analysing."""
    if radius_m is not None:
        positive_length(radius_m, "radius_m")
    if antivibrateur_radius_m is not None:
        positive_length(antivibrateur_radius_m, "antivibrateur_radius_m")
    if balance_factor is not None:
        low, high = _BALANCE_FACTOR_RANGE
        if (
            isinstance(balance_factor, bool)
            or not isinstance(balance_factor, numbers.Real)
            # mypy does not support the numbers ABCs (python/mypy#3186): a Real compares
            # with a float; float() would make a huge Fraction an OverflowError here
            or not low <= balance_factor <= high  # type: ignore[operator]
        ):
            raise CounterweightError(
                f"must be a fraction of the reciprocating masses from "
                f"{low:g} to {high:g}, got {balance_factor!r}",
                "balance_factor",
            )
    checked_offsets(shaft_offsets_m, _checked_orders(shaft_orders, max_order))
    if antivibrateur_radius_m is not None and max_order < 2:
        raise CounterweightError(
            "needs max_order of at least 2: the rotor cancels the second order",
            "antivibrateur_radius_m",
        )
