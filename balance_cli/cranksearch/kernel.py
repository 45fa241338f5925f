"""The evaluation kernel: scores of (prefix, suffix) pairs by vectorised blocks, pruned by
the bound |P + Q| ≥ |P| − max|Q|, and the pool of the best symmetry classes found so far.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

__all__ = ["Pool", "Chunk", "work_units", "evaluate", "SCORE_TIE", "TIE_CAP", "BLOCK"]

#: scores closer than this are equal (the coefficients are of order one and carry rounding
#: errors of about 1e-14); equal scores are ranked by firing order. Scores are compared with
#: the weights divided by the largest one, so the tie is relative to the score's scale: a
#: lone term of weight 1e-10 still ranks M1 = 0 above M1 = 5
SCORE_TIE = 1e-9
#: more arrangements than this tying at the K-th best score are not all kept
TIE_CAP = 100_000
#: a block of (prefix × suffix × channel) values evaluated at once
BLOCK = 1 << 21


def _sums(problem, rows, throws):
    """Σ over ``throws`` of each channel's rotated phasor, for every row: (n_rows, C)."""
    out = np.zeros((len(rows), problem.rotated.shape[2]), complex)
    for col, j in enumerate(throws):
        out += problem.rotated[j, rows[:, col]]
    return out


class Pool:
    """The best symmetry classes found so far: at most ``top`` scores and everything tied."""

    def __init__(self, problem, top, threshold=math.inf):
        self.problem, self.top = problem, top
        self.best: dict = {}
        self.threshold = threshold
        self.truncated = False
        # the threshold is brought down when the pool reaches this size, which then doubles:
        # sorting at every offer made a large top quadratic (minutes at top = 100 000)
        self.recount = top

    @property
    def full(self):
        """Holding ``top`` and TIE_CAP tied: only a better score than the threshold gets in."""
        return len(self.best) >= self.top + TIE_CAP

    def offer(self, score, crank):
        if score > self.threshold + SCORE_TIE:
            return
        if self.full and score > self.threshold - SCORE_TIE:
            # another tie, or the same class again: not let in either way, and decided before
            # its symmetry class is worked out (a grid of uneven cranks tied by the million at
            # 0 spent minutes there)
            self.truncated = True
            return
        key = self.problem.orbit_key(crank)
        old = self.best.get(key)
        if old is not None and old <= score:
            return
        self.best[key] = score
        if len(self.best) >= self.recount:
            scores = np.fromiter(self.best.values(), float, len(self.best))
            self.threshold = min(
                self.threshold, float(np.partition(scores, self.top - 1)[self.top - 1])
            )
            self.best = {k: v for k, v in self.best.items() if v <= self.threshold + SCORE_TIE}
            self.recount = max(2 * len(self.best), self.top) + 64


@dataclass
class Chunk:
    candidates: list
    evaluated: int
    pruned: int
    truncated: bool


def work_units(problem, target=BLOCK):
    """(group, prefix start, prefix end) pieces of roughly ``target`` channel values each."""
    units = []
    C = max(problem.rotated.shape[2], 1)
    # the prefixes are sorted by group: each group's run from its start to the next run's
    # (the last to the end); no run without prefixes
    groups = problem.prefix_group
    bounds = [*np.flatnonzero(np.diff(groups, prepend=-1)), len(groups)]
    for lo, hi in zip(bounds, bounds[1:], strict=False):
        g = int(groups[lo])
        per = max(1, target // (max(len(problem.suffix_rows[g]), 1) * C))
        for a in range(lo, hi, per):
            units.append((g, int(a), int(min(a + per, hi))))
    return units


def evaluate(problem, units, top, threshold=math.inf, shared=None):
    """Score every (prefix, suffix) pair of ``units`` not excluded by symmetry or bound."""
    pool = Pool(problem, top, threshold)
    evaluated = pruned = 0
    split = problem.split
    prefix_throws = list(range(1, split))
    suffix_throws = list(range(split, problem.n_throws))
    w = problem.weights
    cached_group = None  # the group whose suffix sums Q, Qmax hold (units come by group)
    for g, lo, hi in units:
        if shared is not None:
            pool.threshold = min(pool.threshold, shared.value)
        srows = problem.suffix_rows[g]
        if cached_group != g:
            Q = _sums(problem, srows, suffix_throws)
            Qmax = np.abs(Q).max(axis=0) if len(Q) else np.zeros(len(w))
            cached_group = g
        rows = problem.prefix_rows[lo:hi]
        Pm = _sums(problem, rows, prefix_throws) + problem.rotated[0, 0]
        ties = problem.prefix_tie[lo:hi]
        second = rows[:, 0] if rows.shape[1] else np.zeros(len(rows), int)
        mkey = problem.suffix_key[g]
        for v in np.unique(second):
            start = int(np.searchsorted(mkey, v)) if mkey is not None else 0
            Qs = Q[start:]
            leader = problem.suffix_leader[g][start:]
            mine = np.flatnonzero(second == v)
            # each channel's |sum| is at least |prefix| − the largest |suffix|; the largest of
            # such lower bounds bounds the largest (TV1) as the sum bounds the sum
            bound = problem.score(np.clip(np.abs(Pm[mine]) - Qmax, 0.0, None))
            ok = bound <= pool.threshold + SCORE_TIE
            pruned += int((~ok).sum()) * len(Qs)
            for tie in (False, True):
                sel = mine[ok & (ties[mine] == tie)]
                if not len(sel) or not len(Qs):
                    continue
                cols = np.flatnonzero(leader) if tie else None
                Qt = Qs if cols is None else Qs[cols]
                step = max(1, BLOCK // (len(Qt) * len(w) or 1))
                for a in range(0, len(sel), step):
                    block = sel[a : a + step]
                    S = Pm[block][:, None, :] + Qt[None, :, :]
                    score = problem.score(np.sqrt(S.real**2 + S.imag**2))
                    evaluated += score.size
                    hits = np.argwhere(score <= pool.threshold + SCORE_TIE)
                    if len(hits) > 4 * (top + 64):
                        # a class is met at most four times (its symmetry images), so the
                        # 4·top-th smallest score is at least the top-th best class's
                        values = score[hits[:, 0], hits[:, 1]]
                        cut = np.partition(values, 4 * top - 1)[4 * top - 1]
                        hits = hits[values <= cut + SCORE_TIE]
                    for i, q in hits:
                        qi = q if cols is None else cols[q]
                        crank = problem.crank(rows[block[i]], problem.suffix_rows[g][start + qi])
                        pool.offer(float(score[i, q]), crank)
                    if shared is not None and pool.threshold < shared.value:
                        with shared.get_lock():
                            shared.value = min(shared.value, pool.threshold)
    return Chunk(list((s, k) for k, s in pool.best.items()), evaluated, pruned, pool.truncated)
