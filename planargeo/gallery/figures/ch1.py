"""Chapter 1 figures: material vs spatial acceleration of a spinning disk (1.2, 1.3)."""
from __future__ import annotations

import numpy as np

from planargeo.draw.picture import PX_PER_PT
from planargeo.draw.pictures.kit import aim_label, label_at
from planargeo.draw.sketch import arrow, panel, show
from planargeo.draw.style import COLORS
from planargeo.gallery.figures import register
from planargeo.screws.twists import X_P, crm, unit_rotation

OMEGA, R_DISK, P = 2.0, 1.0, np.array([0.7, 0.35])
#: arrow length per unit velocity or acceleration (m per m/s, m per m/s²)
ARROW = 0.2
#: the body points' colour (a dark dot) and the other instants' (grey)
DOT, DOT_OTHER = "#222222", "#999999"


def _disk(ax):
    """Figs 1.2-1.3's disk spinning about O: ``(picture, twist v, velocity v_P of the point at P)``."""
    pic = panel(ax, [[-1.1, -1.1], [1.6, 1.1]], margin=0.03)
    t = np.linspace(0.0, 2 * np.pi, 97)[:-1]
    pic.path("disk", R_DISK * np.column_stack([np.cos(t), np.sin(t)]), role="body", closed=True,
             fill=COLORS["body"], alpha=0.35, color="#1f3a4d", symbol="disk",
             desc=f"the disk: radius {R_DISK:g} m, centre O")
    v = OMEGA * unit_rotation([0.0, 0.0])     # constant spin about O
    pic.point("v", v, role="twist", symbol="v", label="v (ω = const)",
              desc=f"the disk's twist v: rotation about O at ω = {OMEGA:g} rad/s (constant)")
    aim_label(pic.elements[-1], (0.0, -1.0), 22.0)     # below the glyph, clear of P's arrows
    return pic, v, (X_P(P) @ v)[:2]


def _vector(pic, id, p, d, *, role, symbol, desc, label=None, aim=None):
    """An arrow from ``p`` along the data vector ``d``, labelled at its tip (tried first toward ``aim``)."""
    tip = np.asarray(p) + np.asarray(d)
    el = arrow(pic, id, p, tip, role=role, symbol=symbol, desc=desc)
    label_at(pic, tip, symbol if label is None else label, gap=4.0)
    if aim is not None:
        aim_label(el, aim, 8.0)


def _dot(pic, id, xy, *, color=DOT, symbol="", desc="", label=None, aim=(1.0, 1.0)):
    """A body point: a small dot, with a placed label (tried first in the pixel direction ``aim``)."""
    pic.marks(id, [xy], role="text", color=color, size=3.5 * PX_PER_PT, symbol=symbol, desc=desc)
    if label:
        label_at(pic, xy, label, gap=4.0)
        aim_label(pic.elements[-1], aim, 7.0)


@register(1.02, height=2.3)
def fig1_2(ax):
    """Fig. 1.2 — material acceleration of a disk spinning at constant ω: the body point at P moves
    on a circle, so its acceleration v̇_P + ω × v_P = −ω² r is centripetal (computed from the twist
    with X_P and crm)."""
    pic, v, vP = _disk(ax)
    a_spatial = np.zeros(3)                     # dv/dt = 0 for constant spin
    aP = (X_P(P) @ a_spatial)[:2] + (crm(v) @ np.append(vP, 0.0))[:2]  # ω × v_P
    assert np.allclose(aP, -OMEGA ** 2 * P)
    t = np.linspace(0, 2 * np.pi, 100)
    r = np.hypot(*P)
    pic.path("path of P", np.column_stack([r * np.cos(t), r * np.sin(t)]), role="construct",
             color=COLORS["construct"], width=0.6 * PX_PER_PT, dash=[4 * PX_PER_PT, 3 * PX_PER_PT],
             symbol="path", desc=f"the circle the body point at P moves on: radius r = {r:.3g} m", z=2)
    _dot(pic, "P", P, symbol="P", label="P",
         desc=f"a body point, at P = ({P[0]:g}, {P[1]:g}) m now")
    _vector(pic, "v_P", P, ARROW * vP, role="twist", symbol="vₚ",
            desc=f"velocity of the body point at P (X_P v, 4.8): |vₚ| = {np.hypot(*vP):.3g} m/s")
    _vector(pic, "a_P", P, ARROW * aP, role="accel", symbol="−ω² r",
            desc=f"its material acceleration v̇ₚ + ω × vₚ = −ω² r: {np.hypot(*aP):.3g} m/s², towards O",
            aim=(1.0, -1.0))
    show(pic, ax)


@register(1.03, height=2.3)
def fig1_3(ax):
    """Fig. 1.3 — spatial acceleration of the same disk is zero: the velocity of whatever body
    point occupies the fixed spatial location P is the same at every instant (grey dots: body
    points that are at P a moment before and after; each has velocity v_P there, one arrow), so
    a = dv/dt = 0 (no acceleration pole)."""
    pic, _, vP = _disk(ax)
    for k, dt in enumerate((-0.12, 0.0, 0.12)):
        # the body point that is at P at time dt had been elsewhere: its own velocity at P is still vP
        c, s_ = np.cos(OMEGA * dt), np.sin(OMEGA * dt)
        Pk = np.array([[c, -s_], [s_, c]]) @ P
        if k != 1:
            _dot(pic, f"body point {k}", Pk, color=DOT_OTHER, symbol="body point",
                 desc=f"the body point that is at P {abs(dt):g} s {'later' if dt < 0 else 'earlier'}")
    _dot(pic, "P", P, symbol="P", label="P (fixed in space)", aim=(-1.0, -0.25),
         desc=f"the fixed spatial location P = ({P[0]:g}, {P[1]:g}) m")
    _vector(pic, "v_P", P, ARROW * vP, role="twist", symbol="vₚ", label="vₚ (constant at P)",
            desc=f"velocity of whatever body point is at P (X_P v, 4.8): {np.hypot(*vP):.3g} m/s, "
                 "the same at every instant")
    x0, x1, y0, y1 = pic.box
    pic.text("a", (x1 - 0.02 * (x1 - x0), y0 + 0.04 * (y1 - y0)), "spatial acceleration a = v̇ = 0",
             role="accel", ha="right", symbol="a", desc="the spatial acceleration a = dv/dt: zero")
    show(pic, ax)
