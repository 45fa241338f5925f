"""Firing orders and intervals, fitted to the top dead centres of the geometry."""

from collections.abc import Mapping
from dataclasses import dataclass, field
from functools import lru_cache
from types import MappingProxyType
from typing import TYPE_CHECKING

import numpy as np

from ..errors import FiringError
from ..kinematics.tdc import tdc_angles
from ..tolerances import TDC_PRECISION_DEG, UNIFORM_FIRING_DEG
from ..units import round_degrees, wrap_degrees

if TYPE_CHECKING:
    from ..model import Engine

__all__ = ["Firing", "firing_sequence", "firing_angles"]

#: brute-force search of four-stroke orders up to this many cylinders
_EXHAUSTIVE_LIMIT = 16
_EPS = TDC_PRECISION_DEG


@dataclass(frozen=True)
class Firing:
    """Firing sequence over one working cycle.

    Attributes
    ----------
    order : tuple of int
        cylinder numbers in firing order
    angles_deg : tuple of float
        firing angles in firing order, the first at 0, degrees of crank (engine) angle
    intervals_deg : tuple of float
        gaps between consecutive firings, the last wrapping round the cycle, degrees
    uniform : bool
        every interval within ``UNIFORM_FIRING_DEG`` of cycle/cylinders
    given : bool
        the order came from the configuration (else it was chosen as the most uniform)
    tdc_deg : mapping (read-only)
        each cylinder's top-dead-centre engine angle in [0, 360), by cylinder number
    """

    order: tuple
    angles_deg: tuple
    intervals_deg: tuple
    uniform: bool
    given: bool
    tdc_deg: Mapping = field(default_factory=dict, compare=False)

    @property
    def max_deviation_deg(self) -> float:
        mean = sum(self.intervals_deg) / len(self.intervals_deg)
        return max(abs(i - mean) for i in self.intervals_deg)

    def to_dict(self) -> dict:
        """The ``firing`` entry of ``compare --format json``."""
        return {
            "order": list(self.order),
            "angles_deg": list(self.angles_deg),
            "intervals_deg": list(self.intervals_deg),
            "uniform": self.uniform,
            "max_deviation_deg": self.max_deviation_deg,
            "given": self.given,
        }


def _after(angle, reference):
    """``angle`` − ``reference`` in [0, 360), with TDCs equal to search precision made equal."""
    return wrap_degrees(angle - reference, tolerance=_EPS)


def _fit_order(order, tdc, cycle_deg):
    """Firing angles for ``order``, each at one of its TDCs, increasing through the cycle.

    Four-stroke firings must be strictly increasing (two cylinders at TDC together fire a
    revolution apart); a two-stroke fires at every TDC, so cylinders may fire together.
    """
    reference = tdc[order[0]]
    margin = _EPS if cycle_deg > 360.0 else -_EPS
    angles = [0.0]
    for number in order[1:]:
        angle = _after(tdc[number], reference)
        while angle <= angles[-1] + margin:
            angle += 360.0
        if angle >= cycle_deg - _EPS:
            raise FiringError(
                f"cylinder {number} cannot fire after cylinder {order[len(angles) - 1]} within one "
                f"{cycle_deg:.0f}° cycle (its TDCs are at {round_degrees(tdc[number], 1):.1f}° "
                f"+ n·360°); "
                f"list an order the crank allows, or leave firing_order out to get one"
            )
        angles.append(angle)
    return angles


def _intervals(angles, cycle_deg):
    return [b - a for a, b in zip(angles, angles[1:], strict=False)] + [
        cycle_deg - angles[-1] + angles[0]
    ]


def _scores(base, shifts, ideal, cycle_deg):
    """Worst and summed-square deviation of the gaps, and firing sequence, for each row of
    shifts."""
    angles = base[None, :] + shifts
    sequence = np.argsort(angles, axis=1, kind="stable")
    ordered = np.take_along_axis(angles, sequence, axis=1)
    gaps = np.diff(np.hstack([ordered, ordered[:, :1] + cycle_deg]), axis=1)
    worst = np.round(np.abs(gaps - ideal).max(axis=1), 3)
    spread = np.round(((gaps - ideal) ** 2).sum(axis=1), 3)
    return worst, spread, sequence


