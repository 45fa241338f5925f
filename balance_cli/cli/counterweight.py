"""balance counterweight: the counterweights, balancer shafts and antivibrateur that cancel
what can be cancelled, what they leave, and the configuration with them added (--write).
"""

import click

from ..analysis.balancing import Balances
from ..analysis.counterweight import check_options, counterweights
from ..config import WRITE_DIGITS, as_built_toml, read_configuration
from ..report.counterweight import balance_tables
from ..report.csvfile import balance_csv
from ..units import Scale
from . import options
from .batch import inputs, load_all, passed_over, run_each, settings
from .dispatch import guard, render, write
from .group import main, reported
from .options import (
    ABSOLUTE,
    FORMAT,
    INPUTS,
    MAX_ORDER,
    OUTPUT,
    SAMPLES,
    SPEED,
    UNITS,
    length_option,
    orders_option,
    shaft_offsets_option,
)

__all__ = ["counterweight"]


@main.command()
@INPUTS
@click.option(
    "--planes",
    metavar="A[,B]",
    help="Correction planes: throw numbers (1,6) or axial positions ('0 mm,750 mm'); one "
    "plane cancels the force only. Default: the first and last throws.",
)
@click.option(
    "--radius",
    metavar="LENGTH",
    help="Radius of the counterweights' centre of mass, e.g. '60 mm'. Default: the crank radius.",
)
@click.option(
    "--balance-factor",
    type=float,
    metavar="F",
    help="Size for the rotating masses plus F (0 to 1) times the reciprocating ones per "
    "throw (0.5 is the classic single's), instead of cancelling the forward first order.",
)
@click.option(
    "--shafts",
    metavar="K[,K...]",
    help="Cancel these residual orders with balancer shafts (k× speed, with or against the crank).",
)
@click.option(
    "--shaft-offset",
    "shaft_offsets",
    multiple=True,
    metavar="[RATIO:]LATERAL,VERTICAL",
    help="Put the shafts' axes off the crank axis, e.g. '120 mm,-80 mm' (lateral along the "
    "engine's horizontal, vertical along its vertical); '-2:…' places only the shaft "
    "of speed ratio −2. Repeatable. Reports the rolling moment the offsets leave.",
)
@click.option(
    "--antivibrateur",
    "antivibrateur",
    is_flag=True,
    help="Add Fraeys de Veubeke's rotor on the crank pin (twice crank speed), sized to "
    "cancel the forward second order (single-throw engines with a turning crank).",
)
@click.option(
    "--antivibrateur-radius",
    default="40 mm",
    show_default=True,
    metavar="LENGTH",
    help="Eccentricity of the antivibrateur's mass (with --antivibrateur).",
)
@click.option(
    "--test-masses",
    is_flag=True,
    help="Also give the balancing-machine mass to hang on each crank pin (not for a rotary).",
)
@click.option(
    "--write",
    "write_path",
    default=None,
    metavar="FILE.toml",
    help="Write the engine's configuration (one input file) with the proposed "
    "counterweights added as [[counterweights]] and, with --shafts, the proposed "
    "shafts as [[shafts]], named 'NAME, balanced' and to 12 significant digits: loading "
    "it gives the residual reported here. Atomic.",
)
@SAMPLES
@MAX_ORDER
@ABSOLUTE
@UNITS
@SPEED
@FORMAT
@OUTPUT
def counterweight(
    paths,
    planes,
    radius,
    balance_factor,
    shafts,
    shaft_offsets,
    antivibrateur,
    antivibrateur_radius,
    test_masses,
    write_path,
    samples,
    max_order,
    absolute,
    units,
    speed,
    fmt,
    output,
):
    """Counterweights that cancel the forward first order, and what is left.

    Two planes cancel the forward first-order force and moment; one plane the force only.
    Optionally: balancer shafts for residual orders (placed off the crank axis with
    --shaft-offset), the antivibrateur of radial engines, and the balancing-machine test masses.

    An engine whose configuration has counterweights ([[counterweights]]) or balancer shafts
    ([[shafts]]) as built is balanced as built: the report first gives what they leave, order
    by order, and every counterweight or shaft proposed is an ADDITION to them (the built ones
    stay). --write puts the additions into a copy of the configuration, after the built ones.
    """
    files = inputs(paths)
    if write_path is not None:
        if len(files) != 1:
            raise click.BadParameter(
                f"writes one configuration, but {len(files)} files were given; give one file",
                param_hint="--write",
            )
        if antivibrateur:
            raise click.BadParameter(
                "cannot describe the antivibrateur in a configuration, and "
                "the counterweights proposed with it include its mass; leave "
                "out --antivibrateur",
                param_hint="--write",
            )
        if write_path == "-" or write_path == output:
            raise click.BadParameter(
                "needs a file of its own (not standard output, not --output)", param_hint="--write"
            )
    guard([output] + ([write_path] if write_path else []), files)
    settings(samples, max_order)
    plane_specs = options.planes(planes)
    orders = orders_option(shafts)
    radius_m = length_option(radius, "--radius")
    rotor = length_option(antivibrateur_radius, "--antivibrateur-radius") if antivibrateur else None
    offsets = shaft_offsets_option(shaft_offsets)
    flags = {"shaft_offsets_m": "--shaft-offset"}
    with reported(flags=flags):
        check_options(radius_m, balance_factor, orders, rotor, max_order, offsets)
    engines = load_all(files, speed)
    # counterweights are proposed for one crankshaft (alone, an engine with several is an
    # error that says why)
    engines = passed_over(
        engines,
        lambda e: not e.has_several_crankshafts,
        lambda e: (
            f"{len(e.crankshafts)} crankshafts; counterweights are proposed for an engine with one"
        ),
        "every engine here has several crankshafts; counterweights are "
        "proposed for an engine with one",
    )

    def work(engine):
        return counterweights(
            engine,
            plane_specs,
            radius_m,
            balance_factor,
            orders,
            rotor,
            test_masses,
            samples,
            max_order,
            offsets,
        )

    balances = run_each(engines, "Balancing", work)
    scale = Scale.of(absolute, units)
    text = render(
        fmt,
        json=lambda: Balances(tuple(balances)).to_dict(),
        csv=lambda: balance_csv(balances, scale),
        table=lambda: balance_tables(balances, scale, fmt),
    )
    configuration = None
    if write_path is not None:
        # built before anything is written: a failure leaves no file and no report half done
        engine = balances[0].engine
        with reported(engine):
            configuration = as_built_toml(
                read_configuration(files[0]).data,
                balances[0].configuration_tables(shafts=bool(orders)),
                f"{engine.name}, with the counterweights{' and shafts' if orders else ''}"
                f" proposed by\nbalance counterweight added as built (from {files[0]}).\n"
                f"Their figures are written to {WRITE_DIGITS} significant digits.",
                # a name of its own: compared with the file it came from, it is another engine
                name=f"{engine.name}, balanced",
            )
    if configuration is not None:
        write(write_path, configuration)
    write(output, text)
