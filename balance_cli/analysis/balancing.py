"""What balancing proposes and leaves: correction planes, counterweights, balancer shafts,
the antivibrateur, rolling moments, and the result of :func:`~balance_cli.counterweights`."""

import math
import numbers
from dataclasses import dataclass

from ..errors import CounterweightError, UnitError
from ..model import Engine
from ..output import DOCUMENT_VERSION
from ..tabular import Tabular, prefixed
from ..units import check_finite_range, phasor_deg, rad_s_to_rpm
from .shaking import DEFAULT_SAMPLES, Shaking

__all__ = [
    "Plane",
    "Counterweight",
    "Shaft",
    "ShaftMass",
    "BalancerShaft",
    "RollingMoment",
    "Antivibrateur",
    "Balance",
    "Balances",
    "built_weight_record",
    "positive_length",
]


@dataclass(frozen=True)
class Plane:
    """A correction plane: axial position, m, and the number of the throw it sits on, if any
    (``Plane(z_m)`` names an axial position; :func:`~balance_cli.counterweights` puts it on the
    throw that sits there)."""

    z_m: float
    throw: int | None = None

    def to_dict(self) -> dict:
        return {"z_m": self.z_m, "throw": self.throw}


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
        return {
            "z_m": self.plane.z_m,
            "throw": self.plane.throw,
            "mass_kg": self.mass_kg,
            "radius_m": self.radius_m,
            "angle_deg": self.angle_deg,
        }


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
        return {
            "order": self.order,
            "speed_ratio": self.speed_ratio,
            "mass_eccentricity_kgm": self.mass_eccentricity_kgm,
            "phase_deg": self.phase_deg,
            "z_m": self.z_m,
        }


@dataclass(frozen=True)
class ShaftMass:
    """One unbalance on a balancer shaft: m·e (kg·m), its direction from the reference axis
    (positive with rotation) when the crank angle is 0, and its axial position (m)."""

    mass_eccentricity_kgm: float
    phase_deg: float
    z_m: float

    def mass_kg(self, eccentricity_m: float) -> float:
        """The mass that gives this unbalance at ``eccentricity_m``, kg."""
        return self.mass_eccentricity_kgm / positive_length(eccentricity_m, "eccentricity_m")

    def to_dict(self) -> dict:
        return {
            "mass_eccentricity_kgm": self.mass_eccentricity_kgm,
            "phase_deg": self.phase_deg,
            "z_m": self.z_m,
        }


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

        def clean(x):
            return float(x) if abs(x) >= floor_nm else 0.0

        return cls(int(order), clean(phasor.real), clean(-phasor.imag), tuple(speed_ratios))

    @property
    def amplitude_nm(self) -> float:
        return math.hypot(self.cos_nm, self.sin_nm)

    @property
    def phase_deg(self) -> float:
        return phasor_deg(complex(self.cos_nm, self.sin_nm))

    def to_dict(self) -> dict:
        entry: dict = {
            "order": self.order,
            "cos_Nm": self.cos_nm,
            "sin_Nm": self.sin_nm,
            "amplitude_Nm": self.amplitude_nm,
            "phase_deg": self.phase_deg,
        }
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
        return {
            "speed_ratio": self.speed_ratio,
            "order": self.order,
            "turning": "with" if self.speed_ratio > 0 else "against",
            "offset_m": {"lateral": self.lateral_m, "vertical": self.vertical_m},
            "masses": [m.to_dict() for m in self.masses],
            "force_N": self.force_n,
            "rolling_moment": moment.to_dict(),
        }


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
        return {
            "mass_eccentricity_kgm": self.mass_eccentricity_kgm,
            "eccentricity_m": self.eccentricity_m,
            "mass_kg": self.mass_kg,
            "phase_deg": self.phase_deg,
        }


