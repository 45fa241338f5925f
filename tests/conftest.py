"""Fixtures every test module may use (plain helpers are in tests/support.py)."""

import os
import sys

import pytest

from tests.support import TWIN

os.environ.setdefault("MPLBACKEND", "Agg")


@pytest.fixture(autouse=True)
def _close_figures():
    yield
    if "matplotlib.pyplot" in sys.modules:
        sys.modules["matplotlib.pyplot"].close("all")


@pytest.fixture
def twin(tmp_path):
    """The shared twin configuration (180°, 90 mm apart) in a file."""
    path = tmp_path / "twin.toml"
    path.write_text(TWIN, encoding="utf-8")
    return path
