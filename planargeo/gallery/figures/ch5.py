"""Chapter 5 figures: homogeneous coordinates, conic polarity, inertia mappings (5.1-5.7)."""
from __future__ import annotations

import numpy as np

from planargeo.draw.picture import PX_PER_PT
from planargeo.draw.pictures.common import label_toward, labelled_line
from planargeo.draw.polars import (interior_construction, line_conic_points, percussion, polar_exterior,
                                   polar_interior, power, power_values)
from planargeo.draw.sketch import _arrow_parts, body, label, link_polygon, panel, segment, show
from planargeo.draw.style import COLORS
from planargeo.gallery.figures import register
from planargeo.geometry.conics import (conic_ellipse, decompose_line_special, decompose_point_special, polar,
                                       special_base)
from planargeo.geometry.projective import from_standard, from_xy, join, to_xy
from planargeo.screws.inertia import Inertia, percussion_axis

#: the axes' colour in Figs 5.1 and 5.5
AXES = "#555555"
#: length of an arrow's head (pixels)
HEAD_PX = 8.0


def _vec_arrow(pic, id, p, d, text, *, color, symbol, desc, offset=(5, 5), width=1.0):
    """An arrow from the data point ``p`` along the data vector ``d``, its text at the tip (``offset`` points)."""
    p = np.asarray(p, float)
    pic.path(id, np.zeros((0, 2)), role="construct", symbol=symbol, desc=desc, color=color,
             width=width * PX_PER_PT, dash=[], z=5)
    pic.elements[-1]["parts"] = _arrow_parts(pic, p, p + np.asarray(d, float), head=HEAD_PX)
    if text:
        label(pic, id + ":label", p + d, text, offset=offset, color=color, symbol=symbol, desc=desc)


def _coords(ax, alternative: bool):
    """A point P and a line L in standard (Fig. 5.1) or alternative (Fig. 5.5) coordinates."""
    pic = panel(ax, [[-0.6, -1.6], [2.8, 2.6]], margin=0.03)
    size = 2.6                                          # the axes, from -0.3 to size + 0.3
    for d, name in ((np.array([1.0, 0.0]), "x"), (np.array([0.0, 1.0]), "y")):
        _vec_arrow(pic, f"{name} axis", -0.3 * d, (size + 0.3) * d, "", color=AXES, symbol=name,
                   desc=f"the {name} axis", width=0.7)
    label(pic, "x", [size, 0], "x", offset=(2, -10), color=AXES, symbol="x", desc="the x axis")
    label(pic, "y", [0, size], "y", offset=(-10, 0), va="top", color=AXES, symbol="y", desc="the y axis")
    lamP, rP = np.deg2rad(62), 2.0
    lamL, rL = np.deg2rad(-20), 1.8
    # the point and the line are built from their standard coordinates (5.4, 5.14a)
    P = from_standard([1.0, rP * np.cos(lamP), rP * np.sin(lamP)])
    L = from_standard([rL, -np.cos(lamL), -np.sin(lamL)])
    Pxy = to_xy(P)
    foot = rL * np.array([np.cos(lamL), np.sin(lamL)])
    segment(pic, "r_P", [0, 0], Pxy, symbol="r", desc=f"distance r of P from the origin (5.4): {rP:g}")
    segment(pic, "r_L", [0, 0], foot, symbol="r", desc=f"distance r of L from the origin (5.14): {rL:g}")
    labelled_line(pic, "L", L, "L", role="wrench", arrow=False, symbol="L", anchor=[2.5, -1.0], side=-1.0,
                  desc=f"the line L at distance r = {rL:g} from the origin, unit normal n at "
                       f"{np.rad2deg(lamL):.0f}° (5.14): L = [r; −n]")
    pic.point("P", P, role="twist", glyph=False, symbol="P",
              desc=f"the point P at distance r = {rP:g} from the origin, direction n at "
                   f"{np.rad2deg(lamP):.0f}° (5.4): P = [1; r n]")
    nP, nL = Pxy / rP, foot / rL
    if alternative:
        eP = np.array([-nP[1], nP[0]])          # (5.50)
        eL = np.array([-nL[1], nL[0]])          # along the line (5.55)
        _vec_arrow(pic, "e_P", Pxy, 0.7 * eP, "e⃗", color=COLORS["twist"], symbol="e",
                   desc="unit vector e of P, perpendicular to n (5.50)", width=1.4)
        _vec_arrow(pic, "e_L", foot, 0.7 * eL, "e⃗", color=COLORS["wrench"], symbol="e",
                   desc="unit vector e of L, along the line (5.55)", width=1.4)
        text = "P = [−r e⃗; 1] (5.49),  L = [e⃗; r] (5.55)"
    else:
        _vec_arrow(pic, "n_P", [0, 0], 0.7 * nP, "n⃗", color=COLORS["twist"], offset=(-12, -2), symbol="n",
                   desc="unit vector n towards P (5.4)", width=1.4)
        _vec_arrow(pic, "n_L", [0, 0], 0.7 * nL, "n⃗", color=COLORS["wrench"], offset=(-4, -16), symbol="n",
                   desc="unit normal n of L (5.14)", width=1.4)
        text = "P = [1; r n⃗],  L = [r; −n⃗] (5.4, 5.14)"
    x0, x1, y0, y1 = pic.box
    pic.text("coordinates", (x1 - 0.02 * (x1 - x0), y0 + 0.02 * (y1 - y0)), text, ha="right",
             symbol="P, L", desc=("alternative" if alternative else "standard") + " homogeneous coordinates of "
                                 "P and L " + ("(5.49, 5.55)" if alternative else "(5.4, 5.14)"))
    label(pic, "r_P:label", 0.72 * Pxy, "r", offset=(-10, 2), symbol="r", desc="the distance r of P (5.4)")
    label(pic, "r_L:label", 0.72 * foot, "r", offset=(0, 4), symbol="r", desc="the distance r of L (5.14)")
    show(pic, ax)


