"""`make schemas`: write the JSON Schema of every document balance writes,
balance_cli/schemas/DOCUMENT.vN.json (Draft 2020-12), from the definitions below.

Usage: python tools/json_schemas.py [--check]   (--check: fail if a file would change)

The parts several documents share (an order's force and moment, a firing, a torque series, the
power related unbalance) are defined once here and copied into each schema's ``$defs``, so that
every file stands alone: a reader needs no other file to use one. The files are committed and
installed with the package; a test checks that they are what this script writes.

A schema of the version balance writes is closed (``additionalProperties: false``): a key
added, dropped or renamed fails it, so a change of the documents' keys cannot pass unnoticed,
and makes a new version with a schema of its own. The schemas of the compare document's
versions 1 and 2 are the keys ``balance regress`` reads of a baseline of that version: open to
the other keys those versions held (releases of one version added keys to it).
"""

import json
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from balance_cli.output import DOCUMENT_VERSION, STEADINESS_VERSION  # noqa: E402
from balance_cli.schemas import schema_name  # noqa: E402

TARGET = ROOT / "balance_cli" / "schemas"
DRAFT = "https://json-schema.org/draft/2020-12/schema"

# --- building blocks -----------------------------------------------------------------------------


def _typed(kind, description, null=False, **rules):
    schema = {"type": [kind, "null"] if null else kind, "description": description}
    schema.update({k: v for k, v in rules.items() if v is not None})
    return schema


def number(
    description, *, minimum=None, above=None, below=None, maximum=None, null=False, multiple=None
):
    """A number: ``above``/``below`` are exclusive bounds, ``minimum``/``maximum`` inclusive."""
    return _typed(
        "number",
        description,
        null,
        minimum=minimum,
        exclusiveMinimum=above,
        exclusiveMaximum=below,
        maximum=maximum,
        multipleOf=multiple,
    )


def size(description, null=False):
    """A magnitude: a number from 0."""
    return number(description, minimum=0, null=null)


def positive(description, null=False):
    return number(description, above=0, null=null)


def degrees(description, period=360, null=False):
    """An angle as balance wraps it: in [0, period) degrees."""
    return number(description, minimum=0, below=period, null=null)


def integer(description, minimum=None, maximum=None, null=False):
    return _typed("integer", description, null, minimum=minimum, maximum=maximum)


def text(description, enum=None, pattern=None, null=False):
    schema = _typed("string", description, null, pattern=pattern)
    if enum is not None:
        schema["enum"] = list(enum) + ([None] if null else [])
    return schema


def flag(description):
    return {"type": "boolean", "description": description}


def array(items, description, min_items=None, max_items=None, null=False):
    schema = _typed("array", description, null, minItems=min_items, maxItems=max_items)
    schema["items"] = items
    return schema


def ref(name, description=None, null=False):
    """A reference to ``#/$defs/NAME``, or null when ``null``."""
    target = {"$ref": f"#/$defs/{name}"}
    if not null:
        return {**target, "description": description} if description else target
    schema = {"anyOf": [target, {"type": "null"}]}
    if description:
        schema["description"] = description
    return schema


def closed(description, required, optional=None, null=False):
    """An object with exactly these keys: every key of ``required``, any of ``optional``,
    nothing else."""
    schema = {
        "type": ["object", "null"] if null else "object",
        "description": description,
        "properties": {**required, **(optional or {})},
        "required": list(required),
        "additionalProperties": False,
    }
    return schema


def document(name, version, description, required, optional=None):
    """A whole schema: the document's own keys, its ``balance_version`` fixed."""
    body = closed(description, {"balance_version": VERSION(version), **required}, optional)
    return {"$schema": DRAFT, "title": f"balance {name} document, version {version}", **body}


def _refs(node):
    """The names of the ``$defs`` that ``node`` refers to."""
    if isinstance(node, dict):
        found = {node["$ref"].removeprefix("#/$defs/")} if "$ref" in node else set()
        return found.union(*(_refs(v) for v in node.values()))
    if isinstance(node, list):
        return set().union(*(_refs(v) for v in node))
    return set()


def with_defs(schema):
    """``schema`` with the shared parts it uses, and those they use, in its ``$defs``: each
    file stands alone."""
    wanted, todo = set(), _refs(schema)
    while todo:
        name = todo.pop()
        wanted.add(name)
        todo |= _refs(DEFS[name]) - wanted
    if wanted:
        schema["$defs"] = {name: DEFS[name] for name in sorted(wanted)}
    return schema


def VERSION(version):  # noqa: N802  (reads as the constant it makes)
    return {"const": version, "description": f"format version of this document: {version}"}


SETTINGS = {
    "samples": integer(
        "crank angles a revolution of the Fourier analysis (from 4·max_order + 1 to 65536)",
        minimum=5,
        maximum=65536,
    ),
    # 65536 samples resolve orders up to 16383
    "max_order": integer("highest order analysed", minimum=1, maximum=16383),
}
ENGINE_NAME = text("the engine's name, as its configuration gives it")
CONFIG = text("its configuration file, as given (empty for an engine built in code)")
CYCLE = {"enum": [2, 4], "description": "strokes a working cycle: 2 or 4"}
SPEED = positive("crank speed (a rotary's crankcase speed), rev/min")
UNIT_FORCE = positive(
    "m_rec·r·ω² with the mean reciprocating mass per cylinder, N: divide a force by it and by "
    "the number of cylinders for Tanaka's per-cylinder figure"
)
FRAME = text(
    '"fixed", or "rotary" (the crank stands still and the crankcase turns)',
    enum=("fixed", "rotary"),
)
HALF = 0.5  # four-stroke torques repeat every 720°: their orders are multiples of ½
#: an order of a torque or of the torsional excitation
ORDER = number("k, a multiple of ½ for a four-stroke", above=0, multiple=HALF)


def _part(unit, components=True):
    """An order's force (N) or free moment (N·m): forward and backward phasors, the ellipse
    they trace, and (``components``) its vertical and horizontal components."""
    what = {"N": "N", "Nm": "N·m"}[unit]
    properties = {
        f"forward_{unit}": size(f"|X⁺|, the forward component (turns with the crank), {what}"),
        "forward_deg": degrees(
            "direction of the forward component at θ = 0, degrees from the reference axis, "
            "positive with rotation (0 when it is zero)"
        ),
        f"backward_{unit}": size(f"|X⁻|, the backward component (turns against it), {what}"),
        "backward_deg": degrees("direction of the backward component at θ = 0, degrees"),
        f"max_{unit}": size(f"the ellipse's semi-major axis |X⁺| + |X⁻|, {what}"),
        f"min_{unit}": size(f"its semi-minor axis ||X⁺| − |X⁻||, {what}"),
        "axis_deg": degrees(
            "direction of the major axis, degrees in [0, 180); null for a circle (one of the "
            "components is zero) or nothing",
            period=180,
            null=True,
        ),
    }
    if components:
        pitching = " (pitching: the moment of the vertical forces)" if unit == "Nm" else ""
        properties.update(
            {
                f"vertical_{unit}": size(
                    f"amplitude of the component along the engine's vertical{pitching}, {what}"
                ),
                "vertical_deg": degrees(
                    "its phase: the component is amplitude·cos(kθ − phase), degrees"
                ),
                f"horizontal_{unit}": size(
                    "amplitude of the horizontal component (90° on from the vertical with "
                    f"rotation{'; yawing' if unit == 'Nm' else ''}), {what}"
                ),
                "horizontal_deg": degrees("its phase, degrees"),
            }
        )
    kind = "force" if unit == "N" else "free moment"
    return closed(
        f"the order's {kind}: X(θ) = X⁺·e^(ikθ) + X⁻·e^(−ikθ), exact zeros below the noise floor",
        properties,
    )


def _series(unit):
    """A quantity over the cycle as a Fourier series (Series.to_dict)."""
    what = {"N": "N", "Nm": "N·m"}[unit]
    term = closed(
        "one order k: c·cos kθ + s·sin kθ = amplitude·cos(kθ − phase)",
        {
            "order": number(
                "k, a multiple of ½ for a four-stroke (its period is 720°)",
                above=0,
                multiple=HALF,
            ),
            f"cos_{unit}": number(f"c, {what}"),
            f"sin_{unit}": number(f"s, {what}"),
            f"amplitude_{unit}": size(f"√(c² + s²), {what}"),
            "phase_deg": degrees("the phase, degrees of kθ"),
        },
    )
    return closed(
        f"X(θ) = mean + Σ_k (c_k·cos kθ + s_k·sin kθ), θ the crank angle of throw 1, {what}; "
        "terms below the noise floor are exact zeros",
        {
            f"mean_{unit}": number(f"the mean, {what}"),
            f"max_{unit}": number(f"the largest value over the cycle, {what}"),
            f"min_{unit}": number(f"the smallest, {what}"),
            f"range_{unit}": size(f"max − min, {what}"),
            "orders": array(term, "every order up to max_order, in steps of ½ or 1"),
        },
    )


