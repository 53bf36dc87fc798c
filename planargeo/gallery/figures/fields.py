"""Figures 1.1 and 1.4 (planar): the velocity field of a twist and the moment field of a wrench."""
from __future__ import annotations

import numpy as np

from planargeo.draw.picture import PX_PER_PT
from planargeo.draw.pictures.kit import aim_label, label_at
from planargeo.draw.sketch import label, panel, segment, show
from planargeo.draw.style import COLORS, LABEL_PT
from planargeo.gallery.figures import register
from planargeo.screws.twists import X_P, X_P_inv_T, Twist, Wrench

#: the twist of Fig. 1.1: ω = 1.2 about (0.4, 0.2)
POLE, OMEGA = np.array([0.4, 0.2]), 1.2
#: the wrench of Fig. 1.4: 1 N along the direction 25° through (0, -0.3)
LINE_POINT, ANGLE = np.array([0.0, -0.3]), np.radians(25.0)


@register(1.01, height=2.9)
def fig1_1(ax):
    """Fig. 1.1 — the velocity field of a planar twist v (ω = 1.2 about the pole): the velocity of
    the body point at each P, the linear part of X_P v (4.8), is perpendicular to the line from
    the pole to P and grows with the distance r as ω r (1.3 with pitch 0: the helical field of the
    spatial case without its axial part); at the pole it vanishes."""
    v = Twist.rotation(POLE, OMEGA).array
    t = np.linspace(-1.5, 1.5, 7)
    P = np.array([[x, y] for y in t for x in t])                                # a 7 × 7 grid
    V = np.array([(X_P(p) @ v)[:2] for p in P])
    r = P - POLE
    assert np.allclose(np.einsum("ij,ij->i", V, r), 0.0)                       # perpendicular
    assert np.allclose(np.hypot(*V.T), OMEGA * np.hypot(*r.T))                  # |v_P| = ω r
    s = 0.17
    pic = panel(ax, [[-1.75, -1.75], [1.75, 1.75]], margin=0.0)
    # the field itself is a chart (matplotlib's quiver); the named elements are the picture's
    ax.quiver(P[:, 0], P[:, 1], s * V[:, 0], s * V[:, 1], angles="xy", scale_units="xy", scale=1,
              color=COLORS["twist"], width=0.006, headwidth=3.5, headlength=4, alpha=0.85)
    pic.point("v", v, role="twist", symbol="v", label="pole of v",
              desc=f"the pole of the twist v (4.10): at ({POLE[0]:g}, {POLE[1]:g}) m, ω = {OMEGA:g} rad/s")
    aim_label(pic.elements[-1], (-0.6, -1.0), 20.0)
    k = 12                                           # one point named: P = (1, -1) and its v_P
    Q = P[k]
    r = float(np.hypot(*(Q - POLE)))
    segment(pic, "r", POLE, Q, label="r", symbol="r",
            desc=f"r: the distance from the pole to P, {r:.3g} m")
    pic.marks("P", [Q], role="text", color="#222222", size=3.0 * PX_PER_PT, symbol="P",
              desc=f"a body point P = ({Q[0]:g}, {Q[1]:g}) m")
    label_at(pic, Q, "P", gap=5.0)
    aim_label(pic.elements[-1], (-1.0, -1.0), 5.0)
    label(pic, "v_P", Q + s * V[k], "vₚ = ω r", offset=(0, -6), va="top", role="twist", symbol="vₚ",
          desc=f"vₚ = ω r (1.3 with pitch 0): the velocity of the body point at P, "
               f"{OMEGA * r:.3g} m/s, perpendicular to r")
    show(pic, ax)


@register(1.04, height=2.9)
def fig1_4(ax):
    """Fig. 1.4 — the moment field of a planar force f (1 N along its line of action): the moment
    τ_P about each point P, the last component of X_P⁻ᵀ f (4.24), is the force times P's signed
    distance from the line (1.43 with pitch 0), so its level lines run parallel to the line of
    action, zero on it, counter-clockwise on its left and clockwise on its right."""
    pic = panel(ax, [[-1.75, -1.75], [1.75, 1.75]], margin=0.0)
    e = np.array([np.cos(ANGLE), np.sin(ANGLE)])
    f = Wrench.force(LINE_POINT, e).array
    t = np.linspace(-2.6, 2.6, 105)
    X, Y = np.meshgrid(t, t)
    tau = np.array([(X_P_inv_T(p) @ f)[2] for p in np.stack([X.ravel(), Y.ravel()], -1)])
    tau = tau.reshape(X.shape)
    # the closed form: τ_P = F · (signed distance of P, positive on the left of f)
    n_ = np.array([-e[1], e[0]])
    assert np.allclose(tau, (X - LINE_POINT[0]) * n_[0] + (Y - LINE_POINT[1]) * n_[1])
    # the level lines are a chart (matplotlib's contour, with their values); the force is the picture's
    levels = np.arange(-1.5, 1.51, 0.5)
    ax.contour(X, Y, tau, levels=levels, colors=[COLORS["momentum"]], linewidths=0.8,
               linestyles=["--" if v < 0 else ":" if v > 0 else "-" for v in levels])
    for lv, t_along, text in ((1.0, -1.2, "τ = 1"), (-1.0, 1.2, "τ = −1")):
        p = LINE_POINT + lv * n_ + t_along * e      # on the level line τ = lv
        ax.text(*p, text, fontsize=LABEL_PT, color=COLORS["momentum"], ha="center", va="center",
                bbox=dict(fc="white", ec="none", pad=0.5))
    for p, text in (((-0.75, 1.5), "τ > 0: counter-clockwise"), ((0.85, -1.55), "τ < 0: clockwise")):
        ax.text(*p, text, fontsize=LABEL_PT, color=COLORS["momentum"], ha="center", va="center",
                bbox=dict(fc="white", ec="none", pad=0.5))
    pic.line("f", f, role="wrench", symbol="f", anchor=LINE_POINT + 0.4 * e,
             desc=f"the force f (4.27): 1 N along {np.degrees(ANGLE):g}° through "
                  f"({LINE_POINT[0]:g}, {LINE_POINT[1]:g}) m, its line of action τ = 0")
    show(pic, ax)
