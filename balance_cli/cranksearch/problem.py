"""The problem a crank search solves: every throw's order-k phasors, computed once from the
template's exact kinematics, the channels (complex sums) the objective's score needs with their
units and weights, and the picklable object that carries them to every worker.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from ..analysis.shaking import shaking_forces
from ..analysis.torque import torque
from ..errors import AnalysisError
from .objective import SCALAR_KINDS

__all__ = [
    "Problem",
    "throw_phasors",
    "guide_phasors",
    "torsion_phasors",
    "minor_orders",
    "guide_couple_units",
    "order_units",
    "mean_pitch",
    "objective_channels",
    "merge_channels",
    "MERGE_TOLERANCE",
]


@dataclass
class Problem:
    """Everything a worker needs, picklable: the lattice, the phasor tables, the objective's
    channels and the prefix/suffix tables."""

    n_throws: int
    lattice: int  # P: phase indices 0..P−1
    step_deg: float
    base_deg: np.ndarray  # (n_throws,) phase of index 0 for each throw
    capacity: int  # cylinders per lattice point (0: uneven, no constraint)
    offsets: list  # per throw: lattice offsets e_c of its cylinders
    rotated: np.ndarray  # (n_throws, P, C) complex: channel phasor at each phase index
    weights: np.ndarray  # (C,) score = Σ weights·|channel sum| (+ the TV1 part)
    reversal: bool
    mirror: bool
    split: int  # the prefix is throws 1 to split − 1 by their place in Engine.throws
    largest: Any = None  # (C,) TV1: score += max over channels of largest·|sum|
    offset: float = 0.0  # the part of every score no arrangement changes (merge_channels)
    followers: Any = None  # even banks: {cylinder: (bank-1 cylinder on its throw, angle after)}
    # filled by build_tables
    prefix_rows: Any = None  # (n_pref, split−1) phase indices
    prefix_group: Any = None  # (n_pref,) group index
    prefix_tie: Any = None  # (n_pref,) prefix equals its reversal
    suffix_rows: Any = None  # per group: (n_suf, n − split) rows
    suffix_key: Any = None  # per group: mirror key (sorted), or None
    suffix_leader: Any = None  # per group: suffix ≤ its reversal

    def score(self, magnitudes):
        """The score of channel magnitudes |sum| (..., C): the weighted sum, plus a TV1
        term's largest scaled magnitude, plus the constant part of every score."""
        out = magnitudes @ self.weights + self.offset
        if self.largest is not None:
            out = out + (magnitudes * self.largest).max(axis=-1)
        return out

    def crank(self, prefix, suffix):
        return (0,) + tuple(int(p) for p in prefix) + tuple(int(p) for p in suffix)

    def images(self, crank):
        """The crank's symmetry class: itself, its reversal, mirror image and both."""
        P = self.lattice
        out = [crank]
        if self.mirror:
            last = crank[-1]
            out.append(tuple((crank[-1 - j] - last) % P for j in range(len(crank))))
        if self.reversal:
            out += [tuple((-p) % P for p in c) for c in list(out)]
        return out

    def orbit_key(self, crank):
        return min(self.images(crank))


def throw_phasors(template, samples, max_order):
    """Per throw and order: forward and backward force (N) and moment (N·m) phasors."""
    shaking = shaking_forces(template, samples, max_order)
    masses = shaking.masses
    per_mass = shaking.mass_coefficients
    # shaking_forces keeps the per-mass shares (a balancer added by Shaking.plus drops them)
    assert masses is not None and per_mass is not None
    orders = np.arange(1, max_order + 1)
    lever = (masses.z_m - template.mean_z_m)[:, None]
    n = len(template.throws)
    out = np.zeros((4, n, max_order), complex)
    for j in range(n):
        mine = masses.throw_index == j
        forces = per_mass[mine]
        out[0, j] = forces[:, orders].sum(axis=0)
        out[1, j] = forces[:, -orders].sum(axis=0)
        out[2, j] = (lever[mine] * forces[:, orders]).sum(axis=0)
        out[3, j] = (lever[mine] * forces[:, -orders]).sum(axis=0)
    return out


