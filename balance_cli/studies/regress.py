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
import re
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from ..analysis.results import Comparison, analyse, compare
from ..analysis.shaking import check_settings
from ..errors import AnalysisError, RegressError
from ..output import DOCUMENT_VERSION, READABLE_VERSIONS
from ..schemas import problem
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


def _where(document, path):
    """A JSON path with the name of the engine it leads into: ``$.engines[0] ('V8')...``."""
    match = re.match(r"^\$\.engines\[(\d+)\]", path)
    if match is None:
        return path
    engines = document.get("engines")
    index = int(match.group(1))
    name = engines[index].get("name") if isinstance(engines[index], dict) else None
    if not isinstance(name, str):
        return path
    return f"{match.group(0)} ({name!r}){path[match.end() :]}"


def _fail(where, problem):
    raise RegressError(
        f"{where}: {problem}; write the baseline again with balance compare "
        "FILE|DIR --format json -o BASELINE.json"
    )


def check_baseline(document, path="<baseline>"):
    """Raise RegressError unless ``document`` is a comparison balance wrote: valid under the
    JSON Schema of its version (:mod:`balance_cli.schemas`: ``compare.v3.json`` is every key of
    the document, ``compare.v1.json`` and ``v2`` what a regression table reads of one that
    old), with settings that work together and each engine and order listed once. The error
    names the file, the JSON path and what is wrong there."""
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
    found = problem(document, "compare", version)
    if found is not None:
        _fail(f"{path}: {_where(document, found.path)}", f"{found.message} ({found.schema})")
    try:
        check_settings(document["samples"], document["max_order"])
    except AnalysisError as exc:
        _fail(path, f"records {exc}")
    for i, engine in enumerate(document["engines"]):
        listed = [o["order"] for o in engine["orders"]]
        twice = next((k for k in listed if listed.count(k) > 1), None)
        if twice is not None:
            _fail(
                f"{path}: {_where(document, f'$.engines[{i}].orders')}",
                f"lists order {twice} twice",
            )
    names = [engine["name"] for engine in document["engines"]]
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
