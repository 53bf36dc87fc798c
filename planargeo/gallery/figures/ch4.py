"""Chapter 4 figures: twist and wrench addition, kinematics, Newton-Euler (4.1-4.10)."""
from __future__ import annotations

import numpy as np
from matplotlib.patches import Polygon

from planargeo.algorithms.rnea import newton_euler
from planargeo.geometry.projective import from_xy, join, meet, to_xy
from planargeo.screws.twists import inertia_matrix, unit_rotation, unit_translation
from planargeo.draw.artists import plot_conic, plot_line
from planargeo.draw.constructions import (draw_acceleration_step, draw_dimension, draw_newton_euler,
                             draw_twist_sum, draw_velocity_step, draw_wrench_sum, label)
from planargeo.draw.mechanism import draw_com, draw_frame, draw_ground, draw_link, draw_model, draw_pin
from planargeo.draw.style import COLORS, LABEL_PT, legend
from planargeo.draw.layout import fit_view
from planargeo.gallery.figures import chain, register


@register(4.01, height=1.9)
def fig4_1(ax):
    """Fig. 4.1 — two rotations add to a rotation on the line through their poles: ω₃ = ω₁ + ω₂
    (4.11), P = Q₁ + β(Q₂ − Q₁) with β = ω₂/(ω₁ + ω₂) (4.12–4.13)."""
    v1 = 1.0 * unit_rotation([0.0, 0.0])
    v2 = 2.0 * unit_rotation([3.0, 0.0])
    out = draw_twist_sum(v1, v2, ax, labels=("$v_1$ (ω=1)", "$v_2$ (ω=2)", "$v_3$ (ω=3)"),
                         text_offsets=(None, None, (0.0, 19.0)))
    out["v3"].set_text_alignment("center")
    P, Q1, Q2 = to_xy(v1 + v2), to_xy(v1), to_xy(v2)
    draw_dimension(Q1, P, r"$\beta k$", offset=-0.55, ax=ax)
    draw_dimension(Q1, Q2, "$k$", offset=-1.0, ax=ax)
    legend([("twist", "point", "twist (pole)"), ("twist", "sum-point", "sum of twists"),
            ("construct", "line", "lever line")], ax)
    fit_view([Q1, Q2, P, Q1 + [0, -1.1], Q2 + [2.2, 0.6]], margin=0.06, ax=ax)


@register(4.02, height=1.9)
def fig4_2(ax):
    """Fig. 4.2 — lever rule in statics: the reactions R₁, R₂ balancing a load F on a simply
    supported beam, solved as wrenches (F + R₁ + R₂ = 0); β = R₂/(R₁ + R₂) (4.14–4.15)."""
    L, xF, Fmag = 4.0, 1.0, 3.0
    F = join(from_xy([xF, 0.0]), from_xy([xF, -1.0])) * Fmag       # downward load through (xF, 0)
    B = np.column_stack([join(from_xy([0.0, 0.0]), from_xy([0.0, 1.0])),   # unit upward force at 0
                         join(from_xy([L, 0.0]), from_xy([L, 1.0]))])      # ... and at L
    r = np.linalg.solve(B[[1, 2]], -F[[1, 2]])                         # force balance and moment
    R1, R2 = B[:, 0] * r[0], B[:, 1] * r[1]
    assert np.allclose(F + R1 + R2, 0)
    draw_link([0, 0.12], [L, 0.12], ax, width=0.16)
    for x in (0.0, L):
        ax.add_patch(Polygon(
            [[x, 0.04], [x - 0.15, -0.22], [x + 0.15, -0.22]], closed=True, fc="#dddddd",
            ec="#222222", lw=0.8, zorder=2))
        draw_ground([x, -0.22], ax, width=0.5, depth=0.1)
    sc = 0.35
    plot_line(F, ax, scale=sc, anchor=[xF, 0.8], text=f"$F$ = {Fmag:g}")
    plot_line(R1, ax, role="reaction", scale=sc, anchor=[0, -0.75], text=f"$R_1$ = {r[0]:.3g}",
              text_offset=(8, -6))
    plot_line(R2, ax, role="reaction", scale=sc, anchor=[L, -0.75], text=f"$R_2$ = {r[1]:.3g}",
              text_offset=(-6, -6)).set_text_alignment("right")
    beta = r[1] / (r[0] + r[1])
    draw_dimension([0, 0.45], [beta * L, 0.45], r"$\beta L$", ax=ax)
    ax.text(0.6, 0.97, rf"$\beta = R_2/(R_1 + R_2)$ = {beta:.2g}", transform=ax.transAxes,
            ha="center", va="top", fontsize=LABEL_PT)
    fit_view([[-0.3, -1.4], [L + 0.3, 1.4]], margin=0.03, ax=ax)


