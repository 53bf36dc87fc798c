"""Parity of the two renderers of a picture: the page (canvas.js) and matplotlib (draw/render.py).

For every explorer, in each state the browser tests visit (the default; after a
drag of its first handle in view; after a slider change; with a display toggle and
with a focus; with its key on; zoomed in, as the page asks), the explorer's picture (``ex.picture()``, plain data) is drawn

* by the page: ``canvas.js`` as SVG in headless chromium, in one static page served
  from 127.0.0.1 with a stand-in for the anywidget model
  (:class:`browser_harness.CanvasHarness`), every picture in turn;
* by matplotlib: :func:`planargeo.draw.render.figure`, every artist tagged with its
  element's id, its place read through matplotlib's own transforms
  (``get_window_extent`` at the picture's size, 100 dpi).

The two must show the same elements, and the same lines below the plot (a key no corner
had room for, the picture's ``"below"``: the same texts and colours, in order, each at the
same place); the same ids and roles (the page writes each
element's role as ``data-role``), the same colours per element, the same label texts, and every
marker, rotation glyph, arrow, line, curve and label at the same pixel, within 1 px
at the same size.  A label's place is its box's edge (or centre) on the side it is
anchored by: across, from its characters' advances (a glyph's ink may reach past
its origin: T, ĵ); up and down, the box's bottom, top or middle, which the browser
takes from the font's line box and matplotlib from the text's glyphs, so they are
compared within :data:`TEXT_DY_PX`.

The page's drawing is also checked for the layout rule "no two visible labels
overlap" (:func:`overlapping_labels`, measured on the SVG text boxes).
"""
from __future__ import annotations

import math

import numpy as np
import pytest

pytestmark = pytest.mark.browser

#: Largest distance between the two renderers' places of one thing (pixels).
TOL_PX = 1.0
#: Largest vertical distance between the two renderers' centres of one label (pixels).
TEXT_DY_PX = 2.0
#: Two label boxes overlap when they share more than this (pixels) both across and up.
OVERLAP_PX = 1.0


# --------------------------------------------------------------------------- the states visited
def _in_view(pic, xy, margin=0.08):
    x0, x1, y0, y1 = pic["box"]
    mx, my = margin * (x1 - x0), margin * (y1 - y0)
    return x0 + mx < xy[0] < x1 - mx and y0 + my < xy[1] < y1 - my


def visited_states(name: str):
    """``(state name, picture dict)`` for the states the browser tests visit, of one explorer."""
    import ipywidgets as W

    import planargeo.widgets as pw

    ex = getattr(pw, name)(display="page")     # a canvas with no page: its messages handled in Python
    out = [("default", ex.picture())]
    pic = out[0][1]
    # a drag of its first handle in view, by 8 % of the view's width (or up, or the other way)
    x0, x1, y0, y1 = pic["box"]
    for h in pic["handles"]:
        if not _in_view(pic, (h["x"], h["y"])):
            continue
        done = False
        for dx, dy in ((0.08, 0.0), (-0.08, 0.0), (0.0, 0.08), (0.0, -0.08)):
            end = (h["x"] + dx * (x1 - x0), h["y"] + dy * (y1 - y0))
            ex.reset()
            before = ex.picture()
            ex.drag(h["id"], (h["x"], h["y"]), end, steps=4)
            after = ex.picture()
            if not ex.message and after["elements"] != before["elements"]:
                out.append((f"drag {h['id']}", after))
                done = True
                break
        if done:
            break
    # a slider change: the first slider of the scene (not a display control) that changes the picture
    ex.reset()
    for key, c in ex.controls.items():
        if key in ex.display_controls or not isinstance(c, (W.FloatSlider, W.IntSlider)) or c.disabled:
            continue
        lo, hi = c.min, c.max
        target = lo + 0.7 * (hi - lo)
        if isinstance(c, W.IntSlider):
            target = int(round(target))
        if target == c.value:
            target = lo + 0.3 * (hi - lo) if isinstance(c, W.FloatSlider) else int(round(lo + 0.3 * (hi - lo)))
        before = ex.picture()
        ex.set(**{key: target})
        after = ex.picture()
        if not ex.message and after["elements"] != before["elements"]:
            out.append((f"slider {key}", after))
            break
        ex.reset()
    # a display toggle (a checkbox that changes what is drawn) and a focus
    ex.reset()
    for key in ex.display_controls:
        c = ex.controls[key]
        if isinstance(c, W.Checkbox) and not c.disabled:
            before = ex.picture()
            ex.set(**{key: not c.value})
            after = ex.picture()
            if not ex.message and after["elements"] != before["elements"]:
                out.append((f"toggle {key}", after))
                break
            ex.reset()
    ex.reset()
    if "focus" in ex.controls and len(ex.controls["focus"].options) > 1:
        ex.set(focus=ex.controls["focus"].options[1])
        if not ex.message:
            out.append((f"focus {ex.controls['focus'].value}", ex.picture()))
    # the key on (in a corner of the plot, or below it when no corner has room)
    ex.reset()
    if "key" in ex.controls and not ex.controls["key"].disabled:
        ex.set(key=True)
        if not ex.message:
            out.append(("key on", ex.picture()))
        ex.set(key=False)
    # zoomed in about a point off centre, as the page asks for it (the canvas's checked view message)
    ex.reset()
    bx0, bx1, by0, by1 = ex.picture()["box"]
    cx, cy = bx0 + 0.45 * (bx1 - bx0), by0 + 0.55 * (by1 - by0)
    box = [cx + (bx0 - cx) * 0.7, cx + (bx1 - cx) * 0.7, cy + (by0 - cy) * 0.7, cy + (by1 - cy) * 0.7]
    ok, why = ex.canvas.handle_message({"type": "view", "box": box, "seq": 1})
    assert ok, f"{name}: the view {box} refused: {why}"
    out.append(("zoomed", ex.picture()))
    return out


