"""SplittingExplorer (thesis 7.4-7.6, example 7.5) against an independent maximal-coordinates KKT solve.

The reference is written here from scratch: every body's acceleration (a twist at the origin)
and every pin's force ``λ_j`` (a force through the pin, reaction basis ``R_j = [[1, 0], [0, 1],
[-y_j, x_j]]``) from ``M a - Gᵀ λ = w``, ``G a = 0`` (at rest: no velocity terms), with the
couple ``τ`` of the slider on the tip (counter-clockwise positive: ``-f_{n+1} = [0, 0, τ]``, 7.44) and gravity through each centre of mass.  The force
of joint ``j`` on body ``j`` is ``f_j = R_j λ_j`` (thesis 7.33).
"""
from __future__ import annotations

import math

import numpy as np
import pytest

from planargeo import scenes
from _picture_checks import elements, label_boxes, problems
from planargeo.errors import InputError, SceneError
from planargeo.widgets import SplittingExplorer
from planargeo.widgets.splitting import x_over_L_7_48


def kkt_solve(n, rho, phi, loads, g=0.0, L=1.0, m=1.0):
    """(a (n, 3), f (n, 3)): body accelerations and joint forces of the pinned bent chain at rest.

    ``loads`` (n, 3): world wrenches at the origin applied to the bodies (besides gravity).
    """
    th = np.cumsum([0.0] + [phi] * (n - 1))
    joints = np.vstack([[0.0, 0.0], np.cumsum(L * np.column_stack([np.cos(th), np.sin(th)]), axis=0)])
    M = np.zeros((3 * n, 3 * n))
    w = np.asarray(loads, dtype=float).reshape(3 * n).copy()
    for b in range(n):
        c = 0.5 * (joints[b] + joints[b + 1])                 # centre of mass half-way
        J = m * rho * rho + m * (c @ c)
        M[3 * b:3 * b + 3, 3 * b:3 * b + 3] = [[m, 0, -m * c[1]], [0, m, m * c[0]], [-m * c[1], m * c[0], J]]
        w[3 * b:3 * b + 3] += [0.0, -m * g, -m * g * c[0]]   # weight (0, -mg) through c: τ = x fy - y fx
    G = np.zeros((2 * n, 3 * n))
    Rs = []
    for j in range(n):                                        # pin j between body j-1 (or ground) and j
        x, y = joints[j]
        R = np.array([[1.0, 0.0], [0.0, 1.0], [-y, x]])
        Rs.append(R)
        G[2 * j:2 * j + 2, 3 * j:3 * j + 3] = R.T
        if j > 0:
            G[2 * j:2 * j + 2, 3 * (j - 1):3 * j] = -R.T
    K = np.block([[M, -G.T], [G, np.zeros((2 * n, 2 * n))]])
    sol = np.linalg.solve(K, np.concatenate([w, np.zeros(2 * n)]))
    lam = sol[3 * n:].reshape(n, 2)
    return sol[:3 * n].reshape(n, 3), np.array([R @ l for R, l in zip(Rs, lam)])


def kkt_pinned_chain(n, rho, phi, tau, g=0.0):
    """The chain with the couple ``tau`` (counter-clockwise) on the tip: ``-f_{n+1} = [0, 0, tau]`` (7.44)."""
    loads = np.zeros((n, 3))
    loads[-1, 2] = tau
    return kkt_solve(n, rho, phi, loads, g)


def kkt_mobility(n, rho, phi):
    """``Λ_n⁻¹`` of the tip: ``a_n = -Λ_n⁻¹ f`` for a wrench ``-f`` on it (7.28, 7.45), column by column."""
    cols = []
    for k in range(3):
        loads = np.zeros((n, 3))
        loads[-1, k] = -1.0
        cols.append(-kkt_solve(n, rho, phi, loads)[0][-1])
    return np.column_stack(cols)


