"""Chapter 5 figures: homogeneous coordinates, conic polarity, inertia mappings (5.1-5.7)."""
from __future__ import annotations

import numpy as np

from planargeo.geometry.conics import (conic_ellipse, decompose_line_special, decompose_point_special, polar,
                       special_base)
from planargeo.screws.inertia import Inertia, percussion_axis
from planargeo.geometry.projective import from_standard, from_xy, join, to_xy
from planargeo.draw.artists import plot_conic, plot_line, plot_point
from planargeo.draw.constructions import (line_conic_points, draw_percussion, draw_polar_exterior,
                             draw_polar_interior, draw_power, draw_segment, label)
from planargeo.draw.mechanism import draw_body, link_polygon
from planargeo.draw.style import COLORS, LABEL_PT
from planargeo.draw.layout import fit_view
from planargeo.gallery.figures import register


def _vec_arrow(ax, p, d, text, color="#222222", **kw):
    p = np.asarray(p, float)
    q = p + np.asarray(d, float)
    ax.annotate("", xy=tuple(q), xytext=tuple(p),
                arrowprops=dict(arrowstyle="-|>", color=color, lw=1.0, shrinkA=0, shrinkB=0,
                                mutation_scale=9))
    label(q, text, color=color, **kw, ax=ax)


def _axes_cross(ax, size=2.6):
    for d in ([1, 0], [0, 1]):
        ax.annotate("", xy=tuple(np.array(d) * size), xytext=tuple(-np.array(d) * 0.3),
                    arrowprops=dict(arrowstyle="-|>", color="#555555", lw=0.7, mutation_scale=7))
    label([size, 0], "$x$", offset=(2, -10), color="#555555", ax=ax)
    label([0, size], "$y$", offset=(-10, 0), va="top", color="#555555", ax=ax)


def _coords(ax, alternative: bool):
    """A point P and a line L in standard (Fig. 5.1) or alternative (Fig. 5.5) coordinates."""
    _axes_cross(ax)
    lamP, rP = np.deg2rad(62), 2.0
    lamL, rL = np.deg2rad(-20), 1.8
    # the point and the line are built from their standard coordinates (5.4, 5.14a)
    P = from_standard([1.0, rP * np.cos(lamP), rP * np.sin(lamP)])
    L = from_standard([rL, -np.cos(lamL), -np.sin(lamL)])
    Pxy = to_xy(P)
    plot_point(P, ax, glyph=False, text="$P$")
    plot_line(L, ax, scale=None, text="$L$", anchor=[2.5, -1.0])
    foot = rL * np.array([np.cos(lamL), np.sin(lamL)])
    draw_segment([0, 0], Pxy, ax=ax)
    draw_segment([0, 0], foot, ax=ax)
    nP, nL = Pxy / rP, foot / rL
    if alternative:
        eP = np.array([-nP[1], nP[0]])          # (5.50)
        eL = np.array([-nL[1], nL[0]])          # along the line (5.55)
        _vec_arrow(ax, Pxy, 0.7 * eP, r"$\vec e$", color=COLORS["twist"])
        _vec_arrow(ax, foot, 0.7 * eL, r"$\vec e$", color=COLORS["wrench"])
        ax.text(0.98, 0.02, r"$P=[-r\vec e;\,1]$ (5.49),  $L=[\vec e;\,r]$ (5.55)",
                transform=ax.transAxes, fontsize=LABEL_PT, ha="right", va="bottom")
    else:
        _vec_arrow(ax, [0, 0], 0.7 * nP, r"$\vec n$", color=COLORS["twist"], offset=(-12, -2))
        _vec_arrow(ax, [0, 0], 0.7 * nL, r"$\vec n$", color=COLORS["wrench"], offset=(-4, -16))
        ax.text(0.98, 0.02, r"$P=[1;\,r\vec n]$,  $L=[r;\,-\vec n]$ (5.4, 5.14)",
                transform=ax.transAxes, fontsize=LABEL_PT, ha="right", va="bottom")
    label(0.72 * Pxy, "$r$", offset=(-10, 2), ax=ax)      # beyond the unit-vector arrows
    label(0.72 * foot, "$r$", offset=(0, 4), ax=ax)
    fit_view([[-0.6, -1.6], [2.8, 2.6]], margin=0.03, ax=ax)


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
    draw_polar_exterior(C, p, ax)
    th = np.deg2rad(230)   # Q: where the ray from the centre at angle th meets C
    ray = join(from_xy([0.0, 0.0]), from_xy([np.cos(th), np.sin(th)]))
    q = max(line_conic_points(C, ray), key=lambda X: to_xy(X) @ [np.cos(th), np.sin(th)])
    assert abs(q @ C @ q) < 1e-9 * np.abs(C).max() * (q @ q)
    plot_point(q, ax, glyph=False, role="accel", text="$Q$", text_offset=(-12, -12))
    plot_line(polar(C, q), ax, role="construct", scale=None, text="$M = CQ$",
              anchor=to_xy(q) + [-0.6, 0.6], color=COLORS["accel"])
    fit_view([[-2.0, -1.6], [2.9, 1.6]], margin=0.05, ax=ax)


