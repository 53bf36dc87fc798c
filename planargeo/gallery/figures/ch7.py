"""Chapter 7 figures: articulated inertias and mobilities, the examples and their charts (7.1-7.11)."""
from __future__ import annotations

import numpy as np

from planargeo.algorithms.articulated_inertia import articulated_inertia
from planargeo.algorithms.articulated_mobility import articulated_mobility
from planargeo.algorithms.chain_splitting import mobility_split
from planargeo.mechanics.kinematics import kinematics
from planargeo.geometry.projective import to_xy
from planargeo.scenes import build as build_scene
from planargeo.draw.artists import plot_conic, plot_line, plot_point
from planargeo.draw.charts import plot_curves, polar_curves
from planargeo.draw.constructions import draw_dimension, label
from planargeo.draw.mechanism import draw_model
from planargeo.draw.style import COLORS, LABEL_PT
from planargeo.draw.layout import fit_panel, fit_view, shape_points
from planargeo.gallery.figures import chain, register, scene_state

#: The joint angles of the four-link chains of Figs 7.1, 7.2 and 7.11.
Q4 = np.array([0.3, 0.5, -0.6, 0.7])


def _chain4(ax, q, base="revolute"):
    """The four-link chain of Figs 7.1, 7.2 and 7.11 drawn at rest at ``q``.

    Returns the model, its kinematics and the outline points of the drawn bodies.
    """
    m = chain(4, base=base)
    d = kinematics(m, q, np.zeros(m.nq))
    arts = draw_model(m, d, ax, show_com=False)
    return m, d, shape_points(*arts["shapes"])


@register(7.01, height=2.6)
def fig7_1(ax):
    """Fig. 7.1 — articulated inertia A_i of a free-floating sub-chain (7.1–7.8): the internal
    force f_i at joint i accelerates body i by a_i = A_i⁻¹ f_i (at rest), including the bodies
    beyond; A₂ drawn as its (sign-flipped) conic about the effective centre."""
    q = np.concatenate([[0.0, 0.0, 0.2], Q4[1:]])
    m, d, outline = _chain4(ax, q, base="plane")
    i = 1
    A = articulated_inertia(m, q).A[i]
    plot_conic(A, ax, role="inertia", text="$A_2$", text_offset=(-26, 10))
    plot_conic(d.I[i], ax, role="inertia", color=COLORS["construct"], mark_center=False)
    o = d.origin[i]
    f = np.array([1.0, 0.0, -o[1]])                 # a unit force along +x through joint 2 (4.27)
    a = np.linalg.solve(A, f)
    plot_line(f, ax, role="reaction", scale=0.6, anchor=o - [0.5, 0.0], text="$f_2$",
              text_offset=(-4, -16))
    plot_point(a, ax, role="accel", text="$a_2 = A_2^{-1}f_2$", glyph_scale=2.0,
               text_offset=(10, 10))
    fit_panel([*outline, to_xy(a), o - [1.0, 0.0]], margin=0.06, ax=ax)


@register(7.02, height=2.6)
def fig7_2(ax):
    """Fig. 7.2 — articulated mobility Λ_i⁻¹ of a constrained chain (7.28–7.38, corrected sign of
    7.38a, see docs/errata.md): the load −f_{i+1} on body i accelerates it by a_i = −Λ_i⁻¹ f_{i+1}
    (at rest), including the bodies before it."""
    m, d, outline = _chain4(ax, Q4)
    i = 1
    o = d.origin[i + 1]
    f_next = np.array([-1.0, 0.0, o[1]])   # f_3: a unit force along -x through joint 3 (4.27)
    a = -articulated_mobility(m, Q4).Lambda_inv[i] @ f_next
    # the label above-left of joint 3 (free of links 2 and 3), not on link 3 at the arrow's tip
    plot_line(-f_next, ax, role="reaction", scale=0.6, anchor=o, text="$-f_3$", text_at="anchor",
              text_offset=(-10, 4)).set_text_alignment("right", "bottom")
    plot_point(a, ax, role="accel", text="$a_2 = -\\Lambda_2^{-1}f_3$")
    fit_panel([*outline, to_xy(a), d.origin[0] - [0.0, 0.15]], margin=0.06, ax=ax)


