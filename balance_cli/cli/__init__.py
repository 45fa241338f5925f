"""The ``balance`` command: a thin face of the library.

Commands parse their options, call the library, render its results and write them. Library
errors name the library's parameters; here they are put in the words of the command line (its
flags, the configuration file) and become one line on standard error with exit status 1.

:mod:`.group` holds the group and that translation of errors; :mod:`.options`, :mod:`.batch`,
:mod:`.dispatch` and :mod:`.headless` what the commands share; each other module registers a
few commands on the group when imported here.
"""

import sys

from . import (  # noqa: F401
    animate,
    compare,
    counterweight,
    inspect,
    mounts,
    pictures,
    regress,
    search,
    sweep,
    torque,
    torsion,
    workshop,
)
from .group import main

__all__ = ["main"]


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
