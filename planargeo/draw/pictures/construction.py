"""The construction explorer's picture: chapter 4's constructions step by step (thesis 4.2–4.7, 10.2.4).

The elements of steps ``1 … k``, the last at full strength and the earlier ones faded,
shown or hidden, with the step's caption in a band at the bottom of the view.

Examples
--------
>>> from planargeo.scenes.construction import construct
>>> c = construct("twist_sum", x1=0.0, y1=0.0, w1=1.0, x2=3.0, y2=0.0, w2=3.0)
>>> d = construction_picture(c, step=3, view=(-4, 4, -4, 4)).to_dict()
>>> els = {e["id"]: e for e in d["elements"]}
>>> v3 = els["v3"]["parts"][0]; (v3["x"], v3["y"])          # β = 3/4 of the way from Q₁ to Q₂ (4.12)
(2.25, 0.0)
>>> els["v3"]["symbol"], els["v3"]["desc"]
('v₃ = v₁ + v₂', 'sum v₃ = v₁ + v₂ (4.11–4.13): rate 4 rad/s, at (2.25, 0) m')
"""
from __future__ import annotations

import math
import textwrap

import numpy as np

from planargeo.draw.picture import FONT_PX, PX_PER_PT, Picture, _align, _glyph_radius, plain_text
from planargeo.draw.pictures._words import num, where, words_data
from planargeo.draw.pictures.common import builder, label_line, label_toward
from planargeo.draw.pictures.kit import label_at
from planargeo.draw.style import COLORS, SUM
from planargeo.geometry.projective import is_at_infinity, is_ideal
from planargeo.screws.inertia import mass, radius_of_gyration

__all__ = ["construction_picture", "MEANINGS", "FADED", "CAPTION_CHARS"]

#: opacity of the earlier steps when they are faded
FADED = 0.4
#: characters per caption line (two lines at most)
CAPTION_CHARS = 70

#: per construction and element name: its meaning with its equation, or (symbol, meaning) for an
#: element drawn without a label (an element's symbol is its label, the thesis symbol); kept as data
MEANINGS = {kind: {k: tuple(v) if isinstance(v, list) else v for k, v in table.items()}
            for kind, table in words_data("construction")["elements"].items()}
_RATE_UNIT = {"twist": "rad/s", "accel": "rad/s²"}
#: labels whose symbol :func:`~planargeo.draw.picture.plain_text` cannot write (no Unicode superscript e, t)
_SYMBOLS = {r"$f^{net}$": "fⁿᵉᵗ"}


def _symbol(label: str) -> str:
    """The thesis symbol of a mathtext label (superscript words the Unicode table lacks, by hand)."""
    return _SYMBOLS.get(label) or plain_text(label)


def _value(e) -> str:
    """The element's value in words (a pole's rate and place, a force's size and line, a construction
    line's place, a length)."""
    v = np.asarray(e.value, float)
    if e.kind == "point":
        unit = _RATE_UNIT.get(e.role)
        return (f"rate {num(v[2])} {unit}, " if unit and not bool(is_ideal(v)) else
                "a translation, " if unit else "") + where(v)
    if e.kind == "line":
        F = math.hypot(v[0], v[1])
        if e.role == "construct":    # a line of the construction (a join of poles): no size, no unit
            return ("the line at infinity" if bool(is_at_infinity(v)) else
                    f"a line {num(abs(v[2]) / F)} m from the origin")
        if bool(is_at_infinity(v)):
            return f"a couple of {num(v[2])} N·m (the line at infinity)"
        return f"|force| {num(F)} N, {num(abs(v[2]) / F)} m from the origin"
    if e.kind == "segment":
        return f"length {num(float(np.hypot(*(v[1] - v[0]))))} m"
    if e.role == "inertia":
        return f"mass {num(mass(v))} kg, radius of gyration {num(radius_of_gyration(v))} m"
    return f"radius {num(math.sqrt(-v[2, 2] / v[0, 0]))} m" if v[0, 0] > 0 > v[2, 2] else ""


