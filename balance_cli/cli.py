"""The ``balance`` command: thin commands that wire configuration, analyses and reports."""

import contextlib
import sys
import warnings

import click

from . import __version__
from .compare import analyse, reference_index
from .config import ConfigError, find_configs, load, load_many
from .counterweight import BalanceError, balance, plane_at, plane_at_throw
from .firing import FiringError, firing
from .output import OutputError, write_text
from .report.document import balance_document, compare_document, to_json
from .report.table import (balance_csv, balance_tables, compare_csv, compare_tables, list_table,
                           show_table)
from .report.values import Scale
from .shaking import DEFAULT_MAX_ORDER, DEFAULT_SAMPLES
from .units import UnitError, parse_quantity

__all__ = ["main"]

_INPUTS = click.argument("paths", nargs=-1, required=True, metavar="FILE|DIR...")
_SAMPLES = click.option("--samples", default=DEFAULT_SAMPLES, show_default=True,
                        type=click.IntRange(16, 1 << 16),
                        help="Crank angles per revolution for the Fourier analysis.")
_MAX_ORDER = click.option("--max-order", default=DEFAULT_MAX_ORDER, show_default=True,
                          type=click.IntRange(1, 1000), help="Highest order analysed and reported.")
_FORMAT = click.option("--format", "fmt", type=click.Choice(["table", "markdown", "csv", "json"]),
                       default="table", show_default=True, help="Output format.")
_OUTPUT = click.option("--output", "-o", default="-", metavar="FILE", show_default=True,
                       help="Write here (atomically) instead of standard output.")
_ABSOLUTE = click.option("--absolute", is_flag=True,
                         help="Forces in newtons (or --units) instead of per cylinder (× m_rec·r·ω²·n).")
_UNITS = click.option("--units", type=click.Choice(["N", "kgf"]), default="N", show_default=True,
                      help="Units of absolute forces and of moments; kgf implies --absolute.")


def _fail(message):
    raise click.ClickException(message)


def _progress(items, label):
    """A progress bar on a terminal for several items; nothing when output is not a terminal."""
    if len(items) > 1 and sys.stderr.isatty():
        return click.progressbar(items, label=label, file=sys.stderr)
    return contextlib.nullcontext(items)


@contextlib.contextmanager
def _firing_order_of(engine):
    """A firing order that does not fit the crank is an error of its configuration file."""
    try:
        yield
    except FiringError as exc:
        raise ConfigError(engine.config_path, "firing_order", str(exc)) from None


def _checked_firing(engine):
    with _firing_order_of(engine):
        return firing(engine)


def _analysed(engine, samples, max_order):
    with _firing_order_of(engine):
        return analyse(engine, samples, max_order)


def _config_files(paths):
    files = find_configs(paths)
    if not files:
        _fail(f"no .toml configuration found in {', '.join(map(str, paths))}")
    return files


def _load_all(paths):
    try:
        return load_many(paths)
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
    bad = 0
    for path in _config_files(paths):
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
    engines, errors = [], []
    for path in _config_files([folder]):
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
    click.echo(show_table(engine, fire), nl=False)


@main.command()
@_INPUTS
@_SAMPLES
@_MAX_ORDER
@_ABSOLUTE
@_UNITS
@click.option("--reference", default=None, metavar="NAME",
              help="Engine the percentages refer to (name or unique prefix); default the first.")
@_FORMAT
@_OUTPUT
def compare(paths, samples, max_order, absolute, units, reference, fmt, output):
    """Compare engines order by order, in the style of Tanaka's Part III.

    FILE|DIR...: configuration files, or folders searched recursively for .toml files,
    compared in the order given (files of a folder sorted by path).
    """
    engines = _load_all(paths)
    results = _analyse_all(engines, samples, max_order)
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


def _planes(engine, text):
    """--planes: throw numbers ("1,6") or axial positions ("0 mm,750 mm"), one or two."""
    if text is None:
        return None
    planes = []
    for token in (t.strip() for t in text.split(",")):
        if token.isdigit():
            planes.append(plane_at_throw(engine, int(token)))
        else:
            try:
                planes.append(plane_at(engine, parse_quantity(token, "length")))
            except UnitError as exc:
                raise BalanceError(f"--planes: {exc}") from None
    return planes


def _orders_option(text):
    if not text:
        return ()
    try:
        return tuple(int(t) for t in text.split(","))
    except ValueError:
        raise click.BadParameter("give orders as whole numbers, such as 1,2", param_hint="--shafts")


@main.command()
@_INPUTS
@click.option("--planes", metavar="A[,B]",
              help="Correction planes: throw numbers (1,6) or axial positions ('0 mm,750 mm'); one "
                   "plane cancels the force only. Default: the first and last throws.")
@click.option("--radius", metavar="LENGTH",
              help="Radius of the counterweights' centre of mass, e.g. '60 mm'. Default: the crank radius.")
@click.option("--balance-factor", type=float, metavar="F",
              help="Size for the rotating masses plus F times the reciprocating ones per throw "
                   "(0.5 is the classic single's), instead of cancelling the forward first order.")
@click.option("--shafts", metavar="K[,K...]",
              help="Cancel these residual orders with balancer shafts (k× speed, with or against the crank).")
@click.option("--antivibrateur", "antivibrateur", is_flag=True,
              help="Add Fraeys de Veubeke's rotor on the crank pin (twice crank speed), sized to "
                   "cancel the forward second order (single-throw engines).")
@click.option("--antivibrateur-radius", default="40 mm", show_default=True, metavar="LENGTH",
              help="Eccentricity of the antivibrateur's mass.")
@click.option("--test-masses", is_flag=True,
              help="Also give the balancing-machine mass to hang on each crank pin.")
