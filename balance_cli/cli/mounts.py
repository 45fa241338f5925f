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
_FLAGS = {"orders": "--orders", "power_w": "--power"}


@main.command(
    help="""The engine on its mounts ([mounts] table): the six rigid-body modes with their
    kinetic-energy distribution (percent of each mode's energy in fore-aft, lateral, bounce,
    roll, pitch and yaw), the torque roll axis and the elastic axis of the crank's torque, the
    static deflections under the weight and the mean torque's reaction (the [gas] cycle's, or
    --power), the resonances crossed within --speeds, and the forced response: each mount's
    force on the frame, every order against speed and all orders summed over a cycle.

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
def mounts(paths, speeds, max_order, orders, power, samples, fmt, output, plot_dir):
    from ..mounting import mounts as mounts_of

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
    results = run_each(
        engines,
        "Mounts",
        lambda e: _analysed(mounts_of, e, speeds_rpm, chosen, max_order, power_w, samples),
    )
    from ..report.mounts import mount_csv, mount_tables

    text = render(
        fmt,
        json=lambda: {
            "balance_version": DOCUMENT_VERSION,
            "engines": [r.to_dict() for r in results],
        },
        csv=lambda: mount_csv(results),
        table=lambda: mount_tables(results, fmt),
    )
    if plot_dir is not None:
        _draw(files, results, plot_dir)
    write(output, text)


def _analysed(mounts_of, engine, speeds_rpm, orders, max_order, power_w, samples):
    with reported(engine, flags=_FLAGS):
        return mounts_of(engine, speeds_rpm, orders, max_order, power_w, samples)


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
