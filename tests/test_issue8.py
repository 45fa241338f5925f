"""Regressions of issue 8 (hardening), item by item, beside the hostile inputs of test_hostile.

Each test fails on the code before the fix: the item number is in its name.
"""

import dataclasses
import json
import math
import os
import stat
import threading

import pytest
from click.testing import CliRunner
from numpy.testing import assert_allclose

import balance_cli
import balance_cli as balance
from balance_cli.cli import main
from balance_cli.errors import ModelError, OutputError
from balance_cli.model import Cylinder
from balance_cli.output import refuse_inputs, write_bytes, write_folder, write_text
from balance_cli.units import round_degrees, wrap_degrees
from tests.support import CONFIGS, PART3, make_engine

BOXER = """\
name = "Flat twin | opposed <script>alert(1)</script>"
cycle = 2
speed = "3000 rpm"
crank_radius = "40 mm"
rod_length = "140 mm"

[masses]
reciprocating = "500 g"

[[banks]]
angle = 0
[[banks]]
angle = 180

[[throws]]
phase = 0
[[throws]]
phase = 180

[[cylinders]]
number = 1
bank = 1
throw = 1
[[cylinders]]
number = 2
bank = 2
throw = 2
"""


def invoke(*args):
    return CliRunner().invoke(main, [str(a) for a in args])


# ---- item 2: writing through links, devices and FIFOs; item 3: short temporary names ----------


def test_item2_a_symbolic_link_is_written_through(tmp_path):
    target = tmp_path / "real.txt"
    target.write_text("old")
    target.chmod(0o640)
    link = tmp_path / "link.txt"
    link.symlink_to(target)
    write_text(link, "new")
    assert link.is_symlink() and os.readlink(link) == str(target)
    assert target.read_text() == "new"
    assert stat.S_IMODE(target.stat().st_mode) == 0o640      # the file's permissions are kept
    assert sorted(p.name for p in tmp_path.iterdir()) == ["link.txt", "real.txt"]


def test_item2_a_dangling_link_creates_its_target(tmp_path):
    link = tmp_path / "link.txt"
    link.symlink_to(tmp_path / "made.txt")
    write_text(link, "x")
    assert (tmp_path / "made.txt").read_text() == "x" and link.is_symlink()


def test_item2_devices_are_written_directly():
    write_text("/dev/null", "nothing")
    assert stat.S_ISCHR(os.stat("/dev/null").st_mode)


def test_item2_a_fifo_is_written_directly(tmp_path):
    fifo = tmp_path / "pipe"
    os.mkfifo(fifo)
    received = []
    reader = threading.Thread(target=lambda: received.append(fifo.read_text()))
    reader.start()
    write_text(fifo, "through the pipe")
    reader.join(timeout=10)
    assert received == ["through the pipe"] and stat.S_ISFIFO(fifo.stat().st_mode)


@pytest.mark.skipif(not os.path.exists("/dev/full"), reason="no /dev/full here")
def test_item2_a_device_error_is_one_output_error():
    with pytest.raises(OutputError, match="No space left on device"):
        write_text("/dev/full", "x" * 100_000)
    assert stat.S_ISCHR(os.stat("/dev/full").st_mode)


def test_item3_a_250_character_file_name_can_be_written(tmp_path):
    name = "r" * 245 + ".json"
    result = invoke("compare", PART3 / "1a-v8-90-flat.toml", "--format", "json", "-o", tmp_path / name)
    assert result.exit_code == 0, result.output
    assert json.loads((tmp_path / name).read_text())["engines"][0]["cylinders"] == 8
    assert [p.name for p in tmp_path.iterdir()] == [name]


def test_item3_a_failing_writer_leaves_nothing_behind(tmp_path):
    def broken(handle):
        handle.write(b"half")
        raise OSError(28, "No space left on device")

    with pytest.raises(OutputError, match="No space left on device"):
        write_bytes(tmp_path / "out.bin", broken)
    assert list(tmp_path.iterdir()) == []


def test_item13_a_new_report_folder_appears_whole_and_an_old_one_is_kept_on_failure(tmp_path):
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


def test_item1_refuse_inputs_sees_through_links_and_dots(tmp_path):
    config = tmp_path / "e.toml"
    config.write_text("x")
    (tmp_path / "alias.toml").symlink_to(config)
    for output in (config, tmp_path / "alias.toml", tmp_path / "sub" / ".." / "e.toml"):
        with pytest.raises(OutputError, match="is an input file"):
            refuse_inputs([output], [config])
    refuse_inputs([tmp_path / "other.json", "-"], [config])


