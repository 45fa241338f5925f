"""A project-guide table for an engine family: one cylinder's data, every number of cylinders.

For each cylinder count the in-line engine is built at the family's cylinder pitch, its crank
and firing order found by the exhaustive search (:func:`balance_cli.cranksearch`, proved optimal
for the objective; the labelled heuristic where the count is too large to enumerate) or taken
from the firing orders the user gives, and analysed as the makers' project guides tabulate
it: the external moments M1V, M1H, M2V, M2H, their power related unbalance and its class, the
largest H-type and X-type guide-force moments, and whether a second-order compensator is
indicated.
"""

import math
import os
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from typing import Any

from ..analysis.results import analyse
from ..analysis.shaking import DEFAULT_MAX_ORDER, DEFAULT_SAMPLES
from ..analysis.torque import torque
from ..checks import instance, positive, whole
from ..config import Configuration, build, read_configuration
from ..cranksearch import DEFAULT_LIMIT, search
from ..errors import AnalysisError, BalanceError
from ..output import DOCUMENT_VERSION

__all__ = ["FamilyRow", "FamilyResult", "family", "default_objective"]

#: the PRU classes that call for a second-order compensator
_COMPENSATOR = ("likely", "most likely")


@dataclass(frozen=True)
class FamilyRow:
    """One number of cylinders.

    ``method``: "exhaustive" (proved optimal for the objective), "heuristic" (the best found,
    not proved) or "given" (the firing order the user gave); ``result``: the engine analysed
    (an :class:`~balance_cli.EngineResult`); ``guide``: its :class:`GuideForces` (None without
    a crosshead or piston guide, on a rotary).
    """

    cylinders: int
    method: str
    score: float | None
    result: Any
    guide: Any

    def to_dict(self) -> dict:
        record = self.result.to_dict()
        orders = record["orders"]
        moments = {
            f"M{k}{d}_Nm": orders[k - 1]["moment"][f"{w}_Nm"]
            for k in (1, 2)
            for d, w in (("V", "vertical"), ("H", "horizontal"))
        }
        pru = record["pru"]
        balanced = None if pru is None else pru["first_order_balanced"]
        if balanced is not None:
            moments.update(
                M1V_balanced_Nm=balanced["vertical_Nm"], M1H_balanced_Nm=balanced["horizontal_Nm"]
            )
        second = None if pru is None else next((e for e in pru["orders"] if e["order"] == 2), None)
        return {
            "cylinders": self.cylinders,
            "method": self.method,
            "score": self.score,
            "firing_order": record["firing"]["order"],
            "phases_deg": [math.degrees(t.phase_rad) % 360.0 for t in self.result.engine.throws],
            **moments,
            "power_kW": record["power_kW"],
            "pru": pru,
            "pru_note": record["pru_note"],
            "h_type": _largest(self.guide.h_type) if self.guide else None,
            "x_type": _largest(self.guide.x_type) if self.guide else None,
            "second_order_compensator": None
            if second is None
            else second["vertical_class"] in _COMPENSATOR
            or second["horizontal_class"] in _COMPENSATOR,
        }


def _largest(series):
    """The order with the largest amplitude of a guide-force moment: {order, amplitude_Nm};
    None when every order analysed is zero (an N-cylinder's H-type moment lives at multiples
    of N, which may lie above them)."""
    if not series.orders:
        return None
    order, cos, sin = max(series.orders, key=lambda o: math.hypot(o[1], o[2]))
    amplitude = math.hypot(cos, sin)
    return {"order": order, "amplitude_Nm": amplitude} if amplitude > 0 else None


