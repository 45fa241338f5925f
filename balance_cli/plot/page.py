"""The animation as one self-contained HTML page: the scene's data as JSON, drawn as SVG by a
small script (``animate.js``, shipped with the package), with play and pause, a speed slider,
a step to each firing top dead centre, and orders and cylinders on and off.

Nothing is loaded from the network or from another file. The same content, without the
document round it (:func:`fragment`), goes inside another page: the HTML report, a notebook, the
documentation; the script mounts every animation of a page once, however often it is included.

Where the page draws what, in pixels, is decided here (:func:`layout`), so that a test can
find a piston's drawn position from the kinematics alone: the end view maps a point at
``p`` (m, complex) to (x0 + s·(Im p − left), y0 + s·(top − Re p)), the side view a point at
axial position z to (x0 + s·(z − left), y0 + s·(top − Re(p·e^{−iu}))), u its vertical.
"""

import html
import json
import math
from importlib import resources

import numpy as np

from ..tolerances import NOISE_FLOOR
from ..units import rad_s_to_rpm
from .scene import PISTON_PIN_AT, Scene

__all__ = [
    "page",
    "fragment",
    "layout",
    "scene_data",
    "VIEW_PX",
    "MIN_VIEW_PX",
    "PANEL_PX",
    "DATA_CLASS",
]

#: the largest side of a view of the mechanism, CSS pixels
VIEW_PX = 420
#: the narrowest view, CSS pixels (an opposed-piston engine seen end on is tall and thin)
MIN_VIEW_PX = 200
#: the side of a phasor panel, CSS pixels
PANEL_PX = 150
#: the class of the <script type="application/json"> holding an animation's data
DATA_CLASS = "balance-animation-data"
#: positions in the page: whole micrometres (a pixel is a millimetre or more)
_MICROMETRE = 1e-6

_CSS = """
.balance-animation { font-family: sans-serif; color: #222; margin: 0.5em 0 1.5em; }
.balance-animation .ba-title { font-weight: bold; margin-bottom: 0.3em; }
.balance-animation .ba-controls { display: flex; flex-wrap: wrap; gap: 0.4em 1em;
  align-items: center; font-size: 0.85em; margin: 0.3em 0; }
.balance-animation .ba-controls label { white-space: nowrap; }
.balance-animation .ba-controls fieldset { border: 1px solid #ccc; padding: 0.1em 0.5em;
  margin: 0; }
.balance-animation .ba-controls legend { font-size: 1em; float: none; width: auto;
  padding: 0 0.2em; margin: 0; }
.balance-animation .ba-controls input[type=checkbox] { margin: 0 0.1em 0 0.4em; }
.balance-animation button { font-size: 0.95em; }
.balance-animation svg { display: block; }
.balance-animation .ba-mechanism { overflow-x: auto; }
.balance-animation .ba-panels { display: flex; flex-wrap: wrap; gap: 4px; }
.balance-animation .ba-readout { font-size: 0.8em; color: #444; min-height: 1.2em; }
.balance-animation .ba-note { font-size: 0.8em; color: #555; max-width: 60em; }
"""


def layout(view: Scene) -> dict:
    """Where the page draws each view: ``end`` and (when the scene has a side view) ``side``,
    each [x0, y0, s, left, top] (CSS pixels, pixels a metre, m), and the mechanism's
    ``width`` and ``height`` (CSS pixels)."""
    out: dict = {}
    boxes = [("end", view.end_box)] + ([("side", view.side_box)] if view.side_box else [])
    x0 = 0.0
    height = 0.0
    for name, (left, right, bottom, top) in boxes:
        scale = VIEW_PX / max(right - left, top - bottom)
        # a narrow view widened about its middle: room for its title
        grow = max(0.0, MIN_VIEW_PX / scale - (right - left)) / 2
        left, right = left - grow, right + grow
        out[name] = [x0, 24.0, scale, left, top]
        x0 += scale * (right - left) + 20.0
        height = max(height, scale * (top - bottom))
    out["width"] = math.ceil(x0 - 20.0)
    out["height"] = math.ceil(height + 28.0)
    return out


def _micrometres(values):
    """Positions as [real, imaginary] lists of whole micrometres."""
    values = np.asarray(values)
    return [
        np.rint(values.real / _MICROMETRE).astype(int).tolist(),
        np.rint(values.imag / _MICROMETRE).astype(int).tolist(),
    ]


def _pairs(values):
    """Complex phasors as [forward re, forward im, backward re, backward im] per order."""
    return [[float(f.real), float(f.imag), float(b.real), float(b.imag)] for f, b in values]


def scene_data(view: Scene, orders, engine) -> dict:
    """What the page's script draws: the scene as JSON-ready values (see the module text)."""
    return {
        "name": view.name,
        "cycle": view.cycle_deg,
        "rotary": view.rotary,
        "frames": view.frames,
        "speedRpm": rad_s_to_rpm(engine.speed_rad_s),
        "points": {name: _micrometres(values) for name, values in view.points.items()},
        "fixed": {name: [value.real, value.imag] for name, value in view.fixed.items()},
        "z": view.z_m,
        "parts": [
            [p.kind, list(p.points), p.z_m, p.cylinder, p.axis_rad, p.outward, list(p.span_m)]
            for p in view.parts
        ],
        "events": [[angle, number] for angle, number in view.events],
        "eventPoints": {name: _micrometres(values) for name, values in view.event_points.items()},
        "bore": view.bore_m,
        "piston": view.piston_m,
        "pinAt": PISTON_PIN_AT,
        "crankRadius": view.crank_radius_m,
        "side": view.side_rad,
        "layout": layout(view),
        "panel": PANEL_PX,
        "orders": list(view.orders),
        "shown": list(orders),
        "groups": [dict(g) for g in view.groups],
        "force": [_pairs(g) for g in view.force],
        "moment": [_pairs(g) for g in view.moment],
        "meanZ": view.mean_z_m,
        "unitN": view.unit_n,
        "noiseFloor": NOISE_FLOOR,
    }


def script() -> str:
    """The ``<script>`` element that draws every animation of a page (once is enough for a
    page of several: it mounts each one once, however often it runs)."""
    source = resources.files("balance_cli.plot").joinpath("animate.js").read_text(encoding="utf-8")
    return f"<script>\n{source}</script>\n"


def style() -> str:
    """The ``<style>`` element of the animations (once for a page of several)."""
    return f"<style>{_CSS}</style>\n"


def _json(data):
    # inside <script>: no "</script>" or "<!--" can end it early
    return json.dumps(data, ensure_ascii=False, separators=(",", ":")).replace("<", "\\u003c")


def fragment(view: Scene, orders, engine, whole: bool = True) -> str:
    """The animation's content, to put inside another page: its data in an element the
    script draws in; ``whole``: with the style and the script (else the page holds them once:
    :func:`style`, :func:`script`)."""
    data = (
        f'<div class="balance-animation"><script type="application/json" class="{DATA_CLASS}">'
        f"{_json(scene_data(view, orders, engine))}</script></div>\n"
    )
    return style() + data + script() if whole else data


def page(view: Scene, orders, engine) -> str:
    """The animation as one self-contained HTML document."""
    return (
        '<!DOCTYPE html>\n<html lang="en"><head><meta charset="utf-8">'
        '<meta name="viewport" content="width=device-width, initial-scale=1">'
        f"<title>{html.escape(view.name)}: balance animate</title></head><body>\n"
        f"{fragment(view, orders, engine)}</body></html>\n"
    )
