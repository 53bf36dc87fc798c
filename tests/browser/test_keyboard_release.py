"""Arrow keys nudge a handle; letting go of them ends the nudges as a mouse-up ends a drag.

The page renderer (``canvas.js``) runs alone in headless chromium
(:class:`browser_harness.CanvasHarness`), the kernel played by the test.  A click on a handle
gives it the keyboard; each arrow key press moves it 2 px (a ``drag``, one request in flight, the
latest wins); letting go of the key sends one ``release`` for that handle after the last
``drag``, and nothing more.  Holding two arrow keys (a diagonal) releases once both are up; the
picture losing the keyboard's focus while a key is held releases too.  On the kernel's side a
``release`` ends a drag (``PictureCanvas.on_release``: the car explorer's view fits the car
again, tests/test_car_play_and_view.py).
"""
from __future__ import annotations

import pytest

from .conftest import ack, one_handle_picture, open_harness_view, requests_sent

pytestmark = pytest.mark.browser

PX_PER_UNIT = 75.0          # one_handle_picture: 300 px for 4 units


def _answer_all(page, limit: int = 20):
    """Acknowledge each request as it comes (the kernel taking every one); what was sent, in order."""
    done = 0
    for _ in range(limit):
        sent = requests_sent(page)
        if len(sent) == done:
            return sent
        for m in sent[done:]:
            ack(page, m)
        done = len(sent)
    raise AssertionError("the page kept sending requests")


def _focused_view(page):
    """A view of the picture whose handle P has the keyboard (clicked, not moved)."""
    page.mouse.click(*open_harness_view(page, one_handle_picture()))
    assert requests_sent(page) == [], "a click without a move sent a request"


def test_letting_go_of_an_arrow_key_releases_the_nudged_handle(harness_page):
    page = harness_page
    _focused_view(page)
    for _ in range(3):                        # the key held: three presses (the key's repeat)
        page.keyboard.down("ArrowRight")
    sent = requests_sent(page)
    assert [m["type"] for m in sent] == ["drag"], sent          # one request in flight
    page.keyboard.up("ArrowRight")
    assert len(requests_sent(page)) == 1, "a request sent while the first was unanswered"
    sent = _answer_all(page)
    assert [m["type"] for m in sent] == ["drag", "drag", "release"], sent
    last = sent[1]                            # 3 nudges of 2 px to the right
    assert last["id"] == "P" and abs(last["x"] - 6 / PX_PER_UNIT) < 1e-9 and abs(last["y"]) < 1e-9, last
    assert sent[2]["id"] == "P"


def test_two_arrow_keys_release_once_both_are_up(harness_page):
    page = harness_page
    _focused_view(page)
    page.keyboard.down("ArrowUp")
    _answer_all(page)
    page.keyboard.down("ArrowLeft")
    _answer_all(page)
    page.keyboard.up("ArrowUp")               # one still held: the nudges go on
    assert [m["type"] for m in _answer_all(page)] == ["drag", "drag"]
    page.keyboard.down("ArrowLeft")
    page.keyboard.up("ArrowLeft")
    sent = _answer_all(page)
    assert [m["type"] for m in sent] == ["drag", "drag", "drag", "release"], sent
    assert abs(sent[2]["x"] + 4 / PX_PER_UNIT) < 1e-9 and abs(sent[2]["y"] - 2 / PX_PER_UNIT) < 1e-9


def test_losing_the_focus_while_a_key_is_held_releases(harness_page):
    page = harness_page
    _focused_view(page)
    page.keyboard.down("ArrowDown")
    page.evaluate("document.querySelector('.pg-canvas svg').blur()")
    sent = _answer_all(page)
    assert [m["type"] for m in sent] == ["drag", "release"], sent
    page.keyboard.up("ArrowDown")             # the key's own let-go later: nothing more
    assert len(_answer_all(page)) == 2


def test_quick_taps_while_the_kernel_is_busy_end_with_a_release(harness_page):
    # tap, tap while the first drag is unanswered: the second tap's release goes after its drag
    page = harness_page
    _focused_view(page)
    page.keyboard.press("ArrowRight")
    page.keyboard.press("ArrowRight")
    assert [m["type"] for m in requests_sent(page)] == ["drag"]
    sent = _answer_all(page)
    assert [m["type"] for m in sent][-2:] == ["drag", "release"], sent
    assert abs(sent[-2]["x"] - 4 / PX_PER_UNIT) < 1e-9
