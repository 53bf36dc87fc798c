"""A picture described once, its geometry done here: plain elements every renderer draws alike.

:meth:`Picture.to_dict` gives plain JSON that the page (``planargeo/widgets/canvas.js``) and
matplotlib (:func:`planargeo.draw.render.draw_picture`) draw.  Every element has a stable ``id``,
a ``role`` (its style, :mod:`planargeo.draw.style`), its thesis ``symbol`` and a description
``desc`` shown on hover, and is drawn from *parts* in data coordinates:

``{"p": "path", "xy": [[x, y], ...], "closed": bool}``
    a polyline or polygon (stroke, and fill when the element has one);
``{"p": "ellipse", "x": cx, "y": cy, "m": [a, b, c, d]}``
    the unit circle under the affine map ``(x, y) + [[a, b], [c, d]] (cos t, sin t)``;
``{"p": "mark", "x": x, "y": y, "shape": "o" | "D" | "s", "size": px}``
    a marker of fixed pixel size;
``{"p": "glyph", "x": x, "y": y, "r": px, "ccw": bool}``
    the 270° rotation arrow of a pole (:func:`planargeo.draw.geometry.arc_glyph`);
``{"p": "arrow", "x": x, "y": y, "dx": px, "dy": px}``
    an arrow of fixed pixel length from a data point (edge arrows, force senses);
``{"p": "text", "x": x, "y": y, "dx": px, "dy": px, "text": str, "ha": .., "va": ..}``
    a label at a data point, moved by a pixel offset.

Pixel sizes are at the picture's ``size``; y of a pixel offset points up.

Examples
--------
>>> pic = Picture((-2, 2, -2, 2), size=(300, 300))
>>> pic.point("P", [1.0, 0.0, 1.0], role="twist", symbol="P", desc="a pole")  # pole (0, 1)
>>> pic.line("f", [1.0, 0.0, 0.0], role="wrench", symbol="f", desc="a force along x")
>>> d = pic.to_dict()
>>> els = {e["id"]: e for e in d["elements"]}
>>> els["f"]["parts"][0]["xy"]           # the x axis, clipped to the view
[[-2.0, 0.0], [2.0, 0.0]]
>>> [part["p"] for part in els["P"]["parts"]]   # marker, rotation glyph, label
['mark', 'glyph', 'text']
"""
from __future__ import annotations

import copy
import math
from operator import itemgetter
from typing import Any

import numpy as np

from planargeo.draw._labels import _align, loops_cached, place_labels
from planargeo.draw.geometry import _clip, conic_curves, conic_geometry
from planargeo.draw.style import COLORS, LABEL_PT, LINEWIDTHS, STYLES
from planargeo.errors import InputError, NonFiniteError, ShapeError
from planargeo.geometry._docs import entries

__all__ = ["Picture", "PX_PER_PT", "FONT_PX", "nice_ticks", "plain_text", "warm_labels"]

#: Pixels per point of a picture (the explorers' 100 dpi).
PX_PER_PT = 100.0 / 72.0
#: Label text size in pixels (:data:`planargeo.draw.style.LABEL_PT` at 100 dpi: 11.5 px).
FONT_PX = round(LABEL_PT * PX_PER_PT, 2)
#: Estimated advance of one character, in font sizes (DejaVu Sans, mixed text).
_CHAR_EM = 0.6
#: A finite pole farther than this many view diagonals is drawn like an ideal point.
FAR = 1e6
#: Height of a line of text below the plot area (:meth:`Picture.below`), and the room left under the last.
_BELOW_LINE_PX, _BELOW_PAD_PX = 14.0, 4.0


def nice_ticks(lo: float, hi: float, n: int = 5) -> list[float]:
    """About ``n`` round tick values (1, 2, 5 × 10ᵏ apart) between ``lo`` and ``hi``.

    Parameters
    ----------
    lo, hi : float
        The axis range.
    n : int
        Roughly how many ticks.

    Returns
    -------
    list of float

    Examples
    --------
    >>> nice_ticks(-4, 4), nice_ticks(0.0, 1.0, 3)
    ([-4.0, -2.0, 0.0, 2.0, 4.0], [0.0, 0.5, 1.0])
    """
    span = hi - lo
    if not span > 0 or not math.isfinite(span):
        return []
    raw = span / max(n - 1, 1)
    mag = 10.0 ** math.floor(math.log10(raw))
    # the 1-2-5 step whose tick count is nearest n
    step = min((m * mag for m in (0.5, 1, 2, 5, 10)), key=lambda s: abs(span / s + 1 - n))
    out = []
    k = math.ceil(lo / step - 1e-9)
    while k * step <= hi + 1e-9 * step:
        out.append(round(k * step, 12) + 0.0)
        k += 1
    return out


