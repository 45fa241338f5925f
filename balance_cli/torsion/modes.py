"""The natural modes of the shaft line as balance reports them: each shape scaled so that its
largest amplitude is +1 (amplitudes below :data:`~balance_cli.tolerances.MODE_FLOOR` of it
taken as zero), its phase-vector sums, and the criticals it meets in a speed range.

A mode is scaled by the largest amplitude of its whole shape, not of its throws: when every
throw sits at (or next to) a node, scaling by the throws' largest amplitude divided by
rounding noise and reported amplitudes of 10¹⁶ and phase-vector sums of a mode the cylinders
cannot excite.
"""

import math
from dataclasses import dataclass

import numpy as np

from ..tolerances import MODE_FLOOR
from ..units import rad_s_to_rpm
from .excitation import phase_vector_sum

__all__ = ["Mode", "Critical", "normalised", "modes_and_criticals", "CRITICAL_KINDS"]

#: an order whose equal-amplitude sum is within this fraction of the cylinders' number puts
#: them all in phase (a major order)
_MAJOR = 1e-6
#: what ``TorsionResult.filtered(criticals=...)`` and ``torsion --criticals`` choose from
CRITICAL_KINDS = ("excited", "major", "all")


def normalised(shape) -> np.ndarray:
    """``shape`` scaled so that its largest amplitude is +1, amplitudes below MODE_FLOOR of the
    largest set to exactly zero (rounding noise at a node)."""
    shape = np.asarray(shape, dtype=float)
    size = np.abs(shape)
    # the first of the largest amplitudes (to rounding), so that a symmetric mode's sign does
    # not depend on which of two equal ends the noise makes larger
    biggest = int(np.flatnonzero(size >= size.max() * (1 - 1e-9))[0])
    out = shape / shape[biggest]
    out[np.abs(out) < MODE_FLOOR] = 0.0
    return out


@dataclass(frozen=True)
class Mode:
    """One natural mode: its frequency, its shape over the shaft line (the largest amplitude
    +1, amplitudes below MODE_FLOOR zero) and its phase-vector sums by order."""

    number: int
    frequency_hz: float
    shape: np.ndarray  # per node
    throw_amplitudes: np.ndarray
    phase_vector_sums: dict  # order -> |Σ β e^{ikφ}|, 0.0 where the cylinders cannot excite it

    def excited(self, order) -> bool:
        """Whether the cylinders excite this mode at ``order``: its phase-vector sum is not
        zero (identical cylinders put a torque Σ β·e^{ikφ} times one cylinder's into it)."""
        return self.phase_vector_sums[float(order)] > 0.0

    def to_dict(self, names) -> dict:
        return {
            "mode": self.number,
            "frequency_Hz": self.frequency_hz,
            "frequency_cpm": 60.0 * self.frequency_hz,
            "shape": [
                {"node": name, "amplitude": float(a)}
                for name, a in zip(names, self.shape, strict=True)
            ],
            "throw_amplitudes": [float(a) for a in self.throw_amplitudes],
            "phase_vector_sums": [
                {"order": k, "sum": v, "excited": v > 0.0}
                for k, v in self.phase_vector_sums.items()
            ],
        }


@dataclass(frozen=True)
class Critical:
    """A mode's resonance with an order: at ``speed_rpm`` the order's frequency k·n equals
    the mode's. ``major``: the order puts every cylinder in phase; ``excited``: the mode's
    phase-vector sum at that order is not zero (a critical the cylinders cannot excite is
    listed, flagged, so that a speed near it is not mistaken for a resonance)."""

    mode: int
    order: float
    speed_rpm: float
    phase_vector_sum: float
    major: bool
    excited: bool = True

    @property
    def kind(self) -> str:
        """ "major" or "minor", with ", not excited" where the cylinders cannot excite it."""
        return ("major" if self.major else "minor") + ("" if self.excited else ", not excited")

    def to_dict(self) -> dict:
        return {
            "mode": self.mode,
            "order": self.order,
            "speed_rpm": self.speed_rpm,
            "phase_vector_sum": self.phase_vector_sum,
            "major": self.major,
            "excited": self.excited,
        }


def modes_and_criticals(omega_n, vectors, throw_nodes, fire, cylinders, orders, speed_range):
    """The modes (frequencies ``omega_n``, rad/s, shapes the columns of ``vectors``), the
    criticals of ``orders`` within ``speed_range`` (rpm, low and high), sorted by speed, and
    the major orders (those that put every cylinder in phase).
    ``fire`` maps a cylinder number to its firing angle (degrees), ``cylinders`` lists
    (number, throw index) pairs."""
    numbers = [number for number, _ in cylinders]
    throw_of = [throw for _, throw in cylinders]
    angles = [fire[m] for m in numbers]
    n_cyl = len(numbers)
    major = {
        float(k): abs(abs(phase_vector_sum(np.ones(n_cyl), angles, k)) - n_cyl) < _MAJOR * n_cyl
        for k in orders
    }
    low, high = speed_range
    modes, criticals = [], []
    for i, (w, raw) in enumerate(zip(omega_n, vectors.T, strict=True), 1):
        shape = normalised(raw)
        beta = shape[list(throw_nodes)]
        sums = {}
        for k in orders:
            total = abs(phase_vector_sum([beta[t] for t in throw_of], angles, k))
            # each |β| ≤ 1: a sum below MODE_FLOOR of the cylinders' number cancels to
            # rounding, and the cylinders cannot excite the mode at this order
            sums[float(k)] = total if total >= MODE_FLOOR * n_cyl else 0.0
        modes.append(Mode(i, w / (2 * math.pi), shape, beta, sums))
        for k in orders:
            rpm = rad_s_to_rpm(w / k)
            if low <= rpm <= high:
                value = sums[float(k)]
                criticals.append(Critical(i, float(k), rpm, value, major[float(k)], value > 0.0))
    criticals.sort(key=lambda c: c.speed_rpm)
    return tuple(modes), tuple(criticals), tuple(k for k, v in major.items() if v)
