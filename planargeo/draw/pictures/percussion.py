"""The percussion explorer's picture: a body, its inertia, a pole and its axis of percussion (thesis 5.4).

The inertia ``I`` as its circle of gyration, the pole ``a`` and the axis ``f = I a`` (5.64),
the line ``a``–``c`` and the centre of percussion ``ρ²/d`` beyond ``c`` (5.68), or the
grip's sweet spot when driven by an impact (5.67).

Examples
--------
>>> import numpy as np
>>> from shapely.geometry import box
>>> from planargeo.screws.inertia import Inertia, percussion_axis
>>> I = Inertia.from_polygon(box(-1.0, -0.05, 1.0, 0.05))     # a rod 2 m long, c at the origin
>>> a = np.array([0.0, 1.0, 1.0])                               # the pole at its end (-1, 0)
>>> st = {"shape": box(-1.0, -0.05, 1.0, 0.05), "I": I, "c": np.zeros(2), "a": a,
...       "f": percussion_axis(I.matrix, a)}
>>> d = percussion_picture(st, view=(-1.5, 1.5, -1, 1)).to_dict()
>>> els = {e["id"]: e for e in d["elements"]}
>>> x = els["axis of percussion"]["parts"][0]["xy"][0][0]; round(x, 4)   # ρ²/d = (4/12 + ...)/1
0.3342
"""
from __future__ import annotations

import math

import numpy as np

from planargeo.draw.picture import Picture
from planargeo.draw.pictures._words import num, pair, where
from planargeo.draw.pictures.common import builder, label_line
from planargeo.draw.pictures.kit import label_at
from planargeo.draw.style import COLORS
from planargeo.geometry.projective import from_xy, is_ideal

__all__ = ["percussion_picture", "percussion_numbers"]


def percussion_numbers(st: dict) -> dict:
    """The construction's points and lengths: pole ``P``, ``d``, ``r``, centre of percussion, grip's sweet spot.

    Parameters
    ----------
    st : dict
        ``I`` (:class:`~planargeo.screws.inertia.Inertia`), ``c`` (centre of mass), ``a`` (pole);
        optionally ``rho``, ``mass`` (``I``'s, already found).

    Returns
    -------
    dict
        ``P``, ``d``, ``rho``, ``mass``, ``r``, ``spot``, ``grip_spot`` (None where undefined).
    """
    I, c, a = st["I"], np.asarray(st["c"], float), np.asarray(st["a"], float)
    rho = st["rho"] if "rho" in st else float(I.radius_of_gyration)
    out = {"rho": rho, "mass": st["mass"] if "mass" in st else float(I.mass), "P": None, "d": math.inf, "r": None,
           "spot": None}
    if not bool(is_ideal(a)):
        P = np.array([-a[1] / a[2], a[0] / a[2]])
        d = float(np.hypot(*(P - c)))
        out.update(P=P, d=d)
        if d > 1e-9 * max(rho, 1e-300):
            r = rho * rho / d
            out.update(r=r, spot=c + (c - P) / d * r)      # where the axis crosses the line pole-c (5.68)
    d0 = float(np.hypot(*c))
    out["grip_spot"] = c + c / d0 * (rho * rho / d0) if d0 > 0 else None
    return out


@builder
def percussion_picture(st: dict, *, impact: bool = False, view, size=(600, 480)) -> Picture:
    """The picture of one state of the percussion explorer (module docstring).

    Parameters
    ----------
    st : dict
        ``shape`` (shapely polygon), ``I``, ``c``, ``a`` (the pole), ``f`` (the axis of percussion).
    impact : bool
        Driven by an impact: the grip's sweet spot is marked.
    """
    pic = Picture(view, size=size)
    nums = percussion_numbers(st)
    c, a, f = np.asarray(st["c"], float), st["a"], st["f"]
    rho = nums["rho"]
    pic.path("body", np.asarray(st["shape"].exterior.coords), role="body", closed=True,
             fill=COLORS["body"], color="#000000", width=1.0 * 1.389, alpha=0.6, z=2,
             symbol="body", desc=f"the body, a uniform lamina (5.64): mass m = {num(nums['mass'])} kg, "
                                 f"area {num(st['shape'].area)} m²")
    pic.marks("grip", [[0.0, 0.0]], role="body", shape="s", size=9.0, color=COLORS["ground"], z=3,
              symbol="grip", desc="the grip, where the hands hold the body: at the origin (0, 0) m")
    label_at(pic, (0.0, 0.0), "grip", gap=-7.0, ha="right", va="top")
    pic.conic("I", st["I"].matrix, role="inertia", symbol="I", label="ρ", mark_center=False,
              desc=f"inertia I as its circle of gyration (5.4, 1.65): radius ρ = {num(rho)} m")
    if nums["spot"] is not None:
        pic.line("join", np.cross(a / a[2], from_xy(c)), role="construct", arrow=False, label="", symbol="ac",
                 desc="the line from the pole a through the centre of mass c (5.68): "
                      f"d = |a − c| = {num(nums['d'])} m")
    F = math.hypot(f[0], f[1])
    pic.line("axis of percussion", f, role="wrench", symbol="f = I a", label="",
             anchor=nums["spot"] if nums["spot"] is not None else c,
             desc="axis of percussion f = I a (5.64): "
                  + (f"r = ρ²/d = {num(nums['r'])} m beyond c" if nums["r"] is not None else
                     "a pure couple (the pole is at c)" if F == 0 else "through c (the pole is at infinity)"))
    if F > 0:   # the label near the axis's upper end, clear of the body and of the spot's label
        up = np.array([f[0], f[1]]) / F * (1.0 if (f[1], f[0]) >= (0.0, 0.0) else -1.0)
        label_line(pic, "axis of percussion", "axis of percussion f = I a", anchor=c + 1e3 * up)
    grip_spot = impact and nums["grip_spot"] is not None
    s = nums["grip_spot"] if grip_spot else nums["spot"]
    if s is not None:
        name = "sweet spot" if grip_spot else "centre of percussion"
        where_ = f"at {pair(s)} m"
        pic.marks("spot", [s], role="wrench", shape="D", size=10.0, color=COLORS["wrench"], z=6, symbol=name,
                  desc=f"sweet spot of the grip (5.67): strike there and the hands feel no sting, {where_}"
                  if grip_spot else f"centre of percussion (5.68): where the axis crosses the line a–c, {where_}")
        label_at(pic, s, name, gap=7.0, dy=-7.0 if grip_spot else -11.0, va="top")
    pic.point("c", from_xy(c), role="twist", glyph=False, color="#000000", size=6.5, symbol="c",
              desc=f"centre of mass c (1.65): at {pair(c)} m")
    pic.point("a", a, role="accel", glyph_scale=0.3, size=9.5, symbol="a",
              desc=f"acceleration pole a (5.64): the point of the body with no acceleration, {where(a)}")
    return pic
