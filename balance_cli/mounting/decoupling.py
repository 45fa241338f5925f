"""Design help: the mount rates that put the roll mode on the torque roll axis.

A couple about the crank axis turns the free engine about its torque roll axis (TRA), ê =
J⁻¹·x̂/|J⁻¹·x̂| through the centre of gravity (:mod:`.axes`). On its mounts the engine answers
the firing pulses with that one motion when the rotation about the TRA, q* = (0, ê), is a
natural mode: K·q* = λ·M·q*. As M·q* = (0, J·ê) is a couple about x, this says the mounts
answer a turn about the TRA with a couple about the crank axis alone: no force (three
conditions) and no moment about y or z (two) — Jeong and Singh's (2000, J. Sound Vib.
234(1):85–114) torque roll axis decoupling conditions. The TRA is then also the elastic axis
of the crank's torque (:func:`~.axes.elastic_axis`, their angle zero).

K = Σ k·Tᵀ·d·dᵀ·T is linear in each principal rate k (d its direction, T the mount's transfer
matrix), so the conditions are linear equations in the rates varied. Mass-weighted (L·Lᵀ = M,
v = Lᵀ·q*), they say that L⁻¹·K·q* is parallel to v; its part across v, over its size — the
sine of the angle between them, :attr:`TraState.coupling` — is what must vanish:

- where the rates varied can make it vanish and the bounds allow it, the least change does
  it in closed form: the minimum-norm solution of the linear conditions in the relative
  changes Δk/k (a pseudo-inverse);
- where that leaves the bounds, scipy.optimize's SLSQP finds the least change that meets the
  conditions within them;
- where no rates within the bounds (or no values of these rates at all) meet them, the rates
  whose TRA mode is purest (scipy's L-BFGS-B on the purity, from the rates as given and from
  the bounded least-squares solution of the linear conditions, ``lsq_linear``).

Harris' closed forms for mounts with planes of symmetry are special cases (the tests derive
one: a pair of inclined mounts focused on the roll axis).
"""

import math
from dataclasses import dataclass

import numpy as np

from ..checks import instance, is_real
from ..errors import AnalysisError
from ..model import Engine, MountSystem
from ..tabular import Tabular
from .axes import Axis, torque_roll_axis
from .purity import TraState, tra_rotation, tra_state

__all__ = [
    "decouple",
    "Decoupling",
    "VariedRate",
    "RATE_NAMES",
    "DEFAULT_SPREAD",
]

#: how a rate is named: along an engine axis, or a mount's compression or (both) shear rates
RATE_NAMES = ("x", "y", "z", "compression", "shear")
#: the default bounds of a rate varied: its value divided and multiplied by this
DEFAULT_SPREAD = 10.0
#: a coupling below this is decoupled to rounding (the exact solutions reach 1e-15)
EXACT = 1e-9
#: a rate's direction lies along an engine axis within this (the model's own tolerance for
#: perpendicular directions)
_ALONG = 1e-9
#: singular values of the conditions below this fraction of the largest are rounding: those
#: combinations of the rates do not change the coupling
_RANK = 1e-12
_AXES = {"x": 0, "y": 1, "z": 2}


@dataclass(frozen=True)
class VariedRate:
    """One rate varied: the same value for every mount of ``mounts``.

    Attributes
    ----------
    mounts : tuple of str
        the mounts that share it
    rate : str
        "x", "y", "z" (the rate along that engine axis), "compression" or "shear" (both
        shear rates of a mount given with compression and shear)
    slots : tuple of (str, int)
        the rates set: (mount, which of its three principal rates, 1 to 3) — one per mount,
        two for "shear"
    before_n_m : tuple of float
        each slot's rate before, N/m
    after_n_m : float
        the rate found, N/m
    low_n_m, high_n_m : float
        its bounds, N/m
    """

    mounts: tuple
    rate: str
    slots: tuple
    before_n_m: tuple
    after_n_m: float
    low_n_m: float
    high_n_m: float

    @property
    def label(self) -> str:
        """``A:z``, ``A+B:y``: how the command line names it."""
        return f"{'+'.join(self.mounts)}:{self.rate}"

    @property
    def at_bound(self) -> bool:
        """Whether the rate found sits on a bound (to 1e-9 of it)."""
        return bool(
            abs(self.after_n_m - self.low_n_m) <= 1e-9 * self.low_n_m
            or abs(self.after_n_m - self.high_n_m) <= 1e-9 * self.high_n_m
        )

    def to_dict(self) -> dict:
        return {
            "mounts": list(self.mounts),
            "rate": self.rate,
            "slots": [{"mount": m, "principal": j} for m, j in self.slots],
            "before_N_per_m": list(self.before_n_m),
            "after_N_per_m": self.after_n_m,
            "low_N_per_m": self.low_n_m,
            "high_N_per_m": self.high_n_m,
            "at_bound": self.at_bound,
        }


