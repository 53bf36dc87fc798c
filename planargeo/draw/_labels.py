"""The label placer of :class:`planargeo.draw.picture.Picture`: labels kept off lines, glyphs and labels.

Every element's drawn strokes (paths, ellipses, pole glyphs, arrows, markers) are sampled every
:data:`STEP` pixels and counted in a raster of :data:`CELL`-pixel cells; a summed-area table of the
counts tells, for every spot of every label at once, whether a stroke passes through the cells whose
centres lie in its box (less :data:`TOL`).  A spot is clear when none does (its own element's
strokes count too: the spots beside a line or a pole are off it).

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
_HA_OF = {0.0: "left", 0.5: "center", 1.0: "right"}
_VA_OF = {0.0: "bottom", 0.5: "center", 1.0: "top"}
#: how many of a label's spots, best first, are tried before it hides
_TRIES = 12
#: the first ring's column among a label's candidate spots (the asked one, then the slides)
_RING = 1 + len(_SIDE)
#: a pole glyph (planargeo.draw.geometry.arc_glyph): its 270° arc, per unit radius
_T = np.deg2rad(np.linspace(-45.0, 225.0, 19))
_ARC = np.column_stack([np.cos(_T), np.sin(_T)])
_CIRCLE = np.column_stack([np.cos(np.linspace(0, 2 * np.pi, 33)), np.sin(np.linspace(0, 2 * np.pi, 33))])
_SQUARE = np.array([[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0], [-1.0, -1.0]])


def _strokes(pic) -> tuple[np.ndarray, np.ndarray]:
    """``(a, b)``: every drawn straight piece as pixel segments ``a → b``."""
    bx0, by0, kx, ky = pic.box[0], pic.box[2], pic.kx, pic.ky
    paths = []
    kinds: dict[str, list] = {"glyph": [], "arrow": [], "mark": [], "ellipse": []}
    for el in pic.elements:
        if el["color"] == "none":
            continue
        for part in el["parts"]:
            p = part["p"]
            if p == "path":
                xy = np.asarray(part["xy"], float)
                paths.append(np.vstack([xy, xy[:1]]) if part.get("closed") else xy)
            elif p in kinds:
                kinds[p].append((part, el["width"]))
    a, b = [], []
    if paths:
        xy = (np.concatenate(paths) - (bx0, by0)) * (kx, ky)
        ok = np.ones(len(xy) - 1, bool)
        ok[np.cumsum([len(q) for q in paths])[:-1] - 1] = False        # a path's last point starts none
        a.append(xy[:-1][ok])
        b.append(xy[1:][ok])

    def at(rows):        # (m, 1, 2) pixel anchors
        return np.array([((p["x"] - bx0) * kx, (p["y"] - by0) * ky) for p, _w in rows])[:, None, :]

    def glyphs(rows):    # the arc, then the head at its end (planargeo.draw.geometry.arc_glyph)
        r, ccw = np.array([(p["r"], p["ccw"]) for p, _w in rows]).T[:, :, None, None]
        ccw = ccw > 0
        hd = np.clip(0.45 * r, 3.0, 6.0)
        end = np.where(ccw, _ARC[-1], _ARC[0])                   # (m, 1, 2)
        tip = r * end + hd * np.where(ccw, 1.0, -1.0) * end[..., ::-1] * (-1.0, 1.0)
        head = np.concatenate([tip, (r - 0.5 * hd) * end, (r + 0.5 * hd) * end, tip], axis=1)
        return at(rows) + np.concatenate([r * np.where(ccw, _ARC, _ARC[::-1]), head], axis=1)

    def arrows(rows):    # the shaft and the head's triangle (the page's: max(8, 4 × width) long)
        v, hp = np.array([(p["dx"], p["dy"]) for p, _w in rows]), np.maximum(8.0, 4.0 * np.array([w for _p, w in rows]))
        u = v / np.maximum(np.hypot(v[:, 0], v[:, 1]), 1e-9)[:, None] * hp[:, None]
        n = u[:, ::-1] * (-0.35, 0.35)
        return at(rows) + np.stack([0.0 * v, v, v - u + n, v - u - n, v], axis=1)

    def marks(rows):
        return at(rows) + np.array([p["size"] / 2 for p, _w in rows])[:, None, None] * _SQUARE

    def ellipses(rows):
        m = np.array([p["m"] for p, _w in rows])                 # (n, 4): a, b, c, d
        ex = _CIRCLE[:, 0] * m[:, None, 0] + _CIRCLE[:, 1] * m[:, None, 1]
        ey = _CIRCLE[:, 0] * m[:, None, 2] + _CIRCLE[:, 1] * m[:, None, 3]
        return at(rows) + np.stack([ex * kx, ey * ky], axis=-1)

    for kind, shape in (("glyph", glyphs), ("arrow", arrows), ("mark", marks), ("ellipse", ellipses)):
        if kinds[kind]:
            q = shape(kinds[kind])                          # (m, k, 2) pixel polylines
            a.append(q[:, :-1].reshape(-1, 2))
            b.append(q[:, 1:].reshape(-1, 2))
    if not a:
        return np.zeros((0, 2)), np.zeros((0, 2))
    return np.concatenate(a), np.concatenate(b)


def _table(pic) -> np.ndarray:
    """Summed-area table (``rows + 1, cols + 1``) of the stroke samples in each raster cell."""
    pw, ph = pic._plot
    nx, ny = int(pw // CELL) + 1, int(ph // CELL) + 1
    a, b = _strokes(pic)
    d = b - a
    n = (np.hypot(d[:, 0], d[:, 1]) * (1.0 / STEP)).astype(int) + 2      # samples of each segment
    start = np.repeat(np.cumsum(n) - n, n)
    t = (np.arange(len(start)) - start) / np.repeat(n - 1.0, n)
    ix = np.floor((np.repeat(a[:, 0], n) + t * np.repeat(d[:, 0], n)) * (1.0 / CELL)).astype(int)
    iy = np.floor((np.repeat(a[:, 1], n) + t * np.repeat(d[:, 1], n)) * (1.0 / CELL)).astype(int)
    inside = (ix >= 0) & (ix < nx) & (iy >= 0) & (iy < ny)
    cell = (iy * (nx + 1) + ix + nx + 2)[inside]          # in the table's frame (a zero row and column first)
    count = np.bincount(cell, minlength=(ny + 1) * (nx + 1)).reshape(ny + 1, nx + 1).astype(float)
    return count.cumsum(0).cumsum(1)


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
    rows: dict[int, list[tuple[float, float, float, float]]] = {}   # placed boxes by row of one label height
    get = rows.get

    def reserve(x0, y0, x1, y1) -> None:
        box = (x0, y0, x1, y1)
        for j in range(int(y0 // h), int(y1 // h) + 1):
            row = get(j)
            if row is None:
                rows[j] = [box]
            else:
                row.append(box)

    def meets_label(x0, y0, x1, y1) -> bool:
        for j in range(int(y0 // h), int(y1 // h) + 1):
            for px0, py0, px1, py1 in get(j, ()):
                if x0 < px1 and px0 < x1 and y0 < py1 and py0 < y1:
                    return True
        return False

    # texts written at a fixed place (a key's rows, a scale bar's length, a message) first
    free = []            # (-z, part): the labels to place
    for el in pic.elements:
        for part in el["parts"]:
            if part["p"] != "text" or not part["text"]:
                continue
            if not part.get("fixed"):
                free.append((-el["z"], part))
            elif not part.get("over"):
                w = em * len(part["text"])
                x0 = (part["x"] - bx0) * kx + part["dx"] - ALIGN_X[part["ha"]] * w
                y0 = (part["y"] - by0) * ky + part["dy"] - ALIGN_Y[part["va"]] * h
                reserve(x0, y0, x0 + w, y0 + h)
    if not free:
        return
    free.sort(key=itemgetter(0))   # topmost first (a stable sort: the elements' order otherwise)

    # every candidate box of every label: the asked spot, slides along its line (a label that
    # has one) on either side, then two rings of eight around its anchor
    parts = [p for _, p in free]
    qx, qy, dx0, dy0, fx0, fy0, w, ux, uy = np.array(
        [((p["x"] - bx0) * kx, (p["y"] - by0) * ky, p["dx"], p["dy"], ALIGN_X[p["ha"]], ALIGN_Y[p["va"]],
          em * len(p["text"]), *p.get("along", (0.0, 0.0))) for p in parts]).T[:, :, None]
    a0 = dx0 * ux + dy0 * uy                         # the asked offset: along the line and across it
    vx, vy = dx0 - a0 * ux, dy0 - a0 * uy
    g = np.hypot(vx, vy)
    flat = g < 1e-9
    g = np.where(flat, 1.0, g)
    sx = _SIDE * np.where(flat, -uy, vx / g)        # (m, 13): the side of each slide, a unit vector
    sy = _SIDE * np.where(flat, ux, vy / g)
    g = np.maximum(np.where(flat, 0.0, g), 6.0)
    t = a0 + _SHIFT * (2.0 * h)
    r = np.maximum(np.hypot(dx0, dy0), 6.0) * _RADII + _REACH * h       # (m, 16): the rings' radii
    dx = np.hstack([dx0, t * ux + g * sx, r * _RING_X])
    dy = np.hstack([dy0, t * uy + g * sy, r * _RING_Y])
    fx = np.hstack([fx0, (sx <= 0.3) * (0.5 + 0.5 * (sx < -0.3)), np.broadcast_to(_FX2, (len(parts), 16))])
    fy = np.hstack([fy0, (sy <= 0.3) * (0.5 + 0.5 * (sy < -0.3)), np.broadcast_to(_FY2, (len(parts), 16))])
    x0 = qx + dx - fx * w
    y0 = qy + dy - fy * h
    x1, y1 = x0 + w, y0 + h
    inside = (x0 >= 0.0) & (y0 >= 0.0) & (x1 <= pw) & (y1 <= ph)
    inside[:, 1:_RING] &= (ux != 0.0) | (uy != 0.0)     # slides: labels of lines only
    # clear of strokes: the cells whose centres lie in the box (less TOL) hold no sample
    table = _table(pic)
    ny, nx = table.shape[0] - 1, table.shape[1] - 1
    i0 = np.clip(((x0 + TOL) * (1.0 / CELL) + 0.5).astype(int), 0, nx)    # the cells whose centres
    i1 = np.clip(((x1 - TOL) * (1.0 / CELL) + 0.5).astype(int), 0, nx)    # are in the box
    j0 = np.clip(((y0 + TOL) * (1.0 / CELL) + 0.5).astype(int), 0, ny)
    j1 = np.clip(((y1 - TOL) * (1.0 / CELL) + 0.5).astype(int), 0, ny)
    cnt = table[j1, i1] - table[j0, i1] - table[j1, i0] + table[j0, i0]
    clear = inside & (cnt == 0)

    # the clear spots in their order, then the others by how many stroke samples they cover
    n = clear.shape[1]
    rank = np.where(inside, np.where(clear, 0.0, (cnt + 1.0) * n) + np.arange(n), np.inf)
    best = np.argsort(rank, 1)[:, :_TRIES]
    tries = np.isfinite(np.take_along_axis(rank, best, 1)).sum(1).tolist()
    bx = np.take_along_axis(x0, best, 1).tolist()
    by = np.take_along_axis(y0, best, 1).tolist()
    for i, (part, ks, X0, Y0, m, W) in enumerate(zip(parts, best.tolist(), bx, by, tries, w[:, 0].tolist())):
        for j in range(m):
            if not meets_label(X0[j], Y0[j], X0[j] + W, Y0[j] + h):
                break
        else:            # no free place: the label hides (the element keeps its hover text)
            part["hidden"] = True
            continue
        k = ks[j]
        if k:            # not the asked spot
            part["dx"], part["dy"] = round(float(dx[i, k]), 2), round(float(dy[i, k]), 2)
            part["ha"], part["va"] = _HA_OF[float(fx[i, k])], _VA_OF[float(fy[i, k])]
        part.pop("hidden", None)
        reserve(X0[j], Y0[j], X0[j] + W, Y0[j] + h)
