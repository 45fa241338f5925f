"""The crank searches: balance search (the best crank arrangements and firing orders of a
template) and balance family (a project-guide table, one best firing order per number of
cylinders). The search is imported only when they run.
"""

import contextlib
import re
from pathlib import Path

import click

from ..about import install_hint
from ..analysis.results import compare as comparison_of
from ..errors import BalanceError, OutputError
from ..output import check_folder, refuse_inputs, write_folder, write_text
from ..report.csvfile import search_csv
from ..report.search import search_tables
from ..units import Scale
from .batch import progress_bar, settings
from .dispatch import emit, guard, render, same_path, write
from .group import main, message, reported
from .options import (
    FIRST_ORDER_BALANCE,
    FORMAT,
    MAX_ORDER,
    OUTPUT,
    SAMPLES,
    SPEED,
    UNITS,
    counts_option,
    firing_orders_option,
    quantity_option,
)

__all__ = ["search", "family_"]


_SEARCH_FLAGS = {
    "objective": "--objective",
    "top": "--top",
    "step_deg": "--step",
    "workers": "--workers",
    "scheduler": "--scheduler",
    "even_banks": "--even-banks",
    "limit": "--limit",
    "restarts": "--restarts",
    "seed": "--seed",
    "template": "the template",
}
#: library words inside the search's messages, in the command line's terms
_SEARCH_WORDS = {
    "allow_uneven": "--allow-uneven",
    "even_banks": "--even-banks",
    "step_deg": "--step",
    "max_order": "--max-order",
    "heuristic search": "heuristic search (--heuristic)",
    "cluster scheduler": "cluster (--scheduler)",
}


@contextlib.contextmanager
def _search_reported(engine):
    try:
        yield
    except BalanceError as exc:
        text = message(exc, engine, _SEARCH_FLAGS)
        for word, flag in _SEARCH_WORDS.items():
            text = re.sub(rf"\b{re.escape(word)}\b", flag, text)
        raise click.ClickException(text) from None


