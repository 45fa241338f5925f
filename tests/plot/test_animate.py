"""The animation: its scene (every position the kinematics', every phasor the analysis's, by
cylinder), its GIF (frames and size), its page's data, and its errors. The page in a browser:
tests/plot/test_animate_page.py."""

import json
import math

import numpy as np
import pytest
from numpy.testing import assert_allclose
from PIL import Image

import balance_cli as balance
from balance_cli.errors import PlotError
from balance_cli.kinematics import kinematic_state
from balance_cli.plot import animate
from balance_cli.plot.animation import MOVIE_DPI, MOVIE_SIZE_IN
from balance_cli.plot.page import DATA_CLASS, layout
from balance_cli.plot.scene import scene
from tests.support import BOXER, CONFIGS, JUMO, RADIAL

V8 = CONFIGS / "today" / "v" / "v8-90-cross-plane.toml"
H16 = CONFIGS / "today" / "h" / "brm-h16.toml"
ROTARY = CONFIGS / "clerget-rotary.toml"
LANCHESTER = CONFIGS / "inline-4-car-lanchester.toml"


@pytest.fixture(scope="module")
def analysed():
    return {
        name: balance.analyse(balance.load(path))
        for name, path in {
            "v8": V8,
            "h16": H16,
            "rotary": ROTARY,
            "radial": RADIAL,
            "jumo": JUMO,
            "lanchester": LANCHESTER,
        }.items()
    }


def angles(view):
    return 2 * np.pi * np.arange(view.frames) / view.frames


def slider(r, rod, crank):
    """A plain rod's piston pin from its crank axis along its cylinder axis, the crank at
    ``crank`` (rad) from that axis: r·cos φ + √(rod² − r²·sin² φ), by hand."""
    return r * np.cos(crank) + np.sqrt(rod**2 - (r * np.sin(crank)) ** 2)


def test_the_pistons_are_the_kinematic_states(analysed):
    for result in analysed.values():
        view = scene(result, 36)
        state = kinematic_state(result.engine, 36)
        for c in result.engine.cylinders:
            row = np.flatnonzero(state.masses.cylinder == c.number)[0]
            assert_allclose(
                view.points[f"p{c.number}"], state.masses.positions[row], rtol=0, atol=0
            )


def test_two_crankshafts_turn_at_their_directions_and_phases(analysed):
    # BRM H16: the lower crankshaft 180 mm across, turning backward, 90° ahead; its throw 5
    # (phase 0) and 6 (phase 180) pins by hand: centre + r·exp(−i(θ + 90° + β))
    result = analysed["h16"]
    view = scene(result, 72)
    theta = angles(view)
    r = result.engine.crank_radius_m
    centre = complex(0.0, -0.180)
    for throw, beta in ((5, 0.0), (6, math.pi)):
        pin = centre + r * np.exp(-1j * (theta + math.pi / 2 + beta))
        # the big end from the rod's small end back along the rod: to rounding
        assert_allclose(view.points[f"t{throw}"], pin, rtol=0, atol=1e-12)
    for throw, beta in ((1, 0.0), (2, math.pi)):
        assert_allclose(view.points[f"t{throw}"], r * np.exp(1j * (theta + beta)), atol=1e-12)
    assert view.fixed == {"c1": 0j, "c2": centre}


def test_opposed_pistons_meet(analysed):
    # Junkers Jumo 205, cylinder 1: the lower piston pushed up from the crank at 0 by throw 1
    # (phase 0), the upper one pushed down from the crank 1 m above by throw 7 (191°), each by
    # hand; the bore between them closes to its inner dead centre and opens again
    result = analysed["jumo"]
    engine = result.engine
    view = scene(result, 360)
    theta = angles(view)
    r, rod = engine.crank_radius_m, engine.rod_length_m
    lower = slider(r, rod, theta)
    upper = 1.0 - slider(r, rod, theta + math.radians(191) - math.pi)
    assert_allclose(view.points["p1"], lower, rtol=0, atol=1e-12)
    assert_allclose(view.points["o1"], upper, rtol=0, atol=1e-12)
    gap = upper - lower
    # closest at θ = −5.5° (the lead halved), 1 − 2(r·cos 5.5° + √(l² − r² sin² 5.5°)); the
    # frames are 1° apart, that instant half-way between two: the gap there is larger by
    # about its curvature 2r times (0.5°)²/2, 6e-6 m
    closest = 1.0 - 2 * slider(r, rod, math.radians(5.5))
    assert closest <= gap.min() <= closest + 1e-5
    assert gap.max() > closest + 3.9 * r


def test_a_rotary_turns_its_crankcase_about_a_fixed_crank(analysed):
    # Clerget: the crank pin stands still on the reference axis; cylinder 1 (the master) turns
    # with the crankcase, at angle θ, its pin at r·cos θ + √(l² − r² sin² θ) from the axis
    result = analysed["rotary"]
    engine = result.engine
    view = scene(result, 72)
    theta = angles(view)
    r, rod = engine.crank_radius_m, engine.rod_length_m
    assert_allclose(view.points["t1"], np.full(72, r + 0j), rtol=0, atol=1e-12)
    assert_allclose(view.points["p1"], slider(r, rod, -theta) * np.exp(1j * theta), atol=1e-12)
    assert view.rotary and view.side_rad is None


