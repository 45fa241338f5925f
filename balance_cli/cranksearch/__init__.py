"""The best crank arrangements and firing orders of a template engine, with proof.

A template is an engine whose throw phases are to be chosen (see
:func:`balance_cli.config.load_template`). The search varies the phases of throws 2..n
(throw 1 stays at 0°: turning the whole crank changes nothing) and, for a four-stroke, which
of its two top dead centres each cylinder fires at.

**Evaluation.** Every throw's order-k phasors (its cylinders and crank-pin masses, forces
and moments about the cylinders' mean axial position) are computed once, from the exact
kinematics of the template (:func:`balance_cli.analysis.shaking.shaking_forces`). Turning a throw by
β turns its forward parts by kβ and its backward parts by −kβ, so an arrangement's orders
are sums of rotated phasors: exact for any rod type, and no per-layout formula.

**Even firing.** Every cylinder's top dead centre must fall on one lattice of spacing s
(360°/cylinders for a two-stroke; 720°/cylinders for a four-stroke with an even number of
cylinders, 360°/cylinders with an odd one), each lattice point taken by the same number of
cylinders. A throw's phase is then a lattice multiple, and the arrangement is an exact
cover, which is enumerated without ever producing an uneven crank.

**Exhaustive enumeration (meet in the middle).** The free throws are split into a prefix and
a suffix. Prefixes are grouped by the lattice points they fill; each group is paired with the
suffixes that fill the rest, and every (prefix, suffix) score is a sum of the two partial
phasor sums: one vectorised block per group, which processes or a Dask cluster share.

**Symmetries** (each checked on the template's own numbers before it is used):

- *reversal* (running the other way round, every phase negated): used when every throw's
  phasors lie on one line through the origin for every order (then |Σ aⱼe^{−ikβⱼ}| =
  |Σ aⱼe^{ikβⱼ}| exactly) and the firing lattice is symmetric; such arrangements count once.
- *mirror image* (the crank read from the other end): used when throw n+1−j's phasors are
  throw j's times one unit factor per order and part, and the throws fire alike; a mirror
  image is a different engine, listed, but its score is known without evaluating it.

Only the lexicographically least member of each symmetry class is evaluated (a lex-leader
condition on the prefix and a slice of the sorted suffixes).

**Bounds.** |P + Q| ≥ |P| − max|Q|: a prefix whose lower bound exceeds the K-th best score
found so far cannot improve on it and is skipped, with its suffixes. Evaluated + skipped by
bound + skipped by symmetry = every arrangement, which is the proof of optimality.
"""

from __future__ import annotations

import itertools
import math
import os
import re
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass, replace
from typing import Any

import numpy as np

from ..analysis.results import DOCUMENT_VERSION, EngineResult, analyse
from ..errors import AnalysisError
from ..analysis.firing import firing_sequence, tdc_angles
from ..kinematics.linkage import check_assembly
from ..model import MAX_NAME_LENGTH, Engine, Throw
from ..analysis.shaking import DEFAULT_MAX_ORDER, DEFAULT_SAMPLES, check_settings, shaking_forces
from ..tolerances import UNIFORM_FIRING_DEG
from ..analysis.torque import torque
from ..units import round_degrees

__all__ = ["Term", "parse_objective", "default_objective", "coefficients", "Arrangement",
           "SearchResult", "search", "DEFAULT_TOP", "DEFAULT_LIMIT"]

DEFAULT_TOP = 10
#: more arrangements than this are not listed: each is analysed as compare analyses it (about
#: 5 ms and 110 kB apiece, measured on an in-line 10), so 1000 take seconds and 110 MB where
#: the 100 000 once accepted grew past 7 GB
MAX_TOP = 1000
#: an exhaustive search evaluating more arrangements than this is refused (about a minute
#: on two cores); --limit raises it, --heuristic or a cluster are the alternatives
DEFAULT_LIMIT = 2_000_000_000
#: scores closer than this are equal (the coefficients are of order one and carry rounding
#: errors of about 1e-14); equal scores are ranked by firing order. Scores are compared with
#: the weights divided by the largest one, so the tie is relative to the score's scale: a
#: lone term of weight 1e-10 still ranks M1 = 0 above M1 = 5
SCORE_TIE = 1e-9
#: the weights a term may have: the scores they make stay finite (a coefficient is at most a
#: few times the number of throws squared) and their ratio within what a double resolves
WEIGHT_RANGE = (1e-100, 1e100)
#: phasors of a symmetry check may differ by this fraction of the largest throw phasor
SYMMETRY_TOLERANCE = 1e-9
#: more arrangements than this tying at the K-th best score are not all kept
TIE_CAP = 100_000
#: more processes than this are refused (each costs memory and start-up)
MAX_WORKERS = 1024
#: cheapest count of even-firing cranks by dynamic programming, in state updates: beyond it
#: (an in-line 20 took 38 s) the count is a closed form or an upper bound
_COUNT_WORK = 10_000_000
#: a block of (prefix × suffix × channel) values evaluated at once
_BLOCK = 1 << 21
_TERM = re.compile(r"^\s*(TV|[FMHXV])(\d+)([+-]?)\s*(?::\s*(.+?))?\s*$")
_HALF_ORDER = re.compile(r"^\s*[FMHXV]\s*\d*\.\d*")
#: the kinds that are one real quantity per order, with no forward or backward part
_SCALAR_KINDS = ("H", "X", "V", "TV")


# --- objective ------------------------------------------------------------------------

@dataclass(frozen=True)
class Term:
    """One part of the objective: ``weight`` × the coefficient ``name``.

    ``kind`` "F" (force), "M" (moment), "H" (H-type guide-force moment), "X" (X-type) or
    "V" (the first torsional mode's phase-vector sum, :mod:`balance_cli.torsion`) or "TV"
    (order 1 only: the first mode's largest V over the minor orders, see :func:`search`);
    ``part`` "max" (the order's largest value, |X⁺| + |X⁻|), "forward" (|X⁺|) or "backward"
    (|X⁻|); H, X and V are one real quantity per order, "max" only (their amplitude).
    """

    kind: str
    order: int
    part: str = "max"
    weight: float = 1.0

    @property
    def name(self) -> str:
        return f"{self.kind}{self.order}" + {"max": "", "forward": "+", "backward": "-"}[self.part]

    def __str__(self) -> str:
        return self.name if self.weight == 1.0 else f"{self.name}:{self.weight:g}"


def default_objective(max_order: int = DEFAULT_MAX_ORDER) -> tuple[Term, ...]:
    """Every F_k and M_k for k = 1..max_order, weight 1."""
    return tuple(Term(kind, k) for k in range(1, max_order + 1) for kind in "FM")


