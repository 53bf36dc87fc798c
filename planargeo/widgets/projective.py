"""Projective playground: a conic maps points to lines and back (thesis 5.2).

A real conic or an inertia (an imaginary circle, 5.4) maps a movable point ``P`` to its polar
``C P`` (5.36) and a movable line ``M`` to its pole ``C⁻¹ M`` (5.37); for a real conic the
constructions of 5.2.2 follow ``P`` (tangents from outside, Fig 5.2; chords from inside, Fig 5.3).
The readout shows the invariant ``P·M = pole(M)·polar(P)`` (5.40-5.41); ideal elements are
ordinary (``P`` at infinity has a diameter for its polar).

Examples
--------
>>> ex = ProjectiveExplorer(display="agg")
>>> ex.drag("P", (2.0, 1.5), (0.5, 0.25), steps=3).values["P x"]
0.5
"""
from __future__ import annotations

import math

import ipywidgets as W
import numpy as np

from planargeo.geometry.conics import (centre, classify, conic_circle, conic_ellipse, conic_hyperbola,
                      conic_parabola, polar, polar_construction_interior, pole,
                      tangents_from_point)
from planargeo.draw.pictures.projective import projective_picture
from planargeo.errors import DegenerateGeometryError, InputError
from planargeo.geometry.projective import from_xy, is_at_infinity, is_ideal
from planargeo.widgets._explorer import Described, xy_handle
from planargeo.widgets.base import Explorer, Handle, Step, Toggle
from planargeo.widgets.readout import point_value

__all__ = ["ProjectiveExplorer", "CONICS", "make_conic"]

CONICS = ("circle", "ellipse", "hyperbola", "parabola", "inertia (imaginary circle)")


def make_conic(kind: str, a: float, b: float, tilt_deg: float) -> np.ndarray:
    """The playground's conic: centred at the origin (parabola: vertex), turned by ``tilt``.

    Parameters
    ----------
    kind : str
        One of :data:`CONICS`.
    a, b : float
        Semi-axes (circle: radius ``a``; parabola: ``a / 4`` is the focal distance).
    tilt_deg : float
        Turn of the axes in degrees.

    Returns
    -------
    numpy.ndarray
        The conic's (3, 3) matrix.

    Examples
    --------
    >>> from planargeo.geometry.conics import classify
    >>> [str(classify(make_conic(k, 1.5, 1.0, 20.0))) for k in CONICS]
    ['real circle', 'real ellipse', 'real hyperbola', 'real parabola', 'imaginary circle']
    """
    t = math.radians(tilt_deg)
    if kind == "circle":
        return conic_circle([0.0, 0.0], a)
    if kind == "ellipse":
        return conic_ellipse([0.0, 0.0], [a, b], t)
    if kind == "hyperbola":
        return conic_hyperbola([0.0, 0.0], [a, b], t)
    if kind == "parabola":
        return conic_parabola([0.0, 0.0], a / 4.0, t)
    return conic_circle([0.0, 0.0], a, imaginary=True)


def _line(angle_deg: float, offset: float) -> np.ndarray:
    """Line with direction ``angle`` at signed distance ``offset`` left of the origin (5.55)."""
    t = math.radians(angle_deg)
    e = np.array([math.cos(t), math.sin(t)])
    # points (x, y) with tz + y fx - x fy = 0; through the foot point -offset * (-e_y, e_x)
    foot = offset * np.array([-e[1], e[0]])
    return np.array([e[0], e[1], foot[0] * e[1] - foot[1] * e[0]])


def _angle_offset(M) -> tuple[float, float]:
    """``(angle in degrees, offset)`` of the finite line ``M`` (inverse of :func:`_line`)."""
    fx, fy, tz = (float(v) for v in M)
    F = math.hypot(fx, fy)
    if is_at_infinity(np.array([fx, fy, tz])):
        raise DegenerateGeometryError("the line is the line at infinity: no angle and offset")
    e = np.array([fx, fy]) / F
    # the foot offset * (-e_y, e_x) satisfies tz + offset (e_x fx + e_y fy) = 0 -> offset = -tz / F
    return math.degrees(math.atan2(e[1], e[0])), -tz / F


#: a computed homogeneous result counts as ideal when its weight is within this many rounding
#: units (times the conic's condition number) of zero: see :func:`_settle`
ROUNDING_UNITS = 64.0


