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
from .options import FORMAT, INPUTS, OUTPUT, SAMPLES, UNIT_CHOICE, numbers_option, speeds_option

__all__ = ["torsion"]

#: the library's parameters as this command's flags
_FLAGS = {"orders": "--orders", "modes": "--modes", "criticals": "--criticals"}


def _mode_numbers(text):
    try:
        numbers = tuple(int(t) for t in text.split(","))
    except ValueError:
        numbers = ()
    if not numbers or min(numbers) < 1:
        raise click.BadParameter(
            f"{text!r}: give mode numbers from 1, such as 1,2", param_hint="--modes"
        )
    return numbers


@main.command(
    help=f"""Torsional vibration of the crankshaft (needs openTorsion:
    {install_hint("torsion")}): natural frequencies and mode shapes of the [torsion] model, the
    phase-vector sums of the firing order, the criticals within --speeds, and the vibratory
    torque (and shear stress, with a shaft diameter) in every section against speed.

    The excitation is each cylinder's exact gas ([gas] table) and inertia torque, order by
    order, at its throw: the gas torque the same at every speed, the inertia torque growing
    as the speed squared. The free end's swing is given whole and as its elastic twist (less
    the turning of the whole line's centre of inertia).
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
@click.option(
    "--criticals",
    "kind",
    type=click.Choice(["excited", "major", "all"]),
    default="excited",
    show_default=True,
    help="Criticals listed and marked: those the cylinders excite (a phase-vector sum "
    "above zero), only the excited ones of major orders, or all (those the cylinders "
    "cannot excite too, flagged).",
)
@click.option(
    "--orders",
    default=None,
    metavar="K,K,...",
    help="List and mark the criticals of these orders only (e.g. 4.5,6), and show their "
    "phase-vector sums only; the response is still that of every order.",
)
@click.option(
    "--modes",
    default=None,
    metavar="N,N,...",
    help="List and mark the criticals of these modes only (e.g. 1,2), and show their "
    "phase-vector sums only.",
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
    "torque against speed per section, the largest peak labelled) into DIR; NAME is "
    "the file's stem.",
)
@click.option(
    "--units",
    type=UNIT_CHOICE,
    default="N",
    show_default=True,
    help="Unit of the vibratory torques (tables, CSV, pictures): N (N·m), kN (kN·m), MN "
    "(MN·m), kgf (kgf·m) or lbf (lbf·ft). JSON stays SI.",
)
def torsion(paths, speeds, max_order, kind, orders, modes, samples, fmt, output, plot_dir, units):
    from ..torsion import require_opentorsion
    from ..torsion import torsional_vibration as torsion_of

    with reported():
        require_opentorsion()  # before any work, and not tied to one file
    speeds_rpm = speeds_option(speeds)
    chosen_orders = None if orders is None else numbers_option(orders, "--orders")
    chosen_modes = None if modes is None else _mode_numbers(modes)
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
        "inertias and stiffnesses); see balance's documentation, How-to: Torsional "
        "vibration",
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
    chosen = []
    for result in results:
        with reported(result.engine, flags=_FLAGS):
            chosen.append(result.filtered(kind, chosen_orders, chosen_modes))
    results = chosen
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
