"""report.html: the report's blocks as one self-contained page, pictures inlined as SVG."""

import html
import re
from pathlib import Path

from tabulate import tabulate

from .display import plain_text

__all__ = ["page"]

_CSS = """
body { font-family: sans-serif; margin: 2em auto; max-width: 1200px; color: #222; }
table { border-collapse: collapse; margin: 0.5em 0 1.5em; font-size: 0.85em; }
th, td { border: 1px solid #bbb; padding: 0.2em 0.5em; text-align: right; }
th:first-child, td:first-child { text-align: left; }
figure { margin: 1em 0 2em; } figure svg { max-width: 100%; height: auto; }
figcaption { font-size: 0.9em; color: #444; }
"""


def _inline_svg(path):
    """The <svg> element of a picture file, without its XML prologue."""
    text = Path(path).read_text(encoding="utf-8")
    return text[text.index("<svg") :]


def _table(headers, rows):
    # tabulate's "html" format escapes every cell
    return tabulate(
        [[plain_text(c) for c in row] for row in rows],
        headers=headers,
        tablefmt="html",
        disable_numparse=True,
    )


def page(blocks, folder, animations=()):
    """The page; the pictures are read from ``folder``; ``animations`` (each engine's name and
    its animation's HTML without style and script, :meth:`EngineAnimation.html
    <balance_cli.plot.EngineAnimation.html>`) in a section of their own at the end, drawn by
    one script."""
    body = []
    for block in blocks:
        if block[0] == "h":
            body.append(f"<h{block[1]}>{html.escape(block[2])}</h{block[1]}>")
        elif block[0] == "p":
            text = re.sub(r"`([^`]+)`", r"<code>\1</code>", html.escape(block[1]))
            body.append(f"<p>{text}</p>")
        elif block[0] == "table":
            body.append(_table(block[1], block[2]))
        else:
            _, file, title, caption = block
            body.append(
                f'<figure id="{html.escape(file)}"><h3>{html.escape(title)}</h3>'
                f"{_inline_svg(Path(folder) / file)}<figcaption>{html.escape(caption)}"
                "</figcaption></figure>"
            )
    if animations:
        from ..plot.page import script, style

        body.append("<h2>Animations</h2>")
        body.append(
            "<p>Each engine turning through its cycle, beside the forward and backward phasors "
            "of its force and free moment, orders 1 and 2 at first: play and pause, speed, a "
            "step to each firing top dead centre, orders and cylinders on and off.</p>"
        )
        for name, content in animations:
            body.append(f"<h3>{html.escape(name)}</h3>\n{content}")
        body.append(style() + script())
    return (
        '<!DOCTYPE html>\n<html lang="en"><head><meta charset="utf-8">'
        "<title>Balance report</title>"
        f"<style>{_CSS}</style></head><body>\n" + "\n".join(body) + "\n</body></html>\n"
    )
