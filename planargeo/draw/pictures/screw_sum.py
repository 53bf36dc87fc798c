"""The screw-sum explorer's picture: two twists (points) or wrenches (lines) and their sum (thesis 4.2, 4.4).

Twists: the poles, the lever line ``Q₁Q₂`` and the sum's pole on it (4.11–4.13); wrenches:
the lines of action, their meet ``P`` and the sum's line through it (4.33).

Examples
--------
>>> from planargeo.screws.twists import Twist, add_twists
>>> c = add_twists(Twist.rotation((0.0, 0.0), 1.0), Twist.rotation((4.0, 0.0), 3.0))
>>> d = screw_sum_picture("twists", c, view=(-4, 4, -4, 4)).to_dict()
>>> els = {e["id"]: e for e in d["elements"]}
>>> v3 = els["v3"]["parts"][0]; (v3["x"], v3["y"])        # 3/4 of the way from Q₁ to Q₂ (4.12)
(3.0, 0.0)
"""
from __future__ import annotations

import math

import numpy as np

from planargeo.draw.picture import FONT_PX, PX_PER_PT, Picture, _glyph_radius
from planargeo.draw.pictures._words import num, subscript, where
from planargeo.draw.pictures.common import builder, label_toward, labelled_line
from planargeo.draw.style import COLORS, SUM
from planargeo.draw.sums import _label_sides
from planargeo.geometry.projective import is_at_infinity, is_ideal

__all__ = ["screw_sum_picture"]

def _twist_words(t, k) -> str:
    w = float(t[2])
    if w == 0.0:
        return f"a translation, u{subscript(k)} = {num(math.hypot(t[0], t[1]))} m/s, its pole {where(t)}"
    return f"ω{subscript(k)} = {num(w)} rad/s, {where(t)}"


def _wrench_words(f, k) -> str:
    if bool(is_at_infinity(f)):
        return f"a couple, τ{subscript(k)} = {num(f[2])} N·m (the line at infinity)"
    F = math.hypot(f[0], f[1])
    return f"|F{subscript(k)}| = {num(F)} N, {num(abs(f[2]) / F)} m from the origin"


def _glyph_gap(w: float) -> float:
    """Pixels from a pole to its label: clear of its rotation glyph (which grows with |ω|)."""
    return (6.0 + _glyph_radius(w)) * PX_PER_PT * 0.8


@builder
def screw_sum_picture(mode: str, c, *, anchors=None, view, size=(560, 500), arms=None) -> Picture:
    """The picture of one sum (module docstring).

    Parameters
    ----------
    mode : {"twists", "wrenches"}
    c : Data
        :func:`~planargeo.screws.twists.add_twists` or ``add_wrenches``.
    anchors : ((x1, y1), (x2, y2)), optional
        Wrenches: where the arrows sit on their lines.
    arms : ((x, y), (x, y)) or None per term, optional
        Twists: a translation's velocity ``u`` drawn as an arrow from this point, one unit long
        (where its direction is dragged), labelled ``u₁`` / ``u₂``.
    """
    pic = Picture(view, size=size)
    if mode == "twists":
        _twists(pic, c)
        for k, (t, foot) in enumerate(zip((c.v1.array, c.v2.array), arms or (None, None)), start=1):
            if foot is not None and bool(is_ideal(t)):
                _velocity_arm(pic, k, t, foot)
    else:
        _wrenches(pic, c, anchors)
    return pic


#: length (data units) of a translation's velocity arrow (the explorer's direction handle sits at its tip)
ARM = 1.0


