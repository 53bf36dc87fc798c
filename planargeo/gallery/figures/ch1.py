"""Chapter 1 figures: material vs spatial acceleration of a spinning disk (1.2, 1.3)."""
from __future__ import annotations

import numpy as np
from matplotlib.patches import Circle

from planargeo.screws.twists import X_P, crm, unit_rotation
from planargeo.draw.artists import plot_point
from planargeo.draw.constructions import label
from planargeo.draw.style import COLORS, LABEL_PT
from planargeo.draw.layout import fit_view
from planargeo.gallery.figures import register

OMEGA, R_DISK, P = 2.0, 1.0, np.array([0.7, 0.35])


def _disk(ax):
    """The disk spinning at constant ω about O, in the view of Figs 1.2-1.3.

    Returns its twist ``v`` and the velocity ``v_P`` of the body point at ``P``.
    """
    ax.add_patch(Circle((0, 0), R_DISK, fc=COLORS["body"], alpha=0.35, ec="#1f3a4d", lw=1.0))
    v = OMEGA * unit_rotation([0.0, 0.0])     # constant spin about O
    plot_point(v, ax, text="$v$ (ω = const)", text_offset=(-34, -26))
    fit_view([[-1.1, -1.1], [1.6, 1.1]], margin=0.03, ax=ax)
    return v, (X_P(P) @ v)[:2]


def _arrow(ax, p, d, text, color, offset=(4, 4)):
    q = np.asarray(p) + np.asarray(d)
    ax.annotate("", xy=tuple(q), xytext=tuple(p),
                arrowprops=dict(arrowstyle="-|>", color=color, lw=1.4, shrinkA=0, shrinkB=0))
    label(q, text, color=color, offset=offset, fontsize=LABEL_PT, ax=ax)


@register(1.02, height=2.3)
def fig1_2(ax):
    """Fig. 1.2 — material acceleration of a disk spinning at constant ω: the body point at P moves
    on a circle, so its acceleration v̇_P + ω × v_P = −ω² r is centripetal (computed from the twist
    with X_P and crm)."""
    v, vP = _disk(ax)
    a_spatial = np.zeros(3)                     # dv/dt = 0 for constant spin
    aP = (X_P(P) @ a_spatial)[:2] + (crm(v) @ np.append(vP, 0.0))[:2]  # ω × v_P
    assert np.allclose(aP, -OMEGA ** 2 * P)
    ax.plot(*P, "o", color="#222222", ms=3.5)
    label(P, "$P$", offset=(4, -10), ax=ax)
    s = 0.2
    _arrow(ax, P, s * vP, "$v_P$", COLORS["twist"])
    _arrow(ax, P, s * aP, r"$-\omega^2 r$", COLORS["accel"], offset=(-4, -12))
    t = np.linspace(0, 2 * np.pi, 100)
    ax.plot(np.hypot(*P) * np.cos(t), np.hypot(*P) * np.sin(t), color=COLORS["construct"], lw=0.6,
            ls="--")


@register(1.03, height=2.3)
def fig1_3(ax):
    """Fig. 1.3 — spatial acceleration of the same disk is zero: the velocity of whatever body
    point occupies the fixed spatial location P is the same at every instant (grey dots: body
    points that are at P a moment before and after; each has velocity v_P there, one arrow), so
    a = dv/dt = 0 (no acceleration pole)."""
    _, vP = _disk(ax)
    for k, dt in enumerate((-0.12, 0.0, 0.12)):
        # the body point that is at P at time dt had been elsewhere: its own velocity at P is still vP
        c, s_ = np.cos(OMEGA * dt), np.sin(OMEGA * dt)
        Pk = np.array([[c, -s_], [s_, c]]) @ P
        ax.plot(*Pk, "o", color="#999999" if k != 1 else "#222222", ms=3)
    ax.annotate("", xy=tuple(P + 0.2 * vP), xytext=tuple(P),
                arrowprops=dict(arrowstyle="-|>", color=COLORS["twist"], lw=1.4))
    label(P + 0.2 * vP, "$v_P$ (constant at $P$)", color=COLORS["twist"], fontsize=LABEL_PT, ax=ax)
    label(P, "$P$ (fixed in space)", offset=(4, -11), fontsize=LABEL_PT, ax=ax)
    ax.text(0.98, 0.04, "spatial acceleration $a = \\dot v = 0$", transform=ax.transAxes,
            ha="right", fontsize=LABEL_PT, color=COLORS["accel"])
