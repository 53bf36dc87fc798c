"""The label placer of :class:`planargeo.draw.picture.Picture`: labels kept off lines, glyphs and labels.

Every element's drawn strokes (paths, ellipses, pole glyphs, arrows, markers) are sampled every
:data:`STEP` pixels and counted in a raster of :data:`CELL`-pixel cells; a summed-area table of the
counts tells, for every spot of every label at once, whether a stroke passes through the cells whose
centres lie in its box (less :data:`TOL`).  A spot is clear when none does (its own element's
strokes count too: the spots beside a line or a pole are off it).  An element written with
``Picture.text(..., obstacle=False)`` (a refusal's words and the panel drawn with them) is none.

Labels are placed topmost first.  Each tries its asked spot, then (the label of a line) spots
beside its line on either side, up to six label heights along it, then two rings of eight around
its anchor; it takes the first that is clear and meets no label placed before it.  With none
clear, it takes the free one that covers the fewest samples (it then crosses some stroke); with
none free among its best :data:`_TRIES`, it hides (its element keeps its hover text).

Examples
--------
>>> from planargeo.draw.picture import Picture
>>> pic = Picture((-2, 2, -2, 2), size=(300, 300), ticks=False)
>>> pic.line("f", [1.0, 0.0, 0.0], symbol="f")       # the x axis: its label 12 px on, 8 px above
>>> pic.to_dict()["elements"][0]["parts"][-1]["dx"]
12.0
>>> pic.line("g", [0.0, 1.0, 0.2], symbol="g")       # the line x = 0.2, 14 px right of the centre
>>> [p["dx"] for e in pic.to_dict()["elements"] for p in e["parts"] if p["p"] == "text"]  # f's slid on
[40.65, -8.0]
"""
from __future__ import annotations

import math
import sys
from operator import itemgetter

import numpy as np

#: Pixels between samples along a stroke, and the raster's cell size (pixels).
STEP, CELL = 3.0, 4.0
#: A stroke may graze a label box's edge by this many pixels, and about half a cell more (the box
#: is 1.25 font sizes high and 0.6 of one per character: room around its text).
TOL = 1.0


def _align(n) -> tuple[str, str]:
    """Text alignment for a label put beside an anchor in the pixel direction ``n``."""
    ha = "left" if n[0] > 0.3 else "right" if n[0] < -0.3 else "center"
    va = "bottom" if n[1] > 0.3 else "top" if n[1] < -0.3 else "center"
    return ha, va


ALIGN_X = {"left": 0.0, "center": 0.5, "right": 1.0}
ALIGN_Y = {"bottom": 0.0, "center": 0.5, "top": 1.0}
_ANGLES = np.deg2rad([45, 135, 225, 315, 0, 90, 180, 270])
_DIR = np.column_stack([np.cos(_ANGLES), np.sin(_ANGLES)])
_HA, _VA = zip(*map(_align, _DIR))
#: the eight spots around an anchor: direction and the box's left edge and bottom in box sizes
_FX = np.array([ALIGN_X[a] for a in _HA])
_FY = np.array([ALIGN_Y[a] for a in _VA])
#: slides of a line's label: the side (+1 the asked one) and the shift along the line (label heights × 2)
_SIDE = np.array([1, 1, 1, 1, 1, 1, -1, -1, -1, -1, -1, -1, -1], float)
_SHIFT = np.array([1, -1, 2, -2, 3, -3, 0, 1, -1, 2, -2, 3, -3], float)
#: the rings' spots: direction, radius (the asked distance, plus one label height for the second
#: ring) and the box's left edge and bottom in box sizes
_RING_X, _RING_Y = np.tile(_DIR[:, 0], 2), np.tile(_DIR[:, 1], 2)
_RADII, _REACH = np.ones(16), np.repeat([0.0, 1.0], 8)
_FX2, _FY2 = np.tile(_FX, 2), np.tile(_FY, 2)
_NOT_ALONG = (0.0, 0.0)
_HA_OF = {0.0: "left", 0.5: "center", 1.0: "right"}
_VA_OF = {0.0: "bottom", 0.5: "center", 1.0: "top"}
#: how many of a label's spots, best first, are tried before it hides
_TRIES = 12
#: the first ring's column among a label's candidate spots (the asked one, then the slides)
_RING = 1 + len(_SIDE)
#: a pole glyph (planargeo.draw.geometry.arc_glyph): its 270° arc, per unit radius
_T = np.deg2rad(np.linspace(-45.0, 225.0, 19))
_ARC = np.column_stack([np.cos(_T), np.sin(_T)])


