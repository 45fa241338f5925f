"""Marine figures: the engine's power and the power related unbalance (PRU).

The MAN B&W and WinGD project guides judge a large two-stroke engine's external moments by
PRU = external moment / engine power (N·m/kW) at the same speed, and class it by whether a
moment compensator is needed (MAN B&W, "Power Related Unbalance", section 17.04 of the project
guides, Table 17.04.01; WinGD Marine Installation Manuals, section 6.1): 0–60 not relevant,
60–120 unlikely, 120–220 likely, above 220 most likely. The moments are the vertical (pitching,
M1V, M2V) and horizontal (yawing, M1H, M2H) components of balance's exact free moments.

The first order is judged as the guides give it: with their **standard balancing**,
counterweights for the rotating masses and half the reciprocating ones, so that the first-order
moments act vertically and horizontally with the same magnitude (MAN B&W project guides, chapter
17 "External Forces and Moments"; WinGD Marine Installation Manuals, section 6.1.1: "standard
counterweights, fitted to the ends of the crankshaft", and non-standard ones to reduce M1V or
M1H instead). The seven-cylinder S80MC-C7's printed PRU1/PRU2 = 9.3/36.4 fits that balance, not
the rotating masses' alone (docs/VALIDATION.md). The balance factor can be chosen, and two named
alternatives are kept beside it: the rotating masses alone balanced (factor 0: the reciprocating
masses' first order stays, vertical only, twice the standard figure) and the crank as it stands
(no counterweights but those built). Every higher order is as the crank stands: counterweights
turn at crank speed.
"""

import math
from dataclasses import dataclass

from ..checks import positive
from ..errors import AnalysisError, BalanceError
from ..kinematics import FINE_SAMPLES, kinematic_state
from ..tabular import Tabular
from .counterweight import counterweights
from .shaking import Shaking

__all__ = [
    "DEFAULT_PRU_CLASSES",
    "FIRST_ORDER_BALANCES",
    "FirstOrderBalance",
    "first_order_balance",
    "first_order_moments",
    "judged_balance",
    "STANDARD_BALANCE",
    "DEFAULT_PRU_ORDERS",
    "Power",
    "PowerRelatedUnbalance",
    "engine_power",
    "power_related_unbalance",
    "pru_class",
    "check_classes",
]

#: upper bounds (N·m/kW) of the project guides' classes and their words; the last is open
DEFAULT_PRU_CLASSES = (
    (60.0, "not relevant"),
    (120.0, "unlikely"),
    (220.0, "likely"),
    (math.inf, "most likely"),
)
#: the orders the guides give: first and second
DEFAULT_PRU_ORDERS = (1, 2)
_CLASS_WORDS = ("not relevant", "unlikely", "likely", "most likely")
#: the named first-order balances: the fraction of the reciprocating masses the counterweights
#: carry besides the rotating masses, None for the crank as it stands
FIRST_ORDER_BALANCES = {"standard": 0.5, "rotating": 0.0, "crank": None}
_BALANCE_WORDS = {
    "standard": "the project guides' standard balance: counterweights for the rotating masses "
    "and half the reciprocating ones (balance factor 0.5), M1V = M1H",
    "rotating": "counterweights for the rotating masses only (balance factor 0): the "
    "reciprocating masses' first order stays, vertical",
    "crank": "as the crank stands (no counterweights but those built)",
}
#: crank angles a revolution on which a cylinder's stroke is found (its extremes are flat:
#: 3600 points put them within 1e-8 of the exact stroke): every second point of the fine grid
_STROKE_SAMPLES = 3600
_STROKE_STEP = FINE_SAMPLES // _STROKE_SAMPLES


@dataclass(frozen=True)
class Power:
    """An engine's power at the speed it is analysed at.

    ``watts``; ``source``: "given" (the configuration's ``power``), "option" (given with the
    analysis, e.g. ``--power``) or "indicated" (imep · swept volume of every cylinder · cycles
    a second, from the ``[gas]`` table).
    """

    watts: float
    source: str

    @property
    def kilowatts(self) -> float:
        return self.watts / 1e3