@dataclass(frozen=True)
class Balance(Tabular):
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

    def records(self) -> list:
        """One row per stage and order: ``engine``, ``stage`` ("original": before anything
        proposed, as the crank and what is built in it leave; "residual": after the
        counterweights; "after_shafts": after the shafts too, when they were asked for),
        ``order``, and the order's force and moment as :meth:`EngineResult.records
        <balance_cli.EngineResult.records>` gives them (``force_max_N``, ...)."""
        stages = [("original", self.original), ("residual", self.residual)]
        if self.after_shafts is not None:
            stages.append(("after_shafts", self.after_shafts))
        return [
            {
                "engine": self.engine.name,
                "stage": stage,
                "order": record["order"],
                **prefixed("force", record["force"]),
                **prefixed("moment", record["moment"]),
            }
            for stage, shaking in stages
            for record in shaking.records(self.engine)
        ]

    def to_dict(self) -> dict:
        """This engine's entry of ``counterweight --format json`` (SI units; see the JSON page)."""
        engine = self.engine

        def stage(shaking):
            # below the noise floor it is rounding, an exact zero as compare writes it
            largest = shaking.largest_force()
            return {
                "largest_resultant_N": largest if largest >= engine.noise_floor_n else 0.0,
                "orders": shaking.records(engine),
            }

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
                "counterweights": [built_weight_record(engine, w) for w in engine.counterweights],
                "balancer_shafts": [s.to_dict() for s in self.built_shafts],
                **stage(self.original),
            }
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
            raise CounterweightError(
                "has no configuration table, and the counterweights "
                "proposed include its mass; leave it out to write a "
                "configuration",
                "antivibrateur_radius_m",
            )
        engine = self.engine
        if engine.is_rotary:
            raise CounterweightError(
                "of a rotary engine cannot be written as configuration tables: its counterweights "
                "ride on the turning crankcase, and [[counterweights]] and [[shafts]] describe "
                "masses geared to a turning crank",
                "counterweights",
            )
        first = math.degrees(engine.throws[0].phase_rad)
        weights = []
        for weight in self.counterweights:
            if weight.mass_kg == 0.0:
                continue
            index = 0 if weight.plane.throw is None else weight.plane.throw - 1
            # Counterweight.angle_deg is measured from throw 1; a built one from its own throw
            angle = weight.angle_deg + first - math.degrees(engine.throws[index].phase_rad)
            weights.append(
                {
                    "throw": index + 1,
                    "mass": f"{float(weight.mass_kg)!r} kg",
                    "radius": f"{float(weight.radius_m)!r} m",
                    "angle": float(math.remainder(angle, 360.0)) + 0.0,
                    "z": f"{float(weight.plane.z_m)!r} m",
                }
            )
        tables: dict = {"counterweights": weights}
        if shafts:
            tables["shafts"] = [
                {
                    "ratio": shaft.speed_ratio,
                    "lateral": f"{float(shaft.lateral_m)!r} m",
                    "vertical": f"{float(shaft.vertical_m)!r} m",
                    # ShaftMass.phase_deg is measured with the crank; a built mass's angle in its
                    # shaft's own sense of turning
                    "masses": [
                        {
                            "mass_radius": f"{float(m.mass_eccentricity_kgm)!r} kg*m",
                            "angle": math.remainder(
                                math.copysign(1, shaft.speed_ratio) * m.phase_deg, 360.0
                            )
                            + 0.0,
                            "z": f"{float(m.z_m)!r} m",
                        }
                        for m in shaft.masses
                    ],
                }
                for shaft in self.balancer_shafts
            ]
        return tables


def built_weight_record(engine, weight) -> dict:
    """A counterweight as built, as ``counterweight --format json`` lists it under ``as_built``."""
    return {
        "throw": weight.throw,
        "mass_radius_kgm": weight.mass_radius_kgm,
        "mass_kg": weight.mass_kg,
        "radius_m": weight.radius_m,
        "angle_deg": math.degrees(weight.angle_rad),
        "z_m": engine.counterweight_z_m(weight),
    }


@dataclass(frozen=True)
class Balances(Tabular):
    """The counterweights of several engines, balanced with the same settings."""

    balances: tuple

    def __post_init__(self):
        if not self.balances:
            raise CounterweightError("needs at least one balanced engine", "balances")
        if len({(b.samples, b.max_order) for b in self.balances}) > 1:
            raise CounterweightError(
                "must all be analysed with the same samples and max_order", "balances"
            )

    def records(self) -> list:
        """Every engine's :meth:`Balance.records`, one after the other."""
        return [row for balance in self.balances for row in balance.records()]

    def to_dict(self) -> dict:
        """What ``counterweight --format json`` writes: one :meth:`Balance.to_dict` per engine."""
        first = self.balances[0]
        return {
            "balance_version": DOCUMENT_VERSION,
            "samples": first.samples,
            "max_order": first.max_order,
            "engines": [b.to_dict() for b in self.balances],
        }


def positive_length(value, parameter):
    """``value`` as a float if it is a finite length above zero in metres; CounterweightError
    naming ``parameter`` otherwise."""
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        raise CounterweightError(f"must be a length in metres, got {value!r}", parameter)
    if value <= 0:
        raise CounterweightError(f"must be greater than zero, got {value!r} m", parameter)
    try:
        check_finite_range(float(value), "length")
    except UnitError as exc:
        raise CounterweightError(f"is invalid: {exc}", parameter) from None
    return float(value)
