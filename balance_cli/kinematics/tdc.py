"""Top dead centres: the engine angle at which each piston is farthest out, once per engine."""

import math
from functools import lru_cache

import numpy as np

from ..tolerances import TDC_PRECISION_DEG
from ..units import wrap_degrees
from .linkage import piston_travel

__all__ = ["tdc_angles"]

#: cylinders whose TDCs are refined together
_TDC_BLOCK = 16


def tdc_angles(engine) -> dict[int, float]:
    """Engine angle (degrees in [0, 360)) at which each piston is farthest out, by cylinder number.

    A plain rod's piston is farthest out where crank and rod are in line: in closed form. A
    link rod's or an opposed bore's travel has one maximum a revolution: found on a 0.5° grid,
    then refined three times by a factor of 50 on the exact linkage (to about 2e-6°). Found
    once per engine (the firing sequence, the search and ``show`` all ask for them).
    """
    return dict(_tdc_angles(engine))


@lru_cache(maxsize=256)
def _tdc_angles(engine):
    closed = _plain_tdc_crank_angles(engine)
    numbers = [c.number for c in engine.cylinders if c.number not in closed]
    if not numbers:
        return _as_engine_angles(engine, closed)
    grid = np.linspace(0.0, 2 * np.pi, 720, endpoint=False)
    travel = piston_travel(engine, grid, numbers)
    best = np.array([grid[np.argmax(travel[n])] for n in numbers])
    step = grid[1]
    for _ in range(3):
        # a fine grid round each cylinder's best angle, a block of cylinders at a time (each
        # block's grids are closed together and the diagonal kept): memory stays linear in
        # the number of cylinders, and the Python loop short
        for start in range(0, len(numbers), _TDC_BLOCK):
            block = numbers[start : start + _TDC_BLOCK]
            local = best[start : start + len(block), None] + np.linspace(-step, step, 101)
            travel = piston_travel(engine, local, block)
            for i, n in enumerate(block):
                best[start + i] = local[i, np.argmax(travel[n][i])]
        step /= 50
    closed.update(zip(numbers, best, strict=True))
    return _as_engine_angles(engine, closed)


def _plain_tdc_crank_angles(engine):
    """The crank angle (rad) of each plain-rod piston's top dead centre, in closed form: a
    piston offset o from its axis is farthest out, at l + r from the crank axis, where crank
    and rod are in line, the pin at asin(o/(l + r)) from the axis; link rods and opposed
    bores are found on the linkage instead."""
    out = {}
    reach = engine.rod_length_m + engine.crank_radius_m
    for c in engine.cylinders:
        if c.is_link or c.is_opposed:
            continue
        throw = engine.throws[c.throw_index]
        shaft = engine.crankshafts[throw.crankshaft_index]
        d = shaft.direction
        pin = engine.bank_angles_rad[c.bank_index] + math.asin(d * engine.pin_offset_of(c) / reach)
        # the pin points at d·(θ + φ_s + β)
        out[c.number] = d * pin - shaft.phase_rad - throw.phase_rad
    return out


def _as_engine_angles(engine, crank_rad):
    """Crank angles (rad) by cylinder as engine angles in degrees [0, 360), in the engine's
    cylinder order (a rotary's crankcase turns the other way)."""
    out = {}
    for c in engine.cylinders:
        angle = math.degrees(float(crank_rad[c.number]))
        out[c.number] = wrap_degrees(
            -angle if engine.is_rotary else angle, tolerance=TDC_PRECISION_DEG
        )
    return out
