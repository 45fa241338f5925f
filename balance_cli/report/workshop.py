"""The workshop's tables: ``balance match`` (the assignment, what it leaves, the engine as
assembled beside the parts in the order given), ``balance tolerance`` (the spread of each
order over the runs beside its closed form) and ``balance bobweight`` (the balancing sheet),
and their CSV (each result's records)."""

import csv
import io
import math

from ..analysis.results import compare
from ..units import Scale, kg_to_g
from .compare import compare_tables
from .display import figure
from .table import order_parts, render, safe_for

__all__ = ["match_tables", "tolerance_tables", "bobweight_tables", "records_csv"]


def records_csv(rows) -> str:
    """Rows of plain values as CSV, the keys of the first row as the header."""
    out = io.StringIO()
    if rows:
        writer = csv.DictWriter(out, fieldnames=list(rows[0]), lineterminator="\n")
        writer.writeheader()
        for row in rows:
            writer.writerow({k: "" if v is None else v for k, v in row.items()})
    return out.getvalue()


def _blocks(parts, fmt):
    heading = "#### " if fmt == "markdown" else ""
    safe = safe_for(fmt)
    out = []
    for title, headers, rows, note in parts:
        out += [f"{heading}{safe(title)}", ""] + ([render(headers, rows, fmt), ""] if rows else [])
        if note:
            out += [note, ""]
    return "\n".join(out)


def _grams(kg):
    """A mass in grams to six significant digits, as a parts list gives it (552.4, not 552.400)."""
    return f"{kg_to_g(kg):.6g}"


def _match_summary(result, scale):
    kinds = " and ".join(result.parts.kinds)
    how = (
        f"exhaustive: {result.evaluated:,} of {result.assignments_total:,} assignments "
        f"evaluated, one of each class of {result.symmetries} that the crank makes equivalent; "
        "no assignment scores better (proved)"
        if result.exhaustive
        else f"HEURISTIC ({result.assignments_distinct:,} distinct assignments are more than "
        f"the limit): exchanges from several starts, {result.evaluated:,} evaluated; the best "
        "found, NOT proved"
    )
    given, best = result.given.score_n, result.best.score_n
    unit = scale.units
    factor = scale.force(1.0, 1.0)
    lower = f"{100 * (1 - best / given):.1f} % lower" if given else "nothing to gain"
    return [
        f"{result.engine.name}: {kinds} of {result.parts.source or 'the parts given'} fitted "
        f"to {result.engine.n_cylinders} cylinders",
        f"Objective: {result.objective.label} ({unit}), of what the parts' deviations add "
        f"(the engine as assembled minus the same engine with every cylinder and throw at the "
        f"mean mass); moments over a pitch of {result.objective.pitch_m * 1000:.4g} mm",
        how + f" ({result.elapsed_s:.2f} s)",
        f"Score: matched {figure(best * factor)} {unit}, in the order given "
        f"{figure(given * factor)} {unit}: {lower}",
    ]


def _assignment_part(result):
    best, given = result.best, result.given
    rows = []
    for b, g in zip(best.cylinder_rows(), given.cylinder_rows(), strict=True):
        rows.append(
            [
                str(b["cylinder"]),
                str(b["throw"]),
                b["piston"] or "-",
                b["rod"] or "-",
                _grams(b["reciprocating_kg"]),
                _grams(b["rotating_kg"]),
                g["piston"] or "-",
                g["rod"] or "-",
                _grams(g["reciprocating_kg"]),
            ]
        )
    headers = [
        "Cyl",
        "Throw",
        "Piston",
        "Rod",
        "Recip. (g)",
        "Throw's rotating (g)",
        "Given: piston",
        "Given: rod",
        "Given: recip. (g)",
    ]
    return ("Assignment (matched, and the parts in the order given)", headers, rows, None)


