"""Chapter 6 figures: subspace decompositions T/U, inertia splits, projective kinematics, car (6.1-6.6)."""
from __future__ import annotations

import numpy as np
from shapely.geometry import Point

from planargeo.screws.inertia import Inertia, centre_of_mass
from planargeo.mechanics.joints import revolute
from planargeo.geometry.projective import from_xy, join, to_xy
from planargeo.scenes import build as build_scene
from planargeo.draw.artists import plot_conic, plot_line, plot_point
from planargeo.draw.constructions import (draw_decomposition, draw_projective_step, draw_twist_split,
                             draw_wrench_split)
from planargeo.draw.mechanism import draw_body, draw_com, draw_pin, link_polygon
from planargeo.draw.layout import fit_panel, fit_view, shape_points
from planargeo.draw.style import LABEL_PT
from planargeo.gallery.figures import register
from planargeo.gallery.figures.ch4 import QDD47, chain47

J = np.array([0.0, 0.0])


def _pinned_body(ax):
    """The body of Figs 6.1-6.4 pinned at ``J``, drawn with its centre of mass and inertia.

    Returns its shape, its inertia (from the polygon) and the revolute joint at ``J``.
    """
    shape = link_polygon(J, [2.0, 0.7], 0.6)
    I = Inertia.from_polygon(shape, density=1.0).matrix
    draw_body(shape, ax, com=centre_of_mass(I))
    draw_pin(J, ax)
    plot_conic(I, ax, role="inertia", mark_center=False)
    return shape, I, revolute(J)


def _on_line(L, y):
    """The point of the line ``L`` (4.27: ``tz + y fx − x fy = 0``) at height ``y`` (L not horizontal)."""
    return np.array([(L[2] + y * L[0]) / L[1], y])


def _view(ax, shape, pts, margin=0.1, *, panel=False):
    """Fit the view to the body and the computed points (single panel: the figure height too)."""
    P = np.vstack([shape_points(shape), np.reshape(pts, (-1, 2))])
    (fit_view if panel else fit_panel)(P, ax=ax, margin=margin)


@register(6.01, height=2.6)
def fig6_1(ax):
    """Fig. 6.1 — basic decomposition at a pin joint: force space [T R₁ R₂] with T = I s the axis
    of percussion of the joint (6.2–6.3) and two unit reactions through the joint; their mapped
    accelerations I⁻¹T = s, I⁻¹R₁, I⁻¹R₂ (percussion poles). Drawn by
    constructions.draw_decomposition."""
    shape, I, j = _pinned_body(ax)
    out = draw_decomposition(
        j.s, j.R, I, ax, reactive="inverse",
        labels={"s": "$s = I^{-1}T$", "T": "$T = Is$", "AiR1": "$I^{-1}R_1$",
                "AiR2": "$I^{-1}R_2$"},
        text_offsets={"s": (-5, -4), "T": (5, -3), "R1": (-14, -13), "R2": (-14, -4),
                      "AiR1": (7, 3), "AiR2": (7, 3)})
    # the joint's label below-left of the pin, right-aligned so it grows into the view
    out["s"].set_text_alignment("right", "top")
    T = out["values"]["T"][:, 0]
    pts = [to_xy(out["values"]["AiR"][:, k]) for k in range(2)]
    lo = min(-0.5, pts[0][1] - 2.0)
    out["T"].set_anchor(_on_line(T, lo + 0.25))
    out["R1"].set_anchor([pts[1][0] + 1.4, 0.0])
    out["R2"].set_anchor([0.0, pts[0][1]])
    _view(ax, shape, pts + [[pts[1][0] + 1.5, lo], [-0.7, pts[0][1] + 0.3]], margin=0.02)


@register(6.02, height=2.6)
def fig6_2(ax):
    """Fig. 6.2 — decoupled decomposition (6.36–6.48): the reactive accelerations
    U = I⁻¹R(RᵀI⁻¹R)⁻¹ lie on the axis of percussion T, U₁ on R₂ and U₂ on R₁, so RᵀU = 1
    (6.47–6.48). Drawn with the inverse that the printed (6.33)–(6.34) miss (there RᵀU = (RᵀI⁻¹R)²,
    not 1; docs/errata.md, (6.33)–(6.34)). From constructions.draw_decomposition."""
    shape, I, j = _pinned_body(ax)
    out = draw_decomposition(j.s, j.R, I, ax, text_offsets={
        "s": (-12, 5), "T": (5, -3), "R1": (-14, -13), "R2": (-14, -4), "U1": (6, 3),
        "U2": (6, 3)})
    U = out["values"]["U"]
    assert np.allclose(j.R.T @ U, np.eye(2))
    pts = [to_xy(U[:, k]) for k in range(2)]     # U₁ on R₂ (x = 0), U₂ on R₁ (y = 0)
    out["T"].set_anchor(_on_line(out["values"]["T"][:, 0], -0.45))
    out["R1"].set_anchor([pts[1][0] + 1.0, 0.0])
    out["R2"].set_anchor([0.0, 0.5 * (1.0 + pts[0][1])])
    _view(ax, shape, pts + [[pts[1][0] + 1.1, -0.6], [-0.6, pts[0][1] + 0.3]], margin=0.02)


