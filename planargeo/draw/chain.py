"""The picture of a chain's solved state, built natively (no matplotlib): links, poles, forces, inertias.

From the articulated-body workspace of one state (:func:`planargeo.scenes.chain.chain_workspace`),
per body or joint as the overlays ask (:data:`LAYERS`): velocity and acceleration poles, bias
terms, joint forces, their T/U split and the articulated inertias, each with its symbol,
equation and value shown on hover.  A focus fades every element but one link's or joint's.

Examples
--------
>>> from planargeo.mechanics.model import chain_model
>>> from planargeo.scenes.chain import chain_workspace
>>> w = chain_workspace(chain_model(3), [0.3, -0.2, 0.1], [1.0, 0.0, 0.0], [0.0, 0.0, 0.0])
>>> pic = chain_picture(w, overlays={"velocity poles": True}, view=(-3.5, 3.5, -3.5, 3.5))
>>> sorted(e["symbol"] for e in pic.to_dict()["elements"] if e["role"] == "twist")
['v₁', 'v₂', 'v₃']
"""
from __future__ import annotations

import math

import numpy as np

from planargeo.draw.picture import Picture
from planargeo.draw.pictures._words import subscript
from planargeo.draw.style import COLORS

__all__ = ["chain_picture", "OVERLAYS", "LAYERS"]

OVERLAYS = ("velocity poles", "acceleration poles", "bias terms", "internal forces",
            "T/U split", "articulated inertias")

#: key of the data (its symbol) | overlay | kind | per link or joint | role | colour's role |
#: equation | unit, and below, the meaning
_TABLE = """
f  | internal forces      | line  | joint | wrench   | wrench   | 3.13 | N
     force the joint passes on to the body outboard
v  | velocity poles       | point | link  | twist    | twist    | 4.5  | rad/s
     velocity pole of the link (its instant centre)
a  | acceleration poles   | point | link  | accel    | accel    | 4.6  | rad/s²
     acceleration pole of the link
TQ | T/U split            | line  | joint | wrench   | wrench   | 6.38 | N
     active part of the joint force, along the percussion axis
Rμ | T/U split            | line  | joint | reaction | reaction | 6.38 | N
     reaction part of the joint force, through the joint
sψ | T/U split            | point | joint | accel    | accel    | 6.44 | rad/s²
     part of the acceleration along the joint's motion space
Uγ | T/U split            | point | joint | accel    | reaction | 6.44 | rad/s²
     reactive part of the acceleration
κ  | bias terms           | point | link  | accel    | momentum | 3.38 | rad/s²
     bias acceleration of the link
p  | bias terms           | line  | link  | momentum | momentum | 3.38 | N
     bias force of the link
A  | articulated inertias | conic | link  | inertia  | inertia  | 3.38 |
     articulated inertia of the link, as a conic
"""
_ROWS = _TABLE.strip().splitlines()
#: (key of the data, overlay, symbol, kind, per body or joint, role, colour, meaning, equation, unit)
LAYERS = tuple((key, overlay, key, kind, per, role, COLORS[colour], meaning.strip(), eq, unit)
               for (key, overlay, kind, per, role, colour, eq, unit), meaning in
               zip(([c.strip() for c in row.split("|")] for row in _ROWS[::2]), _ROWS[1::2]))
#: the ground under the base, relative to it (NaN-separated strokes)
_GROUND = np.vstack([[[-0.4, -0.1], [0.4, -0.1], [np.nan, np.nan]]]
                    + [[[x, -0.1], [x - 0.1, -0.2], [np.nan, np.nan]] for x in np.linspace(-0.35, 0.4, 6)])
#: opacity of the elements outside the focus
FADED = 0.18


def _where(p) -> str:
    w = float(p[2])
    if w != 0.0:                              # planargeo.draw.geometry.point_xy, on floats
        x, y = -float(p[1]) / w, float(p[0]) / w
        if math.isfinite(x) and math.isfinite(y):   # round-off below a nanometre and −0 read 0
            x, y = (0.0 if abs(v) < 1e-9 else v for v in (x, y))
            return f"at ({x:.3g}, {y:.3g}) m"
    return "at infinity"


def _value(kind: str, x, unit: str) -> str:
    if kind == "point":
        return f"rate {float(x[2]):.3g} {unit}, {_where(x)}"
    if kind == "line":
        fx, fy = float(x[0]), float(x[1])
        return f"|force| {math.hypot(fx, fy):.3g} {unit}" + (" (a couple)" if fx == 0.0 and fy == 0.0 else "")
    return ""