def parse_objective(text: str | None, max_order: int = DEFAULT_MAX_ORDER) -> tuple[Term, ...]:
    """Terms from ``"F2:4,M1,M2"``: a coefficient name (F or M, an order, + or − for the
    forward or backward part only), optionally ``:weight`` (default 1); None or empty for
    :func:`default_objective`.

    Raises
    ------
    AnalysisError
        naming ``objective`` (or ``max_order`` for an order above it)
    """
    if text is None:
        return default_objective(max_order)
    if not isinstance(text, str) or not text.strip():
        raise AnalysisError("is empty; give terms such as M1,M2 (or leave it out for every F_k "
                            "and M_k)", "objective")
    terms: list[Term] = []
    for item in text.split(","):
        match = _TERM.match(item)
        if not match and _HALF_ORDER.match(item):
            # a four-stroke's half orders of a cylinder's couple turn with the revolution it
            # fires in, which a throw's phase does not fix: no phasor per throw to sum
            raise AnalysisError(f"term {item.strip()!r}: the search takes whole orders only (half "
                                "orders of a four-stroke depend on which revolution each cylinder "
                                "fires in, not on the crank alone)", "objective")
        if not match:
            raise AnalysisError(f"term {item.strip()!r} is not a coefficient such as F2, M1, F1+, "
                                "H4, V3 or F2:4 (F force, M moment, H and X the H- and X-type "
                                "guide-force moments, V the first torsional mode's phase-vector "
                                "sum, the order, + forward or - backward part only, :weight)",
                                "objective")
        kind, order, sign, weight_text = match.groups()
        if kind in _SCALAR_KINDS and sign:
            raise AnalysisError(f"term {item.strip()!r}: {kind} is one quantity per order, "
                                f"with no forward or backward part; write {kind}{order}",
                                "objective")
        order = int(order)
        if order < 1:
            raise AnalysisError(f"term {item.strip()!r}: orders start at 1", "objective")
        if kind == "TV" and order != 1:
            raise AnalysisError(f"term {item.strip()!r}: TV1 (the first torsional mode) is the "
                                "one TV term; name single orders of it with V terms", "objective")
        if order > max_order:
            raise AnalysisError(f"term {item.strip()!r} asks for order {order}, but orders 1 to "
                                f"{max_order} are analysed; set max_order to {order} or drop the "
                                "term", "objective")
        weight = 1.0
        if weight_text is not None:
            try:
                weight = float(weight_text)
            except ValueError:
                weight = math.nan
            if not _weight_ok(weight):
                raise AnalysisError(f"term {item.strip()!r}: the weight after ':' must be a "
                                    f"positive number from {WEIGHT_RANGE[0]:g} to "
                                    f"{WEIGHT_RANGE[1]:g}, such as 4", "objective")
        term = Term(kind, order, {"": "max", "+": "forward", "-": "backward"}[sign], weight)
        if any(t.name == term.name for t in terms):
            raise AnalysisError(f"term {term.name} is listed twice; give it once (with a "
                                "weight if it matters more)", "objective")
        terms.append(term)
    return tuple(terms)


def _weight_ok(weight):
    return (isinstance(weight, (int, float, np.integer, np.floating)) and not isinstance(weight, bool)
            and math.isfinite(weight) and WEIGHT_RANGE[0] <= weight <= WEIGHT_RANGE[1])


def _check_terms(terms, max_order):
    """Terms given as objects must be what :func:`parse_objective` would have made: a bound
    that assumes positive weights is no proof with a negative or non-finite one."""
    if not terms:
        raise AnalysisError(f"must name coefficients of orders 1 to {max_order}", "objective")
    for term in terms:
        if not isinstance(term, Term):
            raise AnalysisError(f"must be a string such as 'M1,M2' or Terms, got {term!r}",
                                "objective")
        if (term.kind not in ("F", "M", "H", "X", "V", "TV")
                or (term.kind == "TV" and term.order != 1)
                or term.part not in (("max",) if term.kind in _SCALAR_KINDS else
                                     ("max", "forward", "backward"))
                or isinstance(term.order, bool) or not isinstance(term.order, (int, np.integer))
                or not 1 <= term.order <= max_order):
            raise AnalysisError(f"term {term!r} must be F or M, of an order from 1 to {max_order}, "
                                "part max, forward or backward, or H, X or V, part max, or TV1",
                                "objective")
        if not _weight_ok(term.weight):
            raise AnalysisError(f"term {term.name}: the weight must be a positive number from "
                                f"{WEIGHT_RANGE[0]:g} to {WEIGHT_RANGE[1]:g}, got {term.weight!r}",
                                "objective")
    names = [t.name for t in terms]
    twice = next((name for name in names if names.count(name) > 1), None)
    if twice:
        raise AnalysisError(f"term {twice} is listed twice; give it once", "objective")


def coefficients(force_forward, force_backward, moment_forward, moment_backward, units_n,
                 pitch_m):
    """F_k and M_k (max, forward and backward parts) from phasors of orders 1..K.

    The one home of the coefficients: the search's vectorised kernel and the report of each
    result both use it. Arrays of shape (..., K): forces in N, moments in N·m; ``units_n``
    (K,) the largest order-k force of one throw alone (0 where a throw has no order-k force:
    the coefficient is 0 there), ``pitch_m`` the mean throw pitch.

    Returns a dict {"F": (max, forward, backward), "M": (...)} of arrays (..., K).
    """
    units_n = np.asarray(units_n, float)
    scale = np.divide(1.0, units_n, out=np.zeros_like(units_n), where=units_n > 0.0)
    out = {}
    for kind, forward, backward, unit in (("F", force_forward, force_backward, 1.0),
                                          ("M", moment_forward, moment_backward, pitch_m)):
        f = np.abs(forward) * scale / unit
        b = np.abs(backward) * scale / unit
        out[kind] = (f + b, f, b)
    return out


# --- results --------------------------------------------------------------------------

@dataclass(frozen=True)
class Arrangement:
    """One arrangement found: a crank and a firing order, with its analysis.

    Attributes
    ----------
    rank : int
        1 for the best
    score : float
        the objective's weighted sum of coefficients
    phases_deg : tuple of float
        throw phases, throw 1 first (at 0), degrees in [0, 360)
    result : EngineResult
        the arrangement analysed as ``balance compare`` analyses it (firing included)
    coefficients : dict
        every F_k and M_k (k = 1..max_order) by name, and the objective's forward/backward
        parts (``F1+``, ``M2-``) where it names them
    mirror_of : int or None
        the rank of the first arrangement listed above this one whose crank is this crank's
        mirror image (read from the other end), when it is another crank
    """

    rank: int
    score: float
    phases_deg: tuple
    result: EngineResult
    coefficients: dict
    mirror_of: int | None = None

    @property
    def engine(self) -> Engine:
        return self.result.engine

    @property
    def firing_order(self) -> tuple:
        return self.result.firing.order

    def to_dict(self) -> dict:
        """One entry of ``results`` in ``search --format json``."""
        full = self.result.to_dict()
        return {"rank": self.rank, "score": self.score, "phases_deg": list(self.phases_deg),
                "firing": {"order": list(self.result.firing.order),
                           "intervals_deg": list(self.result.firing.intervals_deg),
                           "uniform": self.result.firing.uniform},
                "mirror_of": self.mirror_of,
                "coefficients": dict(self.coefficients), "orders": full["orders"]}


@dataclass(frozen=True)
class SearchResult:
    """What ``balance search`` reports.

    Attributes
    ----------
    template : Engine
    objective : tuple of Term
    arrangements : tuple of Arrangement
        the best, ranked (score, then firing order)
    arrangements_total : int
        arrangements with throw 1 at 0° (every crank and, for a four-stroke, every choice of
        firing top dead centres), before any symmetry
    arrangements_distinct : int
        counting an arrangement and the same engine run the other way round once
    evaluated : int
        cranks scored one by one (mirror images and reversals of evaluated ones are not)
    pruned : int
        cranks skipped because a bound proved they cannot beat the K-th best
    exhaustive : bool
        the listed scores are proved the best (full enumeration with symmetries and bounds);
        False for a heuristic search
    method : str
        "exhaustive" or "heuristic"
    symmetries : tuple of str
        the symmetries used
    firing_orders_per_crank : int
    even : bool
        arrangements fire evenly (False with allow_uneven)
    step_deg : float
        the phase lattice (degrees)
    ties_truncated : bool
        more than TIE_CAP cranks tied at the K-th best score; the tie-break by firing order
        saw only the first found
    elapsed_s : float
    workers : int
    max_order, samples : int
    """

    template: Engine
    objective: tuple
    arrangements: tuple
    arrangements_total: int
    arrangements_distinct: int
    evaluated: int
    pruned: int
    exhaustive: bool
    method: str
    symmetries: tuple
    firing_orders_per_crank: int
    even: bool
    step_deg: float
    ties_truncated: bool
    elapsed_s: float
    workers: int
    max_order: int
    samples: int

    def to_dict(self) -> dict:
        """What ``search --format json`` writes (see the README)."""
        return {
            "balance_version": DOCUMENT_VERSION,
            "template": self.template.config_path or self.template.name,
            "name": self.template.name,
            "objective": [str(t) for t in self.objective],
            "method": self.method,
            "even_firing": self.even,
            "step_deg": self.step_deg,
            "arrangements_total": self.arrangements_total,
            "arrangements_distinct": self.arrangements_distinct,
            "firing_orders_per_crank": self.firing_orders_per_crank,
            "evaluated": self.evaluated,
            "pruned": self.pruned,
            "exhaustive": self.exhaustive,
            "symmetries": list(self.symmetries),
            "ties_truncated": self.ties_truncated,
            "elapsed_s": self.elapsed_s,
            "workers": self.workers,
            "samples": self.samples,
            "max_order": self.max_order,
            "results": [a.to_dict() for a in self.arrangements],
        }


