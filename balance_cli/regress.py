"""Regression tables: what moved between a baseline comparison and the same engines now.

A baseline is what ``balance compare --format json`` wrote (:meth:`Comparison.to_dict`); it
records the samples and the highest order, so the engines are analysed again exactly alike.
Engines are matched by name. Tolerances are those the project's own golden tables use:

- forces, moments and resultants: 1e-9 of the engine's m_rec·r·ω²·n (N, or N·m);
- phases (and an ellipse's axis, modulo 180°): 1e-6°, compared only where the phasor exceeds
  1e-6 of m_rec·r·ω²·n (below that its direction is rounding noise);
- firing angles: 1e-4° (the top-dead-centre search is good to about 2e-6°).

``rtol`` loosens them for a design under development: a force, moment or resultant may then
move by ``rtol`` times its baseline value, and an angle by ``rtol`` radians (a phasor changed by
a fraction ``rtol`` of itself turns by at most that much), whichever is larger.
"""

import math
from dataclasses import dataclass, field

from .analysis import DOCUMENT_VERSION, Comparison
from .errors import BalanceError

__all__ = ["RegressError", "Moved", "Regression", "regression", "check_baseline", "RELATIVE",
           "PHASE_FLOOR", "PHASE_DEG", "FIRING_DEG"]

#: forces and moments may move by this fraction of the engine's m_rec·r·ω²·n
RELATIVE = 1e-9
#: phases are compared only where the phasor exceeds this fraction of m_rec·r·ω²·n
PHASE_FLOOR = 1e-6
PHASE_DEG = 1e-6
#: firing angles come from a TDC search good to about 2e-6°
FIRING_DEG = 1e-4

_ENGINE_KEYS = {"name", "config", "cylinders", "unit_force_N", "firing", "orders"}


class RegressError(BalanceError, ValueError):
    """A baseline that is not a comparison balance can check against."""


@dataclass(frozen=True)
class Moved:
    """One quantity that moved beyond its tolerance.

    ``order`` is None for quantities of the whole engine (resultants, firing); ``baseline`` and
    ``now`` are numbers (SI, degrees for ``*_deg``) or, for the firing order and flags, values.
    """

    engine: str
    order: int | None
    quantity: str
    baseline: object
    now: object
    tolerance: float | None

    @property
    def change(self) -> float | None:
        if _number(self.baseline) and _number(self.now):
            if self.quantity.endswith("_deg"):
                period = 180.0 if self.quantity.endswith("axis_deg") else 360.0
                return _angle_change(self.baseline, self.now, period)
            return self.now - self.baseline
        return None

    @property
    def relative_change(self) -> float | None:
        change = self.change
        if change is None or not self.baseline or self.quantity.endswith("_deg"):
            return None
        return change / abs(self.baseline)

    def to_dict(self) -> dict:
        return {"engine": self.engine, "order": self.order, "quantity": self.quantity,
                "baseline": self.baseline, "now": self.now, "change": self.change,
                "relative_change": self.relative_change, "tolerance": self.tolerance}


@dataclass(frozen=True)
class Regression:
    """The regression table: what moved, and the engines added and removed."""

    baseline_path: str
    rtol: float
    rows: tuple
    added: tuple
    removed: tuple
    checked: tuple = field(default_factory=tuple)

    @property
    def moved(self) -> bool:
        """Something changed: a quantity beyond its tolerance, or an engine added or removed."""
        return bool(self.rows or self.added or self.removed)

    def rows_of(self, engine) -> list:
        return [row for row in self.rows if row.engine == engine]

    def to_dict(self) -> dict:
        return {"balance_version": DOCUMENT_VERSION, "baseline": self.baseline_path,
                "rtol": self.rtol, "moved": self.moved, "engines_checked": list(self.checked),
                "rows": [row.to_dict() for row in self.rows], "added": list(self.added),
                "removed": list(self.removed)}


def _number(value):
    return isinstance(value, (int, float)) and not isinstance(value, bool)


def _angle_change(a, b, period):
    return (b - a + period / 2) % period - period / 2


