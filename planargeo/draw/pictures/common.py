"""Steps shared by the explorers' pictures: line labels, label directions, direction arrows, :func:`builder`.

Examples
--------
>>> from planargeo.draw.picture import Picture
>>> pic = Picture((-2, 2, -2, 2), size=(300, 300))
>>> pic.line("L", [1.0, 1.0, 0.0], label="", arrow=False)      # the line y = x
>>> label_line(pic, "L", "L")
>>> part = pic.elements[-1]["parts"][-1]
>>> part["text"], part["ha"], part["va"]                      # up and to the left of the line
('L', 'right', 'bottom')
>>> point_along(pic, "P", [1.0, 0.0, 0.0], symbol="P")          # the direction (0, 1): up
>>> arrow = pic.elements[-1]["parts"][0]
>>> arrow["dx"] == 0.0 and arrow["dy"] > 0
True
"""
from __future__ import annotations

import inspect
import math
import re

import numpy as np

from planargeo.draw._shared import view_centre
from planargeo.draw.picture import Picture, _align, _text_part
from planargeo.geometry.projective import is_ideal

__all__ = ["label_line", "label_toward", "point_along", "builder"]

#: what every picture builder's docstring ends with: the parameters all of them take, and the result
_BUILDER_DOC = {"view": "view : (x0, x1, y0, y1)\n    What must be in view.",
                "size": "size : (int, int)\n    Pixels.",
                "Returns": "\nReturns\n-------\nPicture"}


def builder(fn):
    """Mark ``fn`` as a picture builder: its docstring gets the ``view``, ``size`` and Returns it lacks.

    Parameters
    ----------
    fn : callable
        A function ``(state..., view, size) -> Picture`` whose docstring ends with its Parameters.

    Returns
    -------
    callable
        ``fn``, its docstring completed.
    """
    doc = inspect.cleandoc(fn.__doc__ or "")
    fn.__doc__ = "\n".join([doc] + [text for key, text in _BUILDER_DOC.items()
                                     if not re.search(rf"^{key}\b", doc, re.M)])
    return fn


def label_line(pic: Picture, id: str, text: str, *, anchor=None, gap: float = 7.0,
               side: float = 1.0, end: float | None = None) -> None:
    """Label the line element ``id`` ``gap`` pixels off it, aligned away from it, near ``anchor``.

    Parameters
    ----------
    pic, id, text
    anchor : (float, float), optional
        Near which point of the line (default: the view's centre).
    gap : float
    side : float
        +1: above the line (right of a vertical one); -1: below it.
    end : float, optional
        Keep the label at least this many pixels from the drawn segment's ends (default: within
        its middle 80 %).
    """
    el = next(e for e in pic.elements if e["id"] == id)
    seg = next((p["xy"] for p in el["parts"] if p["p"] == "path"), None)
    if seg is None or not text:
        return
    seg = np.asarray(seg, float)
    a = view_centre(pic) if anchor is None else np.asarray(anchor, float)
    d = seg[1] - seg[0]
    dp = np.array([d[0] * pic.kx, d[1] * pic.ky])
    Lp = max(math.hypot(*dp), 1e-300)
    lo = 0.1 if end is None else min(end / Lp, 0.5)
    t = 0.5 if float(d @ d) == 0 else float(np.clip((a - seg[0]) @ d / float(d @ d), lo, 1.0 - lo))
    foot = seg[0] + t * d
    n = np.array([-dp[1], dp[0]]) / Lp
    if n[1] < -1e-9 or (abs(n[1]) <= 1e-9 and n[0] < 0):
        n = -n
    n = n * side
    el["parts"].append(_text_part(foot[0], foot[1], text, n[0] * gap, n[1] * gap, *_align(n),
                                   along=dp / Lp))


def point_along(pic: Picture, id: str, p, **kw) -> None:
    """A point as :meth:`Picture.point` (``**kw``); an ideal one's edge arrow points along its direction.

    (:meth:`Picture.point` draws a translation's pole, its arrow across the pole's direction.)

    Parameters
    ----------
    pic, id, p, **kw
    """
    kw.setdefault("glyph", False)
    pic.point(id, p, **kw)
    p = np.asarray(p, float)
    if not bool(is_ideal(p)) or not np.any(p):
        return
    el = pic.elements[-1]
    arrow = next((q for q in el["parts"] if q["p"] == "arrow"), None)
    if arrow is None:
        return
    L = math.hypot(arrow["dx"], arrow["dy"])
    mid = np.array([arrow["x"] + arrow["dx"] / 2 / pic.kx, arrow["y"] + arrow["dy"] / 2 / pic.ky])
    dirn = np.array([-p[1] * pic.kx, p[0] * pic.ky])
    dirn /= math.hypot(*dirn)
    arrow["x"] = float(mid[0] - dirn[0] * L / 2 / pic.kx)
    arrow["y"] = float(mid[1] - dirn[1] * L / 2 / pic.ky)
    arrow["dx"], arrow["dy"] = float(dirn[0] * L), float(dirn[1] * L)


def label_toward(el: dict, u, gap: float = 9.0) -> None:
    """Put the label of the point element ``el`` ``gap`` pixels from it in the pixel direction ``u``.

    Parameters
    ----------
    el, u, gap
    """
    u = np.asarray(u, float)
    u = u / max(math.hypot(*u), 1e-300)
    for part in el["parts"]:
        if part["p"] == "text":
            part["dx"], part["dy"] = float(u[0] * gap), float(u[1] * gap)
            part["ha"], part["va"] = _align(u)
            return


def labelled_line(pic, id: str, l, text: str, *, anchor=None, side: float = 1.0, ahead: float = 0.0,
                  gap: float = 7.0, end: float | None = None, **kw) -> dict:
    """The line ``l`` (:meth:`Picture.line`, ``**kw``) labelled ``text`` beside it; its element.

    The arrow sits near ``anchor``, the label ``ahead`` (data units) from it along the force, ``gap``
    pixels on ``side`` +1 (above) or -1 (below), ``end`` pixels or more from the drawn ends
    (:func:`label_line`); a couple's glyph is labelled ``text: couple``.
    """
    l = np.asarray(l, dtype=float)
    couple = l[0] == 0.0 and l[1] == 0.0
    pic.line(id, l, label=text if couple else "", anchor=anchor, **kw)
    if not couple:
        if anchor is not None and ahead:
            anchor = np.asarray(anchor, dtype=float) + ahead * l[:2] / math.hypot(l[0], l[1])
        label_line(pic, id, text, anchor=anchor, side=side, gap=gap, end=end)
    return pic.elements[-1]
