"""Layout helpers for the figures of chapters 6, 7, 9 and the extras (views fitted to computed points)."""
from __future__ import annotations

import numpy as np

from . import fit_view


def shape_points(*shapes) -> np.ndarray:
    """Exterior vertices (n, 2) of shapely shapes (polygons or multipolygons), for view fitting."""
    out = [np.zeros((0, 2))]
    for s in shapes:
        for g in getattr(s, "geoms", [s]):
            out.append(np.asarray(g.exterior.coords)[:, :2])
    return np.vstack(out)


def fit_panel(ax, points, margin=0.08, *, hmin=1.5, hmax=4.6):
    """Fit a single-panel figure to ``points``: the figure height follows the points' aspect.

    The width stays; the height becomes ``width × (extent_y / extent_x)`` (clamped to
    ``[hmin, hmax]`` inches), so that the drawing fills the panel instead of
    leaving a band empty; then :func:`~planargeo.draw.figures.fit_view`.
    """
    P = np.asarray(points, float).reshape(-1, 2)
    P = P[np.all(np.isfinite(P), axis=1)]
    ext = P.max(axis=0) - P.min(axis=0) + 2 * margin * np.max(P.max(axis=0) - P.min(axis=0))
    fig = ax.figure
    fw, _ = fig.get_size_inches()
    bb = ax.get_position(original=True)
    h = float(np.clip(fw * bb.width * ext[1] / ext[0] / bb.height, hmin, hmax))
    fig.set_size_inches(fw, h)
    fit_view(ax, P, margin=margin)
    return ax
