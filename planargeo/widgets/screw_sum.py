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
:func:`planargeo.screws.add_wrenches`; this module only draws it.  The readout
names the special case reached (:mod:`planargeo.screws.special`, thesis 10.2.4):
dragging or sliding into it passes through the ideal element (a pole at
infinity, parallel lines meeting at infinity, a couple) without an error.

Handles (under ``%matplotlib widget``, or :meth:`Explorer.drag` in tests): the
poles ``v1``, ``v2`` of rotations; the directions ``v1 direction``,
``v2 direction`` of translations; the force lines ``f1``, ``f2`` by a point
and ``f1 direction``, ``f2 direction`` by the tip of their arrow.

Examples
--------
>>> ex = ScrewSumExplorer(display="agg", add="wrenches")
>>> ex.readout_values["special case"]
'concurrent forces: the sum passes through their meet (4.4.1)'
>>> _ = ex.drag("f2 direction", ex.handle_position("f2 direction"), (2.5, 0.5))  # turned parallel to f1
>>> ex.readout_values["special case"], ex.readout_values["meet of lines"], ex.message
('parallel forces: the lines meet at infinity, lever rule (4.43)', 'at infinity', '')
"""
from __future__ import annotations

import math

import ipywidgets as W
import numpy as np

from planargeo.draw.artists import LineArtist, PointArtist
from planargeo.draw.style import sum_style
from planargeo.errors import InputError
from planargeo.screws.special import twists_case, wrenches_case
from planargeo.screws.twists import Twist, Wrench, add_twists, add_wrenches
from planargeo.widgets.base import Explorer, Handle, Step

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


#: length of a direction handle's arm (data units), from the screw's point
ARM = 1.0


class ScrewSumExplorer(Explorer):
    """Add two twists (points) or two wrenches (lines) and watch the construction (thesis 4.2, 4.4).

    Controls: ``add`` (twists or wrenches), and per screw ``k = 1, 2`` its kind,
    point ``(xk, yk)`` [m], size (``ω`` [rad/s], speed [m/s], force [N] or
    moment [N·m]) and direction ``anglek`` [deg].  The readout gives the
    construction's numbers with units and the special case by name.

    Parameters
    ----------
    **kwargs
        As :class:`~planargeo.widgets.base.Explorer` (``display``, initial control values).

    Raises
    ------
    InputError
        An unknown control or a value it does not take.
    """

    title = "Twist and wrench addition"
    slug = "screw-sum"
    figsize = (5.6, 5.0)
    limits = (-4, 4, -4, 4)
    scale = 3.0
    units = {"x1": "m", "ω1": "rad/s", "ω2": "rad/s", "ω1+ω2": "rad/s", "pole of sum": "m",
             "F1": "N", "F2": "N", "|F1+F2|": "N", "meet of lines": "m", "β": "—", "ρ": "m",
             "case": "—", "special case": "—", "sum": "—"}

    def make_controls(self):
        """The mode ``add`` and, per screw, its kind, point, size and direction.

        Returns
        -------
        dict
        """
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
        """Keep the kinds consistent with the mode (twists: rotation/translation...).

        Parameters
        ----------
        values : dict
            The control values.
        changed : set
            The controls that changed.

        Returns
        -------
        dict
            Kinds that follow a change of ``add``.
        """
        if "add" not in changed:
            return {}
        mapping = {"twists": {"force": "rotation", "couple": "translation"},
                   "wrenches": {"rotation": "force", "translation": "couple"}}[values["add"]]
        return {f"kind{k}": mapping[values[f"kind{k}"]] for k in (1, 2)
                if values[f"kind{k}"] in mapping}

    def setup_axes(self, ax):
        """The base's axes, with ticks every 2 m (drawing ticks was half of a redraw).

        Parameters
        ----------
        ax : matplotlib.axes.Axes
        """
        from matplotlib.ticker import MultipleLocator

        super().setup_axes(ax)
        for axis in (ax.xaxis, ax.yaxis):
            axis.set_major_locator(MultipleLocator(2.0))

    def make_artists(self, ax):
        """The poles, the lever line, the force lines and their meet, made once.

        Parameters
        ----------
        ax : matplotlib.axes.Axes
        """
        z = np.array([0.0, 0.0, 1.0])
        zl = np.array([1.0, 0.0, 0.0])
        self.q1 = ax.add_artist(PointArtist(z, role="twist", text="$v_1$"))
        self.q2 = ax.add_artist(PointArtist(z, role="twist", text="$v_2$"))
        self.p3 = ax.add_artist(PointArtist(z, role="twist", text="$v_3 = v_1 + v_2$",
                                            **sum_style("point")))
        self.join = ax.add_artist(LineArtist(zl, role="construct", scale=None))
        self.l1 = ax.add_artist(LineArtist(zl, role="wrench", scale=0.5, text="$f_1$"))
        self.l2 = ax.add_artist(LineArtist(zl, role="wrench", scale=0.5, text="$f_2$",
                                           corner="upper left"))
        self.l3 = ax.add_artist(LineArtist(zl, role="wrench", scale=0.5, text="$f_3 = f_1 + f_2$",
                                           corner="lower right", **sum_style("line")))
        self.meet = ax.add_artist(PointArtist(z, role="twist", glyph=False, color="#7F7F7F",
                                              text="$P$"))

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
        """The sum's construction (:func:`~planargeo.screws.twists.add_twists` or ``add_wrenches``).

        Parameters
        ----------
        v : dict
            The control values.
        changed : set
            The controls that changed.

        Returns
        -------
        dict
            ``{"mode", "c"}``.

        Raises
        ------
        PlanargeoError
            A zero screw (named), or a sum beyond double precision.
        """
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
        """Update the artists and return the readout (numbers with units, the special case).

        Parameters
        ----------
        st : dict
            The computed state.

        Returns
        -------
        dict
        """
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
            self._place_twist_labels(c)
            out.update({"case": c.case, "ω1": c.omega1, "ω2": c.omega2, "ω1+ω2": c.omega3,
                        "pole of sum": _xy_or_ideal(c.P),
                        "special case": twists_case(c.v1, c.v2).text})
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
                        "meet of lines": _meet_label(c),
                        "special case": wrenches_case(c.f1, c.f2).text})
        out.update({"β": "—" if c.beta is None else c.beta, "ρ": "—" if c.rho is None else c.rho,
                    "sum": tuple(float(x) for x in c.sum.array)})
        return out

    def _place_twist_labels(self, c):
        """Labels of v₁, v₂ on one side of the lever line Q₁Q₂, the sum's on the other side.

        Each label sits clear of its rotation glyph (which grows with ``|ω|``);
        coincident poles spread the three labels around the common pole.
        """
        def gap(w):
            return 6.0 + min(max(6.0 * abs(w), 4.0), 16.0)

        q1, q2 = c.Q1, c.Q2
        if c.line is None or q1[2] == 0 or q2[2] == 0:
            u1, u2, u3 = (-0.7, 0.7), (0.7, 0.7), (0.0, -1.0)
        else:
            d = np.array([-q2[1] + q1[1], q2[0] - q1[0]])          # Q2 - Q1 in (x, y)
            d = d / np.hypot(*d)
            n = np.array([-d[1], d[0]]) if d[0] >= 0 else np.array([d[1], -d[0]])  # upward side
            u1 = u2 = tuple(n)
            u3 = tuple(-n)
        for art, p, u, w in ((self.q1, q1, u1, c.omega1), (self.q2, q2, u2, c.omega2),
                             (self.p3, c.P, u3, c.omega3)):
            if p is None or p[2] == 0:      # an ideal pole: the artist's own label at the edge
                art.set_text_offset(None)
            else:
                art.set_text_beside(self._inward(p, u), gap(w) + (2.0 if art is self.p3 else 0.0))

    def _inward(self, p, u):
        """``u`` turned toward the view's centre for a point near a side (its label stays in view)."""
        x0, x1 = self.ax.get_xlim()
        x = float(-p[1] / p[2])
        half = (x1 - x0) / 2
        off = (x - (x0 + x1) / 2) / half
        if abs(off) > 0.45 and u[0] * off >= -0.35:
            ux = -0.75 if off > 0 else 0.75
            return (ux, 0.66 * (1.0 if u[1] >= 0 else -1.0))
        return u

    # ------------------------------------------------------------------ handles
    def handles(self) -> list[Handle]:
        """The draggable poles, force lines (by a point) and directions (by an arm's tip).

        ``v1``, ``v2``: the pole of a rotation (sets ``xk``, ``yk``);
        ``v1 direction``, ``v2 direction``: a translation's direction (``anglek``);
        ``f1``, ``f2``: a point of a force line (``xk``, ``yk``);
        ``f1 direction``, ``f2 direction``: the tip of an arm of length
        :data:`ARM` along the force (``anglek``).  A handle of a screw of
        another kind, or of the other mode, is not draggable (``where()`` is None).

        Returns
        -------
        list of Handle
        """
        out = []
        for k in (1, 2):
            out += [Handle(f"v{k}", self._where(k, "rotation", False), self._move(k)),
                    Handle(f"v{k} direction", self._where(k, "translation", True), self._turn(k)),
                    Handle(f"f{k}", self._where(k, "force", False), self._move(k)),
                    Handle(f"f{k} direction", self._where(k, "force", True), self._turn(k))]
        return out

    def handle_position(self, name: str):
        """Current data position of handle ``name`` (None: not draggable now).

        Parameters
        ----------
        name : str

        Returns
        -------
        (float, float) or None

        Raises
        ------
        InputError
            No handle of that name.
        """
        for h in self.handles():
            if h.name == name:
                return h.where()
        raise InputError(f"name must name a handle of ScrewSumExplorer, got {name!r}")

    def _where(self, k: int, kind: str, arm: bool):
        def where():
            v = self.shown_values or self.values
            if v.get(f"kind{k}") != kind:
                return None
            x, y = v[f"x{k}"], v[f"y{k}"]
            if not arm:
                return (x, y)
            a = math.radians(v[f"angle{k}"])
            sign = -1.0 if (kind == "force" and v[f"size{k}"] < 0) else 1.0
            return (x + sign * ARM * math.cos(a), y + sign * ARM * math.sin(a))
        return where

    def _move(self, k: int):
        def drag(x, y):
            return {f"x{k}": x, f"y{k}": y}
        return drag

    def _turn(self, k: int):
        def drag(x, y):
            v = self.shown_values or self.values
            dx, dy = x - v[f"x{k}"], y - v[f"y{k}"]
            if dx == 0 and dy == 0:
                raise InputError(f"angle{k}: the direction handle is on the screw's point, "
                                 f"which gives no direction")
            if v[f"kind{k}"] == "force" and v[f"size{k}"] < 0:
                dx, dy = -dx, -dy          # the arm points along the force, not along the angle
            return {f"angle{k}": math.degrees(math.atan2(dy, dx))}
        return drag
