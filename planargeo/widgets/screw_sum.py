"""Twist and wrench addition explorer (thesis 4.2 and 4.4).

Two twists (rotations about a pole, or translations) add to a twist whose pole
lies on the line joining the two poles, at the lever ratio ``β = ω2/(ω1+ω2)``
(4.11-4.13); a rotation plus a translation is a rotation shifted by
``ρ = u/ω`` (4.16); two opposite rotations make a translation (an ideal pole).

Dually, two wrenches (forces on lines, or couples) add to a wrench whose line
passes through the meet of the two lines (4.4.1); parallel forces follow the
lever rule (4.4.2), a force plus a couple is a parallel force shifted by
``ρ = τ/F`` (4.4.3), and equal opposite parallel forces make a couple (the
line at infinity).

All the arithmetic is :func:`planargeo.screws.add_twists` /
:func:`planargeo.screws.add_wrenches`; this module only draws it.
"""
from __future__ import annotations

import math

import ipywidgets as W
import numpy as np

from planargeo.draw.artists import LineArtist, PointArtist
from planargeo.screws.twists import Twist, Wrench, add_twists, add_wrenches
from planargeo.widgets.base import Explorer, Step

__all__ = ["ScrewSumExplorer"]

_TWIST_KINDS = ("rotation", "translation")
_WRENCH_KINDS = ("force", "couple")


def _xy_or_ideal(p):
    if p is None:
        return "none"
    if p[2] == 0:
        return "at infinity"
    return (float(-p[1] / p[2]), float(p[0] / p[2]))


def _same_line(a, b, rtol: float = 1e-9) -> bool:
    """Two forces (not couples) on one line: proportional wrenches ``a × b = 0`` (5.21)."""
    a, b = np.asarray(a, float), np.asarray(b, float)
    Fa, Fb = np.hypot(a[0], a[1]), np.hypot(b[0], b[1])
    if Fa == 0 or Fb == 0:
        return False
    return bool(np.all(np.abs(np.cross(a, b)) <= rtol * np.linalg.norm(a) * np.linalg.norm(b)))


def _meet_label(c):
    """Where the two force lines meet: a point, at infinity (parallel lines) or the common line."""
    if c.P is not None and _same_line(c.f1.array, c.f2.array):
        return "every point of their common line"
    return _xy_or_ideal(c.P)