# --------------------------------------------------------------------------- matplotlib's side
def matplotlib_measure(pic: dict) -> dict:
    """What matplotlib draws of ``pic``: per element id, its parts' artists' boxes (pixels, y down)."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.colors import to_hex

    from planargeo.draw import render
    from planargeo.draw.style import rc_context

    drawn: list = []
    fig = render.figure(pic, artists=drawn)     # the exports' figure (render.picture_bytes)
    FigureCanvasAgg(fig)
    with rc_context():
        renderer = fig.canvas.get_renderer()
        fig.draw(renderer)
    H = fig.get_size_inches()[1] * fig.dpi
    out: dict[str, list] = {}
    for gid, i, art in drawn:
        with rc_context():
            bb = art.get_window_extent(renderer)
        box = [bb.x0, H - bb.y1, bb.x1, H - bb.y0]
        text = art.get_text() if hasattr(art, "get_text") else None
        colors = set()
        for getter in ("get_color", "get_facecolor", "get_edgecolor"):
            if hasattr(art, getter) and text is None:
                with np.errstate(all="ignore"):
                    try:
                        col = getattr(art, getter)()
                        if getter != "get_color" and getattr(art, "get_fill", lambda: True)() is False \
                                and getter == "get_facecolor":
                            continue
                        if col is not None and not (hasattr(col, "__len__") and len(col) == 4 and col[3] == 0):
                            colors.add(to_hex(col))
                    except (ValueError, TypeError):
                        pass
        out.setdefault(gid, []).append({"part": i, "box": box, "text": text, "colors": colors,
                                        "kind": type(art).__name__})
    return out


def matplotlib_below(pic: dict) -> list[dict]:
    """The lines below the plot as matplotlib draws them: text, colour, box (pixels, y down)."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.colors import to_hex

    from planargeo.draw import render
    from planargeo.draw.style import rc_context

    fig = render.figure(pic)
    FigureCanvasAgg(fig)
    with rc_context():
        renderer = fig.canvas.get_renderer()
        fig.draw(renderer)
        H = fig.get_size_inches()[1] * fig.dpi
        out = []
        for t in fig.texts:
            if (t.get_gid() or "").endswith(":below"):
                bb = t.get_window_extent(renderer)
                out.append({"text": t.get_text(), "color": to_hex(t.get_color()),
                            "box": [bb.x0, H - bb.y1, bb.x1, H - bb.y0],
                            "px": t.get_fontsize() * fig.dpi / 72.0})
    return out