def _pru_entry():
    classes = ("not relevant", "unlikely", "likely", "most likely")
    return closed(
        "one order's moments and their power related unbalance",
        {
            "order": integer("k", minimum=1),
            "vertical_Nm": size("M_kV, amplitude of the pitching moment, N·m"),
            "horizontal_Nm": size("M_kH, amplitude of the yawing moment, N·m"),
            "vertical_Nm_per_kW": size("its PRU: M_kV / power, N·m/kW"),
            "horizontal_Nm_per_kW": size("M_kH / power, N·m/kW"),
            "vertical_class": text("the class of the vertical PRU", enum=classes),
            "horizontal_class": text("the class of the horizontal PRU", enum=classes),
        },
    )


def _shaft_mass():
    return closed(
        "one unbalance on a balancer shaft",
        {
            "mass_eccentricity_kgm": size("m·e, kg·m"),
            "phase_deg": degrees(
                "its direction from the reference axis at crank angle 0, positive with the "
                "crank's rotation, degrees"
            ),
            "z_m": number("axial position, m"),
        },
    )


DEFS = {
    "force": _part("N"),
    "moment": _part("Nm"),
    "pin_force": closed(
        "the order's force on the pin or bearing: forward and backward phasors and their "
        "ellipse (the steady part, order 0, as its forward phasor)",
        _part("N", components=False)["properties"],
    ),
    "order": closed(
        "one order k of the shaking: F_k(θ) = F⁺·e^(ikθ) + F⁻·e^(−ikθ), θ the crank angle",
        {
            "order": integer("k, from 1", minimum=1),
            "force": ref("force"),
            "moment": ref("moment"),
        },
    ),
    "orders": array(
        {"$ref": "#/$defs/order"},
        "every order 1..max_order, zero orders included",
        min_items=1,
    ),
    "stage": closed(
        "the shaking at one stage of balancing",
        {
            "largest_resultant_N": size(
                "largest magnitude of the resultant force over a revolution, all orders, N"
            ),
            "orders": ref("orders"),
        },
    ),
    "firing": closed(
        "the firing sequence over one working cycle",
        {
            "order": array(integer("a cylinder's number", minimum=1), "cylinders in firing order"),
            "angles_deg": array(
                number("degrees of crank angle", minimum=0),
                "firing angles in firing order, the first at 0, within the cycle (720° or 360°)",
            ),
            "intervals_deg": array(
                size("degrees"),
                "gaps between consecutive firings, the last wrapping round the cycle",
            ),
            "uniform": flag("every interval within 0.01° of cycle/cylinders"),
            "max_deviation_deg": size("largest deviation of an interval from the mean, degrees"),
            "given": flag(
                "the order came from the configuration (else balance chose the most uniform)"
            ),
        },
    ),
    "balance": closed(
        "the first-order balance the first-order moments are given under",
        {
            "name": text(
                '"standard" (the project guides\': the rotating masses and half the '
                'reciprocating ones), "rotating", "crank" (as the crank stands) or "factor"',
                enum=("standard", "rotating", "crank", "factor"),
            ),
            "balance_factor": number(
                "the fraction of the reciprocating masses the counterweights carry besides "
                "the rotating masses; null for the crank as it stands",
                minimum=0,
                maximum=1,
                null=True,
            ),
            "description": text("the balance in words"),
        },
    ),
    "pru_entry": _pru_entry(),
    "pru": closed(
        "the power related unbalance (MAN B&W and WinGD project guides): external moment / "
        "engine power at the same speed",
        {
            "power_kW": positive("the power it refers to, kW"),
            "power_source": text(
                '"given" (the configuration\'s power), "option" (given with the analysis) or '
                '"indicated" (from the [gas] table\'s imep)',
                enum=("given", "option", "indicated"),
            ),
            "classes": array(
                closed(
                    "a class and its upper bound",
                    {
                        "below_Nm_per_kW": positive(
                            "the class's upper bound, N·m/kW (null: none, the last)", null=True
                        ),
                        "class": text(
                            "the class",
                            enum=("not relevant", "unlikely", "likely", "most likely"),
                        ),
                    },
                ),
                "the four classes, lowest first",
                min_items=4,
                max_items=4,
            ),
            "orders": array(
                {"$ref": "#/$defs/pru_entry"},
                "each order judged: order 1 under first_order_balance, the others as the "
                "crank stands",
                min_items=1,
            ),
            "first_order_balance": ref("balance"),
            "first_order": closed(
                "the first order under each named balance; null when order 1 is not judged",
                {
                    "standard": ref(
                        "pru_entry",
                        "under the standard balance (null where counterweights are not "
                        "proposed: a rotary, several crankshafts)",
                        null=True,
                    ),
                    "rotating": ref(
                        "pru_entry", "under the rotating masses' balance (null alike)", null=True
                    ),
                    "crank": ref("pru_entry", "as the crank stands"),
                },
                null=True,
            ),
        },
    ),
    "series_Nm": _series("Nm"),
    "series_N": _series("N"),
    "pin_orders": array(
        closed(
            "one order of the force",
            {
                "order": number("k, from 0 (the steady part)", minimum=0, multiple=HALF),
                "force": ref("pin_force"),
            },
        ),
        "orders 0..max_order (halves too for a four-stroke with gas)",
        min_items=1,
    ),
    "crank_pin": closed(
        "the force of the rods on one crank pin over the cycle, in the fixed frame",
        {
            "throw": integer("the throw's number", 1),
            "orders": ref("pin_orders"),
            "radial": ref("series_N", "the force outwards along the throw, N"),
            "tangential": ref(
                "series_N", "the force across the throw, positive with its crankshaft's turning, N"
            ),
        },
    ),
    "main_bearings": closed(
        "a crankshaft's force on its main bearings together over the cycle, in the fixed frame",
        {
            "throw": {"type": "null", "description": "null: no one throw"},
            "orders": ref("pin_orders"),
        },
    ),
    "shaft_mass": _shaft_mass(),
    "rolling_moment": closed(
        "a moment about the crank axis of one order, positive with rotation: "
        "M(θ) = cos·cos kθ + sin·sin kθ = amplitude·cos(kθ − phase)",
        {
            "order": integer("k", minimum=1),
            "cos_Nm": number("N·m"),
            "sin_Nm": number("N·m"),
            "amplitude_Nm": size("N·m"),
            "phase_deg": degrees("degrees"),
        },
    ),
    "balancer_shaft": closed(
        "a balancer shaft: one shaft turning at speed_ratio × crank speed, with its masses",
        {
            "speed_ratio": integer("+k with the crank, −k against it"),
            "order": integer("k = |speed_ratio|", minimum=1),
            "turning": text('"with" or "against" the crank', enum=("with", "against")),
            "offset_m": closed(
                "its axis from the crank axis, m",
                {
                    "lateral": number("along the engine's horizontal, m"),
                    "vertical": number("along the engine's vertical, m"),
                },
            ),
            "masses": array({"$ref": "#/$defs/shaft_mass"}, "its unbalances"),
            "force_N": size("the size of the rotating force of all its masses together, N"),
            "rolling_moment": ref(
                "rolling_moment", "the moment that force makes about the crank axis"
            ),
        },
    ),
}

# --- the documents -------------------------------------------------------------------------------


def compare():
    engine = closed(
        "one engine compared (EngineResult.to_dict)",
        {
            "name": ENGINE_NAME,
            "config": CONFIG,
            "source": text("where its data come from (empty when not given)"),
            "cylinders": integer("number of cylinders", minimum=1),
            "cycle": CYCLE,
            "frame": FRAME,
            "speed_rpm": SPEED,
            "unit_force_N": UNIT_FORCE,
            "firing": ref("firing"),
            "largest_resultant_N": size(
                "largest magnitude of the resultant force over a revolution, all orders, N"
            ),
            "counterweighted_resultant_N": size(
                "the same after an ideal crankshaft counterweight (none on a rotary), N"
            ),
            "counterweighted_resultant_per_cylinder": size(
                "that over unit_force_N·cylinders (Tanaka's Part III figure)"
            ),
            "percent_of_reference": size(
                "counterweighted_resultant_per_cylinder as a percentage of the reference "
                "engine's, %; null when the reference has none",
                null=True,
            ),
            "percent_of_reference_absolute": size(
                "counterweighted_resultant_N as a percentage of the reference engine's, %; null "
                "alike",
                null=True,
            ),
            "vertical_deg": degrees("the engine's vertical, degrees from the reference axis"),
            "noise_floor_N": size("forces below this are written as exact zeros, N"),
            "noise_floor_Nm": size("moments below this are written as exact zeros, N·m"),
            "largest_moment_Nm": size(
                "largest magnitude of the free moment over a revolution, N·m"
            ),
            "counterweighted_moment_Nm": size(
                "the same after an ideal two-plane counterweight, N·m"
            ),
            "main_force_order": main_order("N"),
            "main_moment_order": main_order("Nm"),
            "power_kW": positive("the power at the speed analysed, kW (null without one)", True),
            "pru": ref("pru", "the power related unbalance; null without a power", null=True),
            "pru_note": text("why there is no PRU; null when there is one", null=True),
            "sampling_ok": flag("false when the samples were too few for the highest orders"),
            "orders": ref("orders"),
        },
    )
    return document(
        "compare",
        DOCUMENT_VERSION,
        "balance compare --format json: engines compared order by order (Comparison.to_dict); "
        "balance regress reads it as a baseline. SI units throughout, angles in degrees.",
        {
            **SETTINGS,
            "reference": text("name of the engine the percentages refer to"),
            "engines": array(engine, "one per engine, in the order compared", min_items=1),
        },
        {
            "speed_override_rpm": positive(
                "with --speed: the speed that replaced the files' speeds, rev/min"
            )
        },
    )


