"""balance search: its JSON document, written arrangements, options and errors."""

import json
import math
import os
import shutil
from pathlib import Path

import pytest
from numpy.testing import assert_allclose

import balance_cli as balance
from balance_cli.cranksearch import search
from tests.support import ROOT, TEMPLATES, check_refused, inline_template_text, invoke, snapshot


def test_json_document_has_the_documented_keys():
    import json

    run = invoke(
        "search",
        TEMPLATES / "inline-6-2stroke.toml",
        "--objective",
        "M1",
        "--top",
        "2",
        "--format",
        "json",
        "--workers",
        "1",
    )
    assert run.exit_code == 0, run.output
    document = json.loads(run.output)
    for key in (
        "balance_version",
        "template",
        "objective",
        "arrangements_total",
        "arrangements_distinct",
        "evaluated",
        "exhaustive",
        "elapsed_s",
        "results",
    ):
        assert key in document
    first = document["results"][0]
    assert set(first) >= {"rank", "score", "phases_deg", "firing", "coefficients", "orders"}
    assert set(first["firing"]) >= {"order", "intervals_deg"}
    assert len(first["orders"]) == 8 and "M1" in first["coefficients"]


def test_written_arrangements_are_complete_configurations(tmp_path):
    """--write: compare reads each file back with the firing order and couples listed."""
    import json

    out = tmp_path / "best"
    run = invoke(
        "search",
        TEMPLATES / "nakanishi-w12-60-2stroke.toml",
        "--objective",
        "F1,F2,F3,M2,M1:0.01",
        "--top",
        "2",
        "--write",
        out,
        "--format",
        "json",
        "--workers",
        "1",
    )
    assert run.exit_code == 0, run.output
    listed = json.loads(run.output)["results"]
    assert sorted(p.name for p in out.iterdir()) == ["arrangement-01.toml", "arrangement-02.toml"]
    for record in listed:
        engine = balance.load(out / f"arrangement-{record['rank']:02d}.toml")
        again = balance.analyse(engine)
        assert list(again.firing.order) == record["firing"]["order"]
        assert_allclose(
            again.order(1).moment_forward.__abs__(),
            record["orders"][0]["moment"]["forward_Nm"],
            rtol=1e-12,
        )


@pytest.mark.parametrize(
    "args,words",
    [
        (["--objective", "F0"], "--objective"),
        (["--top", "0"], "--top"),
        (["--step", "30"], "--step"),
        (["--allow-uneven"], "--step"),
        (["--limit", "5"], "--limit"),
    ],
)
def test_command_errors_are_one_line_naming_the_option(args, words):
    run = invoke("search", TEMPLATES / "inline-6-2stroke.toml", *args)
    assert run.exit_code == 1 and isinstance(run.exception, SystemExit)
    assert words in run.output and len(run.output.strip().splitlines()) == 1


def test_a_configuration_with_phases_is_not_a_template():
    run = invoke("search", ROOT / "configs/inline-4-car.toml")
    assert run.exit_code == 1 and isinstance(run.exception, SystemExit)
    assert "throws[1].phase" in run.output and "remove phase" in run.output


@pytest.mark.parametrize(
    "args,words",
    [
        (["--allow-uneven", "--step", "0"], "--step must divide 360°"),
        (["--allow-uneven", "--step", "nan"], "--step must divide 360°"),
        (["--allow-uneven", "--step", "1e-9"], "--step must divide 360°"),
        (["--scheduler", "garbage"], "not a scheduler address"),
        (["--scheduler", "foo://x:1"], "not a scheduler address"),
        (["--heuristic", "--seed", "-1"], "--seed must be a whole number from 0"),
        (["--objective", ""], "--objective is empty"),
        (["--objective", " "], "--objective is empty"),
        (["--objective", "F0"], "orders start at 1"),
        (["--objective", "F9"], "set --max-order to 9"),
        (
            ["--heuristic", "--scheduler", "tcp://127.0.0.1:1"],
            "--scheduler applies to the exhaustive",
        ),
        (["--workers", "100000"], "--workers must be a whole number from 1 to 1,024"),
        (["--heuristic", "--restarts", "100000000"], "--restarts must be"),
        (["--step", "30"], "--step applies only with --allow-uneven"),
    ],
)
def test_hostile_options_are_one_line(args, words):
    run = invoke("search", TEMPLATES / "inline-6-2stroke.toml", *args)
    assert run.exit_code == 1 and isinstance(run.exception, SystemExit), run.output
    assert words in run.output and len(run.output.strip().splitlines()) == 1


def test_write_never_replaces_the_template_or_the_output(tmp_path):
    folder = tmp_path / "w"
    folder.mkdir()
    inside = folder / "arrangement-01.toml"
    inside.write_bytes((TEMPLATES / "inline-6-2stroke.toml").read_bytes())
    before = inside.read_bytes()
    run = invoke("search", inside, "--write", folder, "--top", "2")
    assert run.exit_code == 1 and "input file" in run.output and inside.read_bytes() == before
    run = invoke(
        "search",
        TEMPLATES / "inline-6-2stroke.toml",
        "--write",
        tmp_path / "x",
        "-o",
        tmp_path / "x" / "arrangement-01.toml",
    )
    assert run.exit_code == 1 and "--write writes" in run.output and not (tmp_path / "x").exists()


def test_a_failed_output_writes_no_folder(tmp_path):
    (tmp_path / "taken").mkdir()
    run = invoke(
        "search",
        TEMPLATES / "inline-6-2stroke.toml",
        "--top",
        "2",
        "--write",
        tmp_path / "new",
        "-o",
        tmp_path / "taken",
    )
    assert run.exit_code == 1 and not (tmp_path / "new").exists()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["taken"]


