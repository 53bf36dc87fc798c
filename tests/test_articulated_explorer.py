"""ArticulatedExplorer (thesis 7.1-7.3, 10.2.2, 10.2.3) against independent references.

References: the dense free-floating Schur complement of each body's outboard chain
(``dense_articulated``: Pinocchio / KKT) for ``A_k``, the same of the chain *cut* after the
included outboard bodies for the truncated recursion, the hand closed forms 7.20 and 7.27,
and for Play the energy balance ``T + V + W = E₀`` with ``W`` the dissipated energy.
"""
from __future__ import annotations

import math

import numpy as np
import pytest

from _picture_checks import elements, problems
from planargeo.mechanics.model import Model
from planargeo.scenes.articulated import bent_chain_model, inertia_at
from planargeo.widgets import ArticulatedExplorer
from test_articulated_reference import dense_articulated


def _legible(ex):
    """Shown; every element of the picture has its symbol and description; no two labels overlap."""
    assert ex.message == ""
    found = problems(ex.picture())
    assert found == [], found


def _segment(ex, id):
    (xy,) = [np.asarray(p["xy"], float) for p in elements(ex.picture())[id]["parts"] if p["p"] == "path"]
    return xy


def _reference_A(n, lam, phi_deg, base_deg, k, outboard=None):
    """A_k (0-based k) at the origin: dense Schur complement of the chain cut after the included bodies."""
    model = bent_chain_model(n, 1.0 / lam)
    last = n if outboard is None else min(n, k + outboard + 1)
    cut = Model(model.bodies[:last], model.joints[:last], list(model.parents[:last]), model.gravity)
    q = np.array([math.radians(base_deg)] + [math.radians(phi_deg)] * (last - 1))
    z = np.zeros(last)
    return dense_articulated(cut, q, z, z, None, k)[0]


def test_default_state_matches_the_dense_reference_and_is_legible():
    ex = ArticulatedExplorer(display="agg")
    _legible(ex)
    st = ex.state
    for k in range(4):
        ref = _reference_A(4, 3.0, 25.0, 0.0, k)
        np.testing.assert_allclose(st["A"][k], ref, atol=1e-10 * np.abs(ref).max())
        el = elements(ex.picture())[f"A{k + 1}"]
        assert el.get("dash")                                   # drawn through its real partner, dashed (10.2.3)
        # the drawn ellipse is centred on the effective centre A⁻¹ [0, 0, 1] (7.26)
        P = np.linalg.solve(ref, [0.0, 0.0, 1.0])
        (e,) = [p for p in el["parts"] if p["p"] == "ellipse"]
        np.testing.assert_allclose([e["x"], e["y"]], [-P[1] / P[2], P[0] / P[2]], atol=1e-5)
    Aj = inertia_at(_reference_A(4, 3.0, 25.0, 0.0, 0), (0.0, 0.0))
    assert ex.readout_values["Aₖ: inertia about joint k"] == pytest.approx(Aj[2, 2], rel=1e-10)


@pytest.mark.parametrize("phi_deg", [0.0, 40.0, 90.0, 135.0])
@pytest.mark.parametrize("lam", [0.8, 2.0, 5.0])
def test_thesis_7_2_effective_mass_7_20(phi_deg, lam):
    ex = ArticulatedExplorer(display="agg", **{"bodies n": 2, "λ = L/ρ": lam, "bend φ (deg)": phi_deg})
    L, rho, c = 1.0, 1.0 / lam, math.cos(math.radians(phi_deg))
    mx = (L**2 + 8 * rho**2 + L**2 * c**2) / (L**2 + 4 * rho**2)          # 7.20 with m = 1
    assert ex.readout_values["Aₖ: mass along x"] == pytest.approx(mx, rel=1e-12)
    _legible(ex)