@dataclass(frozen=True)
class Decoupling(Tabular):
    """The rates that put the roll mode on the torque roll axis, and what they do.

    Attributes
    ----------
    name : str
        the engine's name ("" for a mount system given alone)
    system_before, system : MountSystem
        the mounts as given, and with the rates found (analyse it with
        ``balance.mounts(engine, system=result.system)``)
    rates : tuple of VariedRate
    torque_roll_axis : Axis
        J⁻¹·x̂ through the centre of gravity (the rates do not move it)
    before, after : TraState
    exact : bool
        whether the rates found decouple to rounding (``after.coupling`` below 1e-9)
    method : str
        "closed form" (the least change, by a pseudo-inverse), "SLSQP" (the least change
        within the bounds) or "purest" (no rates within the bounds decouple: those whose
        mode is purest, by scipy's L-BFGS-B)
    """

    name: str
    system_before: MountSystem
    system: MountSystem
    rates: tuple
    torque_roll_axis: Axis
    before: TraState
    after: TraState
    exact: bool
    method: str

    def to_dict(self) -> dict:
        """The ``decoupling`` object of ``mounts --decouple --format json`` (SI)."""
        return {
            "torque_roll_axis": self.torque_roll_axis.to_dict(),
            "method": self.method,
            "exact": self.exact,
            "rates": [r.to_dict() for r in self.rates],
            "before": self.before.to_dict(),
            "after": self.after.to_dict(),
        }

    def records(self) -> list:
        """One row per principal rate set: ``mount``, ``rate`` (as varied), ``principal``
        (which of the mount's three rates, 1 to 3), ``before_N_per_m``, ``after_N_per_m``, the
        bounds, and the purity and the TRA mode's frequency before and after (the same on
        every row)."""
        out = []
        for r in self.rates:
            for (mount, principal), before in zip(r.slots, r.before_n_m, strict=True):
                out.append(
                    {
                        "engine": self.name,
                        "mount": mount,
                        "rate": r.rate,
                        "principal": principal,
                        "before_N_per_m": float(before),
                        "after_N_per_m": r.after_n_m,
                        "low_N_per_m": r.low_n_m,
                        "high_N_per_m": r.high_n_m,
                        "purity_before_pct": self.before.purity_pct,
                        "purity_after_pct": self.after.purity_pct,
                        "frequency_before_Hz": self.before.frequency_hz,
                        "frequency_after_Hz": self.after.frequency_hz,
                        "exact": self.exact,
                    }
                )
        return out


def _rate_columns(system, q, lower):
    """L⁻¹·(Tᵀ·d·dᵀ·T·q*) of every principal rate: the change of L⁻¹·K·q* per N/m, by
    (mount, rate index)."""
    out = {}
    for mount in system.mounts:
        t = mount.transfer()
        for j, d in enumerate(np.array(mount.directions)):
            out[(mount.name, j)] = np.linalg.solve(lower, t.T @ d * float(d @ t @ q))
    return out


