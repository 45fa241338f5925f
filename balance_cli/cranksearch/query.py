"""The streamed kernel: each unit's prefixes paired with the suffixes near their opposite.

A pair (prefix P, suffix Q) scores Σ_c w_c·|P_c + Q_c| (plus a TV1 term's largest part), a
sum of non-negative terms, so a pair within the threshold T (the K-th best score found) has
|P_c + Q_c| ≤ T / w_c in **every** channel c: Q_c lies in a disc of that radius about −P_c.
The suffixes' sums in the most selective channel (the smallest disc against their extent) are
put on a grid of cells sorted by column and row; each prefix reads the few runs of cells that
cover its disc, and only those pairs are scored. Before any threshold is known (the first
block of a worker) every pair is scored by broadcasting.

The symmetry conditions are those of the tabled enumeration (:mod:`.tables`): a prefix no
greater than its reversal, and a suffix whose mirror key is at least the prefix's second
throw (a prefix equal to its reversal takes only suffixes no greater than theirs). The pairs
they leave are counted per prefix without enumerating them; those not scored are the ones
the bound skipped: evaluated + skipped by bound + left out by symmetry = every arrangement.
"""

from __future__ import annotations

import math

import numpy as np

from .kernel import BLOCK, SCORE_TIE, Chunk, Pool
from .tables import lex_sign
from .units import Enumerator, mirror_keys

__all__ = ["evaluate_units", "PIECE"]

#: channel values computed at once: small enough that the sums, their squares and roots stay
#: in the processor's cache (2^21 at once, as the tabled kernel does, took four times as
#: long a pair: 126 ns against 32 ns for ten channels)
PIECE = 1 << 16


class _Grid:
    """The suffixes' sums in one channel on a square grid of cells (side ``h``, a fraction of
    the radius asked or more), sorted by column then row: the suffixes within ``r`` of a
    point lie in at most ``COLUMNS`` columns, each a contiguous run of sorted positions.
    Cells of half the radius cover about 6r² about a point, where cells of twice it covered
    16r² (and scored 2.5 times as many pairs on an in-line 14)."""

    #: cells a side at most: the cell keys stay small integers whatever the radius
    CELLS = 2048
    #: the cell side is the radius over this: a square of side 2r spans 2·FINENESS cells,
    #: and one more
    FINENESS = 2
    COLUMNS = 2 * FINENESS + 1

    def __init__(self, values, r, spread):
        self.r = r
        self.x0, self.y0 = float(values.real.min()), float(values.imag.min())
        self.h = max(r / self.FINENESS, spread / self.CELLS, np.finfo(float).tiny)
        cx = np.floor((values.real - self.x0) / self.h).astype(np.int64)
        cy = np.floor((values.imag - self.y0) / self.h).astype(np.int64)
        self.nx, self.ny = int(cx.max()) + 1, int(cy.max()) + 1
        key = cx * self.ny + cy
        self.order = np.argsort(key, kind="stable")
        self.keys = key[self.order]

    def ranges(self, targets):
        """(lo, hi) (m, COLUMNS): the runs of sorted positions that hold every suffix whose
        value is within the grid's radius of each target, in real and in imaginary part
        (floor((v − origin)/h) is monotonic in v, so no such suffix is missed)."""
        r = self.r

        def cells(v, origin, count):
            lo = np.floor((v - r - origin) / self.h)
            hi = np.floor((v + r - origin) / self.h)
            ok = (hi >= 0) & (lo <= count - 1)
            return (
                np.clip(lo, 0, count - 1).astype(np.int64),
                np.clip(hi, 0, count - 1).astype(np.int64),
                ok,
            )

        x_lo, x_hi, x_ok = cells(targets.real, self.x0, self.nx)
        y_lo, y_hi, y_ok = cells(targets.imag, self.y0, self.ny)
        ok = x_ok & y_ok
        lo = np.zeros((len(targets), self.COLUMNS), np.int64)
        hi = np.zeros((len(targets), self.COLUMNS), np.int64)
        for k in range(self.COLUMNS):
            column = x_lo + k
            here = ok & (column <= x_hi)
            lo[:, k] = np.searchsorted(self.keys, column * self.ny + y_lo, "left")
            hi[:, k] = np.searchsorted(self.keys, column * self.ny + y_hi, "right")
            hi[:, k] = np.where(here, np.maximum(hi[:, k], lo[:, k]), lo[:, k])
        return lo, hi


