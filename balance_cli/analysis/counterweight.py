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

from .results import DOCUMENT_VERSION, EngineResult, analyse
from .. import checks
from ..errors import CounterweightError, UnitError
from ..kinematics.linkage import BALANCER, BIG_ENDS, COUNTERWEIGHT
from ..model import Engine, offset_position
from .shaking import DEFAULT_MAX_ORDER, DEFAULT_SAMPLES, Shaking
from ..tolerances import SAME_POSITION_M
from ..units import check_finite_range, phasor_deg, rad_s_to_rpm

__all__ = ["Plane", "Counterweight", "Shaft", "ShaftMass", "BalancerShaft", "RollingMoment",
           "Antivibrateur", "Balance", "Balances", "counterweights", "check_options",
           "plane_at_throw", "plane_at", "offset_position", "rolling_moment_phasor", "built_shafts"]

#: the balance factor is a fraction of the reciprocating masses
_BALANCE_FACTOR_RANGE = (0.0, 1.0)


@dataclass(frozen=True)
class Plane:
    """A correction plane: axial position, m, and the throw it sits on (1-based) if any."""

    z_m: float
    throw: int | None = None


@dataclass(frozen=True)
class Counterweight:
    """A mass on the crank (on the crankcase of a rotary) in one plane.

    ``angle_deg`` is measured like a throw phase: from throw 1, positive with rotation (from
    the reference axis at θ = 0 when throw 1's phase is 0, as in every shipped configuration).
    """

    plane: Plane
    mass_kg: float
    radius_m: float
    angle_deg: float

    def to_dict(self) -> dict:
        return {"z_m": self.plane.z_m, "throw": self.plane.throw, "mass_kg": self.mass_kg,
                "radius_m": self.radius_m, "angle_deg": self.angle_deg}


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

    def to_dict(self) -> dict:
        return {"order": self.order, "speed_ratio": self.speed_ratio,
                "mass_eccentricity_kgm": self.mass_eccentricity_kgm, "phase_deg": self.phase_deg,
                "z_m": self.z_m}


@dataclass(frozen=True)
class ShaftMass:
    """One unbalance on a balancer shaft: m·e (kg·m), its direction from the reference axis
    (positive with rotation) when the crank angle is 0, and its axial position (m)."""

    mass_eccentricity_kgm: float
    phase_deg: float
    z_m: float

    def mass_kg(self, eccentricity_m: float) -> float:
        """The mass that gives this unbalance at ``eccentricity_m``, kg."""
        return self.mass_eccentricity_kgm / _positive_length(eccentricity_m, "eccentricity_m")

    def to_dict(self) -> dict:
        return {"mass_eccentricity_kgm": self.mass_eccentricity_kgm, "phase_deg": self.phase_deg,
                "z_m": self.z_m}


@dataclass(frozen=True)
class RollingMoment:
    """A moment about the crank axis of one order, N·m, positive with rotation (the sense of
    ``balance torque``'s frame torque, so the two add):
    M(θ) = cos·cos kθ + sin·sin kθ = amplitude·cos(kθ − phase).

    ``speed_ratios`` names the shafts that make it.
    """

    order: int
    cos_nm: float
    sin_nm: float
    speed_ratios: tuple = ()

    @classmethod
    def from_phasor(cls, order, phasor, floor_nm, speed_ratios=()):
        """From C with M(θ) = Re(C·e^{ikθ}); parts below ``floor_nm`` are rounding noise."""
        clean = lambda x: float(x) if abs(x) >= floor_nm else 0.0  # noqa: E731
        return cls(int(order), clean(phasor.real), clean(-phasor.imag), tuple(speed_ratios))

    @property
    def amplitude_nm(self) -> float:
        return math.hypot(self.cos_nm, self.sin_nm)

    @property
    def phase_deg(self) -> float:
        return phasor_deg(complex(self.cos_nm, self.sin_nm))

    def to_dict(self) -> dict:
        entry: dict = {"order": self.order, "cos_Nm": self.cos_nm, "sin_Nm": self.sin_nm,
                 "amplitude_Nm": self.amplitude_nm, "phase_deg": self.phase_deg}
        if self.speed_ratios:
            entry["speed_ratios"] = list(self.speed_ratios)
        return entry


