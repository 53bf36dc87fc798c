"""Chapter 4 figures: twist and wrench addition, kinematics, Newton-Euler (4.1-4.10)."""
from __future__ import annotations

import numpy as np

from ...algorithms.rnea import newton_euler
from ...kinematics import kinematics
from ...model import Body, Joint, Model
from ...projective import from_xy, join, meet, to_xy
from ...screws import inertia_matrix, unit_rotation, unit_translation
from ..artists import plot_conic, plot_line, plot_point
from ..constructions import draw_dimension, draw_segment, draw_twist_sum, draw_wrench_sum, label
from ..mechanism import draw_com, draw_ground, draw_link, draw_model, draw_pin, draw_frame
from ..style import COLORS
from . import fit_view, new_figure, register


def _legend(ax, items, loc="lower right"):
    from matplotlib.lines import Line2D

    handles = [Line2D([], [], color=COLORS[role], lw=2 if kind == "line" else 0,
                      marker="o" if kind == "point" else None, ms=5, label=text,
                      linestyle="--" if role in ("inertia", "construct") and kind == "line" else "-")
               for role, kind, text in items]
    ax.legend(handles=handles, loc=loc, fontsize=6.5, handlelength=1.8)


@register("fig4_1", "Fig. 4.1 — two rotations add to a rotation on the line through their poles: "
          "ω₃ = ω₁ + ω₂ (4.11), P = Q₁ + β(Q₂ − Q₁) with β = ω₂/(ω₁ + ω₂) (4.12–4.13).", 4.01)
def fig4_1():
    fig, ax = new_figure(3.4, 1.9)
    v1 = 1.0 * unit_rotation([0.0, 0.0])
    v2 = 2.0 * unit_rotation([3.0, 0.0])
    draw_twist_sum(v1, v2, ax, labels=("$v_1$ (ω=1)", "$v_2$ (ω=2)", "$v_3$ (ω=3)"))
    P, Q1, Q2 = to_xy(v1 + v2), to_xy(v1), to_xy(v2)
    draw_dimension(ax, Q1, P, r"$\beta k$", offset=-0.55)
    draw_dimension(ax, Q1, Q2, "$k$", offset=-1.0)
    fit_view(ax, [Q1, Q2, P, Q1 + [0, -1.1], Q2 + [0.9, 0.6]], margin=0.08)
    return fig


@register("fig4_2", "Fig. 4.2 — lever rule in statics: the reactions R₁, R₂ balancing a load F on a "
          "simply supported beam, solved as wrenches (F + R₁ + R₂ = 0); β = R₂/(R₁ + R₂) (4.14–4.15).",
          4.02)
def fig4_2():
    fig, ax = new_figure(3.4, 1.9)
    L, xF, Fmag = 4.0, 1.0, 3.0
    F = join(from_xy([xF, 0.0]), from_xy([xF, -1.0])) * Fmag       # downward load through (xF, 0)
    B = np.column_stack([join(from_xy([0.0, 0.0]), from_xy([0.0, 1.0])),   # unit upward force at 0
                         join(from_xy([L, 0.0]), from_xy([L, 1.0]))])      # ... and at L
    r = np.linalg.solve(B[[1, 2]], -F[[1, 2]])                         # force balance and moment
    R1, R2 = B[:, 0] * r[0], B[:, 1] * r[1]
    assert np.allclose(F + R1 + R2, 0)
    draw_link([0, 0.12], [L, 0.12], ax, width=0.16)
    for x in (0.0, L):
        ax.add_patch(__import__("matplotlib.patches", fromlist=["Polygon"]).Polygon(
            [[x, 0.04], [x - 0.15, -0.22], [x + 0.15, -0.22]], closed=True, fc="#dddddd",
            ec="#222222", lw=0.8, zorder=2))
        draw_ground([x, -0.22], ax, width=0.5, depth=0.1)
    sc = 0.35
    plot_line(F, ax, scale=sc, anchor=[xF, 0.8], text=f"$F$ = {Fmag:g}")
    plot_line(R1, ax, role="reaction", scale=sc, anchor=[0, -0.75], text=f"$R_1$ = {r[0]:.3g}",
              text_offset=(8, -6))
    plot_line(R2, ax, role="reaction", scale=sc, anchor=[L, -0.75], text=f"$R_2$ = {r[1]:.3g}",
              text_offset=(-38, -6))
    beta = r[1] / (r[0] + r[1])
    draw_dimension(ax, [0, 0.45], [beta * L, 0.45], rf"$\beta L$, β={beta:.2g}")
    fit_view(ax, [[-0.3, -1.4], [L + 0.3, 1.4]], margin=0.03)
    return fig