_GREEK = {
    "alpha": "α", "beta": "β", "gamma": "γ", "delta": "δ", "epsilon": "ε", "varepsilon": "ε",
    "zeta": "ζ", "eta": "η", "theta": "θ", "vartheta": "ϑ", "iota": "ι", "kappa": "κ",
    "lambda": "λ", "mu": "μ", "nu": "ν", "xi": "ξ", "pi": "π", "rho": "ρ", "sigma": "σ",
    "tau": "τ", "upsilon": "υ", "phi": "φ", "varphi": "φ", "chi": "χ", "psi": "ψ", "omega": "ω",
    "Gamma": "Γ", "Delta": "Δ", "Theta": "Θ", "Lambda": "Λ", "Xi": "Ξ", "Pi": "Π", "Sigma": "Σ",
    "Phi": "Φ", "Psi": "Ψ", "Omega": "Ω", "infty": "∞", "cdot": "·", "times": "×", "to": "→",
    "rightarrow": "→", "leftarrow": "←", "approx": "≈", "leq": "≤", "geq": "≥", "neq": "≠",
    "pm": "±", "prime": "′", "perp": "⊥", "parallel": "∥", "circ": "°", "ell": "ℓ",
    "partial": "∂", "nabla": "∇", "sum": "Σ", ",": " ", ";": " ", "!": "", " ": " ", "quad": "  ",
}
_SUB = dict(zip("0123456789+-=()aehijklmnoprstuvx", "₀₁₂₃₄₅₆₇₈₉₊₋₌₍₎ₐₑₕᵢⱼₖₗₘₙₒₚᵣₛₜᵤᵥₓ"))
_SUP = dict(zip("0123456789+-=()inT", "⁰¹²³⁴⁵⁶⁷⁸⁹⁺⁻⁼⁽⁾ⁱⁿᵀ"))
_ACCENT = {"dot": "\u0307", "ddot": "\u0308", "hat": "\u0302", "bar": "\u0304", "tilde": "\u0303",
           "vec": "\u20d7"}


def warm_labels() -> bool:
    """Compile (or load from numba's cache) the label placer's loops, as the first picture would.

    ``make install`` runs it after the dynamics kernels, so that no lesson waits for the compiler.

    Returns
    -------
    bool
        Whether nothing needed compiling (both loops were in numba's cache, or numba is off).

    Examples
    --------
    >>> isinstance(warm_labels(), bool)
    True
    """
    cached = loops_cached()
    pic = Picture((-1, 1, -1, 1), size=(200, 200), ticks=False)
    pic.line("l", [0.0, 1.0, 0.0], symbol="l")
    pic.to_dict()
    return cached


def _math_to_unicode(m: str) -> str:
    out, i = [], 0

    def command_end(j):
        """Index after the command that starts with the backslash at j (letters, or one sign)."""
        k = j + 1
        while k < len(m) and m[k].isalpha():
            k += 1
        return max(k, j + 2)

    def group(j):
        """(text of the group or single token at j, index after it)."""
        if j < len(m) and m[j] == "{":
            depth, k = 1, j + 1
            while k < len(m) and depth:
                depth += {"{": 1, "}": -1}.get(m[k], 0)
                k += 1
            return _math_to_unicode(m[j + 1:k - 1]), k
        if j < len(m) and m[j] == "\\":
            k = command_end(j)
            return _math_to_unicode(m[j:k]), k
        return (m[j], j + 1) if j < len(m) else ("", j)

    while i < len(m):
        c = m[i]
        if c == "\\":
            k = command_end(i)
            name = m[i + 1:k]
            if name in _ACCENT:
                body, k = group(k)
                out.append((body[:1] + _ACCENT[name] + body[1:]) if body else "")
            elif name in ("mathrm", "mathbf", "mathit", "text", "rm", "mathsf", "boldsymbol",
                          "operatorname", "mathcal"):
                body, k = group(k) if k < len(m) and m[k] == "{" else ("", k)
                out.append(body)
            elif name in ("left", "right", "big", "Big"):
                pass
            else:
                out.append(_GREEK.get(name, name))
            i = k
        elif c in "_^":
            body, k = group(i + 1)
            table = _SUB if c == "_" else _SUP
            out.append("".join(table[ch] for ch in body) if body and all(ch in table for ch in body)
                       else body)
            i = k
        elif c in "{}":
            i += 1
        else:
            out.append(c)
            i += 1
    return "".join(out)


def plain_text(s: str) -> str:
    r"""Text with matplotlib's ``$...$`` mathtext turned into Unicode (subscripts as subscripts).

    Parameters
    ----------
    s : str
        A label, e.g. ``"$v_{1}$"`` or ``"$R_2\mu_2$"``.

    Returns
    -------
    str

    Examples
    --------
    >>> plain_text("$v_{1}$"), plain_text(r"$R_2\mu_2$"), plain_text(r"$\ddot{q}_3$"), plain_text("$s^T T$")
    ('v₁', 'R₂μ₂', 'q̈₃', 'sᵀ T')
    >>> plain_text(r"$v = s\omega$ (ICR)")
    'v = sω (ICR)'
    """
    s = str(s)
    if "$" not in s:
        return s
    parts = s.split("$")
    return "".join(_math_to_unicode(p) if k % 2 else p for k, p in enumerate(parts))


