"""The engine on its mounts: the powertrain as one rigid body (its mass, centre of gravity and
inertia tensor) held by elastic mounts, in the engine's axes.

Engine axes: x along the crankshaft towards the front (throw 1's end: balance's axial ``z``
grows towards the back, so x = z̄ − z), z up (balance's *vertical*, the banks' bisector unless
the configuration's ``vertical`` says otherwise), y = z × x completing a right-handed set. The
six motions of the rigid body are the translations of its centre of gravity along x, y, z and
its small rotations about x, y, z (right-handed), in that order: fore-aft, lateral, bounce,
roll, pitch and yaw.

A mount is a point spring at a position from the centre of gravity, with three principal
rates along three perpendicular directions (compression and two shears); it passes on to the
frame the force K·u of its deflection u = X + θ × r (X the centre of gravity's translation, θ
the rotation, r the mount's position). The inertia tensor is the matrix J with angular
momentum H = J·ω about the centre of gravity: its off-diagonal entries are −∫xy dm, ....
"""

import dataclasses
import math
from dataclasses import dataclass

import numpy as np

from ..checks import is_real
from ..errors import ModelError
from .values import check_quantity

__all__ = [
    "Mount",
    "MountSystem",
    "MOTIONS",
    "DOF_LABELS",
    "ROTATIONS",
    "PRODUCT_CONVENTIONS",
    "STANDARD_GRAVITY",
    "inertia_matrix",
    "motion_name",
]

#: the six motions of the rigid body, in the order of its coordinates
MOTIONS = ("fore-aft", "lateral", "bounce", "roll", "pitch", "yaw")
#: the same as coordinates: translations of the centre of gravity, rotations about the axes
DOF_LABELS = ("x", "y", "z", "rx", "ry", "rz")
#: how the crank turns, seen from the front (the end towards +x); SAE J824's standard engine
#: rotation, counter-clockwise seen from the flywheel, is clockwise seen from the front
ROTATIONS = ("clockwise", "anticlockwise")
#: how products of inertia are given: "tensor", the entries of J itself (−∫xy dm); "integral",
#: the integrals ∫xy dm (J's entries are their negatives)
PRODUCT_CONVENTIONS = ("tensor", "integral")
#: m/s², ISO 80000-3
STANDARD_GRAVITY = 9.80665
#: a mount system whose softest motion is this much softer (k/m against the stiffest's) holds
#: nothing there: the motion is free
_FREE = 1e-10
#: a principal moment may exceed the sum of the other two by this fraction of the largest (a
#: flat body meets the triangle inequality with equality; rounding of the entries may not)
_TRIANGLE = 1e-9
#: directions given in code are perpendicular within this
_PERPENDICULAR = 1e-9


def motion_name(index: int) -> str:
    """The motion of coordinate ``index`` (0-5) in words, with its coordinate: "roll (rx)"."""
    return f"{MOTIONS[index]} ({DOF_LABELS[index]})"


def _vector(value, parameter, dimension, sign="any", count=3):
    """``count`` finite SI values (a tuple), each checked as ``dimension``."""
    if isinstance(value, (str, bytes)) or not hasattr(value, "__len__") or len(value) != count:
        raise ModelError(f"must be {count} numbers, got {value!r}", parameter)
    for v in value:
        check_quantity(v, dimension, parameter, sign=sign)
    return tuple(float(v) + 0.0 for v in value)


def _unit(value, parameter):
    """A direction: three finite numbers, not all zero, as a unit vector."""
    if isinstance(value, (str, bytes)) or not hasattr(value, "__len__") or len(value) != 3:
        raise ModelError(
            f"must be a direction of three numbers (x, y, z), got {value!r}", parameter
        )
    if not all(is_real(v) and math.isfinite(v) for v in value):
        raise ModelError(f"must be three finite numbers, got {value!r}", parameter)
    vector = np.array(value, dtype=float)
    size = float(np.linalg.norm(vector))
    if size == 0.0:
        raise ModelError("must not be (0, 0, 0): give the direction it points along", parameter)
    return vector / size


def inertia_matrix(moments_kgm2, products_kgm2=(0.0, 0.0, 0.0), convention="tensor"):
    """The matrix J (H = J·ω) from the principal-axis-free moments (J_xx, J_yy, J_zz) and the
    products (xy, xz, yz) given in ``convention`` ("tensor": J's own entries, −∫xy dm;
    "integral": ∫xy dm, whose negatives J holds), kg·m², as a tuple of three rows."""
    if convention not in PRODUCT_CONVENTIONS:
        raise ModelError(
            f"must be one of {', '.join(PRODUCT_CONVENTIONS)}, got {convention!r}", "convention"
        )
    xx, yy, zz = _vector(moments_kgm2, "moments_kgm2", "moment of inertia", "positive")
    xy, xz, yz = _vector(products_kgm2, "products_kgm2", "moment of inertia")
    sign = 1.0 if convention == "tensor" else -1.0
    xy, xz, yz = sign * xy, sign * xz, sign * yz
    return ((xx, xy, xz), (xy, yy, yz), (xz, yz, zz))


