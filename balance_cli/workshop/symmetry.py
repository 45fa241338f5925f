"""Cylinders the crank makes equivalent: permutations of the cylinders that leave every
assignment's score as it is, found and checked on the engine's own numbers.

A permutation π is a symmetry when there is one turning of the crank by Δ (the coefficient of
order k times e^{ikΔ}), optionally read backwards in time and mirrored across the reference
axis (every coefficient conjugated), and one turning α of the transverse plane, that carry
each cylinder's responses (force, and its big end's where rods are fitted) onto those of
cylinder π(i), with its moments carried alike or reversed in sign (the crank read from the
other end: z − z̄ changes sign). None of these changes the largest force or moment over a
revolution, nor any order's |X⁺| + |X⁻|, nor its forward or backward part. Fitting part p at
cylinder i, or at π(i), then scores the same, so the assignments fall into classes of |G|
(the group's order) of which one is evaluated.
"""

import itertools

import numpy as np

__all__ = ["symmetries", "canonical", "SYMMETRY_TOLERANCE"]

#: responses equal to this fraction of the largest are the same (the FFT of exact positions
#: is good to about 1e-13)
SYMMETRY_TOLERANCE = 1e-9


def _matches(transformed, target, tolerance):
    """For each row of ``transformed``, the one row of ``target`` it equals, or None."""
    distance = np.linalg.norm(transformed[:, None, :] - target[None, :, :], axis=-1)
    close = distance <= tolerance
    if not np.all(close.sum(axis=1) == 1):
        return None
    image = close.argmax(axis=1)
    return image if len(set(image.tolist())) == len(image) else None


def symmetries(force, moment, orders, shift_ok=lambda delta: True):
    """The permutations of the cylinders (each an array: cylinder position i goes to
    ``perm[i]``) that are symmetries, the identity first.

    Parameters
    ----------
    force, moment : ndarray, complex, shape (n, L)
        each cylinder's response coefficients (its piston's, then its big end's where rods are
        fitted), N/kg and N·m/kg
    orders : ndarray of int, shape (L,)
        the signed order of each column
    shift_ok : callable
        whether a turning of the crank by Δ (rad) keeps the objective's angles (its grid)
    """
    n = force.shape[0]
    identity = tuple(range(n))
    scale = max(np.abs(force).max(), np.abs(moment).max(), 1e-300)
    tolerance = SYMMETRY_TOLERANCE * scale
    first = np.flatnonzero(orders == 1)[:1]
    last = np.flatnonzero(orders == -1)[:1]
    if not len(first) or not len(last):
        return [np.array(identity)]
    a, b = int(first[0]), int(last[0])
    if min(abs(force[0, a]), abs(force[0, b])) < 1e-6 * scale:
        return [np.array(identity)]
    found = {identity}
    both = np.hstack([force, moment])
    for mirrored in (False, True):
        base_f = np.conj(force) if mirrored else force
        base_m = np.conj(moment) if mirrored else moment
        for j in range(n):
            ahead, behind = force[j, a] / base_f[0, a], force[j, b] / base_f[0, b]
            if abs(abs(ahead) - 1) > 1e-6 or abs(abs(behind) - 1) > 1e-6:
                continue
            half = (np.angle(ahead) - np.angle(behind)) / 2
            for delta in (half, half + np.pi):
                if not shift_ok(delta):
                    continue
                turn = np.exp(1j * (np.angle(ahead) - delta + orders * delta))
                for sign in (1.0, -1.0):
                    image = _matches(
                        np.hstack([base_f * turn, base_m * turn * sign]), both, tolerance
                    )
                    if image is not None:
                        found.add(tuple(int(i) for i in image))
    group = [np.array(p) for p in sorted(found)]
    # the symmetries of one problem make a group: anything else is taken for noise, and none
    # is used
    for p, q in itertools.product(group, repeat=2):
        if tuple(int(i) for i in p[q]) not in found:
            return [np.array(identity)]
    return sorted(group, key=lambda p: tuple(p) != identity)


def canonical(perms, group):
    """Which rows of ``perms`` (each the part at every cylinder) are the least, in
    lexicographic order, of their class: ``perm`` and ``perm[inverse(π)]`` for every π of
    ``group`` (the part at i moved to π(i))."""
    keep = np.ones(len(perms), bool)
    for pi in group[1:]:
        moved = perms[:, np.argsort(pi)]
        differ = perms != moved
        first = differ.argmax(axis=1)
        rows = np.arange(len(perms))
        keep &= perms[rows, first] < moved[rows, first]
    return keep
