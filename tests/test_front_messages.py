"""A refusal is said whole: on the picture, wrapped onto lines inside the figure, and in the
message line, which reserves two lines and grows for a longer one (review H4: both were cut)."""
from __future__ import annotations

from planargeo.draw.picture import FONT_PX
from planargeo.widgets import ChainExplorer
from planargeo.widgets.slider_crank import SliderCrankExplorer

CHAR_PX = 0.6 * FONT_PX        # the widest a character of the label font is estimated at


def _message_lines(pic):
    (el,) = [e for e in pic["elements"] if e["id"] == "figure message"]
    return [p for p in el["parts"] if p["p"] == "text"]


def test_a_long_refusal_is_written_whole_inside_the_figure():
    ex = ChainExplorer(display="agg")
    typed = "fast, then faster, and then as fast as the chain can go without flying apart"
    ex.set(**{"joint speeds": typed})                   # refused, the typed text said back
    assert ex.message.startswith("joint speeds must be numbers") and typed in ex.figure_text
    pic = ex.picture()
    lines = _message_lines(pic)
    assert len(lines) >= 2
    # every word of the refusal, in order, none cut ("…" or "...")
    assert " ".join(p["text"] for p in lines).split() == ex.figure_text.split()
    assert not any(p["text"].endswith(("…", "...")) for p in lines)
    plot_px = pic["size"][0] - pic["margin"][0] - pic["margin"][1]
    for p in lines:                       # centred lines, each narrower than the plot
        assert p["ha"] == "center" and len(p["text"]) * CHAR_PX < plot_px
    dys = [p["dy"] for p in lines]        # one below the other, a line height apart
    assert all(a - b >= FONT_PX for a, b in zip(dys, dys[1:]))


def test_the_message_line_reserves_two_lines_and_is_never_cut():
    ex = SliderCrankExplorer(display="agg")
    box = ex.message_box.layout
    assert box.min_height == "2.8em"                    # nothing moves for a message of two lines
    assert box.height in (None, "", "auto") and box.max_height in (None, "")   # a longer one: grows
    assert box.overflow in (None, "", "visible")


def _key(pic):
    return {e["id"]: e for e in pic["elements"] if e["id"].startswith("key ")}


def test_the_key_says_each_meaning_whole_within_half_the_figure():
    ex = ChainExplorer(display="agg", key=True)
    pic = ex.picture()
    plot_px = pic["size"][0] - pic["margin"][0] - pic["margin"][1]
    entries = [e for k, e in _key(pic).items() if k != "key panel"]
    said = [" ".join(p["text"] for p in e["parts"] if p["p"] == "text").split() for e in entries]
    # the meaning of the joint forces, whole (it was cut to "…passes on to the body…")
    assert "f₁…f₄: force the joint passes on to the body outboard".split() in said
    for e in entries:
        assert e["desc"].startswith("key: ")
        texts = [p["text"] for p in e["parts"] if p["p"] == "text"]
        assert " ".join(texts).split() == e["desc"][5:].split()           # the whole entry
        assert all(len(t) <= max(40, plot_px / 2 / CHAR_PX) for t in texts)    # half the width


def _inside(xy, box):
    (u0, v0), (u1, v1) = xy.min(axis=0), xy.max(axis=0)
    return (box[:, 0] > u0) & (box[:, 0] < u1) & (box[:, 1] > v0) & (box[:, 1] < v1)


def test_the_key_covers_neither_the_chain_nor_its_forces_and_poles():
    import numpy as np

    ex = ChainExplorer(display="agg", key=True)
    pic = ex.picture()
    panel = np.asarray(_key(pic)["key panel"]["parts"][0]["xy"], float)
    for el in pic["elements"]:
        if el["id"] in ("links", "joints") or el["id"][0] in "fv":
            for q in el["parts"]:
                pts = np.asarray(q["xy"], float) if "xy" in q else np.array([[q["x"], q["y"]]])
                t = np.linspace(0.0, 1.0, 200)[:, None]       # points all along each segment
                dense = np.concatenate([pts[:1]] + [a + t * (b - a) for a, b in zip(pts[:-1], pts[1:])])
                assert not _inside(panel, dense).any(), el["id"]


def test_the_readout_says_each_unit_once():
    import html
    import re

    ex = ChainExplorer(display="agg")
    rows = [[html.unescape(re.sub("<[^>]+>", "", c)).strip() for c in re.findall(r"<td[^>]*>(.*?)</td>", r)]
            for r in re.findall(r"<tr>(.*?)</tr>", ex.readout.value)]
    by_name = {name: (value, unit) for name, value, unit in rows}
    assert by_name["kinetic energy"][1] == "J" and by_name["t"][1] == "s"
    assert by_name["|base force|"] == (f"{ex.readout_values['|base force| (N)']:.4g}", "N")
    for name, _value, unit in rows:            # never "kinetic energy (J) … J"
        assert not (unit and f"({unit})" in name), name