def _glyph_templates():
    """A pole glyph's polyline as ``r × R + hd × HD`` (radius r, head length hd), clockwise and counter-clockwise."""
    R, HD = [], []
    for ccw in (False, True):
        end = _ARC[-1] if ccw else _ARC[0]
        side = (1.0 if ccw else -1.0) * end[::-1] * (-1.0, 1.0)     # across the arc's end
        R.append(np.vstack([_ARC if ccw else _ARC[::-1], end, end, end, end]))
        HD.append(np.vstack([np.zeros_like(_ARC), side, -0.5 * end, 0.5 * end, side]))
    return np.array(R), np.array(HD)


_GLYPH_R, _GLYPH_HD = _glyph_templates()
_CIRCLE = np.column_stack([np.cos(np.linspace(0, 2 * np.pi, 33)), np.sin(np.linspace(0, 2 * np.pi, 33))])
_SQUARE = np.array([[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0], [-1.0, -1.0]])


def _gather(pic) -> tuple[tuple, list, list]:
    """One pass over the parts: the strokes by kind, the fixed texts' boxes to keep clear of, the labels."""
    paths, glyphs, arrows, marks, ellipses = [], [], [], [], []
    texts, free = [], []
    for el in pic.elements:
        stroke = el["color"] != "none" and el.get("obstacle", True)      # not Picture.text(obstacle=False)
        for part in el["parts"]:
            p = part["p"]
            if p == "text":
                if not part["text"]:
                    continue
                if not part.get("fixed"):
                    free.append((-el["z"], part))
                elif not part.get("over"):
                    texts.append(part)
            elif not stroke:
                continue
            elif p == "path":
                xy = part["xy"]
                if part.get("closed"):
                    xy = np.vstack([xy, xy[:1]])
                paths.append(xy)
            elif p == "mark":
                marks.append((part["x"], part["y"], part["size"] / 2))
            elif p == "arrow":
                arrows.append((part["x"], part["y"], part["dx"], part["dy"], el["width"]))
            elif p == "glyph":
                glyphs.append((part["x"], part["y"], part["r"], part["ccw"]))
            elif p == "ellipse":
                ellipses.append((part["x"], part["y"], *part["m"]))
    return (paths, glyphs, arrows, marks, ellipses), texts, free


