"""Chapter 6 figures: subspace decompositions T/U, inertia splits, projective kinematics, car (6.1-6.6)."""
from __future__ import annotations

import numpy as np
from shapely.geometry import Point

from planargeo.draw.layout import shape_points
from planargeo.draw.pictures._words import num, pair
from planargeo.draw.pictures.kit import aim_label, force as force_arrow, label_at
from planargeo.draw.sketch import body, com, link_polygon, model, model_shapes, panel, pin, show
from planargeo.draw.splits import (decomposition, projective_step, twist_parts, twist_split,
                                   wrench_parts, wrench_split)
from planargeo.gallery.figures import register
from planargeo.gallery.figures.ch4 import QDD47, chain47_state
from planargeo.geometry.projective import from_xy, join, to_xy
from planargeo.mechanics.joints import revolute
from planargeo.mechanics.subspaces import Decomposition
from planargeo.scenes import build as build_scene
from planargeo.screws.inertia import Inertia, centre_of_mass

J = np.array([0.0, 0.0])


def _rod():
    """The body of Figs 6.1-6.4 pinned at ``J``: its shape, its inertia (from the polygon) and the joint."""
    shape = link_polygon(J, [2.0, 0.7], 0.6)
    I = Inertia.from_polygon(shape, density=1.0).matrix
    return shape, I, revolute(J)


def _pinned_body(pic, shape, I):
    """Draw the rod with its centre of mass, the pin at ``J`` and its inertia's conic."""
    c = centre_of_mass(I)
    body(pic, "body", shape, com=c, symbol="body",
         desc=f"the body: a rod of density 1 kg/m², mass {I[0, 0]:.3g} kg, "
              f"centre of mass at {pair(c)} m")
    pin(pic, "pin", J, desc="the revolute joint at the origin (the pin)")
    pic.conic("inertia", I, role="inertia", mark_center=False, symbol="I", label="",
              desc=f"the body's inertia as a conic (5.6): centred at its centre of mass {pair(c)} m, "
                   f"radius of gyration {np.sqrt(I[2, 2] / I[0, 0] - c @ c):.3g} m")


def _show(pic, ax):
    """Name the sketch's unnamed marks (centre-of-mass discs, pins: no symbol argument) and draw."""
    for el in pic.elements:
        if not el["symbol"]:
            el["symbol"] = "centre of mass" if ":com" in el["id"] or el["id"].startswith("cg") else \
                el["id"].replace("pin", "joint")
    return show(pic, ax)


def _on_line(L, y):
    """The point of the line ``L`` (4.27: ``tz + y fx − x fy = 0``) at height ``y`` (L not horizontal)."""
    return np.array([(L[2] + y * L[0]) / L[1], y])


@register(6.01, height=2.6)
def fig6_1(ax):
    """Fig. 6.1 — basic decomposition at a pin joint: force space [T R₁ R₂] with T = I s the axis
    of percussion of the joint (6.2–6.3) and two unit reactions through the joint; their mapped
    accelerations I⁻¹T = s, I⁻¹R₁, I⁻¹R₂ (percussion poles). Drawn by
    splits.decomposition."""
    shape, I, j = _rod()
    AiR = np.linalg.solve(I, j.R)
    pts = [to_xy(AiR[:, k]) for k in range(2)]
    lo = min(-0.5, pts[0][1] - 2.0)
    pic = panel(ax, np.vstack([shape_points(shape), pts, [[pts[1][0] + 1.5, lo],
                                                         [-0.7, pts[0][1] + 0.3]]]),
                margin=0.02, fit_height=True)
    _pinned_body(pic, shape, I)
    T = Decomposition(I, j.s, j.R).T[:, 0]
    decomposition(
        pic, j.s, j.R, I, reactive="inverse",
        labels={"s": "$s = I^{-1}T$", "T": "$T = Is$", "AiR1": "$I^{-1}R_1$", "AiR2": "$I^{-1}R_2$"},
        anchors={"T": _on_line(T, lo + 0.25), "R1": [pts[1][0] + 1.4, 0.0], "R2": [0.0, pts[0][1]]},
        sides={"R1": -1.0, "R2": -1.0},
        aims={"s": (-8.0, -7.0), "AiR1": (10.0, 4.0), "AiR2": (10.0, 4.0)})
    _show(pic, ax)


