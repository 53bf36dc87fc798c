"""Chapter 6 figures: subspace decompositions T/U, inertia splits, projective kinematics, car (6.1-6.6)."""
from __future__ import annotations

import numpy as np

from ...algorithms.rnea import newton_euler
from ...inertia import Inertia, percussion_pole
from ...joints import revolute
from ...projective import from_xy, join, to_xy
from ...scenes import build as build_scene
from ...subspaces import Decomposition
from ..artists import plot_conic, plot_line, plot_point
from ..constructions import label
from ..mechanism import draw_body, draw_com, draw_ground, draw_model, draw_pin, link_polygon
from ..style import COLORS
from . import fit_view, new_figure, register

J = np.array([0.0, 0.0])


def _body():
    shape = link_polygon(J, [2.0, 0.7], 0.6)
    return shape, Inertia.from_polygon(shape, density=1.0).matrix


def _base(ax, shape, I):
    draw_body(shape, ax)
    c = np.array([I[1, 2], -I[0, 2]]) / I[0, 0]
    draw_com(c, ax)
    draw_pin(J, ax)
    plot_conic(I, ax, role="inertia", mark_center=False)
    return c


def _view(ax, pts, margin=0.12):
    fit_view(ax, list(pts) + [[-0.6, -0.8], [2.6, 1.4]], margin=margin)


@register("fig6_1", "Fig. 6.1 — basic decomposition at a pin joint: force space [T R₁ R₂] with "
          "T = I s the axis of percussion of the joint (6.2–6.3) and two unit reactions through "
          "the joint; their mapped accelerations I⁻¹T = s, I⁻¹R₁, I⁻¹R₂ (percussion poles).", 6.01)
def fig6_1():
    fig, ax = new_figure(3.4, 2.6)
    shape, I = _body()
    _base(ax, shape, I)
    j = revolute(J)
    s = j.s[:, 0]
    T = I @ s
    R1, R2 = j.R[:, 0], j.R[:, 1]
    plot_point(s, ax, glyph=False, text="$s = I^{-1}T$", text_offset=(-40, 8))
    plot_line(T, ax, role="momentum", scale=None, text="$T = Is$", anchor=[2.2, 1.0])
    pts = []
    for k, R in enumerate((R1, R2), start=1):
        plot_line(R, ax, role="reaction", scale=None, text=f"$R_{k}$",
                  anchor=J + 1.1 * R[:2] / np.hypot(*R[:2]))
        a = percussion_pole(I, R)
        plot_point(a, ax, role="accel", glyph=False, text=f"$I^{{-1}}R_{k}$",
                   text_offset=(6, 4) if k == 1 else (8, -14))
        pts.append(to_xy(a))
    _view(ax, pts)
    return fig


@register("fig6_2", "Fig. 6.2 — decoupled decomposition (6.36–6.48): the reactive accelerations "
          "U = I⁻¹R(RᵀI⁻¹R)⁻¹ lie on the axis of percussion T, U₁ on R₂ and U₂ on R₁, so "
          "RᵀU = 1 (6.47–6.48). From subspaces.Decomposition.", 6.02)
def fig6_2():
    fig, ax = new_figure(3.4, 2.6)
    shape, I = _body()
    _base(ax, shape, I)
    j = revolute(J)
    dec = Decomposition.from_joint(j, I)
    assert np.allclose(dec.R.T @ dec.U, np.eye(2))
    plot_point(j.s[:, 0], ax, glyph=False, text="$s$", text_offset=(-14, 8))
    plot_line(dec.T[:, 0], ax, role="momentum", scale=None, text="$T$", anchor=[2.4, 1.0])
    pts = []
    for k in range(2):
        R = dec.R[:, k]
        plot_line(R, ax, role="reaction", scale=None, text=f"$R_{k + 1}$",
                  anchor=J + 1.1 * R[:2] / np.hypot(*R[:2]))
        plot_point(dec.U[:, k], ax, role="accel", glyph=False, text=f"$U_{k + 1}$")
        pts.append(to_xy(dec.U[:, k]))
    _view(ax, pts)
    return fig


def _split_panels(kind):
    fig, axs = new_figure(3.4, 4.2, nrows=2)
    shape, I = _body()
    j = revolute(J)
    dec = Decomposition.from_joint(j, I)
    if kind == "inertia":
        a = from_xy([2.6, -0.4]) * 1.0          # an acceleration pole, unit α
        psi, gamma = dec.split_twist(a)
        a1, a2 = j.s @ psi, dec.U @ gamma       # a = s ψ + U γ (6.44)
        f1, f2 = I @ a1, I @ a2                 # I = T sᵀI + R UᵀI (6.76)
        assert np.allclose(f1 + f2, I @ a) and np.allclose(f1, dec.T @ (j.s.T @ I @ a))
        panels = (("A", a1, f1, "$a_1 = s\\psi$", "$f_1 = Ia_1$"),
                  ("B", a2, f2, "$a_2 = U\\gamma$", "$f_2 = Ia_2$"))
    else:
        f = join(from_xy([2.4, -0.6]), from_xy([2.0, 1.2]))   # an applied force
        Q, mu = dec.split_wrench(f)
        f1, f2 = dec.T @ Q, dec.R @ mu          # f = T Q + R μ (6.38)
        a1, a2 = np.linalg.solve(I, f1), np.linalg.solve(I, f2)   # (6.80), (6.81)
        assert np.allclose(a1, j.s @ (dec.T.T @ np.linalg.solve(I, f)))
        panels = (("A", a1, f1, "$a_1 = I^{-1}f_1$", "$f_1 = TQ$"),
                  ("B", a2, f2, "$a_2 = I^{-1}f_2$", "$f_2 = R\\mu$"))
    for ax, (tag, a, f, ta, tf) in zip(axs, panels):
        _base(ax, shape, I)
        plot_line(dec.T[:, 0], ax, role="construct", scale=None, text="$T$", anchor=[2.5, 1.2])
        plot_point(a, ax, role="accel", text=ta)
        plot_line(f, ax, role="wrench", scale=0.6 / max(np.hypot(*f[:2]), 1e-12) if np.any(f[:2])
                  else None, text=tf, anchor=to_xy(a) if a[2] != 0 else None,
                  corner="lower right")
        ax.text(0.02, 0.96, tag, transform=ax.transAxes, fontsize=9, fontweight="bold", va="top")
        _view(ax, [to_xy(a)])
    return fig