def _polylines(pic, kinds) -> tuple[np.ndarray, np.ndarray]:
    """``(xy, ends)``: the strokes gathered by :func:`_gather` as pixel polylines one after another,
    and where each but the last ends (its last point starts no segment)."""
    paths, glyphs, arrows, marks, ellipses = kinds
    bx0, by0, kx, ky = pic.box[0], pic.box[2], pic.kx, pic.ky
    pieces, ends = [], []
    if paths:
        xy = np.concatenate(paths)
        pieces.append((xy - (bx0, by0)) * (kx, ky))
        ends.append(np.cumsum([len(q) for q in paths]) - 1)

    def at(q):           # (m, 1, 2) pixel anchors
        return ((q[:, :2] - (bx0, by0)) * (kx, ky))[:, None, :]

    polys = []
    if glyphs:           # the arc, then the head at its end (planargeo.draw.geometry.arc_glyph)
        q = np.array(glyphs, float)
        r = q[:, 2, None, None]
        ccw = (q[:, 3] > 0).astype(np.intp)
        polys.append(at(q) + r * _GLYPH_R[ccw] + np.clip(0.45 * r, 3.0, 6.0) * _GLYPH_HD[ccw])
    if arrows:           # the shaft and the head's triangle (the page's: max(8, 4 × width) long)
        q = np.array(arrows, float)
        v, hp = q[:, 2:4], np.maximum(8.0, 4.0 * q[:, 4])
        u = v / np.maximum(np.hypot(v[:, 0], v[:, 1]), 1e-9)[:, None] * hp[:, None]
        n = u[:, ::-1] * (-0.35, 0.35)
        polys.append(at(q) + np.stack([0.0 * v, v, v - u + n, v - u - n, v], axis=1))
    if marks:
        q = np.array(marks, float)
        polys.append(at(q) + q[:, 2, None, None] * _SQUARE)
    if ellipses:
        q = np.array(ellipses, float)                       # x, y and the matrix a, b, c, d
        ex = _CIRCLE[:, 0] * q[:, None, 2] + _CIRCLE[:, 1] * q[:, None, 3]
        ey = _CIRCLE[:, 0] * q[:, None, 4] + _CIRCLE[:, 1] * q[:, None, 5]
        polys.append(at(q) + np.stack([ex * kx, ey * ky], axis=-1))
    start = len(pieces[0]) if pieces else 0
    for q in polys:      # (m, k, 2) pixel polylines
        m, k = q.shape[:2]
        pieces.append(q.reshape(-1, 2))
        ends.append(np.arange(start + k - 1, start + m * k, k))
        start += m * k
    if not pieces:
        return np.zeros((0, 2)), np.zeros(0, np.intp)
    return np.concatenate(pieces), np.concatenate(ends)[:-1]


