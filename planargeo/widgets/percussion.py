"""Inertia and percussion explorer: the sweet spot of thesis 5.4.

A body at rest (a preset shape or your own polygon) has an inertia ``I``, an
imaginary conic drawn as its radius-of-gyration circle.  ``I`` maps an
acceleration pole ``a`` (a point) to the force ``f = I a`` (a line) that
produces it: the *axis of percussion* of ``a`` (5.64-5.67).  It is
perpendicular to the line from ``a`` to the centre of mass, on the far side,
at ``r = ρ²/d`` from the centre of mass (5.68).

Two ways to play:

``drive = "acceleration pole"``
    move the pole (sliders, or drag it under ``%matplotlib widget``); the axis
    of percussion follows;
``drive = "impact"``
    strike the body with a force across its long axis at a chosen place; the
    pole of the resulting acceleration follows (``a = I⁻¹ f``).  Strike at
    the sweet spot and the body starts turning exactly about the grip: the
    hands feel no sting.

The polygon is integrated once per shape (its area, centroid and polar
moment); the inertia is linear in the mass, so a change of mass, pole or
impact point needs no integration.  The angular acceleration ``α`` only
enters the readout (``m d α``, 5.66): changing it only redraws.
"""
from __future__ import annotations

import math

import ipywidgets as W
import numpy as np
from matplotlib.lines import Line2D
from matplotlib.patches import Polygon as MplPolygon
from shapely.geometry import Point as SPoint
from shapely.geometry import Polygon, box