@register(7.03, height=2.9, ncols=2, gridspec_kw={"width_ratios": [2.3, 1.0]})
def fig7_3(axs):
    """Fig. 7.3 — two identical bodies at angle φ pushed by a horizontal force f₁ at CJ₁ (scene
    'two-body', 7.9–7.24): the articulated inertia A₁ (black) from the bodies' inertias (grey);
    a₁ = A₁⁻¹f₁ is the acceleration pole of body 1 (below CJ₁); m_x = {A₁}₁₁ (7.12)."""
    from matplotlib.patches import Rectangle

    res, d = scene_state("two-body")
    A1 = np.array(res.quantities["A1"])
    f1 = np.array([1.0, 0.0, 0.0])                  # unit horizontal force through CJ₁ (4.27)
    a1 = np.linalg.solve(A1, f1)
    ax1 = to_xy(a1)
    # left: the bodies, their inertias and A₁ in detail; right: the same scene with the pole a₁
    for k, ax in enumerate(axs):
        detail = k == 0
        arts = draw_model(res.model, d, ax, ground=False, labels=False, show_com=detail)
        cs = [plot_conic(d.I[j], ax, role="inertia", color=COLORS["construct"], mark_center=False)
              for j in range(2)] if detail else []
        cs.append(plot_conic(A1, ax, role="inertia", mark_center=detail))
        plot_line(f1, ax, scale=0.6 if detail else None, anchor=[-0.35, 0.0],
                  text="$f_1$" if detail else None, text_offset=(-20, 4))
        plot_line([0.0, 1.0, 0.0], ax, role="construct", scale=None)    # x = 0 through CJ₁
        P = np.vstack([shape_points(*arts["shapes"]), *[c.get_xy() for c in cs]])
        if detail:
            label([0, 0], "$CJ_1$", offset=(-22, -14), fontsize=LABEL_PT, ax=ax)
            # A₁'s label outside every circle: at its lower-right point (the bodies' grey
            # circles lie left and above), pushed outward
            xy = cs[-1].get_xy()
            label(xy[np.argmax(xy[:, 0] - xy[:, 1])], "$A_1$", offset=(2, -2), ha="left",
                  va="top", ax=ax)
            ax.text(0.98, 0.02, f"φ = {np.rad2deg(res.params['phi']):.0f}°, "
                    f"λ = {res.quantities['lam']:g}:\n$m_x/m$ = {res.quantities['mx_over_m']:.3f}",
                    transform=ax.transAxes, fontsize=LABEL_PT, ha="right")
            fit_view(np.vstack([P, P.min(axis=0) - [0.3, 0.7]]), margin=0.03, ax=ax)
        else:
            plot_point(a1, ax, role="accel", text=f"$a_1$\n({ax1[0]:.2f}, {ax1[1]:.2f})",
                       text_offset=(6, 4))
            fit_view(np.vstack([P, ax1, ax1 + [1.6, -0.3]]), margin=0.03, ax=ax)
            ax.add_patch(Rectangle((0, 0), 1, 1, transform=ax.transAxes, fill=False, ec="#bbbbbb",
                                   lw=0.6))


@register(7.04, height=2.4, margins=(0.16, 0.97, 0.18, 0.95))
def fig7_4(ax):
    """Fig. 7.4 — effective horizontal mass m_x/m of the two-body example over φ for several size
    ratios λ = L/ρ (7.22), computed with the articulated inertia recursion (scene 'two-body'); the
    λ → ∞ limit is 1 + cos²φ (7.23)."""
    phi = np.linspace(0, np.pi, 61)
    lams = (0.5, 1.0, 2.0, 4.0, 10.0)
    ys = [[build_scene("two-body", rho=1.0 / lam, phi=p).quantities["mx_over_m"] for p in phi]
          for lam in lams]
    ys.append(1 + np.cos(phi) ** 2)
    plot_curves(np.rad2deg(phi), ys, [f"λ = {lam:g}" for lam in lams] + ["λ → ∞"], ax,
                xlabel="φ [deg]", ylabel="$m_x/m$", ylim=(0.9, 2.45),
                legend=dict(ncol=3, loc="upper center", fontsize=LABEL_PT))
    ax.set_xticks([0, 45, 90, 135, 180])