def chain_picture(w, *, overlays: dict, view, split: dict | None = None, focus=None,
                  size=(560, 540), ends=None, time: float | None = None) -> Picture:
    """The picture of one state of a chain (module docstring).

    Parameters
    ----------
    w : Data
        The state's articulated-body workspace (``origin``, ``pose``, ``com``, ``v``, ``a``,
        ``kappa``, ``p``, ``f``, ``A``).
    overlays : dict
        ``{overlay name: shown}`` for the names of :data:`OVERLAYS`.
    view : (x0, x1, y0, y1)
        What must be in view.
    split : dict, optional
        The T/U split (``active``, ``reaction``, ``active_on``, ``motion``, ``reactive``),
        needed when the "T/U split" overlay is on.
    focus : ("link" | "joint", i), optional
        The element kept bright; the rest is faded.
    size : (int, int)
        Pixels.
    ends : array_like (N, 2), optional
        The far ends of the links (default: the next joint; the last one link length on).
    time : float, optional
        The state's time (s), written in the lower right corner.

    Returns
    -------
    Picture
    """
    n = len(w.pose)
    pic = Picture(view, size=size, ticks=False, margin=(6, 6, 6, 30))
    if ends is None:
        ends = np.vstack([w.pose[1:, :2], w.pose[-1:, :2] + (w.pose[-1, :2] - w.pose[-2, :2]
                                                              if n > 1 else [1.0, 0.0])])
    chain = np.empty((2 * n + 1, 2))
    chain[0] = w.origin[0]
    chain[1::2] = w.pose[:, :2]
    chain[2::2] = ends
    base = np.asarray(w.origin[0], float)
    pic.path("ground", base + _GROUND, role="ground", color=COLORS["ground"], width=1.6,
             desc="the ground: the base is pinned to it", z=4)
    pic.path("links", chain, role="body", color=COLORS["ground"], width=3.4,
             desc=f"the chain's {n} links", z=5)
    pic.marks("joints", w.pose[:, :2], role="body", color=COLORS["ground"], size=6.0,
              desc="the joints", z=6)
    data = {"f": w.f, "v": w.v, "a": w.a, "κ": w.kappa, "p": w.p, "A": w.A}
    if split:
        data.update({"TQ": split["active"], "Rμ": split["reaction"], "sψ": split["motion"],
                     "Uγ": split["reactive"]})
    anchors = {"joint": w.pose[:, :2].tolist(), "link": np.asarray(w.com, float).tolist()}
    subs = [subscript(i + 1) for i in range(n)]
    on = split["active_on"].tolist() if split else [True] * n
    point, line, conic = pic.point, pic.line, pic.conic
    for key, flag, sym, kind, per, role, color, meaning, eq, unit in LAYERS:
        if not overlays.get(flag) or key not in data:
            continue
        arr = data[key] if kind == "conic" else np.asarray(data[key], float).tolist()   # floats: cheap rows
        glyph, scale, at = key in ("v", "a"), 4.0 if key == "v" else 1.0, anchors[per]
        dash = [1.5, 2.5] if key == "TQ" else None
        head = f"{meaning} ({eq}): "
        for i in range(n):
            if key == "TQ" and not on[i]:
                continue
            desc = head + _value(kind, arr[i], unit)
            if focus is not None and focus != (per, i):
                label, opacity = "", FADED
            else:
                label, opacity = None, 1.0
            if kind == "point":
                point(f"{key}{i + 1}", arr[i], glyph=glyph, glyph_scale=scale, role=role, color=color,
                      symbol=sym + subs[i], desc=desc, label=label, opacity=opacity)
            elif kind == "line":
                line(f"{key}{i + 1}", arr[i], anchor=at[i], dash=dash and list(dash), role=role,
                     color=color, symbol=sym + subs[i], desc=desc, label=label, opacity=opacity)
            else:
                conic(f"{key}{i + 1}", arr[i], role=role, color=color, symbol=sym + subs[i], desc=desc,
                      label=label, opacity=opacity)
    if time is not None:
        x1, y0 = pic.box[1], pic.box[2]
        pic.text("time", (x1, y0), f"t = {time:.2f} s", ha="right", va="bottom", dx=-6.0, dy=4.0,
                 symbol="t", desc=f"time since the state the controls set: {time:.2f} s")
    return pic
