"""Chapter 7 figures: articulated inertias and mobilities, the examples and their charts (7.1-7.11)."""
from __future__ import annotations

import numpy as np
from matplotlib.patches import Rectangle

from planargeo.algorithms.articulated_inertia import articulated_inertia
from planargeo.algorithms.articulated_mobility import articulated_mobility
from planargeo.algorithms.chain_splitting import mobility_split
from planargeo.draw.charts import plot_curves, polar_curves
from planargeo.draw.geometry import conic_geometry
from planargeo.draw.layout import shape_points
from planargeo.draw.picture import PX_PER_PT, _align, _text_part
from planargeo.draw.pictures._words import num
from planargeo.draw.pictures.common import label_toward
from planargeo.draw.pictures.kit import force, where
from planargeo.draw.sketch import dimension, label, model, model_shapes, panel, segment, show
from planargeo.draw.style import COLORS, LABEL_PT
from planargeo.gallery.figures import chain, register, scene_state
from planargeo.geometry.projective import to_xy
from planargeo.mechanics.kinematics import kinematics
from planargeo.scenes import build as build_scene

#: The joint angles of the four-link chains of Figs 7.1, 7.2 and 7.11.
Q4 = np.array([0.3, 0.5, -0.6, 0.7])


def _conic_xy(C, n: int = 48) -> np.ndarray:
    """Points of the conic ``C`` as the picture draws it (an inertia by its circle of gyration), to fit a view."""
    A = conic_geometry(C)["affine"]
    t = np.linspace(0.0, 2 * np.pi, n, endpoint=False)
    return (A @ np.vstack([np.cos(t), np.sin(t), np.ones(n)]))[:2].T


def _inertia(pic, id, A, symbol, toward, *, desc, text=None):
    """The inertia ``A``, labelled ``text`` (or ``symbol``) outside its point farthest ``toward``."""
    pic.conic(id, A, role="inertia", symbol=symbol, label="", desc=desc)
    xy, text = _conic_xy(A), text or symbol
    u = np.asarray(toward, float) / np.hypot(*toward)
    ha, va = _align(u)
    label(pic, id + ":label", xy[np.argmax(xy @ u)], text, offset=(4.0 * u[0], 4.0 * u[1]), ha=ha, va=va,
          symbol=text, desc=desc)


def _chain4(q, base="revolute"):
    """The four-link chain of Figs 7.1, 7.2 and 7.11 at rest at ``q``: model, kinematics, outline."""
    m = chain(4, base=base)
    d = kinematics(m, q, np.zeros(m.nq))
    return m, d, shape_points(*model_shapes(m, d))


@register(7.01, height=2.6)
def fig7_1(ax):
    """Fig. 7.1 — articulated inertia A_i of a free-floating sub-chain (7.1–7.8): the internal
    force f_i at joint i accelerates body i by a_i = A_i⁻¹ f_i (at rest), including the bodies
    beyond; A₂ drawn as its (sign-flipped) conic about the effective centre."""
    q = np.concatenate([[0.0, 0.0, 0.2], Q4[1:]])
    m, d, outline = _chain4(q, base="plane")
    i = 1
    A = articulated_inertia(m, q).A[i]
    o = d.origin[i]
    f = np.array([1.0, 0.0, -o[1]])                 # a unit force along +x through joint 2 (4.27)
    a = np.linalg.solve(A, f)
    pic = panel(ax, [*outline, to_xy(a), o - [1.0, 0.0]], margin=0.06, fit_height=True)
    model(pic, m, d, show_com=False)
    pic.conic("I2", d.I[i], role="inertia", color=COLORS["construct"], mark_center=False, label="",
              symbol="I₂", desc="inertia I₂ of body 2 alone (5.64), as its circle of gyration")
    _inertia(pic, "A2", A, "A₂", (-1.0, 1.0), desc="articulated inertia A₂ of bodies 2–4, free-floating "
             "(7.1–7.8): its sign-flipped conic about the effective centre")
    force(pic, "f2", f, scale=0.6, anchor=o - [0.5, 0.0], symbol="f₂",
          desc=f"the internal force f₂ at joint 2 (7.1): 1 N along +x through ({num(o[0], 3)}, {num(o[1], 3)}) m")
    pic.point("a2", a, role="accel", symbol="a₂", label="a₂ = A₂⁻¹f₂", glyph_scale=2.0,
              desc=f"acceleration pole a₂ = A₂⁻¹f₂ of body 2 (7.8): {where(a)}, rate {a[2]:.3g} rad/s²")
    show(pic, ax)


