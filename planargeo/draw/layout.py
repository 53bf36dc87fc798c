"""Views fitted to computed points (and the figure height to their aspect) for the gallery figures."""
from __future__ import annotations

import numpy as np


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
    leaving a band empty; then :func:`fit_view`.
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


def fit_view(ax, points, margin=0.25, *, aspect=None):
    """Set limits to the bounding box of the finite ``points`` (Euclidean, (n, 2)) plus a margin.

    ``margin`` is a fraction of the larger extent; with ``aspect`` (height /
    width of the panel) the box is widened so that equal-aspect drawing fills it.
    """
    P = np.asarray(points, float).reshape(-1, 2)
    P = P[np.all(np.isfinite(P), axis=1)]
    if len(P) > 2:  # ignore far outliers (poles of near-translations)
        med = np.median(P, axis=0)
        dist = np.hypot(*(P - med).T)
        P = P[dist <= 20 * max(np.median(dist), 1e-9) + 1e-9] if np.median(dist) > 0 else P
    lo, hi = P.min(axis=0), P.max(axis=0)
    size = max(float(np.max(hi - lo)), 1e-9)
    lo, hi = lo - margin * size, hi + margin * size
    if aspect is None:
        bb = ax.get_position(original=True)
        fw, fh = ax.figure.get_size_inches()
        aspect = (bb.height * fh) / (bb.width * fw)
    w, h = hi - lo
    c = (lo + hi) / 2
    if h / w < aspect:
        h = w * aspect
    else:
        w = h / aspect
    ax.set_xlim(c[0] - w / 2, c[0] + w / 2)
    ax.set_ylim(c[1] - h / 2, c[1] + h / 2)
    return ax
