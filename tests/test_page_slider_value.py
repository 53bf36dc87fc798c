"""A slider value the page sets reaches the explorer exactly, and the page gets the picture first.

No browser here: the value arrives as the slider's view sends it (``set_state``, the widget's
own path for a page-set value, inside a running asyncio loop as in the kernel), and what the
canvas and the readout send is caught (``send``, ``send_state``).
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


def _text(picture) -> str:
    return json.dumps(picture, sort_keys=True, default=lambda a: a.tolist())


def _watched(**values):
    """A page chain and the log of what leaves it: "picture" (the canvas) and "readout" (its sync)."""
    ex = ChainExplorer(display="page", links=4, **values)
    log = []
    ex.canvas.send = lambda m, *a, **k: log.append("picture")
    readout_sent = ex.readout.send_state

    def send_state(key=None):
        if key:                                       # (a hold with nothing held sends nothing)
            log.append("readout")
        readout_sent(key)

    ex.readout.send_state = send_state
    return ex, log


def test_a_value_the_page_sets_is_applied_exactly_and_a_fresh_explorer_from_the_values_is_the_same():
    ex, log = _watched()
    w = ex.controls["angle"]

    async def main():
        w.set_state({"value": -12.345678901234567})   # off the slider's 1° grid: kept as it is
        await asyncio.sleep(0.05)

    _alone(lambda: asyncio.run(main()))
    assert w.value == ex.values["angle"] == ex.shown_values["angle"] == -12.345678901234567
    assert log == ["picture", "readout"]              # one update: the picture first
    again = ChainExplorer(display="page", **ex.values)
    assert again.values == ex.values
    assert again.readout_values == ex.readout_values and again.readout.value == ex.readout.value
    assert _text(again.canvas.picture) == _text(ex.canvas.picture)


def test_page_steps_each_send_the_picture_before_the_readout_with_the_state_of_their_value():
    ex, log = _watched()
    w = ex.controls["angle"]
    tables = []

    async def main():
        for a in (-29.0, -28.0, -29.0):
            w.set_state({"value": a})
            tables.append(ex.readout.value)

    _alone(lambda: asyncio.run(main()))
    assert log == ["picture", "readout"] * 3
    assert tables[0] == tables[2] != tables[1]
    assert tables[1] == ChainExplorer(display="agg", links=4, angle=-28.0).readout.value