@dataclass(frozen=True)
class Mount:
    """One elastic mount: a point spring with three principal rates.

    Parameters
    ----------
    name : str
        shown in the tables, one line
    position_m : tuple of float
        (x, y, z) from the centre of gravity, engine axes, m
    rates_n_m : tuple of float
        the principal stiffnesses along ``directions``, N/m: for a mount built by
        :meth:`oriented` the compression rate, then the two shear rates
    directions : tuple of tuple of float
        three perpendicular unit vectors (engine axes) the rates act along; default the
        engine's axes x, y, z
    loss_factor : float
        hysteretic damping η of all three rates (the rate is k·(1 + iη) in the forced
        response), 0 to 2
    damping_ns_m : tuple of float
        viscous damping along ``directions``, N·s/m

    Raises
    ------
    ModelError
        a rate that is not positive, directions that are not perpendicular unit vectors, a
        damping that is negative
    """

    name: str
    position_m: tuple
    rates_n_m: tuple
    directions: tuple = ((1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0))
    loss_factor: float = 0.0
    damping_ns_m: tuple = (0.0, 0.0, 0.0)

    def __post_init__(self):
        if not isinstance(self.name, str) or not self.name.strip() or not self.name.isprintable():
            raise ModelError(f"must be one line of printable text, got {self.name!r}", "name")
        set_ = object.__setattr__
        set_(self, "position_m", _vector(self.position_m, "position_m", "length"))
        set_(self, "rates_n_m", _vector(self.rates_n_m, "rates_n_m", "stiffness", "positive"))
        set_(
            self,
            "damping_ns_m",
            _vector(self.damping_ns_m, "damping_ns_m", "viscous damping", "non-negative"),
        )
        if not is_real(self.loss_factor) or not 0.0 <= self.loss_factor <= 2.0:
            raise ModelError(
                f"must be a number from 0 to 2, got {self.loss_factor!r}", "loss_factor"
            )
        set_(self, "loss_factor", float(self.loss_factor))
        if isinstance(self.directions, (str, bytes)) or len(self.directions) != 3:
            raise ModelError(f"must be three directions, got {self.directions!r}", "directions")
        rows = np.array([_unit(d, "directions") for d in self.directions])
        if np.abs(rows @ rows.T - np.eye(3)).max() > _PERPENDICULAR:
            raise ModelError("must be three perpendicular directions", "directions")
        set_(self, "directions", tuple(tuple(float(v) + 0.0 for v in row) for row in rows))

    @classmethod
    def aligned(cls, name, position_m, rates_n_m, **damping) -> "Mount":
        """A mount whose principal axes are the engine's: ``rates_n_m`` along x, y, z, N/m."""
        return cls(name, position_m, rates_n_m, **damping)

    @classmethod
    def oriented(
        cls, name, position_m, compression_n_m, shear_n_m, axis, shear_axis=None, **damping
    ) -> "Mount":
        """A mount of compression rate ``compression_n_m`` along ``axis`` (a direction in engine
        axes, any length) and shear rates ``shear_n_m`` (one for both, or two: along
        ``shear_axis``, then along axis × shear_axis), N/m. ``shear_axis`` defaults to the
        engine's x made perpendicular to the axis (y when the axis lies along x).

        Raises
        ------
        ModelError
            a zero direction, a shear axis along the compression axis
        """
        a = _unit(axis, "axis")
        if shear_axis is None:
            guess = np.array([1.0, 0.0, 0.0]) if abs(a[0]) < 0.9 else np.array([0.0, 1.0, 0.0])
        else:
            guess = _unit(shear_axis, "shear_axis")
        s = guess - (guess @ a) * a
        if np.linalg.norm(s) < 1e-6:
            raise ModelError(
                "lies along the compression axis; give a direction across it", "shear_axis"
            )
        s = s / np.linalg.norm(s)
        shears = (shear_n_m,) if is_real(shear_n_m) else tuple(shear_n_m)
        shears = shears * 2 if len(shears) == 1 else shears
        if len(shears) != 2:
            raise ModelError(f"must be one rate or two, got {shear_n_m!r}", "shear_n_m")
        return cls(
            name,
            position_m,
            (compression_n_m, *shears),
            (tuple(a), tuple(s), tuple(np.cross(a, s))),
            **damping,
        )

    @property
    def compression_axis(self) -> tuple:
        """The direction of the first rate (the compression axis of an oriented mount)."""
        return self.directions[0]

    def _in_engine_axes(self, values):
        d = np.array(self.directions)
        return d.T @ np.diag(values) @ d

    def stiffness(self) -> np.ndarray:
        """The 3×3 stiffness matrix in engine axes, Σ k_j·d_j·d_jᵀ, N/m."""
        return self._in_engine_axes(self.rates_n_m)

    def viscous(self) -> np.ndarray:
        """The 3×3 viscous damping matrix in engine axes, N·s/m."""
        return self._in_engine_axes(self.damping_ns_m)

    def transfer(self) -> np.ndarray:
        """The 3×6 matrix T that gives the mount's deflection u = T·q from the body's six
        coordinates q: u = X + θ × r = X − [r]×·θ."""
        x, y, z = self.position_m
        return np.array(
            [
                [1.0, 0.0, 0.0, 0.0, z, -y],
                [0.0, 1.0, 0.0, -z, 0.0, x],
                [0.0, 0.0, 1.0, y, -x, 0.0],
            ]
        )

    def replace(self, **changes) -> "Mount":
        """A copy with ``changes`` (field names, SI values), checked like a new mount."""
        return dataclasses.replace(self, **changes)


