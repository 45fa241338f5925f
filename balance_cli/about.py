"""What this package is called and which version it is: the one source of both.

The distribution on the package index is ``engine-balance`` (``balance`` there is an unrelated
survey-weighting library); the command is ``balance`` and the import package ``balance_cli``.
Imports nothing: the ground floor of the package.
"""

__all__ = ["__version__", "DISTRIBUTION", "install_hint"]

__version__ = "0.3.0"

#: the distribution's name on the package index: what ``pip install`` takes
DISTRIBUTION = "engine-balance"


def install_hint(extra: str) -> str:
    """The command that installs this distribution with an optional ``extra``."""
    return f"pip install '{DISTRIBUTION}[{extra}]'"
