"""balance validate, list and show."""

from tests.support import CONFIGS, ROOT, TODAY, check_refused, invoke, snapshot


def _listing(folder):
    from click.testing import CliRunner

    from balance_cli.cli import main

    return CliRunner().invoke(main, ["list", str(folder)])


def _headings(output):
    return [
        line
        for line in output.splitlines()
        if line.endswith(")") and "engine" in line and not line.startswith(("Config", "-", " "))
    ]


def test_validate_accepts_the_whole_library():
    result = invoke("validate", CONFIGS)
    assert result.exit_code == 0, result.output
    assert result.output.count("ok: ") == len(list(CONFIGS.rglob("*.toml")))


def test_list_and_show():
    listing = invoke("list", CONFIGS)
    assert (
        listing.exit_code == 0 and "ABC Dragonfly" in listing.output and "Source" in listing.output
    )
    shown = invoke("show", CONFIGS / "bramo-323.toml")
    assert shown.exit_code == 0
    assert "link on 1 (261.5 mm, knuckle 71.26 mm at 80°)" in shown.output
    assert "TDC (°)" in shown.output


def test_list_of_a_missing_folder_prints_no_table(tmp_path):
    before = snapshot(tmp_path)
    check_refused(invoke("list", tmp_path / "nodir"), 1, "no such folder", before, tmp_path)


def test_list_prints_one_table_per_folder_in_path_order(tmp_path):
    """Files at the top, in folders and in a nested folder: one headed table each, DIR's own
    files first (headed by DIR as given), then the folders by path, a folder before its
    subfolders (a/x.toml sorts after a/b/y.toml, but folder a comes before a/b)."""
    twin = (ROOT / "configs" / "today" / "inline" / "inline-2-180.toml").read_text(encoding="utf-8")
    for relative in ("b.toml", "a/x.toml", "a/b/y.toml", "a/b/z.toml", "c/w.toml"):
        path = tmp_path / relative
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(
            twin.replace(
                'name = "In-line 2, 180° crank (Kawasaki Ninja 650)"', f'name = "twin {relative}"'
            ),
            encoding="utf-8",
        )
    result = _listing(tmp_path)
    assert result.exit_code == 0, result.output
    assert _headings(result.output) == [
        f"{tmp_path} (1 engine)",
        "a (1 engine)",
        "a/b (2 engines)",
        "c (1 engine)",
    ]
    blocks = result.output.split("\n\n")
    assert "twin b.toml" in blocks[0] and "twin a/x.toml" not in blocks[0]
    assert "twin a/x.toml" in blocks[1]
    assert "twin a/b/y.toml" in blocks[2] and "twin a/b/z.toml" in blocks[2]


def test_list_of_the_library_groups_today_by_family():
    result = _listing(ROOT / "configs")
    assert result.exit_code == 0, result.output
    headings = _headings(result.output)
    for family, count in (("inline", 9), ("v", 11), ("boxer", 4), ("w", 1)):
        assert (
            f"today/{family} ({count} engines)" in headings
            or f"today/{family} (1 engine)" in headings
        )
    assert headings.index("today/boxer (4 engines)") < headings.index("today/inline (9 engines)")
    assert "tanaka-part3 (9 engines)" in headings


def test_list_reports_an_invalid_file_after_the_tables_of_the_valid_ones(tmp_path):
    """One bad file in a folder: the other folders are still listed, the bad one is named on
    standard error in one line, and the exit status is 1."""
    from click.testing import CliRunner

    from balance_cli.cli import main

    twin = (TODAY / "inline" / "inline-2-180.toml").read_text(encoding="utf-8")
    (tmp_path / "good").mkdir()
    (tmp_path / "bad").mkdir()
    (tmp_path / "good" / "twin.toml").write_text(twin, encoding="utf-8")
    (tmp_path / "bad" / "twin.toml").write_text(
        twin.replace('speed = "8000 rpm"', 'speed = "8000 kg"'), encoding="utf-8"
    )
    result = CliRunner().invoke(main, ["list", str(tmp_path)])
    assert result.exit_code == 1
    assert _headings(result.stdout) == ["good (1 engine)"]
    errors = [line for line in result.stderr.splitlines() if line]
    assert len(errors) == 1 and errors[0].startswith("invalid: ") and "bad" in errors[0]
    assert "speed" in errors[0] and "Traceback" not in result.output


def test_show_prints_the_parts_and_the_rod_inertias_they_leave_out():
    """Table VIII's parts, and C = J − B·H·(L − H), c = j − b·h·(l − h) by hand."""
    from click.testing import CliRunner

    from balance_cli.cli import main

    result = CliRunner().invoke(main, ["show", str(CONFIGS / "bramo-323.toml")])
    assert result.exit_code == 0, result.output
    master = 0.122625 - 10.54 * 0.0413 * (0.330 - 0.0413)
    link = 0.0141264 - 1.42 * 0.1385 * (0.2615 - 0.1385)
    assert "piston 2972 g; rod 10540 g, centre of gravity 41.3 mm from the big end" in result.output
    assert f"master rods C = J − M·H·(L − H) = {master:g} kg·m²" in result.output
    assert f"link rods c = j − m·h·(l − h) = {link:g} kg·m²" in result.output
