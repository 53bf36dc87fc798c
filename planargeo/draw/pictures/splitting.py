"""The splitting explorer's picture: a chain split at a joint, its poles, the split force (thesis 7.4–7.6).

The two sides of the split in two colours, the split joint's force ``fᵢ₊₁`` (7.56), the
couple ``−fₙ₊₁`` on the tip (7.44), every body's acceleration pole (4.6) and the centre
of ``Λᵢ⁻¹`` (7.5); a focus on one side fades the other.

Examples
--------
>>> import math
>>> import numpy as np
>>> from planargeo.scenes.articulated import bent_chain_model
>>> from planargeo.scenes.splitting import splitting_state
>>> st = splitting_state(bent_chain_model(2, 0.5, 1.0, 1.0, 0.0), np.array([0.0, math.pi / 4]), 1, 1.0)
>>> st.update(n=2, split=1)
>>> d = splitting_picture(st, view=(-0.5, 2.0, -1.0, 1.0)).to_dict()
>>> [e["symbol"] for e in d["elements"] if e["id"] in ("a1", "a2")]
['a₁', 'a₂']
"""
from __future__ import annotations

import math

import numpy as np

from planargeo.draw.pictures.common import builder, labelled_line
from planargeo.draw.pictures.kit import label_at
from planargeo.draw.picture import PX_PER_PT, Picture
from planargeo.draw.pictures._words import force, num, pair, subscript, where
from planargeo.draw.style import COLORS, OKABE_ITO
from planargeo.scenes.splitting import twist_pole

__all__ = ["splitting_picture", "LOWER", "UPPER", "FADED", "CUT"]

LOWER, UPPER = OKABE_ITO["blue"], OKABE_ITO["vermillion"]
#: the split joint's ring
CUT = "#b00020"
#: opacity of the side out of focus
FADED = 0.2


def _bodies(a: int, b: int) -> str:
    """Bodies ``a`` to ``b`` and their mass, in words (one body, or several of 1 kg each)."""
    return f"body {a}, of 1 kg" if a == b else f"bodies {a}…{b}, of 1 kg each"


@builder
def splitting_picture(st: dict, *, view, focus: str = "all", centres: bool = True,
                      size=(760, 520)) -> Picture:
    """The picture of one state of the splitting explorer (module docstring).

    Parameters
    ----------
    st : dict
        :func:`planargeo.scenes.splitting.splitting_state` with ``n`` and ``split`` (0-based).
    focus : {"all", "constrained part", "free-floating part"}
        The side kept bright.
    centres : bool
        Draw the centre of ``Λᵢ⁻¹``.
    """
    n, i = int(st["n"]), int(st["split"])
    pts = np.asarray(st["joints"], float)
    low, up = ((1.0, 1.0) if focus == "all" else (1.0, FADED) if focus == "constrained part" else (FADED, 1.0))
    pic = Picture(view, size=size)
    thick = 7.0 * PX_PER_PT
    pic.path("lower", pts[:i + 1], role="body", color=LOWER, width=thick, symbol=f"1…{i}" if i > 1 else "1",
             desc=f"the constrained chain below the split (7.4): {_bodies(1, i)}", z=1,
             opacity=0.55 * low)
    pic.path("upper", pts[i:], role="body", color=UPPER, width=thick,
             symbol=f"{i + 1}…{n}" if n > i + 1 else str(n),
             desc=f"the free-floating chain above the split (7.4): {_bodies(i + 1, n)}", z=1,
             opacity=0.55 * up)
    pic.marks("ground", [pts[0]], role="ground", color=COLORS["ground"], shape="s", size=9.0, symbol="CJ₁",
              desc="joint 1, pinned to the ground: at (0, 0) m", z=3)
    pic.marks("split", [pts[i]], role="body", color=CUT, size=15.0, symbol="split",
              desc=f"the split joint i+1 = {i + 1} (7.4): at {pair(pts[i])} m", z=2)
    label_at(pic, pts[i], "split", gap=9.0)
    pic.marks("pins", pts[1:-1], role="body", color="#000000", size=5.0, symbol="joints", z=4,
              desc="the joint between the two bodies: a pin L = 1 m from the ground" if n == 2 else
              f"the joints between the bodies: {n - 1} pins, L = 1 m apart")
    f = np.asarray(st["f_split"], float)
    fs = f"f{subscript(i + 1)}"
    labelled_line(pic, "f", f, fs, role="reaction", symbol=fs, anchor=pts[i], ahead=0.3,
                  desc=f"force of the split joint {i + 1} on body {i + 1}, its line of action (7.56): {force(f)}")
    tip = -np.asarray(st["f_tip"], float)                 # the fictitious joint n+1 pushes the tip with −f_{n+1}
    turn = ("no couple: the tip is free" if tip[2] == 0.0 else
            "counter-clockwise" if tip[2] > 0 else "clockwise")
    pic.line("couple", tip, role="wrench", symbol=f"−f{subscript(n + 1)}", label=f"−f{subscript(n + 1)} on the tip",
             desc=f"the couple τ on the tip, −f{subscript(n + 1)} from a fictitious joint {n + 1} (7.44): "
                  f"{num(tip[2])} N·m ({turn})")
    poles = [twist_pole(a) for a in st["a"]]
    hide = None
    if poles[i - 1] is None and poles[i] is None:          # both translate the same way: one arrow says it
        u, w = st["a"][i - 1][:2], st["a"][i][:2]
        nu, nw = np.hypot(*u), np.hypot(*w)
        if nu > 0 and nw > 0 and abs(u[0] * w[1] - u[1] * w[0]) <= 0.2 * nu * nw:
            hide = i                                       # (no acceleration at all: each says "none")
    for b in range(n):
        if b == hide:
            continue
        a = np.array(st["a"][b], dtype=float)
        ax, ay, az = (num(v) for v in a)
        if poles[b] is None:
            a[2] = 0.0                                     # a translation: its pole is the ideal point
        side = "the constrained chain" if b < i else "the free-floating chain"
        pic.point(f"a{b + 1}", a, role="accel", color=LOWER if b < i else UPPER, glyph=False, size=6.0,
                  symbol=f"a{subscript(b + 1)}",
                  desc=f"acceleration of body {b + 1} ({side}) as its pole (4.6, 7.54): "
                       f"({ax} m/s², {ay} m/s², {az} rad/s²), pole {where(a)}")
        if (b < i and low < 1) or (b >= i and up < 1):
            pic.elements[-1]["opacity"] = FADED
            for part in pic.elements[-1]["parts"]:
                if part["p"] == "text":
                    part["text"] = ""
    if not np.any(np.asarray(st["a"], float)):             # no load at all (τ = 0, g = 0): exactly at rest
        x0, _x1, _y0, y1 = pic.box
        pic.text("at rest", (x0, y1), "no load: the chain stays at rest", role="text", symbol="at rest",
                 desc="no couple on the tip and no gravity: every acceleration is zero, so no pole is drawn; "
                      "the mobilities and their centre do not depend on the load: at rest",
                 ha="left", va="top", dx=6.0, dy=-6.0)
    c = np.asarray(st["centres"][i - 1], float)
    if centres and bool(np.all(np.isfinite(c))):
        pic.point("centre", [c[1], -c[0], 1.0], role="twist", glyph=False, shape="D", size=7.0,
                  symbol=f"centre of Λ{subscript(i)}⁻¹",
                  desc=f"where a couple on body {i} alone turns it: the pole of −Λ{subscript(i)}⁻¹ [0, 0, 1] "
                       f"(section 7.5): at {pair(c)} m")
    return pic