@pytest.mark.parametrize("lam", [1.0, 2.0, 3.0])
def test_thesis_7_3_effective_centre_and_truncation(lam):
    ex = ArticulatedExplorer(display="agg", **{"bodies n": 5, "λ = L/ρ": lam, "bend φ (deg)": 0.0})
    full = ex.readout_values["effective centre d/L (7.27)"]
    ref = _reference_A(5, lam, 0.0, 0.0, 0)
    assert full == pytest.approx(ref[1, 2] / ref[1, 1], rel=1e-10)      # 7.26: d = c / m_y on the axis
    for k in range(4):
        ex.set(**{"outboard bodies": k})
        ref_k = _reference_A(5, lam, 0.0, 0.0, 0, outboard=k)
        np.testing.assert_allclose(ex.state["A"][0], ref_k, atol=1e-10 * np.abs(ref_k).max())
        err = np.linalg.norm(ref_k - ref) / np.linalg.norm(ref)
        assert ex.readout_values["truncation error of Aₖ"] == pytest.approx(err, rel=1e-8)
        assert ex.readout_values["outboard included"] == f"{k} of 4"
        if lam == 2.0:                                                    # 7.27: 2/3 from the first step on
            assert ex.readout_values["effective centre d/L (7.27)"] == pytest.approx(
                2 / 3 if k > 0 else 0.5, rel=1e-12)
        _legible(ex)


def test_percussion_axis_and_its_point_reflection():
    ex = ArticulatedExplorer(display="agg", **{"focus": "body 2", "pole x": 2.5, "pole y": -1.2})
    k = 1
    A = _reference_A(4, 3.0, 25.0, 0.0, k)
    a = np.array([-1.2, -2.5, 1.0])                                       # the pole (2.5, -1.2) as [y, -x, 1]
    axis = A @ a                                                           # the axis of percussion (5.64)
    for X in _segment(ex, "Aa"):                                           # drawn through it
        assert abs(axis[2] + X[1] * axis[0] - X[0] * axis[1]) < 1e-4 * np.abs(axis).max()
    # 10.2.3: the polar of a w.r.t. the drawn real conic is the axis reflected through the centre
    P = np.linalg.solve(A, [0.0, 0.0, 1.0])
    c = np.array([-P[1] / P[2], P[0] / P[2]])
    for Y in _segment(ex, "polar"):                  # every drawn point of the polar, reflected, is on the axis
        X = 2 * c - Y
        assert abs(axis[2] + X[1] * axis[0] - X[0] * axis[1]) < 1e-4 * np.abs(axis).max()
    _legible(ex)


def test_chart_components_and_error_per_step():
    ex = ArticulatedExplorer(display="agg", **{"bodies n": 6, "focus": "body 2"})
    errs = np.asarray(ex.state["error"][1])
    marks = [p for p in elements(ex.picture())["chart error"]["parts"] if p["p"] == "mark"]
    assert len(marks) == len(errs) and "(10.2.2)" in elements(ex.picture())["chart error"]["desc"]
    assert len(errs) == 5 and errs[-1] == 0.0 and np.all(np.diff(errs) < 0)
    full = _reference_A(6, 3.0, 25.0, 0.0, 1)
    for j, k in enumerate(range(5)):
        ref = _reference_A(6, 3.0, 25.0, 0.0, 1, outboard=k)
        assert errs[j] == pytest.approx(np.linalg.norm(ref - full) / np.linalg.norm(full), rel=1e-8, abs=1e-14)
    comps = np.asarray(ex.state["components"][1])
    for name in ("xx", "yy", "zz"):                 # each drawn curve ends at its full value: 1
        j = ("xx", "yy", "zz").index(name)
        assert comps[-1, j] / comps[-1, j] == 1.0 and elements(ex.picture())[f"chart {name}"]["desc"].endswith(", 1")
    _legible(ex)


