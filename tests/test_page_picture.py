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
from planargeo.errors import PlanargeoError
from planargeo.widgets import ChainExplorer

NAMES = list(pw.EXPLORERS)


@pytest.fixture(autouse=True)
def _answered_at_once(monkeypatch):
    """Replies at once, as with no kernel: an event loop a browser test left running in this process
    would otherwise hold them for a kernel's idle message (``PictureCanvas.defer``) that never comes."""
    from planargeo.widgets.canvas import PictureCanvas

    monkeypatch.setattr(PictureCanvas, "defer", False)


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
    {"type": "describe", "id": 5}, {"type": "describe", "id": "no such element"},
    {"type": "sync", "version": 1.5}, {"type": "sync", "version": True},
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
    ids = {i.removesuffix(":label") for i in re.findall(r'id="([^"]+)"', svg)}   # a text: "<id>:label"
    drawn = {e["id"] for e in pic["elements"] if e["parts"]}
    assert {"v1", "v4", "f1", "f4", "links"} <= drawn
    assert drawn <= ids, sorted(drawn - ids)[:5]


def test_the_chain_in_the_page_shows_the_numbers_of_the_explorer_without_a_front_end():
    """Native picture and readout: the page shows what the explorer computes with no front end."""
    kw = dict(links=5, angle=20.0, **{"velocity poles": True, "T/U split": True})
    page, agg = ChainExplorer(display="page", **kw), ChainExplorer(display="agg", **kw)
    for k, v in agg.readout_values.items():
        assert page.readout_values[k] == v, k
    assert page.canvas.picture == agg.picture()                    # one picture, whoever asks
    # every velocity pole of the picture sits at the pole of the state's twist (thesis 4.5):
    # (x, y) = (-vy / w, vx / w) by hand
    els = {e["id"]: e for e in page.canvas.picture["elements"]}
    for i, (vx, vy, w) in enumerate(page.state["w"].v):
        mark = next((p for p in els[f"v{i + 1}"]["parts"] if p["p"] == "mark"), None)
        if mark is None or w == 0.0:
            continue
        assert np.allclose([mark["x"], mark["y"]], [-vy / w, vx / w], atol=1e-4), (i, mark)


# ----------------------------------------------------------------- the page's update messages
OVERLAYS_ALL = ("velocity poles", "acceleration poles", "bias terms", "internal forces", "T/U split",
                "articulated inertias")


def _apply(held: dict, update: dict) -> dict:
    """What the page does with an update (canvas.js ``apply``), on the whole picture it holds."""
    if update.get("base") is None:
        held = {"head": {}, "order": [], "set": {}, "handles": [], "tips": {}}
    else:
        assert update["base"] == held["version"], "an update for another version"
    els = {k: dict(v) for k, v in held["set"].items()}
    for eid, fields in update.get("set", {}).items():
        el = els.setdefault(eid, {})
        for k, v in fields.items():
            if v is None:
                el.pop(k, None)
            else:
                el[k] = v
    order = update.get("order", held["order"])
    return {"version": update["version"], "head": update.get("head", held["head"]), "order": order,
            "set": {k: els[k] for k in order}, "handles": update.get("handles", held["handles"]),
            "tips": update.get("tips", held["tips"])}


def _fresh_snapshot(picture: dict) -> dict:
    """The whole picture as a canvas that never drew anything before sends it (the reference)."""
    from planargeo.widgets.canvas import PictureCanvas

    c = PictureCanvas()
    c.picture = picture
    snap = c._snapshot()
    return {k: snap[k] for k in ("head", "order", "set", "handles", "tips")}


def _acks(canvas) -> list:
    sent = []
    canvas.send = lambda m, *a, **k: sent.append(m)
    return sent