@register(7.05, height=1.8)
def fig7_5(ax):
    """Fig. 7.5 — horizontal chain of n bodies (scene 'horizontal-chain', 7.25–7.27): the
    articulated inertia A₁ of the first body grows with each body added; its effective centre d₁ is
    marked for n = 1…4 (λ = 2 here)."""
    lam = 2.0
    res, d = scene_state("horizontal-chain", n=4, lam=lam)
    draw_model(res.model, d, ax, show_com=True, ground=False, labels=False)
    plot_conic(np.array(res.quantities["A1"]), ax, role="inertia", text="$A_1$ (n=4)",
               text_offset=(4, 10))
    groups = {}
    for n in range(1, 5):
        dn = build_scene("horizontal-chain", n=n, lam=lam).quantities["d_over_L"]
        key = next((k for k in groups if np.isclose(k, dn, rtol=1e-9)), dn)
        groups.setdefault(key, []).append(n)
    for k, (dn, ns) in enumerate(sorted(groups.items())):
        y = -0.5 - 0.2 * k
        ax.plot([dn, dn], [y, -0.3], color=COLORS["accel"], lw=0.8)
        label([dn, y], f"$d_1$ = {dn:.3f} L (n = {', '.join(map(str, ns))})", offset=(2, -2),
              fontsize=LABEL_PT, va="top", color=COLORS["accel"], ax=ax)
    fit_view([[-0.3, -1.1], [4.2, 0.7]], margin=0.02, ax=ax)


#: The margins of the λ charts, Figs 7.6-7.8.
LAM_CHART = (0.17, 0.97, 0.19, 0.95)


def _lam_chart(ax, key, ylabel, caption_n=(2, 3, 4)):
    """Figs 7.6-7.8: the quantity ``key`` of the first body's articulated inertia over λ."""
    lam = np.geomspace(0.1, 10.0, 49)
    ys = [[build_scene("horizontal-chain", n=n, lam=x).quantities[key] for x in lam]
          for n in caption_n]
    plot_curves(lam, ys, [f"n = {n}" + (" (thesis)" if n == 2 else "") for n in caption_n], ax,
                xlabel="λ = L/ρ", ylabel=ylabel, logx=True)


@register(7.06, height=2.3, margins=LAM_CHART)
def fig7_6(ax):
    """Fig. 7.6 — relative location d/L of the effective centre of the first body over λ = L/ρ
    (7.26–7.27); n = 2 is the thesis's two-body system, n = 3, 4 added for comparison
    (d/L = (λ²+12)/(2(λ²+8)) for n = 2, derived in docs/errata.md)."""
    _lam_chart(ax, "d_over_L", "$d/L$")


@register(7.07, height=2.3, margins=LAM_CHART)
def fig7_7(ax):
    """Fig. 7.7 — effective vertical mass m_y/m of the first body over λ (7.26);
    m_y/m = (λ²+8)/(λ²+4) for n = 2. The thesis's claim that bodies beyond two change nothing at
    λ = 2 holds for m_y (all curves meet at 3/2) but not for m_x (errata §5)."""
    _lam_chart(ax, "my_over_m", "$m_y/m$")


@register(7.08, height=2.3, margins=LAM_CHART)
def fig7_8(ax):
    """Fig. 7.8 — effective rotational inertia A_z/(mρ²) of the first body over λ (7.26);
    2(λ²+4)/(λ²+8) for n = 2; all n meet at 4/3 for λ = 2."""
    _lam_chart(ax, "Az_over_m_rho2", r"$A_z/(m\rho^2)$")


