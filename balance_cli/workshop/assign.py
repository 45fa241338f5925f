"""Finding the assignment of parts to cylinders that scores least: every one (with proof)
while they are few enough, a labelled heuristic beyond.

**Linearity.** Forces are linear in the masses, so the channels of an assignment (σ of the
pistons, ρ of the rods: the part at each cylinder) are sums of the parts' deviations times
each cylinder's response to one kilogram: Σᵢ δp_σ(i)·uᵢ + Σᵢ (δs_ρ(i)·uᵢ + δb_ρ(i)·vᵢ), u a
cylinder's piston pin, v its crank pin. With both kinds, the pistons' sums and the rods' sums
are computed once each and every pair is a sum of two rows.

**Exhaustive.** The pistons' permutations (the rods' when only rods are fitted) are enumerated
one representative per class of the symmetry group (:mod:`.symmetry`), each with every
permutation of the other kind. For the default objective every pair is first scored on a
subset of its grid (a lower bound of its score); only pairs whose bound is below the best
score found so far are scored on the whole grid. Evaluated + left out by symmetry = every
assignment: the best is proved.

**Heuristic.** Descent by exchanging two parts of a kind, from the order given, from the
pairing of pistons with rods that evens out the cylinders' reciprocating masses
(:func:`scipy.optimize.linear_sum_assignment`, blind to the crank, as the workshop's
spreadsheet does it) and from random orders: the best found, not proved.
"""

import itertools
import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from .symmetry import canonical

__all__ = ["Problem", "Found", "exhaustive", "heuristic", "DEFAULT_LIMIT", "DEFAULT_RESTARTS"]

#: an exhaustive matching evaluates at most this many assignments by default (about ten
#: seconds on one core); more are matched by the heuristic
DEFAULT_LIMIT = 10_000_000
DEFAULT_RESTARTS = 50
#: complex numbers in one block of pair scores (memory: 16 bytes each)
_BLOCK = 1 << 21
#: permutations generated at a time
_CHUNK = 50_000


@dataclass(frozen=True)
class Problem:
    """An assignment problem: the parts' deviations from their means (kg; None for a kind not
    fitted), each cylinder's channels for one kilogram at its piston pin (``unit``) and its
    crank pin (``pin``), the channels of what the masses not matched leave (``offset``), the
    objective and the symmetry group."""

    pistons: Any
    small: Any
    big: Any
    unit: np.ndarray
    pin: np.ndarray
    offset: np.ndarray
    objective: Any
    group: list

    @property
    def n(self) -> int:
        return self.unit.shape[0]

    @property
    def total(self) -> int:
        kinds = (self.pistons is not None) + (self.small is not None)
        return math.factorial(self.n) ** kinds

    @property
    def distinct(self) -> int:
        return self.total // len(self.group)

    def piston_channels(self, perms, columns=slice(None)):
        """Channels of the pistons at ``perms`` (rows: the piston at each cylinder)."""
        return self.pistons[perms] @ self.unit[:, columns]

    def rod_channels(self, perms, columns=slice(None)):
        return self.small[perms] @ self.unit[:, columns] + self.big[perms] @ self.pin[:, columns]

    def channels(self, sigma, rho, columns=slice(None)):
        """Channels of assignments (rows of ``sigma`` and ``rho``; either may be None)."""
        out = self.offset[columns]
        if sigma is not None:
            out = out + self.piston_channels(sigma, columns)
        if rho is not None:
            out = out + self.rod_channels(rho, columns)
        return out


@dataclass(frozen=True)
class Found:
    """The best assignment found: the piston and rod at each cylinder (None where that kind is
    not fitted), its score (N), how many assignments were evaluated, whether it is proved."""

    sigma: tuple | None
    rho: tuple | None
    score: float
    evaluated: int
    exhaustive: bool