def _table(pic, kinds=None) -> np.ndarray:
    """Summed-area table (``rows + 1, cols + 1``) of the stroke samples in each raster cell."""
    pw, ph = pic._plot
    xy, ends = _polylines(pic, _gather(pic)[0] if kinds is None else kinds)
    d = np.diff(xy, axis=0)
    n = (np.hypot(d[:, 0], d[:, 1]) * (1.0 / STEP)).astype(np.intp) + 2      # samples of each segment
    n[ends] = 0                   # none from a polyline's end to the next one's start
    return _compiled(_count)(xy, d, n, int(pw // CELL) + 1, int(ph // CELL) + 1)


def _count(xy, d, n, nx, ny):
    """:func:`_table` from the segments ``xy[s] → xy[s] + d[s]`` (pixels), ``n[s]`` samples each."""
    count = np.zeros((ny + 2, nx + 2), np.int64)     # columns -1 … nx and rows -1 … ny: the samples
    for s in range(len(n)):                          # outside the raster in the first or last ones
        for k in range(n[s]):
            t = k / (n[s] - 1.0)
            i = math.floor(min(max((d[s, 0] * t + xy[s, 0]) * (1.0 / CELL), -1.0), nx))
            j = math.floor(min(max((d[s, 1] * t + xy[s, 1]) * (1.0 / CELL), -1.0), ny))
            count[j + 1, i + 1] += 1
    table = count[:ny + 1, :nx + 1]    # the first row and column (below or left of the raster) become
    table[0] = 0                       # the table's zero row and column
    table[:, 0] = 0
    for j in range(ny + 1):
        for i in range(1, nx + 1):
            table[j, i] += table[j, i - 1]
    for j in range(1, ny + 1):
        table[j] += table[j - 1]
    return table


def _place(q, a0, g0, r0, view, table, boxes, p):
    """The labels' spots, in order (:func:`place_labels`): ``(m, 5)`` rows of the spot taken (0 the
    asked one; -1: none free) and its offset and box corner ``dx, dy, fx, fy``.

    ``q``: the labels' anchors, asked offsets, alignments, lengths and line directions, with the
    asked offset along the line ``a0``, its distance from it ``g0`` and its length ``r0`` (at least
    6 px); ``view``: the view's corner and scale, the label sizes and the plot area;
    ``boxes[:p]``: the fixed texts' boxes (the placed labels' are added after them).
    """
    bx0, by0, kx, ky, em, h, pw, ph = view
    ny, nx = table.shape[0] - 1, table.shape[1] - 1
    n = _RING + 16
    out = np.full((len(q), 5), -1.0)
    dx, dy, fx, fy = np.empty(n), np.empty(n), np.empty(n), np.empty(n)    # a label's spots: offsets, box
    x0, y0, rank = np.empty(n), np.empty(n), np.empty(n)                  # corners, boxes, ranks
    for i in range(len(q)):
        w, ux, uy = em * q[i, 6], q[i, 7], q[i, 8]
        flat = g0[i] < 1e-9       # the slides' sides: across the line, away from the asked spot
        sx = -uy if flat else (q[i, 2] - a0[i] * ux) / g0[i]
        sy = ux if flat else (q[i, 3] - a0[i] * uy) / g0[i]
        g = max(0.0 if flat else g0[i], 6.0)
        dx[0], dy[0], fx[0], fy[0] = q[i, 2], q[i, 3], q[i, 4], q[i, 5]
        for j in range(1, n):
            if j < _RING:         # a slide along the line
                vx, vy, t = _SIDE[j - 1] * sx, _SIDE[j - 1] * sy, a0[i] + _SHIFT[j - 1] * (2.0 * h)
                dx[j], dy[j] = t * ux + g * vx, t * uy + g * vy
                fx[j] = 0.0 if vx > 0.3 else 1.0 if vx < -0.3 else 0.5
                fy[j] = 0.0 if vy > 0.3 else 1.0 if vy < -0.3 else 0.5
            else:                 # a spot on a ring
                r = r0[i] * _RADII[j - _RING] + _REACH[j - _RING] * h
                dx[j], dy[j], fx[j], fy[j] = r * _RING_X[j - _RING], r * _RING_Y[j - _RING], _FX2[j - _RING], _FY2[j - _RING]
        for j in range(n):
            x0[j] = (q[i, 0] - bx0) * kx + dx[j] - fx[j] * w
            y0[j] = (q[i, 1] - by0) * ky + dy[j] - fy[j] * h
            x1, y1 = x0[j] + w, y0[j] + h
            if not (x0[j] >= 0.0 and y0[j] >= 0.0 and x1 <= pw and y1 <= ph) or (
                    0 < j < _RING and ux == 0.0 and uy == 0.0):       # slides: labels of lines only
                rank[j] = np.inf
                continue
            # clear of strokes: the cells whose centres lie in the box (less TOL) hold no sample
            i0 = int(min(max((x0[j] + TOL) * (1.0 / CELL) + 0.5, 0.0), nx))
            i1 = int(min(max((x1 - TOL) * (1.0 / CELL) + 0.5, 0.0), nx))
            j0 = int(min(max((y0[j] + TOL) * (1.0 / CELL) + 0.5, 0.0), ny))
            j1 = int(min(max((y1 - TOL) * (1.0 / CELL) + 0.5, 0.0), ny))
            cnt = table[j1, i1] - table[j0, i1] - table[j1, i0] + table[j0, i0]
            # the clear spots in their order, then the others by how many stroke samples they cover
            rank[j] = j if cnt == 0 else (cnt + 1.0) * n + j
        order = np.argsort(rank)
        for k in range(_TRIES):   # the first that meets no box placed before
            j = order[k]
            if rank[j] == np.inf:
                break
            x1, y1 = x0[j] + w, y0[j] + h
            c = 0
            while c < p and not (x0[j] < boxes[c, 2] and boxes[c, 0] < x1 and y0[j] < boxes[c, 3] and boxes[c, 1] < y1):
                c += 1
            if c == p:
                boxes[p, 0], boxes[p, 1], boxes[p, 2], boxes[p, 3] = x0[j], y0[j], x1, y1
                p += 1
                out[i, 0], out[i, 1], out[i, 2], out[i, 3], out[i, 4] = j, dx[j], dy[j], fx[j], fy[j]
                break
    return out


_JIT: dict = {}


def _compiled(f):
    """``f`` compiled by numba (imported with the first picture; the machine code cached on disk)."""
    if f not in _JIT:
        from numba import njit

        _JIT[f] = jit = njit(cache=True, nogil=True)(f)
        interactive = "ipykernel" in sys.modules or getattr(sys.stderr, "isatty", lambda: False)()
        if interactive and not _cached(jit):
            print("planargeo: compiling the label placer for this machine (once; a few seconds). "
                  "`make install` does it ahead of time.", file=sys.stderr, flush=True)
    return _JIT[f]


def _cached(jit) -> bool:
    """Whether ``jit`` needs no compiling: numba's cache holds its code for the current source, or
    numba is off (``NUMBA_DISABLE_JIT=1``: plain Python)."""
    if not hasattr(jit, "_cache"):
        return True
    try:
        return bool(jit._cache._cache_file._load_index())
    except Exception:                                      # (unreadable or foreign files: not cached)
        return False


def loops_cached() -> bool:
    """Whether the placer's two loops need no compiling (in numba's cache, or numba off); compiles nothing."""
    return all(_cached(_compiled(f)) for f in (_count, _place))


def place_labels(pic, font_px: float, char_em: float) -> None:
    """Place the labels of a :class:`~planargeo.draw.picture.Picture` (module docstring).

    The rings are at the asked distance ``r`` (at least 6 px) and at ``r`` plus one label height.
    Texts written at a fixed place are not moved; the labels keep clear of them unless they are
    marked ``over``.  A label moved gets its new offset and alignment; one that cannot be placed
    gets ``hidden``.

    Parameters
    ----------
    pic : Picture
    font_px, char_em : float
        The label font size (pixels) and a character's estimated advance (font sizes).
    """
    pw, ph = pic._plot
    h = 1.25 * font_px
    em = char_em * font_px
    bx0, by0, kx, ky = pic.box[0], pic.box[2], pic.kx, pic.ky
    kinds, texts, free = _gather(pic)
    if not free:
        return
    # texts written at a fixed place (a key's rows, a scale bar's length, a message) first, then
    # the labels' boxes as they are placed
    boxes = np.empty((len(texts) + len(free), 4))
    for k, part in enumerate(texts):
        w = em * len(part["text"])
        x0 = (part["x"] - bx0) * kx + part["dx"] - ALIGN_X[part["ha"]] * w
        y0 = (part["y"] - by0) * ky + part["dy"] - ALIGN_Y[part["va"]] * h
        boxes[k] = x0, y0, x0 + w, y0 + h
    free.sort(key=itemgetter(0))   # topmost first (a stable sort: the elements' order otherwise)

    # every candidate box of every label: the asked spot, slides along its line (a label that
    # has one) on either side, then two rings of eight around its anchor
    parts = [p for _, p in free]
    num = itemgetter("x", "y", "dx", "dy")
    q = np.empty((len(parts), 9))
    q[:, :4] = [num(p) for p in parts]
    q[:, 4] = [ALIGN_X[p["ha"]] for p in parts]
    q[:, 5] = [ALIGN_Y[p["va"]] for p in parts]
    q[:, 6] = [len(p["text"]) for p in parts]
    q[:, 7:] = [p.get("along", _NOT_ALONG) for p in parts]
    a0 = q[:, 2] * q[:, 7] + q[:, 3] * q[:, 8]       # the asked offset: along the line and across it
    g0 = np.hypot(q[:, 2] - a0 * q[:, 7], q[:, 3] - a0 * q[:, 8])
    r0 = np.maximum(np.hypot(q[:, 2], q[:, 3]), 6.0)
    view = tuple(float(v) for v in (bx0, by0, kx, ky, em, h, pw, ph))
    took = _compiled(_place)(q, a0, g0, r0, view, _table(pic, kinds), boxes, len(texts))
    moved = []
    for part, (spot, *new) in zip(parts, took.tolist()):
        if spot < 0:     # no free place: the label hides (the element keeps its hover text)
            part["hidden"] = True
            continue
        part.pop("hidden", None)
        if spot > 0:     # not the asked spot: its new offset and alignment
            moved.append((part, new))
    if moved:
        dxy = np.round([new[:2] for _, new in moved], 2).tolist()
        for (part, (_, _, fx, fy)), (dx, dy) in zip(moved, dxy):
            part["dx"], part["dy"], part["ha"], part["va"] = dx, dy, _HA_OF[fx], _VA_OF[fy]
