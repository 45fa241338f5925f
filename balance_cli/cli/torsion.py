"""balance torsion: the torsional vibration of the shaft line, its tables and pictures.
openTorsion is imported only when it runs.
"""

from pathlib import Path

import click

from ..about import install_hint
from ..output import DOCUMENT_VERSION, write_folder
from ..units import Scale
from . import headless
from .batch import inputs, load_all, passed_over, run_each, settings
from .dispatch import guard, render, write
from .group import main, reported
from .options import FORMAT, INPUTS, OUTPUT, SAMPLES, UNITS, speeds_option

__all__ = ["torsion"]


@main.command(
    help=f"""Torsional vibration of the crankshaft (needs openTorsion:
    {install_hint("torsion")}): natural frequencies and mode shapes of the [torsion] model, the
    phase-vector sums of the firing order, the criticals within --speeds, and the vibratory
    torque (and shear stress, with a shaft diameter) in every section against speed.

    The excitation is each cylinder's exact gas ([gas] table) and inertia torque, order by
    order, at its throw: the gas torque the same at every speed, the inertia torque growing
    as the speed squared.
    """
)
@INPUTS
@click.option(
    "--speeds",
    default=None,
    metavar="FROM:TO:STEP",
    help="Engine speeds of the forced response, rpm: a range with its step (both ends "
    "included, e.g. 600:2400:25) or a comma-separated list. Default: 201 speeds "
    "from 20 % to 120 % of each engine's speed.",
)
@click.option(
    "--max-order",
    default=12,
    show_default=True,
    type=click.IntRange(1, 64),
    help="Highest order of the excitation (half orders too for a four-stroke).",
)
@SAMPLES
@FORMAT
@OUTPUT
@click.option(
    "--plot",
    "plot_dir",
    default=None,
    metavar="DIR",
    help="Also draw, per engine, NAME-campbell.png (Campbell diagram with the "
    "criticals), NAME-modes.png (mode shapes) and NAME-torque.png (vibratory "
    "torque against speed per section) into DIR; NAME is the file's stem.",
)
@UNITS
def torsion(paths, speeds, max_order, samples, fmt, output, plot_dir, units):
    from ..torsion import require_opentorsion
    from ..torsion import torsional_vibration as torsion_of

    with reported():
        require_opentorsion()  # before any work, and not tied to one file
    speeds_rpm = speeds_option(speeds)
    files = inputs(paths)
    guard([output], files)
    settings(samples, max_order)
    engines = load_all(files)
    # a folder holds engines without a shaft line (alone, one is an error that says why)
    engines = passed_over(
        engines,
        lambda e: e.torsion is not None,
        lambda e: "no [torsion] table",
        "none of these engines has a [torsion] table (the shaft line's "
        "inertias and stiffnesses); see the README, Torsional vibration",
    )
    files = [Path(e.config_path) for e in engines]
    if plot_dir is not None:
        # pictures are named after the files: two of one name would overwrite each other, and
        # --output into the folder would replace a picture with the tables
        stems = [Path(f).stem for f in files]
        twice = sorted({s for s in stems if stems.count(s) > 1})
        if twice:
            raise click.BadParameter(
                f"names pictures after the files, and {twice[0]}.toml is "
                "given twice (from different folders); draw them one at a "
                "time or rename one",
                param_hint="--plot",
            )
        if output not in (None, "-") and Path(output).resolve().parent == Path(plot_dir).resolve():
            pictures_named = {
                f"{s}-{k}.png" for s in stems for k in ("campbell", "modes", "torque")
            }
            if Path(output).name in pictures_named:
                raise click.BadParameter(
                    f"{output} is one of the pictures --plot draws; write the tables elsewhere",
                    param_hint="--output",
                )
    results = run_each(engines, "Torsion", lambda e: torsion_of(e, speeds_rpm, max_order, samples))
    from ..report.torsion import torsion_csv, torsion_tables

    scale = Scale.of(False, units)

    text = render(
        fmt,
        json=lambda: {
            "balance_version": DOCUMENT_VERSION,
            "max_order": max_order,
            "engines": [r.to_dict() for r in results],
        },
        csv=lambda: torsion_csv(results, scale),
        table=lambda: torsion_tables(results, fmt, scale),
    )
    if plot_dir is not None:
        headless.use_agg()
        from .. import plot as pictures

        def fill(folder):
            names = []
            for file, result in zip(files, results, strict=True):
                for kind, draw in (
                    ("campbell", pictures.campbell),
                    ("modes", pictures.mode_shapes),
                    ("torque", lambda r: pictures.torque_speed(r, scale=scale)),
                ):
                    name = f"{Path(file).stem}-{kind}.png"
                    draw(result).savefig(folder / name, dpi=120)
                    names.append(name)
            return names

        with reported(), headless.drawing():
            written = write_folder(plot_dir, fill)
        for path in written:
            click.echo(f"wrote {path}", err=True)
    write(output, text)
