"""What several test modules share: the repository's paths, engines written as text or built in
code, the command line run in-process, and second methods written apart from the library.

Tests import it as ``tests.support`` (the repository root is on pytest's ``pythonpath``);
fixtures are in ``tests/conftest.py``.
"""

import json
import math
import os
import textwrap
from pathlib import Path

import numpy as np
from click.testing import CliRunner

from balance_cli.cli import main
from balance_cli.model import Cylinder, Engine, Throw

# --- paths -------------------------------------------------------------------------------------

ROOT = Path(__file__).resolve().parent.parent
CONFIGS = ROOT / "configs"
TEMPLATES = ROOT / "templates"
PART3 = CONFIGS / "tanaka-part3"
#: the reference records and second methods of tests/validation
REFERENCE = ROOT / "tests" / "validation" / "reference"

#: engines of the library that several modules use
TODAY = CONFIGS / "today"
V8 = PART3 / "1a-v8-90-flat.toml"
RADIAL = PART3 / "5a-radial-9.toml"
V12 = CONFIGS / "nakanishi-v12-90-2stroke.toml"
BRAMO = CONFIGS / "bramo-323.toml"
JUMO = "configs/today/opposed-piston/junkers-jumo-205.toml"
VR6 = "configs/today/vr/vw-vr6.toml"

# --- engines as text ---------------------------------------------------------------------------

#: a valid two-cylinder configuration that tests of bad input change one key at a time
TWIN = """\
name = "test twin"
cycle = 4
speed = "3000 rpm"
crank_radius = "40 mm"
rod_length = "140 mm"
firing_order = [1, 2]

[masses]
reciprocating = "500 g"

[[banks]]
angle = 0

[[throws]]
phase = 0
z = "0 mm"
[[throws]]
phase = 180
z = "90 mm"
"""
#: the twin's first cylinder alone
SINGLE = (
    TWIN.replace('name = "test twin"', 'name = "test single"')
    .replace("firing_order = [1, 2]\n", "")
    .split("[[throws]]")[0]
    + "[[throws]]\nphase = 0\n"
)
#: TWIN's (and SINGLE's) reciprocating mass, kg, crank radius, m, and throw spacing, m
TWIN_RECIPROCATING_KG, TWIN_CRANK_RADIUS_M, TWIN_PITCH = 0.5, 0.040, 0.090


def replaced(old, new, base=TWIN):
    """``base`` with its first ``old`` made ``new`` (which must be there)."""
    assert old in base, old
    return base.replace(old, new, 1)


#: a V-twin on one throw whose second cylinder rides on a link rod
LINKED = textwrap.dedent("""\
    name = "test V"
    cycle = 4
    speed = "3000 rpm"
    crank_radius = "40 mm"
    rod_length = "140 mm"

    [masses]
    reciprocating = "500 g"

    [[banks]]
    angle = -30
    [[banks]]
    angle = 30

    [[throws]]
    phase = 0

    [links]
    master_bank = 1
    length = "110 mm"
    knuckle_radius = "30 mm"
""")

#: a flat twin whose name holds a table's column separator and a script tag
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

#: an in-line 6 four-stroke, crank 0-240-120-120-240-0, firing 1-5-3-6-2-4
INLINE6 = """\
name = "test in-line 6"
cycle = 4
speed = "2000 rpm"
crank_radius = "68.5 mm"
rod_length = "207 mm"
firing_order = [1, 5, 3, 6, 2, 4]

[masses]
reciprocating = "2.521 kg"

[[banks]]
angle = 0

[[throws]]
phase = 0
[[throws]]
phase = 240
[[throws]]
phase = 120
[[throws]]
phase = 120
[[throws]]
phase = 240
[[throws]]
phase = 0
"""

#: INLINE6's shaft line: a pulley, six throws and a flywheel
TORSION6 = """
[torsion]
throw_inertia = "0.0467 kg*m^2"
stiffness = "1.253e6 N*m/rad"
throw_damping = "2 N*m*s/rad"
loss_factor = 0.035
shaft_diameter = "80 mm"

[[torsion.front]]
name = "pulley"
inertia = "0.017 kg*m^2"
stiffness = "1.106e6 N*m/rad"

[torsion.flywheel]
inertia = "2.075 kg*m^2"
stiffness = "1.976e6 N*m/rad"
"""

