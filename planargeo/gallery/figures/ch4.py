"""Chapter 4 figures: twist and wrench addition, kinematics, Newton-Euler (4.1-4.10)."""
from __future__ import annotations

import numpy as np

from planargeo.algorithms.rnea import newton_euler
from planargeo.draw.picture import PX_PER_PT, Picture
from planargeo.draw.pictures._words import force as force_words, num
from planargeo.draw.pictures.kit import aim_label, force
from planargeo.draw.sketch import arrow, com, dimension, frame, ground, label, link, model, panel, pin, show
from planargeo.draw.style import legend
from planargeo.draw.sums import acceleration_step, newton_euler as newton_euler_balance, twist_sum, \
    velocity_step, wrench_sum
from planargeo.gallery.figures import chain, register
from planargeo.geometry.projective import from_xy, join, meet, to_xy
from planargeo.screws.twists import inertia_matrix, unit_rotation, unit_translation


@register(4.01, height=1.9)
def fig4_1(ax):
    """Fig. 4.1 — two rotations add to a rotation on the line through their poles: ω₃ = ω₁ + ω₂
    (4.11), P = Q₁ + β(Q₂ − Q₁) with β = ω₂/(ω₁ + ω₂) (4.12–4.13)."""
    v1 = 1.0 * unit_rotation([0.0, 0.0])
    v2 = 2.0 * unit_rotation([3.0, 0.0])
    P, Q1, Q2 = to_xy(v1 + v2), to_xy(v1), to_xy(v2)
    pic = panel(ax, [Q1, Q2, P, Q1 + [0, -1.1], Q2 + [2.2, 0.6]], margin=0.06)
    twist_sum(pic, v1, v2, labels=("$v_1$ (ω=1)", "$v_2$ (ω=2)", "$v_3$ (ω=3)"),
              toward=(None, None, (0.0, 1.0)))
    dimension(pic, "beta k", Q1, P, "βk", offset=-0.55,
              desc=f"distance βk from Q₁ to the sum's pole P (4.12–4.13): β = 2/3, βk = {num(P[0] - Q1[0])} m")
    dimension(pic, "k", Q1, Q2, "k", offset=-1.0,
              desc=f"distance k between the poles Q₁ and Q₂ (4.12): {num(Q2[0] - Q1[0])} m")
    show(pic, ax)
    legend([("twist", "point", "twist (pole)"), ("twist", "sum-point", "sum of twists"),
            ("construct", "line", "lever line")], ax)


def _support(pic: Picture, id: str, x: float) -> None:
    """A simple support under the beam at ``x``: a triangle on hatched ground."""
    pic.path(id, [[x, 0.04], [x - 0.15, -0.22], [x + 0.15, -0.22]], role="body", closed=True,
             fill="#dddddd", color="#222222", width=0.8 * 100 / 72, z=2, symbol="support",
             desc=f"a simple support at x = {num(x)} m: it pushes only up or down")
    ground(pic, id + " ground", [x, -0.22], width=0.5, depth=0.1)


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
    beta = r[1] / (r[0] + r[1])
    pic = panel(ax, [[-0.3, -1.4], [L + 0.3, 1.4]], margin=0.03)
    link(pic, "beam", [0, 0.12], [L, 0.12], width=0.16, symbol="beam", desc=f"the beam, {num(L)} m long")
    for k, x in ((1, 0.0), (2, L)):
        _support(pic, f"support {k}", x)
    sc = 0.35
    force(pic, "F", F, scale=sc, anchor=[xF, 0.8], role="wrench", symbol="F", label=f"F = {Fmag:g}",
          desc=f"load F on the beam (4.14): {force_words(F)}")
    force(pic, "R1", R1, scale=sc, anchor=[0, -0.75], role="reaction", symbol="R₁",
          label=f"R₁ = {r[0]:.3g}", desc=f"reaction R₁ of the left support (4.15): {force_words(R1)}")
    aim_label(pic.elements[-1], (1.0, -0.3))
    force(pic, "R2", R2, scale=sc, anchor=[L, -0.75], role="reaction", symbol="R₂",
          label=f"R₂ = {r[1]:.3g}", desc=f"reaction R₂ of the right support (4.15): {force_words(R2)}")
    aim_label(pic.elements[-1], (-1.0, -0.3))
    dimension(pic, "beta L", [0, 0.45], [beta * L, 0.45], "βL",
              desc=f"lever arm βL of the load from the left support (4.15): {num(beta * L)} m")["z"] = 6
    x0, x1, y0, y1 = pic.box
    label(pic, "beta", (x0 + 0.6 * (x1 - x0), y1), f"β = R₂/(R₁ + R₂) = {beta:.2g}", offset=(0, -2),
          ha="center", va="top", fixed=True, symbol="β", desc=f"lever ratio β = R₂/(R₁ + R₂) (4.15): {beta:.4g}")
    show(pic, ax)


