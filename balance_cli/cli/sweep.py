"""balance sweep: one engine analysed again and again with one value of its configuration
changed, as tables and a picture.
"""

import sys
import warnings
from pathlib import Path

import click

from ..errors import SamplingWarning
from . import headless
from .batch import settings
from .dispatch import guard, render, same_path, write
from .group import main, reported
from .options import FORMAT, LOAD, MAX_ORDER, OUTPUT, SAMPLES, UNIT_CHOICE, quantity_option

__all__ = ["sweep"]


@main.command()
@click.argument("path", metavar="FILE")
@click.option(
    "--vary",
    "parameter",
    required=True,
    metavar="PARAM",
    help="The configuration key to vary, as written in the file: speed, crank_radius, "
    "rod_length, pin_offset, masses.rotating, banks[2].angle, throws[3].phase, "
    "throws[2].z, gas.imep, cylinders[4].reciprocating, ... (any number of the "
    "file; a key the format allows may be added), or balance_factor (classic "
    "per-throw counterweights of that factor, 0 to 1).",
)
@click.option(
    "--from",
    "start",
    metavar="A",
    help="First value, as in the file: '140 mm', "
    "'3000 rpm', or a plain number for angles and ratios.",
)
@click.option("--to", "stop", metavar="B", help="Last value (in any unit of the same kind).")
@click.option(
    "--steps", type=int, metavar="N", help="Values from --from to --to, both included (2 or more)."
)
@click.option(
    "--values",
    "listed",
    metavar="a,b,c",
    help="The values instead, comma-separated: '140 mm,150 mm,170 mm'.",
)
@click.option(
    "--quantity",
    "quantities",
    metavar="Q[,Q...]",
    help="What to report: F<k> (order-k force, its ellipse's max), F<k>V, F<k>H "
    "(vertical, horizontal amplitude), F<k>+, F<k>- (forward, backward), the same "
    "with M for free moments (M1V pitching, M1H yawing); largest_force, "
    "largest_moment (after an ideal counterweight); torque_mean, torque_max, "
    "torque_min, torque_range (ΔC of the total torque); steadiness (needs "
    "--inertia and a [gas] table). Default: largest_force,largest_moment.",
)
@click.option("--inertia", metavar="I", help="Flywheel inertia for steadiness, e.g. '2.5 kg*m^2'.")
@LOAD
@click.option(
    "--speed",
    metavar="SPEED",
    help="Speed of every point instead of the file's, e.g. '3000 rpm' (not with --vary speed).",
)
@click.option(
    "--units",
    type=UNIT_CHOICE,
    default="N",
    show_default=True,
    help="Table and picture units: N, kN, MN, kgf or lbf for forces, and N·m, kN·m, MN·m, "
    "kgf·m or lbf·ft for moments and torques; JSON and CSV stay SI.",
)
@SAMPLES
@MAX_ORDER
@FORMAT
@OUTPUT
@click.option(
    "--plot",
    "picture",
    metavar="FILE.png|svg|pdf",
    help="Also draw the quantities against the parameter into this picture.",
)
def sweep(
    path,
    parameter,
    start,
    stop,
    steps,
    listed,
    quantities,
    inertia,
    load,
    speed,
    units,
    samples,
    max_order,
    fmt,
    output,
    picture,
):
    """Analyse one engine again and again with one value of its configuration changed.

    Each value is set in the file's TOML and the engine rebuilt and checked exactly as a file
    is, so a value that makes no engine is reported with the file, the key and the value.
    """
    from ..config.library import resolve
    from ..report.sweeps import sweep_csv, sweep_tables
    from ..studies.sweep import span
    from ..studies.sweep import sweep as sweep_of

    spanned = (start, stop, steps)
    if listed is not None and any(v is not None for v in spanned):
        raise click.UsageError("give --values or --from/--to/--steps, not both")
    if listed is None and any(v is None for v in spanned):
        missing = [
            flag
            for flag, v in zip(("--from", "--to", "--steps"), spanned, strict=True)
            if v is None
        ]
        raise click.UsageError(
            f"give --values, or --from, --to and --steps ({', '.join(missing)} missing)"
        )
    flags = {
        "parameter": "--vary",
        "values": "--values",
        "quantities": "--quantity",
        "start": "--from",
        "stop": "--to",
        "steps": "--steps",
        "inertia_kgm2": "--inertia",
        "overrides": "--speed",
    }
    if speed is not None and parameter.strip() == "speed":
        raise click.UsageError("--speed fixes the speed that --vary speed varies; give one of them")
    outputs = [output] + ([picture] if picture else [])
    with reported():
        guard(outputs, [Path(resolve(path))])
    if picture is not None and output not in (None, "-") and same_path(output, picture):
        raise click.ClickException(f"--plot and --output both name {picture!r}; give two files")
    settings(samples, max_order)
    inertia_kgm2 = quantity_option(inertia, "--inertia", "moment of inertia")
    quantity_option(speed, "--speed", "angular speed")  # its unit, in the option's words
    if picture is not None:
        headless.use_agg()
        from .. import plot  # matplotlib only when a picture is asked for

        with reported(flags={"path": "--plot"}):
            plot.format_of(picture)
    with reported(flags=flags):
        values = listed.split(",") if listed is not None else span(start, stop, steps)
    state: dict = {}

    def progress(done, total):
        # a bar only for sweeps long enough to wait for, and only on a terminal
        if "bar" not in state and total > 1 and sys.stderr.isatty():
            state["bar"] = click.progressbar(length=total, label="Sweeping", file=sys.stderr)
            state["bar"].__enter__()
        if "bar" in state:
            state["bar"].update(done - state["bar"].pos)

    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", SamplingWarning)
        try:
            with reported(flags=flags):
                result = sweep_of(
                    path,
                    parameter,
                    values,
                    quantities,
                    samples,
                    max_order,
                    inertia_kgm2=inertia_kgm2,
                    load=load,
                    progress=progress,
                    overrides=None if speed is None else {"speed": speed},
                )
        finally:
            if "bar" in state:
                state["bar"].__exit__(None, None, None)
            # one line per distinct sampling warning, not one per point; others as they came
            for text in dict.fromkeys(
                str(w.message) for w in caught if issubclass(w.category, SamplingWarning)
            ):
                click.echo(f"warning: {text} (--samples)", err=True)
            for w in caught:
                if not issubclass(w.category, SamplingWarning):
                    warnings.showwarning(w.message, w.category, w.filename, w.lineno)
    text = render(
        fmt,
        json=result.to_dict,
        csv=lambda: sweep_csv(result),
        table=lambda: sweep_tables(result, fmt, units),
    )
    if picture is not None:
        from .. import plot

        with reported(flags={"path": "--plot"}), headless.drawing():
            plot.save(plot.sweep_figure(result, units), picture)
    write(output, text)
    if picture is not None:
        click.echo(f"wrote {picture}", err=True)
