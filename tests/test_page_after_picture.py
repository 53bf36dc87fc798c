"""In the page, the picture goes first and the readout and controls follow a frame later.

Sent right behind the picture, the readout's and controls' new values reach the page with it,
and the page works on them (the readout's table parsed, styled and laid out) before it paints
the picture; held ``Explorer.after_picture_s`` longer, the picture is painted first.  No browser
here: what the canvas and the widgets send is caught (``send``, ``send_state``), and an asyncio
loop stands in for the kernel's.  The values themselves change at once in Python, and a value
the page sets is applied exactly (the slider's own path, ``set_state``, as its view sends it).
"""
from __future__ import annotations

import asyncio
import concurrent.futures
import json

from planargeo.widgets import ChainExplorer


def _alone(fn):
    """Run ``fn`` in a thread of its own: no event loop another test left in this one reaches it."""
    with concurrent.futures.ThreadPoolExecutor(1) as pool:
        return pool.submit(fn).result()


def _watched(**values):
    """A page chain and the log of what leaves it: ("picture", version) and ("readout", its text)."""
    ex = ChainExplorer(display="page", links=4, **values)
    log = []
    ex.canvas.send = lambda m, *a, **k: log.append(("picture", m.get("version") or m.get("update", {}).get("version")))
    readout_sent = ex.readout.send_state

    def send_state(key=None):
        if key:                                       # (a hold with nothing held sends nothing)
            log.append(("readout", ex.readout.value))
        readout_sent(key)

    ex.readout.send_state = send_state
    return ex, log


def test_in_an_event_loop_the_readout_follows_the_picture_a_frame_later():
    ex, log = _watched()
    assert 0.0 < ex.after_picture_s <= 0.05          # a frame or so: no lag anyone sees

    async def main():
        ex.controls["angle"].value = -20.0
        at_once = list(log)
        table = ex.readout.value                      # Python holds the new readout at once
        await asyncio.sleep(ex.after_picture_s + 0.05)
        return at_once, table

    at_once, table = _alone(lambda: asyncio.run(main()))
    assert [k for k, _ in at_once] == ["picture"]
    assert [k for k, _ in log] == ["picture", "readout"] and log[1][1] == table
    assert ex.readout_values == ChainExplorer(display="agg", links=4, angle=-20.0).readout_values


def test_steps_within_the_wait_send_each_picture_and_the_readout_once_with_the_last_values():
    ex, log = _watched()

    async def main():
        for a in (-29.0, -28.0, -27.0):
            ex.controls["angle"].value = a
        await asyncio.sleep(ex.after_picture_s + 0.05)

    _alone(lambda: asyncio.run(main()))
    assert [k for k, _ in log] == ["picture"] * 3 + ["readout"]
    assert log[-1][1] == ex.readout.value == ChainExplorer(display="agg", links=4, angle=-27.0).readout.value


def test_without_an_event_loop_or_with_no_wait_the_readout_goes_at_once():
    ex, log = _watched()
    _alone(lambda: setattr(ex.controls["angle"], "value", -25.0))
    assert [k for k, _ in log] == ["picture", "readout"]

    async def main():
        ex.after_picture_s = 0.0
        ex.controls["angle"].value = -24.0
        return list(log)

    assert [k for k, _ in _alone(lambda: asyncio.run(main()))] == ["picture", "readout"] * 2


def test_a_value_the_page_sets_is_applied_exactly_and_a_fresh_explorer_from_the_values_is_the_same():
    ex, log = _watched()
    w = ex.controls["angle"]

    async def main():
        w.set_state({"value": -12.345678901234567})   # as the slider's view sends it
        await asyncio.sleep(ex.after_picture_s + 0.05)

    _alone(lambda: asyncio.run(main()))
    assert w.value == ex.values["angle"] == ex.shown_values["angle"] == -12.345678901234567
    again = ChainExplorer(display="page", **ex.values)
    assert again.values == ex.values
    assert again.readout_values == ex.readout_values and again.readout.value == ex.readout.value
    assert _text(again.canvas.picture) == _text(ex.canvas.picture)


def _text(picture) -> str:
    return json.dumps(picture, sort_keys=True, default=lambda a: a.tolist())
