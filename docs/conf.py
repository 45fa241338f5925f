"""Sphinx configuration of balance's documentation site (``make docs``).

The reference is generated from the package so that it cannot drift: the Python API by
autosummary and numpydoc from ``balance_cli.__all__``, the command line by sphinx-click from
the ``balance`` group, the configuration keys by ``_ext/balance_docs.py`` from the reader's key
sets. The tutorials and examples are sphinx-gallery scripts, run at every build (headless:
Agg). The build runs with ``-W --keep-going -n``: any warning, and any cross-reference that
does not resolve, fails it. Nothing is fetched from the network (no intersphinx).
"""

import os
import sys
from pathlib import Path

# the examples draw headless; set before anything imports matplotlib
os.environ.setdefault("MPLBACKEND", "Agg")

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
sys.path.insert(0, str(HERE / "_ext"))

import balance_cli  # noqa: E402  (after the backend is chosen)

project = "balance"
author = "the balance authors"
copyright = "the balance authors, MIT licence"
release = balance_cli.__version__
version = release

extensions = [
    "sphinx.ext.autodoc",
    "sphinx.ext.autosummary",
    "numpydoc",
    "sphinx_click",
    "sphinx_gallery.gen_gallery",
    "myst_parser",
    "balance_docs",
]

source_suffix = {".rst": "restructuredtext", ".md": "markdown"}
root_doc = "index"
# what Sphinx does not read as pages: the build, the gallery sources (sphinx-gallery turns them
# into pages under generated/), and the pictures the README shows
exclude_patterns = [
    "_build",
    "tutorials",
    "examples",
    "_ext",
    "_templates",
    # included by validation.md, not a page of its own
    "VALIDATION.md",
    "Thumbs.db",
    ".DS_Store",
]
templates_path = ["_templates"]

# every cross-reference must resolve (-n)
nitpicky = True
# a docstring's types are words, not cross-references (numpydoc_xref_param_type stays False),
# and signatures show no annotations: the docstrings give the types with their units
autodoc_typehints = "none"
autosummary_generate = True
# a module's page lists what its __all__ names (balance_cli.plot re-exports its submodules')
autosummary_ignore_module_all = False
# numpydoc lists a class's members itself; autosummary's class template does not repeat them
numpydoc_show_class_members = False
numpydoc_class_members_toctree = False

# MyST: ``:::`` fences and definition lists; headings get anchors for cross-page links
myst_enable_extensions = ["colon_fence", "deflist"]
myst_heading_anchors = 3

# the tutorials and the examples: run at every build (run_stale_examples: the library may have
# changed under an unchanged script), each a page with its pictures
sphinx_gallery_conf = {
    "examples_dirs": ["tutorials", "examples"],
    "gallery_dirs": ["generated/tutorials", "generated/examples"],
    "filename_pattern": r"/plot_",
    "run_stale_examples": True,
    "abort_on_example_error": True,
    "only_warn_on_example_error": False,
    "download_all_examples": False,
    "remove_config_comments": True,
    "matplotlib_animations": False,
    "image_scrapers": ("matplotlib",),
    "reference_url": {"balance_cli": None},
    "backreferences_dir": None,
    "within_subsection_order": "FileNameSortKey",
    "show_memory": False,
    "plot_gallery": "True",
    "write_computation_times": False,
}

html_theme = "pydata_sphinx_theme"
html_title = f"balance {release}"
html_theme_options = {
    "navigation_with_keys": False,
    "show_toc_level": 2,
    "footer_start": ["copyright"],
    "footer_end": ["sphinx-version"],
    "icon_links": [],
}
# without a default mode the theme reads "" on a reader's first visit (nothing stored yet) and
# logs a console error before falling back to auto (tools/check_site.py, run by make docs, saw it)
html_context = {"default_mode": "auto"}
html_static_path: list[str] = []
html_show_sourcelink = False