@register(5.01, height=2.7)
def fig5_1(ax):
    """Fig. 5.1 — standard homogeneous coordinates: a point P = [1, r n] and a line L = [r, −n] at
    distance r with unit normal n (5.1–5.16); both built with projective.from_standard."""
    _coords(ax, alternative=False)


def _ellipse():
    return conic_ellipse([0.0, 0.0], [1.6, 1.0], np.deg2rad(15))


@register(5.02, height=2.6)
def fig5_2(ax):
    """Fig. 5.2 — polar of an exterior point: the tangents from P touch the conic C at two points
    whose join is L = C P (5.36); a point Q on C maps to its tangent M = C Q (5.38–5.39). From
    conics.polar_construction_exterior."""
    C = _ellipse()
    p = from_xy([2.6, 1.3])
    pic = panel(ax, [[-2.0, -1.6], [2.9, 1.6]], margin=0.05)
    polar_exterior(pic, C, p, L_side=-1.0)           # L's label inside C, under the chord
    th = np.deg2rad(230)   # Q: where the ray from the centre at angle th meets C
    ray = join(from_xy([0.0, 0.0]), from_xy([np.cos(th), np.sin(th)]))
    q = max(line_conic_points(C, ray), key=lambda X: to_xy(X) @ [np.cos(th), np.sin(th)])
    assert abs(q @ C @ q) < 1e-9 * np.abs(C).max() * (q @ q)
    qxy = to_xy(q)
    labelled_line(pic, "M", polar(C, q), "M = CQ", role="construct", color=COLORS["accel"], arrow=False,
                  symbol="M = CQ", anchor=qxy + [0.9, -0.2], side=-1.0,    # below M, right of Q
                  desc="the polar M = C Q of a point Q on C: its tangent there (5.38–5.39)")
    pic.point("Q", q, role="accel", glyph=False, symbol="Q",
              desc=f"a point Q on the conic C (5.38): at ({qxy[0]:.3g}, {qxy[1]:.3g})")
    label_toward(pic.elements[-1], (-1.0, -1.0), 8.0)
    show(pic, ax)