class _Suffixes:
    """One occupancy's suffixes with what every head of it reads: their sums, mirror keys,
    leaders (asked for once), each channel's largest |Q| and the grids built on them."""

    def __init__(self, problem, srows, Q):
        self.problem, self.srows, self.Q = problem, srows, Q
        self.mkey = mirror_keys(problem, srows).astype(np.int64) if problem.mirror else None
        self._leader = None
        self.Qmax = np.abs(Q).max(axis=0) if len(Q) else np.zeros(Q.shape[1])
        # each channel's extent, about (the disc that holds its values): it chooses the
        # channel and bounds the number of cells a side
        self.spread = 2.0 * self.Qmax
        self.grids: dict = {}

    def leader(self, needed):
        """Which suffixes are no greater than their reversal: asked only by a prefix that is
        its own reversal (an in-line two-stroke's never is)."""
        if self._leader is None and needed:
            self._leader = lex_sign(self.srows, self.problem.lattice) <= 0
        if self._leader is None:
            return np.ones(len(self.srows), bool)
        return self._leader

    def grid(self, c, r):
        """A grid of channel c for radius r: the one built before while its radius is
        between r and 2r (the threshold only falls)."""
        grid = self.grids.get(c)
        if grid is None or not r <= grid.r <= 2 * r:
            grid = self.grids[c] = _Grid(self.Q[:, c], r, self.spread[c])
        return grid