@dataclass(frozen=True)
class FirstOrderBalance:
    """How the first-order moments are judged: ``name`` "standard", "rotating", "crank" or
    "factor" (a balance factor of one's own); ``balance_factor`` the fraction (0 to 1) of the
    reciprocating masses the counterweights carry besides the rotating masses, None for the
    crank as it stands."""

    name: str
    balance_factor: float | None

    @property
    def description(self) -> str:
        if self.name == "factor":
            return (
                f"counterweights for the rotating masses and {self.balance_factor:g} of the "
                f"reciprocating ones (balance factor {self.balance_factor:g})"
            )
        return _BALANCE_WORDS[self.name]

    def to_dict(self) -> dict:
        return {
            "name": self.name,
            "balance_factor": self.balance_factor,
            "description": self.description,
        }


#: the guides' standard balance, the default
STANDARD_BALANCE = FirstOrderBalance("standard", 0.5)


def first_order_balance(value="standard") -> FirstOrderBalance:
    """A :class:`FirstOrderBalance` from a name ("standard", "rotating", "crank"), a balance
    factor from 0 to 1 (a number, or its text), or one already made."""
    if isinstance(value, FirstOrderBalance):
        if value.name in FIRST_ORDER_BALANCES and FIRST_ORDER_BALANCES[value.name] == (
            value.balance_factor
        ):
            return value
        if value.name == "factor":
            return first_order_balance(value.balance_factor)
    elif isinstance(value, str) and value.strip().lower() in FIRST_ORDER_BALANCES:
        name = value.strip().lower()
        return FirstOrderBalance(name, FIRST_ORDER_BALANCES[name])
    elif not isinstance(value, bool):
        try:
            factor = float(value) if isinstance(value, (int, float, str)) else math.nan
        except ValueError:
            factor = math.nan
        if 0.0 <= factor <= 1.0:
            factor += 0.0  # not -0
            named = next((n for n, f in FIRST_ORDER_BALANCES.items() if f == factor), None)
            # a factor of a named balance is that balance, so one figure has one name
            return FirstOrderBalance(named or "factor", factor)
    raise AnalysisError(
        f"must be standard (the project guides': balance factor 0.5), rotating (0), crank (as "
        f"the crank stands) or a balance factor from 0 to 1, got {value!r}",
        "first_order_balance",
    )


def first_order_moments(result, balance=STANDARD_BALANCE) -> dict | None:
    """The first-order moment of an analysed engine under a first-order balance: its JSON
    record (``vertical_Nm``, ``horizontal_Nm``, forward and backward parts, ...) after the
    counterweights ``balance`` calls for; None where counterweights are not proposed (a
    rotary, whose crank does not turn; several crankshafts) unless it is "crank"."""
    balance = first_order_balance(balance)
    engine = result.engine
    if balance.balance_factor is None:
        return dict(result.order_records()[0]["moment"])
    if engine.is_rotary or engine.has_several_crankshafts:
        return None
    built = counterweights(result, balance_factor=balance.balance_factor)
    return dict(built.residual.records(engine)[0]["moment"])


def check_classes(bounds):
    """The PRU classes for the bounds (N·m/kW) between "not relevant", "unlikely", "likely"
    and "most likely": three increasing positive numbers."""
    try:
        values = [float(b) for b in bounds]
    except (TypeError, ValueError):
        raise AnalysisError(
            f"must be three numbers of N·m/kW, got {bounds!r}", "pru_classes"
        ) from None
    if (
        len(values) != 3
        or not all(math.isfinite(v) and v > 0 for v in values)
        or not values[0] < values[1] < values[2]
    ):
        raise AnalysisError(
            f"must be three increasing positive numbers of N·m/kW (the bounds "
            f"of {', '.join(_CLASS_WORDS)}), got {bounds!r}",
            "pru_classes",
        )
    return tuple(zip(values + [math.inf], _CLASS_WORDS, strict=True))


def _check_class_table(classes):
    """A table of (bound, word) as :func:`check_classes` makes, the last bound infinite."""
    try:
        bounds = [bound for bound, _ in classes]
        if (
            len(bounds) == 4
            and math.isinf(bounds[-1])
            and all(isinstance(word, str) for _, word in classes)
        ):
            check_classes(bounds[:-1])
            return
    except (TypeError, ValueError, BalanceError):
        pass
    raise AnalysisError(
        "must be (bound, class) pairs as check_classes((60, 120, 220)) "
        f"makes them, got {classes!r}",
        "classes",
    )