@_SAMPLES
@_MAX_ORDER
@_ABSOLUTE
@_UNITS
@_FORMAT
@_OUTPUT
def counterweight(paths, planes, radius, balance_factor, shafts, antivibrateur, antivibrateur_radius,
                  test_masses, samples, max_order, absolute, units, fmt, output):
    """Counterweights that cancel the forward first order, and what is left.

    Two planes cancel the forward first-order force and moment; one plane the force only.
    Optionally: balancer shafts for residual orders, the antivibrateur of radial engines, and
    the balancing-machine test masses.
    """
    engines = _load_all(paths)
    _check_orders(samples, max_order)
    orders = _orders_option(shafts)
    try:
        radius_m = None if radius is None else parse_quantity(radius, "length")
        rotor = parse_quantity(antivibrateur_radius, "length") if antivibrateur else None
    except UnitError as exc:
        _fail(f"--radius or --antivibrateur-radius: {exc}")

    def work(engine):
        try:
            return balance(engine, _planes(engine, planes), radius_m, balance_factor, orders, rotor,
                           test_masses, samples, max_order)
        except BalanceError as exc:
            raise ConfigError(engine.config_path, "", str(exc)) from None

    results = _run_each(engines, "Balancing", work)
    scale = Scale(absolute=absolute or units == "kgf", units=units)
    if fmt == "json":
        text = to_json(balance_document(results, samples, max_order))
    elif fmt == "csv":
        text = balance_csv(results, scale)
    else:
        text = balance_tables(results, scale, fmt)
    try:
        write_text(output, text)
    except OutputError as exc:
        _fail(str(exc))


def _check_orders(samples, max_order):
    if max_order >= samples // 4:
        _fail(f"--max-order {max_order} needs --samples above {4 * max_order}")


def _run_each(engines, label, work):
    """``work(engine)`` for every engine: a progress bar on a terminal, warnings echoed once,
    a configuration error as one line."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        try:
            with _progress(engines, label) as bar:
                results = [work(e) for e in bar]
        except ConfigError as exc:
            _fail(str(exc))
    for w in caught:
        click.echo(f"warning: {w.message}", err=True)
    return results


def _analyse_all(engines, samples, max_order):
    """Analyse every engine; a firing order that does not fit is reported against its file."""
    _check_orders(samples, max_order)
    return _run_each(engines, "Analysing", lambda e: _analysed(e, samples, max_order))


@main.command()
@_INPUTS
@click.option("--kind", type=click.Choice(["locus", "spectrum", "star", "firing"]), required=True,
              help="locus: resultant force per cylinder over a revolution (Tanaka's Fig. 9); "
                   "spectrum: forward and backward parts by order; star: each cylinder's phasor "
                   "of one order, chained; firing: firing angles on a dial.")
@click.option("--output", "-o", required=True, metavar="PATH",
              help="Picture file: PNG, or SVG when the name ends in .svg. Folders are created.")
@click.option("--order", type=click.IntRange(1, 1000), default=None,
              help="locus: one order only (default all); star: the order drawn (default 2).")
@click.option("--units", type=click.Choice(["per-cylinder", "N", "kgf"]), default="per-cylinder",
              show_default=True, help="spectrum: units of the forces.")
@_SAMPLES
@_MAX_ORDER
def plot(paths, kind, output, order, units, samples, max_order):
    """Draw a picture of one or more engines (headless; PNG or SVG)."""
    engines = _load_all(paths)
    if order is not None and order > max_order:
        _fail(f"--order {order} is above --max-order {max_order}")
    results = _analyse_all(engines, samples, max_order)
    from .report import plot as drawing  # matplotlib only for commands that draw

    if kind == "locus":
        figure = drawing.figure_locus(results, order)
    elif kind == "spectrum":
        figure = drawing.figure_spectrum(results, units.replace("-", "_"))
    elif kind == "star":
        figure = drawing.figure_star(_stars(results, order or 2, samples), order or 2)
    else:
        figure = drawing.figure_firing(results)
    try:
        drawing.save(figure, output)
    except OutputError as exc:
        _fail(str(exc))


def _stars(results, order, samples):
    from .shaking import cylinder_phasors

    return [(r.engine.name, cylinder_phasors(r.engine, order, samples), r.per_cylinder_unit_n)
            for r in results]


@main.command()
@_INPUTS
@click.option("--output", "-o", required=True, metavar="DIR",
              help="Folder for report.md and its pictures (created if needed).")
@click.option("--html", "with_html", is_flag=True,
              help="Also write report.html: one self-contained page, pictures inlined as SVG.")
@click.option("--reference", default=None, metavar="NAME",
              help="Engine the percentages refer to (name or unique prefix); default the first.")
@click.option("--star-order", default=2, show_default=True, type=click.IntRange(1, 1000),
              help="Order drawn in the star diagram.")
@_SAMPLES
@_MAX_ORDER
def report(paths, output, with_html, reference, star_order, samples, max_order):
    """Write a comparison report: tables, counterweights and pictures (Markdown, optionally HTML)."""
    engines = _load_all(paths)
    if star_order > max_order:
        _fail(f"--star-order {star_order} is above --max-order {max_order}")
    results = _analyse_all(engines, samples, max_order)
    try:
        index = reference_index(results, reference)
    except ValueError as exc:
        _fail(str(exc))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # already reported by the analysis above
        balances = [balance(e, samples=samples, max_order=max_order) for e in engines]
    from .report.document_html import write_report

    try:
        written = write_report(output, results, balances, index, Scale(), samples, star_order,
                               _stars(results, star_order, samples), with_html)
    except OutputError as exc:
        _fail(str(exc))
    for path in written:
        click.echo(f"wrote {path}")


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
