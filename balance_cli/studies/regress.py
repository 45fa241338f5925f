"""Regression tables: what moved between a baseline comparison and the same engines now.

A baseline is what ``balance compare --format json`` wrote (:meth:`Comparison.to_dict`); it
records the samples and the highest order, so the engines are analysed again exactly alike.
Engines are matched by name. Tolerances are those the project's own golden tables use
(:mod:`balance_cli.tolerances`):

- forces, moments and resultants: NOISE_FLOOR (1e-9) of the engine's m_rec·r·ω²·n (N, or N·m);
- phases (and an ellipse's axis, modulo 180°): PHASE_CHANGE_DEG (1e-6°), compared only where
  the phasor exceeds PHASE_FLOOR (1e-6) of m_rec·r·ω²·n (below that its direction is noise);
- firing angles: FIRING_CHANGE_DEG (1e-4°; the top-dead-centre search is good to 2e-6°).

``rtol`` loosens them for a design under development: a force, moment or resultant may then
move by ``rtol`` times its baseline value, and an angle by ``rtol`` radians (a phasor changed by
a fraction ``rtol`` of itself turns by at most that much), whichever is larger.
"""

import math
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from ..analysis.results import Comparison, analyse, compare
from ..analysis.shaking import check_settings
from ..errors import AnalysisError, RegressError
from ..output import DOCUMENT_VERSION, READABLE_VERSIONS
from ..tabular import Tabular, joined
from ..tolerances import FIRING_CHANGE_DEG, NOISE_FLOOR, PHASE_CHANGE_DEG, PHASE_FLOOR
from ..units import angle_change

__all__ = [
    "Moved",
    "Regression",
    "regression",
    "check_baseline",
    "check_rtol",
    "baseline_configs",
    "compared_like",
    "reanalyse",
]

#: what a quantity is: a value compared by size, a phase (period 360°) or an axis (period 180°)
_PERIODS = {"value": None, "phase": 360.0, "axis": 180.0}


@dataclass(frozen=True)
class Moved:
    """One quantity that moved beyond its tolerance.

    ``order`` is None for quantities of the whole engine (resultants, firing); ``baseline`` and
    ``now`` are numbers (SI; degrees for angles, whose ``period`` is 360 or 180) or, for the
    firing order and flags, plain values.
    """

    engine: str
    order: int | None
    quantity: str
    baseline: Any
    now: Any
    tolerance: float | None
    period: float | None = None

    @property
    def change(self) -> float | None:
        if not (_number(self.baseline) and _number(self.now)):
            return None
        if self.period:
            return angle_change(self.baseline, self.now, self.period)
        return self.now - self.baseline

    @property
    def relative_change(self) -> float | None:
        change = self.change
        if change is None or self.period or not self.baseline:
            return None
        return change / abs(self.baseline)

    def to_dict(self) -> dict:
        return {
            "engine": self.engine,
            "order": self.order,
            "quantity": self.quantity,
            "baseline": self.baseline,
            "now": self.now,
            "change": self.change,
            "relative_change": self.relative_change,
            "tolerance": self.tolerance,
        }


@dataclass(frozen=True)
class Regression(Tabular):
    """The regression table: what moved, and the engines added and removed.

    ``configs`` maps every engine's name to its configuration file (baseline's or now).
    """

    baseline_path: str
    rtol: float
    rows: tuple
    added: tuple
    removed: tuple
    checked: tuple = ()
    configs: dict = field(default_factory=dict, compare=False)

    @property
    def moved(self) -> bool:
        """Something changed: a quantity beyond its tolerance, or an engine added or removed."""
        return bool(self.rows or self.added or self.removed)

    def rows_of(self, engine) -> list:
        return [row for row in self.rows if row.engine == engine]

    def records(self) -> list:
        """One row per quantity that moved (the JSON's ``rows``: ``engine``, ``order``,
        ``quantity``, ``baseline``, ``now``, ``change``, ``relative_change``, ``tolerance``;
        SI, degrees for angles; a firing order as text, "1-3-4-2"); none when nothing moved
        (``added`` and ``removed`` name the engines that came and went)."""
        return [
            {
                key: joined(value) if isinstance(value, (list, tuple)) else value
                for key, value in row.to_dict().items()
            }
            for row in self.rows
        ]

    def to_dict(self) -> dict:
        return {
            "balance_version": DOCUMENT_VERSION,
            "baseline": self.baseline_path,
            "rtol": self.rtol,
            "moved": self.moved,
            "engines_checked": list(self.checked),
            "rows": [row.to_dict() for row in self.rows],
            "added": list(self.added),
            "removed": list(self.removed),
        }


def _number(value):
    return isinstance(value, (int, float)) and not isinstance(value, bool) and math.isfinite(value)