@register(7.02, height=2.6)
def fig7_2(ax):
    """Fig. 7.2 — articulated mobility Λ_i⁻¹ of a constrained chain (7.28–7.38, corrected sign of
    7.38a, see docs/errata.md): the load −f_{i+1} on body i accelerates it by a_i = −Λ_i⁻¹ f_{i+1}
    (at rest), including the bodies before it."""
    m, d, outline = _chain4(Q4)
    i = 1
    o = d.origin[i + 1]
    f_next = np.array([-1.0, 0.0, o[1]])   # f_3: a unit force along -x through joint 3 (4.27)
    a = -articulated_mobility(m, Q4).Lambda_inv[i] @ f_next
    pic = panel(ax, [*outline, to_xy(a), d.origin[0] - [0.0, 0.15]], margin=0.06, fit_height=True)
    model(pic, m, d, show_com=False)
    force(pic, "-f3", -f_next, scale=0.35, anchor=o, start=True, symbol="−f₃", label="",
          desc="the load −f₃ on body 2 from body 3 (7.28): 1 N along +x through joint 3")
    # the label above-left of joint 3 (free of links 2 and 3), not on link 3 at the arrow's tip
    label(pic, "-f3:label", o, "−f₃", offset=(-10, 4), ha="right", color=COLORS["reaction"], symbol="−f₃",
          desc="the load −f₃ on body 2 (7.28)")
    pic.point("a2", a, role="accel", symbol="a₂", label="a₂ = −Λ₂⁻¹f₃",
              desc=f"acceleration pole a₂ = −Λ₂⁻¹f₃ of body 2 (7.38, corrected): {where(a)}, "
                   f"rate {a[2]:.3g} rad/s²")
    show(pic, ax)


