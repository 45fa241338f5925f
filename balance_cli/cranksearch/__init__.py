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

**Exhaustive enumeration (meet in the middle, streamed).** The free throws are split into a
prefix and a suffix. The parent counts the lattice occupancies the prefixes can leave (dynamic
programming, never enumerating them) and sends each as a work unit; a worker enumerates the
unit's own prefixes and the suffixes that fill the rest, with their partial sums, scores their
pairs and drops them, so its memory is one unit's. Processes or a Dask cluster share the units;
the best are merged as they come back. (``enumeration="tabled"``: the former method, every
prefix and suffix tabled at once in the parent, kept as a cross-check.)

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
found so far cannot improve on it and is skipped, with its suffixes; and a pair within that
score T has every channel's |P + Q| ≤ T / its weight, so a prefix is paired only with the
suffixes whose sums lie near its opposite in the most selective channel (a grid of them).
Evaluated + skipped by bound + skipped by symmetry = every arrangement, which is the proof of
optimality.

**Modules.** ``objective`` (terms and coefficients), ``results`` (what a search returns),
``problem`` (each throw's phasors and the objective's channels), ``lattice`` (the firing lattice
and the symmetry checks), ``units`` (the streamed work units and the rows a worker builds),
``query`` (their pairs scored near the threshold), ``tables`` (the tabled prefixes and
suffixes, counting), ``kernel`` (the tabled evaluation and the pool of the best), ``parallel``
(local processes, a Dask cluster),
``heuristic``, ``firing`` (firing orders and expansion), ``final`` (the listed arrangements) and
``run`` (:func:`search` itself).
"""

from .kernel import SCORE_TIE, TIE_CAP
from .lattice import SYMMETRY_TOLERANCE
from .objective import WEIGHT_RANGE, Term, coefficients, default_objective, parse_objective
from .results import Arrangement, SearchResult
from .run import DEFAULT_LIMIT, DEFAULT_TOP, MAX_TOP, MAX_WORKERS, search

__all__ = [
    "Term",
    "parse_objective",
    "default_objective",
    "coefficients",
    "Arrangement",
    "SearchResult",
    "search",
    "DEFAULT_TOP",
    "DEFAULT_LIMIT",
    "MAX_TOP",
    "MAX_WORKERS",
    "SCORE_TIE",
    "TIE_CAP",
    "WEIGHT_RANGE",
    "SYMMETRY_TOLERANCE",
]