def _frame(c, upto: int):
    """``(centroid, n)``: the finite poles' centroid and the upward normal of the line along them."""
    P = np.array([[-e.value[1] / e.value[2], e.value[0] / e.value[2]] for e in c.elements(upto)
                  if e.kind == "point" and e.value[2] != 0] or [[0.0, 0.0]])
    m = P.mean(axis=0)
    spread = len(P) > 1 and np.ptp(P, axis=0).max() > 0
    d = np.linalg.svd(P - m)[2][0] if spread else np.array([1.0, 0.0])     # the line's direction
    n = np.array([-d[1], d[0]])
    if n[1] < 0 or (n[1] == 0 and n[0] < 0):
        n = -n
    return m, n


def caption_lines(text: str) -> list[str]:
    """The caption in at most two lines of :data:`CAPTION_CHARS` (the second ends in … when cut).

    Parameters
    ----------
    text : str

    Returns
    -------
    list of str
    """
    lines = textwrap.wrap(text, CAPTION_CHARS)
    if len(lines) > 2:
        lines = [lines[0], textwrap.shorten(" ".join(lines[1:]), CAPTION_CHARS, placeholder=" …")]
    return lines


@builder
def construction_picture(c, *, step: int, earlier: str = "faded", view, size=(560, 560),
                         all_steps: bool = False, caption: str | None = None,
                         band_below: bool = True) -> Picture:
    """The picture of steps ``1 … step`` of the construction ``c`` (module docstring).

    Parameters
    ----------
    c : Construction
        From :func:`planargeo.scenes.construction.construct`.
    step : int
        The step shown (clipped to the construction's steps).
    earlier : {"faded", "shown", "hidden"}
        How the earlier steps look.
    all_steps : bool
        Every step at full strength (the layered export).
    caption : str, optional
        The caption (default: ``Step k/n: <the step's caption>``).
    band_below : bool
        Add the caption's band below ``view``; False: ``view`` (zoomed or panned) holds the band.
    """
    n = len(c.steps)
    k = min(max(int(step), 1), n)
    shown = n if all_steps else k
    if all_steps:
        earlier = "shown"
    if caption is None:
        caption = f"Step {k}/{n}: {c.steps[k - 1].caption}"
    lines = caption_lines(caption)
    x0, x1, y0, y1 = (float(v) for v in view)
    ml, mr, mt, mb = 44.0, 12.0, 10.0, 30.0
    band_px = len(lines) * 1.3 * FONT_PX + 10.0       # the caption's band, below the drawing
    if band_below:
        kx = (size[0] - ml - mr) / (x1 - x0)
        ky = (size[1] - mt - mb - band_px) / (y1 - y0)
        y0 -= band_px / min(kx, ky)
    pic = Picture((x0, x1, y0, y1), size=size, margin=(ml, mr, mt, mb))
    bx0, bx1, by0, by1 = pic.box
    band_top = by0 + band_px / pic.ky
    # one element: the band (white, a thin frame) and the caption's lines in it, at a fixed place
    # (the label placer moves none of them: a line moved off a stroke crossing the band left it and
    # was drawn over the plot; the drawing's labels keep clear of them)
    pic.path("caption", [[bx0, by0], [bx1, by0], [bx1, band_top], [bx0, band_top]], role="text",
             closed=True, fill="#FFFFFF", color="#444444", width=0.6, z=20, symbol="step",
             desc=f"the step shown: {caption}")
    for i, line in enumerate(lines):
        label_at(pic, (bx0, band_top), line, gap=6.0, dy=-5.0 - 1.3 * FONT_PX * i, va="top")
        pic.elements[-1]["parts"][-1]["fixed"] = True
    centre, nrm = _frame(c, shown)
    view_centre = np.array([(x0 + x1) / 2, (y0 + y1) / 2])
    lines_labelled = 0
    for i in range(shown):
        if earlier == "hidden" and i != shown - 1:
            continue
        faded = earlier == "faded" and i != shown - 1
        for e in c.steps[i].elements:
            label = _symbol(e.label) if e.label else ""
            text = MEANINGS.get(c.kind, {}).get(e.name, e.name)
            sym, meaning = text if isinstance(text, tuple) else ("", text)
            sym = label or sym
            desc = f"{meaning}: {_value(e)}" if _value(e) else meaning
            v = np.asarray(e.value, float)
            if e.kind == "point":
                glyph = e.role in ("twist", "accel")
                kw = dict(shape="D", size=SUM["point"]["markersize"] * PX_PER_PT) if e.emphasis else {}
                pic.point(e.name, v, role=e.role if glyph else "twist", glyph=glyph, symbol=sym,
                          label=label or sym, desc=desc, color=None if glyph else COLORS.get(e.role, COLORS["text"]),
                          **kw)
                if label and not bool(is_ideal(v)):
                    xy = np.array([-v[1] / v[2], v[0] / v[2]])
                    u = -nrm if e.emphasis else nrm
                    away = xy - centre
                    if not e.emphasis and np.hypot(*away) > 1e-9:
                        away = away / np.hypot(*away)
                        if abs(away @ nrm) < 0.3:
                            u = away
                    r = _glyph_radius(v[2]) if glyph else 0.0
                    label_toward(pic.elements[-1], u, (7.0 + 0.75 * r) * PX_PER_PT)
            elif e.kind == "line":
                anchor = None
                if np.any(v[:2]):   # labelled lines' arrows and labels spread along them
                    f = v[:2] / np.hypot(*v[:2])
                    foot = np.array([v[2] * f[1], -v[2] * f[0]]) / np.hypot(*v[:2])
                    foot = foot + ((view_centre - foot) @ f) * f
                    if label:
                        anchor = foot + (1.1 * lines_labelled - 0.8) * f
                        lines_labelled += 1
                pic.line(e.name, v, role=e.role, symbol=sym, label="", desc=desc, anchor=anchor,
                         arrow=e.role != "construct",
                         width=SUM["line"]["linewidth"] * PX_PER_PT if e.emphasis else None)
                if bool(is_at_infinity(v)):
                    # the line at infinity: a couple (a wrench), or the join of two ideal poles;
                    # drawn in the lower right corner, above the caption (the upper edge has the
                    # arrows of ideal points)
                    what = "couple (line at ∞)" if e.role != "construct" else "the line at ∞"
                    for part in pic.elements[-1]["parts"]:
                        if part["p"] == "text":
                            part["text"] = ((label or sym) + ": " if (label or sym) else "") + what
                        if part["p"] in ("text", "glyph"):
                            part["y"] = band_top + 26.0 / pic.ky
                elif label:
                    label_line(pic, e.name, label, anchor=anchor)
            elif e.kind == "conic":
                pic.conic(e.name, v, role=e.role, symbol=sym, label=label, desc=desc)
            else:   # a segment, with its label beside its middle
                (a, b) = v
                construct = e.role == "construct"
                pic.path(e.name, v, role=e.role, symbol=sym, desc=desc, z=3,
                         color=COLORS.get(e.role, COLORS["construct"]),
                         width=(1.2 if construct else 1.6) * PX_PER_PT,
                         dash=[4.0 * PX_PER_PT, 3.0 * PX_PER_PT] if construct else None)
                if label:
                    d = (b - a) * np.array([pic.kx, pic.ky])
                    u = np.array([-d[1], d[0]]) / max(math.hypot(*d), 1e-300)
                    ha, va = _align(u)
                    label_at(pic, (a + b) / 2, label, gap=float(u[0] * 8), dy=float(u[1] * 8), ha=ha, va=va)
            if faded:
                pic.elements[-1]["opacity"] = FADED
            pic.elements[-1]["step"] = i + 1
    return pic