def test_link_rods_close_on_the_master_rod(analysed):
    result = analysed["radial"]
    view = scene(result, 90)
    for c in result.engine.cylinders:
        if not c.is_link:
            continue
        knuckle, pin = view.points[f"k{c.number}"], view.points["t1"]
        assert_allclose(np.abs(knuckle - pin), c.knuckle_radius_m, rtol=1e-12)
        assert_allclose(np.abs(view.points[f"p{c.number}"] - knuckle), c.link_length_m, rtol=1e-12)


def test_balancer_shaft_masses_turn_at_their_ratio(analysed):
    # Lanchester: two shafts at ±2×, 70 mm above and 69.8 mm below the crank; a mass given by
    # its unbalance alone is drawn at 0.7 r from its shaft, in the direction the state has it
    result = analysed["lanchester"]
    view = scene(result, 72)
    theta = angles(view)
    r = result.engine.crank_radius_m
    above = view.fixed["s1"] + 0.7 * r * np.exp(1j * (2 * theta + math.pi))
    below = view.fixed["s2"] + 0.7 * r * np.exp(-1j * (2 * theta + math.pi))
    assert_allclose(view.fixed["s1"], 0.070 + 0j, atol=1e-15)
    assert_allclose(view.fixed["s2"], -0.0698 + 0j, atol=1e-15)
    assert_allclose(view.points["b1"], above, atol=1e-12)
    assert_allclose(view.points["b2"], below, atol=1e-12)


def test_firings_are_the_engines_firing_tdcs(analysed):
    # the cross-plane V8 fires 1-8-7-2-6-5-4-3 every 90°, cylinder 1 at its TDC, 45°
    view = scene(analysed["v8"])
    assert [n for _, n in view.events] == [1, 8, 7, 2, 6, 5, 4, 3]
    assert_allclose([a for a, _ in view.events], 45.0 + 90.0 * np.arange(8), atol=1e-9)
    # a firing's own instant is the linkage at that angle: cylinder 1 at its TDC, l + r up its
    # bank (45°)
    engine = analysed["v8"].engine
    top = view.at(45.0)["p1"]
    reach = engine.rod_length_m + engine.crank_radius_m
    assert_allclose(top, reach * np.exp(1j * math.pi / 4), rtol=0, atol=1e-12)


def without(engine, number):
    order = engine.firing_order
    return engine.replace(
        name=f"{engine.name} without {number}",
        cylinders=tuple(c for c in engine.cylinders if c.number != number),
        firing_order=None if order is None else tuple(n for n in order if n != number),
    )


@pytest.mark.parametrize(("name", "number"), [("v8", 3), ("jumo", 6), ("radial", 5)])
def test_a_cylinder_left_out_is_the_engine_without_it(analysed, name, number):
    # a second method: the engine built without the cylinder and analysed afresh, its moment
    # about its own cylinders' mean z
    result = analysed[name]
    view = scene(result, 36)
    force, moment = view.shares(left_out=(number,))
    reduced = balance.analyse(without(result.engine, number))
    scale_n = reduced.engine.per_cylinder_unit_n
    for k, order in enumerate(reduced.shaking.orders):
        # rounding of sums in another order: far below 1e-12 of m·r·ω²·n
        assert_allclose(force[k], [order.force_forward, order.force_backward], atol=1e-12 * scale_n)
        lever = scale_n * reduced.engine.length_scale_m
        assert_allclose(
            moment[k], [order.moment_forward, order.moment_backward], atol=1e-12 * lever
        )
    floor_n, floor_nm = view.noise_floors((number,))
    assert_allclose(floor_n, reduced.engine.noise_floor_n, rtol=1e-12)
    assert_allclose(floor_nm, reduced.engine.noise_floor_nm, rtol=1e-12)


def test_master_rods_cylinders_cannot_be_left_out(analysed):
    groups = {g["label"]: g for g in scene(analysed["radial"], 36).groups}
    assert not groups["1"]["toggle"] and groups["2"]["toggle"]
    assert not groups.get("crank pins", {"toggle": False})["toggle"]


def test_the_gif_has_its_frames_and_size(analysed, tmp_path):
    # a four-stroke's 720° in 24 frames of 30°, 10 × 6.2 in at 72 dpi: 720 × 446 pixels
    path = tmp_path / "v8.gif"
    animate(analysed["v8"]).save(path, frames=24, fps=12)
    with Image.open(path) as gif:
        assert gif.n_frames == 24
        assert gif.size == (720, 446) == (MOVIE_SIZE_IN[0] * MOVIE_DPI, int(MOVIE_SIZE_IN[1] * 72))
        # a GIF keeps hundredths of a second: 1/12 s is 80 ms
        assert gif.info["duration"] == 80 and gif.info["loop"] == 0
        first = np.asarray(gif.convert("RGB"))
        gif.seek(1)
        second = np.asarray(gif.convert("RGB"))
    # it moves; and the firing colour (orange) is there when a cylinder fires (at 45°: in
    # the second frame, 30° to 60°... of the mark's 45° after TDC)
    assert (first != second).any()
    orange = np.array([255, 140, 0])
    assert (np.abs(second.astype(int) - orange).sum(axis=2) < 40).any()


