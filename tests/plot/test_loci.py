"""The locus picture: the resultant force per cylinder, or the free moment, over a revolution."""

import math
import re

import numpy as np
import pytest
from numpy.testing import assert_allclose

import balance_cli as balance
from balance_cli import analyse, load, plot
from tests.support import MRW2, PITCH, V8, inline_toml, write


def test_radial_secondary_locus_is_a_circle_of_its_forward_amplitude(part3):
    """F⁺e^{2iθ} + F⁻e^{−2iθ}: the radius stays within |F⁻| of |F⁺| (F⁻ is 0.06 % of F⁺)."""
    result = part3["5a-radial-9"]
    x, y = plot.locus_points(result, order=2)
    second = result.order(2)
    unit = result.per_cylinder_unit_n
    assert_allclose(
        np.hypot(x, y),
        abs(second.force_forward) / unit,
        atol=abs(second.force_backward) / unit + 1e-12,
    )


def test_flat_crank_v8_secondary_locus_is_a_segment_across(part3):
    x, y = plot.locus_points(part3["1a-v8-90-flat"], order=2)
    assert np.abs(y).max() < 1e-12
    assert_allclose(np.abs(x).max(), 0.21473, atol=1e-5)  # √2/2·B2: test_papers
    assert x.min() < 0 < x.max()


def test_locus_leaves_out_the_forward_first_order_on_a_crankshaft_only(part3):
    x, y = plot.locus_points(part3["5a-radial-9"])
    assert np.hypot(x, y).max() < 0.07  # the 0.5 primary is counterweighted
    x, y = plot.locus_points(part3["5b-rotary-9"])
    assert_allclose(np.abs(x).max(), 0.0341, atol=1e-4)  # nothing removed on a rotary


def test_locus_figure_draws_each_engines_points_with_its_own_colour(part3):
    results = list(part3.values())
    fig = plot.locus(results)
    lines = [
        line for line in fig.axes[0].lines if line.get_label() in {r.engine.name for r in results}
    ]
    assert [line.get_label() for line in lines] == [r.engine.name for r in results]
    for line, result in zip(lines, results, strict=True):
        x, y = plot.locus_points(result)
        assert_allclose(line.get_xdata()[:-1], x, atol=1e-15)
        assert_allclose(line.get_ydata()[:-1], y, atol=1e-15)
    assert len({line.get_color() for line in lines}) == len(lines)


def test_locus_draws_into_a_given_axes():
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots()
    assert plot.locus([analyse(load(V8))], ax=ax) is fig and ax.lines


def test_inline_3_moment_locus_is_all_pitching_until_the_counterweight_turns_half_of_it(couples):
    """Without a counterweight the primary couple M⁺e^{iθ} + M⁻e^{−iθ}, M⁻ = conj(M⁺), is real:
    a segment along the reference axis (pitching) of half-length √3·m·r·ω²·d; an ideal
    two-plane counterweight cancels M⁺ and leaves the circle of radius |M⁻| = √3/2·m·r·ω²·d."""
    result = couples["inline-3"]
    theta = 2 * np.pi * np.arange(4 * result.samples) / (4 * result.samples)
    x, y = plot.locus_points(result, 1, of="moment", counterweight=False)
    assert_allclose(x, 0.0, atol=1e-9)
    # Σ (z_i − z̄)·m·r·ω²·cos(θ + β_i) = m·r·ω²·d·(cos(θ + 240°) − cos θ),
    # of amplitude √3·m·r·ω²·d
    assert_allclose(
        y, MRW2 * PITCH * (np.cos(theta + math.radians(240)) - np.cos(theta)), rtol=0, atol=1e-9
    )
    assert_allclose(np.abs(y).max(), math.sqrt(3) * MRW2 * PITCH, rtol=1e-5)  # sampled peak
    x, y = plot.locus_points(result, 1, of="moment")
    assert_allclose(np.hypot(x, y), math.sqrt(3) / 2 * MRW2 * PITCH, rtol=1e-12)


def test_twin_moment_locus_of_order_1_is_a_segment_of_half_length_m_r_w2_d(couples):
    """At θ the first-order forces are m·r·ω²·cos θ at z = 0 and −m·r·ω²·cos θ at z = d, about
    z̄ = d/2: M(θ) = −m·r·ω²·d·cos θ along the axis, forward and backward m·r·ω²·d/2 each. The
    ideal counterweight takes the forward half: a circle of radius m·r·ω²·d/2."""
    result = couples["twin"]
    theta = 2 * np.pi * np.arange(4 * result.samples) / (4 * result.samples)
    x, y = plot.locus_points(result, 1, of="moment", counterweight=False)
    assert_allclose(y, -MRW2 * PITCH * np.cos(theta), rtol=0, atol=1e-9)
    assert_allclose(x, 0.0, rtol=0, atol=1e-9)
    x, y = plot.locus_points(result, 1, of="moment")
    assert_allclose(np.hypot(x, y), MRW2 * PITCH / 2, rtol=1e-12)
    # all orders: a 180° twin's even orders are in phase at both cylinders, so their couples
    # cancel; the odd ones beyond the first are zero for a plain rod (its motion has none)
    x_all, y_all = plot.locus_points(result, of="moment", counterweight=False)
    assert_allclose(y_all, y_all.real, atol=0)
    assert_allclose(y_all, -MRW2 * PITCH * np.cos(theta), rtol=0, atol=1e-8)


