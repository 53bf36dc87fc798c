"""What a student review of the page found, checked in headless chromium on the page renderer alone.

``canvas.js`` runs in a static page (:class:`browser_harness.CanvasHarness`), the kernel played
by the test.  The references are the picture's own numbers (its size, box, where an element is),
not the page's code:

* in a container narrower than the figure, the figure is shown whole, scaled to the container's
  width (its aspect kept, its text at least 11 px as shown), and a handle dragged to a point
  reaches the kernel as that point's data coordinates; narrower than the smallest scale (text
  drawn 1.15 times larger), the figure keeps that scale and its container scrolls sideways;
* a click on an element focuses it (the rest faded); a click on the background clears the focus,
  and a focus on an element that left the picture is dropped;
* a hover description near any edge of the figure is shown whole inside the figure;
* the keyboard reaches the handles: Tab into the figure (a visible outline) marks the first
  handle, Tab the next, the arrow keys nudge the marked one (then a release);
* the element hovered is the nearest one to the pointer: a thin line under a filled polygon.
"""
from __future__ import annotations

import pytest

pytestmark = pytest.mark.browser

MIN_TEXT_PX = 11.0


def _font_px():
    from planargeo.draw.picture import FONT_PX

    return FONT_PX


FONT_PX = _font_px()


def _open(page, pic: dict, host_width: int | None = None):
    from planargeo.widgets.canvas import PictureCanvas

    c = PictureCanvas()
    c.picture = pic
    style = f"width: {host_width}px" if host_width else ""
    page.evaluate("(s) => { document.getElementById('host').style.cssText = s; }", style)
    page.evaluate("(s) => window.openView(s)",
                  {k: v for k, v in c.get_state().items() if k in ("snapshot", "playing")})
    _ack_all(page)
    page.evaluate("window.sent.length = 0")
    page.wait_for_timeout(100)        # the resize observer's first call
    return c


def _ack_all(page, desc: str | None = None) -> list:
    sent = page.evaluate("window.sent.slice()")
    for m in sent:
        ack = {"type": "ack", "seq": m["seq"], "client": m.get("client"), "ok": True, "message": ""}
        if m["type"] == "describe" and desc is not None:
            ack.update(desc=desc, id=m["id"])
        page.evaluate("(m) => window.deliver(m)", ack)
    return sent


def _settle(page) -> list:
    """Acknowledge each request as it comes until the page sends no more; what was sent."""
    done = 0
    for _ in range(20):
        sent = page.evaluate("window.sent.slice()")
        for m in sent[done:]:
            page.evaluate("(m) => window.deliver(m)", {"type": "ack", "seq": m["seq"], "client": m.get("client"),
                                                        "ok": True, "message": ""})
        if len(sent) == done:
            return sent
        done = len(sent)
    raise AssertionError("the page kept sending requests")


def _box(page, selector: str) -> dict:
    return page.locator(selector).first.bounding_box()


def _square(size: int = 620):
    from planargeo.draw.picture import Picture

    return Picture((-2, 2, -2, 2), size=(size, size), ticks=False, margin=(0, 0, 0, 0))


def _narrow_picture():
    pic = _square(620)
    pic.marks("P", [[0.0, 0.0]], symbol="P", desc="a point")
    pic.text("far", (1.9, -1.9), "far corner", ha="right", va="bottom")
    pic.handle("P", (0.0, 0.0), symbol="P", desc="drag P")
    return pic.to_dict()