#: what a regression table reads of each engine of a baseline, by the version that wrote it:
#: its own keys, those of its firing, those of each order's force and moment with {u} the
#: unit, N or Nm; version 2 added the moments' largest values, the vertical and the vertical
#: and horizontal components of every order
_V1_ENGINE = (
    "name",
    "config",
    "cylinders",
    "cycle",
    "frame",
    "speed_rpm",
    "unit_force_N",
    "largest_resultant_N",
    "counterweighted_resultant_N",
    "sampling_ok",
    "firing",
    "orders",
)
_FIRING = ("order", "angles_deg", "uniform")
_V1_PART = (
    "forward_{u}",
    "forward_deg",
    "backward_{u}",
    "backward_deg",
    "max_{u}",
    "min_{u}",
    "axis_deg",
)
_NEEDED: dict[int, tuple[tuple[str, ...], tuple[str, ...], tuple[str, ...]]] = {
    1: (_V1_ENGINE, _FIRING, _V1_PART),
    2: (
        _V1_ENGINE + ("largest_moment_Nm", "counterweighted_moment_Nm", "vertical_deg"),
        _FIRING,
        _V1_PART + ("vertical_{u}", "vertical_deg", "horizontal_{u}", "horizontal_deg"),
    ),
}
#: the numbers among an engine's keys (resultants, moments, speed, the vertical)
_ENGINE_NUMBERS = (
    "speed_rpm",
    "largest_resultant_N",
    "counterweighted_resultant_N",
    "largest_moment_Nm",
    "counterweighted_moment_Nm",
    "vertical_deg",
)


def _missing(record, keys):
    """The keys of ``keys`` that ``record`` lacks, in their order."""
    return [key for key in keys if key not in record]


def _lacks(keys):
    return f"lacks {', '.join(repr(k) for k in keys)}, which balance regress compares"


def _fail(where, problem):
    raise RegressError(
        f"{where}: {problem}; write the baseline again with balance compare "
        "FILE|DIR --format json -o BASELINE.json"
    )


def check_baseline(document, path="<baseline>"):
    """Raise RegressError unless ``document`` is a comparison balance wrote: every record a
    regression table reads is there, with numbers where numbers belong."""
    for key in ("engines", "balance_version"):
        if not isinstance(document, dict) or key not in document:
            _fail(path, f"not a `balance compare --format json` document (no {key!r})")
    version = document["balance_version"]
    if type(version) is not int or version not in READABLE_VERSIONS:
        raise RegressError(
            f"{path}: written by balance_version {version!r}, but this balance "
            f"reads versions {', '.join(map(str, READABLE_VERSIONS))}; write the "
            "baseline again with this version"
        )
    for key in ("samples", "max_order"):
        if isinstance(document.get(key), bool) or not isinstance(document.get(key), int):
            _fail(path, f"has no whole number {key!r}")
    override = document.get("speed_override_rpm")
    if override is not None and not (_number(override) and override > 0):
        _fail(path, f"records a speed_override_rpm that is not a speed ({override!r})")
    try:
        check_settings(document["samples"], document["max_order"])
    except AnalysisError as exc:
        _fail(path, f"records {exc}")
    engines = document["engines"]
    if not isinstance(engines, list) or not engines:
        _fail(path, "lists no engines")
    # a later version than those listed reads at least the latest's keys
    engine_keys, firing_keys, part_keys = _NEEDED[max(v for v in _NEEDED if v <= version)]
    names = []
    for i, engine in enumerate(engines, 1):
        where = f"{path}: engines[{i}]"
        if not isinstance(engine, dict):
            _fail(where, "is not an object")
        if isinstance(engine.get("name"), str):
            where += f" ({engine['name']!r})"
        missing = _missing(engine, engine_keys)
        if missing:
            _fail(where, _lacks(missing))
        if not isinstance(engine["name"], str) or not isinstance(engine["config"], str):
            _fail(where, "has a name or config that is not text")
        odd = [k for k in _ENGINE_NUMBERS if k in engine_keys and not _number(engine[k])]
        if odd:
            _fail(where, f"has {', '.join(repr(k) for k in odd)} that is not a finite number")
        if (
            not _number(engine["unit_force_N"])
            or not _number(engine["cylinders"])
            or engine["unit_force_N"] <= 0
            or engine["cylinders"] <= 0
        ):
            _fail(where, "has no positive unit_force_N and cylinders")
        firing = engine["firing"]
        if isinstance(firing, dict) and _missing(firing, firing_keys):
            _fail(f"{where} firing", _lacks(_missing(firing, firing_keys)))
        if (
            not isinstance(firing, dict)
            or not isinstance(firing.get("order"), list)
            or not isinstance(firing.get("angles_deg"), list)
            or not all(_number(a) for a in firing["angles_deg"])
        ):
            _fail(where, "has no firing order and angles")
        orders = engine["orders"]
        if not isinstance(orders, list):
            _fail(where, "has no list of orders")
        for o in orders:
            parts = [o.get(part) for part in ("force", "moment")] if isinstance(o, dict) else []
            if (
                not isinstance(o, dict)
                or not _number(o.get("order"))
                or not all(
                    isinstance(p, dict)
                    and all(_number(v) or k == "axis_deg" and v is None for k, v in p.items())
                    for p in parts
                )
                or len(parts) != 2
            ):
                _fail(
                    where,
                    "has an order that is not {order, force: {...}, moment: {...}} of "
                    "finite numbers (an axis may be null)",
                )
            for part, unit in (("force", "N"), ("moment", "Nm")):
                missing = _missing(o[part], [k.format(u=unit) for k in part_keys])
                if missing:
                    _fail(f"{where} order {o['order']:g} {part}", _lacks(missing))
        listed = [o["order"] for o in orders]
        if len(set(listed)) != len(listed):
            _fail(where, "lists an order twice")
        names.append(engine["name"])
    twice = sorted({n for n in names if names.count(n) > 1})
    if twice:
        raise RegressError(
            f"{path}: names {twice[0]!r} twice; engines are matched by name, so "
            "give each configuration its own name"
        )


