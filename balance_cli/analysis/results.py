"""The analysis of one engine (shaking, firing, largest resultant) and the comparison of several."""

import math
from collections.abc import Iterable, Sequence
from dataclasses import dataclass

import numpy as np

from ..checks import instance, items, positive
from ..errors import AnalysisError
from ..kinematics import check_assembly
from ..model import Engine
from ..output import DOCUMENT_VERSION
from ..tabular import Tabular, prefixed
from ..units import rad_s_to_rpm, wrap_degrees
from .firing import Firing, firing_sequence
from .marine import (
    DEFAULT_PRU_CLASSES,
    STANDARD_BALANCE,
    FirstOrderBalance,
    check_classes,
    first_order_balance,
    power_related_unbalance,
)
from .shaking import (
    DEFAULT_MAX_ORDER,
    DEFAULT_SAMPLES,
    OrderComponents,
    Shaking,
    part_values,
    shaking_forces,
)

__all__ = ["EngineResult", "Comparison", "analyse", "compare", "find_reference"]


#: an ellipse's axis within this of the vertical or the horizontal is called so in words
_DIRECTION_WORD_DEG = 1.0
#: an ellipse whose min is at least this fraction of its max is called nearly rotating: its
#: axis barely matters to the mounts
_NEARLY_ROUND = 0.9


