"""SplittingExplorer (thesis 7.4-7.6, example 7.5) against an independent maximal-coordinates KKT solve.

The reference is written here from scratch: every body's acceleration (a twist at the origin)
and every pin's force ``λ_j`` (a force through the pin, reaction basis ``R_j = [[1, 0], [0, 1],
[-y_j, x_j]]``) from ``M a - Gᵀ λ = w``, ``G a = 0`` (at rest: no velocity terms), with the
couple ``-f_{n+1} = [0, 0, -τ]`` on the tip and gravity through each centre of mass.  The force
of joint ``j`` on body ``j`` is ``f_j = R_j λ_j`` (thesis 7.33).
"""
from __future__ import annotations

import math

import numpy as np
import pytest

from planargeo import scenes
from planargeo.draw.layout import legibility_problems
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
    """The chain with the couple ``-f_{n+1} = [0, 0, -tau]`` on the tip (7.44)."""
    loads = np.zeros((n, 3))
    loads[-1, 2] = -tau
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
    assert ex.message == ""
    assert legibility_problems(ex.fig) == []


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
    ex.set(**{"couple τ (N·m)": 0.0})
    assert "couple τ must be non-zero" in ex.message
    assert ex.values["couple τ (N·m)"] == 1.0 and ex.readout_values == shown
    ex.set(**{"bodies n": 1})
    assert "bodies n must be an integer between 2 and 8" in ex.message
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
    assert ex.n_computes == n and not ex.centre.get_visible()
    _legible(ex)
    assert ex.export_svg(tmp_path / "s.svg").stat().st_size > 1000
    assert ex.export_png(tmp_path / "s.png").stat().st_size > 1000
    assert not ex.has_play                                    # a single instant: nothing moves


def test_focus_fades_the_other_side():
    ex = SplittingExplorer(display="agg", **{"bodies n": 4, "split at joint": 3})
    n = ex.n_computes
    ex.set(focus="free-floating part")
    assert ex.message == ""
    assert ex.lower.get_alpha() < ex.upper.get_alpha()
    _legible(ex)
    ex.set(focus="constrained part")
    assert ex.lower.get_alpha() > ex.upper.get_alpha()
    _legible(ex)


def test_every_pole_is_shown_and_labelled_in_or_out_of_view():
    """A pole outside the view is a labelled arrow at the edge (issue 13), each with its symbol a_k."""
    from matplotlib.text import Text

    ex = SplittingExplorer(display="agg", **{"bodies n": 8, "split at joint": 6, "bend φ (deg)": 10.0})
    assert ex.message == ""
    (x0, x1), (y0, y1) = ex.ax.get_xlim(), ex.ax.get_ylim()
    off = [b for b, a in enumerate(ex.poles[:8])
           if a.get_xy() is None or not (x0 <= a.get_xy()[0] <= x1 and y0 <= a.get_xy()[1] <= y1)]
    assert off and all(ex.poles[b].get_visible() for b in range(8))
    assert not any(a.get_visible() for a in ex.poles[8:])
    ex.fig.canvas.draw()
    bb = ex.ax.get_window_extent()
    shown = {t.get_text(): t.get_window_extent() for t in ex.fig.findobj(Text)
             if t.get_visible() and t.get_text().startswith("$a_")}
    for b in range(8):                                    # every pole's symbol is drawn, inside the axes
        sym = f"$a_{{{b + 1}}}$"
        assert sym in shown, sym
        e = shown[sym]
        assert bb.x0 <= e.x0 and e.x1 <= bb.x1 and bb.y0 <= e.y0 and e.y1 <= bb.y1, sym
    _legible(ex)