def _phase_sums(angles, n, cycle_deg):
    """Σ_{m=1}^{n−1} |Σ_j e^{2πi·m·a_j/cycle}|² for each row of firing angles a_j, degrees:
    the squared phase sums of the gas torque's orders below the n-th of the cycle, which an
    even firing cancels."""
    turns = np.asarray(angles) / cycle_deg
    total = np.zeros(len(turns))
    for m in range(1, n):
        total += np.abs(np.exp(2j * np.pi * m * turns).sum(axis=1)) ** 2
    return total


def _most_uniform_four_stroke(numbers, tdc, cycle_deg):
    """Choose for each cylinder which of its two TDCs fires, making the gaps most uniform.

    Up to ``_EXHAUSTIVE_LIMIT`` cylinders every choice is tried; beyond, a local search starts
    from alternate revolutions round the TDC sequence and flips one cylinder at a time while
    that helps (not guaranteed to be the best, but uniform where the usual layouts allow).
    """
    first = numbers[0]
    base = np.array([_after(tdc[n], tdc[first]) for n in numbers])
    n = len(numbers)
    ideal = cycle_deg / n
    if n <= _EXHAUSTIVE_LIMIT:
        # every choice as the bits of a counter, in itertools.product's order (the first
        # cylinder's own choice fixed at 0): the tuples of a 16-cylinder product took 40 ms
        bits = (np.arange(1 << (n - 1))[:, None] >> np.arange(n - 2, -1, -1)) & 1
        shifts = np.hstack([np.zeros((len(bits), 1)), 360.0 * bits])
    else:
        ranks = np.argsort(base, kind="stable")
        current = np.zeros(n)
        current[ranks[1::2]] = 360.0
        flips = np.eye(n)[1:] * 360.0
        for _ in range(4 * n):
            candidates = np.vstack([current, (current + flips) % cycle_deg])
            worst, spread, _ = _scores(base, candidates, ideal, cycle_deg)
            best = np.lexsort((spread, worst))[0]
            if best == 0:
                break
            current = candidates[best]
        shifts = current[None, :]
    worst, spread, sequence = _scores(base, shifts, ideal, cycle_deg)
    best = np.lexsort((spread, worst))[0]
    tied = np.flatnonzero((worst == worst[best]) & (spread == spread[best]))
    # gaps alike (the H16's 0° and 90°) can still bunch the firings (one in a 90° slot, three
    # in another): of those, the one that excites least gas torque below the n-th order
    excitation = _phase_sums(base[None, :] + shifts[tied], n, cycle_deg)
    tied = tied[excitation <= excitation.min() + 1e-6 * n * n]
    choice = min(tied, key=lambda i: tuple(numbers[j] for j in sequence[i]))
    angles = base + shifts[choice]
    order = tuple(numbers[j] for j in sequence[choice])
    return order, [float(angles[j]) for j in sequence[choice]]


@lru_cache(maxsize=256)
def firing_sequence(engine: "Engine") -> Firing:
    """The engine's firing sequence: the configured order fitted to the crank, or the most
    uniform one the crank allows. Found once per engine: every analysis asks for it.

    Raises
    ------
    FiringError
        the engine's ``firing_order`` cannot be fired within one cycle on this crank
    """
    tdc = tdc_angles(engine)
    cycle_deg = engine.cycle_deg
    numbers = sorted(tdc)
    given = engine.firing_order is not None
    if given:
        order = tuple(engine.firing_order or ())
        angles = _fit_order(order, tdc, cycle_deg)
    elif engine.cycle == 2:
        first = numbers[0]
        order = tuple(sorted(numbers, key=lambda n: (_after(tdc[n], tdc[first]), n)))
        angles = [_after(tdc[n], tdc[first]) for n in order]
    else:
        order, angles = _most_uniform_four_stroke(numbers, tdc, cycle_deg)
    intervals = _intervals(angles, cycle_deg)
    ideal = cycle_deg / len(order)
    uniform = max(abs(i - ideal) for i in intervals) <= UNIFORM_FIRING_DEG
    # kept for the engine and handed to every caller: read-only
    return Firing(order, tuple(angles), tuple(intervals), uniform, given, MappingProxyType(tdc))


def firing_angles(engine: "Engine") -> dict[int, float]:
    """The engine angle of each cylinder's firing top dead centre, by cylinder number, degrees
    in [0, cycle): where the gas torque and the torsional excitation put its pressure curve."""
    firing = firing_sequence(engine)
    start = firing.tdc_deg[firing.order[0]]
    return {
        n: (start + a) % engine.cycle_deg
        for n, a in zip(firing.order, firing.angles_deg, strict=True)
    }
