"""The engine library and search templates shipped with the package, named from any folder:
``library:NAME`` and ``template:NAME`` wherever a configuration path is taken.

From the checkout (the editable install ``make`` builds) they are the checkout's own configs/
and templates/; that a regular install carries them is what ``make install-check`` shows.
"""

import json
import re
import subprocess
import sys
import tomllib
from pathlib import Path

import pytest

import balance_cli as balance
from balance_cli.config import find_configs, load_many, load_template, read_configuration
from balance_cli.config.library import library_folder, resolve, templates_folder
from balance_cli.errors import ConfigError
from tests.support import CONFIGS, PART3, ROOT, TEMPLATES, invoke


@pytest.fixture
def elsewhere(tmp_path, monkeypatch):
    """A current folder outside the checkout: names must not depend on it."""
    monkeypatch.chdir(tmp_path)
    return tmp_path


def test_the_library_and_templates_of_a_checkout_are_its_own_folders():
    assert library_folder() == CONFIGS
    assert templates_folder() == TEMPLATES
    assert resolve("library:") == CONFIGS
    with pytest.raises(
        ConfigError,
        match="template:: names no template; give one of "
        "template:inline-12-2stroke, template:inline-3-2stroke",
    ):
        resolve("template:")


def test_library_names_resolve_to_the_checkouts_files_and_folders(elsewhere):
    assert resolve("library:tanaka-part3") == PART3
    assert resolve("library:tanaka-part3/") == PART3
    v8 = CONFIGS / "today" / "v" / "v8-90-cross-plane.toml"
    assert resolve("library:today/v/v8-90-cross-plane.toml") == v8
    assert resolve("library:today/v/v8-90-cross-plane") == v8  # the .toml is optional
    assert find_configs(["library:tanaka-part3"]) == find_configs([PART3])
    assert find_configs("library:") == find_configs([CONFIGS])
    assert [e.name for e in load_many(["library:tanaka-part3"])] == [
        e.name for e in load_many([PART3])
    ]
    assert balance.load("library:today/v/v8-90-cross-plane").name == balance.load(v8).name
    assert (
        read_configuration("library:inline-4-car.toml").data
        == read_configuration(CONFIGS / "inline-4-car.toml").data
    )


def test_template_names_resolve_with_or_without_their_toml(elsewhere):
    file = TEMPLATES / "inline-3-2stroke.toml"
    assert resolve("template:inline-3-2stroke.toml") == resolve("template:inline-3-2stroke") == file
    engine = load_template("template:inline-3-2stroke")
    assert engine.name == load_template(file).name
    assert read_configuration("template:inline-3-2stroke").data == read_configuration(file).data
    assert [resolve(f"template:{p.stem}") for p in sorted(TEMPLATES.glob("*.toml"))] == sorted(
        TEMPLATES.glob("*.toml")
    )


def test_only_strings_are_names_and_other_paths_are_left_alone():
    assert resolve("configs/inline-4-car.toml") == "configs/inline-4-car.toml"
    assert resolve(PART3) is PART3
    with pytest.raises(balance.ConfigError, match="no such file"):
        balance.load(Path("library:inline-4-car.toml"))  # a Path is a path, not a name


@pytest.mark.parametrize(
    "name, where, held",
    [
        ("library:tanaka", "library:", ["tanaka-part3/", "today/", "inline-4-car.toml"]),
        (
            "library:today/v/v9-90.toml",
            "library:today/v",
            ["v12-60.toml", "v8-90-cross-plane.toml"],
        ),
        ("library:today/nope/v12-60.toml", "library:today", ["boxer/", "v/", "w/"]),
        (
            "template:inline-5-2stroke",
            "template:",
            ["inline-3-2stroke.toml", "inline-6-4stroke.toml"],
        ),
    ],
)
def test_a_bad_name_is_one_line_naming_it_and_what_exists(name, where, held):
    with pytest.raises(balance.ConfigError) as caught:
        balance.load(name)
    text = str(caught.value)
    assert "\n" not in text
    assert text.startswith(f"{name}: not in the shipped ")
    assert f"; {where} holds " in text
    for entry in held:
        assert entry in text
    assert "README" not in text  # what can be named: folders and .toml files