@dataclass(frozen=True)
class FamilyResult:
    """The family table: ``rows`` (one :class:`FamilyRow` per number of cylinders), the
    template's ``name`` and ``config``, the ``objective``, ``pitch_m`` and
    ``power_per_cylinder_w`` (None without a power)."""

    name: str
    config: str
    objective: str
    pitch_m: float
    power_per_cylinder_w: float | None
    rows: tuple
    samples: int
    max_order: int
    has_gas: bool = False

    def to_dict(self) -> dict:
        """What ``balance family --format json`` writes (SI; see the README)."""
        return {
            "balance_version": DOCUMENT_VERSION,
            "name": self.name,
            "config": self.config,
            "objective": self.objective,
            "pitch_m": self.pitch_m,
            "guide_forces_from": "gas and inertia" if self.has_gas else "inertia only",
            "power_per_cylinder_kW": None
            if self.power_per_cylinder_w is None
            else self.power_per_cylinder_w / 1e3,
            "samples": self.samples,
            "max_order": self.max_order,
            "rows": [r.to_dict() for r in self.rows],
        }


def _counts(cylinders):
    counts = list(cylinders) if isinstance(cylinders, (list, tuple, range)) else None
    if not counts:
        raise AnalysisError(
            f"must be numbers of cylinders from 2 to 24, got {cylinders!r}", "cylinders"
        )
    return sorted({whole(n, "cylinders", 2, 24) for n in counts})


def default_objective(data, path, samples, max_order):
    """The family's default objective in N·m (per pitch): the search's coefficients are each
    in its order's own unit (one throw's largest order-k force × pitch), so M1⁻ and M2 add up
    physically only weighted by those forces: 2·|M1⁻| is the first-order couple left with the
    rotating masses balanced (what the reciprocating masses make: forward and backward halves
    alike), |M2| the second-order couple. Returns "M1-:w,M2" with w = 2·F1/F2 of one throw."""
    one = {k: v for k, v in data.items() if k not in ("throws", "power", "firing_order")}
    one["throws"] = [{"z": "0 m"}]
    orders = analyse(build(one, path, template=True), samples, max(2, min(max_order, 2))).shaking
    f1 = abs(orders.order(1).force_forward) + abs(orders.order(1).force_backward)
    f2 = abs(orders.order(2).force_forward) + abs(orders.order(2).force_backward)
    if f2 == 0.0:
        return "M1-"
    return f"M1-:{2 * f1 / f2:.6g},M2"


def _even_phases(order, n):
    """A two-stroke's throw phases for a firing order at even intervals: the cylinder that
    fires i-th does so 360·i/n after cylinder 1, so its throw sits that far behind."""
    fired = {c: 360.0 * i / n for i, c in enumerate(order)}
    return [(-fired[c]) % 360.0 for c in range(1, n + 1)]


