"""Checks on an explorer's picture data (``ex.picture()``), shared by the tests of the native explorers.

The label boxes are computed here from the plain picture data (the view, the pixel
size, each text's anchor, offset and alignment), with the same estimate of a text's
width the picture's placer uses (0.6 font sizes per character, 1.25 font sizes high);
a test that a label box is measured right is in tests/test_pictures_e2.py.
"""
from __future__ import annotations

import math
import re

import numpy as np

_AX = {"left": 0.0, "center": 0.5, "right": 1.0}
_AY = {"bottom": 0.0, "center": 0.5, "top": 1.0, "baseline": 0.0}


def elements(pic: dict) -> dict:
    """``{id: element}`` of a picture."""
    return {e["id"]: e for e in pic["elements"]}


def to_px(pic: dict, x: float, y: float) -> tuple[float, float]:
    """Pixels from the plot area's lower left (y up) of a data point."""
    x0, x1, y0, y1 = pic["box"]
    ml, mr, mt, mb = pic["margin"]
    w, h = pic["size"]
    return ((x - x0) / (x1 - x0) * (w - ml - mr), (y - y0) / (y1 - y0) * (h - mt - mb))


def label_boxes(pic: dict) -> list[tuple[str, str, tuple[float, float, float, float]]]:
    """``(element id, text, (x0, y0, x1, y1) pixels)`` of every shown text."""
    f = pic.get("font_px", 11.46)
    out = []
    for e in pic["elements"]:
        for part in e["parts"]:
            if part["p"] != "text" or part.get("hidden") or not part["text"]:
                continue
            qx, qy = to_px(pic, part["x"], part["y"])
            w, h = 0.6 * f * len(part["text"]), 1.25 * f
            bx = qx + part["dx"] - _AX[part["ha"]] * w
            by = qy + part["dy"] - _AY[part["va"]] * h
            out.append((e["id"], part["text"], (bx, by, bx + w, by + h)))
    return out


def overlapping_labels(pic: dict, tol: float = 0.5) -> list:
    """Pairs of shown texts whose boxes overlap by more than ``tol`` pixels both ways."""
    boxes = label_boxes(pic)
    out = []
    for i, (ida, ta, a) in enumerate(boxes):
        for idb, tb, b in boxes[i + 1:]:
            ox = min(a[2], b[2]) - max(a[0], b[0])
            oy = min(a[3], b[3]) - max(a[1], b[1])
            if ox > tol and oy > tol:
                out.append(((ida, ta), (idb, tb)))
    return out


#: elements the explorer base adds to every picture (the symbol key, a refusal's message): checked there
BASE_IDS = re.compile(r"key \d+|figure message")


def problems(pic: dict) -> list[str]:
    """What a student would find wrong in a picture: an element with no symbol or description, a
    description without a value ('meaning: value'), labels on top of each other, non-finite data."""
    out = []
    ids = [e["id"] for e in pic["elements"]]
    if len(ids) != len(set(ids)):
        out.append(f"ids used twice: {sorted({i for i in ids if ids.count(i) > 1})}")
    for e in pic["elements"]:
        if BASE_IDS.fullmatch(e["id"]):
            continue
        if not e.get("symbol"):
            out.append(f"{e['id']}: no symbol")
        desc = e.get("desc", "")
        if ":" not in desc:
            out.append(f"{e['id']}: description {desc!r} has no 'meaning: value'")
        for part in e["parts"]:
            for k in ("x", "y"):
                if k in part and not math.isfinite(part[k]):
                    out.append(f"{e['id']}: non-finite {k}")
            if "xy" in part and not np.all(np.isfinite(np.asarray(part["xy"], float))):
                out.append(f"{e['id']}: non-finite path")
    for a, b in overlapping_labels(pic):
        if not (BASE_IDS.fullmatch(a[0]) or BASE_IDS.fullmatch(b[0])):
            out.append(f"labels overlap: {a} and {b}")
    return out


def fill(pic: dict, pts) -> float:
    """The larger of the mechanism's extent over the view's width and over its height."""
    x0, x1, y0, y1 = pic["box"]
    pts = np.asarray(pts, float).reshape(-1, 2)
    return max(float(np.ptp(pts[:, 0])) / (x1 - x0), float(np.ptp(pts[:, 1])) / (y1 - y0))


def _arc(r: float, ccw: bool, n: int = 40) -> np.ndarray:
    """A pole glyph's 270° arc and head about the origin (pixels), drawn as the page does (-45° on)."""
    a0, span = math.radians(-45.0), math.radians(270.0)
    t = np.linspace(a0, a0 + span, n) if ccw else np.linspace(a0 + span, a0, n)
    arc = r * np.column_stack([np.cos(t), np.sin(t)])
    te = t[-1]
    tang = np.array([-math.sin(te), math.cos(te)]) * (1.0 if ccw else -1.0)
    nrm = np.array([math.cos(te), math.sin(te)])
    h = min(max(3.0, 0.45 * r), 6.0)
    end = arc[-1]
    return arc, np.array([end + tang * h, end - 0.5 * h * nrm, end + 0.5 * h * nrm, end + tang * h])