# ---- item 4: any number of samples ----------------------------------------------------------


@pytest.mark.parametrize("config", ["tanaka-part3/5a-radial-9.toml", "bramo-323.toml",
                                    "inline-4-car.toml", "clerget-rotary.toml"])
def test_item4_odd_and_even_samples_give_the_same_orders(config):
    engine = balance.load(CONFIGS / config)
    reference = balance.analyse(engine, samples=256, max_order=8)
    unit = engine.per_cylinder_unit_n
    for samples in (101, 255, 1001, 1024):
        result = balance.analyse(engine, samples=samples, max_order=8)
        for ours, theirs in zip(result.shaking.orders, reference.shaking.orders):
            for a, b in ((ours.force_forward, theirs.force_forward),
                         (ours.force_backward, theirs.force_backward),
                         (ours.moment_forward, theirs.moment_forward)):
                assert abs(a - b) < 1e-10 * unit, (samples, ours.order)
        # the resultant's largest magnitude comes from the padded synthesis, odd or even
        assert_allclose(result.largest_force_n, reference.largest_force_n, rtol=1e-7)


# ---- item 7: no percentage of a reference without a resultant --------------------------------


def test_item7_percent_of_a_balanced_reference_is_not_available(tmp_path):
    boxer = tmp_path / "boxer.toml"
    boxer.write_text(BOXER, encoding="utf-8")
    result = invoke("compare", boxer, PART3 / "1a-v8-90-flat.toml", "--format", "json")
    engines = json.loads(result.stdout)["engines"]
    assert engines[0]["counterweighted_resultant_N"] == 0.0
    assert [e["percent_of_reference"] for e in engines] == [None, None]
    table = invoke("compare", boxer, PART3 / "1a-v8-90-flat.toml").stdout
    assert "n/a" in table and "e+" not in table
    # the other way round the boxer is 0 % of the V8
    engines = json.loads(invoke("compare", PART3 / "1a-v8-90-flat.toml", boxer,
                                "--format", "json").stdout)["engines"]
    assert [e["percent_of_reference"] for e in engines] == [100.0, 0.0]


# ---- item 8: more samples never warn --------------------------------------------------------


@pytest.mark.parametrize("samples", [8192, 32768])
def test_item8_more_samples_never_warn(samples):
    """pytest turns a SamplingWarning into an error (pyproject.toml)."""
    for engine in balance.load_many([CONFIGS]):
        assert balance.analyse(engine, samples=samples, max_order=8).shaking.sampling_ok


def test_item8_too_few_samples_still_warn():
    engine = balance.load(CONFIGS / "inline-4-marine.toml")
    with pytest.warns(balance.SamplingWarning, match="16 samples a revolution are too few"):
        assert not balance.analyse(engine, samples=16, max_order=3).shaking.sampling_ok


# ---- item 9: angles normalised once ---------------------------------------------------------


def test_item9_wrap_and_round_degrees():
    assert wrap_degrees(-1e-12) == 0.0 and wrap_degrees(360.0) == 0.0
    assert wrap_degrees(179.9999999, 180.0) == 0.0 and wrap_degrees(179.99, 180.0) == 179.99
    assert wrap_degrees(-90.0) == 270.0 and wrap_degrees(725.0) == 5.0
    assert round_degrees(359.996, 2) == 0.0 and round_degrees(359.994, 2) == 359.99


def test_item9_every_angle_of_the_library_is_in_its_range():
    document = json.loads(invoke("compare", CONFIGS, "--format", "json", "--max-order", "12").stdout)
    for engine in document["engines"]:
        for order in engine["orders"]:
            for part, unit in (("force", "N"), ("moment", "Nm")):
                values = order[part]
                floor = engine[f"noise_floor_{unit}"]
                # a circle, or nothing, has no axis
                if values[f"forward_{unit}"] == 0.0 or values[f"backward_{unit}"] == 0.0:
                    assert values["axis_deg"] is None
                else:
                    assert 0.0 <= values["axis_deg"] < 180.0
                assert 0.0 <= values["forward_deg"] < 360.0 and 0.0 <= values["backward_deg"] < 360.0
                assert values[f"min_{unit}"] == 0.0 or values[f"min_{unit}"] >= floor
        assert all(0.0 <= a < 180.0 * engine["cycle"] for a in engine["firing"]["angles_deg"])


