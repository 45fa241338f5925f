"""The packages to install, which pyproject.toml (where everything else is) cannot list: a
``find`` there takes no package whose folder is mapped elsewhere, and the list must hold
every package of balance_cli, found, and the data-only packages balance_cli.library and
balance_cli.templates that pyproject.toml's package-dir maps onto configs/ and templates/."""

from setuptools import find_packages, setup

setup(packages=find_packages(include=["balance_cli", "balance_cli.*"])
      + ["balance_cli.library", "balance_cli.templates"])
