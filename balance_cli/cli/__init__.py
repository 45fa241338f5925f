"""The ``balance`` command: a thin face of the library.

Commands parse their options, call the library, render its results and write them. Library
errors name the library's parameters; here they are put in the words of the command line (its
flags, the configuration file) and become one line on standard error with exit status 1.
"""

import contextlib
import math
import json
import re
import sys
import warnings
from pathlib import Path

import click
import numpy as np

from .. import __version__
from ..analysis.results import DOCUMENT_VERSION, analyse, compare as comparison_of
from ..config import as_built_toml, find_configs, load, load_data
from ..analysis.counterweight import Balances, check_options, counterweights
from ..errors import (BalanceError, ConfigError, FiringError, ModelError, OutputError,
                      SamplingWarning)
from ..analysis.firing import firing_sequence
from ..output import check_folder, refuse_inputs, to_json, write_folder, write_text
from ..studies.regress import (RegressError, baseline_configs, check_baseline, check_rtol,
                               compared_like)
from ..studies.regress import regression as regression_of
from ..report.csvfile import balance_csv, compare_csv, search_csv, torque_csv
from ..units import Scale
from ..report.junit import junit_xml
from ..report.tables import (balance_tables, compare_tables, list_tables, regression_tables,
                             search_tables, show_table, steadiness_text, torque_tables)
from ..analysis.shaking import DEFAULT_MAX_ORDER, DEFAULT_SAMPLES, MAX_SAMPLES, check_settings
from ..units import UNIT_SYSTEMS, parse_quantity, rad_s_to_rpm, unit_system

__all__ = ["main"]

#: library parameter -> command-line flag, for the library's messages
FLAGS = {
    "samples": "--samples", "max_order": "--max-order", "reference": "--reference",
    "planes": "--planes", "radius_m": "--radius", "balance_factor": "--balance-factor",
    "shaft_orders": "--shafts", "antivibrateur_radius_m": "--antivibrateur-radius",
    "test_masses": "--test-masses", "path": "--output", "units": "--units", "rtol": "--rtol",
    "order": "--order", "pressure": "--pressure", "inertia_kgm2": "--inertia", "target": "--target",
    "speed_rad_s": "--speed", "load": "--load", "torque_nm": "--torque", "bore_m": "--bore",
}

_INPUTS = click.argument("paths", nargs=-1, required=True, metavar="FILE|DIR...")
_SAMPLES = click.option("--samples", default=DEFAULT_SAMPLES, show_default=True, type=int,
                        help=f"Crank angles per revolution for the Fourier analysis: any number "
                             f"from 4 × --max-order + 1 to {MAX_SAMPLES}.")
_MAX_ORDER = click.option("--max-order", default=DEFAULT_MAX_ORDER, show_default=True, type=int,
                          help="Highest order analysed and reported.")
_FORMAT = click.option("--format", "fmt", type=click.Choice(["table", "markdown", "csv", "json"]),
                       default="table", show_default=True, help="Output format.")
_OUTPUT = click.option("--output", "-o", default="-", metavar="FILE", show_default=True,
                       help="Write here (atomically) instead of standard output.")
_ABSOLUTE = click.option("--absolute", is_flag=True,
                         help="Forces in newtons (or --units) instead of per cylinder (× m_rec·r·ω²·n).")
class _Units(click.ParamType):
    """--units: a system of units in any letter case that has one reading (kn is kN; mn, milli-
    or meganewtons, is refused naming both), and the ``extra`` words a command allows."""

    def __init__(self, extra=()):
        self.extra = tuple(extra)
        self.name = "|".join(self.extra + tuple(UNIT_SYSTEMS))

    def get_metavar(self, param, *args, **kwargs):
        return "[" + self.name + "]"

    def convert(self, value, param, ctx):
        for word in self.extra:
            if isinstance(value, str) and value.strip().lower() == word:
                return word
        try:
            return unit_system(value)
        except BalanceError as exc:
            self.fail(exc.problem, param, ctx)


_UNIT_CHOICE = _Units()
_UNITS = click.option("--units", type=_UNIT_CHOICE, default="N", show_default=True,
                      help="Units of absolute forces and of moments, one system: N and N·m, kN and "
                           "kN·m, MN and MN·m, kgf and kgf·m, lbf and lbf·ft; any but N implies "
                           "--absolute. JSON stays SI.")
_SPEED = click.option("--speed", "speed", default=None, metavar="SPEED",
                      help="Analyse at this speed instead of the files' (e.g. '3000 rpm').")


def _message(exc, engine=None, flags=None):
    """A library error in the command line's words: flags for parameters, and the file of the
    engine it concerns."""
    if isinstance(exc, ConfigError):
        return str(exc)
    if isinstance(exc, FiringError):
        return str(ConfigError(engine.config_path, "firing_order", str(exc)))
    text = exc.named({**FLAGS, **(flags or {})})
    return f"{engine.config_path}: {text}" if engine is not None else text


@contextlib.contextmanager
def _reported(engine=None, flags=None):
    """Any library error inside becomes one line and exit status 1; ``flags`` names this
    command's options where they differ from the usual ones."""
    try:
        yield
    except BalanceError as exc:
        raise click.ClickException(_message(exc, engine, flags)) from None


def _progress(items, label):
    """A progress bar on a terminal for several items; nothing when output is not a terminal."""
    if len(items) > 1 and sys.stderr.isatty():
        return click.progressbar(items, label=label, file=sys.stderr)
    return contextlib.nullcontext(items)


