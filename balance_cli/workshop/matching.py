"""balance match: which weighed piston and rod go in which cylinder, so that the engine as
assembled shakes least; what that leaves, against the parts fitted in the order given."""

import time
from dataclasses import dataclass

import numpy as np

from .. import checks
from ..analysis.results import EngineResult, analyse
from ..analysis.shaking import DEFAULT_MAX_ORDER, DEFAULT_SAMPLES, Shaking, check_settings
from ..errors import AnalysisError
from ..harmonics import orders_of
from ..model import Engine
from ..output import DOCUMENT_VERSION
from ..tabular import Tabular
from .assembly import Fit, assembled, at_means, check_fits, deviations
from .assign import DEFAULT_LIMIT, DEFAULT_RESTARTS, Problem, exhaustive
from .assign import heuristic as descend
from .basis import unit_basis
from .objective import MatchObjective, match_objective
from .parts import PartSet, as_parts
from .symmetry import symmetries

__all__ = ["match", "MatchResult", "Fitting"]


@dataclass(frozen=True)
class Fitting(Tabular):
    """One assignment of the parts and what it leaves.

    Attributes
    ----------
    label : str
        "best" (the matching's) or "given" (the parts in the order given: the first listed
        in the cylinder of the lowest number, and so on)
    fit : Fit
    pistons, rods : tuple of str or None
        the id of the piston and of the rod in each cylinder, in the order of
        ``Engine.cylinders`` (None where that kind is not fitted)
    score_n : float
        the objective's value, N
    largest_force_n, largest_moment_nm : float
        of what the parts' deviations add (the engine as assembled minus the same engine with
        every part at the mean of its kind): the largest resultant force and free moment over
        a revolution, all orders, N and N·m
    difference : Shaking
        that difference, order by order
    assembled : EngineResult
        the engine as assembled, analysed as ``compare`` analyses it
    """

    label: str
    fit: Fit
    pistons: tuple | None
    rods: tuple | None
    score_n: float
    largest_force_n: float
    largest_moment_nm: float
    difference: Shaking
    assembled: EngineResult

    @property
    def engine(self) -> Engine:
        return self.assembled.engine

    def cylinder_rows(self) -> list:
        """One dict per cylinder: ``cylinder``, ``throw``, ``piston``, ``rod`` (ids or None),
        ``reciprocating_kg`` and its throw's ``rotating_kg`` as assembled."""
        engine = self.engine
        return [
            {
                "cylinder": c.number,
                "throw": c.throw,
                "piston": None if self.pistons is None else self.pistons[i],
                "rod": None if self.rods is None else self.rods[i],
                "reciprocating_kg": c.reciprocating_kg,
                "rotating_kg": engine.rotating_of(c.throw_index),
            }
            for i, c in enumerate(engine.cylinders)
        ]

    def records(self) -> list:
        """:meth:`cylinder_rows`, each with ``fitting`` (the label) first."""
        return [{"fitting": self.label, **row} for row in self.cylinder_rows()]

    def to_dict(self) -> dict:
        engine = self.engine
        return {
            "fitting": self.label,
            "score_N": self.score_n,
            "largest_force_N": self.largest_force_n,
            "largest_moment_Nm": self.largest_moment_nm,
            "cylinders": self.cylinder_rows(),
            "difference_orders": self.difference.records(engine),
            "assembled": self.assembled.to_dict(),
        }


