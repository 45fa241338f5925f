"""balance sweep: one engine analysed again and again with one value of its configuration
changed, or two over a grid, as tables and a picture.
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
from .options import (
    FORMAT,
    LOAD,
    MAX_ORDER,
    OUTPUT,
    SAMPLES,
    UNIT_CHOICE,
    quantity_option,
    speeds_option,
)

__all__ = ["sweep"]

#: the options that say what a sweep varies: each --vary takes those that follow it
_VARY = ("--vary", "--from", "--to", "--steps", "--values")
_ORDER = "balance.sweep.order"


def _occurrences(args):
    """The options of :data:`_VARY` in the order the command line gives them."""
    order = []
    tokens = iter(args)
    for token in tokens:
        if token == "--":
            break
        name = token.split("=", 1)[0]
        if name in _VARY:
            order.append(name)
            if "=" not in token:
                next(tokens, None)  # its value, whatever it looks like
    return order


class _SweepCommand(click.Command):
    """A command that keeps the order of its --vary options and their values (click gathers
    each repeated option into one tuple and loses which --vary a --values follows)."""

    def parse_args(self, ctx, args):
        ctx.meta[_ORDER] = _occurrences(args)
        return super().parse_args(ctx, args)


def _groups(order, parameters, starts, stops, steps, listed):
    """One dict per --vary: its parameter and the --from/--to/--steps or --values after it
    (any given before the first --vary belong to the first)."""
    given = {
        "--vary": list(parameters),
        "--from": list(starts),
        "--to": list(stops),
        "--steps": list(steps),
        "--values": list(listed),
    }
    if [order.count(name) for name in _VARY] != [len(given[name]) for name in _VARY]:
        raise click.UsageError(
            "give each --vary its values after it: --vary A --from X --to Y --steps N "
            "--vary B --values a,b,c"
        )
    groups: list = []
    early: dict = {}
    for name in order:
        value = given[name].pop(0)
        if name == "--vary":
            groups.append({**early, "--vary": value} if not groups else {"--vary": value})
            early = {}
            continue
        group = groups[-1] if groups else early
        if name in group:
            which = f" for --vary {group['--vary']}" if "--vary" in group else ""
            raise click.UsageError(f"{name} given twice{which}; give each --vary its own values")
        group[name] = value
    return groups


def _values_of(group, span):
    """The values of one --vary: its --values, or --from/--to/--steps spaced evenly."""
    key = group["--vary"]
    spanned = [group.get(flag) for flag in ("--from", "--to", "--steps")]
    if "--values" in group:
        if any(v is not None for v in spanned):
            raise click.UsageError(f"--vary {key}: give --values or --from/--to/--steps, not both")
        return group["--values"].split(",")
    if any(v is None for v in spanned):
        missing = [
            flag
            for flag, v in zip(("--from", "--to", "--steps"), spanned, strict=True)
            if v is None
        ]
        raise click.UsageError(
            f"--vary {key}: give --values, or --from, --to and --steps "
            f"({', '.join(missing)} missing)"
        )
    return span(*spanned)


@main.command(cls=_SweepCommand)
@click.argument("path", metavar="FILE")
@click.option(
    "--vary",
    "parameters",
    required=True,
    multiple=True,
    metavar="PARAM",
    help="The configuration key to vary, as written in the file: speed, crank_radius, "
    "rod_length, pin_offset, masses.rotating, banks[2].angle, throws[3].phase, "
    "throws[2].z, gas.imep, power (for PRU), cylinders[4].reciprocating, ... (any number "
    "of the file; a key the format allows may be added); or one derived from the keys: "
    "rod_ratio (rod_length / crank_radius: sets rod_length, holds crank_radius; not for "
    "link rods), stroke (2 × crank_radius: sets crank_radius, holds rod_length), "
    "bore_pitch (the even spacing of the throws' z: sets every throw's z from the first, "
    "moving listed cylinders' and counterweights' z with their throws); or balance_factor "
    "(classic per-throw counterweights of that factor, 0 to 1); or a key of [mounts]: "
    "mounts.mass, mounts.mount[2].stiffness[3] (a mount by number or name; its rate along "
    "z), mounts.mount[*].stiffness[3] (every mount, one value), mounts.mount[C].compression, "
    "mounts.centre_of_gravity[3], ... Give --vary twice for a grid of every pair of values, "
    "each --vary followed by its own values.",
)
@click.option(
    "--from",
    "starts",
    multiple=True,
    metavar="A",
    help="First value, as in the file: '140 mm', "
    "'3000 rpm', or a plain number for angles and ratios.",
)
@click.option(
    "--to", "stops", multiple=True, metavar="B", help="Last value (in any unit of the same kind)."
)
@click.option(
    "--steps",
    "step_counts",
    type=int,
    multiple=True,
    metavar="N",
    help="Values from --from to --to, both included (2 or more).",
)
@click.option(
    "--values",
    "listed",
    multiple=True,
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
    "--inertia and a [gas] table); PRU<k>V, PRU<k>H (power related unbalance, N·m/kW: "
    "needs the power at each point's speed); of the engine on its mounts: mode_1 ... mode_6 "
    "(Hz), roll_mode (likewise fore_aft_mode, lateral_mode, bounce_mode, pitch_mode, "
    "yaw_mode), tra_purity (%), axes_angle (°), mount_A_force and mount_A_Fx, _Fy, _Fz (N, "
    "the largest over a cycle, orders to --max-order summed; a mount by name or number). "
    "Default: largest_force,largest_moment.",
)
@click.option(
    "--mount-speeds",
    default=None,
    metavar="FROM:TO:STEP",
    help="The mount forces (mount_A_force, ...) as their largest over these speeds, rpm: a "
    "range with its step or a comma-separated list (default: each point's own speed).",
)
@click.option("--inertia", metavar="I", help="Flywheel inertia for steadiness, e.g. '2.5 kg*m^2'.")
@LOAD
@click.option(
    "--speed",
    metavar="SPEED",
    help="Speed of every point instead of the file's, e.g. '3000 rpm' (not with --vary "
    "speed). The file's power is given at the file's speed: for PRU give --power too.",
)
@click.option(
    "--power",
    metavar="POWER",
    help="The engine's power at the speed of every point (the file's, or --speed), for PRU, "
    "e.g. '14280 kW' (not with --vary power or --vary speed).",
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
    help="Also draw the quantities against the parameter into this picture (of two --vary: "
    "a heat map with contour lines per quantity).",
)
def sweep(
    path,
    parameters,
    starts,
    stops,
    step_counts,
    listed,
    quantities,
    mount_speeds,
    inertia,
    load,
    speed,
    power,
    units,
    samples,
    max_order,
    fmt,
    output,
    picture,
):
    """Analyse one engine again and again with one value of its configuration changed, or
    with two over every pair of their values (--vary A ... --vary B ...).

    Each value is set in the file's TOML and the engine rebuilt and checked exactly as a file
    is, so a value that makes no engine is reported with the file, the key and the value.
    """
    from ..config.library import resolve
    from ..report.sweeps import sweep_csv, sweep_tables
    from ..studies.sweep import SweepGrid, SweepResult, span, sweep_grid
    from ..studies.sweep import sweep as sweep_of

    order = click.get_current_context().meta.get(_ORDER, [])
    groups = _groups(order, parameters, starts, stops, step_counts, listed)
    if len(groups) > 2:
        raise click.UsageError(
            f"--vary is given {len(groups)} times; a sweep varies one key, or two over a grid"
        )
    keys = [g["--vary"].strip() for g in groups]
    for flag, value, key in (("--speed", speed, "speed"), ("--power", power, "power")):
        if value is not None and key in keys:
            raise click.UsageError(
                f"{flag} fixes the {key} that --vary {key} varies; give one of them"
            )
    if power is not None and "speed" in keys:
        raise click.UsageError(
            "--power gives the power at one speed, and --vary speed varies the speed; vary "
            "power too (a grid of speed and power) or leave --power out"
        )
    overrides = {
        key: value for key, value in (("speed", speed), ("power", power)) if value is not None
    }
    flags = {
        "parameter": "--vary",
        "parameters": "--vary",
        "values": "--values",
        "quantities": "--quantity",
        "start": "--from",
        "stop": "--to",
        "steps": "--steps",
        "inertia_kgm2": "--inertia",
        "overrides": "--speed" if speed is not None else "--power",
        "mount_speeds_rpm": "--mount-speeds",
    }
    outputs = [output] + ([picture] if picture else [])
    with reported():
        guard(outputs, [Path(resolve(path))])
    if picture is not None and output not in (None, "-") and same_path(output, picture):
        raise click.ClickException(f"--plot and --output both name {picture!r}; give two files")
    settings(samples, max_order)
    mount_speeds_rpm = speeds_option(mount_speeds, "--mount-speeds")
    inertia_kgm2 = quantity_option(inertia, "--inertia", "moment of inertia")
    quantity_option(speed, "--speed", "angular speed")  # its unit, in the option's words
    quantity_option(power, "--power", "power")
    if picture is not None:
        headless.use_agg()
        from .. import plot  # matplotlib only when a picture is asked for

        with reported(flags={"path": "--plot"}):
            plot.format_of(picture)
    with reported(flags=flags):
        values = [_values_of(group, span) for group in groups]
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
                options = dict(
                    inertia_kgm2=inertia_kgm2,
                    load=load,
                    progress=progress,
                    overrides=overrides or None,
                    mount_speeds_rpm=mount_speeds_rpm,
                )
                result: SweepResult | SweepGrid
                if len(groups) == 1:
                    result = sweep_of(
                        path, keys[0], values[0], quantities, samples, max_order, **options
                    )
                else:
                    result = sweep_grid(
                        path, keys, values, quantities, samples, max_order, **options
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
