"""The minimal computations of ``benchmarks/scene_cost.py`` give the numbers their consumers read.

``scene_cost.py`` times, per scene and consumer, the scene as it runs against
the minimal computation that consumer needs.  A saving only counts if the
minimal path computes the same thing: these tests check agreement (bitwise
where the operations are the same, else to rounding), never timing.
"""
from __future__ import annotations

import importlib.util
import sys
from pathlib import Path

import numpy as np
import pytest

from planargeo import scenes
from planargeo.algorithms.loops import loop_solve
from planargeo.contacts import Contact
from planargeo.errors import SingularConfigurationError
from planargeo.model import Model, chain_model

_PATH = Path(__file__).resolve().parents[1] / "benchmarks" / "scene_cost.py"
_spec = importlib.util.spec_from_file_location("_scene_cost", _PATH)
sc = importlib.util.module_from_spec(_spec)
sys.modules["_scene_cost"] = sc          # dataclasses look their module up
_spec.loader.exec_module(sc)

CASES = sc.cases()


def _agree(a: dict, b: dict, exact: bool, rtol: float, label: str) -> None:
    assert set(a) == set(b), label
    for k in a:
        x, y = a[k], b[k]
        if isinstance(x, Model):
            assert x == y, (label, k)
        elif isinstance(x, dict):
            _agree(x, y, exact, rtol, f"{label}: {k}")
        else:
            x, y = np.asarray(x, dtype=float), np.asarray(y, dtype=float)
            assert x.shape == y.shape, (label, k)
            if exact:
                assert np.array_equal(x, y), (label, k)
            else:
                scale = float(np.max(np.abs(x), initial=0.0))
                np.testing.assert_allclose(y, x, rtol=0, atol=rtol * scale, err_msg=f"{label}: {k}")


@pytest.mark.parametrize("case", CASES, ids=lambda c: f"{c.scene}: {c.consumer}")
def test_minimal_path_gives_the_numbers_the_consumer_reads(case):
    full = case.read_full(case.full())
    minimal = case.read_minimal(case.minimal())
    _agree(full, minimal, case.exact, case.rtol, f"{case.scene}: {case.consumer}")


def test_explorer_compute_steps_agree():
    for case in sc.explorer_cases():
        full = case.read_full(case.full())
        minimal = case.read_minimal(case.minimal())
        _agree(full, minimal, case.exact, case.rtol, case.consumer)


def test_every_scene_has_a_case():
    covered = {c.scene for c in CASES}
    assert set(scenes.names()) <= covered, set(scenes.names()) - covered


@pytest.mark.parametrize("psi, drive", [(0.4, "free"), (0.4, "constant-speed"), (2.5, "free"), (-1.2, "constant-speed")])
def test_loop_solve_columns_matches_loop_solve_on_the_slider_crank(psi, drive):
    # every field the explorers and the report read, with and without the crank drive
    res = scenes.build("slider-crank", psi=psi, drive=drive)
    sol = res.extra["solution"]
    model = res.model
    q, qd = np.asarray(res.state["q"]), np.asarray(res.state["qd"])
    cols = sc.loop_solve_columns(model, q, qd, np.zeros(3), prescribed={0: 0.0} if drive == "constant-speed" else None)
    for k, ref in (("a", sol.a), ("qdd", sol.qdd), ("F", sol.F), ("xi", sol.xi), ("tau_drive", sol.tau_drive),
                   ("u", sol.u)):
        np.testing.assert_allclose(cols[k], ref, rtol=0, atol=1e-12 * max(1.0, np.abs(ref).max()), err_msg=k)
    assert cols["cond"] == pytest.approx(sol.cond, rel=1e-9)
    # the columns hold the report's Λ₃⁻¹ = G Λ⁻¹ Gᵀ (the slider acts on body 3)
    np.testing.assert_allclose(np.asarray(res.quantities["Lambda3_inv"]),
                               sol.Lambda_inv[6:9, 6:9], rtol=0, atol=1e-15)


def test_loop_solve_columns_on_a_four_bar_and_at_the_fold():
    # the parallelogram four-bar of loop_solve's docstring (φ̈ = -6/5 g cos φ), and the folded slider-crank,
    # where both refuse
    pin = Contact("pin", 2, -1, point_a=(1.0, 0.0), point_b=(1.0, 0.0))
    m = chain_model(3)
    m = Model(m.bodies, m.joints, m.parents, m.gravity, contacts=(pin,))
    q, qd = np.array([1.2, -1.2, 1.2 - np.pi]), np.array([1.0, -1.0, 1.0])
    cols = sc.loop_solve_columns(m, q, qd, np.zeros(3))
    assert abs(cols["qdd"][0] - (-6 / 5 * 9.81 * np.cos(1.2))) < 1e-12
    np.testing.assert_allclose(cols["qdd"], loop_solve(m, q, qd, np.zeros(3)).qdd, rtol=0, atol=1e-12)
    from planargeo.scenes.slider_crank import slider_crank_model, slider_crank_state

    r = 2.29
    model = slider_crank_model(l=r * (1 + 1e-11))
    q, qd = slider_crank_state(0.0, 20.0, r, r * (1 + 1e-11))
    for solve in (loop_solve, sc.loop_solve_columns):
        with pytest.raises(SingularConfigurationError):
            solve(model, q, qd, np.zeros(3))


def test_cached_models_are_the_scenes_models():
    assert sc._sc_model(0.40, 0.15, 0.30, 2.29, 5.0, 0.5, 9.81) == scenes.build("slider-crank").model
    assert sc._tree_model(1.0, 1.0, 9.81) == scenes.build("tree").model
    model, q, unit = sc._constrained_setup(1.0, 1.0, 9.81)
    res = scenes.build("constrained-tree", speed=2.0)
    assert model == res.model
    np.testing.assert_allclose(2.0 * unit, res.state["qd"], rtol=0, atol=1e-14)


def test_report_writer_formats_every_case(tmp_path):
    # the Markdown writer on made-up timings (no measuring here)
    labels = [(c.group, c.scene, c.consumer, c.skipped) for c in CASES] + list(sc.EXPLORER_LABELS)
    rows = [{"group": g, "scene": s, "consumer": c, "skipped": k, "full_us": 100.0, "minimal_us": 50.0,
             "saved_us": 50.0, "ratio": {"best": 0.5, "median": 0.55}} for g, s, c, k in labels]
    res = {"cases": rows, "meta": {"date": "today", "python": "3", "runtime_s": 1.0, "quick": True, "rounds": 2},
           "updates": [{"explorer": "chain", "on_ms": 80.0, "off_ms": 40.0, "ratio": {"best": 0.5, "median": 0.5}},
                       {"explorer": "car", "update_ms": 34.0, "draw_ms": 30.0}]}
    res["notes"] = sc._notes(res)
    sc.write_markdown(res, tmp_path / "scene_cost.md")
    text = (tmp_path / "scene_cost.md").read_text()
    for c in CASES:
        assert c.consumer in text
    assert "## Reading the numbers" in text and "0.55" in text