#: The page's lines below the plot (``text.pg-below``): text, colour, box and advance (SVG pixels)
PAGE_BELOW_JS = """() => {
  const svg = document.querySelector(".pg-canvas svg"), r0 = svg.getBoundingClientRect();
  return [...svg.querySelectorAll("text.pg-below")].map((t) => {
    const r = t.getBoundingClientRect(), n = t.getNumberOfChars(), m = t.getCTM();
    const a = t.getExtentOfChar(0), b = t.getExtentOfChar(n - 1);
    return { text: t.textContent.replace(t.querySelector("title")?.textContent ?? "", ""),
             color: t.getAttribute("fill"), box: [r.left - r0.left, r.top - r0.top, r.right - r0.left, r.bottom - r0.top],
             advance: [m.a * a.x + m.e, m.a * (b.x + b.width) + m.e],
             px: parseFloat(getComputedStyle(t).fontSize) * r0.width / svg.viewBox.baseVal.width };
  });
}"""


def compare_below(pic: dict, page_below: list[dict], mpl_below: list[dict]) -> list[str]:
    """Differences between the two renderers' lines below the plot (empty: the same)."""
    from matplotlib.colors import to_hex

    want = [(b["text"], to_hex(b["color"])) for b in pic.get("below", [])]
    got_page = [(b["text"], to_hex(b["color"])) for b in page_below]
    got_mpl = [(b["text"], b["color"]) for b in mpl_below]
    if not (want == got_page == got_mpl):
        return [f"lines below: {want} in the picture, {got_page} in the page, {got_mpl} in matplotlib"]
    problems = []
    for p, m in zip(page_below, mpl_below):
        if abs(p["advance"][0] - m["box"][0]) > TOL_PX or abs(p["box"][1] - m["box"][1]) > TEXT_DY_PX:
            problems.append(f"below {p['text']!r}: left, top ({p['advance'][0]:.1f}, {p['box'][1]:.1f}) in "
                            f"the page, ({m['box'][0]:.1f}, {m['box'][1]:.1f}) in matplotlib")
    return problems


# --------------------------------------------------------------------------- comparison
_DOM_NODES = {"path": 1, "ellipse": 1, "mark": 1, "glyph": 2, "arrow": 2, "text": 1}


def _page_parts(el: dict, page_el: dict) -> list[list[dict]]:
    """The page's SVG nodes of each part of element ``el`` (canvas.js draws parts in order)."""
    nodes, k, out = page_el["nodes"], 0, []
    for part in el["parts"]:
        n = 0 if part["p"] == "text" and part.get("hidden") else _DOM_NODES[part["p"]]
        out.append(nodes[k:k + n])
        k += n
    if k != len(nodes):
        raise AssertionError(f"{el['id']}: the page drew {len(nodes)} SVG nodes for parts needing {k}")
    return out


def _union(boxes):
    b = np.array(boxes, dtype=float).reshape(-1, 4)
    return [b[:, 0].min(), b[:, 1].min(), b[:, 2].max(), b[:, 3].max()]


def _norm_color(c):
    from matplotlib.colors import to_hex

    if c in (None, "none", "white", "#ffffff", "#FFFFFF"):
        return None
    try:
        return to_hex(c)
    except ValueError:
        return c


