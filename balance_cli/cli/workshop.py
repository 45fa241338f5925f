"""The workshop's commands: balance match (weighed parts to cylinders), balance tolerance (what
a tolerance band leaves across a production run) and balance bobweight (the balancing sheet).
The workshop is imported only when they run.
"""

from pathlib import Path

import click

from ..config import WRITE_DIGITS, read_configuration, resolve
from ..units import Scale
from . import headless
from .batch import load_all, progress_bar, settings
from .dispatch import guard, render, write
from .group import main, reported
from .options import FORMAT, MAX_ORDER, OUTPUT, SAMPLES, SPEED, UNITS

__all__ = ["match", "tolerance", "bobweight"]

_FLAGS = {
    "parts": "--parts",
    "objective": "--objective",
    "limit": "--limit",
    "restarts": "--restarts",
    "seed": "--seed",
    "runs": "--runs",
    "tolerances": "[tolerances]",
    "factors": "--factors",
    "heuristic": "--heuristic",
    "write": "--write",
}
FILE = click.argument("path", metavar="FILE.toml")
_PARTS_HELP = (
    "The weighed parts: a CSV file with the columns kind,id,mass; kind piston (with its pin, "
    "rings and clips), rod_small or rod_big (a rod's two ends, one id); masses with units "
    "('512.4 g')."
)


def _engine(path, speed):
    return load_all([path], speed)[0]


@main.command()
@FILE
@click.option("--parts", "parts_path", required=True, metavar="PARTS.csv", help=_PARTS_HELP)
@click.option(
    "--objective",
    default=None,
    metavar="TERMS",
    help="What to minimise: F and M terms as for balance search (F1,M2:4, F1+), in "
    "newtons (moments over the mean throw pitch). Default: of what the parts' deviations "
    "add, the largest force over a revolution plus the largest moment over the pitch.",
)
@click.option(
    "--limit",
    default=None,
    type=int,
    metavar="N",
    help="Evaluate every assignment while there are at most N (one per symmetry class); "
    "beyond, the heuristic  [default: 1e7, about half a minute].",
)
@click.option(
    "--heuristic",
    is_flag=True,
    help="Exchanges of two parts from several starts: the best found, NOT proved optimal.",
)
@click.option(
    "--restarts",
    default=50,
    show_default=True,
    type=int,
    metavar="N",
    help="Random starts of the heuristic.",
)
@click.option(
    "--seed", default=0, show_default=True, type=int, help="Random seed of the heuristic."
)
@click.option(
    "--write",
    "write_path",
    default=None,
    metavar="FILE.toml",
    help="Write the engine as matched: the configuration with every cylinder's own "
    "reciprocating mass and, with rods, every throw's own rotating mass, named 'NAME, as "
    f"matched', to {WRITE_DIGITS} significant digits. Atomic.",
)
@SAMPLES
@MAX_ORDER
@UNITS
@SPEED
@FORMAT
@OUTPUT
def match(
    path,
    parts_path,
    objective,
    limit,
    heuristic,
    restarts,
    seed,
    write_path,
    samples,
    max_order,
    units,
    speed,
    fmt,
    output,
):
    """Fit weighed pistons and rods to the cylinders so that the engine shakes least.

    Every assignment is evaluated (one of each class of cylinders the crank makes
    equivalent) while they are within --limit: the best is then proved. Reports the
    assignment, each cylinder's masses, what the parts' deviations add order by order (the
    engine as assembled against the same engine with every cylinder and throw at the mean
    mass, Tanaka's measure), the engine as assembled as compare shows it, and the same for
    the parts fitted in the order given (the first listed in cylinder 1, ...).
    """
    from ..report.workshop import match_tables, records_csv
    from ..workshop import DEFAULT_LIMIT, assembled_toml
    from ..workshop import match as match_of

    source = resolve(path)
    outputs = [output] + ([write_path] if write_path else [])
    if write_path is not None and (write_path == "-" or write_path == output):
        raise click.BadParameter(
            "needs a file of its own (not standard output, not --output)", param_hint="--write"
        )
    guard(outputs, [Path(source), Path(parts_path)])
    settings(samples, max_order)
    engine = _engine(path, speed)
    callback, bar = progress_bar("Matching")
    with reported(engine, _FLAGS), bar:
        result = match_of(
            engine,
            parts_path,
            objective,
            limit=DEFAULT_LIMIT if limit is None else limit,
            heuristic=True if heuristic else None,
            restarts=restarts,
            seed=seed,
            samples=samples,
            max_order=max_order,
            progress=callback,
        )
    configuration = None
    if write_path is not None:
        with reported(engine, _FLAGS):
            configuration = assembled_toml(
                read_configuration(path).data,
                engine,
                result.best.engine,
                f"{engine.name}, as matched by balance match from {path} and {parts_path}\n"
                f"(objective {result.objective.label}: {result.best.score_n:.6g} N, "
                f"{result.method}). Masses to {WRITE_DIGITS} significant digits.",
                result.best.engine.name,
            )
    text = render(
        fmt,
        json=result.to_dict,
        csv=lambda: records_csv(result.records()),
        table=lambda: match_tables(result, Scale.of(True, units), fmt),
    )
    if configuration is not None:
        write(write_path, configuration)
    write(output, text)


