"""JUnit XML of a regression table: one test case per engine, a failure per engine that moved
(and per engine added or removed), for CI systems to display."""

import xml.etree.ElementTree as ET

from .regress import value_text

__all__ = ["junit_xml"]


def _failure_text(rows):
    lines = []
    for row in rows:
        where = "" if row.order is None else f"order {row.order} "
        detail = [] if row.change is None else [f"{row.change:+.3g}"]
        detail += [] if row.tolerance is None else [f"tolerance {row.tolerance:.3g}"]
        suffix = f" ({', '.join(detail)})" if detail else ""
        lines.append(
            f"{where}{row.quantity}: {value_text(row.baseline)} -> {value_text(row.now)}{suffix}"
        )
    return "\n".join(lines)


def junit_xml(regression):
    """The XML text of a :class:`~balance_cli.studies.regress.Regression`."""
    cases = []
    for name in list(regression.checked) + list(regression.added) + list(regression.removed):
        case = ET.Element(
            "testcase",
            classname="balance.regress",
            name=name,
            file=regression.configs.get(name, ""),
        )
        rows = regression.rows_of(name)
        if rows:
            failure = ET.SubElement(
                case,
                "failure",
                type="regression",
                message=f"{len(rows)} quantities moved beyond tolerance",
            )
            failure.text = _failure_text(rows)
        elif name in regression.added:
            ET.SubElement(
                case, "failure", type="added", message="engine added: it is not in the baseline"
            )
        elif name in regression.removed:
            ET.SubElement(
                case,
                "failure",
                type="removed",
                message="engine removed: the baseline has it, the engines checked do not",
            )
        cases.append(case)
    failures = sum(1 for case in cases if case.find("failure") is not None)
    suites = ET.Element(
        "testsuites",
        name="balance regress",
        tests=str(len(cases)),
        failures=str(failures),
        errors="0",
    )
    suite = ET.SubElement(
        suites,
        "testsuite",
        name=f"balance regress {regression.baseline_path}",
        tests=str(len(cases)),
        failures=str(failures),
        errors="0",
        skipped="0",
    )
    suite.extend(cases)
    ET.indent(suites)
    return (
        '<?xml version="1.0" encoding="utf-8"?>\n' + ET.tostring(suites, encoding="unicode") + "\n"
    )