def test_a_narrow_container_shows_the_whole_figure_and_a_drag_lands_under_the_pointer(harness_page):
    page = harness_page
    _open(page, _narrow_picture(), host_width=560)
    host, svg = _box(page, "#host"), _box(page, ".pg-canvas svg")
    # whole, inside the container, aspect kept
    assert svg["x"] >= host["x"] - 0.5 and svg["x"] + svg["width"] <= host["x"] + host["width"] + 0.5, (svg, host)
    assert svg["width"] == pytest.approx(560, abs=1) and svg["height"] == pytest.approx(svg["width"], abs=1)
    # the text as shown: at least 11 px
    shown = page.evaluate("""() => { const t = document.querySelector('.pg-canvas g[data-id="far"] text');
        const r = t.getBoundingClientRect(); return [parseFloat(getComputedStyle(t).fontSize), r.right, r.bottom]; }""")
    scale = svg["width"] / 620
    assert shown[0] * scale >= MIN_TEXT_PX - 0.01, shown
    assert shown[1] <= svg["x"] + svg["width"] + 1 and shown[2] <= svg["y"] + svg["height"] + 1, (shown, svg)
    # a drag: the handle follows the pointer; the kernel gets the pointer's data point
    h = _box(page, "circle.pg-handle")
    page.mouse.move(h["x"] + h["width"] / 2, h["y"] + h["height"] / 2)
    page.mouse.down()
    to = (svg["x"] + 0.75 * svg["width"], svg["y"] + 0.25 * svg["height"])      # data (1, 1)
    page.mouse.move(*to)
    h = _box(page, "circle.pg-handle")
    assert h["x"] + h["width"] / 2 == pytest.approx(to[0], abs=1)
    assert h["y"] + h["height"] / 2 == pytest.approx(to[1], abs=1)
    drags = [m for m in page.evaluate("window.sent") if m["type"] == "drag"]
    assert drags and drags[-1]["x"] == pytest.approx(1.0, abs=4 / svg["width"] * 1.01)
    assert drags[-1]["y"] == pytest.approx(1.0, abs=4 / svg["width"] * 1.01)
    page.mouse.up()
    _settle(page)
    # the wheel zooms about the point under the pointer: data (-1, 0.5) stays there
    page.evaluate("window.sent.length = 0")
    page.mouse.move(svg["x"] + 0.25 * svg["width"], svg["y"] + 0.375 * svg["height"])
    page.mouse.wheel(0, 100)
    (view,) = [m for m in page.evaluate("window.sent") if m["type"] == "view"]
    x0, x1, y0, y1 = view["box"]
    assert x1 - x0 > 4.0 and (-1.0 - x0) / (x1 - x0) == pytest.approx(0.25, abs=2 / svg["width"])
    assert (y1 - 0.5) / (y1 - y0) == pytest.approx(0.375, abs=2 / svg["height"])
    _ack_all(page)


def test_narrower_than_the_smallest_scale_the_container_scrolls(harness_page):
    page = harness_page
    _open(page, _narrow_picture(), host_width=400)
    svg = _box(page, ".pg-canvas svg")
    # the smallest scale: the labels (FONT_PX) drawn at most 1.15 times larger, shown at 11 px
    assert svg["width"] == pytest.approx(620 * 11 / (1.15 * FONT_PX), abs=1.5), svg
    text_px = page.evaluate("""() => parseFloat(getComputedStyle(
        document.querySelector('.pg-canvas g[data-id="far"] text')).fontSize)""")
    assert text_px * svg["width"] / 620 >= MIN_TEXT_PX - 0.01
    widths = page.evaluate("(() => { const r = document.querySelector('.pg-canvas'); "
                           "return [r.scrollWidth, r.clientWidth, getComputedStyle(r).overflowX]; })()")
    assert widths[0] > widths[1] and widths[2] == "auto", widths


def _focus_picture(with_q: bool = True):
    pic = _square(400)
    pic.marks("P", [[-1.0, 0.0]], symbol="P", desc="a point", size=12)
    if with_q:
        pic.marks("Q", [[1.0, 0.0]], symbol="Q", desc="another point", size=12)
    return pic.to_dict()


def _faded(page) -> dict:
    return page.evaluate("Object.fromEntries([...document.querySelectorAll('.pg-el')].map("
                         "(g) => [g.dataset.id, g.classList.contains('pg-faded')]))")


def _at(page, x: float, y: float, size: int = 400) -> tuple[float, float]:
    """The page point of data (x, y) in a square picture of box (-2, 2)², no margins."""
    svg = _box(page, ".pg-canvas svg")
    return svg["x"] + (x + 2) / 4 * svg["width"], svg["y"] + (2 - y) / 4 * svg["height"]


def test_a_background_click_clears_the_focus_and_a_gone_element_drops_it(harness_page):
    page = harness_page
    c = _open(page, _focus_picture())
    page.mouse.click(*_at(page, 1.0, 0.0))
    assert _faded(page) == {"P": True, "Q": False}
    page.mouse.click(*_at(page, 0.0, 1.5))          # the background
    assert _faded(page) == {"P": False, "Q": False}
    page.mouse.click(*_at(page, 1.0, 0.0))
    assert _faded(page)["P"] is True
    # Q leaves the picture (its overlay unticked): nothing stays faded
    c.picture = _focus_picture(with_q=False)
    page.evaluate("(m) => window.deliver(m)", {"type": "update", **c.last_update})
    assert _faded(page) == {"P": False}


