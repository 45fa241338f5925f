"""Cylinder labels beside the arrows of a star: how large a label is, where it finds room
(beside its arrow, over no other label, across as few arrows as can be) and putting it
there."""

import functools
import math

import numpy as np

__all__ = [
    "STAR_LABEL_PT",
    "STAR_LABEL_GAP_PT",
    "STAR_LABEL_MIN_PT",
    "place_labels",
    "label_arrows",
]

#: font size of the star's cylinder labels (points), and their gap from their arrow (points)
STAR_LABEL_PT = 6.5
STAR_LABEL_GAP_PT = 1.5
#: an arrow shorter than this (points) gets no label: the eye cannot tell which arrow it names
STAR_LABEL_MIN_PT = 5.0


@functools.lru_cache(maxsize=1024)
def _text_size_pt(text, fontsize):
    """Width and height (points) of one line of ``text``, as a Text artist lays it out; the
    same cylinder numbers recur on every engine, so each is measured once."""
    from matplotlib.font_manager import FontProperties
    from matplotlib.textpath import text_to_path

    prop = FontProperties(size=fontsize)
    width, _, _ = text_to_path.get_text_width_height_descent(text, prop, ismath=False)
    _, height, descent = text_to_path.get_text_width_height_descent("lp", prop, ismath=False)
    return width, height + descent


def _boxes_overlap(a, b):
    return a[0] < b[2] and b[0] < a[2] and a[1] < b[3] and b[1] < a[3]


def _crosses(box, p, q):
    """Whether the segment ``p``–``q`` passes through ``box`` (x0, y0, x1, y1)."""
    # clip the segment's parameter range to the box on each axis (Liang–Barsky)
    low, high = 0.0, 1.0
    for start, step, lower, upper in (
        (p[0], q[0] - p[0], box[0], box[2]),
        (p[1], q[1] - p[1], box[1], box[3]),
    ):
        if step == 0:
            if not lower < start < upper:
                return False
            continue
        t0, t1 = sorted(((lower - start) / step, (upper - start) / step))
        low, high = max(low, t0), min(high, t1)
        if low >= high:
            return False
    return True


def place_labels(segments, sizes, gap=STAR_LABEL_GAP_PT, shortest=STAR_LABEL_MIN_PT, crowded=0.3):
    """Centres for labels of line ``segments`` ((x0, y0), (x1, y1)) of ``sizes`` (width,
    height), all in one unit (points or pixels) on equal axes; None for a label left out.

    The longest segments are labelled first. Each label sits beside its segment, at its
    middle or a third of the way from an end, on the side away from the centre of the whole
    drawing first; a place that overlaps a label already placed is refused, and among the
    rest the one crossing the fewest segments wins; only segments of at least ``crowded``
    times the longest may have a label across another segment. A segment with no such place,
    or shorter than ``shortest``, goes unlabelled: on a crowded star the short arrows are the
    ones whose number matters least."""
    points = np.array([p for segment in segments for p in segment], float).reshape(-1, 2)
    centre = points.mean(axis=0) if len(points) else np.zeros(2)
    placed: list[tuple[float, float, float, float]] = []
    found: list[tuple[float, float] | None] = [None] * len(segments)
    lengths = [math.dist(*segment) for segment in segments]
    for i in sorted(range(len(segments)), key=lambda i: -lengths[i]):
        if lengths[i] < shortest:
            continue
        (x0, y0), (x1, y1) = segments[i]
        w, h = sizes[i]
        ux, uy = (x1 - x0) / lengths[i], (y1 - y0) / lengths[i]
        nx, ny = -uy, ux
        middle = ((x0 + x1) / 2, (y0 + y1) / 2)
        if (middle[0] - centre[0]) * nx + (middle[1] - centre[1]) * ny < 0:
            nx, ny = -nx, -ny
        # from the segment to the box's edge along the normal, then the gap
        offset = gap + abs(nx) * w / 2 + abs(ny) * h / 2
        best = None
        for side in (1, -1):
            for t in (0.5, 1 / 3, 2 / 3):
                cx = x0 + t * (x1 - x0) + side * nx * offset
                cy = y0 + t * (y1 - y0) + side * ny * offset
                box = (cx - w / 2, cy - h / 2, cx + w / 2, cy + h / 2)
                # a point of room: the renderer's hinted glyphs are a little wider than the
                # font's outlines
                room = (box[0] - 1, box[1] - 1, box[2] + 1, box[3] + 1)
                if any(_boxes_overlap(room, other) for other in placed):
                    continue
                crossings = sum(_crosses(box, *segment) for segment in segments)
                if best is None or crossings < best[0]:
                    best = (crossings, (cx, cy), box)
                if crossings == 0:
                    break
            if best is not None and best[0] == 0:
                break
        # over another arrow a short arrow's label would name that arrow as well as its own
        if best is not None and (best[0] == 0 or lengths[i] >= crowded * max(lengths)):
            found[i] = best[1]
            placed.append(best[2])
    return found


def label_arrows(ax, arrows):
    """Cylinder labels beside ``arrows`` (label, tail, head, colour), where
    :func:`place_labels` finds room."""
    fig = ax.figure
    to_pt = 72.0 / fig.dpi

    def data_to_pt(z):
        return ax.transData.transform((z.imag, z.real)) * to_pt

    segments = [(tuple(data_to_pt(tail)), tuple(data_to_pt(head))) for _, tail, head, _ in arrows]
    sizes = [_text_size_pt(label, STAR_LABEL_PT) for label, _, _, _ in arrows]
    centres = place_labels(segments, sizes)
    to_data = ax.transData.inverted()
    for (label, _, _, colour), centre in zip(arrows, centres, strict=True):
        if centre is None:
            continue
        x, y = to_data.transform(np.array(centre) / to_pt)
        ax.text(
            x,
            y,
            label,
            fontsize=STAR_LABEL_PT,
            color=colour,
            ha="center",
            va="center",
            gid="cylinder label",
        )