@main.command()
@click.argument("template_path", metavar="TEMPLATE.toml")
@click.option(
    "--objective",
    default=None,
    metavar="TERMS",
    help="What to minimise: coefficients such as M1,M2 or F2:4,M1,M2,X4 (F force, M "
    "moment, H and X the H- and X-type guide-force moments, the order, + or - for "
    "a force's or moment's forward or backward part only, :weight, default 1). "
    "Default: every F_k and M_k up to --max-order.",
)
@click.option(
    "--top",
    default=10,
    show_default=True,
    type=int,
    metavar="K",
    help="How many arrangements to list (ties ranked by firing order).",
)
@click.option(
    "--allow-uneven",
    is_flag=True,
    help="Search every crank on a grid of --step degrees, firing evenly or not.",
)
@click.option(
    "--step",
    "step",
    default=None,
    type=float,
    metavar="DEG",
    help="The phase grid of --allow-uneven, in degrees (a divisor of 360 such as 30).",
)
@click.option(
    "--workers", default=None, type=int, metavar="N", help="Processes to use [default: every core]."
)
@click.option(
    "--scheduler",
    default=None,
    metavar="ADDRESS",
    help="Run on a Dask distributed cluster (tcp://host:8786) instead; needs "
    f"{install_hint('cluster')}.",
)
@click.option(
    "--even-banks",
    is_flag=True,
    help="Each bank fires evenly on its own, the other banks' cylinders the bank angle "
    "after their partner on the throw (the rule of medium-speed V engines, whose bank angle "
    "seldom lets the whole engine fire evenly).",
)
@click.option(
    "--heuristic",
    is_flag=True,
    help="A local search from random cranks for templates too large to enumerate: "
    "the best found, NOT proved optimal.",
)
@click.option(
    "--restarts",
    default=200,
    show_default=True,
    type=int,
    metavar="N",
    help="Random starts of --heuristic.",
)
@click.option("--seed", default=0, show_default=True, type=int, help="Random seed of --heuristic.")
@click.option(
    "--limit",
    default=None,
    type=int,
    metavar="N",
    help="Refuse an exhaustive search evaluating more cranks than this "
    "[default: 2e9, about a minute on two cores].",
)
@SAMPLES
@MAX_ORDER
@UNITS
@SPEED
@FORMAT
@OUTPUT
@click.option(
    "--write",
    "write_dir",
    default=None,
    metavar="DIR",
    help="Also write each listed arrangement as a complete configuration "
    "(DIR/arrangement-01.toml, ...), for compare, counterweight and plot.",
)
def search(
    template_path,
    objective,
    top,
    allow_uneven,
    step,
    workers,
    scheduler,
    even_banks,
    heuristic,
    restarts,
    seed,
    limit,
    samples,
    max_order,
    units,
    speed,
    fmt,
    output,
    write_dir,
):
    """Find the crank arrangements and firing orders that leave the least of what you ask.

    TEMPLATE.toml is an ordinary configuration whose [[throws]] give only z (no phase) and
    which has no firing_order. Throw 1 stays at 0°; arrangements that are the same engine run
    the other way round count once; mirror images (the crank read from the other end) balance
    alike and are listed, but evaluated once. Without --heuristic the result is exhaustive:
    nothing scores better than what is listed.
    """
    from ..config import arrangement_toml, read_configuration, resolve
    from ..cranksearch import DEFAULT_LIMIT
    from ..cranksearch import search as search_of

    with reported():
        refuse_inputs([output], [Path(resolve(template_path))])
        configuration = read_configuration(template_path)
        template = configuration.template()
        data = configuration.data
        if write_dir is not None:
            check_folder(write_dir, "--write")
            # the files --write may write must replace neither the template nor --output
            planned = [
                Path(write_dir) / f"arrangement-{k:02d}.toml" for k in range(1, max(top, 1) + 1)
            ]
            refuse_inputs(planned, [Path(resolve(template_path))])
            if output not in (None, "-") and any(same_path(output, p) for p in planned):
                raise OutputError(
                    f"{output!r} is one of the files --write writes; write the table somewhere else"
                )
    settings(samples, max_order)
    speed_rad_s = quantity_option(speed, "--speed", "angular speed")
    if speed_rad_s is not None:
        with reported(template):
            template = template.replace(speed_rad_s=speed_rad_s)
        # the configurations --write writes are at the speed analysed
        data = {**data, "speed": speed}
    callback, bar = progress_bar("Searching")
    with _search_reported(template), bar:
        result = search_of(
            template,
            objective,
            top=top,
            allow_uneven=allow_uneven,
            step_deg=step,
            workers=workers,
            scheduler=scheduler,
            even_banks=even_banks,
            heuristic=heuristic,
            restarts=restarts,
            seed=seed,
            limit=DEFAULT_LIMIT if limit is None else limit,
            samples=samples,
            max_order=max_order,
            progress=callback,
        )

    def table():
        with reported():
            comparison = (
                comparison_of([a.result for a in result.arrangements])
                if result.arrangements
                else None
            )
        return search_tables(result, comparison, Scale.of(False, units), fmt)

    text = render(fmt, json=result.to_dict, csv=lambda: search_csv(result), table=table)
    if write_dir is None:
        write(output, text)
        return

    def fill(folder):
        # --output is written last inside the folder's transaction: if it fails, the folder
        # is not written either
        names = []
        for a in result.arrangements:
            name = f"arrangement-{a.rank:02d}.toml"
            header = (
                f"written by balance search from {template_path}, rank {a.rank} of "
                f"{len(result.arrangements)}\nobjective "
                f"{', '.join(str(t) for t in result.objective)}: score {a.score:.6g}"
                + ("" if result.exhaustive else " (heuristic, not proved optimal)")
            )
            (folder / name).write_text(
                arrangement_toml(data, a.phases_deg, a.engine.firing_order, a.engine.name, header),
                encoding="utf-8",
            )
            names.append(name)
        write_text(output, text)
        return names

    with reported():
        write_folder(write_dir, fill)