def _edge_picture():
    pic = _square(400)
    for eid, (x, y) in {"L": (-1.95, 0.0), "R": (1.95, 0.0), "T": (0.0, 1.95), "B": (0.0, -1.95),
                        "BR": (1.95, -1.95)}.items():
        pic.marks(eid, [[x, y]], symbol=eid, desc="near the edge", size=8)
    return pic.to_dict()


LONG = "a description long enough to need two or three lines in the hover box, near an edge"


@pytest.mark.parametrize("eid, xy", [("L", (-1.95, 0.0)), ("R", (1.95, 0.0)), ("T", (0.0, 1.95)),
                                     ("B", (0.0, -1.95)), ("BR", (1.95, -1.95))])
def test_a_hover_description_near_an_edge_stays_inside_the_figure(harness_page, eid, xy):
    page = harness_page
    _open(page, _edge_picture())
    page.mouse.move(*_at(page, 0.0, 0.5))
    page.mouse.move(*_at(page, *xy))
    _ack_all(page, desc=f"{eid} — {LONG}")
    tip, svg = _box(page, ".pg-tip"), _box(page, ".pg-canvas svg")
    assert page.locator(".pg-tip").text_content().startswith(eid)
    assert tip["height"] > 30                       # the long text wraps
    assert svg["x"] - 0.5 <= tip["x"] and tip["x"] + tip["width"] <= svg["x"] + svg["width"] + 0.5, (tip, svg)
    assert svg["y"] - 0.5 <= tip["y"] and tip["y"] + tip["height"] <= svg["y"] + svg["height"] + 0.5, (tip, svg)


def _two_handles():
    pic = _square(400)
    pic.handle("A", (-1.0, 0.0), symbol="A", desc="drag A")
    pic.handle("B", (1.0, 0.0), symbol="B", desc="drag B")
    return pic.to_dict()


def _marked(page) -> list:
    return page.evaluate("[...document.querySelectorAll('circle.pg-handle.pg-kbd')].map((c) => c.dataset.handle)")


def test_tab_reaches_the_handles_and_the_arrow_keys_nudge_the_marked_one(harness_page):
    page = harness_page
    _open(page, _two_handles())
    page.evaluate("document.activeElement && document.activeElement.blur()")
    page.keyboard.press("Tab")                      # the "reset view" button
    page.keyboard.press("Tab")                      # the figure
    assert page.evaluate("document.activeElement.tagName") == "svg"
    outline = page.evaluate("getComputedStyle(document.querySelector('.pg-canvas svg')).outlineStyle")
    assert outline != "none"
    assert _marked(page) == ["A"]
    stroke = page.evaluate("getComputedStyle(document.querySelector('circle.pg-kbd')).stroke")
    assert stroke == "rgb(26, 115, 232)"
    page.keyboard.press("Tab")
    assert _marked(page) == ["B"] and page.evaluate("document.activeElement.tagName") == "svg"
    page.keyboard.press("ArrowRight")
    done = 0
    for _ in range(5):                              # each request acknowledged as it comes
        sent = page.evaluate("window.sent.slice()")
        for m in sent[done:]:
            page.evaluate("(m) => window.deliver(m)", {"type": "ack", "seq": m["seq"], "client": m.get("client"),
                                                        "ok": True, "message": ""})
        if len(sent) == done:
            break
        done = len(sent)
    kinds = [(m["type"], m.get("id")) for m in sent]
    assert kinds == [("drag", "B"), ("release", "B")], kinds
    assert sent[0]["x"] == pytest.approx(1.0 + 2 * 4 / 400) and sent[0]["y"] == pytest.approx(0.0)
    page.keyboard.press("Shift+Tab")
    assert _marked(page) == ["A"]
    page.keyboard.press("Tab")
    page.keyboard.press("Tab")                      # past the last handle: the focus leaves
    assert page.evaluate("document.activeElement.tagName") != "svg"


def _line_under_a_polygon():
    pic = _square(400)
    pic.path("line", [[-2.0, 0.0], [2.0, 0.0]], role="wrench", symbol="l", desc="the thin line", width=1.0, z=1)
    pic.path("body", [[-1.5, -1.5], [1.5, -1.5], [1.5, 1.5], [-1.5, 1.5]], closed=True, fill="#cccccc",
             symbol="B", desc="a body", z=5)
    return pic.to_dict()


