"""The star picture: each cylinder's phasors chained tip to tail, and labels that stay readable."""

import math

import matplotlib
import numpy as np
import pytest
from numpy.testing import assert_allclose

from balance_cli import analyse, load, plot
from balance_cli.errors import PlotError
from tests.support import MRW2, PITCH, RADIAL


@pytest.mark.parametrize(
    "config",
    [
        "tanaka-part3/1b-v8-90-flat-links.toml",
        "tanaka-part3/5a-radial-9.toml",
        "tanaka-part3/5b-rotary-9.toml",
        "bramo-323.toml",
        "nakanishi-w12-60-2stroke.toml",
    ],
)
@pytest.mark.parametrize("order", [1, 2, 4])
def test_star_chain_closes_on_the_resultant_of_compare(library, config, order):
    result = next(r for r in library if r.engine.config_path.endswith(config))
    chains = plot.star_chains(result, order)
    o = result.order(order)
    unit = result.per_cylinder_unit_n
    for part, expected in (("forward", o.force_forward), ("backward", o.force_backward)):
        arrows = chains[part]
        end = arrows[-1][2] if arrows else 0j
        assert_allclose(end, expected / unit, atol=1e-10)
        # tip to tail
        for (_, _, head), (_, tail, _) in zip(arrows, arrows[1:], strict=False):
            assert head == tail
    labels = {a[0] for part in chains.values() for a in part}
    assert labels <= {str(c.number) for c in result.engine.cylinders} | {"pins"}


def test_star_figure_draws_the_chains(library):
    chosen = library[:4]
    fig = plot.star(chosen, order=2)
    for ax, result in zip(fig.axes, chosen, strict=True):
        chains = plot.star_chains(result, 2)
        quivers = [c for c in ax.collections if isinstance(c, matplotlib.quiver.Quiver)]
        drawn = [part for part in ("forward", "backward") if chains[part]]
        assert len(quivers) == len(drawn)
        for quiver, part in zip(quivers, drawn, strict=True):
            tails = np.array([a[1] for a in chains[part]])
            assert_allclose(quiver.X, tails.imag, atol=1e-15)  # across is horizontal
            assert_allclose(quiver.Y, tails.real, atol=1e-15)  # along is vertical
    assert len(fig.axes) == len(chosen)  # the empty cells of the grid get no axes


def test_inline_3_moment_star_chains_each_cylinders_lever_times_its_force(couples):
    """Cylinder i at z_i = (i − 1)·d, z̄ = d, primary force m·r·ω²·cos(θ + β_i) along the axis
    (exact for a plain rod without pin offset): forward share (z_i − z̄)·m·r·ω²/2·e^{iβ_i},
    backward the conjugate. The chain ends at the primary couple, √3/2·m·r·ω²·d each way, √3·
    m·r·ω²·d at most (test_results); cylinder 2, on z̄, has no share."""
    result = couples["inline-3"]
    chains = plot.star_chains(result, 1, of="moment")
    for part, sign in (("forward", 1), ("backward", -1)):
        arrows = chains[part]
        assert [label for label, _, _ in arrows] == ["1", "3"]
        expected = {
            "1": -PITCH * MRW2 / 2,
            "3": PITCH * MRW2 / 2 * np.exp(sign * 1j * math.radians(240)),
        }
        for label, tail, head in arrows:
            assert_allclose(head - tail, expected[label], rtol=1e-12, atol=1e-9)
        for (_, _, head), (_, tail, _) in zip(arrows, arrows[1:], strict=False):
            assert head == tail
        end = arrows[-1][2]
        assert_allclose(abs(end), math.sqrt(3) / 2 * MRW2 * PITCH, rtol=1e-12)
        moment = (
            result.order(1).moment_forward if part == "forward" else result.order(1).moment_backward
        )
        assert_allclose(end, moment, rtol=1e-12, atol=1e-9)


