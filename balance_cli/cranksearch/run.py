"""The crank search itself: :func:`search` checks its arguments, builds the problem, runs the
exhaustive enumeration (local processes or a Dask cluster) or the heuristic, and lists the best.
"""

from __future__ import annotations

import itertools
import math
import os
import time
from collections.abc import Callable, Sequence
from dataclasses import replace

import numpy as np

from ..analysis.shaking import DEFAULT_MAX_ORDER, DEFAULT_SAMPLES, check_settings
from ..errors import AnalysisError
from ..kinematics.linkage import check_assembly
from ..model import Engine, Throw
from .final import final
from .firing import firing_orders, reversed_order

# under their former names: search has parameters and locals named as the functions are
from .heuristic import heuristic_search
from .kernel import SCORE_TIE, Pool, evaluate, work_units
from .lattice import bank_followers, check_mirror, check_reversal, lattice
from .objective import Term, check_terms, parse_objective
from .parallel import Reduction, run_cluster, run_local
from .problem import (
    Problem,
    guide_couple_units,
    guide_phasors,
    mean_pitch,
    merge_channels,
    minor_orders,
    objective_channels,
    order_units,
    throw_phasors,
    torsion_phasors,
)
from .query import evaluate_units
from .results import SearchResult
from .tables import build_tables, count_cranks
from .units import plan_units

__all__ = ["search", "DEFAULT_TOP", "MAX_TOP", "DEFAULT_LIMIT", "MAX_WORKERS"]

DEFAULT_TOP = 10
#: more arrangements than this are not listed: each is analysed as compare analyses it (about
#: 5 ms and 110 kB apiece, measured on an in-line 10), so 1000 take seconds and 110 MB where
#: the 100 000 once accepted grew past 7 GB
MAX_TOP = 1000
#: an exhaustive search covering more arrangements than this is refused: where the bound
#: prunes nothing, about a minute on two cores (2e7 pairs a second a core for ten channels);
#: the in-line 14's 1.6e9 take 1.5 s for M1,M2,M3,M4 and for every F_k and M_k alike.
#: --limit raises it, --heuristic or a cluster are the alternatives
DEFAULT_LIMIT = 2_000_000_000
#: more processes than this are refused (each costs memory and start-up)
MAX_WORKERS = 1024