def _legible(ex):
    """Shown; every element of the picture has its symbol and description; no two labels overlap."""
    assert ex.message == ""
    found = problems(ex.picture())
    assert found == [], found


def test_thesis_example_7_5_in_the_readout():
    ex = SplittingExplorer(display="agg")                     # n = 2, rho = L/2, phi = 45°, tau = 1
    r = ex.readout_values
    a_ref, f_ref = kkt_pinned_chain(2, 0.5, math.pi / 4, 1.0)
    np.testing.assert_allclose(r["aₙ (tip)"], a_ref[1], atol=1e-12)                 # 7.46
    x = -a_ref[1][1] / a_ref[1][2]
    assert r["x/L of aₙ's pole (7.48)"] == pytest.approx(x, rel=1e-12)             # 7.47-7.48
    assert r["x/L closed form"] == pytest.approx(x, rel=1e-12)
    assert x == pytest.approx(1.2357022603955, rel=1e-12)      # errata: 1.613 with 7.38a as printed
    np.testing.assert_allclose(r["fᵢ₊₁ (7.56)"], f_ref[1], atol=1e-12)
    np.testing.assert_allclose(r["aᵢ (7.54)"], a_ref[0], atol=1e-12)
    # 7.42: Lambda_1^-1 = diag(0, 0, 4 / (m (L^2 + 4 rho^2)))
    np.testing.assert_allclose(np.array([r["row 1 of Λᵢ⁻¹"], r["row 2 of Λᵢ⁻¹"], r["row 3 of Λᵢ⁻¹"]]),
                               np.diag([0.0, 0.0, 2.0]), atol=1e-12)
    _legible(ex)


@pytest.mark.parametrize("phi_deg", [0.0, 30.0, 90.0, 150.0, -120.0])
@pytest.mark.parametrize("rho", [0.2, 0.5, 1.3])
def test_thesis_7_43_mobility_of_body_2_against_kkt(phi_deg, rho):
    r = scenes.build("splitting", rho=rho, phi=math.radians(phi_deg))
    Lam2 = np.array(r.quantities["Lambda2_inv"])
    ref = kkt_mobility(2, rho, math.radians(phi_deg))
    np.testing.assert_allclose(Lam2, ref, atol=1e-11 * np.abs(ref).max())
    assert r.quantities["x_over_L"] == pytest.approx(x_over_L_7_48(rho, 1.0, math.radians(phi_deg)), rel=1e-11)


@pytest.mark.parametrize("n, split, g, tau", [(3, 1, 0.0, 1.0), (3, 2, 9.81, -2.0), (5, 3, 9.81, 0.5),
                                              (8, 7, 0.0, 1.0), (6, 2, 3.0, 0.0)])
def test_split_accelerations_and_force_against_kkt(n, split, g, tau):
    ex = SplittingExplorer(display="agg")
    ex.set(**{"bodies n": n, "split at joint": split + 1, "g (m/s²)": g, "couple τ (N·m)": tau,
              "bend φ (deg)": 35.0, "ρ (m)": 0.4})
    a_ref, f_ref = kkt_pinned_chain(n, 0.4, math.radians(35.0), tau, g)
    r = ex.readout_values
    scale = 1 + np.abs(a_ref).max()
    np.testing.assert_allclose(r["aᵢ (7.54)"], a_ref[split - 1], atol=1e-10 * scale)   # below the split
    np.testing.assert_allclose(r["aᵢ₊₁"], a_ref[split], atol=1e-10 * scale)            # above it
    np.testing.assert_allclose(r["fᵢ₊₁ (7.56)"], f_ref[split], atol=1e-10 * (1 + np.abs(f_ref).max()))
    np.testing.assert_allclose(ex.state["a"], a_ref, atol=1e-10 * scale)
    assert "x/L of aₙ's pole (7.48)" not in r
    _legible(ex)


