"""A project-guide table for an engine family: one cylinder's data, every number of cylinders.

For each cylinder count the in-line (or V) engine is built at the family's cylinder pitch, its crank
and firing order found by the exhaustive search (:func:`balance_cli.cranksearch`, proved optimal
for the objective; the labelled heuristic where the count is too large to enumerate) or taken
from the firing orders the user gives, and analysed as the makers' project guides tabulate
it: the external moments M1V, M1H, M2V, M2H and M4V, M4H, their power related unbalance and its
class, the largest H-type and X-type guide-force moments, and whether a second-order compensator
is indicated. The first order is under the guides' standard balance unless another is asked
(:mod:`balance_cli.analysis.marine`), with the rotating-only and as-the-crank-stands figures
beside it.

A V family (a template of two banks, a throw for each pair of cylinders) is searched as the
makers of medium-speed V engines choose their cranks: each bank fires evenly on its own (its
firing order an in-line engine's), the other bank's cylinder on each throw the bank angle
after (the Wärtsilä Vasa 32's 12V32: A1-B1-A5-B5-A3-B3-A6-B6-A2-B2-A4-B4, bank A the 6R32's
1-5-3-6-2-4), the free moments least; of the two ways the banks can follow each other (a
cylinder of bank B the bank angle, or that plus a revolution, after its partner) the one
that excites the torsional major orders least: the orders at which every cylinder of a bank
fires in phase, where the two banks' vectors add as |1 + e^{ik·Δ}|.
"""

import math
import os
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from typing import Any

from ..analysis import marine
from ..analysis.results import analyse
from ..analysis.shaking import DEFAULT_MAX_ORDER, DEFAULT_SAMPLES
from ..analysis.torque import torque
from ..checks import instance, positive, whole
from ..config import Configuration, build, read_configuration
from ..cranksearch import DEFAULT_LIMIT, search
from ..errors import AnalysisError, BalanceError
from ..output import DOCUMENT_VERSION
from ..tabular import Tabular, joined
from .vfamily import bank_phasing, major_orders, v_objective

__all__ = ["FamilyRow", "FamilyResult", "family", "default_objective"]

#: the PRU classes that call for a second-order compensator
_COMPENSATOR = ("likely", "most likely")
#: the orders whose moments the table shows besides the first: the second, and the fourth the
#: guides single out (MAN B&W's seven-cylinder engines; WinGD's M4V)
_MOMENT_ORDERS = (2, 4)