def compare(pic: dict, page: dict, mpl: dict) -> list[str]:
    """Differences between the page's drawing of ``pic`` and matplotlib's (empty: the same)."""
    problems = []
    by_id = {e["id"]: e for e in page["elements"]}
    want = {e["id"] for e in pic["elements"]}
    if set(by_id) != want:
        problems.append(f"page ids differ from the picture's: missing {sorted(want - set(by_id))}, "
                        f"extra {sorted(set(by_id) - want)}")
    drawn_page = {i for i, e in by_id.items() if e["nodes"]}
    drawn_mpl = set(mpl)
    if drawn_page != drawn_mpl:
        problems.append(f"elements drawn: only in the page {sorted(drawn_page - drawn_mpl)}, "
                        f"only in matplotlib {sorted(drawn_mpl - drawn_page)}")
    for el in pic["elements"]:
        pid = el["id"]
        if pid not in by_id:
            continue
        pe = by_id[pid]
        if pe["role"] != el.get("role", "body"):
            problems.append(f"{pid}: role {pe['role']!r} in the page, {el.get('role')!r} in the picture")
        try:
            nodes = _page_parts(el, pe)
        except AssertionError as exc:
            problems.append(str(exc))
            continue
        arts = {}
        for a in mpl.get(pid, []):
            arts.setdefault(a["part"], []).append(a)
        page_cols = {_norm_color(n.get(k)) for ns in nodes for n in ns for k in ("fill", "stroke")
                     if n["tag"] != "text"} - {None}
        mpl_cols = {_norm_color(c) for ar in arts.values() for a in ar for c in a["colors"]} - {None}
        if page_cols and mpl_cols and page_cols != mpl_cols:
            problems.append(f"{pid}: colours {sorted(page_cols)} in the page, {sorted(mpl_cols)} in matplotlib")
        for i, part in enumerate(el["parts"]):
            kind = part["p"]
            pn, ma = nodes[i], arts.get(i, [])
            if not pn and not ma:
                continue
            if bool(pn) != bool(ma):
                problems.append(f"{pid} part {i} ({kind}): drawn only by {'the page' if pn else 'matplotlib'}")
                continue
            if kind == "text":
                t_page, t_mpl = pn[0]["text"], ma[0]["text"]
                if t_page == t_mpl == "":      # an empty label shows nothing in either
                    continue
                if t_page != t_mpl:
                    problems.append(f"{pid}: label {t_page!r} in the page, {t_mpl!r} in matplotlib")
                bp, bm = pn[0]["box"], ma[0]["box"]
                fx = {"left": 0.0, "center": 0.5, "right": 1.0}[part["ha"]]
                fy = {"top": 0.0, "center": 0.5, "bottom": 1.0}[part["va"]]
                ap = pn[0]["advance"] or bp[::2]   # along the baseline, by advances (no glyph ink)
                xp, xm = ap[0] + fx * (ap[1] - ap[0]), bm[0] + fx * (bm[2] - bm[0])
                yp, ym = bp[1] + fy * (bp[3] - bp[1]), bm[1] + fy * (bm[3] - bm[1])
                if abs(xp - xm) > TOL_PX or abs(yp - ym) > TEXT_DY_PX:
                    problems.append(f"{pid}: label {t_page!r} ({part['ha']}, {part['va']}) at "
                                    f"({xp:.1f}, {yp:.1f}) in the page, ({xm:.1f}, {ym:.1f}) in matplotlib")
                continue
            if kind == "mark":
                bp, bm = pn[0]["box"], ma[0]["box"]
                cp = ((bp[0] + bp[2]) / 2, (bp[1] + bp[3]) / 2)
                cm = ((bm[0] + bm[2]) / 2, (bm[1] + bm[3]) / 2)
                if math.dist(cp, cm) > TOL_PX:
                    problems.append(f"{pid}: marker at ({cp[0]:.1f}, {cp[1]:.1f}) in the page, "
                                    f"({cm[0]:.1f}, {cm[1]:.1f}) in matplotlib")
                continue
            # path, ellipse, glyph, arrow: the geometry's box (strokes left out on both sides)
            bp, bm = _union([n["box"] for n in pn]), _union([a["box"] for a in ma])
            d = max(abs(u - v) for u, v in zip(bp, bm))
            if d > TOL_PX:
                problems.append(f"{pid} part {i} ({kind}): box {np.round(bp, 1).tolist()} in the page, "
                                f"{np.round(bm, 1).tolist()} in matplotlib ({d:.1f} px apart)")
    return problems


def overlapping_labels(page: dict) -> list[str]:
    """Pairs of visible element labels whose boxes (as the browser drew them) overlap."""
    boxes = [(e["id"], n["text"], n["box"]) for e in page["elements"] for n in e["nodes"]
             if n["tag"] == "text" and n["text"]]
    out = []
    for a in range(len(boxes)):
        for b in range(a + 1, len(boxes)):
            p, q = boxes[a][2], boxes[b][2]
            ox = min(p[2], q[2]) - max(p[0], q[0])
            oy = min(p[3], q[3]) - max(p[1], q[1])
            if ox > OVERLAP_PX and oy > OVERLAP_PX:
                out.append(f"{boxes[a][0]} {boxes[a][1]!r} and {boxes[b][0]} {boxes[b][1]!r} "
                           f"overlap by {ox:.1f} x {oy:.1f} px")
    return out


# --------------------------------------------------------------------------- the tests
def _explorers():
    import planargeo.widgets as pw

    return list(pw.EXPLORERS)