def _settle(x, C, operand, kind: str) -> np.ndarray:
    """``x`` (a pole ``C⁻¹ M`` or polar ``C P``), exactly ideal if so within rounding (5.37, 5.36).

    The pole of the line at infinity for a parabola comes out with ``w ≈ 1e-17``, not 0.
    ``solve`` is backward stable: the weight is uncertain by about ``ε cond(C) ‖x‖`` (``C P``:
    ``ε ‖C‖ ‖P‖``); within :data:`ROUNDING_UNITS` of that it cannot be told from 0 and is set to 0.
    A genuinely far pole has a weight 10¹⁰ times larger and stays finite.
    """
    x = np.array(x, dtype=float)
    eps = np.finfo(float).eps
    if kind == "pole":
        err = ROUNDING_UNITS * eps * float(np.linalg.cond(C)) * float(np.linalg.norm(x))
        if x[2] != 0 and abs(x[2]) <= err:
            x[2] = 0.0
    else:
        err = ROUNDING_UNITS * eps * float(np.linalg.norm(C, 2)) * float(np.linalg.norm(operand))
        if np.any(x[:2]) and float(np.hypot(x[0], x[1])) <= err:
            x[0] = x[1] = 0.0
    return x


#: what the linear form ``t = PᵀM`` (5.40) is when ``P`` or ``M`` is ideal: a number, not a distance
FORM_MEANINGS = {
    "line at infinity": "the linear form t = PᵀM (5.40) with M the line at infinity [0, 0, 1]: the weight of "
                        "P = [y, −x, 1], so 1 for every finite point (0 only for a point at infinity); "
                        "a number, not a distance",
    "point at infinity": "the linear form t = PᵀM (5.40) with P at infinity, P = [dy, −dx, 0] for its "
                         "direction d = (P x, P y): the cross product e × d of M's direction e and d, "
                         "0 exactly when P is M's own point at infinity (M runs towards d); a number, "
                         "not a distance",
    "both at infinity": "the linear form t = PᵀM (5.40) with P at infinity and M the line at infinity: 0, "
                        "every point at infinity lies on the line at infinity; a number, not a distance",
}


def _form_case(P, M) -> str:
    """What ``PᵀM`` is: ``"distance"`` (both finite, 5.40), or the key of :data:`FORM_MEANINGS`.

    Examples
    --------
    >>> _form_case([1.5, -2.0, 1.0], [0.0, 1.0, 0.5]), _form_case([1.5, -2.0, 1.0], [0.0, 0.0, 1.0])
    ('distance', 'line at infinity')
    >>> _form_case([1.5, -2.0, 0.0], [0.0, 1.0, 0.5]), _form_case([1.5, -2.0, 0.0], [0.0, 0.0, 1.0])
    ('point at infinity', 'both at infinity')
    """
    ideal_P, ideal_M = bool(is_ideal(np.asarray(P, float))), bool(is_at_infinity(np.asarray(M, float)))
    if ideal_P and ideal_M:
        return "both at infinity"
    if ideal_M:
        return "line at infinity"
    return "point at infinity" if ideal_P else "distance"