def test_drag_split_marker_and_tip():
    ex = SplittingExplorer(display="agg", **{"bodies n": 5})
    j4 = ex.state["joints"][3]
    ex.drag("split", ex.state["joints"][1], tuple(j4 + 0.05), steps=4)
    assert ex.values["split at joint"] == 4 and ex.message == ""
    _legible(ex)
    ex.set(**{"bodies n": 2})
    assert ex.values["split at joint"] == 2                    # followed the shorter chain
    ex.drag("tip", ex.state["joints"][-1], (1.0, 1.0), steps=5)
    assert ex.values["bend φ (deg)"] == pytest.approx(90.0, abs=1e-6)   # not snapped to the 0.5° grid
    assert ex.readout_values["x/L closed form"] == pytest.approx(1.0)   # phi = 90°: the joint of body 2
    _legible(ex)


def test_bad_input_keeps_the_last_good_state():
    ex = SplittingExplorer(display="agg")
    shown = dict(ex.readout_values)
    ex.set(**{"bodies n": 1})
    assert "bodies n must be an integer between 2 and 8" in ex.message
    assert ex.values["bodies n"] == 2 and ex.readout_values == shown
    with pytest.raises(SceneError, match="split must be between 1 and n - 1"):
        scenes.build("splitting", n=3, split=3)
    with pytest.raises(SceneError, match="n must be at least 2"):
        scenes.build("splitting", n=1)
    with pytest.raises(InputError):
        ex.drag("nothing", (0, 0), (1, 1))


def test_display_control_and_exports(tmp_path):
    ex = SplittingExplorer(display="agg")
    n = ex.n_computes
    ex.set(**{"mobility centres": False})
    assert ex.n_computes == n and "centre" not in elements(ex.picture())
    _legible(ex)
    assert ex.export_svg(tmp_path / "s.svg").stat().st_size > 1000
    assert ex.export_png(tmp_path / "s.png").stat().st_size > 1000
    assert not ex.has_play                                    # a single instant: nothing moves


def test_focus_fades_the_other_side():
    ex = SplittingExplorer(display="agg", **{"bodies n": 4, "split at joint": 3})
    n = ex.n_computes
    ex.set(focus="free-floating part")
    assert ex.message == ""
    els = elements(ex.picture())
    assert els["lower"]["opacity"] < els["upper"]["opacity"]
    assert els["a1"].get("opacity", 1.0) < 1.0 and els["a4"].get("opacity", 1.0) == 1.0
    _legible(ex)
    ex.set(focus="constrained part")
    els = elements(ex.picture())
    assert els["lower"]["opacity"] > els["upper"]["opacity"]
    _legible(ex)


def test_every_pole_is_shown_and_labelled_in_or_out_of_view():
    """A pole outside the view is a labelled arrow at the edge (issue 13), each with its symbol a_k."""
    ex = SplittingExplorer(display="agg", **{"bodies n": 8, "split at joint": 6, "bend φ (deg)": 10.0})
    assert ex.message == ""
    pic = ex.picture()
    els = elements(pic)
    assert [f"a{b + 1}" in els for b in range(8)] == [True] * 8 and "a9" not in els
    off = [b for b in range(8) if not any(p["p"] == "mark" for p in els[f"a{b + 1}"]["parts"])]
    assert off and all(any(p["p"] == "arrow" for p in els[f"a{b + 1}"]["parts"]) for b in off)
    w, h = pic["size"]
    ml, mr, mt, mb = pic["margin"]
    shown = {text: box for _id, text, box in label_boxes(pic)}
    for b in range(8):                                    # every pole's symbol is drawn, inside the plot area
        sym = f"a{str(b + 1).translate(str.maketrans('0123456789', '₀₁₂₃₄₅₆₇₈₉'))}"
        (text,) = [t for t in shown if t == sym or t.startswith(sym + " ")]
        x0, y0, x1, y1 = shown[text]
        assert -0.5 <= x0 and x1 <= w - ml - mr + 0.5 and -0.5 <= y0 and y1 <= h - mt - mb + 0.5, text
    _legible(ex)