def _difference_parts(result, scale):
    """What the deviations add, order by order and over a revolution, for both fittings."""
    fittings = (("matched", result.best), ("in the order given", result.given))
    entries = [(name, f.difference.records(result.engine), 1.0) for name, f in fittings]
    parts = [
        ("What the parts' deviations add: " + title[0].lower() + title[1:], headers, rows, note)
        for title, headers, rows, note in order_parts(entries, scale, result.samples)
    ]
    summary = [
        [
            name,
            figure(scale.force(f.largest_force_n, 1.0)),
            figure(scale.moment(f.largest_moment_nm)),
            figure(scale.force(f.score_n, 1.0)),
        ]
        for name, f in fittings
    ]
    headers = [
        "Fitting",
        f"Largest force ({scale.units})",
        f"Largest moment ({scale.moment_label})",
        f"Score ({scale.units})",
    ]
    parts.append(
        ("What the parts' deviations add over a revolution (all orders)", headers, summary, None)
    )
    return parts


def match_tables(result, scale, fmt) -> str:
    """``balance match``'s report: summary, assignment, what the deviations add, and the
    engine as assembled beside the parts in the order given (as ``compare`` shows them)."""
    if not scale.absolute:
        scale = Scale.of(True, scale.units)
    safe = safe_for(fmt)
    lines = [safe(line) for line in _match_summary(result, scale)]
    text = "\n".join(lines) + "\n\n"
    text += _blocks([_assignment_part(result), *_difference_parts(result, scale)], fmt)
    heading = "#### " if fmt == "markdown" else ""
    text += f"\n{heading}The engine as assembled, as compare analyses it\n\n"
    text += compare_tables(compare([result.best.assembled, result.given.assembled]), scale, fmt)
    return text


def _band_text(band):
    values = [
        ("reciprocating", kg_to_g(band.reciprocating_kg), " g"),
        ("rotating", kg_to_g(band.rotating_kg), " g"),
        ("crank radius", band.crank_radius_m * 1e3, " mm"),
        ("rod length", band.rod_length_m * 1e3, " mm"),
        ("phase", math.degrees(band.phase_rad), "°"),
        ("bank angle", math.degrees(band.bank_angle_rad), "°"),
        ("pin offset", band.pin_offset_m * 1e3, " mm"),
    ]
    return ", ".join(f"{name} {value:g}{unit}" for name, value, unit in values if value)


def _spread_rows(result, part, scale):
    shown = (lambda v: scale.force(v, 1.0)) if part == "force" else scale.moment
    floor = result.engine.noise_floor_n if part == "force" else result.engine.noise_floor_nm
    rows = []
    for spread in result.orders:
        stats = getattr(spread, part)
        linear = getattr(spread, f"linear_{part}")
        for name in ("vertical", "horizontal", "max"):
            s = stats[name]
            if s.max < floor:
                continue
            low, high = s.p95_interval
            closed = linear.get(name)
            rows.append(
                [
                    str(spread.order),
                    name,
                    figure(shown(s.mean)) + f" ± {figure(shown(s.mean_error), 2)}",
                    figure(shown(s.median)),
                    f"{figure(shown(s.p95))} ({figure(shown(low))}–{figure(shown(high))})",
                    figure(shown(s.p99)),
                    figure(shown(s.max)),
                    "-" if closed is None else figure(shown(closed.mean)),
                    "-" if closed is None else figure(shown(closed.p95)),
                ]
            )
    return rows


