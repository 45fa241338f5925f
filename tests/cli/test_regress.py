"""balance regress: a user's design guarded in CI."""

import json
import math
import re
import shutil
import xml.etree.ElementTree as ET

import pytest
from numpy.testing import assert_allclose

import balance_cli as balance
from balance_cli.studies.regress import check_baseline, regression
from tests.support import CONFIGS, ROOT, TWIN, check_refused, invoke, snapshot

#: the library's engines, counted rather than written down: adding a configuration must not
#: break these tests
LIBRARY = len(balance.find_configs([CONFIGS]))


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
    path.write_text(
        text.replace(
            f'reciprocating = "{old}"', f'reciprocating = "{float(number) * factor!r} {unit}"', 1
        ),
        encoding="utf-8",
    )


def test_a_baseline_of_the_library_regresses_clean(project):
    result = invoke("regress", "baseline.json")
    assert result.exit_code == 0, result.output
    assert (
        f"nothing moved beyond tolerance ({LIBRARY} engines checked against baseline.json)"
        in result.stdout
    )


def test_one_percent_more_reciprocating_mass_fails_naming_the_engine_and_its_orders(project):
    change_mass(project / "configs" / "inline-4-car.toml", 1.01)
    result = invoke("regress", "baseline.json", "--format", "json")
    assert result.exit_code == 1
    document = json.loads(result.stdout)
    assert document["moved"] and document["added"] == [] and document["removed"] == []
    assert {row["engine"] for row in document["rows"]} == {"In-line 4, car proportions"}
    orders = {row["order"] for row in document["rows"] if row["quantity"] == "force.max_N"}
    assert orders == {2, 4, 6, 8}  # a flat-crank four: the even orders, all 1 % up
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
    extra = (
        (project / "configs" / "inline-4-car.toml")
        .read_text(encoding="utf-8")
        .replace('name = "In-line 4, car proportions"', 'name = "In-line 4, my variant"')
    )
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
    assert (
        root.tag == "testsuites"
        and root.get("tests") == str(LIBRARY)
        and root.get("failures") == "1"
    )
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
    invoke(
        "compare",
        "configs/tanaka-part3",
        "--format",
        "json",
        "--samples",
        "128",
        "--max-order",
        "5",
        "-o",
        "small.json",
    )
    result = invoke("regress", "small.json", "--format", "json")
    assert result.exit_code == 0, result.output
    assert len(json.loads(result.stdout)["engines_checked"]) == 9


@pytest.mark.parametrize(
    "content, words",
    [
        ("not json", "not JSON"),
        ('{"engines": []}', "no 'balance_version'"),
        (
            '{"balance_version": 4, "engines": [], "samples": 256, "max_order": 8}',
            "written by balance_version 4",
        ),
        ("[1, 2]", "not a `balance compare --format json` document"),
        (
            '{"balance_version": 1, "samples": 256, "max_order": 8, "engines": [{"name": "x"}]}',
            "$.engines[0] ('x'): lacks 'config', 'cylinders', 'cycle', 'frame', 'speed_rpm', "
            "'unit_force_N', 'largest_resultant_N', 'counterweighted_resultant_N', "
            "'sampling_ok', 'firing', 'orders' (compare.v1.json)",
        ),
    ],
)
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
    assert (
        "names the configuration 'configs/inline-12.toml' of 'In-line 12', which no longer exists"
        in result.stderr
    )
    result = invoke("regress", "nothing.json")
    assert result.exit_code == 1 and "nothing.json: no such file" in result.stderr


def test_usage_errors_and_outputs_that_are_inputs(project):
    assert invoke("regress", "baseline.json", "--format", "xml").exit_code == 2
    assert invoke("regress", "baseline.json", "--rtol", "1.5").exit_code == 1
    before = (project / "baseline.json").read_bytes()
    result = invoke("regress", "baseline.json", "-o", "baseline.json")
    assert result.exit_code == 1 and "is an input file" in result.stderr
    assert (project / "baseline.json").read_bytes() == before


@pytest.mark.parametrize(
    "content, words",
    [
        ("[" * 100_000 + "]" * 100_000, "not JSON that balance can read"),
        ('{"balance_version": 1, "samples": ' + "9" * 5000 + "}", "not JSON that balance can read"),
        ('{"balance_version": true, "engines": [1]}', "written by balance_version True"),
        (
            '{"balance_version": 1, "samples": -5, "max_order": 8, "engines": [1]}',
            "$.samples: is -5, below 5 (compare.v1.json)",
        ),
        (
            '{"balance_version": 3, "samples": 256, "max_order": 8, "engines": [1]}',
            "$: lacks 'reference' (compare.v3.json)",
        ),
    ],
)
def test_baselines_that_are_not_comparisons(tmp_path, content, words):
    baseline = tmp_path / "b.json"
    baseline.write_text(content, encoding="utf-8")
    before = snapshot(tmp_path)
    check_refused(invoke("regress", baseline), 1, words, before, tmp_path)


