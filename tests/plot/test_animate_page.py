"""The animation's HTML page in headless Chromium: it animates, it draws the pistons where the
kinematics put them, its step to each firing TDC lands where ``balance show`` says, and leaving
a cylinder out gives what ``compare`` gives for the engine without it; no console error.

A probe injected first into a copy of the page drives the page's own controls (through
``window.balanceAnimations``, what its buttons call), reads what it drew from the rendered SVG
(getBoundingClientRect: the pixels on screen), and writes a report into the page, which
``--dump-dom`` hands back. Chromium runs with virtual time: the page's timers run without
waiting for them.
"""

import html
import json
import re
import shutil
import subprocess

import numpy as np
import pytest
from numpy.testing import assert_allclose

import balance_cli as balance
from balance_cli.kinematics import kinematic_state
from balance_cli.plot.page import DATA_CLASS
from tests.support import CONFIGS, JUMO, RADIAL, invoke

CHROMIUM = shutil.which("chromium") or shutil.which("chromium-browser")
CHROME_FLAGS = [
    "--headless",
    "--no-sandbox",
    "--disable-gpu",
    "--disable-quic",
    "--no-first-run",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
    "--enable-logging=stderr",
    "--v=0",
    # wide enough that nothing is scaled: a CSS pixel of the page is a pixel of its SVG
    "--window-size=1600,1400",
    "--virtual-time-budget=4000",
    "--dump-dom",
]
V8 = CONFIGS / "today" / "v" / "v8-90-cross-plane.toml"
#: the cylinder left out of each engine: a plain one, a link rod's, an opposed bore
LEFT_OUT = {"v8": 3, "radial": 4, "jumo": 2}
ENGINES = {"v8": V8, "radial": RADIAL, "jumo": JUMO}
REPORT_ID = "balance-animation-probe"
#: the cylinder whose piston pin is measured on screen: one that moves across the picture as
#: well as along it (the V8's left bank, the radial's first link rod)
WATCHED = 2

#: first in <head>: records errors; on load, reads the page twice while it plays, then steps
#: through every firing TDC, then leaves a cylinder out, and writes what it saw
PROBE = """<script>
(function () {
  var errors = [];
  var consoleError = console.error;
  console.error = function () {
    errors.push("console.error: " + Array.prototype.join.call(arguments, " "));
    return consoleError.apply(console, arguments);
  };
  window.addEventListener("error", function (event) {
    errors.push("uncaught: " + event.message);
  }, true);
  function pixel(name, view) {
    var svg = document.querySelector(".balance-animation svg.ba-views");
    var dot = svg.querySelector("g.ba-" + view + " circle[data-point='" + name + "']");
    if (!dot) { return null; }
    var box = svg.getBoundingClientRect(), r = dot.getBoundingClientRect();
    return [r.left + r.width / 2 - box.left, r.top + r.height / 2 - box.top];
  }
  function seen(a) {
    var s = a.state();
    s.end = pixel("@POINT@", "end");
    s.side = pixel("@POINT@", "side");
    s.now = performance.now();
    return s;
  }
  window.addEventListener("load", function () {
    var a = window.balanceAnimations[0];
    var report = {count: window.balanceAnimations.length, instants: [seen(a)]};
    setTimeout(function () {
      report.instants.push(seen(a));
      setTimeout(function () {
        report.instants.push(seen(a));
        a.seek(0);
        report.steps = [];
        for (var i = 0; i <= a.data.events.length; i++) {
          var step = a.stepTDC();
          step.end = pixel("@POINT@", "end");
          report.steps.push(step);
        }
        report.all = a.phasors();
        report.leftOut = a.setCylinder(@CYLINDER@, false);
        report.without = a.phasors();
        report.refused = a.setCylinder(@MASTER@, false);
        a.setCylinder(@CYLINDER@, true);
        report.back = a.phasors();
        report.errors = errors;
        var out = document.createElement("pre");
        out.id = "@ID@";
        out.textContent = JSON.stringify(report);
        document.body.appendChild(out);
      }, 700);
    }, 600);
  });
})();
</script>"""

pytestmark = pytest.mark.skipif(
    CHROMIUM is None,
    reason="Debian's chromium is not installed (.ci/run installs it when the package index "
    "can be reached)",
)