@dataclass(frozen=True)
class EngineResult(Tabular):
    """Everything ``balance compare`` reports for one engine.

    Attributes
    ----------
    engine : Engine
    shaking : Shaking
        forces (N) and free moments (N·m), order by order
    firing : Firing
    samples : int
        crank angles a revolution the analysis used
    largest_force_n : float
        largest magnitude of the resultant force over a revolution, all orders, N
    counterweighted_force_n : float
        the same once an ideal crankshaft counterweight has cancelled the forward first order
        (what Tanaka's Part III compares), N; a rotary's crank does not turn, so nothing is
        cancelled there. Both are exact zeros below the engine's noise floor.
    largest_moment_nm, counterweighted_moment_nm : float
        the same for the free moment, N·m: an ideal two-plane counterweight cancels the
        forward first-order moment too
    """

    engine: Engine
    shaking: Shaking
    firing: Firing
    samples: int
    largest_force_n: float
    counterweighted_force_n: float
    largest_moment_nm: float = 0.0
    counterweighted_moment_nm: float = 0.0

    @property
    def max_order(self) -> int:
        return self.shaking.max_order

    @property
    def per_cylinder_unit_n(self) -> float:
        """m_rec·r·ω²·n, N: divide a force by it to get Part III's per-cylinder figure."""
        return self.engine.per_cylinder_unit_n

    @property
    def counterweight_cancels_first_order(self) -> bool:
        """An ideal crankshaft counterweight takes (some of) the first order away."""
        return any(self.counterweight_cancels)

    @property
    def counterweight_cancels(self) -> tuple[bool, bool]:
        """Whether ideal crankshaft counterweights take the (forward, backward) first order
        away: the forward on any engine whose crank turns, the backward too where a crankshaft
        turns against the first (its counterweights turn backward)."""
        return _counterweight_cancels(self.engine)

    @property
    def counterweighted_per_cylinder(self) -> float:
        """The largest counterweighted resultant in Part III's per-cylinder units."""
        return self.counterweighted_force_n / self.per_cylinder_unit_n

    def order(self, k: int) -> OrderComponents:
        """Order ``k`` (1-based) of the forces and moments; KeyError outside 1..max_order."""
        return self.shaking.order(k)

    def counterweighted_locus(
        self, order: int | None = None, points: int | None = None
    ) -> np.ndarray:
        """The resultant force over one revolution after an ideal crankshaft counterweight, N
        (complex: real along the reference axis); one order only if ``order`` is given.
        ``points`` defaults to four times the samples."""
        forward, backward = self.counterweight_cancels
        return self.shaking.locus(order, forward, points, skip_backward_first=backward)

    def percent_of(self, reference: "EngineResult", absolute: bool = False) -> float | None:
        """The largest counterweighted resultant as a percentage of ``reference``'s, per
        cylinder (Tanaka's Part III) or, with ``absolute``, in newtons; None when the reference
        has none (it is below its noise floor)."""
        if reference.counterweighted_force_n == 0.0:
            return None
        if absolute:
            return 100.0 * self.counterweighted_force_n / reference.counterweighted_force_n
        return 100.0 * self.counterweighted_per_cylinder / reference.counterweighted_per_cylinder

    def main_order(self, part: str = "force") -> dict | None:
        """The order that contributes most to the counterweighted ``part`` ("force" or
        "moment"): ``order``, ``max`` (N or N·m, the ellipse's largest value, the forward first
        order left out where a counterweight takes it), ``axis_deg`` (None: it turns) and
        ``direction`` in words: "rotating forward" or "rotating backward" for a circle (and
        "nearly rotating ..." when min ≥ 0.9·max), else "vertical", "horizontal" or "+30° from
        vertical" (positive with rotation; for a moment "pitching", "yawing", "+30° from
        pitching"). None when nothing is left."""
        if part not in ("force", "moment"):
            raise AnalysisError(f'must be "force" or "moment", got {part!r}', "part")
        engine = self.engine
        unit = "N" if part == "force" else "Nm"
        floor = engine.noise_floor_n if part == "force" else engine.noise_floor_nm
        best = None
        records = self.order_records()
        skip_forward, skip_backward = self.counterweight_cancels
        for o in self.shaking.orders:
            if o.order == 1 and (skip_forward or skip_backward):
                forward = o.force_forward if part == "force" else o.moment_forward
                backward = o.force_backward if part == "force" else o.moment_backward
                values = part_values(
                    0j if skip_forward else forward,
                    0j if skip_backward else backward,
                    floor,
                    unit,
                    engine.vertical_axis_rad,
                )
            else:
                values = records[o.order - 1][part]
            if values[f"max_{unit}"] > (best["max"] if best else 0.0):
                best = {
                    "order": o.order,
                    "max": values[f"max_{unit}"],
                    "axis_deg": values["axis_deg"],
                    "min": values[f"min_{unit}"],
                    "sense": "forward"
                    if values[f"forward_{unit}"] >= values[f"backward_{unit}"]
                    else "backward",
                }
        if best is None:
            return None
        best["direction"] = _direction_words(best, engine.vertical_axis_rad, part)
        del best["min"], best["sense"]
        return best

    def order_records(self) -> list:
        """The orders' JSON records (``orders`` of ``compare --format json``), made once: the
        summary and the PRU read them too. Shared: copy before changing one."""
        cached = self.__dict__.get("_order_records")
        if cached is None:
            cached = self.shaking.records(self.engine)
            object.__setattr__(self, "_order_records", cached)
        return cached

    def records(self) -> list:
        """One row per order 1..max_order, zero orders too: ``engine`` (its name), ``order``,
        then the order's force and moment as ``compare --format json`` gives them, with
        ``force_`` and ``moment_`` before each key: ``force_forward_N``, ``force_forward_deg``,
        ``force_max_N``, ``force_axis_deg``, ``moment_vertical_Nm``, ... (N, N·m, degrees)."""
        return [
            {
                "engine": self.engine.name,
                "order": record["order"],
                **prefixed("force", record["force"]),
                **prefixed("moment", record["moment"]),
            }
            for record in self.order_records()
        ]

    def power_related_unbalance(
        self, power_w: float | None = None, orders=(1, 2), classes=None, balance=STANDARD_BALANCE
    ):
        """The power related unbalance of this engine (:mod:`balance_cli.analysis.marine`): a
        :class:`~balance_cli.analysis.marine.PowerRelatedUnbalance` (``available`` False, with
        its ``note``, without a power); ``balance`` the first order's (default the project
        guides' standard balance)."""
        return power_related_unbalance(
            self, power_w, orders, classes or DEFAULT_PRU_CLASSES, balance
        )

    def to_dict(
        self,
        reference: "EngineResult | None" = None,
        pru_classes=None,
        pru_orders=(1, 2),
        pru_balance=STANDARD_BALANCE,
        power_w: float | None = None,
    ) -> dict:
        """This engine's entry of ``compare --format json`` (SI units; see the JSON page).

        ``reference`` is the result the percentage refers to (default: this one, as in the
        comparison of a single engine); ``pru_classes`` the bounds of the power related
        unbalance's classes (default the project guides'), ``pru_orders`` the orders it
        judges, ``pru_balance`` the first order's balance (default the guides' standard) and
        ``power_w`` the power (W) at the speed analysed that the power related unbalance
        refers to instead of the engine's own (its ``power_source`` is then "option").
        """
        pru = self.power_related_unbalance(
            power_w, orders=pru_orders, classes=pru_classes, balance=pru_balance
        )
        engine = self.engine
        return {
            "name": engine.name,
            "config": engine.config_path,
            "source": engine.source,
            "cylinders": engine.n_cylinders,
            "cycle": engine.cycle,
            "frame": engine.frame,
            "speed_rpm": rad_s_to_rpm(engine.speed_rad_s),
            "unit_force_N": engine.unit_force_n,
            "firing": self.firing.to_dict(),
            "largest_resultant_N": self.largest_force_n,
            "counterweighted_resultant_N": self.counterweighted_force_n,
            "counterweighted_resultant_per_cylinder": self.counterweighted_per_cylinder,
            "percent_of_reference": self.percent_of(reference or self),
            "percent_of_reference_absolute": self.percent_of(reference or self, absolute=True),
            "vertical_deg": wrap_degrees(math.degrees(engine.vertical_axis_rad)),
            "noise_floor_N": engine.noise_floor_n,
            "noise_floor_Nm": engine.noise_floor_nm,
            "largest_moment_Nm": self.largest_moment_nm,
            "counterweighted_moment_Nm": self.counterweighted_moment_nm,
            "main_force_order": _main_record(self.main_order("force"), "N"),
            "main_moment_order": _main_record(self.main_order("moment"), "Nm"),
            "power_kW": pru.power.kilowatts if pru.available else None,
            "pru": pru.to_dict() if pru.available else None,
            "pru_note": pru.note,
            "sampling_ok": self.shaking.sampling_ok,
            # the cached records are flat dicts in a dict: a copy two levels deep is a copy
            "orders": [
                {k: dict(v) if isinstance(v, dict) else v for k, v in record.items()}
                for record in self.order_records()
            ],
        }