@pytest.mark.parametrize(
    "damage, words",
    [
        (lambda e: e["orders"][0].pop("force"), ".orders[0]: lacks 'force' (compare.v3.json)"),
        (lambda e: e.update(orders="x"), '.orders: is "x", not a list'),
        (lambda e: e.update(name=["a"]), '$.engines[0].name: is ["a"], not text'),
        (
            lambda e: e["orders"][0]["force"].update(max_N=math.nan),
            ".orders[0].force.max_N: is not a finite number",
        ),
        (lambda e: e.update(unit_force_N=-1.0), ".unit_force_N: is -1.0, not above 0"),
        (lambda e: e["firing"].update(order=None), ".firing.order: is null, not a list"),
        (lambda e: e["orders"].append(e["orders"][0]), ".orders: lists order 1 twice"),
    ],
)
def test_a_damaged_baseline_is_one_error_line(tmp_path, damage, words):
    document = balance.compare(
        [balance.analyse(balance.load(CONFIGS / "inline-4-car.toml"))]
    ).to_dict()
    damage(document["engines"][0])
    baseline = tmp_path / "b.json"
    baseline.write_text(json.dumps(document), encoding="utf-8")
    result = invoke("regress", baseline, CONFIGS / "inline-4-car.toml")
    assert result.exit_code == 1 and isinstance(result.exception, SystemExit)
    assert result.stderr.count("\n") == 1 and words in result.stderr


@pytest.mark.parametrize(
    "damage, words",
    [
        (
            lambda e: e.pop("largest_moment_Nm"),
            "$.engines[0] ('In-line 4, car'): lacks 'largest_moment_Nm' (compare.v3.json)",
        ),
        (lambda e: e.pop("vertical_deg"), "('In-line 4, car'): lacks 'vertical_deg'"),
        (
            lambda e: e["orders"][1]["moment"].pop("vertical_Nm"),
            "('In-line 4, car').orders[1].moment: lacks 'vertical_Nm'",
        ),
        (
            lambda e: [e["orders"][0]["force"].pop(k) for k in ("horizontal_N", "vertical_deg")],
            ".orders[0].force: lacks 'vertical_deg', 'horizontal_N'",
        ),
        (lambda e: e["firing"].pop("uniform"), "('In-line 4, car').firing: lacks 'uniform'"),
        (lambda e: e.pop("sampling_ok"), "lacks 'sampling_ok'"),
        (
            lambda e: e.update(counterweighted_moment_Nm=None),
            "('In-line 4, car').counterweighted_moment_Nm: is null, not a number",
        ),
        # version 3's schema is closed: a key it does not name is drift, not data
        (
            lambda e: e.update(comment="checked by hand"),
            "('In-line 4, car'): has 'comment', which the schema does not define (compare.v3.json)",
        ),
        (lambda e: e.pop("pru_note"), "('In-line 4, car'): lacks 'pru_note' (compare.v3.json)"),
        (
            lambda e: e["firing"].update(given="yes"),
            "('In-line 4, car').firing.given: is \"yes\", not true or false",
        ),
    ],
)
def test_a_version_2_baseline_lacking_what_regress_compares_is_refused(tmp_path, damage, words):
    """A baseline is checked against the schema of its version (compare.v3.json): each key the
    comparison reads is needed (a record without one used to pass, the key compared only
    "where both documents have it", leaving that guard off), and so is every other key, and
    no key the schema does not name. Refused in one line naming the file, the JSON path with
    its engine and what is wrong, with --update and --output too: nothing written, the
    baseline as it was."""
    config = tmp_path / "car.toml"
    text = (CONFIGS / "inline-4-car.toml").read_text(encoding="utf-8")
    name = next(line for line in text.splitlines() if line.startswith("name = "))
    config.write_text(text.replace(name, 'name = "In-line 4, car"'), encoding="utf-8")
    document = balance.compare([balance.analyse(balance.load(config))]).to_dict()
    assert document["balance_version"] == 3
    damage(document["engines"][0])
    baseline = tmp_path / "b.json"
    baseline.write_text(json.dumps(document), encoding="utf-8")
    before = snapshot(tmp_path)
    for extra in ([], ["--update"], ["--output", tmp_path / "moved.json"]):
        result = invoke("regress", baseline, config, *extra)
        check_refused(result, 1, f"{baseline}: $.engines[0] ", before, tmp_path)
        assert words in result.stderr, result.stderr
    with pytest.raises(balance.RegressError, match=re.escape(words)):
        regression(document, document)


def test_a_version_1_baseline_needs_only_version_1_keys():
    """The golden version-1 baseline lacks every version-2 key and is read, and so is one
    with keys that version 1 did not name (its schema, compare.v1.json, is what regress reads:
    releases of version 1 added keys to it); without one of version 1's keys (speed_rpm) it
    is refused like a version-3 one."""
    old = json.loads((ROOT / "tests" / "golden" / "compare-v1.json").read_text(encoding="utf-8"))
    check_baseline(old)
    check_baseline({**old, "comment": "kept by hand"})
    old["engines"][2].pop("speed_rpm")
    with pytest.raises(
        balance.RegressError, match=r"\$\.engines\[2\] \('.*'\): lacks 'speed_rpm' \(compare\.v1"
    ):
        check_baseline(old, "compare-v1.json")


