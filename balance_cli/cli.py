"""The ``balance`` command: thin commands that wire configuration, analyses and reports."""

import sys
import warnings

import click

from . import __version__
from .compare import analyse, reference_index
from .config import ConfigError, find_configs, load
from .firing import FiringError, firing, tdc_angles
from .output import OutputError, write_text
from .report.document import compare_document, to_json
from .report.table import compare_csv, compare_tables, list_table, show_table
from .report.values import Scale
from .shaking import DEFAULT_MAX_ORDER, DEFAULT_SAMPLES

__all__ = ["main"]

_INPUTS = click.argument("paths", nargs=-1, required=True, metavar="FILE|DIR...")


def _fail(message):
    raise click.ClickException(message)


def _checked_firing(engine):
    """Firing of ``engine``, with an order that does not fit reported against its file."""
    try:
        return firing(engine)
    except FiringError as exc:
        raise ConfigError(engine.config_path, "firing_order", str(exc)) from None


def _analysed(engine, samples, max_order):
    try:
        return analyse(engine, samples, max_order)
    except FiringError as exc:
        raise ConfigError(engine.config_path, "firing_order", str(exc)) from None


def _load_all(paths):
    files = find_configs(paths)
    if not files:
        _fail(f"no .toml configuration found in {', '.join(paths)}")
    try:
        return [load(f) for f in files]
    except ConfigError as exc:
        _fail(str(exc))


@click.group(context_settings={"help_option_names": ["-h", "--help"]})
@click.version_option(__version__, prog_name="balance")
def main():
    """Compare reciprocating-engine layouts for mechanical balance.

    Engines are described in TOML files (see configs/ and the README). Forces and moments
    are computed exactly from the true motion of every mass, order by order.
    """


@main.command()
@_INPUTS
def validate(paths):
    """Check configuration files (and the folders' .toml files): syntax, units, geometry, firing.

    Prints one line per file; exits with status 1 if any file is invalid.
    """
    files = find_configs(paths)
    if not files:
        _fail(f"no .toml configuration found in {', '.join(paths)}")
    bad = 0
    for path in files:
        try:
            engine = load(path)
            _checked_firing(engine)
        except ConfigError as exc:
            bad += 1
            click.echo(f"invalid: {exc}", err=True)
        else:
            click.echo(f"ok: {path} ({engine.name}, {engine.n_cylinders} cylinders)")
    if bad:
        raise SystemExit(1)


@main.command("list")
@click.argument("folder", required=False, default="configs", metavar="[DIR]")
def list_(folder):
    """List the engines in DIR (default: configs): name, cylinders, cycle, frame, source.

    Invalid files are reported on standard error (exit status 1) after the listing.
    """
    files = find_configs([folder])
    if not files:
        _fail(f"no .toml configuration found in {folder}")
    engines, errors = [], []
    for path in files:
        try:
            engines.append(load(path))
        except ConfigError as exc:
            errors.append(str(exc))
    click.echo(list_table(engines))
    for error in errors:
        click.echo(f"invalid: {error}", err=True)
    if errors:
        raise SystemExit(1)


@main.command()
@click.argument("path", metavar="FILE")
def show(path):
    """Show one engine, one row per cylinder: bank, throw, phase, z, rod type and TDC angle.

    The TDC angle is the engine angle (crank angle; crankcase angle for a rotary) at which
    the piston is farthest out, found on the exact linkage.
    """
    try:
        engine = load(path)
        fire = _checked_firing(engine)
    except ConfigError as exc:
        _fail(str(exc))
    click.echo(show_table(engine, tdc_angles(engine), fire), nl=False)


@main.command()
@_INPUTS
@click.option("--samples", default=DEFAULT_SAMPLES, show_default=True, type=click.IntRange(16, 1 << 16),
              help="Crank angles per revolution for the Fourier analysis.")
@click.option("--max-order", default=DEFAULT_MAX_ORDER, show_default=True, type=click.IntRange(1, 1000),
              help="Highest order reported.")
@click.option("--absolute", is_flag=True,
              help="Forces in newtons (or --units) instead of per cylinder (× m_rec·r·ω²·n).")
@click.option("--units", type=click.Choice(["N", "kgf"]), default="N", show_default=True,
              help="Units of absolute forces and of moments; kgf implies --absolute.")
@click.option("--reference", default=None, metavar="NAME",
              help="Engine the percentages refer to (name or unique prefix); default the first.")
@click.option("--format", "fmt", type=click.Choice(["table", "markdown", "csv", "json"]),
              default="table", show_default=True, help="Output format.")
@click.option("--output", "-o", default="-", metavar="FILE", show_default=True,
              help="Write here (atomically) instead of standard output.")
def compare(paths, samples, max_order, absolute, units, reference, fmt, output):
    """Compare engines order by order, in the style of Tanaka's Part III.

    FILE|DIR...: configuration files, or folders searched recursively for .toml files,
    compared in the order given (files of a folder sorted by path).
    """
    engines = _load_all(paths)
    if max_order >= samples // 4:
        _fail(f"--max-order {max_order} needs --samples above {4 * max_order}")
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        try:
            results = [_analysed(e, samples, max_order) for e in engines]
        except ConfigError as exc:
            _fail(str(exc))
    for w in caught:
        click.echo(f"warning: {w.message}", err=True)
    try:
        index = reference_index(results, reference)
    except ValueError as exc:
        _fail(str(exc))
    scale = Scale(absolute=absolute or units == "kgf", units=units)
    if fmt == "json":
        text = to_json(compare_document(results, index, samples, max_order))
    elif fmt == "csv":
        text = compare_csv(results, scale)
    else:
        text = compare_tables(results, index, scale, fmt, samples)
    try:
        write_text(output, text)
    except OutputError as exc:
        _fail(str(exc))


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