@dataclass(frozen=True)
class FamilyRow:
    """One number of cylinders.

    ``method``: "exhaustive" (proved optimal for the objective), "heuristic" (the best found,
    not proved) or "given" (the firing order the user gave); ``result``: the engine analysed
    (an :class:`~balance_cli.EngineResult`); ``guide``: its :class:`GuideForces` (None without
    a crosshead or piston guide, on a rotary); ``majors``: :func:`major_orders` of it.
    """

    cylinders: int
    method: str
    score: float | None
    result: Any
    guide: Any
    balance: Any = marine.STANDARD_BALANCE
    majors: tuple = ()

    def to_dict(self) -> dict:
        record = self.result.to_dict(pru_balance=self.balance)
        orders = record["orders"]
        balance = marine.judged_balance(self.result.engine, self.balance)
        first = marine.first_order_moments(self.result, balance)
        # judged_balance falls back to the crank where no counterweights are proposed
        assert first is not None
        moments = {"M1V_Nm": first["vertical_Nm"], "M1H_Nm": first["horizontal_Nm"]}
        for name in marine.FIRST_ORDER_BALANCES:
            named = marine.first_order_moments(self.result, name)
            for d, w in (("V", "vertical"), ("H", "horizontal")):
                moments[f"M1{d}_{name}_Nm"] = None if named is None else named[f"{w}_Nm"]
        for k in _MOMENT_ORDERS:
            for d, w in (("V", "vertical"), ("H", "horizontal")):
                moments[f"M{k}{d}_Nm"] = (
                    orders[k - 1]["moment"][f"{w}_Nm"] if k <= len(orders) else None
                )
        pru = record["pru"]
        second = None if pru is None else next((e for e in pru["orders"] if e["order"] == 2), None)
        return {
            "cylinders": self.cylinders,
            "method": self.method,
            "score": self.score,
            "firing_order": record["firing"]["order"],
            "phases_deg": [math.degrees(t.phase_rad) % 360.0 for t in self.result.engine.throws],
            "first_order_balance": balance.to_dict(),
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
            "major_orders": [{"order": k, "vector_sum": v} for k, v in self.majors],
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
class FamilyResult(Tabular):
    """The family table: ``rows`` (one :class:`FamilyRow` per number of cylinders), the
    template's ``name`` and ``config``, the ``objective``, ``pitch_m``,
    ``power_per_cylinder_w`` (None without a power) and ``banks`` (1 in-line, 2 a V family,
    searched with every bank firing evenly on its own)."""

    name: str
    config: str
    objective: str
    pitch_m: float
    power_per_cylinder_w: float | None
    rows: tuple
    samples: int
    max_order: int
    has_gas: bool = False
    first_order_balance: Any = marine.STANDARD_BALANCE
    banks: int = 1

    def records(self) -> list:
        """One row per number of cylinders, the keys of the JSON's ``rows`` made flat:
        ``firing_order`` as text ("1-5-3-4-2-6"), ``phases_deg`` as text ("0 240 120"),
        ``first_order_balance`` by name, the moments ``M1V_Nm`` ... ``M4H_Nm`` (N·m),
        ``power_kW``, the PRU of each order judged as ``PRU_M2V_Nm_per_kW`` and
        ``PRU_M2V_class``, the largest guide-force moments as ``h_type_Nm``, ``h_type_order``,
        ``x_type_Nm``, ``x_type_order``, ``second_order_compensator``, and the first major
        orders as ``major_order_1``, ``major_vector_sum_1``, ..."""
        return [_flat_row(row.to_dict()) for row in self.rows]

    def to_dict(self) -> dict:
        """What ``balance family --format json`` writes (SI; see the JSON page)."""
        return {
            "balance_version": DOCUMENT_VERSION,
            "name": self.name,
            "config": self.config,
            "objective": self.objective,
            "first_order_balance": self.first_order_balance.to_dict(),
            "firing": "even within each bank" if self.banks > 1 else "even",
            "pitch_m": self.pitch_m,
            "guide_forces_from": "gas and inertia" if self.has_gas else "inertia only",
            "power_per_cylinder_kW": None
            if self.power_per_cylinder_w is None
            else self.power_per_cylinder_w / 1e3,
            "samples": self.samples,
            "max_order": self.max_order,
            "rows": [r.to_dict() for r in self.rows],
        }


def _flat_row(record):
    """A family row's JSON record as one flat row (:meth:`FamilyResult.records`)."""
    flat: dict = {}
    for key, value in record.items():
        if key in ("firing_order", "phases_deg"):
            flat[key] = joined(value, "-" if key == "firing_order" else " ")
        elif key == "first_order_balance":
            flat[key] = value["name"]
        elif key in ("h_type", "x_type"):
            flat[f"{key}_Nm"] = None if value is None else value["amplitude_Nm"]
            flat[f"{key}_order"] = None if value is None else value["order"]
        elif key == "major_orders":
            for i, entry in enumerate(value, 1):
                flat[f"major_order_{i}"] = entry["order"]
                flat[f"major_vector_sum_{i}"] = entry["vector_sum"]
        elif key == "pru":
            for entry in value["orders"] if value else ():
                for side in ("vertical", "horizontal"):
                    name = f"PRU_M{entry['order']}{side[0].upper()}"
                    flat[f"{name}_Nm_per_kW"] = entry[f"{side}_Nm_per_kW"]
                    flat[f"{name}_class"] = entry[f"{side}_class"]
        else:
            flat[key] = value
    return flat


def _counts(cylinders):
    counts = list(cylinders) if isinstance(cylinders, (list, tuple, range)) else None
    if not counts:
        raise AnalysisError(
            f"must be numbers of cylinders from 2 to 24, got {cylinders!r}", "cylinders"
        )
    return sorted({whole(n, "cylinders", 2, 24) for n in counts})


def default_objective(data, path, samples, max_order, balance=marine.STANDARD_BALANCE):
    """The family's default objective in N·m (per pitch): the pitching plus the yawing couple
    of orders 1, 2 and 4, M1V + M1H + M2V + M2H + M4V + M4H, the moments the guides tabulate.

    The search's coefficients are each in its order's own unit (one throw's largest order-k
    force F_k × pitch), so they add up physically only weighted by those forces. Counterweights
    carrying the rotating masses and a fraction c of the reciprocating ones leave (1 − c) of
    the reciprocating first order vertical and c of it horizontal: M1V + M1H = 2·|M1⁻| (the
    backward part, which only the reciprocating masses make) whatever c is, so the crank
    chosen does not depend on the balance factor; as the crank stands it is 2·|M1⁺|. An
    in-line engine's higher orders act along the cylinders: M_kV = |M_k⁺| + |M_k⁻|, M_kH = 0.
    Returns "M1-:w1,M2,M4:w4" (M1+ as the crank stands) with w1 = 2·F1/F2 and w4 = F4/F2 of
    one throw; orders beyond ``max_order`` are left out.
    """
    balance = marine.first_order_balance(balance)
    one = {k: v for k, v in data.items() if k not in ("throws", "power", "firing_order")}
    one["throws"] = [{"z": "0 m"}]
    top = max(2, min(max_order, max(_MOMENT_ORDERS)))
    orders = analyse(build(one, path, template=True), samples, top).shaking

    def force(k):
        order = orders.order(k)
        return abs(order.force_forward) + abs(order.force_backward)

    first = "M1+" if balance.balance_factor is None else "M1-"
    f2 = force(2)
    if f2 == 0.0:
        return first
    terms = [f"{first}:{2 * force(1) / f2:.6g}", "M2"]
    if top >= 4 and force(4) > 0.0:
        terms.append(f"M4:{force(4) / f2:.6g}")
    return ",".join(terms)


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
    first_order_balance="standard",
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
        what the search minimises (default, or empty: :func:`default_objective`, the
        pitching plus yawing couples of orders 1, 2 and 4, in N·m)
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
    progress : callable(done, total), optional
        called at once with (0, total) and as each count's search goes on: ``total`` is
        1000 a count, each count's share filled as its own search reports
    first_order_balance : str, float or FirstOrderBalance
        the balance the first-order moments are given under
        (:func:`~balance_cli.analysis.marine.first_order_balance`): "standard" (default, the
        project guides': the rotating masses and half the reciprocating ones), "rotating",
        "crank" or a balance factor from 0 to 1

    Raises
    ------
    AnalysisError, ConfigError
        naming the parameter, or the file and key
    """
    counts = _counts(cylinders)
    balance = marine.first_order_balance(first_order_balance)
    if limit is not None:
        limit = whole(limit, "limit", 1, 10**15)
    if objective is not None:
        instance(objective, str, "objective", hint=" of terms such as 'M1-,M2'")
    if progress is not None and not callable(progress):
        raise AnalysisError(f"must be a function of (done, total), got {progress!r}", "progress")
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
    banks = len(template.bank_angles_rad)
    if (
        template.is_rotary
        or banks not in (1, 2)
        or "cylinders" in data
        or template.has_several_crankshafts
    ):
        raise AnalysisError(
            "must be an in-line or V template (one or two banks, one crankshaft, no "
            "[[cylinders]] list): a family is the same cylinder (or pair of cylinders) "
            "repeated at a pitch",
            "template",
        )
    odd = [n for n in counts if n % banks]
    if odd:
        raise AnalysisError(
            f"must be even for a V family (two cylinders a throw), got {odd[0]}", "cylinders"
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
        if template.cycle != 2 or banks != 1:
            raise AnalysisError(
                "fit an in-line two-stroke only (its firing order at even intervals "
                "fixes the crank; a four-stroke's or a V's does not)",
                "firing_orders",
            )
    objective = objective.strip() if objective else ""
    if not objective:
        objective = (
            default_objective(data, path, samples, max_order, balance)
            if banks == 1
            else v_objective(data, path, samples, max_order, balance)
        )
    rows = []
    share = 1000
    if progress is not None:
        progress(0, share * len(counts))
    for done, n in enumerate(counts):

        def searching(part, whole_, base=done * share):
            if progress is not None and whole_:
                progress(base + min(share, share * part // whole_), share * len(counts))

        throws = [{"z": f"{j * pitch_m!r} m"} for j in range(n // banks)]
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
                    progress=searching,
                    even_banks=banks > 1,
                )
            except BalanceError as exc:
                if getattr(exc, "parameter", None) != "limit":
                    raise
                found = search(
                    engine,
                    objective,
                    top=1,
                    heuristic=True,
                    samples=samples,
                    max_order=max_order,
                    progress=searching,
                    even_banks=banks > 1,
                )
            best = found.arrangements[0]
            result, method, score = best.result, found.method, best.score
        majors = major_orders(result.engine, banks)
        if banks > 1:
            result, majors = bank_phasing(result, case, path, samples, max_order)
        # an n-cylinder's H-type moment lives at order n: analyse the torques that far
        orders = max(max_order, n) if samples >= 4 * n + 1 else max_order
        guide = torque(result.engine, samples, orders, bearings=False).guide
        rows.append(FamilyRow(n, method, score, result, guide, balance, majors))
        if progress is not None:
            progress((done + 1) * share, share * len(counts))
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
        balance,
        banks,
    )
