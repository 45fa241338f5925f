"""balance regress: engines checked against a baseline that balance compare wrote, and the
baseline rewritten (--update).
"""

import json
from pathlib import Path

import click

from ..config import find_configs
from ..errors import RegressError
from ..output import refuse_inputs, to_json
from ..report.junit import junit_xml
from ..report.regress import regression_tables
from ..studies.regress import baseline_configs, check_baseline, check_rtol, compared_like
from ..studies.regress import regression as regression_of
from ..units import Scale
from .batch import analyse_all, load_all, settings
from .compare import compare_document
from .dispatch import emit, write
from .group import main, reported
from .options import OUTPUT, UNIT_CHOICE

__all__ = ["regress"]


def _read_baseline(path):
    """The baseline document, checked; one RegressError line for anything else."""
    try:
        text = Path(path).read_text(encoding="utf-8")
    except FileNotFoundError:
        raise RegressError(
            f"{path}: no such file; write a baseline with balance compare FILE|DIR "
            "--format json -o BASELINE.json"
        ) from None
    except (OSError, UnicodeDecodeError) as exc:
        raise RegressError(
            f"{path}: cannot read the file ({getattr(exc, 'strerror', None) or exc})"
        ) from None
    try:
        document = json.loads(text)
    except (json.JSONDecodeError, RecursionError, ValueError) as exc:
        # ValueError: an integer of thousands of digits; RecursionError: nesting without end
        reason = exc if isinstance(exc, json.JSONDecodeError) else "not a document balance wrote"
        raise RegressError(
            f"{path}: not JSON that balance can read ({reason}); give what "
            "balance compare --format json wrote"
        ) from None
    check_baseline(document, path)
    return document


@main.command()
@click.argument("baseline", metavar="BASELINE.json")
@click.argument("paths", nargs=-1, metavar="[FILE|DIR...]")
@click.option(
    "--rtol",
    type=float,
    default=0.0,
    show_default=True,
    metavar="R",
    help="Loosen the tolerances: a force, moment or resultant may move by R times its "
    "baseline value, an angle by R radians (0 to below 1).",
)
@click.option(
    "--update",
    is_flag=True,
    help="Rewrite BASELINE.json (atomically) with the engines as they are now, after "
    "printing what changed; exit status 0.",
)
@click.option(
    "--format",
    "fmt",
    type=click.Choice(["table", "markdown", "json", "junit"]),
    default="table",
    show_default=True,
    help="markdown suits a CI job summary; junit is JUnit XML for CI test reports.",
)
@click.option(
    "--units",
    type=UNIT_CHOICE,
    default="N",
    show_default=True,
    help="Units of the forces and moments in the table (N, kN, MN, kgf or lbf with "
    "N·m, ...); JSON and JUnit stay SI.",
)
@OUTPUT
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
    with reported():
        document = _read_baseline(baseline)
        files = find_configs(paths) if paths else baseline_configs(document, baseline)
        refuse_inputs([output], files + [Path(baseline)])
        check_rtol(rtol)
    settings(document["samples"], document["max_order"])
    override = document.get("speed_override_rpm")
    engines = load_all(files, None if override is None else f"{override!r} rpm")
    results = analyse_all(engines, document["samples"], document["max_order"])
    with reported():
        comparison = compared_like(document, results)
        regression = regression_of(document, comparison, rtol, str(baseline))
    emit(
        output,
        fmt,
        json=regression.to_dict,
        junit=lambda: junit_xml(regression),
        table=lambda: regression_tables(regression, fmt, Scale.of(True, units)),
    )
    if update:
        write(baseline, to_json(compare_document(comparison, engines if override else None)))
        click.echo(f"wrote {baseline}", err=True)
        return
    if regression.moved:
        raise SystemExit(1)
