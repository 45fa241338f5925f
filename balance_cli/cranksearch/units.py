"""The streamed enumeration: work units that carry what they need, and the rows a worker
builds for each of them.

The tabled enumeration (:mod:`.tables`) builds every prefix and every suffix of the meet in
the middle at once, in the parent, and sends them whole to every worker: three gigabytes for
an in-line 14. Here the parent keeps only the **occupancies** a prefix can leave (which
lattice points throw 1 and the prefix throws fill, counted by dynamic programming over the
occupancy, never enumerated), and each becomes a work unit: the occupancy, and where one
occupancy holds too much work, a head (the phases of the first prefix throws). A worker
enumerates the unit's own prefixes (those that fill exactly that occupancy, starting with the
head) and suffixes (those that fill the rest), a few thousand rows with their partial sums
accumulated throw by throw, scores their pairs (:func:`.query.evaluate_units`), and drops
them: its memory is that of one unit, whatever the template's size.

Both enumerations apply the same symmetry conditions to the same pairs (a prefix no greater
than its reversal, a suffix whose mirror key is at least the prefix's second throw), so they
evaluate or skip exactly the same arrangements; a test checks that they list the same.
"""

from __future__ import annotations

import math

import numpy as np

from .tables import lex_sign

__all__ = ["occupancy", "occupancy_of_first", "plan_units", "Enumerator", "mirror_keys"]

#: a unit of about this many (prefix, suffix) pairs before symmetry: an in-line 14's groups
#: of 720 × 5040 are one unit each; larger groups are split by the phases of their first
#: prefix throws
UNIT_PAIRS = 1 << 23


def occupancy(problem):
    """(n_throws, P, P) int8: the cylinders throw j at phase index p puts on each lattice
    point (a cylinder of lattice offset e on a throw turned by p steps fires at point e − p)."""
    P = problem.lattice
    out = np.zeros((problem.n_throws, P, P), np.int8)
    for j, offsets in enumerate(problem.offsets):
        for p in range(P):
            for e in offsets:
                out[j, p, (e - p) % P] += 1
    return out


def _states(problem, occ, throws, start):
    """The occupancies ``throws`` can reach from ``start`` without overfilling a point, each
    with the number of ways: (digits (m, P) int8, counts (m,) int64)."""
    P, cap = problem.lattice, problem.capacity
    digits = start[None, :].astype(np.int8)
    counts = np.ones(1, np.int64)
    radix = (cap + 1) ** np.arange(P, dtype=np.int64)
    for j in throws:
        fits = (digits[:, None, :] + occ[j][None, :, :] <= cap).all(axis=2)
        r, p = np.nonzero(fits)
        new = digits[r] + occ[j, p]
        keys = new.astype(np.int64) @ radix
        unique, first, inverse = np.unique(keys, return_index=True, return_inverse=True)
        digits = new[first]
        counts = np.bincount(inverse.ravel(), weights=counts[r], minlength=len(unique))
        counts = np.rint(counts).astype(np.int64)
    return digits, counts


def plan_units(problem, target=UNIT_PAIRS):
    """The work units of an even-firing search: [(prefix occupancy digits, head)], with the
    (prefix, suffix) pairs each holds before symmetry, in the same order.

    ``head`` is a tuple of phase indices of throws 2, 3, ... (empty for a whole occupancy);
    without a lattice constraint (an uneven search) there is one occupancy, split by heads.
    Heads that are greater than their own reversal are left out when the reversal symmetry is
    used: none of their prefixes is a leader.
    """
    P, cap, n, split = problem.lattice, problem.capacity, problem.n_throws, problem.split
    prefix_throws = list(range(1, split))
    suffix_throws = list(range(split, n))
    if not cap:
        states = [(np.zeros(P, np.int8), P ** len(prefix_throws), P ** len(suffix_throws))]
    else:
        occ = occupancy(problem)
        first = occ[0, 0]
        pre, pre_counts = _states(problem, occ, prefix_throws, first)
        suf, suf_counts = _states(problem, occ, suffix_throws, np.zeros(P, np.int8))
        radix = (cap + 1) ** np.arange(P, dtype=np.int64)
        have = dict(zip((suf.astype(np.int64) @ radix).tolist(), suf_counts.tolist(), strict=True))
        need = ((cap - pre).astype(np.int64) @ radix).tolist()
        states = [
            (digits, int(count), have[key])
            for digits, count, key in zip(pre, pre_counts.tolist(), need, strict=True)
            if key in have
        ]
    units: list = []
    pairs: list = []
    for digits, n_prefix, n_suffix in states:
        work = n_prefix * n_suffix
        depth = 0
        while depth < len(prefix_throws) and work > target * P**depth:
            depth += 1
        if depth == 0:
            units.append((tuple(int(d) for d in digits), ()))
            pairs.append(work)
            continue
        heads, _ = Enumerator(problem).rows(
            prefix_throws[:depth], digits - occupancy_of_first(problem), exact=False
        )
        if problem.reversal:
            heads = heads[lex_sign(heads, P) <= 0]
        share = math.ceil(work / max(len(heads), 1))
        for head in heads:
            units.append((tuple(int(d) for d in digits), tuple(int(p) for p in head)))
            pairs.append(share)
    return units, pairs


def occupancy_of_first(problem):
    """The points throw 1 fills at its phase 0 (P,) int8."""
    out = np.zeros(problem.lattice, np.int8)
    for e in problem.offsets[0]:
        out[e % problem.lattice] += 1
    return out