@register(5.03, height=2.8)
def fig5_3(ax):
    """Fig. 5.3 — polar of an interior point: two chords through P; the tangents at each chord's
    ends meet at its pole R_i (Theorem 12); L = C P joins R₁ and R₂. From
    conics.polar_construction_interior."""
    C = _ellipse()
    p = from_xy([1.0, 0.45])
    angles = (np.deg2rad(75), np.deg2rad(150))
    K = interior_construction(C, p, angles)
    R1, R2 = to_xy(K.poles[0]), to_xy(K.poles[1])
    pic = panel(ax, [R1, R2, [-1.8, -1.2], [1.8, 1.2]], margin=0.15)
    out = polar_interior(pic, C, p, angles=angles, L_anchor=(R1 + R2) / 2)   # L's label between R1 and R2
    label_toward(out["R1"], (1.0, -0.4), 10.0)
    label_toward(out["R2"], (-1.0, 0.5), 9.0)                                 # R2's label left of L
    show(pic, ax)


@register(5.04, height=2.8)
def fig5_4(ax):
    """Fig. 5.4 — special decomposition P = u₁Q₁ + u₂Q₂ + u₃Q₃ (5.42) on Q₁ exterior and Q₂, Q₃ its
    tangent contacts, so u_i come from single projections (5.44–5.45); the dual lines M_i = C Q_i
    decompose L = C P with the same u_i (5.43, 5.46)."""
    C = _ellipse()
    Q1, Q2, Q3 = special_base(C, from_xy([2.4, 1.6]))
    P = from_xy([0.4, -0.5])
    u = decompose_point_special(C, P, Q1, Q2, Q3)
    uL = decompose_line_special(C, polar(C, P), Q1, Q2, Q3)
    assert np.allclose(u, uL, rtol=1e-9, atol=1e-12)
    q1, q2, q3 = to_xy(Q1), to_xy(Q2), to_xy(Q3)
    pic = panel(ax, [q1, [-1.9, -1.5], [1.9, 1.5]], margin=0.1)
    pic.conic("C", C, role="conic", symbol="C", label="", desc="the conic C (5.35): the points x with xᵀCx = 0")
    label(pic, "C:label", [-1.0, 0.15], "C", offset=(0, 0), ha="center", va="center", symbol="C",
          desc="the conic C (5.35)")                     # inside C, clear of the curve
    uu = u / (u @ [Q1[2], Q2[2], Q3[2]])
    # M1 = C Q1 is the chord Q2 Q3, M2 and M3 the tangents Q1 Q2 and Q1 Q3: labels away from the Qs
    anchors = (q3 + 0.5 * (q3 - q2) / np.hypot(*(q3 - q2)), (q1 + q2) / 2, (q1 + q3) / 2)
    what = ("the chord through Q₂ and Q₃", "the tangent at Q₂ (through Q₁)", "the tangent at Q₃ (through Q₁)")
    sub = "₁₂₃"
    for k, Q in enumerate((Q1, Q2, Q3)):
        labelled_line(pic, f"M{k + 1}", polar(C, Q), f"M{sub[k]}", role="construct", arrow=False,
                      symbol=f"M{sub[k]}", anchor=anchors[k], side=-1.0 if k == 2 else 1.0,
                      desc=f"the polar M{sub[k]} = C Q{sub[k]} (5.43): {what[k]}")
    labelled_line(pic, "L", polar(C, P), "L = CP", role="wrench", arrow=False, symbol="L = CP",
                  anchor=[1.0, -1.2], side=-1.0,
                  desc="the polar L = C P (5.36), decomposed on the Mᵢ with the same uᵢ (5.43, 5.46)")
    for k, (Q, xy) in enumerate(zip((Q1, Q2, Q3), (q1, q2, q3))):
        pic.point(f"Q{k + 1}", Q, role="twist", glyph=False, symbol=f"Q{sub[k]}",
                  desc=f"base point Q{sub[k]} (5.42): at ({xy[0]:.3g}, {xy[1]:.3g}), u{sub[k]} = {uu[k]:.2f}")
        label_toward(pic.elements[-1], ((-1.0, 1.0), (-0.6, 1.0), (-1.0, -0.3))[k], 8.0)
    pxy = to_xy(P)
    pic.point("P", P, role="accel", glyph=False, symbol="P",
              desc=f"the point P = u₁Q₁ + u₂Q₂ + u₃Q₃ (5.42): at ({pxy[0]:.3g}, {pxy[1]:.3g})")
    txt = ", ".join(f"u{sub[k]} = {v:.2f}" for k, v in enumerate(uu))
    x0, x1, y0, y1 = pic.box
    pic.text("u", (x0 + 0.02 * (x1 - x0), y1 - 0.02 * (y1 - y0)), txt, ha="left", va="top", symbol="u",
             desc=f"the coordinates of P on the base Q₁, Q₂, Q₃ (5.44–5.45): {txt}")
    show(pic, ax)


