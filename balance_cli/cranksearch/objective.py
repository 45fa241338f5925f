"""The objective of a crank search: its terms, how they are read and checked, and the
coefficients they weigh.

A term is a weight times one coefficient of an arrangement: F_k or M_k (the order-k free force
or moment, divided by one throw's alone), a guide-force moment H_k or X_k, or the first torsional
mode's phase-vector sum V_k (TV1 its largest over the minor orders).
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass

import numpy as np

from ..analysis.shaking import DEFAULT_MAX_ORDER
from ..errors import AnalysisError

__all__ = [
    "Term",
    "parse_objective",
    "default_objective",
    "check_terms",
    "coefficients",
    "WEIGHT_RANGE",
    "SCALAR_KINDS",
]

#: the weights a term may have: the scores they make stay finite (a coefficient is at most a
#: few times the number of throws squared) and their ratio within what a double resolves
WEIGHT_RANGE = (1e-100, 1e100)
_TERM = re.compile(r"^\s*(TV|[FMHXV])(\d+)([+-]?)\s*(?::\s*(.+?))?\s*$")
_HALF_ORDER = re.compile(r"^\s*[FMHXV]\s*\d*\.\d*")
#: the kinds that are one real quantity per order, with no forward or backward part
SCALAR_KINDS = ("H", "X", "V", "TV")


@dataclass(frozen=True)
class Term:
    """One part of the objective: ``weight`` × the coefficient ``name``.

    ``kind`` "F" (force), "M" (moment), "H" (H-type guide-force moment), "X" (X-type) or
    "V" (the first torsional mode's phase-vector sum, :mod:`balance_cli.torsion`) or "TV"
    (order 1 only: the first mode's largest V over the minor orders, see :func:`search`);
    ``part`` "max" (the order's largest value, ``|X⁺| + |X⁻|``), "forward" (``|X⁺|``) or
    "backward" (``|X⁻|``); H, X and V are one real quantity per order, "max" only (their amplitude).
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

    def to_dict(self) -> dict:
        return {
            "term": self.name,
            "kind": self.kind,
            "order": self.order,
            "part": self.part,
            "weight": self.weight,
        }


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
        raise AnalysisError(
            "is empty; give terms such as M1,M2 (or leave it out for every F_k and M_k)",
            "objective",
        )
    terms: list[Term] = []
    for item in text.split(","):
        match = _TERM.match(item)
        if not match and _HALF_ORDER.match(item):
            # a four-stroke's half orders of a cylinder's couple turn with the revolution it
            # fires in, which a throw's phase does not fix: no phasor per throw to sum
            raise AnalysisError(
                f"term {item.strip()!r}: the search takes whole orders only (half "
                "orders of a four-stroke depend on which revolution each cylinder "
                "fires in, not on the crank alone)",
                "objective",
            )
        if not match:
            raise AnalysisError(
                f"term {item.strip()!r} is not a coefficient such as F2, M1, F1+, "
                "H4, V3 or F2:4 (F force, M moment, H and X the H- and X-type "
                "guide-force moments, V the first torsional mode's phase-vector "
                "sum, the order, + forward or - backward part only, :weight)",
                "objective",
            )
        kind, order, sign, weight_text = match.groups()
        if kind in SCALAR_KINDS and sign:
            raise AnalysisError(
                f"term {item.strip()!r}: {kind} is one quantity per order, "
                f"with no forward or backward part; write {kind}{order}",
                "objective",
            )
        order = int(order)
        if order < 1:
            raise AnalysisError(f"term {item.strip()!r}: orders start at 1", "objective")
        if kind == "TV" and order != 1:
            raise AnalysisError(
                f"term {item.strip()!r}: TV1 (the first torsional mode) is the "
                "one TV term; name single orders of it with V terms",
                "objective",
            )
        if order > max_order:
            raise AnalysisError(
                f"term {item.strip()!r} asks for order {order}, but orders 1 to "
                f"{max_order} are analysed; set max_order to {order} or drop the "
                "term",
                "objective",
            )
        weight = 1.0
        if weight_text is not None:
            try:
                weight = float(weight_text)
            except ValueError:
                weight = math.nan
            if not _weight_ok(weight):
                raise AnalysisError(
                    f"term {item.strip()!r}: the weight after ':' must be a "
                    f"positive number from {WEIGHT_RANGE[0]:g} to "
                    f"{WEIGHT_RANGE[1]:g}, such as 4",
                    "objective",
                )
        term = Term(kind, order, {"": "max", "+": "forward", "-": "backward"}[sign], weight)
        if any(t.name == term.name for t in terms):
            raise AnalysisError(
                f"term {term.name} is listed twice; give it once (with a "
                "weight if it matters more)",
                "objective",
            )
        terms.append(term)
    return tuple(terms)


def _weight_ok(weight):
    return (
        isinstance(weight, (int, float, np.integer, np.floating))
        and not isinstance(weight, bool)
        and math.isfinite(weight)
        and WEIGHT_RANGE[0] <= weight <= WEIGHT_RANGE[1]
    )


def check_terms(terms, max_order):
    """Terms given as objects must be what :func:`parse_objective` would have made: a bound
    that assumes positive weights is no proof with a negative or non-finite one."""
    if not terms:
        raise AnalysisError(f"must name coefficients of orders 1 to {max_order}", "objective")
    for term in terms:
        if not isinstance(term, Term):
            raise AnalysisError(
                f"must be a string such as 'M1,M2' or Terms, got {term!r}", "objective"
            )
        if (
            term.kind not in ("F", "M", "H", "X", "V", "TV")
            or (term.kind == "TV" and term.order != 1)
            or term.part
            not in (("max",) if term.kind in SCALAR_KINDS else ("max", "forward", "backward"))
            or isinstance(term.order, bool)
            or not isinstance(term.order, (int, np.integer))
            or not 1 <= term.order <= max_order
        ):
            raise AnalysisError(
                f"term {term!r} must be F or M, of an order from 1 to {max_order}, "
                "part max, forward or backward, or H, X or V, part max, or TV1",
                "objective",
            )
        if not _weight_ok(term.weight):
            raise AnalysisError(
                f"term {term.name}: the weight must be a positive number from "
                f"{WEIGHT_RANGE[0]:g} to {WEIGHT_RANGE[1]:g}, got {term.weight!r}",
                "objective",
            )
    names = [t.name for t in terms]
    twice = next((name for name in names if names.count(name) > 1), None)
    if twice:
        raise AnalysisError(f"term {twice} is listed twice; give it once", "objective")


def coefficients(force_forward, force_backward, moment_forward, moment_backward, units_n, pitch_m):
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
    for kind, forward, backward, unit in (
        ("F", force_forward, force_backward, 1.0),
        ("M", moment_forward, moment_backward, pitch_m),
    ):
        f = np.abs(forward) * scale / unit
        b = np.abs(backward) * scale / unit
        out[kind] = (f + b, f, b)
    return out