def test_a_name_cannot_leave_the_library():
    with pytest.raises(
        balance.ConfigError, match=r"'\.\.' leads out of the shipped engine library"
    ):
        find_configs(["library:../templates"])


def test_every_file_of_the_library_and_templates_is_package_data():
    """pyproject.toml's package-data globs take every file of configs/ and templates/: a new
    kind of file the configurations need (a CSV, say) must be added to them."""
    setuptools = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))["tool"][
        "setuptools"
    ]
    for package, folder in (("balance_cli.library", CONFIGS), ("balance_cli.templates", TEMPLATES)):
        assert setuptools["package-dir"][package] == folder.name
        taken = {p for pattern in setuptools["package-data"][package] for p in folder.glob(pattern)}
        files = {p for p in folder.rglob("*") if p.is_file() and "__pycache__" not in p.parts}
        assert files - taken == set()
    assert (CONFIGS / "README.md") in {p for p in CONFIGS.glob("**/*.md")}


def test_list_without_a_folder_lists_the_shipped_library_by_its_names(elsewhere):
    result = invoke("list")
    assert result.exit_code == 0, result.output
    headings = [
        line.split(" (")[0]
        for line in result.output.splitlines()
        if re.fullmatch(r"library:\S* \(\d+ engines?\)", line)
    ]
    folders = sorted({p.parent.relative_to(CONFIGS).as_posix() for p in CONFIGS.rglob("*.toml")})
    assert headings == ["library:" + ("" if f == "." else f) for f in folders]
    assert "library:today/v/v8-90-cross-plane.toml " in result.output  # files by their names
    assert str(CONFIGS) not in result.output
    assert invoke("list", "library:today/v").output.startswith("library:today/v (11 engines)\n")


def test_a_folder_of_ones_own_is_still_listed_by_its_paths():
    result = invoke("list", PART3)
    assert result.exit_code == 0, result.output
    assert result.output.startswith(f"{PART3} (9 engines)\n")
    assert str(PART3 / "1a-v8-90-flat.toml") in result.output


def test_commands_take_library_and_template_names_from_any_folder(elsewhere):
    shown = invoke("show", "library:today/v/v8-90-cross-plane.toml")
    assert shown.exit_code == 0 and "GM LS3" in shown.output, shown.output
    compared = invoke("compare", "library:tanaka-part3", "--format", "json")
    assert compared.exit_code == 0, compared.output
    assert len(json.loads(compared.output)["engines"]) == 9
    searched = invoke(
        "search",
        "template:inline-3-2stroke.toml",
        "--top",
        "1",
        "--format",
        "json",
        "--workers",
        "1",
    )
    assert searched.exit_code == 0, searched.output
    assert len(json.loads(searched.output)["results"]) == 1
    checked = invoke("validate", "library:tanaka-part3")
    assert checked.exit_code == 0 and checked.output.count("ok: ") == 9, checked.output


def test_a_bad_name_on_the_command_line_is_one_line_and_no_traceback(elsewhere):
    code = "from balance_cli.cli import main; main()"
    for args in (
        ["compare", "library:tanaka-part-3"],
        ["list", "library:today/x"],
        ["search", "template:inline-9-2stroke", "--top", "1"],
    ):
        done = subprocess.run([sys.executable, "-c", code, *args], capture_output=True, text=True)
        assert done.returncode == 1, (args, done.stderr)
        assert done.stdout == "" and "Traceback" not in done.stderr
        assert done.stderr.count("\n") == 1, done.stderr
        assert done.stderr.startswith(f"Error: {args[1]}: not in the shipped "), done.stderr


def test_library_configs_cite_papers_not_project_files():
    for path in CONFIGS.rglob("*.toml"):
        assert "INDEX.md" not in path.read_text(encoding="utf-8"), path


def test_a_configurations_data_is_a_copy_each_time():
    """Changing the dict it gives, or the dict it was given, changes nothing in it."""
    given = read_configuration(CONFIGS / "inline-4-car.toml").data
    configuration = balance.Configuration(given, "car.toml")
    given["name"] = "changed after"
    configuration.data["unknown_key"] = 1
    assert configuration.engine().name == "In-line 4, car proportions"
    assert "unknown_key" not in configuration.data
    assert configuration == balance.Configuration(
        read_configuration(CONFIGS / "inline-4-car.toml").data, "car.toml"
    )
