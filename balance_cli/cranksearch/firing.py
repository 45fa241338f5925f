"""Firing orders of the cranks found: every order an even-firing crank allows, the order of
the reversed engine, and the expansion of the best symmetry classes into distinct arrangements.
"""

from __future__ import annotations

import itertools
import math
from dataclasses import replace

from ..model import Throw
from ..units import round_degrees

__all__ = ["firing_orders", "reversed_order", "crank_phases", "arrangement_engine", "expand"]


def _cylinder_lattice(template, problem, crank):
    """Each cylinder's lattice index (top dead centre in steps of the firing interval); the
    followers of an even-banks search are not on the lattice."""
    P = problem.lattice
    follow = problem.followers or {}
    out = {}
    for j in range(problem.n_throws):
        mine = sorted(
            c.number for c in template.cylinders if c.throw_index == j and c.number not in follow
        )
        for c, e in zip(mine, problem.offsets[j], strict=True):
            out[c] = (e - crank[j]) % P
    return out


def firing_orders(template, problem, crank):
    """Every firing order of an even-firing crank: which of its cylinders fires at each
    firing slot of its lattice point (for a four-stroke, in which revolution)."""
    P, s = problem.lattice, problem.step_deg
    cycle = template.cycle_deg
    n_cyl = template.n_cylinders
    interval = cycle / (n_cyl - len(problem.followers or {}))
    index = _cylinder_lattice(template, problem, crank)
    first = min(index)
    points: dict[int, list] = {}
    for c, i in index.items():
        points.setdefault((i - index[first]) % P, []).append(c)
    options = []
    for r, cyls in sorted(points.items()):
        slots = [
            a
            for a in (r * s + 360.0 * t for t in range(template.cycle // 2))
            if abs(a / interval - round(a / interval)) < 1e-9
        ]
        choices = []
        for perm in itertools.permutations(slots):
            assignment = dict(zip(sorted(cyls), perm, strict=True))
            if first in assignment and abs(assignment[first]) > 1e-9:
                continue
            choices.append(assignment)
        options.append(choices)
    orders = []
    for combination in itertools.product(*options):
        angles = {c: a for part in combination for c, a in part.items()}
        # an even-banks search: each other bank's cylinder fires its fixed angle after the
        # cylinder of bank 1 on its throw (within the revolution after it)
        for c, (mate, delta) in (problem.followers or {}).items():
            angles[c] = (angles[mate] + delta) % cycle
        orders.append(tuple(sorted(angles, key=lambda c: (angles[c], c))))
    return orders


def reversed_order(order, template, problem, shift):
    """The firing order of the reversed engine, with cylinders renamed across the reflection
    (a cylinder goes to the one of its throw at the mirrored lattice offset)."""
    rename = {}
    for j in range(problem.n_throws):
        mine = sorted(c.number for c in template.cylinders if c.throw_index == j)
        e = problem.offsets[j]
        used = set()
        for c, ec in zip(mine, e, strict=True):
            target = (shift - ec) % problem.lattice
            partner = next(
                x for x, ex in zip(mine, e, strict=True) if ex == target and x not in used
            )
            used.add(partner)
            rename[c] = partner
    backwards = [rename[c] for c in reversed(order)]
    start = backwards.index(min(backwards))
    return tuple(backwards[start:] + backwards[:start])


def crank_phases(problem, crank):
    return tuple(
        round_degrees((problem.base_deg[j] + p * problem.step_deg) % 360.0, 9) % 360.0
        for j, p in enumerate(crank)
    )


def arrangement_engine(template, phases, order, name):
    throws = tuple(
        Throw(math.radians(p if p <= 180.0 else p - 360.0), t.z_m)
        for p, t in zip(phases, template.throws, strict=True)
    )
    return replace(template, throws=throws, firing_order=order, name=name)


def expand(template, problem, orbits, shift):
    """Distinct arrangements (crank, firing order) of the best classes, each with the score of
    its class and its mirror partner: [(score, firing order, crank, mirror crank or None)]."""
    out = {}
    for score, key in orbits:
        cranks = [key]
        if problem.mirror:
            mirrored = problem.images(key)[1]
            cranks.append(mirrored)
        for position, crank in enumerate(cranks):
            if problem.capacity:
                orders = firing_orders(template, problem, crank)
            else:
                orders = [None]
            for order in orders:
                member = (crank, order)
                if problem.reversal and order is not None:
                    reverse = (
                        tuple((-p) % problem.lattice for p in crank),
                        reversed_order(order, template, problem, shift),
                    )
                    if reverse[1] < order:
                        member = reverse
                elif problem.reversal and order is None:
                    reverse = (tuple((-p) % problem.lattice for p in crank), None)
                    member = min(member, reverse, key=lambda m: m[0])
                if member not in out:
                    out[member] = (score, position)
    return out