def _hovered(page) -> list:
    return page.evaluate("[...document.querySelectorAll('.pg-el.pg-hover')].map((g) => g.dataset.id)")


def test_the_hover_goes_to_the_nearest_element_not_the_topmost(harness_page):
    page = harness_page
    _open(page, _line_under_a_polygon())
    order = page.evaluate("[...document.querySelectorAll('.pg-el')].map((g) => g.dataset.id)")
    assert order.index("line") < order.index("body")         # the line is drawn under the body
    x, y = _at(page, 0.5, 0.0)
    page.mouse.move(x, y + 2)                                 # 2 px from the line, inside the body
    assert _hovered(page) == ["line"]
    _ack_all(page, desc="l — the thin line")
    assert page.locator(".pg-tip").text_content().startswith("l")
    page.mouse.move(*_at(page, 0.5, 0.8))                     # inside the body, far from the line
    assert _hovered(page) == ["body"]
    page.mouse.move(*_at(page, 1.8, 1.8))                     # the background
    assert _hovered(page) == []


@pytest.mark.parametrize("kind, magic", [("svg", b"<?xml"), ("png", b"\x89PNG\r\n\x1a\n")])
def test_an_export_message_downloads_the_file_at_once(harness_page, kind, magic, tmp_path):
    # the message an export button's click sends (Python's own), handed to the page: a download
    # of that name and those bytes, with no further click; another view's message is not saved
    from planargeo.widgets import ProjectiveExplorer

    page = harness_page
    _open(page, _focus_picture())
    ex = ProjectiveExplorer(display="page")
    sent = []
    ex.canvas.send = lambda m, *a, **k: sent.append(m)
    {"svg": ex.export_button, "png": ex.export_png_button}[kind].click()
    (m,) = [m for m in sent if m["type"] == "download"]
    with page.expect_download(timeout=10_000) as info:
        page.evaluate("(m) => window.deliver(m)", m)
    d = info.value
    assert d.suggested_filename == f"planargeo-{ex.slug}.{kind}"
    path = tmp_path / d.suggested_filename
    d.save_as(path)
    data = path.read_bytes()
    assert data.lstrip().startswith(magic) and data == (ex._svg_bytes() if kind == "svg" else ex._png_bytes())
    if kind == "svg":
        import xml.etree.ElementTree as ET

        assert ET.fromstring(data).tag.endswith("svg")
    else:
        from io import BytesIO

        from PIL import Image

        assert Image.open(BytesIO(data)).size[0] > 100
    # a message for another view: nothing saved
    downloads = []

    def seen(dl):
        downloads.append(dl)

    page.on("download", seen)
    try:
        page.evaluate("(m) => window.deliver(m)", {**m, "client": "another-view"})
        page.wait_for_timeout(300)
    finally:
        page.remove_listener("download", seen)
    assert downloads == []


NARROW_CELLS = ["from planargeo.widgets import ChainExplorer",
                "ChainExplorer()",                           # 620 px: shrunk to the column
                "ChainExplorer(figsize=(9.6, 5.4))"]         # 960 px: too wide to shrink, scrolls


