"""Writing results (balance_cli.output): through links, to devices and FIFOs, under short
temporary names, a folder whole or not at all, and never over an input."""

import json
import os
import stat
import threading

import pytest

from balance_cli.errors import OutputError
from balance_cli.output import refuse_inputs, write_bytes, write_folder, write_text
from tests.support import PART3, invoke


def test_refuse_inputs_sees_through_links_and_dots(tmp_path):
    config = tmp_path / "e.toml"
    config.write_text("x")
    (tmp_path / "alias.toml").symlink_to(config)
    for output in (config, tmp_path / "alias.toml", tmp_path / "sub" / ".." / "e.toml"):
        with pytest.raises(OutputError, match="is an input file"):
            refuse_inputs([output], [config])
    refuse_inputs([tmp_path / "other.json", "-"], [config])


def test_a_symbolic_link_is_written_through(tmp_path):
    target = tmp_path / "real.txt"
    target.write_text("old")
    target.chmod(0o640)
    link = tmp_path / "link.txt"
    link.symlink_to(target)
    write_text(link, "new")
    assert link.is_symlink() and os.readlink(link) == str(target)
    assert target.read_text() == "new"
    assert stat.S_IMODE(target.stat().st_mode) == 0o640  # the file's permissions are kept
    assert sorted(p.name for p in tmp_path.iterdir()) == ["link.txt", "real.txt"]


def test_a_dangling_link_creates_its_target(tmp_path):
    link = tmp_path / "link.txt"
    link.symlink_to(tmp_path / "made.txt")
    write_text(link, "x")
    assert (tmp_path / "made.txt").read_text() == "x" and link.is_symlink()


def test_devices_are_written_directly():
    write_text("/dev/null", "nothing")
    assert stat.S_ISCHR(os.stat("/dev/null").st_mode)


def test_a_fifo_is_written_directly(tmp_path):
    fifo = tmp_path / "pipe"
    os.mkfifo(fifo)
    received = []
    reader = threading.Thread(target=lambda: received.append(fifo.read_text()))
    reader.start()
    write_text(fifo, "through the pipe")
    reader.join(timeout=10)
    assert received == ["through the pipe"] and stat.S_ISFIFO(fifo.stat().st_mode)


@pytest.mark.skipif(not os.path.exists("/dev/full"), reason="no /dev/full here")
def test_a_device_error_is_one_output_error():
    with pytest.raises(OutputError, match="No space left on device"):
        write_text("/dev/full", "x" * 100_000)
    assert stat.S_ISCHR(os.stat("/dev/full").st_mode)


def test_a_250_character_file_name_can_be_written(tmp_path):
    name = "r" * 245 + ".json"
    result = invoke(
        "compare", PART3 / "1a-v8-90-flat.toml", "--format", "json", "-o", tmp_path / name
    )
    assert result.exit_code == 0, result.output
    assert json.loads((tmp_path / name).read_text())["engines"][0]["cylinders"] == 8
    assert [p.name for p in tmp_path.iterdir()] == [name]


def test_a_failing_writer_leaves_nothing_behind(tmp_path):
    def broken(handle):
        handle.write(b"half")
        raise OSError(28, "No space left on device")

    with pytest.raises(OutputError, match="No space left on device"):
        write_bytes(tmp_path / "out.bin", broken)
    assert list(tmp_path.iterdir()) == []


def test_a_new_report_folder_appears_whole_and_an_old_one_is_kept_on_failure(tmp_path):
    def fill(folder):
        (folder / "a.txt").write_text("a")
        (folder / "b.txt").write_text("b")
        return ["a.txt", "b.txt"]

    written = write_folder(tmp_path / "new", fill)
    assert sorted(p.name for p in written) == ["a.txt", "b.txt"]
    assert sorted(p.name for p in tmp_path.iterdir()) == ["new"]
    old = tmp_path / "old"
    (old / "b.txt").mkdir(parents=True)
    (old / "keep.txt").write_text("keep")
    with pytest.raises(OutputError, match="b.txt': it is not a regular file"):
        write_folder(old, fill)
    assert sorted(p.name for p in old.iterdir()) == ["b.txt", "keep.txt"]
    assert not (old / "a.txt").exists()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["new", "old"]
