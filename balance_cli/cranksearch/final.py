"""The listed arrangements: the best classes expanded, each analysed as ``compare`` analyses
it, ranked by score and then firing order, with the coefficients the objective names.
"""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np

from ..analysis.firing import firing_sequence
from ..analysis.results import analyse
from ..analysis.torque import torque
from ..model import MAX_NAME_LENGTH
from .firing import arrangement_engine, crank_phases, expand
from .kernel import SCORE_TIE
from .objective import coefficients
from .results import Arrangement

__all__ = ["final"]


def final(
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
    tick=None,
    couple_units=None,
    tv_orders=(),
):
    """The listed arrangements: expanded to firing orders and mirror images, analysed exactly
    as ``compare`` would, ranked by score and then firing order."""
    members = expand(flat, problem, orbits, shift)
    rows = []
    for (crank, order), (score, _position) in members.items():
        phases = crank_phases(problem, crank)
        engine = None
        if order is None:  # uneven: the most uniform order the crank allows, not written
            engine = arrangement_engine(template, phases, order, template.name)
            order = firing_sequence(engine).order
        # scores are normalised (of order one, see channels): the tie is relative
        rows.append((round(score / SCORE_TIE), order, crank, phases, engine))
    rows.sort(key=lambda r: (r[0], r[1]))
    listed = []
    rank_of: dict = {}
    for rank, (_, order, crank, phases, engine) in enumerate(rows[:top], 1):
        if engine is None:  # built for the listed ones only: each costs a model check
            engine = arrangement_engine(template, phases, order, template.name)
        result = analyse(engine, samples, max_order)
        if tick:
            tick(1)
        values = _coefficients_of(result, units, pitch, terms, couple_units, tv_orders)
        score = float(sum(t.weight * values[t.name] for t in terms))
        suffix = f", arrangement {rank}"
        name = template.name[: MAX_NAME_LENGTH - len(suffix)].rstrip() + suffix
        engine = replace(result.engine, name=name)
        result = replace(result, engine=engine)
        mirror_of = None
        own = _reversal_class(problem, crank)
        if problem.mirror:
            partner = _reversal_class(problem, problem.images(crank)[1])
            mirror_of = rank_of.get(partner) if partner != own else None
        rank_of.setdefault(own, rank)
        listed.append(Arrangement(rank, score, phases, result, values, mirror_of))
    if tick and top > len(listed):
        tick(top - len(listed))
    return listed


def _reversal_class(problem, crank):
    if not problem.reversal:
        return crank
    return min(crank, tuple((-p) % problem.lattice for p in crank))


def _coefficients_of(result, units, pitch, terms, couple_units=None, tv_orders=()):
    """Every F_k, M_k by name (and the forward/backward parts and H_k, X_k the objective
    names)."""
    orders = result.shaking.orders
    engine = result.engine
    floors = (engine.noise_floor_n,) * 2 + (engine.noise_floor_nm,) * 2
    # the same noise floors as compare's: what it prints as zero is zero here too
    parts = [
        np.array([z if abs(z) >= floor else 0.0 for z in values])
        for values, floor in zip(
            zip(
                *(
                    (o.force_forward, o.force_backward, o.moment_forward, o.moment_backward)
                    for o in orders
                ),
                strict=True,
            ),
            floors,
            strict=True,
        )
    ]
    force_forward, force_backward, moment_forward, moment_backward = parts
    c = coefficients(force_forward, force_backward, moment_forward, moment_backward, units, pitch)
    values = {}
    for k in range(1, len(orders) + 1):
        for kind in "FM":
            values[f"{kind}{k}"] = float(c[kind][0][k - 1])
    for t in terms:
        if t.part != "max":
            values[t.name] = float(c[t.kind][1 if t.part == "forward" else 2][t.order - 1])
    if any(t.kind in ("V", "TV") for t in terms):
        # the arrangement's own firing angles and first mode, as balance torsion sums them
        from ..analysis.firing import firing_angles
        from ..torsion import first_mode_amplitudes, phase_vector_sum

        beta = first_mode_amplitudes(engine, result.samples)
        fire = firing_angles(engine)
        amplitudes = [beta[c.throw_index] for c in engine.cylinders]
        angles = [fire[c.number] for c in engine.cylinders]
        unit = sum(abs(b) for b in amplitudes)
        for t in terms:
            if t.kind == "V":
                values[t.name] = abs(phase_vector_sum(amplitudes, angles, t.order)) / unit
            if t.kind == "TV":
                values[t.name] = max(
                    (abs(phase_vector_sum(amplitudes, angles, k)) / unit for k in tv_orders),
                    default=0.0,
                )
    if couple_units is not None and any(t.kind in ("H", "X") for t in terms):
        # the arrangement's own torques, not the template's phasors turned: a second method
        guide = torque(result.engine, result.samples, len(orders), bearings=False).guide
        for t in terms:
            if t.kind in ("H", "X"):
                unit = couple_units[t.order - 1]
                series = guide.h_type if t.kind == "H" else guide.x_type
                lever = 1.0 if t.kind == "H" else guide.lever_m / pitch
                values[t.name] = (
                    float(math.hypot(*series.order(t.order)) * lever / unit) if unit > 0.0 else 0.0
                )
    return values