@register(6.02, height=2.6)
def fig6_2(ax):
    """Fig. 6.2 — decoupled decomposition (6.36–6.48): the reactive accelerations
    U = I⁻¹R(RᵀI⁻¹R)⁻¹ lie on the axis of percussion T, U₁ on R₂ and U₂ on R₁, so RᵀU = 1
    (6.47–6.48). Drawn with the inverse that the printed (6.33)–(6.34) miss (there RᵀU = (RᵀI⁻¹R)²,
    not 1; docs/errata.md, (6.33)–(6.34)). From splits.decomposition."""
    shape, I, j = _rod()
    dec = Decomposition(I, j.s, j.R)
    U, T = dec.U, dec.T[:, 0]
    assert np.allclose(j.R.T @ U, np.eye(2))
    pts = [to_xy(U[:, k]) for k in range(2)]     # U₁ on R₂ (x = 0), U₂ on R₁ (y = 0)
    pic = panel(ax, np.vstack([shape_points(shape), pts, [[pts[1][0] + 1.1, -0.6],
                                                         [-0.6, pts[0][1] + 0.3]]]),
                margin=0.02, fit_height=True)
    _pinned_body(pic, shape, I)
    decomposition(pic, j.s, j.R, I,
                  anchors={"T": _on_line(T, -0.45), "R1": [pts[1][0] + 1.0, 0.0],
                           "R2": [0.0, 0.5 * (1.0 + pts[0][1])]},
                  sides={"R1": -1.0, "R2": -1.0},
                  aims={"s": (-14.0, 8.0), "U1": (8.0, 4.0), "U2": (8.0, 4.0)})
    _show(pic, ax)


def _split_panels(axs, kind):
    """Figs 6.3-6.4: an acceleration (``kind`` "inertia") or a force split by the pin joint."""
    shape, I, j = _rod()
    if kind == "inertia":
        q = from_xy([2.6, -0.4]) * 1.0          # an acceleration pole, unit α
        draw, names = twist_split, {"a1": "$a_1 = s\\psi$", "a2": "$a_2 = U\\gamma$",
                                    "f1": "$f_1 = Ia_1$", "f2": "$f_2 = Ia_2$"}
        v = twist_parts(j.s, j.R, I, q)
        # a = sψ + Uγ (6.44), I a = f₁ + f₂ (6.76)
        assert np.allclose(v["a1"] + v["a2"], q) and np.allclose(v["f1"] + v["f2"], I @ q)
    else:
        q = join(from_xy([2.4, -0.6]), from_xy([2.0, 1.2]))   # an applied force
        draw, names = wrench_split, {"a1": "$a_1 = I^{-1}f_1$", "a2": "$a_2 = I^{-1}f_2$"}
        v = wrench_parts(j.s, j.R, I, q)
        # f = TQ + Rμ (6.38), a₁ = s TᵀI⁻¹f (6.80)
        assert np.allclose(v["f1"] + v["f2"], q)
        assert np.allclose(v["a1"], j.s @ (v["T"].T @ np.linalg.solve(I, q)))
    T = v["T"][:, 0]
    for k, ax in enumerate(axs, start=1):
        a, f = v[f"a{k}"], v[f"f{k}"]
        xa = to_xy(a)
        pic = panel(ax, np.vstack([shape_points(shape), xa, [-0.7, -0.95], [2.9, 1.95]]), margin=0.02)
        _pinned_body(pic, shape, I)
        if np.hypot(*xa) < 0.1:          # the pole at the joint: label left of the body
            aim_a = (-14.0, -28.0)
        elif shape.contains(Point(xa)):  # a pole on the body: label above the body's edge
            aim_a = (11.0, 25.0)
        else:
            aim_a = (14.0, 1.0)
        # the force arrow above the body, where its line leaves it; its label beside the
        # arrow's middle on the side the line leaves free (away from the body)
        e = f[:2] / np.hypot(*f[:2])
        top = _on_line(f, 1.55) if abs(e[1]) > 0.3 else xa
        rising = e[0] * e[1] > 0
        draw(pic, j.s, j.R, I, q, parts=[k], names=names, arrow_length=0.6,
             anchors={"T": _on_line(T, -0.85), f"f{k}": top},
             aims={f"a{k}": aim_a, f"f{k}": (-11.0, 0.0) if rising else (11.0, 0.0)})
        x0, x1, y0, y1 = pic.box
        what = ("the acceleration about the joint and its force" if k == 1 else
                "the acceleration on the axis T and its force through the joint")
        if kind != "inertia":
            what = ("the active part of the force and its acceleration" if k == 1 else
                    "the reaction part of the force and its acceleration")
        pic.text("panel", (x0, y1), "AB"[k - 1], dx=4.0, dy=-4.0, va="top", symbol="AB"[k - 1],
                 desc=f"panel {'AB'[k - 1]}: part {k}, {what}")
        _show(pic, ax)