def test_in_a_narrow_jupyterlab_the_figure_fits_and_a_drag_lands_under_the_pointer(lab, browser):
    """JupyterLab at 1000 × 900 with the file browser open (the review's window: an output column
    of about 570 px): the chain's 620 px figure is shown whole inside the explorer, and its first
    handle dragged to a point is drawn there once the kernel has answered; a 960 px figure keeps
    its smallest scale and scrolls sideways inside the column (nothing cut out of reach)."""
    import time

    from .conftest import ARTIFACTS, open_in_lab, write_notebook

    write_notebook(lab.root / "narrow.ipynb", NARROW_CELLS)
    page = browser.new_page(viewport={"width": 1000, "height": 900})
    try:
        open_in_lab(page, lab, "narrow.ipynb", file_browser=True)
        ex = page.locator(".planargeo-explorer").first
        ex.locator("svg .pg-frame").first.wait_for(state="attached", timeout=240_000)
        svg = ex.locator(".pg-canvas svg").first
        svg.scroll_into_view_if_needed()
        time.sleep(1.0)                                    # the layout settles
        ARTIFACTS.mkdir(exist_ok=True)
        page.screenshot(path=str(ARTIFACTS / "narrow-lab-chain.png"))
        out = ex.evaluate("(e) => { const r = e.getBoundingClientRect(); "
                          "const p = e.closest('.jp-OutputArea-output') || e.parentElement; const q = p.getBoundingClientRect();"
                          "return [r.left, r.right, q.left, q.right]; }")
        box = svg.bounding_box()
        assert box["width"] < 620 * 0.99, box                       # scaled down
        assert box["height"] == pytest.approx(box["width"] * 540 / 620, abs=2)
        assert box["x"] >= out[2] - 1 and box["x"] + box["width"] <= out[3] + 1, (box, out)
        font = page.evaluate("(s) => parseFloat(getComputedStyle(s.querySelector('text')).fontSize)",
                             svg.element_handle())
        assert font * box["width"] / 620 >= 11 - 0.01
        handle = ex.locator("circle.pg-handle").first
        h = handle.bounding_box()
        start = (h["x"] + h["width"] / 2, h["y"] + h["height"] / 2)
        to = (start[0] + 30, start[1] - 20)
        page.mouse.move(*start)
        page.mouse.down()
        for k in range(1, 6):
            page.mouse.move(start[0] + 6 * k, start[1] - 4 * k)
            time.sleep(0.05)
        page.mouse.up()
        deadline = time.time() + 30
        while time.time() < deadline and ex.locator(".pg-canvas").first.evaluate(
                "(c) => c.__planargeo.busy()"):
            time.sleep(0.1)
        time.sleep(0.5)
        page.screenshot(path=str(ARTIFACTS / "narrow-lab-chain-dragged.png"))
        h2 = ex.locator(f"circle.pg-handle[data-handle='{handle.get_attribute('data-handle')}']").bounding_box()
        # the kernel's redraw puts the handle where the pointer let go (a joint may be held to a
        # circle: then on that circle, within the handle's own radius of the pointer)
        got = (h2["x"] + h2["width"] / 2, h2["y"] + h2["height"] / 2)
        assert abs(got[0] - to[0]) < h2["width"] and abs(got[1] - to[1]) < h2["height"], (got, to)
        assert (got[0] - start[0]) ** 2 + (got[1] - start[1]) ** 2 > 15 ** 2, (got, start)
        # the 960 px figure: its smallest scale, a scrollbar; scrolled to the end, its right edge in view
        wide = page.locator(".planargeo-explorer").nth(1)
        wide.locator("svg .pg-frame").first.wait_for(state="attached", timeout=240_000)
        wide.locator(".pg-canvas svg").first.scroll_into_view_if_needed()
        time.sleep(0.5)
        cv = wide.locator(".pg-canvas").first
        sizes = cv.evaluate("(c) => [c.scrollWidth, c.clientWidth]")
        wbox = wide.locator(".pg-canvas svg").first.bounding_box()
        assert wbox["width"] == pytest.approx(960 * 11 / (1.15 * FONT_PX), abs=1.5), wbox
        assert sizes[0] > sizes[1] and sizes[0] == pytest.approx(wbox["width"], abs=1.5), sizes
        cv.evaluate("(c) => { c.scrollLeft = c.scrollWidth; }")
        time.sleep(0.3)
        page.screenshot(path=str(ARTIFACTS / "narrow-lab-chain-960-scrolled.png"))
        wbox, cbox = wide.locator(".pg-canvas svg").first.bounding_box(), cv.bounding_box()
        assert abs(wbox["x"] + wbox["width"] - (cbox["x"] + cbox["width"])) < 1.5, (wbox, cbox)
    finally:
        page.close()


def test_a_mark_under_a_handle_is_described_once_the_pointer_rests(harness_page):
    # a joint drawn under its handle: the pointer on the handle hovers the joint; its description
    # is asked for only once the pointer rests (a drag starting at once does not wait behind it)
    page = harness_page
    pic = _square(400)
    pic.marks("J", [[0.5, 0.5]], symbol="J", desc="a joint", size=8)
    pic.handle("J", (0.5, 0.5), symbol="J", desc="drag J")
    _open(page, pic.to_dict())
    page.mouse.move(*_at(page, 0.5, 0.5))
    assert _hovered(page) == ["J"]
    assert [m for m in page.evaluate("window.sent") if m["type"] == "describe"] == []
    page.wait_for_timeout(500)
    asked = [m for m in page.evaluate("window.sent") if m["type"] == "describe"]
    assert [m["id"] for m in asked] == ["J"]
    _ack_all(page, desc="J — a joint")
    assert page.locator(".pg-tip").text_content() == "J — a joint"