def pru_class(value, classes=DEFAULT_PRU_CLASSES):
    """The class of a PRU value (N·m/kW): the words of the first bound it stays below."""
    return next(word for bound, word in classes if value < bound)


def engine_power(engine, power_w=None):
    """The :class:`Power` of ``engine`` at its speed, or (None, why not).

    ``power_w`` (W, at the engine's speed) wins; then the configuration's ``power`` when it is
    given at the speed the engine is analysed at; then the indicated power of a ``[gas]`` cycle
    with an imep: imep · Σ swept volumes · ω/(2π) · 2/cycle, exact by the cycle's own
    definition (its heat release is scaled so that ∮p dV = imep · swept volume).
    """
    if power_w is not None:
        return Power(positive(power_w, "power_w", "power"), "option"), None
    if engine.power_at_speed_w is not None:
        return Power(engine.power_at_speed_w, "given"), None
    gas = engine.gas
    if gas is not None and gas.imep_pa is not None:
        travel = kinematic_state(engine, FINE_SAMPLES).travel
        swept = sum(
            gas.piston_area_m2 * (t[::_STROKE_STEP].max() - t[::_STROKE_STEP].min())
            for t in travel.values()
        )
        cycles_per_s = engine.speed_rad_s / (2 * math.pi) * 2 / engine.cycle
        return Power(gas.imep_pa * swept * cycles_per_s, "indicated"), None
    if engine.power_w is not None:
        return None, (
            f"the power is given at {engine.power_speed_rad_s * 30 / math.pi:g} rpm, "
            f"not at the {engine.speed_rad_s * 30 / math.pi:g} rpm analysed; give the "
            "power at this speed"
        )
    return (
        None,
        "no power: give `power` in the configuration, a [gas] table with an imep, or the power "
        "with the analysis",
    )


@dataclass(frozen=True)
class PowerRelatedUnbalance(Tabular):
    """The PRU of an analysed engine, or why it has none.

    Attributes
    ----------
    power : Power or None
        None when the engine has no power at the speed analysed (then ``note`` says why, and
        ``orders`` is empty)
    orders : tuple of dict
        per order k: ``order``, ``vertical_Nm`` and ``horizontal_Nm`` (M_kV, M_kH: the
        amplitudes of the pitching and yawing moments), ``vertical_Nm_per_kW`` and
        ``horizontal_Nm_per_kW`` (their PRU) and ``vertical_class``, ``horizontal_class``;
        the first order under ``balance``, the others as the crank stands
    balance : FirstOrderBalance
        the first-order balance the first order is judged under (default the project
        guides' standard balance; "crank" on a rotary or an engine with several crankshafts,
        whose counterweights are not proposed)
    first_order : dict or None
        the first order under each named balance ("standard", "rotating", "crank"): an entry
        as in ``orders``, None where counterweights are not proposed; None when the first
        order is not judged
    classes : tuple of (bound, word)
    note : str or None
        why there is no PRU (no power), else None
    """

    power: Power | None
    orders: tuple = ()
    balance: FirstOrderBalance = STANDARD_BALANCE
    first_order: dict | None = None
    classes: tuple = DEFAULT_PRU_CLASSES
    note: str | None = None

    @property
    def available(self) -> bool:
        """Whether the engine has a power, and so a PRU."""
        return self.power is not None

    def records(self) -> list:
        """One row per order judged, none without a power: ``order``, ``vertical_Nm`` and
        ``horizontal_Nm`` (M_kV, M_kH), ``vertical_Nm_per_kW`` and ``horizontal_Nm_per_kW``
        (their PRU), ``vertical_class``, ``horizontal_class``, ``balance`` (the first order's
        ``balance`` by name, "crank" for the other orders: as the crank stands) and
        ``power_kW``."""
        if self.power is None:
            return []
        return [
            {
                **entry,
                "balance": self.balance.name if entry["order"] == 1 else "crank",
                "power_kW": self.power.kilowatts,
            }
            for entry in self.orders
        ]

    def to_dict(self) -> dict:
        """``pru`` of ``compare --format json`` (see the JSON page); without a power, only
        ``note``."""
        if self.power is None:
            return {"note": self.note}
        return {
            "power_kW": self.power.kilowatts,
            "power_source": self.power.source,
            "classes": [
                {"below_Nm_per_kW": None if math.isinf(b) else b, "class": w}
                for b, w in self.classes
            ],
            "orders": list(self.orders),
            "first_order_balance": self.balance.to_dict(),
            "first_order": self.first_order,
        }