#: the orders of a four-stroke's torsional excitation, ½ to 12
TORSION_ORDERS = np.arange(1, 25) / 2


#: a [gas] cycle for the car's in-line four (configs/inline-4-car.toml)
CAR_GAS = """
[gas]
bore = "86 mm"
compression_ratio = 10
imep = "12 bar"
"""


def inline_toml(name, phases, pitch_mm, cycle=2, banks=(0,)):
    """An engine with reciprocating masses only (1 kg, r = 50 mm, 3000 rpm), one throw per
    phase, ``pitch_mm`` apart: m·r·ω² = 1·0.05·(100π)² N."""
    text = (
        f'name = "{name}"\ncycle = {cycle}\nspeed = "3000 rpm"\ncrank_radius = "50 mm"\n'
        'rod_length = "200 mm"\n\n[masses]\nreciprocating = "1 kg"\n'
    )
    text += "".join(f"\n[[banks]]\nangle = {b}\n" for b in banks)
    return text + "".join(
        f'\n[[throws]]\nphase = {p}\nz = "{j * pitch_mm} mm"\n' for j, p in enumerate(phases)
    )


MRW2 = 1.0 * 0.05 * (3000 * math.pi / 30) ** 2  # inline_toml's m·r·ω², N
PITCH = 0.1  # d, m


def inline_template_text(n, pitch_mm=500):
    """An in-line two-stroke template of ``n`` throws, as a user would write it."""
    throws = "".join(f'[[throws]]\nz = "{j * pitch_mm} mm"\n' for j in range(n))
    return (
        f'name = "In-line {n}"\ncycle = 2\nspeed = "300 rpm"\ncrank_radius = "150 mm"\n'
        f'rod_length = "600 mm"\n[masses]\nreciprocating = "120 kg"\n[[banks]]\nangle = 0\n'
        + throws
    )


# --- engines built in code ---------------------------------------------------------------------


def make_engine(
    banks_deg,
    throws,
    *,
    r=0.08,
    rod=0.28,
    m=1.0,
    rpm=1000.0,
    cycle=4,
    frame="fixed",
    rotating=0.0,
    pin_offset=0.0,
    links=None,
    firing_order=None,
):
    """A grid engine: one cylinder per (bank, throw), numbered bank by bank.

    ``throws`` is a list of (phase in degrees, z in metres); ``links`` is None or
    (master bank index, link length m, knuckle radius m, knuckle mass kg).
    """
    throw_objs = tuple(Throw(math.radians(p), z) for p, z in throws)
    banks = tuple(math.radians(b) for b in banks_deg)
    cylinders = []
    for b in range(len(banks)):
        for t, throw in enumerate(throw_objs):
            number = b * len(throws) + t + 1
            extra = {}
            if links is not None and b != links[0]:
                master_bank, length, radius, knuckle = links
                extra = dict(
                    master=master_bank * len(throws) + t + 1,
                    link_length_m=length,
                    knuckle_radius_m=radius,
                    knuckle_angle_rad=banks[b] - banks[master_bank],
                    knuckle_kg=knuckle,
                )
            cylinders.append(Cylinder(number, b + 1, t + 1, throw.z_m, m, **extra))
    return Engine(
        name="test engine",
        cycle=cycle,
        speed_rad_s=rpm * math.pi / 30.0,
        crank_radius_m=r,
        rod_length_m=rod,
        bank_angles_rad=banks,
        throws=throw_objs,
        cylinders=tuple(cylinders),
        rotating_kg=rotating,
        pin_offset_m=pin_offset,
        frame=frame,
        firing_order=firing_order,
    )


#: the opposed single's crank radius and rod, m, one piston's reciprocating mass, kg, and speed
OPPOSED_R, OPPOSED_L, OPPOSED_M, OPPOSED_RPM = 0.08, 0.32, 2.0, 2000.0
OPPOSED_OMEGA = OPPOSED_RPM * math.pi / 30


