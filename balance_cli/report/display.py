"""Text safety for tables: where figures get their significant digits, and where names are
made safe for Markdown and plain-text tables (display units are
:class:`~balance_cli.units.Scale`'s)."""

from ..units import significant

__all__ = ["markdown_text", "plain_text", "figure"]

#: significant figures of a force, moment or torque in a table
DIGITS = 4


def figure(value, digits=DIGITS):
    """A force, moment, torque or mass as table text: ``digits`` significant figures."""
    return significant(value, digits)


def plain_text(value):
    """One line of text for a table cell: line breaks and tabs become spaces."""
    return (
        " ".join(str(value).split()) if any(c in str(value) for c in "\r\n\t\v\f") else str(value)
    )


_MARKDOWN = str.maketrans(
    {
        "|": r"\|",
        "<": "&lt;",
        ">": "&gt;",
        "&": "&amp;",
        "`": r"\`",
        "*": r"\*",
        "_": r"\_",
        "[": r"\[",
        "]": r"\]",
        "\\": "\\\\",
    }
)


def markdown_text(value):
    """Text that a Markdown renderer shows as written: one line, no table breaks, no HTML."""
    return plain_text(value).translate(_MARKDOWN)
