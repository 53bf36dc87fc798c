"""While the page drags a handle, the controls', readout's and message's syncs wait (the picture
goes with every step); at the drag's release, or a refused step, every held value goes at once,
after the picture, and controls, readout and picture agree.

No browser: the drag and release messages arrive as the page sends them (``PictureCanvas._on_msg``
without an event loop: answered at once, through the explorer's hold); what leaves is caught (the
canvas's ``send``, each widget's ``_send``, the ipywidgets method every sync goes through).
"""
from __future__ import annotations

import json

import pytest

from planargeo.errors import SceneError
from planargeo.widgets import ChainExplorer

from _dot import Dot


def _watched(ex):
    """``ex`` and the log of what leaves it, in order: ("picture", version) and (widget, value)."""
    log = []

    def canvas_send(m, *a, **k):
        if m.get("type") == "update" or m.get("update"):
            log.append(("picture", ex.canvas.version))
        elif m.get("type") == "ack":
            log.append(("ack", m.get("ok")))

    ex.canvas.send = canvas_send

    def recorder(name):
        return lambda msg, buffers=None: log.append((name, msg["state"].get("value")))

    for k, w in ex.controls.items():
        w._send = recorder(k)
    ex.readout._send = recorder("readout")
    ex.message_box._send = recorder("message")
    return log


def _drag(ex, hid, x, y, seq):
    ex.canvas._on_msg(None, {"type": "drag", "id": hid, "x": x, "y": y, "seq": seq}, None)


def _release(ex, hid, seq):
    ex.canvas._on_msg(None, {"type": "release", "id": hid, "seq": seq}, None)


def _shows_as_a_fresh(ex, cls):
    """``ex`` shows what a fresh ``cls`` of its values shows: the same readout and picture."""
    fresh = cls(display="page", **ex.values)
    assert fresh.readout.value == ex.readout.value
    assert json.dumps(fresh.canvas.picture, sort_keys=True, default=str) == \
        json.dumps(ex.canvas.picture, sort_keys=True, default=str)


def _names(log):
    return [kind for kind, _v in log]


def test_a_drag_holds_the_syncs_and_its_release_sends_them_after_the_picture():
    ex = Dot(display="page")
    ex.drag_sync_s = 3600.0              # no periodic sync within this test: only the release's
    log = _watched(ex)
    for k in range(1, 6):
        _drag(ex, "dot", 0.2 * k, 0.1 * k, k)
    assert _names(log).count("picture") == 5                  # a picture with every step
    assert not {"x", "y", "readout", "message"} & set(_names(log))   # nothing else yet
    assert ex.values["x"] == pytest.approx(1.0) and ex.readout_values["x"] == pytest.approx(1.0)
    del log[:]
    _release(ex, "dot", 6)
    names = _names(log)
    assert names[0] in ("picture", "ack")                      # the reply first, then the syncs
    assert names.index("readout") > 0 and names.index("x") > 0 and names.index("y") > 0
    sent = {kind: v for kind, v in log}
    assert sent["x"] == ex.values["x"] == pytest.approx(1.0)
    assert sent["y"] == ex.values["y"] == pytest.approx(0.5)
    assert sent["readout"] == ex.readout.value
    _shows_as_a_fresh(ex, Dot)                                 # what a fresh explorer shows


def test_with_drag_sync_zero_every_step_sends_its_syncs():
    ex = Dot(display="page")
    ex.drag_sync_s = 0.0
    log = _watched(ex)
    for k in range(1, 4):
        _drag(ex, "dot", 0.2 * k, 0.0, k)
    assert _names(log).count("readout") == 3 and _names(log).count("x") == 3
    assert [v for kind, v in log if kind == "x"] == pytest.approx([0.2, 0.4, 0.6])


def test_a_refused_step_sends_the_reverted_controls_message_and_readout_at_once():
    ex = Dot(display="page")
    ex.drag_sync_s = 3600.0
    log = _watched(ex)
    _drag(ex, "dot", 0.8, 0.3, 1)
    _drag(ex, "dot", 1.2, 0.4, 2)
    assert not {"x", "readout", "message"} & set(_names(log))
    del log[:]
    _drag(ex, "dot", 1.8, 0.5, 3)                              # x > 1.5: refused
    assert "x must not exceed 1.5" in ex.message
    sent = {}
    for kind, v in log:
        sent[kind] = v
    # the page is told at once: the controls back on the last computed state, which the
    # readout shows, and why
    assert sent["x"] == ex.values["x"] == pytest.approx(1.2)
    assert sent["y"] == ex.values["y"] == pytest.approx(0.4)
    assert "x must not exceed 1.5" in sent["message"]
    assert sent["readout"] == ex.readout.value and ex.readout_values["x"] == pytest.approx(1.2)
    assert ex.values == ex.shown_values