@dataclass(frozen=True)
class BalancerShaft:
    """A balancer shaft as built: one shaft turning at ``speed_ratio`` × crank speed (+k with
    the crank, −k against it) with its masses, its axis at ``lateral_m`` and ``vertical_m``
    from the crank axis (lateral along the engine's horizontal, 90° on from its vertical with
    rotation).

    ``force_n`` is the size of the rotating force of all its masses together, N, and
    ``rolling_moment`` the moment that force makes about the crank axis (zero on the axis).
    """

    speed_ratio: int
    masses: tuple
    lateral_m: float = 0.0
    vertical_m: float = 0.0
    force_n: float = 0.0
    rolling_moment: RollingMoment | None = None

    @property
    def order(self) -> int:
        return abs(self.speed_ratio)

    @property
    def centred(self) -> bool:
        return self.lateral_m == 0.0 and self.vertical_m == 0.0

    def to_dict(self) -> dict:
        moment = self.rolling_moment or RollingMoment(self.order, 0.0, 0.0)
        return {"speed_ratio": self.speed_ratio, "order": self.order,
                "turning": "with" if self.speed_ratio > 0 else "against",
                "offset_m": {"lateral": self.lateral_m, "vertical": self.vertical_m},
                "masses": [m.to_dict() for m in self.masses], "force_N": self.force_n,
                "rolling_moment": moment.to_dict()}


@dataclass(frozen=True)
class Antivibrateur:
    """Fraeys de Veubeke's rotor: a mass M at eccentricity e about the crank-pin axis, turning
    at twice crank speed in the crank's sense (geared to a fixed pinion)."""

    mass_eccentricity_kgm: float
    eccentricity_m: float
    phase_deg: float

    @property
    def mass_kg(self) -> float:
        return self.mass_eccentricity_kgm / self.eccentricity_m

    def to_dict(self) -> dict:
        return {"mass_eccentricity_kgm": self.mass_eccentricity_kgm,
                "eccentricity_m": self.eccentricity_m, "mass_kg": self.mass_kg,
                "phase_deg": self.phase_deg}