# --- the problem ----------------------------------------------------------------------

@dataclass
class _Problem:
    """Everything a worker needs, picklable: the lattice, the phasor tables, the objective's
    channels and the prefix/suffix tables."""

    n_throws: int
    lattice: int                  # P: phase indices 0..P−1
    step_deg: float
    base_deg: np.ndarray          # (n_throws,) phase of index 0 for each throw
    capacity: int                 # cylinders per lattice point (0: uneven, no constraint)
    offsets: list                 # per throw: lattice offsets e_c of its cylinders
    rotated: np.ndarray           # (n_throws, P, C) complex: channel phasor at each phase index
    weights: np.ndarray           # (C,) score = Σ weights·|channel sum| (+ the TV1 part)
    reversal: bool
    mirror: bool
    split: int                    # prefix throws are 1..split−1 (0-based: 1..split-1)
    largest: Any = None           # (C,) TV1: score += max over channels of largest·|sum|
    # filled by _build_tables
    prefix_rows: Any = None     # (n_pref, split−1) phase indices
    prefix_group: Any = None    # (n_pref,) group index
    prefix_tie: Any = None      # (n_pref,) prefix equals its reversal
    suffix_rows: Any = None     # per group: (n_suf, n − split) rows
    suffix_key: Any = None      # per group: mirror key (sorted), or None
    suffix_leader: Any = None   # per group: suffix ≤ its reversal

    def score(self, magnitudes):
        """The score of channel magnitudes |sum| (..., C): the weighted sum, plus a TV1
        term's largest scaled magnitude."""
        out = magnitudes @ self.weights
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


def _throw_phasors(template, samples, max_order):
    """Per throw and order: forward and backward force (N) and moment (N·m) phasors."""
    shaking = shaking_forces(template, samples, max_order)
    masses = shaking.masses
    per_mass = shaking.mass_coefficients
    orders = np.arange(1, max_order + 1)
    lever = (masses.z_m - template.mean_z_m)[:, None]
    n = len(template.throws)
    out = np.zeros((4, n, max_order), complex)
    for j in range(n):
        mine = masses.throw == j
        forces = per_mass[mine]
        out[0, j] = forces[:, orders].sum(axis=0)
        out[1, j] = forces[:, -orders].sum(axis=0)
        out[2, j] = (lever[mine] * forces[:, orders]).sum(axis=0)
        out[3, j] = (lever[mine] * forces[:, -orders]).sum(axis=0)
    return out


def _guide_phasors(template, samples, max_order):
    """Per throw and order, the H-type and X-type phasors (kinds 4 and 5): Σ over the throw's
    cylinders of the couple's (cos − i·sin), whose modulus is the amplitude, and that times
    z − z̄. Turning a throw by β shifts its cylinders' couples by β in θ (firing with them), so
    these turn by e^{ikβ} like a forward force phasor. For a four-stroke a whole order of the
    720° couple is the same whichever revolution a cylinder fires in; half orders are not
    searched. The X-type's division by the guide distance cancels in its coefficient."""
    guide = torque(template, samples, max_order, bearings=False).guide
    out = np.zeros((2, len(template.throws), max_order), complex)
    for cylinder, own in zip(template.cylinders, guide.cylinders):
        for k in range(1, max_order + 1):
            cos, sin = own.couple.order(k)
            out[0, cylinder.throw, k - 1] += complex(cos, -sin)
            out[1, cylinder.throw, k - 1] += complex(cos, -sin) * (cylinder.z_m - guide.mean_z_m)
    return out


def _torsion_phasors(template, samples, max_order):
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
        gamma = template.bank_angles_rad[cylinder.bank]
        out[0, cylinder.throw] += beta[cylinder.throw] * np.exp(-1j * orders * gamma)
    unit = sum(abs(beta[c.throw]) for c in template.cylinders)
    return out, np.full(max_order, unit)


def _minor_orders(template, allow_uneven, max_order):
    """The whole orders 1..max_order a TV1 term takes the largest V of: for an even-firing
    search all but the major orders, where the firing angles, equally spaced, put every
    cylinder in phase whatever the arrangement (k times the interval a multiple of 360°)."""
    if allow_uneven:
        return tuple(range(1, max_order + 1))
    interval = template.cycle_deg / template.n_cylinders
    return tuple(k for k in range(1, max_order + 1)
                 if abs(math.remainder(k * interval, 360.0)) > 1e-9)


def _couple_units(guide, floor):
    """The order-k couple amplitude of one throw alone, N·m (0 below the noise floor: the two
    cylinders of a 90° V throw cancel at order 2 to rounding, and a unit of 1e-10 made a
    coefficient of noise)."""
    largest = np.abs(guide[0]).max(axis=0)
    return np.where(largest > floor, largest, 0.0)


def _units(phasors, floor):
    """The largest order-k force of one throw alone, N (0 below the noise floor)."""
    largest = (np.abs(phasors[0]) + np.abs(phasors[1])).max(axis=0)
    return np.where(largest > floor, largest, 0.0)


def _pitch(template):
    z = sorted(t.z_m for t in template.throws)
    pitch = (z[-1] - z[0]) / (len(z) - 1)
    if pitch <= 0.0:
        raise AnalysisError("has every throw at the same axial position, so moments have no "
                            "pitch to refer to; give each throw its z", "template")
    return pitch


def _channels(objective, units, pitch, couple_units=None, torsion_units=None, tv_orders=()):
    """The complex sums the score needs, (kind 0..6, order index), and their weights, divided
    by the largest term weight (the search compares scores of order one; see SCORE_TIE); and
    for a TV1 term, which of them it takes the largest of (a mask) with their scales."""
    weights = {}
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
        unit = (couple_units[k] if term.kind in ("H", "X") else
                torsion_units[k] if term.kind == "V" else units[k])
        if unit == 0.0:
            continue
        scale = term.weight / largest / unit / (pitch if term.kind in ("M", "X") else 1.0)
        first = {"F": 0, "M": 2, "H": 4, "X": 5, "V": 6}[term.kind]
        parts = {"max": (0, 1), "forward": (0,), "backward": (1,)}[term.part]
        if term.kind in _SCALAR_KINDS:
            parts = (0,)   # a real torque: its forward phasor alone carries the amplitude
        for p in parts:
            key = (first + p, k)
            weights[key] = weights.get(key, 0.0) + scale
    keys = sorted(weights)
    return (keys, np.array([weights[c] for c in keys]),
            np.array([tv.get(c, 0.0) for c in keys]))


