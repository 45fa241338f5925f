"""What matching minimises: a linear map from force and moment coefficients to a few channels,
and a score of those channels.

**Default** (Tanaka's Part I § 5 measure of inequality): of what the parts' differences add
to the engine, the largest resultant force over a revolution (all orders resolved by the
samples) plus the largest free moment over a revolution divided by the mean throw pitch, in
newtons. Both are taken over :data:`GRID` crank angles (every 1/12°): a grid that every whole
and twelfth of a degree of turning maps onto itself, so that cylinders the crank makes
equivalent by turning it score alike exactly.

**Terms** (``"F1,M2:4"``, read as for :func:`balance_cli.search`, F and M only): weight times
|X⁺| + |X⁻| of the order-k force (N) or moment divided by the pitch (N), or one part of it;
exact per order, no grid.
"""

import math
from dataclasses import dataclass

import numpy as np

from ..cranksearch.objective import Term, check_terms, parse_objective
from ..errors import AnalysisError
from ..harmonics import orders_of
from ..tolerances import SAME_POSITION_M

__all__ = ["GRID", "MatchObjective", "match_objective", "match_pitch"]

#: crank angles a revolution of the default objective: every 1/12°
GRID = 4320
#: the screening grid: every so many points of GRID (a subset, so its largest values are
#: lower bounds of the grid's)
_SCREEN_STEP = 36


def match_pitch(engine) -> float:
    """The mean throw pitch, m: (z of the last throw − z of the first) / (throws − 1); for an
    engine whose throws share one plane, its lever arm (:attr:`Engine.length_scale_m`)."""
    z = sorted(t.z_m for t in engine.throws)
    if len(z) > 1 and z[-1] - z[0] > SAME_POSITION_M:
        return (z[-1] - z[0]) / (len(z) - 1)
    return engine.length_scale_m


def _grid_matrix(samples, points):
    """Evaluates a signal from its ``samples`` Fourier coefficients at ``points`` angles
    evenly spread over a revolution: x(θ) = Σ c_k·e^{ikθ} (the Nyquist term as a cosine)."""
    k = orders_of(samples)
    theta = 2.0 * np.pi * np.arange(points) / points
    matrix = np.exp(1j * np.outer(k, theta))
    if samples % 2 == 0:
        matrix[samples // 2] = np.cos(samples // 2 * theta)
    return matrix


@dataclass(frozen=True)
class MatchObjective:
    """The objective: ``terms`` (None for the default), the pitch moments are divided by (m),
    and the linear maps to its channels.

    ``force_map`` and ``moment_map`` (samples × channels) turn force (N) and moment (N·m)
    coefficients into the channels (for the default, ``force_map`` is the grid's and the
    channels are the force on the grid, then the moment over the pitch on it);
    :meth:`score` reads them.
    """

    terms: tuple | None
    pitch_m: float
    force_map: np.ndarray
    moment_map: np.ndarray
    weights: np.ndarray | None

    @property
    def default(self) -> bool:
        return self.terms is None

    @property
    def label(self) -> str:
        if self.terms is None:
            return "largest force + largest moment / pitch"
        return ",".join(str(t) for t in self.terms)

    def channels(self, force, moment):
        """The channels of coefficient arrays (..., samples), N."""
        if self.terms is None:
            grid = self.force_map
            return np.concatenate([force @ grid, (moment @ grid) / self.pitch_m], axis=-1)
        return force @ self.force_map + moment @ self.moment_map

    def score(self, channels):
        """The score of channels (..., K), N."""
        size = np.abs(channels)
        if self.terms is None:
            half = size.shape[-1] // 2
            return size[..., :half].max(axis=-1) + size[..., half:].max(axis=-1)
        return size @ self.weights

    def screen(self) -> np.ndarray | None:
        """Channels whose score is a lower bound of the score (every :data:`_SCREEN_STEP`-th
        grid point), or None when the score is exact on few channels already (terms)."""
        if self.terms is not None:
            return None
        half = GRID
        step = np.arange(0, half, _SCREEN_STEP)
        return np.concatenate([step, half + step])

    def shift_ok(self, shift_rad) -> bool:
        """Whether turning by ``shift_rad`` maps the channels' angles onto themselves."""
        if self.terms is not None:
            return True
        steps = shift_rad / (2 * np.pi / GRID)
        return abs(steps - round(steps)) < 1e-6

    def to_dict(self) -> dict:
        return {
            "objective": self.label,
            "default": self.default,
            "terms": None if self.terms is None else [t.to_dict() for t in self.terms],
            "pitch_m": self.pitch_m,
            "grid_points": GRID if self.terms is None else None,
        }


def match_objective(objective, engine, samples, max_order) -> MatchObjective:
    """The objective ``objective`` (None: the default; a string of F and M terms such as
    ``"F1,M1:2"``; or Terms) of ``engine`` analysed at ``samples`` angles.

    Raises
    ------
    AnalysisError
        naming ``objective``: a term other than F or M, or one that cannot be read
    """
    pitch = match_pitch(engine)
    if objective is None:
        grid = _grid_matrix(samples, GRID)
        return MatchObjective(None, pitch, grid, grid, None)
    if isinstance(objective, str):
        terms = parse_objective(objective, max_order)
    else:
        terms = tuple(objective)
        check_terms(terms, max_order)
    other = [t.name for t in terms if not isinstance(t, Term) or t.kind not in ("F", "M")]
    if other:
        raise AnalysisError(
            f"term {other[0]} is not a force or moment: matching weighs F and M terms "
            "(such as F1, M2:4, F1+)",
            "objective",
        )
    columns, weights = [], []
    for term in terms:
        parts = {"max": (1, -1), "forward": (1,), "backward": (-1,)}[term.part]
        for sign in parts:
            columns.append((term.kind, sign * term.order % samples))
            weights.append(term.weight)
    force_map = np.zeros((samples, len(columns)), complex)
    moment_map = np.zeros((samples, len(columns)), complex)
    for j, (kind, index) in enumerate(columns):
        if kind == "F":
            force_map[index, j] = 1.0
        else:
            moment_map[index, j] = 1.0 / pitch
    if not all(math.isfinite(w) for w in weights):
        raise AnalysisError("weights must be finite", "objective")
    return MatchObjective(terms, pitch, force_map, moment_map, np.array(weights))