class ProjectiveExplorer(Described, Explorer):
    """Pole and polar of a movable point and line with respect to a conic."""

    title = "Projective playground: poles, polars and constructions"
    slug = "projective"
    figsize = (5.6, 5.4)
    limits = (-4, 4, -4, 4)
    display_controls = ("construction", "line and its pole")
    scale = 4.0

    def make_controls(self):
        return {
            "P x": Step(-4, 4, 0.05, 2.0, "P x (m)"),
            "P y": Step(-4, 4, 0.05, 1.5, "P y (m)"),
            "line angle (deg)": Step(-180, 180, 1, 100, "line angle (deg)"),
            "line offset": Step(-4, 4, 0.05, 0.5, "line offset (m)"),
            "conic": W.Dropdown(options=CONICS, value="ellipse", description="conic"),
            "a": Step(0.2, 3, 0.05, 1.5, "semi-axis a (m)"),
            "b": Step(0.2, 3, 0.05, 1.0, "semi-axis b (m)"),
            "tilt (deg)": Step(-90, 90, 1, 20, "tilt (deg)"),
            "P at infinity": Toggle(False, "P at infinity (direction P x, P y)"),
            "M at infinity": Toggle(False, "M = line at infinity"),
            "construction": Toggle(True, "construction (5.2.2)"),
            "line and its pole": Toggle(True, "line and its pole"),
        }

    def disabled(self, values):
        out = {}
        kind = values["conic"]
        if kind in ("circle", "parabola", "inertia (imaginary circle)"):
            out["b"] = f"a {kind.split(' ')[0]} has one size: a"
        if kind in ("circle", "inertia (imaginary circle)"):
            out["tilt (deg)"] = "a circle looks the same turned"
        if values["M at infinity"]:
            out["line angle (deg)"] = out["line offset"] = "M is the line at infinity"
        if kind == "inertia (imaginary circle)":
            out["construction"] = "an imaginary conic has no real tangents to construct with"
        return out

    def _M_points(self):
        """(foot, second point) of the finite line M: its point nearest the origin, one unit on."""
        st = self.state
        if st is None or self.values["M at infinity"] or not self.values["line and its pole"]:
            return None
        ang, off = _angle_offset(st["M"])
        t = math.radians(ang)
        e = np.array([math.cos(t), math.sin(t)])
        foot = off * np.array([-e[1], e[0]])
        pivot = getattr(self, "_M_pivot", None)  # the point M turns about: kept while on M
        M = st["M"]
        if pivot is None or abs(M[2] + pivot[1] * M[0] - pivot[0] * M[1]) > 1e-9 * max(
                1.0, float(np.abs(pivot).max())) or not self._in_view(pivot):
            pivot = foot
        self._M_pivot = pivot
        # the direction handle: a point of M in view, ahead of the pivot if it can be (else behind)
        for arm in (1.5, -1.5, 0.75, -0.75, 0.3, -0.3):
            if self._in_view(pivot + arm * e):
                break
        self._M_arm = arm
        return pivot, pivot + arm * e

    def mechanism_points(self):
        # not the pole of M: a line near the centre has its pole far away
        pts = [h.where() for h in self.handles() if h.name != "pole of M"]
        return np.array([p for p in pts if p is not None], dtype=float).reshape(-1, 2)

    def _in_view(self, xy) -> bool:
        """True for a data point inside the (fixed) view: a handle there can be grabbed."""
        x0, x1, y0, y1 = self.limits
        return bool(x0 <= xy[0] <= x1 and y0 <= xy[1] <= y1)

    def _drag_M_point(self, x, y):
        ang = self.values["line angle (deg)"]
        t = math.radians(ang)
        self._M_pivot = np.array([x, y], dtype=float)
        return {"line offset": -math.sin(t) * x + math.cos(t) * y}

    def _drag_M_direction(self, x, y):
        pts = self._M_points()
        if pts is None:
            raise DegenerateGeometryError("M is not shown as a finite line")
        foot = pts[0]  # the pivot: M turns about it
        d = (np.array([x, y]) - foot) * (1.0 if self._M_arm > 0 else -1.0)   # along M's direction
        if np.hypot(*d) < 1e-9:
            raise DegenerateGeometryError("the direction handle is on the point M turns about: "
                                          "no direction there")
        ang = math.degrees(math.atan2(d[1], d[0]))
        t = math.radians(ang)
        return {"line angle (deg)": ang, "line offset": -math.sin(t) * foot[0] + math.cos(t) * foot[1]}

    def _drag_pole_of_M(self, x, y):
        C = self.state["C"]
        M = polar(C, from_xy([x, y]))
        if math.hypot(M[0], M[1]) <= 1e-12 * float(np.abs(M).max()):
            raise DegenerateGeometryError("the polar of the conic's centre is the line at infinity, "
                                          "which the line sliders cannot hold: tick "
                                          "“M = line at infinity” to show it")
        ang, off = _angle_offset(M)
        lo, hi = self.controls["line offset"].min, self.controls["line offset"].max
        if not lo <= off <= hi:
            raise InputError(f"the polar of ({x:.3g}, {y:.3g}) m lies {off:.3g} m from the origin, "
                             f"beyond the line offset slider ({lo:g} to {hi:g} m)")
        return {"line angle (deg)": ang, "line offset": off}

    def handles(self):
        def pole_where():
            st = self.state
            if st is None or self._M_points() is None:
                return None
            p = st["poleM"]
            if is_ideal(p):
                return None
            return (float(-p[1] / p[2]), float(p[0] / p[2]))

        return [
            xy_handle(self, "P", "P x", "P y", when=lambda: not self.values["P at infinity"]),
            Handle("M (point)", lambda: None if self._M_points() is None else
                   tuple(self._M_points()[0]), self._drag_M_point),
            Handle("M (direction)", lambda: None if self._M_points() is None else
                   tuple(self._M_points()[1]), self._drag_M_direction),
            Handle("pole of M", pole_where, self._drag_pole_of_M),
        ]

    def compute(self, values, changed):
        C = make_conic(values["conic"], values["a"], values["b"], values["tilt (deg)"])
        if values["P at infinity"]:
            # the ideal point in the direction (dx, dy): [dy, -dx, 0] (conventions: direction (-b, a))
            P = np.array([values["P y"], -values["P x"], 0.0])
            if not np.any(P):
                raise DegenerateGeometryError("P x = P y = 0 gives no direction: a point at "
                                              "infinity needs (P x, P y) ≠ (0, 0)")
        else:
            P = from_xy([values["P x"], values["P y"]])
        M = np.array([0.0, 0.0, 1.0]) if values["M at infinity"] else _line(values["line angle (deg)"],
                                                                       values["line offset"])
        ctype = classify(C)
        polarP = _settle(polar(C, P), C, P, "polar")
        poleM = _settle(pole(C, M), C, M, "pole")
        st = {"C": C, "P": P, "M": M, "type": ctype, "polar": polarP, "poleM": poleM,
              "where": "—", "tangents": None, "contacts": None, "interior": None}
        if ctype.reality == "real":
            res = float(P @ C @ P)
            if is_ideal(P) and abs(res) <= 1e-12 * float(np.abs(C).max()) * float(P @ P):
                # an ideal point on the conic (asymptote / parabola axis direction)
                st["where"] = "on the conic (at infinity)"
                return st
            T, X = tangents_from_point(C, P, on_interior="nan")
            if np.all(np.isfinite(T)):
                st["tangents"], st["contacts"] = T, X
                st["where"] = "on the conic" if abs(res) <= 1e-9 * np.abs(C).max() else "outside"
                if is_ideal(P):
                    st["where"] += " (at infinity)"
            elif is_ideal(P):
                st["where"] = "inside (at infinity)"
            else:
                st["where"] = "inside"
                st["interior"] = polar_construction_interior(C, P, on_miss="nan")
        elif ctype.reality == "imaginary":
            st["where"] = "no real points: algebraic map only"
        return st

    def readout_of(self, state):
        v = self.values
        P, M, pol, pm = state["P"], state["M"], state["polar"], state["poleM"]
        # polar of P: normalised line [e, r] (5.55): direction and signed distance from the origin
        F = float(np.hypot(pol[0], pol[1]))
        out = {
            "P x": v["P x"], "P y": v["P y"],
            "P": point_value(P),
            "conic": str(state["type"]),
            "P is": state["where"],
            "polar of P: distance to origin": ("line at infinity" if is_at_infinity(pol)
                                               else abs(pol[2]) / F),
            "pole of M": point_value(pm),
            "P·M": float(P @ M),
            "pole(M)·polar(P)": float(pm @ pol),
        }
        # a distance only between a finite point of weight 1 and a finite line with |e| = 1 (5.40, 5.55);
        # with an ideal element the same form is a plain number (the weight of P, or a cross of directions)
        unit = "m" if _form_case(P, M) == "distance" else "—"
        self.units = {**type(self).units, "P·M": unit, "pole(M)·polar(P)": unit}
        if v["P at infinity"]:                 # (P x, P y) is then a direction, not a place
            self.units.update({"P x": "—", "P y": "—"})
        if state["type"].kind == "parabola":   # its centre is the ideal point of its axis
            out["centre"] = point_value(_settle(pole(state["C"], [0.0, 0.0, 1.0]), state["C"], [0.0, 0.0, 1.0], "pole"))
        else:
            out["centre"] = point_value(centre(state["C"]))
        return out

    def explain(self):
        out = super().explain()
        st = self.state
        if st is not None:
            case = _form_case(st["P"], st["M"])
            if case != "distance":
                out["P·M"] = FORM_MEANINGS[case]
                out["pole(M)·polar(P)"] = ("the same number from the images, t = (C⁻¹M)ᵀ(C P) (5.41): "
                                           "a linear form is kept by the conic's map")
        return out

    def scene_picture(self, state, view=None):
        v = self.values
        return projective_picture(state, construction=bool(v["construction"]),
                                  line_and_pole=bool(v["line and its pole"]),
                                  view=view or self.limits, size=self.figure_px)