#: The roles an element may have: the style table's (:mod:`planargeo.draw.style`).
ROLES = frozenset(COLORS) | frozenset(STYLES) | frozenset(LINEWIDTHS)
#: each role's line width in pixels
_WIDTHS = {role: round(LINEWIDTHS.get(role, 1.3) * PX_PER_PT, 2) for role in ROLES}


def _three(id, v, what: str) -> tuple[float, float, float]:
    """``v`` as three finite floats, or the package's error naming the element."""
    try:
        a, b, c = v
        a, b, c = float(a), float(b), float(c)
    except (TypeError, ValueError):
        raise ShapeError(f"{what} {id!r} must be three numbers, got {v!r}") from None
    if not (math.isfinite(a) and math.isfinite(b) and math.isfinite(c)):
        raise NonFiniteError(f"{what} {id!r} must be finite, got {[a, b, c]}")
    return a, b, c


def _glyph_radius(w: float, scale: float = 6.0) -> float:
    """Radius (points) of the rotation glyph of a pole of weight ``w``: ``scale |w|`` within [4, 16]."""
    return min(max(scale * abs(w), 4.0), 16.0)


def _color(role: str, color: str | None) -> str:
    return color or COLORS.get(role) or STYLES.get(role, {}).get("color") or COLORS["text"]


def _dash(role: str):
    if role in _DASHES:                  # a new list each time (an element's own)
        d = _DASHES[role]
        return None if d is None else list(d)
    ls = STYLES.get(role, {}).get("linestyle")
    _DASHES[role] = d = [round(v * PX_PER_PT, 2) for v in ls[1]] if isinstance(ls, tuple) else None
    return None if d is None else list(d)


#: each role's dash pattern in pixels (:func:`_dash`, worked out once)
_DASHES: dict = {}


def _text_part(x, y, text, dx=0.0, dy=0.0, ha="left", va="bottom", along=None) -> dict:
    """A text part: ``text`` (mathtext made plain) at ``(x, y)``, moved ``(dx, dy)`` pixels.

    ``along``: the pixel direction of a line the label may slide along, on either side (the
    placer's, left out of the data).
    """
    part = {"p": "text", "x": float(x), "y": float(y), "dx": float(dx), "dy": float(dy),
            "text": text if type(text) is str and "$" not in text else plain_text(text), "ha": ha, "va": va}
    if along is not None:
        part["along"] = (float(along[0]), float(along[1]))
    return part


#: Docstring entries of the element methods (and of :mod:`planargeo.draw._shared`), written once
_ENTRIES = {"id": "id : str\n    Stable name of the element.",
            "role": "role : str\n    Style role (:mod:`planargeo.draw.style`).",
            "symbol": "symbol, desc : str\n    Thesis symbol and a one-line description.",
            "color": "color : str, optional\n    Colour instead of the role's.",
            "z": "z : int\n    Drawing order.",
            "opacity": "opacity : float\n    Opacity of the whole element (faded: below 1).",
            "label": "label : str, optional\n    Its text in the picture (default: ``symbol``).",
            "width": "width : float, optional\n    Line width in pixels.",
            "dash": "dash : list of float, optional\n    Dash pattern in pixels (a line's default: its role's)."}
_documented = entries(_ENTRIES)

#: element keys left out of the data when they hold these values
_DEFAULTS = {"dash": None, "fill": None, "alpha": 1.0, "opacity": 1.0, "desc": "", "symbol": ""}
_DEFAULT_ITEMS = tuple(_DEFAULTS.items())


