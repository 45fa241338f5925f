"""report.md: the report's blocks as Markdown, pictures by relative links."""

from .table import render

__all__ = ["markdown"]


def markdown(blocks):
    out = []
    for block in blocks:
        if block[0] == "h":
            out += ["#" * block[1] + " " + block[2], ""]
        elif block[0] == "p":
            out += [block[1], ""]
        elif block[0] == "table":
            out += [render(block[1], block[2], "markdown"), ""]
        else:
            _, file, title, caption = block
            out += [f"### {title}", "", f"![{title}]({file})", "", caption, ""]
    return "\n".join(out)