def test_a_long_template_name_leaves_room_for_the_rank(tmp_path):
    text = (
        (TEMPLATES / "inline-6-2stroke.toml")
        .read_text()
        .replace('name = "In-line 6, two-stroke"', f'name = "{"A" * 118}"')
    )
    path = tmp_path / "long.toml"
    path.write_text(text)
    run = invoke("search", path, "--objective", "M1", "--top", "3")
    assert run.exit_code == 0, run.output
    names = [a.engine.name for a in search(balance.load_template(path), "M1", top=3).arrangements]
    assert len(set(names)) == 3 and all(len(n) <= 120 for n in names)


@pytest.mark.parametrize("objective", ["M1:1e300", "M1:1e308,M2:1e308", "M1:1e-300"])
def test_search_weights_beyond_their_range_are_refused_with_it(tmp_path, objective):
    """Guards against these weights ending in an OverflowError traceback."""
    template = tmp_path / "t.toml"
    shutil.copy(TEMPLATES / "inline-6-2stroke.toml", template)
    before = snapshot(tmp_path)
    result = invoke("search", template, "--objective", objective, "--workers", "1")
    check_refused(result, 1, "must be a positive number from 1e-100 to 1e+100", before, tmp_path)


def test_huge_weights_print_a_readable_score(tmp_path):
    result = invoke(
        "search",
        TEMPLATES / "inline-6-2stroke.toml",
        "--objective",
        "M1:1e100",
        "--top",
        "3",
        "--workers",
        "1",
    )
    assert result.exit_code == 0, result.output
    row = next(line for line in result.stdout.splitlines() if line.startswith("3 "))
    score = row.split()[1]
    assert len(score) <= 12 and float(score) > 1e99, row


def test_a_top_beyond_what_can_be_held_is_refused(tmp_path):
    """Guards against --top 100000 on an in-line 10 reaching 100 % and then growing past
    7 GB."""
    template = tmp_path / "i10.toml"
    template.write_text(inline_template_text(10), encoding="utf-8")
    before = snapshot(tmp_path)
    result = invoke("search", template, "--objective", "M1", "--top", "100000")
    check_refused(
        result, 1, "--top must be a whole number from 1 to 1,000, got 100000", before, tmp_path
    )


def test_heuristic_with_a_scheduler_names_the_flags():
    result = invoke(
        "search",
        TEMPLATES / "inline-6-2stroke.toml",
        "--heuristic",
        "--scheduler",
        "tcp://127.0.0.1:1",
    )
    assert result.exit_code == 1
    assert result.stderr.endswith(
        ": --scheduler applies to the exhaustive search, but the "
        "heuristic search (--heuristic) runs in this process: leave "
        "out one of the two\n"
    )


def test_ctrl_c_in_a_multi_process_search_prints_no_worker_traceback(tmp_path):
    """Guards against Ctrl-C (SIGINT to the whole process group, as a terminal sends it)
    printing stray 'Process ForkPoolWorker-N:' tracebacks. Now one 'Aborted!' from the command."""
    import signal
    import subprocess
    import sys
    import time

    template = tmp_path / "i13.toml"
    template.write_text(inline_template_text(13), encoding="utf-8")
    code = (
        "import sys; from balance_cli.cranksearch import parallel as c; "
        "c._cores = lambda: 2; "  # two processes even on a one-core machine
        "from balance_cli.cli import main; sys.exit(main())"
    )
    process = subprocess.Popen(
        [
            sys.executable,
            "-c",
            code,
            "search",
            str(template),
            "--workers",
            "2",
        ],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        start_new_session=True,
    )
    # interrupt once the workers run (the search of an in-line 13 for the default objective,
    # every F_k and M_k, takes about six seconds after they start: M1 alone took half a second,
    # which a Ctrl-C 0.3 s after the workers started could miss): the parent's children, as
    # Linux lists them
    children = Path(f"/proc/{process.pid}/task/{process.pid}/children")
    deadline = time.monotonic() + 60
    while time.monotonic() < deadline and process.poll() is None:
        if children.exists() and len(children.read_text().split()) >= 2:
            break
        time.sleep(0.05)
    time.sleep(0.3)
    os.killpg(process.pid, signal.SIGINT)
    out, err = process.communicate(timeout=60)
    assert process.returncode == 1, (out, err)
    assert "Traceback" not in err and "ForkPoolWorker" not in err, err
    assert err.strip() == "Aborted!", err


def test_search_takes_units_and_speed(tmp_path):
    """--speed on a template: the listed arrangement's forces follow ω² (×4 at twice the
    speed), and --write writes the speed asked for."""
    template = "templates/inline-3-2stroke.toml"
    slow = json.loads(invoke("search", template, "--top", "1", "--format", "json").output)
    fast = invoke("search", template, "--top", "1", "--format", "json", "--speed", "2x")
    assert fast.exit_code == 1 and "--speed" in fast.output
    base = balance.load_template(template).speed_rad_s * 30 / math.pi
    fast = json.loads(
        invoke(
            "search",
            template,
            "--top",
            "1",
            "--format",
            "json",
            "--speed",
            f"{2 * base} rpm",
            "--write",
            tmp_path,
        ).output
    )
    a, b = slow["results"][0], fast["results"][0]
    assert_allclose(
        b["orders"][0]["moment"]["max_Nm"], 4 * a["orders"][0]["moment"]["max_Nm"], rtol=1e-12
    )
    assert balance.load(tmp_path / "arrangement-01.toml").speed_rad_s == pytest.approx(
        2 * base * math.pi / 30, rel=1e-12
    )
    table = invoke("search", template, "--top", "1", "--units", "kN")
    assert table.exit_code == 0 and "(kN·m)" in table.output
