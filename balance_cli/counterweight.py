"""Counterweights, balancer shafts, the antivibrateur and balancing-machine test masses.

Everything works on the phasors of ``shaking``: a mass m at radius ρ turning with the crank at
angle φ (measured like a throw phase) adds m·ρ·ω²·e^{iφ} to the forward first-order force
and (z − z̄) times that to the free moment. A balancer shaft of order k adds m·e·(kω)²·e^{iφ}
to the forward (or, counter-rotating, the backward) part of order k.
"""

import cmath
import math
from dataclasses import dataclass

from .shaking import DEFAULT_MAX_ORDER, DEFAULT_SAMPLES, mean_cylinder_z, per_mass_force_coefficients, shaking

__all__ = [
    "BalanceError", "Plane", "Counterweight", "Shaft", "Antivibrateur", "Balance", "balance",
    "plane_at_throw", "plane_at",
]

#: a moment below this fraction of m_rec·r·ω²·n times one metre needs no pair of shafts
_NEGLIGIBLE = 1e-9


class BalanceError(ValueError):
    """A balancing request that cannot be carried out (bad planes, radius, orders)."""


@dataclass(frozen=True)
class Plane:
    """A correction plane: axial position, m, and the throw it sits on (1-based) if any."""

    z_m: float
    throw: int | None = None


@dataclass(frozen=True)
class Counterweight:
    """A mass on the crank (on the crankcase of a rotary) in one plane.

    ``angle_deg`` is measured like a throw phase: from throw 1, positive with rotation.
    """

    plane: Plane
    mass_kg: float
    radius_m: float
    angle_deg: float


@dataclass(frozen=True)
class Shaft:
    """A balancer shaft of order k with an unbalance m·e.

    ``speed_ratio`` is +k (turning with the crank) or −k (against it); the unbalance lies at
    ``phase_deg`` from the reference axis when the crank angle is 0, and turns at k·θ or −k·θ.
    """

    order: int
    speed_ratio: int
    mass_eccentricity_kgm: float
    phase_deg: float
    z_m: float

    @property
    def direction(self):
        return "with the crank" if self.speed_ratio > 0 else "against the crank"


@dataclass(frozen=True)
class Antivibrateur:
    """Fraeys de Veubeke's rotor: a mass M at eccentricity e about the crank-pin axis, turning
    at twice crank speed in the crank's sense (geared to a fixed pinion)."""

    mass_eccentricity_kgm: float
    eccentricity_m: float
    phase_deg: float

    @property
    def mass_kg(self):
        return self.mass_eccentricity_kgm / self.eccentricity_m


@dataclass(frozen=True)
class Balance:
    """What ``balance counterweight`` reports for one engine."""

    engine: object
    original: object             # Shaking before anything is added
    antivibrateur: Antivibrateur | None
    counterweights: tuple
    balance_factor: float | None
    residual: object             # Shaking after antivibrateur and counterweights
    shafts: tuple
    after_shafts: object | None  # Shaking after the shafts too
    test_masses_kg: tuple | None


def plane_at_throw(engine, number):
    if not 1 <= number <= len(engine.throws):
        raise BalanceError(f"--planes: there is no throw {number} (the engine has "
                           f"{len(engine.throws)}); give throw numbers or positions such as '120 mm'")
    return Plane(engine.throws[number - 1].z_m, number)


def plane_at(engine, z_m):
    """A plane at an axial position, on a throw if one sits there."""
    for i, throw in enumerate(engine.throws, 1):
        if math.isclose(throw.z_m, z_m, abs_tol=1e-9):
            return Plane(throw.z_m, i)
    return Plane(z_m, None)


def default_planes(engine):
    """The first and last throws, or one plane where every throw sits at one position."""
    first, last = plane_at_throw(engine, 1), plane_at_throw(engine, len(engine.throws))
    return (first,) if math.isclose(first.z_m, last.z_m, abs_tol=1e-9) else (first, last)