def _indices(mount, rate, where):
    """The indices into ``mount.rates_n_m`` that ``rate`` names."""
    directions = np.array(mount.directions)
    if rate in _AXES:
        axis = _AXES[rate]
        along = [j for j in range(3) if abs(abs(directions[j, axis]) - 1.0) <= _ALONG]
        if not along:
            shown = ", ".join(
                "(" + ", ".join(f"{v:.3g}" for v in d) + ")" for d in mount.directions
            )
            raise AnalysisError(
                f"{where}: mount {mount.name!r} has no rate along {rate} (its rates act along "
                f"{shown}); name its compression or shear rate",
                "vary",
            )
        return (along[0],)
    if np.allclose(directions, np.eye(3), rtol=0, atol=_ALONG):
        raise AnalysisError(
            f"{where}: mount {mount.name!r} gives its rates along x, y and z; vary 'x', 'y' or 'z'",
            "vary",
        )
    return (0,) if rate == "compression" else (1, 2)


def _items(system, vary) -> list:
    """((mount names, rate, ((name, index), ...)), ...) of ``vary``, checked."""
    if vary is None:
        vary = [
            (m.name, rate)
            for m in system.mounts
            for rate in (
                ("x", "y", "z")
                if np.allclose(np.array(m.directions), np.eye(3), rtol=0, atol=_ALONG)
                else ("compression", "shear")
            )
        ]
    if isinstance(vary, (str, bytes)) or not hasattr(vary, "__iter__"):
        raise AnalysisError(
            f"must be a list of (mount, rate) pairs such as [('A', 'z'), (('A', 'B'), 'y')], "
            f"got {vary!r}",
            "vary",
        )
    out: list = []
    seen: dict = {}  # (mount, index) -> the item varying it, as shown
    for item in vary:
        if isinstance(item, (str, bytes)) or not isinstance(item, (tuple, list)) or len(item) != 2:
            raise AnalysisError(
                f"holds {item!r}: give (mount, rate) pairs such as ('A', 'z'), or (('A', 'B'), "
                "'y') for one rate the mounts share",
                "vary",
            )
        names, rate = item
        names = (names,) if isinstance(names, str) else names
        if not isinstance(names, (tuple, list)) or not names:
            raise AnalysisError(f"holds {item!r}: name a mount or a tuple of mounts", "vary")
        # as the command line writes it: A:z, A+B:y
        shown = "+".join(map(str, names)) + f":{rate}"
        if rate not in RATE_NAMES:
            raise AnalysisError(
                f"holds {shown}: the rate must be one of {', '.join(RATE_NAMES)}", "vary"
            )
        pairs = []
        for name in names:
            if not isinstance(name, str) or name not in system.names:
                raise AnalysisError(
                    f"holds {shown}: {name!r} is not one of the mounts ({', '.join(system.names)})",
                    "vary",
                )
            for j in _indices(system.mount(name), rate, f"holds {shown}"):
                if (name, j) in seen:
                    raise AnalysisError(
                        f"varies the {rate} rate of mount {name!r} twice ({seen[(name, j)]} and "
                        f"{shown}); give each rate once",
                        "vary",
                    )
                seen[(name, j)] = shown
                pairs.append((name, j))
        out.append((tuple(names), rate, tuple(pairs)))
    if not out:
        raise AnalysisError("must name one rate or more to vary", "vary")
    return out


def _bounds(items, start, bounds_n_m):
    """(low, high) per item, N/m."""
    if bounds_n_m is None:
        return [(k / DEFAULT_SPREAD, k * DEFAULT_SPREAD) for k in start]
    if (
        isinstance(bounds_n_m, (str, bytes))
        or not hasattr(bounds_n_m, "__len__")
        or len(bounds_n_m) != 2
        or not all(is_real(b) and math.isfinite(b) for b in bounds_n_m)
        or not 0 < bounds_n_m[0] < bounds_n_m[1]
    ):
        raise AnalysisError(
            f"must be (low, high) in N/m with 0 < low < high, got {bounds_n_m!r}", "bounds_n_m"
        )
    return [(float(bounds_n_m[0]), float(bounds_n_m[1]))] * len(items)