def test_a_version_2_baseline_needs_version_2_keys():
    """A version-2 baseline is read against compare.v2.json: the vertical and horizontal
    components are needed, the keys version 3 added are not."""
    document = balance.compare([balance.analyse(balance.load(CONFIGS / "inline-4-car.toml"))])
    v2 = {**document.to_dict(), "balance_version": 2}
    v2["engines"][0] = {k: v for k, v in v2["engines"][0].items() if k not in ("pru", "pru_note")}
    check_baseline(v2)
    v2["engines"][0]["orders"][0]["moment"].pop("horizontal_deg")
    with pytest.raises(
        balance.RegressError,
        match=re.escape(
            "$.engines[0] ('In-line 4, car proportions').orders[0].moment: lacks "
            "'horizontal_deg' (compare.v2.json)"
        ),
    ):
        check_baseline(v2, "v2.json")


def test_settings_that_do_not_work_together_are_refused():
    """The schema takes each setting alone; 20 samples cannot resolve 8 orders (33 needed)."""
    old = json.loads((ROOT / "tests" / "golden" / "compare-v1.json").read_text(encoding="utf-8"))
    with pytest.raises(balance.RegressError, match="records samples must be from 49 to 65536"):
        check_baseline({**old, "samples": 20}, "compare-v1.json")


def test_regress_finds_configurations_from_the_baselines_folders(tmp_path, monkeypatch):
    """The README's CI example: a baseline written at the repository's root, kept in design/,
    naming design/x.toml, checked from inside design/."""
    design = tmp_path / "design"
    design.mkdir()
    (design / "car.toml").write_text((CONFIGS / "inline-4-car.toml").read_text(), encoding="utf-8")
    monkeypatch.chdir(tmp_path)
    assert (
        invoke("compare", "design", "--format", "json", "-o", "design/baseline.json").exit_code == 0
    )
    monkeypatch.chdir(design)
    result = invoke("regress", "baseline.json")
    assert result.exit_code == 0, result.output


def test_json_version_2_and_regress_reads_version_1(monkeypatch):
    """New keys only, and a baseline written by version 1 still regresses clean."""
    monkeypatch.chdir(ROOT)  # the baselines name their configurations from the root
    data = json.loads(invoke("compare", "configs", "--format", "json").output)
    assert data["balance_version"] == 3
    engine = data["engines"][0]
    for key in (
        "vertical_deg",
        "largest_moment_Nm",
        "counterweighted_moment_Nm",
        "main_force_order",
        "main_moment_order",
        "noise_floor_N",
        "noise_floor_Nm",
    ):
        assert key in engine
    # compare-v1.json is the golden baseline as version 1 wrote it, kept unchanged
    old = ROOT / "tests" / "golden" / "compare-v1.json"
    assert json.loads(old.read_text(encoding="utf-8"))["balance_version"] == 1
    out = invoke("regress", old)
    assert out.exit_code == 0, out.output


def test_regress_checks_the_version_2_quantities(twin, tmp_path):
    """Turning the engine's vertical by 60° moves no ellipse but every vertical and horizontal
    component: the twin's couple m·r·ω²·d was all pitch and is now cos 60° = ½ of it pitch."""
    baseline = tmp_path / "base.json"
    baseline.write_text(invoke("compare", twin, "--format", "json").output, encoding="utf-8")
    turned = tmp_path / "turned.toml"
    turned.write_text("vertical = 60\n" + TWIN, encoding="utf-8")
    out = invoke("regress", baseline, turned, "--format", "json")
    assert out.exit_code == 1
    rows = {(r["order"], r["quantity"]): r for r in json.loads(out.output)["rows"]}
    assert_allclose(
        rows[(1, "moment.vertical_Nm")]["now"],
        0.5 * rows[(1, "moment.vertical_Nm")]["baseline"],
        rtol=1e-12,
    )
    assert (None, "vertical_deg") in rows and (1, "moment.max_Nm") not in rows


def test_a_baseline_written_at_another_speed_is_checked_at_that_speed(twin, tmp_path):
    baseline = tmp_path / "fast.json"
    baseline.write_text(
        invoke("compare", twin, "--speed", "5000 rpm", "--format", "json").output, encoding="utf-8"
    )
    assert json.loads(baseline.read_text(encoding="utf-8"))["speed_override_rpm"] == 5000.0
    out = invoke("regress", baseline)
    assert out.exit_code == 0 and "nothing moved" in out.output and "1 engine checked" in out.output
    broken = json.loads(baseline.read_text(encoding="utf-8"))
    broken["speed_override_rpm"] = -1
    baseline.write_text(json.dumps(broken), encoding="utf-8")
    out = invoke("regress", baseline)
    assert out.exit_code == 1 and "speed_override_rpm" in out.output