def test_kept_chart_view_and_energies_follow_the_chain_while_the_pole_is_dragged():
    """The chart, the conics' boxes and the energies are kept while only the pole moves: after each
    change of the bend and drags of the pole the chart's errors are the dense reference's, every drawn
    articulated conic's centre is in view, and E₀ is the chain's potential energy at rest (m g Σ y_c)."""
    ex = ArticulatedExplorer(display="agg", **{"bodies n": 4})
    for phi in (25.0, 70.0, 25.0, -40.0):
        ex.set(**{"bend φ (deg)": phi})
        ex.drag("pole a", (0.0, -0.8), (0.3, -0.5), steps=2)
        full = _reference_A(4, 3.0, phi, 0.0, 0)
        want = [np.linalg.norm(_reference_A(4, 3.0, phi, 0.0, 0, outboard=k) - full) / np.linalg.norm(full)
                for k in range(4)]
        els = elements(ex.picture())
        shown = [float(v) for v in els["chart error"]["desc"].rsplit(": ", 1)[1].split(", ")]
        assert shown == pytest.approx(want, rel=5e-3, abs=1e-12)
        x0, x1, y0, y1 = ex.picture()["box"]
        for k in range(4):
            (e,) = [p for p in els[f"A{k + 1}"]["parts"] if p["p"] == "ellipse"]
            assert x0 < e["x"] < x1 and y0 < e["y"] < y1
        th = np.radians([0.0] + [phi * j for j in range(1, 4)])
        joints = np.concatenate([[0.0], np.cumsum(np.sin(th))])
        assert ex.readout_values["initial energy E₀"] == pytest.approx(
            9.81 * sum(joints[j] + 0.5 * math.sin(th[j]) for j in range(4)), rel=1e-9, abs=1e-9)


def test_drags_pole_tip_and_first_body():
    ex = ArticulatedExplorer(display="agg", **{"bodies n": 2})
    ex.drag("pole a", (0.0, -0.8), (1.2345, 0.6789), steps=3)
    assert (ex.values["pole x"], ex.values["pole y"]) == pytest.approx((1.2345, 0.6789), abs=1e-12)   # no grid snap
    ex.drag("tip", tuple(ex.state["joints"][-1]), (1.0, 1.0), steps=4)
    assert ex.values["bend φ (deg)"] == pytest.approx(90.0, abs=1e-6)
    ex.drag("first body", (1.0, 0.0), (0.0, 1.0), steps=4)
    assert ex.values["base θ₁ (deg)"] == pytest.approx(90.0, abs=1e-9)
    _legible(ex)
    ex.set(**{"focus": "body 2"})
    ex.set(**{"bodies n": 1})
    assert ex.values["focus"] == "all"                   # body 2 is gone: the focus falls back
    with pytest.raises(Exception, match="cannot be dragged"):
        ex.drag("tip", (1.0, 0.0), (0.0, 1.0))
    _legible(ex)


def test_play_swings_with_damping_and_keeps_the_energy_balance():
    ex = ArticulatedExplorer(display="agg", **{"bodies n": 3, "damping c": 0.5})
    ex.advance(12)
    r = ex.readout_values
    assert r["t"] == pytest.approx(12 * ex.play_dt)
    assert r["dissipated W"] > 1e-3
    scale = max(abs(r["initial energy E₀"]), 1.0)
    assert abs(r["T + V + W"] - r["initial energy E₀"]) < 1e-7 * scale
    _legible(ex)
    # the conics follow the motion: A_1 is the reference at the swung configuration
    q = ex.state["q"]
    model = bent_chain_model(3, 1 / 3.0)
    A_ref = dense_articulated(model, q, np.zeros(3), np.zeros(3), None, 0)[0]
    np.testing.assert_allclose(ex.state["A"][0], A_ref, atol=1e-10 * np.abs(A_ref).max())
    # without damping nothing is dissipated; a change of the chain restarts at t = 0
    ex.set(**{"damping c": 0.0})
    assert ex.values["time (s)"] == 0.0 and ex.readout_values["t"] == 0.0
    ex.advance(5)
    assert ex.readout_values["dissipated W"] == 0.0
    assert abs(ex.readout_values["T + V + W"] - ex.readout_values["initial energy E₀"]) < 1e-7 * scale