@register(7.03, height=2.9, ncols=2, gridspec_kw={"width_ratios": [2.3, 1.0]})
def fig7_3(axs):
    """Fig. 7.3 — two identical bodies at angle φ pushed by a horizontal force f₁ at CJ₁ (scene
    'two-body', 7.9–7.24): the articulated inertia A₁ (black) from the bodies' inertias (grey);
    a₁ = A₁⁻¹f₁ is the acceleration pole of body 1 (below CJ₁); m_x = {A₁}₁₁ (7.12)."""
    res, d = scene_state("two-body")
    A1 = np.array(res.quantities["A1"])
    f1 = np.array([1.0, 0.0, 0.0])                  # unit horizontal force through CJ₁ (4.27)
    a1 = np.linalg.solve(A1, f1)
    ax1 = to_xy(a1)
    outline = shape_points(*model_shapes(res.model, d))
    A1_xy = _conic_xy(A1)
    # left: the bodies, their inertias and A₁ in detail; right: the same scene with the pole a₁
    for k, ax in enumerate(axs):
        detail = k == 0
        if detail:
            P = np.vstack([outline, A1_xy, *[_conic_xy(d.I[j]) for j in range(2)]])
            pic = panel(ax, np.vstack([P, P.min(axis=0) - [0.3, 0.7]]), margin=0.03)
        else:
            pic = panel(ax, np.vstack([outline, A1_xy, ax1, ax1 + [1.6, -0.3]]), margin=0.03)
        model(pic, res.model, d, ground=False, labels=False, show_com=detail)
        if detail:
            for j in range(2):
                pic.conic(f"I{j + 1}", d.I[j], role="inertia", color=COLORS["construct"], mark_center=False,
                          label="", symbol=f"I{'₁₂'[j]}", desc=f"inertia of body {j + 1} alone (5.64)")
        pic.conic("A1", A1, role="inertia", mark_center=detail, label="", symbol="A₁",
                  desc=f"articulated inertia A₁ of the two bodies at CJ₁ (7.9–7.24): mₓ/m = {{A₁}}₁₁/m = "
                       f"{res.quantities['mx_over_m']:.3f}")
        pic.line("x = 0", [0.0, 1.0, 0.0], role="construct", arrow=False, label="", symbol="x = 0",
                 desc="the vertical x = 0 through CJ₁")
        if detail:
            force(pic, "f1", f1, scale=0.6, anchor=[-0.35, 0.0], role="wrench", symbol="f₁", label="",
                  desc="the force f₁: 1 N horizontal through CJ₁ (7.9)")
            label(pic, "f1:label", [-0.35, 0.0], "f₁", offset=(-20, 4), color=COLORS["wrench"], symbol="f₁",
                  desc="the force f₁ (7.9)")
            label(pic, "CJ1", [0, 0], "CJ₁", offset=(-22, -14), symbol="CJ₁", desc="the joint CJ₁ at the origin")
            # A₁'s label outside every circle: at its lower-right point (the bodies' grey circles lie
            # left and above), pushed outward
            label(pic, "A1:label", A1_xy[np.argmax(A1_xy[:, 0] - A1_xy[:, 1])], "A₁", offset=(2, -2),
                  va="top", symbol="A₁", desc="articulated inertia A₁ (7.9)")
            x0, x1, y0, y1 = pic.box
            at = (x1 - 0.02 * (x1 - x0), y0 + 0.02 * (y1 - y0))
            pic.text("mx", at, f"mₓ/m = {res.quantities['mx_over_m']:.3f}", ha="right", symbol="mₓ/m",
                     desc="the effective horizontal mass over the mass (7.12): {A₁}₁₁ / m")
            pic.text("phi", at, f"φ = {np.rad2deg(res.params['phi']):.0f}°, λ = {res.quantities['lam']:g}:",
                     ha="right", dy=16.0, symbol="φ, λ", desc="the scene's angle φ and size ratio λ = L/ρ")
        else:
            pic.line("f1", f1, role="wrench", arrow=False, label="", symbol="f₁",
                     desc="the force f₁: 1 N horizontal through CJ₁ (7.9)")
            pic.point("a1", a1, role="accel", symbol="a₁", label=f"a₁ ({num(ax1[0], 3)}, {num(ax1[1], 3)})",
                      desc=f"acceleration pole a₁ = A₁⁻¹f₁ of body 1 (7.9): {where(a1)}")
            label_toward(pic.elements[-1], (1.0, 0.6), 8.0)
        show(pic, ax)
        if not detail:
            ax.add_patch(Rectangle((0, 0), 1, 1, transform=ax.transAxes, fill=False, ec="#bbbbbb", lw=0.6))


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
    pic = panel(ax, [[-0.3, -1.1], [4.2, 0.7]], margin=0.02)
    model(pic, res.model, d, show_com=True, ground=False, labels=False)
    A1 = np.array(res.quantities["A1"])
    _inertia(pic, "A1", A1, "A₁", (0.0, 1.0), text="A₁ (n = 4)", desc="articulated inertia A₁ of the "
             "first body with 4 bodies (7.25–7.27), about its effective centre")
    groups = {}
    for n in range(1, 5):
        dn = build_scene("horizontal-chain", n=n, lam=lam).quantities["d_over_L"]
        key = next((k for k in groups if np.isclose(k, dn, rtol=1e-9)), dn)
        groups.setdefault(key, []).append(n)
    marks = sorted(groups.items())
    for k, (dn, ns) in enumerate(marks):
        # the leftmost mark reaches lowest, so that each text runs right under the marks beyond it
        y = -0.5 - 0.2 * (len(marks) - 1 - k)
        text = f"d₁ = {dn:.3f} L (n = {', '.join(map(str, ns))})"
        segment(pic, f"d1 {k + 1}", [dn, y], [dn, -0.3], role="accel", color=COLORS["accel"], dash=[],
                width=0.8 * PX_PER_PT, symbol="d₁",
                desc=f"effective centre d₁ of the first body (7.27): {dn:.3f} L for n = {', '.join(map(str, ns))}")
        label(pic, f"d1 {k + 1}:label", [dn, y], text, offset=(2, -2), va="top", color=COLORS["accel"],
              symbol="d₁", desc=f"effective centre d₁ (7.27): {text}")
    show(pic, ax)


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
    a2 = np.array(res.quantities["a2"])
    x = to_xy(a2)
    pic = panel(ax, [*d.origin, d.com[1] * 2 - d.origin[1], x, [0, -0.5]], margin=0.12)
    model(pic, res.model, d)
    f3 = np.array(res.quantities["f3"])
    # a pure couple (the line at infinity): its glyph in the upper left corner, clear of body 2
    x0, x1, y0, y1 = pic.box
    gx, gy = x0 + 26 / pic.kx, y1 - 26 / pic.ky
    segment(pic, "-f3", [gx, gy], [gx, gy], role="wrench", symbol="−f₃",
            desc=f"the load −f₃ on body 2: a pure couple of {-f3[2]:.3g} N·m (the line at infinity, 4.27)")
    pic.elements[-1]["parts"] = [
        {"p": "glyph", "x": float(gx), "y": float(gy), "r": 12.0, "ccw": bool(-f3[2] > 0)},
        _text_part(gx, gy, "−f₃: couple on body 2 (line at ∞)", 18.0, 0.0, "left", "center")]
    pic.point("a2", a2, role="accel", symbol="a₂",
              desc=f"acceleration pole a₂ of body 2 (7.40–7.49): {where(a2)}, on the x axis")
    xl = res.quantities["x_over_L"]
    dimension(pic, "x", [0, -0.35], [x[0], -0.35], f"x = {xl:.3f} L",
              desc=f"where a₂ lies on the x axis (7.47, corrected 7.38a): x/L = {xl:.3f}")["symbol"] = "x"
    show(pic, ax)


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
    m, d, outline = _chain4(Q4)
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
    A3 = r_in.A[2]
    pic = panel(ax, [*outline, *_conic_xy(A3), tip, to_xy(sol.a[1]), to_xy(sol.a[2]),
                     d.origin[0] - [0.0, 0.2]], margin=0.05, fit_height=True)
    model(pic, m, d, show_com=False)
    _inertia(pic, "A3", A3, "A₃", (0.0, -1.0),                                        # below A₃, off link 3
             desc="articulated inertia A₃ of the free-floating chain, bodies 3–4 (7.52–7.55)")
    force(pic, "F", F[3], scale=0.5, anchor=tip, role="wrench", symbol="F",
          desc="the external force F: 1 N downward through the tip of body 4")
    force(pic, "f3", f3, scale=0.5, anchor=d.origin[2], symbol="f₃",
          desc=f"the internal force f₃ at joint 3 from the split (7.56): {np.hypot(*f3[:2]):.3g} N")
    a2_text = "a₂ = −Λ₂⁻¹f₃" if b2_zero else "a₂ = b₂ − Λ₂⁻¹f₃"
    pic.point("a2", sol.a[1], role="accel", symbol="a₂", label=a2_text,
              desc=f"acceleration pole of body 2, {a2_text} (7.53): {where(sol.a[1])}")
    label_toward(pic.elements[-1], (1.0, -0.8), 10.0)                             # right of it, below f₃
    pic.point("a3", sol.a[2], role="accel", symbol="a₃", label="a₃ = A₃⁻¹(f₃ − d₃)",
              desc=f"acceleration pole of body 3, a₃ = A₃⁻¹(f₃ − d₃) (7.55): {where(sol.a[2])}")
    show(pic, ax)