def main_order(unit):
    what = {"N": "N", "Nm": "N·m"}[unit]
    names = ("vertical", "horizontal") if unit == "N" else ("pitching", "yawing")
    part = "force" if unit == "N" else "moment"
    return closed(
        f"the order with the largest {part} ellipse after the ideal counterweight; null when "
        "nothing is left",
        {
            "order": integer("k", minimum=1),
            f"max_{unit}": size(f"its ellipse's semi-major axis, {what}"),
            "axis_deg": degrees(
                "its major axis, degrees in [0, 180); null for a circle", period=180, null=True
            ),
            "direction": text(
                f'in words: "rotating forward", "nearly rotating backward", "{names[0]}", '
                f'"{names[1]}" or "+30° from {names[0]}"',
                pattern=(
                    f"^((nearly )?rotating (forward|backward)|{names[0]}|{names[1]}"
                    f"|[+-][0-9]+° from {names[0]})$"
                ),
            ),
        },
        null=True,
    )


def compare_reader(version):
    """What balance regress reads of a compare document of an earlier ``version``: those keys,
    typed; the document may hold more (releases of one version added keys)."""
    part_keys = [
        "forward_{u}",
        "forward_deg",
        "backward_{u}",
        "backward_deg",
        "max_{u}",
        "min_{u}",
        "axis_deg",
    ]
    if version >= 2:
        part_keys += ["vertical_{u}", "vertical_deg", "horizontal_{u}", "horizontal_deg"]

    def part(unit):
        full = _part(unit)["properties"]
        keys = [k.format(u=unit) for k in part_keys]
        return {
            "type": "object",
            "description": f"the order's {'force' if unit == 'N' else 'free moment'}",
            "properties": {k: full[k] for k in keys},
            "required": keys,
        }

    engine_keys = {
        "name": ENGINE_NAME,
        "config": CONFIG,
        "cylinders": integer("number of cylinders", minimum=1),
        "cycle": CYCLE,
        "frame": FRAME,
        "speed_rpm": SPEED,
        "unit_force_N": UNIT_FORCE,
        "largest_resultant_N": size("largest resultant force over a revolution, N"),
        "counterweighted_resultant_N": size("the same after an ideal counterweight, N"),
        "sampling_ok": flag("false when the samples were too few"),
        "firing": {
            "type": "object",
            "description": "the firing sequence",
            "properties": {
                k: v
                for k, v in DEFS["firing"]["properties"].items()
                if k in ("order", "angles_deg", "uniform")
            },
            "required": ["order", "angles_deg", "uniform"],
        },
        "orders": array(
            {
                "type": "object",
                "description": "one order",
                "properties": {
                    "order": integer("k", minimum=1),
                    "force": part("N"),
                    "moment": part("Nm"),
                },
                "required": ["order", "force", "moment"],
            },
            "the orders",
        ),
    }
    if version >= 2:
        engine_keys.update(
            {
                "largest_moment_Nm": size("largest free moment over a revolution, N·m"),
                "counterweighted_moment_Nm": size("the same after an ideal counterweight, N·m"),
                "vertical_deg": degrees("the engine's vertical, degrees"),
            }
        )
    engine = {
        "type": "object",
        "description": "one engine",
        "properties": engine_keys,
        "required": list(engine_keys),
    }
    return {
        "$schema": DRAFT,
        "title": f"balance compare document, version {version} (what balance regress reads)",
        "description": (
            f"The keys balance regress reads of a baseline that balance compare wrote as version "
            f"{version}. Open: a document of this version may hold other keys."
        ),
        "type": "object",
        "properties": {
            "balance_version": VERSION(version),
            **SETTINGS,
            "reference": text("name of the engine the percentages refer to"),
            "speed_override_rpm": positive("the speed that replaced the files' speeds, rev/min"),
            "engines": array(engine, "one per engine", min_items=1),
        },
        "required": ["balance_version", "samples", "max_order", "engines"],
    }


def counterweight():
    weight = closed(
        "a counterweight proposed, in one correction plane",
        {
            "z_m": number("the plane's axial position, m"),
            "throw": integer("the throw it sits on (null: an axial position)", 1, null=True),
            "mass_kg": size("its mass, kg"),
            "radius_m": positive("radius of its centre of mass, m"),
            "angle_deg": degrees(
                "its direction, measured like a throw phase from throw 1, degrees"
            ),
        },
    )
    built = closed(
        "a counterweight as built (the configuration's [[counterweights]])",
        {
            "throw": integer("the throw whose pin it is measured from", 1),
            "mass_radius_kgm": size("its unbalance m·ρ, kg·m"),
            "mass_kg": size("its mass, kg (null when its radius is not given)", null=True),
            "radius_m": positive("radius of its centre of mass, m (null: not given)", True),
            "angle_deg": number("its direction from its throw's pin, degrees, as configured"),
            "z_m": number("its axial position, m"),
        },
    )
    shaft = closed(
        "one mass of a balancer shaft proposed",
        {
            "order": integer("the order it cancels", minimum=1),
            "speed_ratio": integer("+k with the crank, −k against it"),
            "mass_eccentricity_kgm": size("m·e, kg·m"),
            "phase_deg": degrees("its direction at crank angle 0, degrees"),
            "z_m": number("axial position, m"),
        },
    )
    engine = closed(
        "one engine balanced (Balance.to_dict)",
        {
            "name": ENGINE_NAME,
            "config": CONFIG,
            "cylinders": integer("number of cylinders", minimum=1),
            "frame": FRAME,
            "speed_rpm": SPEED,
            "unit_force_N": UNIT_FORCE,
            "balance_factor": number(
                "the balance factor asked for; null: the forward first order cancelled exactly",
                minimum=0,
                maximum=1,
                null=True,
            ),
            "counterweights": array(weight, "one per correction plane"),
            "antivibrateur": closed(
                "Fraeys de Veubeke's rotor, turning at twice crank speed (null unless asked for)",
                {
                    "mass_eccentricity_kgm": size("M·e, kg·m"),
                    "eccentricity_m": positive("e, m"),
                    "mass_kg": size("M, kg"),
                    "phase_deg": degrees("its direction at crank angle 0, degrees"),
                },
                null=True,
            ),
            "residual": ref("stage", "what the counterweights (and the rotor) leave"),
        },
        {
            "shafts": array(shaft, "with --shafts: one entry per balancer mass"),
            "after_shafts": ref("stage", "with --shafts: what the shafts leave besides"),
            "shaft_orders": array(integer("k", minimum=1), "with --shafts: the orders asked for"),
            "balancer_shafts": array(
                {"$ref": "#/$defs/balancer_shaft"}, "with --shafts: the shafts, one per speed ratio"
            ),
            "shaft_rolling_moments": array(
                closed(
                    "the rolling moment of one order's shafts together (a Lanchester pair's "
                    "couple; zero when they sit on the crank axis)",
                    {
                        **DEFS["rolling_moment"]["properties"],
                        "speed_ratios": array(
                            integer("a shaft's speed ratio"), "the shafts that make it", 1
                        ),
                    },
                ),
                "with --shafts: per order with shafts",
            ),
            "test_masses_kg": array(
                size("kg"),
                "with --test-masses: the balancing-machine mass for each crank pin, throw order",
            ),
            "as_built": closed(
                "for an engine with counterweights or balancer shafts as built: those, and what "
                "they leave (everything proposed is in addition to them)",
                {
                    "counterweights": array(built, "the counterweights as built"),
                    "balancer_shafts": array(
                        {"$ref": "#/$defs/balancer_shaft"}, "the balancer shafts as built"
                    ),
                    **DEFS["stage"]["properties"],
                },
            ),
        },
    )
    return document(
        "counterweight",
        DOCUMENT_VERSION,
        "balance counterweight --format json: the counterweights proposed and what they leave "
        "(Balances.to_dict). SI units, angles in degrees.",
        {**SETTINGS, "engines": array(engine, "one per engine", min_items=1)},
    )