class _Group:
    """One unit's prefixes and suffixes, paired under the symmetry conditions and the bound."""

    def __init__(self, problem, pool, prows, Pm, ties, suffixes):
        self.problem, self.pool = problem, pool
        self.prows, self.Pm, self.ties = prows, Pm, ties
        self.suffixes = suffixes
        self.srows, self.Q, self.mkey = suffixes.srows, suffixes.Q, suffixes.mkey
        self.leader = leader = suffixes.leader(bool(ties.any()) and suffixes.srows.shape[1] > 0)
        mkey, Q = self.mkey, self.Q
        P = problem.lattice
        self.second = prows[:, 0].astype(np.int64) if prows.shape[1] else np.zeros(len(prows), int)
        # the suffixes each prefix pairs with, counted: those whose mirror key is at least
        # its second throw's phase (every one without the mirror), leaders only for a prefix
        # that is its own reversal
        if mkey is None:
            plain = np.full(len(prows), len(Q))
            tied = np.full(len(prows), int(leader.sum()))
        else:
            at_least = np.cumsum(np.bincount(mkey, minlength=P + 1)[::-1])[::-1]
            leaders = np.cumsum(np.bincount(mkey[leader], minlength=P + 1)[::-1])[::-1]
            plain, tied = at_least[self.second], leaders[self.second]
        self.allowed = np.where(ties, tied, plain)
        self.weights = problem.weights + (problem.largest if problem.largest is not None else 0.0)
        self.Qmax, self.spread = suffixes.Qmax, suffixes.spread
        self.evaluated = 0

    def keep(self, i, j):
        """Which pairs (prefix i, suffix j) the symmetry conditions leave."""
        ok = ~self.ties[i] | self.leader[j]
        if self.mkey is not None:
            ok &= self.mkey[j] >= self.second[i]
        return ok

    def offer(self, score, i, j, top):
        """Offer the pairs (i, j) whose ``score`` is within the threshold to the pool."""
        pool = self.pool
        hits = np.flatnonzero(score <= pool.threshold + SCORE_TIE)
        if pool.full and len(hits):
            # ties are no longer let in: only the strictly better ones are offered
            better = hits[score[hits] <= pool.threshold - SCORE_TIE]
            pool.truncated |= len(better) < len(hits)
            hits = better
        if len(hits) > 4 * (top + 64):
            # a class is met at most four times (its symmetry images), so the 4·top-th
            # smallest score is at least the top-th best class's
            cut = np.partition(score[hits], 4 * top - 1)[4 * top - 1]
            hits = hits[score[hits] <= cut + SCORE_TIE]
        for h in hits:
            crank = self.problem.crank(self.prows[i[h]], self.srows[j[h]])
            pool.offer(float(score[h]), crank)

    def brute(self, block, top):
        """Every allowed pair of the prefixes ``block``, by broadcasting, a piece of about
        PIECE channel values at a time."""
        n_s, channels = len(self.Q), max(self.Q.shape[1], 1)
        per = max(1, PIECE // channels)  # pairs a piece
        width = min(n_s, per)  # suffixes a piece
        rows = max(1, per // width)  # prefixes a piece
        for a in range(0, len(block), rows):
            prefixes = block[a : a + rows]
            for lo in range(0, n_s, width):
                suffixes = np.arange(lo, min(lo + width, n_s))
                S = self.Pm[prefixes][:, None, :] + self.Q[suffixes][None, :, :]
                score = self.problem.score(np.sqrt(S.real**2 + S.imag**2)).ravel()
                i = np.repeat(prefixes, len(suffixes))
                j = np.tile(suffixes, len(prefixes))
                valid = self.keep(i, j)
                self.evaluated += int(valid.sum())
                self.offer(score[valid], i[valid], j[valid], top)

    def channel(self, threshold):
        """The channel whose disc of the threshold is smallest against the suffixes' extent,
        and the disc's radius (padded for the rounding of the sums)."""
        with np.errstate(divide="ignore", invalid="ignore"):
            radius = (threshold - self.problem.offset + SCORE_TIE) / self.weights
            radius = radius * (1 + 1e-9) + 1e-12 * (self.Qmax.max() + 1e-300)
            ratio = np.where((self.spread > 0) & (self.weights > 0), radius / self.spread, np.inf)
        c = int(np.argmin(ratio))
        return c, float(radius[c])

    def queried(self, block, top, threshold):
        """The prefixes ``block`` against the suffixes near each one's opposite in the most
        selective channel, a piece of at most BLOCK channel values at a time."""
        c, r = self.channel(threshold)
        grid = self.suffixes.grid(c, r)
        lo, hi = grid.ranges(-self.Pm[block, c])
        lengths = hi - lo
        ends = np.cumsum(lengths.sum(axis=1))
        limit = max(1, PIECE // max(self.Q.shape[1], 1))
        a = 0
        while a < len(block):
            base = ends[a - 1] if a else 0
            b = min(len(block), max(a + 1, int(np.searchsorted(ends, base + limit, "right"))))
            L = lengths[a:b].ravel()
            total = int(L.sum())
            if total:
                owner = np.repeat(np.repeat(np.arange(a, b), grid.COLUMNS), L)
                pos = np.repeat(lo[a:b].ravel() - (np.cumsum(L) - L), L) + np.arange(total)
                i, j = block[owner], grid.order[pos]
                ok = self.keep(i, j)
                i, j = i[ok], j[ok]
                self.evaluated += len(i)
                S = self.Pm[i] + self.Q[j]
                self.offer(self.problem.score(np.sqrt(S.real**2 + S.imag**2)), i, j, top)
            a = b


def evaluate_units(problem, units, top, threshold=math.inf, shared=None):
    """Score every (prefix, suffix) pair of the streamed ``units`` (:func:`.units.plan_units`)
    that the symmetry conditions leave and the bound does not exclude: a :class:`Chunk`.

    ``threshold``: a score no better than the K-th best known (pairs above it are not kept);
    ``shared``: a process-shared value of it, read and lowered as the work goes.
    """
    pool = Pool(problem, top, threshold)
    evaluated = pruned = 0
    P, cap, split, n = problem.lattice, problem.capacity, problem.split, problem.n_throws
    prefix_throws = list(range(1, split))
    suffix_throws = list(range(split, n))
    enumerator = Enumerator(problem)
    # one occupancy's suffixes: the heads of an occupancy come one after another
    suffixes, key = None, None
    for digits, head in units:
        if shared is not None:
            pool.threshold = min(pool.threshold, shared.value)
        digits = np.asarray(digits, np.int8)
        if suffixes is None or key != tuple(digits):
            key = tuple(digits)
            suffixes = _Suffixes(
                problem, *enumerator.rows(suffix_throws, cap - digits if cap else digits)
            )
        prows, Pm = enumerator.rows(
            prefix_throws, digits - enumerator.first if cap else digits, head
        )
        Pm = Pm + problem.rotated[0, 0]
        ties = np.zeros(len(prows), bool)
        if problem.reversal and prows.shape[1]:
            sign = lex_sign(prows, P)
            keep = sign <= 0
            prows, Pm, ties = prows[keep], Pm[keep], (sign == 0)[keep]
        group = _Group(problem, pool, prows, Pm, ties, suffixes)
        _pair(group, top, shared)
        evaluated += group.evaluated
        pruned += int(group.allowed.sum()) - group.evaluated
    return Chunk(list((s, k) for k, s in pool.best.items()), evaluated, pruned, pool.truncated)


def _pair(group, top, shared):
    """Every prefix of ``group`` against its suffixes, a block at a time: pruned by the bound
    and read off the grid where the threshold's disc is small against the suffixes' extent;
    broadcast (every pair scored) while no threshold is known or where the disc covers most
    of them (an objective of many terms: the grid would only add its bookkeeping)."""
    pool = group.pool
    n_p, n_s = len(group.Pm), len(group.Q)
    if not n_p or not n_s:
        return
    channels = group.Q.shape[1]
    at = 0
    while at < n_p:
        threshold = pool.threshold
        known = math.isfinite(threshold) and channels > 0
        selective = False
        if known:
            c, r = group.channel(threshold)
            selective = r < group.spread[c] / 2
        step = 4096 if selective else max(1, BLOCK // (n_s * max(channels, 1)))

        block = np.arange(at, min(at + step, n_p))
        if known:
            # |P + Q| ≥ |P| − max|Q| in each channel: a prefix whose bound passes the
            # threshold skips every suffix
            bound = group.problem.score(np.clip(np.abs(group.Pm[block]) - group.Qmax, 0.0, None))
            block = block[bound <= threshold + SCORE_TIE]
        if len(block):
            if selective:
                group.queried(block, top, threshold)
            else:
                group.brute(block, top)
        at += step
        if shared is not None:
            if pool.threshold < shared.value:
                with shared.get_lock():
                    shared.value = min(shared.value, pool.threshold)
            pool.threshold = min(pool.threshold, shared.value)