def _permutations(n):
    """Every permutation of range(n), in blocks (arrays of rows)."""
    source = itertools.permutations(range(n))
    while True:
        block = np.array(list(itertools.islice(source, _CHUNK)), dtype=np.intp)
        if not len(block):
            return
        yield block


class _Best:
    """The best pair so far, with the refinement of a lower-bound screen on the full grid."""

    def __init__(self, problem, exact):
        self.problem, self.exact = problem, exact
        self.score, self.sigma, self.rho = math.inf, None, None

    def offer(self, bounds, rows_of):
        """Assignments scored ``bounds`` on the screen; ``rows_of(indices)`` gives their
        (sigma rows or None, rho rows or None)."""
        if self.exact:
            i = int(np.argmin(bounds))
            if bounds[i] < self.score:
                sigmas, rhos = rows_of(np.array([i]))
                self._take(bounds[i], sigmas, rhos)
            return
        hopeful = np.flatnonzero(bounds < self.score)
        hopeful = hopeful[np.argsort(bounds[hopeful], kind="stable")]
        for start in range(0, len(hopeful), 64):
            batch = hopeful[start : start + 64]
            batch = batch[bounds[batch] < self.score]
            if not len(batch):
                return
            sigmas, rhos = rows_of(batch)
            scores = self.problem.objective.score(self.problem.channels(sigmas, rhos))
            i = int(np.argmin(scores))
            if scores[i] < self.score:
                self._take(
                    scores[i],
                    None if sigmas is None else sigmas[i : i + 1],
                    None if rhos is None else rhos[i : i + 1],
                )

    def _take(self, score, sigmas, rhos):
        self.score = float(score)
        self.sigma = None if sigmas is None else tuple(int(x) for x in sigmas[0])
        self.rho = None if rhos is None else tuple(int(x) for x in rhos[0])


