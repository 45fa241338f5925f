"""balance mounts: the engine on its mounts, its tables and pictures."""

import math
from pathlib import Path

import click

from ..output import DOCUMENT_VERSION, write_folder
from . import headless
from .batch import inputs, load_all, passed_over, run_each, settings
from .dispatch import guard, render, write
from .group import main, reported
from .options import FORMAT, INPUTS, OUTPUT, SAMPLES, numbers_option, quantity_option, speeds_option

__all__ = ["mounts"]

#: the pictures --plot draws per engine: file name's ending -> what it shows
PICTURES = ("mount-modes", "mount-energy", "mount-forces")
#: the library's parameters as this command's flags
_FLAGS = {
    "orders": "--orders",
    "power_w": "--power",
    "vary": "--decouple",
    "bounds_n_m": "--rate-bounds",
}


@main.command(
    help="""The engine on its mounts ([mounts] table): the six rigid-body modes with their
    kinetic-energy distribution (percent of each mode's energy in fore-aft, lateral, bounce,
    roll, pitch and yaw), the torque roll axis and the elastic axis of the crank's torque, the
    static deflections under the weight and the mean torque's reaction (the [gas] cycle's, or
    --power), the resonances crossed within --speeds, and the forced response: each mount's
    force on the frame, every order against speed and all orders summed over a cycle.

    With --decouple, first the rates that put the roll mode on the torque roll axis (Jeong
    and Singh's decoupling), then all of the above for the mounts with those rates.

    The excitation is the engine's own: every order of the shaking force and free moment
    (vertical and horizontal) at the crank axis, moved to the centre of gravity, and the
    frame torque's orders about the crank axis (roll). The inertia parts grow as the speed
    squared; the gas torque is taken as the same cycle at every speed.
    """
)
@INPUTS
@click.option(
    "--speeds",
    default=None,
    metavar="FROM:TO:STEP",
    help="Engine speeds of the forced response, rpm: a range with its step (both ends "
    "included, e.g. 300:3000:10) or a comma-separated list. Default: 221 speeds from 10 % "
    "to 120 % of each engine's speed.",
)
@click.option(
    "--max-order",
    default=12,
    show_default=True,
    type=click.IntRange(1, 64),
    help="Highest order applied (half orders too for a four-stroke).",
)
@click.option(
    "--orders",
    default=None,
    metavar="K,K,...",
    help="Apply these orders only (e.g. 0.5,1,2), instead of every one up to --max-order.",
)
@click.option(
    "--power",
    default=None,
    metavar="POWER",
    help="The power whose mean torque (power / the file's speed) the static deflection is "
    "under, e.g. '110 kW' (default: the [gas] cycle's mean torque, else the file's power).",
)
@click.option(
    "--decouple",
    "decouple",
    multiple=True,
    metavar="MOUNT:RATE",
    help="Find this rate so that the roll mode turns about the torque roll axis (repeat for "
    "each rate; five or more in general): RATE is x, y or z (the rate along that engine "
    "axis), compression or shear (both shear rates of an inclined mount); A+B:y is one "
    "rate two mounts share; 'all' varies every rate of every mount. The least change of "
    "the rates that decouples is taken, or the purest mode where none does; the analysis "
    "is then of the mounts with the rates found.",
)
@click.option(
    "--rate-bounds",
    default=None,
    metavar="LOW,HIGH",
    help="The range of the rates --decouple may choose, e.g. '20 N/mm,1000 N/mm' (default: "
    "each rate as given, divided and multiplied by 10).",
)
@SAMPLES
@FORMAT
@OUTPUT
@click.option(
    "--plot",
    "plot_dir",
    default=None,
    metavar="DIR",
    help="Also draw, per engine, NAME-mount-modes.png (the mode shapes: the engine as a box "
    "on its mounts), NAME-mount-energy.png (each mode's kinetic-energy distribution) and "
    "NAME-mount-forces.png (each mount's force on the frame against speed, the resonances "
    "marked) into DIR; NAME is the file's stem.",
)
def mounts(
    paths,
    speeds,
    max_order,
    orders,
    power,
    decouple,
    rate_bounds,
    samples,
    fmt,
    output,
    plot_dir,
):
    from ..mounting import decouple as decouple_of
    from ..mounting import mounts as mounts_of

    vary = _vary_option(decouple)
    bounds_n_m = _bounds_option(rate_bounds)
    if bounds_n_m is not None and not decouple:
        raise click.UsageError("--rate-bounds bounds the rates --decouple finds; give --decouple")
    speeds_rpm = speeds_option(speeds)
    chosen = None if orders is None else numbers_option(orders, "--orders")
    power_w = quantity_option(power, "--power", "power")
    settings(samples, math.ceil(max(chosen)) if chosen else max_order)
    files = inputs(paths)
    guard([output], files)
    engines = load_all(files)
    engines = passed_over(
        engines,
        lambda e: e.mounts is not None,
        lambda e: "no [mounts] table",
        "none of these engines has a [mounts] table (the powertrain's mass, centre of "
        "gravity, inertia and mounts); see the how-to page 'The engine on its mounts'",
    )
    files = [Path(e.config_path) for e in engines]
    if plot_dir is not None:
        _check_pictures(files, output, plot_dir)
    decouplings: list = []

    def work(engine):
        system = None
        if decouple:
            with reported(engine, flags=_FLAGS):
                decouplings.append(decouple_of(engine, vary, bounds_n_m))
            system = decouplings[-1].system
        return _analysed(mounts_of, engine, speeds_rpm, chosen, max_order, power_w, samples, system)

    results = run_each(engines, "Mounts", work)
    from ..report.mounts import decoupling_tables, mount_csv, mount_tables

    def document(i, r):
        return {**r.to_dict(), "decoupling": decouplings[i].to_dict()} if decouple else r.to_dict()

    def tables():
        if not decouple:
            return mount_tables(results, fmt)
        return "\n".join(
            decoupling_tables([d], fmt) + "\n" + mount_tables([r], fmt)
            for d, r in zip(decouplings, results, strict=True)
        )

    text = render(
        fmt,
        json=lambda: {
            "balance_version": DOCUMENT_VERSION,
            "engines": [document(i, r) for i, r in enumerate(results)],
        },
        csv=lambda: mount_csv(results),
        table=tables,
    )
    if plot_dir is not None:
        _draw(files, results, plot_dir)
    write(output, text)


