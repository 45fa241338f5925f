"""The heuristic search: steepest descent from random valid cranks, not proved optimal."""

from __future__ import annotations

import math

import numpy as np

from .kernel import SCORE_TIE, Chunk, Pool

__all__ = ["heuristic_search"]


def _score_cranks(problem, cranks):
    cranks = np.asarray(cranks)
    S = np.zeros((len(cranks), problem.rotated.shape[2]), complex)
    for j in range(problem.n_throws):
        S += problem.rotated[j, cranks[:, j]]
    return problem.score(np.abs(S))


def _random_crank(problem, rng):
    """A random valid crank: throws in random phases, backtracking when a lattice point fills."""
    P, cap, n = problem.lattice, problem.capacity, problem.n_throws
    counts = np.zeros(P, int)
    crank = [0] * n

    def place(j):
        if j == n:
            return True
        choices = [0] if j == 0 else rng.permutation(P)
        for p in choices:
            occ = [(e - p) % P for e in problem.offsets[j]]
            if cap:
                for x in occ:
                    counts[x] += 1
                if (counts > cap).any():
                    for x in occ:
                        counts[x] -= 1
                    continue
            crank[j] = int(p)
            if place(j + 1):
                return True
            for x in occ:
                counts[x] -= 1
        return False

    place(0)
    return tuple(crank)


def heuristic_search(problem, top, restarts, seed, progress):
    """Steepest descent from random cranks; moves: swap the phases of two throws that fire
    alike (keeps even firing), or, without even firing, turn one throw to another phase."""
    rng = np.random.default_rng(seed)
    n, P = problem.n_throws, problem.lattice
    pool = Pool(problem, top)
    pairs = [
        (a, b)
        for a in range(1, n)
        for b in range(a + 1, n)
        if sorted(problem.offsets[a]) == sorted(problem.offsets[b])
    ]
    evaluated = 0
    for _ in range(restarts):
        crank = np.array(_random_crank(problem, rng))
        score = float(_score_cranks(problem, [crank])[0])
        while True:
            moves = []
            for a, b in pairs:
                c = crank.copy()
                c[a], c[b] = c[b], c[a]
                moves.append(c)
            if not problem.capacity:
                for j in range(1, n):
                    for p in range(P):
                        if p != crank[j]:
                            c = crank.copy()
                            c[j] = p
                            moves.append(c)
            if not moves:
                break
            scores = _score_cranks(problem, moves)
            evaluated += len(moves)
            best = int(np.argmin(scores))
            if scores[best] >= score - SCORE_TIE:
                break
            crank, score = moves[best], float(scores[best])
        pool.threshold = math.inf
        pool.offer(score, tuple(int(p) for p in crank))
        if progress:
            progress(1)
    return [Chunk(list((s, k) for k, s in pool.best.items()), evaluated, 0, pool.truncated)]
