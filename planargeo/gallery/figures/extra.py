"""Extra figures: the inertia's point->line field, joint force splits, slider-crank dynamics."""
from __future__ import annotations

import numpy as np
from shapely.ops import unary_union

from planargeo.algorithms.articulated_inertia import articulated_inertia
from planargeo.algorithms.rnea import newton_euler
from planargeo.mechanics.contacts import world_point
from planargeo.screws.inertia import Inertia, centre_of_mass, percussion_axis
from planargeo.screws.twists import inertia_matrix
from planargeo.geometry.projective import from_xy, to_xy
from planargeo.draw.artists import plot_conic, plot_line, plot_point
from planargeo.draw.constructions import label
from planargeo.draw.mechanism import draw_body, draw_joint_split, draw_model, link_polygon
from planargeo.draw.layout import fit_view, shape_points
from planargeo.draw.style import LABEL_PT
from planargeo.gallery.figures import chain, register
from planargeo.gallery.figures.ch3 import QD, QDD, Q
from planargeo.gallery.figures.ch9 import slider_crank


@register(10.01, height=2.8)
def extra_inertia_field(ax):
    """Extra — the inertia as a point→line map (5.64–5.68): several acceleration poles a_k and
    their axes of percussion I a_k; the pole at the centre of mass maps to the line at infinity (a
    couple, corner glyph), a translation (ideal point, edge arrow) to a line through the centre of
    mass."""
    shape = link_polygon([-0.8, 0.0], [0.8, 0.0], 0.6)
    I = Inertia.from_polygon(shape).matrix
    c = centre_of_mass(I)
    draw_body(shape, ax, alpha=0.2, com=c)
    plot_conic(I, ax, role="inertia")
    poles = [from_xy([-1.6, 0.9]), from_xy([1.3, -1.0]), from_xy([0.2, 1.3]), from_xy(c),
             np.array([1.0, 0.6, 0.0])]
    for k, a in enumerate(poles, start=1):
        f = percussion_axis(I, a)
        plot_point(a, ax, role="accel", glyph=False, text=f"$a_{k}$")
        anchor = None
        if np.any(f[:2]):
            e = f[:2] / np.hypot(*f[:2])
            foot = c - np.array([-e[1], e[0]]) * (
                (f[2] + c[1] * f[0] - c[0] * f[1]) / np.hypot(*f[:2]))   # foot of c on f (4.27)
            anchor = foot + 1.3 * e
        plot_line(f, ax, role="wrench", scale=None, text=f"$Ia_{k}$", anchor=anchor, linewidth=1.2)
    fit_view([[-2.0, -1.4], [2.0, 1.6]], margin=0.02, ax=ax)


@register(10.02, height=6.0, nrows=3)
def extra_joint_splits(axs):
    """Extra — every joint force of a 3-link chain under gravity (RNEA) split into its active part
    T_iQ_i and its reaction R_iμ_i (6.38, 6.61) with T_i, U_i built on the articulated inertia A_i
    (6.105); one panel per joint."""
    m = chain(3, gravity=(0.0, -9.81))
    w = newton_euler(m, Q, QD, QDD)
    r = articulated_inertia(m, Q, QD, w.tau)
    for i, ax in enumerate(axs):
        arts = draw_model(m, w, ax, alpha=0.2, show_com=False)
        out, (Qi, mu, act, rea) = draw_joint_split(r.S[i], r.R[i], r.A[i], w.f[i], ax,
                                                   name=str(i + 1), scale=0.03, anchor=w.origin[i],
                                                   avoid=unary_union(arts["shapes"]))
        assert np.allclose(act + rea, w.f[i]) and np.allclose(Qi, w.tau[i])
        ax.text(0.02, 0.02, f"joint {i + 1}: Q = τ = {Qi[0]:.2f}", transform=ax.transAxes,
                fontsize=LABEL_PT, bbox=dict(fc="white", ec="none", pad=0.5))
        ends = [p for a in out.values() if a.get_arrow() is not None for p in a.get_arrow()]
        fit_view([*shape_points(*arts["shapes"]), *ends, [-0.3, -0.5]], margin=0.1, ax=ax)