@main.command()
@FILE
@click.option(
    "--runs",
    default=10_000,
    show_default=True,
    type=int,
    metavar="N",
    help="Engines drawn from the band.",
)
@click.option("--seed", default=0, show_default=True, type=int, help="Random seed of the draws.")
@click.option(
    "--plot",
    "plot_path",
    default=None,
    metavar="PATH",
    help="Also draw histograms of --order's vertical force and moment and of the largest "
    "over a revolution (.png, .svg, .pdf, ...).",
)
@click.option(
    "--order", default=1, show_default=True, type=click.IntRange(1), help="The order --plot draws."
)
@SAMPLES
@MAX_ORDER
@UNITS
@SPEED
@FORMAT
@OUTPUT
def tolerance(path, runs, seed, plot_path, order, samples, max_order, units, speed, fmt, output):
    """What the [tolerances] of FILE.toml leave across a production run of its engine.

    Each run draws every part's mass and every dimension the band names from a normal
    scatter of its standard deviation, and analyses that engine exactly (all runs at once).
    Reports, order by order, the spread of the free force and moment (vertical, horizontal,
    largest) with its sampling error, beside the closed-form spread of the scatter's linear
    part, and the spread of the largest resultant over a revolution.
    """
    from ..report.workshop import records_csv, tolerance_tables
    from ..workshop import tolerance as tolerance_of

    outputs = [output] + ([plot_path] if plot_path else [])
    guard(outputs, [Path(resolve(path))])
    settings(samples, max_order)
    if plot_path is not None:
        headless.use_agg()
        from .. import plot as drawing

        with reported():
            drawing.format_of(plot_path)
        if order > max_order:
            raise click.BadParameter(
                f"is {order}, above --max-order {max_order}", param_hint="--order"
            )
    engine = _engine(path, speed)
    callback, bar = progress_bar("Drawing runs")
    with reported(engine, _FLAGS), bar:
        result = tolerance_of(
            engine, runs=runs, seed=seed, samples=samples, max_order=max_order, progress=callback
        )
    scale = Scale.of(True, units)
    text = render(
        fmt,
        json=result.to_dict,
        csv=lambda: records_csv(result.records()),
        table=lambda: tolerance_tables(result, scale, fmt),
    )
    if plot_path is not None:
        with reported(), headless.drawing():
            figure = drawing.tolerance_histograms(result, order, scale.units)
            drawing.save(figure, plot_path)
    write(output, text)


@main.command()
@FILE
@click.option("--parts", "parts_path", default=None, metavar="PARTS.csv", help=_PARTS_HELP)
@click.option(
    "--balance-factor",
    type=float,
    metavar="F",
    help="The fraction (0 to 1) of the reciprocating masses a bobweight carries  [default: "
    "the one balance counterweight implies, ½ on plain rods].",
)
@click.option(
    "--factors",
    default=None,
    metavar="F[,F...]",
    help="A single's or twin's trade: the balance factors to table  [default: 0.5,0.55,...,0.85].",
)
@SAMPLES
@MAX_ORDER
@UNITS
@SPEED
@FORMAT
@OUTPUT
def bobweight(
    path, parts_path, balance_factor, factors, samples, max_order, units, speed, fmt, output
):
    """The balancing sheet: each crank pin's bobweight for a balancing machine.

    Bobweight = the rotating parts on the pin (big ends) + the balance factor × its
    reciprocating parts (pistons with pins, rings and clips, and the rods' small ends), from
    the configuration's masses or, with --parts, the weighed parts fitted in the order given
    (write a matched engine with balance match --write first). For a single or a twin, also
    the first-order shaking left vertically and horizontally at each balance factor.
    """
    from ..report.workshop import bobweight_tables, records_csv
    from ..workshop import DEFAULT_FACTORS, bobweights

    inputs = [Path(resolve(path))] + ([Path(parts_path)] if parts_path else [])
    guard([output], inputs)
    settings(samples, max_order)
    chosen: tuple = DEFAULT_FACTORS
    if factors is not None:
        try:
            chosen = tuple(float(f) for f in factors.split(","))
        except ValueError:
            raise click.BadParameter(
                f"{factors!r} is not a list of numbers such as 0.5,0.6,0.85", param_hint="--factors"
            ) from None
    engine = _engine(path, speed)
    with reported(engine, _FLAGS):
        sheet = bobweights(engine, parts_path, balance_factor, chosen, samples, max_order)
    emit_scale = Scale.of(True, units)
    text = render(
        fmt,
        json=sheet.to_dict,
        csv=lambda: records_csv(sheet.records()),
        table=lambda: bobweight_tables(sheet, emit_scale, fmt),
    )
    write(output, text)