@register("fig4_3", "Fig. 4.3 — a rotation v₁ (ω) plus a translation v₂ (speed u, an ideal point, "
          "arrow at the edge of the view) is a rotation about P = Q + ρn, ρ = u/ω (4.16).", 4.03)
def fig4_3():
    fig, ax = new_figure(3.4, 2.4)
    omega, u, lam = 1.0, 1.5, np.deg2rad(30)
    v1 = omega * unit_rotation([0.0, 0.0])
    v2 = u * unit_translation([np.cos(lam), np.sin(lam)])
    out = draw_twist_sum(v1, v2, ax, labels=("$v_1$ about $Q$", "$v_2$ (translation)",
                                             "$v_3 = v_1 + v_2$"))
    out["v3"].set_text(None)
    label(ax, to_xy(v1 + v2), "$v_3 = v_1 + v_2$", offset=(10, -14), color=COLORS["accel"])
    P, Q = to_xy(v1 + v2), to_xy(v1)
    draw_dimension(ax, Q, P, r"$\rho = u/\omega$", offset=0.25)
    e = np.array([np.cos(lam), np.sin(lam)])
    ax.annotate("", xy=tuple(Q + 0.8 * e), xytext=tuple(Q),
                arrowprops=dict(arrowstyle="-|>", color=COLORS["twist"], lw=1))
    label(ax, Q + 0.8 * e, "$e$", color=COLORS["twist"])
    fit_view(ax, [Q, P, Q - [1.2, 0.8], P + [1.2, 0.5]], margin=0.1)
    _ = out
    return fig


@register("fig4_4", "Fig. 4.4 — two crossing forces add by the parallelogram rule; f₃ passes through "
          "the meet of f₁ and f₂ (4.33–4.39).", 4.04)
def fig4_4():
    fig, ax = new_figure(3.4, 2.4)
    f1 = join(from_xy([-1.0, 0.5]), from_xy([0.0, 1.0])) * 1.2
    f2 = join(from_xy([2.0, -1.0]), from_xy([1.6, 0.5])) * 1.0
    draw_wrench_sum(f1, f2, ax, scale=0.9)
    P = to_xy(meet(f1, f2))
    fit_view(ax, [P, P + 0.9 * (f1 + f2)[:2], [-1.0, -1.0], P + [1.8, 1.5]], margin=0.12)
    return fig


@register("fig4_5", "Fig. 4.5 — parallel forces add like two rotations: f₃ lies between them by the "
          "lever rule, F₃ = F₁ + F₂, d₃ = d₁ + β(d₂ − d₁), β = F₂/(F₁ + F₂) (4.40–4.45).", 4.05)
def fig4_5():
    fig, ax = new_figure(3.4, 2.0)
    down = np.array([0.0, -1.0])
    f1 = join(from_xy([0.0, 0.0]), from_xy(down)) * 2.0
    f2 = join(from_xy([3.0, 0.0]), from_xy([3.0, -1.0])) * 1.0
    f3 = f1 + f2
    plot_line(f1, ax, scale=0.4, anchor=[0, 0.3], text="$f_1$ ($F_1$=2)")
    plot_line(f2, ax, scale=0.4, anchor=[3, 0.3], text="$f_2$ ($F_2$=1)")
    plot_line(f3, ax, role="reaction", scale=0.4, anchor=[0, -0.3], text="$f_3$ ($F_3$=3)")
    lever = join(from_xy([0.0, 0.0]), from_xy([1.0, 0.0]))
    plot_line(lever, ax, role="construct", scale=None)
    x3 = to_xy(meet(f3, lever))
    draw_dimension(ax, [0, -1.1], [x3[0], -1.1], r"$\beta\,(d_2-d_1)$")
    draw_dimension(ax, [0, -1.6], [3, -1.6], r"$d_2-d_1$")
    fit_view(ax, [[-0.5, -1.9], [3.5, 1.0]], margin=0.05)
    return fig


