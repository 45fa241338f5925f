"""The analysis of one engine (shaking, firing, largest resultant) and the comparison of several."""

from collections.abc import Iterable, Sequence
from dataclasses import dataclass

import numpy as np

from .checks import instance, items
from .errors import AnalysisError
from .firing import Firing, firing_sequence
from .kinematics import check_assembly
from .model import Engine
from .shaking import DEFAULT_MAX_ORDER, DEFAULT_SAMPLES, OrderComponents, Shaking, shaking_forces
from .units import rad_s_to_rpm

__all__ = ["EngineResult", "Comparison", "analyse", "compare", "find_reference"]

#: version of the JSON documents balance writes
DOCUMENT_VERSION = 1


@dataclass(frozen=True)
class EngineResult:
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
    """

    engine: Engine
    shaking: Shaking
    firing: Firing
    samples: int
    largest_force_n: float
    counterweighted_force_n: float

    @property
    def max_order(self) -> int:
        return self.shaking.max_order

    @property
    def per_cylinder_unit_n(self) -> float:
        """m_rec·r·ω²·n, N: divide a force by it to get Part III's per-cylinder figure."""
        return self.engine.per_cylinder_unit_n

    @property
    def counterweight_cancels_first_order(self) -> bool:
        return _counterweight_cancels_first_order(self.engine)

    @property
    def counterweighted_per_cylinder(self) -> float:
        """The largest counterweighted resultant in Part III's per-cylinder units."""
        return self.counterweighted_force_n / self.per_cylinder_unit_n

    def order(self, k: int) -> OrderComponents:
        """Order ``k`` (1-based) of the forces and moments; KeyError outside 1..max_order."""
        return self.shaking.order(k)

    def counterweighted_locus(self, order: int | None = None, points: int | None = None) -> np.ndarray:
        """The resultant force over one revolution after an ideal crankshaft counterweight, N
        (complex: real along the reference axis); one order only if ``order`` is given.
        ``points`` defaults to four times the samples."""
        return self.shaking.locus(order, self.counterweight_cancels_first_order, points)

    def percent_of(self, reference: "EngineResult") -> float | None:
        """The largest counterweighted resultant as a percentage of ``reference``'s; None when
        the reference has none (it is below its noise floor)."""
        if reference.counterweighted_force_n == 0.0:
            return None
        return 100.0 * self.counterweighted_per_cylinder / reference.counterweighted_per_cylinder

    def to_dict(self, reference: "EngineResult | None" = None) -> dict:
        """This engine's entry of ``compare --format json`` (SI units; see the README).

        ``reference`` is the result the percentage refers to (default: this one, as in the
        comparison of a single engine).
        """
        engine = self.engine
        floor = engine.noise_floor_n
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
            "sampling_ok": self.shaking.sampling_ok,
            "orders": [o.to_dict(floor) for o in self.shaking.orders],
        }


def _counterweight_cancels_first_order(engine):
    """An ideal crankshaft counterweight takes the forward first order away (not on a rotary,
    whose crank does not turn)."""
    return not engine.is_rotary


def _above_floor(value, engine):
    return value if value >= engine.noise_floor_n else 0.0


def analyse(engine: Engine, samples: int = DEFAULT_SAMPLES,
            max_order: int = DEFAULT_MAX_ORDER) -> EngineResult:
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
    return EngineResult(
        engine=engine,
        shaking=shaking,
        firing=firing_sequence(engine),
        samples=samples,
        largest_force_n=_above_floor(shaking.largest_force(), engine),
        counterweighted_force_n=_above_floor(
            shaking.largest_force(skip_forward_first=_counterweight_cancels_first_order(engine)),
            engine),
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
class Comparison:
    """Several engines analysed alike, and the one the percentages refer to."""

    results: tuple
    reference_index: int

    @property
    def reference(self) -> EngineResult:
        return self.results[self.reference_index]

    @property
    def samples(self) -> int:
        return self.results[0].samples

    @property
    def max_order(self) -> int:
        return self.results[0].max_order

    def to_dict(self) -> dict:
        """What ``compare --format json`` writes."""
        return {
            "balance_version": DOCUMENT_VERSION,
            "samples": self.samples,
            "max_order": self.max_order,
            "reference": self.reference.engine.name,
            "engines": [r.to_dict(self.reference) for r in self.results],
        }


def compare(results: "Iterable[EngineResult]", reference: str | None = None) -> Comparison:
    """The comparison of analysed engines (:func:`analyse`, same settings); ``reference`` is
    the name (or a unique prefix) of the engine the percentages refer to, default the first."""
    results = tuple(items(results, EngineResult, "results"))
    if reference is not None and not isinstance(reference, str):
        raise AnalysisError(f"must be an engine's name (a str) or None, got {reference!r}",
                            "reference")
    names = [r.engine.name for r in results]
    twice = next((n for n in names if names.count(n) > 1), None)
    if twice is not None:
        files = ", ".join(r.engine.config_path for r in results if r.engine.name == twice)
        raise AnalysisError(f"name {twice!r} more than once ({files}): engines are told apart by "
                            "name (in percentages, regression tables, legends); give each "
                            "configuration its own name, or compare each file once", "results")
    if len({(r.samples, r.max_order) for r in results}) > 1:
        raise AnalysisError("must all be analysed with the same samples and max_order", "results")
    return Comparison(results, find_reference(results, reference))
