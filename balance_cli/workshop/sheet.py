"""balance bobweight: the balancing sheet. Per crank pin, the bobweight a balancing machine
needs to spin the crankshaft as the engine loads it: the rotating parts on the pin plus a
balance factor times the reciprocating parts, from the configuration's masses or from weighed
parts; and, for a single or a twin, what each balance factor leaves, so a builder picks one.

**The factor.** Chosen (``balance_factor``), or the one ``balance counterweight`` implies:
its counterweights cancel the forward first order, and the mass that does that on each pin
(its test mass, Nakanishi § 4) is, for a plain rod, the whole rotating mass and half the
reciprocating one: the reciprocating mass's first-order force is a line force, half of which
turns with the crank. That factor is reported as what the test mass makes of the pin's
masses (exactly ½ on plain rods; link rods and pin offsets move it a little). The race shops'
rule for a V8 (two rods a pin: 100 % rotating plus 50 % reciprocating) is that factor.

**The trade** of a single or a twin: with counterweights for the rotating masses plus F times
the reciprocating ones (``balance counterweight --balance-factor F``), the first-order force
left is (1 − F)·m·r·ω² along the cylinder axis and F·m·r·ω² across it for a single: a builder
trades vertical shaking for horizontal (the Triumph 650 twin used 85 %).
"""

from dataclasses import dataclass

from .. import checks
from ..analysis.counterweight import check_options, counterweights
from ..analysis.shaking import DEFAULT_MAX_ORDER, DEFAULT_SAMPLES, check_settings, directional
from ..errors import AnalysisError
from ..model import Engine
from ..output import DOCUMENT_VERSION
from ..tabular import Tabular
from .assembly import Fit, assembled, check_fits
from .parts import as_parts

__all__ = ["bobweights", "BobweightSheet", "Bobweight", "Trade", "DEFAULT_FACTORS"]

#: the balance factors of a single's or twin's trade
DEFAULT_FACTORS = (0.5, 0.55, 0.6, 0.65, 0.7, 0.75, 0.8, 0.85)
#: the most cylinders whose trade is tabled: a single and a twin
_TRADE_CYLINDERS = 2


@dataclass(frozen=True)
class Bobweight:
    """One crank pin's bobweight: its throw (from 1), the cylinders on it, the rotating mass
    on it (big ends, and link rods' knuckle shares), kg, the reciprocating mass of its
    cylinders, kg, the factor, and the bobweight = rotating + factor × reciprocating, kg."""

    throw: int
    cylinders: tuple
    rotating_kg: float
    reciprocating_kg: float
    factor: float
    bobweight_kg: float

    def to_dict(self) -> dict:
        return {
            "throw": self.throw,
            "cylinders": list(self.cylinders),
            "rotating_kg": self.rotating_kg,
            "reciprocating_kg": self.reciprocating_kg,
            "factor": self.factor,
            "bobweight_kg": self.bobweight_kg,
        }


@dataclass(frozen=True)
class Trade:
    """What counterweights sized at balance factor ``factor`` leave of a single or twin: the
    first-order force's vertical and horizontal amplitudes (N), the first-order moment's
    (N·m), and the largest resultant force over a revolution, all orders (N)."""

    factor: float
    force_vertical_n: float
    force_horizontal_n: float
    moment_vertical_nm: float
    moment_horizontal_nm: float
    largest_force_n: float

    def to_dict(self) -> dict:
        return {
            "factor": self.factor,
            "force_vertical_N": self.force_vertical_n,
            "force_horizontal_N": self.force_horizontal_n,
            "moment_vertical_Nm": self.moment_vertical_nm,
            "moment_horizontal_Nm": self.moment_horizontal_nm,
            "largest_force_N": self.largest_force_n,
        }


@dataclass(frozen=True)
class BobweightSheet(Tabular):
    """The balancing sheet of one engine.

    Attributes
    ----------
    engine : Engine
        as balanced: with the weighed parts fitted in the order given, if any
    parts : str
        the parts file the masses come from ("" for the configuration's own)
    chosen_factor : float or None
        the balance factor asked for; None: ``counterweight``'s (see the module)
    pins : tuple of Bobweight
    trade : tuple of Trade
        a single's or twin's residual at each factor (empty for more cylinders)
    """

    engine: Engine
    parts: str
    chosen_factor: float | None
    pins: tuple
    trade: tuple

    def records(self) -> list:
        """One row per crank pin: ``throw``, ``cylinders`` (as text "1 2"), ``rotating_kg``,
        ``reciprocating_kg``, ``factor``, ``bobweight_kg``."""
        return [{**p.to_dict(), "cylinders": " ".join(map(str, p.cylinders))} for p in self.pins]

    def to_dict(self) -> dict:
        """What ``balance bobweight --format json`` writes."""
        return {
            "balance_version": DOCUMENT_VERSION,
            "engine": self.engine.name,
            "config": self.engine.config_path,
            "parts": self.parts,
            "balance_factor": self.chosen_factor,
            "pins": [p.to_dict() for p in self.pins],
            "trade": [t.to_dict() for t in self.trade],
        }