def _lattice(template, allow_uneven, step_deg):
    """Phase lattice: (P, step, capacity, base phase per throw, lattice offsets per throw)."""
    n_cyl = template.n_cylinders
    if allow_uneven:
        if step_deg is None:
            raise AnalysisError("is needed with allow_uneven: the grid of throw phases to try, "
                                "in degrees (such as 30)", "step_deg")
        ok = (isinstance(step_deg, (int, float)) and not isinstance(step_deg, bool)
              and math.isfinite(step_deg) and 0.1 - 1e-12 <= step_deg <= 180.0)
        P = round(360.0 / step_deg) if ok else 0
        if not ok or abs(P * step_deg - 360.0) > 1e-9:
            raise AnalysisError(f"must divide 360° into equal steps of 0.1° to 180° (such as 30 "
                                f"or 45), got {step_deg!r}", "step_deg")
        n = len(template.throws)
        return P, 360.0 / P, 0, np.zeros(n), [[] for _ in range(n)]
    if step_deg is not None:
        raise AnalysisError("applies only with allow_uneven: an even-firing search takes its "
                            "phases from the firing interval", "step_deg")
    if template.cycle == 2 or n_cyl % 2:
        s = 360.0 / n_cyl
    else:
        s = 720.0 / n_cyl
    P = round(360.0 / s)
    capacity = n_cyl // P
    tdc = tdc_angles(template)
    first = min(c.number for c in template.cylinders if c.throw == 0)
    origin = tdc[first]
    base = np.zeros(len(template.throws))
    offsets = []
    for j in range(len(template.throws)):
        mine = sorted((c.number for c in template.cylinders if c.throw == j))
        if not mine:
            offsets.append([])
            continue
        rel = [(tdc[c] - origin) % 360.0 for c in mine]
        base_j = rel[0] % s
        if s - base_j < UNIFORM_FIRING_DEG / 2:
            base_j = 0.0
        if j == 0 and base_j > UNIFORM_FIRING_DEG / 2:
            base_j = 0.0
        e = []
        for c, r in zip(mine, rel):
            steps = (r - base_j) / s
            if abs(steps - round(steps)) * s > UNIFORM_FIRING_DEG / 2:
                raise AnalysisError(
                    f"cannot fire evenly: cylinders {mine[0]} and {c} ride on throw {j + 1} with top dead centres "
                    f"{round_degrees((tdc[c] - tdc[mine[0]]) % 360.0, 3):g}° apart, not a multiple "
                    f"of the {s:g}° firing interval; "
                    "search with allow_uneven and a step_deg", "template")
            e.append(round(steps) % P)
        base[j] = base_j
        offsets.append(e)
    return P, s, capacity, base, offsets


def _check_reversal(phasors, offsets, base, P, floor):
    """Reversal keeps every score when each channel's throw phasors are collinear through the
    origin, and keeps even firing when every throw's lattice offsets are symmetric about one
    common point."""
    if np.any(base != 0.0):
        return False, None
    for channel in phasors.reshape(-1, phasors.shape[1], phasors.shape[2]).transpose(0, 2, 1):
        for row in channel:  # one order of one kind: a phasor per throw
            big = np.abs(row).max()
            if big <= floor:  # rounding noise: no direction to keep
                continue
            direction = row[np.argmax(np.abs(row))] / big
            if np.abs((row * direction.conjugate()).imag).max() > SYMMETRY_TOLERANCE * big:
                return False, None
    shifts = None
    for e in offsets:
        if not e:
            continue
        fits = {t for t in range(P) if sorted((t - x) % P for x in e) == sorted(e)}
        shifts = fits if shifts is None else shifts & fits
    if shifts is not None and not shifts:
        return False, None
    return True, (min(shifts) if shifts else 0)


def _check_mirror(phasors, offsets, base, floor):
    """A mirror image balances alike when throw n+1−j's phasors are throw j's times one unit
    factor per channel, and fires evenly when mirrored throws have the same lattice offsets."""
    n = phasors.shape[1]
    if n < 2 or np.any(base != 0.0):
        return False
    if any(sorted(offsets[j]) != sorted(offsets[n - 1 - j]) for j in range(n)):
        return False
    for kind in range(phasors.shape[0]):
        for k in range(phasors.shape[2]):
            row = phasors[kind, :, k]
            big = np.abs(row).max()
            if big <= floor:
                continue
            j = int(np.argmax(np.abs(row)))
            unit = row[n - 1 - j] / row[j]
            if abs(abs(unit) - 1.0) > SYMMETRY_TOLERANCE or \
                    np.abs(row[::-1] - unit * row).max() > SYMMETRY_TOLERANCE * big:
                return False
    return True


def _assignments(problem, throws, first_fixed=False):
    """Every phase assignment of ``throws`` that overfills no lattice point: (rows, counts)."""
    P, cap = problem.lattice, problem.capacity
    rows = np.zeros((1, 0), np.int16)
    counts = np.zeros((1, P), np.int16)
    for j in throws:
        candidates = np.arange(P, dtype=np.int16)
        occupancy = np.zeros((P, P), np.int16)
        for p in range(P):
            for e in problem.offsets[j]:
                occupancy[p, (e - p) % P] += 1
        new_rows = np.concatenate([np.repeat(rows, P, axis=0),
                                   np.tile(candidates, len(rows))[:, None]], axis=1)
        new_counts = np.repeat(counts, P, axis=0) + np.tile(occupancy, (len(rows), 1))
        if cap:
            keep = (new_counts <= cap).all(axis=1)
            new_rows, new_counts = new_rows[keep], new_counts[keep]
        rows, counts = new_rows, new_counts
    return rows, counts


def _lex_sign(rows, P):
    """−1, 0 or +1: each row against its reversal (−row mod P), lexicographically."""
    negated = (-rows.astype(np.int32)) % P
    diff = rows.astype(np.int32) - negated
    sign = np.zeros(len(rows), np.int8)
    undecided = np.ones(len(rows), bool)
    for col in range(rows.shape[1]):
        d = diff[:, col]
        now = undecided & (d != 0)
        sign[now] = np.sign(d[now])
        undecided &= d == 0
    return sign


def _build_tables(problem):
    """Prefix rows grouped with the suffix rows that complete them (see the module text)."""
    n, P, cap = problem.n_throws, problem.lattice, problem.capacity
    prefix_throws = list(range(1, problem.split))
    suffix_throws = list(range(problem.split, n))
    base_rows, base_counts = _assignments(problem, [0])
    rows, counts = _assignments(problem, prefix_throws)
    first = base_counts[0] if cap else np.zeros(P, np.int16)
    counts = counts + first
    if cap:
        keep = (counts <= cap).all(axis=1)
        rows, counts = rows[keep], counts[keep]
    srows, scounts = _assignments(problem, suffix_throws)
    if cap:
        key_of = lambda c: c.astype(np.int64) @ (cap + 1) ** np.arange(P, dtype=np.int64)  # noqa: E731
        have = np.sort(key_of(scounts))
        need = key_of(cap - counts)
        total = int((np.searchsorted(have, need, "right") - np.searchsorted(have, need)).sum())
    else:
        total = len(rows) * len(srows)
    tie = np.zeros(len(rows), bool)
    if problem.reversal and rows.shape[1]:
        sign = _lex_sign(rows, P)
        rows, counts, tie = rows[sign <= 0], counts[sign <= 0], (sign == 0)[sign <= 0]
    if cap:
        need = key_of(cap - counts)
        have = key_of(scounts)
    else:
        need = np.zeros(len(rows), np.int64)
        have = np.zeros(len(srows), np.int64)
    keys, group = np.unique(need, return_inverse=True)
    suffix_rows, suffix_key, suffix_leader = [], [], []
    order = np.argsort(have, kind="stable")
    sorted_have = have[order]
    for key in keys:
        lo, hi = np.searchsorted(sorted_have, key), np.searchsorted(sorted_have, key, "right")
        mine = srows[order[lo:hi]]
        if problem.mirror:
            a = (mine[:, -2].astype(np.int32) - mine[:, -1]) % P
            mkey = np.minimum(a, (-a) % P) if problem.reversal else a
            sort = np.argsort(mkey, kind="stable")
            mine, mkey = mine[sort], mkey[sort]
        else:
            mkey = None
        suffix_rows.append(mine)
        suffix_key.append(mkey)
        suffix_leader.append(_lex_sign(mine, P) <= 0 if problem.reversal and mine.shape[1]
                             else np.ones(len(mine), bool))
    # prefixes sorted by group, then by their second throw's phase (the mirror condition)
    second = rows[:, 0] if rows.shape[1] else np.zeros(len(rows), np.int16)
    sort = np.lexsort((second, group))
    problem.prefix_rows, problem.prefix_group, problem.prefix_tie = rows[sort], group[sort], tie[sort]
    problem.suffix_rows, problem.suffix_key, problem.suffix_leader = suffix_rows, suffix_key, suffix_leader
    return total