def _angle_deg(phasor):
    """Direction of a phasor in [0, 360) degrees; rounding noise below 0 reads as 0."""
    degrees = math.degrees(cmath.phase(phasor)) % 360.0 if phasor else 0.0
    return 0.0 if degrees > 360.0 - 1e-7 else degrees


def _check_planes(planes):
    if not 1 <= len(planes) <= 2:
        raise BalanceError("--planes takes one plane (force only) or two (force and moment)")
    if len(planes) == 2 and math.isclose(planes[0].z_m, planes[1].z_m, abs_tol=1e-9):
        raise BalanceError("--planes: the two planes coincide; choose planes apart, or give one")


def _share(force, moment, planes, z_mean):
    """Phasors in each plane that add up to ``force`` and, with two planes, ``moment``.

    Two planes at a = z_A − z̄, b = z_B − z̄: c_A + c_B = F and a·c_A + b·c_B = M.
    """
    if len(planes) == 1:
        return (force,)
    a, b = planes[0].z_m - z_mean, planes[1].z_m - z_mean
    first = (moment - b * force) / (a - b)
    return (first, force - first)


def _rotating_target(engine, factor, speed):
    """Forward first-order force and moment (N, N·m) of the classic per-throw counterweights:
    rotating, crank and knuckle masses plus ``factor`` times the reciprocating ones, opposite
    each throw at crank radius."""
    z_mean = mean_cylinder_z(engine)
    force = moment = 0j
    for index, throw in enumerate(engine.throws):
        on_throw = [c for c in engine.cylinders if c.throw == index]
        mass = (engine.rotating_kg + engine.crank_kg + sum(c.knuckle_kg for c in on_throw)
                + factor * sum(c.reciprocating_kg for c in on_throw))
        phasor = -mass * engine.crank_radius_m * speed**2 * cmath.exp(1j * throw.phase_rad)
        force += phasor
        moment += (throw.z_m - z_mean) * phasor
    return force, moment


def _antivibrateur(engine, shaking_, eccentricity):
    """Size the rotor to cancel the forward second order exactly; return it and its phasors."""
    if len(engine.throws) != 1:
        raise BalanceError("the antivibrateur turns on the crank pin of a single-throw engine "
                           f"(this one has {len(engine.throws)} throws)")
    if eccentricity <= 0:
        raise BalanceError("--antivibrateur-radius must be greater than zero")
    second = shaking_.orders[1].force_forward
    omega = engine.speed_rad_s
    me = abs(second) / (4 * omega**2)
    rotor = Antivibrateur(me, eccentricity, _angle_deg(-second))
    # its mass also rides on the crank pin: a forward first order like a rotating mass
    pin = rotor.mass_kg * engine.crank_radius_m * omega**2 * cmath.exp(1j * engine.throws[0].phase_rad)
    return rotor, -second, pin


def _shafts_for(order, shaking_, planes, z_mean, speed, scale):
    """Shafts cancelling order ``order``: per turning sense, one shaft at z̄ when the part has
    no moment (with its counterpart: Lanchester's pair for a line force), else two apart."""
    o = shaking_.orders[order - 1]
    out = []
    for sign, force, moment in ((1, o.force_forward, o.moment_forward),
                                (-1, o.force_backward, o.moment_backward)):
        if abs(force) < _NEGLIGIBLE * scale and abs(moment) < _NEGLIGIBLE * scale:
            continue
        if abs(moment) < _NEGLIGIBLE * scale or len(planes) == 1:
            where = (Plane(z_mean),)
            phasors = (-force,)
        else:
            where = planes
            phasors = _share(-force, -moment, planes, z_mean)
        for plane, phasor in zip(where, phasors):
            if abs(phasor) < _NEGLIGIBLE * scale:
                continue
            out.append(Shaft(order, sign * order, abs(phasor) / (order * speed) ** 2,
                             _angle_deg(phasor), plane.z_m))
    return out


