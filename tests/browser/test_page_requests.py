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

pytestmark = pytest.mark.browser


def _picture():
    from planargeo.draw.picture import Picture

    pic = Picture((-2, 2, -2, 2), size=(300, 300), ticks=False, margin=(0, 0, 0, 0))
    pic.marks("P", [[0.0, 0.0]], role="twist", symbol="P", desc="a point")
    pic.handle("P", (0.0, 0.0), symbol="P", desc="drag P")
    return pic.to_dict()


def _requests(page):
    return page.evaluate("window.sent.filter((m) => m.type !== 'sync' && m.type !== 'describe')")


def _ack(page, m):
    page.evaluate("(m) => window.deliver(m)",
                  {"type": "ack", "seq": m["seq"], "client": m.get("client"), "ok": True, "message": ""})


def test_one_request_in_flight_and_the_latest_position_wins(harness_page):
    page = harness_page
    from planargeo.widgets.canvas import PictureCanvas

    pic = _picture()
    c = PictureCanvas()
    c.picture = pic
    page.evaluate("(s) => window.openView(s)",
                  {k: v for k, v in c.get_state().items() if k in ("snapshot", "playing")})
    for m in page.evaluate("window.sent"):        # the view's own first request (a sync), answered
        _ack(page, m)
    page.evaluate("window.sent.length = 0")
    box = page.locator("circle.pg-handle").first.bounding_box()
    x, y = box["x"] + box["width"] / 2, box["y"] + box["height"] / 2
    page.mouse.move(x, y)
    page.mouse.down()
    for k in range(1, 21):
        page.mouse.move(x + 3 * k, y - 2 * k)
    sent = _requests(page)
    assert [m["type"] for m in sent] == ["drag"], f"{len(sent)} requests sent while the first was unanswered"
    _ack(page, sent[0])
    sent = _requests(page)
    assert len(sent) == 2, f"after the ack: {len(sent) - 1} requests, not 1"
    last = sent[1]
    # the pointer's last place, (60, 40) px right and up of P at the picture's 75 px per unit
    assert last["type"] == "drag" and last["id"] == "P"
    assert abs(last["x"] - 60 / 75) < 0.02 and abs(last["y"] - 40 / 75) < 0.02, last
    page.mouse.up()
    assert len(_requests(page)) == 2, "a request sent while the second was unanswered"
    _ack(page, last)
    sent = _requests(page)        # the mouse let go: the release, after the drag's last request
    assert [m["type"] for m in sent[2:]] == ["release"] and sent[2]["id"] == "P", sent[2:]
    _ack(page, sent[2])
    assert len(_requests(page)) == 3, "a request sent with nothing new to ask"
