"""Pictures of the engine on its mounts: what each draws, and the equivalent box."""

import numpy as np
import pytest
from numpy.testing import assert_allclose

import balance_cli as balance
from tests.mounting.helpers import COUPLED, SYMMETRIC


@pytest.fixture(scope="module")
def coupled():
    return balance.mounts(balance.load(COUPLED), speeds_rpm=np.linspace(200, 2000, 37))


def test_equivalent_box_has_the_systems_mass_and_moments():
    """The uniform box of half-sides a, b, c and mass m has J_xx = m·(b² + c²)/3, ...: the box
    drawn for the symmetric example (m = 150 kg, J = diag(6, 9, 8)) gives those back."""
    system = balance.load(SYMMETRIC).mounts
    a, b, c = balance.plot.equivalent_box(system)
    m = system.mass_kg
    assert_allclose(
        [m * (b * b + c * c) / 3, m * (a * a + c * c) / 3, m * (a * a + b * b) / 3],
        [6.0, 9.0, 8.0],
        rtol=1e-14,  # rounding of the square roots
    )


def test_mode_shapes_draw_six_boxes_on_their_mounts(coupled):
    fig = balance.plot.mount_modes(coupled)
    axes = fig.axes
    assert len(axes) == 6 and all(ax.name == "3d" for ax in axes)
    # each: the box at rest and moved (12 edges each) and the crank axis
    assert all(len(ax.lines) == 25 for ax in axes)
    assert "mode 1" in axes[0].get_title() and "lateral" in axes[0].get_title()


def test_energy_bars_add_up_to_the_table(coupled):
    fig = balance.plot.energy_bars(coupled)
    (ax,) = fig.axes
    widths = np.zeros(6)
    for patch in ax.patches:
        widths[int(round(patch.get_y() + patch.get_height() / 2))] += patch.get_width()
    clipped = [np.clip(m.energy_pct, 0.0, None).sum() for m in coupled.modes]
    assert_allclose(widths, clipped, rtol=1e-12)


def test_mount_forces_one_panel_a_mount_with_the_driven_resonances(coupled):
    fig = balance.plot.mount_forces(coupled)
    panels = fig.axes
    assert [ax.get_title() for ax in panels] == [f"mount {n}" for n in "ABCD"]
    driven = [c for c in coupled.crossings if c.excited]
    assert driven
    # a line at each, a label where it clears the one before
    assert len(panels[0].lines) == 4 + len(driven)
    assert 1 <= len(panels[0].texts) <= len(driven)
    assert_allclose(panels[0].lines[3].get_ydata(), coupled.response.force_magnitude_peak_n[:, 0])


def test_pictures_refuse_what_is_not_a_mount_result():
    with pytest.raises(balance.PlotError, match="result must be a MountResult"):
        balance.plot.mount_modes(balance.analyse(balance.load(SYMMETRIC)))
