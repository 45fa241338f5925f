"""Reading the command line: the options several commands share, the custom parameter type
of --units, and the parsers of option values (lengths, quantities, orders, planes, speeds,
cylinder counts, firing orders) that turn a text into the library's SI values or one clean
error naming the flag.
"""

import math

import click
import numpy as np

from ..analysis.balancing import Plane
from ..analysis.shaking import DEFAULT_MAX_ORDER, DEFAULT_SAMPLES, MAX_SAMPLES
from ..errors import BalanceError
from ..units import UNIT_SYSTEMS, parse_quantity, unit_system

__all__ = [
    "INPUTS",
    "SAMPLES",
    "MAX_ORDER",
    "FORMAT",
    "OUTPUT",
    "ABSOLUTE",
    "Units",
    "UNIT_CHOICE",
    "UNITS",
    "SPEED",
    "LOAD",
    "planes",
    "orders_option",
    "numbers_option",
    "shaft_offsets_option",
    "length_option",
    "quantity_option",
    "speeds_option",
    "counts_option",
    "firing_orders_option",
]


INPUTS = click.argument("paths", nargs=-1, required=True, metavar="FILE|DIR...")
SAMPLES = click.option(
    "--samples",
    default=DEFAULT_SAMPLES,
    show_default=True,
    type=int,
    help=f"Crank angles per revolution for the Fourier analysis: any number "
    f"from 4 × --max-order + 1 to {MAX_SAMPLES}.",
)
MAX_ORDER = click.option(
    "--max-order",
    default=DEFAULT_MAX_ORDER,
    show_default=True,
    type=int,
    help="Highest order analysed and reported.",
)
FORMAT = click.option(
    "--format",
    "fmt",
    type=click.Choice(["table", "markdown", "csv", "json"]),
    default="table",
    show_default=True,
    help="Output format.",
)
OUTPUT = click.option(
    "--output",
    "-o",
    default="-",
    metavar="FILE",
    show_default=True,
    help="Write here (atomically) instead of standard output.",
)
ABSOLUTE = click.option(
    "--absolute",
    is_flag=True,
    help="Forces in newtons (or --units) instead of per cylinder (× m_rec·r·ω²·n).",
)


class Units(click.ParamType):
    """--units: a system of units in any letter case that has one reading (kn is kN; mn, milli-
    or meganewtons, is refused naming both), and the ``extra`` words a command allows."""

    def __init__(self, extra=()):
        self.extra = tuple(extra)
        self.name = "|".join(self.extra + tuple(UNIT_SYSTEMS))

    def get_metavar(self, param, *args, **kwargs):
        return "[" + self.name + "]"

    def convert(self, value, param, ctx):
        for word in self.extra:
            if isinstance(value, str) and value.strip().lower() == word:
                return word
        try:
            return unit_system(value)
        except BalanceError as exc:
            self.fail(exc.problem, param, ctx)


UNIT_CHOICE = Units()
UNITS = click.option(
    "--units",
    type=UNIT_CHOICE,
    default=None,
    help="Units of forces and moments, one system: N and N·m, kN and kN·m, MN and MN·m, "
    "kgf and kgf·m, lbf and lbf·ft. Given (N too), it shows forces in it instead of "
    "per cylinder  [default: forces per cylinder, moments in N·m]. JSON stays SI.",
)
SPEED = click.option(
    "--speed",
    "speed",
    default=None,
    metavar="SPEED",
    help="Analyse at this speed instead of the files' (e.g. '3000 rpm').",
)


FIRST_ORDER_BALANCE = click.option(
    "--first-order-balance",
    "first_order_balance",
    default="standard",
    show_default=True,
    metavar="standard|rotating|crank|FACTOR",
    help="The balance the first-order moments (M1V, M1H and their PRU) are given under: "
    "standard, the project guides' (counterweights for the rotating masses and half the "
    "reciprocating ones: M1V = M1H); rotating (the rotating masses only: M1V twice as "
    "large, M1H 0); crank (as the crank stands); or a balance factor from 0 to 1 (the "
    "fraction of the reciprocating masses the counterweights carry).",
)


LOAD = click.option(
    "--load",
    type=click.Choice(["propeller", "constant"]),
    default="propeller",
    show_default=True,
    help="What the engine drives: a propeller (torque ℓ·ω², ℓ = C_m/ω_m²) or a "
    "constant torque C_m.",
)


def planes(text):
    """--planes: throw numbers ("1,6") or axial positions ("0 mm,750 mm"), one or two."""
    if text is None:
        return None
    chosen: list[int | Plane] = []
    for token in (t.strip() for t in text.split(",")):
        if token.isascii() and token.isdigit():
            chosen.append(int(token))
            continue
        try:
            chosen.append(Plane(parse_quantity(token, "length")))
        except BalanceError as exc:
            if str(exc).startswith("cannot read"):
                raise click.ClickException(
                    f"--planes: cannot read {token!r}: give throw numbers (1, 2, ...) or axial "
                    "positions with a unit such as '120 mm'"
                ) from None
            raise click.ClickException(f"--planes: {exc}") from None
    return chosen


