"""The report folder: pictures, report.md and (optionally) report.html, written whole."""

from .. import plot
from ..output import write_folder, write_text
from .document import PICTURES, blocks
from .html import page
from .markdown import markdown

__all__ = ["write_report", "REPORT_FILES", "REPORT_FRAMES"]

#: each engine's animation in report.html: frames a revolution (4° apart: a report of the
#: whole library stays a few megabytes)
REPORT_FRAMES = 90

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
            write_text(folder / "report.html", page(content, folder, _animations(results)))
            names.append("report.html")
        return names

    return write_folder(target, fill)


def _animations(results):
    """Each engine's name and animation (orders 1 and 2, or 1 alone when only it is
    analysed), for report.html."""
    out = []
    for r in results:
        orders = [k for k in plot.DEFAULT_ORDERS if k <= r.max_order]
        out.append((r.engine.name, plot.animate(r, orders).html(REPORT_FRAMES, whole=False)))
    return out