def opposed_single(lead_deg=0.0, direction=1, rotating="0 kg", gas=""):
    """One bore, two pistons, two crankshafts 1 m apart along it; the second crank at
    180° − lead in its own sense (its piston `lead` later than the mirror image)."""
    import balance_cli as balance

    return balance.loads(
        textwrap.dedent(f"""
        name = "opposed single"
        cycle = 2
        speed = "{OPPOSED_RPM} rpm"
        crank_radius = "{OPPOSED_R * 1000} mm"
        rod_length = "{OPPOSED_L * 1000} mm"
        [masses]
        reciprocating = "{OPPOSED_M} kg"
        rotating = "{rotating}"
        [[banks]]
        angle = 0
        [[crankshafts]]
        [[crankshafts]]
        x = "1 m"
        direction = {direction}
        [[throws]]
        phase = 0
        [[throws]]
        phase = {180.0 - lead_deg}
        crankshaft = 2
        [[cylinders]]
        number = 1
        bank = 1
        throw = 1
        opposed_throw = 2
        {gas}
        """)
    )


# --- second methods, apart from the library ----------------------------------------------------


def exact_b(q, k):
    """B_k of a plain slider-crank (inertia force = m·r·ω²·Σ B_k cos kθ) by a second method:
    the closed-form acceleration ẍ/(−rω²) = cos θ + q cos 2θ/√(1 − q² sin²θ)
    + q³ sin²2θ/(4(1 − q² sin²θ)^{3/2}), projected on cos kθ by the trapezoidal rule (exact to
    rounding for periodic integrands)."""
    theta = np.linspace(0.0, 2 * np.pi, 4096, endpoint=False)
    root = np.sqrt(1 - q**2 * np.sin(theta) ** 2)
    accel = (
        np.cos(theta) + q * np.cos(2 * theta) / root + q**3 * np.sin(2 * theta) ** 2 / (4 * root**3)
    )
    return 2 * np.mean(accel * np.cos(k * theta))


def holzer(inertias, stiffnesses, omega2):
    """Holzer's table: θ₁ = 1; the torque passed on T_i = Σ_{m≤i} J_m·ω²·θ_m; θ_{i+1} =
    θ_i − T_i/k_i. Returns the angles and the residual torque after the last disk."""
    theta, passed, angles = 1.0, 0.0, []
    for i, j in enumerate(inertias):
        angles.append(theta)
        passed += j * omega2 * theta
        if i < len(stiffnesses):
            theta -= passed / stiffnesses[i]
    return np.array(angles), passed


def sinusoid(cylinders=4, mean=80.0, spread=120.0, samples=4096):
    """Margoulis's (3): C = C_m + (ΔC/2)·sin(Nθ/2) over a four-stroke's 720°."""
    theta = np.arange(samples) * 4 * math.pi / samples
    return mean + spread / 2 * np.sin(cylinders * theta / 2)


def rad_s(rpm):
    return rpm * 2 * math.pi / 60


# --- the command line and the library, run as a user runs them ---------------------------------


def invoke(*args):
    """``balance ARGS`` in this process (arguments made strings: paths may be given)."""
    return CliRunner().invoke(main, [str(a) for a in args])


def search_api(template, objective, **kwargs):
    """The library's search in this process (one worker)."""
    from balance_cli.cranksearch import search

    return search(template, objective, workers=1, **kwargs)


def write(tmp_path, text, name="engine.toml"):
    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    return path


def twin_file(tmp_path, text=TWIN, name="e.toml"):
    """A configuration file, the twin unless told otherwise."""
    config = tmp_path / name
    config.write_text(text, encoding="utf-8")
    return config


def strict_json(text):
    """JSON as the standard reads it: Infinity and NaN are not numbers there."""

    def refuse(constant):
        raise AssertionError(f"{constant} is not JSON")

    return json.loads(text, parse_constant=refuse)


def snapshot(folder):
    """Every file under ``folder`` with its bytes (and what each symbolic link points to)."""
    out = {}
    for path in sorted(Path(folder).rglob("*")):
        if path.is_symlink():
            out[str(path)] = ("link", os.readlink(path))
        elif path.is_file():
            out[str(path)] = path.read_bytes()
        else:
            out[str(path)] = "folder"
    return out


def check_refused(result, code, words, before, folder):
    """The one error line, its words, the exit status, no traceback, nothing changed."""
    assert isinstance(result.exception, SystemExit), result.exception
    assert result.exit_code == code, (result.exit_code, result.output)
    errors = [line for line in result.stderr.splitlines() if line.startswith("Error:")]
    assert len(errors) == 1, result.stderr
    assert words in errors[0], errors[0]
    if code == 1:
        assert result.stderr.count("\n") == 1, result.stderr  # exactly one line
    assert result.stdout == "", result.stdout
    assert snapshot(folder) == before
