"""Figure 3.3 in the plane: apparent mass depends on the direction of the force (thesis 3.3, 7.7a).

The thesis's sphere with a sliding cylinder becomes a disc ``B`` (mass ``m``) with a slot along
``x`` and a slider ``S`` (mass ``m``) in it, both centred at the origin and free in the plane.  A
force on ``S`` meets the articulated inertia ``A_S = I_S + R Uᵀ I_B`` (7.7a: the prismatic joint
passes ``R Uᵀ I_B`` of the disc on, :func:`planargeo.mechanics.subspaces.effective_base_inertia`),
and its apparent mass along a line is ``1 / (uᵀ A_S⁻¹ u)``
(:func:`planargeo.mechanics.impulse.apparent_mass`): ``m`` along the slot, ``2m`` across it.
"""
from __future__ import annotations

import numpy as np
from shapely.geometry import Point, box

from planargeo.draw.artists import plot_line
from planargeo.draw.layout import fit_view
from planargeo.draw.mechanism import draw_body
from planargeo.draw.style import COLORS
from planargeo.gallery.figures import register
from planargeo.mechanics.impulse import apparent_mass
from planargeo.mechanics.joints import reaction_space
from planargeo.mechanics.subspaces import effective_base_inertia
from planargeo.screws.twists import inertia_matrix

M = 1.0


def _slider_inertia() -> np.ndarray:
    """``A_S`` of the slider: its own inertia plus the disc's, passed on through the slot (7.7a)."""
    I_S = inertia_matrix(M, (0.0, 0.0), M * 0.02)
    I_B = inertia_matrix(M, (0.0, 0.0), M * 0.5 * 0.6 ** 2)
    return I_S + effective_base_inertia(I_B, reaction_space("prismatic", (0.0, 0.0), (1.0, 0.0)))


@register(3.03, height=2.6)
def fig3_3(ax):
    """Fig. 3.3 (planar) — apparent mass: a disc of mass m with a slot along x holds a slider of mass
    m; a force on the slider along the slot meets the slider alone (apparent mass m), across it both
    bodies (2m). The curve is the apparent mass 1/(uᵀA_S⁻¹u) of a force through the centre in each
    direction (radius ∝ mass), with A_S = I_S + R Uᵀ I_B the slider's articulated inertia (7.7a)."""
    A = _slider_inertia()
    draw_body(Point(0.0, 0.0).buffer(0.6, quad_segs=48).difference(box(-0.6, -0.09, 0.6, 0.09)), ax,
              label=None)
    draw_body(box(-0.16, -0.08, 0.16, 0.08), ax, color=COLORS["momentum"], alpha=0.5)
    th = np.linspace(0.0, 2 * np.pi, 181)
    m_app = np.array([apparent_mass(A, [np.cos(t), np.sin(t), 0.0]) for t in th])
    r = 0.4 * m_app / M
    ax.plot(r * np.cos(th), r * np.sin(th), color=COLORS["wrench"], lw=1.0, ls=(0, (4, 2)))
    ax.text(0.62, -0.62, "apparent mass\n$1/(u^T A_S^{-1} u)$", fontsize=8, color=COLORS["wrench"],
            ha="left", va="top")
    mx = apparent_mass(A, [1.0, 0.0, 0.0])
    my = apparent_mass(A, [0.0, 1.0, 0.0])
    assert np.isclose(mx, M) and np.isclose(my, 2 * M)
    plot_line([1.0, 0.0, 0.0], ax, scale=0.35, anchor=(0.85, 0.0), text="$F_x$: $m$")
    plot_line([0.0, 1.0, 0.0], ax, scale=0.35, anchor=(0.0, 1.0), text="$F_y$: $2m$")
    fit_view(ax, [(-0.9, -0.9), (1.5, 1.3)], margin=0.05)
