"""The files every command reads and writes: inputs found or refused, outputs written whole or
not at all, never over an input, and the errors of paths, permissions and devices in one line
each (the exit status, no traceback, nothing changed)."""

import json
import os
import shutil
import stat
import tempfile
from pathlib import Path

import pytest

from tests.support import PART3, TWIN, check_refused, invoke, snapshot, twin_file


def as_ordinary_user(args):
    """Run the command line as it runs for a user without root's powers: directly when this
    is not root, else in a forked child that drops to the user nobody (no new interpreter
    needs to start, so root's private folders do not matter)."""
    if os.geteuid() != 0:
        result = invoke(*args)
        return {
            "code": result.exit_code,
            "stdout": result.stdout,
            "stderr": result.stderr,
            "exception": type(result.exception).__name__,
        }
    read, write = os.pipe()
    pid = os.fork()
    if pid == 0:  # pragma: no cover - the child
        try:
            os.close(read)
            os.setgroups([])
            os.setgid(65534)
            os.setuid(65534)
            result = invoke(*args)
            payload = {
                "code": result.exit_code,
                "stdout": result.stdout,
                "stderr": result.stderr,
                "exception": type(result.exception).__name__,
            }
            os.write(write, json.dumps(payload).encode())
        finally:
            os._exit(0)
    os.close(write)
    chunks = []
    while chunk := os.read(read, 65536):
        chunks.append(chunk)
    os.close(read)
    os.waitpid(pid, 0)
    return json.loads(b"".join(chunks))


@pytest.fixture
def shared_folder():
    """A folder every user may enter (pytest's own tmp_path is private to its owner)."""
    folder = Path(tempfile.mkdtemp(prefix="balance-hostile-"))
    folder.chmod(0o777)
    yield folder
    for path in [folder, *folder.rglob("*")]:
        if path.is_dir() and not path.is_symlink():
            path.chmod(0o777)
    shutil.rmtree(folder)


def check_user_refused(outcome, words, before, folder):
    assert outcome["exception"] == "SystemExit" and outcome["code"] == 1, outcome
    assert outcome["stdout"] == "" and outcome["stderr"].count("\n") == 1, outcome
    assert words in outcome["stderr"], outcome["stderr"]
    assert snapshot(folder) == before


def test_missing_file_and_empty_folder(tmp_path):
    result = invoke("compare", tmp_path / "nothing.toml")
    assert result.exit_code != 0 and "no such file" in result.output
    result = invoke("compare", tmp_path)
    assert result.exit_code != 0 and "no .toml configuration found" in result.output


def test_unwritable_output_leaves_nothing(tmp_path):
    blocker = tmp_path / "file"
    blocker.write_text("x")
    result = invoke(
        "compare", PART3 / "1a-v8-90-flat.toml", "--output", blocker / "sub" / "out.json"
    )
    assert result.exit_code != 0 and "cannot create the folder" in result.output
    assert isinstance(result.exception, SystemExit), result.exception


@pytest.mark.parametrize("command", ["compare", "counterweight", "plot", "report"])
def test_output_that_is_the_input_is_refused_before_computing(tmp_path, command, monkeypatch):
    from balance_cli.cli import batch

    monkeypatch.setattr(batch, "analyse", lambda *a: pytest.fail("analysed before refusing"))
    config = tmp_path / "e.toml"
    config.write_text(TWIN, encoding="utf-8")
    before = snapshot(tmp_path)
    extra = ["--kind", "locus"] if command == "plot" else []
    result = invoke(command, config, *extra, "-o", config)
    words = "is not a folder" if command == "report" else "is an input file"
    check_refused(result, 1, words, before, tmp_path)


@pytest.mark.parametrize("how", ["symlink", "inside-folder", "relative"])
def test_output_resolving_to_an_input_is_refused(tmp_path, how, monkeypatch):
    folder = tmp_path / "engines"
    folder.mkdir()
    config = folder / "e.toml"
    config.write_text(TWIN, encoding="utf-8")
    if how == "symlink":
        (tmp_path / "link.txt").symlink_to(config)
        inputs, output = [config], tmp_path / "link.txt"
    elif how == "inside-folder":
        inputs, output = [folder], folder / "e.toml"
    else:
        monkeypatch.chdir(tmp_path)
        inputs, output = [Path("engines")], Path("engines/../engines/e.toml")
    before = snapshot(tmp_path)
    check_refused(invoke("compare", *inputs, "-o", output), 1, "is an input file", before, tmp_path)


def test_output_that_is_a_folder(tmp_path):
    config = tmp_path / "e.toml"
    config.write_text(TWIN, encoding="utf-8")
    (tmp_path / "out").mkdir()
    before = snapshot(tmp_path)
    check_refused(
        invoke("compare", config, "-o", tmp_path / "out"),
        1,
        "is a folder; give a file name",
        before,
        tmp_path,
    )


def test_output_below_a_file(tmp_path):
    config = tmp_path / "e.toml"
    config.write_text(TWIN, encoding="utf-8")
    before = snapshot(tmp_path)
    check_refused(
        invoke("compare", config, "-o", tmp_path / "e.toml" / "sub" / "o.json"),
        1,
        "cannot create the folder",
        before,
        tmp_path,
    )


@pytest.mark.skipif(not os.path.exists("/dev/full"), reason="no /dev/full on this system")
def test_device_is_written_directly_and_its_error_reported(tmp_path):
    config = tmp_path / "e.toml"
    config.write_text(TWIN, encoding="utf-8")
    before = snapshot(tmp_path)
    check_refused(
        invoke("compare", config, "-o", "/dev/full"),
        1,
        "cannot write '/dev/full': No space left on device",
        before,
        tmp_path,
    )
    assert stat.S_ISCHR(os.stat("/dev/full").st_mode)  # still the device