class ScrewSumExplorer(Explorer):
    """Add two twists (points) or two wrenches (lines) and watch the construction."""

    title = "Twist and wrench addition"
    slug = "screw-sum"
    figsize = (5.6, 5.0)
    limits = (-4, 4, -4, 4)

    def make_controls(self):
        kinds = W.ToggleButtons(options=("twists", "wrenches"), value="twists", description="add")
        c = {"add": kinds}
        for k, (x, y, mag, ang) in ((1, (-1.5, 0.0, 1.0, 0.0)), (2, (1.5, 0.5, 2.0, 90.0))):
            c[f"kind{k}"] = W.Dropdown(options=_TWIST_KINDS + _WRENCH_KINDS, value="rotation",
                                       description=f"screw {k}")
            c[f"x{k}"] = Step(-3, 3, 0.05, x, f"x{k}").make(f"x{k}")
            c[f"y{k}"] = Step(-3, 3, 0.05, y, f"y{k}").make(f"y{k}")
            c[f"size{k}"] = Step(-3, 3, 0.05, mag, f"size{k}").make(f"size{k}")
            c[f"angle{k}"] = Step(-180, 180, 5, ang, f"angle{k} (deg)").make(f"angle{k}")
        return c

    def adjust(self, values, changed):
        """Keep the kinds consistent with the mode (twists: rotation/translation...)."""
        if "add" not in changed:
            return {}
        mapping = {"twists": {"force": "rotation", "couple": "translation"},
                   "wrenches": {"rotation": "force", "translation": "couple"}}[values["add"]]
        return {f"kind{k}": mapping[values[f"kind{k}"]] for k in (1, 2)
                if values[f"kind{k}"] in mapping}

    def make_artists(self, ax):
        z = np.array([0.0, 0.0, 1.0])
        zl = np.array([1.0, 0.0, 0.0])
        self.q1 = ax.add_artist(PointArtist(z, role="twist", text="v1"))
        self.q2 = ax.add_artist(PointArtist(z, role="twist", text="v2"))
        self.p3 = ax.add_artist(PointArtist(z, role="accel", text="v1+v2"))
        self.join = ax.add_artist(LineArtist(zl, role="construct", scale=None))
        self.l1 = ax.add_artist(LineArtist(zl, role="wrench", scale=0.5, text="f1"))
        self.l2 = ax.add_artist(LineArtist(zl, role="wrench", scale=0.5, text="f2",
                                           corner="upper left"))
        self.l3 = ax.add_artist(LineArtist(zl, role="reaction", scale=0.5, text="f1+f2",
                                           corner="lower right"))
        self.meet = ax.add_artist(PointArtist(z, role="twist", glyph=False, color="#7F7F7F"))

    def _screw(self, v, k):
        kind = v[f"kind{k}"]
        x, y, m = v[f"x{k}"], v[f"y{k}"], v[f"size{k}"]
        a = math.radians(v[f"angle{k}"])
        d = (m * math.cos(a), m * math.sin(a))
        if kind == "rotation":
            return Twist.rotation((x, y), m)
        if kind == "translation":
            return Twist.translation(d)
        if kind == "force":
            return Wrench.force((x, y), d)
        return Wrench.couple(m)

    def compute(self, v, changed):
        mode = v["add"]
        s1, s2 = self._screw(v, 1), self._screw(v, 2)
        if mode == "twists":
            if isinstance(s1, Wrench) or isinstance(s2, Wrench):
                s1, s2 = Twist(s1.array), Twist(s2.array)
            return {"mode": mode, "c": add_twists(s1, s2)}
        if isinstance(s1, Twist) or isinstance(s2, Twist):
            s1, s2 = Wrench(s1.array), Wrench(s2.array)
        return {"mode": mode, "c": add_wrenches(s1, s2)}

    def render(self, st):
        c = st["c"]
        tw = st["mode"] == "twists"
        for a in (self.q1, self.q2, self.p3, self.join):
            a.set_visible(tw)
        for a in (self.l1, self.l2, self.l3, self.meet):
            a.set_visible(not tw)
        v = self.values
        out = {"x1": v["x1"]}
        if tw:
            self.q1.set_point(c.v1.array)
            self.q2.set_point(c.v2.array)
            if c.P is None:
                self.p3.set_visible(False)
            else:
                self.p3.set_point(c.sum.array)
            if c.line is None:
                self.join.set_visible(False)
            else:
                self.join.set_line(c.line)
            out.update({"case": c.case, "ω1": c.omega1, "ω2": c.omega2, "ω1+ω2": c.omega3,
                        "pole of sum": _xy_or_ideal(c.P)})
        else:
            self.l1.set_line(c.f1.array)
            self.l2.set_line(c.f2.array)
            self.l1.set_anchor((v["x1"], v["y1"]))
            self.l2.set_anchor((v["x2"], v["y2"]))
            meet = _xy_or_ideal(c.P)
            self.l3.set_anchor(meet if isinstance(meet, tuple) else
                               (0.5 * (v["x1"] + v["x2"]), 0.5 * (v["y1"] + v["y2"])))
            if c.L3 is None:
                self.l3.set_visible(False)
            else:
                self.l3.set_line(c.sum.array)
            if c.P is None or c.P[2] == 0:
                self.meet.set_visible(False)
            else:
                self.meet.set_point(c.P)
            out.update({"case": c.case, "F1": c.F1, "F2": c.F2, "|F1+F2|": c.F3,
                        "meet of lines": _meet_label(c)})
        out.update({"β": "—" if c.beta is None else c.beta, "ρ": "—" if c.rho is None else c.rho,
                    "sum": tuple(float(x) for x in c.sum.array)})
        return out
