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
from planargeo.draw.layout import shape_points
from planargeo.draw.picture import _CHAR_EM, FONT_PX, PX_PER_PT
from planargeo.draw.pictures._words import subscript
from planargeo.draw.pictures.common import labelled_line
from planargeo.draw.pictures.kit import aim_label, foot_on_line, force, rate, where
from planargeo.draw.sketch import (body, joint_split, label, link_polygon, model, model_shapes, panel,
                                   segment, show, split_arrows)
from planargeo.gallery.figures import chain, register, scene_state
from planargeo.gallery.figures.ch3 import QD, QDD, Q


def _caption(pic, id, text, *, desc):
    """A text in the lower left corner of the view on a white box (the lines pass behind it)."""
    x0, x1, y0, y1 = pic.box
    w, h = _CHAR_EM * FONT_PX * len(text) + 4.0, 1.25 * FONT_PX + 2.0      # pixels (the label placer's estimate)
    x, y = x0 + 6.0 / pic.kx, y0 + 0.5 / pic.ky
    box = [[x - 2.0 / pic.kx, y], [x + (w - 2.0) / pic.kx, y], [x + (w - 2.0) / pic.kx, y + h / pic.ky],
           [x - 2.0 / pic.kx, y + h / pic.ky]]
    pic.path(f"{id}:box", box, role="text", closed=True, fill="white", color="none", z=7)
    pic.text(id, (x, y), text, symbol=id, desc=desc)


@register(10.01, height=2.8)
def extra_inertia_field(ax):
    """Extra — the inertia as a point→line map (5.64–5.68): several acceleration poles a_k and
    their axes of percussion I a_k; the pole at the centre of mass maps to the line at infinity (a
    couple, corner glyph), a translation (ideal point, edge arrow) to a line through the centre of
    mass."""
    shape = link_polygon([-0.8, 0.0], [0.8, 0.0], 0.6)
    I = Inertia.from_polygon(shape).matrix
    c = centre_of_mass(I)
    # a band at the top for the couple's corner glyph and its words (the pole a₄ at c maps to it)
    pic = panel(ax, [[-2.0, -1.4], [2.0, 1.9]], margin=0.02)
    body(pic, "body", shape, alpha=0.2, com=c, symbol="body",
         desc="a uniform plate, a rounded bar 1.6 m by 0.6 m, mass 1 kg per m²")
    pic.conic("I", I, role="inertia", label="", symbol="I",
              desc="its inertia I (5.4): the circle of gyration about the centre of mass")
    poles = [from_xy([-1.6, 0.9]), from_xy([1.3, -1.0]), from_xy([0.2, 1.3]), from_xy(c),
             np.array([1.0, 0.6, 0.0])]
    for k, a in enumerate(poles, start=1):
        f = percussion_axis(I, a)
        pic.point(f"a{k}", a, role="accel", glyph=False, symbol=f"a{subscript(k)}",
                  desc=f"an acceleration pole a{subscript(k)} (a point): {where(a)}")
        if k in (3, 5):          # below a₃'s pole, left of a₅'s edge arrow: clear of the couple's words
            aim_label(pic.elements[-1], (0.0, -1.0) if k == 3 else (-1.0, 0.0), 6.0)
        # the label 1.3 m along the line from the foot of c (4.27); a couple has no foot
        anchor = foot_on_line(f, c) + 1.3 * f[:2] / np.hypot(*f[:2]) if np.any(f[:2]) else None
        labelled_line(pic, f"Ia{k}", f, f"Ia{subscript(k)}", role="wrench", arrow=False, anchor=anchor,
                      width=1.2 * PX_PER_PT, symbol=f"Ia{subscript(k)}",
                      desc=f"the axis of percussion I a{subscript(k)} (5.64-5.68): the force that gives the body "
                           f"at rest the acceleration a{subscript(k)}"
                           + ("; a couple, the line at infinity" if not np.any(f[:2]) else ""))
    show(pic, ax)