def test_the_default_gif_is_under_two_megabytes(analysed, tmp_path):
    path = tmp_path / "v8.gif"
    animate(analysed["v8"]).save(path)
    with Image.open(path) as gif:
        assert gif.n_frames == 72
    assert path.stat().st_size < 2_000_000


def test_a_two_stroke_turns_once_a_cycle(analysed, tmp_path):
    # any number of frames a cycle, which is one revolution; the matplotlib animation (what
    # an MP4 is written from) has them too
    anim = animate(analysed["jumo"], orders=[1])
    anim.save(tmp_path / "j.gif", frames=9)
    with Image.open(tmp_path / "j.gif") as gif:
        assert gif.n_frames == 9
    page = anim.movie(frames=4, fps=4).to_jshtml()
    assert page.count("frames[3] =") == 1 and "frames[4] =" not in page


def test_the_still_figure(analysed):
    # the end view, the side view (several rows) and 2 orders' force and moment panels with
    # their sums; a radial has no side view
    fig = animate(analysed["v8"]).figure(45.0)
    assert len(fig.axes) == 2 + 6
    assert len(animate(analysed["radial"], orders=[1, 2, 4]).figure(10).axes) == 1 + 8


def test_the_page_data(analysed):
    result = analysed["radial"]
    anim = animate(result)
    text = anim.page()
    start = text.index(f'class="{DATA_CLASS}">') + len(f'class="{DATA_CLASS}">')
    data = json.loads(text[start : text.index("</script>", start)])
    view = anim.scene()
    assert data["frames"] == 180 and data["shown"] == [1, 2] and data["orders"] == list(range(1, 9))
    # positions in whole micrometres
    assert_allclose(
        np.array(data["points"]["p2"][0]) * 1e-6, view.points["p2"].real, rtol=0, atol=0.5e-6
    )
    # each cylinder's shares add up to the engine's phasors
    total = np.array(data["force"]).sum(axis=0)
    order2 = result.order(2)
    assert_allclose(
        total[1],
        [
            order2.force_forward.real,
            order2.force_forward.imag,
            order2.force_backward.real,
            order2.force_backward.imag,
        ],
        atol=1e-9,
    )
    assert data["layout"] == layout(view)
    assert text.count("<script>") == 1 and "<script>\n" in text


def test_a_name_cannot_break_out_of_the_page(tmp_path):
    engine = balance.loads(BOXER, "boxer.toml")
    text = animate(balance.analyse(engine)).page()
    # the name (with a script tag) escaped in the title, and kept whole in the data
    assert "<script>alert(1)" not in text
    assert "&lt;script&gt;alert(1)&lt;/script&gt;" in text
    assert "\\u003cscript>alert(1)\\u003c/script>" in text


@pytest.mark.parametrize(
    ("kwargs", "message"),
    [
        ({"orders": [0]}, "orders must be whole numbers from 1 to 8"),
        ({"orders": [9]}, "orders must be whole numbers from 1 to 8"),
        ({"orders": []}, "orders must name at least one order"),
        ({"orders": "12"}, "orders must be whole numbers from 1 to 8"),
    ],
)
def test_bad_orders(analysed, kwargs, message):
    with pytest.raises(PlotError, match=message):
        animate(analysed["v8"], **kwargs)


def test_bad_results_frames_and_files(analysed, tmp_path, monkeypatch):
    with pytest.raises(PlotError, match="result must be"):
        animate(analysed["v8"].engine)
    anim = animate(analysed["v8"])
    with pytest.raises(
        PlotError, match="frames must be a whole number a revolution: a multiple of 2"
    ):
        anim.save(tmp_path / "a.gif", frames=25)
    with pytest.raises(PlotError, match="fps must be"):
        anim.save(tmp_path / "a.gif", fps=0)
    with pytest.raises(
        PlotError, match=r"a.png' has '.png'; end the file name in .gif, .mp4 or .html"
    ):
        anim.save(tmp_path / "a.png")
    monkeypatch.setattr("shutil.which", lambda name: None)
    with pytest.raises(PlotError, match="an .mp4 is written by ffmpeg, which is not installed"):
        anim.save(tmp_path / "a.mp4")
    assert list(tmp_path.iterdir()) == []


@pytest.mark.skipif(
    __import__("shutil").which("ffmpeg") is None, reason="ffmpeg is not installed here"
)
def test_an_mp4_where_ffmpeg_is_installed(analysed, tmp_path):
    path = tmp_path / "v8.mp4"
    animate(analysed["v8"]).save(path, frames=8)
    assert path.read_bytes()[4:8] == b"ftyp"