def test_hover_texts_count_bodies_and_pins_in_good_english():
    """One pin is "a pin", one body is "body k, of 1 kg"; several are counted, "1 kg each"."""
    def descs(ex):
        return {e["id"]: e["desc"] for e in ex.picture()["elements"]}

    ex = SplittingExplorer(display="agg", **{"bodies n": 2, "split at joint": 2})
    d = descs(ex)
    assert d["pins"] == "the joint between the two bodies: a pin L = 1 m from the ground"
    assert d["lower"].endswith("body 1, of 1 kg") and d["upper"].endswith("body 2, of 1 kg")
    ex.set(**{"bodies n": 5, "split at joint": 3})
    d = descs(ex)
    assert d["pins"] == "the joints between the bodies: 4 pins, L = 1 m apart"
    assert d["lower"].endswith("bodies 1…2, of 1 kg each") and d["upper"].endswith("bodies 3…5, of 1 kg each")
    assert not any(" 1 pins" in t or "1 kg each" in t and "bodies" not in t for t in d.values())


def lagrange_qdd_at_rest(n, rho, phi, tau, g=0.0, L=1.0, m=1.0):
    """Joint accelerations of the pinned bent chain at rest from Lagrange's equations ``H q̈ = Q``.

    At rest the velocity terms vanish.  ``H = Σ m J_cᵀ J_c + m ρ² J_θᵀ J_θ`` from the Jacobians of each
    centre of mass and each body angle in the relative joint angles; ``Q`` is the virtual work of the
    couple ``τ`` on the tip (``τ ∂θ_n/∂q``) and of gravity (``-m g ∂y_c/∂q``).
    """
    q = np.array([0.0] + [phi] * (n - 1))
    th = np.cumsum(q)
    H, Q = np.zeros((n, n)), np.zeros(n)
    for b in range(n):
        Jth = np.array([1.0 if k <= b else 0.0 for k in range(n)])     # θ_b = q_1 + ... + q_b
        Jc = np.zeros((2, n))
        for k in range(n):                     # d c_b / d q_k: the part of the chain beyond joint k turns
            for j in range(k, b + 1):
                r = L if j < b else L / 2
                Jc[:, k] += r * np.array([-np.sin(th[j]), np.cos(th[j])])
        H += m * Jc.T @ Jc + m * rho * rho * np.outer(Jth, Jth)
        Q += -m * g * Jc[1]
        if b == n - 1:
            Q += tau * Jth
    return np.linalg.solve(H, Q)


def test_lagrange_two_links_closed_form_by_sympy():
    """Issue: "couple τ on the tip 1.00" applied −1 N·m.  Lagrange's equations of two links, derived with sympy
    (``T`` of both bodies, ``Q = τ ∂θ₂/∂q``), at rest: ``H q̈ = (τ, τ)`` with
    ``H = m/4 [[6L² + 4L² cos q₂ + 8ρ², L²(1 + 2 cos q₂) + 4ρ²], [same, L² + 4ρ²]]``.
    For m = 1, L = 1, ρ = 0.5, φ = 45°, τ = +1 N·m: q̈ = (−0.5657, +2.9657) rad/s² (sympy: -0.565685424949238,
    2.96568542494924)."""
    c = math.cos(math.pi / 4)
    H = np.array([[6 + 4 * c + 2, 1 + 2 * c + 1], [1 + 2 * c + 1, 1 + 1]]) / 4
    ref = np.linalg.solve(H, [1.0, 1.0])
    np.testing.assert_allclose(ref, [-0.565685424949238, 2.96568542494924], atol=1e-12)
    np.testing.assert_allclose(lagrange_qdd_at_rest(2, 0.5, math.pi / 4, 1.0), ref, atol=1e-12)
    ex = SplittingExplorer(display="agg")
    assert ex.values["couple τ (N·m)"] == 1.0
    np.testing.assert_allclose(ex.readout_values["q̈ (6.110)"], ref, atol=1e-12)
    assert ex.readout_values["aₙ (tip)"][2] == pytest.approx(sum(ref), abs=1e-12)   # body 2 turns at q̈₁ + q̈₂ > 0
    desc = {e["id"]: e["desc"] for e in ex.picture()["elements"]}
    assert desc["couple"].endswith(": 1 N·m (counter-clockwise)"), desc["couple"]