def test_missing_inputs_and_empty_folder(tmp_path):
    before = snapshot(tmp_path)
    check_refused(
        invoke("compare", tmp_path / "nothing.toml", "-o", tmp_path / "o"),
        1,
        "no such file; check the path",
        before,
        tmp_path,
    )
    check_refused(
        invoke("compare", tmp_path, "-o", tmp_path / "o"),
        1,
        "no .toml configuration found in this folder",
        before,
        tmp_path,
    )
    check_refused(invoke("show", tmp_path), 1, "is a folder; give a .toml file", before, tmp_path)


def test_folder_without_write_permission(shared_folder):
    config = shared_folder / "e.toml"
    config.write_text(TWIN, encoding="utf-8")
    config.chmod(0o644)
    locked = shared_folder / "locked"
    locked.mkdir()
    locked.chmod(0o555)
    before = snapshot(shared_folder)
    outcome = as_ordinary_user(["compare", config, "-o", locked / "out.json"])
    check_user_refused(outcome, "Permission denied", before, shared_folder)


def test_folder_without_read_permission(shared_folder):
    folder = shared_folder / "secret"
    folder.mkdir()
    (folder / "e.toml").write_text(TWIN, encoding="utf-8")
    folder.chmod(0o300)
    before = snapshot(shared_folder)
    outcome = as_ordinary_user(["compare", folder, "-o", shared_folder / "o.json"])
    check_user_refused(outcome, "cannot read the folder (Permission denied)", before, shared_folder)


def test_file_without_read_permission(shared_folder):
    config = shared_folder / "e.toml"
    config.write_text(TWIN, encoding="utf-8")
    config.chmod(0o200)
    before = snapshot(shared_folder)
    outcome = as_ordinary_user(["compare", config, "-o", shared_folder / "o.json"])
    check_user_refused(outcome, "cannot read the file (Permission denied)", before, shared_folder)


@pytest.mark.parametrize(
    "make, words",
    [
        (
            lambda d: (
                os.symlink(d / "loopB", d / "loopA"),
                os.symlink(d / "loopA", d / "loopB"),
                d / "loopA",
            )[2],
            "Too many levels of symbolic links",
        ),
        (
            lambda d: (
                os.symlink("/nonexistent-balance/dir/f.txt", d / "dangling"),
                d / "dangling",
            )[1],
            "whose folder does not exist",
        ),
        (lambda d: "", "the output path is empty"),
        (lambda d: str(d / "pic.json") + os.sep, "is a folder; give a file name"),
        (lambda d: d / ("a" * 300 + ".json"), "File name too long"),
    ],
)
def test_odd_output_paths(tmp_path, make, words):
    config = twin_file(tmp_path)
    output = make(tmp_path)
    before = snapshot(tmp_path)
    check_refused(invoke("compare", config, "-o", output), 1, words, before, tmp_path)
    assert not Path("/nonexistent-balance").exists()


def test_a_read_only_output_file_is_not_replaced(shared_folder):
    config = shared_folder / "e.toml"
    config.write_text(TWIN, encoding="utf-8")
    config.chmod(0o644)
    locked = shared_folder / "out.txt"
    locked.write_text("keep me")
    locked.chmod(0o444)
    before = snapshot(shared_folder)
    outcome = as_ordinary_user(["compare", config, "-o", locked])
    check_user_refused(outcome, "cannot write", before, shared_folder)
    assert "read-only" in outcome["stderr"]


def test_a_read_only_output_file_is_not_replaced_even_by_root(tmp_path):
    """access() grants root everything; the mode bits still say the owner meant it read-only."""
    config = twin_file(tmp_path)
    locked = tmp_path / "out.txt"
    locked.write_text("keep me")
    locked.chmod(0o444)
    before = snapshot(tmp_path)
    check_refused(
        invoke("compare", config, "-o", locked), 1, "the file is read-only", before, tmp_path
    )


def test_a_fifo_named_like_a_configuration_is_refused_not_waited_for(tmp_path):
    folder = tmp_path / "engines"
    folder.mkdir()
    twin_file(folder)
    os.mkfifo(folder / "z.toml")
    result = invoke("compare", folder, "--format", "json")  # the FIFO in a folder: skipped
    assert result.exit_code == 0 and len(json.loads(result.stdout)["engines"]) == 1
    result = invoke("compare", folder / "z.toml")
    assert result.exit_code == 1 and "is not a regular file" in result.stderr


def test_standard_output_errors_are_one_line(tmp_path):
    import subprocess
    import sys

    config = twin_file(tmp_path)
    code = "from balance_cli.cli import main; main()"
    full = subprocess.run(
        [sys.executable, "-c", code, "compare", str(config)],
        stdout=open("/dev/full", "w"),
        stderr=subprocess.PIPE,
        text=True,
    )
    assert full.returncode == 1
    assert full.stderr == "Error: cannot write standard output: No space left on device\n"
    closed = subprocess.run(
        [sys.executable, "-c", code, "compare", str(config)],
        stdout=subprocess.DEVNULL,
        stderr=subprocess.PIPE,
        text=True,
        preexec_fn=lambda: os.close(1),
    )
    assert closed.returncode == 1 and closed.stderr.count("\n") == 1, closed.stderr
    ascii_only = subprocess.run(
        [sys.executable, "-c", code, "compare", str(config)],
        capture_output=True,
        env={**os.environ, "PYTHONIOENCODING": "ascii"},
    )
    assert ascii_only.returncode == 0 and "m_rec·r·ω²·n" in ascii_only.stdout.decode("utf-8")
