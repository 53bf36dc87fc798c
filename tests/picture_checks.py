"""Checks on an explorer's picture data (``ex.picture()``): elements by id, label boxes, descriptions.

Shared by the car, slider-crank and trees tests.  Label boxes are estimated from the
picture's font size (0.6 em per character, 1.25 em high), independently of the placer.
"""
from __future__ import annotations

import re

import numpy as np

#: a description ends with a value and its unit, or says where something is
VALUE = re.compile(r"\d")


def elements(pic: dict) -> dict:
    """``{id: element}`` of a picture's data."""
    return {e["id"]: e for e in pic["elements"]}


def parts(el: dict, kind: str) -> list:
    """The parts of one kind (``"path"``, ``"arrow"``, ``"text"``, ``"mark"``...) of an element."""
    return [p for p in el["parts"] if p["p"] == kind]


def shown_labels(pic: dict) -> list:
    """``[(element id, text)]`` of the labels drawn (not hidden)."""
    return [(e["id"], p["text"]) for e in pic["elements"] for p in e["parts"]
            if p["p"] == "text" and not p.get("hidden") and p["text"]]


def _overlay(el: dict) -> bool:
    """The base's overlays on the picture (a refusal's message, the key), not the explorer's labels."""
    return el["id"] == "figure message" or el["id"].startswith("key ")


def label_boxes(pic: dict) -> list:
    """``[(text, (x0, y0, x1, y1))]`` pixel boxes of the drawn labels (from the plot area's lower left).

    The base's overlays (a refusal's message, the key) are left out.
    """
    x0, x1, y0, y1 = pic["box"]
    w, h = pic["size"]
    ml, mr, mt, mb = pic["margin"]
    kx, ky = (w - ml - mr) / (x1 - x0), (h - mt - mb) / (y1 - y0)
    fpx = pic["font_px"]
    out = []
    for e in pic["elements"]:
        if _overlay(e):
            continue
        for p in e["parts"]:
            if p["p"] != "text" or p.get("hidden") or not p["text"]:
                continue
            bw, bh = 0.6 * fpx * len(p["text"]), 1.25 * fpx
            qx = (p["x"] - x0) * kx + p["dx"] - {"left": 0.0, "center": 0.5, "right": 1.0}[p["ha"]] * bw
            qy = (p["y"] - y0) * ky + p["dy"] - {"bottom": 0.0, "center": 0.5, "top": 1.0}[p["va"]] * bh
            out.append((p["text"], (qx, qy, qx + bw, qy + bh)))
    return out


def overlapping_labels(pic: dict, tol: float = 0.5) -> list:
    """Pairs of drawn labels whose boxes overlap by more than ``tol`` pixels both ways."""
    boxes = label_boxes(pic)
    bad = []
    for i in range(len(boxes)):
        for j in range(i + 1, len(boxes)):
            a, b = boxes[i][1], boxes[j][1]
            if min(a[2], b[2]) - max(a[0], b[0]) > tol and min(a[3], b[3]) - max(a[1], b[1]) > tol:
                bad.append((boxes[i][0], boxes[j][0]))
    return bad


def undescribed(pic: dict) -> list:
    """Ids of elements without a symbol, or with a description giving no value."""
    return [e["id"] for e in pic["elements"] if not _overlay(e) and (
            not e.get("symbol") or not e.get("desc") or not VALUE.search(e["desc"]))]


def on_line(xy, a, b, tol: float = 1e-6) -> bool:
    """Whether the point ``xy`` lies on the line through ``a`` and ``b`` (relative tolerance)."""
    a, b, xy = (np.asarray(v, float) for v in (a, b, xy))
    d = b - a
    n = np.array([-d[1], d[0]]) / np.hypot(*d)
    return abs(float((xy - a) @ n)) <= tol * max(1.0, float(np.hypot(*d)))


def px_per_unit(pic: dict) -> float:
    """Pixels per data unit of a picture (one scale on both axes)."""
    x0, x1, _y0, _y1 = pic["box"]
    return (pic["size"][0] - pic["margin"][0] - pic["margin"][1]) / (x1 - x0)


def drawn_arrow(pic: dict, eid: str):
    """``(vector, middle)`` of an element's arrow in data units, or None when it has no arrow."""
    arrows = parts(elements(pic)[eid], "arrow")
    if not arrows:
        return None
    (a,) = arrows
    vec = np.array([a["dx"], a["dy"]]) / px_per_unit(pic)
    return vec, np.array([a["x"], a["y"]]) + vec / 2


def text_of(pic: dict, eid: str) -> str:
    """The text of a text element (a banner, the figure message), "" when there is none."""
    el = elements(pic).get(eid)
    return "" if el is None else parts(el, "text")[0]["text"]