def _split_panels(axs, kind):
    """Figs 6.3-6.4: an acceleration (``kind`` "inertia") or a force split by the pin joint."""
    if kind == "inertia":
        q = from_xy([2.6, -0.4]) * 1.0          # an acceleration pole, unit α
        draw, names = draw_twist_split, {"a1": "$a_1 = s\\psi$", "a2": "$a_2 = U\\gamma$",
                                         "f1": "$f_1 = Ia_1$", "f2": "$f_2 = Ia_2$"}
    else:
        q = join(from_xy([2.4, -0.6]), from_xy([2.0, 1.2]))   # an applied force
        draw, names = draw_wrench_split, {"a1": "$a_1 = I^{-1}f_1$", "a2": "$a_2 = I^{-1}f_2$"}
    for k, ax in enumerate(axs, start=1):
        shape, I, j = _pinned_body(ax)
        out = draw(j.s, j.R, I, q, ax, parts=[k], names=names, arrow_length=0.6)
        v = out["values"]
        if kind == "inertia":   # a = sψ + Uγ (6.44), I a = f₁ + f₂ (6.76)
            assert np.allclose(v["a1"] + v["a2"], q) and np.allclose(v["f1"] + v["f2"], I @ q)
        else:                   # f = TQ + Rμ (6.38), a₁ = s TᵀI⁻¹f (6.80)
            assert np.allclose(v["f1"] + v["f2"], q)
            assert np.allclose(v["a1"], j.s @ (v["T"].T @ np.linalg.solve(I, q)))
        T = v["T"][:, 0]
        out["T"].set_anchor(_on_line(T, -0.85))
        a, f = v[f"a{k}"], v[f"f{k}"]
        xa = to_xy(a)
        if np.hypot(*xa) < 0.1:          # the pole at the joint: label left of the body
            out[f"a{k}"].set_text_offset((-62, -16))
        elif shape.contains(Point(xa)):  # a pole on the body: label above the body's edge
            out[f"a{k}"].set_text_offset((8, 18))
        else:
            out[f"a{k}"].set_text_offset((10, 1))
        # the force arrow above the body, where its line leaves it; its label beside the
        # arrow's middle on the side the line leaves free (away from the body)
        e = f[:2] / np.hypot(*f[:2])
        top = _on_line(f, 1.55) if abs(e[1]) > 0.3 else xa
        rising = e[0] * e[1] > 0
        art = out[f"f{k}"]
        art.set_anchor(top)
        art.set_text_offset((-8, 0) if rising else (8, 0))
        art.set_text_alignment("right" if rising else "left", "center")
        ax.text(0.02, 0.96, "AB"[k - 1], transform=ax.transAxes, fontsize=9, fontweight="bold",
                va="top")
        _view(ax, shape, [xa, [-0.7, -0.95], [2.9, 1.95]], margin=0.02, panel=True)


@register(6.03, height=4.2, nrows=2)
def fig6_3(axs):
    """Fig. 6.3 — inertia decomposition I = T sᵀI + R UᵀI (6.75–6.76): an acceleration a = sψ + Uγ;
    A) f₁ = I sψ accelerates the body about the joint (on T), B) f₂ = I Uγ accelerates it along the
    reactive space (a force through the joint). Drawn by constructions.draw_twist_split."""
    _split_panels(axs, "inertia")


@register(6.04, height=4.2, nrows=2)
def fig6_4(axs):
    """Fig. 6.4 — inverse inertia decomposition (6.77–6.81): a force f = TQ + Rμ; A) the active
    part TQ produces a₁ = sTᵀI⁻¹f about the joint, B) the reaction Rμ produces a₂ = URᵀI⁻¹f on the
    axis T. Drawn by constructions.draw_wrench_split."""
    _split_panels(axs, "inverse")