def _counterweight_cancels(engine):
    """(forward, backward): ideal counterweights in two planes of a crankshaft turning with
    the first make any forward first-order force and couple, and of one turning against it
    any backward one; a rotary's crank does not turn."""
    if engine.is_rotary:
        return False, False
    return True, any(s.direction == -1 for s in engine.crankshafts)


def _above_floor(value, floor):
    return value if value >= floor else 0.0


def _main_record(main, unit):
    """``main_order``'s entry in JSON: its ``max`` with the unit in the key."""
    if main is None:
        return None
    return {
        "order": main["order"],
        f"max_{unit}": main["max"],
        "axis_deg": main["axis_deg"],
        "direction": main["direction"],
    }


def _direction_words(main, vertical_rad, part):
    """An order's ellipse in words: turning (and which way) when it is a circle or nearly one,
    else its axis from the engine's vertical."""
    axis_deg = main["axis_deg"]
    if axis_deg is None:
        return f"rotating {main['sense']}"
    if main["min"] >= _NEARLY_ROUND * main["max"]:
        return f"nearly rotating {main['sense']}"
    off = (axis_deg - math.degrees(vertical_rad)) % 180.0
    names = ("vertical", "horizontal") if part == "force" else ("pitching", "yawing")
    if min(off, 180.0 - off) <= _DIRECTION_WORD_DEG:
        return names[0]
    if abs(off - 90.0) <= _DIRECTION_WORD_DEG:
        return names[1]
    # the axis measured from the vertical the short way, positive with rotation
    signed = off if off <= 90.0 else off - 180.0
    return f"{signed:+.0f}° from {names[0]}"


def analyse(
    engine: Engine, samples: int = DEFAULT_SAMPLES, max_order: int = DEFAULT_MAX_ORDER
) -> EngineResult:
    """Shaking forces and moments, firing and largest resultant of ``engine``.

    Parameters
    ----------
    engine : Engine
    samples : int
        crank angles a revolution for the Fourier analysis (any number from 4·max_order + 1)
    max_order : int
        highest order analysed

    Raises
    ------
    AnalysisError
        ``samples`` or ``max_order`` out of range
    ModelError
        a linkage that cannot be assembled
    FiringError
        the engine's ``firing_order`` cannot be fired on its crank

    Warns
    -----
    SamplingWarning
        the highest orders still carry energy, so ``samples`` are too few
    """
    instance(engine, Engine, "engine", hint=" (balance.load gives one)")
    check_assembly(engine)
    shaking = shaking_forces(engine, samples, max_order)
    forward, backward = _counterweight_cancels(engine)
    return EngineResult(
        engine=engine,
        shaking=shaking,
        firing=firing_sequence(engine),
        samples=samples,
        largest_force_n=_above_floor(shaking.largest_force(), engine.noise_floor_n),
        counterweighted_force_n=_above_floor(
            shaking.largest_force(forward, backward), engine.noise_floor_n
        ),
        largest_moment_nm=_above_floor(shaking.largest_moment(), engine.noise_floor_nm),
        counterweighted_moment_nm=_above_floor(
            shaking.largest_moment(forward, backward), engine.noise_floor_nm
        ),
    )