@register(5.03, height=2.8)
def fig5_3(ax):
    """Fig. 5.3 — polar of an interior point: two chords through P; the tangents at each chord's
    ends meet at its pole R_i (Theorem 12); L = C P joins R₁ and R₂. From
    conics.polar_construction_interior."""
    C = _ellipse()
    p = from_xy([1.0, 0.45])
    out = draw_polar_interior(C, p, ax, angles=(np.deg2rad(75), np.deg2rad(150)),
                              text_offsets=(None, (10.0, -4.0), None, (-8.0, 4.0)))
    K = out["construction"]
    R1, R2 = to_xy(K.poles[0]), to_xy(K.poles[1])
    out["L"].set_anchor((R1 + R2) / 2)           # L's label between R1 and R2, right of L
    out["R2"].set_text_alignment("right")        # R2's label left of L
    fit_view([R1, R2, [-1.8, -1.2], [1.8, 1.2]], margin=0.15, ax=ax)


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
    plot_conic(C, ax, text="$C$")
    q1, q2, q3 = to_xy(Q1), to_xy(Q2), to_xy(Q3)
    # M1 = C Q1 is the chord Q2 Q3, M2 and M3 the tangents Q1 Q2 and Q1 Q3: labels away from the Qs
    anchors = (q3 + 0.5 * (q3 - q2) / np.hypot(*(q3 - q2)), (q1 + q2) / 2, (q1 + q3) / 2)
    offsets = ((6.0, 2.0), (-4.0, 6.0), (8.0, -6.0))
    q_offsets = ((-6.0, 6.0), (-6.0, 8.0), (-10.0, -2.0))
    for k, Q in enumerate((Q1, Q2, Q3)):
        pt = plot_point(Q, ax, glyph=False, text=f"$Q_{k + 1}$", text_offset=q_offsets[k])
        if k == 0:
            pt.set_text_alignment("right")
        if k == 2:
            pt.set_text_alignment("right", "top")
        plot_line(polar(C, Q), ax, role="construct", scale=None, text=f"$M_{k + 1}$",
                  anchor=anchors[k], text_offset=offsets[k])
    plot_point(P, ax, glyph=False, role="accel", text="$P$")
    plot_line(polar(C, P), ax, scale=None, text="$L = CP$", anchor=[1.0, -1.2],
              text_offset=(8.0, -12.0))
    txt = ", ".join(f"$u_{k + 1}$={v:.2f}" for k, v in enumerate(u / (u @ [Q1[2], Q2[2], Q3[2]])))
    ax.text(0.02, 0.98, txt, transform=ax.transAxes, fontsize=LABEL_PT, ha="left", va="top")
    fit_view([q1, [-1.9, -1.5], [1.9, 1.5]], margin=0.1, ax=ax)


@register(5.05, height=2.7)
def fig5_5(ax):
    """Fig. 5.5 — alternative homogeneous coordinates (5.47–5.56): P = [−r e; 1] with e ⟂ n
    (5.49–5.50), L = [e; r] with e along the line (5.55): a twist about P and a wrench along L."""
    _coords(ax, alternative=True)


def _body(ax):
    """The link of Figs 5.6-5.7 drawn with its centre of mass; returns its inertia (from the shape)."""
    shape = link_polygon([-0.2, 0.0], [2.2, 0.0], 0.7)
    I = Inertia.from_polygon(shape, density=1.0)
    draw_body(shape, ax, com=I.com)
    return I


@register(5.06, height=2.0)
def fig5_6(ax):
    """Fig. 5.6 — the inertia maps an acceleration pole a to its axis of percussion f = I a
    (5.64–5.68): at distance d from the centre of mass, the axis lies beyond it at ρ²/d. Inertia
    from the body's polygon (Inertia.from_polygon), drawn as its radius-of-gyration circle."""
    I = _body(ax)
    c = np.asarray(I.com)
    a = from_xy(c - [1.5, 0.0])
    f = percussion_axis(I.matrix, a)
    d, rho = 1.5, float(I.radius_of_gyration)
    x_axis = to_xy(np.cross(f, [1.0, 0.0, -c[1]]))  # meet with the line y = c_y
    assert np.isclose(x_axis[0] - c[0], rho ** 2 / d)
    # the axis's label near the top of the view, right of the line and outside the circle
    draw_percussion(I.matrix, a, ax, f_anchor=[x_axis[0], c[1] + 0.8], text_offsets=(None, (5.0, 0.0)))
    fit_view([to_xy(a) - [0.3, 0], [2.6, -0.7], [2.6, 0.7]], margin=0.06, ax=ax)


@register(5.07, height=2.4)
def fig5_7(ax):
    """Fig. 5.7 — power relations: a powerless force f passes through the velocity pole v (vᵀf = 0,
    5.69), and a powerless acceleration a lies on the momentum line p = I v (pᵀa = 0,
    5.71–5.72)."""
    I = _body(ax)
    v = 1.2 * from_xy([0.6, -1.1])
    out = draw_power(v, I.matrix, ax, text_offsets=((-14.0, -16.0), (8.0, 4.0), (0.0, -14.0), None),
                     p_label_at=-2.3, f_label_at=-1.0)
    out["v"].set_text_alignment("right")
    fit_view([[-0.6, -1.5], [2.6, 1.45], out["a"].get_xy(), to_xy(v)], margin=0.08, ax=ax)