@dataclass(frozen=True)
class Balance:
    """What ``balance counterweight`` reports for one engine.

    Attributes
    ----------
    engine : Engine
    original : Shaking
        before anything is added
    antivibrateur : Antivibrateur or None
    counterweights : tuple of Counterweight
    balance_factor : float or None
        None when the counterweights cancel the forward first order exactly
    residual : Shaking
        after the antivibrateur and the counterweights
    shafts : tuple of Shaft
        one entry per mass, as in the JSON's ``shafts``
    after_shafts : Shaking or None
        after the shafts too (None when no shaft was asked for)
    test_masses_kg : tuple of float or None
        the balancing-machine mass for each crank pin, in throw order (when asked for)
    samples : int
    balancer_shafts : tuple of BalancerShaft
        the same shafts as built: one per speed ratio, carrying its masses
    rolling_moments : tuple of RollingMoment
        for each order with shafts, the rolling moment of all of that order's shafts together
        (a Lanchester pair's couple); zero when they sit on the crank axis
    shaft_orders : tuple of int
        the orders shafts were asked for (an order already zero gets none)
    built_shafts : tuple of BalancerShaft
        the engine's own balancer shafts as built (``Engine.balancer_shafts``), with the force
        and rolling moment each makes

    With counterweights or balancer shafts as built in the engine, ``original`` is what they
    leave, and everything proposed (``counterweights``, ``shafts``) is **in addition** to them:
    built and proposed together leave ``residual`` and ``after_shafts``.
    """

    engine: Engine
    original: Shaking
    antivibrateur: Antivibrateur | None
    counterweights: tuple
    balance_factor: float | None
    residual: Shaking
    shafts: tuple
    after_shafts: Shaking | None
    test_masses_kg: tuple | None
    samples: int = DEFAULT_SAMPLES
    balancer_shafts: tuple = ()
    rolling_moments: tuple = ()
    shaft_orders: tuple = ()
    built_shafts: tuple = ()

    @property
    def max_order(self) -> int:
        return self.original.max_order

    def to_dict(self) -> dict:
        """This engine's entry of ``counterweight --format json`` (SI units; see the README)."""
        engine = self.engine

        def stage(shaking):
            # below the noise floor it is rounding, an exact zero as compare writes it
            largest = shaking.largest_force()
            return {"largest_resultant_N": largest if largest >= engine.noise_floor_n else 0.0,
                    "orders": shaking.records(engine)}

        entry = {
            "name": engine.name,
            "config": engine.config_path,
            "cylinders": engine.n_cylinders,
            "frame": engine.frame,
            "speed_rpm": rad_s_to_rpm(engine.speed_rad_s),
            "unit_force_N": engine.unit_force_n,
            "balance_factor": self.balance_factor,
            "counterweights": [c.to_dict() for c in self.counterweights],
            "antivibrateur": None if self.antivibrateur is None else self.antivibrateur.to_dict(),
            "residual": stage(self.residual),
        }
        if self.after_shafts is not None:
            entry["shafts"] = [s.to_dict() for s in self.shafts]
            entry["after_shafts"] = stage(self.after_shafts)
            entry["shaft_orders"] = list(self.shaft_orders)
            entry["balancer_shafts"] = [s.to_dict() for s in self.balancer_shafts]
            entry["shaft_rolling_moments"] = [m.to_dict() for m in self.rolling_moments]
        if self.test_masses_kg is not None:
            entry["test_masses_kg"] = list(self.test_masses_kg)
        if engine.counterweights or engine.balancer_shafts:
            entry["as_built"] = {
                "counterweights": [_built_weight_record(engine, w) for w in engine.counterweights],
                "balancer_shafts": [s.to_dict() for s in self.built_shafts],
                **stage(self.original)}
        return entry

    def configuration_tables(self, shafts: bool = False) -> dict:
        """The proposal as configuration tables, in the file's keys and units: ``counterweights``
        (each on a throw, its angle from that throw's pin) and, with ``shafts``, ``shafts``
        (each with its ``masses``), ready to be added to the engine's own
        ``[[counterweights]]`` and ``[[shafts]]``. Lengths in m, unbalances in kg·m, angles in
        degrees, at full precision: the file read back leaves exactly ``residual`` (and
        ``after_shafts``).

        Raises
        ------
        CounterweightError
            for an antivibrateur, which no configuration table describes, and for a rotary
            engine, whose counterweights ride on its crankcase
        """
        if self.antivibrateur is not None:
            raise CounterweightError("has no configuration table, and the counterweights "
                                     "proposed include its mass; leave it out to write a "
                                     "configuration", "antivibrateur_radius_m")
        engine = self.engine
        if engine.is_rotary:
            raise CounterweightError(
                "of a rotary engine cannot be written as configuration tables: its counterweights "
                "ride on the turning crankcase, and [[counterweights]] and [[shafts]] describe "
                "masses geared to a turning crank", "counterweights")
        first = math.degrees(engine.throws[0].phase_rad)
        weights = []
        for weight in self.counterweights:
            if weight.mass_kg == 0.0:
                continue
            index = 0 if weight.plane.throw is None else weight.plane.throw - 1
            # Counterweight.angle_deg is measured from throw 1; a built one from its own throw
            angle = weight.angle_deg + first - math.degrees(engine.throws[index].phase_rad)
            weights.append({"throw": index + 1, "mass": f"{float(weight.mass_kg)!r} kg",
                            "radius": f"{float(weight.radius_m)!r} m",
                            "angle": float(math.remainder(angle, 360.0)) + 0.0,
                            "z": f"{float(weight.plane.z_m)!r} m"})
        tables: dict = {"counterweights": weights}
        if shafts:
            tables["shafts"] = [
                {"ratio": shaft.speed_ratio, "lateral": f"{float(shaft.lateral_m)!r} m",
                 "vertical": f"{float(shaft.vertical_m)!r} m",
                 # ShaftMass.phase_deg is measured with the crank; a built mass's angle in its
                 # shaft's own sense of turning
                 "masses": [{"mass_radius": f"{float(m.mass_eccentricity_kgm)!r} kg*m",
                             "angle": math.remainder(math.copysign(1, shaft.speed_ratio)
                                                     * m.phase_deg, 360.0) + 0.0,
                             "z": f"{float(m.z_m)!r} m"} for m in shaft.masses]}
                for shaft in self.balancer_shafts]
        return tables