def baseline_configs(document, path):
    """The configuration files the baseline names: as written (relative to the current folder),
    else relative to the baseline's own folder or one of its parents (a baseline written from
    a repository's root and kept in a folder of it, checked from anywhere)."""
    files = []
    folder = Path(path).resolve().parent
    for engine in document["engines"]:
        named = Path(engine["config"])
        for candidate in [named] + [base / named for base in (folder, *folder.parents)]:
            if candidate.is_file():
                files.append(candidate)
                break
        else:
            raise RegressError(
                f"{path}: names the configuration {engine['config']!r} of "
                f"{engine['name']!r}, which no longer exists; restore it, or give "
                "the files to check (and update the baseline to record the change)"
            )
    return files


def compared_like(document, results) -> Comparison:
    """Analysed ``results`` compared as the baseline compared its engines: with its reference
    engine when they still hold it, else with the first."""
    reference = document.get("reference")
    return compare(results, reference if reference in [r.engine.name for r in results] else None)


def reanalyse(document, engines) -> Comparison:
    """``engines`` analysed with the baseline's samples and orders and compared like it."""
    return compared_like(
        document, [analyse(e, document["samples"], document["max_order"]) for e in engines]
    )


def check_rtol(rtol):
    """Raise RegressError unless ``rtol`` is a number from 0 up to (not including) 1."""
    if isinstance(rtol, bool) or not isinstance(rtol, (int, float)) or not 0 <= rtol < 1:
        raise RegressError(f"must be a number from 0 up to (not including) 1, got {rtol!r}", "rtol")


def regression(baseline, current, rtol=0.0, baseline_path="<baseline>") -> Regression:
    """Compare ``current`` (a :class:`Comparison`, or its ``to_dict()``) with ``baseline``.

    Parameters
    ----------
    baseline : dict
        a comparison as ``balance compare --format json`` wrote it
    current : Comparison or dict
        the same engines analysed now, with the baseline's samples and max_order
    rtol : float
        loosen every tolerance (see the module's documentation); 0 for the strict defaults

    Raises
    ------
    RegressError
        a baseline that is not a comparison, an ``rtol`` out of range, or ``current`` analysed
        with other samples or orders than the baseline
    """
    check_baseline(baseline, baseline_path)
    check_rtol(rtol)
    now = current.to_dict() if isinstance(current, Comparison) else current
    if not isinstance(now, dict):
        raise RegressError(
            f"current must be a Comparison or its to_dict(), got {type(current).__name__}"
        )
    for key in ("samples", "max_order"):
        if now.get(key) != baseline[key]:
            raise RegressError(
                f"the engines were analysed with {key} = {now.get(key)!r}, the "
                f"baseline with {baseline[key]!r}; analyse them alike "
                "(regress.reanalyse does)"
            )
    old = {e["name"]: e for e in baseline["engines"]}
    new = {e["name"]: e for e in now["engines"]}
    rows = []
    for name in [n for n in new if n in old]:
        rows += _engine_rows(name, old[name], new[name], rtol)
    configs = {n: e["config"] for n, e in old.items()} | {n: e["config"] for n, e in new.items()}
    return Regression(
        baseline_path,
        float(rtol),
        tuple(rows),
        tuple(n for n in new if n not in old),
        tuple(n for n in old if n not in new),
        tuple(n for n in new if n in old),
        configs,
    )