@dataclass(frozen=True)
class MountSystem:
    """The powertrain as a rigid body on its mounts.

    Parameters
    ----------
    mass_kg : float
        the whole powertrain's mass, kg
    inertia_kgm2 : tuple of tuple of float
        the matrix J about the centre of gravity with H = J·ω (off-diagonal entries −∫xy dm,
        ...), engine axes, kg·m² (:func:`inertia_matrix` builds it from moments and products)
    mounts : tuple of Mount
    cg_m : tuple of float
        the centre of gravity from the point the shaking analysis takes its moments about (on
        the first crankshaft's axis, at z̄, the cylinders' mean axial position), engine axes, m
    rotation : str
        "clockwise" (the default) or "anticlockwise": how the crank turns seen from the front

    Raises
    ------
    ModelError
        a mass that is not positive; an inertia tensor that is not symmetric, not positive
        definite or whose principal moments break the triangle inequality; no mounts, two of
        one name; mounts that leave a motion free (``mounts``: the message names the motion)
    """

    mass_kg: float
    inertia_kgm2: tuple
    mounts: tuple
    cg_m: tuple = (0.0, 0.0, 0.0)
    rotation: str = "clockwise"

    def __post_init__(self):
        set_ = object.__setattr__
        check_quantity(self.mass_kg, "mass", "mass_kg")
        set_(self, "mass_kg", float(self.mass_kg))
        set_(self, "cg_m", _vector(self.cg_m, "cg_m", "length"))
        if self.rotation not in ROTATIONS:
            raise ModelError(
                f"must be {' or '.join(map(repr, ROTATIONS))} (seen from the front), got "
                f"{self.rotation!r}",
                "rotation",
            )
        set_(self, "inertia_kgm2", _checked_inertia(self.inertia_kgm2))
        if isinstance(self.mounts, list):
            set_(self, "mounts", tuple(self.mounts))
        if not isinstance(self.mounts, tuple) or not self.mounts:
            raise ModelError("must be one or more mounts", "mounts")
        for mount in self.mounts:
            if not isinstance(mount, Mount):
                raise ModelError(f"must hold Mounts only, got {type(mount).__name__}", "mounts")
        names = [m.name for m in self.mounts]
        twice = sorted({n for n in names if names.count(n) > 1})
        if twice:
            raise ModelError(f"has two mounts named {twice[0]!r}; give each its own name", "mounts")
        self._check_held()

    @property
    def spin(self) -> int:
        """The crank's angular velocity along x: −1 turning clockwise seen from the front (its
        rotation vector points backwards), +1 anticlockwise."""
        return -1 if self.rotation == "clockwise" else 1

    @property
    def horizontal(self) -> np.ndarray:
        """Balance's *horizontal* (90° on from the vertical, with the crank's rotation) as a unit
        vector of engine axes: the turning that takes z there is about the crank's rotation
        vector spin·x, so it is −spin·y."""
        return np.array([0.0, -float(self.spin), 0.0])

    @property
    def names(self) -> tuple:
        return tuple(m.name for m in self.mounts)

    def mass_matrix(self) -> np.ndarray:
        """The 6×6 mass matrix: m on the translations, J on the rotations (kg, kg·m²)."""
        out = np.zeros((6, 6))
        out[:3, :3] = self.mass_kg * np.eye(3)
        out[3:, 3:] = np.array(self.inertia_kgm2)
        return out

    def _assembled(self, part):
        out = np.zeros((6, 6))
        for mount in self.mounts:
            t = mount.transfer()
            out += t.T @ part(mount) @ t
        return out

    def stiffness_matrix(self) -> np.ndarray:
        """The 6×6 stiffness matrix Σ Tᵢᵀ·Kᵢ·Tᵢ about the centre of gravity (N/m, N, N·m/rad)."""
        return self._assembled(Mount.stiffness)

    def loss_matrix(self) -> np.ndarray:
        """The hysteretic part Σ ηᵢ·Tᵢᵀ·Kᵢ·Tᵢ: the imaginary part of the complex stiffness."""
        return self._assembled(lambda m: m.loss_factor * m.stiffness())

    def damping_matrix(self) -> np.ndarray:
        """The 6×6 viscous damping matrix Σ Tᵢᵀ·Cᵢ·Tᵢ."""
        return self._assembled(Mount.viscous)

    def mount(self, name) -> Mount:
        """The mount called ``name``."""
        for mount in self.mounts:
            if mount.name == name:
                return mount
        raise ModelError(f"{name!r} is not one of the mounts ({', '.join(self.names)})", "name")

    def replace(self, **changes) -> "MountSystem":
        """A copy with ``changes`` (field names, SI values), checked like a new system, such as
        ``system.replace(mass_kg=1.1 * system.mass_kg)``.

        Raises
        ------
        ModelError
            a value the system cannot have (see the class)
        """
        return dataclasses.replace(self, **changes)

    def replace_mount(self, name, **changes) -> "MountSystem":
        """A copy with the mount called ``name`` changed (:meth:`Mount.replace`'s fields), the
        whole system checked again, such as
        ``system.replace_mount("A", rates_n_m=(2e5, 1.2e5, 2.5e5))``.

        Raises
        ------
        ModelError
            no mount of that name (``name``), or a value the system cannot have
        """
        self.mount(name)
        mounts = tuple(m.replace(**changes) if m.name == name else m for m in self.mounts)
        return self.replace(mounts=mounts)

    def _check_held(self):
        """Every motion meets a stiffness: the generalised eigenvalues k/m of the softest motion
        against the stiffest's."""
        stiffness, mass = self.stiffness_matrix(), self.mass_matrix()
        # M^(-1/2)·K·M^(-1/2): the mass-weighted stiffness, whose eigenvalues are ω²
        lower = np.linalg.cholesky(mass)
        inverse = np.linalg.inv(lower)
        values, vectors = np.linalg.eigh(inverse @ stiffness @ inverse.T)
        if values[0] > _FREE * values[-1]:
            return
        shape = inverse.T @ vectors[:, 0]
        energy = shape * (mass @ shape)
        free = int(np.argmax(np.abs(energy)))
        raise ModelError(
            f"leave the engine free to move: nothing resists a motion that is mostly "
            f"{motion_name(free)}; give a mount a rate across that motion (or place the mounts "
            "so that their rates hold it)",
            "mounts",
        )