def _built_weight_record(engine, weight) -> dict:
    """A counterweight as built, as ``counterweight --format json`` lists it under ``as_built``."""
    return {"throw": weight.throw + 1, "mass_radius_kgm": weight.mass_radius_kgm,
            "mass_kg": weight.mass_kg, "radius_m": weight.radius_m,
            "angle_deg": math.degrees(weight.angle_rad), "z_m": engine.counterweight_z_m(weight)}


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
    if isinstance(spec, Plane):
        return spec
    if isinstance(spec, numbers.Integral) and not isinstance(spec, bool):
        return plane_at_throw(engine, spec)
    if isinstance(spec, numbers.Real) and not isinstance(spec, bool):
        return plane_at(engine, spec)
    raise CounterweightError(f"takes throw numbers (int), axial positions in metres (float) or "
                             f"Plane objects, got {spec!r}", "planes")


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


def _positive_length(value, parameter):
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        raise CounterweightError(f"must be a length in metres, got {value!r}", parameter)
    if value <= 0:
        raise CounterweightError(f"must be greater than zero, got {value!r} m", parameter)
    try:
        check_finite_range(float(value), "length")
    except UnitError as exc:
        raise CounterweightError(f"is invalid: {exc}", parameter) from None
    return float(value)


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
        on_throw = [c for c in engine.cylinders if c.throw == index]
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


def _checked_offsets(shaft_offsets, orders):
    """{speed ratio or None (every other shaft): (lateral, vertical) m} from a pair or a
    mapping; ratios must belong to the orders asked for."""
    if shaft_offsets is None:
        return {}
    if not orders:
        raise CounterweightError("places balancer shafts, but no shaft order was asked for",
                                 "shaft_offsets")
    items = shaft_offsets.items() if isinstance(shaft_offsets, Mapping) else [(None, shaft_offsets)]
    checked = {}
    for ratio, pair in items:
        if ratio is not None:
            if isinstance(ratio, bool) or not isinstance(ratio, numbers.Integral) \
                    or abs(int(ratio)) not in orders:
                raise CounterweightError(
                    f"names speed ratio {ratio!r}, but shafts are made for orders "
                    f"{', '.join(map(str, orders))} only (ratios ±k, + with the crank)",
                    "shaft_offsets")
            ratio = int(ratio)
        if isinstance(pair, (str, bytes)) or not isinstance(pair, Sequence) or len(pair) != 2:
            raise CounterweightError(f"takes (lateral, vertical) pairs in metres, got {pair!r}",
                                     "shaft_offsets")
        values = []
        for value in pair:
            if isinstance(value, bool) or not isinstance(value, numbers.Real):
                raise CounterweightError(f"takes lengths in metres, got {value!r}", "shaft_offsets")
            try:
                check_finite_range(float(value), "length", smallest=False)
            except UnitError as exc:
                raise CounterweightError(f"has an offset that is invalid: {exc}",
                                         "shaft_offsets") from None
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
        mine = (masses.throw == index) & (masses.cylinder >= BIG_ENDS)
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


