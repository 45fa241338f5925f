"""The workshop: matching weighed parts to cylinders, the scatter a tolerance band leaves across
a production run, and the balancing sheet.

Everything here rests on one fact: an engine's forces and moments are linear in its masses.
The engine's own exact analysis of one kilogram at each point mass (:mod:`.basis`) turns any
set of masses into forces and moments by a weighted sum, exactly; scattered dimensions close
each run's linkage, all runs at once (:mod:`.runs`).

- :func:`match` (:mod:`.matching`): which weighed piston and rod go in which cylinder so that the
  engine as assembled shakes least. :mod:`.parts` reads the parts file, :mod:`.assembly` makes
  the engine as assembled and writes it, :mod:`.objective` is what is minimised,
  :mod:`.symmetry` the cylinders the crank makes equivalent, :mod:`.assign` the exhaustive
  and heuristic searches.
- :func:`tolerance` (:mod:`.production`): the spread of each order's free force and moment over
  a production run, beside its closed-form linear spread (:mod:`.spread`).
- :func:`bobweights` (:mod:`.sheet`): the bobweight of each crank pin, and a single's or
  twin's trade between vertical and horizontal shaking over the balance factor.
"""

from .assembly import Fit, assembled, assembled_toml
from .assign import DEFAULT_LIMIT, DEFAULT_RESTARTS
from .matching import Fitting, MatchResult, match
from .objective import GRID
from .parts import PartSet, Piston, Rod, as_parts, read_parts_csv
from .production import DEFAULT_RUNS, OrderSpread, ToleranceResult, tolerance
from .sheet import DEFAULT_FACTORS, Bobweight, BobweightSheet, Trade, bobweights
from .spread import Linear, Stats

__all__ = [
    "match",
    "MatchResult",
    "Fitting",
    "Fit",
    "PartSet",
    "Piston",
    "Rod",
    "read_parts_csv",
    "as_parts",
    "assembled",
    "assembled_toml",
    "tolerance",
    "ToleranceResult",
    "OrderSpread",
    "Stats",
    "Linear",
    "bobweights",
    "BobweightSheet",
    "Bobweight",
    "Trade",
    "DEFAULT_LIMIT",
    "DEFAULT_RESTARTS",
    "DEFAULT_RUNS",
    "DEFAULT_FACTORS",
    "GRID",
]
