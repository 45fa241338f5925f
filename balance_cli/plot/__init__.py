"""Pictures of analysed engines (matplotlib).

Each function takes results of :func:`balance_cli.analyse`, draws, and returns the Figure; none
recomputes an analysis. Give ``ax`` (locus) or ``fig`` (the others) to draw into your own;
otherwise a new pyplot figure is made, so figures show inline in a notebook. Importing this
module never chooses a backend: that is the application's business (the command line uses Agg).

Kinds: :func:`locus` (Tanaka's Fig. 9), :func:`spectrum`, :func:`star`, :func:`firing` (of
:func:`balance_cli.analyse`'s results) and :func:`torque` (of
:func:`balance_cli.analysis.torque.torque`'s); ``of="moment"`` makes the locus and the star
those of the free moment instead of the force.
:func:`save` writes a figure in the format its file name's extension names.

:func:`animate` makes an :class:`EngineAnimation` of one analysed engine: its mechanism turning
through its cycle beside the phasors of chosen orders, written as a GIF, an MP4 or a
self-contained HTML page (its :class:`Scene` holds what is drawn).

Also :func:`campbell`, :func:`mode_shapes` and :func:`torque_speed` of a torsional vibration
analysis; :func:`mount_modes`, :func:`energy_bars` and :func:`mount_forces` of the engine on
its mounts; :func:`sweep_figure` of a sweep (curves) or a grid of two parameters (heat maps);
and :func:`tolerance_histograms` of a tolerance band's scatter (:func:`balance_cli.tolerance`).

One module per picture: ``loci``, ``spectra``, ``stars`` (its labels placed by ``labels``),
``firings``, ``torques``, ``torsion``, ``mounts``, ``sweep`` and ``tolerances``; ``figure`` holds
what they share. The animation: ``scene`` (what is drawn), ``movie`` (one instant drawn by
matplotlib), ``animation`` (the animation and its files) and ``page`` (the HTML page, drawn by
the script ``animate.js``).
"""

from .animation import ANIMATION_FORMATS, DEFAULT_ORDERS, EngineAnimation, animate
from .figure import (
    CELL_IN,
    DPI,
    FORMATS,
    KINDS,
    MIN_WIDTH_IN,
    QUANTITIES,
    colours,
    format_of,
    grid_size,
    save,
    short,
)
from .firings import firing
from .labels import STAR_LABEL_GAP_PT, STAR_LABEL_MIN_PT, STAR_LABEL_PT, place_labels
from .loci import coinciding, locus, locus_points
from .mounts import energy_bars, equivalent_box, mount_forces, mount_modes
from .scene import Part, Scene
from .spectra import SPECTRUM_UNITS, spectrum, spectrum_data
from .stars import STAR_TITLE_CHARS, star, star_chains
from .sweep import axis_values, sweep_figure
from .tolerances import tolerance_histograms
from .torques import TORQUE_STYLES, TORQUE_UNITS, torque, torque_data
from .torsion import campbell, mode_shapes, torque_speed

__all__ = [
    "KINDS",
    "FORMATS",
    "QUANTITIES",
    "locus",
    "spectrum",
    "star",
    "firing",
    "torque",
    "animate",
    "EngineAnimation",
    "Scene",
    "Part",
    "ANIMATION_FORMATS",
    "DEFAULT_ORDERS",
    "save",
    "format_of",
    "grid_size",
    "locus_points",
    "coinciding",
    "spectrum_data",
    "star_chains",
    "torque_data",
    "colours",
    "short",
    "place_labels",
    "campbell",
    "mode_shapes",
    "torque_speed",
    "mount_modes",
    "energy_bars",
    "mount_forces",
    "equivalent_box",
    "sweep_figure",
    "axis_values",
    "tolerance_histograms",
    "CELL_IN",
    "MIN_WIDTH_IN",
    "DPI",
    "SPECTRUM_UNITS",
    "TORQUE_UNITS",
    "TORQUE_STYLES",
    "STAR_LABEL_PT",
    "STAR_LABEL_GAP_PT",
    "STAR_LABEL_MIN_PT",
    "STAR_TITLE_CHARS",
]