def _run_each(items, label, work):
    """``work(item)`` for every item: a progress bar on a terminal, warnings echoed once on
    standard error after the bar, a library error as one line naming its file."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", SamplingWarning)
        results = []
        try:
            with _progress(items, label) as bar:
                for item in bar:
                    with _reported(getattr(item, "engine", item)):
                        results.append(work(item))
        finally:
            # warnings of the engines done before an error are still worth seeing
            for w in caught:
                text = f"{w.message} (--samples)" if issubclass(w.category, SamplingWarning) \
                    else w.message
                click.echo(f"warning: {text}", err=True)
    return results


def _inputs(paths):
    """The configuration files under ``paths``, found before anything is computed."""
    with _reported():
        return find_configs(paths)


def _load_all(files, speed=None):
    """The engines of ``files``, at ``speed`` (the --speed text) when given."""
    speed_rad_s = _quantity_option(speed, "--speed", "angular speed")
    with _reported():
        engines = [load(f) for f in files]
    if speed_rad_s is None:
        return engines
    out = []
    for engine in engines:
        with _reported(engine):
            out.append(engine.replace(speed_rad_s=speed_rad_s))
    return out


def _guard(outputs, files):
    """Refuse outputs that would replace an input, before anything is computed."""
    with _reported():
        refuse_inputs(outputs, files)


def _settings(samples, max_order):
    with _reported():
        check_settings(samples, max_order)


def _analyse_all(engines, samples, max_order):
    return _run_each(engines, "Analysing", lambda e: analyse(e, samples, max_order))


def _passed_over(engines, takes, why, none_message):
    """Of several engines, those the command ``takes``; the others named on standard error
    with ``why`` (engine -> text), and an error when none is left. One engine alone is kept,
    for the command to refuse with its own message."""
    if len(engines) < 2:
        return engines
    for engine in engines:
        if not takes(engine):
            click.echo(f"note: {engine.config_path}: {why(engine)}; passed over", err=True)
    kept = [e for e in engines if takes(e)]
    if not kept:
        raise click.ClickException(none_message)
    return kept


def _write(output, text):
    with _reported():
        write_text(output, text)


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
    for path in _inputs(paths):
        try:
            engine = load(path)
            with _reported(engine):
                firing_sequence(engine)
        except ConfigError as exc:
            bad += 1
            click.echo(f"invalid: {exc}", err=True)
        except click.ClickException as exc:
            bad += 1
            click.echo(f"invalid: {exc.message}", err=True)
        else:
            count = engine.n_cylinders
            click.echo(f"ok: {path} ({engine.name}, {count} cylinder{'s' if count != 1 else ''})")
    if bad:
        raise SystemExit(1)


@main.command("list")
@click.argument("folder", required=False, default="configs", metavar="[DIR]")
def list_(folder):
    """List the engines in DIR (default: configs, in the current folder): name, cylinders,
    cycle, frame, source.

    One table per folder, headed by the folder's path relative to DIR (DIR itself for the
    files directly in it): the files of DIR first, then each folder in path order, a folder
    before its subfolders (configs, tanaka-part3, today/boxer, today/inline, ...).

    Invalid files are reported on standard error (exit status 1) after the listing.
    """
    root = Path(folder)
    if not root.is_dir():
        raise click.ClickException(f"{folder}: no such folder; give a folder of .toml files")
    groups, errors = {}, []
    for path in _inputs([folder]):
        try:
            engine = load(path)
        except ConfigError as exc:
            errors.append(str(exc))
            continue
        groups.setdefault(Path(path).parent.relative_to(root).parts, []).append(engine)
    # folders sorted by their path parts: DIR's own files first, a folder before its subfolders
    if groups:
        click.echo(list_tables((folder if not parts else "/".join(parts), groups[parts])
                               for parts in sorted(groups)))
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
    with _reported():
        engine = load(path)
    with _reported(engine):
        fire = firing_sequence(engine)
    click.echo(show_table(engine, fire), nl=False)


@main.command()
@_INPUTS
@_SAMPLES
@_MAX_ORDER
@_ABSOLUTE
@_UNITS
@_SPEED
@click.option("--reference", default=None, metavar="NAME",
              help="Engine the percentages refer to (name or unique prefix); default the first.")
@click.option("--power", default=None, metavar="POWER",
              help="The engines' power at the speed analysed (e.g. '14 280 kW', '21 MW', "
                   "'19 000 hp'), for the power related unbalance; default each file's power "
                   "(or its [gas] cycle's indicated power).")
@click.option("--pru-classes", default=None, metavar="A,B,C",
              help="Bounds of the PRU classes not relevant / unlikely / likely / most likely, "
                   "N·m/kW  [default: 60,120,220, the project guides'].")
@click.option("--pru-orders", default=None, metavar="K[,K...]",
              help="Orders whose moments the power related unbalance judges  [default: 1,2].")
@_FORMAT
@_OUTPUT
def compare(paths, samples, max_order, absolute, units, speed, reference, power, pru_classes,
            pru_orders, fmt, output):
    """Compare engines order by order, in the style of Tanaka's Part III.

    FILE|DIR...: configuration files, or folders searched recursively for .toml files,
    compared in the order given (files of a folder sorted by path).
    """
    files = _inputs(paths)
    _guard([output], files)
    _settings(samples, max_order)
    classes = None if pru_classes is None else _numbers_option(pru_classes, "--pru-classes")
    orders = None if pru_orders is None else _orders_option(pru_orders, "--pru-orders")
    engines = _with_power(_load_all(files, speed), power)
    results = _analyse_all(engines, samples, max_order)
    with _reported(flags={"pru_classes": "--pru-classes", "pru_orders": "--pru-orders"}):
        comparison = comparison_of(results, reference, classes, orders)
    scale = Scale.of(absolute, units)
    if fmt == "json":
        text = to_json(_compare_document(comparison, engines if speed else None))
    elif fmt == "csv":
        text = compare_csv(comparison, scale)
    else:
        text = compare_tables(comparison, scale, fmt)
    _write(output, text)


def _compare_document(comparison, overridden=None):
    """compare's JSON; with the engines of a --speed run, the speed it imposed, so that
    balance regress analyses them again at that speed."""
    document = comparison.to_dict()
    if overridden:
        document["speed_override_rpm"] = rad_s_to_rpm(overridden[0].speed_rad_s)
    return document


def _planes(text):
    """--planes: throw numbers ("1,6") or axial positions ("0 mm,750 mm"), one or two."""
    if text is None:
        return None
    planes = []
    for token in (t.strip() for t in text.split(",")):
        if token.isascii() and token.isdigit():
            planes.append(int(token))
            continue
        try:
            planes.append(parse_quantity(token, "length"))
        except BalanceError as exc:
            if str(exc).startswith("cannot read"):
                raise click.ClickException(
                    f"--planes: cannot read {token!r}: give throw numbers (1, 2, ...) or axial "
                    "positions with a unit such as '120 mm'") from None
            raise click.ClickException(f"--planes: {exc}") from None
    return planes


def _orders_option(text, flag="--shafts"):
    if text is None:
        return ()
    try:
        return tuple(int(t) for t in text.split(","))
    except ValueError:
        raise click.BadParameter(f"{text!r}: give orders as whole numbers, such as 1,2",
                                 param_hint=flag) from None


def _numbers_option(text, flag):
    try:
        return tuple(float(t.replace(" ", "")) for t in text.split(","))
    except ValueError:
        raise click.BadParameter(f"{text!r}: give numbers such as 60,120,220",
                                 param_hint=flag) from None


def _with_power(engines, power):
    """The engines with --power as their power at the speed they are analysed at."""
    if power is None:
        return engines
    power_w = _quantity_option(power.replace("\u202f", " "), "--power", "power")
    out = []
    for engine in engines:
        with _reported(engine):
            out.append(engine.replace(power_w=power_w, power_speed_rad_s=engine.speed_rad_s))
    return out


def _shaft_offsets_option(texts):
    """``--shaft-offset [RATIO:]LATERAL,VERTICAL`` (repeatable) as the library's mapping:
    without RATIO the offset of every shaft not named."""
    offsets = {}
    for text in texts:
        ratio, _, lengths = text.rpartition(":")
        key = None
        if ratio.strip():
            try:
                key = int(ratio)
            except ValueError:
                raise click.BadParameter(f"{text!r}: the speed ratio before ':' must be a whole "
                                         "number such as +2 or -2", param_hint="--shaft-offset") from None
        parts = lengths.split(",")
        if len(parts) != 2:
            raise click.BadParameter(f"{text!r}: give LATERAL,VERTICAL such as '120 mm,-80 mm', "
                                     "optionally after a speed ratio ('-2:120 mm,-80 mm')",
                                     param_hint="--shaft-offset")
        if key in offsets:
            which = "every shaft" if key is None else f"speed ratio {key:+d}"
            raise click.BadParameter(f"{which} is placed twice", param_hint="--shaft-offset")
        offsets[key] = tuple(_length_option(p.strip(), "--shaft-offset") for p in parts)
    return offsets or None


def _length_option(text, flag):
    if text is None:
        return None
    try:
        return parse_quantity(text, "length")
    except BalanceError as exc:
        raise click.ClickException(f"{flag}: {exc}") from None


@main.command()
@_INPUTS
@click.option("--planes", metavar="A[,B]",
              help="Correction planes: throw numbers (1,6) or axial positions ('0 mm,750 mm'); one "
                   "plane cancels the force only. Default: the first and last throws.")
@click.option("--radius", metavar="LENGTH",
              help="Radius of the counterweights' centre of mass, e.g. '60 mm'. Default: the crank radius.")
@click.option("--balance-factor", type=float, metavar="F",
              help="Size for the rotating masses plus F (0 to 1) times the reciprocating ones per "
                   "throw (0.5 is the classic single's), instead of cancelling the forward first order.")
@click.option("--shafts", metavar="K[,K...]",
              help="Cancel these residual orders with balancer shafts (k× speed, with or against the crank).")
@click.option("--shaft-offset", "shaft_offsets", multiple=True, metavar="[RATIO:]LATERAL,VERTICAL",
              help="Put the shafts' axes off the crank axis, e.g. '120 mm,-80 mm' (lateral along the "
                   "engine's horizontal, vertical along its vertical); '-2:…' places only the shaft "
                   "of speed ratio −2. Repeatable. Reports the rolling moment the offsets leave.")
@click.option("--antivibrateur", "antivibrateur", is_flag=True,
              help="Add Fraeys de Veubeke's rotor on the crank pin (twice crank speed), sized to "
                   "cancel the forward second order (single-throw engines with a turning crank).")
@click.option("--antivibrateur-radius", default="40 mm", show_default=True, metavar="LENGTH",
              help="Eccentricity of the antivibrateur's mass (with --antivibrateur).")
@click.option("--test-masses", is_flag=True,
              help="Also give the balancing-machine mass to hang on each crank pin (not for a rotary).")
@click.option("--write", "write_path", default=None, metavar="FILE.toml",
              help="Write the engine's configuration (one input file) with the proposed "
                   "counterweights added as [[counterweights]] and, with --shafts, the proposed "
                   "shafts as [[shafts]]: loading it gives the residual reported here. Atomic.")
@_SAMPLES
@_MAX_ORDER
@_ABSOLUTE
@_UNITS
@_SPEED
@_FORMAT
@_OUTPUT
def counterweight(paths, planes, radius, balance_factor, shafts, shaft_offsets, antivibrateur,
                  antivibrateur_radius, test_masses, write_path, samples, max_order, absolute, units,
                  speed, fmt, output):
    """Counterweights that cancel the forward first order, and what is left.

    Two planes cancel the forward first-order force and moment; one plane the force only.
    Optionally: balancer shafts for residual orders (placed off the crank axis with
    --shaft-offset), the antivibrateur of radial engines, and the balancing-machine test masses.

    An engine whose configuration has counterweights ([[counterweights]]) or balancer shafts
    ([[shafts]]) as built is balanced as built: the report first gives what they leave, order
    by order, and every counterweight or shaft proposed is an ADDITION to them (the built ones
    stay). --write puts the additions into a copy of the configuration, after the built ones.
    """
    files = _inputs(paths)
    if write_path is not None:
        if len(files) != 1:
            raise click.BadParameter(f"writes one configuration, but {len(files)} files were "
                                     "given; give one file", param_hint="--write")
        if antivibrateur:
            raise click.BadParameter("cannot describe the antivibrateur in a configuration, and "
                                     "the counterweights proposed with it include its mass; leave "
                                     "out --antivibrateur", param_hint="--write")
        if write_path == "-" or write_path == output:
            raise click.BadParameter("needs a file of its own (not standard output, not "
                                     "--output)", param_hint="--write")
    _guard([output] + ([write_path] if write_path else []), files)
    _settings(samples, max_order)
    plane_specs = _planes(planes)
    orders = _orders_option(shafts)
    radius_m = _length_option(radius, "--radius")
    rotor = _length_option(antivibrateur_radius, "--antivibrateur-radius") if antivibrateur else None
    offsets = _shaft_offsets_option(shaft_offsets)
    flags = {"shaft_offsets": "--shaft-offset"}
    with _reported(flags=flags):
        check_options(radius_m, balance_factor, orders, rotor, max_order, offsets)
    engines = _load_all(files, speed)
    # counterweights are proposed for one crankshaft (alone, an engine with several is an
    # error that says why)
    engines = _passed_over(engines, lambda e: not e.has_several_crankshafts,
                           lambda e: f"{len(e.crankshafts)} crankshafts; counterweights are "
                                     "proposed for an engine with one",
                           "every engine here has several crankshafts; counterweights are "
                           "proposed for an engine with one")

    def work(engine):
        return counterweights(engine, plane_specs, radius_m, balance_factor, orders, rotor,
                              test_masses, samples, max_order, offsets)

    balances = _run_each(engines, "Balancing", work)
    scale = Scale.of(absolute, units)
    if fmt == "json":
        text = to_json(Balances(tuple(balances)).to_dict())
    elif fmt == "csv":
        text = balance_csv(balances, scale)
    else:
        text = balance_tables(balances, scale, fmt)
    configuration = None
    if write_path is not None:
        # built before anything is written: a failure leaves no file and no report half done
        with _reported(balances[0].engine):
            configuration = as_built_toml(
                load_data(files[0]), balances[0].configuration_tables(shafts=bool(orders)),
                f"{balances[0].engine.name}, with the counterweights{' and shafts' if orders else ''}"
                f" proposed by\nbalance counterweight added as built (from {files[0]}).")
    if configuration is not None:
        _write(write_path, configuration)
    _write(output, text)


def _use_agg():
    """Draw without a display: the command line's choice of backend, not the library's."""
    import matplotlib

    matplotlib.use("Agg")


@contextlib.contextmanager
def _drawing():
    """matplotlib warns once per character its font lacks (a name in Chinese, an emoji):
    one line says so instead."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.filterwarnings("always", message=r"Glyph \d+ .*missing from font")
        yield
    missing = [w for w in caught if "missing from font" in str(w.message)]
    if missing:
        click.echo(f"warning: the pictures' font lacks {len(missing)} characters of the engine "
                   "names; they are drawn as boxes", err=True)
    for w in caught:
        if w not in missing:
            warnings.showwarning(w.message, w.category, w.filename, w.lineno)


