"""balance animate: one engine turning through its cycle, with its phasors, as a GIF, an MP4
or a self-contained HTML page. matplotlib is imported only when it runs."""

import time

import click

from . import headless
from .batch import analyse_all, inputs, load_all, settings
from .dispatch import guard
from .group import main, reported
from .options import MAX_ORDER, SAMPLES, SPEED, orders_option

__all__ = ["animate"]


@main.command()
@click.argument("path", metavar="FILE")
@click.option(
    "--output",
    "-o",
    "outputs",
    required=True,
    multiple=True,
    metavar="PATH",
    help="The animation; its extension gives the format: .gif (Pillow), .mp4 (ffmpeg, when "
    "installed) or .html (one self-contained page: play and pause, speed, a step to each "
    "firing TDC, orders and cylinders on and off). Give -o again for several.",
)
@click.option(
    "--orders",
    default="1,2",
    show_default=True,
    metavar="K,K...",
    help="The orders whose phasors are shown (the page can show every order analysed).",
)
@click.option(
    "--frames",
    default=None,
    type=int,
    help="A movie's frames over one working cycle, a whole number a revolution  "
    "[default: 72]; the page has 180 a revolution.",
)
@click.option(
    "--fps", default=18.0, show_default=True, type=float, help="A movie's frames a second."
)
@SAMPLES
@MAX_ORDER
@SPEED
def animate(path, outputs, orders, frames, fps, samples, max_order, speed):
    """Animate one engine: its mechanism turning through one working cycle, seen along the
    crank axis (and from the side for an engine of several rows), beside the forward and
    backward phasors of the chosen orders of its shaking force and free moment, their sum,
    and the resultant's locus being traced; the pistons firing marked.

    Every position drawn is the engine's exact kinematics; every phasor its analysis's (those
    compare reports). Each file is written whole or not at all.
    """
    files = inputs([path])
    if len(files) != 1:
        raise click.ClickException(
            f"{path}: holds {len(files)} engines; animate draws one: give one file"
        )
    guard(list(outputs), files)
    settings(samples, max_order)
    chosen = orders_option(orders, "--orders")
    headless.use_agg()
    from ..plot.animation import animate as animation_of
    from ..plot.animation import check_writer

    flags = {"path": "--output", "frames": "--frames", "fps": "--fps", "orders": "--orders"}
    with reported(flags=flags):
        formats = [check_writer(output) for output in outputs]
    (result,) = analyse_all(load_all(files, speed), samples, max_order)
    with reported(result.engine, flags), headless.drawing():
        animation = animation_of(result, chosen)
        for output, fmt in zip(outputs, formats, strict=True):
            start = time.perf_counter()
            animation.save(output, frames=None if fmt == "html" else frames, fps=fps)
            took = time.perf_counter() - start
            click.echo(f"wrote {output} ({took:.3g} s)", err=True)