@register(4.03, height=2.4)
def fig4_3(ax):
    """Fig. 4.3 — a rotation v₁ (ω) plus a translation v₂ (speed u, an ideal point, arrow at the
    edge of the view) is a rotation about P = Q + ρn, ρ = u/ω (4.16)."""
    omega, u, lam = 1.0, 1.5, np.deg2rad(30)
    v1 = omega * unit_rotation([0.0, 0.0])
    v2 = u * unit_translation([np.cos(lam), np.sin(lam)])
    draw_twist_sum(v1, v2, ax, labels=("$v_1$ about $Q$", "$v_2$ (translation)",
                                       "$v_3 = v_1 + v_2$"),
                   text_offsets=((12.0, -18.0), (14.0, -4.0), (12.0, -14.0)))
    P, Q = to_xy(v1 + v2), to_xy(v1)
    draw_dimension(Q, P, r"$\rho = u/\omega$", offset=0.25, ax=ax)
    e = np.array([np.cos(lam), np.sin(lam)])
    ax.annotate("", xy=tuple(Q + 0.8 * e), xytext=tuple(Q),
                arrowprops=dict(arrowstyle="-|>", color=COLORS["twist"], lw=1))
    label(Q + 0.8 * e, "$e$", color=COLORS["twist"], ax=ax)
    fit_view([Q, P, Q - [1.2, 0.8], P + [1.2, 0.5]], margin=0.1, ax=ax)


@register(4.04, height=2.4)
def fig4_4(ax):
    """Fig. 4.4 — two crossing forces add by the parallelogram rule; f₃ passes through the meet
    P = f₁ × f₂ of f₁ and f₂ (4.33–4.39). Erratum: the printed meet 4.35 with the intercepts of
    4.37 has the sign of one y-intercept wrong (both are −τᵢ/f_xi); P is computed homogeneously,
    see docs/errata.md (4.37)."""
    f1 = join(from_xy([-1.0, 0.5]), from_xy([0.0, 1.0])) * 1.2
    f2 = join(from_xy([2.0, -1.0]), from_xy([1.6, 0.5])) * 1.0
    draw_wrench_sum(f1, f2, ax, scale=0.9)
    P = to_xy(meet(f1, f2))
    fit_view([P, P + 0.9 * (f1 + f2)[:2], [-1.0, -1.0], P + [1.8, 1.5]], margin=0.12, ax=ax)


@register(4.05, height=2.0)
def fig4_5(ax):
    """Fig. 4.5 — parallel forces add like two rotations: f₃ lies between them by the lever rule,
    F₃ = F₁ + F₂, d₃ = d₁ + β(d₂ − d₁), β = F₂/(F₁ + F₂) (4.40–4.45)."""
    f1 = join(from_xy([0.0, 0.0]), from_xy([0.0, -1.0])) * 2.0     # downward through x = 0
    f2 = join(from_xy([3.0, 0.0]), from_xy([3.0, -1.0])) * 1.0     # downward through x = 3
    out = draw_wrench_sum(f1, f2, ax, scale=0.4, anchors=([0, 0.45], [3, 0.45], [0, 0.15]),
                          labels=("$f_1$ ($F_1$=2)", "$f_2$ ($F_2$=1)", "$f_3$ ($F_3$=3)"),
                          text_offsets=((-4.0, 6.0), (-4.0, 6.0), (5.0, -4.0)))
    for k in ("f1", "f2"):   # labels to the left of their lines, clear of f3
        out[k].set_text_alignment("right")
    lever = join(from_xy([0.0, 0.0]), from_xy([1.0, 0.0]))
    plot_line(lever, ax, role="construct", scale=None)
    x3 = to_xy(meet(f1 + f2, lever))
    draw_dimension([0, -1.1], [x3[0], -1.1], r"$\beta d$", ax=ax)
    draw_dimension([0, -1.6], [3, -1.6], r"$d = d_2-d_1$", at=0.68, ax=ax)
    fit_view([[-1.3, -1.9], [3.5, 1.0]], margin=0.05, ax=ax)