def torque():
    steady = {
        **steadiness_keys(),
        "flywheel_for_target_kgm2": positive(
            "with --target: the flywheel inertia that reaches it, kg·m² (else null)", True
        ),
    }
    guide = closed(
        "the guide forces and the H-type and X-type guide-force moments (MAN B&W, WinGD)",
        {
            "lever_m": positive("L, the guide distance the bimoment is divided by: the rod, m"),
            "mean_z_m": number("z̄, the cylinders' mean axial position, m"),
            "h_type": ref("series_Nm", "Σ_j couple_j(θ), N·m"),
            "x_type": ref("series_Nm", "Σ_j couple_j(θ)·(z_j − z̄)/L, N·m"),
            "cylinders": array(
                closed(
                    "one cylinder's guide force and couple",
                    {
                        "cylinder": integer("its number", 1),
                        "z_m": number("its axial position, m"),
                        "max_force_N": size("largest guide force over the cycle, N"),
                        "max_couple_Nm": size("largest couple on the frame, N·m"),
                    },
                ),
                "in the engine's cylinder order",
            ),
        },
        null=True,
    )
    engine = closed(
        "one engine's torques at constant speed (TorqueResult.to_dict)",
        {
            "name": ENGINE_NAME,
            "config": CONFIG,
            "cycle": CYCLE,
            "speed_rpm": SPEED,
            "period_deg": {"enum": [360, 720], "description": "the torques' period, degrees"},
            "reduced_mass": closed(
                "μ(θ): the kinetic energy of the moving parts is ½·μ·ω²",
                {
                    "mean_kgm2": size("kg·m²"),
                    "min_kgm2": size("kg·m²"),
                    "max_kgm2": size("kg·m²"),
                },
            ),
            "inertia": ref(
                "series_Nm", "the inertia torque on the crankshaft, positive with rotation"
            ),
            "frame": ref("series_Nm", "the reaction on the frame about the crank axis"),
            "tilting": ref("series_Nm", "the rods' and pistons' tilting couple −dH/dt"),
            "gas": ref("series_Nm", "the gas torque; null without a pressure", null=True),
            "indicated_power_kW": number(
                "the mean gas torque × ω, kW (null without gas)", null=True
            ),
            "total": ref("series_Nm", "inertia and gas together"),
            "bearing": closed(
                "the forces on the crank pins and the main bearings",
                {
                    "crank_pins": array({"$ref": "#/$defs/crank_pin"}, "one per throw"),
                    "main_bearings": ref(
                        "main_bearings",
                        "the crankshaft's force on its main bearings together (null for a "
                        "rotary and several crankshafts)",
                        null=True,
                    ),
                },
            ),
            "steadiness": closed(
                "with --inertia or --target: the speed over the cycle (else null)",
                steady,
                null=True,
            ),
            "guide_force": guide,
            "crankshafts": array(
                closed(
                    "one crankshaft of several",
                    {
                        "crankshaft": integer("its number", 1),
                        "direction": {
                            "enum": [1, -1],
                            "description": "+1 turning with the first crankshaft, −1 against it",
                        },
                        "torque": ref(
                            "series_Nm", "the torque it passes on, positive in its own sense"
                        ),
                        "main_bearings": ref(
                            "main_bearings",
                            "its force on its main bearings (null: not asked for)",
                            True,
                        ),
                    },
                ),
                "each crankshaft's torque and bearings (empty with one)",
            ),
        },
    )
    return document(
        "torque",
        DOCUMENT_VERSION,
        "balance torque --format json: torques at constant speed, order by order "
        "(TorqueSet.to_dict). SI units; orders are multiples of ½ for a four-stroke.",
        {**SETTINGS, "engines": array(engine, "one per engine", min_items=1)},
    )


def steadiness_keys():
    return {
        "mean_speed_rpm": positive("mean speed, rev/min"),
        "min_speed_rpm": positive("lowest speed over the cycle, rev/min"),
        "max_speed_rpm": positive("highest speed, rev/min"),
        "steadiness": positive(
            "ω_m/(ω_max − ω_min), integrated (null: the speed does not vary)", True
        ),
        "r_c": positive("Margoulis's closed form, constant load (null beyond a double)", True),
        "r_v": number("Margoulis's closed form, no inertia (null beyond a double)", null=True),
        "r_h": size("Margoulis's closed form, propeller (null beyond a double)", True),
        "mean_torque_Nm": number("C_m, the driving torque's mean, N·m"),
        "torque_range_Nm": size("ΔC, its range, N·m"),
        "order": number("the order of its largest harmonic", minimum=0, multiple=HALF),
        "inertia_kgm2": positive("I, the flywheel (and propeller) inertia, kg·m²"),
        "reduced_mass_kgm2": size("the engine's mean reduced mass added to I, kg·m²"),
        "load": text('"propeller" or "constant"', enum=("propeller", "constant")),
    }


def steadiness():
    return document(
        "steadiness",
        STEADINESS_VERSION,
        "balance steadiness --format json: the speed of a flywheel driven by a measured "
        "torque curve. Speeds in rev/min, torques in N·m.",
        {
            "torque_file": text("the torque curve read"),
            "cycle_deg": {"enum": [360, 720], "description": "the curve's cycle, degrees"},
            **steadiness_keys(),
            "inertia_for_target_kgm2": positive(
                "with --target: the inertia that reaches it, kg·m² (else null)", True
            ),
        },
    )


def torsion():
    criticals = integer("mode number", 1)
    engine = closed(
        "one engine's torsional vibration (TorsionResult.to_dict)",
        {
            "name": ENGINE_NAME,
            "config": CONFIG,
            "cycle": CYCLE,
            "excitation": text(
                '"gas and inertia", or "inertia" without a gas torque',
                enum=("gas and inertia", "inertia"),
            ),
            "nodes": array(
                closed(
                    "an inertia of the shaft line",
                    {"node": text("its name"), "inertia_kgm2": positive("kg·m²")},
                ),
                "the shaft line's inertias, free end first",
                min_items=2,
            ),
            "sections": array(
                closed(
                    "the shaft between two nodes",
                    {
                        "section": text('"A–B", its nodes'),
                        "stiffness_Nm_per_rad": positive("N·m/rad"),
                    },
                ),
                "the sections between consecutive nodes",
                min_items=1,
            ),
            "modes": array(
                closed(
                    "one natural mode",
                    {
                        "mode": integer("its number, from 1", 1),
                        "frequency_Hz": positive("Hz"),
                        "frequency_cpm": positive("vibrations a minute (60 × Hz)"),
                        "shape": array(
                            closed(
                                "a node's relative amplitude",
                                {
                                    "node": text("the node"),
                                    "amplitude": number(
                                        "the largest +1; below 1e-9 of it exactly 0",
                                        minimum=-1,
                                        maximum=1,
                                    ),
                                },
                            ),
                            "per node",
                        ),
                        "throw_amplitudes": array(
                            number("relative amplitude", minimum=-1, maximum=1),
                            "at each throw's node, throw order",
                        ),
                        "phase_vector_sums": array(
                            closed(
                                "the mode's phase-vector sum at one order",
                                {
                                    "order": ORDER,
                                    "sum": size("|Σ β·e^(ikφ)|, 0 where it cancels"),
                                    "excited": flag("the sum is not zero"),
                                },
                            ),
                            "per order of the excitation",
                        ),
                    },
                ),
                "the natural modes, lowest first",
            ),
            "criticals": array(
                closed(
                    "a mode's resonance with an order",
                    {
                        "mode": criticals,
                        "order": ORDER,
                        "speed_rpm": positive("where k·n is the mode's frequency, rev/min"),
                        "phase_vector_sum": size("the mode's sum at that order"),
                        "major": flag("the order puts every cylinder in phase"),
                        "excited": flag("the cylinders excite it (its sum is not zero)"),
                    },
                ),
                "the criticals within the speeds, as chosen, by speed",
            ),
            "criticals_chosen": closed(
                "the choice of criticals",
                {
                    "kind": text('"excited", "major" or "all"', enum=("excited", "major", "all")),
                    "orders": array(ORDER, "the orders chosen (null: all)", null=True),
                    "modes": array(criticals, "the modes chosen (null: all)", null=True),
                },
            ),
            "peak": closed(
                "the sweep's largest vibratory torque, all sections and speeds",
                {
                    "section": text("where"),
                    "torque_Nm": size("N·m"),
                    "speed_rpm": positive("rev/min"),
                    "order": {**ORDER, "description": "the order of the largest amplitude there"},
                    "mode": integer(
                        "the mode whose critical of that order is within 10 % (null: none)",
                        1,
                        null=True,
                    ),
                    "critical_rpm": positive("that critical's speed, rev/min", null=True),
                    "major": flag("a major order"),
                },
            ),
            "largest": array(
                closed(
                    "a section's largest vibratory torque over the speeds",
                    {
                        "section": text("the section"),
                        "torque_Nm": size("N·m"),
                        "speed_rpm": positive("where, rev/min"),
                        "stress_Pa": size(
                            "as shear stress with the shaft diameter, Pa (null without one)",
                            null=True,
                        ),
                    },
                ),
                "per section",
            ),
            "response": array(
                closed(
                    "the forced response at one speed",
                    {
                        "speed_rpm": positive("rev/min"),
                        "criticals": array(
                            closed(
                                "a critical near this speed",
                                {"mode": criticals, "order": ORDER},
                            ),
                            "criticals within 10 % of this speed",
                        ),
                        "free_end_deg": size("the free end's angular amplitude, degrees"),
                        "free_end_elastic_deg": size(
                            "its elastic part (the rigid-body turning taken out), degrees",
                            null=True,
                        ),
                        "free_end_orders": array(
                            closed(
                                "one order at the free end",
                                {
                                    "order": ORDER,
                                    "amplitude_deg": size("degrees"),
                                    "elastic_deg": size("its elastic part, degrees", null=True),
                                },
                            ),
                            "per order",
                        ),
                        "sections": array(
                            closed(
                                "one section's vibratory torque",
                                {
                                    "section": text("the section"),
                                    "torque_Nm": size("the waveform's peak over the cycle, N·m"),
                                    "stress_Pa": size("as shear stress, Pa", null=True),
                                    "orders": array(
                                        closed(
                                            "one order",
                                            {"order": ORDER, "torque_Nm": size("N·m")},
                                        ),
                                        "per order",
                                    ),
                                },
                            ),
                            "per section",
                        ),
                    },
                ),
                "per speed",
                min_items=1,
            ),
        },
    )
    return document(
        "torsion",
        DOCUMENT_VERSION,
        "balance torsion --format json: the shaft line's modes, criticals and forced response "
        "(TorsionResult.to_dict per engine). SI units; orders are multiples of ½ for a "
        "four-stroke.",
        {
            "max_order": integer("highest order of the excitation", minimum=1),
            "engines": array(engine, "one per engine with a [torsion] table", min_items=1),
        },
    )