@register("fig4_6", "Fig. 4.6 — a force f₁ plus a pure couple f₂ (the line at infinity, glyph in the "
          "corner) is a parallel force at ρ = τ/F (4.46).", 4.06)
def fig4_6():
    fig, ax = new_figure(3.4, 2.0)
    F, tau = 2.0, 1.5
    f1 = join(from_xy([0.0, 0.0]), from_xy([0.0, 1.0])) * F
    f2 = np.array([0.0, 0.0, tau])
    out = draw_wrench_sum(f1, f2, ax, scale=0.4, labels=("$f_1$", "$f_2$ = couple τ",
                                                         "$f_3 = f_1 + f_2$"),
                          anchors=([0, 0], None, [0, 0]))
    x3 = to_xy(meet(f1 + f2, [1.0, 0.0, 0.0]))
    draw_dimension(ax, [0, -0.7], [x3[0], -0.7], r"$\rho = \tau/F$")
    fit_view(ax, [[-1.2, -1.0], [x3[0] + 1.2, 1.0]], margin=0.05)
    _ = out
    return fig


def _chain3(gravity=(0.0, 0.0)):
    bodies = [Body(1.0, (0.5, 0.0), 1 / 12, name="1"), Body(1.0, (0.5, 0.0), 1 / 12, name="2"),
              Body(1.0, (0.4, 0.0), 1 / 12, name="3")]
    joints = [Joint("revolute", (0.0, 0.0, 0.0)), Joint("revolute", (1.0, 0.0, 0.0)),
              Joint("revolute", (1.0, 0.0, 0.0))]
    return Model(bodies, joints, [-1, 0, 1], gravity)


Q47 = np.array([0.5, 0.7, -0.9])
QD47 = np.array([1.5, -0.6, 1.2])
QDD47 = np.array([1.0, 2.0, -6.0])


@register("fig4_7", "Fig. 4.7 — velocity kinematics v_i = v_{i−1} + s_i q̇_i (4.47): the pole of v₃ "
          "lies on the line joining the pole of v₂ and the joint, at β k with β = q̇/(q̇ + ω_{i−1}) "
          "(4.48–4.49); computed with planargeo.kinematics.", 4.07)
def fig4_7():
    fig, ax = new_figure(3.4, 2.6)
    m = _chain3()
    d = kinematics(m, Q47, QD47)
    draw_model(m, d, ax, show_com=False)
    v2, v3 = d.v[1], d.v[2]
    s3 = d.s(2)[:, 0] * QD47[2]
    plot_line(join(v2, s3), ax, role="construct", scale=None)
    plot_point(v2, ax, text="$v_2$")
    plot_point(s3, ax, role="twist", text=r"$s_3\dot q_3$", text_offset=(8, -12))
    plot_point(v3, ax, role="accel", text="$v_3$")
    pts = [to_xy(v2), to_xy(s3), to_xy(v3), *d.origin, d.pose[2, :2] + 0.8 * np.array(
        [np.cos(d.pose[2, 2]), np.sin(d.pose[2, 2])])]
    draw_dimension(ax, to_xy(v2), to_xy(s3), "$k$", offset=0.25)
    fit_view(ax, pts, margin=0.12)
    return fig


@register("fig4_8", "Fig. 4.8 — acceleration kinematics a_i = a_{i−1} + s_i q̈_i + v_i × s_i q̇_i "
          "(4.52): the bias term is a translation (ideal point); s_i q̈_i plus the bias is a rotation "
          "offset from the joint (4.54), and a_i lies on its line to a_{i−1}.", 4.08)