@main.command()
@_INPUTS
@click.option("--kind", type=click.Choice(["locus", "spectrum", "star", "firing", "torque"]),
              required=True,
              help="locus: resultant force per cylinder (or free moment: --of moment) over a "
                   "revolution (Tanaka's Fig. 9); spectrum: forward and backward parts by order; "
                   "star: each cylinder's phasor of one order (of force or moment), chained; firing: firing angles on a dial; torque: inertia, gas "
                   "(from a [gas] table) and total torque over a cycle, and the orders of the total.")
@click.option("--output", "-o", required=True, metavar="PATH",
              help="Picture file; its extension gives the format: .png, .svg, .svgz, .pdf, .eps, "
                   ".ps, .jpg, .jpeg, .tif, .tiff, .webp. Folders are created.")
@click.option("--order", type=click.IntRange(1), default=None,
              help="locus: one order only (default all); star: the order drawn (default 2).")
@click.option("--of", "quantity", type=click.Choice(["force", "moment"]), default=None,
              help="locus and star: the resultant force (the default) or the free moment "
                   "about the engine's mid-length, N·m.")
@click.option("--units", type=_Units(["per-cylinder"]), default=None,
              help="spectrum: units of the forces, default per-cylinder (N, kN, MN, kgf or lbf also "
                   "put moments in N·m, kN·m, MN·m, kgf·m or lbf·ft); torque: N (N·m, the "
                   "default), kN, MN, kgf or lbf.")