def find_reference(results: "Sequence[EngineResult]", name: str | None) -> int:
    """Index of the reference engine among ``results``: by name (exact, else a unique
    case-insensitive prefix); the first when ``name`` is None."""
    if name is None:
        return 0
    names = [r.engine.name for r in results]
    if name in names:
        return names.index(name)
    matches = [n for n in names if n.lower().startswith(name.lower())]
    if len(matches) == 1:
        return names.index(matches[0])
    if matches:
        problem = f"{name!r} matches several engines: {'; '.join(matches)}; give more of the name"
    else:
        problem = f"{name!r} matches no engine; choose one of: {'; '.join(names)}"
    raise AnalysisError(problem, "reference")


@dataclass(frozen=True)
class Comparison(Tabular):
    """Several engines analysed alike, and the one the percentages refer to."""

    results: tuple
    reference_index: int
    pru_classes: tuple | None = None
    pru_orders: tuple = (1, 2)
    pru_balance: FirstOrderBalance = STANDARD_BALANCE
    #: the power (W) every engine's power related unbalance refers to, instead of its own
    power_w: float | None = None

    @property
    def reference(self) -> EngineResult:
        return self.results[self.reference_index]

    @property
    def samples(self) -> int:
        return self.results[0].samples

    @property
    def max_order(self) -> int:
        return self.results[0].max_order

    def records(self) -> list:
        """Every engine's :meth:`EngineResult.records`, one after the other (``engine`` tells
        them apart)."""
        return [row for result in self.results for row in result.records()]

    def to_dict(self) -> dict:
        """What ``compare --format json`` writes."""
        return {
            "balance_version": DOCUMENT_VERSION,
            "samples": self.samples,
            "max_order": self.max_order,
            "reference": self.reference.engine.name,
            "engines": [
                r.to_dict(
                    self.reference,
                    self.pru_classes,
                    self.pru_orders,
                    self.pru_balance,
                    self.power_w,
                )
                for r in self.results
            ],
        }


def compare(
    results: "Iterable[EngineResult]",
    reference: str | None = None,
    pru_classes=None,
    pru_orders=None,
    pru_balance=STANDARD_BALANCE,
    power_w: float | None = None,
) -> Comparison:
    """The comparison of analysed engines (:func:`analyse`, same settings); ``reference`` is
    the name (or a unique prefix) of the engine the percentages refer to, default the first;
    ``pru_classes`` the bounds of the power related unbalance's classes (N·m/kW; default the
    project guides' 60, 120, 220), ``pru_orders`` the orders it judges (default 1 and
    2, those analysed), ``pru_balance`` the first order's balance: "standard" (default:
    the project guides', counterweights for the rotating masses and half the reciprocating
    ones), "rotating", "crank" or a balance factor from 0 to 1; ``power_w`` the engines' power
    at the speed analysed (W), which the power related unbalance refers to instead of each
    engine's own (``compare --power``)."""
    results = tuple(items(results, EngineResult, "results"))
    if power_w is not None:
        power_w = positive(power_w, "power_w", "power")
    if reference is not None and not isinstance(reference, str):
        raise AnalysisError(
            f"must be an engine's name (a str) or None, got {reference!r}", "reference"
        )
    names = [r.engine.name for r in results]
    twice = next((n for n in names if names.count(n) > 1), None)
    if twice is not None:
        files = ", ".join(r.engine.config_path for r in results if r.engine.name == twice)
        raise AnalysisError(
            f"name {twice!r} more than once ({files}): engines are told apart by "
            "name (in percentages, regression tables, legends); give each "
            "configuration its own name, or compare each file once",
            "results",
        )
    if len({(r.samples, r.max_order) for r in results}) > 1:
        raise AnalysisError("must all be analysed with the same samples and max_order", "results")
    if pru_classes is not None:
        pru_classes = check_classes(pru_classes)
    if pru_orders is None:
        pru_orders = tuple(k for k in (1, 2) if k <= results[0].max_order)
    # an order asked twice is judged once
    pru_orders = (
        tuple(dict.fromkeys(pru_orders)) if isinstance(pru_orders, (list, tuple)) else pru_orders
    )
    if (
        not isinstance(pru_orders, tuple)
        or not pru_orders
        or not all(
            isinstance(k, int) and not isinstance(k, bool) and 1 <= k <= results[0].max_order
            for k in pru_orders
        )
    ):
        raise AnalysisError(
            f"must be orders from 1 to {results[0].max_order}, got {pru_orders!r}", "pru_orders"
        )
    pru_balance = first_order_balance(pru_balance)
    return Comparison(
        results, find_reference(results, reference), pru_classes, pru_orders, pru_balance, power_w
    )