@register(4.03, height=2.4)
def fig4_3(ax):
    """Fig. 4.3 — a rotation v₁ (ω) plus a translation v₂ (speed u, an ideal point, arrow at the
    edge of the view) is a rotation about P = Q + ρn, ρ = u/ω (4.16)."""
    omega, u, lam = 1.0, 1.5, np.deg2rad(30)
    v1 = omega * unit_rotation([0.0, 0.0])
    v2 = u * unit_translation([np.cos(lam), np.sin(lam)])
    P, Q = to_xy(v1 + v2), to_xy(v1)
    e = np.array([np.cos(lam), np.sin(lam)])
    pic = panel(ax, [Q, P, Q - [1.2, 0.8], P + [1.2, 0.5]], margin=0.1)
    twist_sum(pic, v1, v2, labels=("$v_1$ about $Q$", "$v_2$ (translation)", "$v_3 = v_1 + v_2$"),
              toward=((1.0, -1.0), None, (1.0, -0.5)))
    dimension(pic, "rho", Q, P, "ρ = u/ω", offset=0.25,
              desc=f"distance ρ = u/ω from Q to the sum's pole P (4.16): {num(u / omega)} m")
    arrow(pic, "e", Q, Q + 0.8 * e, role="twist", label="e", offset=6 * e / PX_PER_PT, symbol="e",
          desc="direction e of the translation v₂ (4.16): 30° from x")     # the label 6 px beyond the tip
    show(pic, ax)


@register(4.04, height=2.4)
def fig4_4(ax):
    """Fig. 4.4 — two crossing forces add by the parallelogram rule; f₃ passes through the meet
    P = f₁ × f₂ of f₁ and f₂ (4.33–4.39). Erratum: the printed meet 4.35 with the intercepts of
    4.37 has the sign of one y-intercept wrong (both are −τᵢ/f_xi); P is computed homogeneously,
    see docs/errata.md (4.37)."""
    f1 = join(from_xy([-1.0, 0.5]), from_xy([0.0, 1.0])) * 1.2
    f2 = join(from_xy([2.0, -1.0]), from_xy([1.6, 0.5])) * 1.0
    P = to_xy(meet(f1, f2))
    pic = panel(ax, [P, P + 0.9 * (f1 + f2)[:2], [-1.0, -1.0], P + [1.8, 1.5]], margin=0.12)
    wrench_sum(pic, f1, f2, scale=0.9)
    show(pic, ax)


@register(4.05, height=2.0)
def fig4_5(ax):
    """Fig. 4.5 — parallel forces add like two rotations: f₃ lies between them by the lever rule,
    F₃ = F₁ + F₂, d₃ = d₁ + β(d₂ − d₁), β = F₂/(F₁ + F₂) (4.40–4.45)."""
    f1 = join(from_xy([0.0, 0.0]), from_xy([0.0, -1.0])) * 2.0     # downward through x = 0
    f2 = join(from_xy([3.0, 0.0]), from_xy([3.0, -1.0])) * 1.0     # downward through x = 3
    lever = join(from_xy([0.0, 0.0]), from_xy([1.0, 0.0]))
    x3 = to_xy(meet(f1 + f2, lever))
    pic = panel(ax, [[-1.3, -1.9], [3.5, 1.0]], margin=0.05)
    pic.line("lever", lever, role="construct", arrow=False, label="", symbol="lever line",
             desc="lever line through the two points of application (4.43): the sum's line meets it at d₃")
    wrench_sum(pic, f1, f2, scale=0.4, anchors=([0, 0.45], [3, 0.45], [0, 0.15]),
               labels=("$f_1$ ($F_1$=2)", "$f_2$ ($F_2$=1)", "$f_3$ ($F_3$=3)"),
               toward=((-1.0, 0.4), (-1.0, 0.4), (1.0, -0.3)))
    dimension(pic, "beta d", [0, -1.1], [x3[0], -1.1], "βd",
              desc=f"distance βd from f₁ to the sum's line (4.43): β = 1/3, βd = {num(x3[0])} m")["z"] = 6
    dimension(pic, "d", [0, -1.6], [3, -1.6], "d = d₂ − d₁", at=0.68,
              desc="distance d = d₂ − d₁ between the two forces (4.43): 3 m")["z"] = 6
    show(pic, ax)