def _checked_inertia(value):
    try:
        matrix = np.array(value, dtype=float)
    except (TypeError, ValueError):
        raise ModelError(
            f"must be a 3×3 matrix of numbers, kg·m², got {value!r}", "inertia_kgm2"
        ) from None
    if matrix.shape != (3, 3) or not np.all(np.isfinite(matrix)):
        raise ModelError(
            f"must be a 3×3 matrix of finite numbers, kg·m², got {value!r}", "inertia_kgm2"
        )
    if np.abs(matrix - matrix.T).max() > 1e-12 * np.abs(matrix).max():
        raise ModelError("must be symmetric (J_xy = J_yx, ...)", "inertia_kgm2")
    principal = np.linalg.eigvalsh(matrix)
    shown = ", ".join(f"{p:.4g}" for p in principal)
    if principal[0] <= 0.0:
        raise ModelError(
            f"is not positive definite: its principal moments are {shown} kg·m²; check the "
            "products of inertia and the sign they are given with",
            "inertia_kgm2",
        )
    if principal[2] > (principal[0] + principal[1]) * (1.0 + _TRIANGLE):
        raise ModelError(
            f"breaks the triangle inequality: its principal moments {shown} kg·m² have the "
            "largest above the sum of the other two, which no body can have; check the "
            "moments and products of inertia",
            "inertia_kgm2",
        )
    return tuple(tuple(float(v) + 0.0 for v in row) for row in matrix)
