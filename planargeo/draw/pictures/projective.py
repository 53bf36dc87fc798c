"""The projective playground's picture: a conic, a point and its polar, a line and its pole (thesis 5.2).

The conic ``C`` (5.35; an inertia as its dashed real stand-in), ``P`` and its polar ``C P``
(5.36), ``M`` and its pole ``C⁻¹ M`` (5.37), and the construction of 5.2.2 (Figs 5.2, 5.3).
Ideal elements are ordinary: ``P`` at infinity is an arrow at the edge of the view.

Examples
--------
>>> import numpy as np
>>> from planargeo.geometry.conics import conic_circle, polar, pole, classify
>>> C = conic_circle([0.0, 0.0], 1.0)
>>> P, M = np.array([0.0, -2.0, 1.0]), np.array([1.0, 0.0, -0.5])    # P = (2, 0); M: y = 0.5
>>> st = {"C": C, "P": P, "M": M, "type": classify(C), "polar": polar(C, P), "poleM": pole(C, M),
...       "tangents": None, "contacts": None, "interior": None}
>>> d = projective_picture(st, view=(-3, 3, -3, 3)).to_dict()
>>> els = {e["id"]: e for e in d["elements"]}
>>> els["polar"]["parts"][0]["xy"]            # x = 1/2: the polar of (2, 0) for the unit circle
[[0.5, 3.0], [0.5, -3.0]]
"""
from __future__ import annotations

import math

import numpy as np

from planargeo.draw.picture import Picture
from planargeo.draw.pictures._words import num, subscript, where
from planargeo.draw.pictures.common import builder, label_line, point_along
from planargeo.geometry.projective import is_at_infinity, is_ideal

__all__ = ["projective_picture"]

#: colour of the construction's contact points and poles
GREY = "#7F7F7F"


def _line_words(L) -> str:
    """A line in words: its distance from the origin and direction, or "the line at infinity"."""
    L = np.asarray(L, float)
    if bool(is_at_infinity(L)):
        return "the line at infinity"
    F = math.hypot(L[0], L[1])
    ang = math.degrees(math.atan2(L[1], L[0]))
    return f"{num(abs(L[2]) / F)} m from the origin, direction {num(ang)}°"


def _in_box(pic: Picture, p) -> bool:
    """True for a finite point inside the picture's view (drawn as a marker, not an edge arrow)."""
    p = np.asarray(p, float)
    if bool(is_ideal(p)):
        return False
    x, y = -p[1] / p[2], p[0] / p[2]          # [vx, vy, w] -> (x, y) (4.10)
    x0, x1, y0, y1 = pic.box
    return bool(x0 <= x <= x1 and y0 <= y <= y1)


@builder
def projective_picture(st: dict, *, construction: bool = True, line_and_pole: bool = True,
                       view=(-4.0, 4.0, -4.0, 4.0), size=(560, 540)) -> Picture:
    """The picture of one state of the projective playground (module docstring).

    Parameters
    ----------
    st : dict
        ``C``, ``type``, ``P``, ``polar``, ``M``, ``poleM``, and ``tangents`` and ``contacts``
        (P outside) or ``interior`` (:func:`~planargeo.geometry.conics.polar_construction_interior`).
    construction, line_and_pole : bool
        Draw the construction of 5.2.2; the line ``M`` and its pole.
    """
    pic = Picture(view, size=size)
    ctype = st["type"]
    imaginary = getattr(ctype, "reality", "real") == "imaginary"
    pic.conic("C", st["C"], role="inertia" if imaginary else "conic", symbol="C",
              desc=f"the conic C, QᵀCQ = 0 (5.35): {ctype}"
              + (" (no real points: drawn as its real stand-in, dashed)" if imaginary else ""))
    if construction:
        lines, points = [], []
        if st.get("tangents") is not None:
            lines = [(f"tangent {k + 1}", f"t{subscript(k + 1)}", st["tangents"][k], "tangent from P to the conic")
                     for k in range(2)]
            points = [(f"contact {k + 1}", f"X{subscript(k + 1)}", st["contacts"][k],
                       "where a tangent from P touches the conic") for k in range(2)]
            eq = "5.2.2, Fig 5.2"
        elif st.get("interior") is not None:
            K = st["interior"]
            if bool(np.all(np.isfinite(K.tangents)) and np.all(np.isfinite(K.poles))):
                lines = [(f"chord {i + 1}", f"c{subscript(i + 1)}", K.lines[i], "a chord of the conic through P")
                         for i in range(2)]
                lines += [(f"tangent {2 * i + j + 1}", f"t{subscript(2 * i + j + 1)}", K.tangents[i, j],
                           f"tangent at an end of chord c{subscript(i + 1)}") for i in range(2) for j in range(2)]
                points = [(f"chord end {2 * i + j + 1}", f"X{subscript(2 * i + j + 1)}", K.chord_points[i, j],
                           f"an end of chord c{subscript(i + 1)}") for i in range(2) for j in range(2)]
                points += [(f"chord pole {i + 1}", f"K{subscript(i + 1)}", K.poles[i],
                            f"pole K{subscript(i + 1)} of chord c{subscript(i + 1)}, where its tangents meet, "
                            "on the polar of P") for i in range(2)]
            eq = "5.2.2, Fig 5.3"
        for name, sym, L, meaning in lines:
            pic.line(name, L, role="construct", symbol=sym, label="", arrow=False,
                     desc=f"{meaning} ({eq}): {_line_words(L)}",
                     width=0.6 * 1.389 if name.startswith("chord") else None)
        for name, sym, p, meaning in points:
            # unlabelled in view (its tangent shows it); off view its edge arrow names it
            label = (f"pole of chord c{sym[-1]}" if name.startswith("chord pole")
                     else "" if _in_box(pic, p) else sym)
            point_along(pic, name, p, role="twist", color=GREY, size=5.5, symbol=sym, label=label,
                        desc=f"{meaning} ({eq}): {where(p)}")
    pic.line("polar", st["polar"], role="wrench", symbol="C P", label="", arrow=False,
             desc=f"polar of P, the line C P (5.36): {_line_words(st['polar'])}")
    label_line(pic, "polar", "polar of P")
    if line_and_pole:
        pic.line("M", st["M"], role="momentum", symbol="M", arrow=False, label="",
                 desc=f"the movable line M = [e, r] (5.55): {_line_words(st['M'])}")
        label_line(pic, "M", "M", side=-1.0)
        for q in pic.elements[-1]["parts"]:
            if q["p"] == "text" and "line at ∞" in q["text"]:     # not a couple here: the line itself
                q["text"] = "M at ∞"
        point_along(pic, "pole of M", st["poleM"], role="accel", glyph=False, symbol="C⁻¹ M", label="pole of M",
                  size=8.5, desc=f"pole C⁻¹ M of the line M (5.37): {where(st['poleM'])}")
    point_along(pic, "P", st["P"], role="twist", symbol="P", size=9.5,
              desc=f"the movable point P (5.49): {where(st['P'])}")
    return pic