def fig4_8():
    fig, ax = new_figure(3.4, 2.8)
    m = _chain3()
    w = newton_euler(m, Q47, QD47, QDD47)
    a2, a3 = w.a[1], w.a[2]
    s3 = w.s(2)[:, 0]
    rel = s3 * QDD47[2]
    bias = w.kappa[2]
    combo = rel + bias
    assert np.allclose(a2 + combo, a3)
    draw_model(m, w, ax, show_com=False)
    plot_line(join(a2, combo), ax, role="construct", scale=None)
    plot_line(join(s3, combo), ax, role="construct", scale=None, linewidth=0.6)
    plot_point(a2, ax, role="accel", text="$a_2$")
    plot_point(rel, ax, role="accel", text=r"$s_3\ddot q_3$", text_offset=(-30, 6))
    plot_point(bias, ax, role="accel", text=r"$v_3\times s_3\dot q_3$")
    plot_point(combo, ax, role="accel", text=r"$s_3\ddot q_3 + v_3\times s_3\dot q_3$",
               text_offset=(10, -16))
    plot_point(a3, ax, role="accel", text="$a_3$")
    fit_view(ax, [to_xy(a2), to_xy(rel), to_xy(combo), to_xy(a3), *w.origin], margin=0.15)
    return fig


@register("fig4_9", "Fig. 4.9 — Newton–Euler for body 2 of a chain: f_net = I a + p (4.55–4.56); "
          "I a is the axis of percussion of a, p the centripetal force through the centre of mass "
          "toward the velocity pole, f_net = f₂ − f₃ the net joint force (RNEA, no gravity).", 4.09)
def fig4_9():
    fig, ax = new_figure(3.4, 2.8)
    m = _chain3()
    w = newton_euler(m, Q47, QD47, QDD47)
    i = 1
    I, a, v, p = w.I[i], w.a[i], w.v[i], w.p[i]
    Ia = I @ a
    fnet = w.f[i] - w.f[i + 1]
    assert np.allclose(fnet, Ia + p)
    draw_model(m, w, ax)
    plot_conic(I, ax, role="inertia")
    sc = 0.07
    c = w.com[i]

    def along(f, t):  # a point on line f at signed distance t from the foot of c
        e = f[:2] / np.hypot(*f[:2])
        return c + e * t

    plot_point(v, ax, text="$v_2$")
    plot_point(a, ax, role="accel", text="$a_2$")
    plot_line(Ia, ax, scale=sc, text="$I_2a_2$", anchor=along(Ia, -1.0))
    plot_line(p, ax, role="momentum", scale=sc, text="$p_2$", anchor=along(p, -0.9),
              text_offset=(-14, 4))
    plot_line(fnet, ax, role="reaction", scale=sc, text=r"$f^{net}_2 = f_2 - f_3$",
              anchor=along(fnet, 1.0), text_offset=(-20, 8))
    fit_view(ax, [to_xy(v), to_xy(a), *w.origin, c, c + [1.6, 0.0]], margin=0.1)
    return fig


@register("fig4_10", "Fig. 4.10 — local frame of the planar examples: origin at the joint, x toward "
          "the centre of mass at distance C; the inertia (4.58) drawn as its radius-of-gyration "
          "circle r about the centre of mass.", 4.10)
def fig4_10():
    fig, ax = new_figure(3.4, 1.9)
    mass, C, r = 1.0, 1.2, 0.45
    I = inertia_matrix(mass, [C, 0.0], mass * r * r)
    draw_link([0, 0], [2 * C, 0], ax, width=0.5)
    draw_pin([0, 0], ax, radius=0.06)
    draw_frame([0, 0], 0.0, ax, length=0.55)
    draw_com([C, 0], ax)
    plot_conic(I, ax, role="inertia", mark_center=False)
    draw_dimension(ax, [0, -0.55], [C, -0.55], "$C_i$")
    draw_dimension(ax, [C, 0], [C + r * np.cos(0.8), r * np.sin(0.8)], "$r_i$")
    fit_view(ax, [[-0.4, -0.8], [2 * C + 0.4, 0.8]], margin=0.02)
    return fig


_ = (plot_conic, draw_segment, label)