@register(6.03, height=4.2, nrows=2)
def fig6_3(axs):
    """Fig. 6.3 — inertia decomposition I = T sᵀI + R UᵀI (6.75–6.76): an acceleration a = sψ + Uγ;
    A) f₁ = I sψ accelerates the body about the joint (on T), B) f₂ = I Uγ accelerates it along the
    reactive space (a force through the joint). Drawn by splits.twist_split."""
    _split_panels(axs, "inertia")


@register(6.04, height=4.2, nrows=2)
def fig6_4(axs):
    """Fig. 6.4 — inverse inertia decomposition (6.77–6.81): a force f = TQ + Rμ; A) the active
    part TQ produces a₁ = sTᵀI⁻¹f about the joint, B) the reaction Rμ produces a₂ = URᵀI⁻¹f on the
    axis T. Drawn by splits.wrench_split."""
    _split_panels(axs, "inverse")


@register(6.05, height=2.8)
def fig6_5(ax):
    """Fig. 6.5 — projective kinematics (6.98–6.101): ψ_i = T_iᵀa_i and ψ_{i−1} = T_iᵀa_{i−1} are
    the absolute accelerations along joint i, q̈_i = ψ_i − T_iᵀ(a_{i−1} + κ_i); T_i from the body
    inertia of link 2 (RNEA state). Drawn by splits.projective_step."""
    m, w = chain47_state()
    i = 1
    P = np.vstack([shape_points(*model_shapes(m, w)), to_xy(w.a[i - 1]), to_xy(w.a[i])])
    lo = P.min(axis=0)
    pic = panel(ax, np.vstack([P, lo - [0.0, 0.45]]), margin=0.04, fit_height=True)
    model(pic, m, w, show_com=False)
    out = projective_step(pic, w.s(i), revolute(w.origin[i]).R, w.I[i], w.a[i - 1], w.a[i],
                          w.kappa[i], names=("$T_2$", "$s_2$", "$a_1$", "$a_2$"),
                          aims={"T": (-6.0, 8.0), "s": (-14.0, -14.0), "a_prev": (-14.0, 10.0),
                                "a": (20.0, -6.0)},
                          T_anchor=P.max(axis=0) - [0.9, 0.0])
    v = out["values"]
    psi_i, psi_prev, qdd = v["psi"][0], v["psi_prev"][0], v["qdd"][0]
    assert np.isclose(qdd, QDD47[i])
    x0, x1, y0, y1 = pic.box
    pic.text("readout", (x1, y0), f"ψ₂ = {psi_i:.3g},  ψ₁ = {psi_prev:.3g},  q̈₂ = {qdd:.3g}",
             dx=-4.0, dy=4.0, ha="right", symbol="ψ₂, ψ₁, q̈₂",
             desc=f"the accelerations along joint 2 (6.100): ψ₂ = T₂ᵀa₂ = {num(psi_i)} rad/s², "
                  f"ψ₁ = T₂ᵀa₁ = {num(psi_prev)} rad/s²; the joint acceleration (6.110): "
                  f"q̈₂ = ψ₂ − T₂ᵀ(a₁ + κ₂) = {num(qdd)} rad/s²")
    _show(pic, ax)