def test_a_chain_dragged_in_the_page_agrees_with_a_fresh_chain_after_its_release():
    ex = ChainExplorer(display="page", links=4)
    ex.drag_sync_s = 3600.0
    log = _watched(ex)
    h = next(h for h in ex.canvas.picture["handles"] if h["id"] == "link 4 end")
    for k in range(1, 8):
        _drag(ex, "link 4 end", h["x"] + 0.03 * k, h["y"] - 0.02 * k, k)
    assert "readout" not in _names(log)
    _release(ex, "link 4 end", 8)
    last = {kind: v for kind, v in log}
    assert last["readout"] == ex.readout.value
    for k, w in ex.controls.items():           # every control the drag moved: its value sent
        if k in last:
            assert last[k] == w.get_state()["value"]
    moved = [k for k in ex.controls if ex.values[k] != ChainExplorer(display="agg", links=4).values[k]]
    assert moved and all(k in last for k in moved)
    _shows_as_a_fresh(ex, ChainExplorer)


def test_a_drag_from_python_ends_with_everything_sent():
    ex = Dot(display="page")
    ex.drag_sync_s = 3600.0
    log = _watched(ex)
    ex.drag("dot", (0.0, 0.0), (1.0, -0.5), steps=4)
    last = {kind: v for kind, v in log}
    assert last["x"] == pytest.approx(1.0) and last["y"] == pytest.approx(-0.5)
    assert last["readout"] == ex.readout.value


def test_in_a_kernel_the_held_values_go_after_drag_sync_s_even_without_a_release():
    """A drag whose release never comes (the page closed mid-drag): the held values still reach
    the page, ``drag_sync_s`` after they were first held (a timer on the kernel's event loop)."""
    import asyncio
    import concurrent.futures

    ex = Dot(display="page")
    ex.drag_sync_s = 0.3
    log = _watched(ex)

    async def main():
        held = []
        for k in range(1, 4):
            _drag(ex, "dot", 0.2 * k, 0.0, k)
            await asyncio.sleep(0)               # answered (call_soon)
            await asyncio.sleep(0)
            held.append("picture" in _names(log) and "readout" not in _names(log))
        await asyncio.sleep(1.0)
        return held[0]

    with concurrent.futures.ThreadPoolExecutor(1) as pool:     # an event loop of its own
        held = pool.submit(lambda: asyncio.run(main())).result()
    assert held
    last = {kind: v for kind, v in log}
    assert last["x"] == ex.values["x"] == pytest.approx(0.6) and last["readout"] == ex.readout.value


def test_a_refusal_the_explorer_shows_is_not_said_a_third_time_beside_reset_view():
    """The explorer's message line and picture show a refused step; the ack marks it said, so the
    page's status line beside "reset view" stays empty.  A refusal the explorer does not show (a
    handle the picture no longer has) is still said there."""
    from planargeo.widgets.canvas import PictureCanvas

    ex = Dot(display="page")
    acks = []
    ex.canvas.send = lambda m, *a, **k: acks.append(m) if m.get("type") == "ack" else None
    _drag(ex, "dot", 1.8, 0.5, 1)                              # x > 1.5: refused
    assert acks[-1]["ok"] is False and acks[-1]["said"] is True
    assert acks[-1]["message"] == ex.message and "x must not exceed 1.5" in ex.figure_text
    _drag(ex, "no such handle", 0.0, 0.0, 2)
    assert acks[-1]["ok"] is False and "said" not in acks[-1] and "no handle" in acks[-1]["message"]
    bare = PictureCanvas(on_drag=lambda h, x, y: (_ for _ in ()).throw(SceneError("too far")))
    bare.picture = {"handles": [{"id": "h", "x": 0.0, "y": 0.0}], "elements": []}
    got = []
    bare.send = lambda m, *a, **k: got.append(m)
    bare._on_msg(None, {"type": "drag", "id": "h", "x": 1.0, "y": 0.0, "seq": 1}, None)
    assert got[-1]["ok"] is False and got[-1]["message"] == "too far" and "said" not in got[-1]