def _steps(outer, inner, width):
    """Blocks (outer rows, inner rows) of at most _BLOCK complex numbers of pair channels."""
    if inner * width <= _BLOCK:
        per = max(1, _BLOCK // (inner * width))
        return [(slice(s, s + per), slice(None)) for s in range(0, outer, per)]
    per = max(1, _BLOCK // width)
    return [
        (slice(s, s + 1), slice(t, t + per)) for s in range(outer) for t in range(0, inner, per)
    ]


def _single(block, pistons):
    """The rows of ``block`` at indices, as (sigma, rho): pistons or rods only."""

    def rows_of(i):
        return (block[i], None) if pistons else (None, block[i])

    return rows_of


def _paired(outer, inner):
    """The pairs of rows of ``outer`` and ``inner`` at flat indices (outer major)."""

    def rows_of(i):
        return outer[i // len(inner)], inner[i % len(inner)]

    return rows_of


def exhaustive(problem: Problem, progress=None) -> Found:
    """Every assignment, one per symmetry class: the best, proved."""
    objective = problem.objective
    screen = objective.screen()
    columns = slice(None) if screen is None else screen
    best = _Best(problem, exact=screen is None)
    both = problem.pistons is not None and problem.small is not None
    outer_is_pistons = problem.pistons is not None
    inner: Any = None
    inner_channels: Any = None
    if both:
        inner = np.concatenate(list(_permutations(problem.n)))
        inner_channels = problem.rod_channels(inner, columns)
    evaluated = 0
    for block in _permutations(problem.n):
        block = block[canonical(block, problem.group)]
        if not len(block):
            continue
        if outer_is_pistons:
            outer_channels = problem.piston_channels(block, columns)
        else:
            outer_channels = problem.rod_channels(block, columns)
        outer_channels = outer_channels + problem.offset[columns]
        if not both:
            best.offer(objective.score(outer_channels), _single(block, outer_is_pistons))
            evaluated += len(block)
        else:
            for rows, cols in _steps(len(block), len(inner), outer_channels.shape[1]):
                pairs = outer_channels[rows, None, :] + inner_channels[None, cols, :]
                bounds = objective.score(pairs).ravel()
                best.offer(bounds, _paired(block[rows], inner[cols]))
                evaluated += len(bounds)
        if progress is not None:
            progress(evaluated, problem.distinct)
    return Found(best.sigma, best.rho, best.score, evaluated, True)


def _swaps(n):
    a, b = np.triu_indices(n, 1)
    return a, b


def _descend(problem, sigma, rho, columns):
    """Steepest descent by exchanging two parts of one kind, on ``columns`` of the channels."""
    a, b = _swaps(problem.n)
    unit = problem.unit[:, columns]
    pin = problem.pin[:, columns]
    current = problem.channels(
        None if sigma is None else sigma[None], None if rho is None else rho[None], columns
    )[0]
    score = float(problem.objective.score(current))
    evaluated = 1
    while True:
        moves, deltas = [], []
        if sigma is not None:
            gain = problem.pistons[sigma[b]] - problem.pistons[sigma[a]]
            deltas.append(gain[:, None] * (unit[a] - unit[b]))
            moves += [("p", i, j) for i, j in zip(a, b, strict=True)]
        if rho is not None:
            small = problem.small[rho[b]] - problem.small[rho[a]]
            big = problem.big[rho[b]] - problem.big[rho[a]]
            deltas.append(small[:, None] * (unit[a] - unit[b]) + big[:, None] * (pin[a] - pin[b]))
            moves += [("r", i, j) for i, j in zip(a, b, strict=True)]
        if not moves:
            return sigma, rho, score, evaluated
        trial = current + np.concatenate(deltas)
        scores = problem.objective.score(trial)
        evaluated += len(scores)
        k = int(np.argmin(scores))
        if not scores[k] < score * (1 - 1e-12):
            return sigma, rho, score, evaluated
        kind, i, j = moves[k]
        target = sigma if kind == "p" else rho
        target = target.copy()
        target[[i, j]] = target[[j, i]]
        if kind == "p":
            sigma = target
        else:
            rho = target
        current, score = trial[k], float(scores[k])


def _even_pairs(problem):
    """Pistons paired with rods so that each cylinder's reciprocating deviation is as small as
    can be (least squares): a linear assignment, blind to the crank."""
    from scipy.optimize import linear_sum_assignment

    cost = (problem.pistons[:, None] + problem.small[None, :]) ** 2
    pistons, rods = linear_sum_assignment(cost)
    return pistons.astype(np.intp), rods.astype(np.intp)


def heuristic(problem: Problem, restarts=DEFAULT_RESTARTS, seed=0, progress=None) -> Found:
    """Descent from the order given, the even pairing and ``restarts`` random orders (seeded
    by ``seed``): the best found, not proved."""
    rng = np.random.default_rng(seed)
    n = problem.n
    has_p, has_r = problem.pistons is not None, problem.small is not None
    starts = [(np.arange(n) if has_p else None, np.arange(n) if has_r else None)]
    if has_p and has_r:
        starts.append(_even_pairs(problem))
    for _ in range(restarts):
        starts.append(
            (rng.permutation(n) if has_p else None, rng.permutation(n) if has_r else None)
        )
    screen = problem.objective.screen()
    columns = slice(None) if screen is None else screen
    best = (math.inf, None, None)
    evaluated = 0
    for done, (sigma, rho) in enumerate(starts, 1):
        sigma, rho, _, count = _descend(problem, sigma, rho, columns)
        evaluated += count
        score = float(
            problem.objective.score(
                problem.channels(
                    None if sigma is None else sigma[None], None if rho is None else rho[None]
                )
            )[0]
        )
        if score < best[0]:
            best = (score, sigma, rho)
        if progress is not None:
            progress(done, len(starts))
    _, sigma, rho = best
    sigma, rho, score, count = _descend(problem, sigma, rho, slice(None))
    return Found(
        None if sigma is None else tuple(int(x) for x in sigma),
        None if rho is None else tuple(int(x) for x in rho),
        score,
        evaluated + count,
        False,
    )
