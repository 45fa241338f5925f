"""Looking at configurations without analysing them: validate, list and show."""

from pathlib import Path
from typing import TYPE_CHECKING

import click

from ..analysis.firing import firing_sequence
from ..config import build, load, parse_text, read_provenance, read_text
from ..config.library import LIBRARY, TEMPLATE, resolve
from ..errors import ConfigError
from ..report.inspect import list_tables, show_table
from .batch import inputs
from .group import main, reported
from .options import INPUTS

if TYPE_CHECKING:
    from ..model import Engine

__all__ = ["validate", "list_", "show"]


@main.command()
@INPUTS
def validate(paths):
    """Check configuration files (and the folders' .toml files): syntax, units, geometry, firing.

    Prints one line per file; exits with status 1 if any file is invalid.
    """
    bad = 0
    for path in inputs(paths):
        try:
            engine = load(path)
            with reported(engine):
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
@click.argument("folder", required=False, default=LIBRARY, metavar="[DIR]")
def list_(folder):
    """List the engines in DIR (default: the engine library shipped with balance, library:):
    name, cylinders, cycle, frame, estimates, source.

    Estimates: how many of the file's numbers its `estimates` key names ("none" where it
    declares sources and no estimates; blank where it declares neither).

    One table per folder, headed by the folder's path relative to DIR (DIR itself for the
    files directly in it): the files of DIR first, then each folder in path order, a folder
    before its subfolders (configs, tanaka-part3, today/boxer, today/inline, ...). In the
    shipped library (DIR a library: name) the headings and files are given by their library:
    names, what compare, show and the other commands take (library:tanaka-part3, ...).

    Invalid files are reported on standard error (exit status 1) after the listing.
    """
    with reported():
        root = Path(resolve(folder))
    if not root.is_dir():
        raise click.ClickException(f"{folder}: no such folder; give a folder of .toml files")
    # in the shipped library, folders and files by their names: what the other commands take
    named = folder.startswith((LIBRARY, TEMPLATE))
    inside = (folder if folder.endswith((":", "/")) else folder + "/") if named else ""
    # by the folder's path parts: its engines and how many of each one's numbers are estimates
    groups: dict[tuple[str, ...], list[tuple[Engine, int | None]]] = {}
    errors: list[str] = []
    for path in inputs([root]):
        try:
            data = parse_text(read_text(Path(path)), str(path))
            engine = build(data, str(path))
            provenance = read_provenance(data, str(path))
            where = Path(path).relative_to(root)
            if named:
                engine = engine.replace(config_path=inside + where.as_posix())
        except ConfigError as exc:
            errors.append(str(exc))
            continue
        estimated = len(provenance.estimated(data)) if provenance.declared else None
        groups.setdefault(where.parent.parts, []).append((engine, estimated))
    # folders sorted by their path parts: DIR's own files first, a folder before its subfolders
    if groups:
        click.echo(
            list_tables(
                (
                    inside + "/".join(parts) if parts else folder,
                    [engine for engine, _ in groups[parts]],
                    [estimated for _, estimated in groups[parts]],
                )
                for parts in sorted(groups)
            )
        )
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
    with reported():
        engine = load(path)
    with reported(engine):
        fire = firing_sequence(engine)
    click.echo(show_table(engine, fire), nl=False)