def _pin_masses(engine, index):
    """The rotating and reciprocating masses on the pin of the throw at ``index``, kg."""
    on_pin = [c for c in engine.cylinders if c.throw_index == index]
    rotating = engine.rotating_of(index) + sum(c.knuckle_kg for c in on_pin if c.is_link)
    reciprocating = sum(c.reciprocating_kg for c in on_pin) + sum(
        c.opposed_reciprocating_kg for c in engine.cylinders if c.opposed_throw_index == index
    )
    numbers = tuple(c.number for c in on_pin) + tuple(
        c.number for c in engine.cylinders if c.opposed_throw_index == index
    )
    return numbers, rotating, reciprocating


def _trade(engine, factors, samples, max_order):
    rows = []
    for factor in factors:
        residual = counterweights(
            engine, balance_factor=factor, samples=samples, max_order=max_order
        ).residual
        first = residual.order(1)
        fv, fh = directional(first.force_forward, first.force_backward, engine.vertical_axis_rad)
        mv, mh = directional(first.moment_forward, first.moment_backward, engine.vertical_axis_rad)
        rows.append(
            Trade(factor, abs(fv), abs(fh), abs(mv), abs(mh), float(residual.largest_force()))
        )
    return tuple(rows)


def bobweights(
    engine: Engine,
    parts=None,
    balance_factor: float | None = None,
    factors=DEFAULT_FACTORS,
    samples: int = DEFAULT_SAMPLES,
    max_order: int = DEFAULT_MAX_ORDER,
) -> BobweightSheet:
    """The balancing sheet of ``engine``: per crank pin, the bobweight; for a single or a twin,
    the trade between vertical and horizontal shaking over ``factors``.

    Parameters
    ----------
    engine : Engine
    parts : PartSet or path, optional
        weighed pistons and rods, fitted in the order given (the first in the cylinder of the
        lowest number): the engine as assembled (see :mod:`balance_cli.workshop.assembly`);
        fit them as :func:`balance_cli.match` finds best with ``balance match --write`` first
    balance_factor : float, optional
        the fraction (0 to 1) of the reciprocating masses a bobweight carries; default the one
        ``balance counterweight`` implies (½ on plain rods)
    factors : sequence of float
        the balance factors of a single's or twin's trade (each 0 to 1)
    samples, max_order : int
        as for :func:`~balance_cli.analyse`

    Raises
    ------
    AnalysisError or CounterweightError
        naming the parameter: a rotary (its crank stands still), an engine with several
        crankshafts, a factor outside 0 to 1, parts that do not fit
    """
    checks.instance(engine, Engine, "engine", hint=" (balance.load gives one)")
    check_settings(samples, max_order)
    check_options(balance_factor=balance_factor)
    if isinstance(factors, (str, bytes)) or not hasattr(factors, "__iter__"):
        raise AnalysisError(f"must be a list of balance factors, got {factors!r}", "factors")
    factors = tuple(factors)
    if not factors:
        raise AnalysisError("needs one balance factor at least", "factors")
    for factor in factors:
        check_options(balance_factor=factor)
    if engine.is_rotary or engine.has_several_crankshafts:
        raise AnalysisError(
            f"{engine.name!r} "
            + (
                "is a rotary: its crank stands still"
                if engine.is_rotary
                else "has several crankshafts"
            )
            + "; a balancing machine spins one crankshaft that turns",
            "engine",
        )
    source = ""
    if parts is not None:
        parts = as_parts(parts)
        check_fits(engine, parts)
        listed = tuple(sorted(range(engine.n_cylinders), key=lambda i: engine.cylinders[i].number))
        order = tuple(listed.index(i) for i in range(engine.n_cylinders))
        fit = Fit(order if parts.pistons else None, order if parts.rods else None)
        engine = assembled(engine, parts, fit, engine.name)
        source = parts.source
    tests = None
    if balance_factor is None:
        tests = counterweights(
            engine, test_masses=True, samples=samples, max_order=max_order
        ).test_masses_kg
    pins = []
    for index in range(len(engine.throws)):
        numbers, rotating, reciprocating = _pin_masses(engine, index)
        if tests is None:
            assert balance_factor is not None
            factor = float(balance_factor)
            weight = rotating + factor * reciprocating
        else:
            weight = tests[index]
            factor = (weight - rotating) / reciprocating if reciprocating else 0.0
        pins.append(Bobweight(index + 1, numbers, rotating, reciprocating, factor, weight))
    trade = ()
    if engine.n_cylinders <= _TRADE_CYLINDERS:
        trade = _trade(engine, factors, samples, max_order)
    return BobweightSheet(engine, source, balance_factor, tuple(pins), trade)