@register("fig6_3", "Fig. 6.3 — inertia decomposition I = T sᵀI + R UᵀI (6.75–6.76): an "
          "acceleration a = sψ + Uγ; A) f₁ = I sψ accelerates the body about the joint (on T), "
          "B) f₂ = I Uγ accelerates it along the reactive space (a force through the joint).", 6.03)
def fig6_3():
    return _split_panels("inertia")


@register("fig6_4", "Fig. 6.4 — inverse inertia decomposition (6.77–6.81): a force f = TQ + Rμ; "
          "A) the active part TQ produces a₁ = sTᵀI⁻¹f about the joint, B) the reaction Rμ "
          "produces a₂ = URᵀI⁻¹f on the axis T.", 6.04)
def fig6_4():
    return _split_panels("inverse")


@register("fig6_5", "Fig. 6.5 — projective kinematics (6.98–6.101): ψ_i = T_iᵀa_i and ψ_{i−1} = "
          "T_iᵀa_{i−1} are the absolute accelerations along joint i, q̈_i = ψ_i − T_iᵀ(a_{i−1} + "
          "κ_i); T_i from the body inertia of link 2 (RNEA state).", 6.05)
def fig6_5():
    from .ch4 import Q47, QD47, QDD47, _chain3

    fig, ax = new_figure(3.4, 2.8)
    m = _chain3()
    w = newton_euler(m, Q47, QD47, QDD47)
    i = 1
    dec = Decomposition(w.s(i), revolute(w.origin[i]).R, w.I[i])
    T = dec.T[:, 0]
    psi_i, psi_prev = T @ w.a[i], T @ w.a[i - 1]
    qdd = psi_i - T @ (w.a[i - 1] + w.kappa[i])
    assert np.isclose(qdd, QDD47[i])
    draw_model(m, w, ax, show_com=False)
    plot_line(T, ax, role="momentum", scale=None, text="$T_2$")
    plot_point(w.s(i)[:, 0], ax, glyph=False, text="$s_2$", text_offset=(-16, -12))
    plot_point(w.a[i - 1], ax, role="accel", text="$a_1$")
    plot_point(w.a[i], ax, role="accel", text="$a_2$")
    ax.text(0.02, 0.98, f"$\\psi_2$ = {psi_i:.3g},  $\\psi_1$ = {psi_prev:.3g},  "
            f"$\\ddot q_2$ = {qdd:.3g}", transform=ax.transAxes, fontsize=7, va="top")
    fit_view(ax, [to_xy(w.a[i - 1]), to_xy(w.a[i]), *w.origin], margin=0.15)
    return fig


@register("fig6_6", "Fig. 6.6 — car cornering and accelerating (6.114–6.133, scene 'car'): the ICR "
          "is the joint s, the tyre reactions R₁μ₁ (rear) and R₂μ₂ (front) act along the axles, "
          "f_A drives the front wheels; a is the resulting acceleration pole.", 6.06)
def fig6_6():
    res = build_scene("car")
    ex, qn = res.extra, res.quantities
    fig, ax = new_figure(3.4, 3.0)
    shape = res.model.bodies[0].shape
    draw_body(shape, ax, alpha=0.25)
    for t in ex["tyres"]:
        draw_body(t, ax, color="#333333", alpha=0.9)
    draw_com(ex["cg"], ax, radius=0.12)
    plot_point(ex["s"][:, 0], ax, glyph=False, text="ICR ($s$)", text_offset=(4, -20))
    sc = 1.0 / 1000.0
    R1mu, R2mu = ex["tyre_wrenches"][:, 0], ex["tyre_wrenches"][:, 1]
    plot_line(R1mu, ax, role="reaction", scale=sc, anchor=0.5 * ex["rear_contact"],
              text=f"$R_1\\mu_1$ = {qn['mu'][0]:.0f} N (rear)", text_offset=(30, -20))
    plot_line(R2mu, ax, role="reaction", scale=sc, anchor=0.5 * ex["front_contact"],
              text=f"$R_2\\mu_2$ = {qn['mu'][1]:.0f} N (front)", text_offset=(-30, 8))
    plot_line(qn["f_A"], ax, scale=sc, anchor=ex["front_contact"] + 0.9 * ex["front_rolling"],
              text="$f_A$")
    plot_line(ex["T"][:, 0], ax, role="momentum", scale=None, text="$T$")
    plot_point(qn["a"], ax, role="accel", text="$a$", text_offset=(-14, 8))
    pts = [ex["icr"], ex["rear_contact"], ex["front_contact"], to_xy(qn["a"])]
    fit_view(ax, pts, margin=0.15)
    ax.text(0.02, 0.98, f"$\\dot\\omega$ = {qn['omega_dot']:.3f} rad/s²", transform=ax.transAxes, fontsize=7,
            va="top")
    return fig


_ = (draw_ground, COLORS)
