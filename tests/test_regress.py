"""`balance regress` (issue 12): a user's design guarded in CI."""

import json
import shutil
import xml.etree.ElementTree as ET

import pytest
from click.testing import CliRunner

import balance_cli as balance
from balance_cli.cli import main
from balance_cli.studies.regress import regression as regress
from tests.support import CONFIGS


#: the library's engines, counted rather than written down: adding a configuration must not
#: break these tests
LIBRARY = len(balance.find_configs([CONFIGS]))


def invoke(*args):
    return CliRunner().invoke(main, [str(a) for a in args])


@pytest.fixture
def project(tmp_path, monkeypatch):
    """A user's repository: the library's configurations and a baseline of them, committed."""
    shutil.copytree(CONFIGS, tmp_path / "configs")
    monkeypatch.chdir(tmp_path)
    result = invoke("compare", "configs", "--format", "json", "-o", "baseline.json")
    assert result.exit_code == 0, result.output
    return tmp_path


def change_mass(path, factor):
    text = path.read_text(encoding="utf-8")
    old = text.split('reciprocating = "', 1)[1].split('"', 1)[0]
    number, unit = old.split()
    path.write_text(text.replace(f'reciprocating = "{old}"',
                                 f'reciprocating = "{float(number) * factor!r} {unit}"', 1),
                    encoding="utf-8")


def test_a_baseline_of_the_library_regresses_clean(project):
    result = invoke("regress", "baseline.json")
    assert result.exit_code == 0, result.output
    assert f"nothing moved beyond tolerance ({LIBRARY} engines checked against baseline.json)" in result.stdout


def test_one_percent_more_reciprocating_mass_fails_naming_the_engine_and_its_orders(project):
    change_mass(project / "configs" / "inline-4-car.toml", 1.01)
    result = invoke("regress", "baseline.json", "--format", "json")
    assert result.exit_code == 1
    document = json.loads(result.stdout)
    assert document["moved"] and document["added"] == [] and document["removed"] == []
    assert {row["engine"] for row in document["rows"]} == {"In-line 4, car proportions"}
    orders = {row["order"] for row in document["rows"] if row["quantity"] == "force.max_N"}
    assert orders == {2, 4, 6, 8}      # a flat-crank four: the even orders, all 1 % up
    for row in document["rows"]:
        if row["quantity"].startswith("force.") and row["quantity"].endswith("_N"):
            # exactly 1 % (forces are proportional to the mass); the 8th order, 1e-5 of the
            # 2nd, carries its rounding (1e-13 of the largest force) as 1e-8 of itself
            assert row["relative_change"] == pytest.approx(0.01, rel=1e-6)
    # a looser tolerance lets it pass; a tighter one not
    assert invoke("regress", "baseline.json", "--rtol", "0.011").exit_code == 0
    assert invoke("regress", "baseline.json", "--rtol", "0.009").exit_code == 1


def test_added_and_removed_engines_are_listed(project):
    (project / "configs" / "inline-12.toml").rename(project / "elsewhere.toml")
    extra = (project / "configs" / "inline-4-car.toml").read_text(encoding="utf-8").replace(
        'name = "In-line 4, car proportions"', 'name = "In-line 4, my variant"')
    (project / "configs" / "mine.toml").write_text(extra, encoding="utf-8")
    result = invoke("regress", "baseline.json", "configs")
    assert result.exit_code == 1
    text = result.stdout
    assert f"0 quantities moved in 0 of {LIBRARY - 1} engines; 1 added, 1 removed" in text
    added = text.split("Engines added")[1].split("Engines removed")[0]
    removed = text.split("Engines removed")[1]
    assert "- In-line 4, my variant" in added and "- In-line 12" in removed


def test_junit_parses_and_counts_the_failure(project):
    change_mass(project / "configs" / "abc-dragonfly.toml", 1.01)
    result = invoke("regress", "baseline.json", "--format", "junit", "-o", "report.xml")
    assert result.exit_code == 1
    root = ET.parse(project / "report.xml").getroot()
    assert root.tag == "testsuites" and root.get("tests") == str(LIBRARY) and root.get("failures") == "1"
    (suite,) = root
    failed = [case for case in suite if case.find("failure") is not None]
    assert [case.get("name") for case in failed] == ["ABC Dragonfly 9-cylinder radial"]
    assert failed[0].get("file") == "configs/abc-dragonfly.toml"
    assert "order 1 force.forward_N" in failed[0].find("failure").text