def test_cross_plane_v8_primary_couple_is_all_forward_and_the_counterweight_leaves_none(couples):
    """√10·m·r·ω²·d (test_results; each throw's two cylinders 90° apart make a rotating force
    m·r·ω²), all forward: the star's forward chain ends there, the backward one at zero, and
    after the ideal counterweight the first-order moment locus is nothing."""
    result = couples["v8-cross"]
    chains = plot.star_chains(result, 1, of="moment")
    assert_allclose(abs(chains["forward"][-1][2]), math.sqrt(10) * MRW2 * PITCH, rtol=1e-12)
    backward = chains["backward"][-1][2] if chains["backward"] else 0j
    assert abs(backward) < result.engine.noise_floor_nm
    x, y = plot.locus_points(result, 1, of="moment")
    assert not x.any() and not y.any()
    fig = plot.locus([result], 1, of="moment")
    assert fig.axes[0].lines[0].get_label() == "90° V8, cross-plane (no free moment)"


@pytest.mark.parametrize(
    "config",
    [
        "nakanishi-v12-90-2stroke.toml",
        "nakanishi-w12-60-2stroke.toml",
        "bramo-323.toml",
        "inline-12.toml",
    ],
)
@pytest.mark.parametrize("order", [1, 2])
def test_moment_star_closes_on_the_free_moment_of_compare(library, config, order):
    result = next(r for r in library if r.engine.config_path.endswith(config))
    chains = plot.star_chains(result, order, of="moment")
    o = result.order(order)
    for part, expected in (("forward", o.moment_forward), ("backward", o.moment_backward)):
        arrows = chains[part]
        end = arrows[-1][2] if arrows else 0j
        assert_allclose(end, expected, rtol=0, atol=1e3 * result.engine.noise_floor_nm)


def test_moment_star_and_locus_figures_draw_the_moment_in_n_m(couples):
    result = couples["inline-3"]
    fig = plot.star([result], order=1, of="moment")
    (ax,) = [a for a in fig.axes if a.axison or a.collections]
    quivers = [c for c in ax.collections if isinstance(c, matplotlib.quiver.Quiver)]
    tails = np.array([a[1] for a in plot.star_chains(result, 1, of="moment")["forward"]])
    assert_allclose(quivers[0].X, tails.imag, atol=1e-12)
    assert_allclose(quivers[0].Y, tails.real, atol=1e-12)
    texts = [t.get_text() for t in ax.texts]
    assert f"forward: |Σ| = {math.sqrt(3) / 2 * MRW2 * PITCH:.4g} N·m" in texts
    assert "free moment" in fig._suptitle.get_text()
    assert plot.stars._magnitude(4980395.12, "N·m") == "4 980 395 N·m"
    assert (
        plot.stars._magnitude(427.3664, "N·m") == "427.4 N·m"
        and plot.stars._magnitude(0.0, "N·m") == "0 N·m"
    )
    fig = plot.locus([result], of="moment")
    assert "free moment" in fig.axes[0].get_title() and "N·m" in fig.axes[0].get_xlabel()
    x, y = plot.locus_points(result, of="moment")
    assert_allclose(fig.axes[0].lines[0].get_ydata()[:-1], y, atol=0)
    for call in (
        lambda: plot.locus([result], of="torque"),
        lambda: plot.star_chains(result, 1, "couple"),
        lambda: plot.locus_points(result, of="Moment"),
    ):
        with pytest.raises(PlotError, match="of must be one of force, moment"):
            call()


