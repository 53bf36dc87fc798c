"""A page request is answered after the kernel's message handler has returned (PictureCanvas.defer).

The kernel publishes "idle" as its handler returns; answering after that lets the page handle
the kernel's busy/idle pair before the reply (JupyterLab works on each status change).
Without a running event loop (tests, scripts) a request is answered at once.
"""
from __future__ import annotations

import asyncio
import concurrent.futures

from planargeo.widgets.canvas import PictureCanvas


def _alone(fn):
    """Run ``fn`` in a thread of its own: no event loop another test left in this one reaches it."""
    with concurrent.futures.ThreadPoolExecutor(1) as pool:
        return pool.submit(fn).result()


def _canvas(sent: list) -> PictureCanvas:
    c = PictureCanvas(on_drag=lambda h, x, y: None)
    c.defer = True                     # the default, whatever tests/conftest.py set for this thread
    c.picture = {"handles": [{"id": "P", "x": 0.0, "y": 0.0}]}
    c.send = lambda msg, *a, **k: sent.append(msg)
    return c


def test_without_an_event_loop_a_request_is_answered_at_once():
    sent: list = []
    c = _canvas(sent)
    _alone(lambda: c._on_msg(c, {"type": "drag", "id": "P", "x": 1.0, "y": 2.0, "seq": 1}, None))
    assert [m["type"] for m in sent] == ["ack"] and sent[0]["seq"] == 1 and sent[0]["ok"]
    assert c.n_requests == 1


def test_in_an_event_loop_the_answer_comes_after_the_handler_returns():
    sent: list = []

    async def main():
        c = _canvas(sent)
        c._on_msg(c, {"type": "drag", "id": "P", "x": 1.0, "y": 2.0, "seq": 7}, None)
        after_handler = (c.n_requests, list(sent))    # what had happened when the handler returned
        await asyncio.sleep(0)
        return after_handler, c.n_requests

    (n_then, sent_then), n_now = _alone(lambda: asyncio.run(main()))
    assert (n_then, sent_then) == (0, [])
    assert n_now == 1 and [m["type"] for m in sent] == ["ack"] and sent[0]["seq"] == 7


def test_in_an_event_loop_without_defer_the_answer_is_at_once():
    sent: list = []

    async def main():
        c = _canvas(sent)
        c.defer = False
        c._on_msg(c, {"type": "ping", "seq": 3}, None)
        return c.n_requests

    assert _alone(lambda: asyncio.run(main())) == 1 and sent[0]["seq"] == 3


def test_deferred_requests_are_answered_in_the_order_they_came():
    sent: list = []

    async def main():
        c = _canvas(sent)
        for k, x in enumerate((1.0, 2.0, float("nan"))):
            c._on_msg(c, {"type": "drag", "id": "P", "x": x, "y": 0.0, "seq": k}, None)
        await asyncio.sleep(0)

    _alone(lambda: asyncio.run(main()))
    assert [(m["seq"], m["ok"]) for m in sent] == [(0, True), (1, True), (2, False)]