@_SAMPLES
@_MAX_ORDER
@_SPEED
def plot(paths, kind, output, order, quantity, units, samples, max_order, speed):
    """Draw a picture of one or more engines (headless)."""
    if units is not None and kind not in ("spectrum", "torque"):
        raise click.UsageError(f"--units applies to --kind spectrum and torque only, not {kind}")
    if units == "per-cylinder" and kind == "torque":
        raise click.UsageError("--units per-cylinder applies to --kind spectrum only; torques "
                               "are drawn in N·m (N) or kgf·m (kgf)")
    if order is not None and kind not in ("locus", "star"):
        raise click.UsageError(f"--order applies to --kind locus and star only, not {kind}")
    if quantity is not None and kind not in ("locus", "star"):
        raise click.UsageError(f"--of applies to --kind locus and star only, not {kind}")
    files = _inputs(paths)
    _guard([output], files)
    _settings(samples, max_order)
    if order is not None and order > max_order:
        raise click.ClickException(f"--order {order} is above --max-order {max_order}")
    _use_agg()
    from .. import plot as drawing  # matplotlib only for commands that draw

    with _reported():
        drawing.format_of(output)
    engines = _load_all(files, speed)
    if kind == "torque":
        from ..analysis.torque import torque as torque_of

        # the picture draws the torques only
        results = _run_each(engines, "Torques", lambda e: torque_of(
            e, samples, max_order, bearings=False, guide=False))
    else:
        results = _analyse_all(engines, samples, max_order)
    with _reported(), _drawing():
        if kind == "locus":
            figure = drawing.locus(results, order, of=quantity or "force")
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
@_INPUTS
@click.option("--output", "-o", required=True, metavar="DIR",
              help="Folder for report.md and its pictures (created if needed).")
@click.option("--html", "with_html", is_flag=True,
              help="Also write report.html: one self-contained page, pictures inlined as SVG.")
@click.option("--reference", default=None, metavar="NAME",
              help="Engine the percentages refer to (name or unique prefix); default the first.")
@click.option("--star-order", default=None, type=click.IntRange(1),
              help="Order drawn in the star diagram  [default: 2, or 1 with --max-order 1].")
@_SAMPLES
@_MAX_ORDER
@click.option("--units", type=_UNIT_CHOICE, default="N", show_default=True,
              help="Units of moments and torques (and of forces other than the per-cylinder "
                   "comparison): N, kN, MN, kgf or lbf with N·m, kN·m, MN·m, kgf·m or lbf·ft.")
@_SPEED
@click.option("--family", "family_path", default=None, metavar="FILE.toml",
              help="Also a section with the project-guide table of this engine family (as "
                   "balance family, with --family-cylinders).")
@click.option("--family-cylinders", default="5-12", show_default=True, metavar="N-M",
              help="The numbers of cylinders of --family.")
def report(paths, output, with_html, reference, star_order, samples, max_order, units, speed,
           family_path, family_cylinders):
    """Write a comparison report: tables, counterweights, torques and pictures (Markdown,
    optionally HTML).

    The files are written into DIR all at once at the end; files of the same names already in
    DIR are replaced, others are left alone.
    """
    files = _inputs(paths)
    _use_agg()
    from ..report.folder import REPORT_FILES, write_report

    with _reported():
        check_folder(output)   # the text given: Path("") would be the current folder
    target = Path(output)
    _guard([target] + [target / name for name in REPORT_FILES], files)
    _settings(samples, max_order)
    star_order = min(2, max_order) if star_order is None else star_order
    if star_order > max_order:
        raise click.ClickException(f"--star-order {star_order} is above --max-order {max_order}")
    results = _analyse_all(_load_all(files, speed), samples, max_order)
    with _reported():
        comparison = comparison_of(results, reference)
    # counterweights are proposed for one crankshaft; the report names the engines left out
    balances = _run_each([r for r in results if not r.engine.has_several_crankshafts],
                         "Balancing", counterweights)
    from ..analysis.torque import torque as torque_of

    # the report shows no bearing forces: leaving them out halves the work
    torques = _run_each([r.engine for r in results], "Torques",
                        lambda e: torque_of(e, samples, max_order, bearings=False, guide=False))
    family_table = None
    if family_path is not None:
        from ..config import load_data
        from ..studies.family import family

        with _reported(flags={"cylinders": "--family-cylinders", "template": family_path}):
            family_table = family(load_data(family_path), str(family_path),
                                  _counts_option(family_cylinders), samples=samples,
                                  max_order=max_order)
    torsion = None
    if any(r.engine.torsion is not None for r in results):
        from ..torsion import TorsionUnavailable, require_opentorsion, torsion as torsion_of

        try:
            require_opentorsion()
        except TorsionUnavailable as exc:
            torsion = f"Not computed: {exc}."
        else:
            torsion = _run_each([r.engine for r in results if r.engine.torsion is not None],
                                "Torsion", torsion_of)
    with _reported(), _drawing():
        written = write_report(target, comparison, balances, star_order, with_html, torques,
                               Scale.of(False, units), family_table, torsion)
    for path in written:
        click.echo(f"wrote {path}", err=True)


def _quantity_option(text, flag, dimension):
    if text is None:
        return None
    try:
        value = parse_quantity(text, dimension)
    except BalanceError as exc:
        raise click.ClickException(f"{flag}: {exc}") from None
    if not value > 0:
        raise click.ClickException(f"{flag}: must be greater than zero, got {text!r}")
    return value


_LOAD = click.option("--load", type=click.Choice(["propeller", "constant"]), default="propeller",
                     show_default=True,
                     help="What the engine drives: a propeller (torque ℓ·ω², ℓ = C_m/ω_m²) or a "
                          "constant torque C_m.")


@main.command()
@_INPUTS
@click.option("--pressure", metavar="FILE.csv",
              help="Cylinder pressure over one cycle from the firing top dead centre: a header "
                   "angle_deg,pressure_bar (or another pressure unit), one row per angle; the same "
                   "curve for every cylinder at its own firing angle. Default: the configuration's "
                   "[gas] cycle, if it has one.")
@click.option("--bore", metavar="LENGTH", help="Cylinder bore for --pressure, e.g. '154 mm' "
                                               "(default the [gas] bore).")
@click.option("--inertia", metavar="I", help="Flywheel and propeller inertia, e.g. '2.5 kg*m^2': "
                                             "integrate the speed over the cycle and give the "
                                             "steadiness (needs a gas torque).")
@click.option("--target", type=float, metavar="R",
              help="Also give the flywheel inertia that reaches steadiness R.")
@_LOAD
@_SAMPLES
@_MAX_ORDER
@click.option("--units", type=_UNIT_CHOICE, default="N", show_default=True,
              help="Units of torques (N·m, kN·m, MN·m, kgf·m or lbf·ft) and forces (N, kN, MN, "
                   "kgf or lbf) in the tables; JSON stays SI.")
@_SPEED
@click.option("--format", "fmt", type=click.Choice(["table", "markdown", "csv", "json"]),
              default="table", show_default=True, help="Output format.")
