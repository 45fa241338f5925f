"""Golden regression tables: `balance compare` of the whole library, JSON at full precision.

python tools/regress.py            compare with tests/golden/compare.json; list what moved
python tools/regress.py --update   rewrite it and show what changed (never in CI)
"""

import json
import math
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
GOLDEN = ROOT / "tests" / "golden" / "compare.json"
SAMPLES, MAX_ORDER = 256, 12
#: forces and moments may move by this fraction of the engine's m_rec·r·ω²·n (N, or N·m)
RELATIVE = 1e-9
#: phases are compared only where the phasor exceeds this fraction of m_rec·r·ω²·n
PHASE_FLOOR = 1e-6
PHASE_DEG = 1e-6
#: firing angles come from a TDC search good to about 2e-6°
FIRING_DEG = 1e-4


def current():
    """The comparison document of every configuration in configs/, as balance writes it."""
    sys.path.insert(0, str(ROOT))
    import balance_cli as balance

    engines = balance.load_many([ROOT / "configs"])
    document = balance.compare([balance.analyse(e, SAMPLES, MAX_ORDER) for e in engines]).to_dict()
    for engine in document["engines"]:
        engine["config"] = str(Path(engine["config"]).relative_to(ROOT))
    return document


def differences(old, new):
    """Human-readable lines: which engine, order and quantity moved, and by how much."""
    out = []
    old_engines = {e["name"]: e for e in old["engines"]}
    new_engines = {e["name"]: e for e in new["engines"]}
    for name in sorted(set(old_engines) ^ set(new_engines)):
        out.append(f"{name}: {'added' if name in new_engines else 'removed'}")
    for name in [n for n in new_engines if n in old_engines]:
        a, b = old_engines[name], new_engines[name]
        scale = b["unit_force_N"] * b["cylinders"]
        out += _walk(name, a, b, scale)
    return out


def _walk(path, a, b, scale):
    if isinstance(a, dict) and isinstance(b, dict):
        lines = []
        for key in sorted(set(a) | set(b)):
            if key not in a or key not in b:
                lines.append(f"{path}.{key}: {'added' if key in b else 'removed'}")
            elif key == "orders":
                for x, y in zip(a[key], b[key]):
                    lines += _walk(f"{path} order {y['order']}", x, y, scale)
                if len(a[key]) != len(b[key]):
                    lines.append(f"{path}: {len(a[key])} orders, now {len(b[key])}")
            else:
                lines += _walk(f"{path}.{key}", a[key], b[key], scale)
        if path.endswith(("force", "moment")):
            lines = _drop_noisy_phases(path, a, b, scale, lines)
        return lines
    if isinstance(a, list) and isinstance(b, list):
        if len(a) != len(b):
            return [f"{path}: {a} -> {b}"]
        return [line for i, (x, y) in enumerate(zip(a, b)) for line in _walk(f"{path}[{i}]", x, y, scale)]
    if isinstance(a, float) or isinstance(b, float):
        if a is None or b is None:
            return [] if a == b else [f"{path}: {a} -> {b}"]
        if ".firing." in path:
            tolerance = FIRING_DEG
        else:
            tolerance = PHASE_DEG if path.endswith("_deg") else RELATIVE * scale
        # angles compare round their period: an ellipse's axis is defined modulo 180°
        period = 180.0 if path.endswith("axis_deg") else 360.0
        if path.endswith("_deg") and abs((b - a + period / 2) % period - period / 2) <= tolerance:
            return []
        if abs(b - a) > tolerance:
            return [f"{path}: {a!r} -> {b!r} ({b - a:+.3g})"]
        return []
    return [] if a == b else [f"{path}: {a!r} -> {b!r}"]


def _drop_noisy_phases(path, a, b, scale, lines):
    """A phase is noise where its phasor is tiny: keep only meaningful phase changes."""
    keep = []
    for line in lines:
        for part in ("forward", "backward"):
            if f".{part}_deg" in line:
                unit = "N" if path.endswith("force") else "Nm"
                magnitude = max(a.get(f"{part}_{unit}", 0.0), b.get(f"{part}_{unit}", 0.0))
                if magnitude < PHASE_FLOOR * scale:
                    break
        else:
            keep.append(line)
    return keep


def main(argv):
    new = current()
    text = json.dumps(new, indent=1, ensure_ascii=False) + "\n"
    old = json.loads(GOLDEN.read_text(encoding="utf-8")) if GOLDEN.exists() else {"engines": []}
    moved = differences(old, new)
    if "--update" in argv:
        GOLDEN.parent.mkdir(parents=True, exist_ok=True)
        GOLDEN.write_text(text, encoding="utf-8")
        print("\n".join(moved) if moved else "no change beyond the tolerances")
        print(f"wrote {GOLDEN.relative_to(ROOT)}")
        return 0
    print("\n".join(moved) if moved else "golden tables match")
    return 1 if moved else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