@dataclass(frozen=True)
class MatchResult(Tabular):
    """What :func:`match` found.

    Attributes
    ----------
    engine : Engine
        the engine as configured
    parts : PartSet
    objective : MatchObjective
    method : str
        "exhaustive" (every assignment evaluated, one per symmetry class: the best is
        proved) or "heuristic" (descent by exchanges from several starts: not proved)
    assignments_total, assignments_distinct : int
        every assignment, and the classes the symmetries leave
    symmetries : int
        the order of the symmetry group (1: none found)
    evaluated : int
        assignments scored
    best, given : Fitting
        the best assignment, and the parts in the order given
    elapsed_s : float
    samples, max_order : int
    """

    engine: Engine
    parts: PartSet
    objective: MatchObjective
    method: str
    assignments_total: int
    assignments_distinct: int
    symmetries: int
    evaluated: int
    best: Fitting
    given: Fitting
    elapsed_s: float
    samples: int
    max_order: int

    @property
    def exhaustive(self) -> bool:
        return self.method == "exhaustive"

    @property
    def gain_n(self) -> float:
        """How much the matching lowered the score from the order given, N."""
        return self.given.score_n - self.best.score_n

    @property
    def ratio(self) -> float | None:
        """The best score over the given order's (None when that is zero)."""
        return self.best.score_n / self.given.score_n if self.given.score_n else None

    def records(self) -> list:
        """One row per cylinder of the best assignment, then of the order given (``fitting``
        tells them apart): see :meth:`Fitting.cylinder_rows`."""
        return self.best.records() + self.given.records()

    def to_dict(self) -> dict:
        """What ``balance match --format json`` writes."""
        return {
            "balance_version": DOCUMENT_VERSION,
            "engine": self.engine.name,
            "config": self.engine.config_path,
            "parts": self.parts.source,
            "kinds": list(self.parts.kinds),
            "samples": self.samples,
            "max_order": self.max_order,
            **self.objective.to_dict(),
            "method": self.method,
            "exhaustive": self.exhaustive,
            "assignments_total": self.assignments_total,
            "assignments_distinct": self.assignments_distinct,
            "symmetries": self.symmetries,
            "evaluated": self.evaluated,
            "elapsed_s": self.elapsed_s,
            "gain_N": self.gain_n,
            "ratio": self.ratio,
            "best": self.best.to_dict(),
            "given": self.given.to_dict(),
        }


def _fitting(label, engine, parts, fit, basis, rows, objective, samples, max_order, name):
    """One assignment's figures: its difference, exactly, and the engine as assembled."""
    pistons, pins = rows
    reciprocating, rotating = deviations(engine, parts, fit)
    force = reciprocating @ basis.force[pistons] + rotating @ basis.force[pins]
    moment = reciprocating @ basis.moment[pistons] + rotating @ basis.moment[pins]
    grid = match_objective(None, engine, samples, max_order) if objective.terms else objective
    over = grid.channels(force, moment)
    half = over.shape[-1] // 2
    built = assembled(engine, parts, fit, name)
    return Fitting(
        label=label,
        fit=fit,
        pistons=None if fit.pistons is None else tuple(parts.pistons[i].id for i in fit.pistons),
        rods=None if fit.rods is None else tuple(parts.rods[i].id for i in fit.rods),
        score_n=float(objective.score(objective.channels(force, moment))),
        largest_force_n=float(np.abs(over[:half]).max()),
        largest_moment_nm=float(np.abs(over[half:]).max()) * grid.pitch_m,
        difference=Shaking.from_coefficients(force, moment, max_order),
        assembled=analyse(built, samples, max_order),
    )


def _group(engine, basis, rows, parts, rests, goal, samples):
    """The symmetries of the matching: of the cylinders' responses (their crank pins' too
    where rods are fitted or the throws' own rotating masses differ), that leave the masses
    not matched where they are."""
    pistons, pins = rows
    rest, rest_pins = rests
    throws = np.array([c.throw_index for c in engine.cylinders])
    scale = max(float(np.abs(rest).max()), float(np.abs(rest_pins).max()), 1e-300)
    pins_matter = bool(parts.rods) or float(np.ptp(rest_pins)) > 1e-12 * scale
    stacks_f, stacks_m = [basis.force[pistons]], [basis.moment[pistons]]
    if pins_matter:
        stacks_f.append(basis.force[pins])
        stacks_m.append(basis.moment[pins])
    orders = np.tile(orders_of(samples).astype(int), len(stacks_f))
    group = symmetries(np.hstack(stacks_f), np.hstack(stacks_m), orders, goal.shift_ok)
    tolerance = 1e-12 * max(scale, 1.0)
    return [
        p
        for p in group
        if np.abs(rest[p] - rest).max() <= tolerance
        and np.abs(rest_pins[throws[p]] - rest_pins[throws]).max() <= tolerance
    ]


def _named(engine, words):
    room = 120 - len(words)
    return engine.name[:room] + words