def test_refusals_and_exports(tmp_path):
    ex = ArticulatedExplorer(display="agg")
    shown = dict(ex.readout_values)
    ex.set(**{"bodies n": 0})
    assert "bodies n must be an integer between 1 and 8" in ex.message
    assert ex.readout_values == shown and ex.values["bodies n"] == 4
    n = ex.n_computes
    ex.set(**{"rigid inertias": False, "percussion axes": False})
    els = elements(ex.picture())
    assert ex.n_computes == n and "I1" not in els and "Aa" not in els and "A1" in els
    _legible(ex)
    assert ex.export_svg(tmp_path / "a.svg").stat().st_size > 1000
    assert ex.export_png(tmp_path / "a.png").stat().st_size > 1000


@pytest.mark.parametrize("seed", range(6))
def test_bend_for_tip_finds_the_nearest_tip_of_a_dense_search(seed):
    """The tip drag's bend against a brute-force search of its own: every 0.001° of φ, the tip
    summed link by link with math.cos/sin (the explorer measures a grid coarsely, then refines)."""
    from planargeo.widgets.articulated import bend_for_tip

    rng = np.random.default_rng(seed)
    for _ in range(4):
        n, L, base = int(rng.integers(2, 9)), float(rng.uniform(0.3, 2.0)), float(rng.uniform(-3, 3))
        r, a = rng.uniform(0.0, 1.2) * n * L, rng.uniform(-math.pi, math.pi)
        target = (r * math.cos(a), r * math.sin(a))

        def dist(phi):
            x = sum(L * math.cos(base + k * phi) for k in range(n))
            y = sum(L * math.sin(base + k * phi) for k in range(n))
            return math.hypot(x - target[0], y - target[1])

        phis = np.linspace(-math.pi, math.pi, 360001)
        k = np.arange(n)
        th = base + np.multiply.outer(phis, k)
        best = float(np.min(np.hypot(L * np.cos(th).sum(1) - target[0], L * np.sin(th).sum(1) - target[1])))
        phi = bend_for_tip(target, n, base, L)
        assert -math.pi <= phi <= math.pi
        # no φ of the dense search brings the tip nearer (to the grid's resolution: |tip'| ≤ L Σk)
        assert dist(phi) <= best + 1e-12 * (1 + best), (n, L, base, target, math.degrees(phi))


def test_bend_for_tip_refuses_a_target_that_is_not_one_finite_point():
    from planargeo.errors import NonFiniteError, ShapeError
    from planargeo.widgets.articulated import bend_for_tip

    with pytest.raises(NonFiniteError, match="xy"):
        bend_for_tip((float("nan"), 0.0), 3, 0.0)
    with pytest.raises(ShapeError, match="one point"):
        bend_for_tip([(1.0, 2.0), (3.0, 4.0)], 3, 0.0)
    # far beyond the chain's reach (distances overflow): still an angle in range, as the whole grid gives
    assert -math.pi <= bend_for_tip((1e308, 1e308), 3, 0.0) <= math.pi


def test_outboard_slider_follows_bodies_in_the_page():
    """n = 1, then n = 8 (as the page sends them): the outboard slider is enabled, spans 0..7 and reads 7
    ("all" outboard bodies of 8), in the kernel and in the page, whatever order the page applies an
    update's keys in (a value never travels beyond the range the page holds)."""
    from _page_slider import PageSlider

    ex = ArticulatedExplorer(display="agg")
    w = ex.controls["outboard bodies"]
    page = PageSlider(w)
    ex.controls["bodies n"].set_state({"value": 1})
    assert (w.value, w.max, w.disabled) == (0, 0, True)
    ex.controls["bodies n"].set_state({"value": 8})
    assert (w.value, w.max, w.disabled) == (7, 7, False)
    assert ex.readout_values["outboard included"] == "7 of 7"
    assert page.problems == []
    assert page.shown == {"value": 7, "min": 0, "max": 7, "disabled": False}
