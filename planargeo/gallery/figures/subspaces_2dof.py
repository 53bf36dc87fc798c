"""A 2-dof joint's subspaces drawn (thesis 6.1–6.4 for k = 2): a line of poles, a pencil of percussion lines.

A pin in a slot (revolute + prismatic) allows rotations about every point of the line through the
pin across the slot: the two columns of ``s`` (a translation along the slot, an ideal point, and
the rotation about the pin) span that *line of poles*, which is the one reaction line ``R`` (the
slot's push across, ``sᵀR = 0``).  Dually the two percussion lines ``T₁``, ``T₂`` meet at the one
reactive-acceleration point ``U`` (``TᵀU = 0``): every active force is a line through ``U``.
"""
from __future__ import annotations

import numpy as np

from planargeo.draw.artists import plot_conic, plot_line, plot_point
from planargeo.draw.layout import fit_view
from planargeo.draw.mechanism import draw_body, draw_com, draw_pin, link_polygon
from planargeo.draw.style import COLORS
from planargeo.gallery.figures import register
from planargeo.scenes.subspace import subspace_state, unit_direction
from planargeo.screws.twists import inertia_matrix

PIN = np.array([0.0, 0.0])
SLOT = 20.0            # degrees
COM = np.array([1.0, 0.25])


@register(6.015, height=2.6)
def fig6_2dof(ax):
    """Subspaces of a 2-dof joint (pin in a slot along e): the columns of s, a translation along e
    (a point at infinity) and the rotation about the pin, span a line of poles — every instant
    centre the joint allows — which is the reaction line R (sᵀR = 0); the percussion lines T₁, T₂
    meet at the reactive-acceleration point U (TᵀU = 0), so the active forces are the pencil of
    lines through U."""
    e = unit_direction(SLOT)
    I = inertia_matrix(2.0, COM, 2.0 * 0.35 ** 2)
    f = np.array([0.0, 1.0, 1.6])
    st = subspace_state("revolute_prismatic", PIN, e, I, f)
    assert max(abs(v) for v in st["residuals"].values()) < 1e-12
    draw_body(link_polygon(PIN - 0.3 * np.array([1.0, 0.0]), (2.0, 0.45), 0.45), ax)
    ax.plot(*np.array([PIN - 0.9 * e, PIN + 0.9 * e]).T, color=COLORS["ground"], lw=4, alpha=0.35,
            solid_capstyle="butt")
    draw_pin(PIN, ax)
    draw_com(COM, ax)
    plot_conic(I, ax, role="inertia", mark_center=False)
    R = st["R"][:, 0]
    plot_line(R, ax, role="reaction", scale=None, anchor=PIN + np.array([0.3, -0.75]),
              text="$R$ = line of poles of $s$")
    plot_point(st["s"][:, 1], ax, role="twist", glyph=False, text="$s_2$")
    plot_point(st["s"][:, 0], ax, role="twist", glyph=False, text="$s_1$")
    U = st["U"][:, 0]
    Uxy = np.array([-U[1] / U[2], U[0] / U[2]])
    for i, t in enumerate((0.8, -0.8)):
        T = st["T"][:, i]
        d = np.array([T[0], T[1]]) / np.hypot(T[0], T[1])
        plot_line(T, ax, scale=None, anchor=Uxy + t * d, linestyle=(0, (6, 3)), linewidth=1.0,
                  text=f"$T_{i + 1}$")
    plot_point(U, ax, role="accel", glyph=False, text="$U$")
    a = st["s_psi"]
    plot_point(a, ax, role="accel", text=r"$s\psi$")
    fit_view([(-1.2, -1.0), (2.3, 1.3), Uxy], margin=0.05, ax=ax)