def _fits(problem, j):
    """For throw j: (offset e, cylinders at it) pairs; a phase p fits where point (e − p) mod P
    has room for that many, for each of them."""
    counts: dict[int, int] = {}
    for e in problem.offsets[j]:
        counts[e % problem.lattice] = counts.get(e % problem.lattice, 0) + 1
    return [((e - np.arange(problem.lattice)) % problem.lattice, k) for e, k in counts.items()]


#: the permutation tables of the fast path, by length (9! rows of 9 at most: 3 MB)
_PERMUTATIONS: dict[int, np.ndarray] = {}
_FAST_LENGTH = 9


def _permutations(k):
    """Every permutation of 0..k−1, (k!, k) int8, built once per process."""
    if k not in _PERMUTATIONS:
        table = np.zeros((1, 0), np.int8)
        for m in range(k):
            # insert m at each position of every permutation of 0..m−1
            grown = [np.insert(table, at, m, axis=1) for at in range(m + 1)]
            table = np.concatenate(grown).astype(np.int8)
        _PERMUTATIONS[k] = table
    return _PERMUTATIONS[k]


class Enumerator:
    """A worker's enumeration of units: what it computes once for the problem (each throw's
    occupancy of the lattice, and its sums by the point it puts its cylinder on), then
    :meth:`rows` for each unit."""

    def __init__(self, problem):
        self.problem = problem
        P = problem.lattice
        self.occ = occupancy(problem) if problem.capacity else None
        self.first = occupancy_of_first(problem)
        self.single = problem.capacity == 1 and all(len(e) == 1 for e in problem.offsets)
        if self.single:
            # by_point[j, x]: throw j's sums with its cylinder at lattice point x
            phase = np.array([[(e[0] - x) % P for x in range(P)] for e in problem.offsets])
            self.phase_of = phase.astype(np.int16)
            self.by_point = problem.rotated[np.arange(problem.n_throws)[:, None], phase]

    def rows(self, throws, left, head=(), exact=True):
        """Every assignment of phase indices to ``throws`` that fills exactly ``left``
        (digits, (P,); without ``exact``, at most ``left``) when the lattice has a capacity
        (any, without one), the first ``len(head)`` throws at ``head``: (rows (m,
        len(throws)) int16, partial sums (m, C) complex)."""
        free = len(throws) - len(head)
        if exact and self.single and 0 < free <= _FAST_LENGTH:
            return self._permuted(throws, left, head)
        return self._grown(throws, left, head, exact)

    def _grown(self, throws, left, head, exact):
        """Throw by throw, each row extended by every phase that fits, the sums accumulated
        so that each row costs one addition per channel."""
        problem = self.problem
        P, cap = problem.lattice, problem.capacity
        rotated = problem.rotated
        rows = np.zeros((1, 0), np.int16)
        sums = np.zeros((1, rotated.shape[2]), complex)
        left = np.asarray(left, np.int8)[None, :]
        for level, j in enumerate(throws):
            if cap:
                fits = np.ones((len(rows), P), bool)
                for points, k in _fits(problem, j):
                    fits &= left[:, points] >= k
                if level < len(head):
                    fits[:, np.arange(P) != head[level]] = False
                r, p = np.nonzero(fits)
            elif level < len(head):
                r = np.arange(len(rows))
                p = np.full(len(rows), head[level], np.intp)
            else:
                r = np.repeat(np.arange(len(rows)), P)
                p = np.tile(np.arange(P), len(rows))
            rows = np.concatenate([rows[r], p[:, None].astype(np.int16)], axis=1)
            sums = sums[r] + rotated[j, p]
            if self.occ is not None:
                left = left[r] - self.occ[j, p]
        if cap and exact:
            done = (left == 0).all(axis=1)
            rows, sums = rows[done], sums[done]
        return rows, sums

    def _permuted(self, throws, left, head):
        """Every throw one cylinder, every point room for one: the free throws take the
        points the head leaves in every order (a permutation table)."""
        problem = self.problem
        P = problem.lattice
        empty = (np.zeros((0, len(throws)), np.int16), np.zeros((0, problem.rotated.shape[2])))
        left = np.array(left, np.int8)
        throws = np.asarray(throws)
        taken = []
        for j, p in zip(throws, head, strict=False):
            point = (problem.offsets[j][0] - p) % P
            if left[point] < 1:
                return empty
            left[point] -= 1
            taken.append(point)
        points = np.flatnonzero(left)
        free = len(throws) - len(head)
        if len(points) != free or np.any(left > 1):
            return empty
        chosen = points[_permutations(free)]  # (free!, free) lattice points
        if head:
            chosen = np.concatenate([np.broadcast_to(taken, (len(chosen), len(head))), chosen], 1)
        rows = self.phase_of[throws[None, :], chosen]
        # np.take of contiguous index columns: twice as fast as fancy indexing
        columns = np.ascontiguousarray(chosen.T)
        sums = np.take(self.by_point[throws[0]], columns[0], axis=0)
        for k in range(1, len(throws)):
            sums += np.take(self.by_point[throws[k]], columns[k], axis=0)
        return rows, sums


def mirror_keys(problem, rows):
    """A suffix's mirror key: the phase of throw n − 1 relative to throw n, the second throw
    of the crank read from the other end (the least of it and its reversal's when reversal is
    used); the mirror image is evaluated instead when the prefix's second throw is above it."""
    P = problem.lattice
    a = (rows[:, -2].astype(np.int32) - rows[:, -1]) % P
    return np.minimum(a, (-a) % P) if problem.reversal else a
