"""Chapter 3 figures: free-body diagram and the articulated-body idea (3.1, 3.2)."""
from __future__ import annotations

import numpy as np
from shapely.ops import unary_union

from planargeo.algorithms.articulated_inertia import articulated_inertia
from planargeo.algorithms.rnea import newton_euler
from planargeo.geometry.projective import to_xy
from planargeo.draw.artists import plot_conic, plot_line, plot_point
from planargeo.draw.mechanism import draw_body, draw_link, draw_model, link_polygon
from planargeo.draw.style import COLORS
from planargeo.draw.layout import fit_view
from planargeo.gallery.figures import chain, register

#: The state of the three-link chain of Figs 3.1-3.2 and of the joint-split extra.
Q = np.array([0.4, 0.6, -0.7])
QD = np.array([1.0, -0.8, 1.2])
QDD = np.array([0.5, 1.0, -1.5])


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
    draw_model(m, w, ax, alpha=0.12)
    draw_link(w.origin[1], w.origin[2], ax, width=0.18, alpha=0.5)   # the free body, highlighted
    sc = 0.06
    plot_line(w.f[i], ax, role="reaction", scale=sc, anchor=w.origin[i], text="$f_2$")
    plot_line(-w.f[i + 1], ax, role="reaction", scale=sc, anchor=w.origin[i + 1], text="$-f_3$")
    plot_line(g, ax, scale=sc, anchor=w.com[i], text="$g_2$")
    fit_view([*w.origin, w.com[-1] * 2 - w.origin[-1]], margin=0.2, ax=ax)


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
    draw_model(m, w, ax, alpha=0.12)
    tip = w.com[-1] * 2 - w.origin[-1]
    merged = unary_union([link_polygon(w.origin[1], w.origin[2], 0.3),
                          link_polygon(w.origin[2], tip, 0.3)])
    draw_body(merged, ax, color=COLORS["momentum"], alpha=0.25)
    plot_conic(r.A[i], ax, role="inertia", text="$A_2$")
    plot_line(w.f[i], ax, role="reaction", scale=0.25, anchor=w.origin[i], text="$f_2$")
    plot_point(w.a[i], ax, role="accel", text="$a_2$")
    fit_view([*w.origin, tip, to_xy(w.a[i])], margin=0.15, ax=ax)
