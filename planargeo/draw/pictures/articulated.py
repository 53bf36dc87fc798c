"""The picture of the articulated-inertia explorer's state: a chain, its inertias as conics, axes and a chart.

What :class:`planargeo.widgets.articulated.ArticulatedExplorer` shows (thesis 7.1–7.3,
10.2.2, 10.2.3), from one state of :func:`planargeo.scenes.articulated.articulated_state`:

* the links, the pins and the ground pin;
* every body's rigid inertia ``Iᵢ`` (grey) and articulated inertia ``Aᵢ`` (7.7a, purple)
  as conics (the real stand-ins of imaginary conics, 10.2.3), the focused body's bold;
* the acceleration pole ``a`` and, for the focused body ``k``, its axes of percussion
  ``Aₖa`` and ``Iₖa`` (5.64–5.68) and the polar of ``a`` with respect to the drawn real
  conic of ``Aₖ`` (10.2.3);
* a chart, on the right of the view: each entry of ``Aₖ`` at joint ``k`` over its full
  value against the recursion steps (10.2.2), with the truncation error.

:func:`fit_box` is the view of a chain's mechanism (shared with the splitting picture).

Examples
--------
>>> fit_box([[0.0, 0.0], [2.0, 0.0]], margin=0.0)
(0.0, 2.0, -1.0, 1.0)
"""
from __future__ import annotations

import numpy as np

__all__ = ["fit_box"]


def fit_box(mechanism, extra=(), margin: float = 0.15, reach: float = 3.0,
            least: float = 1.0) -> tuple[float, float, float, float]:
    """A square box about every finite point of ``mechanism`` and the ``extra`` points near it.

    An ``extra`` point (a pole, a centre) is kept when it lies within ``reach`` times the
    mechanism's size of its middle (a farther one gets its edge arrow).  The box spans at
    least ``least``, plus ``margin`` times its side on every side.

    Parameters
    ----------
    mechanism : array_like (m, 2)
        Points that must be in view.
    extra : array_like (k, 2)
        Points kept in view when near the mechanism.
    margin : float
        Margin on each side, a fraction of the box's side.
    reach : float
        How far (in mechanism sizes) an extra point may lie and still be kept in view.
    least : float
        Smallest side of the box (m).

    Returns
    -------
    tuple
        ``(x0, x1, y0, y1)``.
    """
    M = np.asarray(mechanism, dtype=float).reshape(-1, 2)
    M = M[np.all(np.isfinite(M), axis=1)]
    lo, hi = M.min(axis=0), M.max(axis=0)
    size = max(float(np.max(hi - lo)), least)
    E = np.asarray(extra, dtype=float).reshape(-1, 2)
    E = E[np.all(np.isfinite(E), axis=1)]
    if len(E):
        mid = 0.5 * (lo + hi)
        E = E[np.hypot(*(E - mid).T) <= reach * size]
        if len(E):
            lo, hi = np.minimum(lo, E.min(axis=0)), np.maximum(hi, E.max(axis=0))
    c, half = 0.5 * (lo + hi), 0.5 * max(float(np.max(hi - lo)), least)
    half = half * (1.0 + 2.0 * margin)
    return (float(c[0] - half), float(c[0] + half), float(c[1] - half), float(c[1] + half))