def mounts():
    coordinates = ("x", "y", "z", "rx", "ry", "rz")
    motions = ("fore-aft", "lateral", "bounce", "roll", "pitch", "yaw")
    mount_name = text("the mount's name")

    def vector(description, count=3, item=None):
        return array(
            item or number("engine axes: x, y, z"), description, min_items=count, max_items=count
        )

    axis = closed(
        "a line of engine axes",
        {
            "direction": vector(
                "its unit direction (x first positive)",
                item=number("a component, −1 to 1", minimum=-1, maximum=1),
            ),
            "through_m": vector("its point nearest the centre of gravity, from it, m"),
            "distance_m": size("how far it passes from the centre of gravity, m"),
        },
    )

    def load(kind):
        torque_nm = (
            {"type": "null", "description": "no torque: the weight"}
            if kind == "weight"
            else number("the mean torque whose reaction this is, N·m (positive driving)")
        )
        return closed(
            f"the mounts under the {kind}",
            {
                "load": text("which load", enum=(kind,)),
                "source": text("where the load comes from, in words"),
                "torque_Nm": torque_nm,
                "wrench": closed(
                    "the load at the centre of gravity",
                    {
                        **{k: number("N") for k in ("Fx_N", "Fy_N", "Fz_N")},
                        **{k: number("N·m") for k in ("Mx_Nm", "My_Nm", "Mz_Nm")},
                    },
                ),
                "centre_of_gravity": closed(
                    "its translation (m) and rotation (rad)",
                    {
                        **{k: number("m") for k in ("x_m", "y_m", "z_m")},
                        **{k: number("rad") for k in ("rx_rad", "ry_rad", "rz_rad")},
                    },
                ),
                "mounts": array(
                    closed(
                        "one mount under the load",
                        {
                            "mount": mount_name,
                            "deflection_m": vector("its deflection, engine axes, m"),
                            "local_deflection_m": vector(
                                "along its own directions (compression, shears), m"
                            ),
                            "force_N": vector("the force it passes on to the frame, N"),
                        },
                    ),
                    "per mount",
                    min_items=1,
                ),
            },
            null=kind == "torque",
        )

    peak = {
        key: size("m" if key.endswith("_m") else "rad")
        for key in ("x_m", "y_m", "z_m", "rx_rad", "ry_rad", "rz_rad")
    }
    state = closed(
        "how near the mounts are to torque roll axis decoupling (TraState.to_dict)",
        {
            "mode": integer("the mode nearest the turn about the torque roll axis", 1, 6),
            "frequency_Hz": size("its frequency, Hz"),
            "motion": text("its dominant motion", enum=motions),
            "purity_pct": number("its kinetic energy's share in that turn, %", minimum=0),
            "tra_energy_pct": number("its energy share in the TRA coordinate, %"),
            "axis_angle_deg": number(
                "its axis of rotation to the TRA, degrees", minimum=0, maximum=90
            ),
            "axis_offset_m": size("its screw axis from the centre of gravity, m"),
            "coupling": size("the sine the rates are found by: 0 decoupled"),
            "axes_angle_deg": number("the TRA to the elastic axis, degrees", minimum=0, maximum=90),
        },
    )
    decoupling = closed(
        "mounts --decouple: the rates found and the decoupling before and after "
        "(Decoupling.to_dict); the rest of the engine's object is of the mounts with them",
        {
            "torque_roll_axis": axis,
            "method": text("how the rates were found", enum=("closed form", "SLSQP", "purest")),
            "exact": flag("decoupled to rounding"),
            "rates": array(
                closed(
                    "one rate found (VariedRate.to_dict)",
                    {
                        "mounts": array(mount_name, "the mounts that share it", min_items=1),
                        "rate": text("which rate", enum=("x", "y", "z", "compression", "shear")),
                        "slots": array(
                            closed(
                                "one principal rate set",
                                {
                                    "mount": mount_name,
                                    "principal": integer("which of its three rates", 1, 3),
                                },
                            ),
                            "the principal rates it sets",
                            min_items=1,
                        ),
                        "before_N_per_m": array(
                            positive("N/m"), "each slot's rate before", min_items=1
                        ),
                        "after_N_per_m": positive("the rate found, N/m"),
                        "low_N_per_m": positive("its lower bound, N/m"),
                        "high_N_per_m": positive("its upper bound, N/m"),
                        "at_bound": flag("the rate found sits on a bound"),
                    },
                ),
                "the rates varied",
                min_items=1,
            ),
            "before": state,
            "after": state,
        },
    )
    engine = closed(
        "one engine on its mounts (MountResult.to_dict)",
        {
            "name": ENGINE_NAME,
            "config": CONFIG,
            "cycle": CYCLE,
            "speed_rpm": SPEED,
            "system": closed(
                "the mount system read",
                {
                    "mass_kg": positive("kg"),
                    "centre_of_gravity_m": vector(
                        "from the crank axis at the cylinders' mean axial position, m"
                    ),
                    "inertia_kgm2": array(
                        vector("a row, kg·m²"),
                        "the matrix J about the centre of gravity, H = J·ω",
                        min_items=3,
                        max_items=3,
                    ),
                    "rotation": text(
                        "how the crank turns seen from the front",
                        enum=("clockwise", "anticlockwise"),
                    ),
                    "mounts": array(
                        closed(
                            "one mount",
                            {
                                "mount": mount_name,
                                "position_m": vector("from the centre of gravity, m"),
                                "rates_N_per_m": vector(
                                    "the principal rates along its directions, N/m",
                                    item=positive("N/m"),
                                ),
                                "directions": array(
                                    vector(
                                        "a unit vector",
                                        item=number("a component, −1 to 1", minimum=-1, maximum=1),
                                    ),
                                    "the rates' directions (compression first, for an "
                                    "inclined mount)",
                                    min_items=3,
                                    max_items=3,
                                ),
                                "loss_factor": number("η", minimum=0, maximum=2),
                                "damping_Ns_per_m": vector(
                                    "viscous, along its directions, N·s/m", item=size("N·s/m")
                                ),
                            },
                        ),
                        "its mounts",
                        min_items=1,
                    ),
                },
            ),
            "modes": array(
                closed(
                    "one rigid-body mode",
                    {
                        "mode": integer("its number, from 1", 1, 6),
                        "frequency_Hz": size("Hz"),
                        "motion": text("its dominant motion", enum=motions),
                        "purity_pct": number("the dominant motion's share of its energy, %"),
                        "energy_pct": closed(
                            "the kinetic-energy distribution, % per coordinate",
                            {key: number("%") for key in coordinates},
                        ),
                        "shape": array(
                            number("mass-normalised: m/√kg, rad/(√kg·m)"),
                            "x, y, z, rx, ry, rz",
                            min_items=6,
                            max_items=6,
                        ),
                    },
                ),
                "the six modes, lowest first",
                min_items=6,
                max_items=6,
            ),
            "torque_roll_axis": axis,
            "elastic_axis": axis,
            "axes_angle_deg": number("the angle between them, degrees", minimum=0, maximum=90),
            "static": closed(
                "static deflections",
                {"weight": load("weight"), "torque": load("torque")},
            ),
            "with_gas": flag("the roll excitation has a gas torque"),
            "orders": array(ORDER, "the orders applied", min_items=1),
            "resonances": array(
                closed(
                    "a resonance crossed within the speeds",
                    {
                        "mode": integer("the mode", 1, 6),
                        "motion": text("its dominant motion", enum=motions),
                        "order": ORDER,
                        "speed_rpm": positive("where the order's frequency is the mode's, rev/min"),
                        "excited": flag("the order drives the mode there"),
                    },
                ),
                "by speed",
            ),
            "speeds": array(
                closed(
                    "the forced response at one speed",
                    {
                        "speed_rpm": positive("rev/min"),
                        "motion_peak": closed(
                            "the centre of gravity's largest motion, all orders over a cycle",
                            peak,
                        ),
                        "mounts": array(
                            closed(
                                "a mount's largest, all orders over a cycle",
                                {
                                    "mount": mount_name,
                                    "force_peak_N": vector(
                                        "each component's peak, N", item=size("N")
                                    ),
                                    "force_magnitude_peak_N": size("the vector's largest size, N"),
                                    "deflection_peak_m": vector(
                                        "each component's peak, m", item=size("m")
                                    ),
                                },
                            ),
                            "per mount",
                        ),
                        "orders": array(
                            closed(
                                "one order",
                                {
                                    "order": ORDER,
                                    "motion": array(
                                        size("m or rad"),
                                        "amplitudes x, y, z, rx, ry, rz",
                                        min_items=6,
                                        max_items=6,
                                    ),
                                    "motion_deg": array(
                                        degrees("amplitude·cos(kθ − phase)"),
                                        "their phases",
                                        min_items=6,
                                        max_items=6,
                                    ),
                                    "mounts": array(
                                        closed(
                                            "a mount's force on the frame",
                                            {
                                                "mount": mount_name,
                                                "force_N": vector(
                                                    "amplitudes Fx, Fy, Fz, N", item=size("N")
                                                ),
                                                "force_deg": vector(
                                                    "their phases",
                                                    item=degrees("amplitude·cos(kθ − phase)"),
                                                ),
                                            },
                                        ),
                                        "per mount",
                                    ),
                                },
                            ),
                            "per order",
                        ),
                    },
                ),
                "per speed",
                min_items=1,
            ),
        },
        {"decoupling": decoupling},
    )
    return document(
        "mounts",
        DOCUMENT_VERSION,
        "balance mounts --format json: the engine on its mounts (MountResult.to_dict per "
        "engine): modes, axes, static deflections, resonances crossed and the forced response. "
        "SI units, engine axes (x along the crank towards the front, z up).",
        {"engines": array(engine, "one per engine with a [mounts] table", min_items=1)},
    )


