"""Explorers drawn in the page (``display="page"``): the picture data and the messages from the page.

No browser here: the picture each explorer sends, and what the kernel does with every
kind of message the page may send (the browser tests drive the same path with real
mouse events).
"""
from __future__ import annotations

import json
import math
import re
from pathlib import Path

import numpy as np
import pytest

import planargeo.widgets as pw
from planargeo.widgets import ChainExplorer

NAMES = list(pw.EXPLORERS)


@pytest.fixture(scope="module")
def explorers():
    return {n: getattr(pw, n)(display="page") for n in NAMES}


@pytest.mark.parametrize("name", NAMES)
def test_picture_is_plain_json_with_stable_ids(explorers, name):
    ex = explorers[name]
    pic = ex.canvas.picture
    text = json.dumps(pic, allow_nan=False)          # no NaN or inf can reach the page
    assert json.loads(text) == pic
    ids = [e["id"] for e in pic["elements"]]
    assert len(ids) == len(set(ids)) and ids
    assert [e["id"] for e in ex.picture()["elements"]] == ids    # the same state: the same elements
    for h in pic["handles"]:
        assert math.isfinite(h["x"]) and math.isfinite(h["y"])


BAD = [
    "not a dict", 3, None, {"type": 7}, {"type": "explode"},
    {"type": "drag", "id": "no such handle", "x": 0.0, "y": 0.0},
    {"type": "drag", "id": None, "x": 0.0, "y": 0.0},
    {"type": "drag", "x": float("nan"), "y": 0.0}, {"type": "drag", "x": 1e308, "y": 0.0},
    {"type": "drag", "x": "1", "y": 0.0}, {"type": "drag", "x": True, "y": 0.0},
    {"type": "view", "box": [0, 1, 0]}, {"type": "view", "box": [1, 0, 0, 1]},
    {"type": "view", "box": [0, float("inf"), 0, 1]}, {"type": "view", "box": "all"},
]


@pytest.mark.parametrize("name", NAMES)
def test_bad_messages_are_refused_and_change_nothing(explorers, name):
    ex = explorers[name]
    handles = [h["id"] for h in ex.canvas.picture["handles"]]
    before_values, before_readout = dict(ex.values), dict(ex.readout_values)
    before_pic = json.dumps(ex.canvas.picture)
    for msg in BAD:
        if isinstance(msg, dict) and msg.get("type") == "drag" and "id" not in msg:
            if not handles:
                continue
            msg = {**msg, "id": handles[0]}
        ok, why = ex.canvas.handle_message(msg)
        assert not ok and why, (msg, why)
    assert ex.values == before_values and ex.readout_values == before_readout
    assert json.dumps(ex.canvas.picture) == before_pic


def test_a_flood_of_moves_leaves_one_consistent_state():
    ex = ChainExplorer(display="page", links=3)
    h = next(h for h in ex.canvas.picture["handles"] if h["id"] == "link 3 end")
    for k in range(200):
        ex.canvas.handle_message({"type": "drag", "id": "link 3 end", "x": h["x"] + 1e-3 * k,
                                  "y": h["y"], "seq": k})
    fresh = ChainExplorer(display="agg", **{k: v for k, v in ex.values.items()})
    for k, v in fresh.readout_values.items():
        if isinstance(v, float):
            assert ex.readout_values[k] == pytest.approx(v, rel=1e-9, abs=1e-12), k


def test_the_chain_export_is_its_page_picture(tmp_path):
    """The native chain: the SVG export is the page's picture drawn by matplotlib (the same elements)."""
    ex = ChainExplorer(display="page", links=4, **{"velocity poles": True, "internal forces": True})
    assert ex.native_page
    pic = ex.canvas.picture
    svg = Path(ex.export_svg(tmp_path / "chain.svg")).read_text()
    ids = set(re.findall(r'id="([^"]+)"', svg))
    drawn = {e["id"] for e in pic["elements"] if e["parts"]}
    assert {"v1", "v4", "f1", "f4", "links"} <= drawn
    assert drawn <= ids, sorted(drawn - ids)[:5]


def test_the_chain_in_the_page_shows_the_numbers_of_the_artist_path():
    """Native picture and readout: the same numbers as the explorer drawn by matplotlib artists."""
    kw = dict(links=5, angle=20.0, **{"velocity poles": True, "T/U split": True})
    page, agg = ChainExplorer(display="page", **kw), ChainExplorer(display="agg", **kw)
    for k, v in agg.readout_values.items():
        assert page.readout_values[k] == v, k
    # every velocity pole of the picture sits at the pole the artists hold (thesis 4.5)
    els = {e["id"]: e for e in page.canvas.picture["elements"]}
    for i, art in enumerate(agg.v_art[:5]):
        xy = art.get_xy()
        mark = next((p for p in els[f"v{i + 1}"]["parts"] if p["p"] == "mark"), None)
        if xy is None or mark is None:
            continue
        assert np.allclose([mark["x"], mark["y"]], xy, atol=1e-4 * 10), (i, mark, xy)
