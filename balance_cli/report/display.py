"""Text safety for tables: where figures get their significant digits, and where names are
made safe for Markdown and plain-text tables (display units are
:class:`~balance_cli.units.Scale`'s)."""

import re

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


#: characters a Markdown renderer reads as markup wherever they stand: emphasis, code, links,
#: a table's column separator and the escape itself
_MARKDOWN = str.maketrans(
    {
        "|": r"\|",
        "`": r"\`",
        "*": r"\*",
        "_": r"\_",
        "[": r"\[",
        "]": r"\]",
        "\\": "\\\\",
    }
)
#: what is markup only before certain characters: ``<`` opening an HTML tag, comment or
#: autolink (``<script>``, ``</b>``, ``<!--``, ``<?``), ``&`` a character reference
#: (``&amp;``, ``&#38;``); elsewhere they are plain text ("B&W", "a < b") and left alone
_MARKUP_START = re.compile(r"<(?=[A-Za-z/!?])|&(?=#?[A-Za-z0-9]+;)")


def markdown_text(value):
    """Text that a Markdown renderer shows as written: one line, no table breaks, no HTML. Only
    what Markdown would read as markup is escaped, with a backslash (CommonMark's escape of
    any ASCII punctuation): "B&W" stays "B&W"."""
    text = plain_text(value).translate(_MARKDOWN)
    return _MARKUP_START.sub(lambda match: "\\" + match.group(), text)
