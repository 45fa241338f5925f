"""The report folder: pictures, report.md and (optionally) report.html, written whole."""

from .. import plot
from ..output import write_folder, write_text
from .document import PICTURES, blocks
from .html import page
from .markdown import markdown

__all__ = ["write_report", "REPORT_FILES"]

REPORT_FILES = [file for file, *_ in PICTURES] + ["report.md", "report.html"]


def write_report(
    target,
    comparison,
    balances,
    star_order,
    with_html,
    torques,
    scale=None,
    family=None,
    torsion=None,
):
    """Write the report of ``comparison`` (and its ``balances`` and ``torques``, one of each per
    engine) into the folder ``target``, its moments and torques in ``scale``'s units (a
    :class:`~balance_cli.units.Scale`, default N·m); nothing is left behind if any part
    fails; ``family`` a :class:`~balance_cli.studies.family.FamilyResult` for a section of its own;
    ``torsion`` the :class:`~balance_cli.torsion.TorsionResult` of the engines with a
    [torsion] table (or a one-line note, a string, when openTorsion is missing).
    Returns the paths written."""
    results = comparison.results
    figures = {
        "locus": lambda: plot.locus(results),
        "spectrum": lambda: plot.spectrum(results),
        "star": lambda: plot.star(results, star_order),
        "firing": lambda: plot.firing(results),
        "torque": lambda: plot.torque(torques),
    }

    def fill(folder):
        names = []
        for file, kind, _, _ in PICTURES:
            plot.save(figures[kind](), folder / file)
            names.append(file)
        content = blocks(comparison, balances, star_order, torques, scale, family, torsion)
        write_text(folder / "report.md", markdown(content))
        names.append("report.md")
        if with_html:
            write_text(folder / "report.html", page(content, folder))
            names.append("report.html")
        return names

    return write_folder(target, fill)