@register(5.05, height=2.7)
def fig5_5(ax):
    """Fig. 5.5 — alternative homogeneous coordinates (5.47–5.56): P = [−r e; 1] with e ⟂ n
    (5.49–5.50), L = [e; r] with e along the line (5.55): a twist about P and a wrench along L."""
    _coords(ax, alternative=True)


def _link():
    """The link of Figs 5.6-5.7 and its inertia (from the shape)."""
    shape = link_polygon([-0.2, 0.0], [2.2, 0.0], 0.7)
    return shape, Inertia.from_polygon(shape, density=1.0)


def _body(pic, shape, I):
    """The link drawn with its centre of mass."""
    body(pic, "body", shape, com=I.com, symbol="body",
         desc=f"the body, a uniform lamina: mass {float(I.mass):.3g} kg, radius of gyration "
              f"ρ = {float(I.radius_of_gyration):.3g} m")


@register(5.06, height=2.0)
def fig5_6(ax):
    """Fig. 5.6 — the inertia maps an acceleration pole a to its axis of percussion f = I a
    (5.64–5.68): at distance d from the centre of mass, the axis lies beyond it at ρ²/d. Inertia
    from the body's polygon (Inertia.from_polygon), drawn as its radius-of-gyration circle."""
    shape, I = _link()
    c = np.asarray(I.com)
    a = from_xy(c - [1.5, 0.0])
    pic = panel(ax, [to_xy(a) - [0.3, 0], [2.6, -0.7], [2.6, 0.7]], margin=0.06)
    _body(pic, shape, I)
    d, rho = 1.5, float(I.radius_of_gyration)
    x_axis = c[0] + rho ** 2 / d
    # the axis's label near the top of the view, right of the line and outside the circle
    out = percussion(pic, I.matrix, a, f_anchor=[x_axis, c[1] + 0.8])
    f = out["values"]["f"]
    assert np.allclose(f, percussion_axis(I.matrix, a))
    assert np.isclose(to_xy(np.cross(f, [1.0, 0.0, -c[1]]))[0] - c[0], rho ** 2 / d)   # meets y = c_y at ρ²/d
    show(pic, ax)


@register(5.07, height=2.4)
def fig5_7(ax):
    """Fig. 5.7 — power relations: a powerless force f passes through the velocity pole v (vᵀf = 0,
    5.69), and a powerless acceleration a lies on the momentum line p = I v (pᵀa = 0,
    5.71–5.72)."""
    v = 1.2 * from_xy([0.6, -1.1])
    shape, I = _link()
    val = power_values(v, I.matrix)           # where a lies, for the view
    pic = panel(ax, [[-0.6, -1.5], [2.6, 1.45], to_xy(val["a"]), to_xy(v)], margin=0.08)
    _body(pic, shape, I)
    out = power(pic, v, I.matrix, p_label_at=-2.3, f_label_at=-1.0, f_side=-1.0)   # f's label under f
    label_toward(out["v"], (-1.0, -1.0), 12.0)
    show(pic, ax)