def _stiffness_parts(system, items):
    """(K of the rates held, (K per N/m of each item's rate)): K = K₀ + Σ kᵢ·Kᵢ."""
    varied = {pair for _, _, pairs in items for pair in pairs}
    fixed = np.zeros((6, 6))
    parts = {}
    for mount in system.mounts:
        t = mount.transfer()
        for j, d in enumerate(np.array(mount.directions)):
            unit = t.T @ np.outer(d, d) @ t
            if (mount.name, j) in varied:
                parts[(mount.name, j)] = unit
            else:
                fixed += mount.rates_n_m[j] * unit
    per_item = np.array([sum(parts[p] for p in pairs) for _, _, pairs in items])
    return fixed, per_item


def _with_rates(system, items, values):
    rates = {m.name: list(m.rates_n_m) for m in system.mounts}
    for (_, _, pairs), value in zip(items, values, strict=True):
        for name, j in pairs:
            rates[name][j] = float(value)
    return system.replace(
        mounts=tuple(m.replace(rates_n_m=tuple(rates[m.name])) for m in system.mounts)
    )


def _purest(matrices, mass, q, start, low, high, guesses):
    """The rates (N/m) within [low, high] whose TRA mode is purest: scipy's L-BFGS-B on
    1 − purity over the logarithms of the rates, from each guess; the best."""
    from scipy.linalg import eigh
    from scipy.optimize import minimize

    fixed, per_item = matrices
    weight = mass @ q / math.sqrt(float(q @ mass @ q))

    def impurity(x):
        stiffness = fixed + np.tensordot(start * np.exp(x), per_item, axes=1)
        _, shapes = eigh(stiffness, mass)  # mass-normalised: φᵀ·M·φ = 1
        return 1.0 - float(np.max((weight @ shapes) ** 2))

    bounds = list(zip(np.log(low / start), np.log(high / start), strict=True))
    best = None
    for guess in guesses:
        x0 = np.clip(np.log(guess / start), [b[0] for b in bounds], [b[1] for b in bounds])
        found = minimize(impurity, x0, method="L-BFGS-B", bounds=bounds)
        for x in (x0, found.x):
            value = impurity(x)
            if best is None or value < best[0]:
                best = (value, x)
    assert best is not None
    return start * np.exp(best[1])


def _solve(b, c, low, high):
    """The relative changes z with b·z = c and the least |z|, within low ≤ z ≤ high: (z,
    method), or (None, None) when no z within the bounds meets the conditions."""
    from scipy.optimize import minimize  # scipy only for a design question

    u, s, vt = np.linalg.svd(b, full_matrices=False)
    keep = s > _RANK * s.max() if s.size and s.max() > 0 else np.zeros(len(s), dtype=bool)
    reduced = np.diag(s[keep]) @ vt[keep]  # the conditions the rates can change
    target = u[:, keep].T @ c
    if float(np.linalg.norm(c - u[:, keep] @ target)) > EXACT:
        return None, None  # a part of the coupling these rates cannot change
    z = vt[keep].T @ (target / s[keep])  # the minimum-norm solution: the least change
    inside = 1e-12  # rounding of the bounds' own relative values
    if np.all(z >= low - inside) and np.all(z <= high + inside):
        return np.clip(z, low, high), "closed form"
    found = minimize(
        lambda x: float(x @ x),
        np.clip(z, low, high),
        jac=lambda x: 2.0 * x,
        method="SLSQP",
        bounds=list(zip(low, high, strict=True)),
        constraints=[
            {"type": "eq", "fun": lambda x: reduced @ x - target, "jac": lambda x: reduced}
        ],
        options={"maxiter": 500, "ftol": 1e-14},
    )
    if found.success and np.linalg.norm(reduced @ found.x - target) <= EXACT:
        return np.clip(found.x, low, high), "SLSQP"
    return None, None