@register(10.02, height=6.0, nrows=3)
def extra_joint_splits(axs):
    """Extra — every joint force of a 3-link chain under gravity (RNEA) split into its active part
    T_iQ_i and its reaction R_iμ_i (6.38, 6.61) with T_i, U_i built on the articulated inertia A_i
    (6.105); one panel per joint."""
    m = chain(3, gravity=(0.0, -9.81))
    w = newton_euler(m, Q, QD, QDD)
    r = articulated_inertia(m, Q, QD, w.tau)
    shapes = model_shapes(m, w)                     # the links as model() draws them
    avoid = unary_union(shapes)
    for i, ax in enumerate(axs):
        # the arrows first (they slide along their lines clear of the links), then the view on them
        arrows, _ = split_arrows(r.S[i], r.R[i], r.A[i], w.f[i], scale=0.03, anchor=w.origin[i],
                                 avoid=avoid)
        ends = [p for seg in arrows.values() if seg is not None for p in seg]
        pic = panel(ax, [*shape_points(*shapes), *ends, [-0.3, -0.5]], margin=0.1)
        model(pic, m, w, alpha=0.2, show_com=False)
        _, (Qi, mu, act, rea) = joint_split(pic, f"joint {i + 1}", r.S[i], r.R[i], r.A[i], w.f[i],
                                            name=str(i + 1), scale=0.03, anchor=w.origin[i], avoid=avoid)
        assert np.allclose(act + rea, w.f[i]) and np.allclose(Qi, w.tau[i])
        _caption(pic, "Q", f"joint {i + 1}: Q = τ = {Qi[0]:.2f}",
                 desc=f"the active part's coordinate Q{subscript(i + 1)} (6.38), equal to the joint torque "
                      f"τ{subscript(i + 1)}: {Qi[0]:.2f} N·m")
        show(pic, ax)


@register(10.03, height=3.6)
def extra_slider_crank(ax):
    """Extra — slider-crank dynamics (scene 'slider-crank', 9.78–9.94): the guide drawn from the
    model's slider contact, the contact force F₃ = Bξ (its line: the normal force through the
    contact point shifted by the contact couple; −F₃ acts on the piston, Definition 42), the
    closed-loop accelerations a₁, a₂ (poles; a₁ and the velocity pole v₁ at the crank's pivot) and
    a₃, v₃ (the piston translates: ideal points, arrows at the edge)."""
    res, d = scene_state("slider-crank")
    m = res.model
    (contact,) = m.contacts
    pc = world_point(d.pose, contact.a, contact.point_a)          # the slider's contact point
    a = np.asarray(res.quantities["a"])
    v = np.asarray(res.quantities["v"])
    F3 = np.asarray(res.quantities["F3"])
    outline = shape_points(*model_shapes(m, d, width=0.3))
    pts = [outline, *[np.reshape(to_xy(x), (1, 2)) for x in a[:2]],
           [pc + [1.6, 0.0], d.origin[0] - [1.2, 0.3]]]
    pic = panel(ax, np.vstack(pts), margin=0.06)
    model(pic, m, d, width=0.3, labels=False, show_com=True, pin_radius=0.1, alpha=0.25)
    for i, body in enumerate(m.bodies):      # the crank's name a little up, clear of v₁ at its pivot
        label(pic, f"name {i + 1}", d.com[i], body.name, offset=(-10, 6 if i == 0 else 0), ha="right",
              va="center",
              color="#1f3a4d", desc=f"body {i + 1}: the {body.name}")
    force(pic, "F3", F3, scale=0.01, anchor=pc + [0.9, 0.0], role="reaction", symbol="F₃",
          label=f"F₃ = {np.hypot(*F3[:2]):.1f} N",
          desc=f"the contact force F₃ = Bξ (9.86) on the crank-rod side; −F₃ acts on the piston: "
               f"{np.hypot(*F3[:2]):.1f} N")
    for k in range(3):
        pic.point(f"a{k + 1}", a[k], role="accel", symbol=f"a{subscript(k + 1)}", glyph_scale=0.05,
                  desc=f"the closed-loop acceleration of body {k + 1}, the {m.bodies[k].name} (9.94): "
                       f"{rate(a[k], 'rad/s²')}, pole {where(a[k])}")
        if k == 0:                   # a₁ and v₁ share the crank's pivot: a₁ below right, v₁ left
            aim_label(pic.elements[-1], (1.0, -1.0), 9.0)
    for k in (0, 2):                                  # v₂'s pole (the rod's ICR) lies far right
        pic.point(f"v{k + 1}", v[k], role="twist", glyph=False, symbol=f"v{subscript(k + 1)}",
                  desc=f"the velocity of body {k + 1}, the {m.bodies[k].name}: {rate(v[k], 'rad/s')}, "
                       f"pole {where(v[k])}")
        if k == 0:
            aim_label(pic.elements[-1], (-1.0, 0.0), 9.0)
    show(pic, ax)


