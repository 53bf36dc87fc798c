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