def match(
    engine: Engine,
    parts,
    objective=None,
    limit: int = DEFAULT_LIMIT,
    heuristic: bool | None = None,
    restarts: int = DEFAULT_RESTARTS,
    seed: int = 0,
    samples: int = DEFAULT_SAMPLES,
    max_order: int = DEFAULT_MAX_ORDER,
    progress=None,
) -> MatchResult:
    """The assignment of weighed pistons and rods to the cylinders of ``engine`` that leaves
    the least, and what it leaves beside the parts fitted in the order given.

    Parameters
    ----------
    engine : Engine
        its masses are the engine's with every part at the mean mass of its kind (see
        :mod:`balance_cli.workshop.assembly` for how the parts replace them)
    parts : PartSet or path
        the pistons and rods, or a parts file (``kind,id,mass``); one of a kind per cylinder
    objective : str, sequence of Term or None
        None: of what the parts' deviations add, the largest resultant force over a
        revolution plus the largest free moment over the mean throw pitch, N (Tanaka's Part I
        § 5 measure); or F and M terms as :func:`balance_cli.search` reads them, in newtons
        (moments over the pitch), with weights
    limit : int
        the most assignments an exhaustive matching evaluates
    heuristic : bool or None
        True: the heuristic; False: exhaustive, an error beyond ``limit``; None (default):
        exhaustive within ``limit``, the heuristic beyond
    restarts, seed : int
        the heuristic's random starts and their seed
    samples, max_order : int
        as for :func:`~balance_cli.analyse`
    progress : callable, optional
        called with (done, total) as the work goes on

    Raises
    ------
    AnalysisError
        naming the parameter: parts that do not fit (a number other than the cylinders', rods
        on master and link rods, opposed pistons), an objective that cannot be read, an
        exhaustive matching asked beyond ``limit``
    ConfigError
        a parts file that cannot be read, naming its line
    """
    start = time.perf_counter()
    checks.instance(engine, Engine, "engine", hint=" (balance.load gives one)")
    check_settings(samples, max_order)
    limit = checks.whole(limit, "limit", 1, 10**15)
    restarts = checks.whole(restarts, "restarts", 0, 100_000)
    seed = checks.whole(seed, "seed", 0, 2**63 - 1)
    if heuristic not in (None, True, False):
        raise AnalysisError(f"must be True, False or None, got {heuristic!r}", "heuristic")
    parts = as_parts(parts)
    check_fits(engine, parts)
    goal = match_objective(objective, engine, samples, max_order)
    basis = unit_basis(engine, samples, max_order)
    piston_rows, pin_rows = basis.rows("piston"), basis.rows("pin")
    pistons = [piston_rows[c.number] for c in engine.cylinders]
    pins = [pin_rows[c.throw_index] for c in engine.cylinders]
    throw_pins = [pin_rows[i] for i in range(len(engine.throws))]
    unit = goal.channels(basis.force[pistons], basis.moment[pistons])
    pin = goal.channels(basis.force[pins], basis.moment[pins])
    rest, rest_pins = at_means(engine, parts)
    offset = rest @ unit + rest_pins @ goal.channels(
        basis.force[throw_pins], basis.moment[throw_pins]
    )
    group = _group(engine, basis, (pistons, pins), parts, (rest, rest_pins), goal, samples)

    def centred(values):
        values = np.asarray(values, float)
        return values - values.mean()

    problem = Problem(
        pistons=centred([p.mass_kg for p in parts.pistons]) if parts.pistons else None,
        small=centred([r.small_end_kg for r in parts.rods]) if parts.rods else None,
        big=centred([r.big_end_kg for r in parts.rods]) if parts.rods else None,
        unit=unit,
        pin=pin,
        offset=offset,
        objective=goal,
        group=group,
    )
    use_heuristic = problem.distinct > limit if heuristic is None else heuristic
    if not use_heuristic and problem.distinct > limit:
        raise AnalysisError(
            f"is {limit:,}, but an exhaustive matching evaluates {problem.distinct:,} "
            "assignments; raise it or take the heuristic",
            "limit",
        )
    if use_heuristic:
        found = descend(problem, restarts, seed, progress)
    else:
        found = exhaustive(problem, progress)
    order = sorted(range(engine.n_cylinders), key=lambda i: engine.cylinders[i].number)
    listed = tuple(int(k) for k in np.argsort(order))
    given_fit = Fit(listed if parts.pistons else None, listed if parts.rods else None)
    best_fit = Fit(found.sigma, found.rho)
    rows = (pistons, throw_pins)
    common = (engine, parts)
    best = _fitting(
        "best",
        *common,
        best_fit,
        basis,
        rows,
        goal,
        samples,
        max_order,
        _named(engine, ", as matched"),
    )
    given = _fitting(
        "given",
        *common,
        given_fit,
        basis,
        rows,
        goal,
        samples,
        max_order,
        _named(engine, ", parts as given"),
    )
    return MatchResult(
        engine=engine,
        parts=parts,
        objective=goal,
        method="exhaustive" if found.exhaustive else "heuristic",
        assignments_total=problem.total,
        assignments_distinct=problem.distinct,
        symmetries=len(group),
        evaluated=found.evaluated,
        best=best,
        given=given,
        elapsed_s=time.perf_counter() - start,
        samples=samples,
        max_order=max_order,
    )
