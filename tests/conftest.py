"""Fixtures every test module may use (plain helpers are in tests/support.py)."""

import os
import sys

import pytest

from tests.support import CAR_GAS, CONFIGS, PART3, TWIN, V8, inline_toml

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


# --- analysed engines that the pictures, the report and the papers' checks share -------------


@pytest.fixture(scope="module")
def library():
    """Every engine of configs/, analysed once."""
    import balance_cli as balance

    return [balance.analyse(e) for e in balance.load_many([CONFIGS])]


@pytest.fixture(scope="module")
def part3():
    from balance_cli import analyse, load

    return {path.stem: analyse(load(path)) for path in sorted(PART3.glob("*.toml"))}


@pytest.fixture(scope="module")
def couples(tmp_path_factory):
    """An in-line 3 (throws 0/120/240°), a 180° twin and a cross-plane 90° V8 (throws 0, 90,
    270, 180°), all 100 mm apart; and an in-line 24 two-stroke with throws 105° apart in turn,
    which has free moments of every order (a crowded star)."""
    from balance_cli import analyse, load

    folder = tmp_path_factory.mktemp("couples")
    engines = {
        "inline-3": inline_toml("In-line 3", [0, 120, 240], 100),
        "twin": inline_toml("180° twin", [0, 180], 100, cycle=4),
        "v8-cross": inline_toml(
            "90° V8, cross-plane", [0, 90, 270, 180], 100, cycle=4, banks=(-45, 45)
        ),
        "inline-24": inline_toml("In-line 24", [(105 * j) % 360 for j in range(24)], 90),
    }
    results = {}
    for key, text in engines.items():
        path = folder / f"{key}.toml"
        path.write_text(text, encoding="utf-8")
        results[key] = analyse(load(path))
    return results


@pytest.fixture(scope="module")
def gas_config(tmp_path_factory):
    """The car's in-line four with a [gas] cycle: a four-stroke with gas and half orders."""
    text = (CONFIGS / "inline-4-car.toml").read_text(encoding="utf-8")
    path = tmp_path_factory.mktemp("gas") / "inline-4-gas.toml"
    path.write_text(
        text.replace('name = "In-line 4, car proportions"', 'name = "In-line 4, car, with gas"')
        + CAR_GAS,
        encoding="utf-8",
    )
    return path


@pytest.fixture(scope="module")
def torques(gas_config):
    """A four-stroke with gas, a four-stroke without and a two-stroke, in that order."""
    from balance_cli import load
    from balance_cli.analysis.torque import torque

    return [
        torque(load(path))
        for path in (
            gas_config,
            V8,
            CONFIGS / "inline-4-marine.toml",
            CONFIGS / "nakanishi-w12-60-2stroke.toml",
        )
    ]