def search(
    template: Engine,
    objective: str | Sequence[Term] | None = None,
    top: int = DEFAULT_TOP,
    allow_uneven: bool = False,
    step_deg: float | None = None,
    workers: int | None = None,
    scheduler=None,
    heuristic: bool = False,
    restarts: int = 200,
    seed: int = 0,
    limit: int = DEFAULT_LIMIT,
    samples: int = DEFAULT_SAMPLES,
    max_order: int = DEFAULT_MAX_ORDER,
    progress: Callable[[int, int], None] | None = None,
    client=None,
    enumeration: str = "streamed",
    even_banks: bool = False,
) -> SearchResult:
    """The best crank arrangements and firing orders of ``template``.

    Parameters
    ----------
    template : Engine
        its throw phases and firing order are ignored (see
        :func:`balance_cli.config.load_template`); a fixed frame, two or more throws
    objective : str or sequence of Term or None
        such as ``"F2:4,M1,M2"`` (:func:`parse_objective`); None: every F_k and M_k
    top : int
        how many arrangements to list (ties with the last are ranked by firing order)
    allow_uneven, step_deg : bool, float
        search every crank on a grid of ``step_deg`` degrees, firing or not evenly
    even_banks : bool
        every bank fires evenly on its own, the banks a fixed angle apart (each cylinder of
        banks 2, 3, ... the bank angle after the cylinder of bank 1 on its throw): the
        medium-speed V engines' rule, whose bank angle seldom lets the whole engine fire
        evenly (a 50° V12's intervals alternate 50° and 70°); needs one cylinder of each bank
        on every throw
    workers : int or None
        processes (None: every core)
    scheduler : str or None
        a Dask scheduler address (``tcp://host:8786``) to run the exhaustive search on
        instead (a Client is taken too, as ``client``)
    client : distributed.Client or None
        a Dask client to run the exhaustive search on (yours: it is left open)
    heuristic : bool
        a local search (``restarts`` random starts, ``seed``), not proved optimal
    limit : int
        refuse an exhaustive search that would evaluate more cranks than this
    samples, max_order : int
        as for :func:`balance_cli.analysis.results.analyse`
    progress : callable(done, total) or None
        called as work completes
    enumeration : str
        "streamed" (default): the parent plans work units (the lattice points the first
        half fills) and each worker enumerates its own, in the memory of one unit;
        "tabled": every prefix and suffix tabled at once in the parent and sent whole to
        the workers (the former method, gigabytes for an in-line 14, kept as a cross-check)

    Raises
    ------
    AnalysisError
        naming ``template``, ``objective``, ``top``, ``step_deg``, ``workers``, ``limit``,
        ``scheduler``, ``client`` or ``enumeration``
    """
    started = time.perf_counter()
    check_settings(samples, max_order)
    if workers is None:
        workers = os.cpu_count() or 1
    for name, value, low, high in (
        ("top", top, 1, MAX_TOP),
        ("restarts", restarts, 1, 1_000_000),
        ("limit", limit, 1, 10**15),
        ("seed", seed, 0, 2**63 - 1),
        ("workers", workers, 1, MAX_WORKERS),
    ):
        if (
            isinstance(value, bool)
            or not isinstance(value, (int, np.integer))
            or not low <= value <= high
        ):
            raise AnalysisError(
                f"must be a whole number from {low:,} to {high:,}, got {value!r}", name
            )
    top, restarts, limit, seed, workers = map(int, (top, restarts, limit, seed, workers))
    if not isinstance(even_banks, (bool, np.bool_)):
        raise AnalysisError(f"must be True or False, got {even_banks!r}", "even_banks")
    if even_banks and allow_uneven:
        raise AnalysisError(
            "asks for even firing within each bank, allow_uneven for any firing: leave out "
            "one of the two",
            "even_banks",
        )
    if enumeration not in ("streamed", "tabled"):
        raise AnalysisError(f"must be 'streamed' or 'tabled', got {enumeration!r}", "enumeration")
    cluster, cluster_name = _cluster_of(scheduler, client)
    if heuristic and cluster is not None:
        raise AnalysisError(
            "applies to the exhaustive search, but the heuristic search runs in "
            "this process: leave out one of the two",
            cluster_name,
        )
    if isinstance(objective, str) or objective is None:
        terms = parse_objective(objective, max_order)
    elif isinstance(objective, Term):
        terms = (objective,)
    else:
        try:
            terms = tuple(objective)
        except TypeError:
            raise AnalysisError(
                f"must be a string such as 'M1,M2' or Terms, got {objective!r}", "objective"
            ) from None
    check_terms(terms, max_order)
    if not isinstance(template, Engine):
        raise AnalysisError(
            f"must be an Engine (balance.load_template gives one), got {type(template).__name__}",
            "template",
        )
    if progress is not None and not callable(progress):
        raise AnalysisError(f"must be a callable(done, total), got {progress!r}", "progress")
    if template.is_rotary:
        raise AnalysisError(
            "is a rotary engine: its crank does not turn, so there are no throw "
            "phases to arrange; search a fixed-frame template",
            "template",
        )
    if template.has_several_crankshafts:
        raise AnalysisError(
            f"has {len(template.crankshafts)} crankshafts; the search arranges "
            "the throws of one crankshaft: give a template with one",
            "template",
        )
    if template.counterweights or template.balancer_shafts:
        # a counterweight is sized for one crank and a shaft's force does not turn with the
        # throws: the per-throw phasor sums would score a different engine than the one found
        raise AnalysisError(
            "has counterweights or balancer shafts as built; they belong to one "
            "arrangement, which the search is to choose: remove the "
            "[[counterweights]] and [[shafts]] tables from the template",
            "template",
        )
    n = len(template.throws)
    if n < 2:
        raise AnalysisError(
            "has one throw: with throw 1 at 0° there is nothing to arrange; give "
            "the template two or more [[throws]]",
            "template",
        )
    if any(not any(c.throw_index == j for c in template.cylinders) for j in range(n)):
        empty = next(j for j in range(n) if not any(c.throw_index == j for c in template.cylinders))
        raise AnalysisError(
            f"has no cylinder on throw {empty + 1}; remove the throw or give it a cylinder",
            "template",
        )
    flat = replace(
        template, throws=tuple(Throw(0.0, t.z_m) for t in template.throws), firing_order=None
    )
    check_assembly(flat)
    phasors = throw_phasors(flat, samples, max_order)
    units = order_units(phasors, flat.noise_floor_n)
    pitch = mean_pitch(flat)
    couple_units = torsion_units = None
    if any(term.kind in ("H", "X") for term in terms):
        guide = guide_phasors(flat, samples, max_order)
        couple_units = guide_couple_units(guide, flat.noise_floor_n * flat.crank_radius_m)
        phasors = np.concatenate([phasors, guide])
    tv_orders = ()
    if any(term.kind in ("V", "TV") for term in terms):
        if flat.torsion is None:
            raise AnalysisError(
                "has no [torsion] table: a V term needs the shaft line's first mode", "template"
            )
        if couple_units is None:
            phasors = np.concatenate([phasors, np.zeros((2,) + phasors.shape[1:], complex)])
        torsional, torsion_units = torsion_phasors(flat, samples, max_order)
        # the same scale as the forces', so that the symmetry checks' floor reads alike
        phasors = np.concatenate([phasors, torsional * units.max()])
        torsion_units = torsion_units * units.max()
        tv_orders = minor_orders(flat, allow_uneven, max_order)
    channels, weights, largest = objective_channels(
        terms, units, pitch, couple_units, torsion_units, tv_orders
    )
    followers = bank_followers(flat) if even_banks and len(flat.bank_angles_rad) > 1 else None
    P, s, capacity, base, offsets = lattice(flat, allow_uneven, step_deg, followers)
    reversal, shift = check_reversal(phasors, offsets, base, P, flat.noise_floor_n)
    if followers:
        # running the other way round turns the banks over (bank 1 fires after bank 2):
        # another even-banks rule, not this one
        reversal, shift = False, None
    mirror = check_mirror(phasors, offsets, base, flat.noise_floor_n)
    phase = base[:, None] + s * np.arange(P)[None, :]  # (n, P) degrees
    rotated = np.zeros((n, P, len(channels)), complex)
    for i, (kind, k) in enumerate(channels):
        sign = -1.0 if kind in (1, 3) else 1.0
        rotated[:, :, i] = phasors[kind, :, k][:, None] * np.exp(
            1j * sign * (k + 1) * np.radians(phase)
        )
    rotated, weights, largest, offset = merge_channels(
        rotated, weights, largest if np.any(largest) else None
    )
    split = 1 + (n - 1) // 2
    problem = Problem(
        n,
        P,
        s,
        base,
        capacity,
        offsets,
        rotated,
        weights,
        reversal,
        False,
        split,
        largest=largest,
        offset=offset,
        followers=followers,
    )
    # the mirror condition reads throws n−1 and n from the suffix
    problem.mirror = mirror and n - 2 >= split
    symmetries = ["turning the whole crank (throw 1 at 0°)"]
    if reversal:
        symmetries.append("running the other way round (counted once)")
    if mirror:
        symmetries.append("mirror image, read from the other end (evaluated once, listed)")
    cranks = count_cranks(problem)
    firing_per_crank = math.factorial(capacity) ** P // capacity if capacity else 1
    expected = cranks if cranks is not None else P ** (n - 1)
    symmetry = (2 if reversal else 1) * (2 if problem.mirror else 1)
    if not heuristic and expected // symmetry > limit:
        _refuse_limit(limit, expected // symmetry, "about " if cranks is not None else "up to ")

    # progress counts the listed arrangements' analyses too (top of them at most), the
    # last stage, which took minutes with a large top after the bar had shown 100 %
    if heuristic:
        tick = _ticker(progress, restarts + top)
        reduction = Reduction(problem, top)
        for chunk in heuristic_search(problem, top, restarts, seed, tick):
            reduction.add(chunk)
        total_cranks = cranks
    else:
        if enumeration == "tabled":
            total_cranks = build_tables(problem)
            planned = _planned(problem)
            if planned > limit:
                _refuse_limit(limit, planned, "")
            units_of_work = work_units(problem)
            unit_weights = [1] * len(units_of_work)
            evaluate_with = evaluate
        else:
            total_cranks = cranks
            units_of_work, unit_weights = plan_units(problem)
            evaluate_with = evaluate_units
        tick = _ticker(progress, len(units_of_work) + top)
        if cluster is not None:
            reduction, workers = run_cluster(
                problem,
                units_of_work,
                unit_weights,
                top,
                evaluate_with,
                cluster,
                tick,
                cluster_name,
            )
        else:
            reduction, workers = run_local(
                problem, units_of_work, unit_weights, top, workers, evaluate_with, tick
            )
    truncated = reduction.truncated
    merged = Pool(problem, top)
    for key, score in reduction.pool.best.items():
        merged.offer(score, key)
    truncated |= merged.truncated
    orbits = sorted(((s, k) for k, s in merged.best.items()), key=lambda x: (x[0], x[1]))
    if len(orbits) >= top:
        cut = orbits[top - 1][0]
        orbits = [o for o in orbits if o[0] <= cut + SCORE_TIE]
    arrangements = final(
        template,
        flat,
        problem,
        orbits,
        shift,
        terms,
        top,
        samples,
        max_order,
        units,
        pitch,
        tick,
        couple_units,
        tv_orders,
    )
    total = (total_cranks or 0) * firing_per_crank
    distinct = _distinct(flat, problem, total, shift) if reversal else total
    return SearchResult(
        template=template,
        objective=terms,
        arrangements=tuple(arrangements),
        arrangements_total=total,
        arrangements_distinct=distinct,
        evaluated=reduction.evaluated,
        pruned=reduction.pruned,
        exhaustive=not heuristic,
        method="heuristic" if heuristic else "exhaustive",
        symmetries=tuple(symmetries),
        firing_orders_per_crank=firing_per_crank,
        even=not allow_uneven,
        even_banks=bool(followers),
        step_deg=s,
        ties_truncated=truncated,
        elapsed_s=time.perf_counter() - started,
        workers=1 if heuristic else workers,
        max_order=max_order,
        samples=samples,
    )


def _is_client(value):
    return all(hasattr(value, a) for a in ("scatter", "submit", "nthreads"))


def _cluster_of(scheduler, client):
    """(what to run on, the parameter that named it): a scheduler address, a Client, or
    None for this machine's processes."""
    if client is not None:
        if scheduler is not None:
            raise AnalysisError("and scheduler both name a cluster: give one of the two", "client")
        if not _is_client(client):
            raise AnalysisError(f"must be a distributed.Client, got {client!r}", "client")
        return client, "client"
    if scheduler is None:
        return None, None
    if not isinstance(scheduler, str) and not _is_client(scheduler):
        raise AnalysisError(
            f"must be a scheduler address such as tcp://host:8786 or a "
            f"distributed.Client, got {scheduler!r}",
            "scheduler",
        )
    return scheduler, "scheduler"


def _refuse_limit(limit, cranks, about):
    raise AnalysisError(
        f"is {limit:,} (cranks to evaluate), but an exhaustive search of this template evaluates "
        f"{about}{cranks:,}; raise it (an in-line 14's 1.6 billion take seconds on two "
        "cores, up to a minute a 2 billion where the bound prunes little), or use the "
        "heuristic search (not proved optimal) or a cluster scheduler",
        "limit",
    )


def _planned(problem):
    """Cranks the enumeration will score before any bound: the prefixes times the suffixes the
    symmetry conditions leave each of them."""
    count = 0
    rows, groups, ties = problem.prefix_rows, problem.prefix_group, problem.prefix_tie
    second = rows[:, 0] if rows.shape[1] else np.zeros(len(rows), int)
    for g in np.unique(groups):
        mine = groups == g
        key, leader = problem.suffix_key[g], problem.suffix_leader[g]
        n = len(problem.suffix_rows[g])
        start = np.searchsorted(key, second[mine]) if key is not None else np.zeros(mine.sum(), int)
        plain = n - start
        if ties[mine].any():
            after = np.cumsum(leader[::-1])[::-1]  # leaders from each position on
            tied = np.where(start < n, after[np.minimum(start, n - 1)], 0)
            plain = np.where(ties[mine], tied, plain)
        count += int(plain.sum())
    return count


def _ticker(progress, total):
    if progress is None:
        return None
    done = [0]

    def tick(k):
        done[0] += k
        progress(done[0], total)

    return tick


def _distinct(flat, problem, total, shift):
    """Arrangements counted once with their reversal: (total + self-reversed) / 2."""
    P, n = problem.lattice, problem.n_throws
    if P % 2:
        return total // 2 if total % 2 == 0 else (total + 1) // 2
    if not problem.capacity:
        return (total + 2 ** (n - 1)) // 2  # every crank of phases 0 and 180° is its own reversal
    reach = {(e - p) % P for offsets in problem.offsets for e in offsets for p in (0, P // 2)}
    if len(reach) < P:
        # phases of 0 and 180° alone cannot fill the lattice: no crank is its own reversal (an
        # in-line 22's 2^21 candidates took minutes to rule out one by one)
        return total // 2
    fixed = 0
    for tail in itertools.product((0, P // 2), repeat=n - 1):
        crank = (0,) + tail
        if problem.capacity:
            counts = np.zeros(P, int)
            for j, p in enumerate(crank):
                for e in problem.offsets[j]:
                    counts[(e - p) % P] += 1
            if (counts != problem.capacity).any():
                continue
            for order in firing_orders(flat, problem, crank):
                if reversed_order(order, flat, problem, shift) == order:
                    fixed += 1
        else:
            fixed += 1
    return (total + fixed) // 2