def orders_option(text, flag="--shafts"):
    if text is None:
        return ()
    try:
        return tuple(int(t) for t in text.split(","))
    except ValueError:
        raise click.BadParameter(
            f"{text!r}: give orders as whole numbers, such as 1,2", param_hint=flag
        ) from None


def numbers_option(text, flag):
    try:
        return tuple(float(t.replace(" ", "")) for t in text.split(","))
    except ValueError:
        raise click.BadParameter(
            f"{text!r}: give numbers such as 60,120,220", param_hint=flag
        ) from None


def shaft_offsets_option(texts):
    """``--shaft-offset [RATIO:]LATERAL,VERTICAL`` (repeatable) as the library's mapping:
    without RATIO the offset of every shaft not named."""
    offsets = {}
    for text in texts:
        ratio, _, lengths = text.rpartition(":")
        key = None
        if ratio.strip():
            try:
                key = int(ratio)
            except ValueError:
                raise click.BadParameter(
                    f"{text!r}: the speed ratio before ':' must be a whole number such as +2 or -2",
                    param_hint="--shaft-offset",
                ) from None
        parts = lengths.split(",")
        if len(parts) != 2:
            raise click.BadParameter(
                f"{text!r}: give LATERAL,VERTICAL such as '120 mm,-80 mm', "
                "optionally after a speed ratio ('-2:120 mm,-80 mm')",
                param_hint="--shaft-offset",
            )
        if key in offsets:
            which = "every shaft" if key is None else f"speed ratio {key:+d}"
            raise click.BadParameter(f"{which} is placed twice", param_hint="--shaft-offset")
        offsets[key] = tuple(length_option(p.strip(), "--shaft-offset") for p in parts)
    return offsets or None


def length_option(text, flag):
    if text is None:
        return None
    try:
        return parse_quantity(text, "length")
    except BalanceError as exc:
        raise click.ClickException(f"{flag}: {exc}") from None


def quantity_option(text, flag, dimension):
    if text is None:
        return None
    try:
        value = parse_quantity(text, dimension)
    except BalanceError as exc:
        raise click.ClickException(f"{flag}: {exc}") from None
    if not value > 0:
        raise click.ClickException(f"{flag}: must be greater than zero, got {text!r}")
    return value


def speeds_option(text, flag="--speeds"):
    """--speeds FROM:TO:STEP (rpm, both ends included) or a comma-separated list; None for
    the default (20 % to 120 % of each engine's speed)."""
    if text is None:
        return None
    from ..torsion import MAX_SPEEDS

    try:
        if ":" in text:
            start, stop, step = (float(t) for t in text.split(":"))
            if (
                not all(map(math.isfinite, (start, stop, step)))
                or not step > 0
                or not 0 < start <= stop
                or not 1e-3 <= start
                and stop <= 1e6
            ):
                raise ValueError
            count = int(np.floor((stop - start) / step + 1e-9)) + 1
            if count > MAX_SPEEDS:
                raise ValueError
            return start + step * np.arange(count)
        values = np.array([float(t) for t in text.split(",")])
        if (
            not np.all(np.isfinite(values))
            or np.any(values < 1e-3)
            or np.any(values > 1e6)
            or values.size > MAX_SPEEDS
        ):
            raise ValueError
        return values
    except (ValueError, OverflowError):
        raise click.BadParameter(
            f"expected FROM:TO:STEP in rpm (0.001 <= FROM <= TO <= 1e6, "
            f"STEP > 0, at most {MAX_SPEEDS} speeds) such as 600:2400:25, or "
            f"a list such as 1000,1500, got {text!r}",
            param_hint=flag,
        ) from None


def counts_option(text):
    """--cylinders: "5-12", "6,7,8" or both."""
    counts: list[int] = []
    try:
        for token in text.split(","):
            low, dash, high = token.strip().partition("-")
            if dash and not (low.strip() and high.strip()):
                raise click.BadParameter(
                    f"{token.strip()!r} leaves a range open: give both ends, such as 5-14",
                    param_hint="--cylinders",
                )
            low, high = int(low), int(high or low)
            if high < low:
                raise click.BadParameter(
                    f"{token.strip()!r} runs backwards: write the smaller "
                    f"number first ({high}-{low})",
                    param_hint="--cylinders",
                )
            counts += range(low, high + 1)
    except ValueError:
        raise click.BadParameter(
            f"{text!r}: give numbers of cylinders such as 5-12 or 6,7,8", param_hint="--cylinders"
        ) from None
    return counts


def firing_orders_option(values):
    """--firing-order N:1-5-3-4-2-6, repeatable."""
    orders = {}
    for value in values:
        count, _, order = value.partition(":")
        try:
            n = int(count)
            cylinders = [int(c) for c in order.replace(",", "-").split("-")]
        except ValueError:
            raise click.BadParameter(
                f"{value!r}: write the number of cylinders and the order, such as 6:1-5-3-4-2-6",
                param_hint="--firing-order",
            ) from None
        if n in orders:
            raise click.BadParameter(
                f"{n} cylinders are given twice; give one firing order for "
                "each number of cylinders",
                param_hint="--firing-order",
            )
        orders[n] = cylinders
    return orders