@register(0.5, height=3.2)
def extra_style_key(ax):
    """Extra — the visual language used in every figure: twists (velocity poles, blue, arc
    arrow = sense and size of ω), accelerations (vermillion), ideal points (translations, arrow at
    the view's edge), wrenches (orange lines with force arrows), reactions (green), momenta /
    active parts (purple), the line at infinity (a couple, corner glyph), inertias (dashed
    radius-of-gyration circle), constructions (grey dashed)."""
    # the rows from y = 7 down; a band above them for the couple's corner glyph, one below for the
    # translation's edge arrow
    pic = panel(ax, [[0.0, -1.6], [10.0, 8.6]], margin=0.0)

    def force_row(role):
        return lambda id, y: force(pic, id, [1.0, 0.0, -y], scale=0.8, anchor=(1.1, y), reach=0.9,
                                   role=role, label="", symbol=id, desc=f"a {id}: a line with a force arrow")

    rows = [
        ("twist (pole), ω > 0", "twist",
         lambda id, y: pic.point(id, from_xy([1.0, y]) * 1.0, role="twist", label="", symbol="v",
                                 desc="a twist: its pole, the arc arrow turning with ω (here ω = 1 rad/s)")),
        ("acceleration, α < 0", "acceleration",
         lambda id, y: pic.point(id, from_xy([1.0, y]) * -1.5, role="accel", label="", symbol="a",
                                 desc="an acceleration: its pole, the arc arrow turning with α "
                                      "(here α = −1.5 rad/s²)")),
        ("wrench (line of action)", "wrench", force_row("wrench")),
        ("reaction force", "reaction", force_row("reaction")),
        ("momentum / active part", "momentum", force_row("momentum")),
        ("construction line", "construction",
         lambda id, y: segment(pic, id, (0.2, y), (2.0, y), role="construct", symbol=id,
                               desc="a construction line")),
        ("inertia (radius of gyration)", "inertia",
         lambda id, y: pic.conic(id, inertia_matrix(1.0, [1.0, y], 0.3), role="inertia", label="",
                                 symbol="I", desc="an inertia: its circle of gyration about the centre "
                                                  "of mass (here ρ = 0.3 m)")),
    ]
    for k, (txt, id, make) in enumerate(rows):
        y = 7.0 - 1.05 * k
        make(id, y)
        pic.text(f"{id}:key", (2.4, y), txt, va="center", desc=txt)
    # an ideal point (an arrow at the view's lower edge, its words above it) and a couple (corner glyph)
    pic.point("translation", np.array([-1.0, 0.0, 0.0]), role="twist", label="translation (ideal point)",
              symbol="v", desc="a translation: a twist whose pole is an ideal point, drawn as an arrow at "
                               "the view's edge")
    pic.line("couple", np.array([0.0, 0.0, 1.0]), role="wrench", label="", symbol="couple",
             desc="a couple: a wrench on the line at infinity (4.27), drawn as a corner glyph")
    show(pic, ax)