def check_baseline(document, path="<baseline>"):
    """Raise RegressError unless ``document`` is a comparison balance wrote."""
    where = f"{path}: "
    for key in ("engines", "balance_version"):
        if not isinstance(document, dict) or key not in document:
            raise RegressError(where + f"not a `balance compare --format json` document (no {key!r}); "
                               "write one with balance compare FILE|DIR --format json -o BASELINE.json")
    version = document.get("balance_version")
    if version != DOCUMENT_VERSION:
        raise RegressError(where + f"written by balance_version {version!r}, but this balance reads "
                                   f"version {DOCUMENT_VERSION}; write the baseline again with this version")
    for key in ("samples", "max_order"):
        if not isinstance(document.get(key), int) or isinstance(document.get(key), bool):
            raise RegressError(where + f"has no whole number {key!r}; write the baseline again")
    engines = document["engines"]
    if not isinstance(engines, list) or not engines:
        raise RegressError(where + "lists no engines; write the baseline again")
    for i, engine in enumerate(engines, 1):
        missing = sorted(_ENGINE_KEYS - set(engine)) if isinstance(engine, dict) else ["everything"]
        if missing:
            raise RegressError(where + f"engine {i} lacks {', '.join(missing)}; write the baseline again")
    names = [e["name"] for e in engines]
    twice = sorted({n for n in names if names.count(n) > 1})
    if twice:
        raise RegressError(where + f"names {twice[0]!r} twice; engines are matched by name, so give "
                                   "each configuration its own name")


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
    """
    check_baseline(baseline, baseline_path)
    if isinstance(rtol, bool) or not isinstance(rtol, (int, float)) or not 0 <= rtol < 1:
        raise RegressError(f"must be a number from 0 up to (not including) 1, got {rtol!r}", "rtol")
    now = current.to_dict() if isinstance(current, Comparison) else current
    old = {e["name"]: e for e in baseline["engines"]}
    new = {e["name"]: e for e in now["engines"]}
    rows = []
    for name in [n for n in new if n in old]:
        rows += _engine_rows(name, old[name], new[name], rtol)
    return Regression(baseline_path, float(rtol), tuple(rows),
                      tuple(n for n in new if n not in old), tuple(n for n in old if n not in new),
                      tuple(n for n in new if n in old))


def _engine_rows(name, a, b, rtol):
    scale = b["unit_force_N"] * b["cylinders"]
    rows = []

    def number(quantity, x, y, tolerance, order=None):
        if not (_number(x) and _number(y)):
            if x != y:
                rows.append(Moved(name, order, quantity, x, y, None))
            return
        if quantity.endswith("_deg"):
            period = 180.0 if quantity.endswith("axis_deg") else 360.0
            change = abs(_angle_change(x, y, period))
            tolerance = max(tolerance, math.degrees(rtol))
        else:
            change = abs(y - x)
            tolerance = max(tolerance, rtol * abs(x))
        if change > tolerance:
            rows.append(Moved(name, order, quantity, x, y, tolerance))

    def same(quantity, x, y):
        if x != y:
            rows.append(Moved(name, None, quantity, x, y, None))

    for key in ("cylinders", "cycle", "frame"):
        same(key, a.get(key), b.get(key))
    number("speed_rpm", a.get("speed_rpm"), b.get("speed_rpm"), 1e-9 * abs(a.get("speed_rpm") or 0))
    number("unit_force_N", a["unit_force_N"], b["unit_force_N"], RELATIVE * scale)
    for key in ("largest_resultant_N", "counterweighted_resultant_N"):
        number(key, a.get(key), b.get(key), RELATIVE * scale)
    fa, fb = a["firing"], b["firing"]
    same("firing order", fa.get("order"), fb.get("order"))
    if fa.get("order") == fb.get("order"):
        for number_, x, y in zip(fb["order"], fa.get("angles_deg", []), fb.get("angles_deg", [])):
            number(f"firing angle of cylinder {number_} (deg)", x, y, FIRING_DEG)
    same("firing uniform", fa.get("uniform"), fb.get("uniform"))
    same("sampling_ok", a.get("sampling_ok"), b.get("sampling_ok"))
    orders_a = {o["order"]: o for o in a["orders"]}
    orders_b = {o["order"]: o for o in b["orders"]}
    for k in sorted(set(orders_a) | set(orders_b)):
        if k not in orders_a or k not in orders_b:
            rows.append(Moved(name, k, "order", "listed" if k in orders_a else "absent",
                              "listed" if k in orders_b else "absent", None))
            continue
        for part, unit in (("force", "N"), ("moment", "Nm")):
            x, y = orders_a[k][part], orders_b[k][part]
            for key in (f"forward_{unit}", f"backward_{unit}", f"max_{unit}", f"min_{unit}"):
                number(f"{part}.{key}", x.get(key), y.get(key), RELATIVE * scale, k)
            for phase, magnitude in (("forward_deg", f"forward_{unit}"),
                                     ("backward_deg", f"backward_{unit}"), ("axis_deg", f"min_{unit}")):
                size = max(x.get(magnitude, 0.0), y.get(magnitude, 0.0))
                if phase == "axis_deg":
                    # an axis exists where the ellipse is not a circle: max − min above the floor
                    size = min(x.get(f"max_{unit}", 0.0) - x.get(magnitude, 0.0),
                               y.get(f"max_{unit}", 0.0) - y.get(magnitude, 0.0))
                if size >= PHASE_FLOOR * scale:
                    number(f"{part}.{phase}", x.get(phase), y.get(phase), PHASE_DEG, k)
    return rows
