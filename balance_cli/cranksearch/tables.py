"""The tables of the meet-in-the-middle enumeration, and the count of every even-firing crank.

The free throws are split into a prefix and a suffix: prefixes are grouped by the lattice
points they fill, each group with the suffixes that fill the rest, and only the lexicographic
leaders of a symmetry class are kept. The cranks are counted without enumerating them.
"""

from __future__ import annotations

import math

import numpy as np

__all__ = ["build_tables", "count_cranks", "lex_sign"]

#: cheapest count of even-firing cranks by dynamic programming, in state updates: beyond it
#: (an in-line 20 took 38 s) the count is a closed form or an upper bound
_COUNT_WORK = 10_000_000


def _assignments(problem, throws, first_fixed=False):
    """Every phase assignment of ``throws`` that overfills no lattice point: (rows, counts)."""
    P, cap = problem.lattice, problem.capacity
    rows = np.zeros((1, 0), np.int16)
    counts = np.zeros((1, P), np.int16)
    for j in throws:
        candidates = np.arange(P, dtype=np.int16)
        occupancy = np.zeros((P, P), np.int16)
        for p in range(P):
            for e in problem.offsets[j]:
                occupancy[p, (e - p) % P] += 1
        new_rows = np.concatenate(
            [np.repeat(rows, P, axis=0), np.tile(candidates, len(rows))[:, None]], axis=1
        )
        new_counts = np.repeat(counts, P, axis=0) + np.tile(occupancy, (len(rows), 1))
        if cap:
            keep = (new_counts <= cap).all(axis=1)
            new_rows, new_counts = new_rows[keep], new_counts[keep]
        rows, counts = new_rows, new_counts
    return rows, counts


def lex_sign(rows, P):
    """−1, 0 or +1: each row against its reversal (−row mod P), lexicographically."""
    negated = (-rows.astype(np.int32)) % P
    diff = rows.astype(np.int32) - negated
    sign = np.zeros(len(rows), np.int8)
    undecided = np.ones(len(rows), bool)
    for col in range(rows.shape[1]):
        d = diff[:, col]
        now = undecided & (d != 0)
        sign[now] = np.sign(d[now])
        undecided &= d == 0
    return sign


def build_tables(problem):
    """Prefix rows grouped with the suffix rows that complete them (see the module text)."""
    n, P, cap = problem.n_throws, problem.lattice, problem.capacity
    prefix_throws = list(range(1, problem.split))
    suffix_throws = list(range(problem.split, n))
    base_rows, base_counts = _assignments(problem, [0])
    rows, counts = _assignments(problem, prefix_throws)
    first = base_counts[0] if cap else np.zeros(P, np.int16)
    counts = counts + first
    if cap:
        keep = (counts <= cap).all(axis=1)
        rows, counts = rows[keep], counts[keep]
    srows, scounts = _assignments(problem, suffix_throws)
    if cap:

        def key_of(c):
            return c.astype(np.int64) @ (cap + 1) ** np.arange(P, dtype=np.int64)

        have = np.sort(key_of(scounts))
        need = key_of(cap - counts)
        total = int((np.searchsorted(have, need, "right") - np.searchsorted(have, need)).sum())
    else:
        total = len(rows) * len(srows)
    tie = np.zeros(len(rows), bool)
    if problem.reversal and rows.shape[1]:
        sign = lex_sign(rows, P)
        rows, counts, tie = rows[sign <= 0], counts[sign <= 0], (sign == 0)[sign <= 0]
    if cap:
        need = key_of(cap - counts)
        have = key_of(scounts)
    else:
        need = np.zeros(len(rows), np.int64)
        have = np.zeros(len(srows), np.int64)
    keys, group = np.unique(need, return_inverse=True)
    suffix_rows, suffix_key, suffix_leader = [], [], []
    order = np.argsort(have, kind="stable")
    sorted_have = have[order]
    for key in keys:
        lo, hi = np.searchsorted(sorted_have, key), np.searchsorted(sorted_have, key, "right")
        mine = srows[order[lo:hi]]
        if problem.mirror:
            a = (mine[:, -2].astype(np.int32) - mine[:, -1]) % P
            mkey = np.minimum(a, (-a) % P) if problem.reversal else a
            sort = np.argsort(mkey, kind="stable")
            mine, mkey = mine[sort], mkey[sort]
        else:
            mkey = None
        suffix_rows.append(mine)
        suffix_key.append(mkey)
        suffix_leader.append(
            lex_sign(mine, P) <= 0
            if problem.reversal and mine.shape[1]
            else np.ones(len(mine), bool)
        )
    # prefixes sorted by group, then by their second throw's phase (the mirror condition)
    second = rows[:, 0] if rows.shape[1] else np.zeros(len(rows), np.int16)
    sort = np.lexsort((second, group))
    problem.prefix_rows, problem.prefix_group, problem.prefix_tie = (
        rows[sort],
        group[sort],
        tie[sort],
    )
    problem.suffix_rows, problem.suffix_key, problem.suffix_leader = (
        suffix_rows,
        suffix_key,
        suffix_leader,
    )
    return total


def count_cranks(problem):
    """Every even-firing crank with throw 1 at 0°, counted (dynamic programming over the
    lattice points filled) without enumerating them; None when too many states."""
    P, cap, n = problem.lattice, problem.capacity, problem.n_throws
    if not cap:
        return P ** (n - 1)
    if all(len(e) == 1 for e in problem.offsets):
        # one cylinder a throw (every in-line engine): throw 1 takes a place of its point and
        # the other n − 1 throws share the remaining places, cap at each point: a multinomial
        return math.factorial(n - 1) // (math.factorial(cap - 1) * math.factorial(cap) ** (P - 1))
    if (cap + 1) ** P * n * P > _COUNT_WORK:
        return None
    return _count_by_occupancy(problem)


def _count_by_occupancy(problem):
    """The count over every state of the lattice's occupancy, throw by throw."""
    P, cap, n = problem.lattice, problem.capacity, problem.n_throws
    radix = (cap + 1) ** np.arange(P, dtype=np.int64)
    states = np.arange((cap + 1) ** P, dtype=np.int64)
    digits = (states[:, None] // radix) % (cap + 1)
    count = np.zeros(len(states), object if n > 20 else np.int64)
    count[0] = 1
    for j in range(n):
        new = np.zeros_like(count)
        for p in [0] if j == 0 else range(P):
            occupancy = np.zeros(P, np.int64)
            for e in problem.offsets[j]:
                occupancy[(e - p) % P] += 1
            ok = (digits + occupancy <= cap).all(axis=1) & (count != 0)
            np.add.at(new, states[ok] + occupancy @ radix, count[ok])
        count = new
    return int(count[-1])