def _count_cranks(problem):
    """Every even-firing crank with throw 1 at 0°, counted (dynamic programming over the
    lattice points filled) without enumerating them; None when too many states."""
    P, cap, n = problem.lattice, problem.capacity, problem.n_throws
    if not cap:
        return P ** (n - 1)
    if all(len(e) == 1 for e in problem.offsets):
        # one cylinder a throw (every in-line engine): throw 1 takes a place of its point and
        # the other n − 1 throws share the remaining places, cap at each point: a multinomial
        return math.factorial(n - 1) // (math.factorial(cap - 1) * math.factorial(cap) ** (P - 1))
    if (cap + 1) ** P * n * P > _COUNT_WORK:
        return None
    return _count_by_occupancy(problem)


def _count_by_occupancy(problem):
    """The count over every state of the lattice's occupancy, throw by throw."""
    P, cap, n = problem.lattice, problem.capacity, problem.n_throws
    radix = (cap + 1) ** np.arange(P, dtype=np.int64)
    states = np.arange((cap + 1) ** P, dtype=np.int64)
    digits = (states[:, None] // radix) % (cap + 1)
    count = np.zeros(len(states), object if n > 20 else np.int64)
    count[0] = 1
    for j in range(n):
        new = np.zeros_like(count)
        for p in ([0] if j == 0 else range(P)):
            occupancy = np.zeros(P, np.int64)
            for e in problem.offsets[j]:
                occupancy[(e - p) % P] += 1
            ok = (digits + occupancy <= cap).all(axis=1) & (count != 0)
            np.add.at(new, states[ok] + occupancy @ radix, count[ok])
        count = new
    return int(count[-1])


# --- the kernel -----------------------------------------------------------------------

def _sums(problem, rows, throws):
    """Σ over ``throws`` of each channel's rotated phasor, for every row: (n_rows, C)."""
    out = np.zeros((len(rows), problem.rotated.shape[2]), complex)
    for col, j in enumerate(throws):
        out += problem.rotated[j, rows[:, col]]
    return out


class _Pool:
    """The best symmetry classes found so far: at most ``top`` scores and everything tied."""

    def __init__(self, problem, top, threshold=math.inf):
        self.problem, self.top = problem, top
        self.best: dict = {}
        self.threshold = threshold
        self.truncated = False
        # the threshold is brought down when the pool reaches this size, which then doubles:
        # sorting at every offer made a large top quadratic (minutes at top = 100 000)
        self.recount = top

    def offer(self, score, crank):
        if score > self.threshold + SCORE_TIE:
            return
        key = self.problem.orbit_key(crank)
        old = self.best.get(key)
        if old is not None and old <= score:
            return
        if len(self.best) >= self.top + TIE_CAP and score > self.threshold - SCORE_TIE:
            self.truncated = True
            return
        self.best[key] = score
        if len(self.best) >= self.recount:
            scores = np.fromiter(self.best.values(), float, len(self.best))
            self.threshold = min(self.threshold, float(np.partition(scores, self.top - 1)[self.top - 1]))
            self.best = {k: v for k, v in self.best.items() if v <= self.threshold + SCORE_TIE}
            self.recount = max(2 * len(self.best), self.top) + 64


@dataclass
class _Chunk:
    candidates: list
    evaluated: int
    pruned: int
    truncated: bool


def _work_units(problem, target=_BLOCK):
    """(group, prefix start, prefix end) pieces of roughly ``target`` channel values each."""
    units = []
    C = max(problem.rotated.shape[2], 1)
    starts = np.flatnonzero(np.diff(problem.prefix_group, prepend=-1)) if len(problem.prefix_group) else []
    ends = list(starts[1:]) + [len(problem.prefix_group)]
    for lo, hi in zip(starts, ends):
        g = int(problem.prefix_group[lo])
        per = max(1, target // (max(len(problem.suffix_rows[g]), 1) * C))
        for a in range(lo, hi, per):
            units.append((g, int(a), int(min(a + per, hi))))
    return units


def _evaluate(problem, units, top, threshold=math.inf, shared=None):
    """Score every (prefix, suffix) pair of ``units`` not excluded by symmetry or bound."""
    pool = _Pool(problem, top, threshold)
    evaluated = pruned = 0
    split = problem.split
    prefix_throws = list(range(1, split))
    suffix_throws = list(range(split, problem.n_throws))
    w = problem.weights
    cached = (None, None, None)
    for g, lo, hi in units:
        if shared is not None:
            pool.threshold = min(pool.threshold, shared.value)
        srows = problem.suffix_rows[g]
        if cached[0] != g:
            Q = _sums(problem, srows, suffix_throws)
            cached = (g, Q, np.abs(Q).max(axis=0) if len(Q) else np.zeros(len(w)))
        _, Q, Qmax = cached
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
                Qt = Qs[cols] if tie else Qs
                step = max(1, _BLOCK // (len(Qt) * len(w) or 1))
                for a in range(0, len(sel), step):
                    block = sel[a:a + step]
                    S = Pm[block][:, None, :] + Qt[None, :, :]
                    score = problem.score(np.sqrt(S.real ** 2 + S.imag ** 2))
                    evaluated += score.size
                    hits = np.argwhere(score <= pool.threshold + SCORE_TIE)
                    if len(hits) > 4 * (top + 64):
                        # a class is met at most four times (its symmetry images), so the
                        # 4·top-th smallest score is at least the top-th best class's
                        values = score[hits[:, 0], hits[:, 1]]
                        cut = np.partition(values, 4 * top - 1)[4 * top - 1]
                        hits = hits[values <= cut + SCORE_TIE]
                    for i, q in hits:
                        qi = cols[q] if tie else q
                        crank = problem.crank(rows[block[i]], problem.suffix_rows[g][start + qi])
                        pool.offer(float(score[i, q]), crank)
                    if shared is not None and pool.threshold < shared.value:
                        with shared.get_lock():
                            shared.value = min(shared.value, pool.threshold)
    return _Chunk(list((s, k) for k, s in pool.best.items()), evaluated, pruned, pool.truncated)


# --- workers --------------------------------------------------------------------------

_WORKER: dict = {}


def _init_worker(problem, top, shared):
    # Ctrl-C reaches every process of the terminal's group: the parent stops the pool, and a
    # worker's own KeyboardInterrupt would only print a stray traceback
    import signal

    signal.signal(signal.SIGINT, signal.SIG_IGN)
    _WORKER.update(problem=problem, top=top, shared=shared)


def _worker_chunk(units):
    return _evaluate(_WORKER["problem"], units, _WORKER["top"], shared=_WORKER["shared"])


def _cluster_chunk(problem, units, top, threshold):
    return _evaluate(problem, units, top, threshold)


def _chunks(units, n):
    size = max(1, len(units) // n)
    return [units[i:i + size] for i in range(0, len(units), size)]


def _cores():
    """Cores this process may run on: more processes than these only share them."""
    try:
        return len(os.sched_getaffinity(0)) or 1
    except (AttributeError, OSError):
        return os.cpu_count() or 1


def _run_local(problem, units, top, workers, threshold, progress):
    """(chunks, processes that ran): the processes are capped at the cores and at the
    pieces of work, which is what helps (1000 asked took 4.5 s where two took 1 s)."""
    workers = min(workers, _cores())
    if workers <= 1 or len(units) < 2:
        out = []
        for piece in _chunks(units, 50):
            out.append(_evaluate(problem, piece, top, threshold))
            threshold = min(threshold, _pool_threshold(out, top))
            if progress:
                progress(len(piece))
        return out, 1
    import multiprocessing
    import signal

    methods = multiprocessing.get_all_start_methods()
    context = multiprocessing.get_context("fork" if "fork" in methods else None)
    shared = context.Value("d", threshold)
    out = []
    pieces = _chunks(units, 16 * workers)
    processes = min(workers, len(pieces))
    # forked workers ignore Ctrl-C from their first instruction (the initializer comes later)
    try:
        handler = signal.signal(signal.SIGINT, signal.SIG_IGN)
    except ValueError:   # not the main thread: signals are not ours to change
        handler = None
    try:
        pool = context.Pool(processes, _init_worker, (problem, top, shared))
    finally:
        if handler is not None:
            signal.signal(signal.SIGINT, handler)
    with pool:
        for piece, chunk in zip(pieces, pool.imap(_worker_chunk, pieces)):
            out.append(chunk)
            if progress:
                progress(len(piece))
    return out, processes


#: seconds to wait for a Dask scheduler to answer
_CONNECT_S = 10


def _run_cluster(problem, units, top, threshold, scheduler, progress):
    try:
        from distributed import Client, as_completed
    except ImportError:
        raise AnalysisError("needs the optional cluster support: pip install 'balance[cluster]' "
                            "(dask distributed)", "scheduler") from None
    given = not isinstance(scheduler, str)  # a caller's Client: theirs to close
    client = scheduler if given else None
    try:
        if client is None:
            try:
                client = Client(scheduler, timeout=f"{_CONNECT_S}s")
            except (OSError, TimeoutError) as exc:
                raise AnalysisError(f"{scheduler!r} did not answer within {_CONNECT_S} s ({exc}); "
                                    "check that the scheduler runs there", "scheduler") from None
            except (ValueError, TypeError):
                raise AnalysisError(f"{scheduler!r} is not a scheduler address such as "
                                    "tcp://host:8786", "scheduler") from None
        remote = client.scatter(problem, broadcast=True)
        pieces = _chunks(units, 16 * max(1, sum(client.nthreads().values())))
        futures = [client.submit(_cluster_chunk, remote, piece, top, threshold, pure=False)
                   for piece in pieces]
        sizes = {f.key: len(p) for f, p in zip(futures, pieces)}
        out = []
        for future in as_completed(futures):
            out.append(future.result())
            if progress:
                progress(sizes[future.key])
        return out, sum(client.nthreads().values())
    finally:
        if client is not None and not given:
            client.close()


def _pool_threshold(chunks, top):
    scores = sorted(s for c in chunks for s, _ in c.candidates)
    return scores[top - 1] if len(scores) >= top else math.inf


# --- heuristic ------------------------------------------------------------------------

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


def _heuristic(problem, top, restarts, seed, progress):
    """Steepest descent from random cranks; moves: swap the phases of two throws that fire
    alike (keeps even firing), or, without even firing, turn one throw to another phase."""
    rng = np.random.default_rng(seed)
    n, P = problem.n_throws, problem.lattice
    pool = _Pool(problem, top)
    pairs = [(a, b) for a in range(1, n) for b in range(a + 1, n)
             if sorted(problem.offsets[a]) == sorted(problem.offsets[b])]
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
    return [_Chunk(list((s, k) for k, s in pool.best.items()), evaluated, 0, pool.truncated)]


# --- firing orders and the final list -------------------------------------------------

def _cylinder_lattice(template, problem, crank):
    """Each cylinder's lattice index (top dead centre in steps of the firing interval)."""
    P = problem.lattice
    out = {}
    for j in range(problem.n_throws):
        mine = sorted(c.number for c in template.cylinders if c.throw == j)
        for c, e in zip(mine, problem.offsets[j]):
            out[c] = (e - crank[j]) % P
    return out


def _firing_orders(template, problem, crank):
    """Every firing order of an even-firing crank: which of its cylinders fires at each
    firing slot of its lattice point (for a four-stroke, in which revolution)."""
    P, s = problem.lattice, problem.step_deg
    cycle = template.cycle_deg
    n_cyl = template.n_cylinders
    interval = cycle / n_cyl
    index = _cylinder_lattice(template, problem, crank)
    first = min(index)
    points: dict[int, list] = {}
    for c, i in index.items():
        points.setdefault((i - index[first]) % P, []).append(c)
    options = []
    for r, cyls in sorted(points.items()):
        slots = [a for a in (r * s + 360.0 * t for t in range(template.cycle // 2))
                 if abs(a / interval - round(a / interval)) < 1e-9]
        choices = []
        for perm in itertools.permutations(slots):
            assignment = dict(zip(sorted(cyls), perm))
            if first in assignment and abs(assignment[first]) > 1e-9:
                continue
            choices.append(assignment)
        options.append(choices)
    orders = []
    for combination in itertools.product(*options):
        angles = {c: a for part in combination for c, a in part.items()}
        orders.append(tuple(sorted(angles, key=lambda c: (angles[c], c))))
    return orders


def _reversed_order(order, template, problem, shift):
    """The firing order of the reversed engine, with cylinders renamed across the reflection
    (a cylinder goes to the one of its throw at the mirrored lattice offset)."""
    rename = {}
    for j in range(problem.n_throws):
        mine = sorted(c.number for c in template.cylinders if c.throw == j)
        e = problem.offsets[j]
        used = set()
        for c, ec in zip(mine, e):
            target = (shift - ec) % problem.lattice
            partner = next(x for x, ex in zip(mine, e) if ex == target and x not in used)
            used.add(partner)
            rename[c] = partner
    backwards = [rename[c] for c in reversed(order)]
    start = backwards.index(min(backwards))
    return tuple(backwards[start:] + backwards[:start])


def _phases(problem, crank):
    return tuple(round_degrees((problem.base_deg[j] + p * problem.step_deg) % 360.0, 9) % 360.0
                 for j, p in enumerate(crank))


def _arrangement_engine(template, phases, order, name):
    throws = tuple(Throw(math.radians(p if p <= 180.0 else p - 360.0), t.z_m)
                   for p, t in zip(phases, template.throws))
    return replace(template, throws=throws, firing_order=order, name=name)


def _expand(template, problem, orbits, shift):
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
                orders = _firing_orders(template, problem, crank)
            else:
                orders = [None]
            for order in orders:
                member = (crank, order)
                if problem.reversal and order is not None:
                    reverse = (tuple((-p) % problem.lattice for p in crank),
                               _reversed_order(order, template, problem, shift))
                    if reverse[1] < order:
                        member = reverse
                elif problem.reversal and order is None:
                    reverse = (tuple((-p) % problem.lattice for p in crank), None)
                    member = min(member, reverse, key=lambda m: m[0])
                if member not in out:
                    out[member] = (score, position)
    return out


# --- the search -----------------------------------------------------------------------

def search(template: Engine, objective: "str | Sequence[Term] | None" = None,
           top: int = DEFAULT_TOP, allow_uneven: bool = False, step_deg: float | None = None,
           workers: int | None = None, scheduler=None, heuristic: bool = False,
           restarts: int = 200, seed: int = 0, limit: int = DEFAULT_LIMIT,
           samples: int = DEFAULT_SAMPLES, max_order: int = DEFAULT_MAX_ORDER,
           progress: Callable[[int, int], None] | None = None) -> SearchResult:
    """The best crank arrangements and firing orders of ``template``.

    Parameters
    ----------
    template : Engine
        its throw phases and firing order are ignored (see
        :func:`balance_cli.config.load_template`); a fixed frame, two or more throws
    objective : str or sequence of Term or None
        such as ``"F2:4,M1,M2"`` (:func:`parse_objective`); None: every F_k and M_k
    top : int
        how many arrangements to list (ties with the last are ranked by firing order)
    allow_uneven, step_deg : bool, float
        search every crank on a grid of ``step_deg`` degrees, firing or not evenly
    workers : int or None
        processes (None: every core); ``scheduler``: a Dask scheduler address or Client
        instead
    heuristic : bool
        a local search (``restarts`` random starts, ``seed``), not proved optimal
    limit : int
        refuse an exhaustive search that would evaluate more cranks than this
    samples, max_order : int
        as for :func:`balance_cli.analysis.results.analyse`
    progress : callable(done, total) or None
        called as work completes

    Raises
    ------
    AnalysisError
        naming ``template``, ``objective``, ``top``, ``step_deg``, ``workers``, ``limit`` or
        ``scheduler``
    """
    started = time.perf_counter()
    check_settings(samples, max_order)
    if workers is None:
        workers = os.cpu_count() or 1
    for name, value, low, high in (("top", top, 1, MAX_TOP), ("restarts", restarts, 1, 1_000_000),
                                   ("limit", limit, 1, 10**15), ("seed", seed, 0, 2**63 - 1),
                                   ("workers", workers, 1, MAX_WORKERS)):
        if isinstance(value, bool) or not isinstance(value, (int, np.integer)) \
                or not low <= value <= high:
            raise AnalysisError(f"must be a whole number from {low:,} to {high:,}, got {value!r}",
                                name)
    top, restarts, limit, seed, workers = map(int, (top, restarts, limit, seed, workers))
    if scheduler is not None and not isinstance(scheduler, str) \
            and not all(hasattr(scheduler, a) for a in ("scatter", "submit", "nthreads")):
        raise AnalysisError(f"must be a scheduler address such as tcp://host:8786 or a "
                            f"distributed.Client, got {scheduler!r}", "scheduler")
    if heuristic and scheduler is not None:
        raise AnalysisError("applies to the exhaustive search, but the heuristic search runs in "
                            "this process: leave out one of the two", "scheduler")
    if isinstance(objective, str) or objective is None:
        terms = parse_objective(objective, max_order)
    elif isinstance(objective, Term):
        terms = (objective,)
    else:
        try:
            terms = tuple(objective)
        except TypeError:
            raise AnalysisError(f"must be a string such as 'M1,M2' or Terms, got {objective!r}",
                                "objective") from None
    _check_terms(terms, max_order)
    if not isinstance(template, Engine):
        raise AnalysisError(f"must be an Engine (balance.load_template gives one), got "
                            f"{type(template).__name__}", "template")
    if progress is not None and not callable(progress):
        raise AnalysisError(f"must be a callable(done, total), got {progress!r}", "progress")
    if template.is_rotary:
        raise AnalysisError("is a rotary engine: its crank does not turn, so there are no throw "
                            "phases to arrange; search a fixed-frame template", "template")
    if template.has_several_crankshafts:
        raise AnalysisError(f"has {len(template.crankshafts)} crankshafts; the search arranges "
                            "the throws of one crankshaft: give a template with one", "template")
    if template.counterweights or template.balancer_shafts:
        # a counterweight is sized for one crank and a shaft's force does not turn with the
        # throws: the per-throw phasor sums would score a different engine than the one found
        raise AnalysisError("has counterweights or balancer shafts as built; they belong to one "
                            "arrangement, which the search is to choose: remove the "
                            "[[counterweights]] and [[shafts]] tables from the template",
                            "template")
    n = len(template.throws)
    if n < 2:
        raise AnalysisError("has one throw: with throw 1 at 0° there is nothing to arrange; give "
                            "the template two or more [[throws]]", "template")
    if any(not any(c.throw == j for c in template.cylinders) for j in range(n)):
        empty = next(j for j in range(n) if not any(c.throw == j for c in template.cylinders))
        raise AnalysisError(f"has no cylinder on throw {empty + 1}; remove the throw or give "
                            "it a cylinder", "template")
    flat = replace(template, throws=tuple(Throw(0.0, t.z_m) for t in template.throws),
                   firing_order=None)
    check_assembly(flat)
    phasors = _throw_phasors(flat, samples, max_order)
    units = _units(phasors, flat.noise_floor_n)
    pitch = _pitch(flat)
    couple_units = torsion_units = None
    if any(term.kind in ("H", "X") for term in terms):
        guide = _guide_phasors(flat, samples, max_order)
        couple_units = _couple_units(guide, flat.noise_floor_n * flat.crank_radius_m)
        phasors = np.concatenate([phasors, guide])
    tv_orders = ()
    if any(term.kind in ("V", "TV") for term in terms):
        if flat.torsion is None:
            raise AnalysisError("has no [torsion] table: a V term needs the shaft line's first "
                                "mode", "template")
        if couple_units is None:
            phasors = np.concatenate([phasors, np.zeros((2,) + phasors.shape[1:], complex)])
        torsional, torsion_units = _torsion_phasors(flat, samples, max_order)
        # the same scale as the forces', so that the symmetry checks' floor reads alike
        phasors = np.concatenate([phasors, torsional * units.max()])
        torsion_units = torsion_units * units.max()
        tv_orders = _minor_orders(flat, allow_uneven, max_order)
    channels, weights, largest = _channels(terms, units, pitch, couple_units, torsion_units,
                                           tv_orders)
    P, s, capacity, base, offsets = _lattice(flat, allow_uneven, step_deg)
    reversal, shift = _check_reversal(phasors, offsets, base, P, flat.noise_floor_n)
    mirror = _check_mirror(phasors, offsets, base, flat.noise_floor_n)
    phase = base[:, None] + s * np.arange(P)[None, :]                 # (n, P) degrees
    rotated = np.zeros((n, P, len(channels)), complex)
    for i, (kind, k) in enumerate(channels):
        sign = -1.0 if kind in (1, 3) else 1.0
        rotated[:, :, i] = phasors[kind, :, k][:, None] * np.exp(
            1j * sign * (k + 1) * np.radians(phase))
    split = 1 + (n - 1) // 2
    problem = _Problem(n, P, s, base, capacity, offsets, rotated, weights, reversal, False, split,
                       largest=largest if np.any(largest) else None)
    # the mirror condition reads throws n−1 and n from the suffix
    problem.mirror = mirror and n - 2 >= split
    symmetries = ["turning the whole crank (throw 1 at 0°)"]
    if reversal:
        symmetries.append("running the other way round (counted once)")
    if mirror:
        symmetries.append("mirror image, read from the other end (evaluated once, listed)")
    cranks = _count_cranks(problem)
    firing_per_crank = (math.factorial(capacity) ** P // capacity if capacity else 1)
    expected = cranks if cranks is not None else P ** (n - 1)
    reduction = (2 if reversal else 1) * (2 if problem.mirror else 1)
    if not heuristic and expected // reduction > limit:
        _refuse_limit(limit, expected // reduction, "about " if cranks is not None else "up to ")

    # progress counts the listed arrangements' analyses too (top of them at most), the
    # last stage, which took minutes with a large top after the bar had shown 100 %
    if heuristic:
        tick = _ticker(progress, restarts + top)
        chunks = _heuristic(problem, top, restarts, seed, tick)
        total_cranks = cranks
    else:
        total_cranks = _build_tables(problem)
        planned = _planned(problem)
        if planned > limit:
            _refuse_limit(limit, planned, "")
        units_of_work = _work_units(problem)
        tick = _ticker(progress, len(units_of_work) + top)
        if scheduler is not None:
            chunks, workers = _run_cluster(problem, units_of_work, top, math.inf, scheduler,
                                           tick)
        else:
            chunks, workers = _run_local(problem, units_of_work, top, workers, math.inf, tick)
    truncated = any(c.truncated for c in chunks)
    merged = _Pool(problem, top)
    for chunk in chunks:
        for score, key in chunk.candidates:
            merged.offer(score, key)
    truncated |= merged.truncated
    orbits = sorted(((s, k) for k, s in merged.best.items()), key=lambda x: (x[0], x[1]))
    if len(orbits) >= top:
        cut = orbits[top - 1][0]
        orbits = [o for o in orbits if o[0] <= cut + SCORE_TIE]
    arrangements = _final(template, flat, problem, orbits, shift, terms, top, samples,
                          max_order, units, pitch, tick, couple_units, tv_orders)
    total = (total_cranks or 0) * firing_per_crank
    distinct = _distinct(flat, problem, total, shift) if reversal else total
    return SearchResult(
        template=template, objective=terms, arrangements=tuple(arrangements),
        arrangements_total=total, arrangements_distinct=distinct,
        evaluated=sum(c.evaluated for c in chunks), pruned=sum(c.pruned for c in chunks),
        exhaustive=not heuristic, method="heuristic" if heuristic else "exhaustive",
        symmetries=tuple(symmetries), firing_orders_per_crank=firing_per_crank,
        even=not allow_uneven, step_deg=s, ties_truncated=truncated,
        elapsed_s=time.perf_counter() - started, workers=1 if heuristic else workers,
        max_order=max_order, samples=samples)


def _refuse_limit(limit, cranks, about):
    raise AnalysisError(
        f"is {limit:,} (cranks to evaluate), but an exhaustive search of this template evaluates "
        f"{about}{cranks:,}; raise it (about 30 million a second on two cores), or use the "
        "heuristic search (not proved optimal) or a cluster scheduler", "limit")


def _planned(problem):
    """Cranks the enumeration will score before any bound: the prefixes times the suffixes the
    symmetry conditions leave each of them."""
    count = 0
    rows, groups, ties = problem.prefix_rows, problem.prefix_group, problem.prefix_tie
    second = rows[:, 0] if rows.shape[1] else np.zeros(len(rows), int)
    for g in np.unique(groups):
        mine = groups == g
        key, leader = problem.suffix_key[g], problem.suffix_leader[g]
        n = len(problem.suffix_rows[g])
        start = np.searchsorted(key, second[mine]) if key is not None else np.zeros(mine.sum(), int)
        plain = n - start
        if ties[mine].any():
            after = np.cumsum(leader[::-1])[::-1]  # leaders from each position on
            tied = np.where(start < n, after[np.minimum(start, n - 1)], 0)
            plain = np.where(ties[mine], tied, plain)
        count += int(plain.sum())
    return count


def _ticker(progress, total):
    if progress is None:
        return None
    done = [0]

    def tick(k):
        done[0] += k
        progress(done[0], total)
    return tick


def _distinct(flat, problem, total, shift):
    """Arrangements counted once with their reversal: (total + self-reversed) / 2."""
    P, n = problem.lattice, problem.n_throws
    if P % 2:
        return total // 2 if total % 2 == 0 else (total + 1) // 2
    if not problem.capacity:
        return (total + 2 ** (n - 1)) // 2   # every crank of phases 0 and 180° is its own reversal
    reach = {(e - p) % P for offsets in problem.offsets for e in offsets for p in (0, P // 2)}
    if len(reach) < P:
        # phases of 0 and 180° alone cannot fill the lattice: no crank is its own reversal (an
        # in-line 22's 2^21 candidates took minutes to rule out one by one)
        return total // 2
    fixed = 0
    for tail in itertools.product((0, P // 2), repeat=n - 1):
        crank = (0,) + tail
        if problem.capacity:
            counts = np.zeros(P, int)
            for j, p in enumerate(crank):
                for e in problem.offsets[j]:
                    counts[(e - p) % P] += 1
            if (counts != problem.capacity).any():
                continue
            for order in _firing_orders(flat, problem, crank):
                if _reversed_order(order, flat, problem, shift) == order:
                    fixed += 1
        else:
            fixed += 1
    return (total + fixed) // 2


def _final(template, flat, problem, orbits, shift, terms, top, samples, max_order, units, pitch,
           tick=None, couple_units=None, tv_orders=()):
    """The listed arrangements: expanded to firing orders and mirror images, analysed exactly
    as ``compare`` would, ranked by score and then firing order."""
    members = _expand(flat, problem, orbits, shift)
    rows = []
    for (crank, order), (score, position) in members.items():
        phases = _phases(problem, crank)
        engine = None
        if order is None:  # uneven: the most uniform order the crank allows, not written
            engine = _arrangement_engine(template, phases, order, template.name)
            order = firing_sequence(engine).order
        # scores are normalised (of order one, see _channels): the tie is relative
        rows.append((round(score / SCORE_TIE), order, crank, phases, engine))
    rows.sort(key=lambda r: (r[0], r[1]))
    listed = []
    rank_of: dict = {}
    for rank, (_, order, crank, phases, engine) in enumerate(rows[:top], 1):
        if engine is None:   # built for the listed ones only: each costs a model check
            engine = _arrangement_engine(template, phases, order, template.name)
        result = analyse(engine, samples, max_order)
        if tick:
            tick(1)
        values = _coefficients_of(result, units, pitch, terms, couple_units, tv_orders)
        score = float(sum(t.weight * values[t.name] for t in terms))
        suffix = f", arrangement {rank}"
        name = template.name[:MAX_NAME_LENGTH - len(suffix)].rstrip() + suffix
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
    parts = [np.array([z if abs(z) >= floor else 0.0 for z in values]) for values, floor in
             zip(zip(*((o.force_forward, o.force_backward, o.moment_forward, o.moment_backward)
                       for o in orders)), floors)]
    c = coefficients(*parts, units, pitch)
    values = {}
    for k in range(1, len(orders) + 1):
        for kind in "FM":
            values[f"{kind}{k}"] = float(c[kind][0][k - 1])
    for t in terms:
        if t.part != "max":
            values[t.name] = float(c[t.kind][1 if t.part == "forward" else 2][t.order - 1])
    if any(t.kind in ("V", "TV") for t in terms):
        # the arrangement's own firing angles and first mode, as balance torsion sums them
        from ..analysis.torque import _firing_angles_deg
        from ..torsion import first_mode_amplitudes, phase_vector_sum

        beta = first_mode_amplitudes(engine, result.samples)
        fire = _firing_angles_deg(engine, result.firing)
        amplitudes = [beta[c.throw] for c in engine.cylinders]
        angles = [fire[c.number] for c in engine.cylinders]
        unit = sum(abs(b) for b in amplitudes)
        for t in terms:
            if t.kind == "V":
                values[t.name] = abs(phase_vector_sum(amplitudes, angles, t.order)) / unit
            if t.kind == "TV":
                values[t.name] = max((abs(phase_vector_sum(amplitudes, angles, k)) / unit
                                      for k in tv_orders), default=0.0)
    if couple_units is not None and any(t.kind in ("H", "X") for t in terms):
        # the arrangement's own torques, not the template's phasors turned: a second method
        guide = torque(result.engine, result.samples, len(orders), bearings=False).guide
        for t in terms:
            if t.kind in ("H", "X"):
                unit = couple_units[t.order - 1]
                series = guide.h_type if t.kind == "H" else guide.x_type
                lever = 1.0 if t.kind == "H" else guide.lever_m / pitch
                values[t.name] = (float(math.hypot(*series.order(t.order)) * lever / unit)
                                  if unit > 0.0 else 0.0)
    return values