@register(4.06, height=2.0)
def fig4_6(ax):
    """Fig. 4.6 — a force f₁ plus a pure couple f₂ (the line at infinity, glyph in the corner) is a
    parallel force at ρ = τ/F (4.46)."""
    F, tau = 2.0, 1.5
    f1 = join(from_xy([0.0, 0.0]), from_xy([0.0, 1.0])) * F
    f2 = np.array([0.0, 0.0, tau])
    draw_wrench_sum(f1, f2, ax, scale=0.4, anchors=([0, 0], None, [0, 0]),
                    labels=("$f_1$", "$f_2$ = couple τ", "$f_3 = f_1 + f_2$"))
    x3 = to_xy(meet(f1 + f2, [1.0, 0.0, 0.0]))
    draw_dimension([0, -0.7], [x3[0], -0.7], r"$\rho = \tau/F$", ax=ax)
    fit_view([[-1.2, -1.0], [x3[0] + 1.2, 1.0]], margin=0.05, ax=ax)


#: The state of the chain of Figs 4.7-4.9 and 6.5.
Q47 = np.array([0.5, 0.7, -0.9])
QD47 = np.array([1.5, -0.6, 1.2])
QDD47 = np.array([1.0, 2.0, -6.0])


def _chain3():
    """The chain of Figs 4.7-4.9 and 6.5: three unit links, the last one 0.8 long."""
    return chain(3, tip_com=0.4)


def chain47(ax, **draw):
    """The chain of Figs 4.7-4.9 and 6.5 drawn at ``Q47`` (``draw``: options of ``draw_model``).

    Returns its RNEA state at ``(Q47, QD47, QDD47)`` (4.47-4.56) and the drawn artists.

    Parameters
    ----------
    ax : matplotlib.axes.Axes
        Where to draw.
    **draw : 
        Options of :func:`planargeo.draw.mechanism.draw_model`.

    Returns
    -------
    tuple
        ``(workspace, artists)``.
    """
    m = _chain3()
    w = newton_euler(m, Q47, QD47, QDD47)
    return w, draw_model(m, w, ax, **draw)


@register(4.07, height=2.6)
def fig4_7(ax):
    """Fig. 4.7 — velocity kinematics v_i = v_{i−1} + s_i q̇_i (4.47): the pole of v₃ lies on the
    line joining the pole of v₂ and the joint, at β k with β = q̇/(q̇ + ω_{i−1}) (4.48–4.49);
    computed with planargeo.mechanics.kinematics."""
    d, _ = chain47(ax, show_com=False)
    i = 2
    out = draw_velocity_step(d.v[i - 1], d.s(i)[:, 0], QD47[i], ax,
                             names=("$v_2$", r"$s_3\dot q_3$", "$v_3$"),
                             text_offsets=((8.0, 8.0), (14.0, -20.0), (-22.0, -4.0)),
                             dim_offset=0.4)
    assert np.allclose(out["values"]["v"], d.v[i])
    out["v"].set_text_alignment("right")
    legend([("twist", "point", r"twists $v_2$, $s_3\dot q_3$"),
            ("twist", "sum-point", r"$v_3 = v_2 + s_3\dot q_3$")], ax)
    tip = d.pose[i, :2] + 0.8 * np.array([np.cos(d.pose[i, 2]), np.sin(d.pose[i, 2])])
    fit_view([to_xy(d.v[i - 1]), to_xy(d.v[i]), *d.origin, tip], margin=0.12, ax=ax)


