"""The documented Python API: the examples of its how-to page run, results equal the command
line's JSON, errors derive from one base and name parameters, modules are not shadowed."""

import importlib
import inspect
import json
import pkgutil
import re
import subprocess
import sys

import pytest
from click.testing import CliRunner

import balance_cli as balance
from balance_cli.cli import main
from tests.support import CONFIGS, PART3, ROOT, V12, make_engine

#: the page that documents the API by example (docs/howto/python-api.md)
API_PAGE = ROOT / "docs" / "howto" / "python-api.md"


def page_python_blocks():
    text = API_PAGE.read_text(encoding="utf-8")
    return re.findall(r"^```python\n(.*?)^```", text, flags=re.S | re.M)


def cli_json(*args):
    result = CliRunner().invoke(main, [str(a) for a in args])
    assert result.exit_code == 0, result.output
    return json.loads(result.stdout)


def test_the_api_page_examples_run_as_written(tmp_path, monkeypatch):
    """Run in a folder of their own (they write spectrum.svg), with configs/ beside them."""
    blocks = page_python_blocks()
    assert len(blocks) == 2
    (tmp_path / "configs").symlink_to(CONFIGS)
    (tmp_path / "templates").symlink_to(ROOT / "templates")
    monkeypatch.chdir(tmp_path)
    namespace = {}
    for block in blocks:
        exec(compile(block, str(API_PAGE), "exec"), namespace)
    assert (tmp_path / "spectrum.svg").read_bytes().startswith(b"<?xml")
    assert isinstance(namespace["fig"], __import__("matplotlib.figure").figure.Figure)


def test_a_snippet_with_text_defined_runs_and_raises_for_a_missing_plane():
    """A snippet that asks for planes [1, 6] of the four-throw in-line 4: the library says
    which throw is missing, naming its parameter."""
    path = CONFIGS / "inline-4-car.toml"
    engine = balance.load(path)
    assert balance.loads(path.read_text(encoding="utf-8"), name="my.toml").config_path == "my.toml"
    result = balance.analyse(engine, samples=256, max_order=8)
    assert result.order(2).order == 2
    with pytest.raises(
        balance.CounterweightError, match="planes names throw 6, but the engine has throws 1 to 4"
    ) as caught:
        balance.counterweights(engine, planes=[1, 6], radius_m=0.06, balance_factor=None)
    assert caught.value.parameter == "planes"
    assert balance.plot.locus([result]).axes


@pytest.mark.parametrize("config", sorted(p.relative_to(CONFIGS) for p in CONFIGS.rglob("*.toml")))
def test_result_to_dict_is_the_compare_entry(config):
    path = CONFIGS / config
    (entry,) = cli_json("compare", path, "--format", "json", "--max-order", "10")["engines"]
    assert balance.analyse(balance.load(path), max_order=10).to_dict() == entry


def test_to_dict_with_a_reference_is_the_entry_of_a_comparison():
    document = cli_json("compare", PART3, "--format", "json", "--reference", "60° W12,")
    results = [balance.analyse(e) for e in balance.load_many([PART3])]
    comparison = balance.compare(results, reference="60° W12,")
    assert comparison.to_dict() == document
    assert [r.to_dict(comparison.reference) for r in results] == document["engines"]


@pytest.mark.parametrize(
    "args, kwargs",
    [
        (
            [V12, "--planes", "1,6", "--radius", "60 mm", "--shafts", "6", "--test-masses"],
            dict(planes=[1, 6], radius_m=0.06, shaft_orders=(6,), test_masses=True),
        ),
        ([CONFIGS / "bramo-323.toml", "--antivibrateur"], dict(antivibrateur_radius_m=0.040)),
        (
            [CONFIGS / "inline-4-car.toml", "--balance-factor", "0.5", "--planes", "0 mm,264 mm"],
            dict(balance_factor=0.5, planes=[balance.Plane(0.0), balance.Plane(0.264)]),
        ),
    ],
)
def test_balance_to_dict_is_the_counterweight_entry(args, kwargs):
    (entry,) = cli_json("counterweight", *args, "--format", "json")["engines"]
    engine = balance.load(args[0])
    assert balance.counterweights(engine, **kwargs).to_dict() == entry
    # an analysed result gives the same, without a second analysis
    assert balance.counterweights(balance.analyse(engine), **kwargs).to_dict() == entry