class PageView:
    """A :class:`~planargeo.widgets.canvas.PictureCanvas` in Python and one view of it in the harness page.

    The first picture opens the view from the widget's synced state (as a page that
    opens does); every later one reaches it as the update the widget makes of it.
    """

    def __init__(self, page):
        from planargeo.widgets.canvas import PictureCanvas

        self.page, self.canvas, self.opened = page, PictureCanvas(), False

    def show(self, pic: dict) -> dict:
        self.canvas.picture = pic
        if not self.opened:
            self.opened = True
            state = {k: v for k, v in self.canvas.get_state().items() if k in ("snapshot", "playing", "picture")}
            return self.page.evaluate("(s) => window.openView(s)", state)
        upd = self.canvas.last_update
        return self.page.evaluate("(m) => window.deliver(m)", {"type": "update", **(upd or {})})


def _drawn(harness_page, name):
    view = PageView(harness_page)
    for state, pic in visited_states(name):
        page = view.show(pic)
        page["below"] = harness_page.evaluate(PAGE_BELOW_JS)
        assert page["size"] == pic["size"], f"{name} {state}: the page's SVG is {page['size']}, not {pic['size']}"
        yield state, pic, page


@pytest.mark.parametrize("name", _explorers())
def test_page_and_matplotlib_draw_the_same(harness_page, name):
    failures = []
    for state, pic, page in _drawn(harness_page, name):
        failures += [f"{state}: {p}" for p in compare(pic, page, matplotlib_measure(pic))]
        failures += [f"{state}: {p}" for p in compare_below(pic, page["below"], matplotlib_below(pic))]
    assert not failures, f"{name}:\n" + "\n".join(failures)


#: explorers whose labels overlap in the page today (strict xfails: the entry goes when fixed)
LABELS_NOT_YET: dict[str, str] = {}


@pytest.mark.parametrize("name", [
    pytest.param(n, marks=pytest.mark.xfail(strict=True, reason=LABELS_NOT_YET[n])) if n in LABELS_NOT_YET
    else n for n in _explorers()])
def test_no_two_labels_overlap_in_the_page(harness_page, name):
    failures = []
    for state, _pic, page in _drawn(harness_page, name):
        failures += [f"{state}: {p}" for p in overlapping_labels(page)]
    assert not failures, f"{name}:\n" + "\n".join(failures)


def test_the_comparison_sees_a_pixel_moved(harness_page):
    """The check itself: a marker 2 px off, a label with other text, a missing element are each seen."""
    from planargeo.draw.picture import Picture

    def picture(px=0.0, text="P", extra=False):
        pic = Picture((-2, 2, -2, 2), size=(300, 300))
        pic.point("P", [1.0, -0.5 - px * 4 / pic.size[0], 0.0 + 1.0], role="twist", symbol=text, desc="a pole")
        pic.line("l", [0.0, 1.0, -0.3], role="wrench", symbol="l")
        if extra:
            pic.marks("m", [[0.0, 0.0]])
        return pic.to_dict()

    shown = PageView(harness_page).show(picture())
    assert compare(picture(), shown, matplotlib_measure(picture())) == []
    moved = compare(picture(), shown, matplotlib_measure(picture(px=2.0)))
    assert any("P: marker at" in p for p in moved), moved
    renamed = compare(picture(), shown, matplotlib_measure(picture(text="Q")))
    assert any("label 'P' in the page, 'Q' in matplotlib" in p for p in renamed), renamed
    more = compare(picture(extra=True), shown, matplotlib_measure(picture(extra=True)))
    assert any("missing ['m']" in p for p in more), more
    # lines below the plot: the same, then one moved 3 px down, then another text, in matplotlib
    pic = Picture((-2, 2, -2, 2), size=(300, 300))
    pic.below("key 1", ["P: a pole", "  and more"], color="#d62728", desc="key: P: a pole and more")
    d = pic.to_dict()
    PageView(harness_page).show(d)
    below = harness_page.evaluate(PAGE_BELOW_JS)
    assert len(below) == 2 and compare_below(d, below, matplotlib_below(d)) == []
    moved = {**d, "below": [d["below"][0], {**d["below"][1], "y": d["below"][1]["y"] + 3.0}]}
    assert any("below '  and more'" in p for p in compare_below(d, below, matplotlib_below(moved))), moved
    other = {**d, "below": [d["below"][0], {**d["below"][1], "text": "  and less"}]}
    assert compare_below(d, below, matplotlib_below(other))