def regress():
    value = {
        "type": ["number", "string", "boolean", "array", "null"],
        "description": (
            "a number (SI; degrees for angles), or for the firing order, the flags and an "
            'order listed or not: the value itself ("listed", "absent")'
        ),
    }
    row = closed(
        "one quantity that moved beyond its tolerance",
        {
            "engine": text("the engine's name"),
            "order": integer("the order; null for a quantity of the whole engine", 1, null=True),
            "quantity": text("what moved: a key (force.max_N) or words (firing order)"),
            "baseline": value,
            "now": value,
            "change": number("now − baseline (the short way round for an angle)", null=True),
            "relative_change": number("change / |baseline| (null for an angle)", null=True),
            "tolerance": size("what it may move by; null for a value that must not", null=True),
        },
    )
    return document(
        "regress",
        DOCUMENT_VERSION,
        "balance regress --format json: what moved between a baseline and the engines now "
        "(Regression.to_dict).",
        {
            "baseline": text("the baseline file"),
            "rtol": number("the relative tolerance", minimum=0, below=1),
            "moved": flag("anything moved, was added or was removed"),
            "engines_checked": array(text("an engine's name"), "engines in both"),
            "rows": array(row, "each quantity that moved"),
            "added": array(text("an engine's name"), "engines not in the baseline"),
            "removed": array(text("an engine's name"), "engines of the baseline not there now"),
        },
    )


def search():
    arrangement = closed(
        "one arrangement: a crank and a firing order, analysed",
        {
            "rank": integer("1 for the best", 1),
            "score": size("the objective's value"),
            "phases_deg": array(
                degrees("degrees in [0, 360)"), "throw by throw, throw 1 at 0", min_items=1
            ),
            "firing": closed(
                "the firing sequence",
                {k: DEFS["firing"]["properties"][k] for k in ("order", "intervals_deg", "uniform")},
            ),
            "mirror_of": integer(
                "the rank of its mirror image listed above it, or null", 1, null=True
            ),
            "coefficients": {
                "type": "object",
                "description": (
                    "every F_k and M_k (k = 1..max_order) and the objective's other terms, "
                    "by name (F1, M2, F1+, M2-, H3, X2, V1, TV1)"
                ),
                "patternProperties": {
                    "^(TV|[FMHXV])[1-9][0-9]*[+-]?$": size("a coefficient (dimensionless)")
                },
                "additionalProperties": False,
            },
            "orders": ref("orders"),
        },
    )
    return document(
        "search",
        DOCUMENT_VERSION,
        "balance search --format json: the best crank arrangements and firing orders "
        "(SearchResult.to_dict).",
        {
            "template": text("the template file (its name for one built in code)"),
            "name": text("the template's name"),
            "objective": array(
                text("a term, F2:4 for a weight of 4", pattern="^(TV|[FMHXV])[0-9]+[+-]?(:.+)?$"),
                "the objective's terms",
                min_items=1,
            ),
            "method": text('"exhaustive" or "heuristic"', enum=("exhaustive", "heuristic")),
            "even_firing": flag("only evenly firing cranks were searched"),
            "even_banks": flag("each bank fires evenly on its own, the banks a fixed angle apart"),
            "step_deg": positive("the phase lattice, degrees"),
            "arrangements_total": integer("arrangements in the search space", 0),
            "arrangements_distinct": integer("the same up to turning and reversing", 0),
            "firing_orders_per_crank": integer("firing orders tried on each crank", 0),
            "evaluated": integer("cranks evaluated", 0),
            "pruned": integer("cranks skipped by bound", 0),
            "exhaustive": flag("the result is proved optimal"),
            "symmetries": array(text("a symmetry, in words"), "the symmetries used"),
            "ties_truncated": flag("more tied at the last score than the tie-break saw"),
            "elapsed_s": size("the search's time, s"),
            "workers": integer("processes that ran", 1),
            **SETTINGS,
            "results": array(arrangement, "the arrangements, best first"),
        },
    )