def _engine_rows(name, a, b, rtol):
    # the JSON's per-cylinder unit, m_rec·r·ω²·n, as the JSON documents page gives it
    scale = b["unit_force_N"] * b["cylinders"]
    rows = []

    def number(quantity, x, y, tolerance, kind="value", order=None):
        period = _PERIODS[kind]
        if not (_number(x) and _number(y)):
            if x != y:
                rows.append(Moved(name, order, quantity, x, y, None, period))
            return
        if period:
            change = abs(angle_change(x, y, period))
            tolerance = max(tolerance, math.degrees(rtol))
        else:
            change = abs(y - x)
            tolerance = max(tolerance, rtol * abs(x))
        if change > tolerance:
            rows.append(Moved(name, order, quantity, x, y, tolerance, period))

    def same(quantity, x, y):
        if x != y:
            rows.append(Moved(name, None, quantity, x, y, None))

    for key in ("cylinders", "cycle", "frame"):
        same(key, a.get(key), b.get(key))
    number(
        "speed_rpm",
        a.get("speed_rpm"),
        b.get("speed_rpm"),
        NOISE_FLOOR * abs(a.get("speed_rpm") or 0.0),
    )
    number("unit_force_N", a["unit_force_N"], b["unit_force_N"], NOISE_FLOOR * scale)
    for key in ("largest_resultant_N", "counterweighted_resultant_N"):
        number(key, a.get(key), b.get(key), NOISE_FLOOR * scale)
    # version 2's quantities, where both documents have them (a version-1 baseline has not)
    for key in ("largest_moment_Nm", "counterweighted_moment_Nm"):
        if key in a and key in b:
            number(key, a[key], b[key], NOISE_FLOOR * scale)
    if "vertical_deg" in a and "vertical_deg" in b:
        number("vertical_deg", a["vertical_deg"], b["vertical_deg"], PHASE_CHANGE_DEG, "phase")
    fa, fb = a["firing"], b["firing"]
    same("firing order", fa.get("order"), fb.get("order"))
    if fa.get("order") == fb.get("order"):
        for cylinder, x, y in zip(
            fb["order"], fa.get("angles_deg", []), fb.get("angles_deg", []), strict=False
        ):
            number(f"firing angle of cylinder {cylinder}", x, y, FIRING_CHANGE_DEG, "phase")
    same("firing uniform", fa.get("uniform"), fb.get("uniform"))
    same("sampling_ok", a.get("sampling_ok"), b.get("sampling_ok"))
    orders_a = {o["order"]: o for o in a["orders"]}
    orders_b = {o["order"]: o for o in b["orders"]}
    for k in sorted(set(orders_a) | set(orders_b)):
        if k not in orders_a or k not in orders_b:
            rows.append(
                Moved(
                    name,
                    k,
                    "order",
                    "listed" if k in orders_a else "absent",
                    "listed" if k in orders_b else "absent",
                    None,
                )
            )
            continue
        for part, unit in (("force", "N"), ("moment", "Nm")):
            x, y = orders_a[k][part], orders_b[k][part]
            for key in (f"forward_{unit}", f"backward_{unit}", f"max_{unit}", f"min_{unit}"):
                number(f"{part}.{key}", x.get(key), y.get(key), NOISE_FLOOR * scale, order=k)
            for key in (f"vertical_{unit}", f"horizontal_{unit}"):
                if key in x and key in y:
                    number(f"{part}.{key}", x[key], y[key], NOISE_FLOOR * scale, order=k)
            for key in ("forward", "backward", "vertical", "horizontal"):
                if key in ("vertical", "horizontal") and (
                    f"{key}_{unit}" not in x or f"{key}_{unit}" not in y
                ):
                    continue
                size = max(x.get(f"{key}_{unit}", 0.0), y.get(f"{key}_{unit}", 0.0))
                if size >= PHASE_FLOOR * scale:
                    number(
                        f"{part}.{key}_deg",
                        x.get(f"{key}_deg"),
                        y.get(f"{key}_deg"),
                        PHASE_CHANGE_DEG,
                        "phase",
                        k,
                    )
            # an axis exists where the ellipse is not a circle: max − min above the floor
            size = min(
                x.get(f"max_{unit}", 0.0) - x.get(f"min_{unit}", 0.0),
                y.get(f"max_{unit}", 0.0) - y.get(f"min_{unit}", 0.0),
            )
            if size >= PHASE_FLOOR * scale:
                number(
                    f"{part}.axis_deg",
                    x.get("axis_deg"),
                    y.get("axis_deg"),
                    PHASE_CHANGE_DEG,
                    "axis",
                    k,
                )
    return rows