def test_order_is_one_based_and_keyerror_outside():
    result = balance.analyse(balance.load(V12), max_order=6)
    assert result.order(1) is result.shaking.orders[0] and result.order(6).order == 6
    for k in (0, 7, -1, 1.0, "2"):
        with pytest.raises(KeyError):
            result.order(k)


def test_every_error_derives_from_balance_error_and_names_parameters_not_flags():
    engine = balance.load(V12)
    calls = [
        lambda: balance.analyse(engine, samples=10),
        lambda: balance.analyse(engine, max_order=0),
        lambda: balance.counterweights(engine, radius_m=-1.0),
        lambda: balance.counterweights(engine, balance_factor=2.0),
        lambda: balance.counterweights(engine, shaft_orders=(40,)),
        lambda: balance.counterweights(engine, planes=[1, 2, 3]),
        lambda: balance.counterweights(engine, antivibrateur_radius_m=0.04),
        lambda: balance.compare([balance.analyse(engine)], reference="nothing"),
        lambda: balance.loads("name = ", name="x.toml"),
        lambda: balance.load(CONFIGS / "missing.toml"),
        lambda: balance.plot.spectrum([balance.analyse(engine)], units="furlongs"),
        lambda: balance.plot.save(balance.plot.locus([balance.analyse(engine)]), "x.doc"),
        lambda: balance.plot.locus([]),
    ]
    for call in calls:
        with pytest.raises(balance.BalanceError) as caught:
            call()
        assert "--" not in str(caught.value), str(caught.value)
    for name in balance.__all__:
        thing = getattr(balance, name)
        if isinstance(thing, type) and issubclass(thing, Exception):
            assert issubclass(thing, balance.BalanceError) or thing is balance.SamplingWarning


def test_an_engine_built_in_code_that_cannot_be_assembled_raises():
    """A link rod too short to reach its axis: refused, never clamped."""
    engine = make_engine([0, 60], [(0, 0.0)], links=(0, 0.03, 0.05, 0.0))
    with pytest.raises(balance.ModelError, match="cylinder 2: its link rod cannot reach") as caught:
        balance.analyse(engine)
    assert caught.value.cylinder == 2


def test_modules_and_functions_do_not_shadow_each_other():
    for module in pkgutil.walk_packages(balance.__path__, "balance_cli."):
        imported = importlib.import_module(module.name)
        parent, _, name = module.name.rpartition(".")
        assert getattr(importlib.import_module(parent), name) is imported, module.name


def test_public_names_stay_what_they_are_once_every_module_is_loaded():
    """A lazily loaded function named like its module (balance.family in family.py) would be
    replaced by the module as soon as the module is imported."""
    for module in pkgutil.walk_packages(balance.__path__, "balance_cli."):
        importlib.import_module(module.name)
    modules = [
        name
        for name in balance.__all__
        if name != "plot" and inspect.ismodule(getattr(balance, name))
    ]
    assert modules == []
    assert callable(balance.family) and callable(balance.sweep) and callable(balance.search)


def test_importing_the_library_does_not_import_matplotlib():
    code = "import sys, balance_cli; assert 'matplotlib' not in sys.modules"
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr


def test_the_package_is_typed():
    assert (ROOT / "balance_cli" / "py.typed").exists()
    assert balance.analyse.__annotations__["return"] is balance.EngineResult
    assert "py.typed" in (ROOT / "pyproject.toml").read_text()


def test_compare_does_not_import_matplotlib():
    code = (
        "import sys; from balance_cli.cli import main\n"
        "try:\n    main(['compare', sys.argv[1], '--format', 'json', '-o', sys.argv[2]])\n"
        "except SystemExit:\n    pass\n"
        "assert 'matplotlib' not in sys.modules, 'matplotlib imported'\n"
    )
    import tempfile

    with tempfile.TemporaryDirectory() as folder:
        done = subprocess.run(
            [sys.executable, "-c", code, str(PART3), f"{folder}/o.json"],
            capture_output=True,
            text=True,
        )
    assert done.returncode == 0, done.stderr