def family():
    moments = {}
    for k, null in ((1, False), (2, False), (4, True)):
        for d, word in (("V", "pitching"), ("H", "yawing")):
            extra = " (null beyond max_order)" if null else ""
            moments[f"M{k}{d}_Nm"] = size(f"order-{k} {word} moment, N·m{extra}", null=null)
            if k == 1:
                for name in ("standard", "rotating"):
                    moments[f"M1{d}_{name}_Nm"] = size(
                        f"M1{d} under the {name} balance, N·m (null where counterweights are "
                        "not proposed: a rotary, several crankshafts)",
                        null=True,
                    )
                moments[f"M1{d}_crank_Nm"] = size(f"M1{d} as the crank stands, N·m")
    largest = closed(
        "the order with the largest amplitude (null: every order analysed is zero)",
        {"order": ORDER, "amplitude_Nm": positive("N·m")},
        null=True,
    )
    row = closed(
        "one number of cylinders",
        {
            "cylinders": integer("number of cylinders", 2, 24),
            "method": text(
                '"exhaustive" (proved optimal), "heuristic" or "given"',
                enum=("exhaustive", "heuristic", "given"),
            ),
            "score": size("the objective's value (null for a firing order given)", null=True),
            "firing_order": array(integer("a cylinder's number", 1), "the firing order"),
            "phases_deg": array(degrees("degrees"), "the throws' phases"),
            "first_order_balance": ref("balance", "the balance M1V and M1H are given under"),
            **moments,
            "power_kW": positive("the engine's power, kW (null without one)", True),
            "pru": ref("pru", "power related unbalance, as in compare", null=True),
            "pru_note": text("why there is none (null when there is)", null=True),
            "h_type": largest,
            "x_type": largest,
            "second_order_compensator": {
                "type": ["boolean", "null"],
                "description": "a second-order compensator is indicated (null without a PRU)",
            },
            "major_orders": array(
                closed(
                    "a major order of one bank (its cylinders all in phase)",
                    {
                        "order": positive("the order (a half order for a four-stroke's)"),
                        "vector_sum": size(
                            "|Σ e^{ik·φ}| over the cylinders' firing angles, over their number: "
                            "1 for an in-line engine, |1 + e^{ik·Δ}|/2 for a V's banks Δ apart"
                        ),
                    },
                ),
                "the first two major orders",
            ),
        },
    )
    row["properties"]["x_type"] = {**largest, "description": "the largest X-type moment"}
    row["properties"]["h_type"] = {**largest, "description": "the largest H-type moment"}
    return document(
        "family",
        DOCUMENT_VERSION,
        "balance family --format json: a project-guide table of an engine family "
        "(FamilyResult.to_dict). SI units.",
        {
            "name": text("the family's name"),
            "config": CONFIG,
            "objective": text("what each firing order minimises"),
            "first_order_balance": ref("balance"),
            "firing": text(
                '"even" (in-line) or "even within each bank" (a V family)',
                enum=("even", "even within each bank"),
            ),
            "pitch_m": positive("cylinder pitch, m"),
            "guide_forces_from": text(
                '"gas and inertia" or "inertia only"', enum=("gas and inertia", "inertia only")
            ),
            "power_per_cylinder_kW": positive("one cylinder's power, kW (null without)", True),
            **SETTINGS,
            "rows": array(row, "one per number of cylinders", min_items=1),
        },
    )


#: the quantities a sweep reports (Quantity.name) and the columns they write (Quantity.column)
_MOUNT_NAMES = (
    "|mode_[1-6]|(fore_aft|lateral|bounce|roll|pitch|yaw)_mode|tra_purity|axes_angle"
    "|mount_.+_(force|F[xyz])"
)
_NAMES = (
    "^([FM][1-9][0-9]*(V|H|\\+|-)?|PRU[1-9][0-9]*[VH]|largest_force|largest_moment"
    "|torque_(mean|max|min|range)|steadiness" + _MOUNT_NAMES + ")$"
)
_COLUMNS = (
    "^([FM][1-9][0-9]*(V|H|\\+|-)?_(N|Nm)|PRU[1-9][0-9]*[VH]_Nm_per_kW|largest_force_N"
    "|largest_moment_Nm|torque_(mean|max|min|range)_Nm|steadiness"
    "|mode_[1-6]_Hz|(fore_aft|lateral|bounce|roll|pitch|yaw)_mode_Hz|tra_purity_pct"
    "|axes_angle_deg|mount_.+_(force|F[xyz])_N)$"
)
_KINDS = (
    "length",
    "mass",
    "angular speed",
    "moment of inertia",
    "pressure",
    "torque",
    "power",
    "unbalance",
    "stiffness",
    "viscous damping",
    "angle",
    "number",
    "whole number",
    "fraction",
)


def sweep():
    as_written = {
        "type": ["string", "number"],
        "description": 'as written in the file: text with a unit ("140 mm") or a number',
    }
    parameter = closed(
        "a swept parameter and its values",
        {
            "key": text("the configuration key (banks[2].angle), a derived one or balance_factor"),
            "kind": text("the kind of its value", enum=_KINDS),
            "unit_SI": text(
                "the SI unit of values_SI (empty for a plain number)",
                enum=(
                    "m",
                    "kg",
                    "rad/s",
                    "kg*m^2",
                    "Pa",
                    "N*m",
                    "W",
                    "kg*m",
                    "N/m",
                    "N*s/m",
                    "rad",
                    "",
                ),
            ),
            "file_value": {
                "type": ["string", "number", "null"],
                "description": "its value in the file (null when the file has none)",
            },
            "changes": array(text("a key"), "the keys a value sets"),
            "meaning": text("what a derived parameter is (null for a key)", null=True),
            "values": array(as_written, "its values", min_items=1),
            "values_SI": array(number("SI (radians for angles)"), "the same in SI", min_items=1),
        },
    )
    quantity = closed(
        "a quantity reported at every point",
        {
            "name": text(
                "as asked for, in capitals (F2V, PRU1H) or lower case (largest_moment)",
                pattern=_NAMES,
            ),
            "column": text("its key in points", pattern=_COLUMNS),
            "unit": text(
                '"N", "Nm", "Hz", "%", "deg" or ""', enum=("N", "Nm", "Hz", "%", "deg", "")
            ),
            "kind": text(
                "what it is",
                enum=(
                    "force",
                    "moment",
                    "torque",
                    "steadiness",
                    "pru",
                    "frequency",
                    "decoupling",
                    "axes angle",
                    "mount force",
                ),
            ),
            "meaning": text("in words, with its unit"),
        },
    )
    column = {"patternProperties": {_COLUMNS: number("the quantity at this point, SI")}}
    point = {
        "type": "object",
        "description": "one point: its value and one key per quantity's column",
        "properties": {"value": as_written, "value_SI": number("SI")},
        "required": ["value", "value_SI"],
        **column,
        "additionalProperties": False,
    }
    pair = {
        "type": "object",
        "description": "one pair of values and one key per quantity's column",
        "properties": {
            "value_1": as_written,
            "value_1_SI": number("SI"),
            "value_2": as_written,
            "value_2_SI": number("SI"),
        },
        "required": ["value_1", "value_1_SI", "value_2", "value_2_SI"],
        **column,
        "additionalProperties": False,
    }
    schema = document(
        "sweep",
        DOCUMENT_VERSION,
        "balance sweep --format json: one engine at every value of one key (parameter, "
        "points), or over a grid of two (parameters, shape, points: the second varying "
        "fastest) (SweepResult.to_dict, SweepGrid.to_dict). SI units.",
        {
            "name": ENGINE_NAME,
            "config": CONFIG,
            **SETTINGS,
            "speed_rpm": positive("the speed of every point, rev/min (null: it varies)", True),
            "overrides": {
                "type": "object",
                "description": "keys set at every point (--speed, --power), as written",
                "additionalProperties": as_written,
            },
            "quantities": array(quantity, "what each point reports", min_items=1),
            "inertia_kgm2": positive("the flywheel for the steadiness, kg·m² (null without)", True),
            "load": text(
                '"propeller" or "constant" (null without an inertia)',
                enum=("propeller", "constant"),
                null=True,
            ),
            "mount_speeds_rpm": array(
                positive("rev/min"),
                "the speeds over which a mount's force is its largest (null: each point's own)",
                min_items=1,
                null=True,
            ),
            "points": array({}, "one per value, or per pair of values", min_items=1),
        },
        {
            "parameter": parameter,
            "parameters": array(parameter, "two --vary: the two", min_items=2, max_items=2),
            "shape": array(
                integer("values", 1), "two --vary: values of the first, of the second", 2, 2
            ),
        },
    )
    del schema["properties"]["points"]["items"]
    schema["if"] = {"required": ["parameters"]}
    both = "one --vary (parameter) or two (parameters, shape), not both"
    schema["then"] = {
        "required": ["parameters", "shape"],
        "not": {"required": ["parameter"], "description": both},
        "properties": {"points": {"items": pair}},
    }
    schema["else"] = {
        "required": ["parameter"],
        "not": {"required": ["shape"], "description": both},
        "properties": {"points": {"items": point}},
    }
    return schema


def _stats(unit):
    """A quantity's spread over a tolerance run's engines (spread.Stats.to_dict)."""
    what = {"N": "N", "Nm": "N·m"}[unit]
    interval = array(size(what), "low and high", min_items=2, max_items=2)
    return {
        f"mean_{unit}": size(f"mean over the runs, {what}"),
        f"median_{unit}": size(f"median, {what}"),
        f"p95_{unit}": size(f"95th percentile, {what}"),
        f"p99_{unit}": size(f"99th percentile, {what}"),
        f"max_{unit}": size(f"largest, {what}"),
        f"std_{unit}": size(f"standard deviation over the runs, {what}"),
        f"mean_error_{unit}": size(f"the mean's standard error, std/√runs, {what}"),
        f"p95_interval_{unit}": {
            **interval,
            "description": f"the 95th percentile's 95 % interval (order statistics), {what}",
        },
        f"p99_interval_{unit}": {
            **interval,
            "description": f"the 99th percentile's 95 % interval, {what}",
        },
    }


