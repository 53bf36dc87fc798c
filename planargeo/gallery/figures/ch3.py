"""Chapter 3 figures: free-body diagram and the articulated-body idea (3.1, 3.2)."""
from __future__ import annotations

import numpy as np
from shapely.ops import unary_union

from planargeo.algorithms.articulated_inertia import articulated_inertia
from planargeo.algorithms.rnea import newton_euler
from planargeo.geometry.projective import to_xy
from planargeo.draw.pictures.kit import force
from planargeo.draw.sketch import body, link, link_polygon, model, panel, show
from planargeo.draw.style import COLORS
from planargeo.gallery.figures import chain, register

#: The state of the three-link chain of Figs 3.1-3.2 and of the joint-split extra.
Q = np.array([0.4, 0.6, -0.7])
QD = np.array([1.0, -0.8, 1.2])
QDD = np.array([0.5, 1.0, -1.5])


def _newtons(w) -> str:
    return f"{np.hypot(*np.asarray(w, float)[:2]):.3g} N"


@register(3.01, height=2.6)
def fig3_1(ax):
    """Fig. 3.1 — free-body diagram of body i = 2 of a chain under gravity: applied g₂, internal f₂
    from joint 2 and −f₃ from joint 3 (RNEA); they balance f₂ − f₃ + g₂ = I₂a₂ − (v₂×)ᵀI₂v₂
    (3.9)."""
    m = chain(3, gravity=(0.0, -9.81))
    w = newton_euler(m, Q, QD, QDD)
    i = 1
    g = w.g[i]
    lhs = w.f[i] - w.f[i + 1] + g
    assert np.allclose(lhs, w.I[i] @ w.a[i] + (w.p[i] + g))
    pic = panel(ax, [*w.origin, w.com[-1] * 2 - w.origin[-1]], margin=0.2)
    model(pic, m, w, alpha=0.12)
    link(pic, "free body", w.origin[1], w.origin[2], width=0.18, alpha=0.5,
         desc="the free body i = 2, cut from its neighbours at joints 2 and 3")
    sc = 0.06
    force(pic, "f2", w.f[i], scale=sc, anchor=w.origin[i], role="reaction", symbol="f₂",
          desc=f"internal force on body 2 from joint 2 (3.9): |f₂| = {_newtons(w.f[i])}")
    force(pic, "-f3", -w.f[i + 1], scale=sc, anchor=w.origin[i + 1], role="reaction", symbol="−f₃",
          desc=f"internal force on body 2 from joint 3 (3.9): |f₃| = {_newtons(w.f[i + 1])}")
    force(pic, "g2", g, scale=sc, anchor=w.com[i], role="wrench", symbol="g₂",
          desc=f"gravity on body 2 through its centre of mass (3.9): |g₂| = {_newtons(g)}")
    show(pic, ax)


@register(3.02, height=2.6)
def fig3_2(ax):
    """Fig. 3.2 — articulated body: bodies 2…n treated as one body with the articulated inertia A₂
    (3.20–3.27), so the internal force f₂ and the acceleration a₂ relate by f₂ = A₂a₂ + d₂ (7.7; at
    rest, no gravity, joint torques from RNEA)."""
    m = chain(3)
    w = newton_euler(m, Q, np.zeros(3), QDD)
    r = articulated_inertia(m, Q, np.zeros(3), w.tau)   # the joint torques that realise QDD
    i = 1
    assert np.allclose(w.f[i], r.A[i] @ w.a[i] + r.d[i], atol=1e-9)
    tip = w.com[-1] * 2 - w.origin[-1]
    pic = panel(ax, [*w.origin, tip, to_xy(w.a[i])], margin=0.15)
    model(pic, m, w, alpha=0.12)
    merged = unary_union([link_polygon(w.origin[1], w.origin[2], 0.3),
                          link_polygon(w.origin[2], tip, 0.3)])
    body(pic, "articulated body", merged, color=COLORS["momentum"], alpha=0.25,
         desc="the articulated body: bodies 2 and 3 seen as one through joint 2 (3.20)")
    pic.conic("A2", r.A[i], role="inertia", symbol="A₂",
              desc="articulated inertia of bodies 2…3 at joint 2 (3.27), drawn by its real stand-in")
    force(pic, "f2", w.f[i], scale=0.25, anchor=w.origin[i], role="reaction", symbol="f₂",
          desc=f"internal force on body 2 from joint 2, f₂ = A₂a₂ + d₂ (7.7): |f₂| = {_newtons(w.f[i])}")
    a = np.asarray(w.a[i], float)
    pic.point("a2", a, role="accel", symbol="a₂",
              desc=f"acceleration pole of body 2 (4.6): {a[2]:.3g} rad/s²")
    show(pic, ax)
