"""The commands that draw: balance plot (one picture) and balance report (a Markdown or HTML
report with its pictures). matplotlib is imported only when they run.
"""

from pathlib import Path

import click

from ..analysis.counterweight import counterweights
from ..analysis.results import compare as comparison_of
from ..output import check_folder
from ..units import Scale
from . import headless
from .batch import analyse_all, inputs, load_all, run_each, settings
from .dispatch import guard
from .group import main, reported
from .options import INPUTS, MAX_ORDER, SAMPLES, SPEED, UNIT_CHOICE, Units, counts_option

__all__ = ["plot", "report"]


@main.command()
@INPUTS
@click.option(
    "--kind",
    type=click.Choice(["locus", "spectrum", "star", "firing", "torque"]),
    required=True,
    help="locus: resultant force per cylinder (or free moment: --of moment) over a "
    "revolution (Tanaka's Fig. 9); spectrum: forward and backward parts by order; "
    "star: each cylinder's phasor of one order (of force or moment), chained; firing: firing "
    "angles on a dial; torque: inertia, gas "
    "(from a [gas] table) and total torque over a cycle, and the orders of the total.",
)
@click.option(
    "--output",
    "-o",
    required=True,
    metavar="PATH",
    help="Picture file; its extension gives the format: .png, .svg, .svgz, .pdf, .eps, "
    ".ps, .jpg, .jpeg, .tif, .tiff, .webp. Folders are created.",
)
@click.option(
    "--order",
    type=click.IntRange(1),
    default=None,
    help="locus: one order only (default all); star: the order drawn (default 2).",
)
@click.option(
    "--of",
    "quantity",
    type=click.Choice(["force", "moment"]),
    default=None,
    help="locus and star: the resultant force (the default) or the free moment "
    "about the engine's mid-length, N·m.",
)
@click.option(
    "--units",
    type=Units(["per-cylinder"]),
    default=None,
    help="locus and spectrum: units of the forces, default per-cylinder (N, kN, MN, kgf or "
    "lbf, N too, draw them absolute and put moments in N·m, kN·m, MN·m, kgf·m or lbf·ft); "
    "torque: N (N·m, the default), kN, MN, kgf or lbf.",
)
@SAMPLES
@MAX_ORDER
@SPEED
def plot(paths, kind, output, order, quantity, units, samples, max_order, speed):
    """Draw a picture of one or more engines (headless)."""
    if units is not None and kind not in ("locus", "spectrum", "torque"):
        raise click.UsageError(
            f"--units applies to --kind locus, spectrum and torque only, not {kind}"
        )
    if units == "per-cylinder" and kind == "torque":
        raise click.UsageError(
            "--units per-cylinder applies to --kind locus and spectrum only; torques "
            "are drawn in N·m (N) or kgf·m (kgf)"
        )
    if order is not None and kind not in ("locus", "star"):
        raise click.UsageError(f"--order applies to --kind locus and star only, not {kind}")
    if quantity is not None and kind not in ("locus", "star"):
        raise click.UsageError(f"--of applies to --kind locus and star only, not {kind}")
    files = inputs(paths)
    guard([output], files)
    settings(samples, max_order)
    if order is not None and order > max_order:
        raise click.ClickException(f"--order {order} is above --max-order {max_order}")
    headless.use_agg()
    from .. import plot as drawing  # matplotlib only for commands that draw

    with reported():
        drawing.format_of(output)
    engines = load_all(files, speed)
    if kind == "torque":
        from ..analysis.torque import torque as torque_of

        # the picture draws the torques only
        results = run_each(
            engines,
            "Torques",
            lambda e: torque_of(e, samples, max_order, bearings=False, guide=False),
        )
    else:
        results = analyse_all(engines, samples, max_order)
    with reported(), headless.drawing():
        if kind == "locus":
            figure = drawing.locus(
                results, order, of=quantity or "force", units=units or "per-cylinder"
            )
        elif kind == "spectrum":
            figure = drawing.spectrum(results, units or "per-cylinder")
        elif kind == "star":
            figure = drawing.star(results, order or min(2, max_order), of=quantity or "force")
        elif kind == "torque":
            figure = drawing.torque(results, units or "N")
        else:
            figure = drawing.firing(results)
        drawing.save(figure, output)
    click.echo(f"wrote {output}", err=True)