@register(7.09, height=2.2)
def fig7_9(ax):
    """Fig. 7.9 — articulated mobility example (scene 'mobility-example', 7.40–7.49): CJ₁ pinned to
    the ground, a pure couple f₃ (line at infinity) on body 2; its acceleration pole a₂ lies on the
    x axis at x/L = 1 + 2η²cosφ/(4 + 5η²) (corrected 7.38a)."""
    res, d = scene_state("mobility-example")
    draw_model(res.model, d, ax)
    a2 = np.array(res.quantities["a2"])
    plot_line(-np.array(res.quantities["f3"]), ax, text="$-f_3$ (couple on body 2)",
              corner="upper left")
    plot_point(a2, ax, role="accel", text="$a_2$")
    x = to_xy(a2)
    draw_dimension([0, -0.35], [x[0], -0.35], f"$x$ = {res.quantities['x_over_L']:.3f} L", ax=ax)
    fit_view([*d.origin, d.com[1] * 2 - d.origin[1], x, [0, -0.5]], margin=0.12, ax=ax)


@register(7.1, height=3.0, polar=[0.1, 0.1, 0.66, 0.8])
def fig7_10(ax):
    """Fig. 7.10 — polar plot of the instant centre x/L of body 2 over φ for several η = L/ρ
    (7.47–7.49), computed with the corrected articulated mobility (the printed sign of 7.38a gives
    e.g. 1.613 instead of 1.236 at φ = 45°, η = 2; docs/errata.md)."""
    phi = np.linspace(0, 2 * np.pi, 121)
    etas = (0.5, 1.0, 2.0, 4.0)
    rs = [[build_scene("mobility-example", rho=1.0 / eta, phi=p).quantities["x_over_L"] for p in phi]
          for eta in etas]
    polar_curves(phi, rs, [f"η = {e:g}" for e in etas], ax, rlabel="x/L")


@register(7.11, height=2.6)
def fig7_11(ax):
    """Fig. 7.11 — chain splitting (7.50–7.56): an external force F on the tip; the chain is split
    at joint 3 into a constrained chain (bodies 1–2, articulated mobility Λ₂⁻¹) and a free-floating
    chain (bodies 3–4, articulated inertia A₃); the internal force f₃ from 7.56 gives
    a₂ = b₂ − Λ₂⁻¹f₃ and a₃ = A₃⁻¹(f₃ − d₃) (here at rest without gravity, b₂ = 0). Computed with
    listings 7.1.1 and 7.4.1 as corrected for applied loads (docs/errata.md, chapter 7 items 2 and
    3)."""
    m, d, outline = _chain4(ax, Q4)
    z = np.zeros(4)
    F = np.zeros((4, 3))
    tip = d.origin[3] + 1.0 * np.array([np.cos(d.pose[3, 2]), np.sin(d.pose[3, 2])])
    F[3] = np.array([0.0, -1.0, -tip[0]])       # a downward unit force through the tip (4.27)
    sol = mobility_split(m, Q4, z, z, F)
    r_in = articulated_inertia(m, Q4, z, z, F)
    r_mob = articulated_mobility(m, Q4, z, z, F)
    f3 = sol.f[2]
    # the two halves: the constrained chain's mobility and the floating chain's inertia (7.52-7.55)
    assert np.allclose(sol.a[1], r_mob.b[1] - r_mob.Lambda_inv[1] @ f3)
    assert np.allclose(r_in.A[2] @ sol.a[2], f3 - r_in.d[2])
    b2_zero = np.allclose(r_mob.b[1], 0.0)
    A3 = plot_conic(r_in.A[2], ax, role="inertia", text="$A_3$", text_offset=(10, -30))
    plot_line(F[3], ax, scale=0.5, anchor=tip, text="$F$", text_offset=(-14, -8))
    plot_line(f3, ax, role="reaction", scale=0.5, anchor=d.origin[2], text="$f_3$",
              text_offset=(-16, 4))
    plot_point(sol.a[1], ax, role="accel",
               text="$a_2 = -\\Lambda_2^{-1}f_3$" if b2_zero else "$a_2 = b_2 - \\Lambda_2^{-1}f_3$",
               text_offset=(10, -12))
    plot_point(sol.a[2], ax, role="accel", text="$a_3 = A_3^{-1}(f_3 - d_3)$", text_offset=(-40, 10))
    fit_panel([*outline, *A3.get_xy(), tip, to_xy(sol.a[1]), to_xy(sol.a[2]),
                   d.origin[0] - [0.0, 0.2]], margin=0.05, ax=ax)