def decouple(engine_or_system, vary=None, bounds_n_m=None) -> Decoupling:
    """The mount rates that put the roll mode on the torque roll axis (Jeong and Singh's
    decoupling), the positions and directions of the mounts held.

    Parameters
    ----------
    engine_or_system : Engine or MountSystem
        an engine with a [mounts] table, or a mount system
    vary : list of (mount, rate), optional
        the rates to find: ``("A", "z")`` the rate of mount A along z; ``(("A", "B"), "y")``
        one rate along y that A and B share (a symmetric pair kept alike); the rate
        "x", "y" or "z" (the principal rate along that engine axis), or "compression" or
        "shear" (both shear rates, as one value) of a mount given with compression and
        shear. Default every rate of every mount, each its own. The five conditions need
        five rates or more in general; fewer give the nearest
    bounds_n_m : (float, float), optional
        the lowest and highest rate allowed, N/m; default each rate's own value divided and
        multiplied by 10 (:data:`DEFAULT_SPREAD`; of rates shared, their mean's)

    Returns
    -------
    Decoupling
        the rates found (the least change, Σ(Δk/k)² least, of those that decouple), the
        system with them, and the decoupling before and after

    Raises
    ------
    AnalysisError
        a mount or rate that is not there or is named twice (``vary``), bounds that are not
        0 < low < high (``bounds_n_m``), no [mounts] table (``engine_or_system``)
    """
    instance(engine_or_system, (Engine, MountSystem), "engine_or_system")
    if isinstance(engine_or_system, Engine):
        if engine_or_system.mounts is None:
            raise AnalysisError(
                "has no [mounts] table: give the powertrain's mass, centre of gravity, "
                "inertia and mounts",
                "engine_or_system",
            )
        system, name = engine_or_system.mounts, engine_or_system.name
    else:
        system, name = engine_or_system, ""
    items = _items(system, vary)
    start = np.array(
        [float(np.mean([system.mount(n).rates_n_m[j] for n, j in pairs])) for _, _, pairs in items]
    )
    limits = _bounds(items, start, bounds_n_m)
    q = tra_rotation(system)
    lower = np.linalg.cholesky(system.mass_matrix())
    v = lower.T @ q
    across = np.eye(6) - np.outer(v, v) / float(v @ v)
    columns = _rate_columns(system, q, lower)
    varied = {pair for _, _, pairs in items for pair in pairs}
    # L⁻¹·K·q* with the varied rates at their starts: the fixed rates' part plus theirs
    fixed = sum(
        (
            m.rates_n_m[j] * columns[(m.name, j)]
            for m in system.mounts
            for j in range(3)
            if (m.name, j) not in varied
        ),
        np.zeros(6),
    )
    per_item = np.array([sum(columns[p] for p in pairs) for _, _, pairs in items]).T
    now = fixed + per_item @ start
    scale = float(np.linalg.norm(now)) or 1.0
    # across v, in the relative changes z (k = k₀·(1 + z)): b·z = c
    b = across @ per_item @ np.diag(start) / scale
    c = -across @ now / scale
    low = np.array([lo / k - 1.0 for (lo, _), k in zip(limits, start, strict=True)])
    high = np.array([hi / k - 1.0 for (_, hi), k in zip(limits, start, strict=True)])
    z, method = _solve(b, c, low, high)
    if z is not None:
        found = start * (1.0 + z)
    else:
        # no rates within the bounds decouple: the purest, from the start and from the
        # least-squares rates of the linear conditions
        from scipy.optimize import lsq_linear

        nearest = start * (1.0 + lsq_linear(b, c, bounds=(low, high)).x)
        matrices = _stiffness_parts(system, items)
        lows = np.array([lo for lo, _ in limits])
        highs = np.array([hi for _, hi in limits])
        found = _purest(matrices, system.mass_matrix(), q, start, lows, highs, (start, nearest))
        method = "purest"
    after = _with_rates(system, items, found)
    state = tra_state(after)
    return Decoupling(
        name,
        system,
        after,
        tuple(
            VariedRate(
                names,
                rate,
                tuple((n, j + 1) for n, j in pairs),
                tuple(float(system.mount(n).rates_n_m[j]) for n, j in pairs),
                float(k),
                float(lo),
                float(hi),
            )
            for (names, rate, pairs), k, (lo, hi) in zip(items, found, limits, strict=True)
        ),
        torque_roll_axis(system),
        tra_state(system),
        state,
        state.coupling < EXACT,
        method,
    )