def _entry(order, moment, kilowatts, classes):
    v, h = moment["vertical_Nm"], moment["horizontal_Nm"]
    return {
        "order": order,
        "vertical_Nm": v,
        "horizontal_Nm": h,
        "vertical_Nm_per_kW": v / kilowatts,
        "horizontal_Nm_per_kW": h / kilowatts,
        "vertical_class": pru_class(v / kilowatts, classes),
        "horizontal_class": pru_class(h / kilowatts, classes),
    }


def judged_balance(engine, balance=STANDARD_BALANCE) -> FirstOrderBalance:
    """The balance the first order is judged under: ``balance``, or the crank as it stands
    where counterweights are not proposed (a rotary, several crankshafts)."""
    balance = first_order_balance(balance)
    if balance.balance_factor is not None and (engine.is_rotary or engine.has_several_crankshafts):
        return FirstOrderBalance("crank", None)
    return balance


def power_related_unbalance(
    result,
    power_w=None,
    orders=DEFAULT_PRU_ORDERS,
    classes=DEFAULT_PRU_CLASSES,
    balance=STANDARD_BALANCE,
):
    """The :class:`PowerRelatedUnbalance` of an analysed engine
    (:class:`~balance_cli.EngineResult`); without a power, one that says why
    (``available`` False, ``note``).

    Parameters
    ----------
    power_w : float, optional
        the power at the speed analysed, W (default: the configuration's, or the [gas]
        cycle's indicated power)
    orders : sequence of int
        the orders whose moments are judged (default 1 and 2), each within the analysis
    classes : tuple of (bound, word)
        :data:`DEFAULT_PRU_CLASSES` or :func:`check_classes` of other bounds
    balance : str, float or FirstOrderBalance
        the first order's balance (:func:`first_order_balance`): "standard" (default, the
        project guides'), "rotating", "crank" or a balance factor from 0 to 1
    """
    if not isinstance(getattr(result, "shaking", None), Shaking):
        raise AnalysisError(
            f"must be an analysed engine (balance.analyse(engine) gives one), got "
            f"{type(result).__name__}",
            "result",
        )
    if classes is not DEFAULT_PRU_CLASSES:
        _check_class_table(classes)
    balance = judged_balance(result.engine, balance)
    if (
        isinstance(orders, (str, bytes))
        or not isinstance(orders, (list, tuple, range))
        or not orders
        or not all(
            isinstance(k, int) and not isinstance(k, bool) and 1 <= k <= result.max_order
            for k in orders
        )
    ):
        raise AnalysisError(
            f"must be a list of orders from 1 to {result.max_order}, got {orders!r}", "orders"
        )
    power, why = engine_power(result.engine, power_w)
    if power is None:
        return PowerRelatedUnbalance(None, classes=classes, note=why, balance=balance)
    kilowatts = power.kilowatts
    records = result.order_records()
    alternatives = None
    if 1 in orders:
        alternatives = {}
        for name in FIRST_ORDER_BALANCES:
            moment = first_order_moments(result, name)
            alternatives[name] = None if moment is None else _entry(1, moment, kilowatts, classes)
    entries = []
    for k in orders:
        if k == 1:
            named = alternatives.get(balance.name) if alternatives else None
            moment = first_order_moments(result, balance)
            entries.append(named or _entry(1, moment, kilowatts, classes))
        else:
            entries.append(_entry(k, records[k - 1]["moment"], kilowatts, classes))
    return PowerRelatedUnbalance(power, tuple(entries), balance, alternatives, classes)
