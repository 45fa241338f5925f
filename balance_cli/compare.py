"""The comparison of engines: shaking, firing and the largest resultant of each."""

from dataclasses import dataclass

from .firing import Firing, firing
from .model import Engine
from .shaking import DEFAULT_MAX_ORDER, DEFAULT_SAMPLES, Shaking, shaking

__all__ = ["EngineResult", "analyse", "reference_index"]


@dataclass(frozen=True)
class EngineResult:
    """Everything ``balance compare`` reports for one engine.

    ``largest_force_n`` is the largest magnitude of the resultant force over a revolution,
    all orders; ``counterweighted_force_n`` the same once an ideal crankshaft counterweight
    has cancelled the forward first order (what Tanaka's Part III compares). A rotary's
    crank does not turn, so nothing is cancelled there.
    """

    engine: Engine
    shaking: Shaking
    firing: Firing
    largest_force_n: float
    counterweighted_force_n: float

    @property
    def per_cylinder_unit_n(self):
        """m_rec·r·ω²·n, N: divide a force by it to get Part III's per-cylinder figure."""
        return self.engine.unit_force_n * self.engine.n_cylinders

    @property
    def counterweighted_per_cylinder(self):
        """The largest counterweighted resultant in Part III's per-cylinder units."""
        return self.counterweighted_force_n / self.per_cylinder_unit_n

    def percent_of(self, reference):
        """That as a percentage of ``reference``'s (None when the reference has none)."""
        base = reference.counterweighted_per_cylinder
        return 100.0 * self.counterweighted_per_cylinder / base if base else None


def analyse(engine, samples=DEFAULT_SAMPLES, max_order=DEFAULT_MAX_ORDER):
    """Shaking forces and moments, firing and largest resultant of ``engine``."""
    result = shaking(engine, samples, max_order)
    return EngineResult(
        engine=engine,
        shaking=result,
        firing=firing(engine),
        largest_force_n=result.largest_force(),
        counterweighted_force_n=result.largest_force(skip_forward_first=engine.frame == "fixed"),
    )


def reference_index(results, name):
    """Index of the reference engine: by name (exact, else unique case-insensitive prefix)."""
    if name is None:
        return 0
    names = [r.engine.name for r in results]
    if name in names:
        return names.index(name)
    matches = [i for i, n in enumerate(names) if n.lower().startswith(name.lower())]
    if len(matches) == 1:
        return matches[0]
    listed = "; ".join(names)
    problem = "matches several engines" if matches else "matches no engine"
    raise ValueError(f"--reference {name!r} {problem}; choose one of: {listed}")