@_OUTPUT
def torque(paths, pressure, bore, inertia, target, load, samples, max_order, units, speed, fmt,
           output):
    """Torques at constant speed: inertia, gas, total, the rods' tilting couple and the frame
    reaction, order by order; the reduced mass; the forces on the crank pins and main bearings.

    With --inertia (or --target), the speed over the cycle with a flywheel and a load, and its
    steadiness (Margoulis).
    """
    from ..analysis.gas import read_pressure_csv
    from ..analysis.torque import TorqueSet, torque as torque_of

    if bore is not None and pressure is None:
        raise click.UsageError("--bore applies with --pressure only (a [gas] table gives its own bore)")
    if fmt == "csv" and (inertia is not None or target is not None):
        raise click.UsageError("the steadiness of --inertia and --target is written by --format "
                               "table, markdown and json, not csv")
    files = _inputs(paths)
    inputs = files + ([Path(pressure)] if pressure else [])
    _guard([output], inputs)
    _settings(samples, max_order)
    bore_m = _quantity_option(bore, "--bore", "length")
    inertia_kgm2 = _quantity_option(inertia, "--inertia", "moment of inertia")
    engines = _load_all(files, speed)
    curve = None
    if pressure is not None:
        with _reported():
            # the cycle the file spans; an engine of the other cycle is refused by name
            curve = read_pressure_csv(pressure, None)

    def work(engine):
        return torque_of(engine, samples, max_order, curve, bore_m, inertia_kgm2, load, target)

    results = _run_each(engines, "Torques", work)
    scale = Scale.of(True, units)
    if fmt == "json":
        text = to_json(TorqueSet(tuple(results)).to_dict())
    elif fmt == "csv":
        text = torque_csv(results, scale)
    else:
        text = torque_tables(results, scale, fmt)
    _write(output, text)


def _speeds_option(text):
    """--speeds FROM:TO:STEP (rpm, both ends included) or a comma-separated list; None for
    the default (20 % to 120 % of each engine's speed)."""
    if text is None:
        return None
    from ..torsion import MAX_SPEEDS

    try:
        if ":" in text:
            start, stop, step = (float(t) for t in text.split(":"))
            if not all(map(math.isfinite, (start, stop, step))) or not step > 0 \
                    or not 0 < start <= stop or not 1e-3 <= start and stop <= 1e6:
                raise ValueError
            count = int(np.floor((stop - start) / step + 1e-9)) + 1
            if count > MAX_SPEEDS:
                raise ValueError
            return start + step * np.arange(count)
        values = np.array([float(t) for t in text.split(",")])
        if not np.all(np.isfinite(values)) or np.any(values < 1e-3) or np.any(values > 1e6) \
                or values.size > MAX_SPEEDS:
            raise ValueError
        return values
    except (ValueError, OverflowError):
        raise click.BadParameter(f"expected FROM:TO:STEP in rpm (0.001 <= FROM <= TO <= 1e6, "
                                 f"STEP > 0, at most {MAX_SPEEDS} speeds) such as 600:2400:25, or "
                                 f"a list such as 1000,1500, got {text!r}",
                                 param_hint="--speeds") from None


@main.command()
@_INPUTS
@click.option("--speeds", default=None, metavar="FROM:TO:STEP",
              help="Engine speeds of the forced response, rpm: a range with its step (both ends "
                   "included, e.g. 600:2400:25) or a comma-separated list. Default: 201 speeds "
                   "from 20 % to 120 % of each engine's speed.")
@click.option("--max-order", default=12, show_default=True, type=click.IntRange(1, 64),
              help="Highest order of the excitation (half orders too for a four-stroke).")
@_SAMPLES
@click.option("--format", "fmt", type=click.Choice(["table", "markdown", "csv", "json"]),
              default="table", show_default=True, help="Output format.")
@_OUTPUT
@click.option("--plot", "plot_dir", default=None, metavar="DIR",
              help="Also draw, per engine, NAME-campbell.png (Campbell diagram with the "
                   "criticals), NAME-modes.png (mode shapes) and NAME-torque.png (vibratory "
                   "torque against speed per section) into DIR; NAME is the file's stem.")
@_UNITS
def torsion(paths, speeds, max_order, samples, fmt, output, plot_dir, units):
    """Torsional vibration of the crankshaft (needs openTorsion: pip install
    'balance[torsion]'): natural frequencies and mode shapes of the [torsion] model, the
    phase-vector sums of the firing order, the criticals within --speeds, and the vibratory
    torque (and shear stress, with a shaft diameter) in every section against speed.

    The excitation is each cylinder's exact gas ([gas] table) and inertia torque, order by
    order, at its throw: the gas torque the same at every speed, the inertia torque growing
    as the speed squared.
    """
    from ..torsion import require_opentorsion, torsion as torsion_of

    with _reported():
        require_opentorsion()   # before any work, and not tied to one file
    speeds_rpm = _speeds_option(speeds)
    files = _inputs(paths)
    _guard([output], files)
    _settings(samples, max_order)
    engines = _load_all(files)
    # a folder holds engines without a shaft line (alone, one is an error that says why)
    engines = _passed_over(engines, lambda e: e.torsion is not None,
                           lambda e: "no [torsion] table",
                           "none of these engines has a [torsion] table (the shaft line's "
                           "inertias and stiffnesses); see the README, Torsional vibration")
    files = [Path(e.config_path) for e in engines]
    if plot_dir is not None:
        # pictures are named after the files: two of one name would overwrite each other, and
        # --output into the folder would replace a picture with the tables
        stems = [Path(f).stem for f in files]
        twice = sorted({s for s in stems if stems.count(s) > 1})
        if twice:
            raise click.BadParameter(f"names pictures after the files, and {twice[0]}.toml is "
                                     "given twice (from different folders); draw them one at a "
                                     "time or rename one", param_hint="--plot")
        if output not in (None, "-") and Path(output).resolve().parent == Path(plot_dir).resolve():
            pictures_named = {f"{s}-{k}.png" for s in stems for k in ("campbell", "modes", "torque")}
            if Path(output).name in pictures_named:
                raise click.BadParameter(f"{output} is one of the pictures --plot draws; write "
                                         "the tables elsewhere", param_hint="--output")
    results = _run_each(engines, "Torsion", lambda e: torsion_of(e, speeds_rpm, max_order,
                                                                 samples))
    from ..report.torsion import torsion_csv, torsion_tables

    scale = Scale.of(False, units)

    if fmt == "json":
        text = to_json({"balance_version": DOCUMENT_VERSION, "max_order": max_order,
                        "engines": [r.to_dict() for r in results]})
    elif fmt == "csv":
        text = torsion_csv(results, scale)
    else:
        text = torsion_tables(results, fmt, scale)
    if plot_dir is not None:
        _use_agg()
        from .. import plot as pictures

        def fill(folder):
            names = []
            for file, result in zip(files, results):
                for kind, draw in (("campbell", pictures.campbell), ("modes", pictures.mode_shapes),
                                   ("torque", lambda r: pictures.torque_speed(r, scale=scale))):
                    name = f"{Path(file).stem}-{kind}.png"
                    draw(result).savefig(folder / name, dpi=120)
                    names.append(name)
            return names

        with _reported(), _drawing():
            written = write_folder(plot_dir, fill)
        for path in written:
            click.echo(f"wrote {path}", err=True)
    _write(output, text)


@main.command()
@click.option("--torque", "torque_file", required=True, metavar="FILE.csv",
              help="Driving torque over one cycle: a header angle_deg,torque_Nm (or another "
                   "torque unit), one row per crank angle; the cycle is 360° or 720° as the "
                   "angles span.")