@register(4.08, height=2.8)
def fig4_8(ax):
    """Fig. 4.8 — acceleration kinematics a_i = a_{i−1} + s_i q̈_i + v_i × s_i q̇_i (4.52): the
    bias term is a translation (ideal point); s_i q̈_i plus the bias is a rotation offset from the
    joint (4.54), and a_i lies on its line to a_{i−1}."""
    w, _ = chain47(ax, show_com=False, labels=False)
    i = 2
    out = draw_acceleration_step(
        w.a[i - 1], w.v[i - 1], w.s(i)[:, 0], QD47[i], QDD47[i], ax,
        names=("$a_2$", r"$s_3\ddot q_3$", r"$\kappa_3 = v_3\times s_3\dot q_3$",
               r"$s_3\ddot q_3 + \kappa_3$", "$a_3$"),
        text_offsets=((16.0, -4.0), (-16.0, 12.0), None, (18.0, -4.0), (-22.0, -4.0)))
    out["joint"].set_text_alignment("right")
    out["a"].set_text_alignment("right")
    assert np.allclose(out["values"]["a"], w.a[i])
    assert np.allclose(out["values"]["bias"], w.kappa[i])
    vals = out["values"]
    fit_view([to_xy(vals[k]) for k in ("a_prev", "joint", "joint_total", "a")] + [*w.origin],
             margin=0.15, ax=ax)


@register(4.09, height=2.8)
def fig4_9(ax):
    """Fig. 4.9 — Newton–Euler for body 2 of a chain: f_net = I a + p (4.55–4.56); I a is the axis
    of percussion of a, p the centripetal force through the centre of mass toward the velocity
    pole, f_net = f₂ − f₃ the net joint force (RNEA, no gravity)."""
    w, _ = chain47(ax, labels=False)
    i = 1
    out = draw_newton_euler(w.I[i], w.a[i], w.v[i], ax, scale=0.07,
                            names=("$v_2$", "$a_2$", "$I_2a_2$", "$p_2$",
                                   r"$f^{net}_2 = f_2 - f_3$"),
                            positions=(-1.2, -1.0, 1.0),
                            text_offsets=((-14.0, 8.0), (10.0, -4.0), (-6.0, -16.0), (-20.0, 4.0),
                                          (-30.0, 8.0)))
    assert np.allclose(out["values"]["f_net"], w.f[i] - w.f[i + 1])   # RNEA agrees (4.55)
    legend([("wrench", "line", "force"), ("wrench", "sum-line", "sum of forces"),
            ("momentum", "line", "centripetal $p$"), ("inertia", "line", "inertia")], ax)
    c = w.com[i]
    fit_view([to_xy(w.v[i]), to_xy(w.a[i]), *w.origin, c, c + [1.6, 0.0]], margin=0.1, ax=ax)


@register(4.1, height=1.9)
def fig4_10(ax):
    """Fig. 4.10 — local frame of the planar examples: origin at the joint, x toward the centre of
    mass at distance C; the inertia (4.58) drawn as its radius-of-gyration circle r about the
    centre of mass."""
    mass, C, r = 1.0, 1.2, 0.45
    I = inertia_matrix(mass, [C, 0.0], mass * r * r)
    draw_link([0, 0], [2 * C, 0], ax, width=0.5)
    draw_pin([0, 0], ax, radius=0.06)
    draw_frame([0, 0], ax, length=0.55)
    draw_com([C, 0], ax)
    plot_conic(I, ax, role="inertia", mark_center=False)
    draw_dimension([0, -0.55], [C, -0.55], "$C_i$", ax=ax)
    draw_dimension([C, 0], [C + r * np.cos(0.8), r * np.sin(0.8)], "$r_i$", ax=ax)
    fit_view([[-0.4, -0.8], [2 * C + 0.4, 0.8]], margin=0.02, ax=ax)