@register(10.03, height=3.6)
def extra_slider_crank(ax):
    """Extra — slider-crank dynamics (scene 'slider-crank', 9.78–9.94): the guide drawn from the
    model's slider contact, the contact force F₃ = Bξ (its line: the normal force through the
    contact point shifted by the contact couple; −F₃ acts on the piston, Definition 42), the
    closed-loop accelerations a₁, a₂ (poles; a₁ and the velocity pole v₁ at the crank's pivot) and
    a₃, v₃ (the piston translates: ideal points, arrows at the edge)."""
    res, d, outline = slider_crank(ax, alpha=0.25)
    m = res.model
    for i, body in enumerate(m.bodies):
        label(d.com[i], body.name, offset=(-10, 0), ha="right", va="center", fontsize=LABEL_PT,
              color="#1f3a4d", ax=ax)
    (contact,) = m.contacts
    pc = world_point(d.pose, contact.a, contact.point_a)          # the slider's contact point
    a = np.asarray(res.quantities["a"])
    F3 = np.asarray(res.quantities["F3"])
    plot_line(F3, ax, role="reaction", scale=0.01, anchor=pc + [0.9, 0.0],
              text=f"$F_3$ = {np.hypot(*F3[:2]):.1f} N", text_offset=(-10, 5))
    # label offsets (points): poles beside their glyphs, ideal points (a₃, v₃) beside the edge arrows
    for k, off in enumerate([(10, -14), (10, 4), (-22, -4)]):
        plot_point(a[k], ax, role="accel", text=f"$a_{k + 1}$", glyph_scale=0.05, text_offset=off)
    v = np.asarray(res.quantities["v"])
    for k, off in ((0, (-22, -8)), (2, (8, -4))):     # v₂'s pole (the rod's ICR) lies far right
        plot_point(v[k], ax, role="twist", text=f"$v_{k + 1}$", glyph=False, text_offset=off)
    pts = [outline, *[np.reshape(to_xy(x), (1, 2)) for x in a[:2]],
           [pc + [1.6, 0.0], d.origin[0] - [1.2, 0.3]]]
    fit_view(np.vstack(pts), margin=0.06, ax=ax)


@register(0.5, height=3.2)
def extra_style_key(ax):
    """Extra — the visual language used in every figure: twists (velocity poles, blue, arc
    arrow = sense and size of ω), accelerations (vermillion), ideal points (translations, arrow at
    the view's edge), wrenches (orange lines with force arrows), reactions (green), momenta /
    active parts (purple), the line at infinity (a couple, corner glyph), inertias (dashed
    radius-of-gyration circle), constructions (grey dashed)."""
    ax.set_xlim(0, 10)
    ax.set_ylim(-1.6, 7.6)
    rows = [
        ("twist (pole), ω > 0", lambda y: plot_point(from_xy([1.0, y]) * 1.0, ax)),
        ("acceleration, α < 0", lambda y: plot_point(from_xy([1.0, y]) * -1.5, ax, role="accel")),
        ("wrench (line of action)", lambda y: plot_line(np.array([1.0, 0.0, -y]), ax, scale=1.2,
                                                        anchor=[1.0, y], text=None)),
        ("reaction force", lambda y: plot_line(np.array([1.0, 0.0, -y]), ax, role="reaction",
                                               scale=1.2, anchor=[1.0, y])),
        ("momentum / active part", lambda y: plot_line(np.array([1.0, 0.0, -y]), ax,
                                                       role="momentum", scale=1.2, anchor=[1.0, y])),
        ("construction line", lambda y: plot_line(np.array([1.0, 0.0, -y]), ax, role="construct",
                                                  scale=None)),
        ("inertia (radius of gyration)",
         lambda y: plot_conic(inertia_matrix(1.0, [1.0, y], 0.3), ax, role="inertia")),
    ]
    for k, (txt, make) in enumerate(rows):
        y = 7.0 - 1.05 * k
        make(y)
        ax.text(2.4, y, txt, va="center", fontsize=LABEL_PT,
                bbox=dict(fc="white", ec="none", pad=0.5))
    # bottom band: an ideal point (arrow at the view's lower edge, label above it) and a couple
    plot_point(np.array([-1.0, 0.0, 0.0]), ax, text="translation (ideal point)")
    plot_line(np.array([0.0, 0.0, 1.0]), ax, text="couple", corner="lower right")
