"""Chapter 9 figures: trees, contacts and the slider-crank (9.1-9.3)."""
from __future__ import annotations

import numpy as np

from planargeo.mechanics.contacts import world_point
from planargeo.draw.layout import shape_points
from planargeo.draw.picture import PX_PER_PT, plain_text
from planargeo.draw.pictures.kit import aim_label, force
from planargeo.draw.sketch import BODY_EDGE, label, model, model_shapes, panel, segment, show
from planargeo.draw.style import COLORS
from planargeo.gallery.figures import register, scene_state


@register(9.01, height=3.0)
def fig9_1(ax):
    """Fig. 9.1 — the rigid-body tree of scene 'tree': body 1 is the root (pinned), bodies 4, 7, 8
    and 9 are the tips of the branches (parents (9.1): −, 1, 2, 3, 1, 5, 6, 6, 1)."""
    res, d = scene_state("tree")
    tips = d.pose[:, :2] + 2 * (d.com - d.pose[:, :2])     # the links through their centres of mass
    pic = panel(ax, [*d.origin, *tips], margin=0.08)
    model(pic, res.model, d, width=0.14, show_com=False, names=[str(k + 1) for k in range(9)])
    show(pic, ax)


@register(9.02, height=3.0)
def fig9_2(ax):
    """Fig. 9.2 — constrained tree (scene 'constrained-tree', gravity on): pin contacts (squares)
    close the loops 4–7 and 8–9 (G of 9.49), leaving 9 − 2·2 = 5 dof; the contact forces F = Bξ
    (9.70–9.71; arrows: F on body b, i.e. on 7 and 9) are computed with the tree's full stacked
    mobility Λ⁻¹ that (9.65)–(9.73) must use (the printed block-diagonal Λ⁻¹ gets them 9 % wrong;
    docs/errata.md, chapter 9 item 6)."""
    from shapely.geometry import LineString, Point as SPoint
    from shapely.ops import unary_union

    res, d = scene_state("constrained-tree")
    m = res.model
    shapes = model_shapes(m, d, width=0.14)
    bodies = unary_union(shapes)
    F = np.asarray(res.quantities["F"])
    sc = 0.12
    P = [shape_points(*shapes)]
    mags, lines, arrows = [], [], []
    for k, c in enumerate(m.contacts):
        p = world_point(d.pose, c.a, c.point_a)            # the contact point on body a (9.49)
        f = F[k]                          # Definition 42: +F acts on body b, −F on body a
        mag = np.hypot(*f[:2])
        e = f[:2] / mag
        L = sc * mag
        # the line passes through p (9.70); the arrow beside p, on the side of p where it
        # covers less of the bodies (ahead of p, or behind it pointing at p)
        ahead, behind = p + e * (0.5 * L + 0.12), p - e * (0.5 * L + 0.12)
        anchor = min((ahead, behind), key=lambda q: LineString([q - e * L / 2, q + e * L / 2])
                     .intersection(bodies).length)
        n = np.array([-e[1], e[0]])
        side = 1.0 if bodies.distance(SPoint(*(anchor + 0.2 * n))) >= \
            bodies.distance(SPoint(*(anchor - 0.2 * n))) else -1.0
        P.append(np.array([anchor - e * L / 2, anchor + e * L / 2]))
        arrows.append((f, anchor, side * n, c.name, mag))
        lines.append(f)
    pic = panel(ax, np.vstack(P), margin=0.06, fit_height=True)
    model(pic, m, d, width=0.14, show_com=False, labels=False)
    for k, (f, anchor, u, name, mag) in enumerate(arrows):
        sym = plain_text(f"$F_{{{name}}}$")
        force(pic, f"F{k + 1}", f, scale=sc, anchor=anchor, role="reaction", symbol=sym,
              desc=f"contact force of the pin {name} (9.70–9.71): on body {name.split('-')[1]}, "
                   f"|{sym}| = {mag:.3g} N")
        aim_label(pic.elements[-1], u, gap=5.0 * PX_PER_PT)
        mags.append(f"|{sym}| = {mag:.2f} N")
    # body numbers beside their links, on the side away from the contact-force lines
    for i, shape in enumerate(shapes):
        cxy = np.array(shape.centroid.coords[0])
        a = d.pose[i, :2]
        t = cxy - a
        n = np.array([-t[1], t[0]]) / max(np.hypot(*t), 1e-12)

        def line_dist(q):
            return min(abs(f[2] + q[1] * f[0] - q[0] * f[1]) / np.hypot(*f[:2]) for f in lines)

        u = n if line_dist(cxy + 0.25 * n) >= line_dist(cxy - 0.25 * n) else -n
        label(pic, f"body label {i + 1}", cxy, str(i + 1), offset=tuple(9 * u), color=BODY_EDGE,
              ha="center", va="center", fixed=True, desc=f"body {i + 1}")
    x0, x1, y0, y1 = pic.box
    for j, text in enumerate(reversed(mags)):     # the magnitudes in the lower left, first on top
        label(pic, f"magnitude {len(mags) - j}", (x0, y0), text, role="reaction",
              offset=(0.02 * (x1 - x0) * pic.kx / PX_PER_PT, (3 + 15 * j)), fixed=True,
              desc="size of a contact force (9.71)")
    show(pic, ax)


@register(9.03, height=3.4)
def fig9_3(ax):
    """Fig. 9.3 — slider-crank (scene 'slider-crank', thesis 9.6): relative rotations ψ, θ, φ with
    ψ + θ + φ = π/2; the state closes the loop at θ = 1.6063 (the printed 1.603 and the signs of
    θ̇, φ̇ in 9.78–9.79 are corrected, docs/errata.md)."""
    res, d = scene_state("slider-crank")
    P = shape_points(*model_shapes(res.model, d, width=0.3))
    pic = panel(ax, np.vstack([P, P.min(axis=0) - [1.0, 0.4], P.max(axis=0) + [0.8, 0.2]]),
                margin=0.03)
    model(pic, res.model, d, width=0.3, labels=False, show_com=True, pin_radius=0.1)
    for i, body in enumerate(res.model.bodies):  # the piston's name right of its guide, others left
        right = i == 2
        label(pic, f"name {i + 1}", d.com[i], body.name, offset=(18 if right else -9, 6 if i == 0 else 0),
              color=BODY_EDGE, va="center", ha="left" if right else "right", desc=f"body {i + 1}")
    q = res.state["q"]
    absang = np.cumsum(q)
    for i, (nm, val) in enumerate(zip(("ψ", "θ", "φ"), q)):
        o = d.pose[i, :2]
        base = absang[i] - val
        t = np.linspace(base, absang[i], 30)
        rr = (0.9, 0.7, 0.6)[i]
        pic.path(f"{nm} arc", np.column_stack([o[0] + rr * np.cos(t), o[1] + rr * np.sin(t)]),
                 role="twist", color=COLORS["twist"], width=0.8 * PX_PER_PT, z=3, symbol=nm,
                 desc=f"relative rotation {nm} of joint {i + 1} (9.6): {val:.4f} rad")
        segment(pic, f"{nm} reference", o, o + 0.9 * np.array([np.cos(base), np.sin(base)]),
                width=0.6 * PX_PER_PT, desc=f"the direction {nm} is measured from")
        mid = t[len(t) // 2]
        label(pic, f"{nm} value", o + rr * np.array([np.cos(mid), np.sin(mid)]),
              f"{nm} = {val:.3f}".replace("-", "−"), offset=((6, -12), (6, 2), (-62, 4))[i],
              role="twist", symbol=nm, desc=f"relative rotation {nm} (9.6): {val:.4f} rad")
    show(pic, ax)