def test_item9_tdc_of_cylinder_one_is_zero_not_360():
    """A plain in-line engine's cylinder 1 is at TDC at θ = 0 exactly; the TDC search lands a
    hair below 360°, which must read 0."""
    tdc = balance_cli.kinematics.tdc_angles(balance.load(CONFIGS / "inline-4-car.toml"))
    assert tdc[1] == 0.0 and all(0.0 <= a < 360.0 for a in tdc.values())
    shown = invoke("show", CONFIGS / "inline-4-car.toml").stdout
    assert "360.00" not in shown


# ---- item 10: one cylinder per bore ---------------------------------------------------------


def test_item10_two_cylinders_in_one_bore_are_refused_in_code():
    engine = make_engine([0], [(0, 0.0), (180, 0.1)])
    with pytest.raises(ModelError, match="cylinder 3 sits in the bore of cylinder 1") as caught:
        dataclasses.replace(engine, cylinders=engine.cylinders + (Cylinder(3, 1, 1, 0.0, 1.0),))
    assert caught.value.cylinder == 3
    # side by side on one pin (its own z) is not one bore
    dataclasses.replace(engine, cylinders=engine.cylinders + (Cylinder(3, 1, 1, 0.02, 1.0),))


# ---- item 14: user text in tables -----------------------------------------------------------


def test_item14_names_are_escaped_in_markdown(tmp_path):
    boxer = tmp_path / "boxer.toml"
    boxer.write_text(BOXER, encoding="utf-8")
    markdown = invoke("compare", boxer, "--format", "markdown").stdout
    assert "<script>" not in markdown and "&lt;script&gt;" in markdown
    tables, current = [], []
    for line in markdown.splitlines() + [""]:
        if line.startswith("|"):
            current.append(line)
        elif current:
            tables.append(current)
            current = []
    assert any("Flat twin \\| opposed" in row for table in tables for row in table)
    for header, _, *rows in tables:   # the | in the name does not add a column
        for row in rows:
            assert row.replace("\\|", "").count("|") == header.replace("\\|", "").count("|")
    report = tmp_path / "report"
    assert invoke("report", boxer, "-o", report, "--html").exit_code == 0
    assert "<script>" not in (report / "report.md").read_text(encoding="utf-8")
    assert "<script>" not in (report / "report.html").read_text(encoding="utf-8")


def test_item14_a_name_with_a_line_break_is_refused(tmp_path):
    config = tmp_path / "e.toml"
    config.write_text(BOXER.replace("Flat twin |", "Flat\\ntwin |"), encoding="utf-8")
    result = invoke("compare", config)
    assert result.exit_code == 1 and "name: must be one line of printable text" in result.stderr


# ---- item 16: small ones --------------------------------------------------------------------


def test_item16_library_configs_cite_papers_not_project_files():
    for path in CONFIGS.rglob("*.toml"):
        assert "INDEX.md" not in path.read_text(encoding="utf-8"), path


def test_item16_the_counterweight_table_says_why_a_rotary_gets_no_test_masses():
    result = invoke("counterweight", CONFIGS / "clerget-rotary.toml", "--test-masses")
    assert result.exit_code == 1
    assert "--test-masses does not apply to a rotary engine: its crank stands still" in result.stderr


def test_item6_non_finite_values_are_refused_in_code():
    engine = make_engine([0], [(0, 0.0)])
    for field, value in (("speed_rad_s", math.inf), ("crank_radius_m", math.nan),
                         ("rod_length_m", 1e300), ("rotating_kg", -1.0)):
        with pytest.raises(ModelError, match=field):
            dataclasses.replace(engine, **{field: value})
    with pytest.raises(balance.CounterweightError, match="radius_m is invalid"):
        balance.counterweights(engine, radius_m=math.inf)
    with pytest.raises(balance.CounterweightError, match="balance_factor must be"):
        balance.counterweights(engine, balance_factor=math.nan)


def test_cli_module_keeps_the_default_backend_until_it_draws():
    import subprocess
    import sys

    code = ("import matplotlib, sys; from balance_cli.cli import main\n"
            "assert 'matplotlib.pyplot' not in sys.modules\n")
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