def _analysed(mounts_of, engine, speeds_rpm, orders, max_order, power_w, samples, system):
    with reported(engine, flags=_FLAGS):
        return mounts_of(engine, speeds_rpm, orders, max_order, power_w, samples, system)


def _vary_option(texts):
    """--decouple MOUNT:RATE (repeatable; MOUNT+MOUNT shares one rate; 'all') as the
    library's ``vary``: a list of (mounts, rate), or None for every rate."""
    if not texts:
        return None
    if any(t.strip() == "all" for t in texts):
        if len(texts) > 1:
            raise click.BadParameter(
                "'all' varies every rate already; give it alone", param_hint="--decouple"
            )
        return None
    out = []
    for text in texts:
        names, colon, rate = text.rpartition(":")
        mounts = tuple(n.strip() for n in names.split("+"))
        if not colon or not all(mounts) or not rate.strip():
            raise click.BadParameter(
                f"{text!r}: give MOUNT:RATE, such as A:z, C:compression or A+B:y (one rate "
                "two mounts share)",
                param_hint="--decouple",
            )
        out.append((mounts, rate.strip()))
    return out


def _bounds_option(text):
    """--rate-bounds LOW,HIGH as (low, high) in N/m."""
    if text is None:
        return None
    parts = text.split(",")
    if len(parts) != 2:
        raise click.BadParameter(
            f"{text!r}: give two rates, LOW,HIGH, such as '20 N/mm,1000 N/mm'",
            param_hint="--rate-bounds",
        )
    return tuple(quantity_option(p.strip(), "--rate-bounds", "stiffness") for p in parts)


def _check_pictures(files, output, plot_dir):
    """Pictures are named after the files: two of one name would overwrite each other, and
    --output into the folder would replace a picture with the tables."""
    stems = [f.stem for f in files]
    twice = sorted({s for s in stems if stems.count(s) > 1})
    if twice:
        raise click.BadParameter(
            f"names pictures after the files, and {twice[0]}.toml is given twice (from "
            "different folders); draw them one at a time or rename one",
            param_hint="--plot",
        )
    if output not in (None, "-") and Path(output).resolve().parent == Path(plot_dir).resolve():
        if Path(output).name in {f"{s}-{k}.png" for s in stems for k in PICTURES}:
            raise click.BadParameter(
                f"{output} is one of the pictures --plot draws; write the tables elsewhere",
                param_hint="--output",
            )


def _draw(files, results, plot_dir):
    headless.use_agg()
    from .. import plot as pictures

    def fill(folder):
        names = []
        for file, result in zip(files, results, strict=True):
            for kind, draw in zip(
                PICTURES,
                (pictures.mount_modes, pictures.energy_bars, pictures.mount_forces),
                strict=True,
            ):
                name = f"{file.stem}-{kind}.png"
                pictures.save(draw(result), folder / name)
                names.append(name)
        return names

    with reported(), headless.drawing():
        written = write_folder(plot_dir, fill)
    for path in written:
        click.echo(f"wrote {path}", err=True)
