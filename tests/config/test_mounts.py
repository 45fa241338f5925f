"""The [mounts] table: read as written, and every bad value refused in one line that names the
file, the key and the fix — from the library and from the command line, which then writes
nothing."""

import numpy as np
import pytest
from numpy.testing import assert_allclose

import balance_cli as balance
from balance_cli.errors import ConfigError, ModelError
from balance_cli.model import Mount, MountSystem, inertia_matrix
from tests.mounting.helpers import COUPLED
from tests.support import invoke

TEXT = COUPLED.read_text(encoding="utf-8")


def test_the_coupled_example_reads_as_written():
    """Masses, positions and rates in SI; the inclined mount C's compression axis (0, 1, 1)/√2
    and its shears across it; the products in the tensor convention are J's entries."""
    system = balance.load(COUPLED).mounts
    assert system.mass_kg == 180.0 and system.cg_m == (0.0, 0.0, 0.1)
    assert system.inertia_kgm2 == ((8.0, -0.4, 0.9), (-0.4, 12.0, 0.3), (0.9, 0.3, 10.0))
    a, _, c, d = system.mounts
    assert a.name == "A" and a.position_m == (0.3, 0.25, -0.1)
    assert_allclose(np.diag(a.stiffness()), [150e3, 120e3, 250e3], rtol=1e-15)
    root = 1 / np.sqrt(2)
    # k_c·d·dᵀ + k_s·(I − d·dᵀ) for equal shears: the 45° mount's matrix by hand
    axis = np.array([0, root, root])
    by_hand = 300e3 * np.outer(axis, axis) + 80e3 * (np.eye(3) - np.outer(axis, axis))
    assert_allclose(c.stiffness(), by_hand, rtol=0, atol=1e-9)
    assert_allclose(c.compression_axis, axis, atol=1e-16)
    assert d.loss_factor == 0.0 and d.damping_ns_m == (0.0, 0.0, 0.0)


def test_products_given_as_integrals_are_negated():
    """products_convention = "integral": the file gives ∫xy dm = 0.4, ...; J's entries are
    their negatives, so the same engine is J = [[8, −0.4, 0.9], ...] when the file gives
    [0.4, −0.9, −0.3] as integrals."""
    text = TEXT.replace(
        'products = ["-0.4 kg*m^2", "0.9 kg*m^2", "0.3 kg*m^2"]',
        'products = ["0.4 kg*m^2", "-0.9 kg*m^2", "-0.3 kg*m^2"]',
    ).replace('products_convention = "tensor"', 'products_convention = "integral"')
    assert balance.loads(text).mounts == balance.load(COUPLED).mounts


def test_inertia_matrix_from_moments_and_products():
    assert inertia_matrix((1.0, 2.0, 2.5), (0.1, 0.2, 0.3)) == (
        (1.0, 0.1, 0.2),
        (0.1, 2.0, 0.3),
        (0.2, 0.3, 2.5),
    )
    assert inertia_matrix((1.0, 2.0, 2.5), (0.1, 0.2, 0.3), "integral")[0] == (1.0, -0.1, -0.2)


BAD = [
    (('mass = "180 kg"', 'mass = "0 kg"'), "mounts.mass", "greater than zero"),
    (('mass = "180 kg"', 'mass = "-5 kg"'), "mounts.mass", "greater than zero"),
    (
        (
            'stiffness = ["150 N/mm", "120 N/mm", "250 N/mm"]',
            'stiffness = ["0 N/mm", "1 N/mm", "2 N/mm"]',
        ),
        "mounts.mount[1].stiffness[1]",
        "greater than zero",
    ),
    (
        ('compression = "300 N/mm"', 'compression = "-300 N/mm"'),
        "mounts.mount[3].compression",
        "greater than zero",
    ),
    (
        (
            'inertia = ["8.0 kg*m^2", "12.0 kg*m^2", "10.0 kg*m^2"]',
            'inertia = ["8.0 kg*m^2", "0 kg*m^2", "10.0 kg*m^2"]',
        ),
        "mounts.inertia[2]",
        "greater than zero",
    ),
    (
        (
            'products = ["-0.4 kg*m^2", "0.9 kg*m^2", "0.3 kg*m^2"]',
            'products = ["-0.4 kg*m^2", "9.5 kg*m^2", "0.3 kg*m^2"]',
        ),
        "mounts.products",
        "not positive definite",
    ),
    (
        (
            'inertia = ["8.0 kg*m^2", "12.0 kg*m^2", "10.0 kg*m^2"]',
            'inertia = ["8.0 kg*m^2", "25.0 kg*m^2", "10.0 kg*m^2"]',
        ),
        "mounts.products",
        "triangle inequality",
    ),
    (('mass = "180 kg"', 'mas = "180 kg"'), "mounts.mas", "unknown key"),
    (
        ('name = "C"', 'name = "C"\nstiffness = ["1 N/mm", "1 N/mm", "1 N/mm"]'),
        "mounts.mount[3].stiffness",
        "one of the two",
    ),
    (("axis = [0, 1, 1]", ""), "mounts.mount[3].axis", "missing"),
    (("axis = [0, 1, 1]", "axis = [0, 0, 0]"), "mounts.mount[3].axis", "must not be"),
    (
        ("axis = [0, 1, 1]", "axis = [0, 1, 1]\nshear_axis = [0, 2, 2]"),
        "mounts.mount[3].shear_axis",
        "along the compression axis",
    ),
    (("axis = [0, 1, 1]", 'axis = [0, "1", 1]'), "mounts.mount[3].axis[2]", "number"),
    (
        ('position = ["0.30 m", "0.25 m", "-0.10 m"]', 'position = ["0.30 m", "0.25 m"]'),
        "mounts.mount[1].position",
        "needs 3",
    ),
    (
        (
            'position = ["0.30 m", "0.25 m", "-0.10 m"]',
            'position = ["0.30 m", "0.25 kg", "-0.10 m"]',
        ),
        "mounts.mount[1].position[2]",
        "length",
    ),
    (
        ('products_convention = "tensor"', 'products_convention = "cad"'),
        "mounts.products_convention",
        '"tensor" or "integral"',
    ),
    (('name = "B"', 'name = "A"'), "mounts.mount", "two mounts named 'A'"),
    (
        (
            'stiffness = ["100 N/mm", "90 N/mm", "180 N/mm"]',
            'stiffness = ["100 N/mm", "90 N/mm", "180 N/mm"]\ndamping = "-1 N*s/m"',
        ),
        "mounts.mount[4].damping",
        "negative",
    ),
    (
        (
            'stiffness = ["100 N/mm", "90 N/mm", "180 N/mm"]',
            'stiffness = ["100 N/mm", "90 N/mm", "180 N/mm"]\nloss_factor = 3',
        ),
        "mounts.mount[4].loss_factor",
        "from 0 to 2",
    ),
]