def test_locus_legend_of_many_engines_lies_below_the_axes(library):
    fig = plot.locus(library)
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    (legend,) = fig.legends
    box, axes = legend.get_window_extent(renderer), fig.axes[0].get_tightbbox(renderer)
    assert box.y1 <= axes.y0 and box.y0 >= fig.bbox.y0
    assert fig.bbox.x0 <= box.x0 and box.x1 <= fig.bbox.x1
    assert len(legend.get_texts()) == len(library) > 10


def test_locus_in_units_is_the_force_in_them(tmp_path):
    """An in-line 4 (1 kg, r = 50 mm, l = 200 mm, 3000 rpm; throws 0, 180, 180, 0°) at θ = 0:
    two pistons at top dead centre, whose acceleration is r·ω²·(1 + λ), two at bottom, r·ω²·
    (1 − λ) the other way; the resultant is 4·λ·m·r·ω² = m·r·ω² (λ = 0.25) along the axis:
    4934.8 N, 4.9348 kN, and λ = 0.25 per cylinder (÷ 4·m·r·ω²)."""
    engine = analyse(load(write(tmp_path, inline_toml("In-line 4", [0, 180, 180, 0], 100, 4))))
    for units, expected in (("per-cylinder", 0.25), ("N", MRW2), ("kN", MRW2 / 1e3)):
        x, y = plot.locus_points(engine, units=units)
        # the locus sums orders 1 to 8: those above (10, 12, ...) are ~1e-11 of it at λ = 0.25
        assert_allclose([x[0], y[0]], [0.0, expected], rtol=0, atol=1e-9 * expected)
    x, y = plot.locus_points(engine, of="moment", units="kN")
    assert_allclose(np.abs(x).max() + np.abs(y).max(), 0.0, atol=1e-9)  # no free moment
    fig = plot.locus([engine], units="kN")
    ax = fig.axes[0]
    assert "(kN)" in ax.get_xlabel() and "per cylinder" not in ax.get_title()
    assert_allclose(ax.lines[0].get_ydata()[0], MRW2 / 1e3, rtol=1e-9)  # as above
    assert "kN·m" in plot.locus([engine], of="moment", units="kN").axes[0].get_ylabel()
    assert "per cylinder" in plot.locus([engine]).axes[0].get_title()
    with pytest.raises(balance.PlotError, match="units must be one of per-cylinder, N"):
        plot.locus_points(engine, units="dyn")


def test_coinciding_loci_are_told_apart(tmp_path):
    """Turning a whole crank by 37° (throws 37, 217, 217, 37°) only starts its locus 37°
    later: the same curve, though no point falls on another's (37° is not a multiple of the
    0.35° between the locus's 1024 points); the same engine with a shorter rod (λ = 0.3) has
    another. The turned one is drawn dashed over the first and its legend says so; the other
    stays solid."""
    texts = (
        inline_toml("In-line 4", [0, 180, 180, 0], 100, 4),
        inline_toml("In-line 4, turned", [37, 217, 217, 37], 100, 4),
        inline_toml("In-line 4, short rod", [0, 180, 180, 0], 100, 4).replace(
            'rod_length = "200 mm"', 'rod_length = "166.667 mm"'
        ),
    )
    results = [analyse(load(write(tmp_path, t, f"{i}.toml"))) for i, t in enumerate(texts)]
    points = [plot.locus_points(r) for r in results]
    # not the same samples: the turned curve's first point is another crank angle's
    assert np.hypot(points[0][0] - points[1][0], points[0][1] - points[1][1]).max() > 0.01
    assert plot.coinciding(points) == [None, 0, None]
    fig = plot.locus(results)
    lines = fig.axes[0].lines[:3]
    assert [line.get_label() for line in lines] == [
        "In-line 4",
        "In-line 4, turned (coincides with In-line 4)",
        "In-line 4, short rod",
    ]
    assert lines[0].get_linestyle() == "-" and lines[2].get_linestyle() == "-"
    assert lines[1].get_linestyle() == "--"
    # three equal curves: the two drawn over the first dash a third of the pattern each, one
    # after the other (5-point dashes × the 1.6-point line width: 8 on, 16 off, offsets 16, 8)
    again = analyse(load(write(tmp_path, texts[1].replace("turned", "again"), "3.toml")))
    plot.save(plot.locus(results[:2] + [again]), tmp_path / "three.svg")
    svg = (tmp_path / "three.svg").read_text(encoding="utf-8")
    assert set(re.findall(r"stroke-dasharray: ([\d.,]+)", svg)) == {"8,16"}
    assert set(re.findall(r"stroke-dashoffset: ([\d.]+)", svg)) == {"16", "8"}
