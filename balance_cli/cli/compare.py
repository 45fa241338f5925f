"""balance compare: engines side by side, order by order, and the JSON document that
balance regress reads back.
"""

import click

from ..analysis.results import compare as comparison_of
from ..report.compare import compare_tables
from ..report.csvfile import compare_csv
from ..units import Scale, rad_s_to_rpm
from .batch import analyse_all, inputs, load_all, settings
from .dispatch import emit, guard
from .group import main, reported
from .options import (
    ABSOLUTE,
    FIRST_ORDER_BALANCE,
    FORMAT,
    INPUTS,
    MAX_ORDER,
    OUTPUT,
    SAMPLES,
    SPEED,
    UNITS,
    numbers_option,
    orders_option,
    quantity_option,
)

__all__ = ["compare", "compare_document"]


@main.command()
@INPUTS
@SAMPLES
@MAX_ORDER
@ABSOLUTE
@UNITS
@SPEED
@click.option(
    "--reference",
    default=None,
    metavar="NAME",
    help="Engine the percentages refer to (name or unique prefix); default the first.",
)
@click.option(
    "--power",
    default=None,
    metavar="POWER",
    help="The engines' power at the speed analysed (e.g. '14 280 kW', '21 MW', "
    "'19 000 hp'; hp mechanical, PS metric), for the power related unbalance; default "
    "each file's power (or its [gas] cycle's indicated power).",
)
@click.option(
    "--pru-classes",
    default=None,
    metavar="A,B,C",
    help="Bounds of the PRU classes not relevant / unlikely / likely / most likely, "
    "N·m/kW  [default: 60,120,220, the project guides'].",
)
@click.option(
    "--pru-orders",
    default=None,
    metavar="K[,K...]",
    help="Orders whose moments the power related unbalance judges  [default: 1,2].",
)
@FIRST_ORDER_BALANCE
@FORMAT
@OUTPUT
def compare(
    paths,
    samples,
    max_order,
    absolute,
    units,
    speed,
    reference,
    power,
    pru_classes,
    pru_orders,
    first_order_balance,
    fmt,
    output,
):
    """Compare engines order by order, in the style of Tanaka's Part III.

    FILE|DIR...: configuration files, or folders searched recursively for .toml files,
    compared in the order given (files of a folder sorted by path).
    """
    files = inputs(paths)
    guard([output], files)
    settings(samples, max_order)
    classes = None if pru_classes is None else numbers_option(pru_classes, "--pru-classes")
    orders = None if pru_orders is None else orders_option(pru_orders, "--pru-orders")
    power_w = quantity_option(power, "--power", "power")
    engines = load_all(files, speed)
    results = analyse_all(engines, samples, max_order)
    flags = {
        "pru_classes": "--pru-classes",
        "pru_orders": "--pru-orders",
        "first_order_balance": "--first-order-balance",
        "power_w": "--power",
    }
    with reported(flags=flags):
        comparison = comparison_of(
            results, reference, classes, orders, first_order_balance, power_w=power_w
        )
    scale = Scale.of(absolute, units)
    emit(
        output,
        fmt,
        json=lambda: compare_document(comparison, engines if speed else None),
        csv=lambda: compare_csv(comparison, scale),
        table=lambda: compare_tables(comparison, scale, fmt),
    )


def compare_document(comparison, overridden=None):
    """compare's JSON; with the engines of a --speed run, the speed it imposed, so that
    balance regress analyses them again at that speed."""
    document = comparison.to_dict()
    if overridden:
        document["speed_override_rpm"] = rad_s_to_rpm(overridden[0].speed_rad_s)
    return document