@pytest.mark.parametrize("change, key, words", BAD, ids=[b[1] + ": " + b[2] for b in BAD])
def test_bad_mount_tables_name_the_key(change, key, words, tmp_path):
    assert change[0] in TEXT
    text = TEXT.replace(*change, 1)
    with pytest.raises(ConfigError) as caught:
        balance.loads(text, "engine.toml")
    assert caught.value.key == key, str(caught.value)
    assert words in str(caught.value)
    path = tmp_path / "engine.toml"
    path.write_text(text, encoding="utf-8")
    out = tmp_path / "out.json"
    result = invoke("mounts", path, "--format", "json", "-o", out)
    assert result.exit_code == 1
    lines = result.output.strip().splitlines()
    assert len(lines) == 1 and key in lines[0] and str(path) in lines[0], result.output
    assert "Traceback" not in result.output and not out.exists()


def test_mounts_that_leave_a_motion_free_name_it():
    """The four mounts moved onto one line, y = 0, z = −0.1 m, along x: point springs on a
    line cannot resist turning about it. That turning, θ_x about the line with Y = −0.1·θ_x,
    has kinetic energy ½·(J_xx + m·0.1²)·θ_x² = ½·(8 + 1.8)·θ_x²: mostly roll (8 of 9.8,
    J_xz aside); the message names it and says what to do."""
    text = TEXT
    for old in (
        '"0.25 m", "-0.10 m"',
        '"-0.25 m", "-0.10 m"',
        '"0.20 m", "-0.05 m"',
        '"-0.22 m", "0.05 m"',
    ):
        text = text.replace(old, '"0 m", "-0.10 m"')
    with pytest.raises(ConfigError) as caught:
        balance.loads(text, "engine.toml")
    message = str(caught.value)
    assert caught.value.key == "mounts.mount"
    assert "the mounts leave the engine free to move" in message
    assert "mostly roll (rx)" in message
    assert "give a mount a rate across that motion" in message


def test_a_single_mount_cannot_hold_the_engine():
    """One point spring resists no turning about itself: the rotations through the mount are
    free (its rates act at a point)."""
    mount = Mount.aligned("only", (0.0, 0.0, -0.1), (1e5, 1e5, 1e5))
    with pytest.raises(ModelError, match="free to move") as caught:
        MountSystem(100.0, inertia_matrix((5.0, 5.0, 5.0)), (mount,))
    assert caught.value.parameter == "mounts"


def test_a_mount_system_rebuilt_with_one_rate_changed():
    """The design loop's step: one mount's rates changed, the rest kept, all checked again;
    an unknown mount is an error naming the mounts there are."""
    system = balance.load(COUPLED).mounts
    stiffer = system.replace_mount("A", rates_n_m=(300e3, 120e3, 250e3))
    assert stiffer.mount("A").rates_n_m == (300e3, 120e3, 250e3)
    assert stiffer.mount("B") is system.mount("B")
    assert stiffer.stiffness_matrix()[0, 0] == pytest.approx(
        system.stiffness_matrix()[0, 0] + 150e3
    )
    with pytest.raises(ModelError, match="'E' is not one of the mounts .A, B, C, D."):
        system.replace_mount("E", loss_factor=0.1)
    with pytest.raises(ModelError, match="greater than zero"):
        system.replace_mount("A", rates_n_m=(0.0, 1.0, 1.0))