@click.option("--inertia", required=True, metavar="I",
              help="Flywheel and propeller inertia with the engine's moving parts, e.g. "
                   "'2.5 kg*m^2'.")
@click.option("--speed", required=True, metavar="SPEED", help="Mean speed, e.g. '1650 rpm'.")
@_LOAD
@click.option("--target", type=float, metavar="R",
              help="Also give the inertia that reaches steadiness R.")
@click.option("--format", "fmt", type=click.Choice(["table", "markdown", "json"]), default="table",
              show_default=True, help="Output format.")
@_OUTPUT
def steadiness(torque_file, inertia, speed, load, target, fmt, output):
    """Speed fluctuation of an engine set driven by a measured torque curve: the periodic speed,
    the steadiness ω_m/(ω_max − ω_min), and Margoulis's closed forms r_c, r_v, r_h."""
    from ..analysis.gas import read_cycle_csv
    from ..analysis.steadiness import flywheel_for, steadiness as steadiness_of

    _guard([output], [Path(torque_file)])
    inertia_kgm2 = _quantity_option(inertia, "--inertia", "moment of inertia")
    speed_rad_s = _quantity_option(speed, "--speed", "angular speed")
    with _reported(flags={"torque_nm": f"--torque {torque_file}"}):
        angles, values, cycle = read_cycle_csv(torque_file, "torque")
        # an even grid for the integration, the curve linear between the file's points
        grid = np.arange(4096) * cycle / 4096
        torque_nm = np.interp(grid, angles, values, period=cycle)
        speed = steadiness_of(torque_nm, cycle, inertia_kgm2, speed_rad_s, load)
        flywheel = None if target is None else flywheel_for(target, torque_nm, cycle, speed_rad_s,
                                                            load)
    document = {"balance_version": 1, "torque_file": str(torque_file), "cycle_deg": cycle,
                **speed.to_dict(), "inertia_for_target_kgm2": flywheel}
    if fmt == "json":
        text = to_json(document)
    else:
        text = steadiness_text(speed, flywheel) + "\n"
    _write(output, text)


def _read_baseline(path):
    """The baseline document, checked; one RegressError line for anything else."""
    try:
        text = Path(path).read_text(encoding="utf-8")
    except FileNotFoundError:
        raise RegressError(f"{path}: no such file; write a baseline with balance compare FILE|DIR "
                           "--format json -o BASELINE.json") from None
    except (OSError, UnicodeDecodeError) as exc:
        raise RegressError(f"{path}: cannot read the file ({getattr(exc, 'strerror', None) or exc})") from None
    try:
        document = json.loads(text)
    except (json.JSONDecodeError, RecursionError, ValueError) as exc:
        # ValueError: an integer of thousands of digits; RecursionError: nesting without end
        reason = exc if isinstance(exc, json.JSONDecodeError) else "not a document balance wrote"
        raise RegressError(f"{path}: not JSON that balance can read ({reason}); give what "
                           "balance compare --format json wrote") from None
    check_baseline(document, path)
    return document


@main.command()
@click.argument("baseline", metavar="BASELINE.json")
@click.argument("paths", nargs=-1, metavar="[FILE|DIR...]")
@click.option("--rtol", type=float, default=0.0, show_default=True, metavar="R",
              help="Loosen the tolerances: a force, moment or resultant may move by R times its "
                   "baseline value, an angle by R radians (0 to below 1).")
@click.option("--update", is_flag=True,
              help="Rewrite BASELINE.json (atomically) with the engines as they are now, after "
                   "printing what changed; exit status 0.")
@click.option("--format", "fmt", type=click.Choice(["table", "markdown", "json", "junit"]),
              default="table", show_default=True,
              help="markdown suits a CI job summary; junit is JUnit XML for CI test reports.")
@click.option("--units", type=_UNIT_CHOICE, default="N", show_default=True,
              help="Units of the forces and moments in the table (N, kN, MN, kgf or lbf with "
                   "N·m, ...); JSON and JUnit stay SI.")
@_OUTPUT
def regress(baseline, paths, rtol, update, fmt, units, output):
    """Check engines against a baseline comparison: exit status 1 when anything moved.

    BASELINE.json is what `balance compare --format json` wrote; the engines are analysed again
    with its samples and orders. FILE|DIR... are the configurations to check (default: the
    ones the baseline names); engines are matched by name, and a baseline engine that is not
    among them counts as removed, one not in the baseline as added. Forces and moments may
    move by 1e-9 of each engine's m_rec·r·ω²·n, phases by 1e-6° (where the phasor is above
    1e-6 of it), firing angles by 1e-4°. Exit status: 0 nothing moved, 1 something moved (or
    an error), 2 a usage error.
    """
    with _reported():
        document = _read_baseline(baseline)
        files = find_configs(paths) if paths else baseline_configs(document, baseline)
        refuse_inputs([output], files + [Path(baseline)])
        check_rtol(rtol)
    _settings(document["samples"], document["max_order"])
    override = document.get("speed_override_rpm")
    engines = _load_all(files, None if override is None else f"{override!r} rpm")
    results = _analyse_all(engines, document["samples"], document["max_order"])
    with _reported():
        comparison = compared_like(document, results)
        regression = regression_of(document, comparison, rtol, str(baseline))
    if fmt == "json":
        text = to_json(regression.to_dict())
    elif fmt == "junit":
        text = junit_xml(regression)
    else:
        text = regression_tables(regression, fmt, Scale.of(True, units))
    _write(output, text)
    if update:
        _write(baseline, to_json(_compare_document(comparison, engines if override else None)))
        click.echo(f"wrote {baseline}", err=True)
        return
    if regression.moved:
        raise SystemExit(1)


_SEARCH_FLAGS = {"objective": "--objective", "top": "--top", "step_deg": "--step",
                 "workers": "--workers", "scheduler": "--scheduler", "limit": "--limit",
                 "restarts": "--restarts", "seed": "--seed", "template": "the template"}
#: library words inside the search's messages, in the command line's terms
_SEARCH_WORDS = {"allow_uneven": "--allow-uneven", "step_deg": "--step", "max_order": "--max-order",
                 "heuristic search": "heuristic search (--heuristic)",
                 "cluster scheduler": "cluster (--scheduler)"}


@contextlib.contextmanager
def _search_reported(engine):
    try:
        yield
    except BalanceError as exc:
        text = _message(exc, engine, _SEARCH_FLAGS)
        for word, flag in _SEARCH_WORDS.items():
            text = re.sub(rf"\b{re.escape(word)}\b", flag, text)
        raise click.ClickException(text) from None


def _same_path(a, b):
    try:
        return Path(a).resolve() == Path(b).resolve()
    except OSError:
        return False


def _search_progress():
    """A progress bar on standard error when it is a terminal: (callback, bar or None)."""
    if not sys.stderr.isatty():
        return None, contextlib.nullcontext()
    state: dict = {}

    def update(done, total):
        if "bar" not in state:
            state["bar"] = click.progressbar(length=total, label="Searching", file=sys.stderr)
            state["bar"].__enter__()
        state["bar"].update(done - state["bar"].pos)

    @contextlib.contextmanager
    def closing():
        try:
            yield
        finally:
            if "bar" in state:
                state["bar"].__exit__(None, None, None)

    return update, closing()


