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
from planargeo.mechanics.model import Model

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


def test_cached_models_are_the_scenes_models():
    assert sc._two_body_model(1.0, 0.5, 1.0) == scenes.build("two-body", rho=0.5).model


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