def _family_counts(text, v_family):
    """--cylinders: a V family (two cylinders a throw) takes the even numbers of a range."""
    if text is None:
        text = "12-20" if v_family else "5-12"
    if not v_family:
        return counts_option(text)
    counts: list[int] = []
    for token in text.split(","):
        numbers = counts_option(token)
        counts += [n for n in numbers if n % 2 == 0] if "-" in token else numbers
    return counts


@main.command("family")
@click.argument("path", metavar="FILE.toml")
@click.option(
    "--cylinders",
    "counts",
    default=None,
    metavar="N-M|N,M,...",
    help="The numbers of cylinders of the family (2 to 24); for a V template (two banks) "
    "the even numbers of a range N-M  [default: 5-12, or 12-20 for a V template].",
)
@click.option(
    "--objective",
    default=None,
    metavar="TERMS",
    help="What each firing order minimises, as for balance search (M1,M2, X4, "
    "F2:4, ...)  [default: the pitching plus yawing couples of orders 1, 2 and 4, "
    "M1V + M1H + M2V + M2H + M4V + M4H in N·m: M1-:w1,M2,M4:w4].",
)
@click.option(
    "--firing-order",
    "firing_orders",
    multiple=True,
    metavar="N:ORDER",
    help="Take this firing order for N cylinders instead of searching, e.g. "
    "6:1-5-3-4-2-6 (two-stroke, even firing). Repeatable.",
)
@click.option(
    "--pitch",
    default=None,
    metavar="LENGTH",
    help="Cylinder pitch, e.g. '1020 mm'  [default: the file's mean throw pitch].",
)
@click.option(
    "--power-per-cylinder",
    "power",
    default=None,
    metavar="POWER",
    help="Power of one cylinder at the file's speed, e.g. '2380 kW'  [default: the "
    "file's power over its cylinders].",
)
@click.option(
    "--workers",
    default=None,
    type=int,
    metavar="N",
    help="Processes for the searches [default: every core].",
)
@FIRST_ORDER_BALANCE
@SAMPLES
@MAX_ORDER
@UNITS
@FORMAT
@OUTPUT
def family_(
    path,
    counts,
    objective,
    firing_orders,
    pitch,
    power,
    workers,
    first_order_balance,
    samples,
    max_order,
    units,
    fmt,
    output,
):
    """A project-guide table of an engine family: for each number of cylinders, the firing
    order (proved best for the objective, or given), the external moments M1V, M1H (under
    the project guides' standard balance unless --first-order-balance says otherwise), M2V,
    M2H, M4V, M4H, their power related unbalance and class, the largest H- and X-type
    guide-force moments and whether a second-order compensator is indicated.

    FILE.toml is a configuration or search template of the family's in-line engine: one
    cylinder's data repeated at the pitch (its throws' phases and firing order are not used).
    """
    from ..config import read_configuration, resolve
    from ..report.family import family_tables
    from ..studies.family import family

    given = firing_orders_option(firing_orders)
    with reported():
        guard([output], [Path(resolve(path))])
        configuration = read_configuration(path)
    counts = _family_counts(counts, len(configuration.data.get("banks", ())) == 2)
    settings(samples, max_order)
    pitch_m = quantity_option(pitch, "--pitch", "length")
    power_w = quantity_option(power, "--power-per-cylinder", "power")
    flags = {
        "cylinders": "--cylinders",
        "pitch_m": "--pitch",
        "firing_orders": "--firing-order",
        "objective": "--objective",
        "workers": "--workers",
        "first_order_balance": "--first-order-balance",
        "template": path,
    }
    callback, bar = progress_bar("Family")
    with reported(flags=flags), bar:
        result = family(
            configuration,
            counts,
            objective,
            pitch_m,
            power_w,
            given,
            samples,
            max_order,
            workers,
            progress=callback,
            first_order_balance=first_order_balance,
        )

    def csv():
        from ..report.csvfile import family_csv

        return family_csv(result)

    emit(
        output,
        fmt,
        json=result.to_dict,
        csv=csv,
        table=lambda: family_tables(result, Scale.of(True, units), fmt),
    )