@pytest.mark.parametrize("of", ["force", "moment"])
@pytest.mark.parametrize("order", [1, 2, 4])  # a plain rod has no third order
def test_star_labels_of_24_cylinders_do_not_overlap(couples, of, order):
    """The labels the renderer draws (not the placement's estimate) overlap no other label and
    no picture's title, lie inside the figure, each beside its own arrow; the longest arrows
    of each chain are labelled."""
    result = couples["inline-24"]
    fig = plot.star([result, couples["inline-3"]], order=order, of=of)
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    ax = fig.axes[0]
    labels = [t for t in ax.texts if t.get_gid() == "cylinder label"]
    boxes = [t.get_window_extent(renderer) for t in labels]
    chains = plot.star_chains(result, order, of)
    arrows = chains["forward"] + chains["backward"]
    assert len(labels) >= 12
    for i, box in enumerate(boxes):
        assert not any(box.overlaps(other) for other in boxes[i + 1 :]), labels[i].get_text()
        assert fig.bbox.x0 <= box.x0 and box.x1 <= fig.bbox.x1
        assert fig.bbox.y0 <= box.y0 and box.y1 <= fig.bbox.y1
        for other in (
            fig.texts + [a.title for a in fig.axes] + [t for t in ax.texts if t.get_gid() is None]
        ):
            if other.get_text():
                assert not box.overlaps(other.get_window_extent(renderer))
    # beside its arrow: the label's centre within its size plus 3 points of the segment
    points = 72.0 / fig.dpi
    for label, box in zip(labels, boxes, strict=True):
        centre = np.array([(box.x0 + box.x1) / 2, (box.y0 + box.y1) / 2])
        near = []
        for name, tail, head in arrows:
            if name != label.get_text():
                continue
            p, q = (ax.transData.transform((z.imag, z.real)) for z in (tail, head))
            t = np.clip(np.dot(centre - p, q - p) / np.dot(q - p, q - p), 0, 1)
            near.append(np.linalg.norm(centre - (p + t * (q - p))))
        assert min(near) <= max(box.width, box.height) + 3 / points
    for part in ("forward", "backward"):
        longest = max(chains[part], key=lambda a: abs(a[2] - a[1]))[0]
        assert longest in {t.get_text() for t in labels}


def test_place_labels_refuses_overlaps_and_skips_short_segments():
    """Twelve segments crossing at one point, as the spokes of a star: each placed label box
    is clear of every other, the spoke shorter than ``shortest`` gets none."""
    angles = np.radians(np.arange(12) * 30)
    segments = [((0.0, 0.0), (60 * math.cos(a), 60 * math.sin(a))) for a in angles]
    segments.append(((0.0, 0.0), (2.0, 0.0)))
    sizes = [(8.0, 9.0)] * len(segments)
    centres = plot.place_labels(segments, sizes, shortest=5.0)
    assert centres[-1] is None and all(c is not None for c in centres[:-1])
    boxes = [(x - 4, y - 4.5, x + 4, y + 4.5) for x, y in centres[:-1]]
    for i, a in enumerate(boxes):
        for b in boxes[i + 1 :]:
            assert not (a[0] < b[2] and b[0] < a[2] and a[1] < b[3] and b[1] < a[3])


def test_star_titles_of_long_names_stay_apart(couples, tmp_path):
    """Names cut to 60 characters wrap onto two lines instead of running into the next
    picture's title; an engine with no moment says so."""
    from dataclasses import replace

    results = [
        analyse(
            replace(
                couples[key].engine,
                name=couples[key].engine.name
                + " with a very long descriptive name for the design review",
            )
        )
        for key in ("inline-3", "twin", "v8-cross")
    ]
    fig = plot.star(results + [analyse(load(RADIAL))], order=1, of="moment")
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    titles = [ax.title for ax in fig.axes if ax.title.get_text()]
    assert len(titles) == 4 and all("\n" in t.get_text() for t in titles[:3])
    boxes = [t.get_window_extent(renderer) for t in titles]
    for i, box in enumerate(boxes):
        assert not any(box.overlaps(other) for other in boxes[i + 1 :])
        assert fig.bbox.x0 <= box.x0 and box.x1 <= fig.bbox.x1
        sums = [t.get_window_extent(renderer) for t in fig.axes[i].texts if "|Σ|" in t.get_text()]
        assert len(sums) == 2 and not any(box.overlaps(s) for s in sums)
    assert "no free moment of order 1" in [t.get_text() for t in fig.axes[3].texts]