def _test_masses(engine, samples):
    """Mass to hang on each crank pin so that the counterweighted shaft balances on a machine:
    the forward first order of everything on the throw but the crankshaft itself, as a mass
    at crank radius (Nakanishi § 4)."""
    coefficients, masses = per_mass_force_coefficients(engine, samples)
    unit = engine.crank_radius_m * engine.speed_rad_s**2
    out = []
    for index, throw in enumerate(engine.throws):
        mine = (masses.throw == index) & (masses.cylinder != -1)
        forward = coefficients[mine, 1].sum()
        # the equivalent mass sits on the pin; its share along the pin's direction
        out.append(float((forward * cmath.exp(-1j * throw.phase_rad)).real / unit))
    return tuple(out)


def balance(engine, planes=None, radius_m=None, balance_factor=None, shaft_orders=(),
            antivibrateur_radius_m=None, test_masses=False, samples=DEFAULT_SAMPLES,
            max_order=DEFAULT_MAX_ORDER):
    """Counterweights (and optionally antivibrateur, shafts, test masses) for ``engine``.

    Parameters
    ----------
    planes : sequence of Plane, optional
        one plane (cancel the force only) or two (force and moment); default the first and
        last throws
    radius_m : float, optional
        radius of the counterweights' centre of mass, m; default the crank radius
    balance_factor : float, optional
        size for the rotating masses plus this fraction of the reciprocating ones per throw,
        instead of cancelling the forward first order exactly
    shaft_orders : sequence of int
        residual orders to cancel with balancer shafts
    antivibrateur_radius_m : float, optional
        add Fraeys de Veubeke's rotor of this eccentricity, m, sized to cancel the forward
        second order (single-throw engines)
    """
    planes = tuple(planes) if planes else default_planes(engine)
    _check_planes(planes)
    radius = engine.crank_radius_m if radius_m is None else radius_m
    if radius <= 0:
        raise BalanceError("--radius must be greater than zero")
    bad = [k for k in shaft_orders if not 1 <= k <= max_order]
    if bad:
        raise BalanceError(f"--shafts: order {bad[0]} is outside 1..{max_order} (--max-order)")
    omega = engine.speed_rad_s
    z_mean = mean_cylinder_z(engine)
    scale = engine.unit_force_n * engine.n_cylinders
    original = shaking(engine, samples, max_order)
    current = original

    rotor = None
    if antivibrateur_radius_m is not None:
        rotor, second, pin = _antivibrateur(engine, current, antivibrateur_radius_m)
        lever = engine.throws[0].z_m - z_mean
        current = current.plus(2, forward=second, forward_moment=lever * second)
        current = current.plus(1, forward=pin, forward_moment=lever * pin)

    first = current.orders[0]
    if balance_factor is None:
        target_force, target_moment = -first.force_forward, -first.moment_forward
    else:
        target_force, target_moment = _rotating_target(engine, balance_factor, omega)
    counterweights = []
    for plane, phasor in zip(planes, _share(target_force, target_moment, planes, z_mean)):
        if abs(phasor) < _NEGLIGIBLE * scale:
            phasor = 0j  # rounding noise of a balanced first order: no counterweight
        counterweights.append(Counterweight(plane, abs(phasor) / (radius * omega**2), radius,
                                            _angle_deg(phasor)))
        current = current.plus(1, forward=phasor, forward_moment=(plane.z_m - z_mean) * phasor)
    residual = current

    shafts = []
    shaft_planes = planes if len(planes) == 2 else default_planes(engine)
    for order in sorted(set(shaft_orders)):
        for shaft in _shafts_for(order, residual, shaft_planes, z_mean, omega, scale):
            shafts.append(shaft)
            phasor = shaft.mass_eccentricity_kgm * (order * omega) ** 2 * cmath.exp(
                1j * math.radians(shaft.phase_deg))
            lever = (shaft.z_m - z_mean) * phasor
            if shaft.speed_ratio > 0:
                current = current.plus(order, forward=phasor, forward_moment=lever)
            else:
                current = current.plus(order, backward=phasor, backward_moment=lever)

    masses = _test_masses(engine, samples) if test_masses and engine.frame == "fixed" else None
    return Balance(engine, original, rotor, tuple(counterweights), balance_factor, residual,
                   tuple(shafts), current if shaft_orders else None, masses)