@main.command()
@click.argument("template_path", metavar="TEMPLATE.toml")
@click.option("--objective", default=None, metavar="TERMS",
              help="What to minimise: coefficients such as M1,M2 or F2:4,M1,M2,X4 (F force, M "
                   "moment, H and X the H- and X-type guide-force moments, the order, + or - for "
                   "a force's or moment's forward or backward part only, :weight, default 1). "
                   "Default: every F_k and M_k up to --max-order.")
@click.option("--top", default=10, show_default=True, type=int, metavar="K",
              help="How many arrangements to list (ties ranked by firing order).")
@click.option("--allow-uneven", is_flag=True,
              help="Search every crank on a grid of --step degrees, firing evenly or not.")
@click.option("--step", "step", default=None, type=float, metavar="DEG",
              help="The phase grid of --allow-uneven, in degrees (a divisor of 360 such as 30).")
@click.option("--workers", default=None, type=int, metavar="N",
              help="Processes to use [default: every core].")
@click.option("--scheduler", default=None, metavar="ADDRESS",
              help="Run on a Dask distributed cluster (tcp://host:8786) instead; needs "
                   "pip install 'balance[cluster]'.")
@click.option("--heuristic", is_flag=True,
              help="A local search from random cranks for templates too large to enumerate: "
                   "the best found, NOT proved optimal.")
@click.option("--restarts", default=200, show_default=True, type=int, metavar="N",
              help="Random starts of --heuristic.")
@click.option("--seed", default=0, show_default=True, type=int, help="Random seed of --heuristic.")
@click.option("--limit", default=None, type=int, metavar="N",
              help="Refuse an exhaustive search evaluating more cranks than this "
                   "[default: 2e9, about a minute on two cores].")
@_SAMPLES
@_MAX_ORDER
@_UNITS
@_SPEED
@_FORMAT
@_OUTPUT
@click.option("--write", "write_dir", default=None, metavar="DIR",
              help="Also write each listed arrangement as a complete configuration "
                   "(DIR/arrangement-01.toml, ...), for compare, counterweight and plot.")
def search(template_path, objective, top, allow_uneven, step, workers, scheduler, heuristic,
           restarts, seed, limit, samples, max_order, units, speed, fmt, output, write_dir):
    """Find the crank arrangements and firing orders that leave the least of what you ask.

    TEMPLATE.toml is an ordinary configuration whose [[throws]] give only z (no phase) and
    which has no firing_order. Throw 1 stays at 0°; arrangements that are the same engine run
    the other way round count once; mirror images (the crank read from the other end) balance
    alike and are listed, but evaluated once. Without --heuristic the result is exhaustive:
    nothing scores better than what is listed.
    """
    from ..config import arrangement_toml, load_template
    from ..cranksearch import DEFAULT_LIMIT
    from ..cranksearch import search as search_of

    with _reported():
        refuse_inputs([output], [Path(template_path)])
        template, data = load_template(template_path)
        if write_dir is not None:
            check_folder(write_dir, "--write")
            # the files --write may write must replace neither the template nor --output
            planned = [Path(write_dir) / f"arrangement-{k:02d}.toml" for k in range(1, max(top, 1) + 1)]
            refuse_inputs(planned, [Path(template_path)])
            if output not in (None, "-") and any(_same_path(output, p) for p in planned):
                raise OutputError(f"{output!r} is one of the files --write writes; write the "
                                  "table somewhere else")
    _settings(samples, max_order)
    speed_rad_s = _quantity_option(speed, "--speed", "angular speed")
    if speed_rad_s is not None:
        with _reported(template):
            template = template.replace(speed_rad_s=speed_rad_s)
        # the configurations --write writes are at the speed analysed
        data = {**data, "speed": speed}
    callback, bar = _search_progress()
    with _search_reported(template), bar:
        result = search_of(template, objective, top=top, allow_uneven=allow_uneven,
                           step_deg=step, workers=workers, scheduler=scheduler,
                           heuristic=heuristic, restarts=restarts, seed=seed,
                           limit=DEFAULT_LIMIT if limit is None else limit, samples=samples,
                           max_order=max_order, progress=callback)
    if fmt == "json":
        text = to_json(result.to_dict())
    elif fmt == "csv":
        text = search_csv(result)
    else:
        with _reported():
            comparison = (comparison_of([a.result for a in result.arrangements])
                          if result.arrangements else None)
        text = search_tables(result, comparison, Scale.of(False, units), fmt)
    if write_dir is None:
        _write(output, text)
        return

    def fill(folder):
        # --output is written last inside the folder's transaction: if it fails, the folder
        # is not written either
        names = []
        for a in result.arrangements:
            name = f"arrangement-{a.rank:02d}.toml"
            header = (f"written by balance search from {template_path}, rank {a.rank} of "
                      f"{len(result.arrangements)}\nobjective "
                      f"{', '.join(str(t) for t in result.objective)}: score {a.score:.6g}"
                      + ("" if result.exhaustive else " (heuristic, not proved optimal)"))
            (folder / name).write_text(arrangement_toml(
                data, a.phases_deg, a.engine.firing_order, a.engine.name, header),
                encoding="utf-8")
            names.append(name)
        write_text(output, text)
        return names

    with _reported():
        write_folder(write_dir, fill)


@main.command()
@click.argument("path", metavar="FILE")
@click.option("--vary", "parameter", required=True, metavar="PARAM",
              help="The configuration key to vary, as written in the file: speed, crank_radius, "
                   "rod_length, pin_offset, masses.rotating, banks[2].angle, throws[3].phase, "
                   "throws[2].z, gas.imep, cylinders[4].reciprocating, ... (any number of the "
                   "file; a key the format allows may be added), or balance_factor (classic "
                   "per-throw counterweights of that factor, 0 to 1).")
@click.option("--from", "start", metavar="A", help="First value, as in the file: '140 mm', "
                                                    "'3000 rpm', or a plain number for angles and ratios.")
@click.option("--to", "stop", metavar="B", help="Last value (in any unit of the same kind).")
@click.option("--steps", type=int, metavar="N", help="Values from --from to --to, both included (2 or more).")
@click.option("--values", "listed", metavar="a,b,c", help="The values instead, comma-separated: "
                                                            "'140 mm,150 mm,170 mm'.")
@click.option("--quantity", "quantities", metavar="Q[,Q...]",
              help="What to report: F<k> (order-k force, its ellipse's max), F<k>V, F<k>H "
                   "(vertical, horizontal amplitude), F<k>+, F<k>- (forward, backward), the same "
                   "with M for free moments (M1V pitching, M1H yawing); largest_force, "
                   "largest_moment (after an ideal counterweight); torque_mean, torque_max, "
                   "torque_min, torque_range (ΔC of the total torque); steadiness (needs "
                   "--inertia and a [gas] table). Default: largest_force,largest_moment.")
@click.option("--inertia", metavar="I", help="Flywheel inertia for steadiness, e.g. '2.5 kg*m^2'.")
@_LOAD
@click.option("--speed", metavar="SPEED", help="Speed of every point instead of the file's, e.g. "
                                               "'3000 rpm' (not with --vary speed).")
@click.option("--units", type=_UNIT_CHOICE,
              default="N", show_default=True,
              help="Table and picture units: N, kN, MN, kgf or lbf for forces, and N·m, kN·m, MN·m, "
                   "kgf·m or lbf·ft for moments and torques; JSON and CSV stay SI.")
@_SAMPLES
@_MAX_ORDER
@_FORMAT
@_OUTPUT
@click.option("--plot", "picture", metavar="FILE.png|svg|pdf",
              help="Also draw the quantities against the parameter into this picture.")