def _velocity_arm(pic: Picture, k: int, t, foot) -> None:
    """Translation ``t`` (term ``k``) drawn as its velocity ``u`` from ``foot``, :data:`ARM` long: the
    direction handle at its tip has a meaning to show (a translation moves every point alike, so
    any foot would do)."""
    u = np.array([float(t[0]), float(t[1])])
    speed = math.hypot(*u)
    if not speed > 0:
        return
    d = u / speed
    a, b = np.asarray(foot, float), np.asarray(foot, float) + ARM * d
    s = subscript(k)
    px = np.array([d[0] * pic.kx, d[1] * pic.ky])
    px = px / math.hypot(*px)
    pic.path(f"u{k}", [a, b], role="twist", symbol=f"u{s}", label=f"u{s}", width=1.6 * PX_PER_PT,
             desc=(f"translation u{s} of v{s} (4.10): {num(speed)} m/s at "
                   f"{num(math.degrees(math.atan2(d[1], d[0])))}°, every point moving with it (drawn from "
                   f"({num(a[0])}, {num(a[1])}) m: any point would do); drag its tip to turn it"))
    head = 10.0                                        # the head's length (px), ending at the tip
    pic.elements[-1]["parts"].append({"p": "arrow", "x": float(b[0] - head * px[0] / pic.kx),
                                      "y": float(b[1] - head * px[1] / pic.ky),
                                      "dx": float(head * px[0]), "dy": float(head * px[1])})
    n = np.array([-px[1], px[0]])
    n = n if (n[1], n[0]) >= (0.0, 0.0) else -n            # beside the arrow's middle, above (or right)
    label_toward(pic.elements[-1], tuple(n), 8.0)
    for part in pic.elements[-1]["parts"]:
        if part["p"] == "text":
            part["x"], part["y"] = float((a[0] + b[0]) / 2), float((a[1] + b[1]) / 2)


def _twists(pic: Picture, c) -> None:
    q1, q2 = np.asarray(c.Q1, float), np.asarray(c.Q2, float)
    if c.line is not None:
        pic.line("lever", c.line, role="construct", arrow=False, label="", symbol="Q₁Q₂",
                 desc="lever line Q₁Q₂ through both poles (4.11): the sum's pole lies on it")
        for part in pic.elements[-1]["parts"]:      # two translations: their poles' join is the line at ∞
            if part["p"] == "text":
                part["text"] = "Q₁Q₂: the line at ∞"
    u1, u2, u3 = _label_sides(pic, q1, q2, apart=c.line is not None)
    if c.P is not None:
        u1, u2, u3 = _beside_the_line(pic, (c.v1.array, c.v2.array, c.sum.array), (u1, u2, u3))
    for k, t, u in ((1, c.v1.array, u1), (2, c.v2.array, u2)):
        pic.point(f"v{k}", t, role="twist", symbol=f"v{subscript(k)}",
                  desc=f"twist v{subscript(k)} (4.10): {_twist_words(t, k)}")
        if not bool(is_ideal(t)):
            label_toward(pic.elements[-1], u, _glyph_gap(t[2]))
    if c.P is not None:
        s = c.sum.array
        pic.point("v3", s, role="twist", symbol="v₃ = v₁ + v₂", shape="D",
                  size=SUM["point"]["markersize"] * PX_PER_PT,
                  desc=f"sum v₃ = v₁ + v₂ (4.11–4.13): {_twist_words(s, 3)}")
        if not bool(is_ideal(s)):
            label_toward(pic.elements[-1], u3, _glyph_gap(s[2]) + 3.0)
    _edge_labels_off_the_poles(pic)


def _beside_the_line(pic: Picture, twists, sides):
    """Label directions (px) of ``v₁, v₂, v₃`` when one term is a translation: the other term's pole and
    the sum's lie on one line through it (4.11), so their labels go to either side of that line, not
    along it (one label would fall on the other pole)."""
    finite = [k for k in (0, 1) if not bool(is_ideal(twists[k]))]
    s = twists[2]
    if len(finite) != 1 or bool(is_ideal(s)):
        return sides
    t = twists[finite[0]]
    d = np.array([(-s[1] / s[2] + t[1] / t[2]) * pic.kx, (s[0] / s[2] - t[0] / t[2]) * pic.ky])
    if not math.hypot(*d) > 1e-9:
        return sides
    n = np.array([-d[1], d[0]]) / math.hypot(*d)
    n = n if (n[1], n[0]) >= (0.0, 0.0) else -n             # the term's label above (or right of) the line
    out = list(sides)
    out[finite[0]], out[2] = tuple(n), tuple(-n)
    return tuple(out)


def _text_box(pic: Picture, p) -> tuple:
    """Pixel box ``(x0, y0, x1, y1)`` of a text part (from the plot area's lower left), estimated."""
    bw, bh = 0.6 * FONT_PX * len(p["text"]), 1.25 * FONT_PX
    qx = (p["x"] - pic.box[0]) * pic.kx + p["dx"] - {"left": 0.0, "center": 0.5, "right": 1.0}[p["ha"]] * bw
    qy = (p["y"] - pic.box[2]) * pic.ky + p["dy"] - {"bottom": 0.0, "center": 0.5, "top": 1.0}[p["va"]] * bh
    return qx, qy, qx + bw, qy + bh