def test_markdown_is_a_job_summary(project):
    change_mass(project / "configs" / "inline-4-marine.toml", 0.99)
    result = invoke("regress", "baseline.json", "--format", "markdown")
    assert result.exit_code == 1
    assert result.stdout.startswith("### balance regress: ")
    assert "| In-line 4 marine (lecture notes) | 2 " in result.stdout


def test_update_rewrites_the_baseline_and_then_it_is_clean(project):
    change_mass(project / "configs" / "inline-4-car.toml", 1.01)
    result = invoke("regress", "baseline.json", "--update")
    assert result.exit_code == 0 and "force.max_N" in result.stdout
    assert "wrote baseline.json" in result.stderr
    assert invoke("regress", "baseline.json").exit_code == 0
    assert sorted(p.name for p in project.iterdir()) == ["baseline.json", "configs"]


def test_the_baseline_settings_are_used(project):
    invoke("compare", "configs/tanaka-part3", "--format", "json", "--samples", "128",
           "--max-order", "5", "-o", "small.json")
    result = invoke("regress", "small.json", "--format", "json")
    assert result.exit_code == 0, result.output
    assert len(json.loads(result.stdout)["engines_checked"]) == 9


@pytest.mark.parametrize("content, words", [
    ("not json", "not JSON"),
    ('{"engines": []}', "no 'balance_version'"),
    ('{"balance_version": 3, "engines": [], "samples": 256, "max_order": 8}',
     "written by balance_version 3"),
    ('[1, 2]', "not a `balance compare --format json` document"),
    ('{"balance_version": 1, "samples": 256, "max_order": 8, "engines": [{"name": "x"}]}',
     "engines[1]: lacks config, cylinders, firing, orders, unit_force_N"),
])
def test_a_baseline_that_is_not_a_comparison(tmp_path, content, words):
    baseline = tmp_path / "b.json"
    baseline.write_text(content, encoding="utf-8")
    result = invoke("regress", baseline)
    assert result.exit_code == 1 and isinstance(result.exception, SystemExit)
    assert result.stderr.count("\n") == 1 and words in result.stderr


def test_a_missing_configuration_or_baseline(project):
    (project / "configs" / "inline-12.toml").unlink()
    result = invoke("regress", "baseline.json")
    assert result.exit_code == 1 and result.stderr.count("\n") == 1
    assert "names the configuration 'configs/inline-12.toml' of 'In-line 12', which no longer exists" \
        in result.stderr
    result = invoke("regress", "nothing.json")
    assert result.exit_code == 1 and "nothing.json: no such file" in result.stderr


def test_usage_errors_and_outputs_that_are_inputs(project):
    assert invoke("regress", "baseline.json", "--format", "xml").exit_code == 2
    assert invoke("regress", "baseline.json", "--rtol", "1.5").exit_code == 1
    before = (project / "baseline.json").read_bytes()
    result = invoke("regress", "baseline.json", "-o", "baseline.json")
    assert result.exit_code == 1 and "is an input file" in result.stderr
    assert (project / "baseline.json").read_bytes() == before


def test_regress_from_python():
    """The library function on a document: a phase that turns is a row; one of a phasor at
    the noise level is not."""
    import balance_cli as balance

    comparison = balance.compare([balance.analyse(balance.load(CONFIGS / "abc-dragonfly.toml"))])
    baseline = comparison.to_dict()
    changed = json.loads(json.dumps(baseline))
    second = changed["engines"][0]["orders"][1]["force"]
    second["forward_deg"] = (second["forward_deg"] + 0.5) % 360
    rows = regress(baseline, changed).rows
    assert [(r.order, r.quantity) for r in rows] == [(2, "force.forward_deg")]
    assert rows[0].change == pytest.approx(0.5, abs=1e-9)
    assert not regress(baseline, comparison).moved
