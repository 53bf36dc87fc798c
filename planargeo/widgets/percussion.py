"""Inertia and percussion explorer: the sweet spot of thesis 5.4.

A body at rest (a preset shape or a polygon) has an inertia ``I``, drawn as its radius-of-gyration
circle; ``I`` maps an acceleration pole ``a`` to the force ``f = I a`` that produces it, the
*axis of percussion* (5.64-5.67), at ``r = ρ²/d`` beyond the centre of mass (5.68).  Drive by
the pole (drag it, or drag the axis and the pole follows, ``a = I⁻¹ f``) or by an impact across
the body: struck at the sweet spot, it starts turning about the grip.
"""
from __future__ import annotations

import math

import ipywidgets as W
import numpy as np
from shapely.geometry import Point as SPoint
from shapely.geometry import Polygon, box

from planargeo.draw.pictures.percussion import percussion_numbers, percussion_picture
from planargeo.errors import DegenerateGeometryError, InputError, InvalidPolygonError
from planargeo.screws.inertia import Inertia, percussion_axis, percussion_pole
from planargeo.geometry.projective import from_xy, is_ideal
from planargeo.draw.pictures._words import num
from planargeo.widgets.readout import point_value
from planargeo.widgets._explorer import Described, HeldView, xy_handle
from planargeo.widgets.base import Explorer, Handle, Step, cached

__all__ = ["PercussionExplorer", "PRESETS", "parse_polygon"]

#: Preset shapes (shapely, metres); the grip / pivot of the story is at the origin.
PRESETS = {
    "bat": Polygon([(0.0, -0.016), (0.35, -0.018), (0.6, -0.03), (0.86, -0.034), (0.86, 0.034),
                    (0.6, 0.03), (0.35, 0.018), (0.0, 0.016)]),
    "uniform rod": box(0.0, -0.04, 1.0, 0.04),
    "disc": SPoint(0.5, 0.0).buffer(0.4, quad_segs=32),
    "L-shape": Polygon([(0, -0.05), (1.0, -0.05), (1.0, 0.45), (0.9, 0.45), (0.9, 0.05), (0, 0.05)]),
    "custom polygon": None,
}


def parse_polygon(text: str) -> Polygon:
    """A shapely polygon from ``"x, y; x, y; ..."`` (at least three vertices).

    Parameters
    ----------
    text : str
        Vertices ``"x, y; x, y; ..."``.

    Returns
    -------
    shapely.geometry.Polygon

    Raises
    ------
    InvalidPolygonError
        Fewer than three vertices, unreadable numbers, vertices on one line, or a self-intersecting
        outline.

    Examples
    --------
    >>> parse_polygon("0,0; 1,1; 1,0; 0,1")
    Traceback (most recent call last):
    ...
    planargeo.errors.InvalidPolygonError: polygon must be a simple (non self-intersecting) area, got '0,0; 1,1; 1,0; 0,1'
    >>> parse_polygon("0,0; 1,0")
    Traceback (most recent call last):
    ...
    planargeo.errors.InvalidPolygonError: polygon needs at least three vertices x, y (m), got '0,0; 1,0', 2 of them
    """
    try:
        pts = [tuple(float(c) for c in item.replace(" ", "").split(","))
               for item in text.strip().strip(";").split(";") if item.strip()]
    except ValueError:
        raise InvalidPolygonError(f"polygon must be numbers, vertices x, y (m) separated by ';' "
                                  f"as in 0,0; 1,0; 0,1, got {text!r}") from None
    if not pts:
        raise InvalidPolygonError("polygon is empty: type at least three vertices x, y (m) separated "
                                  "by ';', as in 0,0; 1,0; 0,1")
    if any(len(p) != 2 for p in pts):
        raise InvalidPolygonError(f"polygon: each vertex is two numbers x, y (m), vertices separated by "
                                  f"';', got {text!r}")
    if len(pts) < 3:
        raise InvalidPolygonError(f"polygon needs at least three vertices x, y (m), got {text!r}, {len(pts)} of them")
    poly = Polygon(pts)
    if poly.convex_hull.area <= 0:
        raise InvalidPolygonError(f"polygon must enclose an area (its vertices lie on one line), got {text!r}")
    if not poly.is_valid or poly.area <= 0:
        raise InvalidPolygonError(f"polygon must be a simple (non self-intersecting) area, got {text!r}")
    return poly