def test_keyed_updates_rebuild_the_whole_picture_and_stay_small():
    """Drag and slider updates carry what changed only; applied in order they give the whole picture."""
    ex = ChainExplorer(display="page", links=10, **{k: True for k in OVERLAYS_ALL})
    sent = _acks(ex.canvas)
    held = _apply({}, {**ex.canvas._snapshot(), "base": None})
    h = next(h for h in ex.canvas.picture["handles"] if h["id"] == "link 10 end")
    for k in range(6):
        ex.canvas._on_msg(None, {"type": "drag", "id": "link 10 end", "x": h["x"] + 0.05 * k, "y": h["y"],
                                 "seq": k, "client": "t"}, None)
    ex.controls["angle"].value = -20.0           # a slider: an update of its own, everything moves
    ex.set(**{"bias terms": False})              # elements leave the picture
    updates = [m.get("update") if m["type"] == "ack" else m for m in sent]
    assert [m["seq"] for m in sent if m["type"] == "ack"] == list(range(6))
    assert all(m["client"] == "t" and m["ok"] for m in sent if m["type"] == "ack")
    for u in updates:
        if u is not None:
            held = _apply(held, u)
    want = _fresh_snapshot(ex.canvas.picture)
    assert {k: held[k] for k in want} == want
    assert held["version"] == ex.canvas.version
    # a drag of the last link moves part of the picture: the rest is not sent again
    drag = next(u for u in updates if u is not None)
    assert 0 < len(drag["set"]) < len(want["order"]) and "head" not in drag
    # no descriptions on the wire; every update of the chain (all overlays) within 20 KB
    assert all(len(json.dumps(u)) <= 20 * 1024 for u in updates if u is not None)
    assert not any("desc" in el for el in held["set"].values())


def test_wire_coordinates_are_the_pictures_to_a_tenth_of_a_pixel():
    ex = ChainExplorer(display="page", links=6, **{k: True for k in OVERLAYS_ALL})
    pic, snap = ex.canvas.picture, ex.canvas._snapshot()
    (x0, x1, y0, y1), (w, hgt), (ml, mr, mt, mb) = pic["box"], pic["size"], pic["margin"]
    px = max((x1 - x0) / (w - ml - mr), (y1 - y0) / (hgt - mt - mb))     # data units per pixel
    for el in pic["elements"]:
        wire = snap["set"][el["id"]]
        marks = [p for p in el["parts"] if p["p"] == "mark"]
        wmarks = [q for q in wire["parts"] if q[0] == "M"]
        assert len(marks) == len(wmarks)
        for p, q in zip(marks, wmarks):
            assert abs(p["x"] - q[1]) <= 0.1 * px and abs(p["y"] - q[2]) <= 0.1 * px
        paths = [p for p in el["parts"] if p["p"] == "path"]
        wpaths = [q for q in wire["parts"] if q[0] == "P"]
        for p, q in zip(paths, wpaths):
            assert np.abs(np.asarray(p["xy"]).ravel() - np.asarray(q[2:])).max() <= 0.1 * px
        shown = [p for p in el["parts"] if p["p"] == "text" and not p.get("hidden")]
        assert [p["text"] for p in shown] == [q[5] for q in wire["parts"] if q[0] == "T"]


def test_descriptions_sync_and_ticks_in_the_acks():
    ex = ChainExplorer(display="page", links=3)
    c = ex.canvas
    sent = _acks(c)
    c._on_msg(None, {"type": "describe", "id": "v2", "seq": 1}, None)
    el = next(e for e in c.picture["elements"] if e["id"] == "v2")
    assert sent[-1]["ok"] and sent[-1]["desc"] == f"{el['symbol']} — {el['desc']}" and "(4.5)" in sent[-1]["desc"]
    c._on_msg(None, {"type": "describe", "id": "nothing", "seq": 2}, None)
    assert not sent[-1]["ok"] and "no element 'nothing'" in sent[-1]["message"]
    # a view at the current version gets no picture; an older one gets the whole picture
    c._on_msg(None, {"type": "sync", "version": c.version, "seq": 3}, None)
    assert "update" not in sent[-1]
    c._on_msg(None, {"type": "sync", "version": 0, "seq": 4}, None)
    full = sent[-1]["update"]
    assert full["base"] is None and full["version"] == c.version
    assert {k: full[k] for k in ("head", "order", "set", "handles", "tips")} == _fresh_snapshot(c.picture)
    c._on_msg(None, {"type": "sync", "version": "7", "seq": 5}, None)
    assert not sent[-1]["ok"] and "version must be an int" in sent[-1]["message"]
    # ticks: nothing while Play is off; a refusal is a message and changes nothing
    calls = []

    def tick():
        calls.append(1)
        raise PlanargeoError("the motion ends here")

    c.on_tick = tick
    before = json.dumps(c.picture)
    c._on_msg(None, {"type": "tick", "seq": 6}, None)
    assert sent[-1]["ok"] and calls == []
    c.playing = True
    c._on_msg(None, {"type": "tick", "seq": 7}, None)
    assert not sent[-1]["ok"] and sent[-1]["message"] == "the motion ends here" and calls == [1]
    assert json.dumps(c.picture) == before