def sweep(path, parameter, start, stop, steps, listed, quantities, inertia, load, speed, units,
          samples, max_order, fmt, output, picture):
    """Analyse one engine again and again with one value of its configuration changed.

    Each value is set in the file's TOML and the engine rebuilt and checked exactly as a file
    is, so a value that makes no engine is reported with the file, the key and the value.
    """
    from ..report.sweeps import sweep_csv, sweep_tables
    from ..studies.sweep import span, sweep as sweep_of

    spanned = (start, stop, steps)
    if listed is not None and any(v is not None for v in spanned):
        raise click.UsageError("give --values or --from/--to/--steps, not both")
    if listed is None and any(v is None for v in spanned):
        missing = [flag for flag, v in zip(("--from", "--to", "--steps"), spanned) if v is None]
        raise click.UsageError(f"give --values, or --from, --to and --steps ({', '.join(missing)} "
                               "missing)")
    flags = {"parameter": "--vary", "values": "--values", "quantities": "--quantity",
             "start": "--from", "stop": "--to", "steps": "--steps", "inertia_kgm2": "--inertia",
             "overrides": "--speed"}
    if speed is not None and parameter.strip() == "speed":
        raise click.UsageError("--speed fixes the speed that --vary speed varies; give one of them")
    outputs = [output] + ([picture] if picture else [])
    _guard(outputs, [Path(path)])
    if picture is not None and output not in (None, "-") and _same_path(output, picture):
        raise click.ClickException(f"--plot and --output both name {picture!r}; give two files")
    _settings(samples, max_order)
    inertia_kgm2 = _quantity_option(inertia, "--inertia", "moment of inertia")
    _quantity_option(speed, "--speed", "angular speed")   # its unit, in the option's words
    drawing = None
    if picture is not None:
        _use_agg()
        from .. import plot as drawing   # matplotlib only when a picture is asked for

        with _reported(flags={"path": "--plot"}):
            drawing.format_of(picture)
    with _reported(flags=flags):
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
            with _reported(flags=flags):
                result = sweep_of(path, parameter, values, quantities, samples, max_order,
                                  inertia_kgm2=inertia_kgm2, load=load, progress=progress,
                                  overrides=None if speed is None else {"speed": speed})
        finally:
            if "bar" in state:
                state["bar"].__exit__(None, None, None)
            # one line per distinct sampling warning, not one per point; others as they came
            for text in dict.fromkeys(str(w.message) for w in caught
                                      if issubclass(w.category, SamplingWarning)):
                click.echo(f"warning: {text} (--samples)", err=True)
            for w in caught:
                if not issubclass(w.category, SamplingWarning):
                    warnings.showwarning(w.message, w.category, w.filename, w.lineno)
    if fmt == "json":
        text = to_json(result.to_dict())
    elif fmt == "csv":
        text = sweep_csv(result)
    else:
        text = sweep_tables(result, fmt, units)
    if drawing is not None:
        with _reported(flags={"path": "--plot"}), _drawing():
            drawing.save(drawing.sweep_figure(result, units), picture)
    _write(output, text)
    if drawing is not None:
        click.echo(f"wrote {picture}", err=True)


def _counts_option(text):
    """--cylinders: "5-12", "6,7,8" or both."""
    counts = []
    try:
        for token in text.split(","):
            low, _, high = token.strip().partition("-")
            low, high = int(low), int(high or low)
            if high < low:
                raise click.BadParameter(f"{token.strip()!r} runs backwards: write the smaller "
                                         f"number first ({high}-{low})", param_hint="--cylinders")
            counts += range(low, high + 1)
    except ValueError:
        raise click.BadParameter(f"{text!r}: give numbers of cylinders such as 5-12 or 6,7,8",
                                 param_hint="--cylinders") from None
    return counts


def _firing_orders_option(values):
    """--firing-order N:1-5-3-4-2-6, repeatable."""
    orders = {}
    for value in values:
        count, _, order = value.partition(":")
        try:
            n = int(count)
            cylinders = [int(c) for c in order.replace(",", "-").split("-")]
        except ValueError:
            raise click.BadParameter(f"{value!r}: write the number of cylinders and the order, "
                                     "such as 6:1-5-3-4-2-6", param_hint="--firing-order") from None
        if n in orders:
            raise click.BadParameter(f"{n} cylinders are given twice; give one firing order for "
                                     "each number of cylinders", param_hint="--firing-order")
        orders[n] = cylinders
    return orders


@main.command("family")
@click.argument("path", metavar="FILE.toml")
@click.option("--cylinders", "counts", default="5-12", show_default=True, metavar="N-M|N,M,...",
              help="The numbers of cylinders of the family (2 to 24).")
@click.option("--objective", default=None, metavar="TERMS",
              help="What each firing order minimises, as for balance search (M1,M2, X4, "
                   "F2:4, ...)  [default: the first-order couple left with the rotating masses "
                   "balanced plus the second-order couple, in N·m: M1-:w,M2].")
@click.option("--firing-order", "firing_orders", multiple=True, metavar="N:ORDER",
              help="Take this firing order for N cylinders instead of searching, e.g. "
                   "6:1-5-3-4-2-6 (two-stroke, even firing). Repeatable.")
@click.option("--pitch", default=None, metavar="LENGTH",
              help="Cylinder pitch, e.g. '1020 mm'  [default: the file's mean throw pitch].")
@click.option("--power-per-cylinder", "power", default=None, metavar="POWER",
              help="Power of one cylinder at the file's speed, e.g. '2380 kW'  [default: the "
                   "file's power over its cylinders].")
@click.option("--workers", default=None, type=int, metavar="N",
              help="Processes for the searches [default: every core].")
@_SAMPLES
@_MAX_ORDER
@_UNITS
@_FORMAT
@_OUTPUT
def family_(path, counts, objective, firing_orders, pitch, power, workers, samples, max_order,
            units, fmt, output):
    """A project-guide table of an engine family: for each number of cylinders, the firing
    order (proved best for the objective, or given), the external moments M1V, M1H, M2V, M2H,
    their power related unbalance and class, the largest H- and X-type guide-force moments
    and whether a second-order compensator is indicated.

    FILE.toml is a configuration or search template of the family's in-line engine: one
    cylinder's data repeated at the pitch (its throws' phases and firing order are not used).
    """
    from ..config import load_data
    from ..studies.family import family
    from ..report.tables import family_tables

    counts = _counts_option(counts)
    given = _firing_orders_option(firing_orders)
    _guard([output], [Path(path)])
    _settings(samples, max_order)
    pitch_m = _quantity_option(pitch, "--pitch", "length")
    power_w = _quantity_option(power, "--power-per-cylinder", "power")
    flags = {"cylinders": "--cylinders", "pitch_m": "--pitch", "firing_orders": "--firing-order",
             "objective": "--objective", "workers": "--workers", "template": path}
    callback, bar = _search_progress()
    with _reported():
        data = load_data(path)
    with _reported(flags=flags), bar:
        result = family(data, str(path), counts, objective, pitch_m, power_w, given, samples,
                        max_order, workers, progress=callback)
    if fmt == "json":
        text = to_json(result.to_dict())
    elif fmt == "csv":
        from ..report.csvfile import family_csv

        text = family_csv(result)
    else:
        text = family_tables(result, Scale.of(True, units), fmt)
    _write(output, text)


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