def guide_phasors(template, samples, max_order):
    """Per throw and order, the H-type and X-type phasors (kinds 4 and 5): Σ over the throw's
    cylinders of the couple's (cos − i·sin), whose modulus is the amplitude, and that times
    z − z̄. Turning a throw by β shifts its cylinders' couples by β in θ (firing with them), so
    these turn by e^{ikβ} like a forward force phasor. For a four-stroke a whole order of the
    720° couple is the same whichever revolution a cylinder fires in; half orders are not
    searched. The X-type's division by the guide distance cancels in its coefficient."""
    guide = torque(template, samples, max_order, bearings=False).guide
    out = np.zeros((2, len(template.throws), max_order), complex)
    for cylinder, own in zip(template.cylinders, guide.cylinders, strict=True):
        for k in range(1, max_order + 1):
            cos, sin = own.couple.order(k)
            out[0, cylinder.throw_index, k - 1] += complex(cos, -sin)
            out[1, cylinder.throw_index, k - 1] += complex(cos, -sin) * (
                cylinder.z_m - guide.mean_z_m
            )
    return out


def torsion_phasors(template, samples, max_order):
    """Per throw and order, the first torsional mode's phasor (kind 6): β_j·Σ_c e^{−ik·γ_c}
    over the throw's cylinders (γ_c their banks), β_j the mode's amplitude at the throw. A
    cylinder fires at θ = γ_c − β_throw (a whole order does not see which revolution), so
    turning the throw by β turns the phasor by e^{ikβ} like a forward force phasor, and the
    sum's modulus is the phase-vector sum |Σ_c β·e^{ik·φ_c}|. Also the unit of each order:
    Σ_c |β| (every cylinder in phase)."""
    from ..torsion import first_mode_amplitudes

    beta = first_mode_amplitudes(template, samples)
    orders = np.arange(1, max_order + 1)
    out = np.zeros((1, len(template.throws), max_order), complex)
    for cylinder in template.cylinders:
        gamma = template.bank_angles_rad[cylinder.bank_index]
        out[0, cylinder.throw_index] += beta[cylinder.throw_index] * np.exp(-1j * orders * gamma)
    unit = sum(abs(beta[c.throw_index]) for c in template.cylinders)
    return out, np.full(max_order, unit)


def minor_orders(template, allow_uneven, max_order):
    """The whole orders 1..max_order a TV1 term takes the largest V of: for an even-firing
    search all but the major orders, where the firing angles, equally spaced, put every
    cylinder in phase whatever the arrangement (k times the interval a multiple of 360°)."""
    if allow_uneven:
        return tuple(range(1, max_order + 1))
    interval = template.cycle_deg / template.n_cylinders
    return tuple(
        k for k in range(1, max_order + 1) if abs(math.remainder(k * interval, 360.0)) > 1e-9
    )


def guide_couple_units(guide, floor):
    """The order-k couple amplitude of one throw alone, N·m (0 below the noise floor: the two
    cylinders of a 90° V throw cancel at order 2 to rounding, and a unit of 1e-10 made a
    coefficient of noise)."""
    largest = np.abs(guide[0]).max(axis=0)
    return np.where(largest > floor, largest, 0.0)


def order_units(phasors, floor):
    """The largest order-k force of one throw alone, N (0 below the noise floor)."""
    largest = (np.abs(phasors[0]) + np.abs(phasors[1])).max(axis=0)
    return np.where(largest > floor, largest, 0.0)


def mean_pitch(template):
    z = sorted(t.z_m for t in template.throws)
    pitch = (z[-1] - z[0]) / (len(z) - 1)
    if pitch <= 0.0:
        raise AnalysisError(
            "has every throw at the same axial position, so moments have no "
            "pitch to refer to; give each throw its z",
            "template",
        )
    return pitch