from planargeo.draw.artists import ConicArtist, LineArtist, PointArtist
from planargeo.draw.style import COLORS
from planargeo.errors import InvalidPolygonError
from planargeo.screws.inertia import Inertia, percussion_axis, percussion_pole
from planargeo.geometry.projective import from_xy
from planargeo.widgets.base import Explorer, Step, cached

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

    Raises :class:`~planargeo.errors.InvalidPolygonError` naming ``polygon``.

    Examples
    --------
    >>> parse_polygon("0, 0; 2, 0; 0, 1").area
    1.0
    >>> parse_polygon("0,0; 1,1; 1,0; 0,1")
    Traceback (most recent call last):
    ...
    planargeo.errors.InvalidPolygonError: polygon must be a simple (non self-intersecting) area, got '0,0; 1,1; 1,0; 0,1'
    """
    try:
        pts = [tuple(float(c) for c in item.replace(" ", "").split(","))
               for item in text.strip().strip(";").split(";") if item.strip()]
    except ValueError:
        raise InvalidPolygonError(f"polygon must be 'x, y; x, y; ...', got {text!r}") from None
    if len(pts) < 3 or any(len(p) != 2 for p in pts):
        raise InvalidPolygonError(f"polygon needs at least three 'x, y' vertices, got {text!r}")
    poly = Polygon(pts)
    if not poly.is_valid or poly.area <= 0:
        raise InvalidPolygonError(f"polygon must be a simple (non self-intersecting) area, got {text!r}")
    return poly


class PercussionExplorer(Explorer):
    """Acceleration pole and axis of percussion of a body at rest (thesis 5.4)."""

    title = "Inertia and percussion: the sweet spot"
    slug = "percussion"
    figsize = (6.0, 4.8)
    limits = (-0.9, 1.6, -0.9, 0.9)
    display_controls = ("angular accel. α",)

    def __init__(self, **kw):
        self._inertias: dict = {}   # shape key -> (shape, unit-density Inertia)
        super().__init__(**kw)

    def make_controls(self):
        return {
            "pole x": Step(-1.5, 2.0, 0.01, 0.0, "pole x").make("pole x"),
            "pole y": Step(-1.2, 1.2, 0.01, 0.0, "pole y").make("pole y"),
            "impact at": Step(-0.5, 1.5, 0.005, 0.5, "impact at (x)").make("impact at"),
            "drive": W.ToggleButtons(options=("acceleration pole", "impact"),
                                     value="acceleration pole", description="drive"),
            "shape": W.Dropdown(options=list(PRESETS), value="bat", description="shape"),
            "polygon": W.Text(value="0,-0.05; 1,-0.05; 1,0.05; 0,0.05", description="polygon",
                              continuous_update=False,
                              tooltip="vertices 'x, y; x, y; ...' (used with shape = custom polygon)"),
            "mass (kg)": Step(0.1, 5.0, 0.05, 1.0, "mass (kg)").make("mass"),
            "angular accel. α": Step(-50, 50, 0.5, 10.0, "angular accel. α").make("alpha"),
        }

    def make_artists(self, ax):
        self.body = MplPolygon(np.zeros((3, 2)), closed=True, fc=COLORS["body"], ec="black",
                               alpha=0.6, zorder=2)
        ax.add_patch(self.body)
        self.grip = Line2D([0.0], [0.0], marker="s", ms=7, color=COLORS["ground"], ls="none", zorder=3)
        ax.add_line(self.grip)
        z = np.array([0.0, 0.0, 1.0])
        self.gyration = ax.add_artist(ConicArtist(np.eye(3), role="inertia", text="ρ"))
        self.pole_art = ax.add_artist(PointArtist(z, role="accel", glyph_scale=0.3, text="a",
                                                  markersize=7))
        self.axis_art = ax.add_artist(LineArtist([0.0, 1.0, 0.0], role="wrench", scale=None,
                                                 text="axis of percussion f = I a"))
        self.join_art = ax.add_artist(LineArtist([1.0, 0.0, 0.0], role="construct", scale=None))
        self.spot = Line2D([], [], marker="*", ms=12, color=COLORS["wrench"], mec="black",
                           ls="none", zorder=6)
        ax.add_line(self.spot)

    def connect_mouse(self):
        self.connect_drag("pole x", "pole y", lambda: (self.values["pole x"], self.values["pole y"]))

    def _shape(self, v):
        return self._shape_inertia(v)[0]

    def _shape_inertia(self, v):
        """The shape and its unit-density inertia ``I0`` (5.64), integrated once per shape."""
        key = (v["shape"], v["polygon"] if v["shape"] == "custom polygon" else None)
        return cached(self._inertias, key, lambda: self._integrate(key, v))

    @staticmethod
    def _integrate(key, v):
        shape = parse_polygon(v["polygon"]) if key[1] is not None else PRESETS[key[0]]
        return shape, Inertia.from_polygon(shape)

    def compute(self, v, changed):
        shape, I0 = self._shape_inertia(v)
        m = float(v["mass (kg)"])
        # uniform lamina of mass m: the unit-density inertia scaled by m / area (1.65 is linear)
        I = Inertia(I0.matrix * (m / float(I0.mass)))
        c = np.asarray(I.com, dtype=float)
        Imat = I.matrix
        if v["drive"] == "impact":
            s = float(v["impact at"])
            f = np.array([0.0, 1.0, s])             # unit force along +y through (s, 0) (5.56)
            a = percussion_pole(Imat, f)
            line = f
        else:
            a = from_xy([v["pole x"], v["pole y"]])
            line = percussion_axis(Imat, a)
        return {"shape": shape, "I": I, "c": c, "a": a, "f": line}

    def render(self, st):
        I, c, a, f = st["I"], st["c"], st["a"], st["f"]
        shape = st["shape"]
        self.body.set_xy(np.asarray(shape.exterior.coords))
        self.gyration.set_conic(I.matrix)
        self.pole_art.set_point(a)
        self.axis_art.set_line(f)
        rho = float(I.radius_of_gyration)
        m = float(I.mass)
        out = {"pole x": self.values["pole x"], "pole y": self.values["pole y"],
               "mass m": m, "radius of gyration ρ": rho, "centre of mass": tuple(c)}
        finite_pole = a[2] != 0
        if finite_pole:
            P = np.array([-a[1] / a[2], a[0] / a[2]])
            d = float(np.hypot(*(P - c)))
        else:
            P, d = None, math.inf
        out["pole"] = "at infinity" if P is None else tuple(P)
        out["d = |pole − c|"] = d
        # the construction line from the pole through the centre of mass
        if P is not None and d > 1e-9 * max(rho, 1e-300):
            self.join_art.set_line(np.cross(a / a[2], from_xy(c)))
            self.join_art.set_visible(True)
            r = rho * rho / d
            spot = c + (c - P) / d * r                # where the axis crosses the line pole-c (5.68)
            self.spot.set_data([spot[0]], [spot[1]])
            out["r = ρ²/d (5.68)"] = r
            out["l = d + ρ²/d (5.67)"] = d + r
            out["force for α: m d α (5.66)"] = m * d * float(self.values["angular accel. α"])
            out["centre of percussion"] = tuple(spot)
        else:
            self.join_art.set_visible(False)
            self.spot.set_data([], [])
            out["r = ρ²/d (5.68)"] = 0.0 if P is None else math.inf
            out["l = d + ρ²/d (5.67)"] = math.inf
            out["force for α: m d α (5.66)"] = "pure couple" if P is not None else "—"
            out["centre of percussion"] = "—"
        # the sweet spot of the grip (origin): where a strike makes the body turn about the grip
        d0 = float(np.hypot(*c))
        grip_spot = c + c / d0 * (rho * rho / d0) if d0 > 0 else None
        out["sweet spot of the grip"] = "—" if grip_spot is None else tuple(grip_spot)
        if self.values["drive"] == "impact":
            if grip_spot is not None:
                self.spot.set_data([grip_spot[0]], [grip_spot[1]])
            out["impact at"] = self.values["impact at"]
            out["pole distance from grip"] = "at infinity" if P is None else float(np.hypot(*P))
        self._fit_view(shape)
        return out

    def _fit_view(self, shape):
        """Keep the body (and the slider range of the pole) in view; change limits only if needed."""
        x0, y0, x1, y1 = shape.bounds
        cx, cy = self.controls["pole x"], self.controls["pole y"]
        lo_x, hi_x = min(x0, cx.min) - 0.1, max(x1, cx.max) + 0.1
        lo_y, hi_y = min(y0, cy.min) - 0.1, max(y1, cy.max) + 0.1
        (ax0, ax1), (ay0, ay1) = self.ax.get_xlim(), self.ax.get_ylim()
        if lo_x < ax0 or hi_x > ax1 or lo_y < ay0 or hi_y > ay1:
            self.ax.set_xlim(lo_x, hi_x)
            self.ax.set_ylim(lo_y, hi_y)
