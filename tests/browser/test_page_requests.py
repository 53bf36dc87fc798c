"""One request in flight, the latest wins: the page's rule, with the kernel played by the test.

The page renderer (``canvas.js``) runs alone in headless chromium
(:class:`browser_harness.CanvasHarness`: a static page on 127.0.0.1, a stand-in for
the anywidget model that keeps what the page sends).  A handle is dragged with real
mouse events through twenty moves while the "kernel" answers nothing: the page must
have sent one request only; when that one is acknowledged, it sends exactly one more,
the pointer's latest position (in data coordinates, from the picture's own view), and
then nothing until that is acknowledged too; letting go sends one ``release`` after it, and
then nothing more.  The same real-browser rule is read off
the websocket for every explorer in ``test_page_explorers.py``.
"""
from __future__ import annotations

import pytest

from .conftest import ack, one_handle_picture, open_harness_view, requests_sent

pytestmark = pytest.mark.browser


def test_one_request_in_flight_and_the_latest_position_wins(harness_page):
    page = harness_page
    x, y = open_harness_view(page, one_handle_picture())
    page.mouse.move(x, y)
    page.mouse.down()
    for k in range(1, 21):
        page.mouse.move(x + 3 * k, y - 2 * k)
    sent = requests_sent(page)
    assert [m["type"] for m in sent] == ["drag"], f"{len(sent)} requests sent while the first was unanswered"
    ack(page, sent[0])
    sent = requests_sent(page)
    assert len(sent) == 2, f"after the ack: {len(sent) - 1} requests, not 1"
    last = sent[1]
    # the pointer's last place, (60, 40) px right and up of P at the picture's 75 px per unit
    assert last["type"] == "drag" and last["id"] == "P"
    assert abs(last["x"] - 60 / 75) < 0.02 and abs(last["y"] - 40 / 75) < 0.02, last
    page.mouse.up()
    assert len(requests_sent(page)) == 2, "a request sent while the second was unanswered"
    ack(page, last)
    sent = requests_sent(page)        # the mouse let go: the release, after the drag's last request
    assert [m["type"] for m in sent[2:]] == ["release"] and sent[2]["id"] == "P", sent[2:]
    ack(page, sent[2])
    assert len(requests_sent(page)) == 3, "a request sent with nothing new to ask"
