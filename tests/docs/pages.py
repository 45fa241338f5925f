"""What the documentation site's tests share: its pages, their code blocks, and the keys'
table module of its Sphinx extension (pure Python: the tests need no Sphinx)."""

import importlib.util
import re
import sys

from tests.support import ROOT

DOCS = ROOT / "docs"
#: the site's own pages (not what Sphinx generates into generated/ and _build/)
PAGES = sorted(
    p
    for p in [*DOCS.rglob("*.md"), *DOCS.rglob("*.rst")]
    if not {"_build", "generated"} & set(p.relative_to(DOCS).parts)
)
#: the galleries' scripts, run when the site is built
SCRIPTS = sorted([*(DOCS / "tutorials").glob("*.py"), *(DOCS / "examples").glob("*.py")])

_MD_FENCE = re.compile(r"^```([\w-]*)[^\n]*\n(.*?)^```", re.S | re.M)
_RST_BLOCK = re.compile(r"^\.\. code-block:: (\w+)\n((?:\n|[ \t]+[^\n]*\n)+)", re.M)


def code_blocks(path, language):
    """The code blocks of ``language`` in a Markdown (fenced) or reStructuredText
    (``.. code-block::``) page, in order."""
    text = path.read_text(encoding="utf-8")
    if path.suffix == ".md":
        return [body for lang, body in _MD_FENCE.findall(text) if lang == language]
    blocks = []
    for lang, body in _RST_BLOCK.findall(text):
        if lang == language:
            lines = [line for line in body.splitlines() if line.strip()]
            indent = min(len(line) - len(line.lstrip()) for line in lines)
            blocks.append("\n".join(line[indent:] for line in body.strip("\n").splitlines()))
    return blocks


def keys_table():
    """docs/_ext/keys_table.py, the configuration keys' tables and their check."""
    name = "balance_docs_keys_table"
    if name not in sys.modules:
        spec = importlib.util.spec_from_file_location(name, DOCS / "_ext" / "keys_table.py")
        module = importlib.util.module_from_spec(spec)
        sys.modules[name] = module
        spec.loader.exec_module(module)
    return sys.modules[name]