class Picture:
    """A picture under construction: a view and its elements (module docstring).

    Parameters
    ----------
    view : (float, float, float, float)
        ``(x0, x1, y0, y1)``: what must be in view (``equal``: widened to the plot area's shape).
    size : (int, int)
        Width and height in pixels.
    title : str
        Shown above the picture.
    equal : bool
        One scale on both axes.
    ticks : bool
        Axes with ticks (and their labels) around the plot area.
    margin : (left, right, top, bottom) pixels, optional
        Room around the plot area (default: room for the tick labels and title).

    Raises
    ------
    InputError
        A view that is not a finite box with positive extent, or a size below 50 px.
    """

    def __init__(self, view, size=(560, 540), *, title: str = "", equal: bool = True,
                 ticks: bool = True, margin=None):
        x0, x1, y0, y1 = (float(v) for v in view)
        if not all(map(math.isfinite, (x0, x1, y0, y1))) or not (x1 > x0 and y1 > y0):
            raise InputError(f"view must be a finite box (x0 < x1, y0 < y1), got {tuple(view)}")
        w, h = (int(round(float(s))) for s in size)
        if w < 50 or h < 50:
            raise InputError(f"size must be at least 50 × 50 pixels, got {tuple(size)}")
        self.size = (w, h)
        self.title = str(title)
        self.ticks = bool(ticks)
        if margin is None:
            margin = (44, 12, 26 if title else 10, 30) if ticks else (6, 6, 24 if title else 6, 6)
        self.margin = tuple(float(m) for m in margin)
        ml, mr, mt, mb = self.margin
        self._plot = pw, ph = w - ml - mr, h - mt - mb      # the plot area (pixels)
        if equal:  # widen the box on one axis to the plot area's shape
            k = min(pw / (x1 - x0), ph / (y1 - y0))
            cx, cy = (x0 + x1) / 2, (y0 + y1) / 2
            hx, hy = pw / k / 2, ph / k / 2
            x0, x1, y0, y1 = cx - hx, cx + hx, cy - hy, cy + hy
        self.box = (x0, x1, y0, y1)
        self.kx, self.ky = pw / (x1 - x0), ph / (y1 - y0)  # pixels per data unit
        self.elements: list[dict] = []
        self._edge_labels: dict[tuple, tuple[dict, list[str]]] = {}   # edge arrows' labels, by place
        self.handles: list[dict] = []
        self._ids: set[str] = set()
        self._below: list[dict] = []      # lines of text under the plot area (Picture.below)

    # ------------------------------------------------------------------ helpers
    def copy(self) -> "Picture":
        """A picture with the same view and elements, to which more can be added.

        Returns
        -------
        Picture
            What is added to it does not reach this picture (the elements themselves are shared).

        Examples
        --------
        >>> a = Picture((0, 1, 0, 1), size=(100, 100))
        >>> b = a.copy()
        >>> b.marks("n", [[0.2, 0.2]])
        >>> len(a.elements), len(b.elements)
        (0, 1)
        """
        out = copy.copy(self)
        out.elements = list(self.elements)
        out.handles = list(self.handles)
        out._ids = set(self._ids)
        out._below = list(self._below)
        return out

    def below(self, id: str, lines, *, color: str | None = None, desc: str = "") -> None:
        """Lines of text under the plot area, below its tick labels, outside the plot (a key).

        The figure grows by their height; the plot area, its view, scale and ticks stay as
        they were.  Each line is drawn left-aligned at the plot's left edge, its top
        ``y`` pixels below the plot area's bottom edge (``"below"`` in :meth:`to_dict`).

        Parameters
        ----------
        id : str
            What the lines belong to (one entry of a key).
        lines : list of str
            The lines, one under the other.
        color : str, optional
            Their colour (default: the text's).
        desc : str
            A one-line description (the page shows it on hover).

        Examples
        --------
        >>> pic = Picture((0, 1, 0, 1), size=(200, 200))
        >>> pic.below("key 1", ["P: a pole"], color="#d62728", desc="key: P: a pole")
        >>> d = pic.to_dict()
        >>> d["size"], d["margin"], d["below"][0]["y"]     # 14 px a line and 4 px to spare
        ([200, 218], [44.0, 12.0, 10.0, 48.0], 30.0)
        """
        if not lines:
            return
        if not self._below:
            self._below_top = self.margin[3]      # below the tick labels
        grow = _BELOW_LINE_PX * len(lines) + (0.0 if self._below else _BELOW_PAD_PX)
        for line in lines:
            self._below.append({"id": str(id), "text": plain_text(line), "color": _color("text", color),
                                "desc": str(desc), "x": 0.0,
                                "y": self._below_top + _BELOW_LINE_PX * len(self._below)})
        w, h = self.size
        self.size = (w, int(round(h + grow)))
        self.margin = (*self.margin[:3], self.margin[3] + grow)

    def to_px(self, xy) -> np.ndarray:
        """Pixel coordinates (from the plot area's lower left, y up) of data points.

        Parameters
        ----------
        xy : array_like (..., 2)
            Data points.

        Returns
        -------
        numpy.ndarray
        """
        xy = np.asarray(xy, dtype=float)
        return np.stack([(xy[..., 0] - self.box[0]) * self.kx,
                         (xy[..., 1] - self.box[2]) * self.ky], axis=-1)

    def _add(self, id: str, role: str, symbol: str, desc: str, parts: list, *, color: str,
             width: float | None = None, dash=None, fill: str | None = None,
             alpha: float = 1.0, z: int = 3, opacity: float = 1.0) -> dict:
        id = str(id)
        if role not in ROLES:
            raise InputError(f"role of {id!r} must be one of {sorted(ROLES)}, got {role!r}")
        if id in self._ids:
            raise InputError(f"element id {id!r} is used twice in one picture")
        self._ids.add(id)
        # (plain_text of a str without mathtext is the str itself)
        el = {"id": id, "role": role,
              "symbol": symbol if type(symbol) is str and "$" not in symbol else plain_text(symbol or ""),
              "desc": desc if type(desc) is str and "$" not in desc else plain_text(desc or ""),
              "color": color, "width": _WIDTHS[role] if width is None else round(width, 2),
              "dash": dash, "fill": fill, "alpha": alpha, "z": z, "opacity": opacity, "parts": parts}
        self.elements.append(el)
        return el

    def _edge_arrow(self, n_px, t_px, length, text, infinite):
        """Parts of an arrow at the view's edge in the pixel direction ``n_px`` (along ``t_px``).

        Arrows drawn at one place share one label naming them all (``v₁, v₂ at ∞``), at the first.
        """
        pw, ph = self._plot
        n0, n1 = (float(v) for v in n_px)           # plain floats (the same arithmetic as arrays)
        hn = math.hypot(n0, n1)
        n0, n1 = n0 / hn, n1 / hn
        t0, t1 = (float(v) for v in t_px)
        ht = math.hypot(t0, t1)
        t0, t1 = t0 / ht, t1 / ht
        h0, h1 = pw / 2, ph / 2
        s = min(h / abs(c) for h, c in ((h0, n0), (h1, n1)) if abs(c) > 1e-12)  # one is ≥ 0.7
        b0, b1 = h0 + n0 * (s - 16.0), h1 + n1 * (s - 16.0)  # from the plot area's lower left
        x = self.box[0] + (b0 - t0 * length / 2) / self.kx
        y = self.box[2] + (b1 - t1 * length / 2) / self.ky
        parts = [{"p": "arrow", "x": x, "y": y, "dx": t0 * length, "dy": t1 * length}]
        lx = self.box[0] + (b0 - n0 * (length / 2 + 6)) / self.kx
        ly = self.box[2] + (b1 - n1 * (length / 2 + 6)) / self.ky
        ha = "right" if n0 > 0.5 else "left" if n0 < -0.5 else "center"
        va = "top" if n1 > 0.5 else "bottom" if n1 < -0.5 else "center"
        where = "at ∞" if infinite else "(off view)"
        place = (round(b0), round(b1), round(t0, 2), round(t1, 2), where)
        if text and place in self._edge_labels:       # the first arrow here names this one too
            first, names = self._edge_labels[place]
            names.append(text)
            first["text"] = plain_text(f"{', '.join(names)} {where}")
            return parts
        parts.append(_text_part(lx, ly, (text + " " if text else "") + where, 0.0, 0.0, ha, va))
        if text:
            self._edge_labels[place] = (parts[-1], [text])
        return parts

    # ------------------------------------------------------------------ elements
    @_documented
    def point(self, id: str, p, *, role: str = "twist", symbol: str = "", desc: str = "",
              label: str | None = None, glyph: bool = True, size: float | None = None,
              shape: str | None = None, color: str | None = None, glyph_scale: float = 6.0,
              opacity: float = 1.0):
        """A homogeneous point (a twist's or an acceleration's pole) with its rotation glyph.

        A pole in view is a marker with a 270° arrow turning with the sign of the weight (the rate
        of rotation, 4.10); a pole out of view, or an ideal point, is an arrow at the view's edge.

        Parameters
        ----------
        {id}
        p : array_like (3,)
            ``[vx, vy, w]``.
        {role symbol}
        {label}
        glyph : bool
            Draw the rotation glyph.
        size : float, optional
            Marker size in pixels.
        shape : {"o", "D", "s"}, optional
            Marker shape.
        {color opacity}
        glyph_scale : float
            Glyph radius in pixels per unit ``|w|`` (clamped to [5, 22] px).
        """
        p0, p1, p2 = _three(id, p, "point")    # plain floats: a point costs microseconds
        color = _color(role, color)
        text = symbol if label is None else label
        st = STYLES.get(role, {})
        size = float(size if size is not None else st.get("markersize", 5.0) * PX_PER_PT)
        parts: list[dict] = []
        xy = None
        if p2 != 0.0 and (p0 or p1 or p2):
            x0, x1, y0, y1 = self.box
            diag, cx, cy = math.hypot(x1 - x0, y1 - y0), (x0 + x1) / 2, (y0 + y1) / 2
            off = math.hypot(-p1 - cx * p2, p0 - cy * p2)
            if off <= FAR * diag * abs(p2):
                x, y = -p1 / p2, p0 / p2          # point_xy (planargeo.draw.geometry), on floats
                if math.isfinite(x) and math.isfinite(y):
                    xy = (x, y)
        if xy is not None:
            x, y = xy
            qx, qy = (x - self.box[0]) * self.kx, (y - self.box[2]) * self.ky
            pw, ph = self._plot
            if -1 <= qx <= pw + 1 and -1 <= qy <= ph + 1:
                parts.append({"p": "mark", "x": x, "y": y, "shape": shape or st.get("marker", "o"),
                              "size": size})
                r = _glyph_radius(p2, glyph_scale) * PX_PER_PT
                if glyph:
                    parts.append({"p": "glyph", "x": x, "y": y, "r": round(r, 2), "ccw": p2 > 0})
                if text:
                    gap = (0.75 * r + 3.0) if glyph else size / 2 + 3.0
                    parts.append(_text_part(x, y, text, gap, gap))
            else:
                d = (qx - pw / 2, qy - ph / 2)
                parts += self._edge_arrow(d, d, 22.0, text, infinite=False)
        elif p0 or p1 or p2:
            a, b = p0, p1
            sg = -1.0 if p2 < 0 else 1.0
            n = (-b * self.kx * sg, a * self.ky * sg)
            t = (a * self.kx, b * self.ky)
            L = min(max(glyph_scale * math.hypot(a, b), 12.0), 40.0) * PX_PER_PT
            parts += self._edge_arrow(n, t, L, text, infinite=True)
        self._add(id, role, symbol, desc, parts, color=color, z=7, opacity=opacity)

    @_documented
    def line(self, id: str, l, *, role: str = "wrench", symbol: str = "", desc: str = "",
             label: str | None = None, anchor=None, arrow: bool = True, color: str | None = None,
             width: float | None = None, dash=None, opacity: float = 1.0):
        """A homogeneous line (a wrench's line of action), clipped to the view.

        Its sense is an arrow on the line at ``anchor``; the line at infinity (a couple, 4.27) is a
        couple glyph in the upper right corner.

        Parameters
        ----------
        {id}
        l : array_like (3,)
            ``[fx, fy, tz]``: the force and its moment about the origin, as in 4.27; a zero
            force is the line at infinity.
        {role symbol}
        {label}
        anchor : (float, float), optional
            Where the sense arrow sits (projected onto the line; default: the view's centre).
        arrow : bool
            Draw the sense arrow.
        {color opacity}
        {width dash}
        """
        lx, ly, lz = _three(id, l, "line")
        color = _color(role, color)
        text = symbol if label is None else label
        parts: list[dict] = []
        F = math.hypot(lx, ly)
        x0, x1, y0, y1 = self.box
        cx, cy = (x0 + x1) / 2, (y0 + y1) / 2
        if F != 0.0 and abs(lz + cy * lx - cx * ly) > FAR * math.hypot(x1 - x0, y1 - y0) * F:
            F = lx = ly = 0.0     # farther than FAR view diagonals: drawn like the line at infinity
        seg = _clip(lx, ly, lz, x0, x1, y0, y1) if F else None   # clip_line, on floats
        if seg is not None:
            parts.append({"p": "path", "xy": np.array(seg), "closed": False})
            ex, ey = lx / F, ly / F
            (sx, sy), (tx, ty) = seg
            if anchor is None:
                ax, ay = (self.box[0] + self.box[1]) / 2, (self.box[2] + self.box[3]) / 2
            else:
                ax, ay = anchor
                ax, ay = float(ax), float(ay)
            t_end = (tx - sx) * ex + (ty - sy) * ey
            lo, hi = min(0.0, t_end), max(0.0, t_end)
            t = (ax - sx) * ex + (ay - sy) * ey
            t = min(max(t, lo + 0.1 * (hi - lo)), hi - 0.1 * (hi - lo))
            fx, fy = sx + ex * t, sy + ey * t
            epx, epy = ex * self.kx, ey * self.ky
            n_ep = math.hypot(epx, epy)
            epx, epy = epx / n_ep, epy / n_ep
            if arrow:
                parts.append({"p": "arrow", "x": fx, "y": fy, "dx": epx * 24, "dy": epy * 24})
            if text:
                parts.append(_text_part(fx, fy, text, -epy * 8 + epx * 12, epx * 8 + epy * 12,
                                        along=(epx, epy)))
        elif F == 0.0 and lz != 0.0:
            x0, x1, y0, y1 = self.box
            x, y = x1 - 26 / self.kx, y1 - 26 / self.ky
            parts.append({"p": "glyph", "x": x, "y": y, "r": 12.0, "ccw": lz > 0})
            parts.append(_text_part(x, y, (text + ": " if text else "") + "couple (line at ∞)",
                                    -18.0, 0.0, "right", "center"))
        self._add(id, role, symbol, desc, parts, color=color, width=width,
                  dash=dash if dash is not None else _dash(role), opacity=opacity)

    @_documented
    def conic(self, id: str, C, *, role: str = "conic", symbol: str = "", desc: str = "",
              label: str | None = None, mark_center: bool | None = None, color: str | None = None,
              opacity: float = 1.0):
        """A conic (an inertia's imaginary conic drawn by its real stand-in, dashed).

        Parameters
        ----------
        {id}
        C : array_like (3, 3)
            Symmetric conic matrix.
        role : str
            ``"conic"`` or ``"inertia"`` (dashed, centre marked).
        {symbol}
        {label}
        mark_center : bool, optional
            Mark the centre (default: for inertias and imaginary conics).
        {color opacity}
        """
        g = conic_geometry(C)
        color = _color(role, color)
        text = symbol if label is None else label
        if g["kind"] == "ellipse":  # the unit circle under an affine map: six numbers
            (a, b, x), (c, d, y), _ = g["affine"].tolist()
            parts = [{"p": "ellipse", "x": x, "y": y, "m": [a, b, c, d]}]
        else:
            parts = [{"p": "path", "xy": c, "closed": False} for c in conic_curves(C, self.box, g)]
        imaginary = bool(g.get("imaginary"))
        if "affine" in g:
            mark = mark_center if mark_center is not None else (imaginary or role == "inertia")
            if mark and g["kind"] != "parabola":
                (_, _, cx), (_, _, cy), _ = g["affine"].tolist()
                parts.append({"p": "mark", "x": cx, "y": cy, "shape": "o", "size": 4.0})
            if text:
                top = g["affine"] @ [0.7071, 0.7071, 1.0]
                parts.append(_text_part(top[0], top[1], text, 4.0, 4.0))
        elif g["kind"] == "point":
            x, y = (float(v) for v in g["point"])
            parts.append({"p": "mark", "x": x, "y": y, "shape": "o", "size": 5.0})
        dash = _dash("inertia") if (imaginary or role == "inertia") else _dash(role)
        self._add(id, role, symbol, desc, parts, color=color, dash=dash, z=2, opacity=opacity)

    @_documented
    def path(self, id: str, xy, *, role: str = "body", symbol: str = "", desc: str = "",
             closed: bool = False, fill: str | None = None, color: str | None = None,
             width: float | None = None, dash=None, alpha: float = 1.0, label: str | None = None,
             z: int = 1, opacity: float = 1.0):
        """A polyline or polygon in data coordinates (bodies, links, ground, charts).

        Parameters
        ----------
        {id}
        xy : array_like (n, 2)
            Vertices (a non-finite row separates pieces).
        {role symbol}
        closed : bool
            A polygon.
        fill : str, optional
            Fill colour.
        color : str, optional
            Stroke colour (``"none"``: no stroke).
        {width dash}
        alpha : float
            Opacity of the fill.
        label : str, optional
            Text at the first vertex.
        {z opacity}
        """
        xy = np.asarray(xy, dtype=float).reshape(-1, 2)
        ok = np.all(np.isfinite(xy), axis=1)
        if ok.all():
            parts = [{"p": "path", "xy": xy, "closed": bool(closed)}]
        else:  # non-finite rows separate pieces (matplotlib's convention): the rows between cuts
            cuts = np.flatnonzero(~ok).tolist()
            parts = [{"p": "path", "xy": xy[a + 1:b].copy(), "closed": bool(closed)}
                     for a, b in zip([-1, *cuts], [*cuts, len(xy)]) if b - a > 2]
        if label and ok[0]:
            parts.append(_text_part(xy[0, 0], xy[0, 1], label, 4.0, 4.0))
        self._add(id, role, symbol, desc, parts, color=_color(role, color), width=width,
                  dash=dash, fill=fill, alpha=alpha, z=z, opacity=opacity)

    @_documented
    def marks(self, id: str, xy, *, role: str = "body", symbol: str = "", desc: str = "",
              shape: str = "o", size: float = 6.0, color: str | None = None, z: int = 4,
              opacity: float = 1.0):
        """Markers of one size at data points (pins, centres of mass, samples).

        Parameters
        ----------
        {id}
        xy : array_like (n, 2)
            Where the markers sit.
        {role symbol}
        shape : {"o", "D", "s"}
            Marker shape.
        size : float
            Marker size in pixels.
        {color z opacity}
        """
        xy = np.asarray(xy, dtype=float).reshape(-1, 2)
        parts = [{"p": "mark", "x": float(x), "y": float(y), "shape": shape, "size": float(size)}
                 for x, y in xy if math.isfinite(x) and math.isfinite(y)]
        self._add(id, role, symbol, desc, parts, color=_color(role, color), z=z, opacity=opacity)

    @_documented
    def text(self, id: str, xy, text: str, *, role: str = "text", symbol: str = "", desc: str = "",
             color: str | None = None, ha: str = "left", va: str = "bottom", dx: float = 0.0,
             dy: float = 0.0, z: int = 8, obstacle: bool = True):
        """A text at a data point, moved by a pixel offset (not moved by the label placer).

        Parameters
        ----------
        {id}
        xy : (float, float)
            Anchor in data coordinates.
        text : str
            The text.
        {role symbol color}
        ha, va : str
            Alignment at the anchor (``"left"``, ``"center"``, ``"right"``; ``"bottom"``,
            ``"center"``, ``"top"``, ``"baseline"`` read as bottom).
        dx, dy : float
            Offset in pixels (y up).
        {z}
        obstacle : bool
            The placed labels keep clear of it (default; False for a passing note over everything:
            labels may then lie under it and under the element's other parts, such as a panel).
        """
        x, y = (float(v) for v in xy)
        if not (math.isfinite(x) and math.isfinite(y)):
            return
        va = {"baseline": "bottom", "center_baseline": "center"}.get(va, va)
        part = _text_part(x, y, str(text), dx, dy, ha, va)
        part["fixed"] = True
        el = self._add(id, role, symbol, desc, [part], color=_color(role, color), z=z)
        if not obstacle:     # neither the text nor parts added to it later (a panel) move labels
            part["over"] = True
            el["obstacle"] = False

    def handle(self, id: str, xy, *, symbol: str = "", desc: str = ""):
        """A point the user may drag (the page hit-tests it and moves it at once).

        Parameters
        ----------
        id : str
            The handle's name (one of the explorer's handles).
        xy : (float, float)
            Where it is.
        symbol, desc : str
            What dragging it changes.
        """
        x, y = xy
        x, y = float(x), float(y)
        if math.isfinite(x) and math.isfinite(y):
            self.handles.append({"id": str(id), "x": x, "y": y, "symbol": symbol, "desc": desc})

    # ------------------------------------------------------------------ output
    def _place_labels(self) -> None:
        """Move labels off other elements' lines, glyphs and labels (:mod:`planargeo.draw._labels`)."""
        place_labels(self, FONT_PX, _CHAR_EM)

    def to_dict(self) -> dict[str, Any]:
        """The picture as plain JSON data (labels placed, numbers rounded to 1e-4 of the view).

        Returns
        -------
        dict
            ``{"size", "margin", "box", "title", "ticks", "elements", "handles"}``, and
            ``"below"`` when there are lines below the plot area (:meth:`Picture.below`):
            ``{"id", "text", "color", "desc", "x", "y"}`` each, ``x``, ``y`` the pixels from the
            plot area's lower left corner to the line's upper left (``y`` down).
        """
        self._place_labels()
        span = max(self.box[1] - self.box[0], self.box[3] - self.box[2])
        nd = max(0, 5 - int(math.floor(math.log10(span))))

        def rnd(v):
            if isinstance(v, np.ndarray):
                return (np.round(v, nd) + 0.0).tolist()
            if isinstance(v, float):
                return round(v, nd) + 0.0
            return v

        elements = []
        add_element = elements.append
        paths: list[tuple[dict, np.ndarray]] = []   # (n, 2) float paths, rounded together below
        add_path = paths.append
        float_, ndarray, f64 = float, np.ndarray, np.float64
        for el in sorted(self.elements, key=itemgetter("z")):
            parts = []
            add = parts.append
            x0 = y0 = rx = ry = None     # the last point rounded (a pole's marker, glyph and label share it)
            for part in el["parts"]:
                part = part.copy()
                x = part.get("x")
                if x is not None:
                    y = part["y"]
                    if x is not x0 or y is not y0:
                        x0, y0 = x, y
                        rx = round(x, nd) + 0.0 if type(x) is float_ else rnd(x)
                        ry = round(y, nd) + 0.0 if type(y) is float_ else rnd(y)
                    part["x"] = rx
                    part["y"] = ry
                    if "along" in part:
                        del part["along"]
                if "xy" in part:
                    xy = part["xy"]
                    if type(xy) is ndarray and xy.dtype == f64 and xy.ndim == 2 and xy.shape[1] == 2:
                        add_path((part, xy))
                    else:
                        part["xy"] = rnd(xy)
                if "m" in part:
                    part["m"] = [round(v, nd + 2) + 0.0 for v in part["m"]]
                add(part)
            # keys at their defaults are left out (the renderers read them with defaults), and
            # "obstacle" (the label placer's, Picture.text); the others keep their order
            out = el.copy()
            for k, v in _DEFAULT_ITEMS:
                if k in out and out[k] == v:
                    del out[k]
            if "obstacle" in out:
                del out["obstacle"]
            out["parts"] = parts
            add_element(out)
        if paths:   # one np.round for all paths (elementwise: the same numbers as one by one)
            rows = np.round(np.concatenate([xy for _, xy in paths]), nd)
            rows += 0.0
            rows = rows.tolist()
            i = 0
            for part, xy in paths:
                n = len(xy)
                part["xy"] = rows[i:i + n]
                i += n
        ticks = ({"x": nice_ticks(self.box[0], self.box[1]), "y": nice_ticks(self.box[2], self.box[3])}
                 if self.ticks else None)
        out = {"size": list(self.size), "margin": list(self.margin),
               "box": [round(v, nd) + 0.0 for v in self.box], "title": self.title,
               "ticks": ticks, "font_px": FONT_PX, "elements": elements,
               "handles": [{**h, "x": rnd(h["x"]), "y": rnd(h["y"])} for h in self.handles]}
        if self._below:
            out["below"] = [dict(line) for line in self._below]
        return out