def family(
    configuration,
    cylinders: Sequence[int],
    objective: str | None = None,
    pitch_m: float | None = None,
    power_per_cylinder_w: float | None = None,
    firing_orders: Mapping[int, Sequence[int]] | None = None,
    samples: int = DEFAULT_SAMPLES,
    max_order: int = DEFAULT_MAX_ORDER,
    workers: int | None = None,
    limit: int | None = None,
    progress: Callable[[int, int], None] | None = None,
) -> FamilyResult:
    """The family table of an in-line engine: its one cylinder at every number of cylinders.

    Parameters
    ----------
    configuration : Configuration, str or PathLike
        the engine's configuration (:func:`~balance_cli.read_configuration`), or its file: a
        configuration with phases or a search template (its phases and firing order are
        left out)
    cylinders : sequence of int
        the numbers of cylinders, 2 to 24
    objective : str, optional
        what the search minimises (default :func:`default_objective`: the balanced
        first-order couple plus the second-order couple, in N·m)
    pitch_m : float, optional
        the cylinder pitch, m (default the template's mean throw pitch)
    power_per_cylinder_w : float, optional
        W at the template's speed (default the template's ``power`` over its cylinders)
    firing_orders : mapping of int to sequence of int, optional
        a given firing order for some cylinder counts (two-stroke, even firing), instead of
        the search's
    workers, limit : int, optional
        as for :func:`~balance_cli.cranksearch`; a count whose exhaustive search would pass
        ``limit`` is searched by the heuristic, and labelled so

    Raises
    ------
    AnalysisError, ConfigError
        naming the parameter, or the file and key
    """
    counts = _counts(cylinders)
    if isinstance(configuration, (str, os.PathLike)):
        configuration = read_configuration(configuration)
    instance(
        configuration,
        Configuration,
        "configuration",
        hint=" (balance.read_configuration(path), or a file's path)",
    )
    path = configuration.path
    if power_per_cylinder_w is not None:
        power_per_cylinder_w = positive(power_per_cylinder_w, "power_per_cylinder_w", "power")
    instance(
        firing_orders,
        (dict, type(None)),
        "firing_orders",
        hint=" of cylinder counts to firing orders",
    )
    data = configuration.as_template().data
    template = build(data, path, template=True)
    if (
        template.is_rotary
        or len(template.bank_angles_rad) != 1
        or "cylinders" in data
        or template.has_several_crankshafts
    ):
        raise AnalysisError(
            "must be an in-line template (one bank, one crankshaft, no "
            "[[cylinders]] list): a family is the same cylinder repeated at a "
            "pitch",
            "template",
        )
    zs = sorted(t.z_m for t in template.throws)
    if pitch_m is None:
        if len(zs) < 2 or zs[-1] == zs[0]:
            raise AnalysisError(
                "has no pitch to repeat: give two or more throws apart, or the pitch", "pitch_m"
            )
        pitch_m = (zs[-1] - zs[0]) / (len(zs) - 1)
    pitch_m = positive(pitch_m, "pitch_m", "length")
    if power_per_cylinder_w is None and template.power_w is not None:
        power_per_cylinder_w = template.power_w / template.n_cylinders
    firing_orders = dict(firing_orders or {})
    for n, order in firing_orders.items():
        if n not in counts:
            raise AnalysisError(
                f"gives {n} cylinders, which are not among the numbers asked "
                f"({', '.join(map(str, counts))})",
                "firing_orders",
            )
        if sorted(order) != list(range(1, n + 1)):
            raise AnalysisError(
                f"{n}: {list(order)} is not a firing order of {n} cylinders: "
                f"name each of 1 to {n} once",
                "firing_orders",
            )
        if template.cycle != 2:
            raise AnalysisError(
                "fit a two-stroke only (its firing order at even intervals "
                "fixes the crank; a four-stroke's does not)",
                "firing_orders",
            )
    objective = objective or default_objective(data, path, samples, max_order)
    rows = []
    for done, n in enumerate(counts):
        throws = [{"z": f"{j * pitch_m!r} m"} for j in range(n)]
        case = {k: v for k, v in data.items() if k not in ("throws", "power", "firing_order")}
        case.update(throws=throws, name=f"{data.get('name', 'family')} ({n} cylinders)"[:120])
        if power_per_cylinder_w is not None:
            case["power"] = f"{n * power_per_cylinder_w!r} W"
        if n in firing_orders:
            order = list(firing_orders[n])
            case["throws"] = [
                {**t, "phase": p} for t, p in zip(throws, _even_phases(order, n), strict=True)
            ]
            case["firing_order"] = order
            result = analyse(build(case, path), samples, max_order)
            method, score = "given", None
        else:
            engine = build(case, path, template=True)
            try:
                found = search(
                    engine,
                    objective,
                    top=1,
                    workers=workers,
                    limit=limit or DEFAULT_LIMIT,
                    samples=samples,
                    max_order=max_order,
                )
            except BalanceError as exc:
                if getattr(exc, "parameter", None) != "limit":
                    raise
                found = search(
                    engine, objective, top=1, heuristic=True, samples=samples, max_order=max_order
                )
            best = found.arrangements[0]
            result, method, score = best.result, found.method, best.score
        # an n-cylinder's H-type moment lives at order n: analyse the torques that far
        orders = max(max_order, n) if samples >= 4 * n + 1 else max_order
        guide = torque(result.engine, samples, orders, bearings=False).guide
        rows.append(FamilyRow(n, method, score, result, guide))
        if progress is not None:
            progress(done + 1, len(counts))
    return FamilyResult(
        data.get("name", ""),
        path,
        objective,
        pitch_m,
        power_per_cylinder_w,
        tuple(rows),
        samples,
        max_order,
        template.gas is not None,
    )