#: pixels a label at the view's edge keeps from another pole's glyph (beyond the glyph itself): a
#: label nearer another pole than its own arrow reads as that pole's ("v₂ at ∞" above v₃)
EDGE_LABEL_CLEARANCE = FONT_PX


def _edge_labels_off_the_poles(pic: Picture) -> None:
    """Move a translation's label at the view's edge ("v₂ at ∞") above or below its arrow when a
    pole's glyph, or another label, is drawn over it or next to it (within
    :data:`EDGE_LABEL_CLEARANCE`) where it stands (beside the arrow)."""
    glyphs = [(p["x"], p["y"], p.get("r", 0.0) + 2.0 + EDGE_LABEL_CLEARANCE)
              for e in pic.elements for p in e["parts"] if p["p"] in ("glyph", "mark")]
    texts = [p for e in pic.elements for p in e["parts"] if p["p"] == "text"]

    def clear(p) -> bool:
        x0, y0, x1, y1 = _text_box(pic, p)
        for gx, gy, r in glyphs:
            cx, cy = (gx - pic.box[0]) * pic.kx, (gy - pic.box[2]) * pic.ky
            if math.hypot(cx - min(max(cx, x0), x1), cy - min(max(cy, y0), y1)) <= r:
                return False
        for q in texts:
            if q is not p:
                a0, b0, a1, b1 = _text_box(pic, q)
                if min(x1, a1) - max(x0, a0) > 0.5 and min(y1, b1) - max(y0, b0) > 0.5:
                    return False
        return True

    for e in pic.elements:
        arrows = [p for p in e["parts"] if p["p"] == "arrow"]
        for p in e["parts"]:
            if p["p"] != "text" or not p["text"].endswith(" at ∞") or not arrows or clear(p):
                continue
            a = arrows[0]
            reach = abs(a["dy"]) / 2 + 3.0        # past the arrow's end (px), then a row on
            tries = [(va, sign * (reach + row * 1.25 * FONT_PX)) for row in range(4)
                     for va, sign in (("bottom", 1.0), ("top", -1.0))]
            # above or below, the label starts (ends, is centred) over the arrow, not beside it
            foot = (a["x"] - p["x"]) * pic.kx
            dx = {"left": foot + min(0.0, a["dx"]) - 2.0, "right": foot + max(0.0, a["dx"]) + 2.0,
                  "center": foot + a["dx"] / 2}[p["ha"]]
            for va, dy in tries:
                moved = dict(p, va=va, dx=dx, dy=p["dy"] + dy)
                if clear(moved):
                    p.update(moved)
                    break


def _lower(pic: Picture, rows: int) -> None:
    """Move the couple glyph just drawn ``rows`` rows down (one per couple drawn before it)."""
    for part in pic.elements[-1]["parts"]:
        if part["p"] in ("text", "glyph"):
            part["y"] -= rows * 30.0 / pic.ky


def _wrenches(pic: Picture, c, anchors) -> None:
    anchors = anchors or (None, None)
    couples = 0
    for k, f, a in ((1, c.f1.array, anchors[0]), (2, c.f2.array, anchors[1])):
        sym = f"f{subscript(k)}"        # labelled a metre on along the force from its arrow (clear of P)
        labelled_line(pic, f"f{k}", f, sym, role="wrench", symbol=sym, anchor=a, ahead=1.0,
                      side=1.0 if k == 1 else -1.0,
                      desc=f"wrench {sym} on its line of action (4.27): {_wrench_words(f, k)}")
        if bool(is_at_infinity(f)):
            _lower(pic, couples)
            couples += 1
    P = c.P
    if P is not None and not bool(is_ideal(P)):
        pic.point("P", P, role="twist", glyph=False, color=COLORS["construct"], symbol="P",
                  desc=f"meet P = L₁ × L₂ of the two lines (5.34): {where(P)}")
    if c.L3 is not None:
        s = c.sum.array
        anchor = None if P is None or bool(is_ideal(P)) else [-P[1] / P[2], P[0] / P[2]]
        labelled_line(pic, "f3", s, "f₃ = f₁ + f₂", role="wrench", symbol="f₃ = f₁ + f₂",
                      anchor=anchor, ahead=1.5, side=-1.0, gap=9.0, width=SUM["line"]["linewidth"] * PX_PER_PT,
                      desc=f"sum f₃ = f₁ + f₂ (4.33): {_wrench_words(s, 3)}")
        if bool(is_at_infinity(s)):
            _lower(pic, couples)