@pytest.mark.parametrize("n, tau, g, phi_deg", [(2, -2.5, 0.0, 120.0), (3, 1.0, 0.0, 35.0), (5, -0.5, 9.81, -60.0),
                                                 (8, 3.0, 2.0, 20.0)])
def test_slider_couple_is_the_couple_on_the_tip_by_lagrange(n, tau, g, phi_deg):
    ex = SplittingExplorer(display="agg", **{"bodies n": n, "couple τ (N·m)": tau, "g (m/s²)": g,
                                            "bend φ (deg)": phi_deg, "ρ (m)": 0.5})
    assert ex.message == ""
    ref = lagrange_qdd_at_rest(n, 0.5, math.radians(phi_deg), tau, g)
    np.testing.assert_allclose(ex.readout_values["q̈ (6.110)"], ref, atol=1e-10 * (1 + np.abs(ref).max()))


def test_no_couple_is_an_ordinary_state_drawn_at_rest():
    """τ = 0 with g = 0: nothing moves, every pole is "none", the mobilities and their centre are still shown;
    a keyboard user steps from +0.05 through 0 to −0.05."""
    ex = SplittingExplorer(display="agg")
    lam = ex.readout_values["row 3 of Λᵢ⁻¹"]
    for tau in (0.05, 0.0, -0.05):
        ex.set(**{"couple τ (N·m)": tau})
        assert ex.message == "" and ex.values["couple τ (N·m)"] == tau
    ex.set(**{"couple τ (N·m)": 0.0})
    r = ex.readout_values
    assert r["q̈ (6.110)"] == (0.0, 0.0) and r["fᵢ₊₁ (7.56)"] == (0.0, 0.0, 0.0)
    assert r["pole of aᵢ"] == r["pole of aᵢ₊₁"] == "none: no acceleration"
    assert "x/L of aₙ's pole (7.48)" not in r and r["x/L closed form"] == pytest.approx(1.2357022603955)
    assert r["row 3 of Λᵢ⁻¹"] == lam                                   # the mobility does not depend on the load
    els = elements(ex.picture())
    assert "centre" in els and "a1" in els and "a2" in els
    assert "no couple" in els["couple"]["desc"]
    (note,) = [q["text"] for q in els["at rest"]["parts"] if q["p"] == "text"]
    assert note == "no load: the chain stays at rest"
    ex.set(**{"couple τ (N·m)": 0.05})
    assert "at rest" not in elements(ex.picture())
    _legible(ex)


def test_the_couple_slider_steps_through_zero_like_a_keyboard():
    """Issue: ArrowLeft from +0.05 snapped back to 0.05 (τ = 0 was refused without gravity).  The slider's
    own steps, as the page sends them, from +0.10 to −0.10: each is kept, q̈ is linear in τ (Lagrange)."""
    ex = SplittingExplorer(display="agg")
    w = ex.controls["couple τ (N·m)"]
    ex.set(**{"couple τ (N·m)": 0.1})
    unit = lagrange_qdd_at_rest(2, 0.5, math.pi / 4, 1.0)
    for k in range(4):
        w.value = round(w.value - w.step, 10)          # one ArrowLeft
        assert ex.message == "" and w.value == ex.values["couple τ (N·m)"]
        np.testing.assert_allclose(ex.readout_values["q̈ (6.110)"], w.value * unit, atol=1e-12)
    assert w.value == pytest.approx(-0.1)
