"""``balance search``'s tables: what was searched and whether the list is proved, the
ranking of the best arrangements, and the comparison of those listed."""

from ..units import round_degrees
from .compare import compare_tables
from .table import intervals, render, safe_for

__all__ = ["search_tables", "search_summary", "search_rows"]


def _coefficient_names(result):
    """The objective's coefficients that are not zero in every listed arrangement (all of
    them; a zero column says nothing), and whether any were left out."""
    names = [t.name for t in result.objective]
    shown = [n for n in names if any(a.coefficients[n] != 0.0 for a in result.arrangements)]
    return shown or names[:1], len(shown) < len(names)


def search_summary(result):
    """What was searched, how much, and whether the list is proved: a few lines of text."""
    what = (
        "even firing within each bank"
        if result.even_banks
        else "even firing"
        if result.even
        else f"every crank on a {result.step_deg:g}° grid"
    )
    proof = (
        "exhaustive: no arrangement scores better than those listed"
        if result.exhaustive
        else "HEURISTIC local search: the best found, NOT proved optimal"
    )
    lines = [
        f"{result.template.name} ({result.template.config_path or 'template'}): {what}; "
        f"objective {', '.join(str(t) for t in result.objective)}",
        f"{result.arrangements_total:,} arrangements with throw 1 at 0° "
        f"({result.firing_orders_per_crank} firing order"
        f"{'s' if result.firing_orders_per_crank != 1 else ''} "
        f"a crank), {result.arrangements_distinct:,} distinct; {result.evaluated:,} cranks "
        f"evaluated, {result.pruned:,} skipped by bound ({result.elapsed_s:.2f} s, "
        f"{result.workers} worker{'s' if result.workers != 1 else ''})",
        f"Symmetries: {'; '.join(result.symmetries)}",
        proof
        + (
            "; more arrangements tie at the last score than were kept, so the tie-break "
            "by firing order saw only the first found"
            if result.ties_truncated
            else ""
        ),
    ]
    return lines


def _score_text(score):
    # four decimals read best at the usual sizes; a weight of 1e100 or 1e-10 makes a score
    # that they would print with 100 digits, or as 0.0000
    return f"{score:.4f}" if score == 0 or 1e-3 <= abs(score) < 1e6 else f"{score:.6g}"


def search_rows(result):
    """Ranking rows: rank, score, phases, firing order, intervals, coefficients, mirror."""
    names, _ = _coefficient_names(result)
    rows = []
    for a in result.arrangements:
        record = a.to_dict()
        rows.append(
            [
                str(a.rank),
                _score_text(a.score),
                " ".join(f"{round_degrees(p, 3):g}" for p in a.phases_deg),
                "-".join(map(str, record["firing"]["order"])),
                intervals(record["firing"]),
            ]
            + [f"{a.coefficients[n]:.4f}" for n in names]
            + ["" if a.mirror_of is None else str(a.mirror_of)]
        )
    headers = (
        ["Rank", "Score", "Phases (°)", "Firing order", "Intervals (°)"] + names + ["Mirror of"]
    )
    return headers, rows


def search_tables(result, comparison, scale, fmt):
    """The search as text or Markdown: what was done, the ranking, then the order table of
    every listed arrangement as ``compare`` prints it."""
    heading = "#### " if fmt == "markdown" else ""
    safe = safe_for(fmt)
    out = [safe(line) + ("  " if fmt == "markdown" else "") for line in search_summary(result)]
    headers, rows = search_rows(result)
    out += [
        "",
        f"{heading}Best arrangements (coefficients: F_k in one throw's largest order-k "
        "force, M_k in that force × the mean throw pitch; H_k and X_k in one throw's order-k "
        "guide-force couple, X_k also per mean throw pitch)",
        "",
        render(headers, rows, fmt),
        "",
    ]
    if _coefficient_names(result)[1]:
        out += ["The objective's other coefficients are 0 in every arrangement listed.", ""]
    if comparison is not None:
        out.append(compare_tables(comparison, scale, fmt))
    return "\n".join(out)