def tolerance_tables(result, scale, fmt) -> str:
    """``balance tolerance``'s report: the band, then per order the spread of the free force
    and moment beside their closed form, and of the largest over a revolution."""
    if not scale.absolute:
        scale = Scale.of(True, scale.units)
    safe = safe_for(fmt)
    method = (
        "masses only scattered: each run the runs' masses times the engine's response to one "
        "kilogram at each point mass (exact, forces being linear in the masses)"
        if result.method == "masses"
        else "dimensions scattered: each run's linkage closed exactly, all runs at once"
    )
    lines = [
        f"{result.engine.name}: {result.runs:,} runs (seed {result.seed}), one standard "
        f"deviation of {_band_text(result.band)}",
        f"{method}; {result.samples} samples a revolution ({result.elapsed_s:.2f} s)",
    ]
    f_unit, m_unit = scale.units, scale.moment_label
    headers = [
        "Order",
        "Component",
        "Mean ± s.e.",
        "Median",
        "95th (95 % interval)",
        "99th",
        "Max",
        "Linear: mean",
        "Linear: 95th",
    ]
    note = (
        "Amplitudes over the runs: vertical and horizontal components, and max (|X⁺| + |X⁻|, "
        "the order's largest value in a revolution). Mean ± its standard error; the 95th "
        "percentile with the 95 % interval of its sampling error (order statistics). Linear: "
        "the closed form of the scatter's linear part (zero-mean where the order is nothing "
        "nominally, else about its nominal value)."
    )
    largest = [
        [
            what,
            figure(shown(s.mean)),
            figure(shown(s.median)),
            figure(shown(s.p95)),
            figure(shown(s.p99)),
            figure(shown(s.max)),
        ]
        for what, s, shown in (
            (f"force ({f_unit})", result.largest_force, lambda v: scale.force(v, 1.0)),
            (f"moment ({m_unit})", result.largest_moment, scale.moment),
        )
    ]
    parts = [
        (
            f"Free force by order ({f_unit})",
            headers,
            _spread_rows(result, "force", scale),
            note,
        ),
        (f"Free moment by order ({m_unit})", headers, _spread_rows(result, "moment", scale), None),
        (
            "Largest resultant over a revolution (all orders)",
            ["Quantity", "Mean", "Median", "95th", "99th", "Max"],
            largest,
            None,
        ),
    ]
    return "\n".join(safe(line) for line in lines) + "\n\n" + _blocks(parts, fmt)


def bobweight_tables(sheet, scale, fmt) -> str:
    """``balance bobweight``'s report: each pin's bobweight, and a single's or twin's trade."""
    if not scale.absolute:
        scale = Scale.of(True, scale.units)
    safe = safe_for(fmt)
    factor = (
        "the factor balance counterweight implies (its test masses: the whole rotating mass "
        "and half the reciprocating one on plain rods)"
        if sheet.chosen_factor is None
        else f"balance factor {sheet.chosen_factor:g}"
    )
    lines = [
        f"{sheet.engine.name}: bobweights for a balancing machine, {factor}"
        + (f"; masses from {sheet.parts} fitted in the order given" if sheet.parts else ""),
    ]
    rows = [
        [
            str(p.throw),
            " ".join(map(str, p.cylinders)),
            _grams(p.rotating_kg),
            _grams(p.reciprocating_kg),
            f"{p.factor:.4g}",
            _grams(p.bobweight_kg),
        ]
        for p in sheet.pins
    ]
    parts = [
        (
            "Bobweights",
            ["Throw", "Cylinders", "Rotating (g)", "Reciprocating (g)", "Factor", "Bobweight (g)"],
            rows,
            "Bobweight = rotating + factor × reciprocating, hung on the crank pin (the "
            "crankshaft's own unbalance stays on the machine).",
        )
    ]
    if sheet.trade:
        f_unit, m_unit = scale.units, scale.moment_label
        parts.append(
            (
                "What each balance factor leaves (counterweights for the rotating masses plus "
                "the factor times the reciprocating ones)",
                [
                    "Factor",
                    f"F1 vertical ({f_unit})",
                    f"F1 horizontal ({f_unit})",
                    f"M1 vertical ({m_unit})",
                    f"M1 horizontal ({m_unit})",
                    f"Largest force ({f_unit})",
                ],
                [
                    [
                        f"{100 * t.factor:g} %",
                        figure(scale.force(t.force_vertical_n, 1.0)),
                        figure(scale.force(t.force_horizontal_n, 1.0)),
                        figure(scale.moment(t.moment_vertical_nm)),
                        figure(scale.moment(t.moment_horizontal_nm)),
                        figure(scale.force(t.largest_force_n, 1.0)),
                    ]
                    for t in sheet.trade
                ],
                "First order; vertical along the engine's vertical, horizontal across it. A "
                "higher factor trades vertical shaking for horizontal.",
            )
        )
    return "\n".join(safe(line) for line in lines) + "\n\n" + _blocks(parts, fmt)
