"""A 2-dof joint's subspaces drawn (thesis 6.1–6.4 for k = 2): a line of poles, a pencil of percussion lines."""
from __future__ import annotations

import numpy as np

from planargeo.draw.picture import PX_PER_PT
from planargeo.draw.pictures.common import labelled_line
from planargeo.draw.pictures.kit import where
from planargeo.draw.sketch import com, link, panel, pin, segment, show
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
    U = st["U"][:, 0]
    Uxy = np.array([-U[1] / U[2], U[0] / U[2]])
    pic = panel(ax, [(-1.2, -1.0), (2.3, 1.3), Uxy], margin=0.05)
    link(pic, "body", PIN - 0.3 * np.array([1.0, 0.0]), (2.0, 0.45), width=0.45, symbol="body",
         desc="the body, held by a pin in a slot")
    # the slot: a wide, light grey band along e (as the old 4 pt ground line at 35 % opacity)
    segment(pic, "slot", PIN - 0.9 * e, PIN + 0.9 * e, role="ground", color="#bcbcbc",
            width=4.0 * PX_PER_PT, dash=[], symbol="slot", desc=f"the slot, along e ({SLOT:g}° from x)", z=2)
    pin(pic, "pin", PIN, desc="the pin in the slot (a revolute joint that also slides along e)")
    com(pic, "c", COM, desc=f"the body's centre of mass c = ({COM[0]:g}, {COM[1]:g}) m")
    pic.conic("I", I, role="inertia", mark_center=False, label="", symbol="I",
              desc="the body's inertia: its circle of gyration about c (5.4), m = 2 kg, ρ = 0.35 m")
    R = st["R"][:, 0]
    labelled_line(pic, "R", R, "R = line of poles of s", role="reaction", arrow=False,
                  anchor=PIN + np.array([0.3, -0.75]), symbol="R",
                  desc="the reaction space R (6.1, sᵀR = 0): the slot's push across, and the line of the "
                       "poles of every motion s allows")
    pic.point("s2", st["s"][:, 1], role="twist", glyph=False, symbol="s₂",
              desc=f"s₂: the rotation about the pin, its pole {where(st['s'][:, 1])}")
    pic.point("s1", st["s"][:, 0], role="twist", glyph=False, symbol="s₁",
              desc="s₁: the translation along the slot, its pole at infinity (an ideal point)")
    for i, t in enumerate((0.8, -0.8)):
        T = st["T"][:, i]
        d = np.array([T[0], T[1]]) / np.hypot(T[0], T[1])
        labelled_line(pic, f"T{i + 1}", T, f"T{'₁₂'[i]}", role="wrench", arrow=False,
                      anchor=Uxy + t * d, width=1.0 * PX_PER_PT, dash=[6 * PX_PER_PT, 3 * PX_PER_PT],
                      side=-1.0 if i else 1.0, symbol=f"T{'₁₂'[i]}",
                      desc=f"T{'₁₂'[i]} = I s (sᵀIs)⁻¹ (6.36): the axis of percussion of s{'₁₂'[i]}, "
                           "an active force")
    pic.point("U", U, role="accel", glyph=False, symbol="U",
              desc=f"the reactive acceleration U = I⁻¹R(RᵀI⁻¹R)⁻¹ (6.37), where T₁ and T₂ meet: {where(U)}")
    a = st["s_psi"]
    pic.point("s_psi", a, role="accel", symbol="sψ",
              desc=f"sψ: the body's acceleration under f, held by the joint (6.44): rate {a[2]:.3g} rad/s², "
                   f"pole {where(a)}")
    show(pic, ax)