def strokes(pic: dict) -> list[tuple[str, np.ndarray]]:
    """``(element id, (n, 2) pixel polyline)`` of everything drawn with a line: paths, ellipses,
    pole glyphs (arc and head), arrows (shaft and head) and markers (their outline square)."""
    out = []
    for e in pic["elements"]:
        if e.get("color") == "none":
            continue
        eid = e["id"]
        for part in e["parts"]:
            k = part["p"]
            if k == "path":
                xy = np.asarray(part["xy"], float).reshape(-1, 2)
                if part.get("closed"):
                    xy = np.vstack([xy, xy[:1]])
                out.append((eid, np.array([to_px(pic, x, y) for x, y in xy])))
                continue
            if k in ("text",) or "x" not in part:
                continue
            q = np.array(to_px(pic, part["x"], part["y"]))
            if k == "ellipse":
                t = np.linspace(0.0, 2 * np.pi, 97)
                a, b, c, d = part["m"]
                xy = np.column_stack([part["x"] + a * np.cos(t) + b * np.sin(t),
                                      part["y"] + c * np.cos(t) + d * np.sin(t)])
                out.append((eid, np.array([to_px(pic, x, y) for x, y in xy])))
            elif k == "glyph":
                arc, head = _arc(part["r"], part["ccw"])
                out += [(eid, q + arc), (eid, q + head)]
            elif k == "arrow":
                tip = np.array([part["dx"], part["dy"]])
                hp = max(8.0, 4.0 * e["width"])
                u = tip / (float(np.hypot(*tip)) or 1.0)
                n = np.array([-u[1], u[0]])
                tri = [tip, tip - u * hp + n * 0.35 * hp, tip - u * hp - n * 0.35 * hp, tip]
                out += [(eid, q + np.array([[0.0, 0.0], tip - u * 0.8 * hp])), (eid, q + np.array(tri))]
            elif k == "mark":
                s = part["size"] / 2
                out.append((eid, q + np.array([[-s, -s], [s, -s], [s, s], [-s, s], [-s, -s]])))
    return out


def _meets(xy: np.ndarray, box, tol: float) -> bool:
    """Whether a polyline passes through a box shrunk by ``tol`` pixels (Liang-Barsky per segment)."""
    x0, y0, x1, y1 = box[0] + tol, box[1] + tol, box[2] - tol, box[3] - tol
    if x0 >= x1 or y0 >= y1:
        return False
    a, b = xy[:-1], xy[1:]
    keep = ~((np.maximum(a[:, 0], b[:, 0]) < x0) | (np.minimum(a[:, 0], b[:, 0]) > x1)
             | (np.maximum(a[:, 1], b[:, 1]) < y0) | (np.minimum(a[:, 1], b[:, 1]) > y1))
    for (px, py), (qx, qy) in zip(a[keep], b[keep]):
        t0, t1, dx, dy = 0.0, 1.0, qx - px, qy - py
        for p, q in ((-dx, px - x0), (dx, x1 - px), (-dy, py - y0), (dy, y1 - py)):
            if p == 0:
                if q < 0:
                    break
            else:
                r = q / p
                if p < 0:
                    t0 = max(t0, r)
                else:
                    t1 = min(t1, r)
        else:
            if t0 <= t1:
                return True
    return False


def crossed_labels(pic: dict, tol: float = 1.0, skip=BASE_IDS) -> list[tuple[str, str, str]]:
    """``(element id, label text, other element id)`` for each shown label whose box (shrunk by
    ``tol`` pixels) is crossed by another element's stroke (:func:`strokes`) or meets another
    element's text box.  Texts written at a fixed place (not placed) are obstacles only; elements
    whose id ``skip`` matches (the base's key and message) are left out."""
    boxes = [b for b in label_boxes(pic) if not (skip and skip.fullmatch(b[0]))]
    lines = [s for s in strokes(pic) if not (skip and skip.fullmatch(s[0]))]
    fixed = {(e["id"], p["text"]) for e in pic["elements"] for p in e["parts"] if p["p"] == "text" and p.get("fixed")}
    out = []
    for eid, text, box in boxes:
        if (eid, text) in fixed:         # written at a fixed place (a key's row): not the placer's
            continue
        hits = {oid for oid, xy in lines if oid != eid and _meets(xy, box, tol)}
        hits |= {oid for oid, _t, b in boxes if oid != eid and min(box[2], b[2]) - max(box[0], b[0]) > tol
                 and min(box[3], b[3]) - max(box[1], b[1]) > tol}
        out += [(eid, text, oid) for oid in sorted(hits)]
    return out