def probe(page, tmp_path, point, cylinder, master):
    """Open ``page`` with the probe in headless Chromium: the probe's report and Chromium's
    log of console messages."""
    text = page.read_text(encoding="utf-8")
    script = (
        PROBE.replace("@POINT@", point)
        .replace("@CYLINDER@", str(cylinder))
        .replace("@MASTER@", str(master))
        .replace("@ID@", REPORT_ID)
    )
    head = text.index("<head>") + len("<head>")
    copy = tmp_path / f"probed-{page.name}"
    copy.write_text(text[:head] + script + text[head:], encoding="utf-8")
    done = subprocess.run(
        [CHROMIUM, *CHROME_FLAGS, f"--user-data-dir={tmp_path / 'profile'}", copy.as_uri()],
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert done.returncode == 0, done.stderr[-2000:]
    console = [line for line in done.stderr.splitlines() if ":CONSOLE" in line]
    found = re.search(rf'<pre id="{REPORT_ID}">(.*?)</pre>', done.stdout, re.S)
    assert found, "the probe never reported: " + done.stderr[-2000:]
    return json.loads(html.unescape(found.group(1))), console


@pytest.fixture(scope="module", params=sorted(ENGINES))
def opened(request, tmp_path_factory):
    """Each engine's page written by ``balance animate`` and opened in Chromium."""
    tmp_path = tmp_path_factory.mktemp(request.param)
    config = ENGINES[request.param]
    page = tmp_path / f"{request.param}.html"
    result = invoke("animate", config, "-o", page)
    assert result.exit_code == 0, result.output
    text = page.read_text(encoding="utf-8")
    start = text.index(f'class="{DATA_CLASS}">') + len(f'class="{DATA_CLASS}">')
    data = json.loads(text[start : text.index("</script>", start)])
    engine = balance.load(config)
    masters = [c.master for c in engine.cylinders if c.is_link]
    report, console = probe(
        page, tmp_path, f"p{WATCHED}", LEFT_OUT[request.param], (masters or [0])[0]
    )
    return request.param, engine, data, report, console, text


def expected_pixel(data, view, position, z=0.0):
    """Where the page's layout (balance_cli.plot.page's module text) puts a point at
    ``position`` (m, complex): its end view x across the reference axis, y up along it; its
    side view x along the crank axis, y up along the side view's vertical."""
    x0, y0, scale, left, top = data["layout"][view]
    if view == "end":
        return [x0 + scale * (position.imag - left), y0 + scale * (top - position.real)]
    along = (position * np.exp(-1j * data["side"])).real
    return [x0 + scale * (z - left), y0 + scale * (top - along)]


def test_the_page_is_self_contained(opened):
    _, _, _, report, _, text = opened
    assert report["count"] == 1
    # nothing from the network or another file: one page, its script and data inside it
    assert not re.search(r'\s(src|href)="', text)
    assert "http://" not in text.replace("http://www.w3.org/2000/svg", "")


def test_no_console_errors(opened):
    *_, report, console, _ = opened
    assert report["errors"] == []
    assert console == []


def test_it_animates_and_draws_a_piston_where_the_kinematics_put_it(opened):
    _, engine, data, report, _, _ = opened
    first, *playing = report["instants"]
    # frames advance while it plays, at the speed of its slider (a sixth of the cycle a
    # second), by the page's own clock: the probe reads it 600 ms and 700 ms apart (virtual
    # time), each time what was drawn at the page's last tick
    for before, after in zip(report["instants"], playing, strict=False):
        assert after["playing"] and after["frame"] is not None
        assert after["time"] - before["time"] > 500
        moved = (after["angle"] - before["angle"]) % data["cycle"]
        expected = data["cycle"] / 6 * (after["time"] - before["time"]) / 1000
        # each drawn angle is the nearest frame's, at most half a frame (1°) off the clock's
        assert abs(moved - expected) <= 360 / data["frames"] + 1e-6
    # the watched piston pin at those two instants: the kinematic state, closed here apart
    # from the page, through the page's layout, to the pixel
    state = kinematic_state(engine, data["frames"])
    row = np.flatnonzero(state.masses.cylinder == WATCHED)[0]
    for instant in playing:
        frame = instant["frame"]
        assert_allclose(frame * 360 / data["frames"], instant["angle"] % 360, atol=1e-9)
        position = state.masses.positions[row, frame]
        assert_allclose(instant["end"], expected_pixel(data, "end", position), atol=0.5)
        if data["side"] is not None:
            z = engine.cylinder(WATCHED).z_m
            assert_allclose(instant["side"], expected_pixel(data, "side", position, z), atol=0.5)


def show_table(config):
    """``balance show``'s firing order, intervals and each cylinder's TDC, as it prints them."""
    result = invoke("show", config)
    assert result.exit_code == 0, result.output
    lines = result.output.splitlines()
    order = next(line for line in lines if line.strip().startswith("firing:"))
    order = [int(n) for n in order.split(":")[1].split("(")[0].strip().split("-")]
    intervals = next(line for line in lines if "intervals (°)" in line)
    intervals = [float(v) for v in intervals.split(":")[1].split(",")]
    tdc = {}
    for line in lines:
        words = line.split()
        if words and words[0].isdigit() and len(words) > 3:
            tdc[int(words[0])] = float(words[-1])
    return order, intervals, tdc


def test_step_to_tdc_lands_on_the_firing_angles_show_prints(opened):
    name, engine, data, report, _, _ = opened
    order, intervals, tdc = show_table(ENGINES[name])
    steps = report["steps"]
    # one step for each firing instant (cylinders that fire together share one), then round
    # to the first again
    firings = []
    for step in steps:
        firings += sorted(step["cylinders"], key=order.index)
        for n in step["cylinders"]:
            # show prints TDCs to two decimals
            assert abs((step["angle"] - tdc[n] + 180) % 360 - 180) <= 0.005 + 1e-9, (n, step)
    start = order.index(firings[0])
    assert firings[: len(order)] == order[start:] + order[:start]
    assert firings[len(order) :] == firings[: len(firings) - len(order)]
    # the gaps between the steps are the intervals show prints (firings together: a gap of 0)
    gaps = [
        (b["angle"] - a["angle"]) % data["cycle"] for a, b in zip(steps, steps[1:], strict=False)
    ]
    shown = [i for i in intervals if i > 0.005]
    k = order.index(steps[0]["cylinders"][0])
    rolled = [i for i in intervals[k:] + intervals[:k] if i > 0.005]
    assert len(gaps) == len(shown)
    assert_allclose(gaps, rolled, atol=0.005 * 2 + 1e-9)
    # at a firing's own instant the piston is drawn where the linkage closes at that angle
    # (the state's grid does not hold it: a link rod's TDC falls between its frames)
    from balance_cli.kinematics import linkage_state

    for step in steps[:3]:
        closed = linkage_state(engine, np.radians([step["angle"] % 360]))
        row = np.flatnonzero(closed.masses.cylinder == WATCHED)[0]
        position = closed.masses.positions[row, 0]
        assert_allclose(step["end"], expected_pixel(data, "end", position), atol=0.5)


def without(engine, number):
    """The engine without cylinder ``number``, as a configuration without it would make it: its
    firing order (if given) without it too."""
    order = engine.firing_order
    return engine.replace(
        name=f"{engine.name} without cylinder {number}",
        cylinders=tuple(c for c in engine.cylinders if c.number != number),
        firing_order=None if order is None else tuple(n for n in order if n != number),
    )


def as_complex(pair):
    return complex(pair[0], pair[1])


def test_a_cylinder_left_out_gives_what_compare_gives_for_the_engine_without_it(opened):
    name, engine, data, report, _, _ = opened
    number = LEFT_OUT[name]
    assert report["leftOut"] is True
    reduced = without(engine, number)
    document = balance.compare([balance.analyse(reduced)]).to_dict()["engines"][0]
    # compare's phasors to its own noise floor (below it: exact zeros), N and N·m
    floors = {"force": document["noise_floor_N"], "moment": document["noise_floor_Nm"]}
    units = {"force": "N", "moment": "Nm"}
    changed = False
    for page, record in zip(report["without"], document["orders"], strict=True):
        assert page["order"] == record["order"]
        for quantity in ("force", "moment"):
            values = record[quantity]
            unit = units[quantity]
            for part in ("forward", "backward"):
                expected = values[f"{part}_{unit}"] * np.exp(1j * np.radians(values[f"{part}_deg"]))
                drawn = as_complex(page[quantity][part])
                assert abs(drawn - expected) <= 10 * floors[quantity], (record["order"], quantity)
        whole = report["all"][record["order"] - 1]["force"]["forward"]
        changed |= abs(as_complex(page["force"]["forward"]) - as_complex(whole)) > 1.0
    # it made a difference, and turning the cylinder on again restores the engine's own
    assert changed
    assert report["back"] == report["all"]
    analysed = balance.analyse(engine)
    for page, order in zip(report["all"], analysed.shaking.orders, strict=True):
        assert (
            abs(as_complex(page["force"]["forward"]) - order.force_forward) <= 10 * floors["force"]
        )
        assert (
            abs(as_complex(page["moment"]["backward"]) - order.moment_backward)
            <= 10 * floors["moment"]
        )


def test_a_master_rods_cylinder_cannot_be_left_out(opened):
    # the radial's cylinder 1 carries the link rods: the engine has none without it
    name, *_, report, _, _ = opened
    if name == "radial":
        assert report["refused"] is False