def _linear(unit):
    """The closed-form spread of an amplitude's linear part (spread.Linear.to_dict)."""
    what = {"N": "N", "Nm": "N·m"}[unit]
    return closed(
        "the closed form of the scatter's linear part",
        {
            f"nominal_{unit}": size(f"the engine's own amplitude, {what}"),
            f"rms_{unit}": size(f"root mean square of the linear part, {what}"),
            "model": text(
                '"zero-mean" (the order is nothing nominally: the length of a normal vector) '
                'or "about the nominal" (normal about it)',
                enum=("zero-mean", "about the nominal"),
            ),
            f"mean_{unit}": size(f"mean, {what}"),
            f"median_{unit}": size(f"median, {what}"),
            f"p95_{unit}": size(f"95th percentile, {what}"),
            f"p99_{unit}": size(f"99th percentile, {what}"),
        },
    )


def tolerance():
    parts = {}
    for part, unit in (("force", "N"), ("moment", "Nm")):
        amplitude = closed(
            f"the spread of the order's {part} amplitude over the runs, and its closed form",
            {**_stats(unit), "linear": _linear(unit)},
        )
        largest = closed(
            f"the spread of the order's largest {part} in a revolution (|X⁺| + |X⁻|)",
            _stats(unit),
        )
        parts[part] = closed(
            f"the order's free {part}: vertical and horizontal amplitudes, and max",
            {"vertical": amplitude, "horizontal": amplitude, "max": largest},
        )
    order = closed("one order's spread", {"order": integer("k, from 1", minimum=1), **parts})
    return document(
        "tolerance",
        DOCUMENT_VERSION,
        "balance tolerance --format json: what a tolerance band leaves across a production "
        "run (ToleranceResult.to_dict). SI units.",
        {
            "engine": ENGINE_NAME,
            "config": CONFIG,
            "runs": integer("engines drawn", minimum=2),
            "seed": integer("the draws' random seed", minimum=0),
            **SETTINGS,
            "method": text(
                '"masses" (masses only scattered: linear, exact) or "linkage" (each run\'s '
                "linkage closed)",
                enum=("masses", "linkage"),
            ),
            "elapsed_s": size("the time taken, s"),
            "tolerances": closed(
                "one standard deviation of each scatter ([tolerances])",
                {
                    "reciprocating_kg": size("each cylinder's reciprocating mass, kg"),
                    "rotating_kg": size("each throw's rotating mass, kg"),
                    "crank_radius_m": size("each throw's crank radius, m"),
                    "rod_length_m": size("each rod's length, m"),
                    "phase_deg": size("each throw's phase but throw 1's, degrees"),
                    "bank_angle_deg": size("each bank's direction, degrees"),
                    "pin_offset_m": size("each cylinder's pin offset, m"),
                },
            ),
            "largest_force": closed(
                "the largest resultant force over a revolution, all orders", _stats("N")
            ),
            "largest_moment": closed(
                "the largest free moment over a revolution, all orders", _stats("Nm")
            ),
            "orders": array(order, "every order 1..max_order", min_items=1),
        },
    )


def match():
    engine = compare()["properties"]["engines"]["items"]
    fitting = closed(
        "one assignment of the parts and what it leaves (Fitting.to_dict)",
        {
            "fitting": text('"best" or "given" (the order given)', enum=("best", "given")),
            "score_N": size("the objective's value, N"),
            "largest_force_N": size(
                "of what the parts' deviations add: the largest force over a revolution, N"
            ),
            "largest_moment_Nm": size("and the largest free moment, N·m"),
            "cylinders": array(
                closed(
                    "one cylinder as assembled",
                    {
                        "cylinder": integer("its number", minimum=1),
                        "throw": integer("its throw's number", minimum=1),
                        "piston": text("the piston's id; null without pistons", null=True),
                        "rod": text("the rod's id; null without rods", null=True),
                        "reciprocating_kg": positive("its reciprocating mass, kg"),
                        "rotating_kg": size("its throw's rotating mass, kg"),
                    },
                ),
                "in the order of the engine's cylinders",
                min_items=1,
            ),
            "difference_orders": ref("orders"),
            "assembled": {**engine, "description": "the engine as assembled, as compare writes it"},
        },
    )
    term = closed(
        "one term of the objective",
        {
            "term": text("its name, F2 or M1+", pattern="^[FM][0-9]+[+-]?$"),
            "kind": text('"F" or "M"', enum=("F", "M")),
            "order": integer("k", minimum=1),
            "part": text("max, forward or backward", enum=("max", "forward", "backward")),
            "weight": positive("its weight"),
        },
    )
    return document(
        "match",
        DOCUMENT_VERSION,
        "balance match --format json: weighed parts fitted to the cylinders (MatchResult.to_dict)."
        " SI units.",
        {
            "engine": ENGINE_NAME,
            "config": CONFIG,
            "parts": text("the parts file (empty for parts built in code)"),
            "kinds": array(
                text("a kind fitted", enum=("pistons", "rods")), "what was fitted", min_items=1
            ),
            **SETTINGS,
            "objective": text("the objective in words, or its terms"),
            "default": flag("the default objective (largest force + largest moment / pitch)"),
            "terms": array(term, "the objective's terms; null for the default", null=True),
            "pitch_m": positive("the pitch moments are divided by, m"),
            "grid_points": integer(
                "crank angles of the default's largest values; null for terms", 1, null=True
            ),
            "method": text('"exhaustive" or "heuristic"', enum=("exhaustive", "heuristic")),
            "exhaustive": flag("the best is proved"),
            "assignments_total": integer("every assignment", 1),
            "assignments_distinct": integer("one per symmetry class", 1),
            "symmetries": integer("the symmetry group's order", 1),
            "evaluated": integer("assignments scored", 1),
            "elapsed_s": size("the time taken, s"),
            "gain_N": number("the given order's score less the best's, N"),
            "ratio": size("the best score over the given order's; null when that is 0", True),
            "best": fitting,
            "given": fitting,
        },
    )


def bobweight():
    pin = closed(
        "one crank pin's bobweight",
        {
            "throw": integer("its throw's number", minimum=1),
            "cylinders": array(integer("a cylinder", minimum=1), "the cylinders on the pin"),
            "rotating_kg": size("the rotating mass on the pin (big ends, knuckle shares), kg"),
            "reciprocating_kg": size("its cylinders' reciprocating masses, kg"),
            "factor": number("the balance factor"),
            "bobweight_kg": number("rotating + factor × reciprocating, kg"),
        },
    )
    trade = closed(
        "what counterweights sized at one balance factor leave (a single or a twin)",
        {
            "factor": number("the balance factor", minimum=0, maximum=1),
            "force_vertical_N": size("first-order force along the vertical, N"),
            "force_horizontal_N": size("across it, N"),
            "moment_vertical_Nm": size("first-order pitching moment, N·m"),
            "moment_horizontal_Nm": size("yawing moment, N·m"),
            "largest_force_N": size("the largest resultant over a revolution, all orders, N"),
        },
    )
    return document(
        "bobweight",
        DOCUMENT_VERSION,
        "balance bobweight --format json: the balancing sheet (BobweightSheet.to_dict). SI.",
        {
            "engine": ENGINE_NAME,
            "config": CONFIG,
            "parts": text("the parts file the masses come from (empty: the configuration's)"),
            "balance_factor": number(
                "the factor asked for; null: balance counterweight's",
                minimum=0,
                maximum=1,
                null=True,
            ),
            "pins": array(pin, "every crank pin, in throw order", min_items=1),
            "trade": array(trade, "a single's or twin's trade (empty for more cylinders)"),
        },
    )


def schemas():
    """{file name: schema} of every document and version."""
    out = {
        schema_name("compare", 1): compare_reader(1),
        schema_name("compare", 2): compare_reader(2),
    }
    for name, build in (
        ("compare", compare),
        ("counterweight", counterweight),
        ("torque", torque),
        ("torsion", torsion),
        ("mounts", mounts),
        ("regress", regress),
        ("search", search),
        ("family", family),
        ("sweep", sweep),
        ("match", match),
        ("tolerance", tolerance),
        ("bobweight", bobweight),
    ):
        out[schema_name(name, DOCUMENT_VERSION)] = build()
    out[schema_name("steadiness", STEADINESS_VERSION)] = steadiness()
    return {name: with_defs(schema) for name, schema in out.items()}


def render(schema):
    return json.dumps(schema, indent=2, ensure_ascii=False) + "\n"


def main(argv):
    check = "--check" in argv
    stale = []
    for name, schema in schemas().items():
        path = TARGET / name
        text_ = render(schema)
        if path.exists() and path.read_text(encoding="utf-8") == text_:
            continue
        stale.append(name)
        if not check:
            path.write_text(text_, encoding="utf-8")
    if check and stale:
        print(f"stale: {', '.join(stale)}; run make schemas", file=sys.stderr)
        return 1
    for name in stale:
        print(f"wrote {TARGET / name}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
