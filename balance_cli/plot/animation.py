"""Pictures that move: an engine's mechanism turning through its working cycle, beside the
forward and backward phasors of chosen orders of its shaking force and free moment, their sum,
and the resultant's locus being traced; a mark at each cylinder's firing.

:func:`animate` takes an analysed engine (a result of :func:`balance_cli.analyse`) and returns
an :class:`EngineAnimation`, which writes a GIF (Pillow) or an MP4 (ffmpeg), draws one instant
as a matplotlib figure, or makes one self-contained HTML page with play and pause, a speed
slider, a step to each firing top dead centre, and orders and cylinders on and off
(``page``). Everything drawn comes from the engine's :class:`~balance_cli.plot.Scene`: the
positions from its one kinematic state, the phasors from its analysis.
"""

import io
import math
import os
import shutil
import tempfile
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np

from ..checks import instance, whole
from ..errors import PlotError
from ..output import write_bytes, write_text
from .movie import FIRING_MARK_DEG, Drawing
from .scene import Scene, scene

if TYPE_CHECKING:
    from matplotlib.animation import FuncAnimation
    from matplotlib.figure import Figure

    from ..analysis.results import EngineResult

__all__ = [
    "EngineAnimation",
    "animate",
    "ANIMATION_FORMATS",
    "DEFAULT_ORDERS",
    "MOVIE_FRAMES",
    "MOVIE_FPS",
    "MOVIE_SIZE_IN",
    "MOVIE_DPI",
    "PAGE_FRAMES",
    "FIRING_MARK_DEG",
    "animation_format",
    "check_writer",
]

#: what ``EngineAnimation.save`` writes, by the file name's extension
ANIMATION_FORMATS = ("gif", "mp4", "html")
#: the orders shown unless others are chosen
DEFAULT_ORDERS = (1, 2)
#: a movie's frames over one working cycle (a four-stroke's 720° in 10° steps), its frames a
#: second, its size, inches, and its dots per inch (720 × 446 pixels)
MOVIE_FRAMES = 72
MOVIE_FPS = 18
MOVIE_SIZE_IN = (10.0, 6.2)
MOVIE_DPI = 72
#: the page's frames a revolution (2° apart; each firing has a frame of its own besides)
PAGE_FRAMES = 180

#: colours of a GIF's one palette
_GIF_COLOURS = 64


def animate(result: "EngineResult", orders=DEFAULT_ORDERS) -> "EngineAnimation":
    """An animation of an analysed engine: its mechanism turning through one working cycle,
    beside the phasors of ``orders`` (whole numbers from 1 to the analysis's ``max_order``).

    Returns an :class:`EngineAnimation`; ``save("v8.gif")``, ``save("v8.mp4")`` or
    ``save("v8.html")`` writes it, ``figure(angle_deg)`` draws one instant, and in a notebook
    it shows itself as the HTML page.

    Raises
    ------
    PlotError
        ``result`` that is not an analysed engine, or ``orders`` outside 1..max_order
    """
    from ..analysis.results import EngineResult

    instance(result, EngineResult, "result", PlotError)
    return EngineAnimation(result, _orders(orders, result.max_order))


def _orders(orders, highest):
    if isinstance(orders, int):
        orders = (orders,)
    try:
        chosen = tuple(orders)
    except TypeError:
        raise PlotError(f"must be a list of whole numbers, got {orders!r}", "orders") from None
    if not chosen:
        raise PlotError("must name at least one order", "orders")
    for k in chosen:
        if isinstance(k, bool) or not isinstance(k, (int, np.integer)) or not 1 <= k <= highest:
            raise PlotError(
                f"must be whole numbers from 1 to {highest} (the orders analysed; raise "
                f"max_order for more), got {k!r}",
                "orders",
            )
    return tuple(sorted({int(k) for k in chosen}))