def pole_words(a) -> str:
    """Where the pole ``a`` (``[a, b, w]``, thesis 5.49) is, in words.

    Examples
    --------
    >>> pole_words([0.0, 18.2, 1.0]), pole_words([1.0, 0.0, 0.0])
    ('at (-18.2, 0) m', 'at infinity (direction (0, 1))')
    """
    p = point_value(a)
    return p if isinstance(p, str) else f"at ({num(p[0])}, {num(p[1])}) m"


class PercussionExplorer(HeldView, Described, Explorer):
    """Acceleration pole and axis of percussion of a body at rest (thesis 5.4).

    Parameters
    ----------
    **kw
        Keyword arguments of :class:`~planargeo.widgets.base.Explorer`.
    """

    title = "Inertia and percussion: the sweet spot"
    slug = "percussion"
    figsize = (6.0, 4.8)
    limits = (-0.9, 1.6, -0.9, 0.9)
    #: the scene is 1 m across: numbers below 0.1 mm are round-off left by a drag (the pole set
    #: from a dragged axis: −1.468e-07 m), and read 0
    zero_tol = 1e-4
    display_controls = ("angular accel. α",)

    def make_controls(self):
        return {
            "pole x": Step(-1.5, 2.0, 0.01, 0.0, "pole of a: x (m)"),
            "pole y": Step(-1.2, 1.2, 0.01, 0.0, "pole of a: y (m)"),
            "impact at": Step(-0.5, 1.5, 0.005, 0.5, "impact at x (m)"),
            "drive": W.ToggleButtons(options=("acceleration pole", "impact"),
                                     value="acceleration pole", description="drive"),
            "shape": W.Dropdown(options=list(PRESETS), value="bat", description="shape"),
            "polygon": W.Text(value="0,-0.05; 1,-0.05; 1,0.05; 0,0.05", description="polygon",
                              continuous_update=False,
                              tooltip="vertices 'x, y; x, y; ...' (used with shape = custom polygon)"),
            "mass (kg)": Step(0.1, 5.0, 0.05, 1.0, "mass (kg)"),
            "angular accel. α": Step(-50, 50, 0.5, 10.0, "α (rad/s²)",
                                     tip="angular acceleration α of the body (rad/s²)"),
        }

    def __init__(self, **kw):
        super().__init__(**kw)
        # a greyed pole slider shows no number: the impact's pole is elsewhere (its tooltip says where)
        for name in ("pole x", "pole y"):
            w = self.controls[name]
            w.readout = not w.disabled
            w.observe(lambda ch, w=w: setattr(w, "readout", not ch["new"]), names="disabled")

    def disabled(self, values):
        out = {}
        if values["drive"] == "impact":
            a = None if self.state is None else self.state["a"]
            at = "" if a is None else f", now {pole_words(a)}"
            reason = (f"not used: the impact sets the pole (a = I⁻¹f){at}; choose drive = acceleration pole "
                      "to move it")
            out["pole x"] = out["pole y"] = reason
        else:
            out["impact at"] = "only the impact drive strikes the body: choose drive = impact"
        if values["shape"] != "custom polygon":
            out["polygon"] = "used with shape = custom polygon"
        return out

    def _axis_points(self, f=None):
        """(point on the axis ``f`` (the shown one by default) nearest ``c``, a second point on it),
        or None (no finite axis): where its two handles are."""
        st = self.state
        if st is None:
            return None
        f, c = st["f"] if f is None else f, st["c"]
        F = math.hypot(f[0], f[1])
        if F == 0.0:
            return None
        e = np.array([f[0], f[1]]) / F
        dist = (f[2] + c[1] * f[0] - c[0] * f[1]) / (F * F)
        foot = c - dist * np.array([-f[1], f[0]])
        return foot, foot + 0.35 * e

    def _pole_for_axis(self, f):
        """Control values whose acceleration pole has ``f`` as its axis (``a = I⁻¹ f``); refused where
        a handle of the axis would leave what the view can show (:meth:`_reach`)."""
        x0, x1, y0, y1 = self._reach()
        for what, p in zip(("axis point", "axis direction handle"), self._axis_points(f) or ()):
            if not (x0 <= p[0] <= x1 and y0 <= p[1] <= y1):
                px, py = num(round(float(p[0]), 2)), num(round(float(p[1]), 2))
                raise InputError(f"this axis puts its {what} at ({px}, {py}) m, out of the picture's reach: "
                                 f"it shows the handles within the pole sliders' range, x from {num(x0)} to "
                                 f"{num(x1)} m and y from {num(y0)} to {num(y1)} m")
        a = percussion_pole(self.state["I"].matrix, f)
        if bool(is_ideal(a)) or abs(a[2]) <= 1e-12 * float(np.abs(a).max()):
            raise DegenerateGeometryError("an axis through the centre of mass has its pole at "
                                          "infinity (a pure translation), where the pole sliders "
                                          "cannot go: to see it, choose drive = impact and strike "
                                          "at the centre of mass")
        x, y = float(-a[1] / a[2]), float(a[0] / a[2])
        for name, v in (("pole x", x), ("pole y", y)):
            w = self.controls[name]
            if not w.min <= v <= w.max:
                raise InputError(f"this axis needs the pole of a at {name[-1]} = {v:.3g} m, beyond "
                                 f"its slider ({w.min:g} to {w.max:g} m)")
        return {"pole x": x, "pole y": y}

    def _drag_axis_point(self, x, y):
        f = self.state["f"]
        return self._pole_for_axis(np.array([f[0], f[1], -(y * f[0] - x * f[1])]))

    def _drag_axis_direction(self, x, y):
        foot = self._axis_points()[0]
        d = np.array([x, y]) - foot
        if math.hypot(*d) < 1e-9:
            raise DegenerateGeometryError("the direction handle is on the axis point: no direction there")
        return self._pole_for_axis(np.array([d[0], d[1], -(foot[1] * d[0] - foot[0] * d[1])]))

    def handles(self):
        pole_drive = lambda: self.state is not None and self.values["drive"] == "acceleration pole"
        axis = lambda k: (tuple(self._axis_points()[k]) if pole_drive() and self._axis_points()
                          is not None else None)
        pole = xy_handle(self, "a", "pole x", "pole y", when=pole_drive)
        return [
            Handle(pole.name, pole.where, self.holding(pole.drag)),
            Handle("axis (point)", lambda: axis(0), self.holding(self._drag_axis_point)),
            Handle("axis (direction)", lambda: axis(1),
                   self.holding(self._drag_axis_direction)),
            Handle("impact", lambda: None if pole_drive() or self.state is None
                   else (self.values["impact at"], 0.0),
                   self.holding(lambda x, y: {"impact at": x})),
        ]

    def _reach(self):
        """``(x0, x1, y0, y1)``: where a handle can be and stay in the view (the pole sliders' box,
        which :meth:`mechanism_points` fits the view to)."""
        px, py = self.controls["pole x"], self.controls["pole y"]
        return (px.min, px.max, py.min, py.max)

    def _shape_inertia(self, v):
        """The shape and its unit-density inertia ``I0`` (5.64), integrated once per shape."""
        key = (v["shape"], v["polygon"] if v["shape"] == "custom polygon" else None)

        def integrate():
            shape = parse_polygon(v["polygon"]) if key[1] is not None else PRESETS[key[0]]
            return shape, Inertia.from_polygon(shape)

        return cached(self._cache("_inertias"), key, integrate)

    def compute(self, values, changed):
        self.drag_or_fit()              # a control, Play or reset: the view fits the state again
        shape, I0 = self._shape_inertia(values)
        m = float(values["mass (kg)"])

        def scaled():      # uniform lamina of mass m: the unit-density inertia scaled by m / area (1.65 is linear)
            I = Inertia(I0.matrix * (m / float(I0.mass)))
            c = np.array(I.com, dtype=float)
            c.flags.writeable = False
            return I0, I, c, float(I.radius_of_gyration), float(I.mass)

        # kept per shape and mass (the entry holds I0: its id stays its own), for drags of the pole or impact
        _I0, I, c, rho, mass = cached(self._cache("_scaled"), (id(I0), m), scaled)
        Imat = I.matrix
        if values["drive"] == "impact":
            s = float(values["impact at"])
            f = np.array([0.0, 1.0, s])             # unit force along +y through (s, 0) (5.56)
            a = percussion_pole(Imat, f)
            line = f
        else:
            a = from_xy([values["pole x"], values["pole y"]])
            line = percussion_axis(Imat, a)
        return {"shape": shape, "I": I, "c": c, "a": a, "f": line, "rho": rho, "mass": mass}

    def readout_of(self, state):
        c = state["c"]
        nums = percussion_numbers(state)
        rho, m, P, d = nums["rho"], nums["mass"], nums["P"], nums["d"]
        impact = self.values["drive"] == "impact"
        out = {} if impact else {"pole x": self.values["pole x"], "pole y": self.values["pole y"]}
        out.update({"mass m": m, "radius of gyration ρ": rho, "centre of mass": tuple(c)})
        out["pole"] = point_value(state["a"])
        out["d = |pole − c|"] = d
        if nums["spot"] is not None:
            r = nums["r"]
            out["r = ρ²/d (5.68)"] = r
            out["l = d + ρ²/d (5.67)"] = d + r
            out["angular accel. α"] = float(self.values["angular accel. α"])
            out["force for α: m d α (5.66)"] = m * d * float(self.values["angular accel. α"])
            out["centre of percussion"] = tuple(nums["spot"])
        else:
            out["r = ρ²/d (5.68)"] = 0.0 if P is None else math.inf
            out["l = d + ρ²/d (5.67)"] = math.inf
            out["force for α: m d α (5.66)"] = "pure couple" if P is not None else "—"
            out["centre of percussion"] = "—"
        # the sweet spot of the grip (origin): where a strike makes the body turn about the grip
        grip_spot = nums["grip_spot"]
        out["sweet spot of the grip"] = "—" if grip_spot is None else tuple(grip_spot)
        if impact:
            out["impact at"] = self.values["impact at"]
            out["pole distance from grip"] = "at infinity" if P is None else float(np.hypot(*P))
        return out

    def scene_picture(self, state, view=None):
        return percussion_picture(state, impact=self.values["drive"] == "impact",
                                  view=view or self.held_view or self._view(state), size=self.figure_px)

    #: the view's step (m)
    _STEP = 0.25

    def mechanism_points(self):
        # the outline, the grip and the handles within the pole's reach (a pole near c sends the
        # axis far away: it is drawn clipped)
        st = self.state
        pts = [np.zeros((1, 2))]
        if st is not None:
            pts.append(np.asarray(st["shape"].exterior.coords, float))
        px, py = self.controls["pole x"], self.controls["pole y"]
        for h in self.handles():
            xy = h.where()
            if xy is not None and px.min <= xy[0] <= px.max and py.min <= xy[1] <= py.max:
                pts.append(np.asarray(xy, float).reshape(1, 2))
        return np.vstack(pts)

    def _view(self, st):
        """The view: body, grip and handles in reach, 0.25 m around, square, in steps of 0.25 m."""
        pts = self.mechanism_points()
        lo, hi = pts.min(axis=0) - self._STEP, pts.max(axis=0) + self._STEP
        # as tall as wide (and the other way): the whole mechanism fits either way round
        grow = np.maximum(0.0, float(np.max(hi - lo)) - (hi - lo)) / 2
        lo, hi = lo - grow, hi + grow
        lo = np.floor(lo / self._STEP + 1e-9) * self._STEP
        hi = np.ceil(hi / self._STEP - 1e-9) * self._STEP
        return (float(lo[0]), float(hi[0]), float(lo[1]), float(hi[1]))

    _fitted_view = _view                  # (HeldView)