def counterweights(engine: "Engine | EngineResult",
                   planes: "Sequence[int | float | Plane] | None" = None,
                   radius_m: float | None = None, balance_factor: float | None = None,
                   shaft_orders: "Sequence[int]" = (), antivibrateur_radius_m: float | None = None,
                   test_masses: bool = False, samples: int = DEFAULT_SAMPLES,
                   max_order: int = DEFAULT_MAX_ORDER,
                   shaft_offsets: "tuple[float, float] | Mapping | None" = None) -> Balance:
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
    shaft_offsets : (lateral, vertical) or mapping, optional
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
    checks.instance(engine, (Engine, EngineResult), "engine", CounterweightError)
    for name, value in (("planes", planes), ("shaft_orders", shaft_orders)):
        if (value is not None or name == "shaft_orders") and \
                (isinstance(value, (str, bytes)) or not hasattr(value, "__iter__")):
            raise CounterweightError(f"must be a list, got {value!r}", name)
    if isinstance(engine, EngineResult):
        shaking, samples = engine.shaking, engine.samples
        engine = engine.engine
    else:
        shaking = analyse(engine, samples, max_order).shaking
    if engine.has_several_crankshafts:
        # the planes, shafts and balance factor are about one crankshaft's throws; a second
        # crankshaft (turning either way) needs its own counterweights, which are not proposed
        raise CounterweightError(f"{engine.name!r} has {len(engine.crankshafts)} crankshafts; "
                                 "counterweights are proposed for an engine with one (its free "
                                 "forces and moments are in balance compare)", "engine")
    max_order = shaking.max_order
    check_options(radius_m, balance_factor, shaft_orders, antivibrateur_radius_m, max_order,
                  shaft_offsets)
    planes = _checked_planes(engine, planes)
    radius = engine.crank_radius_m if radius_m is None else float(radius_m)
    balance_factor = None if balance_factor is None else float(balance_factor) + 0.0  # not -0
    orders = _checked_orders(shaft_orders, max_order)
    offsets = _checked_offsets(shaft_offsets, orders)
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


def check_options(radius_m=None, balance_factor=None, shaft_orders=(),
                  antivibrateur_radius_m=None, max_order=DEFAULT_MAX_ORDER, shaft_offsets=None):
    """Raise CounterweightError for options that no engine could use (the ones that depend on
    the engine are checked by :func:`counterweights`); a front end calls it before analysing."""
    if radius_m is not None:
        _positive_length(radius_m, "radius_m")
    if antivibrateur_radius_m is not None:
        _positive_length(antivibrateur_radius_m, "antivibrateur_radius_m")
    if balance_factor is not None:
        low, high = _BALANCE_FACTOR_RANGE
        if isinstance(balance_factor, bool) or not isinstance(balance_factor, numbers.Real) \
                or not low <= balance_factor <= high:
            raise CounterweightError(f"must be a fraction of the reciprocating masses from "
                                     f"{low:g} to {high:g}, got {balance_factor!r}", "balance_factor")
    _checked_offsets(shaft_offsets, _checked_orders(shaft_orders, max_order))
    if antivibrateur_radius_m is not None and max_order < 2:
        raise CounterweightError("needs max_order of at least 2: the rotor cancels the second "
                                 "order", "antivibrateur_radius_m")


@dataclass(frozen=True)
class Balances:
    """The counterweights of several engines, balanced with the same settings."""

    balances: tuple

    def __post_init__(self):
        if not self.balances:
            raise CounterweightError("needs at least one balanced engine", "balances")
        if len({(b.samples, b.max_order) for b in self.balances}) > 1:
            raise CounterweightError("must all be analysed with the same samples and max_order",
                                     "balances")

    def to_dict(self) -> dict:
        """What ``counterweight --format json`` writes: one :meth:`Balance.to_dict` per engine."""
        first = self.balances[0]
        return {"balance_version": DOCUMENT_VERSION, "samples": first.samples,
                "max_order": first.max_order, "engines": [b.to_dict() for b in self.balances]}
