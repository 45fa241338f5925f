"""What a crank search returns: the arrangements it lists and the search's own account
(counts, symmetries, method), each with the ``to_dict`` that ``search --format json`` writes.
"""

from __future__ import annotations

from dataclasses import dataclass

from ..analysis.results import EngineResult
from ..model import Engine
from ..output import DOCUMENT_VERSION
from ..tabular import Tabular, joined

__all__ = ["Arrangement", "SearchResult"]


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
        return {
            "rank": self.rank,
            "score": self.score,
            "phases_deg": list(self.phases_deg),
            "firing": {
                "order": list(self.result.firing.order),
                "intervals_deg": list(self.result.firing.intervals_deg),
                "uniform": self.result.firing.uniform,
            },
            "mirror_of": self.mirror_of,
            "coefficients": dict(self.coefficients),
            "orders": full["orders"],
        }


@dataclass(frozen=True)
class SearchResult(Tabular):
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
        arrangements fire evenly (False with allow_uneven), or each bank does (``even_banks``)
    even_banks : bool
        each bank fires evenly on its own, the banks a fixed angle apart (even_banks, on a
        template of several banks)
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
    even_banks: bool = False

    def records(self) -> list:
        """One row per arrangement listed, best first: ``rank``, ``score``, ``phases_deg``
        ("0 240 120"), ``firing_order`` ("1-2-3") and ``intervals_deg`` as text, ``uniform``,
        ``mirror_of``, then every coefficient by name (``F1``, ``M2``, ``M1+``: pure numbers,
        see :func:`~balance_cli.search`)."""
        return [
            {
                "rank": a.rank,
                "score": a.score,
                "phases_deg": joined(a.phases_deg, " "),
                "firing_order": joined(a.firing_order),
                "intervals_deg": joined(a.result.firing.intervals_deg, " "),
                "uniform": a.result.firing.uniform,
                "mirror_of": a.mirror_of,
                **a.coefficients,
            }
            for a in self.arrangements
        ]

    def to_dict(self) -> dict:
        """What ``search --format json`` writes (see the JSON page)."""
        return {
            "balance_version": DOCUMENT_VERSION,
            "template": self.template.config_path or self.template.name,
            "name": self.template.name,
            "objective": [str(t) for t in self.objective],
            "method": self.method,
            "even_firing": self.even and not self.even_banks,
            "even_banks": self.even_banks,
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
