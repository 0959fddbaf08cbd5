"""Text labels at points of an axes that never overlap: each label tries offsets around its point
and takes the first whose box, measured by the renderer, overlaps no label already placed, no
marker and as few curve vertices as possible and stays inside the axes; a label that finds no such
place near its point goes further out, on a thin leader (a special point without its name would be
an unexplained marker); only one that fits nowhere inside the axes is dropped. Labels at the same place are merged first
("LP2, NS1" rather than "LP2" over "NS1").

Place the labels after the axes' limits and the figure's layout are final (after tight_layout):
the offsets are in points from their anchor, so a later change of scale moves the anchors apart
or together and can make labels overlap again.
"""
import numpy as np

# Offsets tried, in points, in order of preference: above-right first (the usual reading place),
# then around the point, then further out.
_OFFSETS = [(5, 5), (5, -13), (-5, 5), (-5, -13), (8, -4), (-8, -4), (0, 10), (0, -18),
            (14, 14), (14, -22), (-14, 14), (-14, -22), (22, -4), (-22, -4), (0, 24), (0, -32)]
# Further out, on a leader, when every near place is taken: rings of 8 directions.
_FAR = [(round(r * np.cos(a)), round(r * np.sin(a)) - 4) for r in (34, 52, 75, 100) for a in np.linspace(0, 2 * np.pi, 8, endpoint=False) + np.pi / 8]


def merge_close(items, ax, distance=6.0):
    """Labels whose anchors are within `distance` pixels of each other joined into one.

    Parameters
    ----------
    items : list of (x, y, text)
        Anchors in data coordinates and their texts.
    ax : matplotlib.axes.Axes
        Where they will be drawn (its transform gives the pixel distance).
    distance : float, optional
        Pixels.

    Returns
    -------
    list of (x, y, text)
        One item per group, at its first anchor, texts joined by ", ".

    Examples
    --------
    >>> merge_close([(1.0, 2.0, "LP2"), (1.0, 2.0, "NS1")], ax)
    [(1.0, 2.0, 'LP2, NS1')]
    """
    merged = []  # [x, y, pixel position, [texts]]
    for x, y, text in items:
        where = ax.transData.transform((x, y))
        for group in merged:
            if np.hypot(*(where - group[2])) <= distance:
                if text not in group[3]:
                    group[3].append(text)
                break
        else:
            merged.append([x, y, where, [text]])
    return [(x, y, ", ".join(texts)) for x, y, _, texts in merged]


def _line_vertices(ax):
    """Pixel positions of the axes' curve vertices (NaN gaps dropped)."""
    points = [line.get_transform().transform(np.column_stack(line.get_data()).astype(float))
              for line in ax.get_lines() if len(line.get_xdata())]
    points = np.concatenate(points) if points else np.zeros((0, 2))
    return points[np.isfinite(points).all(axis=1)]


def _finite(points):
    return points[np.isfinite(points).all(axis=1)]


def _overlaps(box, boxes):
    return any(box.overlaps(other) for other in boxes)


def place_labels(ax, items, fontsize=8, avoid=()):
    """Draws the labels where they overlap nothing; merges the coincident ones, drops the rest.

    Parameters
    ----------
    ax : matplotlib.axes.Axes
        The axes, limits and layout final.
    items : list of (x, y, text)
        Anchors in data coordinates and texts.
    fontsize : float, optional
        Text size.
    avoid : sequence of matplotlib.transforms.Bbox, optional
        Pixel boxes no label may cover (e.g. the legend's).

    Returns
    -------
    list of matplotlib.text.Annotation
        The labels drawn (fewer than the items when some were merged or dropped).

    Examples
    --------
    >>> place_labels(ax, [(1.08, 2.3, "LP1"), (1.3, 0.4, "LP2")])
    """
    ax.figure.draw_without_rendering()  # places the legend, whose box the labels avoid
    renderer = ax.figure.canvas.get_renderer()
    frame = ax.get_window_extent(renderer)
    vertices = _line_vertices(ax)
    taken = list(avoid)
    legend = ax.get_legend()
    if legend is not None:
        taken.append(legend.get_window_extent(renderer))
    merged = [(x, y, text) for x, y, text in merge_close(items, ax) if frame.contains(*ax.transData.transform((x, y)))]
    taken += [_marker_box(ax.transData.transform((x, y)), 3.0 * ax.figure.dpi / 72) for x, y, _ in merged]  # no text on a dot
    taken += [_marker_box(p, 0.5 * line.get_markersize() * ax.figure.dpi / 72 + 1) for line in ax.get_lines()  # nor on any other marker
              if line.get_marker() not in (None, "None", "", " ") and line.get_linestyle() in ("None", "", " ")
              for p in _finite(line.get_transform().transform(np.column_stack(line.get_data()).astype(float)))]
    placed = []
    for x, y, text in merged:
        best = None
        for dx, dy in _OFFSETS + _FAR:
            if best is not None and (dx, dy) in _FAR:
                break  # a near place found: the far ones are for labels that have none
            label = ax.annotate(text, (x, y), textcoords="offset points", xytext=(dx, dy), fontsize=fontsize,
                                annotation_clip=False)
            box = label.get_window_extent(renderer)
            if frame.contains(box.x0, box.y0) and frame.contains(box.x1, box.y1) and not _overlaps(box, taken):
                inside = np.count_nonzero((vertices[:, 0] >= box.x0) & (vertices[:, 0] <= box.x1)
                                          & (vertices[:, 1] >= box.y0) & (vertices[:, 1] <= box.y1))
                if best is None or inside < best[0]:
                    if best is not None:
                        best[1].remove()
                    best = (inside, label, box)
                    if inside == 0:
                        break
                    continue
            label.remove()
        if best is not None:
            label = best[1]
            dx, dy = label.xyann
            if np.hypot(dx, dy) > 15:  # far from its dot: a thin leader says which dot (drawn after measuring the text alone)
                label.remove()
                label = ax.annotate(text, (x, y), textcoords="offset points", xytext=(dx, dy), fontsize=fontsize, annotation_clip=False,
                                    arrowprops={"arrowstyle": "-", "lw": 0.5, "color": "0.4", "shrinkA": 1, "shrinkB": 3})
            placed.append(label)
            taken.append(best[2])
    return placed


def _marker_box(anchor, half):
    """The pixel box of a marker at `anchor`, `half` its half-width in pixels."""
    from matplotlib.transforms import Bbox
    return Bbox.from_extents(anchor[0] - half, anchor[1] - half, anchor[0] + half, anchor[1] + half)