@register(4.06, height=2.0)
def fig4_6(ax):
    """Fig. 4.6 — a force f₁ plus a pure couple f₂ (the line at infinity, glyph in the corner) is a
    parallel force at ρ = τ/F (4.46)."""
    F, tau = 2.0, 1.5
    f1 = join(from_xy([0.0, 0.0]), from_xy([0.0, 1.0])) * F
    f2 = np.array([0.0, 0.0, tau])
    x3 = to_xy(meet(f1 + f2, [1.0, 0.0, 0.0]))
    pic = panel(ax, [[-1.2, -1.0], [x3[0] + 1.2, 1.0]], margin=0.05)
    wrench_sum(pic, f1, f2, scale=0.4, anchors=([0, 0], None, [0, 0]),
               labels=("$f_1$", "$f_2$ = couple τ", "$f_3 = f_1 + f_2$"))
    dimension(pic, "rho", [0, -0.7], [x3[0], -0.7], "ρ = τ/F",
              desc=f"offset ρ = τ/F of the sum's line from f₁ (4.46): {num(tau / F)} m")["z"] = 6
    show(pic, ax)


#: The state of the chain of Figs 4.7-4.9 and 6.5.
Q47 = np.array([0.5, 0.7, -0.9])
QD47 = np.array([1.5, -0.6, 1.2])
QDD47 = np.array([1.0, 2.0, -6.0])


def _chain3():
    """The chain of Figs 4.7-4.9 and 6.5: three unit links, the last one 0.8 long."""
    return chain(3, tip_com=0.4)


def chain47_state():
    """The chain of Figs 4.7-4.9 and 6.5 and its RNEA state at ``(Q47, QD47, QDD47)`` (4.47-4.56).

    Returns
    -------
    tuple
        ``(model, workspace)``.

    Examples
    --------
    >>> m, w = chain47_state()
    >>> m.N, w.v.shape
    (3, (3, 3))
    """
    m = _chain3()
    return m, newton_euler(m, Q47, QD47, QDD47)


@register(4.07, height=2.6)
def fig4_7(ax):
    """Fig. 4.7 — velocity kinematics v_i = v_{i−1} + s_i q̇_i (4.47): the pole of v₃ lies on the
    line joining the pole of v₂ and the joint, at β k with β = q̇/(q̇ + ω_{i−1}) (4.48–4.49);
    computed with planargeo.mechanics.kinematics."""
    m, d = chain47_state()
    i = 2
    tip = d.pose[i, :2] + 0.8 * np.array([np.cos(d.pose[i, 2]), np.sin(d.pose[i, 2])])   # of the 0.8 link
    pic = panel(ax, [to_xy(d.v[i - 1]), to_xy(d.v[i]), *d.origin, tip], margin=0.12)
    model(pic, m, d, show_com=False)
    out = velocity_step(pic, d.v[i - 1], d.s(i)[:, 0], QD47[i],
                        labels=("$v_2$", r"$s_3\dot{q}_3$", "$v_3$"), dim_offset=0.4,
                        toward=((1.0, 1.0), (1.0, -1.4), (-1.0, -0.2)))
    assert np.allclose(out["values"]["v"], d.v[i])
    show(pic, ax)
    legend([("twist", "point", r"twists $v_2$, $s_3\dot q_3$"),
            ("twist", "sum-point", r"$v_3 = v_2 + s_3\dot q_3$")], ax)


