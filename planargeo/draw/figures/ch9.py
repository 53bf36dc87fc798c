"""Chapter 9 figures: trees, contacts and the slider-crank (9.1-9.3)."""
from __future__ import annotations

import numpy as np

from ...kinematics import kinematics
from ...projective import to_xy
from ...scenes import build as build_scene
from ..artists import plot_line, plot_point
from ..constructions import label
from ..mechanism import draw_ground, draw_model, draw_slider, transform_shape
from ..style import COLORS
from . import fit_view, new_figure, register


def _contact_points(model, data):
    out = []
    for c in model.contacts:
        pa = data.pose[c.a]
        th = pa[2]
        R = np.array([[np.cos(th), -np.sin(th)], [np.sin(th), np.cos(th)]])
        out.append(pa[:2] + R @ np.asarray(c.point_a))
    return out


def _tips(model, data):
    pts = []
    for i in range(model.N):
        th = data.pose[i, 2]
        pts.append(data.pose[i, :2] + 2 * (data.com[i] - data.pose[i, :2]))
        _ = th
    return pts


@register("fig9_1", "Fig. 9.1 — the rigid-body tree of scene 'tree': body 1 is the root (pinned), "
          "bodies 4, 7, 8 and 9 are the tips of the branches (parents (9.1): "
          "−, 1, 2, 3, 1, 5, 6, 6, 1).", 9.01)
def fig9_1():
    res = build_scene("tree")
    d = kinematics(res.model, res.state["q"], np.zeros(res.model.nq))
    fig, ax = new_figure(3.4, 3.0)
    draw_model(res.model, d, ax, width=0.14, show_com=False, names=[str(k + 1) for k in range(9)])
    fit_view(ax, [*d.origin, *_tips(res.model, d)], margin=0.08)
    return fig


@register("fig9_2", "Fig. 9.2 — constrained tree (scene 'constrained-tree'): pin contacts close the "
          "loops 4–7 and 8–9 (G of 9.49); the contact forces F (9.71) drawn as lines (the force on "
          "body a of each contact), with the resulting 5-dof motion (gravity on).", 9.02)
def fig9_2():
    res = build_scene("constrained-tree")
    m = res.model
    d = kinematics(m, res.state["q"], np.asarray(res.state["qd"]))
    fig, ax = new_figure(3.4, 3.0)
    draw_model(m, d, ax, width=0.14, show_com=False, names=[str(k + 1) for k in range(9)])
    F = np.asarray(res.quantities["F"])
    for k, (c, p) in enumerate(zip(m.contacts, _contact_points(m, d))):
        ax.plot(*p, "s", ms=5, mfc="none", mec=COLORS["reaction"], mew=1.2, zorder=8)
        plot_line(F[k], ax, role="reaction", scale=0.12, anchor=p,
                  text=f"$F_{{{c.a + 1}-{c.b + 1}}}$")
    fit_view(ax, [*d.origin, *_tips(m, d)], margin=0.1)
    return fig


def _slider_crank_base(ax, res):
    m = res.model
    d = kinematics(m, res.state["q"], np.asarray(res.state["qd"]))
    draw_model(m, d, ax, width=0.3, labels=False, show_com=True, pin_radius=0.1)
    for i, body in enumerate(m.bodies):
        label(ax, d.com[i], body.name, offset=(9, -3), fontsize=7, color="#1f3a4d", va="center")
    piston = d.pose[2, :2]
    ax.plot([-0.45, -0.45], [piston[1] - 1.3, piston[1] + 1.8], color=COLORS["ground"], lw=1.0)
    ax.plot([0.45, 0.45], [piston[1] - 1.3, piston[1] + 1.8], color=COLORS["ground"], lw=1.0)
    return d


@register("fig9_3", "Fig. 9.3 — slider-crank (scene 'slider-crank', thesis 9.6): relative rotations "
          "ψ, θ, φ with ψ + θ + φ = π/2; the state closes the loop at θ = 1.6063 (the printed 1.603 "
          "and the signs of θ̇, φ̇ in 9.78–9.79 are corrected, docs/errata.md).", 9.03)
def fig9_3():
    res = build_scene("slider-crank")
    fig, ax = new_figure(3.4, 3.4)
    d = _slider_crank_base(ax, res)
    q = res.state["q"]
    absang = np.cumsum(q)
    for i, (nm, val) in enumerate(zip(("ψ", "θ", "φ"), q)):
        o = d.pose[i, :2]
        base = absang[i] - val
        t = np.linspace(base, absang[i], 30)
        rr = (0.9, 0.7, 0.6)[i]
        ax.plot(o[0] + rr * np.cos(t), o[1] + rr * np.sin(t), color=COLORS["twist"], lw=0.8)
        ax.plot([o[0], o[0] + 0.9 * np.cos(base)], [o[1], o[1] + 0.9 * np.sin(base)],
                color=COLORS["construct"], lw=0.6, ls="--")
        mid = t[len(t) // 2]
        label(ax, o + rr * np.array([np.cos(mid), np.sin(mid)]),
              f"{nm} = {val:.3f}", offset=((6, -12), (6, 2), (-62, 4))[i], fontsize=7,
              color=COLORS["twist"])
    fit_view(ax, [*d.origin, d.pose[2, :2] + [0, 1.2], [-1, -0.6], [2.6, 0]], margin=0.08)
    return fig


_ = (draw_ground, draw_slider, transform_shape, plot_point, to_xy)