@register(6.06, height=3.0)
def fig6_6(ax):
    """Fig. 6.6 — car cornering and accelerating (6.114–6.133, scene 'car'): the ICR is the joint
    s, the tyre reactions R₁μ₁ (rear) and R₂μ₂ (front) act along the axles, f_A drives the front
    wheels; a is the resulting acceleration pole."""
    res = build_scene("car")
    ex, qn = res.extra, res.quantities
    shape = res.model.bodies[0].shape
    icr, rear, front = ex["icr"], ex["rear_contact"], ex["front_contact"]
    sc = 1.0 / 1000.0
    R1mu, R2mu = ex["tyre_wrenches"][:, 0], ex["tyre_wrenches"][:, 1]
    fA = np.asarray(qn["f_A"])
    eA = fA[:2] / np.hypot(*fA[:2])
    anchor_A = front + 0.9 * ex["front_rolling"]
    T = ex["T"][:, 0]
    L_A = 0.5 * sc * np.hypot(*fA[:2])
    P = np.vstack([shape_points(shape, *ex["tyres"]), icr, rear, front, to_xy(qn["a"]),
                   anchor_A + eA * L_A, anchor_A - eA * L_A])
    lo, hi = P.min(axis=0), P.max(axis=0)
    pic = panel(ax, np.vstack([P, [lo[0] - 0.6, lo[1] - 0.9], [hi[0] + 0.8, hi[1] + 0.5]]),
                margin=0.02, fit_height=True)
    body(pic, "car", shape, alpha=0.25, symbol="car", desc="the car's body (scene 'car')")
    for k, t in enumerate(ex["tyres"]):
        body(pic, f"tyre {k + 1}", t, color="#333333", alpha=0.9, symbol="tyre",
             desc=f"{'rear' if k == 0 else 'front'} tyre" if len(ex["tyres"]) == 2 else "a tyre")
    com(pic, "cg", ex["cg"], radius=0.12, desc=f"centre of mass of the car, at {pair(ex['cg'])} m")
    pic.point("s", ex["s"][:, 0], role="twist", glyph=False, symbol="s", label="ICR (s)",
              desc=f"the instantaneous centre of rotation, the car's joint s (6.114): at {pair(icr)} m")
    pic.elements[-1]["parts"][-1].update(dx=0.0, dy=-14.0, ha="center", va="top")
    mu = qn["mu"]
    force_arrow(pic, "R1mu", R1mu, scale=sc, anchor=0.5 * (icr + rear), role="reaction",
                symbol="R₁μ₁", label=f"R₁μ₁ = {mu[0]:.0f} N (rear)",
                label_xy=icr + 0.4 * (rear - icr),
                desc=f"the rear tyres' reaction, along their axle through the ICR (6.132): "
                     f"μ₁ = {num(mu[0])} N")
    aim_label(pic.elements[-1], (0.0, -1.0), 9.0)
    force_arrow(pic, "R2mu", R2mu, scale=sc, anchor=0.5 * (icr + front), role="reaction",
                symbol="R₂μ₂", label=f"R₂μ₂ = {mu[1]:.0f} N (front)",
                label_xy=icr + 0.4 * (front - icr),
                desc=f"the front tyres' reaction, along their axle through the ICR (6.132): "
                     f"μ₂ = {num(mu[1])} N")
    aim_label(pic.elements[-1], (0.0, 1.0), 9.0)
    force_arrow(pic, "fA", fA, scale=sc, anchor=anchor_A, role="wrench", symbol="f_A",
                label="$f_A$", desc=f"the driving force on the front wheels (6.120): "
                                    f"{num(np.hypot(*fA[:2]))} N")
    aim_label(pic.elements[-1], (-1.0, 0.3), 10.0)
    pic.line("T", T, role="momentum", symbol="T", label="", arrow=False,
             desc="the axis of percussion of the ICR joint, T = I s (sᵀIs)⁻¹ (6.124)")
    label_at(pic, _on_line(T, lo[1] - 0.5), "T")
    aim_label(pic.elements[-1], (1.0, 0.0), 7.0)
    pic.point("a", qn["a"], role="accel", symbol="a",
              desc=f"the car's acceleration a = sω̇ (γ = 0, 6.129–6.131), its pole: "
                   f"ω̇ = {qn['omega_dot']:.3f} rad/s²")
    x0, x1, y0, y1 = pic.box
    pic.text("omega_dot", (x0, y1), f"ω̇ = {qn['omega_dot']:.3f} rad/s²", dx=4.0, dy=-4.0, va="top",
             symbol="ω̇", desc=f"the car's angular acceleration (6.131): {qn['omega_dot']:.4g} rad/s²")
    _show(pic, ax)