@register(4.08, height=2.8)
def fig4_8(ax):
    """Fig. 4.8 — acceleration kinematics a_i = a_{i−1} + s_i q̈_i + v_i × s_i q̇_i (4.52): the
    bias term is a translation (ideal point); s_i q̈_i plus the bias is a rotation offset from the
    joint (4.54), and a_i lies on its line to a_{i−1}."""
    m, w = chain47_state()
    i = 2
    rel = w.s(i)[:, 0] * QDD47[i]
    pts = [to_xy(p) for p in (w.a[i - 1], rel, rel + w.kappa[i], w.a[i])] + [*w.origin]
    pic = panel(ax, pts, margin=0.15)
    model(pic, m, w, show_com=False, labels=False)
    out = acceleration_step(
        pic, w.a[i - 1], w.v[i - 1], w.s(i)[:, 0], QD47[i], QDD47[i],
        labels=("$a_2$", r"$s_3\ddot{q}_3$", r"$\kappa_3 = v_3 \times s_3\dot{q}_3$",
                r"$s_3\ddot{q}_3 + \kappa_3$", "$a_3$"),
        toward=((1.0, -0.25), (-1.0, 0.75), None, (1.0, -0.2), (-1.0, -0.2)))
    assert np.allclose(out["values"]["a"], w.a[i])
    assert np.allclose(out["values"]["bias"], w.kappa[i])
    show(pic, ax)


@register(4.09, height=2.8)
def fig4_9(ax):
    """Fig. 4.9 — Newton–Euler for body 2 of a chain: f_net = I a + p (4.55–4.56); I a is the axis
    of percussion of a, p the centripetal force through the centre of mass toward the velocity
    pole, f_net = f₂ − f₃ the net joint force (RNEA, no gravity)."""
    m, w = chain47_state()
    i = 1
    c = w.com[i]
    pic = panel(ax, [to_xy(w.v[i]), to_xy(w.a[i]), *w.origin, c, c + [1.6, 0.0]], margin=0.1)
    model(pic, m, w, labels=False)
    out = newton_euler_balance(pic, w.I[i], w.a[i], w.v[i], scale=0.07,
                               labels=("$v_2$", "$a_2$", "$I_2a_2$", "$p_2$", "f₂ⁿᵉᵗ = f₂ − f₃"),
                               positions=(-1.2, -1.0, 1.0))
    assert np.allclose(out["values"]["f_net"], w.f[i] - w.f[i + 1])   # RNEA agrees (4.55)
    show(pic, ax)
    legend([("wrench", "line", "force"), ("wrench", "sum-line", "sum of forces"),
            ("momentum", "line", "centripetal $p$"), ("inertia", "line", "inertia")], ax)


@register(4.1, height=1.9)
def fig4_10(ax):
    """Fig. 4.10 — local frame of the planar examples: origin at the joint, x toward the centre of
    mass at distance C; the inertia (4.58) drawn as its radius-of-gyration circle r about the
    centre of mass."""
    mass, C, r = 1.0, 1.2, 0.45
    I = inertia_matrix(mass, [C, 0.0], mass * r * r)
    pic = panel(ax, [[-0.4, -0.8], [2 * C + 0.4, 0.8]], margin=0.02)
    link(pic, "body", [0, 0], [2 * C, 0], width=0.5, symbol="body i", desc="body i in its local frame")
    pin(pic, "joint", [0, 0], radius=0.06, desc="joint i, the origin of the local frame")
    frame(pic, "frame", [0, 0], length=0.55, desc="local frame of body i: x toward the centre of mass")
    com(pic, "com", [C, 0], desc=f"centre of mass of body i, C = {num(C)} m along x")
    pic.conic("inertia", I, role="inertia", symbol="I", label="", mark_center=False,
              desc=f"inertia I (4.58) as its circle of gyration: radius r = {num(r)} m about the centre of mass")
    dimension(pic, "C", [0, -0.55], [C, -0.55], "Cᵢ",
              desc=f"distance Cᵢ from the joint to the centre of mass (4.58): {num(C)} m")
    dimension(pic, "r", [C, 0], [C + r * np.cos(0.8), r * np.sin(0.8)], "rᵢ",
              desc=f"radius of gyration rᵢ (4.58): {num(r)} m")
    show(pic, ax)