@main.command()
@INPUTS
@click.option(
    "--output",
    "-o",
    required=True,
    metavar="DIR",
    help="Folder for report.md and its pictures (created if needed).",
)
@click.option(
    "--html",
    "with_html",
    is_flag=True,
    help="Also write report.html: one self-contained page, pictures inlined as SVG.",
)
@click.option(
    "--reference",
    default=None,
    metavar="NAME",
    help="Engine the percentages refer to (name or unique prefix); default the first.",
)
@click.option(
    "--star-order",
    default=None,
    type=click.IntRange(1),
    help="Order drawn in the star diagram  [default: 2, or 1 with --max-order 1].",
)
@SAMPLES
@MAX_ORDER
@click.option(
    "--units",
    type=UNIT_CHOICE,
    default=None,
    help="Units of forces, moments and torques, one system: N, kN, MN, kgf or lbf with N·m, "
    "kN·m, MN·m, kgf·m or lbf·ft. Given (N too), the comparison's forces are in it "
    "instead of per cylinder  [default: forces per cylinder, moments and torques in N·m].",
)
@SPEED
@click.option(
    "--family",
    "family_path",
    default=None,
    metavar="FILE.toml",
    help="Also a section with the project-guide table of this engine family (as "
    "balance family, with --family-cylinders).",
)
@click.option(
    "--family-cylinders",
    default="5-12",
    show_default=True,
    metavar="N-M",
    help="The numbers of cylinders of --family.",
)
def report(
    paths,
    output,
    with_html,
    reference,
    star_order,
    samples,
    max_order,
    units,
    speed,
    family_path,
    family_cylinders,
):
    """Write a comparison report: tables, counterweights, torques and pictures (Markdown,
    optionally HTML).

    The files are written into DIR all at once at the end; files of the same names already in
    DIR are replaced, others are left alone.
    """
    files = inputs(paths)
    headless.use_agg()
    from ..report.folder import REPORT_FILES, write_report

    with reported():
        check_folder(output)  # the text given: Path("") would be the current folder
    target = Path(output)
    guard([target] + [target / name for name in REPORT_FILES], files)
    settings(samples, max_order)
    star_order = min(2, max_order) if star_order is None else star_order
    if star_order > max_order:
        raise click.ClickException(f"--star-order {star_order} is above --max-order {max_order}")
    results = analyse_all(load_all(files, speed), samples, max_order)
    with reported():
        comparison = comparison_of(results, reference)
    # counterweights are proposed for one crankshaft; the report names the engines left out
    balances = run_each(
        [r for r in results if not r.engine.has_several_crankshafts], "Balancing", counterweights
    )
    from ..analysis.torque import torque as torque_of

    # the report shows no bearing forces: leaving them out halves the work
    torques = run_each(
        [r.engine for r in results],
        "Torques",
        lambda e: torque_of(e, samples, max_order, bearings=False, guide=False),
    )
    family_table = None
    if family_path is not None:
        from ..config import read_configuration
        from ..studies.family import family

        with reported(flags={"cylinders": "--family-cylinders", "template": family_path}):
            family_table = family(
                read_configuration(family_path),
                counts_option(family_cylinders),
                samples=samples,
                max_order=max_order,
            )
    torsion = None
    if any(r.engine.torsion is not None for r in results):
        from ..errors import TorsionUnavailable
        from ..torsion import require_opentorsion
        from ..torsion import torsional_vibration as torsion_of

        try:
            require_opentorsion()
        except TorsionUnavailable as exc:
            torsion = f"Not computed: {exc}."
        else:
            torsion = run_each(
                [r.engine for r in results if r.engine.torsion is not None], "Torsion", torsion_of
            )
    with reported(), headless.drawing():
        written = write_report(
            target,
            comparison,
            balances,
            star_order,
            with_html,
            torques,
            Scale.of(False, units),
            family_table,
            torsion,
        )
    for path in written:
        click.echo(f"wrote {path}", err=True)
