"""The ``balance`` group, and the one place where a library error becomes a clean message.

Library errors name the library's parameters; here they are put in the words of the command
line (its flags, the configuration file) and become one line on standard error with exit
status 1. Every command registers itself on :func:`main`.
"""

import contextlib

import click

from ..about import __version__
from ..errors import BalanceError, ConfigError, FiringError

__all__ = ["main", "reported", "message", "FLAGS"]


#: library parameter -> command-line flag, for the library's messages
FLAGS = {
    "samples": "--samples",
    "max_order": "--max-order",
    "reference": "--reference",
    "planes": "--planes",
    "radius_m": "--radius",
    "balance_factor": "--balance-factor",
    "shaft_orders": "--shafts",
    "antivibrateur_radius_m": "--antivibrateur-radius",
    "test_masses": "--test-masses",
    "path": "--output",
    "units": "--units",
    "rtol": "--rtol",
    "order": "--order",
    "pressure": "--pressure",
    "inertia_kgm2": "--inertia",
    "target": "--target",
    "speed_rad_s": "--speed",
    "speeds_rpm": "--speeds",
    "load": "--load",
    "torque_nm": "--torque",
    "bore_m": "--bore",
}


def message(exc, engine=None, flags=None):
    """A library error in the command line's words: flags for parameters, and the file of the
    engine it concerns."""
    if isinstance(exc, ConfigError):
        return str(exc)
    if isinstance(exc, FiringError):
        return str(ConfigError(engine.config_path, "firing_order", str(exc)))
    text = exc.named({**FLAGS, **(flags or {})})
    return f"{engine.config_path}: {text}" if engine is not None else text


@contextlib.contextmanager
def reported(engine=None, flags=None):
    """Any library error inside becomes one line and exit status 1; ``flags`` names this
    command's options where they differ from the usual ones."""
    try:
        yield
    except BalanceError as exc:
        raise click.ClickException(message(exc, engine, flags)) from None


@click.group(context_settings={"help_option_names": ["-h", "--help"]})
@click.version_option(__version__, prog_name="balance")
def main():
    """Compare reciprocating-engine layouts for mechanical balance.

    Engines are described in TOML files (see balance's documentation, How-to: Describe an
    engine). Forces and moments are computed exactly from the true motion of every mass,
    order by order.

    The engine library and search templates shipped with balance are named from any folder:
    library:NAME (balance list lists them; library:tanaka-part3, library:today/v/v12-60.toml)
    and template:NAME (template:inline-6-2stroke); the .toml may be left out.
    """