def objective_channels(
    objective, units, pitch, couple_units=None, torsion_units=None, tv_orders=()
):
    """The complex sums the score needs, (kind 0..6, order index), and their weights, divided
    by the largest term weight (the search compares scores of order one; see SCORE_TIE); and
    for a TV1 term, which of them it takes the largest of (a mask) with their scales."""
    weights: dict[tuple[int, int], float] = {}  # (kind, order index): weight
    largest = max(term.weight for term in objective)
    tv = {}
    for term in objective:
        if term.kind == "TV":
            for order in tv_orders:
                if torsion_units[order - 1] > 0.0:
                    weights.setdefault((6, order - 1), 0.0)
                    tv[(6, order - 1)] = term.weight / largest / torsion_units[order - 1]
            continue
        k = term.order - 1
        unit = (
            couple_units[k]
            if term.kind in ("H", "X")
            else torsion_units[k]
            if term.kind == "V"
            else units[k]
        )
        if unit == 0.0:
            continue
        scale = term.weight / largest / unit / (pitch if term.kind in ("M", "X") else 1.0)
        first = {"F": 0, "M": 2, "H": 4, "X": 5, "V": 6}[term.kind]
        parts = {"max": (0, 1), "forward": (0,), "backward": (1,)}[term.part]
        if term.kind in SCALAR_KINDS:
            parts = (0,)  # a real torque: its forward phasor alone carries the amplitude
        for p in parts:
            key = (first + p, k)
            weights[key] = weights.get(key, 0.0) + scale
    keys = sorted(weights)
    return (keys, np.array([weights[c] for c in keys]), np.array([tv.get(c, 0.0) for c in keys]))


#: two channels are merged when one's phasors are the other's (or their conjugates) times
#: one factor to this fraction of the largest: the FFT leaves about 1e-14, and a score changed
#: by 1e-12 of itself stays far inside SCORE_TIE
MERGE_TOLERANCE = 1e-12


def merge_channels(rotated, weights, largest):
    """Channels whose magnitudes are proportional for every crank, merged into one; channels
    that no crank changes, set aside as a constant.

    When every phasor of channel b (every throw, every phase) is λ times channel a's, or λ
    times its conjugate, |Σ b| = |λ|·|Σ a| for every crank, so the score needs a alone with
    weight w_a + |λ|·w_b (and, for a TV1 term, the larger of the two scales). An in-line
    engine's forward and backward parts are such a pair for every order (its throws' phasors
    lie on one line, and turning a throw turns them opposite ways): half the channels. A
    channel that is zero for every crank is dropped, and one whose every throw's phasor is the
    same at every phase (an in-line N two-stroke's order N: every cylinder in phase whatever
    the crank) adds its weighted |sum| to every score instead. Returns (rotated, weights,
    largest, offset) of the channels kept.
    """
    C = rotated.shape[2]
    flat = rotated.reshape(-1, C)
    weights = np.array(weights, float)
    largest = None if largest is None else np.array(largest, float)
    kept: list[int] = []
    offset = 0.0
    for b in range(C):
        column = flat[:, b]
        big = np.abs(column).max()
        if big == 0.0:
            continue
        if (largest is None or largest[b] == 0.0) and np.abs(
            rotated[:, :, b] - rotated[:, :1, b]
        ).max() <= MERGE_TOLERANCE * big:
            offset += weights[b] * abs(rotated[:, 0, b].sum())
            continue
        merged = False
        for a in kept:
            base = flat[:, a]
            at = int(np.argmax(np.abs(base)))
            for candidate in (base, base.conjugate()):
                factor = column[at] / candidate[at]
                if np.abs(column - factor * candidate).max() <= MERGE_TOLERANCE * big:
                    weights[a] += abs(factor) * weights[b]
                    if largest is not None:
                        largest[a] = max(largest[a], abs(factor) * largest[b])
                    merged = True
                    break
            if merged:
                break
        if not merged:
            kept.append(b)
    out_largest = None if largest is None else largest[kept]
    if out_largest is not None and not np.any(out_largest):
        out_largest = None
    return rotated[:, :, kept], weights[kept], out_largest, offset