@register(6.05, height=2.8)
def fig6_5(ax):
    """Fig. 6.5 — projective kinematics (6.98–6.101): ψ_i = T_iᵀa_i and ψ_{i−1} = T_iᵀa_{i−1} are
    the absolute accelerations along joint i, q̈_i = ψ_i − T_iᵀ(a_{i−1} + κ_i); T_i from the body
    inertia of link 2 (RNEA state). Drawn by constructions.draw_projective_step."""
    w, arts = chain47(ax, show_com=False)
    i = 1
    P = np.vstack([shape_points(*arts["shapes"]), to_xy(w.a[i - 1]), to_xy(w.a[i])])
    lo = P.min(axis=0)
    out = draw_projective_step(w.s(i), revolute(w.origin[i]).R, w.I[i], w.a[i - 1], w.a[i],
                               w.kappa[i], ax, names=("$T_2$", "$s_2$", "$a_1$", "$a_2$"),
                               text_offsets=((-4, 6), (-16, -12), (-18, 6), (17, -6)),
                               T_anchor=P.max(axis=0) - [0.9, 0.0])
    v = out["values"]
    psi_i, psi_prev, qdd = v["psi"][0], v["psi_prev"][0], v["qdd"][0]
    assert np.isclose(qdd, QDD47[i])
    fit_panel(np.vstack([P, lo - [0.0, 0.45]]), margin=0.04, ax=ax)
    ax.text(0.98, 0.02, f"$\\psi_2$ = {psi_i:.3g},  $\\psi_1$ = {psi_prev:.3g},  "
            f"$\\ddot q_2$ = {qdd:.3g}", transform=ax.transAxes, fontsize=LABEL_PT, ha="right",
            va="bottom")


@register(6.06, height=3.0)
def fig6_6(ax):
    """Fig. 6.6 — car cornering and accelerating (6.114–6.133, scene 'car'): the ICR is the joint
    s, the tyre reactions R₁μ₁ (rear) and R₂μ₂ (front) act along the axles, f_A drives the front
    wheels; a is the resulting acceleration pole."""
    res = build_scene("car")
    ex, qn = res.extra, res.quantities
    shape = res.model.bodies[0].shape
    draw_body(shape, ax, alpha=0.25)
    for t in ex["tyres"]:
        draw_body(t, ax, color="#333333", alpha=0.9)
    draw_com(ex["cg"], ax, radius=0.12)
    icr, rear, front = ex["icr"], ex["rear_contact"], ex["front_contact"]
    plot_point(ex["s"][:, 0], ax, glyph=False, text="ICR ($s$)", text_offset=(-10, -16))
    sc = 1.0 / 1000.0
    R1mu, R2mu = ex["tyre_wrenches"][:, 0], ex["tyre_wrenches"][:, 1]
    # force arrows halfway between the ICR and the tyres, labels on the open side of each line
    plot_line(R1mu, ax, role="reaction", scale=sc, anchor=0.5 * (icr + rear),
              text=f"$R_1\\mu_1$ = {qn['mu'][0]:.0f} N (rear)", text_offset=(-40, -15))
    plot_line(R2mu, ax, role="reaction", scale=sc, anchor=0.5 * (icr + front),
              text=f"$R_2\\mu_2$ = {qn['mu'][1]:.0f} N (front)", text_offset=(-70, 10))
    fA = np.asarray(qn["f_A"])
    eA = fA[:2] / np.hypot(*fA[:2])
    anchor_A = front + 0.9 * ex["front_rolling"]
    plot_line(fA, ax, scale=sc, anchor=anchor_A, text="$f_A$", text_offset=(-16, -4))
    T = ex["T"][:, 0]
    L_A = 0.5 * sc * np.hypot(*fA[:2])
    P = np.vstack([shape_points(shape, *ex["tyres"]), icr, rear, front, to_xy(qn["a"]),
                   anchor_A + eA * L_A, anchor_A - eA * L_A])
    lo, hi = P.min(axis=0), P.max(axis=0)
    plot_line(T, ax, role="momentum", scale=None, text="$T$", anchor=_on_line(T, lo[1] - 0.5),
              text_offset=(-12, 0))
    plot_point(qn["a"], ax, role="accel", text="$a$", text_offset=(-14, 8))
    fit_panel(np.vstack([P, [lo[0] - 0.6, lo[1] - 0.9], [hi[0] + 0.8, hi[1] + 0.5]]),
              margin=0.02, ax=ax)
    ax.text(0.02, 0.98, f"$\\dot\\omega$ = {qn['omega_dot']:.3f} rad/s²", transform=ax.transAxes,
            fontsize=LABEL_PT, va="top")