class EngineAnimation:
    """An engine turning through its cycle with the phasors of its shaking (see
    :func:`animate`).

    Attributes
    ----------
    result : EngineResult
        the analysed engine
    orders : tuple of int
        the orders shown (the HTML page can show every order analysed)
    """

    def __init__(self, result: "EngineResult", orders: tuple):
        self.result = result
        self.orders = orders
        self._scenes: dict = {}

    def scene(self, frames: int = PAGE_FRAMES) -> Scene:
        """The :class:`~balance_cli.plot.Scene` at ``frames`` engine angles a revolution
        (kept: each renderer asks again)."""
        if frames not in self._scenes:
            self._scenes[frames] = scene(self.result, frames)
        return self._scenes[frames]

    def figure(self, angle_deg: float = 0.0, fig: "Figure | None" = None) -> "Figure":
        """The movie's picture at engine angle ``angle_deg`` (degrees of the cycle; the nearest
        of the page's 180 a revolution, or a firing's own instant), as a matplotlib
        Figure."""
        if not isinstance(angle_deg, (int, float)) or not math.isfinite(angle_deg):
            raise PlotError(f"must be a finite number of degrees, got {angle_deg!r}", "angle_deg")
        if fig is None:
            from .figure import new_figure

            fig = new_figure(MOVIE_SIZE_IN)
        drawing = Drawing(fig, self.scene(PAGE_FRAMES), self.orders)
        drawing.update(float(angle_deg) % self.scene(PAGE_FRAMES).cycle_deg, traced=True)
        return fig

    def movie(self, frames: int = MOVIE_FRAMES, fps: float = MOVIE_FPS) -> "FuncAnimation":
        """A matplotlib animation of ``frames`` evenly spaced instants of one working cycle (a
        whole number of them a revolution), shown at ``fps`` frames a second."""
        frames, fps = self._movie_frames(frames), _positive(fps, "fps")
        from matplotlib.animation import FuncAnimation

        from .figure import new_figure

        fig = new_figure(MOVIE_SIZE_IN)
        view = self.scene(frames // self.result.engine.turns_per_cycle)
        drawing = Drawing(fig, view, self.orders)
        step = view.cycle_deg / frames
        return FuncAnimation(
            fig,
            lambda j: drawing.update(j * step),
            frames=frames,
            interval=1000.0 / fps,
            blit=False,
            repeat=True,
        )

    def _movie_frames(self, frames):
        """``frames`` checked: a whole number of them a revolution."""
        turns = self.result.engine.turns_per_cycle
        frames = whole(frames, "frames", 4 * turns, 3600, error=PlotError)
        if frames % turns:
            raise PlotError(
                f"must be a whole number a revolution: a multiple of {turns} for a "
                f"four-stroke's two revolutions, got {frames}",
                "frames",
            )
        return frames

    def _gif(self, frames, fps):
        """The GIF's bytes: the still parts drawn once, each frame's moving parts drawn over
        them (blitting), every frame in one palette made from a few of them."""
        from matplotlib.backends.backend_agg import FigureCanvasAgg
        from matplotlib.figure import Figure
        from PIL import Image

        frames, fps = self._movie_frames(frames), _positive(fps, "fps")
        fig = Figure(figsize=MOVIE_SIZE_IN, dpi=MOVIE_DPI)
        canvas = FigureCanvasAgg(fig)
        view = self.scene(frames // self.result.engine.turns_per_cycle)
        drawing = Drawing(fig, view, self.orders)
        step = view.cycle_deg / frames
        moving = drawing.update(0.0)
        for artist in moving:
            artist.set_animated(True)
        canvas.draw()
        background = canvas.copy_from_bbox(fig.bbox)
        images = []
        for j in range(frames):
            canvas.restore_region(background)
            for artist in drawing.update(j * step):
                fig.draw_artist(artist)
            images.append(
                Image.frombuffer("RGBA", canvas.get_width_height(), canvas.buffer_rgba()).convert(
                    "RGB"
                )
            )
        # one palette for every frame, from frames spread over the cycle (a firing's colour
        # among them): a palette each would cost time and bytes
        sample = images[:: max(1, frames // 12)]
        width, height = images[0].size
        montage = Image.new("RGB", (width, height * len(sample)))
        for i, image in enumerate(sample):
            montage.paste(image, (0, i * height))
        palette = montage.quantize(colors=_GIF_COLOURS, method=Image.Quantize.MEDIANCUT)
        quantized = [i.quantize(palette=palette, dither=Image.Dither.NONE) for i in images]
        buffer = io.BytesIO()
        quantized[0].save(
            buffer,
            format="GIF",
            save_all=True,
            append_images=quantized[1:],
            duration=round(1000 / fps),
            loop=0,
            optimize=False,
        )
        return buffer.getvalue()

    def page(self, frames: int = PAGE_FRAMES) -> str:
        """The self-contained HTML page at ``frames`` engine angles a revolution: the scene's
        data, and the script that draws it as SVG."""
        from .page import page

        return page(self.scene(frames), self.orders, self.result.engine)

    def html(self, frames: int = PAGE_FRAMES, whole: bool = True) -> str:
        """The page's content, to put inside another page (a report, a notebook); ``whole``:
        with its style and script, else the other page holds them once (``style()`` and
        ``script()`` of ``balance_cli.plot.page``)."""
        from .page import fragment

        return fragment(self.scene(frames), self.orders, self.result.engine, whole)

    def _repr_html_(self) -> str:
        return self.html()

    def save(self, path, frames: int | None = None, fps: float = MOVIE_FPS) -> None:
        """Write the animation to ``path``, in the format its extension names: ``.gif``
        (Pillow), ``.mp4`` (ffmpeg) or ``.html`` (the page). ``frames``: a movie's frames a
        cycle (default 72), the page's a revolution (default 180). Written whole or not at
        all.

        Raises
        ------
        PlotError
            another extension, or ``.mp4`` where ffmpeg is not installed
        OutputError
            the file cannot be written
        """
        fmt = check_writer(path)
        if fmt == "html":
            write_text(path, self.page(PAGE_FRAMES if frames is None else frames))
            return
        frames = MOVIE_FRAMES if frames is None else frames
        if fmt == "gif":
            data = self._gif(frames, fps)
        else:
            anim = self.movie(frames, fps)
            try:
                with tempfile.TemporaryDirectory(prefix="balance-animate-") as scratch:
                    movie = Path(scratch) / "movie.mp4"
                    anim.save(movie, writer=_writer(fps), dpi=MOVIE_DPI)
                    data = movie.read_bytes()
            finally:
                _close(anim._fig)  # type: ignore[attr-defined]
        write_bytes(path, lambda handle: handle.write(data))


def animation_format(path: "str | os.PathLike[str]") -> str:
    """The format :meth:`EngineAnimation.save` writes to ``path``: its extension, one of
    :data:`ANIMATION_FORMATS`."""
    suffix = Path(path).suffix.lower().lstrip(".")
    if suffix not in ANIMATION_FORMATS:
        shown = f"'.{suffix}'" if suffix else "no extension"
        raise PlotError(
            f"{str(path)!r} has {shown}; end the file name in .gif, .mp4 or .html (a still "
            "picture is balance plot's)",
            "path",
        )
    return suffix


def check_writer(path: "str | os.PathLike[str]") -> str:
    """The format of ``path`` (:func:`animation_format`), once its writer is known to be
    installed: Pillow for a GIF, ffmpeg for an MP4; the page needs none.

    Raises
    ------
    PlotError
        naming the file and the writer missing
    """
    fmt = animation_format(path)
    if fmt == "mp4" and shutil.which("ffmpeg") is None:
        raise PlotError(
            f"{str(path)!r}: an .mp4 is written by ffmpeg, which is not installed (not on "
            "PATH); install ffmpeg, or write a .gif (Pillow) or an .html page",
            "path",
        )
    if fmt == "gif":
        try:
            import PIL  # noqa: F401
        except ImportError:  # pragma: no cover - matplotlib itself needs Pillow
            raise PlotError(
                f"{str(path)!r}: a .gif is written by Pillow, which is not installed; pip "
                "install pillow, or write an .html page",
                "path",
            ) from None
    return fmt


def _writer(fps):
    from matplotlib.animation import FFMpegWriter

    return FFMpegWriter(fps=fps)


def _positive(value, name):
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not 0 < value <= 120:
        raise PlotError(
            f"must be a number of frames a second above 0, up to 120, got {value!r}", name
        )
    return float(value)


def _close(fig):
    import sys

    pyplot = sys.modules.get("matplotlib.pyplot")
    if pyplot is not None:
        pyplot.close(fig)
